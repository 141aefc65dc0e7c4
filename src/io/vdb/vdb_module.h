#pragma once
// The OpenVDB codec, built as a module of its own (libtexsynth_vdb.so) that the io module loads
// with dlopen the first time a .vdb file is read or written (io/vdb_codec.cpp). Linking OpenVDB
// into every program cost every texsynth command 55 ms at start-up: the library binds its 69,000
// symbols at load time. The module uses only header-only texsynth types, so it needs nothing
// from the program that loads it; errors cross as texsynth::InputError and OutputError.
#include <cstddef>
#include <string>
#include <vector>

namespace texsynth::vdb_module {

// A dense volume, x fastest, `channels` values per voxel (as texsynth::Volume).
struct DenseVolume {
  int nx = 0, ny = 0, nz = 0, channels = 0;
  std::vector<float> voxels;
};

// What the module offers. `path` names errors only.
struct Codec {
  // OpenVDB file contents: a "density" grid (luminance) and, for 3+ channels, a "color" grid of
  // the first three; `voxels` holds nx*ny*nz*channels values. Throws OutputError.
  std::string (*encode)(const std::string& path, int nx, int ny, int nz, int channels, const float* voxels);
  // A volume from OpenVDB file contents (the rule is in volume_io.h). Throws InputError.
  DenseVolume (*decode)(const std::string& path, std::string bytes);
};

// The module's one exported symbol: extern "C" const Codec* texsynthVdbCodec().
inline constexpr const char* kEntryPoint = "texsynthVdbCodec";
using EntryPoint = const Codec* (*)();

// Encoding and decoding, defined in vdb_write.cpp and vdb_read.cpp.
std::string encode(const std::string& path, int nx, int ny, int nz, int channels, const float* voxels);
DenseVolume decode(const std::string& path, std::string bytes);
// openvdb::initialize() once per process (it registers the grid types).
void initializeOpenVdb();
// Grid metadata (Vec3i) holding the volume's size, so zero borders survive a round trip.
inline constexpr const char* kVdbSizeMetadata = "texsynth_size";

}  // namespace texsynth::vdb_module
