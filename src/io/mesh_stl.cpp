// STL reader, ascii and binary. STL stores each triangle with its own three corners; equal
// corner positions are merged so the result is an indexed mesh (normals are recomputed).
// A file is binary when its size matches the triangle count in its header exactly, ascii when
// it starts with "solid", and otherwise treated as (probably truncated) binary.
#include <bit>
#include <cstring>
#include <unordered_map>
#include <vector>

#include "mesh_parse_support.h"
#include "texsynth/core/error.h"
#include "texsynth/io/mesh_io.h"

namespace texsynth {
namespace {
using namespace mesh_detail;

constexpr std::size_t kBinaryHeaderBytes = 84;    // 80-byte comment + uint32 triangle count
constexpr std::size_t kBinaryTriangleBytes = 50;  // normal, 3 corners (12 floats) + uint16 attribute

// Gives each distinct position one index. Keys are bit patterns, with -0 folded into +0.
class VertexMerger {
 public:
  explicit VertexMerger(Mesh& mesh) : mesh_(mesh) {}
  int indexOf(const Vec3f& p) {
    Key key{};
    for (int k = 0; k < 3; ++k) key.bits[k] = std::bit_cast<std::uint32_t>(p[k] + 0.0f);
    auto [it, inserted] = indices_.try_emplace(key, int(mesh_.positions.size()));
    if (inserted) mesh_.positions.push_back(p);
    return it->second;
  }

 private:
  struct Key {
    std::uint32_t bits[3];
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = k.bits[0] * 0x9E3779B97F4A7C15ull;
      h ^= (h >> 29) + k.bits[1] * 0xBF58476D1CE4E5B9ull;
      h ^= (h >> 31) + k.bits[2] * 0x94D049BB133111EBull;
      return std::size_t(h ^ (h >> 32));
    }
  };
  Mesh& mesh_;
  std::unordered_map<Key, int, KeyHash> indices_;
};

std::uint32_t loadLittleU32(const char* p) {
  unsigned char b[4];
  std::memcpy(b, p, 4);
  return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
}

float loadLittleFloat(const char* p) {
  return std::bit_cast<float>(loadLittleU32(p));
}

bool looksBinary(std::string_view bytes) {
  if (bytes.size() >= kBinaryHeaderBytes) {
    std::uint64_t count = loadLittleU32(bytes.data() + 80);
    if (kBinaryHeaderBytes + count * kBinaryTriangleBytes == bytes.size()) return true;
  }
  std::string_view start = bytes.substr(0, 5);
  return start != "solid";
}

Mesh parseBinaryStl(std::string_view bytes, const std::string& source) {
  if (bytes.size() < kBinaryHeaderBytes)
    throw InputError(
        source, "binary STL needs an 84-byte header but the file has only " + std::to_string(bytes.size()) + " bytes");
  std::uint64_t count = loadLittleU32(bytes.data() + 80);
  requirePlausibleCount(count, kBinaryTriangleBytes, bytes.size() - kBinaryHeaderBytes, "triangles", source, "header ");
  Mesh mesh;
  VertexMerger merger(mesh);
  mesh.triangles.reserve(std::size_t(count));
  int corners[3];
  for (std::uint64_t t = 0; t < count; ++t) {
    const char* record = bytes.data() + kBinaryHeaderBytes + t * kBinaryTriangleBytes;
    for (int c = 0; c < 3; ++c) {
      const char* p = record + 12 + 12 * c;  // skip the stored face normal
      corners[c] = merger.indexOf(Vec3f(loadLittleFloat(p), loadLittleFloat(p + 4), loadLittleFloat(p + 8)));
    }
    addPolygon(corners, mesh.triangles);
  }
  return mesh;
}

Mesh parseAsciiStl(std::string_view bytes, const std::string& source) {
  Mesh mesh;
  VertexMerger merger(mesh);
  TextLines lines(bytes);
  std::string_view line, keyword, token;
  std::vector<int> loop;
  bool inLoop = false, ended = false;
  auto fail = [&](const std::string& problem) { failAtLine(source, lines.lineNumber(), problem); };
  while (lines.next(line)) {
    Tokens tokens(line);
    if (!tokens.next(keyword)) continue;
    if (keyword == "vertex") {
      if (!inLoop) fail("'vertex' outside an 'outer loop'");
      float xyz[3];
      for (float& v : xyz)
        if (!tokens.next(token) || !parseNumber(token, v)) fail("vertex needs three numbers");
      loop.push_back(merger.indexOf(Vec3f(xyz[0], xyz[1], xyz[2])));
    } else if (keyword == "outer") {
      if (inLoop) fail("'outer loop' inside another loop");
      inLoop = true;
      loop.clear();
    } else if (keyword == "endloop") {
      if (!inLoop) fail("'endloop' without 'outer loop'");
      if (loop.size() < 3) fail("facet has " + std::to_string(loop.size()) + " vertices; at least 3 are needed");
      addPolygon(loop, mesh.triangles);
      inLoop = false;
    } else if (keyword == "endsolid") {
      ended = true;
    } else if (keyword != "solid" && keyword != "facet" && keyword != "endfacet") {
      fail("unexpected " + quote(keyword) + " in ascii STL");
    }
  }
  if (inLoop) fail("file ends inside a facet");
  // Ascii STL has no counts: a missing 'endsolid' is the only sign of a cut-off file.
  if (!ended) fail("file ends without 'endsolid' (truncated?)");
  return mesh;
}

}  // namespace

Mesh parseStl(std::string_view bytes, const std::string& source) {
  if (bytes.empty()) throw InputError(source, "file is empty");
  return looksBinary(bytes) ? parseBinaryStl(bytes, source) : parseAsciiStl(bytes, source);
}

}  // namespace texsynth
