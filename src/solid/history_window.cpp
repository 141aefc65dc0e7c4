// History windows: the version of each neighbour a correction reads, and the standard,
// subpass and grid schemes expressed as windows.
#include "texsynth/solid/history_window.h"

#include <algorithm>

#include "texsynth/core/error.h"
#include "texsynth/core/wrap.h"

namespace texsynth {

HistoryWindow::HistoryWindow(int radius, std::int8_t version)
    : radius_(radius), versions_(std::size_t((2 * radius + 1) * (2 * radius + 1) * (2 * radius + 1)), version) {
  TS_CHECK(radius >= 0);
}

HistoryWindow& HistoryWindow::intersect(const HistoryWindow& other) {
  TS_CHECK(other.radius_ == radius_);
  for (std::size_t i = 0; i < versions_.size(); ++i) versions_[i] = std::min(versions_[i], other.versions_[i]);
  return *this;
}

int subpassClassOf(const Vec3i& v, int s) {
  if (s == 1) return 0;
  return wrapIndex(v.x(), s) | wrapIndex(v.y(), s) << 1 | wrapIndex(v.z(), s) << 2;
}

HistoryWindow passWindow(int radius, int pass) {
  TS_CHECK(pass >= 1 && pass < HistoryWindow::kLatest);
  return HistoryWindow(radius, std::int8_t(pass - 1));
}

HistoryWindow subpassWindow(int radius, int pass, int subpass, std::span<const int> classOrder, int s,
                            const Vec3i& voxel) {
  TS_CHECK(subpass >= 0 && std::size_t(subpass) < classOrder.size());
  HistoryWindow window = passWindow(radius, pass);
  std::vector<bool> corrected(std::size_t(s * s * s), false);  // classes done earlier in this pass
  for (int j = 0; j < subpass; ++j) corrected[std::size_t(std::max(classOrder[std::size_t(j)], 0))] = true;
  for (int z = -radius; z <= radius; ++z)
    for (int y = -radius; y <= radius; ++y)
      for (int x = -radius; x <= radius; ++x) {
        const Vec3i offset(x, y, z);
        if (corrected[std::size_t(subpassClassOf(voxel + offset, s))]) window.set(offset, std::int8_t(pass));
      }
  return window;
}

HistoryWindow gridWindow(int radius, int cellSize, int shift, int startVersion, const Vec3i& voxel) {
  TS_CHECK(cellSize >= 1);
  HistoryWindow window(radius, std::int8_t(startVersion));
  Vec3i lo, hi;  // the voxel's cell, relative to the voxel
  for (int a = 0; a < 3; ++a) {
    const int start = voxel[a] - wrapIndex(voxel[a] + shift, cellSize);
    lo[a] = std::max(start - voxel[a], -radius);
    hi[a] = std::min(start + cellSize - 1 - voxel[a], radius);
  }
  for (int z = lo.z(); z <= hi.z(); ++z)
    for (int y = lo.y(); y <= hi.y(); ++y)
      for (int x = lo.x(); x <= hi.x(); ++x) window.set(Vec3i(x, y, z), HistoryWindow::kLatest);
  return window;
}

}  // namespace texsynth
