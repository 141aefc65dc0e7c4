// OpenVDB export for Blender/Houdini: a "density" FloatGrid and, for color volumes, a
// "color" Vec3SGrid, both built from dense copies of the volume by openvdb::tools and
// tagged with the volume's size (kVdbSizeMetadata). The reader is vdb_read.cpp.
// Encoded in memory through io::Stream (which io::File reads back) because io::File
// ignores write errors: a full disk would silently leave a truncated file.
#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>

#include <algorithm>
#include <mutex>
#include <sstream>
#include <vector>

#include "texsynth/core/color.h"
#include "texsynth/core/error.h"
#include "vdb_module.h"

namespace texsynth::vdb_module {

void initializeOpenVdb() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

namespace {

// Voxel size 1/maxDim, shifted half a voxel so voxel (x,y,z) covers
// [x, x+1] / maxDim: the whole volume spans [0,1] along its longest axis.
openvdb::math::Transform::Ptr unitBoxTransform(int nx, int ny, int nz) {
  double voxel = 1.0 / double(std::max({nx, ny, nz}));
  auto transform = openvdb::math::Transform::createLinearTransform(voxel);
  transform->postTranslate(openvdb::Vec3d(0.5 * voxel));
  return transform;
}

template <typename Grid>
typename Grid::Ptr gridFromDense(int nx, int ny, int nz, std::vector<typename Grid::ValueType>& values,
                                 const char* name) {
  using Value = typename Grid::ValueType;
  openvdb::CoordBBox box(openvdb::Coord(0), openvdb::Coord(nx - 1, ny - 1, nz - 1));
  openvdb::tools::Dense<Value, openvdb::tools::LayoutXYZ> dense(box, values.data());  // x fastest, like Volume
  auto grid = Grid::create(openvdb::zeroVal<Value>());
  openvdb::tools::copyFromDense(dense, *grid, openvdb::zeroVal<Value>(), /*serial=*/false);
  grid->setName(name);
  grid->setTransform(unitBoxTransform(nx, ny, nz));
  // Zero voxels stay inactive, so the active box alone would lose black borders.
  grid->insertMeta(kVdbSizeMetadata, openvdb::Vec3IMetadata(openvdb::Vec3i(nx, ny, nz)));
  return grid;
}

}  // namespace

std::string encode(const std::string& path, int nx, int ny, int nz, int channels, const float* voxels) {
  initializeOpenVdb();
  try {
    const std::size_t count = std::size_t(nx) * ny * nz;
    openvdb::GridPtrVec grids;
    {
      std::vector<float> density(count);
      for (std::size_t i = 0; i < count; ++i) {
        density[i] = luminance(&voxels[i * channels], channels);
      }
      auto grid = gridFromDense<openvdb::FloatGrid>(nx, ny, nz, density, "density");
      grid->setGridClass(openvdb::GRID_FOG_VOLUME);
      grids.push_back(grid);
    }
    if (channels >= 3) {
      std::vector<openvdb::Vec3s> color(count);
      for (std::size_t i = 0; i < count; ++i) {
        const float* v = &voxels[i * channels];
        color[i] = openvdb::Vec3s(v[0], v[1], v[2]);
      }
      grids.push_back(gridFromDense<openvdb::Vec3SGrid>(nx, ny, nz, color, "color"));
    }
    std::ostringstream bytes(std::ios::binary);
    openvdb::io::Stream(bytes).write(grids);
    return std::move(bytes).str();
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw OutputError(path, std::string("cannot write OpenVDB: ") + e.what());
  }
}

}  // namespace texsynth::vdb_module
