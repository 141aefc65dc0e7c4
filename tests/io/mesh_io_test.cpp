// Mesh readers and writers on well-formed input: every format, round trips, real meshes.
#include "texsynth/io/mesh_io.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <filesystem>

#include "mesh_test_helpers.h"
#include "test_support.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/color.h"
#include "texsynth/core/data_paths.h"
#include "texsynth/core/error.h"

namespace texsynth {
namespace {
using test::TempDir;

void expectSameTriangles(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.triangleCount(), b.triangleCount());
  for (std::size_t i = 0; i < a.triangleCount(); ++i) EXPECT_EQ(a.triangles[i], b.triangles[i]) << "triangle " << i;
}

TEST(MeshObj, ReadsCornerFormsNegativeIndicesColorsAndPolygons) {
  const std::string obj =
      "# comment\n"
      "mtllib x.mtl\n"
      "v 0 0 0 1 0 0\n"
      "v 1 0 0 0 1 0\n"
      "v 1 1 0 0 0 1\n"
      "v 0 1 0 1 1 1\n"
      "vt 0 0\nvn 0 0 1\n"
      "g group\nusemtl m\n"
      "f 1/1/1 2/1/1 3/1/1 4/1/1\n"  // quad -> 2 triangles
      "f -4//1 -3//1 -1//1\n"        // relative: 1 2 4
      "f 1/1 3/1 4/1\n";
  Mesh mesh = parseObj(obj, "test.obj");
  ASSERT_EQ(mesh.vertexCount(), 4u);
  ASSERT_EQ(mesh.colors.size(), 4u);
  EXPECT_EQ(mesh.colors[2], Vec3f(0, 0, 1));
  ASSERT_EQ(mesh.triangleCount(), 4u);
  EXPECT_EQ(mesh.triangles[0], Vec3i(0, 1, 2));
  EXPECT_EQ(mesh.triangles[1], Vec3i(0, 2, 3));
  EXPECT_EQ(mesh.triangles[2], Vec3i(0, 1, 3));
  EXPECT_EQ(mesh.triangles[3], Vec3i(0, 2, 3));
}

TEST(MeshObj, DropsDegenerateTriangles) {
  Mesh mesh = parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 2\nf 1 1 2 3\nf 2 4 3\n", "t.obj");
  ASSERT_EQ(mesh.triangleCount(), 2u);  // "1 2 2" gone; quad "1 1 2 3" keeps only (1,2,3)
  EXPECT_EQ(mesh.triangles[0], Vec3i(0, 1, 2));
  EXPECT_EQ(mesh.triangles[1], Vec3i(1, 3, 2));
}

TEST(MeshOff, ReadsCommentsColorsAndPolygons) {
  const std::string off =
      "COFF # colored\n"
      "# a comment line\n"
      "\n"
      "5 2 0\n"
      "0 0 0 255 0 0 255\n"
      "1 0 0 0 255 0 255\n"
      "1 1 0 0 0 255 255\n"
      "0 1 0 0.5 0.5 0.5 1.0\n"
      "2 2 2 0 0 0 255  # comment after a vertex\n"
      "4 0 1 2 3\n"
      "3 0 1 4 0.5 0.5 0.5\n";  // trailing face color ignored
  Mesh mesh = parseOff(off, "t.off");
  ASSERT_EQ(mesh.vertexCount(), 5u);
  EXPECT_EQ(mesh.colors[1], Vec3f(0, 1, 0));
  EXPECT_EQ(mesh.colors[3], Vec3f(0.5f, 0.5f, 0.5f));
  ASSERT_EQ(mesh.triangleCount(), 3u);
  EXPECT_EQ(mesh.triangles[1], Vec3i(0, 2, 3));
  EXPECT_EQ(mesh.triangles[2], Vec3i(0, 1, 4));
}

TEST(MeshOff, AcceptsCountsOnTheKeywordLineAndCrLf) {
  Mesh mesh = parseOff("OFF 3 1 0\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n", "t.off");
  EXPECT_EQ(mesh.vertexCount(), 3u);
  EXPECT_EQ(mesh.triangleCount(), 1u);
}

// An ascii PLY with an extra element, unknown properties and a list on the vertices, so the
// reader must skip them by type; plus the same content in both binary byte orders.
std::string asciiPly() {
  return "ply\r\nformat ascii 1.0\r\ncomment made by hand\r\n"
         "element vertex 4\r\n"
         "property double x\r\nproperty double y\r\nproperty double z\r\n"
         "property float confidence\r\n"
         "property list uchar int extra\r\n"
         "property uchar red\r\nproperty uchar green\r\nproperty uchar blue\r\n"
         "element material 2\r\nproperty list ushort float values\r\nproperty short id\r\n"
         "element face 2\r\n"
         "property uchar flags\r\nproperty list ushort uint vertex_indices\r\n"
         "end_header\r\n"
         "0 0 0 0.5 2 7 8 255 0 0\r\n"
         "1 0 0 0.5 0 0 255 0\r\n"
         "1 1 0 0.5 1 9 0 0 255\r\n"
         "0 1 0 0.5 0 255 255 255\r\n"
         "3 1 2 3 -1\r\n0 -2\r\n"
         "9 4 0 1 2 3\r\n"
         "9 3 0 2 3\r\n";
}

std::string binaryPly(bool bigEndian) {
  std::string out = std::string("ply\nformat ") + (bigEndian ? "binary_big_endian" : "binary_little_endian") +
                    " 1.0\n"
                    "element vertex 4\n"
                    "property double x\nproperty double y\nproperty double z\n"
                    "property float confidence\n"
                    "property list uchar int extra\n"
                    "property uchar red\nproperty uchar green\nproperty uchar blue\n"
                    "element material 2\nproperty list ushort float values\nproperty short id\n"
                    "element face 2\n"
                    "property uchar flags\nproperty list ushort uint vertex_indices\n"
                    "end_header\n";
  const double xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const std::uint8_t rgb[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}};
  for (int i = 0; i < 4; ++i) {
    for (double v : xyz[i]) test::appendBytes(out, v, bigEndian);
    test::appendBytes(out, 0.5f, bigEndian);
    test::appendBytes(out, std::uint8_t(i == 0 ? 2 : 0), bigEndian);
    if (i == 0) test::appendBytes(out, 7, bigEndian), test::appendBytes(out, 8, bigEndian);
    for (std::uint8_t c : rgb[i]) test::appendBytes(out, c, bigEndian);
  }
  test::appendBytes(out, std::uint16_t(1), bigEndian);
  test::appendBytes(out, 2.0f, bigEndian);
  test::appendBytes(out, std::int16_t(-1), bigEndian);
  test::appendBytes(out, std::uint16_t(0), bigEndian);
  test::appendBytes(out, std::int16_t(-2), bigEndian);
  const std::vector<std::vector<std::uint32_t>> faces = {{0, 1, 2, 3}, {0, 2, 3}};
  for (const auto& face : faces) {
    test::appendBytes(out, std::uint8_t(9), bigEndian);
    test::appendBytes(out, std::uint16_t(face.size()), bigEndian);
    for (std::uint32_t index : face) test::appendBytes(out, index, bigEndian);
  }
  return out;
}

TEST(MeshPly, AsciiAndBothBinaryByteOrdersAgree) {
  Mesh ascii = parsePly(asciiPly(), "a.ply");
  ASSERT_EQ(ascii.vertexCount(), 4u);
  EXPECT_EQ(ascii.positions[2], Vec3f(1, 1, 0));
  ASSERT_EQ(ascii.colors.size(), 4u);
  EXPECT_EQ(ascii.colors[1], Vec3f(0, 1, 0));
  ASSERT_EQ(ascii.triangleCount(), 3u);
  EXPECT_EQ(ascii.triangles[1], Vec3i(0, 2, 3));
  for (bool bigEndian : {false, true}) {
    SCOPED_TRACE(bigEndian ? "big endian" : "little endian");
    Mesh binary = parsePly(binaryPly(bigEndian), "b.ply");
    EXPECT_EQ(binary.positions, ascii.positions);
    EXPECT_EQ(binary.colors, ascii.colors);
    expectSameTriangles(binary, ascii);
  }
}

TEST(MeshPly, ReadsNormalsAndFloatColors) {
  Mesh mesh = parsePly(
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "property float nx\nproperty float ny\nproperty float nz\n"
      "property float red\nproperty float green\nproperty float blue\n"
      "element face 1\nproperty list uchar int vertex_index\nend_header\n"
      "0 0 0 0 0 1 0.25 0.5 1\n1 0 0 0 0 1 0 0 0\n0 1 0 0 0 1 1 1 1\n3 0 1 2\n",
      "n.ply");
  ASSERT_EQ(mesh.normals.size(), 3u);
  EXPECT_EQ(mesh.normals[0], Vec3f(0, 0, 1));
  EXPECT_EQ(mesh.colors[0], Vec3f(0.25f, 0.5f, 1.0f));
}

TEST(MeshStl, AsciiAndBinaryMergeSharedCorners) {
  Mesh cube = test::makeColoredCube();
  for (const std::string& bytes : {test::encodeBinaryStl(cube), test::encodeAsciiStl(cube)}) {
    Mesh mesh = parseStl(bytes, "cube.stl");
    EXPECT_EQ(mesh.vertexCount(), 8u);  // 36 corners merged into 8 vertices
    ASSERT_EQ(mesh.triangleCount(), 12u);
    for (std::size_t i = 0; i < 12; ++i)
      for (int k = 0; k < 3; ++k) EXPECT_EQ(mesh.positions[mesh.triangles[i][k]], cube.positions[cube.triangles[i][k]]);
    EXPECT_NEAR(mesh.surfaceArea(), 6.0, 1e-6);
  }
}

TEST(MeshStl, BinaryStartingWithSolidIsStillBinary) {
  std::string bytes = test::encodeBinaryStl(test::makeColoredCube());
  bytes.replace(0, 5, "solid");
  EXPECT_EQ(parseStl(bytes, "s.stl").vertexCount(), 8u);
}

TEST(MeshRoundTrip, PlyIsExactWithColorsToOneByte) {
  TempDir dir;
  Mesh cube = test::makeColoredCube();
  writeMesh(dir.file("cube.ply"), cube);
  Mesh back = readMesh(dir.file("cube.ply"));
  EXPECT_EQ(back.positions, cube.positions);
  EXPECT_EQ(back.normals, cube.normals);
  expectSameTriangles(back, cube);
  ASSERT_EQ(back.colors.size(), cube.colors.size());
  for (std::size_t i = 0; i < cube.colors.size(); ++i)
    EXPECT_LE((back.colors[i] - cube.colors[i]).cwiseAbs().maxCoeff(), 0.5f / 255.0f + 1e-6f);
}

TEST(MeshRoundTrip, ObjKeepsPositionsAndColorsExactly) {
  TempDir dir;
  Mesh cube = test::makeColoredCube();
  cube.positions[3] = Vec3f(0.1f, 1e-7f, -123.456f);  // awkward decimals
  writeMesh(dir.file("cube.obj"), cube);
  Mesh back = readMesh(dir.file("cube.obj"));
  ASSERT_EQ(back.vertexCount(), cube.vertexCount());
  // Shortest round-trip decimals: text, yet bit-exact.
  EXPECT_EQ(back.positions, cube.positions);
  EXPECT_EQ(back.colors, cube.colors);
  expectSameTriangles(back, cube);
}

TEST(MeshRoundTrip, WritesNormalsWhenTheMeshHasNone) {
  Mesh cube = test::makeColoredCube();
  std::vector<Vec3f> expected = cube.normals;
  cube.normals.clear();
  cube.colors.clear();
  Mesh back = parsePly(encodePly(cube), "x.ply");
  EXPECT_EQ(back.normals, expected);
  EXPECT_TRUE(back.colors.empty());
  EXPECT_NE(encodeObj(cube).find("\nvn "), std::string::npos);
}

// Reads an accessor's float vec3 data out of a tinygltf model.
std::vector<Vec3f> vec3Data(const tinygltf::Model& model, int accessorIndex) {
  const tinygltf::Accessor& accessor = model.accessors.at(std::size_t(accessorIndex));
  EXPECT_EQ(accessor.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
  EXPECT_EQ(accessor.type, TINYGLTF_TYPE_VEC3);
  const tinygltf::BufferView& view = model.bufferViews.at(std::size_t(accessor.bufferView));
  const auto& data = model.buffers.at(std::size_t(view.buffer)).data;
  std::vector<float> floats(3 * accessor.count);
  std::memcpy(floats.data(), data.data() + view.byteOffset + accessor.byteOffset, floats.size() * sizeof(float));
  std::vector<Vec3f> values;
  for (std::size_t i = 0; i < accessor.count; ++i)
    values.emplace_back(floats[3 * i], floats[3 * i + 1], floats[3 * i + 2]);
  return values;
}

TEST(MeshRoundTrip, GltfBinaryAndTextLoadInTinyGltf) {
  TempDir dir;
  Mesh cube = test::makeColoredCube();
  for (bool binary : {true, false}) {
    SCOPED_TRACE(binary ? "glb" : "gltf");
    const std::string path = dir.file(binary ? "cube.glb" : "cube.gltf");
    writeMesh(path, cube);
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    bool ok = binary ? loader.LoadBinaryFromFile(&model, &error, &warning, path)
                     : loader.LoadASCIIFromFile(&model, &error, &warning, path);
    ASSERT_TRUE(ok) << error;
    ASSERT_EQ(model.meshes.size(), 1u);
    const tinygltf::Primitive& primitive = model.meshes[0].primitives.at(0);
    EXPECT_EQ(primitive.mode, TINYGLTF_MODE_TRIANGLES);
    EXPECT_EQ(vec3Data(model, primitive.attributes.at("POSITION")), cube.positions);
    EXPECT_EQ(vec3Data(model, primitive.attributes.at("NORMAL")), cube.normals);
    std::vector<Vec3f> linear = cube.colors;  // glTF stores linear colours
    for (Vec3f& c : linear)
      for (int k = 0; k < 3; ++k) c[k] = srgbToLinear(c[k]);
    EXPECT_EQ(vec3Data(model, primitive.attributes.at("COLOR_0")), linear);
    const tinygltf::Accessor& indices = model.accessors.at(std::size_t(primitive.indices));
    EXPECT_EQ(indices.count, 3 * cube.triangleCount());
    EXPECT_EQ(indices.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
    const tinygltf::Accessor& position = model.accessors.at(std::size_t(primitive.attributes.at("POSITION")));
    EXPECT_EQ(position.minValues, (std::vector<double>{0, 0, 0}));
    EXPECT_EQ(position.maxValues, (std::vector<double>{1, 1, 1}));
    const tinygltf::Material& material = model.materials.at(std::size_t(primitive.material));
    EXPECT_EQ(material.pbrMetallicRoughness.baseColorFactor, (std::vector<double>{1, 1, 1, 1}));
    EXPECT_EQ(material.pbrMetallicRoughness.metallicFactor, 0.0);
  }
}

TEST(MeshWrite, OutputIsDeterministic) {
  Mesh cube = test::makeColoredCube();
  EXPECT_EQ(encodePly(cube), encodePly(cube));
  EXPECT_EQ(encodeObj(cube), encodeObj(cube));
  EXPECT_EQ(encodeGltf(cube, true), encodeGltf(cube, true));
  EXPECT_EQ(encodeGltf(cube, false), encodeGltf(cube, false));
}

TEST(MeshWrite, FailedWriteLeavesTheOldFileAndNoTemporaries) {
  TempDir dir;
  const std::string path = dir.file("keep.ply");
  writeMesh(path, test::makeColoredCube());
  const std::string before = readFileBytes(path);
  Mesh broken = test::makeColoredCube();
  broken.triangles[3] = Vec3i(0, 1, 99);
  EXPECT_THROW(writeMesh(path, broken), ParameterError);
  EXPECT_THROW(writeMesh(dir.file("cube.xyz"), test::makeColoredCube()), ParameterError);
  EXPECT_THROW(writeMesh(dir.file("missing/cube.ply"), test::makeColoredCube()), OutputError);
  EXPECT_EQ(readFileBytes(path), before);
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    ++files;
    EXPECT_EQ(entry.path().filename(), "keep.ply");
  }
  EXPECT_EQ(files, 1);
}

TEST(MeshRealData, AllCgalMeshesLoadWithSaneCounts) {
  TS_REQUIRE_DATA(cgalMesh("bunny00.off"));
  const std::pair<const char*, std::size_t> meshes[] = {
      {"bunny00.off", 37706}, {"elephant.off", 2775}, {"armadillo.off", 26002}, {"cow.off", 2904}, {"dino.off", 3916},
      {"pig.off", 468},       {"fandisk.off", 6475},  {"sphere.off", 162},      {"cube.off", 8}};
  for (const auto& [name, vertices] : meshes) {
    SCOPED_TRACE(name);
    auto path = cgalMesh(name);
    ASSERT_TRUE(path);
    Mesh mesh = readMesh(*path);
    EXPECT_EQ(mesh.vertexCount(), vertices);
    EXPECT_GE(mesh.triangleCount(), vertices);  // closed-ish surfaces: about 2 triangles per vertex
    EXPECT_LE(mesh.triangleCount(), 3 * vertices);
    EXPECT_EQ(mesh.normals.size(), vertices);
    EXPECT_GT(mesh.surfaceArea(), 0.0);
  }
  Mesh bunny = readMesh(*cgalMesh("bunny00.off"));
  EXPECT_EQ(bunny.triangleCount(), 75408u);
  EXPECT_EQ(readMesh(*cgalMesh("dino.off")).colors.size(), 3916u);  // COFF
}

TEST(MeshRealData, ConvertedBunnyReadsBackIdentically) {
  TS_REQUIRE_DATA(cgalMesh("bunny00.off"));
  Mesh bunny = readMesh(*cgalMesh("bunny00.off"));
  Mesh fromPly = parsePly(encodePly(bunny), "bunny.ply");
  Mesh fromObj = parseObj(encodeObj(bunny), "bunny.obj");
  Mesh fromStl = parseStl(test::encodeBinaryStl(bunny), "bunny.stl");
  EXPECT_EQ(fromPly.positions, bunny.positions);
  EXPECT_EQ(fromObj.positions, bunny.positions);
  expectSameTriangles(fromPly, bunny);
  expectSameTriangles(fromObj, bunny);
  EXPECT_LE(fromStl.vertexCount(), bunny.vertexCount());  // unused vertices vanish in STL
  EXPECT_EQ(fromStl.triangleCount(), bunny.triangleCount());
  EXPECT_NEAR(fromStl.surfaceArea(), bunny.surfaceArea(), 1e-9 * bunny.surfaceArea() + 1e-12);
}

TEST(MeshRead, IsDeterministic) {
  TS_REQUIRE_DATA(cgalMesh("elephant.off"));
  Mesh a = readMesh(*cgalMesh("elephant.off")), b = readMesh(*cgalMesh("elephant.off"));
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.normals, b.normals);
  expectSameTriangles(a, b);
}

}  // namespace
}  // namespace texsynth
