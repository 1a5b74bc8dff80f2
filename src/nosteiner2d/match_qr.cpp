// Thesis §5.4 "Matching R to Q" assembled (match_qr.hpp): the match figures,
// the square vertices of each, and the triangles of Q \ R on that vertex set.
//
// Invariants of the output: every Steiner point lies strictly inside Q \ R
// (kept only when exact orient2d tests put it in the closure of its figure,
// or of the neighbouring figure across the match edge it was put on, and
// strictly off dQ and dR), no two points share coordinates, and the
// triangles are the constrained Delaunay triangulation of Q \ R with dQ's
// sides (unsplit) and dR's mesh edges as constraints (or, with
// Connectivity::Fans, the thesis's fans of match_fans.hpp on the same
// vertices), so they conform to Q^c along dQ and to R's mesh along dR.
#include "nosteiner2d/match_qr.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "cdt2d/constrained_delaunay.hpp"
#include "nosteiner2d/match_fans.hpp"
#include "nosteiner2d/match_figures.hpp"
#include "nosteiner2d/match_squares.hpp"
#include "improve2d/triangle_angles.hpp"
#include "pqmesh/errors.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::detail {

namespace {

// x in the closed figure minus E and F (exact). Outline p -> q -> b -> a
// (triangle: V -> b -> a).
bool in_figure(const MatchFigure& f, Vec2 x) {
  if (orient2d(f.b, f.a, x) != Sign::Positive) return false;          // strictly off F (into Q \ R)
  if (orient2d(f.a, f.p, x) == Sign::Negative) return false;          // match edge at a
  if (f.is_triangle) return orient2d(f.p, f.b, x) != Sign::Negative;  // match edge at b
  return orient2d(f.q, f.b, x) != Sign::Negative && orient2d(f.p, f.q, x) == Sign::Positive;  // at b; off E
}

double interior_angle(Vec2 at, Vec2 u, Vec2 v) { return angle_between(u - at, v - at); }

// The CDT's input with, per CDT point, its combined id and the smallest
// figure scale it belongs to.
struct CdtPoints {
  cdt2d::CdtInput in;
  std::vector<int> combined;                    // CDT point -> combined id
  std::vector<double> scale;                    // CDT point -> smallest figure scale it belongs to
  std::map<std::pair<double, double>, int> at;  // coordinates -> CDT point
  std::map<int, int> local;                     // combined id of a dQ / dR vertex -> CDT point

  // The CDT point of dQ / dR vertex `id` at x, added on first sight.
  int add_fixed(int id, Vec2 x) {
    if (local.contains(id)) return local[id];
    const int k = int(in.points.size());
    if (!at.emplace(std::pair{x.x, x.y}, k).second) throw InternalError("match_q_to_r: dQ and dR share a point");
    in.points.push_back(x);
    combined.push_back(id);
    scale.push_back(std::numeric_limits<double>::infinity());
    local[id] = k;
    return k;
  }
};

// The CDT's fixed points, dQ then dR's mesh vertices, and its constraints.
void add_fixed_points(const PolygonQ& q, const std::vector<MatchFigure>& figs, CdtPoints& pts) {
  for (const auto& loop : q.loops)
    for (int v : loop) pts.add_fixed(v, q.wedges.vertices[std::size_t(v)]);
  for (const auto& f : figs)
    for (std::size_t i = 0; i < f.f.size(); ++i) pts.add_fixed(f.f_ids[i], f.f[i]);

  // Constraints: dQ's sides (Q's interior, hence Q \ R, on the left) and
  // dR's mesh edges reversed (R's interior was on their left).
  for (const auto& loop : q.loops)
    for (std::size_t k = 0; k < loop.size(); ++k)
      pts.in.constraints.push_back({pts.local[loop[k]], pts.local[loop[(k + 1) % loop.size()]]});
  for (const auto& f : figs)
    for (std::size_t i = 0; i + 1 < f.f_ids.size(); ++i)
      pts.in.constraints.push_back({pts.local[f.f_ids[i + 1]], pts.local[f.f_ids[i]]});
}

// The minima of MatchStats start at +infinity (set to 0 by
// finish_figure_stats when nothing was measured).
void start_figure_stats(MatchStats& st) {
  st.min_delta_over_length = std::numeric_limits<double>::infinity();
  st.min_match_angle = st.min_match_angle_triangle = std::numeric_limits<double>::infinity();
  st.min_elongation = std::numeric_limits<double>::infinity();
}

// Counts the figure (trapezoid or triangle) and records its scale and match angles.
void record_figure_shape(const MatchFigure& f, MatchStats& st) {
  (f.is_triangle ? st.triangles_fig : st.trapezoids) += 1;
  if (!f.is_triangle) st.min_delta_over_length = std::min(st.min_delta_over_length, f.scale);
  double& lo = f.is_triangle ? st.min_match_angle_triangle : st.min_match_angle;
  double& hi = f.is_triangle ? st.max_match_angle_triangle : st.max_match_angle;
  for (const double ang : {interior_angle(f.a, f.b, f.p), interior_angle(f.b, f.a, f.q)}) {
    lo = std::min(lo, ang);
    hi = std::max(hi, ang);
  }
}

// The figure's dQ and dR vertices belong to its scale too.
void lower_fixed_scales(const MatchFigure& f, CdtPoints& pts) {
  for (int id : {f.p_id, f.q_id})
    pts.scale[std::size_t(pts.local[id])] = std::min(pts.scale[std::size_t(pts.local[id])], f.scale);
  for (int id : f.f_ids)
    pts.scale[std::size_t(pts.local[id])] = std::min(pts.scale[std::size_t(pts.local[id])], f.scale);
}

// The figure's frame starts with its dR vertices (t = 0) and p, q (t = 1).
void start_frame(const MatchFigure& f, const SquareDrawing& d, CdtPoints& pts, std::vector<FrameVertex>& frame) {
  for (std::size_t i = 0; i < f.f_ids.size() && i < d.f_u.size(); ++i)
    frame.push_back({d.f_u[i], 0.0, pts.local[f.f_ids[i]]});
  frame.push_back({0.0, 1.0, pts.local[f.p_id]});
  frame.push_back({1.0, 1.0, pts.local[f.q_id]});
}

// The square drawing's counters and elongations into the statistics.
void record_drawing(const SquareDrawing& d, MatchStats& st) {
  st.squares += d.squares;
  st.max_steps = std::max(st.max_steps, d.steps);
  st.level_raises += d.level_raises;
  st.lemma41_violations += d.lemma41_violations;
  st.max_elongation_inner = std::max(st.max_elongation_inner, d.max_elongation_inner);
  st.max_elongation_right = std::max(st.max_elongation_right, d.max_elongation_right);
  if (d.squares > 0) st.min_elongation = std::min(st.min_elongation, d.min_elongation);
}

// The square vertices of figure fi kept as Steiner points (in the closed
// figure, or the neighbour's across the match edge they lie on), each added
// once to the CDT points and out.points (combined ids from first_id) and to
// the frames they belong to.
void add_square_points(const std::vector<MatchFigure>& figs, std::size_t fi, const SquareDrawing& d, int first_id,
                       CdtPoints& pts, std::vector<std::vector<FrameVertex>>& frame, MatchQR& out) {
  MatchStats& st = out.stats;
  const MatchFigure& f = figs[fi];
  // A kept square vertex belongs to this figure's frame, and one on a match
  // edge also to the neighbour's across it (at its u = 1 / u = 0, the same t).
  auto keep = [&](const SquarePoint& sp, int k) {
    frame[fi].push_back({sp.u, sp.t, k});
    if (sp.on == SquarePoint::On::StartEdge) frame[std::size_t(f.prev)].push_back({1.0, sp.t, k});
    if (sp.on == SquarePoint::On::EndEdge) frame[std::size_t(f.next)].push_back({0.0, sp.t, k});
  };
  for (const SquarePoint& sp : d.points) {
    ++st.candidates;
    bool inside = in_figure(f, sp.point);
    if (!inside && sp.on == SquarePoint::On::StartEdge) inside = in_figure(figs[std::size_t(f.prev)], sp.point);
    if (!inside && sp.on == SquarePoint::On::EndEdge) inside = in_figure(figs[std::size_t(f.next)], sp.point);
    if (!inside) {
      ++st.dropped;
      continue;
    }
    // The same point from the figure across a match edge (both put their
    // corners at the same heights t = 2^-j on it when the match edge is
    // shared with the same ends) is one vertex.
    const auto [it, added] = pts.at.emplace(std::pair{sp.point.x, sp.point.y}, int(pts.in.points.size()));
    if (!added) {
      ++st.shared;
      pts.scale[std::size_t(it->second)] = std::min(pts.scale[std::size_t(it->second)], f.scale);
      keep(sp, it->second);
      continue;
    }
    keep(sp, int(pts.in.points.size()));
    pts.in.points.push_back(sp.point);
    pts.combined.push_back(first_id + int(out.points.size()));
    pts.scale.push_back(f.scale);
    out.points.push_back(sp.point);
  }
}

// Minima over no figure or square are reported as 0.
void finish_figure_stats(MatchStats& st) {
  if (st.squares == 0) st.min_elongation = 0;
  if (st.trapezoids == 0) st.min_match_angle = st.min_delta_over_length = 0;
  if (st.triangles_fig == 0) st.min_match_angle_triangle = 0;
}

// The construction's triangles: the fans (Connectivity::Fans) when every
// figure fans, else the CDT of all points.
cdt2d::CdtOutput construction_triangles(const std::vector<MatchFigure>& figs,
                                        const std::vector<SquareDrawing>& drawings,
                                        const std::vector<std::vector<FrameVertex>>& frame, const cdt2d::CdtInput& in,
                                        const MatchOptions& options, MatchStats& st) {
  cdt2d::CdtOutput tri;
  bool fanned = options.connectivity == MatchOptions::Connectivity::Fans;
  if (fanned) {
    FanStats fs;
    for (std::size_t fi = 0; fi < figs.size(); ++fi)
      if (!triangulate_figure_by_fans(figs[fi], drawings[fi], frame[fi], in.points, tri.triangles, fs))
        ++st.figures_not_fanned;
    st.fans = fs.fans;
    st.polygon_cdts = fs.polygon_cdts;
    st.fans_min_angle = fs.fans_min_angle;
    st.polygon_cdts_min_angle = fs.polygon_cdts_min_angle;
    if (st.figures_not_fanned > 0) tri.triangles.clear();
    fanned = st.figures_not_fanned == 0;
  }
  if (!fanned) tri = cdt2d::constrained_delaunay(in, /*keep_inside=*/true);
  return tri;
}

// The triangles into out (combined ids), with their min angle overall and
// relative to the smallest scale of their vertices.
void emit_triangles(const cdt2d::CdtOutput& tri, const CdtPoints& pts, MatchQR& out) {
  MatchStats& st = out.stats;
  st.squares_min_angle = std::numeric_limits<double>::infinity();
  st.min_angle_over_scale = std::numeric_limits<double>::infinity();
  out.triangles.reserve(tri.triangles.size());
  for (const auto& t : tri.triangles) {
    const double ang = min_angle(pts.in.points[std::size_t(t[0])], pts.in.points[std::size_t(t[1])],
                                 pts.in.points[std::size_t(t[2])]);
    st.squares_min_angle = std::min(st.squares_min_angle, ang);
    const double s =
        std::min({pts.scale[std::size_t(t[0])], pts.scale[std::size_t(t[1])], pts.scale[std::size_t(t[2])]});
    st.min_angle_over_scale = std::min(st.min_angle_over_scale, ang / s);
    out.triangles.push_back(
        {pts.combined[std::size_t(t[0])], pts.combined[std::size_t(t[1])], pts.combined[std::size_t(t[2])]});
  }
  if (out.triangles.empty()) st.squares_min_angle = st.min_angle_over_scale = 0;
}

// The same region without the square vertices (the first `fixed` CDT
// points): its min angle (a measurement), and with options.keep_better its
// CDT replaces the construction when that angle is larger.
void compare_plain_cdt(std::size_t fixed, const MatchOptions& options, CdtPoints& pts, MatchQR& out) {
  MatchStats& st = out.stats;
  pts.in.points.resize(fixed);
  const cdt2d::CdtOutput plain = cdt2d::constrained_delaunay(pts.in, true);
  st.cdt_min_angle = std::numeric_limits<double>::infinity();
  for (const auto& t : plain.triangles)
    st.cdt_min_angle = std::min(st.cdt_min_angle, min_angle(pts.in.points[std::size_t(t[0])],
                                                            pts.in.points[std::size_t(t[1])],
                                                            pts.in.points[std::size_t(t[2])]));
  st.min_angle = st.squares_min_angle;
  if (options.keep_better && st.cdt_min_angle > st.squares_min_angle) {
    st.used_plain_cdt = true;
    st.min_angle = st.cdt_min_angle;
    out.points.clear();
    out.triangles.clear();
    for (const auto& t : plain.triangles)
      out.triangles.push_back(
          {pts.combined[std::size_t(t[0])], pts.combined[std::size_t(t[1])], pts.combined[std::size_t(t[2])]});
  }
}

}  // namespace

MatchQR match_q_to_r(const PolygonQ& q, const PolygonR& r, const TriMesh2& r_mesh, const MatchOptions& options) {
  MatchQR out;
  MatchStats& st = out.stats;
  const int nq = int(q.wedges.vertices.size());
  const int nr = int(r_mesh.vertices.size());
  const std::vector<MatchFigure> figs = match_figures(q, r, r_mesh);

  // The CDT's points: dQ, then dR's mesh vertices, then the square vertices.
  CdtPoints pts;
  add_fixed_points(q, figs, pts);
  const std::size_t fixed = pts.in.points.size();

  start_figure_stats(st);
  // Per figure, for the fans: the drawing and the kept vertices in its frame.
  std::vector<SquareDrawing> drawings(figs.size());
  std::vector<std::vector<FrameVertex>> frame(figs.size());
  for (std::size_t fi = 0; fi < figs.size(); ++fi) {
    const MatchFigure& f = figs[fi];
    record_figure_shape(f, st);
    lower_fixed_scales(f, pts);
    drawings[fi] = draw_squares(f);
    const SquareDrawing& d = drawings[fi];
    start_frame(f, d, pts, frame[fi]);
    record_drawing(d, st);
    add_square_points(figs, fi, d, nq + nr, pts, frame, out);
  }
  finish_figure_stats(st);

  // The construction's triangles, then (a measurement, and the alternative
  // of MatchOptions::keep_better) the same region without the square vertices.
  const cdt2d::CdtOutput tri = construction_triangles(figs, drawings, frame, pts.in, options, st);
  emit_triangles(tri, pts, out);
  compare_plain_cdt(fixed, options, pts, out);
  return out;
}

}  // namespace pqmesh::detail
