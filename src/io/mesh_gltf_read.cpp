// glTF 2.0 reader through tinygltf (.glb, or .gltf with embedded or neighbouring buffers): the
// triangle primitives of the default scene's meshes, placed by their nodes' transforms, with
// POSITION, NORMAL and COLOR_0 (vec3 or vec4: float, or normalized unsigned byte / short). Each
// primitive's vertices stay its own (glTF splits vertices at material and attribute seams; what
// texsynth writes is one welded primitive).
#include <tiny_gltf.h>

#include <Eigen/Geometry>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>

#include "texsynth/core/color.h"
#include "texsynth/core/error.h"
#include "texsynth/io/mesh_io.h"

namespace texsynth {
namespace {

// Loading only meshes: images are neither decoded nor required.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

class AccessorReader {
 public:
  AccessorReader(const tinygltf::Model& model, int index, const std::string& source, const std::string& what)
      : source_(source), what_(what) {
    if (index < 0 || std::size_t(index) >= model.accessors.size()) fail("refers to a missing accessor");
    accessor_ = &model.accessors[std::size_t(index)];
    if (accessor_->sparse.isSparse) fail("uses a sparse accessor, which texsynth does not read");
    if (accessor_->bufferView < 0 || std::size_t(accessor_->bufferView) >= model.bufferViews.size())
      fail("has no buffer view");
    const tinygltf::BufferView& view = model.bufferViews[std::size_t(accessor_->bufferView)];
    if (view.buffer < 0 || std::size_t(view.buffer) >= model.buffers.size()) fail("has no buffer");
    const std::vector<unsigned char>& buffer = model.buffers[std::size_t(view.buffer)].data;
    components_ = tinygltf::GetNumComponentsInType(std::uint32_t(accessor_->type));
    componentBytes_ = tinygltf::GetComponentSizeInBytes(std::uint32_t(accessor_->componentType));
    if (components_ <= 0 || componentBytes_ <= 0) fail("has an unknown accessor type");
    const std::size_t element = std::size_t(components_) * std::size_t(componentBytes_);
    stride_ = view.byteStride ? view.byteStride : element;
    const std::size_t count = accessor_->count;
    const std::size_t begin = view.byteOffset + accessor_->byteOffset;
    if (stride_ < element || view.byteOffset + view.byteLength > buffer.size() ||
        (count > 0 && begin + (count - 1) * stride_ + element > view.byteOffset + view.byteLength))
      fail("has an accessor past the end of its buffer");
    data_ = buffer.data() + begin;
  }

  std::size_t count() const { return accessor_->count; }
  int components() const { return components_; }
  int componentType() const { return accessor_->componentType; }

  // Component c of element i as a float (normalized integers mapped to [0, 1]).
  float value(std::size_t i, int c) const {
    const unsigned char* p = data_ + i * stride_ + std::size_t(c) * std::size_t(componentBytes_);
    switch (accessor_->componentType) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float v;
        std::memcpy(&v, p, sizeof v);
        return v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return accessor_->normalized ? float(*p) / 255.0f : float(*p);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p, sizeof v);
        return accessor_->normalized ? float(v) / 65535.0f : float(v);
      }
      default:
        fail("has an attribute of an unsupported component type");
    }
  }
  // Element i as an index (unsigned byte, short or int).
  std::uint32_t index(std::size_t i) const {
    const unsigned char* p = data_ + i * stride_;
    switch (accessor_->componentType) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return *p;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p, sizeof v);
        return v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        std::uint32_t v;
        std::memcpy(&v, p, sizeof v);
        return v;
      }
      default:
        fail("has indices of a non-integer type");
    }
  }

  [[noreturn]] void fail(const std::string& problem) const { throw InputError(source_, what_ + " " + problem); }

 private:
  const tinygltf::Accessor* accessor_ = nullptr;
  const unsigned char* data_ = nullptr;
  std::size_t stride_ = 0;
  int components_ = 0, componentBytes_ = 0;
  std::string source_, what_;
};

// A node's local transform: its matrix, else translation * rotation * scale.
Eigen::Affine3d localTransform(const tinygltf::Node& node) {
  Eigen::Affine3d transform = Eigen::Affine3d::Identity();
  if (node.matrix.size() == 16) {
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 3; ++r) transform.matrix()(r, c) = node.matrix[std::size_t(4 * c + r)];  // column-major
    return transform;
  }
  if (node.translation.size() == 3)
    transform.translate(Eigen::Vector3d(node.translation[0], node.translation[1], node.translation[2]));
  if (node.rotation.size() == 4)  // x, y, z, w
    transform.rotate(Eigen::Quaterniond(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
  if (node.scale.size() == 3) transform.scale(Eigen::Vector3d(node.scale[0], node.scale[1], node.scale[2]));
  return transform;
}

struct Collected {
  Mesh mesh;
  bool allNormals = true, anyColors = false;  // primitives without colors are white
};

void addPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive, const Eigen::Affine3d& transform,
                  const std::string& source, Collected& out) {
  if (primitive.mode != -1 && primitive.mode != TINYGLTF_MODE_TRIANGLES) return;  // points, lines, strips
  const auto position = primitive.attributes.find("POSITION");
  if (position == primitive.attributes.end()) throw InputError(source, "a mesh primitive has no POSITION attribute");
  const AccessorReader positions(model, position->second, source, "POSITION");
  if (positions.components() != 3 || positions.componentType() != TINYGLTF_COMPONENT_TYPE_FLOAT)
    positions.fail("is not a float vec3");
  const std::size_t base = out.mesh.positions.size(), count = positions.count();
  if (base + count > std::size_t(std::numeric_limits<int>::max())) throw InputError(source, "has too many vertices");
  for (std::size_t i = 0; i < count; ++i) {
    const Eigen::Vector3d p =
        transform * Eigen::Vector3d(positions.value(i, 0), positions.value(i, 1), positions.value(i, 2));
    out.mesh.positions.push_back(p.cast<float>());
  }
  const auto normal = primitive.attributes.find("NORMAL");
  if (normal != primitive.attributes.end() && out.allNormals) {
    const AccessorReader normals(model, normal->second, source, "NORMAL");
    if (normals.count() != count || normals.components() != 3) normals.fail("does not have one vec3 per vertex");
    const bool turned = !transform.linear().isIdentity(0);  // an untransformed file reads back exactly
    const Eigen::Matrix3d normalMatrix = transform.linear().inverse().transpose();
    for (std::size_t i = 0; i < count; ++i) {
      const Vec3f n(normals.value(i, 0), normals.value(i, 1), normals.value(i, 2));
      out.mesh.normals.push_back(turned ? (normalMatrix * n.cast<double>()).normalized().cast<float>() : n);
    }
  } else {
    out.allNormals = false;
  }
  const auto color = primitive.attributes.find("COLOR_0");
  out.mesh.colors.resize(base + count, Vec3f::Ones());
  if (color != primitive.attributes.end()) {
    out.anyColors = true;
    const AccessorReader colors(model, color->second, source, "COLOR_0");
    if (colors.count() != count || (colors.components() != 3 && colors.components() != 4))
      colors.fail("does not have one vec3 or vec4 per vertex");
    // glTF colours are linear; texsynth's are sRGB-encoded like its images.
    for (std::size_t i = 0; i < count; ++i)
      out.mesh.colors[base + i] =
          Vec3f(linearToSrgb(float(colors.value(i, 0))), linearToSrgb(float(colors.value(i, 1))),
                linearToSrgb(float(colors.value(i, 2))));
  }
  std::vector<std::uint32_t> indices;
  if (primitive.indices >= 0) {
    const AccessorReader reader(model, primitive.indices, source, "indices");
    if (reader.components() != 1) reader.fail("are not scalars");
    for (std::size_t i = 0; i < reader.count(); ++i) indices.push_back(reader.index(i));
  } else {
    for (std::size_t i = 0; i < count; ++i) indices.push_back(std::uint32_t(i));
  }
  for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
    if (indices[i] >= count || indices[i + 1] >= count || indices[i + 2] >= count)
      throw InputError(source, "a triangle index is past its primitive's " + std::to_string(count) + " vertices");
    const Vec3i t(int(base + indices[i]), int(base + indices[i + 1]), int(base + indices[i + 2]));
    if (t[0] != t[1] && t[1] != t[2] && t[2] != t[0]) out.mesh.triangles.push_back(t);  // drop degenerate
  }
}

}  // namespace

Mesh parseGltf(std::string_view bytes, const std::string& source) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(skipImage, nullptr);
  tinygltf::Model model;
  std::string error, warning;
  const std::string directory = std::filesystem::absolute(std::filesystem::path(source)).parent_path().string();
  const bool binary = bytes.size() >= 4 && bytes.substr(0, 4) == "glTF";
  const bool loaded =
      binary
          ? loader.LoadBinaryFromMemory(&model, &error, &warning, reinterpret_cast<const unsigned char*>(bytes.data()),
                                        unsigned(std::min<std::size_t>(bytes.size(), 0xffffffffu)), directory)
          : loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(),
                                       unsigned(std::min<std::size_t>(bytes.size(), 0xffffffffu)), directory);
  if (!loaded) {
    std::string first = error.substr(0, error.find('\n'));
    // tinygltf passes on nlohmann's messages: the reason, without the library's tag.
    if (const std::size_t tag = first.find("[json.exception."); tag != std::string::npos)
      first.erase(tag, first.find("] ", tag) + 2 - tag);
    throw InputError(source, "is not a readable glTF file" + (first.empty() ? std::string() : ": " + first));
  }

  Collected collected;
  std::vector<int> visiting;  // guards against cycles in a malformed node graph
  std::function<void(int, const Eigen::Affine3d&)> visit = [&](int n, const Eigen::Affine3d& parent) {
    if (n < 0 || std::size_t(n) >= model.nodes.size()) throw InputError(source, "refers to a missing node");
    if (std::find(visiting.begin(), visiting.end(), n) != visiting.end())
      throw InputError(source, "has a cycle in its node hierarchy");
    visiting.push_back(n);
    const tinygltf::Node& node = model.nodes[std::size_t(n)];
    const Eigen::Affine3d transform = parent * localTransform(node);
    if (node.mesh >= 0) {
      if (std::size_t(node.mesh) >= model.meshes.size()) throw InputError(source, "refers to a missing mesh");
      for (const tinygltf::Primitive& p : model.meshes[std::size_t(node.mesh)].primitives)
        addPrimitive(model, p, transform, source, collected);
    }
    for (int child : node.children) visit(child, transform);
    visiting.pop_back();
  };
  if (!model.scenes.empty()) {
    const int scene =
        model.defaultScene >= 0 && std::size_t(model.defaultScene) < model.scenes.size() ? model.defaultScene : 0;
    for (int n : model.scenes[std::size_t(scene)].nodes) visit(n, Eigen::Affine3d::Identity());
  } else {  // no scene: every mesh once, untransformed
    for (const tinygltf::Mesh& m : model.meshes)
      for (const tinygltf::Primitive& p : m.primitives)
        addPrimitive(model, p, Eigen::Affine3d::Identity(), source, collected);
  }
  Mesh mesh = std::move(collected.mesh);
  if (mesh.triangles.empty()) throw InputError(source, "has no triangles");
  if (!collected.allNormals) mesh.normals.clear();
  if (!collected.anyColors) mesh.colors.clear();
  return mesh;
}

}  // namespace texsynth
