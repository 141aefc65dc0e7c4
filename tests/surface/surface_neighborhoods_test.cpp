// Resampled surface neighbourhoods: convex rows, exact on flat and developable surfaces, borders
// filled, covering = transpose of members, active centres cover and spread, determinism.
#include "texsynth/surface/surface_neighborhoods.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "mesh_test_support.h"
#include "test_support.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"

using namespace texsynth;

namespace {

using test::icosphere;

constexpr float kPi = std::numbers::pi_v<float>;

// The square [0, n*h]^2 in z = 0 from an (n+1)^2 grid, diagonals chosen by hash, interior vertices
// jittered by up to jitter * h per axis (the border stays straight). Counter-clockwise about +z.
Mesh jitteredPlane(int n, float h, float jitter, std::uint64_t seed = 1) {
  Mesh mesh;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      Vec3f p(float(i) * h, float(j) * h, 0);
      if (i > 0 && i < n && j > 0 && j < n) {
        std::uint64_t v = std::uint64_t(j * (n + 1) + i);
        p.x() += jitter * h * (2 * uniform01(hashKey(seed, v, 0)) - 1);
        p.y() += jitter * h * (2 * uniform01(hashKey(seed, v, 1)) - 1);
      }
      mesh.positions.push_back(p);
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      int v00 = j * (n + 1) + i, v10 = v00 + 1, v01 = v00 + n + 1, v11 = v01 + 1;
      if (hashKey(seed, std::uint64_t(v00), 2) & 1) {
        mesh.triangles.push_back({v00, v10, v11});
        mesh.triangles.push_back({v00, v11, v01});
      } else {
        mesh.triangles.push_back({v00, v10, v01});
        mesh.triangles.push_back({v10, v11, v01});
      }
    }
  }
  mesh.computeNormals();
  return mesh;
}

// The plane bent into smooth bumps (curvature of both signs, plus a border).
Mesh bumpyPlane(int n) {
  Mesh mesh = jitteredPlane(n, 1.0f, 0.2f, 7);
  for (Vec3f& p : mesh.positions) p.z() = 1.5f * std::sin(0.35f * p.x()) * std::cos(0.3f * p.y());
  mesh.computeNormals();
  return mesh;
}

// An open tube around the z axis: `columns` vertices around (chord 1), `rows` + 1 rings `step`
// apart, quads split along one diagonal. Normals radial. Vertex (i, j) is j * columns + i.
Mesh tube(int columns, int rows, float step) {
  const float radius = 1.0f / (2.0f * std::sin(kPi / float(columns)));
  Mesh mesh;
  for (int j = 0; j <= rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      float angle = 2 * kPi * float(i) / float(columns);
      mesh.positions.push_back({radius * std::cos(angle), radius * std::sin(angle), float(j) * step});
      mesh.normals.push_back({std::cos(angle), std::sin(angle), 0});
    }
  }
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      int v00 = j * columns + i, v10 = j * columns + (i + 1) % columns, v01 = v00 + columns, v11 = v10 + columns;
      mesh.triangles.push_back({v00, v10, v11});
      mesh.triangles.push_back({v00, v11, v01});
    }
  }
  return mesh;
}

double meanEdge(const Mesh& mesh) {
  double sum = 0;
  for (const Vec3i& t : mesh.triangles)
    for (int e = 0; e < 3; ++e)
      sum += (mesh.positions[std::size_t(t[e])] - mesh.positions[std::size_t(t[(e + 1) % 3])]).norm();
  return sum / double(3 * mesh.triangles.size());
}

// Tangent i of a field turning around the normal: a different direction at every vertex.
std::vector<Vec3f> turningTangents(const Mesh& mesh) {
  std::vector<Vec3f> tangents;
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
    Frame f = Frame::fromNormal(mesh.normals[v]);
    float angle = 2 * kPi * uniform01(hashKey(3, v));
    tangents.push_back(std::cos(angle) * f.x + std::sin(angle) * f.y + 0.3f * f.z);  // not quite tangent
  }
  return tangents;
}

std::vector<std::int32_t> allVertices(const Mesh& mesh) {
  std::vector<std::int32_t> v(mesh.vertexCount());
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = std::int32_t(i);
  return v;
}

void expectConvexRows(const SurfaceNeighborhoods& nb, std::size_t vertexCount) {
  ASSERT_EQ(nb.cells.size(), nb.activeCount() * std::size_t(nb.cellCount()));
  for (const NeighborhoodCell& c : nb.cells) {
    float sum = 0;
    for (int j = 0; j < 3; ++j) {
      ASSERT_GE(c.vertex[j], 0);
      ASSERT_LT(std::size_t(c.vertex[j]), vertexCount);
      ASSERT_GE(c.weight[j], 0.0f);
      sum += c.weight[j];
    }
    ASSERT_NEAR(sum, 1.0f, 1e-6f);
  }
}

// Resamples a per-vertex scalar into neighbourhood a's cells.
std::vector<float> resampled(const SurfaceNeighborhoods& nb, std::size_t a, const std::vector<float>& values) {
  std::vector<float> out(std::size_t(nb.cellCount()));
  nb.resample(a, values, 1, out);
  return out;
}

bool sameBits(const SurfaceNeighborhoods& x, const SurfaceNeighborhoods& y) {
  auto bytes = [](const auto& v) {
    return std::vector<char>((const char*)v.data(), (const char*)(v.data() + v.size()));
  };
  return x.centres == y.centres && bytes(x.cells) == bytes(y.cells) && x.memberStart == y.memberStart &&
         bytes(x.members) == bytes(y.members) && x.coveringStart == y.coveringStart &&
         bytes(x.covering) == bytes(y.covering);
}

}  // namespace

TEST(SurfaceNeighborhoods, RowsAreConvexAndTheCentreCellIsTheCentre) {
  for (const Mesh& mesh : {bumpyPlane(16), icosphere(3)}) {
    MeshTopology topology(mesh, "test");
    const float spacing = float(meanEdge(mesh));
    const auto tangents = turningTangents(mesh);
    std::vector<float> values(mesh.vertexCount());
    for (std::size_t v = 0; v < values.size(); ++v) values[v] = uniform01(hashKey(5, v));
    for (int size : {1, 7, 9}) {
      SurfaceNeighborhoods nb = resampleNeighborhoods(mesh, topology, tangents, spacing, size, allVertices(mesh));
      EXPECT_EQ(nb.radius, size / 2);
      expectConvexRows(nb, mesh.vertexCount());
      for (std::size_t a = 0; a < nb.activeCount(); ++a) {
        ASSERT_NEAR(resampled(nb, a, values)[std::size_t(nb.cellCount() / 2)], values[std::size_t(nb.centres[a])],
                    1e-6f);
        ASSERT_FALSE(nb.membersOf(a).empty());
      }
    }
  }
}

TEST(SurfaceNeighborhoods, FlatPlaneReproducesALinearRampAnyTangent) {
  const int n = 20;
  const float h = 1.0f, side = float(n) * h;
  const Mesh mesh = jitteredPlane(n, h, 0.2f);
  MeshTopology topology(mesh, "plane");
  const Vec3f slope(0.37f, -1.21f, 0.5f);
  auto ramp = [&](const Vec3f& x) { return slope.dot(x) + 0.25f; };
  std::vector<float> values;
  for (const Vec3f& x : mesh.positions) values.push_back(ramp(x));
  for (float angle : {0.0f, 0.3f, 1.1f, 2.5f, -2.0f}) {
    const Vec3f t(std::cos(angle), std::sin(angle), 0), b = Vec3f::UnitZ().cross(t);
    const std::vector<Vec3f> tangents(mesh.vertexCount(), t);
    for (float spacing : {0.7f, 1.6f}) {
      const SurfaceNeighborhoods nb = resampleNeighborhoods(mesh, topology, tangents, spacing, 9, allVertices(mesh));
      expectConvexRows(nb, mesh.vertexCount());
      int checked = 0;
      for (std::size_t a = 0; a < nb.activeCount(); ++a) {
        const Vec3f p = mesh.positions[std::size_t(nb.centres[a])];
        const std::vector<float> got = resampled(nb, a, values);
        for (int dy = -nb.radius; dy <= nb.radius; ++dy) {
          for (int dx = -nb.radius; dx <= nb.radius; ++dx) {
            const Vec3f x = p + spacing * (float(dx) * t - float(dy) * b);
            if (x.x() < 1e-3f || x.y() < 1e-3f || x.x() > side - 1e-3f || x.y() > side - 1e-3f) continue;
            ++checked;
            ASSERT_NEAR(got[std::size_t((dy + nb.radius) * nb.size + dx + nb.radius)], ramp(x), 2e-4f)
                << "angle " << angle << " spacing " << spacing << " centre " << nb.centres[a] << " cell " << dx << ","
                << dy;
          }
        }
        // Members: exactly the vertices in the square, at their tangent-plane coordinates.
        std::vector<std::int32_t> expected;
        for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
          Vec3f d = (mesh.positions[v] - p) / spacing;
          float ex = d.dot(t), ey = -d.dot(b), limit = float(nb.radius) + 0.5f;
          if (std::abs(std::max(std::abs(ex), std::abs(ey)) - limit) < 1e-3f) continue;  // too close to call
          if (std::abs(ex) <= limit && std::abs(ey) <= limit) expected.push_back(std::int32_t(v));
        }
        std::size_t found = 0;
        for (const NeighborhoodMember& m : nb.membersOf(a)) {
          Vec3f d = (mesh.positions[std::size_t(m.vertex)] - p) / spacing;
          ASSERT_NEAR(m.dx, d.dot(t), 1e-4f);
          ASSERT_NEAR(m.dy, -d.dot(b), 1e-4f);
          found += std::binary_search(expected.begin(), expected.end(), m.vertex);
        }
        ASSERT_EQ(found, expected.size()) << "centre " << nb.centres[a];
      }
      EXPECT_GT(checked, 10000);
    }
  }
}

TEST(SurfaceNeighborhoods, TubeUnrollsToItsDevelopment) {
  // A tube is developable: unfolding must give the unrolled coordinates exactly, for members and
  // (by interpolating those coordinates) for every cell. Around the tube the polyhedral
  // development has one unit chord per column; along it `step` per ring.
  const int columns = 48, rows = 24;
  const float step = 0.9f, spacing = 0.8f, delta = 2 * kPi / float(columns);
  const Mesh mesh = tube(columns, rows, step);
  MeshTopology topology(mesh, "tube");
  std::vector<std::int32_t> centres;
  for (int j = 10; j <= 14; ++j)
    for (int i = 0; i < columns; i += 5) centres.push_back(j * columns + i);
  for (float gamma : {0.0f, kPi / 2, 0.4f, 2.0f, -2.7f}) {
    std::vector<Vec3f> tangents;
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
      Vec3f around = Vec3f::UnitZ().cross(mesh.normals[v]);
      tangents.push_back(std::cos(gamma) * Vec3f::UnitZ() + std::sin(gamma) * around);
    }
    // Within a face the tangent's circumferential part shrinks by cos(delta / 2) (the face's chord
    // is tilted against the smooth tangent plane).
    const float developed = std::atan2(std::sin(gamma) * std::cos(delta / 2), std::cos(gamma));
    const float c = std::cos(developed), s = std::sin(developed);
    const SurfaceNeighborhoods nb = resampleNeighborhoods(mesh, topology, tangents, spacing, 9, centres);
    for (std::size_t a = 0; a < nb.activeCount(); ++a) {
      const int pi = nb.centres[a] % columns, pj = nb.centres[a] / columns;
      std::vector<float> zs(mesh.vertexCount()), ss(mesh.vertexCount());
      for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        int k = ((int(v) % columns - pi) % columns + columns + columns / 2) % columns - columns / 2;
        zs[v] = float(int(v) / columns - pj) * step;
        ss[v] = float(k);
      }
      for (const NeighborhoodMember& m : nb.membersOf(a)) {
        float z = zs[std::size_t(m.vertex)], around = ss[std::size_t(m.vertex)];
        ASSERT_NEAR(m.dx, (z * c + around * s) / spacing, 1e-4f) << "gamma " << gamma << " vertex " << m.vertex;
        ASSERT_NEAR(m.dy, -(z * s - around * c) / spacing, 1e-4f) << "gamma " << gamma << " vertex " << m.vertex;
      }
      EXPECT_GE(nb.membersOf(a).size(), 40u);
      const std::vector<float> gotZ = resampled(nb, a, zs), gotS = resampled(nb, a, ss);
      for (int dy = -nb.radius; dy <= nb.radius; ++dy) {
        for (int dx = -nb.radius; dx <= nb.radius; ++dx) {
          std::size_t i = std::size_t((dy + nb.radius) * nb.size + dx + nb.radius);
          ASSERT_NEAR(gotZ[i], spacing * (float(dx) * c - float(dy) * s), 1e-4f);
          ASSERT_NEAR(gotS[i], spacing * (float(dx) * s + float(dy) * c), 1e-4f);
        }
      }
    }
  }
}

TEST(SurfaceNeighborhoods, BorderCentresGetEveryCellFilledClampedToTheMesh) {
  const int n = 12;
  const float side = float(n);
  const Mesh mesh = jitteredPlane(n, 1.0f, 0.2f, 3);
  MeshTopology topology(mesh, "plane");
  const Vec3f slope(0.8f, 0.45f, 0);
  std::vector<float> values;
  for (const Vec3f& x : mesh.positions) values.push_back(slope.dot(x));
  const std::vector<std::int32_t> centres = {0, n / 2, n, (n + 1) * (n / 2), (n + 1) * (n + 1) - 1};
  for (const Vec3f& t : {Vec3f(1, 0, 0), Vec3f(0, 1, 0), Vec3f(-1, 0, 0), Vec3f(0, -1, 0)}) {
    const Vec3f b = Vec3f::UnitZ().cross(t);
    const std::vector<Vec3f> tangents(mesh.vertexCount(), t);
    const SurfaceNeighborhoods nb = resampleNeighborhoods(mesh, topology, tangents, 0.9f, 11, centres);
    expectConvexRows(nb, mesh.vertexCount());
    for (std::size_t a = 0; a < nb.activeCount(); ++a) {
      const Vec3f p = mesh.positions[std::size_t(nb.centres[a])];
      const std::vector<float> got = resampled(nb, a, values);
      for (int dy = -nb.radius; dy <= nb.radius; ++dy) {
        for (int dx = -nb.radius; dx <= nb.radius; ++dx) {
          Vec3f x = p + nb.spacing * (float(dx) * t - float(dy) * b);
          x = x.cwiseMax(Vec3f::Zero()).cwiseMin(Vec3f(side, side, 0));  // the nearest point of the mesh
          ASSERT_NEAR(got[std::size_t((dy + nb.radius) * nb.size + dx + nb.radius)], slope.dot(x), 1e-4f)
              << "centre " << nb.centres[a] << " cell " << dx << "," << dy;
        }
      }
    }
  }
}

TEST(SurfaceNeighborhoods, CoveringIsTheTransposeOfMembers) {
  const Mesh mesh = bumpyPlane(18);
  MeshTopology topology(mesh, "bumps");
  const auto centres = selectActiveCentres(mesh, 1.0f, 2);
  const SurfaceNeighborhoods nb = resampleNeighborhoods(mesh, topology, turningTangents(mesh), 1.0f, 9, centres);
  ASSERT_EQ(nb.memberStart.size(), nb.activeCount() + 1);
  ASSERT_EQ(nb.coveringStart.size(), mesh.vertexCount() + 1);
  ASSERT_EQ(nb.covering.size(), nb.members.size());
  std::size_t entries = 0;
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
    std::int32_t previous = -1;
    for (const CoveringEntry& e : nb.coveringOf(v)) {
      ASSERT_GT(e.neighborhood, previous);
      previous = e.neighborhood;
      auto members = nb.membersOf(std::size_t(e.neighborhood));
      auto it = std::find_if(members.begin(), members.end(),
                             [&](const NeighborhoodMember& m) { return m.vertex == std::int32_t(v); });
      ASSERT_NE(it, members.end());
      EXPECT_EQ(it->dx, e.dx);
      EXPECT_EQ(it->dy, e.dy);
      ++entries;
    }
  }
  EXPECT_EQ(entries, nb.members.size());
  for (std::size_t a = 0; a < nb.activeCount(); ++a) {
    auto members = nb.membersOf(a);
    for (std::size_t i = 0; i < members.size(); ++i) {
      if (i > 0) {
        ASSERT_LT(members[i - 1].vertex, members[i].vertex);
      }
      ASSERT_LE(std::max(std::abs(members[i].dx), std::abs(members[i].dy)), float(nb.radius) + 0.5f);
      if (members[i].vertex == nb.centres[a]) {
        EXPECT_EQ(std::abs(members[i].dx) + std::abs(members[i].dy), 0.0f);
      }
    }
  }
  // Stride-2 centres with radius-4 squares leave no vertex uncovered.
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v) EXPECT_FALSE(nb.coveringOf(v).empty()) << v;
}

TEST(SurfaceNeighborhoods, ActiveCentresCoverEveryVertexAndKeepApart) {
  for (const Mesh& mesh : {bumpyPlane(24), icosphere(3)}) {
    const float spacing = float(meanEdge(mesh));
    EXPECT_EQ(selectActiveCentres(mesh, spacing, 1), allVertices(mesh));
    for (int stride : {2, 3, 4}) {
      const auto centres = selectActiveCentres(mesh, spacing, stride, 11);
      const float radius = float(stride) * spacing;
      ASSERT_TRUE(std::is_sorted(centres.begin(), centres.end()));
      for (std::size_t i = 0; i < centres.size(); ++i)
        for (std::size_t j = i + 1; j < centres.size(); ++j)
          ASSERT_GT((mesh.positions[std::size_t(centres[i])] - mesh.positions[std::size_t(centres[j])]).norm(), radius);
      for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        float nearest = 1e30f;
        for (std::int32_t c : centres)
          nearest = std::min(nearest, (mesh.positions[v] - mesh.positions[std::size_t(c)]).norm());
        ASSERT_LE(nearest, radius) << "vertex " << v;
      }
      // About one centre per stride^2 cells of area (a disk packing: between 1/4 and 2 of that).
      double cellsPerCentre = double(mesh.vertexCount()) / double(centres.size()) / double(stride * stride);
      EXPECT_GT(cellsPerCentre, 0.25);
      EXPECT_LT(cellsPerCentre, 4.0);
      EXPECT_NE(selectActiveCentres(mesh, spacing, stride, 12), centres);  // the seed matters
    }
  }
}

TEST(SurfaceNeighborhoods, DeterministicForAnyThreadCount) {
  for (const Mesh& mesh : {bumpyPlane(20), icosphere(3)}) {
    MeshTopology topology(mesh, "test");
    const float spacing = float(meanEdge(mesh));
    const auto tangents = turningTangents(mesh);
    auto run = [&] {
      auto centres = selectActiveCentres(mesh, spacing, 2, 4);
      return std::pair{resampleNeighborhoods(mesh, topology, tangents, spacing, 9, centres),
                       resampleNeighborhoods(mesh, topology, tangents, 0.8f * spacing, 7, allVertices(mesh))};
    };
    const auto first = run(), second = run();
    EXPECT_TRUE(sameBits(first.first, second.first));
    EXPECT_TRUE(sameBits(first.second, second.second));
    for (int threads : {1, 3}) {
      ThreadLimit limit(threads);
      const auto limited = run();
      EXPECT_TRUE(sameBits(first.first, limited.first)) << threads << " threads";
      EXPECT_TRUE(sameBits(first.second, limited.second)) << threads << " threads";
    }
  }
}

TEST(SurfaceNeighborhoods, RejectsBadParameters) {
  const Mesh mesh = jitteredPlane(4, 1.0f, 0.0f);
  MeshTopology topology(mesh, "plane");
  const std::vector<Vec3f> tangents(mesh.vertexCount(), Vec3f::UnitX());
  const std::vector<std::int32_t> centres = {0, 3};
  test::expectParameterError([&] { resampleNeighborhoods(mesh, topology, tangents, 1.0f, 8, centres); }, "size");
  test::expectParameterError([&] { resampleNeighborhoods(mesh, topology, tangents, 1.0f, -1, centres); }, "size");
  test::expectParameterError([&] { resampleNeighborhoods(mesh, topology, tangents, 0.0f, 5, centres); }, "spacing");
  test::expectParameterError(
      [&] { resampleNeighborhoods(mesh, topology, std::span(tangents).first(3), 1.0f, 5, centres); }, "tangents");
  const std::vector<std::int32_t> outside = {0, 25};
  test::expectParameterError([&] { resampleNeighborhoods(mesh, topology, tangents, 1.0f, 5, outside); }, "centres");
  const Mesh other = jitteredPlane(5, 1.0f, 0.0f);
  const std::vector<Vec3f> otherTangents(other.vertexCount(), Vec3f::UnitX());
  test::expectParameterError([&] { resampleNeighborhoods(other, topology, otherTangents, 1.0f, 5, centres); },
                             "topology");
  test::expectParameterError([&] { selectActiveCentres(mesh, -1.0f, 2); }, "spacing");
  test::expectParameterError([&] { selectActiveCentres(mesh, 1.0f, 0); }, "stride");
}
