// Thesis ch. 5 assembled: Q^c + (dQ to dR) + the mesh of R, with the
// documented fallbacks, then the refined candidates and the CDT of P as
// alternatives (include/pqmesh/nosteiner.hpp,
// docs/algorithm/nosteiner2d.md "Matching R to Q").
//
// Invariant of every path: the vertices on dP are exactly the input vertices
// (ids 0..n-1 of the output, in input order). Full: Q^c keeps the input
// vertices first and adds spoke ends strictly inside P (polygon_q); R's mesh
// lies inside Q and the matching adds points only strictly inside Q \ R. QOnly: the CDT of Q adds no point. Cdt: the
// CDT of P adds no point. Refined: refinement without constraint splits adds
// points strictly inside P only (refined_candidate.hpp). verify turns this
// argument into a check.
#include <chrono>
#include <cstdio>
#include <exception>
#include <algorithm>
#include <map>
#include <numbers>
#include <optional>
#include <utility>

#include "cdt2d/constrained_delaunay.hpp"
#include "nosteiner2d/match_qr.hpp"
#include "improve2d/quality_pass.hpp"
#include "nosteiner2d/refined_candidate.hpp"
#include "nosteiner2d/fan_bound.hpp"
#include "nosteiner2d/seed_points.hpp"
#include "nosteiner2d/segment_bound.hpp"
#include "improve2d/triangle_angles.hpp"
#include "pqmesh/check.hpp"
#include "nosteiner2d/stages.hpp"

namespace pqmesh {

const char* to_string(NoSteinerPath path) {
  switch (path) {
    case NoSteinerPath::Full: return "full";
    case NoSteinerPath::QOnly: return "q-only";
    case NoSteinerPath::Cdt: return "cdt";
    case NoSteinerPath::CdtBetter: return "cdt-better";
    case NoSteinerPath::Refined: return "refined";
  }
  return "?";
}

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

void add(TriMesh2& mesh, const std::vector<std::array<int, 3>>& triangles, int marker, int offset = 0) {
  for (auto t : triangles) {
    for (int& v : t) v += offset;
    mesh.triangles.push_back(t);
    mesh.triangle_markers.push_back(marker);
  }
}

// Q^c + the CDT of Q (QOnly). Throws when dQ is not a set of disjoint simple loops.
TriMesh2 q_only(const PolygonQ& q) {
  cdt2d::CdtInput in;
  in.points = q.wedges.vertices;
  for (const auto& loop : q.loops)
    for (std::size_t k = 0; k < loop.size(); ++k) in.constraints.push_back({loop[k], loop[(k + 1) % loop.size()]});
  TriMesh2 mesh;
  mesh.vertices = q.wedges.vertices;
  add(mesh, q.wedges.triangles, kRegionWedges);
  add(mesh, cdt2d::constrained_delaunay(in, true).triangles, kRegionQCdt);
  return mesh;
}

// The CDT of P puts only the referenced points in its triangles; an input
// vertex is on some triangle of any triangulation of P, so none is unused.
TriMesh2 p_cdt(const Domain2& domain) {
  TriMesh2 mesh = steiner_free_cdt(domain);
  mesh.triangle_markers.assign(mesh.triangles.size(), kRegionPCdt);
  return mesh;
}

double region_min_angle(const TriMesh2& mesh, int marker, std::int64_t& count) {
  double m = 0;
  count = 0;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    if (mesh.triangle_markers[i] != marker) continue;
    const auto& t = mesh.triangles[i];
    const double a = detail::min_angle(mesh.vertices[std::size_t(t[0])], mesh.vertices[std::size_t(t[1])],
                                       mesh.vertices[std::size_t(t[2])]);
    m = count++ == 0 ? a : std::min(m, a);
  }
  return m;
}

bool passes(const TriMesh2& mesh, const Domain2& domain, std::string& why) {
  const CheckReport r = check_mesh(mesh, domain, CheckOptions{.no_boundary_steiner = true, .max_issues_per_kind = 3});
  if (r.valid()) return true;
  why = r.issues.empty() ? std::string("check failed") : r.issues.front().message;
  return false;
}

// Records the thesis's Steiner-free bound g, the smallest input angle, the
// segment and fan bounds, the upper bound they give, and the time.
void record_bound(const Domain2& domain, NoSteinerStats& st) {
  const auto t = Clock::now();
  const SteinerFreeBound bound = steiner_free_bound(domain);  // the thesis's definition, reported
  st.g = bound.g;
  st.alpha = bound.vertex_term;
  st.segment_bound = detail::segment_bound(domain).angle;
  const detail::FanBound fan = detail::vertex_fan_bound(domain);
  st.fan_bound = std::min(fan.angle, fan.obstacle_angle);
  st.upper_bound = std::min({bound.upper_bound(), bound.vertex_term, st.segment_bound, st.fan_bound});  // NoSteinerStats::upper_bound
  st.seconds_bound = since(t);
}

// The polygon Q, or nothing with the reason in `reason`.
std::optional<PolygonQ> build_q(const Domain2& domain, NoSteinerStats& st, std::string& reason) {
  std::optional<PolygonQ> q;
  const auto t = Clock::now();
  try {
    // Q needs interference through the far end (SteinerFreeOptions;
    // docs/algorithm/nosteiner2d.md "Welding and the polygon Q").
    PolygonQ built = polygon_q(domain, steiner_free_bound(domain, {.sides_at_far_end = true}));
    if (built.representable)
      q = std::move(built);
    else
      reason = "Q not representable in doubles (spiral depth, docs/algorithm/nosteiner2d.md \"Known limits\")";
  } catch (const std::exception& ex) {
    reason = std::string("Q failed: ") + ex.what();
  }
  st.seconds_q = since(t);
  return q;
}

// The polygon R shrunk from Q (into r) and its quad mesh, or nothing with the
// reason in `reason`.
std::optional<QuadMeshResult> build_r_mesh(const PolygonQ& q, const NoSteinerOptions& options, PolygonR& r,
                                           NoSteinerStats& st, std::string& reason) {
  const auto t = Clock::now();
  std::optional<QuadMeshResult> r_mesh;
  try {
    r = shrink_q_to_r(q_loop_points(q));
    if (!r.valid)
      reason = "R invalid: " + r.failure;
    else if (!r.representable)
      reason = "R below double resolution (docs/algorithm/nosteiner2d.md \"Delta and the shrink to R\")";
    else
      r_mesh = quad_mesh(polygon_r_domain(r), options.r_mesh);
  } catch (const std::exception& ex) {
    reason = std::string("R failed: ") + ex.what();
  }
  st.seconds_r = since(t);
  return r_mesh;
}

// The full mesh into `mesh`: Q^c, R's mesh, and the Q-to-R triangles between
// them. False (reason in `reason`) when the matching throws.
bool assemble_full(const PolygonQ& q, const PolygonR& r, const QuadMeshResult& r_mesh, const NoSteinerOptions& options,
                   TriMesh2& mesh, NoSteinerStats& st, std::string& reason) {
  bool full = false;
  const auto t = Clock::now();
  try {
    mesh.vertices = q.wedges.vertices;
    add(mesh, q.wedges.triangles, kRegionWedges);
    const int offset = int(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), r_mesh.mesh.vertices.begin(), r_mesh.mesh.vertices.end());
    add(mesh, r_mesh.mesh.triangles, kRegionR, offset);
    // §5.4: match trapezoids and triangles with square drawing (match_qr.hpp).
    detail::MatchOptions match;
    if (options.thesis_fans) {  // the thesis's construction as it is (no swap for the plain CDT)
      match.connectivity = detail::MatchOptions::Connectivity::Fans;
      match.keep_better = false;
    }
    const auto between = detail::match_q_to_r(q, r, r_mesh.mesh, match);
    mesh.vertices.insert(mesh.vertices.end(), between.points.begin(), between.points.end());
    add(mesh, between.triangles, kRegionBetween);
    // Vertices on dR: R's mesh vertices on a Q-to-R triangle.
    std::vector<char> on_dr(r_mesh.mesh.vertices.size(), 0);
    for (const auto& tri : between.triangles)
      for (int v : tri)
        if (v >= offset && v < offset + int(on_dr.size())) on_dr[std::size_t(v - offset)] = 1;
    for (char c : on_dr) st.r_vertices += c;
    full = true;
  } catch (const std::exception& ex) {
    reason = std::string("Q to R failed: ") + ex.what();
  }
  st.seconds_between = since(t);
  return full;
}

// The full mesh still passes the checker (options.verify)? Else the reason.
bool full_mesh_passes(const TriMesh2& mesh, const Domain2& domain, NoSteinerStats& st, std::string& reason) {
  bool full = true;
  const auto t = Clock::now();
  std::string why;
  if (!passes(mesh, domain, why)) {
    full = false;
    reason = "full mesh failed the check: " + why;
  }
  st.seconds_verify += since(t);
  return full;
}

// The QOnly fallback: Q^c + the CDT of Q into `mesh`, st.path QOnly unless it
// throws or (options.verify) fails the checker, when st.path stays or becomes Cdt.
void q_only_fallback(const PolygonQ& q, const Domain2& domain, const NoSteinerOptions& options, TriMesh2& mesh,
                     NoSteinerStats& st, std::string& reason) {
  try {
    mesh = q_only(q);
    st.path = NoSteinerPath::QOnly;
    if (options.verify) {
      const auto t = Clock::now();
      std::string why;
      if (!passes(mesh, domain, why)) {
        st.path = NoSteinerPath::Cdt;
        reason += "; Q-only mesh failed the check: " + why;
      }
      st.seconds_verify += since(t);
    }
  } catch (const std::exception& ex) {
    reason += std::string("; CDT of Q failed: ") + ex.what();
  }
}

// Given Q: the full mesh (st.path Full) or the QOnly fallback (st.path QOnly,
// or Cdt when that fails too).
void mesh_from_q(const PolygonQ& q, const Domain2& domain, const NoSteinerOptions& options, TriMesh2& mesh,
                 NoSteinerStats& st, std::string& reason) {
  st.q_vertices = 0;
  for (const auto& loop : q.loops) st.q_vertices += std::int64_t(loop.size());
  bool full = false;
  PolygonR r;
  const std::optional<QuadMeshResult> r_mesh = build_r_mesh(q, options, r, st, reason);
  if (r_mesh) full = assemble_full(q, r, *r_mesh, options, mesh, st, reason);
  if (full && options.verify) full = full_mesh_passes(mesh, domain, st, reason);
  if (full) {
    st.path = NoSteinerPath::Full;
  } else {
    q_only_fallback(q, domain, options, mesh, st, reason);
  }
}

// The quality pass (quality_pass.hpp) on `mesh`; with options.verify, the
// mesh before the pass is kept (and the reason appended to `reason`) when
// the output fails the checker. Adds its verify time to st.seconds_verify.
detail::QualityPassStats checked_quality_pass(const Domain2& domain, const NoSteinerOptions& options, TriMesh2& mesh,
                                              NoSteinerStats& st, std::string& reason,
                                              const detail::QualityPassOptions& pass_options = {}) {
  TriMesh2 before = mesh;
  const detail::QualityPassStats pass =
      detail::improve_min_angle(mesh, int(domain.pslg.vertices.size()), pass_options);
  if (options.verify) {  // valid by construction (quality_pass.hpp); checked like every stage
    const auto t = Clock::now();
    std::string why;
    if (!passes(mesh, domain, why)) {
      mesh = std::move(before);
      reason += (reason.empty() ? "" : "; ") + std::string("quality pass output failed the check: ") + why;
    }
    st.seconds_verify += since(t);
  }
  return pass;
}

// The quality pass on the pipeline's mesh, its counts into st.pass_*.
void run_quality_pass(const Domain2& domain, const NoSteinerOptions& options, TriMesh2& mesh, NoSteinerStats& st,
                      std::string& reason) {
  const auto t = Clock::now();
  const double verify_before = st.seconds_verify;
  const detail::QualityPassStats pass = checked_quality_pass(domain, options, mesh, st, reason);
  st.pass_flips = pass.flips;
  st.pass_removals = pass.removals + pass.coarsened;
  st.pass_moves = pass.moves;
  st.pass_cavities = pass.cavities + pass.large_cavities;
  st.pass_stuck = pass.stopped_stuck;
  st.seconds_pass = since(t) - (st.seconds_verify - verify_before);
}

// A target in degrees as printed ("%g").
std::string degrees_text(double degrees) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", degrees);
  return buffer;
}

// One refined candidate c with the quality pass (options.quality_pass: every
// setting of detail::refined_pass_variants on a copy, in order) and, with
// options.verify, dropped when it fails the checker. The best so far (first
// maximum; `any` once one is recorded) is in st.refined_*; a result replaces
// `mesh` (min angle `best`, updated; st.path Refined) when its min angle is
// strictly larger.
void try_refined_candidate(const Domain2& domain, const NoSteinerOptions& options, const detail::RefinedCandidate& c,
                           TriMesh2& mesh, double& best, bool& any, NoSteinerStats& st) {
  const double target = c.target_degrees;
  std::vector<detail::QualityPassOptions> variants = detail::refined_pass_variants(target);
  if (!options.quality_pass) variants.resize(1);  // the candidate as refined (no pass below)
  for (const detail::QualityPassOptions& variant : variants) {
    TriMesh2 m = c.mesh;
    std::string why;
    if (options.quality_pass) checked_quality_pass(domain, options, m, st, why, variant);
    if (options.verify && !passes(m, domain, why)) continue;
    const double angle = min_triangle_angle(m);
    if (!any || angle > st.refined_min_angle) {
      any = true;
      st.refined_min_angle = angle;
      st.refined_target = target;
      st.refined_inserted = std::int64_t(c.inserted);
      st.refined_seeds = std::int64_t(c.seeds);
      st.refined_target_reached = c.target_reached;
    }
    if (angle > best) {
      st.fallback_reason = (st.fallback_reason.empty() ? "" : st.fallback_reason + "; ") +
                           (c.seeds > 0 ? "the seeded refined candidate (target " : "the refined candidate (target ") +
                           degrees_text(target) +
                           " deg) has the larger min angle (" + std::to_string(angle) + " rad against " +
                           std::to_string(best) + " rad)";
      st.path = NoSteinerPath::Refined;
      best = angle;
      mesh = std::move(m);
    }
  }
}

// The refined candidates (options.refine_targets, in order; refined_candidate.hpp):
// per target the plain one, then, when seed_points gives any, the seeded
// one, then the one seeded with the obstacle spokes too when they add
// points, each through try_refined_candidate.
void try_refined_candidates(const Domain2& domain, const NoSteinerOptions& options, TriMesh2& mesh, double& best,
                            NoSteinerStats& st) {
  const auto t = Clock::now();
  const std::size_t cap =
      options.refine_max_points != 0 ? options.refine_max_points : detail::refined_point_cap(domain);
  bool any = false;
  for (const double target : options.refine_targets) {
    try_refined_candidate(domain, options, detail::refined_candidate(domain, target, cap), mesh, best, any, st);
    const std::vector<Vec2> seeds = detail::seed_points(domain, target, false);
    if (!seeds.empty())
      try_refined_candidate(domain, options, detail::refined_candidate(domain, target, cap, seeds), mesh, best, any, st);
    const std::vector<Vec2> more = detail::seed_points(domain, target, true);
    if (more.size() > seeds.size())
      try_refined_candidate(domain, options, detail::refined_candidate(domain, target, cap, more), mesh, best, any, st);
  }
  st.seconds_refine = since(t);
}

// Records the CDT of P's min angle; with options.keep_better_cdt it replaces
// `mesh` (min angle `best`; st.path CdtBetter) when its min angle is larger.
void compare_with_cdt(const Domain2& domain, const NoSteinerOptions& options, TriMesh2& mesh, double best,
                      NoSteinerStats& st) {
  const auto t = Clock::now();
  TriMesh2 cdt = p_cdt(domain);
  st.cdt_min_angle = min_triangle_angle(cdt);
  st.seconds_cdt = since(t);
  if (options.keep_better_cdt && st.path != NoSteinerPath::Cdt && st.cdt_min_angle > best) {
    st.fallback_reason = (st.fallback_reason.empty() ? "" : st.fallback_reason + "; ") + "the CDT of P has the larger min angle (" + std::to_string(st.cdt_min_angle) +
                         " rad against " + std::to_string(best) + " rad from " +
                         to_string(st.path) + ")";
    st.path = NoSteinerPath::CdtBetter;
    mesh = std::move(cdt);
  }
}

// The input segments as the boundary edges (no Steiner point: one mesh edge each).
void add_boundary_edges(const Domain2& domain, TriMesh2& mesh) {
  for (std::size_t l = 0; l < domain.loops.size(); ++l)
    for (std::size_t k = 0; k < domain.loops[l].size(); ++k) {
      mesh.edges.push_back({domain.loops[l][k], domain.loops[l][(k + 1) % domain.loops[l].size()]});
      if (!domain.pslg.segment_markers.empty())
        mesh.edge_markers.push_back(domain.pslg.segment_markers[std::size_t(domain.loop_segments[l][k])]);
    }
}

// The statistics of the final mesh: sizes, min angles overall and per region.
void record_final_stats(const TriMesh2& mesh, NoSteinerStats& st) {
  st.triangles = std::int64_t(mesh.triangles.size());
  st.vertices = std::int64_t(mesh.vertices.size());
  st.min_angle = min_triangle_angle(mesh);
  st.ratio = st.g > 0 ? st.min_angle / st.g : 0;
  std::int64_t n = 0;
  st.wedge_min_angle = region_min_angle(mesh, kRegionWedges, st.wedge_triangles);
  st.between_min_angle = region_min_angle(mesh, kRegionBetween, st.between_triangles);
  st.r_min_angle = region_min_angle(mesh, kRegionR, st.r_triangles);
  region_min_angle(mesh, kRegionQCdt, n);
  st.cdt_triangles = n;
  region_min_angle(mesh, kRegionPCdt, n);
  st.cdt_triangles += n;
  region_min_angle(mesh, kRegionRefined, st.refined_triangles);
  st.target_reached = st.min_angle >= st.target * std::numbers::pi / 180;
}

}  // namespace

NoSteinerResult triangulate_without_boundary_steiner(const Domain2& domain, const NoSteinerOptions& options) {
  const auto start = Clock::now();
  NoSteinerResult out;
  NoSteinerStats& st = out.stats;
  record_bound(domain, st);

  // Each stage either succeeds or records why the next fallback is taken.
  std::string reason;
  const std::optional<PolygonQ> q = build_q(domain, st, reason);
  TriMesh2 mesh;
  st.path = NoSteinerPath::Cdt;
  if (q) mesh_from_q(*q, domain, options, mesh, st, reason);
  if (st.path == NoSteinerPath::Cdt) mesh = p_cdt(domain);
  st.construction_min_angle = min_triangle_angle(mesh);
  st.construction_triangles = std::int64_t(mesh.triangles.size());
  if (options.quality_pass && st.path != NoSteinerPath::Cdt) run_quality_pass(domain, options, mesh, st, reason);
  st.fallback_reason = st.path == NoSteinerPath::Full ? std::string() : reason;
  st.pipeline_path = st.path;
  st.pipeline_min_angle = min_triangle_angle(mesh);
  st.pipeline_triangles = std::int64_t(mesh.triangles.size());
  st.pipeline_vertices = std::int64_t(mesh.vertices.size());
  double best = st.pipeline_min_angle;
  if (!options.refine_targets.empty()) try_refined_candidates(domain, options, mesh, best, st);
  if (options.compare_cdt) compare_with_cdt(domain, options, mesh, best, st);
  st.target = options.min_angle_target;
  add_boundary_edges(domain, mesh);
  record_final_stats(mesh, st);
  out.mesh = std::move(mesh);
  st.seconds_total = since(start);
  return out;
}

}  // namespace pqmesh
