// End-to-end checks of what the CLI accepts: garbage values and flags a mode ignores are refused
// (exit 2, one line naming the flag as typed), bad data in input files is an input error naming
// the file (exit 1), and no library-internal parameter name ever reaches the user.
#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <sstream>
#include <vector>

#include "cli_runner.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/render/primitives.h"

using namespace texsynth;
using test::RunResult;
using test::runTexsynth;

namespace {

// Small inputs every case shares, written once per test.
struct Inputs {
  test::TempDir dir;
  std::string exemplar = dir.file("ex.png"), tiny = dir.file("one.png"), mask = dir.file("mask.png");
  std::string cube = dir.file("cube.ply"), flat = dir.file("flat.off"), sketch = dir.file("sketch.json");
  std::string volume = dir.file("vol.nrrd"), colored = dir.file("colored.ply");
  std::string solid = dir.file("solid.tsgs"), strokes = dir.file("strokes.json");

  Inputs() {
    writeImage(exemplar, test::makeTestPattern(32, 32));
    writeImage(tiny, test::makeTestPattern(1, 1));
    Image mask4(4, 4, 1, 0.0f);
    mask4.pixels[5] = 1.0f;
    writeImage(mask, mask4);
    writeMesh(cube, makeBoxMesh(Vec3f::Zero(), Vec3f::Ones()));
    test::writeBytes(flat, "OFF\n3 1 0\n0.5 0.5 0.5\n0.5 0.5 0.5\n0.5 0.5 0.5\n3 0 1 2\n");
    test::writeBytes(sketch, R"({"curves": [{"points": [[0.1, 0.2, 1.0], [0.5, 0.5, 1.0], [0.9, 0.6, 1.0]]}]})");
    test::writeBytes(strokes, R"({"color": [1, 0, 0], "strokes": [{"points": [[2, 2, 2], [6, 6, 6]]}]})");
    // A closed octahedron with vertex colors: eval's mesh mode.
    Mesh octahedron;
    octahedron.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    octahedron.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    octahedron.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};
    writeMesh(colored, octahedron);
  }
  RunResult run(const std::string& arguments) const { return runTexsynth(arguments + " --quiet", dir); }
  std::string image(const std::string& flags) const {
    return "image " + exemplar + " -o " + dir.file("out.png") + " --size 8 " + flags;
  }
};

// Stderr without the temporary directory's random name (which may look like camelCase).
std::string withoutDir(const RunResult& r, const test::TempDir& dir) {
  std::string err = r.err;
  for (std::size_t at; (at = err.find(dir.path())) != std::string::npos;) err.replace(at, dir.path().size(), "DIR");
  return err;
}

// A library field name (patchSize, maxDisplacement ...) somewhere in the text.
bool hasInternalName(const std::string& text) {
  static const std::regex camelCase("\\b[a-z]+[A-Z][A-Za-z]*\\b");
  return std::regex_search(text, camelCase);
}

// Exit 2, one line naming `flag`, no internal name.
void expectUsageError(const Inputs& in, const std::string& arguments, const std::string& flag) {
  SCOPED_TRACE(arguments);
  RunResult r = in.run(arguments);
  test::expectOneLineError(r, 2, flag);
  EXPECT_FALSE(hasInternalName(withoutDir(r, in.dir))) << r.err;
}

}  // namespace

// Class 4: accepted garbage.

TEST(ReliabilityArguments, WindowsBeyondTwoToThe28AreRejectedByEveryRandomAccessMethod) {
  Inputs in;
  for (const char* method : {"tile-deform", "tile-blend", "parallel"}) {
    expectUsageError(in, in.image(std::string("--method ") + method + " --window 288230376151711744,0,16,4"),
                     "--window");
    expectUsageError(in, in.image(std::string("--method ") + method + " --window 9223372036854775000,0,4,4"),
                     "--window");
  }
  EXPECT_EQ(in.run(in.image("--method tile-blend --window -268435000,268435000,16,4")).exitCode, 0);
}

TEST(ReliabilityArguments, CoordinatesGoOnlyToAndFromFloatExr) {
  Inputs in;
  expectUsageError(in, in.image("--method parallel --coords " + in.dir.file("c.png")), "--coords");
  const std::string coords = in.dir.file("c.exr");
  ASSERT_EQ(in.run(in.image("--method parallel --coords " + coords)).exitCode, 0);
  EXPECT_EQ(readImageInfo(coords).bitsPerChannel, 32);  // pixel indices kept exactly
  const std::string apply = "image " + in.exemplar + " -o " + in.dir.file("applied.png") + " --apply-coords ";
  ASSERT_EQ(in.run(apply + coords).exitCode, 0);
  expectUsageError(in, apply + in.dir.file("out.png"), "--apply-coords");
  writeImage(in.dir.file("fake.png"), readImage(in.exemplar));  // PNG content under an .exr name
  std::rename(in.dir.file("fake.png").c_str(), in.dir.file("fake.exr").c_str());
  test::expectOneLineError(in.run(apply + in.dir.file("fake.exr")), 1, "fake.exr");
}

TEST(ReliabilityArguments, SeedIsAPlainUnsigned64BitInteger) {
  Inputs in;
  for (const char* seed : {"-1", "18446744073709551616", "1.5", "0x10"})
    expectUsageError(in, in.image(std::string("--seed=") + seed), "--seed");
  EXPECT_EQ(in.run(in.image("--seed 18446744073709551615")).exitCode, 0);
}

TEST(ReliabilityArguments, LevelsAndSimilarCountRejectNegatives) {
  Inputs in;
  expectUsageError(in, in.image("--method parallel --levels=-1"), "--levels");
  expectUsageError(in, in.image("--method parallel --levels 100"), "--levels");
  expectUsageError(in, in.image("--method parallel --similar=-1"), "--similar");
}

TEST(ReliabilityArguments, NonFiniteFloatsAreRejected) {
  Inputs in;
  expectUsageError(in, in.image("--seam-threshold nan"), "--seam-threshold");
  expectUsageError(in, in.image("--noise-frequency inf"), "--noise-frequency");
  expectUsageError(in, in.image("--method tile-blend --blend-exponent 1e300"), "--blend-exponent");
}

TEST(ReliabilityArguments, TileDeformClampHasOneRuleIn2DAndSolids) {
  Inputs in;
  for (const char* clamp : {"0.5", "1"}) {
    expectUsageError(in, in.image(std::string("--clamp ") + clamp), "--clamp");
    expectUsageError(in, "solid " + in.exemplar + " --slice z=0.5 -o " + in.dir.file("s.png") + " --clamp " + clamp,
                     "--clamp");
  }
}

TEST(ReliabilityArguments, FieldWeightStaysWhereTheSolverConverges) {
  Inputs in;
  const std::string field =
      "field " + in.cube + " --sketch " + in.sketch + " -o " + in.dir.file("f.tsfield") + " --grid 4 --weight ";
  for (const char* weight : {"1e20", "1e6", "0.5", "0"}) expectUsageError(in, field + weight, "--weight");
  EXPECT_EQ(in.run(field + "1e4").exitCode, 0);
}

TEST(ReliabilityArguments, FlagsTheModeIgnoresAreRejected) {
  Inputs in;
  ASSERT_EQ(in.run(in.image("--method parallel --coords " + in.dir.file("c.exr"))).exitCode, 0);
  const std::string apply =
      "image " + in.exemplar + " -o " + in.dir.file("applied.png") + " --apply-coords " + in.dir.file("c.exr") + " ";
  expectUsageError(in, apply + "--method parallel", "--method");
  expectUsageError(in, apply + "--window 0,0,4,4", "--window");
  expectUsageError(in, in.image("--method tile-blend --cell 4"), "--cell");
  expectUsageError(in, in.image("--method optimize --window 0,0,8,8"), "--window");
  expectUsageError(
      in, "solid " + in.exemplar + " --method tile-blend --slice z=0.5 -o " + in.dir.file("s.png") + " --levels 3",
      "--levels");
  expectUsageError(in, "field " + in.cube + " --sketch " + in.sketch + " -o " + in.dir.file("f.tsfield") + " --views 2",
                   "--views");
}

// Class 5: messages that do not help.

TEST(ReliabilityArguments, LibraryParameterNamesBecomeTheFlagsTyped) {
  Inputs in;
  expectUsageError(in, in.image("--lambda -1"), "--lambda");
  expectUsageError(in, in.image("--cell 0,-3"), "--cell");
  expectUsageError(in, "image " + in.mask + " -o " + in.dir.file("o.png") + " --size 8 --method parallel -k 20", "-k");
  expectUsageError(in, "eval " + in.exemplar + " " + in.exemplar + " --patch 4", "--patch");
  const std::string solid = "solid " + in.exemplar + " --slice z=0.5 -o " + in.dir.file("s.png") + " --resolution 8 ";
  expectUsageError(in, solid + "--cell=-2", "--cell");
  expectUsageError(in, solid + "--method lazy --grid-cell 5", "--grid-cell");
}

TEST(ReliabilityArguments, BadDataInInputFilesIsAnInputErrorNamingTheFile) {
  Inputs in;
  auto expectInputError = [&](const std::string& arguments, const std::string& file) {
    SCOPED_TRACE(arguments);
    RunResult r = in.run(arguments);
    test::expectOneLineError(r, 1, file);
    EXPECT_EQ(r.err.find("bad parameter"), std::string::npos) << r.err;
    EXPECT_FALSE(hasInternalName(withoutDir(r, in.dir))) << r.err;
  };
  expectInputError("image " + in.tiny + " -o " + in.dir.file("o.png") + " --size 8", in.tiny);
  expectInputError("solid " + in.exemplar + " --mesh " + in.flat + " -o " + in.dir.file("c.ply"), in.flat);
  expectInputError("solid " + in.exemplar + " --method lazy --mask " + in.mask + " --slice z=0.5 -o " +
                       in.dir.file("s.png") + " --resolution 8",
                   in.mask);
  expectInputError("eval " + in.tiny + " " + in.exemplar, in.tiny);
}

TEST(ReliabilityArguments, ThreadsRangeIsReadable) {
  Inputs in;
  for (const char* threads : {"-1", "5000"}) {
    RunResult r = in.run(in.image(std::string("--threads=") + threads));
    test::expectOneLineError(r, 2, "--threads");
    EXPECT_NE(r.err.find("[0, 1024]"), std::string::npos) << r.err;
  }
}

TEST(ReliabilityArguments, OutOfMemoryNamesTheFlagsThatDriveIt) {
  Inputs in;
  // A 256 MiB address-space limit: the up-front estimate (1.6 GB) sees the machine's memory, the
  // allocation of the 5000x5000 result fails.
  const std::string command = "ulimit -v 262144; TEXSYNTH_CACHE=" + in.dir.file("cache") + " " + TEXSYNTH_BINARY +
                              " image " + in.exemplar + " -o " + in.dir.file("big.png") + " --size 5000 --quiet 2>" +
                              in.dir.file("err.txt");
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  const std::string err = readFileBytes(in.dir.file("err.txt"));
  EXPECT_EQ(WEXITSTATUS(status), 1) << err;
  EXPECT_NE(err.find("out of memory: lower --size"), std::string::npos) << err;
}

// The sweep: every numeric option of every subcommand, with values no one should get away with.

namespace {

struct HelpOption {
  std::vector<std::string> names;  // "-k", "--similar"
  std::string longName, description;
};

// The options of a --help text that take a number: typed INT, UINT, FLOAT or NUMBER, text with a
// numeric default (--size, --cell), or the text options that hold lists of numbers. CLI11 prints
// each option as "  NAMES TYPE[=DEFAULT]" padded to column 30, then its description, which moves
// to the next line when the names run past that column.
std::vector<HelpOption> numericOptions(const std::string& help) {
  constexpr std::size_t kColumn = 30;
  static const std::regex number(R"(^-?[0-9.]+$)");
  std::vector<std::string> lines;
  std::istringstream stream(help);
  for (std::string text; std::getline(stream, text);) lines.push_back(text);
  std::vector<HelpOption> options;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].rfind("  -", 0) != 0) continue;
    const bool wrapped = i + 1 < lines.size() && lines[i + 1].rfind(std::string(kColumn, ' '), 0) == 0;
    const std::string left = wrapped ? lines[i] : lines[i].substr(0, kColumn);
    HelpOption option;
    option.description = wrapped                     ? lines[i + 1].substr(kColumn)
                         : lines[i].size() > kColumn ? lines[i].substr(kColumn)
                                                     : "";
    std::istringstream words(left);
    std::string names, type;
    words >> names >> type;
    const std::size_t equals = type.find('=');
    const std::string fallback = equals == std::string::npos ? "" : type.substr(equals + 1);
    type = type.substr(0, std::min(type.find(':'), equals));
    const bool numericType = type == "INT" || type == "UINT" || type == "FLOAT" || type == "NUMBER";
    const bool numericText = type == "TEXT" && (std::regex_match(fallback, number) || names == "--window" ||
                                                names == "--jitter" || names == "--neighborhood");
    if (!numericType && !numericText) continue;
    std::istringstream split(names);
    for (std::string name; std::getline(split, name, ',');) {
      option.names.push_back(name);
      if (name.rfind("--", 0) == 0) option.longName = name;
    }
    if (!option.longName.empty()) options.push_back(option);
  }
  return options;
}

// A minimal fast command in which `option` does something (its method, or what else it needs),
// with small outputs wherever it is not the size being swept.
std::string sweepCommand(const std::string& command, const HelpOption& option, const Inputs& in) {
  const std::string& flag = option.longName;
  const std::string out = in.dir.file("sweep");
  std::string base;
  if (command == "image") base = "image " + in.exemplar + " -o " + out + ".png" + (flag == "--size" ? "" : " --size 8");
  if (command == "solid") {
    base = "solid " + in.exemplar + " --slice z=0.5 -o " + out + ".png --resolution 8";
    if (flag == "--render-size" || flag == "--views") base += " --mesh " + in.cube + " --render " + out + "_r.png";
    if (flag == "--surface") base += " --mesh " + in.cube;
    if (flag == "--shell") base += " --mesh " + in.cube + " --inner " + in.exemplar;
  }
  if (command == "field") {
    base = "field " + in.cube + " --sketch " + in.sketch + " -o " + out + ".tsfield --grid 4";
    if (flag == "--grid") base.resize(base.size() - 9);
    if (flag == "--render-size" || flag == "--views" || flag == "--glyphs") base += " --render " + out + "_g.png";
  }
  if (command == "render") base = "render " + in.cube + " -o " + out + ".png" + (flag == "--size" ? "" : " --size 16");
  if (command == "eval")
    base = "eval " + in.exemplar + " " +
           (flag == "--slices"    ? in.volume
            : flag == "--samples" ? in.colored
                                  : in.exemplar);
  if (command == "demo") base = "demo -o " + out + " --exemplar " + in.exemplar + " --mesh " + in.cube;
  const std::string& d = option.description;
  // The commands of the second reliability pass; mesh runs on a small retiling of the cube.
  const auto unless = [&](const char* swept, const std::string& text) { return flag == swept ? "" : " " + text; };
  const std::string smallMesh =
      " --mesh " + in.cube + unless("--vertices", "--vertices 600") + unless("--levels", "--levels 1");
  if (command == "animate") {
    const bool mesh = d.rfind("With --mesh", 0) == 0;  // a mesh flows along a surface preset
    base = "animate " + in.exemplar + (mesh ? " --flow swirl" : " --flow vortex") + " -o " + out + "/%04d.png" +
           unless("--frames", "--frames 2") +
           (mesh ? smallMesh + unless("--render-size", "--render-size 16") : unless("--size", "--size 8"));
  }
  if (command == "surface") {
    base = "surface " + in.exemplar + smallMesh + " -o " + out + ".ply";
    if (d.rfind("With --render", 0) == 0)
      base += " --render " + out + "_r.png" + unless("--render-size", "--render-size 16");
    if (d.rfind("With --bake", 0) == 0) base += " --bake " + out + "_b.png";
  }
  if (command == "edit") base = "edit " + in.solid + " --strokes " + in.strokes + " -o " + out + ".tsgs";
  if (command == "vectorize")
    base = "vectorize " + in.volume + " -o " + out + ".tsgs" + (d.rfind("--optimize", 0) == 0 ? " --optimize" : "");
  if (d.rfind("lazy", 0) == 0)  // one level without passes: accepted values finish in a second
    base += std::string(" --method lazy") + (flag == "--levels" ? "" : " --levels 1") +
            (flag == "--coarsest-passes" ? "" : " --coarsest-passes 0");
  for (const char* method : {"tile-blend", "parallel", "optimize", "gradient"})
    if (d.rfind(method, 0) == 0) base += std::string(" --method ") + method;
  return base + " " + flag + "=";
}

}  // namespace

TEST(ReliabilityArguments, SweepOfEveryNumericFlag) {
  Inputs in;
  ASSERT_EQ(in.run("solid " + in.exemplar + " -o " + in.volume + " --resolution 16").exitCode, 0);
  ASSERT_EQ(in.run("vectorize " + in.volume + " -o " + in.solid).exitCode, 0);
  const std::map<std::string, std::size_t> expected = {{"image", 16}, {"solid", 17},   {"field", 7},   {"render", 5},
                                                       {"eval", 4},   {"demo", 2},     {"animate", 9}, {"surface", 6},
                                                       {"edit", 3},   {"vectorize", 2}};
  const std::vector<std::string> values = {"nan", "inf", "-1", "0", "1e300", "99999999999999999999"};
  int tried = 0;
  for (const auto& [name, minimum] : expected) {
    RunResult help = in.run(name + " --help");
    ASSERT_EQ(help.exitCode, 0) << help.err;
    std::vector<HelpOption> options = numericOptions(help.out);
    EXPECT_GE(options.size(), minimum) << help.out;
    if (name == "image") {  // the global flags, once
      options.push_back({{"--seed"}, "--seed", ""});
      options.push_back({{"--threads"}, "--threads", ""});
    }
    for (const HelpOption& option : options)
      for (const std::string& value : values) {
        const std::string command = sweepCommand(name, option, in) + value;
        SCOPED_TRACE(command);
        RunResult r = in.run(command);
        ++tried;
        const std::string err = withoutDir(r, in.dir);
        EXPECT_TRUE(r.exitCode == 0 || r.exitCode == 2) << r.exitCode << ": " << r.err;
        EXPECT_EQ(err.find("unexpected error"), std::string::npos) << r.err;
        EXPECT_EQ(err.find("bug in texsynth"), std::string::npos) << r.err;
        EXPECT_EQ(err.find("does nothing"), std::string::npos) << r.err;  // the sweep gave the flag its mode
        EXPECT_FALSE(hasInternalName(err)) << r.err;
        if (r.exitCode == 0) continue;
        EXPECT_EQ(test::lineCount(r.err), 1) << r.err;
        bool named = false;
        for (const std::string& flag : option.names) named = named || r.err.find(flag) != std::string::npos;
        EXPECT_TRUE(named) << r.err;
      }
  }
  EXPECT_GT(tried, 370);
}

// The sweep's values in every numeric key of every flow preset: refused as typed, naming --flow.
TEST(ReliabilityArguments, SweepOfEveryFlowPresetValue) {
  Inputs in;
  const std::vector<std::string> presets = {
      "uniform:dx=",        "uniform:dy=",     "vortex:strength=", "vortex:cx=",
      "source:cy=",         "sink:radius=",    "saddle:strength=", "along-field:strength=",
      "downhill:strength=", "swirl:strength=", "swirl:seed="};
  for (const std::string& preset : presets)
    for (const char* value : {"nan", "inf", "-1e300", "1e300", "99999999999999999999", "x"}) {
      const std::string command = "animate " + in.exemplar + " --flow " + preset + value + " --size 8 --frames 2 -o " +
                                  in.dir.file("f/%04d.png");
      SCOPED_TRACE(command);
      expectUsageError(in, command, "--flow");
    }
}
