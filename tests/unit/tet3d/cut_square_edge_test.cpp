// §4.4 Cases B and D on single box-face squares (cut_square_edge.hpp):
// random P edges (two random facet planes through a random line, convex or
// reflex) through random octrees of the unit cube. For every face square of
// every leaf, the triangles of π = S ∩ P (P near the edge: the wedge of the
// two facets) must
//   * be counter-clockwise about +n (exact orient2d on the projection),
//   * have every vertex exactly on S's plane and in the closed square, and
//     inside P by exact predicates or within an ulp of F's or G's plane or of
//     E (an edge crossing: within an ulp of E, with S's coordinate exact),
//   * have total area equal to the area of π computed independently by
//     clipping the square's corners in long double (convex: both half-planes;
//     reflex: inclusion-exclusion), relative 1e-9 of the square's area,
// and triangulating the same square again into the same PointBook (the other
// box sharing it) must give the same triangles and no new vertex; every
// square sharing a box-edge segment must put the same vertices on it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <random>
#include <vector>

#include "../plc/domain_fixtures.hpp"
#include "pqmesh/domain.hpp"
#include "predicates/predicates.hpp"
#include "square_test_util.hpp"
#include "tet3d/squares/cut_square_edge.hpp"

namespace pqmesh::tet3d {
namespace {

using test::coord;

struct Wedge {
  Domain3 domain;
  bool convex = true;
};

// The edge a-b with facet 0 spanned towards wf and facet 1 towards wg, each a
// single triangle oriented so that P is the convex sector between the
// half-planes (convex) or its complement (reflex).
Wedge make_wedge(Vec3 a, Vec3 b, Vec3 wf, Vec3 wg, bool convex) {
  Wedge w;
  w.convex = convex;
  Domain3& d = w.domain;
  d.plc.vertices = {a, b, wf, wg};
  // side_F(x) = orient3d(tri_F, x); convex needs side_F(wg) < 0.
  const Sign want = convex ? Sign::Negative : Sign::Positive;
  std::array<int, 3> tf{0, 1, 2}, tg{0, 1, 3};
  if (orient3d(a, b, wf, wg) != want) tf = {1, 0, 2};
  if (orient3d(a, b, wg, wf) != want) tg = {1, 0, 3};
  d.facet_triangles = {tf, tg};
  d.facet_triangle_owner = {0, 1};
  DomainEdge e;
  e.a = 0;
  e.b = 1;
  e.facets = {0, 1};
  d.edges = {e};
  return w;
}

// Long double plane of a facet triangle: distance-like value, positive beyond.
struct LPlane {
  long double n[3], o[3];
  long double at(const std::array<long double, 3>& p) const {
    return n[0] * (p[0] - o[0]) + n[1] * (p[1] - o[1]) + n[2] * (p[2] - o[2]);
  }
};
LPlane lplane(const Domain3& d, int t) {
  const auto& tri = d.facet_triangles[static_cast<std::size_t>(t)];
  long double v[3][3];
  for (int k = 0; k < 3; ++k) {
    const Vec3& p = d.plc.vertices[static_cast<std::size_t>(tri[static_cast<std::size_t>(k)])];
    v[k][0] = p.x;
    v[k][1] = p.y;
    v[k][2] = p.z;
  }
  const long double e1[3] = {v[1][0] - v[0][0], v[1][1] - v[0][1], v[1][2] - v[0][2]};
  const long double e2[3] = {v[2][0] - v[0][0], v[2][1] - v[0][1], v[2][2] - v[0][2]};
  LPlane pl;
  pl.n[0] = e1[1] * e2[2] - e1[2] * e2[1];
  pl.n[1] = e1[2] * e2[0] - e1[0] * e2[2];
  pl.n[2] = e1[0] * e2[1] - e1[1] * e2[0];
  for (int k = 0; k < 3; ++k) pl.o[k] = v[0][k];
  return pl;
}

using LPoly = std::vector<std::array<long double, 3>>;
LPoly clip(const LPoly& poly, const LPlane& pl) {
  LPoly out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const auto& p = poly[i];
    const auto& q = poly[(i + 1) % poly.size()];
    const long double dp = pl.at(p), dq = pl.at(q);
    if (dp <= 0) out.push_back(p);
    if ((dp < 0 && dq > 0) || (dp > 0 && dq < 0)) {
      const long double t = dp / (dp - dq);
      out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]), p[2] + t * (q[2] - p[2])});
    }
  }
  return out;
}
long double area(const LPoly& poly, int u, int v) {
  long double s = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const auto& p = poly[i];
    const auto& q = poly[(i + 1) % poly.size()];
    s += p[static_cast<std::size_t>(u)] * q[static_cast<std::size_t>(v)] -
         q[static_cast<std::size_t>(u)] * p[static_cast<std::size_t>(v)];
  }
  return s / 2;
}

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  for (;;) {
    const Vec3 d{g(rng), g(rng), g(rng)};
    const double l = norm(d);
    if (l > 0.1) return (1.0 / l) * d;
  }
}

TEST(CutSquareEdge, RandomEdgesThroughRandomTrees) {
  std::map<EdgeCutCase, int> cases;
  int b_convex = 0, b_reflex = 0, d2_any = 0;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (std::uint64_t seed = 1; seed <= 16; ++seed) {
    std::mt19937_64 rng(seed);
    const OctTree t = test::random_tree(rng);
    const std::vector<std::int32_t> leaves = t.leaves();
    const CornerSet corners(t, leaves);
    std::vector<FaceSquare> squares;
    for (const std::int32_t leaf : leaves)
      for (int axis = 0; axis < 3; ++axis)
        for (const bool upper : {false, true}) face_squares(t.key(leaf), axis, upper, corners, squares);
    for (int edge = 0; edge < 5; ++edge) {
      const Vec3 m{unit(rng), unit(rng), unit(rng)};
      const Vec3 d = random_unit(rng);
      const Vec3 a = m - 4.0 * d, b = m + 4.0 * d;
      // Facet directions orthogonal to d, at a random angle (sharp ones too).
      Vec3 p = random_unit(rng);
      p = p - dot(p, d) * d;
      p = (1.0 / norm(p)) * p;
      const Vec3 q = cross(d, p);
      const double angle = (edge % 3 == 0 ? 0.3 : 3.0) * unit(rng) + 0.05;
      const Vec3 wf = m + 2.0 * p + unit(rng) * d;
      const Vec3 wg = m + 2.0 * (std::cos(angle) * p + std::sin(angle) * q) - unit(rng) * d;
      const bool convex = (rng() & 1) != 0;
      const Wedge w = make_wedge(a, b, wf, wg, convex);
      const EdgeCone cone(w.domain, 0);
      ASSERT_EQ(cone.convex(), convex);
      const LPlane lf = lplane(w.domain, 0), lg = lplane(w.domain, 1);
      const Vec3 tf[3] = {w.domain.plc.vertices[static_cast<std::size_t>(w.domain.facet_triangles[0][0])],
                          w.domain.plc.vertices[static_cast<std::size_t>(w.domain.facet_triangles[0][1])],
                          w.domain.plc.vertices[static_cast<std::size_t>(w.domain.facet_triangles[0][2])]};
      const Vec3 tg[3] = {w.domain.plc.vertices[static_cast<std::size_t>(w.domain.facet_triangles[1][0])],
                          w.domain.plc.vertices[static_cast<std::size_t>(w.domain.facet_triangles[1][1])],
                          w.domain.plc.vertices[static_cast<std::size_t>(w.domain.facet_triangles[1][2])]};
      PointBook book;
      // Conformity across squares: the vertices a square puts on a box-edge
      // segment of its ring (found by coordinates) must be the same for every
      // square sharing that segment.
      std::map<std::pair<GridPoint, GridPoint>, std::vector<int>> on_segment;
      for (const FaceSquare& s : squares) {
        std::vector<std::array<int, 3>> tris, again;
        const EdgeCutCase cc = triangulate_edge_square(s, corners, t, cone, book, tris);
        ++cases[cc];
        if (cc == EdgeCutCase::B) ++(convex ? b_convex : b_reflex);
        if (cc == EdgeCutCase::D2Inside || cc == EdgeCutCase::D2On || cc == EdgeCutCase::D2Outside) ++d2_any;
        const int before = book.size();
        triangulate_edge_square(s, corners, t, cone, book, again);
        EXPECT_EQ(tris, again);
        EXPECT_EQ(book.size(), before);
        const std::array<Vec3, 4> sq = test::square_corners(t, s);
        double got = 0;
        for (const auto& tri : tris) {
          const Vec3 p0 = book.point(tri[0]), p1 = book.point(tri[1]), p2 = book.point(tri[2]);
          EXPECT_EQ(orient2d_projected(p0, p1, p2, s.n), Sign::Positive)
              << "seed " << seed << " edge " << edge << " case " << static_cast<int>(cc);
          for (const int id : tri) {
            const Vec3 x = book.point(id);
            EXPECT_TRUE(test::on_closed_square(x, sq, s)) << "seed " << seed << " edge " << edge;
            const Sign xf = orient3d(tf[0], tf[1], tf[2], x), xg = orient3d(tg[0], tg[1], tg[2], x);
            const bool inside =
                convex ? (xf != Sign::Positive && xg != Sign::Positive) : (xf != Sign::Positive || xg != Sign::Positive);
            EXPECT_TRUE(inside || within_ulp_of_plane(x, tf[0], tf[1], tf[2]) ||
                        within_ulp_of_plane(x, tg[0], tg[1], tg[2]) || within_ulp_of_segment(x, a, b))
                << "seed " << seed << " edge " << edge;
            if (book.key(id).kind == VertexKind::EdgeCrossing) {
              EXPECT_TRUE(within_ulp_of_segment(x, a, b));
            }
          }
          got += test::uv_area(p0, p1, p2, s.u, s.v);
        }
        const std::vector<GridPoint> ring = square_ring(s, corners);
        for (std::size_t i = 0; i < ring.size(); ++i) {
          const GridPoint& g0 = std::min(ring[i], ring[(i + 1) % ring.size()]);
          const GridPoint& g1 = std::max(ring[i], ring[(i + 1) % ring.size()]);
          const Vec3 x0 = grid_coordinates(t, g0), x1 = grid_coordinates(t, g1);
          std::vector<int> ids;
          for (const auto& tri : tris)
            for (const int id : tri) {
              const Vec3 x = book.point(id);
              bool on = true;
              for (int ax = 0; ax < 3; ++ax)
                on = on && coord(x, ax) >= std::min(coord(x0, ax), coord(x1, ax)) &&
                     coord(x, ax) <= std::max(coord(x0, ax), coord(x1, ax));
              if (on) ids.push_back(id);
            }
          std::sort(ids.begin(), ids.end());
          ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
          const auto [it, fresh] = on_segment.try_emplace({g0, g1}, ids);
          if (!fresh) {
            EXPECT_EQ(it->second, ids) << "seed " << seed << " edge " << edge << " case " << static_cast<int>(cc);
          }
        }
        LPoly poly;
        for (const Vec3& c : sq) poly.push_back({c.x, c.y, c.z});
        const long double af = area(clip(poly, lf), s.u, s.v), ag = area(clip(poly, lg), s.u, s.v);
        const long double afg = area(clip(clip(poly, lf), lg), s.u, s.v);
        const double expected = static_cast<double>(convex ? afg : af + ag - afg);
        const double h = coord(sq[2] - sq[0], s.u);
        EXPECT_NEAR(got, expected, 1e-9 * h * h)
            << "seed " << seed << " edge " << edge << " case " << static_cast<int>(cc);
      }
    }
  }
  const char* names[] = {"empty", "whole", "B", "one facet (C)", "D1", "D2 inside", "D2 on", "D2 outside", "D two pieces"};
  for (const auto& [cc, count] : cases) std::printf("%s: %d squares\n", names[static_cast<int>(cc)], count);
  std::printf("B convex %d, B reflex %d\n", b_convex, b_reflex);
  EXPECT_GT(b_convex, 0);
  EXPECT_GT(b_reflex, 0);
  EXPECT_GT(cases[EdgeCutCase::D1], 0);
  EXPECT_GT(d2_any, 0);
  EXPECT_GT(cases[EdgeCutCase::DTwoPieces], 0);
  EXPECT_GT(cases[EdgeCutCase::OneFacet], 0);
}

// Exact convexity and the crossing-side identity on a hand-made right-angle
// edge along z: F = {y = 0, x >= 0}, G = {x = 0, y >= 0}.
TEST(CutSquareEdge, ConeSignsByHand) {
  for (const bool convex : {true, false}) {
    const Wedge w = make_wedge({0, 0, -1}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, convex);
    const EdgeCone cone(w.domain, 0);
    EXPECT_EQ(cone.convex(), convex);
    // Convex: P is the quadrant x > 0, y > 0; reflex: its complement.
    EXPECT_EQ(cone.status({0.5, 0.5, 0}), convex ? Sign::Negative : Sign::Positive);
    EXPECT_EQ(cone.status({-0.5, 0.5, 0}), convex ? Sign::Positive : Sign::Negative);
    EXPECT_EQ(cone.status({0.5, 0, 0}), Sign::Zero);
    EXPECT_EQ(cone.status({-0.5, 0, 0}), convex ? Sign::Positive : Sign::Negative);
    // Segment from (1, -1) to (1, 1) crosses F (y = 0) at (1, 0), where x = 1 > 0:
    // on G's "x > 0" side, which is P's side of G iff convex.
    const Sign at = cone.g_at_f_crossing({1, -1, 0}, {1, 1, 0});
    EXPECT_EQ(at, cone.g().side({1, 0, 0}));
    // And G's crossing of the segment from (-1, 2) to (1, 2), at (0, 2).
    EXPECT_EQ(cone.f_at_g_crossing({-1, 2, 0}, {1, 2, 0}), cone.f().side({0, 2, 0}));
    EXPECT_EQ(cone.g_at_f_crossing({-1, -1, 0}, {1, 1, 0}), Sign::Zero);  // through the edge
  }
}

// The unit cube with its bottom split along the diagonal (0, 2)
// (test::cube_with_split_bottom, facet 0 = (0, 3, 2) where y > x, facet 1 =
// (0, 2, 1) where x > y): the edge (0, 2) is flat. Its cone is P's side of
// z = 0 (z > 0), convex; the "sign of G" on the plane is the side of the
// diagonal, Negative in F's (facet 0's) half y > x; at a crossing it is the
// side of the crossing point. Expected signs read off the picture.
TEST(CutSquareEdge, AFlatEdgeSplitsItsPlaneByItsLine) {
  const Domain3 d = make_domain(test::cube_with_split_bottom());
  int flat = -1, crease = -1;
  for (std::size_t e = 0; e < d.edges.size(); ++e) {
    if (d.edges[e].a == 0 && d.edges[e].b == 2) flat = static_cast<int>(e);
    if (d.edges[e].a == 0 && d.edges[e].b == 1) crease = static_cast<int>(e);
  }
  ASSERT_GE(flat, 0);
  ASSERT_GE(crease, 0);
  EXPECT_TRUE(EdgeCone(d, crease).convex());
  EXPECT_FALSE(EdgeCone(d, crease).flat());
  const EdgeCone cone(d, flat);
  EXPECT_TRUE(cone.flat());
  EXPECT_TRUE(cone.convex());
  EXPECT_EQ(cone.f().facet(), 0);
  EXPECT_EQ(cone.status({0.3, 0.6, 0.5}), Sign::Negative);
  EXPECT_EQ(cone.status({0.6, 0.3, 0.5}), Sign::Negative);
  EXPECT_EQ(cone.status({0.3, 0.6, -0.5}), Sign::Positive);
  EXPECT_EQ(cone.status({0.6, 0.3, 0}), Sign::Zero);
  EXPECT_EQ(cone.g_on_f({0.2, 0.8, 0}), Sign::Negative);
  EXPECT_EQ(cone.g_on_f({0.8, 0.2, 0}), Sign::Positive);
  EXPECT_EQ(cone.g_on_f({0.5, 0.5, 0}), Sign::Zero);
  EXPECT_EQ(cone.f_on_g({0.8, 0.2, 0}), Sign::Negative);
  EXPECT_EQ(cone.f_on_g({0.2, 0.8, 0}), Sign::Positive);
  // Crossings of z = 0 in either direction, in either half.
  EXPECT_EQ(cone.g_at_f_crossing({0.2, 0.8, -1}, {0.2, 0.8, 1}), Sign::Negative);
  EXPECT_EQ(cone.g_at_f_crossing({0.2, 0.8, 1}, {0.3, 0.7, -1}), Sign::Negative);
  EXPECT_EQ(cone.g_at_f_crossing({0.8, 0.2, 1}, {0.8, 0.2, -1}), Sign::Positive);
  EXPECT_EQ(cone.f_at_g_crossing({0.8, 0.2, 1}, {0.8, 0.2, -1}), Sign::Negative);
  EXPECT_EQ(cone.f_at_g_crossing({0.2, 0.8, -1}, {0.2, 0.8, 1}), Sign::Positive);
  EXPECT_EQ(cone.g_at_f_crossing({0.5, 0.5, -1}, {0.5, 0.5, 1}), Sign::Zero);  // through the edge
}

}  // namespace
}  // namespace pqmesh::tet3d
