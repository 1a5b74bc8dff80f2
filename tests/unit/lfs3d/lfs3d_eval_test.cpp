// LocalFeatureSize3 (grid + expanding shells) against the brute force over all
// feature pairs, hand-derived values on the unit cube, and the 1-Lipschitz
// property.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "plc/lfs3d.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/lfs3.hpp"
#include "pqmesh/read_domain.hpp"
#include "support/paths.hpp"
#include "support/random_domains.hpp"

namespace pqmesh {
namespace {

Domain3 load(const std::string& name) { return make_domain(read_plc(test::data_path("3d/" + name + ".poly"))); }

// Unit cube [0,1]^3: 8 corners, 12 edges, 6 square facets.
TEST(Lfs3, UnitCubeHandValues) {
  const Domain3 d = load("cube");
  const LocalFeatureSize3 lfs(d);
  // Centre: the 6 facets at 0.5 are nearest; opposite facets are disjoint.
  EXPECT_DOUBLE_EQ(lfs.at({0.5, 0.5, 0.5}), 0.5);
  EXPECT_DOUBLE_EQ(local_feature_size(d, {0.5, 0.5, 0.5}), 0.5);
  // (0.25, 0.5, 0.5): only facet x=0 is nearer than 0.5 (its edges are at
  // sqrt(0.25^2 + 0.5^2) > 0.5); facets y=0 and y=1 are at 0.5 and disjoint.
  EXPECT_DOUBLE_EQ(lfs.at({0.25, 0.5, 0.5}), 0.5);
  // (0.1, 0.1, 0.1): the facets x=0, y=0, z=0 (0.1), the three edges through
  // the origin (0.1414) and the origin (0.1732) all contain the origin, so
  // pairwise meet. Next come the facets x=1, y=1, z=1 at 0.9, and facet x=1
  // is disjoint from facet x=0: 0.9 (the other edges are >= sqrt(0.82)).
  EXPECT_DOUBLE_EQ(lfs.at({0.1, 0.1, 0.1}), 0.9);
  // Near the middle of edge {y=0, z=0}: facets y=0, z=0 (0.05) and that edge
  // (0.0707) meet; then facets x=0 and x=1 at 0.5, disjoint: 0.5.
  EXPECT_DOUBLE_EQ(lfs.at({0.5, 0.05, 0.05}), 0.5);
  // A corner: the nearest features not through it (three facets, three
  // edges, three corners) are all at distance 1.
  for (int v = 0; v < 8; ++v) EXPECT_DOUBLE_EQ(lfs.at_vertex(v), 1.0) << v;
  // Outside at (-1, 0.5, 0.5): facet x=0 at 1, but every feature disjoint from
  // it lies on the plane x=1 (>= 2). Edges {x=0, y=0} and {x=0, y=1} (and the
  // facets y=0, y=1, z=0, z=1) are at sqrt(1.25); the two edges are disjoint.
  EXPECT_DOUBLE_EQ(lfs.at({-1, 0.5, 0.5}), std::sqrt(1.25));
  EXPECT_DOUBLE_EQ(local_feature_size(d, {-1, 0.5, 0.5}), std::sqrt(1.25));
}

// An independent formula for the value at a vertex: the nearest feature not
// incident on v (brute force over the features).
double nearest_non_incident(const Domain3& d, int v) {
  const detail::LfsModel3 m(d);
  const detail::LfsFeature3 self{detail::LfsFeature3::Kind::Vertex, v};
  double best = INFINITY;
  for (const auto& f : m.features())
    if (m.disjoint(self, f)) best = std::min(best, m.dist2(m.points[static_cast<std::size_t>(v)], f));
  return std::sqrt(best);
}

// Random points in the bounding box grown by 10% on every side (and some far
// outside), every vertex, every edge midpoint and every facet-triangle
// centroid; fast == brute force bit for bit.
void expect_fast_equals_brute(const Domain3& d, std::uint64_t seed, int randoms, const std::string& what) {
  const LocalFeatureSize3 lfs(d);
  std::mt19937_64 rng(seed);
  auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  const Vec3 lo = d.bbox_min, hi = d.bbox_max, ext = hi - lo;
  std::vector<Vec3> xs;
  for (int k = 0; k < randoms; ++k)
    xs.push_back({lo.x + (1.2 * u() - 0.1) * ext.x, lo.y + (1.2 * u() - 0.1) * ext.y, lo.z + (1.2 * u() - 0.1) * ext.z});
  for (int k = 0; k < 5; ++k) xs.push_back(lo + (3 * u() + 2) * ext);
  const auto& P = d.plc.vertices;
  for (const auto& e : d.edges) xs.push_back(0.5 * (P[static_cast<std::size_t>(e.a)] + P[static_cast<std::size_t>(e.b)]));
  for (const auto& t : d.facet_triangles)
    xs.push_back((1.0 / 3) * (P[static_cast<std::size_t>(t[0])] + P[static_cast<std::size_t>(t[1])] +
                              P[static_cast<std::size_t>(t[2])]));
  int checked = 0;
  for (const Vec3& x : xs) {
    const double fast = lfs.at(x), brute = local_feature_size(d, x);
    ASSERT_EQ(fast, brute) << what << " at (" << x.x << ", " << x.y << ", " << x.z << ")";
    ASSERT_GT(fast, 0) << what;
    ++checked;
  }
  const detail::LfsModel3 m(d);
  for (int v = 0; v < m.vertex_count(); ++v) {
    if (!m.vertex_used[static_cast<std::size_t>(v)]) continue;
    ASSERT_EQ(lfs.at_vertex(v), local_feature_size(d, P[static_cast<std::size_t>(v)])) << what << " vertex " << v;
    ASSERT_EQ(lfs.at_vertex(v), nearest_non_incident(d, v)) << what << " vertex " << v;
    ++checked;
  }
  EXPECT_GT(checked, randoms);
}

TEST(Lfs3, FastEqualsBruteOnCorpus) {
  for (const char* name : {"cube", "l_block", "cube_cavity", "prongs_slot", "schoenhardt", "fins", "plate_holes",
                           "cube_through_hole", "star_vertex", "wedge_1deg"}) {
    const Domain3 d = load(name);
    expect_fast_equals_brute(d, 7, 400, name);
  }
}

TEST(Lfs3, FastEqualsBruteOnRandomPolyhedra) {
  for (std::uint64_t seed = 0; seed < 12; ++seed) {  // 40 seeds pass; 12 keep the suite short
    const Domain3 d = make_domain(test::random_polyhedron(seed));
    expect_fast_equals_brute(d, seed + 100, 150, test::describe_polyhedron(seed));
  }
}

// lfs is 1-Lipschitz: |lfs(x) - lfs(y)| <= |x - y| (up to rounding).
TEST(Lfs3, Lipschitz) {
  for (const char* name : {"l_block", "prongs_slot", "fins"}) {
    const Domain3 d = load(name);
    const LocalFeatureSize3 lfs(d);
    std::mt19937_64 rng(3);
    auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
    const Vec3 lo = d.bbox_min, ext = d.bbox_max - d.bbox_min;
    const double diam = norm(ext);
    for (int k = 0; k < 3000; ++k) {
      const Vec3 x{lo.x + u() * ext.x, lo.y + u() * ext.y, lo.z + u() * ext.z};
      const Vec3 y = x + (0.05 * diam) * Vec3{u() - 0.5, u() - 0.5, u() - 0.5};
      EXPECT_LE(std::abs(lfs.at(x) - lfs.at(y)), norm(x - y) * (1 + 1e-12) + 1e-12 * diam) << name;
    }
  }
}

// Scale and translation act on lfs as expected (on dyadic data both are exact
// up to the rounding of the distances).
TEST(Lfs3, ScalesWithTheDomain) {
  Plc3 plc = read_plc(test::data_path("3d/prongs_slot.poly"));
  const Domain3 d = make_domain(plc);
  for (auto& p : plc.vertices) p = 8.0 * p + Vec3{-3, 5, 0.5};
  for (auto& p : plc.holes) p = 8.0 * p + Vec3{-3, 5, 0.5};
  const Domain3 big = make_domain(plc);
  const LocalFeatureSize3 a(d), b(big);
  std::mt19937_64 rng(5);
  auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  const Vec3 lo = d.bbox_min, ext = d.bbox_max - d.bbox_min;
  for (int k = 0; k < 500; ++k) {
    const Vec3 x{lo.x + u() * ext.x, lo.y + u() * ext.y, lo.z + u() * ext.z};
    EXPECT_NEAR(b.at(8.0 * x + Vec3{-3, 5, 0.5}), 8.0 * a.at(x), 1e-9 * norm(ext));
  }
}

}  // namespace
}  // namespace pqmesh
