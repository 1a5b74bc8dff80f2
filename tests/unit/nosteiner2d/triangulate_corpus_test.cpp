// The no-boundary-Steiner triangulation (thesis ch. 5 assembled) on data/2d
// and on hand-made hard cases. Every output passes check_mesh with
// the no-boundary-Steiner check (nosteiner_run.hpp); the measured constant k
// (achieved >= k g(P)) is asserted in triangulate_random_test.cpp over this
// corpus and the random polygons, and its floor is also asserted here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "nosteiner_run.hpp"
#include "pqmesh/read_domain.hpp"
#include "support/paths.hpp"
#include "corpus2d.hpp"

namespace pqmesh {
namespace {

// Measured floor of achieved / g(P) (docs/algorithm/nosteiner2d.md "Fallbacks and the CDT
// comparison"), rounded down. With the §5.4 matching the smallest measured value is 0.0063 (the
// regular 1000-gon, where g is nearly pi); on data/2d 0.026 (comb). The floor guards against
// regressions. With the spoke floor (docs/algorithm/nosteiner2d.md "Spoke floor") every input here
// takes the Full path (all 8 + 9), asserted in run().
constexpr double kMeasuredK = 5e-3;

// Measured floor of (construction + quality post-pass) / g(P), rounded down
// (docs/algorithm/nosteiner2d.md "Fallbacks and the CDT comparison";
// quality_pass.hpp): 0.161 on data/2d (comb), 0.055 on the hard cases (regular
// 1000-gon). The pass never ends below the CDT of P (its whole-mesh cavity
// stage; asserted in run_and_check).
constexpr double kMeasuredKPass = 0.05;

// Measured floors of output / upper bound (NoSteinerStats::upper_bound = min(60, C g, alpha, segment
// bound, fan bound); docs/MEASUREMENTS.md "No boundary Steiner points"): the measured minimum less
// 10%, rounded down to two decimals. data/2d: 0.605 (comb) -> 0.54; hard cases: 0.530 (regular
// 1000-gon) -> 0.47.
constexpr double kMeasuredBoundRatioCorpus = 0.54;
constexpr double kMeasuredBoundRatioHard = 0.47;

double min_bound_ratio(const test::RunStats& st) {
  return st.bound_ratios.empty() ? 0 : *std::min_element(st.bound_ratios.begin(), st.bound_ratios.end());
}

using test::loops_pslg;
using test::polygon;

// The pipeline with the thesis's per-piece fans in Q \ R
// (NoSteinerOptions::thesis_fans; never above the CDT connectivity by
// Lawson). Measured min achieved / g: 0.0134 (data/2d, spike_10deg),
// 0.00165 (hard cases, the regular 1000-gon; DISABLED_HardCasesThesisFans),
// 0.0055 (300 random polygons, one-off run); floor rounded down.
constexpr double kMeasuredKFans = 1e-3;

NoSteinerOptions fans_options() {
  NoSteinerOptions o = test::raw_options();
  o.thesis_fans = true;
  return o;
}

void run(const Domain2& d, const std::string& what, test::RunStats& st,
         const NoSteinerOptions& options = test::raw_options(), double k = kMeasuredK) {
  const NoSteinerResult res = test::run_and_check(d, what, st, options);
  const NoSteinerStats& s = res.stats;
  EXPECT_GE(s.construction_min_angle, k * s.g) << what;  // the thesis's construction
  if (options.quality_pass) {
    EXPECT_GE(s.pipeline_min_angle, kMeasuredKPass * s.g) << what;
  }
  EXPECT_EQ(s.pipeline_path, NoSteinerPath::Full) << what << ": " << s.fallback_reason;
  constexpr double deg = 180 / std::numbers::pi;
  std::printf("  %-26s g %8.4f, construction %9.5f, +pass %9.5f (%s, ratio %.3g; %lld flips, %lld removals, %lld moves, %lld cavities%s), cdt %8.4f, output %s %.4f / bound %.4f = %.3f, %lld tri%s%s\n", what.c_str(),
              s.g * deg, s.construction_min_angle * deg, s.pipeline_min_angle * deg, to_string(s.pipeline_path), s.pipeline_min_angle / s.g,
              static_cast<long long>(s.pass_flips), static_cast<long long>(s.pass_removals), static_cast<long long>(s.pass_moves), static_cast<long long>(s.pass_cavities), s.pass_stuck ? "" : ", step bound",
              s.cdt_min_angle * deg, to_string(s.path), s.min_angle * deg, s.upper_bound * deg, s.min_angle / s.upper_bound,
              static_cast<long long>(s.triangles),
              s.pipeline_path == NoSteinerPath::Full ? "" : "; ",
              s.pipeline_path == NoSteinerPath::Full ? "" : s.fallback_reason.substr(0, 90).c_str());
}

TEST(NoSteinerTriangulation, Corpus) {
  test::RunStats st;
  for (const char* name : test::kCorpus2d)
    run(test::corpus_domain(name), name, st);
  test::print(st, "data/2d");
  EXPECT_GE(min_bound_ratio(st), kMeasuredBoundRatioCorpus);
}

TEST(NoSteinerTriangulation, CorpusThesisFans) {
  test::RunStats st;
  for (const char* name : test::kCorpus2d)
    run(test::corpus_domain(name), name, st, fans_options(),
        kMeasuredKFans);
  test::print(st, "data/2d, thesis fans in Q \\ R");
}

// The default options (verify, keep_better_cdt) as the CLI runs them: valid,
// no boundary Steiner point, never below the CDT of P (by construction).
TEST(NoSteinerTriangulation, CorpusDefaultOptions) {
  test::RunStats st;
  const NoSteinerOptions defaults;
  for (const char* name : test::kCorpus2d) test::run_and_check(test::corpus_domain(name), name, st, defaults);
  test::print(st, "data/2d, default options");
}

// The hard cases (corpus2d.hpp).
void hard_cases(const NoSteinerOptions& options, double k, const char* label, double bound_ratio = 0) {
  test::RunStats st;
  for (const test::NamedDomain& c : test::hard_case_domains()) pqmesh::run(c.domain, c.name, st, options, k);
  test::print(st, label);
  EXPECT_GE(min_bound_ratio(st), bound_ratio);
}

// The reflex notch, bound derived by hand (docs/algorithm/nosteiner2d.md
// "Fallbacks and the CDT comparison"): the triangle ABC on the bottom side A =
// (0,0), B = (1,0) cannot reach above the reflex vertex R = (31/64, y) at x =
// 31/64 (the points just above R are outside P), so the smaller of its angles
// at A, B is at most atan(y / (31/64)) in every triangulation without boundary
// Steiner points. g(P) is that value (pair (A, AB), W = R, r = |AR| > 1/e so h
// = angle RAB); the CDT holds ABR, whose smallest angle is at B: atan(y /
// (33/64)).
TEST(NoSteinerTriangulation, NotchBound) {
  for (double y : {1.0 / 128, 1.0 / 4096}) {
    const Domain2 d = polygon({{0, 0}, {1, 0}, {1, 1}, {0.625, 1}, {0.484375, y}, {0.375, 1}, {0, 1}});
    const double bound = std::atan(y * 64 / 31), cdt = std::atan(y * 64 / 33);
    NoSteinerOptions o = test::raw_options();
    const NoSteinerStats s = triangulate_without_boundary_steiner(d, o).stats;
    EXPECT_NEAR(s.g, bound, 1e-9 * bound);
    EXPECT_NEAR(s.cdt_min_angle, cdt, 1e-12 * cdt);
    EXPECT_LE(s.pipeline_min_angle, bound);
    EXPECT_LE(s.construction_min_angle, bound);
    EXPECT_GE(s.pipeline_min_angle, s.cdt_min_angle);  // measured: the pass ends at the CDT here
  }
}

TEST(NoSteinerTriangulation, HardCases) {
  hard_cases(test::raw_options(), kMeasuredK, "hard cases", kMeasuredBoundRatioHard);
}

// The same with the thesis's fans (~5 s CPU; run with
// --gtest_also_run_disabled_tests): the measurement of
// docs/algorithm/nosteiner2d.md "Matching R to Q".
TEST(NoSteinerTriangulation, DISABLED_HardCasesThesisFans) {
  hard_cases(fans_options(), kMeasuredKFans, "hard cases, thesis fans in Q \\ R");
}

}  // namespace
}  // namespace pqmesh
