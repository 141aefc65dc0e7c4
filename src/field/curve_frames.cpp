#include "texsynth/field/curve_frames.h"

#include <cmath>

#include "texsynth/core/error.h"

namespace texsynth {

namespace {

// Evenly spaced points along a polyline (first and last kept exactly).
std::vector<Vec3f> resample(const std::vector<Vec3f>& points, float spacing) {
  std::vector<float> along{0};
  for (std::size_t i = 1; i < points.size(); ++i) along.push_back(along.back() + (points[i] - points[i - 1]).norm());
  const float length = along.back();
  const int count = std::max(2, int(std::ceil(length / spacing)) + 1);
  std::vector<Vec3f> out;
  std::size_t segment = 1;
  for (int k = 0; k < count; ++k) {
    float s = length * float(k) / float(count - 1);
    while (segment + 1 < points.size() && along[segment] < s) ++segment;
    float t = (s - along[segment - 1]) / std::max(1e-30f, along[segment] - along[segment - 1]);
    out.push_back(points[segment - 1] + std::clamp(t, 0.0f, 1.0f) * (points[segment] - points[segment - 1]));
  }
  return out;
}

}  // namespace

std::vector<CurveSample> sampleCurve(const SketchCurve& curve, const SurfaceProjector* projector, float spacing,
                                     float tolerance, const std::string& source) {
  const std::string where = curve.name.empty() ? std::string("curve") : "curve '" + curve.name + "'";
  if (curve.points.size() < 2) throw InputError(source, where + " needs at least 2 points");
  if (!(spacing > 0)) throw ParameterError("spacing", "must be positive");
  std::vector<Vec3f> points;
  std::vector<Vec3f> normals;
  Vec3f planeNormal = curve.planeNormal.normalized();
  auto place = [&](const Vec3f& p, std::size_t index, bool original) -> std::pair<Vec3f, Vec3f> {
    if (curve.placement == CurvePlacement::Surface) {
      if (!projector) throw ParameterError("projector", "a surface curve needs a mesh");
      SurfacePoint s = projector->closestPoint(p);
      if (original && s.distance > tolerance)
        throw InputError(source, where + " point " + std::to_string(index) + " lies " + std::to_string(s.distance) +
                                     " from the mesh surface (tolerance " + std::to_string(tolerance) + ")");
      return {s.position, s.normal};
    }
    Vec3f origin = curve.planePoint.value_or(curve.points[0]);
    float d = (p - origin).dot(planeNormal);
    if (original && std::abs(d) > tolerance)
      throw InputError(source, where + " point " + std::to_string(index) + " lies " + std::to_string(std::abs(d)) +
                                   " from its reference plane (tolerance " + std::to_string(tolerance) + ")");
    return {p - d * planeNormal, planeNormal};
  };
  // Check the user's points first (clear errors), then place the dense samples.
  for (std::size_t i = 0; i < curve.points.size(); ++i) points.push_back(place(curve.points[i], i, true).first);
  std::vector<Vec3f> dense = resample(points, spacing);
  std::vector<CurveSample> samples(dense.size());
  for (std::size_t i = 0; i < dense.size(); ++i) {
    auto [p, n] = place(dense[i], i, false);
    samples[i].position = p;
    samples[i].normal = n;
  }
  for (std::size_t i = 0; i < samples.size(); ++i) {
    // Central differences of the placed samples, one-sided at the ends.
    const Vec3f& ahead = samples[std::min(i + 1, samples.size() - 1)].position;
    const Vec3f& behind = samples[i == 0 ? 0 : i - 1].position;
    Vec3f t = ahead - behind;
    // Snapping can fold two samples together; the original polyline still has a direction.
    if (!(t.norm() > 1e-12f)) t = points.back() - points.front();
    t.normalize();
    Vec3f n = samples[i].normal - samples[i].normal.dot(t) * t;
    if (!(n.norm() > 1e-3f)) {
      if (i == 0) throw InputError(source, where + " runs along the normal at its start; it has no frame there");
      n = samples[i - 1].normal - samples[i - 1].normal.dot(t) * t;  // keep the previous sample's normal
      if (!(n.norm() > 1e-3f)) throw InputError(source, where + " runs along the normal; it has no frame there");
    }
    samples[i].tangent = t;
    samples[i].normal = n.normalized();
  }
  return samples;
}

std::vector<AxisAssignment> allowedAssignments(const SketchCurve& curve) {
  std::vector<AxisAssignment> out;
  // Canonical order: labels (or defaults) first, so the first curve's choice is predictable.
  int firstTangent = curve.tangentAxis.value_or(0);
  for (int ti = 0; ti < 3; ++ti) {
    int tangent = (firstTangent + ti) % 3;
    if (curve.tangentAxis && tangent != *curve.tangentAxis) continue;
    int defaultNormal = (tangent + 2) % 3;
    for (int ni = 0; ni < 2; ++ni) {
      int normal = ni == 0 ? defaultNormal : (tangent + 1) % 3;
      if (curve.normalAxis) {
        if (normal != *curve.normalAxis) continue;
      }
      for (int flips = 0; flips < 4; ++flips) out.push_back({tangent, normal, bool(flips & 1), bool(flips & 2)});
    }
  }
  if (curve.normalAxis && curve.tangentAxis && out.empty()) throw ParameterError("normalAxis", "equals tangentAxis");
  return out;
}

Quatf frameRotation(const CurveSample& sample, const AxisAssignment& a) {
  Mat3f r;
  Vec3f t = a.flipTangent ? Vec3f(-sample.tangent) : sample.tangent;
  Vec3f n = a.flipNormal ? Vec3f(-sample.normal) : sample.normal;
  int third = 3 - a.tangentAxis - a.normalAxis;
  r.col(a.tangentAxis) = t;
  r.col(a.normalAxis) = n;
  // Right-handed: axis (k + 1) = axis k x axis (k + 2) cyclically.
  r.col(third) = (a.normalAxis == (a.tangentAxis + 1) % 3) ? t.cross(n) : n.cross(t);
  return Quatf(r).normalized();
}

}  // namespace texsynth
