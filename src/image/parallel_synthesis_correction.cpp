// k-coherence correction of parallel synthesis (Lefebvre & Hoppe 2005, section 3.4): each
// pixel of a subpass compares its neighborhood of colors (gathered at the current source
// coordinates, spacing 1 on the synthesized grid) with the exemplar neighborhoods of its
// coherent candidates, in the level's PCA space. Pixels of one subpass read only the state
// before the subpass (double buffering), so the result never depends on scheduling.
#include <algorithm>
#include <array>
#include <limits>

#include "texsynth/core/parallel.h"
#include "texsynth/core/wrap.h"
#include "texsynth/image/parallel_synthesis.h"
#include "texsynth/image/window_support.h"

namespace texsynth {
namespace {

// Radius of everything a corrected pixel reads: its neighborhood and the 3x3 candidate sources.
int readRadius(const ExemplarAnalysis& analysis, int level) {
  return std::max(analysis.levels[level].neighborhoodSize / 2, 1);
}

// The s x s pixel classes of one pass in the order they are corrected: for s = 2 the order of
// L&H 2005, (0,0) (1,1) (1,0) (0,1), which alternates diagonals; otherwise row by row.
std::vector<std::array<int, 2>> subpassOrder(int s) {
  if (s == 2) return {{0, 0}, {1, 1}, {1, 0}, {0, 1}};
  std::vector<std::array<int, 2>> order;
  for (int j = 0; j < s; ++j)
    for (int i = 0; i < s; ++i) order.push_back({i, j});
  return order;
}

// Gathers and projects the neighborhoods of synthesized pixels at one level.
class NeighborhoodProjector {
 public:
  NeighborhoodProjector(const ExemplarAnalysis& analysis, int level)
      : level_(analysis.levels[level]),
        radius_(level_.neighborhoodSize / 2),
        channels_(level_.image.channels),
        buffer_(std::size_t(level_.pca.inputDimension)) {
    TS_CHECK(level_.pca.inputDimension == level_.shape().dimension());
  }

  // out[D] = projected neighborhood of colors at the coordinates around absolute (x, y).
  void project(const SourceCoordinates& coords, int x, int y, float* out) {
    float* write = buffer_.data();
    for (int dy = -radius_; dy <= radius_; ++dy)
      for (int dx = -radius_; dx <= radius_; ++dx) {
        const std::int32_t* source = coords.at(x + dx, y + dy);
        const float* color = level_.image.pixel(source[0], source[1]);
        write = std::copy(color, color + channels_, write);
      }
    level_.pca.project(buffer_.data(), out);
  }

  float distanceTo(const float* query, std::int32_t exemplarPixel) const {
    const float* target = level_.projectedAt(exemplarPixel);
    float sum = 0;
    for (int i = 0; i < level_.pca.outputDimension; ++i) {
      const float d = query[i] - target[i];
      sum += d * d;
    }
    return sum;
  }

 private:
  const ExemplarLevel& level_;
  int radius_, channels_;
  std::vector<float> buffer_;
};

// The 3x3 offsets with (0,0) first: the pixel's own coherent candidates win ties.
constexpr int kOffsets[9][2] = {{0, 0}, {-1, -1}, {0, -1}, {1, -1}, {-1, 0}, {1, 0}, {-1, 1}, {0, 1}, {1, 1}};

// One subpass: pixels of `after`'s region with (x mod s, y mod s) = (px, py) are corrected
// from `before`, the others copied.
void correctSubpass(const ExemplarAnalysis& analysis, int level, const SourceCoordinates& before,
                    SourceCoordinates& after, int s, int px, int py, float continuationBias) {
  const float continuationScale = 1.0f - continuationBias;
  const int spacing = analysis.levels[level].spacing;
  const int dimension = analysis.levels[level].pca.outputDimension;
  const int k = analysis.similarCount;
  parallelForChunks(0, after.height, kRowChunk, [&](std::int64_t begin, std::int64_t end) {
    NeighborhoodProjector projector(analysis, level);
    std::vector<float> query(static_cast<std::size_t>(dimension));
    for (int j = int(begin); j < int(end); ++j) {
      const int y = after.y0 + j;
      // The row as it was, then its pixels of this subpass's class corrected in place.
      std::copy_n(before.at(after.x0, y), 2 * std::size_t(after.width), after.at(after.x0, y));
      if (wrapIndex(y, s) != py) continue;
      for (int x = after.x0 + wrapIndex(px - after.x0, s); x < after.x0 + after.width; x += s) {
        std::int32_t* target = after.at(x, y);
        const std::int32_t* current = before.at(x, y);
        projector.project(before, x, y, query.data());
        float best = std::numeric_limits<float>::infinity();
        std::int32_t bestPixel = analysis.pixelIndex(current[0], current[1]);
        // Coherent neighbours propose the same source; its candidates are measured once
        // (a repeat could never win: ties keep the first).
        std::int32_t proposed[9];
        int proposals = 0;
        for (const auto& d : kOffsets) {
          const std::int32_t* neighbor = before.at(x + d[0], y + d[1]);
          const int cx = wrapIndex(neighbor[0] - spacing * d[0], analysis.width);
          const int cy = wrapIndex(neighbor[1] - spacing * d[1], analysis.height);
          const std::int32_t source = analysis.pixelIndex(cx, cy);
          if (std::find(proposed, proposed + proposals, source) != proposed + proposals) continue;
          proposed[proposals++] = source;
          const std::int32_t* similar = analysis.similarAt(level, source);
          for (int i = 0; i < k; ++i) {
            float distance = projector.distanceTo(query.data(), similar[i]);
            if (i == 0) distance *= continuationScale;
            if (distance < best) best = distance, bestPixel = similar[i];
          }
        }
        target[0] = bestPixel % analysis.width;
        target[1] = bestPixel / analysis.width;
      }
    }
  });
}

}  // namespace

int correctionMargin(const ExemplarAnalysis& analysis, int level, int passes, int subpassGrid) {
  return passes * subpassGrid * subpassGrid * readRadius(analysis, level);
}

SourceCoordinates correctCoordinates(const ExemplarAnalysis& analysis, int level, const SourceCoordinates& coords,
                                     int subpassGrid, float continuationBias) {
  TS_CHECK(subpassGrid >= 1);
  const int r = readRadius(analysis, level);
  const int margin = correctionMargin(analysis, level, 1, subpassGrid);
  TS_CHECK(coords.width > 2 * margin && coords.height > 2 * margin);
  SourceCoordinates current = coords;
  for (const auto& subpass : subpassOrder(subpassGrid)) {
    SourceCoordinates next(current.x0 + r, current.y0 + r, current.width - 2 * r, current.height - 2 * r);
    correctSubpass(analysis, level, current, next, subpassGrid, subpass[0], subpass[1], continuationBias);
    current = std::move(next);
  }
  return current;
}

double meanNeighborhoodDistance(const ExemplarAnalysis& analysis, int level, const SourceCoordinates& coords) {
  const int r = analysis.levels[level].neighborhoodSize / 2;
  if (coords.width <= 2 * r || coords.height <= 2 * r) return 0.0;
  const int rows = coords.height - 2 * r;
  std::vector<double> rowSums(static_cast<std::size_t>(rows), 0.0);
  parallelForChunks(0, rows, kRowChunk, [&](std::int64_t begin, std::int64_t end) {
    NeighborhoodProjector projector(analysis, level);
    std::vector<float> query(static_cast<std::size_t>(analysis.levels[level].pca.outputDimension));
    for (int j = int(begin); j < int(end); ++j) {
      const int y = coords.y0 + r + j;
      for (int x = coords.x0 + r; x < coords.x0 + coords.width - r; ++x) {
        projector.project(coords, x, y, query.data());
        const std::int32_t* source = coords.at(x, y);
        rowSums[j] += projector.distanceTo(query.data(), analysis.pixelIndex(source[0], source[1]));
      }
    }
  });
  double total = 0;  // summed in row order: independent of the thread count
  for (double s : rowSums) total += s;
  return total / (double(rows) * (coords.width - 2 * r));
}

}  // namespace texsynth
