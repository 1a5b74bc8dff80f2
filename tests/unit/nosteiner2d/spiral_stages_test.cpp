// Smallest spiral and smallest optimal spiral (thesis §5.1, Theorems 16-20,
// 22, 24): properties the thesis proves for them, checked on every (V, E) of
// the corpus and of random polygons.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "pqmesh/domain.hpp"
#include "nosteiner2d/stages.hpp"
#include "pqmesh/read_domain.hpp"
#include "support/paths.hpp"
#include "support/random_domains.hpp"
#include "corpus2d.hpp"

namespace pqmesh {
namespace {

constexpr double kPi = std::numbers::pi;

void check_spirals(const Domain2& d, const std::string& what) {
  SCOPED_TRACE(what);
  for (const EmptySpiral& e : empty_spirals(d)) {
    ASSERT_LE(e.log_shrink, 0.0);
    EXPECT_EQ(e.shrink, std::exp(e.log_shrink));
    const SmallestSpiral s = smallest_spiral(e);
    // Definition: a quarter of L(E), shrinking four times as fast.
    EXPECT_DOUBLE_EQ(s.length, e.length / 4);
    EXPECT_EQ(s.log_shrink, 4 * e.log_shrink);
    const OptimalSpiral o = optimal_spiral(d, e, s, e.alpha);
    ASSERT_GE(o.triangles, 1);
    // The last spoke lies at phi = alpha, along the other edge F at V.
    EXPECT_NEAR(o.triangles * o.theta, e.alpha, 1e-12);
    EXPECT_LE(o.theta, kPi / 2 + 1e-15);  // Theorem 16
    // Theta was only decreased from theta* = -1/ln s: a >= 1/e (cf. Thm 18's a >= 1/4).
    EXPECT_GE(o.a, std::exp(-1.0) * (1 - 1e-12));
    EXPECT_LE(o.a, 1.0);
    const Vec2 V = d.pslg.vertices[e.vertex], F = d.pslg.vertices[e.far_vertex];
    const Vec2 last = o.spoke_vertices.back();
    // Up to the rounding of V + rho * direction, which grows as rho shrinks:
    // over a wide sector with a small shrinking factor the spokes shrink by
    // ~1/e per triangle and the last one can fall below the coordinates' ulp
    // (see the draft, "limits"); those are skipped.
    const double rho = norm(last - V);
    if (rho >= 1e-6 * e.length) {
      const double tol = 1e-12 + 1e-13 * (std::abs(V.x) + std::abs(V.y) + e.length) / rho;
      EXPECT_NEAR(angle_between(last - V, F - V), 0.0, tol);
    }
    // Spokes follow the geometric progression L/4 * a^i (Theorem 19).
    for (std::size_t i = 0; i < o.spoke_log_ratio.size(); ++i)
      EXPECT_NEAR(o.spoke_log_ratio[i], static_cast<double>(i) * std::log(o.a),
                  1e-12 * (1 + static_cast<double>(i) * std::abs(std::log(o.a))));
    for (std::size_t i = 0; i < o.spoke_vertices.size(); ++i)
      EXPECT_NEAR(norm(o.spoke_vertices[i] - V), s.length * std::pow(o.a, static_cast<double>(i)), 1e-12 * e.length);
    // Theorem 17 (its proof's constants, theta <= pi/2):
    // (a / sqrt 2) sin theta <= sin A and A <= pi a theta.
    EXPECT_LE(o.min_angle, kPi * o.a * o.theta * (1 + 1e-12));
    EXPECT_GE(std::sin(o.min_angle), o.a / std::sqrt(2.0) * std::sin(o.theta) * (1 - 1e-12));
    // Theorem 22: the approximation is within constants of min(omega, -1/(e ln s)).
    // Upper: a theta <= max over a of a theta with a = s^theta is -1/(e ln s),
    // and a theta <= theta <= omega. Lower: a >= 1/e; theta = omega when k = 1,
    // else theta >= min(theta*/2, pi/4) >= min(theta*/2, omega/8) (omega < 2 pi),
    // so a theta >= min(omega, theta*) / (8e) >= ref / (8e).
    const double ref = s.log_shrink < 0 ? std::min(e.alpha, -1 / (std::exp(1.0) * s.log_shrink)) : e.alpha;
    EXPECT_LE(o.min_angle_approx, ref * (1 + 1e-12));
    EXPECT_GE(o.min_angle_approx, ref / (8 * std::exp(1.0)) * (1 - 1e-12));
  }
}

TEST(SpiralStages, Corpus) {
  test::for_each_corpus_domain([](const Domain2& d, const char* name) { check_spirals(d, name); });
}

TEST(SpiralStages, RandomPolygons) {
  for (std::uint64_t seed = 1; seed <= 60; ++seed)
    check_spirals(make_domain(test::random_polygon_with_holes(seed)), test::describe_polygon(seed));
}

}  // namespace
}  // namespace pqmesh
