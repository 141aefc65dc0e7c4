// glTF reading: texsynth's own .glb/.gltf round-trip exactly; node transforms, normalized colors
// and 16-bit indices of other writers; malformed files give one InputError.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cstring>
#include <sstream>

#include "mesh_test_helpers.h"
#include "test_support.h"
#include "texsynth/core/color.h"
#include "texsynth/core/error.h"
#include "texsynth/io/file_kind.h"
#include "texsynth/io/mesh_io.h"

namespace texsynth {
namespace {

TEST(MeshGltfRead, TexsynthsOwnFilesRoundTrip) {
  test::TempDir dir;
  const Mesh cube = test::makeColoredCube();
  for (const char* name : {"cube.glb", "cube.gltf"}) {
    SCOPED_TRACE(name);
    writeMesh(dir.file(name), cube);
    EXPECT_EQ(fileKind(dir.file(name)), FileKind::Mesh);
    const Mesh back = readMesh(dir.file(name));
    EXPECT_EQ(back.positions, cube.positions);
    EXPECT_EQ(back.normals, cube.normals);
    ASSERT_EQ(back.colors.size(), cube.colors.size());  // through linear COLOR_0 and back: float rounding only
    for (std::size_t i = 0; i < cube.colors.size(); ++i) EXPECT_LT((back.colors[i] - cube.colors[i]).norm(), 1e-5f);
    EXPECT_EQ(back.triangles, cube.triangles);
  }
  Mesh plain = cube;
  plain.colors.clear();
  EXPECT_TRUE(parseGltf(encodeGltf(plain, true), "plain.glb").colors.empty());
}

// Appends `bytes` to buffer 0 as a view and an accessor; returns the accessor.
int addAccessor(tinygltf::Model& model, const void* bytes, std::size_t size, int componentType, int type,
                std::size_t count, bool normalized = false) {
  auto& data = model.buffers[0].data;
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = data.size();
  view.byteLength = size;
  data.insert(data.end(), static_cast<const unsigned char*>(bytes), static_cast<const unsigned char*>(bytes) + size);
  model.bufferViews.push_back(view);
  tinygltf::Accessor accessor;
  accessor.bufferView = int(model.bufferViews.size()) - 1;
  accessor.componentType = componentType;
  accessor.type = type;
  accessor.count = count;
  accessor.normalized = normalized;
  model.accessors.push_back(accessor);
  return int(model.accessors.size()) - 1;
}

// One triangle with RGBA8 colors and uint16 indices, under a parent node that translates by
// (10, 0, 0) and a child that scales by 2.
std::string otherWritersTriangle() {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.buffers.resize(1);
  const float positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const unsigned char colors[] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 51, 255};
  const std::uint16_t indices[] = {0, 1, 2, 0};  // padded to 4 bytes
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.attributes["POSITION"] =
      addAccessor(model, positions, sizeof positions, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 3);
  primitive.attributes["COLOR_0"] =
      addAccessor(model, colors, sizeof colors, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_VEC4, 3, true);
  primitive.indices =
      addAccessor(model, indices, sizeof indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, 3);
  tinygltf::Mesh mesh;
  mesh.primitives.push_back(primitive);
  model.meshes.push_back(mesh);
  tinygltf::Node parent, child;
  parent.translation = {10, 0, 0};
  parent.children = {1};
  child.scale = {2, 2, 2};
  child.mesh = 0;
  model.nodes = {parent, child};
  tinygltf::Scene scene;
  scene.nodes = {0};
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  std::ostringstream stream;
  tinygltf::TinyGLTF writer;
  EXPECT_TRUE(writer.WriteGltfSceneToStream(&model, stream, false, true));
  return stream.str();
}

TEST(MeshGltfRead, AppliesNodeTransformsAndReadsNormalizedColors) {
  const Mesh mesh = parseGltf(otherWritersTriangle(), "triangle.glb");
  ASSERT_EQ(mesh.vertexCount(), 3u);
  EXPECT_EQ(mesh.positions[0], Vec3f(10, 0, 0));
  EXPECT_EQ(mesh.positions[1], Vec3f(12, 0, 0));
  EXPECT_EQ(mesh.positions[2], Vec3f(10, 2, 0));
  EXPECT_EQ(mesh.colors[0], Vec3f(1, 0, 0));
  EXPECT_EQ(mesh.colors[2], Vec3f(0, 0, linearToSrgb(0.2f)));  // glTF's linear 51/255, sRGB-encoded
  EXPECT_EQ(mesh.triangles, (std::vector<Vec3i>{{0, 1, 2}}));
  EXPECT_TRUE(mesh.normals.empty());  // none stored: readMesh computes them
}

TEST(MeshGltfRead, MalformedFilesGiveOneInputError) {
  test::TempDir dir;
  test::writeBytes(dir.file("junk.glb"), "glTF\x02\x00\x00\x00garbage");
  test::expectInputError([&] { readMesh(dir.file("junk.glb")); }, dir.file("junk.glb"), "glTF");
  test::writeBytes(dir.file("junk.gltf"), "{\"asset\": ");
  test::expectInputError([&] { readMesh(dir.file("junk.gltf")); }, dir.file("junk.gltf"), "glTF");
  // A valid file whose index points past the vertices.
  std::string bytes = encodeGltf(test::makeColoredCube(), false);
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string error, warning;
  ASSERT_TRUE(loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(), unsigned(bytes.size()), ""));
  auto& data = model.buffers[0].data;
  const tinygltf::Accessor& indices = model.accessors[std::size_t(model.meshes[0].primitives[0].indices)];
  const std::uint32_t past = 1000;
  std::memcpy(&data[model.bufferViews[std::size_t(indices.bufferView)].byteOffset], &past, sizeof past);
  std::ostringstream stream;
  ASSERT_TRUE(tinygltf::TinyGLTF().WriteGltfSceneToStream(&model, stream, false, true));
  test::expectInputError([&] { parseGltf(stream.str(), "bad.glb"); }, "bad.glb", "index");
  // No triangles at all.
  model.meshes[0].primitives[0].mode = TINYGLTF_MODE_POINTS;
  std::ostringstream points;
  ASSERT_TRUE(tinygltf::TinyGLTF().WriteGltfSceneToStream(&model, points, false, true));
  test::expectInputError([&] { parseGltf(points.str(), "points.glb"); }, "points.glb", "no triangles");
}

}  // namespace
}  // namespace texsynth
