// lfs_integral (3D): accuracy on the unit cube against an independent
// brute-force reference, convergence under refinement, scale invariance, and
// times on the larger corpus models (printed, not asserted).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "plc/lfs3d.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/lfs.hpp"  // both headers in one unit: the overloads must not clash
#include "pqmesh/lfs3.hpp"
#include "pqmesh/read_domain.hpp"
#include "support/paths.hpp"

namespace pqmesh {
namespace {

Domain3 load(const std::string& name) { return make_domain(read_plc(test::data_path("3d/" + name + ".poly"))); }

// Brute-force lfs over all feature pairs, with the feature model built once.
double brute(const detail::LfsModel3& m, const std::vector<detail::LfsFeature3>& fs, Vec3 x) {
  std::vector<double> d2(fs.size());
  for (std::size_t i = 0; i < fs.size(); ++i) d2[i] = m.dist2(x, fs[i]);
  double best = INFINITY;
  for (std::size_t i = 0; i < fs.size(); ++i)
    for (std::size_t j = i + 1; j < fs.size(); ++j)
      if (m.disjoint(fs[i], fs[j])) best = std::min(best, std::max(d2[i], d2[j]));
  return std::sqrt(best);
}

// Reference for the unit cube: midpoint rule on a uniform m^3 grid with the
// brute-force lfs (no octree, no grid search, no point location). By hand,
// 0.5 <= lfs <= 1 in the cube: lfs <= 1 because the facets z=0 and z=1 are
// disjoint and both within 1 of x; every disjoint pair has max >= 0.5 since
// two disjoint features of the cube lie on two opposite facets' planes (a
// feature not meeting facet F lies on the facet opposite to F, and a vertex,
// edge or facet lies in each facet plane it touches), whose distances sum to
// >= 1. So 1 <= I3 <= 8, the integrand is bounded and Lipschitz, and the
// midpoint rule converges like 1/m^2 (its change from m/2 is checked).
double cube_reference(const Domain3& d, int m) {
  const detail::LfsModel3 model(d);
  const auto fs = model.features();
  double sum = 0;
  const double h = 1.0 / m;
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        const double f = brute(model, fs, {(i + 0.5) * h, (j + 0.5) * h, (k + 0.5) * h});
        sum += h * h * h / (f * f * f);
      }
  return sum;
}

TEST(Lfs3Integral, UnitCubeAgainstReference) {
  const Domain3 d = load("cube");
  // m = 64 (the m = 96 reference, 4.63369, is 0.05% away; the cost of the
  // brute force grows like m^3, so the suite uses 64 and its check at 32).
  const double ref = cube_reference(d, 64), coarse = cube_reference(d, 32);
  std::printf("unit cube reference: m=32 %.6f, m=64 %.6f\n", coarse, ref);
  EXPECT_NEAR(ref, coarse, 5e-3 * ref);
  EXPECT_GT(ref, 1.0);
  EXPECT_LE(ref, 8.0);
  // refine 1/16 (measured 0.07% off) is left to a manual run: 8x the cells of 1/8.
  for (double refine : {0.5, 0.25, 0.125}) {
    const LfsIntegral3 r = lfs_integral(d, refine);
    std::printf("unit cube, refine %.4f: I3 %.6f (rel. err %.2e), %lld cells, min lfs %.4f\n", refine, r.value,
                std::abs(r.value - ref) / ref, static_cast<long long>(r.cells), r.min_lfs);
    EXPECT_GE(r.min_lfs, 0.5 - 1e-12);
    // Measured: 1.6%, 0.38%, 0.07% for refine 1/4, 1/8, 1/16.
    if (refine <= 0.25) {
      EXPECT_NEAR(r.value, ref, 0.03 * ref) << refine;
    }
    if (refine <= 0.125) {
      EXPECT_NEAR(r.value, ref, 0.01 * ref) << refine;
    }
  }
}

// Halving `refine` changes I3 by little on the corpus (measured: see the
// printed table; the bound asserted is a few times the largest change seen).
TEST(Lfs3Integral, ConvergesUnderRefinement) {
  // prongs_slot (slot 1/2048: I3 ~ 2e5, 3.5e7 cells at refine 1/4) is left
  // out for time, as is the step to 1/16 (measured on cube, l_block,
  // cube_cavity, schoenhardt, cube_through_hole, star_vertex: at most 1.18%
  // from 1/4 to 1/8 and 0.31% from 1/8 to 1/16).
  for (const char* name : {"l_block", "schoenhardt", "star_vertex"}) {
    const Domain3 d = load(name);
    const double a = lfs_integral(d, 0.25).value, b = lfs_integral(d, 0.125).value;
    std::printf("%-18s I3: refine 1/4 %.5g, 1/8 %.5g; change %.2f%%\n", name, a, b, 100 * std::abs(a - b) / b);
    EXPECT_NEAR(a, b, 0.03 * b) << name;
  }
}

Domain3 scaled(const std::string& name, double s, Vec3 shift) {
  Plc3 plc = read_plc(test::data_path("3d/" + name + ".poly"));
  for (auto& p : plc.vertices) p = s * p + shift;
  for (auto& p : plc.holes) p = s * p + shift;
  for (auto& r : plc.regions) r.point = s * r.point + shift;
  return make_domain(plc);
}

// I3 is dimensionless (volume / length^3): invariant under scaling and
// translation.
TEST(Lfs3Integral, ScaleInvariant) {
  for (const char* name : {"l_block", "schoenhardt"}) {
    const double base = lfs_integral(load(name)).value;
    for (double s : {0.125, 3.7, 1000.0}) {
      const double v = lfs_integral(scaled(name, s, {0.3, -11.0, 7.0})).value;
      EXPECT_NEAR(v, base, 0.01 * base) << name << " scale " << s;
    }
  }
}

// A slot that narrows makes the Euclidean I3 grow (see the Scope note of
// pqmesh/lfs3.hpp): two boxes joined by a bridge, gap g between them.
TEST(Lfs3Integral, GrowsAsAGapNarrows) {
  double last = 0;
  for (double g : {0.25, 0.125, 0.0625}) {
    // A U shape in the xz plane extruded along y: two prongs of width 1 and
    // height 2 over a base of height 1, slot of width g between the prongs.
    Plc3 plc;
    const double W = 2 + g;
    const std::vector<std::array<double, 2>> outline = {{0, 0}, {W, 0}, {W, 3}, {1 + g, 3}, {1 + g, 1}, {1, 1}, {1, 3}, {0, 3}};
    const int n = static_cast<int>(outline.size());
    for (double y : {0.0, 1.0})
      for (const auto& p : outline) plc.vertices.push_back({p[0], y, p[1]});
    Facet3 front, back;
    std::vector<int> f0, f1;
    for (int k = 0; k < n; ++k) f0.push_back(k), f1.push_back(n + k);
    front.loops.push_back(f0);
    back.loops.push_back(f1);
    plc.facets.push_back(front);
    plc.facets.push_back(back);
    for (int k = 0; k < n; ++k) {
      Facet3 side;
      side.loops.push_back({k, (k + 1) % n, n + (k + 1) % n, n + k});
      plc.facets.push_back(side);
    }
    const Domain3 d = make_domain(plc);
    const LfsIntegral3 r = lfs_integral(d);
    std::printf("U with gap %.6f: I3 %.5g, %lld cells, min lfs %.5f\n", g, r.value, static_cast<long long>(r.cells),
                r.min_lfs);
    EXPECT_GT(r.value, 2 * last) << g;
    EXPECT_LE(r.min_lfs, g);
    last = r.value;
  }
}

}  // namespace
}  // namespace pqmesh
