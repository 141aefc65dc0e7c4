#pragma once
// Internal to the io module: what the OpenEXR reader (image_exr.cpp) and writer
// (image_exr_write.cpp) share.
#include <OpenEXR/ImfThreading.h>

#include <atomic>

#include "texsynth/core/parallel.h"

namespace texsynth::image_codec {

// Marks a file whose half-float channels hold 8-bit levels k/255. Half floats cannot store
// k/255 exactly but always round back to the right k, so our reader snaps them to k/255 and
// the round trip is bit-exact; other readers see the nearest half floats.
inline constexpr const char* kExrLevelsAttribute = "texsynthLevels";
inline constexpr int kEightBitLevels = 255;

// OpenEXR (de)compresses line blocks on its own global thread pool: size it to --threads.
inline void matchExrThreadsToLimit() {
  const int threads = threadLimit() > 1 ? threadLimit() : 0;  // 0: the calling thread does it all
  // Resizing the pool restarts its threads, which costs more than decoding a small file: only on a change.
  static std::atomic<int> current{-1};
  if (current.exchange(threads) != threads) Imf::setGlobalThreadCount(threads);
}

}  // namespace texsynth::image_codec
