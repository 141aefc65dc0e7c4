#pragma once
// Internal to the io module: one zlib stream (RFC 1950) compressed in parallel, pigz-style.
// The input is cut into fixed-size chunks; each is a raw deflate stream primed with the
// previous 32 KiB of input, so matches may cross chunk boundaries, and ends on a byte
// boundary (a sync flush) so the pieces concatenate; the adler32 checksums are combined.
// Chunking depends only on the input size, so the bytes are the same for any thread count.
#include <cstddef>
#include <cstdint>
#include <string>

namespace texsynth::image_codec {

struct ParallelZlibSettings {
  int level = 6;                                  // zlib level 1..9
  int strategy = 0;                               // Z_DEFAULT_STRATEGY, Z_FILTERED, Z_RLE ...
  std::size_t chunkBytes = std::size_t(1) << 20;  // input bytes per parallel task (1 .. 1 GiB)
};

// A complete zlib stream (header, deflate data, adler32) of data[0..size).
std::string compressZlibParallel(const std::uint8_t* data, std::size_t size, const ParallelZlibSettings& settings);

}  // namespace texsynth::image_codec
