// Preparing exemplar sets for gradient synthesis (see gradient_synthesis.h, synthesis_exemplars.h).
#include "synthesis_exemplars.h"

#include <algorithm>
#include <cmath>

#include "texsynth/core/error.h"
#include "texsynth/exemplar/analysis_cache.h"

namespace texsynth {
namespace {

constexpr int kJointHalf = 4;  // leading crossbar dimensions of each crossbar in the joint (E_z) index

// Gray or RGB: alpha is dropped.
Image colorsOf(const Image& image) {
  return image.withChannels(image.channels >= 3 ? 3 : 1);
}

void checkOptions(const GradientExemplarOptions& options) {
  if (options.levelSizes.empty() || options.levelSizes.size() > 6)
    throw ParameterError("levelSizes", "give 1 to 6 neighbourhood sizes, coarsest first");
  for (int n : options.levelSizes)
    if (n < 3 || n % 2 == 0 || n > 31)
      throw ParameterError("levelSizes", "sizes must be odd, in [3, 31], got " + std::to_string(n));
  if (options.pcaDimensions < 1 || options.pcaDimensions > 64)
    throw ParameterError("pcaDimensions", "must be in [1, 64], got " + std::to_string(options.pcaDimensions));
  if (options.crossbarDimensions < 1 || options.crossbarDimensions > 32)
    throw ParameterError("crossbarDimensions", "must be in [1, 32], got " + std::to_string(options.crossbarDimensions));
  if (options.clusters < 2 || options.clusters > 64)
    throw ParameterError("clusters", "must be in [2, 64], got " + std::to_string(options.clusters));
  if (!(options.featureWeight > 0.0f) || !std::isfinite(options.featureWeight))
    throw ParameterError("featureWeight", "must be finite and > 0");
}

}  // namespace

GradientExemplars::GradientExemplars(const std::vector<Image>& planes, const std::vector<Image>& masks,
                                     const GradientExemplarOptions& options, Progress& progress)
    : impl_(std::make_unique<Impl>()) {
  checkOptions(options);
  if (planes.size() != 1 && planes.size() != 3)
    throw ParameterError("exemplarCount", "give one exemplar for all planes, or three: XY YZ ZX");
  if (masks.size() > 1 && masks.size() != planes.size())
    throw ParameterError("maskCount", "give one mask for all planes, or one per exemplar (XY YZ ZX)");
  std::vector<Image> colors;
  for (const Image& plane : planes) {
    if (plane.empty()) throw ParameterError("exemplars", "an exemplar is empty");
    colors.push_back(colorsOf(plane));
    if (colors.back().width != colors[0].width || colors.back().height != colors[0].height ||
        colors.back().channels != colors[0].channels)
      throw ParameterError("exemplars", "the three exemplars must have the same size and channels");
  }
  const int smallest = std::min(colors[0].width, colors[0].height);
  const int coarsest = 1 << (int(options.levelSizes.size()) - 1);
  if (smallest < 8 * coarsest)
    throw ParameterError("exemplars", "are too small: " + std::to_string(smallest) + " pixels, at least " +
                                          std::to_string(8 * coarsest) + " needed for " +
                                          std::to_string(options.levelSizes.size()) + " levels");
  for (const Image& mask : masks)
    if (mask.width != colors[0].width || mask.height != colors[0].height)
      throw ParameterError("masks", "must be the exemplars' size");

  Impl& s = *impl_;
  s.options = options;
  s.width = colors[0].width;
  s.height = colors[0].height;
  s.colorChannels = colors[0].channels;
  s.hasMask = !masks.empty();
  s.features = s.colorChannels + (s.hasMask ? 1 : 0);

  // Exemplar index e of each slice plane: s_x matches YZ (1), s_y ZX (2), s_z XY (0).
  const int exemplarOf[3] = {1, 2, 0};
  std::array<int, 3> source{};  // plane -> index into `planes` (and masks)
  for (int p = 0; p < 3; ++p) source[std::size_t(p)] = planes.size() == 1 ? 0 : exemplarOf[p];
  const int levelCount = int(options.levelSizes.size());
  for (int p = 0; p < 3; ++p) {
    const int e = source[std::size_t(p)];
    const int m = masks.size() <= 1 ? 0 : e;
    for (int q = 0; q < p && !s.analyses[std::size_t(p)]; ++q)
      if (source[std::size_t(q)] == e)
        s.analyses[std::size_t(p)] = s.analyses[std::size_t(q)], s.levels[std::size_t(p)] = s.levels[std::size_t(q)];
    if (s.analyses[std::size_t(p)]) continue;
    AnalysisOptions analysisOptions;
    analysisOptions.levelCount = levelCount;
    analysisOptions.neighborhoodSize = options.levelSizes.back();
    analysisOptions.levelNeighborhoodSizes = options.levelSizes;
    analysisOptions.pcaDimensions = options.pcaDimensions;
    analysisOptions.similarCount = 1;  // matching searches the whole exemplar: no k-coherence sets
    if (s.hasMask) {
      analysisOptions.featureMask = masks[std::size_t(m)];
      analysisOptions.featureWeight = options.featureWeight;
    }
    auto analysis = std::make_shared<const ExemplarAnalysis>(
        options.cacheDirectory.empty()
            ? analyzeExemplar(colors[std::size_t(e)], analysisOptions, progress)
            : analyzeExemplarCached(colors[std::size_t(e)], analysisOptions, options.cacheDirectory, progress));
    s.analyses[std::size_t(p)] = analysis;
    s.levels[std::size_t(p)].resize(std::size_t(levelCount));
    for (int l = 0; l < levelCount; ++l) {
      Impl::Level& level = s.levels[std::size_t(p)][std::size_t(l)];
      level.level = &analysis->levels[std::size_t(l)];
      const int dimensions = level.level->pca.outputDimension, kept = std::min(dimensions, Impl::kTreeDimensions);
      level.leading = std::make_shared<std::vector<float>>(level.level->image.pixelCount() * kept);
      for (std::size_t q = 0; q < level.level->image.pixelCount(); ++q)
        std::copy_n(level.level->projectedAt(std::int32_t(q)), kept, level.leading->data() + q * kept);
      level.nearest =
          std::make_shared<ProjectedNeighborhoodIndex>(PixelVectors{level.leading->data(), s.width, s.height, kept},
                                                       std::vector<std::int32_t>{}, Impl::kTreeEpsilon);
      level.crossbars =
          std::make_shared<CrossbarIndex>(level.level->image, level.level->spacing, level.level->neighborhoodSize);
    }
  }
  // One crossbar basis per level over the distinct planes, so rows of one compare with columns of another.
  progress.begin("exemplar: crossbars", levelCount);
  for (int l = 0; l < levelCount; ++l) {
    std::vector<CrossbarIndex*> distinct;
    for (int p = 0; p < 3; ++p) {
      CrossbarIndex* index = s.levels[std::size_t(p)][std::size_t(l)].crossbars.get();
      if (std::find(distinct.begin(), distinct.end(), index) == distinct.end()) distinct.push_back(index);
    }
    CrossbarIndex::indexTogether(distinct, options.crossbarDimensions, kJointHalf);
    progress.advance();
  }
  progress.end();

  // Clusters of the finest colours over the distinct planes stacked; regions from the masks.
  std::vector<int> distinctSources;
  for (int p = 0; p < 3; ++p)
    if (std::find(distinctSources.begin(), distinctSources.end(), source[std::size_t(p)]) == distinctSources.end())
      distinctSources.push_back(source[std::size_t(p)]);
  const std::size_t planePixels = std::size_t(s.width) * s.height;
  Image stacked(s.width, s.height * int(distinctSources.size()), s.features);
  std::vector<std::uint8_t> regions;
  for (std::size_t i = 0; i < distinctSources.size(); ++i) {
    const int p = int(std::find(source.begin(), source.end(), distinctSources[i]) - source.begin());
    const Image& finest = s.analyses[std::size_t(p)]->levels.back().image;
    std::copy(finest.pixels.begin(), finest.pixels.end(),
              stacked.pixels.begin() + std::ptrdiff_t(i * finest.pixels.size()));
    if (s.hasMask)
      for (std::size_t q = 0; q < planePixels; ++q)
        regions.push_back(finest.pixels[q * s.features + s.colorChannels] < 0.0f ? 1 : 0);
  }
  s.clusters = clusterColors(stacked, options.clusters, regions, s.colorChannels);
  for (int p = 0; p < 3; ++p) {
    const std::size_t i = std::size_t(
        std::find(distinctSources.begin(), distinctSources.end(), source[std::size_t(p)]) - distinctSources.begin());
    s.labels[std::size_t(p)].assign(s.clusters.labels.begin() + std::ptrdiff_t(i * planePixels),
                                    s.clusters.labels.begin() + std::ptrdiff_t((i + 1) * planePixels));
  }
}

GradientExemplars::~GradientExemplars() = default;
GradientExemplars::GradientExemplars(GradientExemplars&&) noexcept = default;
GradientExemplars& GradientExemplars::operator=(GradientExemplars&&) noexcept = default;
int GradientExemplars::colorChannels() const {
  return impl_->colorChannels;
}
bool GradientExemplars::hasMask() const {
  return impl_->hasMask;
}
int GradientExemplars::levels() const {
  return int(impl_->options.levelSizes.size());
}
const GradientExemplarOptions& GradientExemplars::options() const {
  return impl_->options;
}

}  // namespace texsynth
