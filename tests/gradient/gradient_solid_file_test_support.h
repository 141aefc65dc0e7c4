#pragma once
// Random gradient solids for the .tsgs file tests: every kind of array filled, zero slopes included,
// negative sets numbered out of control order (the file puts them in order).
#include <random>

#include "texsynth/gradient/gradient_solid.h"

namespace texsynth::test {

inline GradientSolid randomGradientSolid(const Vec3i& voxels, int channels, bool regions, bool detail,
                                         unsigned seed = 7) {
  GradientSolid solid = GradientSolid::zeros(voxels, channels, 4);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  // Values in [lo, hi], slopes up to `slope`, every fifth slope exactly zero.
  auto fill = [&](std::vector<float>& sets, int setChannels, float lo, float hi, float slope) {
    for (std::size_t i = 0; i < sets.size(); ++i) {
      const bool value = i % std::size_t(4 * setChannels) < std::size_t(setChannels);
      sets[i] = value ? lo + (hi - lo) * unit(rng) : (i % 5 == 0 ? 0.0f : slope * (2 * unit(rng) - 1));
    }
  };
  fill(solid.positive, channels, 0.0f, 1.0f, 0.3f);
  const auto n = std::size_t(solid.controlCount());
  if (regions) {
    solid.distance.resize(4 * n);
    fill(solid.distance, 1, -6.0f, 6.0f, 2.0f);
    solid.negativeIndex.assign(n, -1);
    int sets = 0;
    for (std::size_t i = n; i-- > 0;)  // reverse order on purpose
      if (std::abs(solid.distance[4 * i]) < 3.0f) solid.negativeIndex[i] = sets++;
    solid.negative.resize(std::size_t(sets) * std::size_t(solid.setSize()));
    fill(solid.negative, channels, 0.2f, 0.9f, 0.25f);
  }
  if (detail) {
    solid.detail.resize(n * std::size_t(solid.setSize()));
    fill(solid.detail, channels, -0.01f, 0.05f, 0.01f);  // a few negative sigmas, stored as 0
  }
  solid.checkConsistent();
  return solid;
}

}  // namespace texsynth::test
