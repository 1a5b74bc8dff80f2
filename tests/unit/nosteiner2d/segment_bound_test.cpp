// The segment bound (src/nosteiner2d/segment_bound.hpp;
// docs/algorithm/nosteiner2d.md "The segment bound") against brute force: for
// every side ab of small inputs, every apex p of a fine candidate set for
// which the triangle abp is a possible triangle of a triangulation without
// boundary Steiner points (p strictly left of ab, no point of dP in the open
// triangle) has min angle <= t*(ab) (the bound is never below a triangle
// actually found), and the best of them reaches 0.9 min(t*(ab), alpha_a,
// alpha_b) (the bound is sharp per side up to the candidate spacing; the
// corner angles are the alpha term's).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "corpus2d.hpp"
#include "improve2d/triangle_angles.hpp"
#include "nosteiner2d/segment_bound.hpp"
#include "nosteiner2d/stages.hpp"

namespace pqmesh {
namespace {

// Whether the closed segment cd meets the open triangle abp (counter-
// clockwise): the parameters t in [0, 1] strictly inside all three edge
// half-planes form an open interval, computed in doubles (a test oracle: a
// grazing contact may be decided either way, which the tolerances absorb).
bool meets_open_triangle(Vec2 a, Vec2 b, Vec2 p, Vec2 c, Vec2 d) {
  double lo = 0, hi = 1;
  bool lo_open = false, hi_open = false;
  const Vec2 tri[3] = {a, b, p};
  for (int i = 0; i < 3; ++i) {
    const Vec2 e0 = tri[i], e1 = tri[(i + 1) % 3];
    const double fc = cross(e1 - e0, c - e0), fd = cross(e1 - e0, d - e0);
    if (fc <= 0 && fd <= 0) return false;
    if (fc > 0 && fd > 0) continue;
    const double t = fc / (fc - fd);
    if (fc > 0) {
      if (t < hi || (t == hi && !hi_open)) hi = t, hi_open = true;
    } else if (t > lo || (t == lo && !lo_open)) {
      lo = t, lo_open = true;
    }
  }
  return lo < hi || (lo == hi && !lo_open && !hi_open);
}

// The best min angle over the feasible apexes of side ab (loop sides of d as
// segments): p = a + x u + y n, u = b - a, n its left normal, x in [-1/4,
// 5/4] in steps of 1/400, y = (sqrt 3 / 2) 2^(-j/16) for j = 0..480 (down to
// about 1e-9 of |ab|, so thin features are resolved).
double brute_force_side(const Domain2& d, Vec2 a, Vec2 b) {
  const Vec2 u = b - a, n = {-u.y, u.x};
  std::vector<std::array<Vec2, 2>> sides;
  for (const auto& loop : d.loops)
    for (std::size_t k = 0; k < loop.size(); ++k)
      sides.push_back({d.pslg.vertices[std::size_t(loop[k])], d.pslg.vertices[std::size_t(loop[(k + 1) % loop.size()])]});
  double best = 0;
  for (int j = 0; j <= 480; ++j) {
    const double y = std::sqrt(3.0) / 2 * std::exp2(-j / 16.0);
    for (int i = -100; i <= 500; ++i) {
      const Vec2 p = a + (i / 400.0) * u + y * n;
      const double angle = detail::min_angle(a, b, p);
      if (angle <= best) continue;
      bool empty = true;
      for (const auto& s : sides)
        if (meets_open_triangle(a, b, p, s[0], s[1])) {
          empty = false;
          break;
        }
      if (empty) best = angle;
    }
  }
  return best;
}

// The interior angle of the loop at loop[k] (interior on the left): from
// next - v counter-clockwise to prev - v, in (0, 2 pi).
double interior_angle(const Domain2& d, const std::vector<int>& loop, std::size_t k) {
  const auto& P = d.pslg.vertices;
  const Vec2 v = P[std::size_t(loop[k])], next = P[std::size_t(loop[(k + 1) % loop.size()])],
             prev = P[std::size_t(loop[(k + loop.size() - 1) % loop.size()])];
  const double a = std::atan2(cross(next - v, prev - v), dot(next - v, prev - v));
  return a > 0 ? a : a + 2 * std::numbers::pi;
}

void check_against_brute_force(const Domain2& d, const std::string& what) {
  SCOPED_TRACE(what);
  const detail::SegmentBound sb = detail::segment_bound(d);
  double smallest = std::numbers::pi / 3;
  for (std::size_t l = 0; l < d.loops.size(); ++l) {
    const auto& loop = d.loops[l];
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Vec2 a = d.pslg.vertices[std::size_t(loop[k])], b = d.pslg.vertices[std::size_t(loop[(k + 1) % loop.size()])];
      const double bound = sb.side_angle[l][k], found = brute_force_side(d, a, b);
      EXPECT_LE(found, bound * (1 + 1e-9)) << "loop " << l << " side " << k;
      // The sides at a and b are left to the alpha term (segment_bound.hpp), so the triangle on
      // ab reaches min(t*, alpha_a, alpha_b).
      const double alpha_a = interior_angle(d, loop, k), alpha_b = interior_angle(d, loop, (k + 1) % loop.size());
      EXPECT_GE(found, 0.9 * std::min({bound, alpha_a, alpha_b})) << "loop " << l << " side " << k;
      smallest = std::min(smallest, bound);
    }
  }
  EXPECT_EQ(sb.angle, smallest);
  // The CDT is a triangulation without boundary Steiner points.
  EXPECT_LE(cdt_min_angle(d), sb.angle * (1 + 1e-12));
}

TEST(SegmentBound, CorpusAgainstBruteForce) {
  for (const char* name : {"square", "l_shape", "comb", "spike_1deg", "spike_10deg", "regions"})
    check_against_brute_force(test::corpus_domain(name), name);
}

TEST(SegmentBound, HardCasesAgainstBruteForce) {
  for (const test::NamedDomain& c : test::hard_case_domains())
    if (c.domain.pslg.vertices.size() <= 60) check_against_brute_force(c.domain, c.name);
}

// Random star-shaped 7-gons with a square hole near one side (dyadic
// coordinates, multiples of 2^-20): obstacles at every distance from the sides.
TEST(SegmentBound, RandomSmallPolygonsAgainstBruteForce) {
  std::mt19937_64 rng(11);
  auto unit = [&] { return std::ldexp(static_cast<double>(rng() >> 44), -20); };
  for (int k = 0; k < 12; ++k) {
    std::vector<Vec2> outer;
    for (int i = 0; i < 7; ++i) {
      const double r = 1 + unit(), phi = 2 * std::numbers::pi * (i + 0.8 * unit()) / 7;
      outer.push_back({std::ldexp(std::round(std::ldexp(r * std::cos(phi), 20)), -20),
                       std::ldexp(std::round(std::ldexp(r * std::sin(phi), 20)), -20)});
    }
    const double w = std::ldexp(1.0, -3 - int(unit() * 8)), x = (unit() - 0.5) * 0.5, y = -0.9 + 0.5 * unit();
    const std::vector<Vec2> hole = {{x, y}, {x, y + w}, {x + w, y + w}, {x + w, y}};
    Pslg2 p = test::loops_pslg({outer, hole});
    p.holes.push_back({x + w / 2, y + w / 2});
    Domain2 d;
    try {
      d = make_domain(p);
    } catch (const std::exception&) {
      continue;  // the hole crossed the outer loop: not an input
    }
    check_against_brute_force(d, "random 7-gon " + std::to_string(k));
  }
}

// The thin trapezoid of the thesis's Fig. 1.1, derived by hand: on the long
// side A = (0,0), B = (1,0) the top vertices (7/16, t), (9/16, t) give
// max(angle qAB, angle qBA) = atan(t / (7/16)) for both, and the bisector
// crossing of the top side (1/2, t) gives atan(t / (1/2)), the smaller: t*(AB)
// = atan(2 t), the bound's value up to the rounding margin of the crossing
// (the other sides give more).
TEST(SegmentBound, ThinTrapezoidByHand) {
  for (const double t : {1.0 / 64, 1.0 / 1024}) {
    const Domain2 d = test::polygon({{0, 0}, {1, 0}, {0.5625, t}, {0.4375, t}});
    const detail::SegmentBound sb = detail::segment_bound(d);
    // The crossing is a constructed point: its angle is raised by 2^-48 s / h (s = 1, h = t).
    EXPECT_GE(sb.angle, std::atan(2 * t));
    EXPECT_LE(sb.angle, std::atan(2 * t) + std::ldexp(1.0, -48) / t + 1e-15);
    EXPECT_EQ(sb.side, 0);
  }
}

}  // namespace
}  // namespace pqmesh
