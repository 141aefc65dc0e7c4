#include "texsynth/animation/surface_flow.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>

#include "mesh_test_support.h"
#include "test_support.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"

using namespace texsynth;
using test::expectInputError;
using test::expectParameterError;
using test::TempDir;

namespace {

constexpr float kSpacing = 0.05f;

// The synthesis mesh of every test: a unit sphere with unit normals and a tangent "up" field
// (the tangent part of +x, normalized).
struct Target {
  Mesh mesh = test::icosphere(3);
  std::vector<Vec3f> fieldUp;
  Target() {
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
      const Vec3f& n = mesh.normals[v];
      const Vec3f t = Vec3f::UnitX() - n.x() * n;
      fieldUp.push_back(t.norm() > 1e-3f ? t.normalized() : n.unitOrthogonal());
    }
  }
  SurfaceFlowMesh view() const { return {&mesh, fieldUp, kSpacing}; }
};

float largestSpeed(const std::vector<Vec3f>& velocities) {
  float largest = 0;
  for (const Vec3f& v : velocities) largest = std::max(largest, v.norm());
  return largest;
}

Vec3f tangentPart(const Vec3f& v, const Vec3f& normal) {
  return v - v.dot(normal) * normal;
}

void expectTangent(const std::vector<Vec3f>& velocities, const Mesh& mesh) {
  ASSERT_EQ(velocities.size(), mesh.vertexCount());
  for (std::size_t v = 0; v < velocities.size(); ++v) EXPECT_NEAR(velocities[v].dot(mesh.normals[v]), 0.0f, 1e-6f);
}

// A per-vertex velocity file of `lines` (comments and blank lines are fine).
std::string writeLines(const TempDir& dir, const std::string& name, const std::vector<std::string>& lines) {
  std::ofstream out(dir.file(name));
  for (const std::string& line : lines) out << line << "\n";
  return dir.file(name);
}

// One "vx vy vz" line per vertex of `input`, every one `velocity`, behind a comment and a blank.
std::string writeConstant(const TempDir& dir, const std::string& name, const Mesh& input, const Vec3f& velocity) {
  std::vector<std::string> lines = {"# velocities", ""};
  for (std::size_t v = 0; v < input.vertexCount(); ++v)
    lines.push_back(std::to_string(velocity.x()) + " " + std::to_string(velocity.y()) + "\t" +
                    std::to_string(velocity.z()) + "  # vertex " + std::to_string(v));
  return writeLines(dir, name, lines);
}

}  // namespace

TEST(SurfaceFlow, DownhillIsTangentAndPointsDown) {
  const Target target;
  const SurfaceFlow flow = SurfaceFlow::parse("downhill:strength=2", target.mesh, target.view(), {.up = {0, 3, 0}});
  const std::vector<Vec3f> v = flow.velocities(0);
  expectTangent(v, target.mesh);
  for (std::size_t i = 0; i < v.size(); ++i) {
    EXPECT_LE(v[i].y(), 1e-7f);
    // Speed: the tangent part of a unit down vector, at most where the surface is vertical.
    const float ny = target.mesh.normals[i].y();
    EXPECT_NEAR(v[i].norm(), 2 * kSpacing * std::sqrt(std::max(0.0f, 1 - ny * ny)), 1e-5f);
  }
  EXPECT_LE(largestSpeed(v), 2 * kSpacing * 1.00001f);
  EXPECT_GT(largestSpeed(v), 2 * kSpacing * 0.99f);
  EXPECT_FALSE(flow.timeVarying());
  EXPECT_EQ(flow.description(), "downhill strength 2");
}

TEST(SurfaceFlow, SwirlIsTangentWithTheRequestedLargestSpeed) {
  const Target target;
  const SurfaceFlow flow = SurfaceFlow::parse("swirl:strength=0.75,seed=9", target.mesh, target.view());
  const std::vector<Vec3f> v = flow.velocities(4);
  expectTangent(v, target.mesh);
  EXPECT_NEAR(largestSpeed(v), 0.75f * kSpacing, 1e-6f);
  // Eddies, not a standstill: most vertices move.
  EXPECT_GT(std::count_if(v.begin(), v.end(), [](const Vec3f& x) { return x.norm() > 0.1f * 0.75f * kSpacing; }),
            std::ptrdiff_t(v.size() / 2));
  // The seed picks the eddies; the default strength is 0.5.
  const std::vector<Vec3f> other = SurfaceFlow::parse("swirl", target.mesh, target.view()).velocities(0);
  EXPECT_NE(other, v);
  EXPECT_NEAR(largestSpeed(other), 0.5f * kSpacing, 1e-6f);
  EXPECT_EQ(flow.description(), "swirl strength 0.75, seed 9");
}

TEST(SurfaceFlow, AlongFieldFollowsTheFieldUp) {
  const Target target;
  const SurfaceFlow flow = SurfaceFlow::parse("along-field:strength=1.5", target.mesh, target.view(), {.scale = 2});
  const std::vector<Vec3f> v = flow.velocities(0);
  expectTangent(v, target.mesh);
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_LT((v[i] - 3 * kSpacing * target.fieldUp[i]).norm(), 1e-6f);
  EXPECT_EQ(flow.description(), "along-field strength 1.5, scale 2");
}

TEST(SurfaceFlow, IdenticalForAnyThreadCount) {
  const Target target;
  TempDir dir;
  Mesh input = test::irregularSphere(2);
  const std::string file = writeConstant(dir, "v.txt", input, {0.3f, -1, 2});
  for (const std::string& spec : std::vector<std::string>{"swirl:seed=3", "downhill", file}) {
    std::vector<Vec3f> one, many;
    {
      ThreadLimit limit(1);
      one = SurfaceFlow::parse(spec, input, target.view()).velocities(0);
    }
    {
      ThreadLimit limit(3);
      many = SurfaceFlow::parse(spec, input, target.view()).velocities(0);
    }
    EXPECT_EQ(one, many) << spec;
  }
}

TEST(SurfaceFlow, VertexFilesAreCarriedToTheSynthesisMeshAndProjected) {
  const Target target;
  TempDir dir;
  Mesh input = test::irregularSphere(2);
  input.normals.clear();  // the input mesh's normals are not needed
  const Vec3f velocity(0.3f, -1, 2);
  const std::string file = writeConstant(dir, "v.txt", input, velocity);
  const SurfaceFlow flow = SurfaceFlow::parse(file, input, target.view(), {.scale = 0.5f});
  const std::vector<Vec3f> v = flow.velocities(0);
  expectTangent(v, target.mesh);
  for (std::size_t i = 0; i < v.size(); ++i)
    EXPECT_LT((v[i] - 0.5f * tangentPart(velocity, target.mesh.normals[i])).norm(), 1e-5f);
  EXPECT_FALSE(flow.timeVarying());
  EXPECT_EQ(flow.description(), "per-vertex velocities " + file + ", scale 0.5");
}

TEST(SurfaceFlow, PatternsReadOneFilePerFrame) {
  const Target target;
  TempDir dir;
  const Mesh input = test::icosphere(1);
  writeConstant(dir, "f0.txt", input, Vec3f::UnitX());
  writeConstant(dir, "f1.txt", input, Vec3f::UnitZ());
  const SurfaceFlow flow = SurfaceFlow::parse(dir.file("f%d.txt"), input, target.view());
  EXPECT_TRUE(flow.timeVarying());
  const std::vector<Vec3f> first = flow.velocities(0), second = flow.velocities(1);
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_LT((first[i] - tangentPart(Vec3f::UnitX(), target.mesh.normals[i])).norm(), 1e-5f);
    EXPECT_LT((second[i] - tangentPart(Vec3f::UnitZ(), target.mesh.normals[i])).norm(), 1e-5f);
  }
  flow.requireFrames(3);
  expectInputError([&] { flow.requireFrames(4); }, dir.file("f2.txt"), "does not exist");
  writeLines(dir, "f2.txt", {"1 2 3"});
  expectInputError([&] { flow.requireFrames(4); }, dir.file("f2.txt"), "has 1 velocity lines, the input mesh has 42");
  expectInputError([&] { SurfaceFlow::parse(dir.file("g%03d.txt"), input, target.view()); }, dir.file("g000.txt"));
}

TEST(SurfaceFlow, BadVertexFilesNameTheFileAndLine) {
  const Target target;
  TempDir dir;
  const Mesh input = test::icosphere(0);  // 12 vertices
  auto parse = [&](const std::string& file) { SurfaceFlow::parse(file, input, target.view()); };
  const std::string shortFile = writeLines(dir, "short.txt", {"# three", "1 0 0", "", "0 1 0", "0 0 1"});
  expectInputError([&] { parse(shortFile); }, shortFile, "has 3 velocity lines, the input mesh has 12 vertices");
  std::vector<std::string> lines(13, "0 0 1");
  const std::string longFile = writeLines(dir, "long.txt", lines);
  expectInputError([&] { parse(longFile); }, longFile, "has 13 velocity lines, the input mesh has 12 vertices");
  lines.resize(12);
  lines[3] = "0 abc 1";
  const std::string badNumber = writeLines(dir, "number.txt", lines);
  expectInputError([&] { parse(badNumber); }, badNumber, "line 4: 'abc' is not a finite number");
  lines[3] = "0 1";
  const std::string twoValues = writeLines(dir, "two.txt", lines);
  expectInputError([&] { parse(twoValues); }, twoValues, "line 4: expected 3 numbers (vx vy vz), found 2");
  lines[3] = "0 1 inf";
  const std::string infinite = writeLines(dir, "inf.txt", lines);
  expectInputError([&] { parse(infinite); }, infinite, "line 4: 'inf' is not a finite number");
  expectInputError([&] { parse(dir.file("none.txt")); }, dir.file("none.txt"), "does not exist");
}

TEST(SurfaceFlow, BadSpecsAreFlowParameterErrors) {
  const Target target;
  const Mesh& input = target.mesh;
  auto parse = [&](const std::string& spec, const SurfaceFlowOptions& options = {}) {
    return [&, spec, options] { SurfaceFlow::parse(spec, input, target.view(), options); };
  };
  try {
    parse("swril")();
    ADD_FAILURE() << "accepted an unknown preset";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.parameter(), "flow");
    EXPECT_EQ(e.problem(), "unknown preset 'swril' (along-field, downhill, swirl)");
  }
  expectParameterError(parse("swirl:sed=2"), "flow");
  expectParameterError(parse("downhill:seed=2"), "flow");  // swirl's key only
  expectParameterError(parse("swirl:seed=-1"), "flow");
  expectParameterError(parse("swirl:seed=1.5"), "flow");
  expectParameterError(parse("swirl:strength=inf"), "flow");
  expectParameterError(parse("along-field:strength="), "flow");
  expectParameterError(parse("downhill", {.up = Vec3f::Zero()}), "flow");
  expectParameterError(parse("swirl", {.scale = NAN}), "flowScale");
  expectParameterError(parse("flow/%x.txt"), "flow");
}
