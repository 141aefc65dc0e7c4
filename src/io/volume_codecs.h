#pragma once
// Internal to the io module: the volume codecs behind volume_io.cpp.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "texsynth/io/volume_io.h"

namespace texsynth::volume_codec {

// NRRD with attached data (raw or gzip).
Volume decodeNrrd(const std::string& path, std::string_view bytes);
// Writes a NRRD to `filePath` (the temporary path of an atomic write); `path` names errors.
void writeNrrd(const std::string& filePath, const std::string& path, const Volume& volume,
               const VolumeWriteOptions& options);

// OpenVDB file contents: "density" (+ "color") grids; `path` names errors. Both go through the
// OpenVDB module (vdb/vdb_module.h), loaded on first use.
std::string encodeVdb(const std::string& path, const Volume& volume);
// A volume from OpenVDB file contents (the rule is in volume_io.h); `path` names errors.
Volume decodeVdb(const std::string& path, std::string bytes);

// gzip/zlib inflate of `compressed` into exactly `expectedBytes` bytes; throws
// InputError(path, ...) if the stream is corrupt or ends early.
std::string inflateExactly(const std::string& path, std::string_view compressed, std::uint64_t expectedBytes);

// Streams gzip output: feed it blocks, each compressed chunk goes to `sink`.
class GzipWriter {
 public:
  explicit GzipWriter(std::function<void(const char*, std::size_t)> sink, int level);
  ~GzipWriter();
  GzipWriter(const GzipWriter&) = delete;
  GzipWriter& operator=(const GzipWriter&) = delete;
  void write(const char* data, std::size_t size);
  void finish();

 private:
  void pump(int flush);
  struct State;
  std::unique_ptr<State> state_;
  std::function<void(const char*, std::size_t)> sink_;
};

}  // namespace texsynth::volume_codec
