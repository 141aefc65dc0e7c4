// Writes 512x512 outputs next to their exemplars for looking at by eye, only when
// $TEXSYNTH_LOOK_DIR names a directory (skipped otherwise, so normal runs stay fast).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "image_test_support.h"
#include "texsynth/eval/histogram_distance.h"
#include "texsynth/image/tile_blend.h"
#include "texsynth/image/tile_deform.h"

namespace texsynth {
namespace {

TEST(Look, WritesOutputsForGimpPatterns) {
  const char* dir = std::getenv("TEXSYNTH_LOOK_DIR");
  if (!dir) GTEST_SKIP() << "set TEXSYNTH_LOOK_DIR to write images";
  for (const char* name : {"Stone/marble1.pat", "Stone/granite1.pat", "Wood/bark.pat", "Wood/wood1.pat"}) {
    auto path = gimpPattern(name);
    if (!path) continue;
    Image exemplar = test::loadPatternRgb(*path, 128);
    std::string stem = std::string(dir) + "/" + std::filesystem::path(name).stem().string();
    Image tiling = exemplar.tiled(512, 512);
    Image deformed = synthesizeTileDeform(exemplar, {}, 0, 0, 512, 512);
    Image blended = synthesizeTileBlend(exemplar, {}, 0, 0, 512, 512);
    writeImage(stem + "_exemplar.png", exemplar);
    writeImage(stem + "_tiling.png", tiling);
    writeImage(stem + "_tile_deform.png", deformed);
    writeImage(stem + "_tile_blend.png", blended);
    std::printf("%-20s %dx%d periodicity tiling %.3f deform %.3f blend %.3f | histogram deform %.4f blend %.4f\n", name,
                exemplar.width, exemplar.height, test::periodicityOf(tiling), test::periodicityOf(deformed),
                test::periodicityOf(blended), histogramDistance(exemplar, deformed), histogramDistance(exemplar, blended));
  }
}

}  // namespace
}  // namespace texsynth
