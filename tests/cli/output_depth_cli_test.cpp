// `texsynth image` keeps a 16-bit exemplar's depth in PNG outputs (it used to drop to 8 bits).
#include <gtest/gtest.h>

#include "cli_runner.h"
#include "texsynth/io/image_io.h"

using namespace texsynth;
using test::RunResult;
using test::runTexsynth;

TEST(OutputDepthCli, SixteenBitExemplarGivesSixteenBitPngAndEightBitStaysEightBit) {
  test::TempDir dir;
  Image exemplar = test::makeTestPattern(48, 40);
  writeImage(dir.file("deep.png"), exemplar, {.bitsPerChannel = 16});
  writeImage(dir.file("shallow.png"), exemplar);
  for (const char* name : {"deep", "shallow"}) {
    std::string output = dir.file(std::string(name) + "_out.png");
    RunResult r = runTexsynth("image " + dir.file(std::string(name) + ".png") +
                                  " --method tile-deform --tileable never --size 64 --quiet -o " + output,
                              dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(readImageInfo(output).bitsPerChannel, std::string(name) == "deep" ? 16 : 8) << name;
  }
}
