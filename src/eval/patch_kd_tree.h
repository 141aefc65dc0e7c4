#pragma once
// Internal: an exact KD-tree over PCA-rotated patch vectors (see patch_vectors.h).
// Splits use only the first kSplitCoordinates coordinates (where PCA puts the variance).
// Each leaf stores its (up to kLeafSize) vectors coordinate-major, so one pass over the
// coordinates computes all of the leaf's distances side by side (SIMD across points, no
// horizontal sums), stopping once every point is past the current limit. That keeps the
// search fast both for queries near the data (few leaves, early stops) and far from it
// (where no exact method can avoid looking at nearly every point).
// Distances are plain sums of squared differences in coordinate order, so a given pair always
// gets the same float value. Pruning keeps a relative slack of kPruneSlack: a cell is skipped
// only when its lower bound clearly exceeds the limit, so rounding never hides a candidate.
#include <vector>

namespace texsynth::eval_detail {

class PatchKdTree {
 public:
  static constexpr int kSplitCoordinates = 8;
  static constexpr int kLeafSize = 16;

  // `points`: count vectors of `stride` floats, in patch-index order.
  PatchKdTree(const std::vector<float>& points, int count, int stride);

  struct Best {
    float distance;  // squared, in rotated float coordinates
    int index;       // patch index, -1 if none yet
  };

  // Squared float distance from `query` to patch `index`.
  float distanceTo(const float* query, int index) const;
  // Improves `best` to the nearest patch; ties go to the lowest patch index. `best` may be
  // seeded with any guess (its distance from distanceTo) to tighten pruning from the start, or
  // with index -1 and a finite distance: then only patches closer than that are looked for
  // (index stays -1 when there is none).
  void nearest(const float* query, Best& best) const;
  // `limit` with the slack pruning keeps: a seed distance under which every patch whose exact
  // distance is at most `limit` is still found despite float rounding.
  static float slackened(float limit);
  // Appends (unordered) every patch index whose float distance is at most `radius`.
  void within(const float* query, float radius, std::vector<int>& out) const;

 private:
  struct Node {
    int coordinate = -1;  // split coordinate; -1 for a leaf
    float split = 0;
    int leaf = -1;              // leaf: its number
    int left = -1, right = -1;  // inner: children
  };
  struct Search;

  int build(std::vector<int>& order, int begin, int end, const std::vector<float>& points);
  // Distances from the query to every slot of `leaf`, or false once all exceed `limit`.
  bool leafDistances(int leaf, const float* query, float limit, float* distances) const;
  void searchNearest(int node, Search& search, float lowerBound) const;
  void searchWithin(int node, Search& search, float lowerBound) const;

  int stride_;
  std::vector<Node> nodes_;
  std::vector<float> leafValues_;  // per leaf: stride x kLeafSize, coordinate-major
  std::vector<int> slotIndex_;     // per leaf slot: patch index, -1 for padding
  std::vector<int> slotOf_;        // patch index -> leaf * kLeafSize + slot
};

}  // namespace texsynth::eval_detail
