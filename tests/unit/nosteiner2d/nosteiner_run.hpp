#pragma once
// Shared by the triangulation tests (thesis ch. 5 assembled): run
// triangulate_without_boundary_steiner on a domain, check the output with the
// no-boundary-Steiner check (independently of the triangulator's own verify),
// check the documented output contract, and collect the measurements.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "nosteiner2d/stages.hpp"

namespace pqmesh::test {

struct RunStats {
  int domains = 0, full = 0, q_only = 0, cdt = 0, cdt_better = 0;
  int worse_than_cdt = 0;                 // achieved < CDT's min angle
  double min_ratio = 1e300, max_ratio = 0;  // achieved / g
  double min_ratio_full = 1e300;          // over Full-path outputs only
  double min_vs_cdt = 1e300;              // achieved / CDT min angle
  std::vector<double> ratios;
  std::vector<double> bound_ratios;       // output min angle / NoSteinerStats::upper_bound
  std::string worst_bound;                // the domain realising the smallest of them
  int refined_outputs = 0;                // outputs that are a refined candidate
  std::string worst;                      // the domain realising min_ratio
  double output_min_ratio = 1e300;        // achieved / g of the output (after keep_better_cdt)
  // The construction before the quality post-pass (NoSteinerStats::construction_min_angle).
  int construction_worse_than_cdt = 0;
  double construction_min_ratio = 1e300;
  std::vector<double> construction_ratios;
  // min_ratio .. min_vs_cdt and the path counts describe the pipeline before
  // keep_better_cdt (NoSteinerStats::pipeline_*).
};

// The pipeline as it is: no internal verify (a failing mesh must fail the
// test, not be replaced by a fallback) and no keep_better_cdt (the mesh
// checked is the pipeline's own, not the CDT).
inline NoSteinerOptions raw_options() {
  NoSteinerOptions o;
  o.verify = false;
  o.keep_better_cdt = false;
  return o;
}

// Runs, checks, records. Returns the result for further checks.
inline NoSteinerResult run_and_check(const Domain2& d, const std::string& what, RunStats& st,
                                     const NoSteinerOptions& options = raw_options()) {
  SCOPED_TRACE(what);
  NoSteinerResult res = triangulate_without_boundary_steiner(d, options);
  const NoSteinerStats& s = res.stats;
  const CheckReport r = check_mesh(res.mesh, d, CheckOptions{.no_boundary_steiner = true});
  EXPECT_TRUE(r.valid()) << r.to_text();
  // Contract: the input vertices come first, unchanged (ids preserved).
  for (std::size_t i = 0; i < d.pslg.vertices.size(); ++i) {
    EXPECT_EQ(res.mesh.vertices[i].x, d.pslg.vertices[i].x);
    EXPECT_EQ(res.mesh.vertices[i].y, d.pslg.vertices[i].y);
  }
  EXPECT_EQ(res.mesh.triangle_markers.size(), res.mesh.triangles.size());
  EXPECT_EQ(s.triangles, std::int64_t(res.mesh.triangles.size()));
  EXPECT_EQ(s.wedge_triangles + s.between_triangles + s.r_triangles + s.cdt_triangles + s.refined_triangles,
            s.triangles);
  // A fallback always says why; the full path never carries a reason.
  EXPECT_EQ(s.path == NoSteinerPath::Full, s.fallback_reason.empty()) << s.fallback_reason;
  // The min angle reported is the mesh's (recomputed here independently of the stats).
  EXPECT_EQ(s.min_angle, min_triangle_angle(res.mesh));
  // Theorem 21 with the constant of docs/algorithm/nosteiner2d.md "The constant": no Steiner-free-boundary
  // triangulation beats C g(P); ours is one, so this must hold.
  EXPECT_LE(s.min_angle, s.upper_bound * (1 + 1e-12))
      << "alpha " << s.alpha << ", C g " << s.constant * s.g << ", segment " << s.segment_bound << ", fan " << s.fan_bound;
  ++st.domains;
  // keep_better_cdt (default): the output is never worse than the CDT.
  if (options.keep_better_cdt) {
    EXPECT_GE(s.min_angle, s.cdt_min_angle);
  }
  EXPECT_GE(s.min_angle, s.pipeline_min_angle);
  // The output is the best of the pipeline and the refined candidates (NoSteinerOptions::refine_targets).
  EXPECT_GE(s.min_angle, s.refined_min_angle);
  if (s.path == NoSteinerPath::Refined) {
    EXPECT_EQ(s.min_angle, s.refined_min_angle);
    EXPECT_GT(s.refined_min_angle, s.pipeline_min_angle);
    EXPECT_EQ(s.refined_triangles, s.triangles);
  }
  if (!options.refine_targets.empty()) {
    EXPECT_GT(s.refined_target, 0);  // a candidate ran (and, with verify, passed the check)
  }
  // The quality post-pass never lowers the min angle (quality_pass.hpp).
  EXPECT_GE(s.pipeline_min_angle, s.construction_min_angle);
  // ... and never stops below the CDT of P (its last candidate, the whole
  // mesh as one cavity, is re-triangulated to the CDT of P): the pipeline
  // itself, before keep_better_cdt, is never worse than the CDT.
  if (options.quality_pass && options.compare_cdt) {
    EXPECT_GE(s.pipeline_min_angle, s.cdt_min_angle);
  }
  if (!options.quality_pass) {
    EXPECT_EQ(s.pipeline_min_angle, s.construction_min_angle);
  }
  if (s.construction_min_angle < s.cdt_min_angle) ++st.construction_worse_than_cdt;
  st.construction_min_ratio = std::min(st.construction_min_ratio, s.construction_min_angle / s.g);
  st.construction_ratios.push_back(s.construction_min_angle / s.g);
  // The pipeline before that choice, measured (docs/algorithm/nosteiner2d.md "Fallbacks and the CDT comparison").
  const double pipeline_ratio = s.pipeline_min_angle / s.g;
  (s.pipeline_path == NoSteinerPath::Full ? st.full : s.pipeline_path == NoSteinerPath::QOnly ? st.q_only : st.cdt)++;
  if (s.path == NoSteinerPath::CdtBetter) ++st.cdt_better;
  if (s.pipeline_min_angle < s.cdt_min_angle) ++st.worse_than_cdt;
  if (pipeline_ratio < st.min_ratio) {
    st.min_ratio = pipeline_ratio;
    st.worst = what;
  }
  st.max_ratio = std::max(st.max_ratio, pipeline_ratio);
  if (s.pipeline_path == NoSteinerPath::Full) st.min_ratio_full = std::min(st.min_ratio_full, pipeline_ratio);
  st.min_vs_cdt = std::min(st.min_vs_cdt, s.pipeline_min_angle / s.cdt_min_angle);
  st.output_min_ratio = std::min(st.output_min_ratio, s.ratio);
  st.ratios.push_back(pipeline_ratio);
  if (st.bound_ratios.empty() || s.min_angle / s.upper_bound < *std::min_element(st.bound_ratios.begin(), st.bound_ratios.end()))
    st.worst_bound = what;
  st.bound_ratios.push_back(s.min_angle / s.upper_bound);
  if (s.path == NoSteinerPath::Refined) ++st.refined_outputs;
  return res;
}

inline void print(const RunStats& st, const char* what) {
  std::vector<double> r = st.ratios, c = st.construction_ratios;
  std::sort(r.begin(), r.end());
  std::sort(c.begin(), c.end());
  const double median = r.empty() ? 0 : r[r.size() / 2];
  std::vector<double> b = st.bound_ratios;
  std::sort(b.begin(), b.end());
  if (!b.empty())
    std::cout << "[no-boundary-Steiner] " << what << ": output / upper bound min " << b.front() << " ("
              << st.worst_bound << "), median "
              << b[b.size() / 2] << ", max " << b.back() << ", below 0.25 on "
              << std::count_if(b.begin(), b.end(), [](double x) { return x < 0.25; }) << "; refined candidate written on " << st.refined_outputs
              << " of " << b.size() << "\n";
  std::cout << "[no-boundary-Steiner] " << what << ": construction (before the quality pass) achieved/g min "
            << st.construction_min_ratio << ", median " << (c.empty() ? 0 : c[c.size() / 2])
            << ", worse than the CDT on " << st.construction_worse_than_cdt << "; after the pass:\n";
  std::cout << "[no-boundary-Steiner] " << what << ": " << st.domains << " domains (pipeline: full " << st.full
            << ", q-only fallback " << st.q_only << ", cdt fallback " << st.cdt << "; output: cdt-better "
            << st.cdt_better << ", output achieved/g min " << st.output_min_ratio << "); pipeline achieved/g min " << st.min_ratio
            << " (" << st.worst << "), median " << median << ", max " << st.max_ratio << "; full-path min "
            << st.min_ratio_full << "; worse than the CDT on " << st.worse_than_cdt << ", min achieved/cdt "
            << st.min_vs_cdt << "\n";
}

}  // namespace pqmesh::test
