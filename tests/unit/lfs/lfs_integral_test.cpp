// lfs_integral: accuracy against a brute-force reference, scale invariance,
// and growth on a comb whose slots narrow.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/lfs.hpp"
#include "pqmesh/read_domain.hpp"
#include "support/paths.hpp"

namespace pqmesh {
namespace {

Domain2 load(const std::string& name) { return make_domain(read_pslg(test::data_path("2d/" + name + ".poly"))); }

// Reference for the unit square: midpoint rule on a uniform m x m grid with
// the brute-force lfs. By hand, 0.5 <= lfs <= 1 in the square: lfs <= 1
// because the bottom and top sides are disjoint and both within 1 of x; and
// every disjoint pair has max >= 0.5, since a pair of opposite sides has
// distances summing to >= 1, and a corner not on a side s lies on the side
// opposite to s (or, for two corners, they differ in one coordinate and lie on
// two opposite sides), and a corner is no nearer than the sides through it.
// So 1 <= I <= 4, the integrand is bounded and Lipschitz, and the m = 400
// midpoint rule is accurate far below the 1% we test (its change from
// m = 200 is checked to be tiny).
double square_reference(const Domain2& d, int m) {
  double sum = 0;
  const double h = 1.0 / m;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const double f = local_feature_size(d, {(i + 0.5) * h, (j + 0.5) * h});
      sum += h * h / (f * f);
    }
  return sum;
}

TEST(LfsIntegral, UnitSquareAgainstReference) {
  const Domain2 d = load("square");
  const double ref = square_reference(d, 400), coarse = square_reference(d, 200);
  EXPECT_NEAR(ref, coarse, 1e-3 * ref);
  EXPECT_GT(ref, 1.0);
  EXPECT_LE(ref, 4.0);
  const LfsIntegral r = lfs_integral(d);
  std::printf("unit square: reference %.6f, lfs_integral %.6f (rel. err %.2e), %lld cells, min lfs %.4f\n", ref,
              r.value, std::abs(r.value - ref) / ref, static_cast<long long>(r.cells), r.min_lfs);
  EXPECT_NEAR(r.value, ref, 0.01 * ref);
  const LfsIntegral fine = lfs_integral(d, 1.0 / 32);
  std::printf("unit square, refine 1/32: %.6f (rel. err %.2e), %lld cells\n", fine.value,
              std::abs(fine.value - ref) / ref, static_cast<long long>(fine.cells));
  EXPECT_NEAR(fine.value, ref, 0.002 * ref);
  EXPECT_GE(r.min_lfs, 0.5 - 1e-12);
}

Domain2 scaled(const Domain2& d, double s, Vec2 shift) {
  Pslg2 g = d.pslg;
  for (auto& p : g.vertices) p = s * p + shift;
  for (auto& p : g.holes) p = s * p + shift;
  return make_domain(g);
}

TEST(LfsIntegral, ScaleInvariant) {
  for (const char* name : {"square_holes", "l_shape", "spike_10deg", "regions"}) {
    const Domain2 d = load(name);
    const double base = lfs_integral(d).value;
    for (double s : {0.125, 3.7, 1000.0}) {
      const double v = lfs_integral(scaled(d, s, {0.3, -11.0})).value;
      EXPECT_NEAR(v, base, 0.01 * base) << name << " scale " << s;
    }
  }
}

// The comb of data/2d/comb.poly with slot width s: 6 teeth of width 0.15625,
// 5 slots, base 0 <= y <= 0.25, teeth up to y = 1 (s = 1/256 is the file).
Domain2 comb(double s) {
  const double tw = 0.15625;
  const double W = 6 * tw + 5 * s;
  Pslg2 g;
  g.vertices = {{0, 0}, {W, 0}, {W, 1}};
  double x = W - tw;  // left side of the rightmost tooth
  for (int k = 0; k < 5; ++k) {
    g.vertices.push_back({x, 1});
    g.vertices.push_back({x, 0.25});
    g.vertices.push_back({x - s, 0.25});
    g.vertices.push_back({x - s, 1});
    x -= s + tw;
  }
  g.vertices.push_back({0, 1});
  const int n = static_cast<int>(g.vertices.size());
  for (int k = 0; k < n; ++k) g.segments.push_back({k, (k + 1) % n});
  return make_domain(g);
}

TEST(LfsIntegral, CombGrowsAsSlotsNarrow) {
  // The file and our construction agree.
  const Domain2 file = load("comb");
  const double from_file = lfs_integral(file, 0.25).value;
  EXPECT_NEAR(lfs_integral(comb(1.0 / 256), 0.25).value, from_file, 1e-9 * from_file);
  // Inside a tooth at distance t from a slot wall, lfs <= t + s (the two walls
  // of a slot are disjoint), so each of the 10 slot walls contributes about
  // 0.75 * integral_0^w dt / (t + s)^2 ~ 0.75 / s: I grows like 7.5 / s.
  // (Coarser refine = 1/4 keeps the test fast; the ratios are what we check.)
  std::vector<double> I;
  for (int k = 0; k < 3; ++k) {
    const double s = std::ldexp(1.0, -6 - 2 * k);  // 1/64, 1/256, 1/1024
    const LfsIntegral r = lfs_integral(comb(s), 0.25);
    std::printf("comb slot width 1/%g: I = %.1f, 7.5/s = %.1f, %lld cells, min lfs %.3g\n", 1 / s, r.value, 7.5 / s,
                static_cast<long long>(r.cells), r.min_lfs);
    I.push_back(r.value);
    EXPECT_GT(r.value, 0.5 * 7.5 / s);
    EXPECT_LT(r.value, 4.0 * 7.5 / s);
  }
  // Slots 4x narrower: the integral grows by a factor close to 4 (the
  // s-independent part from the base and tooth interiors dilutes it).
  EXPECT_GT(I[1] / I[0], 2.5);
  EXPECT_GT(I[2] / I[1], 3.0);
  EXPECT_LT(I[2] / I[1], 4.5);
}

// Self-convergence on every corpus file: halving `refine` changes the
// estimate by little (the error shrinks roughly like refine^2, see the unit
// square above), and the table is printed for the record.
TEST(LfsIntegral, CorpusConverges) {
  for (const char* name : {"square", "square_holes", "l_shape", "comb", "regions", "spike_1deg", "spike_5deg",
                           "spike_10deg"}) {
    const Domain2 d = load(name);
    const LfsIntegral a = lfs_integral(d), b = lfs_integral(d, 1.0 / 16);
    std::printf("%-12s I(1/8) = %10.3f (%8lld cells)  I(1/16) = %10.3f (%8lld cells)  diff %.2e  min lfs %.3g\n",
                name, a.value, static_cast<long long>(a.cells), b.value, static_cast<long long>(b.cells),
                std::abs(a.value - b.value) / b.value, b.min_lfs);
    EXPECT_NEAR(a.value, b.value, 0.01 * b.value) << name;
    EXPECT_GT(a.min_lfs, 0) << name;
  }
}

}  // namespace
}  // namespace pqmesh
