// Thesis §5.4.1 "Triangulation of squares" (Figs. 5.17, 5.19-5.21), §5.4.2:
// the per-piece triangulation of one match figure (match_fans.hpp).
//
// Invariants: every polygon is walked counter-clockwise in the (u, t) plane
// (u to the right, t up) and then reversed, because the frame map reverses
// orientation (p -> q -> b -> a, i.e. (0,1) -> (1,1) -> (1,0) -> (0,0), is
// counter-clockwise in the plane); it names each kept vertex on its sides
// once, so two pieces sharing a side list the same vertices on it; every
// triangle appended is strictly counter-clockwise (exact orient2d) or comes
// from the CDT of its piece.
#include "nosteiner2d/match_fans.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "cdt2d/constrained_delaunay.hpp"
#include "improve2d/triangle_angles.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::detail {

namespace {

using Tri = std::array<int, 3>;

// The kept vertices of a figure by frame line.
struct Frame {
  std::map<double, std::vector<std::pair<double, int>>> on_u;  // u -> (t, point), t increasing
  std::map<double, std::vector<std::pair<double, int>>> on_t;  // t -> (u, point), u increasing
  std::map<std::pair<double, double>, int> at;                 // (u, t) -> point
  std::map<int, std::vector<std::pair<double, double>>> uv;    // point -> its (u, t) (V of a triangle: two)
  // The three points lie on one frame line (u = const or t = const): exactly
  // collinear in the construction, so a triangle on them is a sliver made by
  // rounding, never a piece of the thesis's fans.
  bool on_one_line(int a, int b, int c) const {
    const auto &A = uv.at(a), &B = uv.at(b), &C = uv.at(c);
    for (const auto& x : A)
      for (const auto& y : B)
        for (const auto& z : C)
          if ((x.first == y.first && y.first == z.first) || (x.second == y.second && y.second == z.second)) return true;
    return false;
  }
};

Frame make_frame(const std::vector<FrameVertex>& vertices) {
  Frame f;
  for (const FrameVertex& v : vertices) {
    if (!f.at.emplace(std::pair{v.u, v.t}, v.point).second) continue;
    f.uv[v.point].push_back({v.u, v.t});
    f.on_u[v.u].push_back({v.t, v.point});
    f.on_t[v.t].push_back({v.u, v.point});
  }
  for (auto& [u, list] : f.on_u) std::sort(list.begin(), list.end());
  for (auto& [t, list] : f.on_t) std::sort(list.begin(), list.end());
  return f;
}

// Appends the vertices of the axis-parallel frame segment (u0, t0) -> (u1, t1)
// strictly between its ends, in order, then its end when that is a vertex.
void walk(const Frame& f, double u0, double t0, double u1, double t1, std::vector<int>& poly) {
  if (u0 == u1 && t0 == t1) return;
  const bool vertical = u0 == u1;
  const auto& lines = vertical ? f.on_u : f.on_t;
  const auto it = lines.find(vertical ? u0 : t0);
  if (it != lines.end()) {
    const double from = vertical ? t0 : u0, to = vertical ? t1 : u1;
    if (from < to) {
      for (const auto& [s, k] : it->second)
        if (s > from && s < to) poly.push_back(k);
    } else {
      for (auto r = it->second.rbegin(); r != it->second.rend(); ++r)
        if (r->first < from && r->first > to) poly.push_back(r->second);
    }
  }
  const auto e = f.at.find({u1, t1});
  if (e != f.at.end()) poly.push_back(e->second);
}

// Drops repeated consecutive vertices (also across the wrap).
void close_polygon(std::vector<int>& poly) {
  poly.erase(std::unique(poly.begin(), poly.end()), poly.end());
  while (poly.size() > 1 && poly.front() == poly.back()) poly.pop_back();
}

// Fan from c (a vertex of poly or a point inside it): a triangle per side not
// incident to c. False when one is not strictly counter-clockwise.
// (A side on one frame line with c is refused too: Frame::on_one_line.)
bool fan_from(const Frame& fr, int c, const std::vector<int>& poly, const std::vector<Vec2>& pts,
              std::vector<Tri>& out) {
  std::vector<Tri> tris;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const int x = poly[i], y = poly[(i + 1) % poly.size()];
    if (x == c || y == c) continue;
    if (fr.on_one_line(c, x, y)) return false;
    if (orient2d(pts[std::size_t(c)], pts[std::size_t(x)], pts[std::size_t(y)]) != Sign::Positive) return false;
    tris.push_back({c, x, y});
  }
  out.insert(out.end(), tris.begin(), tris.end());
  return true;
}

void polygon_cdt(const std::vector<int>& poly, const std::vector<Vec2>& pts, std::vector<Tri>& out) {
  cdt2d::CdtInput in;
  const int n = int(poly.size());
  for (int k = 0; k < n; ++k) {
    in.points.push_back(pts[std::size_t(poly[std::size_t(k)])]);
    in.constraints.push_back({k, (k + 1) % n});
  }
  for (const auto& t : cdt2d::constrained_delaunay(in, /*keep_inside=*/true).triangles)
    out.push_back({poly[std::size_t(t[0])], poly[std::size_t(t[1])], poly[std::size_t(t[2])]});
}

// Strictly counter-clockwise and not on one frame line.
bool ccw(const Frame& fr, const std::vector<Vec2>& pts, int a, int b, int c) {
  if (fr.on_one_line(a, b, c)) return false;
  return orient2d(pts[std::size_t(a)], pts[std::size_t(b)], pts[std::size_t(c)]) == Sign::Positive;
}

// The region between the final S and E of a trapezoid: chain = one end of E,
// one side, the bottom, the other side, the other end of E, counter-clockwise
// (the polygon closes with the edge back to the first). Every chain vertex
// goes to the closer end of E (Fig. 5.17); p and q below are the chain's ends.
bool trapezoid_top(const Frame& fr, const std::vector<int>& chain, const std::vector<Vec2>& pts,
                   std::vector<Tri>& out) {
  const int p = chain.front(), q = chain.back();
  std::vector<bool> to_p(chain.size());
  for (std::size_t i = 0; i < chain.size(); ++i) {
    const Vec2 x = pts[std::size_t(chain[i])];
    to_p[i] = i == 0 || (i + 1 < chain.size() && dot(x - pts[std::size_t(p)], x - pts[std::size_t(p)]) <=
                                                     dot(x - pts[std::size_t(q)], x - pts[std::size_t(q)]));
  }
  std::vector<Tri> tris;
  int switches = 0;
  for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
    const int x = chain[i], y = chain[i + 1];
    if (to_p[i] && to_p[i + 1]) {
      if (x == p) continue;
      if (!ccw(fr, pts, p, x, y)) return false;
      tris.push_back({p, x, y});
    } else if (!to_p[i] && !to_p[i + 1]) {
      if (y == q) continue;
      if (!ccw(fr, pts, q, x, y)) return false;
      tris.push_back({q, x, y});
    } else if (to_p[i] && !to_p[i + 1]) {
      ++switches;
      // The quadrilateral x, y, q, p: the diagonal with the larger min angle.
      if (x == p) {
        if (!ccw(fr, pts, x, y, q)) return false;
        tris.push_back({x, y, q});
      } else if (y == q) {
        if (!ccw(fr, pts, x, q, p)) return false;
        tris.push_back({x, q, p});
      } else {
        const std::array<Tri, 2> d1{Tri{x, y, q}, Tri{x, q, p}}, d2{Tri{x, y, p}, Tri{y, q, p}};
        auto quality = [&](const std::array<Tri, 2>& d) {
          for (const Tri& t : d)
            if (!ccw(fr, pts, t[0], t[1], t[2])) return -1.0;
          double m = 10;
          for (const Tri& t : d)
            m = std::min(m, min_angle(pts[std::size_t(t[0])], pts[std::size_t(t[1])], pts[std::size_t(t[2])]));
          return m;
        };
        const double m1 = quality(d1), m2 = quality(d2);
        if (m1 < 0 && m2 < 0) return false;
        const auto& d = m1 >= m2 ? d1 : d2;
        tris.insert(tris.end(), d.begin(), d.end());
      }
    } else {
      return false;  // back from q's side to p's: not the monotone split of Fig. 5.17
    }
  }
  if (switches != 1) return false;
  out.insert(out.end(), tris.begin(), tris.end());
  return true;
}

}  // namespace

bool triangulate_figure_by_fans(const MatchFigure& figure, const SquareDrawing& drawing,
                                const std::vector<FrameVertex>& vertices, const std::vector<Vec2>& points,
                                std::vector<std::array<int, 3>>& triangles, FanStats& stats) {
  if (drawing.final_items.empty()) return false;
  const Frame fr = make_frame(vertices);
  std::vector<Tri> out;
  auto smallest = [&](std::size_t from) {
    double m = 10;
    for (std::size_t i = from; i < out.size(); ++i)
      m = std::min(m, min_angle(points[std::size_t(out[i][0])], points[std::size_t(out[i][1])],
                                points[std::size_t(out[i][2])]));
    return m;
  };
  auto piece = [&](std::vector<int>& poly, const std::vector<int>& centres) {
    const std::size_t from = out.size();
    close_polygon(poly);
    std::reverse(poly.begin(), poly.end());  // counter-clockwise in the plane
    if (poly.size() < 3) return;
    for (int c : centres)
      if (fan_from(fr, c, poly, points, out)) {
        ++stats.fans;
        stats.fans_min_angle = std::min(stats.fans_min_angle, smallest(from));
        return;
      }
    ++stats.polygon_cdts;
    polygon_cdt(poly, points, out);
    stats.polygon_cdts_min_angle = std::min(stats.polygon_cdts_min_angle, smallest(from));
  };
  // The bottom staircase of items, from (u0 of the first, its height) to the
  // end of the last.
  auto staircase = [&](const std::vector<FrameItem>& items, std::vector<int>& poly) {
    for (std::size_t k = 0; k < items.size(); ++k) {
      walk(fr, items[k].u0, items[k].height, items[k].u1, items[k].height, poly);
      if (k + 1 < items.size()) walk(fr, items[k].u1, items[k].height, items[k].u1, items[k + 1].height, poly);
    }
  };

  for (const DrawnSquare& sq : drawing.drawn) {
    const FrameItem& first = sq.items.front();
    const FrameItem& last = sq.items.back();
    std::vector<int> poly;
    if (const auto s = fr.at.find({first.u0, first.height}); s != fr.at.end()) poly.push_back(s->second);
    staircase(sq.items, poly);
    walk(fr, last.u1, last.height, sq.u1, sq.t_top, poly);
    walk(fr, sq.u1, sq.t_top, sq.u0, sq.t_top, poly);
    walk(fr, sq.u0, sq.t_top, first.u0, first.height, poly);
    std::vector<int> centres;
    if (sq.has_centre) {
      if (const auto c = fr.at.find({sq.centre_u, sq.centre_t}); c != fr.at.end()) centres.push_back(c->second);
    } else {
      double top = 0;
      for (const FrameItem& it : sq.items) top = std::max(top, it.height);
      for (std::size_t k = 0; k + 1 < sq.items.size(); ++k)
        if (const auto c = fr.at.find({sq.items[k].u1, top}); c != fr.at.end()) centres.push_back(c->second);
    }
    piece(poly, centres);
  }

  // Between the final S and E (Fig. 5.17), or V for a match triangle (§5.4.2).
  const auto& items = drawing.final_items;
  std::vector<int> chain;
  const auto p = fr.at.find({0.0, 1.0});
  if (p == fr.at.end()) return false;
  chain.push_back(p->second);
  walk(fr, 0, 1, 0, items.front().height, chain);
  staircase(items, chain);
  walk(fr, 1, items.back().height, 1, 1, chain);
  chain.erase(std::unique(chain.begin(), chain.end()), chain.end());
  if (figure.is_triangle) {
    piece(chain, {p->second});
    triangles.insert(triangles.end(), out.begin(), out.end());
    return true;
  }
  // Counter-clockwise in the plane: q, right side down, the bottom from b's
  // end to a's, left side up, p (trapezoid_top is symmetric in its two ends).
  std::reverse(chain.begin(), chain.end());
  const std::size_t from = out.size();
  if (chain.size() >= 3 && trapezoid_top(fr, chain, points, out)) {
    ++stats.fans;
    stats.fans_min_angle = std::min(stats.fans_min_angle, smallest(from));
  } else {
    std::reverse(chain.begin(), chain.end());  // piece() reverses it back
    piece(chain, {});
  }
  triangles.insert(triangles.end(), out.begin(), out.end());
  return true;
}

}  // namespace pqmesh::detail
