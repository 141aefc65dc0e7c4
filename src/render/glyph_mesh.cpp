#include "texsynth/render/glyph_mesh.h"

#include <cmath>

#include "texsynth/core/error.h"

namespace texsynth {

namespace {

void requireAnnotatable(const Mesh& mesh) {
  if (mesh.colors.size() != mesh.positions.size() || mesh.normals.size() != mesh.positions.size())
    throw ParameterError("mesh", "needs a colour and a normal per vertex before glyphs are appended (coloredCopy)");
}

// One flat quad a-b-c-d (counter-clockwise seen from the side `normal` points to).
void appendQuad(Mesh& mesh, const Vec3f& a, const Vec3f& b, const Vec3f& c, const Vec3f& d, const Vec3f& color) {
  Vec3f normal = (b - a).cross(d - a);
  if (!(normal.norm() > 0)) return;
  normal.normalize();
  const int base = int(mesh.positions.size());
  for (const Vec3f* p : {&a, &b, &c, &d}) {
    mesh.positions.push_back(*p);
    mesh.normals.push_back(normal);
    mesh.colors.push_back(color);
  }
  mesh.triangles.push_back({base, base + 1, base + 2});
  mesh.triangles.push_back({base, base + 2, base + 3});
}

// Two unit vectors orthogonal to `axis` and to each other.
std::pair<Vec3f, Vec3f> perpendiculars(const Vec3f& axis) {
  Frame f = Frame::fromNormal(axis);
  return {f.x, f.y};
}

}  // namespace

Mesh coloredCopy(const Mesh& mesh, const Vec3f& color) {
  Mesh out;
  out.positions = mesh.positions;
  out.triangles = mesh.triangles;
  out.normals = mesh.normals;
  if (out.normals.size() != out.positions.size()) out.computeNormals();
  out.colors.assign(out.positions.size(), color);
  return out;
}

void appendStick(Mesh& mesh, const Vec3f& from, const Vec3f& to, float radius, const Vec3f& color) {
  requireAnnotatable(mesh);
  Vec3f axis = to - from;
  if (!(axis.norm() > 0) || !(radius > 0)) return;
  auto [u, v] = perpendiculars(axis.normalized());
  u *= radius;
  v *= radius;
  const Vec3f corners[4] = {u + v, -u + v, -u - v, u - v};
  for (int s = 0; s < 4; ++s) {
    const Vec3f &c0 = corners[s], &c1 = corners[(s + 1) % 4];
    appendQuad(mesh, from + c0, from + c1, to + c1, to + c0, color);
  }
  appendQuad(mesh, to + corners[0], to + corners[1], to + corners[2], to + corners[3], color);
  appendQuad(mesh, from + corners[3], from + corners[2], from + corners[1], from + corners[0], color);
}

void appendPolyline(Mesh& mesh, const std::vector<Vec3f>& points, float radius, const Vec3f& color) {
  requireAnnotatable(mesh);
  for (std::size_t i = 0; i + 1 < points.size(); ++i) appendStick(mesh, points[i], points[i + 1], radius, color);
  // Joints: a short stick along the previous segment's direction, as wide as it is long.
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    Vec3f d = (points[i + 1] - points[i - 1]).normalized() * radius;
    if (d.allFinite()) appendStick(mesh, points[i] - d, points[i] + d, radius * 1.05f, color);
  }
}

void appendAxisGlyph(Mesh& mesh, const Vec3f& center, const Frame& frame, float length, float radius, bool centered) {
  const Vec3f axes[3] = {frame.x, frame.y, frame.z};
  for (int a = 0; a < 3; ++a) {
    Vec3f start = centered ? Vec3f(center - 0.5f * length * axes[a]) : center;
    Vec3f end = centered ? Vec3f(center + 0.5f * length * axes[a]) : Vec3f(center + length * axes[a]);
    appendStick(mesh, start, end, radius, kAxisColors[a]);
  }
}

}  // namespace texsynth
