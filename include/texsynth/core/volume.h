#pragma once
// Volume: a 3D grid of float voxels with N interleaved channels, x fastest then y then z.
#include <cstddef>
#include <vector>

#include "texsynth/core/error.h"

namespace texsynth {

struct Volume {
  int nx = 0, ny = 0, nz = 0, channels = 0;
  std::vector<float> voxels;  // size nx*ny*nz*channels

  Volume() = default;
  Volume(int nx, int ny, int nz, int channels, float fill = 0.0f);

  bool empty() const { return nx == 0 || ny == 0 || nz == 0 || channels == 0; }
  std::size_t voxelCount() const { return std::size_t(nx) * ny * nz; }
  std::size_t index(int x, int y, int z) const { return ((std::size_t(z) * ny + y) * nx + x) * channels; }
  float& at(int x, int y, int z, int c) { return voxels[index(x, y, z) + c]; }
  float at(int x, int y, int z, int c) const { return voxels[index(x, y, z) + c]; }
  float* voxel(int x, int y, int z) { return &voxels[index(x, y, z)]; }
  const float* voxel(int x, int y, int z) const { return &voxels[index(x, y, z)]; }

  // Trilinear lookup at continuous coordinates (voxel centers at integer+0.5), wrapping.
  void sampleTrilinearWrapped(float x, float y, float z, float* out) const;
};

}  // namespace texsynth
