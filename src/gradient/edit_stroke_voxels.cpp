// Stroke polylines to the voxels they pass through (gradient-solid edits, §4.4).
#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "texsynth/core/color.h"
#include "texsynth/core/error.h"
#include "texsynth/gradient/edit_influence.h"

namespace texsynth {
namespace {

// The part [t0, t1] of a + t (b - a), t in [0,1], inside `lo`..`hi` (Liang-Barsky); false if none.
bool clipSegment(const Vec3f& a, const Vec3f& b, const Vec3f& lo, const Vec3f& hi, float& t0, float& t1) {
  t0 = 0.0f;
  t1 = 1.0f;
  for (int axis = 0; axis < 3; ++axis) {
    const float d = b[axis] - a[axis];
    if (d == 0.0f) {
      if (a[axis] < lo[axis] || a[axis] > hi[axis]) return false;
      continue;
    }
    float enter = (lo[axis] - a[axis]) / d, leave = (hi[axis] - a[axis]) / d;
    if (enter > leave) std::swap(enter, leave);
    t0 = std::max(t0, enter);
    t1 = std::min(t1, leave);
  }
  return t0 <= t1;
}

void checkStroke(const EditStroke& stroke, std::size_t index) {
  const std::string where = "strokes[" + std::to_string(index) + "]";
  if (stroke.points.empty()) throw ParameterError("strokes", where + " has no points");
  if (!(stroke.strength >= 0.0f && stroke.strength <= 1.0f))
    throw ParameterError("strokes", where + ".strength must be in [0, 1]");
  for (const Vec3f& p : stroke.points)
    if (!p.allFinite()) throw ParameterError("strokes", where + " has a non-finite point");
}

}  // namespace

StrokeVoxels rasterizeStrokes(const std::vector<EditStroke>& strokes, const Vec3i& extent) {
  if (strokes.empty()) throw ParameterError("strokes", "no strokes");
  StrokeVoxels out;
  std::unordered_map<std::int64_t, int> slotOf;  // voxel index -> position in `out`
  auto add = [&](const Vec3f& p, float strength) {
    Vec3i v;
    for (int a = 0; a < 3; ++a) v[a] = std::clamp(int(std::lround(p[a])), 0, extent[a] - 1);
    const std::int64_t key = (std::int64_t(v.z()) * extent.y() + v.y()) * extent.x() + v.x();
    auto [it, inserted] = slotOf.try_emplace(key, out.size());
    if (inserted) {
      out.positions.push_back(v);
      out.strengths.push_back(strength);
    } else {
      out.strengths[std::size_t(it->second)] = strength;  // later strokes override
    }
  };
  // Points round to voxels inside [0, extent-1] when they lie within half a voxel of it.
  const Vec3f lo = Vec3f::Constant(-0.5f), hi = extent.cast<float>() - Vec3f::Constant(0.5f);
  for (std::size_t s = 0; s < strokes.size(); ++s) {
    const EditStroke& stroke = strokes[s];
    checkStroke(stroke, s);
    const std::size_t segments = std::max<std::size_t>(stroke.points.size(), 2) - 1;
    for (std::size_t i = 0; i < segments; ++i) {
      const Vec3f a = stroke.points[i], b = stroke.points[std::min(i + 1, stroke.points.size() - 1)];
      float t0, t1;
      if (!clipSegment(a, b, lo, hi, t0, t1)) continue;
      const Vec3f from = a + t0 * (b - a), to = a + t1 * (b - a);
      // Steps of at most half a voxel: consecutive samples round to the same or neighbouring voxels.
      const int steps = std::max(1, int(std::ceil((to - from).norm() / 0.5f)));
      for (int k = 0; k <= steps; ++k) add(from + (float(k) / float(steps)) * (to - from), stroke.strength);
    }
  }
  if (out.positions.empty()) throw ParameterError("strokes", "no stroke passes through the volume");
  return out;
}

int editColorChannels(int channels) {
  return channels >= 3 ? 3 : 1;
}

std::array<float, 3> editReference(const Vec3f& color, int colorChannels) {
  if (colorChannels == 3) return {color.x(), color.y(), color.z()};
  const float gray = luminance(color.data(), 3);
  return {gray, gray, gray};
}

}  // namespace texsynth
