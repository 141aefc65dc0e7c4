// OpenVDB reader: picks one grid (a "color" Vec3 grid, else a scalar float grid), finds the
// dense box it covers and copies it into a dense volume with openvdb::tools::copyToDense. The file
// is parsed from memory by io::Stream without delayed loading, so a truncated file fails
// here rather than when a voxel is first touched.
#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>

#include <cstdint>
#include <sstream>
#include <vector>

#include "texsynth/core/error.h"
#include "vdb_module.h"

namespace texsynth::vdb_module {
namespace {

template <typename Grid>
bool isGrid(const openvdb::GridBase::Ptr& grid, const char* name = nullptr) {
  return grid->isType<Grid>() && (!name || grid->getName() == name);
}

bool isScalar(const openvdb::GridBase::Ptr& grid, const char* name = nullptr) {
  return isGrid<openvdb::FloatGrid>(grid, name) || isGrid<openvdb::DoubleGrid>(grid, name);
}

bool isColor(const openvdb::GridBase::Ptr& grid) {
  return isGrid<openvdb::Vec3SGrid>(grid, "color") || isGrid<openvdb::Vec3DGrid>(grid, "color");
}

// OpenVDB's messages may quote garbage read from a corrupt file (a grid type name ...).
std::string printable(std::string text) {
  if (text.size() > 200) text = text.substr(0, 200) + "...";
  for (char& c : text)
    if (c < 0x20 || c > 0x7e) c = '?';
  return text;
}

std::string gridName(const openvdb::GridBase& grid) {
  return (grid.getName().empty() ? "unnamed" : "'" + printable(grid.getName()) + "'") + " (" + grid.valueType() + ")";
}

// "color" first, then "density", then the first scalar grid; null if none fits.
openvdb::GridBase::Ptr chooseGrid(const openvdb::GridPtrVec& grids) {
  for (auto pick : {+[](const openvdb::GridBase::Ptr& g) { return isColor(g); },
                    +[](const openvdb::GridBase::Ptr& g) { return isScalar(g, "density"); },
                    +[](const openvdb::GridBase::Ptr& g) { return isScalar(g); }})
    for (const auto& grid : grids)
      if (grid && pick(grid)) return grid;
  return nullptr;
}

// Index box of the dense volume: the writer's recorded size when it holds every active voxel,
// else the active box, widened to start at 0 when it lies in the positive octant.
openvdb::CoordBBox denseBox(const std::string& path, const openvdb::GridBase& grid) {
  openvdb::CoordBBox active = grid.evalActiveVoxelBoundingBox();
  if (auto size = grid.getMetadata<openvdb::Vec3IMetadata>(kVdbSizeMetadata)) {
    openvdb::Coord n(size->value());
    bool positive = n.x() >= 1 && n.y() >= 1 && n.z() >= 1;
    openvdb::CoordBBox recorded(openvdb::Coord(0), n - openvdb::Coord(1));
    if (positive && (active.empty() || recorded.isInside(active))) return recorded;
  }
  if (active.empty()) throw InputError(path, "OpenVDB grid " + gridName(grid) + " has no active voxels");
  if (active.min().x() >= 0 && active.min().y() >= 0 && active.min().z() >= 0) active.min() = openvdb::Coord(0);
  return active;
}

// The same limits as the NRRD reader: each side 1..65536, at most 2^31 values.
void checkSize(const std::string& path, const openvdb::GridBase& grid, const openvdb::CoordBBox& box, int channels) {
  std::int64_t values = channels;
  std::string sizeText;
  for (int axis = 0; axis < 3; ++axis) {
    std::int64_t side = std::int64_t(box.max()[axis]) - box.min()[axis] + 1;
    sizeText += (axis ? "x" : "") + std::to_string(side);
    values *= side;
  }
  for (int axis = 0; axis < 3; ++axis)
    if (std::int64_t(box.max()[axis]) - box.min()[axis] + 1 > 65536)
      throw InputError(path, "OpenVDB grid " + gridName(grid) + " spans " + sizeText +
                                 " voxels, which is absurd (each side must be 1..65536)");
  if (values > (std::int64_t(1) << 31))
    throw InputError(path, "OpenVDB grid " + gridName(grid) + " spans " + sizeText +
                               " voxels, which is absurd (more than 2^31 values)");
}

// copyToDense converts each value to DenseValue (double to float, Vec3d to Vec3s).
template <typename DenseValue, typename Grid>
void copyGrid(const openvdb::GridBase::Ptr& grid, const openvdb::CoordBBox& box, DenseValue* out) {
  openvdb::tools::Dense<DenseValue, openvdb::tools::LayoutXYZ> dense(box, out);  // x fastest, like Volume
  openvdb::tools::copyToDense(*openvdb::gridPtrCast<Grid>(grid), dense);
}

DenseVolume denseVolume(const std::string& path, const openvdb::GridBase::Ptr& grid) {
  int channels = isColor(grid) ? 3 : 1;
  openvdb::CoordBBox box = denseBox(path, *grid);
  checkSize(path, *grid, box, channels);
  openvdb::Coord dim = box.dim();
  DenseVolume volume{dim.x(), dim.y(), dim.z(), channels, {}};
  const std::size_t voxelCount = std::size_t(dim.x()) * dim.y() * dim.z();
  volume.voxels.assign(voxelCount * channels, 0.0f);
  if (channels == 1) {
    if (grid->isType<openvdb::FloatGrid>())
      copyGrid<float, openvdb::FloatGrid>(grid, box, volume.voxels.data());
    else
      copyGrid<float, openvdb::DoubleGrid>(grid, box, volume.voxels.data());
    return volume;
  }
  std::vector<openvdb::Vec3s> color(voxelCount);
  if (grid->isType<openvdb::Vec3SGrid>())
    copyGrid<openvdb::Vec3s, openvdb::Vec3SGrid>(grid, box, color.data());
  else
    copyGrid<openvdb::Vec3s, openvdb::Vec3DGrid>(grid, box, color.data());
  for (std::size_t i = 0; i < color.size(); ++i)
    for (int c = 0; c < 3; ++c) volume.voxels[3 * i + c] = color[i][c];
  return volume;
}

}  // namespace

DenseVolume decode(const std::string& path, std::string bytes) {
  initializeOpenVdb();
  const std::string unreadable = "not a readable OpenVDB file: ";
  try {
    std::istringstream in(std::move(bytes), std::ios::binary);
    // OpenVDB does not check its reads: past the end it would go on with garbage counts and
    // lengths (minutes of work, gigabytes). Throwing on the first short read stops it there.
    in.exceptions(std::ios::failbit | std::ios::badbit);
    openvdb::io::Stream stream(in, /*delayLoad=*/false);
    openvdb::GridPtrVecPtr grids = stream.getGrids();
    if (!grids || grids->empty()) throw InputError(path, "OpenVDB file holds no grids");
    openvdb::GridBase::Ptr grid = chooseGrid(*grids);
    if (!grid) {
      std::string held;
      for (const auto& g : *grids)
        if (g) held += (held.empty() ? "" : ", ") + gridName(*g);
      throw InputError(path, "no OpenVDB grid to read as a volume: the file holds " + held +
                                 " (readable: a float or double grid, or a vec3s/vec3d grid named 'color')");
    }
    return denseVolume(path, grid);
  } catch (const Error&) {
    throw;
  } catch (const std::ios_base::failure&) {
    throw InputError(path, unreadable + "it ends early (truncated?)");
  } catch (const std::exception& e) {
    throw InputError(path, unreadable + printable(e.what()));
  }
}

}  // namespace texsynth::vdb_module
