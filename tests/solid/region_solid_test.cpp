// RegionSolidTexture: each point goes to its region's part, for preparing and for values;
// the surface-shell rule splits a box into a shell and a core.
#include "texsynth/solid/region_solid.h"

#include <gtest/gtest.h>

#include "test_support.h"
#include "texsynth/render/primitives.h"

namespace texsynth {
namespace {

// A solid of one constant value that records what it was asked to prepare.
class ConstantSolid : public SolidTexture {
 public:
  explicit ConstantSolid(float value) : value_(value) {}
  std::string name() const override { return "constant"; }
  int channels() const override { return 3; }
  void prepare(std::span<const Vec3f> points, Progress&) override {
    prepared.insert(prepared.end(), points.begin(), points.end());
  }
  bool preparesOnDemand() const override { return true; }
  void evaluateSerial(std::span<const Vec3f>, std::span<const Vec3f>, std::span<float> values) const override {
    std::fill(values.begin(), values.end(), value_);
  }
  std::vector<Vec3f> prepared;

 private:
  float value_;
};

TEST(RegionSolid, EachPointUsesAndPreparesItsRegionsPart) {
  auto left = std::make_shared<ConstantSolid>(0.25f), right = std::make_shared<ConstantSolid>(0.75f);
  RegionSolidTexture regions({left, right}, [](const Vec3f& p) { return p.x() < 0 ? 0 : 1; });
  EXPECT_TRUE(regions.preparesOnDemand());
  std::vector<Vec3f> points = {{-1, 0, 0}, {2, 0, 0}, {-3, 1, 0}};
  regions.prepare(points);
  ASSERT_EQ(left->prepared.size(), 2u);
  ASSERT_EQ(right->prepared.size(), 1u);
  EXPECT_EQ(right->prepared[0], Vec3f(2, 0, 0));
  std::vector<Vec3f> colors = regions.evaluateColors(points);
  EXPECT_EQ(colors[0], Vec3f::Constant(0.25f));
  EXPECT_EQ(colors[1], Vec3f::Constant(0.75f));
  EXPECT_EQ(colors[2], Vec3f::Constant(0.25f));
}

TEST(RegionSolid, SurfaceShellRuleSplitsByDepth) {
  Mesh box = makeBoxMesh(Vec3f::Zero(), Vec3f::Ones());
  auto rule = surfaceShellRule(box, 0.1f);
  EXPECT_EQ(rule(Vec3f(0.5f, 0.5f, 0.5f)), 1);   // the centre is 0.5 deep
  EXPECT_EQ(rule(Vec3f(0.5f, 0.5f, 0.95f)), 0);  // 0.05 below the top face
  EXPECT_EQ(rule(Vec3f(0.05f, 0.5f, 0.5f)), 0);  // near a side
  EXPECT_EQ(rule(Vec3f(0.5f, 0.5f, 0.85f)), 1);  // 0.15 deep
  EXPECT_EQ(rule(Vec3f(2.0f, 0.5f, 0.5f)), 0);   // far outside is shell, never core
  test::expectParameterError([&] { surfaceShellRule(box, 0.0f); }, "depth");
}

TEST(RegionSolid, RejectsBadParts) {
  auto part = std::make_shared<ConstantSolid>(0.5f);
  auto rule = [](const Vec3f&) { return 0; };
  test::expectParameterError([&] { RegionSolidTexture({}, rule); }, "parts");
  test::expectParameterError([&] { RegionSolidTexture({part, nullptr}, rule); }, "parts");
  test::expectParameterError([&] { RegionSolidTexture({part}, {}); }, "rule");
}

}  // namespace
}  // namespace texsynth
