// End-to-end checks of input files a user can get wrong: a directory or a missing file is named
// as such before any work (exit 1), float volumes and colour images holding NaN, infinities or
// absurd values are refused naming the file (exit 1), and eval refuses a patch larger than a
// volume's slices at once (exit 2, naming --patch) instead of computing for minutes.
#include <gtest/gtest.h>

#include <limits>

#include "cli_runner.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/volume_io.h"

using namespace texsynth;
using test::RunResult;

namespace {

struct Inputs {
  test::TempDir dir;
  std::string exemplar = dir.file("ex.png"), volume = dir.file("vol.nrrd");

  Inputs() {
    writeImage(exemplar, test::makeTestPattern(64, 64));
    writeVolume(volume, Volume(32, 32, 32, 3, 0.5f));
  }
  RunResult run(const std::string& arguments) const { return test::runTexsynth(arguments + " --quiet", dir); }
  // A 16^3 float RGB volume of plain colour with voxel (1, 2, 3) channel 2 set to `value`.
  std::string volumeHolding(const std::string& name, float value) const {
    Volume volume(16, 16, 16, 3, 0.5f);
    volume.at(1, 2, 3, 2) = value;
    writeVolume(dir.file(name), volume, {.gzip = false});
    return dir.file(name);
  }
};

}  // namespace

TEST(ReliabilityInputs, EvalRefusesAPatchLargerThanTheVolumeSlicesAtOnce) {
  Inputs in;
  RunResult r = in.run("eval " + in.exemplar + " " + in.volume + " --patch 33");
  test::expectOneLineError(r, 2, "--patch");
  EXPECT_NE(r.err.find("32x32 slices"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("at most 31"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("volume slice"), std::string::npos) << r.err;  // no library name
  // A patch that fits still works.
  EXPECT_EQ(in.run("eval " + in.exemplar + " " + in.volume + " --patch 5 --slices 2").exitCode, 0);
}

TEST(ReliabilityInputs, VolumesWithNonFiniteOrAbsurdValuesAreRefusedNamingTheFile) {
  Inputs in;
  const std::pair<float, const char*> cases[] = {{1e30f, "1e+30"}, {std::numeric_limits<float>::quiet_NaN(), "NaN"}};
  for (const auto& [value, text] : cases) {
    SCOPED_TRACE(text);
    const std::string volume = in.volumeHolding("bad.nrrd", value);
    RunResult r = in.run("vectorize " + volume + " -o " + in.dir.file("out.tsgs"));
    test::expectOneLineError(r, 1, volume);
    EXPECT_NE(r.err.find(std::string("voxel (1, 2, 3) channel 2 holds ") + text), std::string::npos) << r.err;
    r = in.run("eval " + in.exemplar + " " + volume + " --patch 5");
    test::expectOneLineError(r, 1, volume);
    EXPECT_NE(r.err.find(std::string("voxel (1, 2, 3) channel 2 holds ") + text), std::string::npos) << r.err;
  }
  EXPECT_EQ(in.run("eval " + in.exemplar + " " + in.volumeHolding("hdr.nrrd", 40.0f) + " --patch 5").exitCode, 0);
}

TEST(ReliabilityInputs, EvalRefusesColourImagesWithAbsurdValues) {
  Inputs in;
  Image image = test::makeTestPattern(24, 24);
  image.at(7, 5, 0) = 1e30f;
  const std::string output = in.dir.file("out.exr");
  writeImage(output, image);
  RunResult r = in.run("eval " + in.exemplar + " " + output);
  test::expectOneLineError(r, 1, output);
  EXPECT_NE(r.err.find("pixel (7, 5) channel 0 holds 1e+30"), std::string::npos) << r.err;
  image.at(7, 5, 0) = std::numeric_limits<float>::infinity();
  writeImage(output, image);
  test::expectOneLineError(in.run("eval " + output + " " + in.exemplar), 1, output);
}

TEST(ReliabilityInputs, DirectoriesAndMissingFilesAreNamedAsSuch) {
  Inputs in;
  const std::string directory = in.dir.file("folder.png"), missing = in.dir.file("missing.xyz");
  ASSERT_EQ(std::system(("mkdir " + directory).c_str()), 0);
  for (const std::string& arguments :
       {"info " + in.dir.path(), "info " + directory, "eval " + directory + " " + in.volume,
        "vectorize " + directory + " -o " + in.dir.file("out.tsgs")}) {
    SCOPED_TRACE(arguments);
    RunResult r = in.run(arguments);
    test::expectOneLineError(r, 1, "is a directory, not a file");
    EXPECT_EQ(r.err.find("unknown file type"), std::string::npos) << r.err;
  }
  for (const std::string& arguments : {"info " + missing, "eval " + in.exemplar + " " + missing,
                                       "vectorize " + missing + " -o " + in.dir.file("o.tsgs")}) {
    SCOPED_TRACE(arguments);
    RunResult r = in.run(arguments);
    test::expectOneLineError(r, 1, missing + ": file does not exist");
  }
}
