// Real peer: G'MIC's patch-based synthesis of a real GIMP stone pattern against a plain
// tiling of the same exemplar. Periodicity and lattice must tell them apart.
#include <gtest/gtest.h>

#include <cstdlib>

#include "eval_test_images.h"
#include "test_support.h"
#include "texsynth/core/data_paths.h"
#include "texsynth/eval/metrics.h"
#include "texsynth/io/image_io.h"

namespace texsynth {
namespace {

bool gmicAvailable() {
  return std::system("command -v gmic >/dev/null 2>&1") == 0;
}

TEST(GmicPeer, TilingIsFarMorePeriodicThanGmicSynthesis) {
  auto pattern = gimpPattern("Stone/stone33.pat");  // 156x156 RGB, no internal repetition
  TS_REQUIRE_DATA(pattern);
  if (!gmicAvailable()) GTEST_SKIP() << "gmic is not on PATH";

  test::TempDir dir;
  const Image exemplar = readImage(*pattern).withChannels(3).crop(10, 10, 128, 128);
  writeImage(dir.file("exemplar.png"), exemplar);
  // One OpenMP thread and a fixed seed make G'MIC's synthesis reproducible.
  const std::string command = "OMP_NUM_THREADS=1 gmic srand 1 " + dir.file("exemplar.png") +
                              " syntexturize_matchpatch 256,256 -o " + dir.file("gmic.png") + " >/dev/null 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const Image synthesized = readImage(dir.file("gmic.png"));
  ASSERT_EQ(synthesized.width, 256);
  ASSERT_EQ(synthesized.height, 256);

  const QualityMetrics tiling = evaluateImage(exemplar, exemplar.tiled(256, 256));
  const QualityMetrics gmic = evaluateImage(exemplar, synthesized);
  RecordProperty("tiling_periodicity", std::to_string(tiling.periodicity));
  RecordProperty("gmic_periodicity", std::to_string(gmic.periodicity));
  RecordProperty("tiling_lattice", std::to_string(tiling.lattice));
  RecordProperty("gmic_lattice", std::to_string(gmic.lattice));
  std::printf("tiling: coherence %.3f completeness %.3f histogram %.3f periodicity %.3f lattice %.3f (%.2fs)\n",
              tiling.coherence, tiling.completeness, tiling.histogram, tiling.periodicity, tiling.lattice,
              tiling.seconds);
  std::printf("gmic:   coherence %.3f completeness %.3f histogram %.3f periodicity %.3f lattice %.3f (%.2fs)\n",
              gmic.coherence, gmic.completeness, gmic.histogram, gmic.periodicity, gmic.lattice, gmic.seconds);
  EXPECT_GT(tiling.periodicity, 0.5);
  EXPECT_LT(gmic.periodicity, tiling.periodicity / 2);
  EXPECT_GT(tiling.lattice, 0.8);
  EXPECT_LT(gmic.lattice, tiling.lattice / 2);
  // Both reuse exemplar content, so both stay coherent; the tiling invents only its seams.
  EXPECT_LT(gmic.coherence, 40.0);
  EXPECT_LT(tiling.completeness, 1e-9);
}

}  // namespace
}  // namespace texsynth
