// The no-boundary-Steiner triangulation (thesis ch. 5 assembled) on data/2d
// and on hand-made hard cases. Every output passes check_mesh with
// the no-boundary-Steiner check (nosteiner_run.hpp); the measured constant k
// (achieved >= k g(P)) is asserted in triangulate_random_test.cpp over this
// corpus and the random polygons, and its floor is also asserted here.
#include <gtest/gtest.h>

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
  std::printf("  %-26s g %8.4f, construction %9.5f, +pass %9.5f (%s, ratio %.3g; %lld flips, %lld removals, %lld moves, %lld cavities%s), cdt %8.4f, output %s %lld tri%s%s\n", what.c_str(),
              s.g * deg, s.construction_min_angle * deg, s.pipeline_min_angle * deg, to_string(s.pipeline_path), s.pipeline_min_angle / s.g,
              static_cast<long long>(s.pass_flips), static_cast<long long>(s.pass_removals), static_cast<long long>(s.pass_moves), static_cast<long long>(s.pass_cavities), s.pass_stuck ? "" : ", step bound",
              s.cdt_min_angle * deg, to_string(s.path), static_cast<long long>(s.triangles),
              s.pipeline_path == NoSteinerPath::Full ? "" : "; ",
              s.pipeline_path == NoSteinerPath::Full ? "" : s.fallback_reason.substr(0, 90).c_str());
}

TEST(NoSteinerTriangulation, Corpus) {
  test::RunStats st;
  for (const char* name : test::kCorpus2d)
    run(test::corpus_domain(name), name, st);
  test::print(st, "data/2d");
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
  for (const char* name : test::kCorpus2d)
    test::run_and_check(test::corpus_domain(name), name, st,
                        NoSteinerOptions{});
  test::print(st, "data/2d, default options");
}

// Hard cases (dyadic coordinates unless said otherwise).
void hard_cases(const NoSteinerOptions& options, double k, const char* label) {
  auto run = [&](const Domain2& d, const std::string& what, test::RunStats& st) {
    pqmesh::run(d, what, st, options, k);
  };
  test::RunStats st;
  // Thesis Fig. 1.1: a thin trapezoid whose long edge faces close vertices.
  for (double t : {1.0 / 64, 1.0 / 1024})
    run(polygon({{0, 0}, {1, 0}, {0.5625, t}, {0.4375, t}}), "fig1.1 trapezoid t=" + std::to_string(t), st);
  // A reflex vertex very close to the middle of a long edge (the notch).
  for (double y : {1.0 / 128, 1.0 / 4096})
    run(polygon({{0, 0}, {1, 0}, {1, 1}, {0.625, 1}, {0.484375, y}, {0.375, 1}, {0, 1}}),
        "reflex notch y=" + std::to_string(y), st);
  // A comb with narrow slots: 8 teeth of width 1/16, slots 1/512 wide, 1/2 deep.
  {
    std::vector<Vec2> c = {{0, 0}, {1, 0}};
    const double tooth = 1.0 / 16, slot = 1.0 / 512;
    double x = 1;
    c.push_back({1, 1});
    for (int i = 0; i < 8; ++i) {
      x -= tooth;
      if (i == 7) break;
      c.push_back({x, 1});
      c.push_back({x, 0.5});
      x -= slot;
      c.push_back({x, 0.5});
      c.push_back({x, 1});
    }
    c.push_back({x, 1});
    c.push_back({0, 1});
    run(polygon(c), "comb narrow slots", st);
  }
  // Small-angle spikes: a star of 12 spikes with tips at radius 1 and
  // valleys at 1/4 (tip angles ~6 deg), plus one 0.5-degree spike.
  {
    std::vector<Vec2> s;
    for (int i = 0; i < 24; ++i) {
      const double a = std::numbers::pi * i / 12, r = i % 2 == 0 ? 1.0 : 0.25;
      s.push_back({std::ldexp(std::round(std::ldexp(r * std::cos(a), 30)), -30),
                   std::ldexp(std::round(std::ldexp(r * std::sin(a), 30)), -30)});
    }
    run(polygon(s), "star 12 spikes", st);
    const double h = std::tan(0.25 * std::numbers::pi / 180);
    run(polygon({{0, -h}, {1, 0}, {0, h}, {-0.5, 0.5}, {-0.5, -0.5}}), "spike 0.5 deg", st);
  }
  // Many holes: an 8 x 8 grid of square holes (64 holes) in the unit square.
  {
    std::vector<std::vector<Vec2>> loops = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j) {
        const double x = (i + 0.25) / 8, y = (j + 0.25) / 8, w = 0.5 / 8;
        loops.push_back({{x, y}, {x, y + w}, {x + w, y + w}, {x + w, y}});
      }
    Pslg2 p = loops_pslg(loops);
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j) p.holes.push_back({(i + 0.5) / 8, (j + 0.5) / 8});
    run(make_domain(p), "64 square holes", st);
  }
  // Regular 1000-gon (rounded cos/sin; make_domain validates it).
  {
    std::vector<Vec2> pts;
    for (int i = 0; i < 1000; ++i)
      pts.push_back({std::cos(2 * std::numbers::pi * i / 1000), std::sin(2 * std::numbers::pi * i / 1000)});
    run(polygon(pts), "regular 1000-gon", st);
  }
  test::print(st, label);
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

TEST(NoSteinerTriangulation, HardCases) { hard_cases(test::raw_options(), kMeasuredK, "hard cases"); }

// The same with the thesis's fans (~5 s CPU; run with
// --gtest_also_run_disabled_tests): the measurement of
// docs/algorithm/nosteiner2d.md "Matching R to Q".
TEST(NoSteinerTriangulation, DISABLED_HardCasesThesisFans) {
  hard_cases(fans_options(), kMeasuredKFans, "hard cases, thesis fans in Q \\ R");
}

}  // namespace
}  // namespace pqmesh
