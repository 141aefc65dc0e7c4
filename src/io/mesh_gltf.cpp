// glTF 2.0 writer through tinygltf: one buffer holding POSITION, NORMAL, COLOR_0 (float vec3, linear),
// TEXCOORD_0 (float vec2, from the "uv" attribute with v flipped: glTF's origin is the top left)
// and uint32 indices, one triangle primitive, and a material whose white base color lets the
// vertex colors show unchanged (non-metallic, fully rough, so viewers do not darken it).
#include <tiny_gltf.h>

#include <algorithm>
#include <sstream>

#include "mesh_write_support.h"
#include "texsynth/core/color.h"
#include "texsynth/core/error.h"
#include "texsynth/io/mesh_io.h"

namespace texsynth {
namespace {

// Appends raw bytes to the buffer as a new buffer view; returns the view's index.
int addBufferView(tinygltf::Model& model, const void* data, std::size_t bytes, int target) {
  std::vector<unsigned char>& buffer = model.buffers[0].data;
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = buffer.size();
  view.byteLength = bytes;
  view.target = target;
  const auto* begin = static_cast<const unsigned char*>(data);
  buffer.insert(buffer.end(), begin, begin + bytes);
  model.bufferViews.push_back(view);
  return int(model.bufferViews.size()) - 1;
}

// A float vec3 vertex attribute; returns the accessor index.
int addVec3Attribute(tinygltf::Model& model, const std::vector<Vec3f>& values, bool withBounds) {
  static_assert(sizeof(Vec3f) == 3 * sizeof(float), "Vec3f must be tightly packed");
  tinygltf::Accessor accessor;
  accessor.bufferView =
      addBufferView(model, values.data(), values.size() * sizeof(Vec3f), TINYGLTF_TARGET_ARRAY_BUFFER);
  accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  accessor.type = TINYGLTF_TYPE_VEC3;
  accessor.count = values.size();
  if (withBounds) {  // the spec requires min/max on POSITION
    Box3f box;
    for (const Vec3f& v : values) box.extend(v);
    accessor.minValues = {box.min.x(), box.min.y(), box.min.z()};
    accessor.maxValues = {box.max.x(), box.max.y(), box.max.z()};
  }
  model.accessors.push_back(accessor);
  return int(model.accessors.size()) - 1;
}

// TEXCOORD_0 from OBJ/PLY-style coordinates (v up); returns the accessor index.
int addTexcoordAttribute(tinygltf::Model& model, const std::vector<float>& uv) {
  std::vector<float> flipped(uv);
  for (std::size_t i = 1; i < flipped.size(); i += 2) flipped[i] = 1.0f - flipped[i];
  tinygltf::Accessor accessor;
  accessor.bufferView =
      addBufferView(model, flipped.data(), flipped.size() * sizeof(float), TINYGLTF_TARGET_ARRAY_BUFFER);
  accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  accessor.type = TINYGLTF_TYPE_VEC2;
  accessor.count = flipped.size() / 2;
  model.accessors.push_back(accessor);
  return int(model.accessors.size()) - 1;
}

int addIndices(tinygltf::Model& model, const std::vector<Vec3i>& triangles) {
  std::vector<std::uint32_t> indices;
  indices.reserve(triangles.size() * 3);
  for (const Vec3i& t : triangles)
    for (int k = 0; k < 3; ++k) indices.push_back(std::uint32_t(t[k]));
  tinygltf::Accessor accessor;
  accessor.bufferView = addBufferView(model, indices.data(), indices.size() * sizeof(std::uint32_t),
                                      TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  accessor.type = TINYGLTF_TYPE_SCALAR;
  accessor.count = indices.size();
  model.accessors.push_back(accessor);
  return int(model.accessors.size()) - 1;
}

tinygltf::Model buildModel(const Mesh& mesh) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "texsynth";
  model.buffers.resize(1);

  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.attributes["POSITION"] = addVec3Attribute(model, mesh.positions, true);
  primitive.attributes["NORMAL"] = addVec3Attribute(model, mesh.normals, false);
  if (!mesh.colors.empty()) {  // glTF colours are linear; texsynth's are sRGB-encoded like its images
    std::vector<Vec3f> linear(mesh.colors.size());
    for (std::size_t i = 0; i < linear.size(); ++i)
      for (int c = 0; c < 3; ++c) linear[i][c] = srgbToLinear(std::clamp(mesh.colors[i][c], 0.0f, 1.0f));
    primitive.attributes["COLOR_0"] = addVec3Attribute(model, linear, false);
  }
  if (auto uv = mesh.attributes.find(kUvAttribute); uv != mesh.attributes.end() && uv->second.components == 2)
    primitive.attributes["TEXCOORD_0"] = addTexcoordAttribute(model, uv->second.values);
  primitive.indices = addIndices(model, mesh.triangles);

  tinygltf::Material material;
  material.name = "vertex colors";
  material.pbrMetallicRoughness.baseColorFactor = {1.0, 1.0, 1.0, 1.0};
  material.pbrMetallicRoughness.metallicFactor = 0.0;
  material.pbrMetallicRoughness.roughnessFactor = 1.0;
  model.materials.push_back(material);
  primitive.material = 0;

  tinygltf::Mesh gltfMesh;
  gltfMesh.name = "mesh";
  gltfMesh.primitives.push_back(primitive);
  model.meshes.push_back(gltfMesh);

  tinygltf::Node node;
  node.mesh = 0;
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes.push_back(0);
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  return model;
}

}  // namespace

std::string encodeGltf(const Mesh& input, bool binary) {
  Mesh storage;
  const Mesh& mesh = mesh_detail::preparedForWriting(input, storage);
  tinygltf::Model model = buildModel(mesh);
  std::ostringstream stream;
  tinygltf::TinyGLTF writer;
  // The stream variant embeds buffers (GLB chunk or data URI) and never touches the disk.
  if (!writer.WriteGltfSceneToStream(&model, stream, /*prettyPrint=*/!binary, /*writeBinary=*/binary))
    throw InternalError("tinygltf failed to serialize the mesh");
  return std::move(stream).str();
}

}  // namespace texsynth
