// Wavefront OBJ reader: 'v x y z [w]' or 'v x y z r g b' vertices, 'vt u [v [w]]' texture
// coordinates and 'f' polygons whose corners are v, v/vt, v//vn or v/vt/vn (negative = relative
// to the elements so far). When every corner has a valid vt, they become the per-vertex attribute "uv":
// a vertex whose corners have different coordinates (a UV seam) is split into one copy per
// coordinate, the copies after the first appended at the end. Normals are computed per vertex
// before the split (OBJ normals are per corner), so shading stays smooth across UV seams; groups
// and materials are ignored.
#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "mesh_parse_support.h"
#include "texsynth/core/error.h"
#include "texsynth/io/mesh_io.h"

namespace texsynth {
namespace {
using namespace mesh_detail;

class ObjParser {
 public:
  ObjParser(std::string_view bytes, const std::string& source) : lines_(bytes), source_(source) {}

  Mesh parse() {
    std::string_view line, keyword;
    while (lines_.next(line)) {
      Tokens tokens(line);
      if (!tokens.next(keyword) || keyword[0] == '#') continue;
      if (keyword == "v") {
        readVertex(tokens);
      } else if (keyword == "vt") {
        readTextureCoordinate(tokens);
      } else if (keyword == "f") {
        readFace(tokens);
      }
      // Everything else (vn, g, o, s, usemtl, mtllib, l, p ...) carries nothing we keep.
    }
    if (!hasColors_) mesh_.colors.clear();
    if (!uvs_.empty() && !uvsBroken_ && !mesh_.triangles.empty()) splitAtUvSeams();
    return std::move(mesh_);
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const { failAtLine(source_, lines_.lineNumber(), problem); }

  void readVertex(Tokens& tokens) {
    float values[7];
    int count = 0;
    std::string_view token;
    while (tokens.next(token)) {
      if (count == 7) fail("vertex has more than 7 numbers");
      if (!parseNumber(token, values[count])) fail("bad vertex coordinate " + quote(token));
      ++count;
    }
    if (count != 3 && count != 4 && count != 6)
      fail("vertex has " + std::to_string(count) + " numbers; expected x y z [w] or x y z r g b");
    bool colored = count == 6;
    if (mesh_.positions.empty()) hasColors_ = colored;
    if (colored != hasColors_)
      fail(colored ? "vertex has a color but earlier vertices have none" : "vertex has no color but earlier ones do");
    mesh_.positions.emplace_back(values[0], values[1], values[2]);
    if (colored) mesh_.colors.emplace_back(values[3], values[4], values[5]);
  }

  // Texture coordinates are optional data: a malformed 'vt' line or reference drops them all (the
  // mesh still loads, as before they were read), it does not reject the file.
  void readTextureCoordinate(Tokens& tokens) {
    float values[3] = {0, 0, 0};
    int count = 0;
    std::string_view token;
    while (tokens.next(token)) {
      if (count == 3 || !parseNumber(token, values[count]) || !std::isfinite(values[count])) uvsBroken_ = true;
      if (count < 3) ++count;
    }
    if (count == 0) uvsBroken_ = true;
    uvs_.emplace_back(values[0], values[1]);
  }

  // The 0-based index of a 1-based (or negative: relative) OBJ reference to one of `defined`
  // elements, or -1 if it is not a valid one.
  static std::int64_t resolve(std::string_view text, std::int64_t defined) {
    std::int64_t index;
    if (!parseNumber(text, index) || index == 0) return -1;
    std::int64_t zeroBased = index > 0 ? index - 1 : defined + index;
    return zeroBased >= 0 && zeroBased < defined ? zeroBased : -1;
  }

  void readFace(Tokens& tokens) {
    polygon_.clear();
    polygonUvs_.clear();
    std::string_view corner;
    const std::int64_t defined = std::int64_t(mesh_.positions.size());
    while (tokens.next(corner)) {
      const std::size_t slash = corner.find('/');
      std::string_view vertexPart = corner.substr(0, slash);
      std::int64_t index;
      if (!parseNumber(vertexPart, index)) fail("bad face index " + quote(corner));
      if (index == 0) fail("face refers to vertex 0, but OBJ indices start at 1");
      std::int64_t zeroBased = resolve(vertexPart, defined);
      if (zeroBased < 0)
        fail("face refers to vertex " + std::to_string(index) + " but only " + std::to_string(defined) +
             " vertices are defined");
      polygon_.push_back(int(zeroBased));
      std::string_view uvPart;  // between the first and the second slash
      if (slash != std::string_view::npos)
        uvPart = corner.substr(slash + 1), uvPart = uvPart.substr(0, uvPart.find('/'));
      const std::int64_t uv = uvPart.empty() ? -1 : resolve(uvPart, std::int64_t(uvs_.size()));
      if (uv < 0) uvsBroken_ = true;  // a corner without one (or with a bad one): no UVs for the mesh
      polygonUvs_.push_back(int(uv));
    }
    if (polygon_.size() < 3) fail("face has " + std::to_string(polygon_.size()) + " vertices; at least 3 are needed");
    addPolygon(polygon_, mesh_.triangles);
    addPolygon(polygon_, polygonUvs_, cornerUvs_);  // the same fan over the corners' texture coordinates
  }

  // Gives every corner's texture coordinate to its vertex, splitting vertices on UV seams.
  void splitAtUvSeams() {
    mesh_.computeNormals();  // before the split: one normal per position
    const std::size_t n = mesh_.positions.size();
    std::vector<std::pair<float, float>> uvOf(n, {0.0f, 0.0f});  // unused vertices keep (0, 0)
    std::vector<bool> assigned(n, false);
    std::map<std::tuple<int, float, float>, int> copyOf;  // (vertex, u, v) -> the copy that has them
    for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) {
      for (int k = 0; k < 3; ++k) {
        const int v = mesh_.triangles[t][k];
        const std::pair<float, float> uv = uvs_[std::size_t(cornerUvs_[t][k])];
        if (!assigned[std::size_t(v)]) {
          assigned[std::size_t(v)] = true;
          uvOf[std::size_t(v)] = uv;
        }
        if (uvOf[std::size_t(v)] == uv) continue;
        auto [at, added] = copyOf.try_emplace({v, uv.first, uv.second}, int(mesh_.positions.size()));
        if (added) {
          mesh_.positions.push_back(mesh_.positions[std::size_t(v)]);
          mesh_.normals.push_back(mesh_.normals[std::size_t(v)]);
          if (!mesh_.colors.empty()) mesh_.colors.push_back(mesh_.colors[std::size_t(v)]);
          uvOf.push_back(uv);
        }
        mesh_.triangles[t][k] = at->second;
      }
    }
    VertexAttribute& attribute = mesh_.attributes[kUvAttribute];
    attribute.components = 2;
    attribute.values.resize(2 * uvOf.size());
    for (std::size_t v = 0; v < uvOf.size(); ++v)
      attribute.values[2 * v] = uvOf[v].first, attribute.values[2 * v + 1] = uvOf[v].second;
  }

  TextLines lines_;
  const std::string& source_;
  Mesh mesh_;
  bool hasColors_ = false;
  std::vector<int> polygon_, polygonUvs_;
  std::vector<std::pair<float, float>> uvs_;  // the 'vt' lines
  std::vector<Vec3i> cornerUvs_;              // per triangle: its corners' vt (-1: none)
  bool uvsBroken_ = false;
};

}  // namespace

Mesh parseObj(std::string_view bytes, const std::string& source) {
  if (bytes.empty()) throw InputError(source, "file is empty");
  return ObjParser(bytes, source).parse();
}

}  // namespace texsynth
