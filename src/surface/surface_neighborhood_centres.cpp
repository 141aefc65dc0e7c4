// The active neighbourhood centres on a mesh: a deterministic maximal Poisson-disk subset of the
// vertices, taken greedily in hashed order with a hashed grid of the accepted ones
// (selectActiveCentres in surface_neighborhoods.h).
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"
#include "texsynth/surface/surface_neighborhoods.h"

namespace texsynth {

namespace {

// Accepted centres bucketed by grid cell (edge R): an open-addressing table of cells, each the
// head of a list of centres threaded through `next`.
class CentreGrid {
 public:
  CentreGrid(std::size_t vertices, float cellSize) : inverse_(1.0 / double(cellSize)), next_(vertices, -1) {
    std::size_t capacity = 16;
    while (capacity < 2 * vertices) capacity *= 2;
    slots_.resize(capacity);
  }

  std::array<std::int64_t, 3> cellOf(const Vec3f& x) const {
    auto coordinate = [&](float c) { return std::int64_t(std::clamp(std::floor(double(c) * inverse_), -1e15, 1e15)); };
    return {coordinate(x.x()), coordinate(x.y()), coordinate(x.z())};
  }

  // First centre in cell c, or -1; the rest follow through next().
  std::int32_t head(const std::array<std::int64_t, 3>& c) const {
    const Slot& s = slots_[find(c)];
    return s.used ? s.head : -1;
  }
  std::int32_t next(std::int32_t v) const { return next_[std::size_t(v)]; }

  void insert(const std::array<std::int64_t, 3>& c, std::int32_t v) {
    Slot& s = slots_[find(c)];
    if (!s.used) {
      s = {c, -1, true};
    }
    next_[std::size_t(v)] = s.head;
    s.head = v;
  }

 private:
  struct Slot {
    std::array<std::int64_t, 3> cell{};
    std::int32_t head = -1;
    bool used = false;
  };

  std::size_t find(const std::array<std::int64_t, 3>& c) const {
    const std::size_t mask = slots_.size() - 1;
    std::size_t i = std::size_t(latticeId(c[0], c[1], c[2])) & mask;
    while (slots_[i].used && slots_[i].cell != c) i = (i + 1) & mask;
    return i;
  }

  double inverse_;
  std::vector<std::int32_t> next_;
  std::vector<Slot> slots_;
};

}  // namespace

std::vector<std::int32_t> selectActiveCentres(const Mesh& mesh, float spacing, int stride, std::uint64_t seed) {
  if (!(spacing > 0) || !std::isfinite(spacing))
    throw ParameterError("spacing", "must be positive and finite, got " + std::to_string(spacing));
  if (stride < 1) throw ParameterError("stride", "must be at least 1, got " + std::to_string(stride));
  const std::size_t n = mesh.vertexCount();
  const bool useNormals = !mesh.normals.empty();
  if (useNormals && mesh.normals.size() != n)
    throw ParameterError(
        "mesh", "has " + std::to_string(mesh.normals.size()) + " normals for " + std::to_string(n) + " vertices");
  std::vector<std::int32_t> centres(n);
  std::iota(centres.begin(), centres.end(), 0);
  if (stride == 1) return centres;

  const float radius = float(stride) * spacing, radius2 = radius * radius;
  if (!std::isfinite(radius2)) throw ParameterError("spacing", "stride * spacing is too large");
  std::vector<std::pair<std::uint64_t, std::int32_t>> order(n);
  parallelFor(
      0, std::int64_t(n),
      [&](std::int64_t v) {
        order[std::size_t(v)] = {hashKey(seed, std::uint64_t(v)), std::int32_t(v)};
      },
      4096);
  std::sort(order.begin(), order.end());

  CentreGrid grid(n, radius);
  centres.clear();
  for (const auto& [priority, v] : order) {
    const Vec3f& x = mesh.positions[std::size_t(v)];
    const auto cell = grid.cellOf(x);
    bool free = true;
    for (int dz = -1; dz <= 1 && free; ++dz)
      for (int dy = -1; dy <= 1 && free; ++dy)
        for (int dx = -1; dx <= 1 && free; ++dx)
          for (std::int32_t u = grid.head({cell[0] + dx, cell[1] + dy, cell[2] + dz}); u >= 0 && free; u = grid.next(u))
            free = !((mesh.positions[std::size_t(u)] - x).squaredNorm() <= radius2 &&
                     (!useNormals || mesh.normals[std::size_t(u)].dot(mesh.normals[std::size_t(v)]) >= 0));
    if (!free) continue;
    grid.insert(cell, v);
    centres.push_back(v);
  }
  std::sort(centres.begin(), centres.end());
  return centres;
}

}  // namespace texsynth
