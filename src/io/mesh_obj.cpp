// Wavefront OBJ reader: 'v x y z [w]' or 'v x y z r g b' vertices and 'f' polygons whose
// corners are v, v/vt, v//vn or v/vt/vn (negative = relative to the vertices so far).
// Texture coordinates, normals, groups and materials are ignored: normals are recomputed
// per vertex because OBJ normals are indexed per corner, not per vertex.
#include <string>
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
      } else if (keyword == "f") {
        readFace(tokens);
      }
      // Everything else (vt, vn, g, o, s, usemtl, mtllib, l, p ...) carries nothing we keep.
    }
    if (!hasColors_) mesh_.colors.clear();
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

  void readFace(Tokens& tokens) {
    polygon_.clear();
    std::string_view corner;
    const std::int64_t defined = std::int64_t(mesh_.positions.size());
    while (tokens.next(corner)) {
      std::string_view vertexPart = corner.substr(0, corner.find('/'));
      std::int64_t index;
      if (!parseNumber(vertexPart, index)) fail("bad face index " + quote(corner));
      if (index == 0) fail("face refers to vertex 0, but OBJ indices start at 1");
      std::int64_t zeroBased = index > 0 ? index - 1 : defined + index;
      if (zeroBased < 0 || zeroBased >= defined)
        fail("face refers to vertex " + std::to_string(index) + " but only " + std::to_string(defined) +
             " vertices are defined");
      polygon_.push_back(int(zeroBased));
    }
    if (polygon_.size() < 3) fail("face has " + std::to_string(polygon_.size()) + " vertices; at least 3 are needed");
    addPolygon(polygon_, mesh_.triangles);
  }

  TextLines lines_;
  const std::string& source_;
  Mesh mesh_;
  bool hasColors_ = false;
  std::vector<int> polygon_;
};

}  // namespace

Mesh parseObj(std::string_view bytes, const std::string& source) {
  if (bytes.empty()) throw InputError(source, "file is empty");
  return ObjParser(bytes, source).parse();
}

}  // namespace texsynth
