// Field files: exact round trips and clear errors for damaged files.
#include "texsynth/field/field_io.h"

#include <gtest/gtest.h>

#include "field_test_support.h"

using namespace texsynth;

namespace {

FieldFile sampleField(bool withScale) {
  FieldDesigner d(test::unitCube(), test::smallGrid(6));
  d.addCurve(test::surfaceCurve({{0.1f, 0.2f, 1.0f}, {0.9f, 0.6f, 1.0f}}));
  FieldFile f{d.field(), ScaleField(d.grid(), 1.0f), withScale};
  if (withScale) f.scales = interpolateScales(d.grid(), {{{0.5f, 0.5f, 0.5f}, 3.0f}, {{0.1f, 0.1f, 0.1f}, 1.0f}});
  return f;
}

}  // namespace

TEST(FieldIo, RoundTripIsExact) {
  test::TempDir dir;
  for (bool withScale : {false, true}) {
    FieldFile f = sampleField(withScale);
    writeField(dir.file("f.tsfield"), f);
    FieldFile back = readField(dir.file("f.tsfield"));
    EXPECT_EQ(back.hasScale, withScale);
    EXPECT_EQ(back.rotations.grid().nodes, f.rotations.grid().nodes);
    EXPECT_EQ(back.rotations.grid().origin, f.rotations.grid().origin);
    EXPECT_EQ(back.rotations.grid().spacing, f.rotations.grid().spacing);
    for (std::int64_t i = 0; i < f.rotations.grid().nodeCount(); ++i)
      ASSERT_EQ(back.rotations.at(i).coeffs(), f.rotations.at(i).coeffs());
    EXPECT_EQ(back.scales.scales(), f.scales.scales());
  }
}

TEST(FieldIo, RejectsDamagedFiles) {
  test::TempDir dir;
  std::string bytes = encodeField(sampleField(true));
  auto expectBad = [&](const std::string& data, const std::string& problem) {
    test::writeBytes(dir.file("bad.tsfield"), data);
    test::expectInputError([&] { readField(dir.file("bad.tsfield")); }, dir.file("bad.tsfield"), problem);
  };
  expectBad("hello", "signature");
  expectBad(bytes.substr(0, bytes.size() - 3), "truncated");
  expectBad(bytes + "x", "trailing bytes");
  std::string wrongHeader = bytes;
  wrongHeader[13] = '!';
  expectBad(wrongHeader, "header");
  std::string notUnit = bytes;
  const std::size_t headerEnd = 12 + std::uint8_t(bytes[8]) + 256 * std::uint8_t(bytes[9]);
  notUnit[headerEnd + 3] = char(0x7f);  // the first w becomes huge
  expectBad(notUnit, "unit quaternion");
  test::expectInputError([&] { readField(dir.file("missing.tsfield")); }, dir.file("missing.tsfield"));
}
