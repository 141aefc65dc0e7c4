// Mesh readers on bad input: every malformed, truncated, empty or absurd file must raise one
// InputError naming the file (never crash, hang, over-allocate or throw something else).
#include <gtest/gtest.h>

#include <functional>

#include "mesh_test_helpers.h"
#include "test_support.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/data_paths.h"
#include "texsynth/core/error.h"
#include "texsynth/core/random.h"
#include "texsynth/io/mesh_io.h"

namespace texsynth {
namespace {
using test::TempDir;
using Parser = std::function<Mesh(std::string_view, const std::string&)>;

// The problem text of the InputError that parsing `bytes` raises ("" if none is raised).
std::string problemOf(const Parser& parse, std::string_view bytes) {
  try {
    parse(bytes, "in.mesh").validate("in.mesh");
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "in.mesh");
    return error.problem();
  }
  return "";
}

TEST(MeshBadInput, AssimpInvalidModelsRaiseInputError) {
  auto dir = assimpInvalidModels();
  TS_REQUIRE_DATA(dir);
  for (const char* name :
       {"empty.obj", "malformed.obj", "malformed2.obj", "empty.off", "OutOfMemory.off", "empty.ply"}) {
    SCOPED_TRACE(name);
    const std::string path = *dir + "/" + name;
    try {
      readMesh(path);
      ADD_FAILURE() << "no error for " << name;
    } catch (const InputError& error) {
      EXPECT_EQ(error.file(), path);
      EXPECT_FALSE(error.problem().empty());
    }
  }
  try {
    readMesh(*dir + "/malformed.obj");
  } catch (const InputError& error) {
    EXPECT_EQ(error.problem(), "line 23: face refers to vertex 12 but only 8 vertices are defined");
  }
}

TEST(MeshBadInput, EmptyFilesAndUnknownFormats) {
  for (const Parser& parse : {Parser(parseObj), Parser(parsePly), Parser(parseOff), Parser(parseStl)})
    EXPECT_EQ(problemOf(parse, ""), "file is empty");
  TempDir dir;
  test::writeBytes(dir.file("mesh.3ds"), "x");
  EXPECT_THROW(readMesh(dir.file("mesh.3ds")), InputError);
  EXPECT_THROW(readMesh(dir.file("absent.obj")), InputError);
}

TEST(MeshBadInput, ObjProblemsNameTheLine) {
  const std::string vertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_EQ(problemOf(parseObj, vertices + "f 1 2 5\n"),
            "line 4: face refers to vertex 5 but only 3 vertices are defined");
  EXPECT_EQ(problemOf(parseObj, vertices + "f -1 -2 -4\n"),
            "line 4: face refers to vertex -4 but only 3 vertices are defined");
  EXPECT_NE(problemOf(parseObj, vertices + "f 0 1 2\n").find("line 4: "), std::string::npos);
  EXPECT_NE(problemOf(parseObj, vertices + "f 1 2\n").find("line 4: face has 2 vertices"), std::string::npos);
  EXPECT_NE(problemOf(parseObj, "v 0 zero 0\n").find("line 1: bad vertex coordinate 'zero'"), std::string::npos);
  EXPECT_NE(problemOf(parseObj, "v 0 0\n").find("line 1: "), std::string::npos);
  EXPECT_NE(problemOf(parseObj, "v 0 0 0 1 1 1\nv 0 0 0\n").find("line 2: "), std::string::npos);
  EXPECT_NE(problemOf(parseObj, vertices + "f 1 2 x\n").find("line 4: bad face index 'x'"), std::string::npos);
  EXPECT_EQ(problemOf(parseObj, "# only a comment\n"), "mesh has no vertices");
}

TEST(MeshBadInput, OffAndPlyProblemsNameTheLine) {
  EXPECT_EQ(problemOf(parseOff, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"),
            "line 6: face refers to vertex 7 but only 3 vertices are defined");
  EXPECT_NE(problemOf(parseOff, "OFX\n3 1 0\n").find("line 1: not an OFF file"), std::string::npos);
  EXPECT_EQ(problemOf(parseOff, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), "");
  EXPECT_EQ(problemOf(parseOff, "OFF\n3 1 0\n0 0 0\n1 0\n"),
            "line 2: declares 3 vertices but only 11 bytes follow (at least 6 bytes each)");
  EXPECT_EQ(problemOf(parseOff, "OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n"),
            "line 4: vertex line ends before its z coordinate");
  EXPECT_EQ(problemOf(parseOff, "OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n# padding comment\n"),
            "line 6: file ends after 0 of 1 faces");
  const std::string plyHeader =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  EXPECT_EQ(problemOf(parsePly, plyHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"),
            "line 13: element 'face' item 0 of 1 refers to vertex 3 but only 3 vertices are defined");
  EXPECT_NE(problemOf(parsePly, plyHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1\n").find("file ends inside element 'face'"),
            std::string::npos);
  EXPECT_NE(problemOf(parsePly, plyHeader + "0 0 0\n1 q 0\n0 1 0\n3 0 1 2\n").find("line 11: bad number 'q'"),
            std::string::npos);
  EXPECT_NE(problemOf(parsePly, "ply\nformat ascii 2.0\n").find("line 2: "), std::string::npos);
  EXPECT_NE(problemOf(parsePly, "ply\nformat ascii 1.0\nelement vertex 1\nproperty flot x\n").find("line 4: "),
            std::string::npos);
  EXPECT_NE(problemOf(parsePly, "plyx\n").find("not a PLY file"), std::string::npos);
}

TEST(MeshBadInput, AbsurdCountsAreRejectedBeforeAllocating) {
  // Honoring any of these counts would need terabytes: bad_alloc instead of InputError fails the test.
  EXPECT_NE(problemOf(parseOff, "OFF\n1000000000000 1 0\n0 0 0\n").find("line 2: declares 1000000000000 vertices"),
            std::string::npos);
  EXPECT_NE(problemOf(parseOff, "OFF\n3 1000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").find("faces"),
            std::string::npos);
  for (const char* format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
    SCOPED_TRACE(format);
    std::string header = std::string("ply\nformat ") + format +
                         " 1.0\nelement vertex 1000000000000\nproperty float x\nproperty float y\nproperty float z\n"
                         "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    EXPECT_NE(problemOf(parsePly, header + std::string(64, '\0')).find("line 3: element 'vertex' declares"),
              std::string::npos);
  }
  // Ten million vertices declared, but the file is far too small to hold them.
  EXPECT_NE(problemOf(parsePly,
                      "ply\nformat binary_little_endian 1.0\nelement vertex 10000000\nproperty float x\n"
                      "property float y\nproperty float z\nend_header\n" +
                          std::string(1000, '\0'))
                .find("declares 10000000 items"),
            std::string::npos);
  std::string stl(80, 'x');
  test::appendBytes(stl, std::uint32_t(0xFFFFFFFFu));
  EXPECT_NE(problemOf(parseStl, stl + std::string(50, '\0')).find("declares 4294967295 triangles"), std::string::npos);
}

// Cuts `bytes` at several offsets; each cut file must raise InputError.
void expectTruncationsRejected(const Parser& parse, const std::string& bytes, std::vector<std::size_t> cuts) {
  for (double fraction : {0.001, 0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99})
    cuts.push_back(std::size_t(fraction * double(bytes.size())));
  for (std::size_t cut : cuts) {
    SCOPED_TRACE("cut at byte " + std::to_string(cut) + " of " + std::to_string(bytes.size()));
    EXPECT_NE(problemOf(parse, std::string_view(bytes).substr(0, cut)), "");
  }
}

TEST(MeshBadInput, TruncatedRealMeshesInEveryFormat) {
  TS_REQUIRE_DATA(cgalMesh("elephant.off"));
  for (const char* name : {"bunny00.off", "elephant.off", "dino.off"}) {
    SCOPED_TRACE(name);
    std::string off = readFileBytes(*cgalMesh(name));
    expectTruncationsRejected(parseOff, off, {0, 1, 3, 4, 12});
  }
  Mesh elephant = readMesh(*cgalMesh("elephant.off"));
  std::string ply = encodePly(elephant);
  std::size_t body = ply.find("end_header\n") + 11;
  expectTruncationsRejected(parsePly, ply, {3, body - 5, body, body + 7, ply.size() - 1});
  std::string stl = test::encodeBinaryStl(elephant);
  expectTruncationsRejected(parseStl, stl, {50, 84, 100, stl.size() - 1});
  std::string asciiStl = test::encodeAsciiStl(elephant);
  expectTruncationsRejected(parseStl, asciiStl, {asciiStl.size() - 14});
}

// Random byte edits of small valid files: the reader must accept the result or raise
// InputError; anything else (crash, other exception) fails. Edits are seeded, so repeatable.
TEST(MeshBadInput, CorruptedFilesOnlyEverRaiseInputError) {
  Mesh cube = test::makeColoredCube();
  const std::pair<Parser, std::string> samples[] = {
      {parseObj, encodeObj(cube)},
      {parsePly, encodePly(cube)},
      {parseOff,
       "COFF\n4 2 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n1 1 0 0 0 255 255\n0 1 0 9 9 9 255\n"
       "4 0 1 2 3\n3 0 2 3\n"},
      {parseStl, test::encodeBinaryStl(cube)},
      {parseStl, test::encodeAsciiStl(cube)}};
  const char replacements[] = {'0', '9', '-', ' ', '\n', '.', 'e', '/', '\0', '\xff'};
  int sample = 0;
  for (const auto& [parse, original] : samples) {
    for (int trial = 0; trial < 300; ++trial) {
      std::string bytes = original;
      for (int edit = 0; edit < 3; ++edit) {
        std::uint64_t key = hashKey(17, std::uint64_t(trial), std::uint64_t(sample), std::uint64_t(edit));
        std::size_t at = uniformBelow(key, std::uint32_t(bytes.size()));
        char value = replacements[uniformBelow(mix64(key), sizeof(replacements))];
        if (key & 1)
          bytes[at] = value;
        else
          bytes.erase(at, 1 + uniformBelow(mix64(key + 1), 8));
        if (bytes.empty()) bytes.push_back('x');
      }
      try {
        parse(bytes, "fuzz").validate("fuzz");
      } catch (const InputError&) {
      } catch (const std::exception& other) {
        ADD_FAILURE() << "sample " << sample << " trial " << trial << ": " << other.what();
      }
    }
    ++sample;
  }
}

}  // namespace
}  // namespace texsynth
