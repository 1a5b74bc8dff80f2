// The no-boundary-Steiner triangulation on 300 seeded random polygons with
// holes (tests/support/random_domains.hpp, the generator of the other ch. 5
// tests): every output passes check_mesh with the no-boundary-Steiner check
// (nosteiner_run.hpp), and the property achieved >= k g(P) holds for the
// construction's mesh (before the quality pass and keep_better_cdt) with the
// measured k below. After the quality pass the pipeline (before
// keep_better_cdt) is never below the CDT of P (asserted in run_and_check;
// docs/algorithm/nosteiner2d.md "Fallbacks and the CDT comparison").
#include <gtest/gtest.h>

#include "nosteiner_run.hpp"
#include "support/random_domains.hpp"

namespace pqmesh {
namespace {

// Measured floor of pipeline min angle / g(P) over these 300 polygons
// (docs/algorithm/nosteiner2d.md "Fallbacks and the CDT comparison"), rounded
// down. A measured constant of this implementation (§5.4 matching), not the
// thesis's. Measured 0.0122 (seed 220). With the spoke floor
// (docs/algorithm/nosteiner2d.md "Spoke floor") every polygon takes the Full
// path (300 of 300), so the Full path is asserted too.
constexpr double kMeasuredK = 0.01;

// Measured floor of output / upper bound over the 300 polygons
// (docs/MEASUREMENTS.md "No boundary Steiner points"): the measured minimum
// 0.642 (seed 220) less 10%, rounded down to two decimals.
constexpr double kMeasuredBoundRatio = 0.57;

// Runs the seeds first..last and checks each output.
void run_seeds(std::uint64_t first, std::uint64_t last) {
  test::RunStats st;
  for (std::uint64_t seed = first; seed <= last; ++seed) {
    const Domain2 d = make_domain(test::random_polygon_with_holes(seed));
    const NoSteinerResult res = test::run_and_check(d, test::describe_polygon(seed), st);
    const NoSteinerStats& s = res.stats;
    EXPECT_GE(s.construction_min_angle, kMeasuredK * s.g) << test::describe_polygon(seed);
    EXPECT_EQ(s.pipeline_path, NoSteinerPath::Full) << test::describe_polygon(seed) << ": " << s.fallback_reason;
  }
  test::print(st, ("random polygons, seeds " + std::to_string(first) + "-" + std::to_string(last)).c_str());
  for (const double r : st.bound_ratios) EXPECT_GE(r, kMeasuredBoundRatio);
}

// All 300 run in the suite, in three shards so that ctest
// runs them in parallel: ~10 s CPU each in Release (R's quadtree mesh, ~50k
// triangles per polygon, is ~80% of it). They cover every feature of
// describe_polygon (0 to 4 holes, 0 to 2 spikes, 0 to 3 near-touching holes,
// 0 to 6 snapped vertices, a random scale and offset per seed); seed 220 is
// the worst (0.0122 g).
TEST(NoSteinerTriangulation, RandomPolygonsWithHoles1to100) { run_seeds(1, 100); }
TEST(NoSteinerTriangulation, RandomPolygonsWithHoles101to200) { run_seeds(101, 200); }
TEST(NoSteinerTriangulation, RandomPolygonsWithHoles201to300) { run_seeds(201, 300); }

}  // namespace
}  // namespace pqmesh
