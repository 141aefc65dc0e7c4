// The unfolding walk around one centre (Turk 2001, Wei & Levoy 2001): the one-ring as a geodesic
// polar map, further triangles unfolded rigidly across shared edges nearest first, then the grid
// cells' barycentric weights and the members (see surface_neighborhoods.h for the rules).
#include "neighborhood_unfolding.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace texsynth::surface_detail {

namespace {

// Barycentric coordinates down to this (relative) amount below zero still count as inside, so a
// cell centre on an edge shared by two triangles is never lost between them.
constexpr float kInsideTolerance = 1e-5f;

struct P2 {
  float x = 0, y = 0;
};
P2 operator+(P2 a, P2 b) {
  return {a.x + b.x, a.y + b.y};
}
P2 operator-(P2 a, P2 b) {
  return {a.x - b.x, a.y - b.y};
}
P2 operator*(float s, P2 a) {
  return {s * a.x, s * a.y};
}
float dot(P2 a, P2 b) {
  return a.x * b.x + a.y * b.y;
}
float cross(P2 a, P2 b) {
  return a.x * b.y - a.y * b.x;
}

// A triangle laid out in the plane in cell coordinates, corners in the mesh triangle's order.
struct Flat {
  std::int32_t tri = 0;
  std::array<std::int32_t, 3> v{};
  std::array<P2, 3> p{};
};

// One triangle around the centre: the centre's corner goes from `entry` to `exit`.
struct FanCorner {
  std::int32_t tri, entry, exit;
};

}  // namespace

// Per-thread working memory, reused across centres (and calls): stamps equal to `generation`
// mark the triangles and vertices the current centre's walk has reached.
struct UnfoldScratch {
  std::vector<std::uint32_t> triStamp, vertexStamp;
  std::uint32_t generation = 0;
  std::vector<Flat> pending, flat;
  std::vector<std::int32_t> head, tail, next;  // the queue: per bucket a list of `pending` slots
  std::size_t cursor = 0;                      // no bucket before it holds anything
  std::vector<FanCorner> fan;
  std::vector<float> cumulative;
  std::vector<P2> ring;
  std::vector<std::int32_t> owner;
  std::vector<NeighborhoodMember> reached;

  void begin(std::size_t vertices, std::size_t triangles, std::size_t buckets) {
    if (triStamp.size() < triangles) triStamp.assign(triangles, 0);
    if (vertexStamp.size() < vertices) vertexStamp.assign(vertices, 0);
    if (++generation == 0) {
      std::fill(triStamp.begin(), triStamp.end(), 0);
      std::fill(vertexStamp.begin(), vertexStamp.end(), 0);
      generation = 1;
    }
    pending.clear();
    flat.clear();
    next.clear();
    head.assign(buckets, -1);
    tail.assign(buckets, -1);
    cursor = buckets;
    reached.clear();
  }

  void push(const Flat& f, float distance) {
    std::size_t b = std::size_t(std::min(distance * NeighborhoodUnfolder::kBucketsPerCell, float(head.size() - 1)));
    std::int32_t slot = std::int32_t(pending.size());
    pending.push_back(f);
    next.push_back(-1);
    if (tail[b] >= 0) {
      next[std::size_t(tail[b])] = slot;
    } else {
      head[b] = slot;
    }
    tail[b] = slot;
    cursor = std::min(cursor, b);
  }

  // The next queued slot, or -1.
  std::int32_t pop() {
    while (cursor < head.size() && head[cursor] < 0) ++cursor;
    if (cursor == head.size()) return -1;
    std::int32_t slot = head[cursor];
    head[cursor] = next[std::size_t(slot)];
    if (head[cursor] < 0) tail[cursor] = -1;
    return slot;
  }
};

namespace {

UnfoldScratch& threadScratch() {
  thread_local UnfoldScratch scratch;
  return scratch;
}

}  // namespace

// ---- the centre's one-ring ----

// Collects into s.fan fan k of the triangles around p (counter-clockwise, from its border if it
// has one); returns whether the fan closes around p.
bool NeighborhoodUnfolder::collectFan(std::int32_t p, int k, UnfoldScratch& s) const {
  s.fan.clear();
  std::span<const int> fan = topology_.fan(p, k);
  for (int t : fan) {
    const Vec3i& corners = tri(t);
    int c = topology_.cornerOf(t, p);
    s.fan.push_back({t, corners[(c + 1) % 3], corners[(c + 2) % 3]});
  }
  const int last = fan.back();
  return topology_.neighbor(last, (topology_.cornerOf(last, p) + 2) % 3) == fan.front();
}

// Lays out s.fan as a geodesic polar map around p (origin), tangent t along +dx, and appends its
// triangles to s.flat.
void NeighborhoodUnfolder::layOutFan(std::int32_t p, const Vec3f& t, const Vec3f& b, bool closed,
                                     UnfoldScratch& s) const {
  const std::size_t m = s.fan.size();
  const Vec3f xp = x(p);
  auto ringVertex = [&](std::size_t k) { return k < m ? s.fan[k].entry : s.fan[m - 1].exit; };
  s.cumulative.assign(m + 1, 0.0f);
  float orientation = 0;
  for (std::size_t i = 0; i < m; ++i) {
    Vec3f e1 = x(s.fan[i].entry) - xp, e2 = x(s.fan[i].exit) - xp;
    s.cumulative[i + 1] = s.cumulative[i] + std::atan2(e1.cross(e2).norm(), e1.dot(e2));
    orientation += e1.dot(t) * e2.dot(b) - e1.dot(b) * e2.dot(t);
  }
  const float total = s.cumulative[m];
  constexpr float kTurn = 2 * std::numbers::pi_v<float>;
  const float scale = (total > 0 && (closed || total > kTurn)) ? kTurn / total : 1.0f;
  const float sign = orientation >= 0 ? 1.0f : -1.0f;

  // The tangent's angle in the fan: in the corner whose wedge holds its projection.
  float best = -kInsideTolerance, tangentAngle = 0;
  bool found = false;
  for (std::size_t i = 0; i < m; ++i) {
    Vec3f e1 = x(s.fan[i].entry) - xp, e2 = x(s.fan[i].exit) - xp;
    Vec3f normal = e1.cross(e2);
    float area = normal.norm();
    if (!(area > 0)) continue;
    normal /= area;
    Vec3f tp = t - t.dot(normal) * normal;
    float a11 = e1.dot(e1), a12 = e1.dot(e2), a22 = e2.dot(e2), r1 = tp.dot(e1), r2 = tp.dot(e2);
    float det = a11 * a22 - a12 * a12;
    if (!(det > 0) || !(tp.squaredNorm() > 0)) continue;
    float l1 = (r1 * a22 - r2 * a12) / det * std::sqrt(a11), l2 = (r2 * a11 - r1 * a12) / det * std::sqrt(a22);
    float score = std::min(l1, l2) / tp.norm();
    if (score > best) {
      best = score;
      float corner = s.cumulative[i + 1] - s.cumulative[i];
      tangentAngle = s.cumulative[i] + std::atan2(l2 * std::sin(corner), l1 + l2 * std::cos(corner));
      found = true;
    }
  }
  float offset = -sign * scale * tangentAngle;
  if (!found) {  // no wedge holds it: turn the ring to agree best with its projection
    float sx = 0, sy = 0;
    for (std::size_t k = 0; k <= m; ++k) {
      Vec3f q = x(ringVertex(k)) - xp;
      float u = q.dot(t), w = q.dot(b), angle = std::atan2(w, u) - sign * scale * s.cumulative[k];
      float weight = std::sqrt(u * u + w * w);
      sx += weight * std::cos(angle);
      sy += weight * std::sin(angle);
    }
    offset = std::atan2(sy, sx);
  }

  s.ring.resize(m + 1);
  for (std::size_t k = 0; k <= m; ++k) {
    if (closed && k == m) {
      s.ring[k] = s.ring[0];
      break;
    }
    float rho = (x(ringVertex(k)) - xp).norm() * invSpacing_, angle = offset + sign * scale * s.cumulative[k];
    s.ring[k] = {rho * std::cos(angle), -rho * std::sin(angle)};  // (u, w) -> (dx, dy) = (u, -w)
  }
  for (std::size_t i = 0; i < m; ++i) {
    const FanCorner& c = s.fan[i];
    Flat f;
    f.tri = walk_.triangleRank[std::size_t(c.tri)];
    if (s.triStamp[std::size_t(f.tri)] == s.generation) continue;
    s.triStamp[std::size_t(f.tri)] = s.generation;
    f.v = records_[std::size_t(f.tri)].v;
    for (int j = 0; j < 3; ++j) {
      std::int32_t v = tri(c.tri)[j];
      f.p[std::size_t(j)] = v == p ? P2{} : v == c.entry ? s.ring[i] : s.ring[i + 1];
    }
    s.flat.push_back(f);
  }
}

void NeighborhoodUnfolder::seedFans(std::int32_t p, UnfoldScratch& s) const {
  Vec3f n = mesh_.normals[std::size_t(p)];
  n = n.squaredNorm() > 0 && n.allFinite() ? n.normalized() : Vec3f::UnitZ();
  Vec3f t = tangents_[std::size_t(p)];
  t = t.allFinite() ? Vec3f(t - t.dot(n) * n) : Vec3f::Zero();
  t = t.squaredNorm() > 1e-12f ? t.normalized() : Frame::fromNormal(n).x;
  const Vec3f b = n.cross(t);
  for (int k = 0; k < topology_.fanCount(p); ++k) {
    bool closed = collectFan(p, k, s);
    layOutFan(p, t, b, closed, s);
  }
}

// ---- the walk ----

// Unfolds the neighbours of s.flat[index] across its edges and queues those that reach the square.
void NeighborhoodUnfolder::expand(std::size_t index, UnfoldScratch& s) const {
  const Flat f = s.flat[index];
  for (int e = 0; e < 3; ++e) {
    const std::int32_t across = records_[std::size_t(f.tri)].across[std::size_t(e)];
    if (across < 0 || s.triStamp[std::size_t(across >> 2)] == s.generation) continue;
    const std::int32_t n = across >> 2;
    const int edge = across & 3;  // n's edge (b, a)
    const TriangleRecord& r = records_[std::size_t(n)];
    // In n, corner edge + 2 lies off its edge from b to a, on the side away from f's third corner.
    const P2 pa = f.p[std::size_t(e)], pb = f.p[std::size_t((e + 1) % 3)], pc = f.p[std::size_t((e + 2) % 3)];
    const P2 d = pa - pb, normal{-d.y, d.x};
    const float out = cross(d, pc - pb) > 0 ? -r.out[std::size_t(edge)] : r.out[std::size_t(edge)];
    const P2 pk = pb + r.along[std::size_t(edge)] * d + out * normal;
    if (std::min({pa.x, pb.x, pk.x}) > limit_ || std::max({pa.x, pb.x, pk.x}) < -limit_ ||
        std::min({pa.y, pb.y, pk.y}) > limit_ || std::max({pa.y, pb.y, pk.y}) < -limit_)
      continue;
    Flat g;
    g.tri = n;
    g.v = r.v;
    g.p[std::size_t(edge)] = pb;
    g.p[std::size_t((edge + 1) % 3)] = pa;
    g.p[std::size_t((edge + 2) % 3)] = pk;
    const P2 centroid = (1.0f / 3.0f) * (pa + pb + pk);
    s.push(g, std::sqrt(dot(centroid, centroid)));
  }
}

// Gives each cell centre the barycentric weights of the first flat triangle containing it.
void NeighborhoodUnfolder::rasterize(std::span<NeighborhoodCell> cells, UnfoldScratch& s) const {
  const float r = float(radius_);
  for (std::size_t i = 0; i < s.flat.size(); ++i) {
    const Flat& f = s.flat[i];
    const P2 a = f.p[0], b = f.p[1], c = f.p[2];
    const float area = cross(b - a, c - a);
    if (!(std::abs(area) > 1e-12f)) continue;
    const float pad = 1e-4f;
    int x0 = int(std::ceil(std::max(-r, std::min({a.x, b.x, c.x}) - pad)));
    int x1 = int(std::floor(std::min(r, std::max({a.x, b.x, c.x}) + pad)));
    int y0 = int(std::ceil(std::max(-r, std::min({a.y, b.y, c.y}) - pad)));
    int y1 = int(std::floor(std::min(r, std::max({a.y, b.y, c.y}) + pad)));
    const float inv = 1.0f / area;
    for (int y = y0; y <= y1; ++y) {
      for (int xx = x0; xx <= x1; ++xx) {
        std::size_t idx = std::size_t((y + radius_) * size_ + xx + radius_);
        if (s.owner[idx] >= 0) continue;
        P2 q{float(xx), float(y)};
        float l0 = cross(b - q, c - q) * inv, l1 = cross(c - q, a - q) * inv, l2 = cross(a - q, b - q) * inv;
        if (std::min({l0, l1, l2}) < -kInsideTolerance) continue;
        l0 = std::max(l0, 0.0f);
        l1 = std::max(l1, 0.0f);
        l2 = std::max(l2, 0.0f);
        float sum = l0 + l1 + l2;
        s.owner[idx] = std::int32_t(i);
        cells[idx] = {f.v, {l0 / sum, l1 / sum, l2 / sum}};
      }
    }
  }
}

// Cells no triangle covers take the weights of the nearest point of the flat triangles.
void NeighborhoodUnfolder::fillUncovered(std::int32_t p, std::span<NeighborhoodCell> cells, UnfoldScratch& s) const {
  for (int y = -radius_; y <= radius_; ++y) {
    for (int xx = -radius_; xx <= radius_; ++xx) {
      std::size_t idx = std::size_t((y + radius_) * size_ + xx + radius_);
      if (s.owner[idx] >= 0) continue;
      const P2 q{float(xx), float(y)};
      float best = std::numeric_limits<float>::infinity();
      NeighborhoodCell cell{{p, p, p}, {1, 0, 0}, false};
      for (const Flat& f : s.flat) {
        float gx = std::max(
            {std::min({f.p[0].x, f.p[1].x, f.p[2].x}) - q.x, q.x - std::max({f.p[0].x, f.p[1].x, f.p[2].x}), 0.0f});
        float gy = std::max(
            {std::min({f.p[0].y, f.p[1].y, f.p[2].y}) - q.y, q.y - std::max({f.p[0].y, f.p[1].y, f.p[2].y}), 0.0f});
        if (gx * gx + gy * gy >= best) continue;
        for (int e = 0; e < 3; ++e) {  // q is outside every triangle: its nearest point is on an edge
          P2 a = f.p[e], d = f.p[(e + 1) % 3] - a;
          float len2 = dot(d, d), u = len2 > 0 ? std::clamp(dot(q - a, d) / len2, 0.0f, 1.0f) : 0.0f;
          P2 gap = a + u * d - q;
          float dist = dot(gap, gap);
          if (dist < best) {
            best = dist;
            cell.vertex = f.v;
            cell.weight = {0, 0, 0};
            cell.weight[std::size_t(e)] = 1 - u;
            cell.weight[std::size_t((e + 1) % 3)] = u;
          }
        }
      }
      cells[idx] = cell;
    }
  }
}

void NeighborhoodUnfolder::run(std::int32_t p, std::span<NeighborhoodCell> cells,
                               std::vector<NeighborhoodMember>& members) const {
  UnfoldScratch& s = threadScratch();
  s.begin(mesh_.vertexCount(), records_.size(), buckets_);
  seedFans(p, s);
  for (std::size_t i = 0, seeds = s.flat.size(); i < seeds; ++i) expand(i, s);
  for (std::int32_t slot = s.pop(); slot >= 0; slot = s.pop()) {
    const Flat& g = s.pending[std::size_t(slot)];
    if (s.triStamp[std::size_t(g.tri)] == s.generation) continue;
    s.triStamp[std::size_t(g.tri)] = s.generation;
    s.flat.push_back(g);
    expand(s.flat.size() - 1, s);
  }

  s.owner.assign(std::size_t(size_ * size_), -1);
  rasterize(cells, s);
  const std::int32_t centre = walk_.vertexRank[std::size_t(p)];
  fillUncovered(centre, cells, s);
  for (NeighborhoodCell& c : cells)
    for (std::int32_t& v : c.vertex) v = walk_.vertexOf[std::size_t(v)];

  s.vertexStamp[std::size_t(centre)] = s.generation;
  s.reached.push_back({p, 0, 0});
  for (const Flat& f : s.flat) {
    for (std::size_t j = 0; j < 3; ++j) {
      std::size_t v = std::size_t(f.v[j]);
      if (s.vertexStamp[v] == s.generation) continue;
      s.vertexStamp[v] = s.generation;
      if (std::abs(f.p[j].x) <= limit_ && std::abs(f.p[j].y) <= limit_)
        s.reached.push_back({walk_.vertexOf[v], f.p[j].x, f.p[j].y});
    }
  }
  std::sort(s.reached.begin(), s.reached.end(), [](const auto& l, const auto& r) { return l.vertex < r.vertex; });
  members.insert(members.end(), s.reached.begin(), s.reached.end());
}

}  // namespace texsynth::surface_detail
