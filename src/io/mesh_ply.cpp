// PLY reader (ascii, binary little and big endian). Keeps vertex x,y,z, optional nx,ny,nz,
// red,green,blue (integer colors scaled by their type's range, float colors taken as 0..1) and
// texture coordinates (u,v or s,t or texture_u,texture_v or texture_s,texture_t: attribute "uv"),
// every other scalar vertex property as a one-component attribute of its name, and the face list
// 'vertex_indices' (or 'vertex_index'), fan-triangulated. Every other element and property is read
// past according to its declared type.
#include <array>
#include <vector>

#include "mesh_ply_header.h"
#include "mesh_ply_sources.h"
#include "texsynth/io/mesh_io.h"

namespace texsynth {
namespace {
using namespace mesh_detail;

// What a vertex property feeds.
enum class Role { Ignore, X, Y, Z, NX, NY, NZ, Red, Green, Blue, U, V, Attribute };
constexpr std::size_t kFixedRoles = 12;  // the roles before Attribute: one value each per vertex

Role roleOf(std::string_view name) {
  static constexpr std::pair<std::string_view, Role> kRoles[] = {{"x", Role::X},
                                                                 {"y", Role::Y},
                                                                 {"z", Role::Z},
                                                                 {"nx", Role::NX},
                                                                 {"ny", Role::NY},
                                                                 {"nz", Role::NZ},
                                                                 {"red", Role::Red},
                                                                 {"green", Role::Green},
                                                                 {"blue", Role::Blue},
                                                                 {"diffuse_red", Role::Red},
                                                                 {"diffuse_green", Role::Green},
                                                                 {"diffuse_blue", Role::Blue}};
  for (const auto& [roleName, role] : kRoles)
    if (roleName == name) return role;
  return Role::Attribute;
}

// The texture coordinate pair of a vertex element: the first of the usual spellings whose both
// properties it has (indices into its properties), or {-1, -1}.
std::pair<int, int> uvProperties(const PlyElement& element) {
  static constexpr std::pair<std::string_view, std::string_view> kPairs[] = {
      {"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}};
  for (const auto& [u, v] : kPairs) {
    const int iu = element.find(u), iv = element.find(v);
    if (iu >= 0 && iv >= 0) return {iu, iv};
  }
  return {-1, -1};
}

float colorScale(PlyType type) {
  switch (type) {
    case PlyType::Float32:
    case PlyType::Float64:
      return 1.0f;
    case PlyType::Int16:
    case PlyType::UInt16:
      return 1.0f / 65535.0f;
    default:
      return 1.0f / 255.0f;
  }
}

template <class Source>
class PlyBodyReader {
 public:
  PlyBodyReader(const PlyHeader& header, Source& in, const std::string& source)
      : header_(header), in_(in), source_(source) {}

  Mesh read() {
    const PlyElement* vertices = nullptr;
    for (const PlyElement& element : header_.elements)
      if (element.name == "vertex") {
        if (vertices) failAtLine(source_, element.line, "a second 'vertex' element");
        vertices = &element;
      }
    if (!vertices) throw InputError(source_, "header declares no 'vertex' element");
    vertexCount_ = vertices->count;  // known from the header, so faces may come first
    for (const PlyElement& element : header_.elements) {
      if (element.name == "vertex")
        readVertices(element);
      else if (element.name == "face")
        readFaces(element);
      else
        skipElement(element);
    }
    return std::move(mesh_);
  }

 private:
  void skipList(const PlyProperty& property) {
    std::int64_t count = in_.integer(property.countType);
    if (count < 0) in_.fail("negative list length in " + in_.position.describe());
    for (std::int64_t k = 0; k < count; ++k) in_.value(property.type);
  }

  void readVertices(const PlyElement& element) {
    std::vector<Role> roles;
    std::array<bool, kFixedRoles> present{};
    const auto [uIndex, vIndex] = uvProperties(element);
    for (const PlyProperty& property : element.properties) {
      const int index = int(roles.size());
      Role role = index == uIndex ? Role::U : index == vIndex ? Role::V : roleOf(property.name);
      if (role == Role::Attribute && property.isList) role = Role::Ignore;  // lists are read past
      if (role != Role::Ignore && property.isList)
        failAtLine(source_, element.line, "vertex property '" + property.name + "' is a list");
      roles.push_back(role);
      if (role != Role::Attribute) present[std::size_t(role)] = true;
    }
    auto has = [&](Role r) { return present[std::size_t(r)]; };
    if (!has(Role::X) || !has(Role::Y) || !has(Role::Z))
      failAtLine(source_, element.line, "vertex element lacks an x, y or z property");
    const bool normals = has(Role::NX) && has(Role::NY) && has(Role::NZ);
    const bool colors = has(Role::Red) && has(Role::Green) && has(Role::Blue);

    const std::size_t n = std::size_t(element.count);
    mesh_.positions.resize(n);
    if (normals) mesh_.normals.resize(n);
    if (colors) mesh_.colors.resize(n);
    std::vector<float>* uv = nullptr;
    if (has(Role::U)) {
      VertexAttribute& attribute = mesh_.attributes[kUvAttribute];
      attribute = {2, std::vector<float>(2 * n)};
      uv = &attribute.values;
    }
    std::vector<std::vector<float>*> attributeValues(roles.size(), nullptr);  // per property
    for (std::size_t p = 0; p < roles.size(); ++p)
      if (roles[p] == Role::Attribute) {
        VertexAttribute& attribute = mesh_.attributes[element.properties[p].name];
        attribute = {1, std::vector<float>(n)};
        attributeValues[p] = &attribute.values;
      }
    in_.position.element = &element;
    for (std::size_t i = 0; i < n; ++i) {
      in_.position.item = i;
      float values[kFixedRoles] = {};
      for (std::size_t p = 0; p < roles.size(); ++p) {
        const PlyProperty& property = element.properties[p];
        if (property.isList) {
          skipList(property);
          continue;
        }
        float v = float(in_.value(property.type));
        if (roles[p] == Role::Attribute) {
          (*attributeValues[p])[i] = v;
          continue;
        }
        if (roles[p] >= Role::Red && roles[p] <= Role::Blue) v *= colorScale(property.type);
        values[std::size_t(roles[p])] = v;
      }
      auto at = [&](Role r) { return values[std::size_t(r)]; };
      mesh_.positions[i] = Vec3f(at(Role::X), at(Role::Y), at(Role::Z));
      if (normals) mesh_.normals[i] = Vec3f(at(Role::NX), at(Role::NY), at(Role::NZ));
      if (colors) mesh_.colors[i] = Vec3f(at(Role::Red), at(Role::Green), at(Role::Blue));
      if (uv) (*uv)[2 * i] = at(Role::U), (*uv)[2 * i + 1] = at(Role::V);
    }
  }

  void readFaces(const PlyElement& element) {
    int indexList = element.find("vertex_indices");
    if (indexList < 0) indexList = element.find("vertex_index");
    if (element.count == 0) return;
    if (indexList < 0 || !element.properties[std::size_t(indexList)].isList)
      failAtLine(source_, element.line, "face element has no 'vertex_indices' list");
    mesh_.triangles.reserve(mesh_.triangles.size() + std::size_t(element.count));
    in_.position.element = &element;
    std::vector<int> polygon;
    for (std::uint64_t i = 0; i < element.count; ++i) {
      in_.position.item = i;
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const PlyProperty& property = element.properties[p];
        if (int(p) != indexList) {
          if (property.isList)
            skipList(property);
          else
            in_.value(property.type);
          continue;
        }
        readPolygon(property, polygon);
      }
      addPolygon(polygon, mesh_.triangles);
    }
  }

  void readPolygon(const PlyProperty& property, std::vector<int>& polygon) {
    std::int64_t count = in_.integer(property.countType);
    if (count < 3)
      in_.fail(in_.position.describe() + " has " + std::to_string(count) + " vertices; at least 3 are needed");
    polygon.clear();  // grows only as indices are actually read, so a huge count cannot over-allocate
    for (std::int64_t k = 0; k < count; ++k) {
      std::int64_t index = in_.integer(property.type);
      if (index < 0 || std::uint64_t(index) >= vertexCount_)
        in_.fail(in_.position.describe() + " refers to vertex " + std::to_string(index) + " but only " +
                 std::to_string(vertexCount_) + " vertices are defined");
      polygon.push_back(int(index));
    }
  }

  void skipElement(const PlyElement& element) {
    if (element.properties.empty()) return;
    in_.position.element = &element;
    bool fixedSize = true;
    for (const PlyProperty& property : element.properties) fixedSize = fixedSize && !property.isList;
    if (Source::kBinary && fixedSize) {
      in_.position.item = 0;
      in_.skipBytes(element.count * element.minBytesPerItem(header_.format));
      return;
    }
    for (std::uint64_t i = 0; i < element.count; ++i) {
      in_.position.item = i;
      for (const PlyProperty& property : element.properties)
        if (property.isList)
          skipList(property);
        else
          in_.value(property.type);
    }
  }

  const PlyHeader& header_;
  Source& in_;
  const std::string& source_;
  Mesh mesh_;
  std::uint64_t vertexCount_ = 0;
};

template <class Source>
Mesh readBody(std::string_view bytes, const PlyHeader& header, const std::string& sourceName) {
  Source in(bytes, header, sourceName);
  return PlyBodyReader<Source>(header, in, sourceName).read();
}

}  // namespace

Mesh parsePly(std::string_view bytes, const std::string& source) {
  if (bytes.empty()) throw InputError(source, "file is empty");
  PlyHeader header = parsePlyHeader(bytes, source);
  if (header.format == PlyFormat::Ascii) return readBody<AsciiPlySource>(bytes, header, source);
  return readBody<BinaryPlySource>(bytes, header, source);
}

}  // namespace texsynth
