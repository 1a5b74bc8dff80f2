// An independent brute-force oracle for the per-(V, E) minimum of h(E, W):
// plain floating-point code written from the definitions in
// pqmesh/nosteiner.hpp (angles by atan2, distances by hypot, no clipping, no
// exact predicates), sampling every interfering side densely and refining
// around the best sample. It bounds the module from both sides:
//   computed <= oracle * (1 + 1e-7) (the oracle only finds eligible points,
//   up to its own rounding: where a side is tangent to the disk |VW| <= L,
//   hypot() accepts points ~sqrt(eps) L outside it, and h is continuous), and
//   computed >= oracle * (1 - 1e-3) (sampling resolution).
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <numbers>

#include "pqmesh/domain.hpp"
#include "nosteiner2d/stages.hpp"
#include "pqmesh/read_domain.hpp"
#include "support/paths.hpp"
#include "support/random_domains.hpp"

namespace pqmesh {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

struct OracleFrame {
  Vec2 V, U, F;
  double hand = 1, alpha = 0, L = 0;
  double angle(Vec2 w) const {  // polar angle from E, the frame's way, in [0, 2 pi)
    const Vec2 d = U - V, x = w - V;
    double a = std::atan2(hand * (d.x * x.y - d.y * x.x), d.x * x.x + d.y * x.y);
    return a < 0 ? a + kTwoPi : a;
  }
  // h(E, W) for an eligible W, +inf otherwise.
  double h(Vec2 w) const {
    const double rv = std::hypot(w.x - V.x, w.y - V.y), ru = std::hypot(w.x - U.x, w.y - U.y);
    if (rv > L || rv > ru) return std::numeric_limits<double>::infinity();
    double om = angle(w);
    if (om > alpha) {
      // Outside the interior sector, except for rounding right at E's ray.
      if (kTwoPi - om < 1e-12)
        om = 0;
      else
        return std::numeric_limits<double>::infinity();
    }
    return om / std::max(1.0, -std::log(rv / L));
  }
};

double oracle_min_h(const Domain2& d, int loop, int k, bool ccw, bool far_end) {
  const auto& ids = d.loops[loop];
  const int n = static_cast<int>(ids.size());
  const auto& P = d.pslg.vertices;
  const int v = ids[k], u = ccw ? ids[(k + 1) % n] : ids[(k + n - 1) % n],
            f = ccw ? ids[(k + n - 1) % n] : ids[(k + 1) % n];
  OracleFrame fr{P[v], P[u], P[f], ccw ? 1.0 : -1.0, 0, std::hypot(P[u].x - P[v].x, P[u].y - P[v].y)};
  fr.alpha = fr.angle(fr.F);
  double best = std::numeric_limits<double>::infinity();
  for (const auto& lp : d.loops) {
    const int m = static_cast<int>(lp.size());
    for (int i = 0; i < m; ++i) {
      const int a = lp[i], b = lp[(i + 1) % m];
      if (a != v && a != u) best = std::min(best, fr.h(P[a]));
      if (a == v || b == v || (!far_end && (a == u || b == u))) continue;
      const Vec2 A = P[a], B = P[b];
      auto at = [&](double t) { return Vec2{A.x + t * (B.x - A.x), A.y + t * (B.y - A.y)}; };
      // Skip sides entirely farther than L (by their closest point).
      const Vec2 D = B - A;
      const double t0 = std::clamp(dot(fr.V - A, D) / dot(D, D), 0.0, 1.0);
      if (std::hypot(at(t0).x - fr.V.x, at(t0).y - fr.V.y) > fr.L * 1.001) continue;
      const int N = 2000;
      double bt = 0, bh = std::numeric_limits<double>::infinity();
      for (int s = 0; s <= N; ++s) {
        const double hv = fr.h(at(static_cast<double>(s) / N));
        if (hv < bh) bh = hv, bt = static_cast<double>(s) / N;
      }
      double width = 1.0 / N;
      for (int round = 0; round < 3 && std::isfinite(bh); ++round) {
        const double lo = std::max(0.0, bt - width), hi = std::min(1.0, bt + width);
        for (int s = 0; s <= 200; ++s) {
          const double t = lo + (hi - lo) * s / 200;
          const double hv = fr.h(at(t));
          if (hv < bh) bh = hv, bt = t;
        }
        width /= 50;
      }
      best = std::min(best, bh);
    }
  }
  return best;
}

void compare_with_oracle(const Domain2& d, const std::string& what, bool far_end) {
  SCOPED_TRACE(what + (far_end ? " (sides at far end)" : ""));
  const std::vector<EmptySpiral> spirals = empty_spirals(d, {.sides_at_far_end = far_end});
  std::size_t idx = 0;
  for (int l = 0; l < static_cast<int>(d.loops.size()); ++l)
    for (int k = 0; k < static_cast<int>(d.loops[l].size()); ++k)
      for (const bool ccw : {true, false}) {
        const EmptySpiral& e = spirals.at(idx++);
        const double o = oracle_min_h(d, l, k, ccw, far_end);
        const double c = e.has_eligible ? e.min_h : std::numeric_limits<double>::infinity();
        if (!std::isfinite(o)) {
          EXPECT_FALSE(std::isfinite(c)) << "vertex " << e.vertex << " other " << e.other << " h " << c;
          continue;
        }
        ASSERT_TRUE(std::isfinite(c)) << "vertex " << e.vertex << " other " << e.other << " oracle " << o;
        EXPECT_LE(c, o * (1 + 1e-7)) << std::setprecision(17) << c << " vs " << o << " vertex " << e.vertex << " other "
                                     << e.other;
        EXPECT_GE(c, o * (1 - 1e-3)) << "vertex " << e.vertex << " other " << e.other;
      }
}

TEST(SteinerFreeOracle, Corpus) {
  for (const char* name : {"square", "l_shape", "comb", "spike_1deg", "spike_5deg", "spike_10deg", "square_holes"}) {
    const std::string path = test::data_path(std::string("2d/") + name + ".poly");
    for (const bool far_end : {false, true}) compare_with_oracle(make_domain(read_pslg(path)), name, far_end);
  }
}

TEST(SteinerFreeOracle, RandomPolygonsWithHoles) {
  for (std::uint64_t seed = 1; seed <= 60; ++seed)
    for (const bool far_end : {false, true})
      compare_with_oracle(make_domain(test::random_polygon_with_holes(seed)), test::describe_polygon(seed), far_end);
}

}  // namespace
}  // namespace pqmesh
