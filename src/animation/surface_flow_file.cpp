#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include "flow_spec.h"
#include "surface_flow_fields.h"
#include "texsynth/animation/flow_limits.h"
#include "texsynth/core/error.h"
#include "texsynth/geometry/surface_projector.h"

namespace texsynth::flow_detail {
namespace {

std::string readText(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path, "file does not exist");
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path, "is not a file");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in || in.bad()) throw InputError(path, "cannot be read");
  return text.str();
}

// A token as it may be quoted in a one-line message.
std::string quoted(std::string_view token) {
  constexpr std::size_t kLongest = 24;
  std::string text(token.substr(0, kLongest));
  for (char& c : text)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
  return "'" + text + (token.size() > kLongest ? "...'" : "'");
}

// Splits on blanks (space, tab, '\r').
std::vector<std::string_view> tokens(std::string_view line) {
  std::vector<std::string_view> out;
  constexpr std::string_view kBlanks = " \t\r\v\f";
  for (std::size_t start = line.find_first_not_of(kBlanks); start != std::string_view::npos;) {
    const std::size_t end = std::min(line.find_first_of(kBlanks, start), line.size());
    out.push_back(line.substr(start, end - start));
    start = line.find_first_not_of(kBlanks, end);
  }
  return out;
}

}  // namespace

std::vector<Vec3f> readVertexVelocities(const std::string& path, std::size_t vertexCount) {
  const std::string text = readText(path);
  std::vector<Vec3f> velocities;
  velocities.reserve(vertexCount);
  std::size_t lines = 0;  // of velocities
  int lineNumber = 0;
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string_view line = std::string_view(text).substr(start, end - start);
    start = end + 1;
    ++lineNumber;
    line = line.substr(0, line.find('#'));
    const std::vector<std::string_view> values = tokens(line);
    if (values.empty()) continue;
    const std::string where = "line " + std::to_string(lineNumber) + ": ";
    if (values.size() != 3)
      throw InputError(path, where + "expected 3 numbers (vx vy vz), found " + std::to_string(values.size()));
    Vec3f v;
    for (int i = 0; i < 3; ++i)
      if (!parseFiniteFloat(values[std::size_t(i)], v[i]) || std::abs(v[i]) > kMaxFlowSpeed)
        throw InputError(path, where + quoted(values[std::size_t(i)]) + " is not a finite number within " +
                                   std::to_string(int(kMaxFlowSpeed)) + " world units per frame");
    // Past the vertex count only count, so the message can say how many lines there are.
    if (++lines <= vertexCount) velocities.push_back(v);
  }
  if (lines != vertexCount)
    throw InputError(path, "has " + std::to_string(lines) + " velocity lines, the input mesh has " +
                               std::to_string(vertexCount) + " vertices");
  return velocities;
}

VertexTransfer::VertexTransfer(const Mesh& input, const Mesh& target)
    : corners_(target.vertexCount()), weights_(target.vertexCount()), normals_(target.normals) {
  const SurfaceProjector projector(input);
  parallelForChunks(0, std::int64_t(target.vertexCount()), 1024, [&](std::int64_t begin, std::int64_t end) {
    for (std::size_t v = std::size_t(begin); v < std::size_t(end); ++v) {
      const SurfacePoint closest = projector.closestPoint(target.positions[v]);
      corners_[v] = input.triangles[std::size_t(closest.triangle)];
      weights_[v] = closest.barycentric;
    }
  });
}

std::vector<Vec3f> VertexTransfer::tangentVelocities(std::span<const Vec3f> inputVelocities) const {
  return perVertex(corners_.size(), [&](std::size_t v) {
    Vec3f velocity = Vec3f::Zero();
    for (int i = 0; i < 3; ++i) velocity += weights_[v][i] * inputVelocities[std::size_t(corners_[v][i])];
    return Vec3f(velocity - velocity.dot(normals_[v]) * normals_[v]);
  });
}

}  // namespace texsynth::flow_detail
