// Slice sampling and crossbar matching of check points (see synthesis_matching.h).
#include "synthesis_matching.h"

#include <algorithm>
#include <limits>

namespace texsynth::gradient_synthesis {
namespace {

// Candidate searches are re-ranked by the slice distance, so they may be approximate.
constexpr float kCandidateEpsilon = 6.0f;
// Patches shortlisted on the leading PCA dimensions before the full distance decides.
constexpr int kShortlist = 8;

struct Scratch {
  std::vector<float> slice, query, joint;
  std::vector<std::uint32_t> candidates;
  std::vector<std::int32_t> shortlist;
};

// The N x N slice of plane `plane` around the check point, in the neighbourhood layout (v rows, u columns,
// channels), at sample spacing h.
void sampleSlice(const LevelContext& ctx, const GradientSolid& state, const CheckPoint& cp, int plane,
                 std::vector<float>& out) {
  int u, v;
  planeAxes(plane, u, v);
  const float h = float(ctx.spacing);
  const Vec3f du = cp.frame.col(u) * h, dv = cp.frame.col(v) * h;
  const int r = ctx.radius(), n = ctx.size, f = state.channels;
  out.resize(std::size_t(n) * n * f);
  if (cp.frame.isIdentity()) {  // axis-aligned: each axis's nearest controls and offsets once per slice
    int nearest[3][kMaxNeighborhoodSize];
    float offset[3][kMaxNeighborhoodSize];
    const float inverse = 1.0f / float(state.spacing);
    for (int a = 0; a < 3; ++a)
      for (int k = -r; k <= r; ++k) {
        const float step = a == u || a == v ? float(k) * h : 0.0f;
        const float p = std::clamp(cp.position[a] + step, 0.0f, float(state.voxels[a] - 1)) * inverse;
        nearest[a][k + r] = std::min(int(p + 0.5f), state.controls[a] - 1);
        offset[a][k + r] = p - float(nearest[a][k + r]);
      }
    const std::size_t setSize = std::size_t(state.setSize());
    int at[3];
    for (int j = -r; j <= r; ++j)
      for (int i = -r; i <= r; ++i) {
        for (int a = 0; a < 3; ++a) at[a] = a == u ? i + r : a == v ? j + r : r;
        const float* set =
            &state.positive[std::size_t(state.controlIndex(nearest[0][at[0]], nearest[1][at[1]], nearest[2][at[2]])) *
                            setSize];
        const float ox = offset[0][at[0]], oy = offset[1][at[1]], oz = offset[2][at[2]];
        float* o = &out[(std::size_t(j + r) * n + std::size_t(i + r)) * f];
        for (int c = 0; c < f; ++c) o[c] = set[c] + ox * set[f + c] + oy * set[2 * f + c] + oz * set[3 * f + c];
      }
    return;
  }
  for (int j = -r; j <= r; ++j) {
    const Vec3f row = cp.position + float(j) * dv;
    for (int i = -r; i <= r; ++i)
      sampleFirstOrder(state, row + float(i) * du, &out[(std::size_t(j + r) * n + std::size_t(i + r)) * f]);
  }
}

float squaredDistance(const float* a, const float* b, int dimension) {
  float sum = 0;
  for (int i = 0; i < dimension; ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
  return sum;
}

// The candidate whose projected neighbourhood is nearest to `query` (ties: the lower pixel).
std::int32_t bestCandidate(const ExemplarLevel& level, const std::vector<std::uint32_t>& candidates,
                           const float* query) {
  std::int32_t best = -1;
  float bestDistance = std::numeric_limits<float>::max();
  const int dimension = level.pca.outputDimension;
  for (std::uint32_t c : candidates) {
    const float d = squaredDistance(level.projectedAt(std::int32_t(c)), query, dimension);
    if (best < 0 || d < bestDistance || (d == bestDistance && std::int32_t(c) < best))
      best = std::int32_t(c), bestDistance = d;
  }
  return best;
}

}  // namespace

void matchCheckPoint(const LevelContext& ctx, const GradientSolid& state, CheckPoint& cp) {
  thread_local Scratch scratch;
  const GradientExemplars::Impl& set = *ctx.sets[std::size_t(cp.set)];
  const GradientSynthesisOptions& options = *ctx.options;
  std::fill(std::begin(cp.pixel), std::end(cp.pixel), -1);
  for (int plane = 0; plane < options.matchedSlices; ++plane) {
    const GradientExemplars::Impl::Level& level = set.at(SlicePlane(plane), ctx.level);
    sampleSlice(ctx, state, cp, plane, scratch.slice);
    scratch.query.resize(std::size_t(level.level->pca.outputDimension));
    level.level->pca.project(scratch.slice.data(), scratch.query.data());
    if (plane == 0 || !options.crossbar) {
      level.nearest->nearest(scratch.query.data(), kShortlist, scratch.shortlist);
      scratch.candidates.assign(scratch.shortlist.begin(), scratch.shortlist.end());
      cp.pixel[plane] = bestCandidate(*level.level, scratch.candidates, scratch.query.data());
      continue;
    }
    const CrossbarIndex& x = *set.at(SlicePlane::X, ctx.level).crossbars;
    const CrossbarIndex& self = *level.crossbars;
    if (plane == 1) {  // s_y's u-row is the z line, E_x's v-column
      self.nearest(CrossbarIndex::Tree::Rows, x.columnReduced(cp.pixel[0]), options.candidatesY, kCandidateEpsilon,
                   scratch.candidates);
    } else {  // s_z's u-row is the x line (E_y's v-column), its v-column the y line (E_x's u-row)
      const CrossbarIndex& y = *set.at(SlicePlane::Y, ctx.level).crossbars;
      const int half = self.jointHalf();
      scratch.joint.resize(std::size_t(2 * half));
      std::copy_n(y.columnReduced(cp.pixel[1]), half, scratch.joint.begin());
      std::copy_n(x.rowReduced(cp.pixel[0]), half, scratch.joint.begin() + half);
      self.nearest(CrossbarIndex::Tree::Joint, scratch.joint.data(), options.candidatesZ, kCandidateEpsilon,
                   scratch.candidates);
    }
    cp.pixel[plane] = bestCandidate(*level.level, scratch.candidates, scratch.query.data());
  }
}

}  // namespace texsynth::gradient_synthesis
