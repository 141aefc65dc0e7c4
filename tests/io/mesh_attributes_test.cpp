// Vertex attributes through the mesh files: texture coordinates from OBJ (split at UV seams, kept
// off when incomplete) and PLY (every usual spelling), other PLY properties by name, exact round
// trips through PLY and OBJ, TEXCOORD_0 in glTF, and checks of inconsistent attributes.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include "mesh_test_helpers.h"
#include "test_support.h"
#include "texsynth/core/error.h"
#include "texsynth/io/mesh_io.h"

namespace texsynth {
namespace {

const std::vector<float>& uvOf(const Mesh& mesh) {
  return mesh.attributes.at(kUvAttribute).values;
}

// Two triangles sharing the edge 1-2 of a unit square; the square's 'vt' lines are `uvs`.
std::string squareObj(const std::string& faces) {
  return "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
         "vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\nvt 0.5 0.5\n" +
         faces;
}

TEST(MeshAttributes, ObjTextureCoordinatesWithoutSeamsKeepTheVertices) {
  const Mesh mesh = parseObj(squareObj("f 1/1 2/2 3/3\nf 2/2/1 4/4/1 3/3/1\n"), "square.obj");
  ASSERT_EQ(mesh.vertexCount(), 4u);
  EXPECT_EQ(uvOf(mesh), (std::vector<float>{0, 0, 1, 0, 0, 1, 1, 1}));
  EXPECT_EQ(mesh.attributes.at(kUvAttribute).components, 2);
  EXPECT_EQ(mesh.triangles[1], Vec3i(1, 3, 2));
}

TEST(MeshAttributes, ObjUvSeamsSplitVerticesAndKeepSmoothNormals) {
  // Vertex 2 (index 1) has another texture coordinate in the second face: a seam.
  const Mesh mesh = parseObj(squareObj("f 1/1 2/2 3/3\nf 2/5 4/4 3/-3\n"), "seam.obj");
  ASSERT_EQ(mesh.vertexCount(), 5u);
  EXPECT_EQ(mesh.positions[4], mesh.positions[1]);
  EXPECT_EQ(mesh.triangles[1], Vec3i(4, 3, 2));
  EXPECT_EQ(uvOf(mesh), (std::vector<float>{0, 0, 1, 0, 0, 1, 1, 1, 0.5f, 0.5f}));
  ASSERT_EQ(mesh.normals.size(), 5u);
  EXPECT_EQ(mesh.normals[4], mesh.normals[1]);  // computed before the split
  mesh.validate("seam.obj");
}

TEST(MeshAttributes, IncompleteOrMalformedObjTextureCoordinatesAreDroppedNotFatal) {
  for (const std::string& faces : {std::string("f 1/1 2/2 3/3\nf 2 4 3\n"),
                                   std::string("f 1/1 2/2 3/9\nf 2/2 4/4 3/3\n"), std::string("f 1/1 2/x 3/3\n")}) {
    SCOPED_TRACE(faces);
    const Mesh mesh = parseObj(squareObj(faces), "partial.obj");
    EXPECT_EQ(mesh.vertexCount(), 4u);
    EXPECT_EQ(mesh.attributes.count(kUvAttribute), 0u);
  }
  const Mesh bad = parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt nan 0\nf 1/1 2/1 3/1\n", "bad.obj");
  EXPECT_EQ(bad.attributes.count(kUvAttribute), 0u);
  EXPECT_EQ(bad.triangleCount(), 1u);
}

TEST(MeshAttributes, PlyReadsEveryUsualUvSpellingAndKeepsOtherProperties) {
  for (const auto& [u, v] : std::vector<std::pair<std::string, std::string>>{
           {"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}}) {
    SCOPED_TRACE(u);
    const std::string ply =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nproperty float " +
        u + "\nproperty uchar quality\nproperty float " + v +
        "\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0 0.25 7 0.5\n1 0 0 1 8 0\n0 1 0 0 9 1\n3 0 1 2\n";
    const Mesh mesh = parsePly(ply, "uv.ply");
    EXPECT_EQ(uvOf(mesh), (std::vector<float>{0.25f, 0.5f, 1, 0, 0, 1}));
    EXPECT_EQ(mesh.attributes.at("quality").values, (std::vector<float>{7, 8, 9}));
    EXPECT_EQ(mesh.attributes.size(), 2u);
  }
}

TEST(MeshAttributes, PlyAndObjRoundTripsAreExact) {
  Mesh cube = test::makeColoredCube();
  VertexAttribute uv{2, {}}, weight{1, {}}, triple{3, {}};
  for (std::size_t i = 0; i < cube.vertexCount(); ++i) {
    uv.values.insert(uv.values.end(), {0.1f * float(i), 1.0f / float(i + 3)});
    weight.values.push_back(float(i) / 7.0f);
    triple.values.insert(triple.values.end(), {1.0f, 2.0f, float(i)});
  }
  cube.attributes = {{kUvAttribute, uv}, {"weight", weight}, {"triple", triple}};
  const Mesh ply = parsePly(encodePly(cube), "cube.ply");
  EXPECT_EQ(uvOf(ply), uv.values);
  EXPECT_EQ(ply.attributes.at("weight").values, weight.values);
  EXPECT_EQ(ply.attributes.at("triple_2").values.at(5), 5.0f);  // several components: one property each
  const Mesh obj = parseObj(encodeObj(cube), "cube.obj");
  ASSERT_EQ(obj.vertexCount(), cube.vertexCount());
  EXPECT_EQ(uvOf(obj), uv.values);
  EXPECT_EQ(obj.positions, cube.positions);
}

TEST(MeshAttributes, GltfHasTexcoordsWithVFlipped) {
  Mesh cube = test::makeColoredCube();
  VertexAttribute uv{2, std::vector<float>(2 * cube.vertexCount(), 0.25f)};
  cube.attributes[kUvAttribute] = uv;
  const std::string glb = encodeGltf(cube, true);
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string error, warning;
  ASSERT_TRUE(loader.LoadBinaryFromMemory(&model, &error, &warning, reinterpret_cast<const unsigned char*>(glb.data()),
                                          unsigned(glb.size())))
      << error;
  const tinygltf::Accessor& accessor =
      model.accessors.at(std::size_t(model.meshes.at(0).primitives.at(0).attributes.at("TEXCOORD_0")));
  ASSERT_EQ(accessor.count, cube.vertexCount());
  const tinygltf::BufferView& view = model.bufferViews.at(std::size_t(accessor.bufferView));
  float first[2];
  std::memcpy(first, model.buffers[0].data.data() + view.byteOffset + accessor.byteOffset, sizeof first);
  EXPECT_EQ(first[0], 0.25f);
  EXPECT_EQ(first[1], 0.75f);
}

TEST(MeshAttributes, InconsistentAttributesAreRejected) {
  Mesh cube = test::makeColoredCube();
  cube.attributes["short"] = {1, {1.0f, 2.0f}};
  test::expectInputError([&] { cube.validate("cube"); }, "cube", "'short' has 2 values for 8 vertices");
  test::expectParameterError([&] { encodePly(cube); }, "mesh");
  cube.attributes.clear();
  cube.attributes["nx"] = {1, std::vector<float>(8, 0.0f)};  // would repeat the normal's property
  test::expectParameterError([&] { encodePly(cube); }, "mesh");
  cube.attributes.clear();
  cube.attributes["two words"] = {1, std::vector<float>(8, 0.0f)};
  test::expectParameterError([&] { encodePly(cube); }, "mesh");
}

}  // namespace
}  // namespace texsynth
