// Thesis §5.4.1 "Drawing squares", "Level", "Elongation" (Lemmas 38-42) and
// the centre vertices of "Triangulation of squares" (match_squares.hpp).
//
// S is the list of items along F from a to b: at first the mesh edges of R
// on F ("triangulation edges", elongation 1), later also the top sides of
// squares. Invariants: the items of S cover [0, 1] in u without gaps and in
// order; after step i every item of level <= i that had a neighbour of level
// <= i was drawn around (the runs are maximal).
#include "nosteiner2d/match_squares.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <utility>

namespace pqmesh::detail {

namespace {

struct Item {
  int level = 1;
  double u0 = 0, u1 = 1;
  bool at_start = false, at_end = false;  // contains F's first / last vertex
  bool mesh_edge = true;                  // a triangulation edge of R on F (not a square)
  double elongation = 1;
  double height = 0;  // t of its top: 0 for a mesh edge
};

// floor(log2(x)) for x >= 1, from the binary exponent (exact on the rounded x).
int floor_log2(double x) { return std::ilogb(x); }

}  // namespace

Vec2 figure_point(const MatchFigure& f, double u, double t) {
  const Vec2 l = f.a + t * (f.p - f.a);
  const Vec2 r = f.b + t * (f.q - f.b);
  if (u == 0) return l;
  if (u == 1) return r;
  return l + u * (r - l);
}

SquareDrawing draw_squares(const MatchFigure& f) {
  SquareDrawing out;
  const std::size_t pieces = f.f.size() - 1;
  const Vec2 ab = f.b - f.a;
  const double ab2 = dot(ab, ab);
  std::vector<double> len(pieces), u(f.f.size());
  for (std::size_t i = 0; i < pieces; ++i) len[i] = std::hypot(f.f[i + 1].x - f.f[i].x, f.f[i + 1].y - f.f[i].y);
  for (std::size_t i = 0; i < f.f.size(); ++i) u[i] = std::clamp(dot(f.f[i] - f.a, ab) / ab2, 0.0, 1.0);
  u.front() = 0;
  u.back() = 1;
  out.f_u = u;
  const double h0 = *std::min_element(len.begin(), len.end());
  if (!(h0 > 0)) return out;

  // Levels from lengths, the end-edge rule, then balance by raising.
  std::vector<int> level(pieces), base(pieces);
  for (std::size_t i = 0; i < pieces; ++i) base[i] = level[i] = 1 + floor_log2(len[i] / h0);
  if (pieces >= 2) {
    level.front() = std::max(level.front(), level[1]);
    level.back() = std::max(level.back(), level[pieces - 2]);
  }
  for (std::size_t i = 1; i < pieces; ++i) level[i] = std::max(level[i], level[i - 1] - 1);
  for (std::size_t i = pieces - 1; i-- > 0;) level[i] = std::max(level[i], level[i + 1] - 1);
  int max_level = 1;
  for (std::size_t i = 0; i < pieces; ++i) {
    out.level_raises += level[i] != base[i];
    max_level = std::max(max_level, level[i]);
  }
  const double lf = std::sqrt(ab2);
  // n: see match_squares.hpp (the last step's squares span 2 to 4 edges).
  const int n = std::min(kMaxSquareSteps, std::max(max_level, floor_log2(std::max(1.0, lf / h0)) - 1));
  out.steps = n;

  std::vector<Item> s(pieces);
  for (std::size_t i = 0; i < pieces; ++i) {
    s[i].level = level[i];
    s[i].u0 = u[i];
    s[i].u1 = u[i + 1];
    s[i].at_start = i == 0;
    s[i].at_end = i + 1 == pieces;
  }

  std::set<std::pair<double, double>> emitted;  // (u, t) of the points already given
  auto emit = [&](double pu, double pt) {
    if (!emitted.emplace(pu, pt).second) return;
    SquarePoint sp;
    sp.point = figure_point(f, pu, pt);
    sp.u = pu;
    sp.t = pt;
    sp.on = pu == 0 ? SquarePoint::On::StartEdge : (pu == 1 ? SquarePoint::On::EndEdge : SquarePoint::On::Inside);
    out.points.push_back(sp);
  };
  out.min_elongation = std::numeric_limits<double>::infinity();

  for (int i = 1; i <= n; ++i) {
    const double t_top = std::ldexp(1.0, -(n - i + 1));  // M_{n-i+1}
    std::vector<Item> next;
    std::size_t k = 0;
    while (k < s.size()) {
      if (s[k].level > i) {
        next.push_back(s[k++]);
        continue;
      }
      std::size_t e = k;
      while (e < s.size() && s[e].level <= i) ++e;
      const std::size_t m = e - k;
      // Groups of the maximal run [k, e).
      std::size_t g = k;
      while (m > 1 && e - g >= 2) {
        std::size_t size = 2;
        if (e - g == 3 && e == s.size()) size = 3;  // the run ends S: the last square takes three
        Item sq;
        sq.level = i + 1;
        sq.u0 = s[g].u0;
        sq.u1 = s[g + size - 1].u1;
        sq.at_start = s[g].at_start;
        sq.at_end = s[g + size - 1].at_end;
        sq.mesh_edge = false;
        sq.elongation = 0;
        sq.height = t_top;
        DrawnSquare drawn{sq.u0, sq.u1, t_top, {}, false, 0, 0};
        bool all_mesh_edges = true;
        for (std::size_t h = g; h < g + size; ++h) {
          drawn.items.push_back({s[h].u0, s[h].u1, s[h].height});
          sq.elongation += s[h].elongation * std::ldexp(1.0, s[h].level - sq.level);
          all_mesh_edges = all_mesh_edges && s[h].mesh_edge;
          if (i > s[h].level + 1) ++out.lemma41_violations;
        }
        ++out.squares;
        if (sq.at_end)
          out.max_elongation_right = std::max(out.max_elongation_right, sq.elongation);
        else
          out.max_elongation_inner = std::max(out.max_elongation_inner, sq.elongation);
        out.min_elongation = std::min(out.min_elongation, sq.elongation);
        emit(sq.u0, t_top);
        emit(sq.u1, t_top);
        // Centre vertex of a square around three triangulation edges (Fig. 5.20):
        // the midpoint of the segment halfway between its bottom and top.
        if (size == 3 && all_mesh_edges) {
          emit((sq.u0 + sq.u1) / 2, t_top / 2);
          drawn.has_centre = true;
          drawn.centre_u = (sq.u0 + sq.u1) / 2;
          drawn.centre_t = t_top / 2;
        }
        out.drawn.push_back(std::move(drawn));
        next.push_back(sq);
        g += size;
      }
      for (; g < e; ++g) next.push_back(s[g]);  // a run of one, or the odd item left over
      k = e;
    }
    s = std::move(next);
  }
  for (const Item& it : s) out.final_items.push_back({it.u0, it.u1, it.height});
  if (s.size() > 1)
    for (const Item& it : s)
      if (it.level + 1 <= n) ++out.lemma41_violations;
  if (out.squares == 0) out.min_elongation = 0;
  return out;
}

}  // namespace pqmesh::detail
