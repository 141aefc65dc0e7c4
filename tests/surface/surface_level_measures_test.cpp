// The rule that keeps a level's refinement (keepsTheTexture): not flatter than a faithful texture
// allows, the distinctive colors kept (keepsTheFeatures), the histogram at most 1.5x as far or
// under the floor; more allowance for a refinement that joins an incoherent start.
#include "texsynth/surface/surface_level_measures.h"

#include <gtest/gtest.h>

using namespace texsynth;

namespace {

SurfaceLevelMeasures measures(double flatness, double histogram, double distinctive, double coherence = 0.05) {
  SurfaceLevelMeasures m;
  m.flatness = flatness, m.histogram = histogram, m.distinctive = distinctive, m.coherence = coherence;
  return m;
}

const SurfaceLevelMeasures kStart = measures(-0.06, 0.010, 0.20);

TEST(KeepsTheTexture, KeepsARefinementThatChangesLittle) {
  EXPECT_TRUE(keepsTheTexture(kStart, kStart));
  EXPECT_TRUE(keepsTheTexture(kStart, measures(0.02, 0.014, 0.19)));
}

TEST(KeepsTheTexture, RefusesAFlatterLevel) {
  EXPECT_FALSE(keepsTheTexture(kStart, measures(0.03, 0.010, 0.20)));  // past 0.025 above a faithful 0
  // Above 0 the tolerance counts from the state itself.
  EXPECT_TRUE(keepsTheTexture(measures(0.1, 0.010, 0.20), measures(0.12, 0.010, 0.20)));
  EXPECT_FALSE(keepsTheTexture(measures(0.1, 0.010, 0.20), measures(0.13, 0.010, 0.20)));
}

TEST(KeepsTheTexture, RefusesLostDistinctiveColors) {
  EXPECT_TRUE(keepsTheTexture(kStart, measures(-0.06, 0.010, 0.181)));
  EXPECT_FALSE(keepsTheTexture(kStart, measures(-0.06, 0.010, 0.179)));  // under 0.9 of 0.2
  // Also from a state that shows more of them than the exemplar's fifth.
  EXPECT_FALSE(keepsTheTexture(measures(-0.06, 0.010, 0.24), measures(-0.06, 0.010, 0.20)));
}

TEST(KeepsTheFeatures, JudgesFlatnessAndDistinctiveColorsButNotTheHistogram) {
  // Flow animation's repaired frames are held to the rule's first two conditions.
  EXPECT_TRUE(keepsTheFeatures(kStart, measures(-0.06, 1.0, 0.181)));
  EXPECT_FALSE(keepsTheFeatures(kStart, measures(0.03, 0.010, 0.20)));
  EXPECT_FALSE(keepsTheFeatures(kStart, measures(-0.06, 0.010, 0.179)));
}

TEST(KeepsTheTexture, RefusesAFarHistogramButNotNoiseUnderTheFloor) {
  EXPECT_TRUE(keepsTheTexture(kStart, measures(-0.06, 0.0149, 0.20)));
  EXPECT_FALSE(keepsTheTexture(kStart, measures(-0.06, 0.0151, 0.20)));
  // A near-perfect histogram may double while it stays under 0.003 ...
  const SurfaceLevelMeasures nearPerfect = measures(-0.06, 0.0012, 0.20);
  EXPECT_TRUE(keepsTheTexture(nearPerfect, measures(-0.06, 0.0029, 0.20)));
  // ... but not past it.
  EXPECT_FALSE(keepsTheTexture(nearPerfect, measures(-0.06, 0.0031, 0.20)));
}

TEST(KeepsTheTexture, AllowsMoreToARefinementThatJoinsAnIncoherentStart) {
  // Coherence distance halved: histogram up to 3x, distinctive share down to 0.8x (a sphere in
  // smooth waves: 2.1x and 0.84x).
  const SurfaceLevelMeasures joined = measures(-0.06, 0.029, 0.161, 0.025);
  EXPECT_TRUE(keepsTheTexture(kStart, joined));
  EXPECT_FALSE(keepsTheTexture(kStart, measures(-0.06, 0.031, 0.161, 0.025)));
  EXPECT_FALSE(keepsTheTexture(kStart, measures(-0.06, 0.029, 0.159, 0.025)));
  // Never flatter.
  EXPECT_FALSE(keepsTheTexture(kStart, measures(0.03, 0.010, 0.20, 0.025)));
  // Not halved: the usual limits.
  EXPECT_FALSE(keepsTheTexture(kStart, measures(-0.06, 0.029, 0.161, 0.026)));
  // Flow animation's rule has no such allowance.
  EXPECT_FALSE(keepsTheFeatures(kStart, joined));
}

}  // namespace
