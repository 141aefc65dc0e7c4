#include "texsynth/core/volume.h"

#include <cmath>

#include "texsynth/core/wrap.h"

namespace texsynth {

Volume::Volume(int x, int y, int z, int c, float fill) : nx(x), ny(y), nz(z), channels(c) {
  if (x < 0 || y < 0 || z < 0 || c < 0) throw ParameterError("volume size", "negative dimension");
  voxels.assign(std::size_t(x) * y * z * c, fill);
}

void Volume::sampleTrilinearWrapped(float x, float y, float z, float* out) const {
  float f[3] = {x - 0.5f, y - 0.5f, z - 0.5f};
  int n[3] = {nx, ny, nz};
  int i0[3], i1[3];
  float t[3];
  for (int a = 0; a < 3; ++a) {
    float fl = std::floor(f[a]);
    t[a] = f[a] - fl;
    i0[a] = wrapIndex(int(fl), n[a]);
    i1[a] = wrapIndex(i0[a] + 1, n[a]);
  }
  for (int c = 0; c < channels; ++c) out[c] = 0.0f;
  for (int corner = 0; corner < 8; ++corner) {
    int ix = corner & 1 ? i1[0] : i0[0], iy = corner & 2 ? i1[1] : i0[1], iz = corner & 4 ? i1[2] : i0[2];
    float w = (corner & 1 ? t[0] : 1 - t[0]) * (corner & 2 ? t[1] : 1 - t[1]) * (corner & 4 ? t[2] : 1 - t[2]);
    const float* v = voxel(ix, iy, iz);
    for (int c = 0; c < channels; ++c) out[c] += w * v[c];
  }
}

}  // namespace texsynth
