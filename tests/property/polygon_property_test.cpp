// Property tests of the 2D foundation (make_domain, Domain2, locate,
// compute_alpha) over 300 seeded random polygons with holes
// (tests/support/random_domains.hpp). Every expected value is computed here
// independently from the generator's structured loops, not from Domain2.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "pqmesh/alpha.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/errors.hpp"
#include "predicates/predicates.hpp"
#include "support/random_domains.hpp"

namespace pqmesh::test {
namespace {

constexpr std::uint64_t kPolygons = 300;

using Loop = std::vector<Vec2>;


// Exact turn at the lowest (then leftmost) vertex of a cyclic sequence.
Sign lowest_corner_turn(const std::vector<Vec2>& P, const std::vector<int>& loop) {
  std::size_t k = 0;
  for (std::size_t i = 1; i < loop.size(); ++i) {
    const Vec2 a = P[loop[i]], b = P[loop[k]];
    if (a.y < b.y || (a.y == b.y && a.x < b.x)) k = i;
  }
  const std::size_t n = loop.size();
  return orient2d(P[loop[(k + n - 1) % n]], P[loop[k]], P[loop[(k + 1) % n]]);
}

// The same cyclic sequence of points, up to rotation (direction included).
bool same_cycle(const Loop& a, const Loop& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t r = 0; r < a.size(); ++r) {
    bool ok = true;
    for (std::size_t i = 0; i < a.size() && ok; ++i) ok = a[i] == b[(i + r) % b.size()];
    if (ok) return true;
  }
  return false;
}

double min_loop_gap(const std::vector<Loop>& loops) {
  auto point_segment = [](Vec2 p, Vec2 a, Vec2 b) {
    const Vec2 ab = b - a;
    const double t = std::clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
    return norm(p - (a + t * ab));
  };
  double best = HUGE_VAL;
  for (std::size_t i = 0; i < loops.size(); ++i)
    for (std::size_t j = 0; j < loops.size(); ++j) {
      if (i == j) continue;
      for (Vec2 p : loops[i])
        for (std::size_t k = 0; k < loops[j].size(); ++k)
          best = std::min(best, point_segment(p, loops[j][k], loops[j][(k + 1) % loops[j].size()]));
    }
  return best;
}

double outer_diameter(const Loop& L) {
  double xlo = HUGE_VAL, xhi = -HUGE_VAL, ylo = HUGE_VAL, yhi = -HUGE_VAL;
  for (Vec2 p : L) xlo = std::min(xlo, p.x), xhi = std::max(xhi, p.x), ylo = std::min(ylo, p.y), yhi = std::max(yhi, p.y);
  return std::max(xhi - xlo, yhi - ylo);
}

// Properties 1-3: validity, area, loop orientation and identity, alpha.
TEST(PolygonProperty, DomainAreaOrientationAndAlpha) {
  for (std::uint64_t seed = 0; seed < kPolygons; ++seed) {
    SCOPED_TRACE(describe_polygon(seed));
    const PolygonWithHoles poly = random_polygon_loops(seed);
    Domain2 d;
    try {
      d = make_domain(random_polygon_with_holes(seed));
    } catch (const Error& e) {
      ADD_FAILURE() << "make_domain rejected a generated polygon: " << e.what();
      continue;
    }
    ASSERT_EQ(d.loops.size(), poly.loops.size());

    double area = 0;
    for (const Loop& L : poly.loops) area += shoelace(L);
    EXPECT_GT(area, 0);
    EXPECT_NEAR(d.area, area, 1e-12 * area);

    const auto& P = d.pslg.vertices;
    for (std::size_t l = 0; l < d.loops.size(); ++l) {
      EXPECT_EQ(lowest_corner_turn(P, d.loops[l]), l == 0 ? Sign::Positive : Sign::Negative) << "loop " << l;
      // Each Domain2 loop is one of the generated loops, same direction.
      Loop pts;
      for (int v : d.loops[l]) pts.push_back(P[v]);
      if (l == 0) {
        EXPECT_TRUE(same_cycle(pts, poly.loops[0])) << "outer loop";
      } else {
        EXPECT_TRUE(std::any_of(poly.loops.begin() + 1, poly.loops.end(),
                                [&](const Loop& h) { return same_cycle(pts, h); }))
            << "hole loop " << l;
      }
      // loop_segments[l][k] joins loops[l][k] and loops[l][k + 1].
      ASSERT_EQ(d.loop_segments[l].size(), d.loops[l].size());
      for (std::size_t k = 0; k < d.loops[l].size(); ++k) {
        const auto s = d.pslg.segments[d.loop_segments[l][k]];
        const int a = d.loops[l][k], b = d.loops[l][(k + 1) % d.loops[l].size()];
        EXPECT_TRUE((s[0] == a && s[1] == b) || (s[0] == b && s[1] == a)) << "loop " << l << " side " << k;
      }
    }

    const AlphaResult alpha = compute_alpha(P, d.loops);
    EXPECT_NEAR(alpha.radians, smallest_corner_angle(poly.loops), 1e-12);
    EXPECT_GT(alpha.radians, 0);
    EXPECT_LT(alpha.radians, std::numbers::pi);  // a polygon always has a convex corner

    // Hole points lie in their holes, every vertex and edge midpoint is on the
    // boundary (midpoints of dyadic points are exact).
    for (Vec2 h : poly.hole_points) EXPECT_EQ(locate(d, h), Location::Outside);
    for (const Loop& L : poly.loops)
      for (std::size_t i = 0; i < L.size(); ++i) {
        EXPECT_EQ(locate(d, L[i]), Location::Boundary);
        EXPECT_EQ(locate(d, 0.5 * (L[i] + L[(i + 1) % L.size()])), Location::Boundary);
      }
  }
}

// The corpus really has the advertised features (so the properties above are
// exercised on them): holes, spikes with corners down to a few degrees,
// near-touching loops, coarse-grid snapping, scale changes.
TEST(PolygonProperty, CorpusCoversTheHardCases) {
  int with_holes = 0, spikes = 0, near = 0, snapped = 0, below_3_deg = 0, tiny_gap = 0;
  double smallest = HUGE_VAL;
  for (std::uint64_t seed = 0; seed < kPolygons; ++seed) {
    const PolygonWithHoles poly = random_polygon_loops(seed);
    with_holes += poly.loops.size() > 1;
    spikes += poly.spikes > 0;
    near += poly.near_touching > 0;
    snapped += poly.snapped > 0;
    const double a = smallest_corner_angle(poly.loops);
    smallest = std::min(smallest, a);
    below_3_deg += a < 3 * std::numbers::pi / 180;
    if (poly.loops.size() > 1) tiny_gap += min_loop_gap(poly.loops) < 5e-3 * outer_diameter(poly.loops[0]);
  }
  EXPECT_GE(with_holes, 200);
  EXPECT_GE(spikes, 60);
  EXPECT_GE(near, 60);
  EXPECT_GE(snapped, 60);
  EXPECT_GE(below_3_deg, 10);
  EXPECT_LT(smallest, 1.5 * std::numbers::pi / 180);
  EXPECT_GE(tiny_gap, 40);
}

// Property 7 (2D): the same seed gives bitwise identical output; different
// seeds give different polygons.
TEST(PolygonProperty, Deterministic) {
  auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v); };
  for (std::uint64_t seed = 0; seed < kPolygons; seed += 7) {
    const Pslg2 a = random_polygon_with_holes(seed), b = random_polygon_with_holes(seed);
    ASSERT_EQ(a.vertices.size(), b.vertices.size()) << seed;
    for (std::size_t i = 0; i < a.vertices.size(); ++i) {
      EXPECT_EQ(bits(a.vertices[i].x), bits(b.vertices[i].x)) << seed;
      EXPECT_EQ(bits(a.vertices[i].y), bits(b.vertices[i].y)) << seed;
    }
    EXPECT_EQ(a.segments, b.segments) << seed;
    EXPECT_EQ(a.segment_markers, b.segment_markers) << seed;
    EXPECT_EQ(a.vertex_markers, b.vertex_markers) << seed;
    ASSERT_EQ(a.holes.size(), b.holes.size()) << seed;
    for (std::size_t i = 0; i < a.holes.size(); ++i) {
      EXPECT_EQ(bits(a.holes[i].x), bits(b.holes[i].x)) << seed;
      EXPECT_EQ(bits(a.holes[i].y), bits(b.holes[i].y)) << seed;
    }
    const Pslg2 c = random_polygon_with_holes(seed + 1);
    EXPECT_FALSE(a.vertices.size() == c.vertices.size() &&
                 std::equal(a.vertices.begin(), a.vertices.end(), c.vertices.begin()))
        << seed;
  }
}

// The knobs: other option sets still give valid domains with the requested
// features (no shuffling keeps the structured order; many near-touching holes).
TEST(PolygonProperty, OptionVariantsAreValid) {
  PolygonOptions plain;
  plain.shuffle_ids = false;
  plain.random_scale = false;
  PolygonOptions crowded;
  crowded.max_holes = 10;
  crowded.near_touch_probability = 1;
  crowded.spike_probability = 1;
  PolygonOptions convex_ish;
  convex_ish.min_vertices = 3;
  convex_ish.max_vertices = 4;
  convex_ish.max_holes = 0;
  for (std::uint64_t seed = 0; seed < 40; ++seed) {
    const PolygonWithHoles p = random_polygon_loops(seed, plain);
    const Pslg2 g = random_polygon_with_holes(seed, plain);
    // Unshuffled: vertices in loop order, segment k from vertex k to k + 1.
    std::size_t k = 0;
    for (const Loop& L : p.loops)
      for (std::size_t i = 0; i < L.size(); ++i, ++k) {
        EXPECT_EQ(g.vertices[k], L[i]);
        EXPECT_EQ(g.segments[k][0], static_cast<int>(k));
      }
    for (const PolygonOptions* o : {&plain, &crowded, &convex_ish}) {
      SCOPED_TRACE(describe_polygon(seed, *o));
      EXPECT_NO_THROW(make_domain(random_polygon_with_holes(seed, *o)));
    }
    EXPECT_EQ(random_polygon_loops(seed, convex_ish).loops.size(), 1u);
  }
}

// Coordinates are exact dyadic rationals (so midpoints are exact and values
// can coincide with tree box planes).
TEST(PolygonProperty, CoordinatesAreDyadic) {
  for (std::uint64_t seed = 0; seed < kPolygons; seed += 3) {
    const Pslg2 p = random_polygon_with_holes(seed);
    for (Vec2 v : p.vertices)
      for (double c : {v.x, v.y}) {
        // Multiples of 2^-30 (grid 2^-20 times scale >= 2^-3, offsets multiples of 1/4).
        const double scaled = std::ldexp(c, 30);
        EXPECT_EQ(scaled, std::round(scaled)) << "seed " << seed << " coordinate " << c;
      }
  }
}

}  // namespace
}  // namespace pqmesh::test
