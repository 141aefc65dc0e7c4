#include "texsynth/render/view_up.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "texsynth/core/error.h"

namespace texsynth {

namespace {

using Point = std::array<double, 2>;

double cross(const Point& o, const Point& a, const Point& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// Area of the convex hull of `points` (Andrew's monotone chain; sorts them).
double hullArea(std::vector<Point>& points) {
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return 0;
  std::vector<Point> hull(2 * points.size());
  std::size_t k = 0;
  for (const Point& p : points) {  // lower chain
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {  // upper chain
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  double twiceArea = 0;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Point &a = hull[i], &b = hull[(i + 1) % hull.size()];
    twiceArea += a[0] * b[1] - b[0] * a[1];
  }
  return 0.5 * std::abs(twiceArea);
}

float radians(float degrees) {
  return degrees * std::numbers::pi_v<float> / 180.0f;
}

float degrees(float radians) {
  return radians * 180.0f / std::numbers::pi_v<float>;
}

}  // namespace

float floorFootprint(const Mesh& mesh, int axis, bool positive) {
  if (axis < 0 || axis > 2) throw ParameterError("axis", "must be 0, 1 or 2, got " + std::to_string(axis));
  if (mesh.positions.empty()) return 0;
  const Box3f box = mesh.bounds();
  const Vec3f size = box.size();
  const int u = (axis + 1) % 3, w = (axis + 2) % 3;
  const double faceArea = double(size[u]) * double(size[w]);
  if (!(faceArea > 0) || !std::isfinite(faceArea)) return 0;
  const double band = double(kFloorBand) * double(size.norm());
  const Eigen::Vector3d centre = box.center().cast<double>();
  std::vector<Eigen::Vector3d> points;
  points.reserve(mesh.positions.size());
  for (const Vec3f& p : mesh.positions) points.push_back(p.cast<double>() - centre);
  // Floors leaning by 0, +-kFloorTilt / 2 and +-kFloorTilt degrees towards each of the face's two axes.
  constexpr std::array<double, 5> kTilts = {0, -0.5, 0.5, -1, 1};
  double widest = 0;
  std::vector<Point> contact;
  for (double a : kTilts)
    for (double b : kTilts) {
      Eigen::Vector3d down = Eigen::Vector3d::Zero();  // the floor's normal, pointing out of the mesh
      down[axis] = positive ? -1 : 1;
      down[u] = std::tan(a * double(kFloorTilt) * std::numbers::pi / 180);
      down[w] = std::tan(b * double(kFloorTilt) * std::numbers::pi / 180);
      down.normalize();
      double lowest = -std::numeric_limits<double>::infinity();
      for (const Eigen::Vector3d& p : points) lowest = std::max(lowest, p.dot(down));
      contact.clear();
      for (const Eigen::Vector3d& p : points)
        if (p.dot(down) >= lowest - band) contact.push_back({p[u], p[w]});
      widest = std::max(widest, hullArea(contact));
    }
  return float(std::min(1.0, widest / faceArea));
}

Vec3f viewUpDirection(const Mesh& mesh) {
  // Candidates in tie-breaking order: +Y, +Z, +X, -Y, -Z, -X.
  constexpr std::array<std::pair<int, bool>, 6> kCandidates = {
      {{1, true}, {2, true}, {0, true}, {1, false}, {2, false}, {0, false}}};
  std::pair<int, bool> best = kCandidates[0];
  float widest = -1;
  for (const auto& candidate : kCandidates) {
    const float footprint = floorFootprint(mesh, candidate.first, candidate.second);
    if (footprint > widest) widest = footprint, best = candidate;
  }
  if (widest < kFloorFootprint) return Vec3f::UnitY();
  Vec3f up = Vec3f::Zero();
  up[best.first] = best.second ? 1.0f : -1.0f;
  return up;
}

Mat3f upFrame(const Vec3f& up) {
  if (!up.allFinite() || !(up.cwiseAbs().maxCoeff() > 0))
    throw ParameterError("up", "must be a finite non-zero vector");
  const Vec3f u = up.stableNormalized();
  if (u == Vec3f::UnitY()) return Mat3f::Identity();
  if (u == -Vec3f::UnitY()) return Vec3f(1, -1, -1).asDiagonal();  // a half turn about +X, exactly
  // In double: near -Y the arc's half-angle cosine (1 + y) / 2 would round to 0 in float.
  return Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitY(), u.cast<double>())
      .toRotationMatrix()
      .cast<float>();
}

std::pair<float, float> anglesAboutUp(const Vec3f& up, std::pair<float, float> yawPitchAboutY) {
  const Mat3f frame = upFrame(up);
  if (frame == Mat3f::Identity()) return yawPitchAboutY;
  const auto [yaw, pitch] = yawPitchAboutY;
  // Where the camera sits, seen from the centre: RenderOptions' orbit about +Y.
  const Vec3f eye(std::cos(radians(pitch)) * std::sin(radians(yaw)), std::sin(radians(pitch)),
                  std::cos(radians(pitch)) * std::cos(radians(yaw)));
  const Vec3f local = frame.transpose() * eye;
  return {degrees(std::atan2(local.x(), local.z())), degrees(std::asin(std::clamp(local.y(), -1.0f, 1.0f)))};
}

}  // namespace texsynth
