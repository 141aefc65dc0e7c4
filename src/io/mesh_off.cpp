// Geomview OFF reader: '[ST][C][N]OFF', then 'V F E' counts, V vertex lines
// 'x y z [nx ny nz] [r g b [a]] [s t]' and F face lines 'n i1 ... in [face color]'.
// '#' starts a comment anywhere; blank lines are skipped. Colors written as integers are
// 0..255, as decimals 0..1 (the Geomview convention).
#include <string>
#include <vector>

#include "mesh_parse_support.h"
#include "texsynth/core/error.h"
#include "texsynth/io/mesh_io.h"

namespace texsynth {
namespace {
using namespace mesh_detail;

// Smallest text a vertex ("0 0 0\n") and a face ("3 0 1 2\n") can occupy.
constexpr std::uint64_t kMinVertexBytes = 6;
constexpr std::uint64_t kMinFaceBytes = 8;

struct OffLayout {
  bool texcoords = false, colors = false, normals = false;
};

class OffParser {
 public:
  OffParser(std::string_view bytes, const std::string& source) : lines_(bytes), source_(source) {}

  Mesh parse() {
    std::string_view line;
    if (!nextContentLine(line)) fail("file has no OFF header");
    Tokens tokens(line);
    std::string_view keyword;
    tokens.next(keyword);
    OffLayout layout = parseKeyword(keyword);
    // Counts usually sit on the next line but may follow the keyword on the same line.
    if (tokens.atEnd()) {
      if (!nextContentLine(line)) fail("file ends before the vertex and face counts");
      tokens = Tokens(line);
    }
    std::int64_t vertexCount = readCount(tokens, "vertex count");
    std::int64_t faceCount = readCount(tokens, "face count");
    const std::string where = "line " + std::to_string(lines_.lineNumber()) + ": ";
    // Each count alone must fit in what follows (+1: the last line may lack its newline).
    // Checked separately so a short vertex line is reported where it is, not as a bad count.
    const std::uint64_t left = lines_.bytesLeft() + 1;
    requirePlausibleCount(std::uint64_t(vertexCount), kMinVertexBytes, left, "vertices", source_, where);
    requirePlausibleCount(std::uint64_t(faceCount), kMinFaceBytes, left, "faces", source_, where);

    mesh_.positions.reserve(std::size_t(vertexCount));
    if (layout.normals) mesh_.normals.reserve(std::size_t(vertexCount));
    if (layout.colors) mesh_.colors.reserve(std::size_t(vertexCount));
    for (std::int64_t i = 0; i < vertexCount; ++i) readVertex(layout, i, vertexCount);
    mesh_.triangles.reserve(std::size_t(faceCount));
    for (std::int64_t i = 0; i < faceCount; ++i) readFace(i, faceCount);
    return std::move(mesh_);
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const { failAtLine(source_, lines_.lineNumber(), problem); }

  // Finds the next line with something besides whitespace and comments (comment stripped);
  // false at the end of the file.
  bool nextContentLine(std::string_view& line) {
    while (lines_.next(line)) {
      line = line.substr(0, line.find('#'));
      if (!Tokens(line).atEnd()) return true;
    }
    return false;
  }

  // The next content line of a section that should hold `count` items, `index` read so far.
  Tokens nextItem(const char* items, std::int64_t index, std::int64_t count) {
    std::string_view line;
    if (!nextContentLine(line))
      fail("file ends after " + std::to_string(index) + " of " + std::to_string(count) + " " + items);
    return Tokens(line);
  }

  OffLayout parseKeyword(std::string_view keyword) {
    OffLayout layout;
    std::string_view rest = keyword;
    if (rest.starts_with("ST")) layout.texcoords = true, rest.remove_prefix(2);
    if (rest.starts_with("C")) layout.colors = true, rest.remove_prefix(1);
    if (rest.starts_with("N")) layout.normals = true, rest.remove_prefix(1);
    if (rest != "OFF") {
      if (keyword.ends_with("OFF")) fail("unsupported OFF variant " + quote(keyword) + " (4D and nOFF are not read)");
      fail("not an OFF file: expected 'OFF' but found " + quote(keyword));
    }
    return layout;
  }

  std::int64_t readCount(Tokens& tokens, const char* what) {
    std::string_view token;
    std::int64_t value;
    if (!tokens.next(token)) fail(std::string("missing ") + what);
    if (!parseNumber(token, value) || value < 0) fail(std::string("bad ") + what + " " + quote(token));
    return value;
  }

  float readFloat(Tokens& tokens, const char* what, std::string_view* tokenOut = nullptr) {
    std::string_view token;
    float value;
    if (!tokens.next(token)) fail(std::string("vertex line ends before its ") + what);
    if (!parseNumber(token, value)) fail(std::string("bad ") + what + " " + quote(token));
    if (tokenOut) *tokenOut = token;
    return value;
  }

  void readVertex(const OffLayout& layout, std::int64_t index, std::int64_t count) {
    Tokens tokens = nextItem("vertices", index, count);
    float x = readFloat(tokens, "x coordinate"), y = readFloat(tokens, "y coordinate");
    float z = readFloat(tokens, "z coordinate");
    mesh_.positions.emplace_back(x, y, z);
    if (layout.normals) {
      float nx = readFloat(tokens, "normal"), ny = readFloat(tokens, "normal"), nz = readFloat(tokens, "normal");
      mesh_.normals.emplace_back(nx, ny, nz);
    }
    if (layout.colors) {
      Vec3f color;
      bool allIntegers = true;
      for (int c = 0; c < 3; ++c) {
        std::string_view token;
        color[c] = readFloat(tokens, "color", &token);
        allIntegers = allIntegers && looksLikeInteger(token);
      }
      mesh_.colors.push_back(allIntegers ? Vec3f(color / 255.0f) : color);
    }
    // Alpha and texture coordinates, if any, are not kept.
  }

  void readFace(std::int64_t index, std::int64_t count) {
    Tokens tokens = nextItem("faces", index, count);
    std::int64_t corners = readCount(tokens, "face vertex count");
    if (corners < 3) fail("face has " + std::to_string(corners) + " vertices; at least 3 are needed");
    const std::int64_t defined = std::int64_t(mesh_.positions.size());
    polygon_.clear();  // grows only with indices actually present, so a huge count cannot over-allocate
    for (std::int64_t k = 0; k < corners; ++k) {
      std::string_view token;
      std::int64_t vertex;
      if (!tokens.next(token))
        fail("face lists " + std::to_string(k) + " of its " + std::to_string(corners) + " vertex indices");
      if (!parseNumber(token, vertex)) fail("bad vertex index " + quote(token));
      if (vertex < 0 || vertex >= defined)
        fail("face refers to vertex " + std::to_string(vertex) + " but only " + std::to_string(defined) +
             " vertices are defined");
      polygon_.push_back(int(vertex));
    }
    // The rest of the line may hold a face color, which is not kept.
    addPolygon(polygon_, mesh_.triangles);
  }

  TextLines lines_;
  const std::string& source_;
  Mesh mesh_;
  std::vector<int> polygon_;
};

}  // namespace

Mesh parseOff(std::string_view bytes, const std::string& source) {
  if (bytes.empty()) throw InputError(source, "file is empty");
  return OffParser(bytes, source).parse();
}

}  // namespace texsynth
