// The 2D quality pass (quality_pass.hpp; docs/algorithm/improve2d.md):
// removals, moves and flips of Steiner vertices, each accepted only when
// exact orient2d keeps every triangle it makes strictly counter-clockwise and
// its smallest new angle is above the floor of the objective.
#include "improve2d/quality_pass.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <queue>
#include <utility>

#include "improve2d/boundary_edges.hpp"
#include "improve2d/cavity_cdt.hpp"
#include "improve2d/polygon_triangulation.hpp"
#include "improve2d/triangle_angles.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::detail {
namespace {

bool ccw(Vec2 a, Vec2 b, Vec2 c) { return orient2d(a, b, c) == Sign::Positive; }

class Pass {
 public:
  Pass(TriMesh2& mesh, int first_steiner, const QualityPassOptions& options)
      : mesh_(mesh), pts_(mesh.vertices), first_steiner_(first_steiner), options_(options),
        inc_(mesh.vertices.size()), boundary_(mesh, mesh.vertices.size()) {
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      add(mesh.triangles[t], mesh.triangle_markers.empty() ? 0 : mesh.triangle_markers[t]);
  }

  QualityPassStats run() {
    QualityPassStats st;
    st.min_angle_before = current_min();
    const std::int64_t max_steps =
        options_.max_steps >= 0 ? options_.max_steps : 4 * std::int64_t(pts_.size()) + 1000;
    std::vector<int> all;  // every Steiner vertex, in id order
    for (std::size_t v = std::size_t(first_steiner_); v < pts_.size(); ++v) all.push_back(int(v));
    if (options_.coarsen) {  // one coarsening sweep over all Steiner vertices first (cheaper than many local ones)
      const std::int64_t removed = remove_above(all, st.min_angle_before);
      st.coarsened += removed;
      st.steps += removed;
    }
    for (int round = 0; round < options_.smoothing_rounds; ++round) {
      st.moves += smooth(all);
      if (options_.coarsen && targeted()) st.coarsened += remove_above(all, st.min_angle_before);
    }
    for (int sweep = 0; sweep < options_.final_smoothing_sweeps; ++sweep) st.moves += smooth(all);
    while (st.steps < max_steps) {
      const int t = worst();
      if (t < 0 || (targeted() && angle_[std::size_t(t)] >= options_.target)) break;
      if (!improve(t, st)) {
        if (targeted()) {
          st.stopped_stuck = true;
          break;
        }
        std::int64_t removed = 0;  // the neighbourhood, then 8 times larger
        for (std::size_t size = std::size_t(options_.coarsen_triangles); removed == 0 && size <= 8 * std::size_t(options_.coarsen_triangles); size *= 8)
          removed = coarsen(t, size, angle_[std::size_t(t)]);
        if (removed == 0) {
          if (options_.large_cavities && large_cavity(t)) {
            ++st.large_cavities;
            ++st.steps;
            continue;
          }
          st.stopped_stuck = true;
          break;
        }
        st.coarsened += removed;
        st.steps += removed;
        continue;
      }
      ++st.steps;
    }
    st.min_angle_after = current_min();
    write_back();
    return st;
  }

 private:
  struct Link {
    std::vector<int> star;     // triangle ids around v
    std::vector<int> polygon;  // link vertices, counter-clockwise around v
  };

  int add(std::array<int, 3> t, int marker) {
    const int id = int(tri_.size());
    tri_.push_back(t);
    marker_.push_back(marker);
    alive_.push_back(1);
    const double a = min_angle(pts_[std::size_t(t[0])], pts_[std::size_t(t[1])], pts_[std::size_t(t[2])]);
    angle_.push_back(a);
    for (int v : t) inc_[std::size_t(v)].push_back(id);
    heap_.push({a, id});
    return id;
  }

  int worst() {
    while (!heap_.empty() && !alive_[std::size_t(heap_.top().second)]) heap_.pop();
    return heap_.empty() ? -1 : heap_.top().second;
  }

  double current_min() {
    const int t = worst();
    return t < 0 ? 0 : angle_[std::size_t(t)];
  }

  // Live triangles at v (drops dead ids from inc_[v]).
  std::vector<int>& star(int v) {
    auto& s = inc_[std::size_t(v)];
    s.erase(std::remove_if(s.begin(), s.end(), [&](int t) { return !alive_[std::size_t(t)]; }), s.end());
    return s;
  }

  // The link of v as a closed CCW cycle; false when the star is not a disk
  // around v (v on the boundary), which never holds for a Steiner vertex.
  bool link(int v, Link& out) {
    out.star = star(v);
    const std::size_t n = out.star.size();
    std::vector<std::pair<int, int>>& arcs = arcs_;  // a -> b for triangle (v, a, b)
    arcs.clear();
    for (int t : out.star) {
      const auto& tr = tri_[std::size_t(t)];
      const int r = tr[0] == v ? 0 : tr[1] == v ? 1 : 2;
      arcs.push_back({tr[std::size_t((r + 1) % 3)], tr[std::size_t((r + 2) % 3)]});
    }
    out.polygon.clear();
    if (n < 3) return false;
    int cur = arcs[0].first;
    for (std::size_t step = 0; step < n; ++step) {
      out.polygon.push_back(cur);
      const auto it = std::find_if(arcs.begin(), arcs.end(), [&](const auto& a) { return a.first == cur; });
      if (it == arcs.end()) return false;
      cur = it->second;
    }
    if (cur != out.polygon.front()) return false;
    std::vector<int> sorted = out.polygon;
    std::sort(sorted.begin(), sorted.end());
    return std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
  }

  // The star of a boundary vertex v as an open CCW chain: polygon = x_0 ...
  // x_k for the triangles (v, x_i, x_i+1); false unless the triangles form
  // one such chain.
  bool open_link(int v, Link& out) {
    out.star = star(v);
    std::vector<std::pair<int, int>>& arcs = arcs_;
    arcs.clear();
    for (int t : out.star) {
      const auto& tr = tri_[std::size_t(t)];
      const int r = tr[0] == v ? 0 : tr[1] == v ? 1 : 2;
      arcs.push_back({tr[std::size_t((r + 1) % 3)], tr[std::size_t((r + 2) % 3)]});
    }
    const auto starts_nowhere = [&](const std::pair<int, int>& a) {
      return std::none_of(arcs.begin(), arcs.end(), [&](const auto& b) { return b.second == a.first; });
    };
    const auto first = std::find_if(arcs.begin(), arcs.end(), starts_nowhere);
    out.polygon.clear();
    if (first == arcs.end()) return false;
    int cur = first->first;
    for (std::size_t step = 0; step < arcs.size(); ++step) {
      out.polygon.push_back(cur);
      const auto it = std::find_if(arcs.begin(), arcs.end(), [&](const auto& a) { return a.first == cur; });
      if (it == arcs.end()) return false;
      cur = it->second;
    }
    out.polygon.push_back(cur);
    std::vector<int> sorted = out.polygon;
    std::sort(sorted.begin(), sorted.end());
    return std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
  }

  // v may go as a boundary vertex (QualityPassOptions::boundary_removable):
  // its pieces a -> v -> b, its open star from b to a with two triangles or
  // more, and a, v, b exactly collinear. Fills lk with the star.
  bool boundary_link(int v, Link& lk) {
    if (options_.boundary_removable.empty() || !options_.boundary_removable[std::size_t(v)]) return false;
    const int e_in = boundary_.into(v), e_out = boundary_.from(v);
    if (e_in < 0 || e_out < 0) return false;
    const int a = boundary_.edge(e_in)[0], b = boundary_.edge(e_out)[1];
    if (!open_link(v, lk) || lk.star.size() < 2 || lk.polygon.front() != b || lk.polygon.back() != a) return false;
    return orient2d(pts_[std::size_t(a)], pts_[std::size_t(v)], pts_[std::size_t(b)]) == Sign::Zero;
  }

  // Min angle of the star of v with v at p; -1 when a triangle is not strictly CCW.
  double star_quality(const std::vector<int>& polygon, Vec2 p) const {
    double m = 4;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const Vec2 a = pts_[std::size_t(polygon[i])], b = pts_[std::size_t(polygon[(i + 1) % polygon.size()])];
      if (!ccw(p, a, b)) return -1;
      m = std::min(m, min_angle(p, a, b));
    }
    return m;
  }

  // Compass search for the position of v maximising its star's min angle.
  double best_position(const std::vector<int>& polygon, int v, Vec2& best) const {
    best = pts_[std::size_t(v)];
    double f = star_quality(polygon, best);
    Vec2 c{0, 0};
    for (int w : polygon) c = c + pts_[std::size_t(w)];
    c = (1.0 / double(polygon.size())) * c;
    if (const double fc = star_quality(polygon, c); fc > f) {
      f = fc;
      best = c;
    }
    double h = 1e300;
    for (int w : polygon) h = std::min(h, norm(pts_[std::size_t(w)] - best));
    h *= 0.25;
    int evals = 2;
    while (evals + 8 <= options_.move_evaluations) {
      Vec2 step_best = best;
      double step_f = f;
      for (int k = 0; k < 8; ++k) {
        const double a = std::numbers::pi * k / 4;
        const Vec2 p = best + h * Vec2{std::cos(a), std::sin(a)};
        if (const double fp = star_quality(polygon, p); fp > step_f) {
          step_f = fp;
          step_best = p;
        }
      }
      evals += 8;
      if (step_f > f) {
        f = step_f;
        best = step_best;
      } else {
        h *= 0.5;
      }
    }
    return f;
  }

  // The triangle across the edge a -> b of a live triangle (b -> a in it), or -1.
  int across(int a, int b) {
    for (int u : star(a)) {
      const auto& ut = tri_[std::size_t(u)];
      for (int r = 0; r < 3; ++r)
        if (ut[std::size_t(r)] == b && ut[std::size_t((r + 1) % 3)] == a) return u;
    }
    return -1;
  }

  // The first `size` triangles reached from t across edges (breadth first, edges in triangle order).
  std::vector<int> grow(int t, std::size_t size) {
    std::vector<int> region = {t};
    std::vector<char>& seen = seen_;
    seen.resize(tri_.size(), 0);
    seen[std::size_t(t)] = 1;
    for (std::size_t head = 0; head < region.size() && region.size() < size; ++head) {
      const auto tr = tri_[std::size_t(region[head])];
      for (int e = 0; e < 3 && region.size() < size; ++e) {
        const int u = across(tr[std::size_t(e)], tr[std::size_t((e + 1) % 3)]);
        if (u >= 0 && !seen[std::size_t(u)]) {
          seen[std::size_t(u)] = 1;
          region.push_back(u);
        }
      }
    }
    for (int r : region) seen[std::size_t(r)] = 0;
    return region;
  }

  // Stuck at t: remove the Steiner vertices of the `size` triangles around t
  // (in the order reached) whose star polygon has a triangulation with every
  // angle above `floor` (the mesh's smallest angle), so that the next single
  // changes at t have room. Returns the number removed.
  std::int64_t coarsen(int t, std::size_t size, double floor) {
    std::vector<int> verts;
    for (int r : grow(t, size))
      for (int v : tri_[std::size_t(r)])
        if (v >= first_steiner_) verts.push_back(v);
    std::vector<int> order;  // first occurrence order
    std::sort(verts.begin(), verts.end());
    verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
    for (int r : grow(t, size))
      for (int v : tri_[std::size_t(r)])
        if (v >= first_steiner_) {
          const auto it = std::lower_bound(verts.begin(), verts.end(), v);
          if (it != verts.end() && *it == v) {
            order.push_back(v);
            verts.erase(it);
          }
        }
    return remove_above(order, floor);
  }

  bool targeted() const { return options_.target >= 0; }

  // The smallest angle of the live triangles `set`.
  double smallest(const std::vector<int>& set) const {
    double m = 4;
    for (int t : set) m = std::min(m, angle_[std::size_t(t)]);
    return m;
  }

  // The floor a change replacing the triangles `set` must stay above: the
  // mesh's smallest angle `global` without a target, else min(target, the
  // set's smallest angle) (QualityPassOptions::target).
  double floor_for(const std::vector<int>& set, double global) const {
    return targeted() ? std::min(options_.target, smallest(set)) : global;
  }

  // Removes, in the given order, each Steiner vertex whose star polygon has a
  // triangulation with every angle above floor_for(star, floor), inner ones
  // and boundary_removable ones (boundary_link); returns the number removed.
  std::int64_t remove_above(const std::vector<int>& verts, double floor) {
    std::int64_t removed = 0;
    Link lk;
    std::vector<Vec2> q;
    std::vector<std::array<int, 3>> tris;
    for (int v : verts) {
      const bool inner = link(v, lk);
      if ((!inner && !boundary_link(v, lk)) || int(lk.star.size()) > options_.max_star) continue;
      q.clear();
      for (int w : lk.polygon) q.push_back(pts_[std::size_t(w)]);
      const double f = floor_for(lk.star, floor);
      if (best_triangulation(q, f, tris, dp_) <= f) continue;
      const int marker = marker_[std::size_t(lk.star.front())];
      for (int s : lk.star) alive_[std::size_t(s)] = 0;
      for (const auto& x : tris)
        add({lk.polygon[std::size_t(x[0])], lk.polygon[std::size_t(x[1])], lk.polygon[std::size_t(x[2])]}, marker);
      if (!inner) boundary_.merge_at(v);  // the polygon's side a -> b is the merged piece
      ++removed;
    }
    return removed;
  }

  // Moves v to p: its star's triangles are replaced by the same ones at p.
  void move_vertex(int v, const Link& lk, Vec2 p) {
    std::vector<int> markers;
    for (int s : lk.star) {
      alive_[std::size_t(s)] = 0;
      markers.push_back(marker_[std::size_t(s)]);
    }
    pts_[std::size_t(v)] = p;
    for (std::size_t i = 0; i < lk.star.size(); ++i) add(tri_[std::size_t(lk.star[i])], markers[i]);
  }

  // One smoothing sweep: each vertex of `verts` still in the mesh whose star's
  // smallest angle is below smoothing_below, in order, goes to the best
  // position of its star when that raises the star's smallest angle
  // (strictly). Returns the number of moves.
  std::int64_t smooth(const std::vector<int>& verts) {
    std::int64_t moves = 0;
    Link lk;
    for (int v : verts) {
      if (!link(v, lk)) continue;
      const double before = smallest(lk.star);
      if (before >= options_.smoothing_below) continue;
      Vec2 p;
      if (best_position(lk.polygon, v, p) > before) {
        move_vertex(v, lk, p);
        ++moves;
      }
    }
    return moves;
  }

  // The border of a set of live triangles: its boundary edges, oriented as in
  // their triangle (region order, then edge order; an edge is on the border
  // when the triangle across it is missing or outside the set), and every
  // vertex of the set, sorted and unique.
  struct RegionBorder {
    std::vector<std::array<int, 2>> edges;
    std::vector<int> vertices;
  };
  RegionBorder border_of(const std::vector<int>& region) {
    RegionBorder border;
    std::vector<char>& in = seen_;
    in.resize(tri_.size(), 0);
    for (int r : region) in[std::size_t(r)] = 1;
    for (int r : region) {
      const auto tr = tri_[std::size_t(r)];
      for (int e = 0; e < 3; ++e) {
        const int a = tr[std::size_t(e)], b = tr[std::size_t((e + 1) % 3)];
        border.vertices.push_back(a);
        const int u = across(a, b);
        if (u < 0 || !in[std::size_t(u)]) border.edges.push_back({a, b});
      }
    }
    for (int r : region) in[std::size_t(r)] = 0;
    std::sort(border.vertices.begin(), border.vertices.end());
    border.vertices.erase(std::unique(border.vertices.begin(), border.vertices.end()), border.vertices.end());
    return border;
  }

  // Stuck at t after coarsening: empty the first 4, 8, 16, ... triangles
  // around t (breadth first, any topology) of their inner vertices and
  // re-triangulate by the CDT of the boundary (cavity_cdt.hpp); the first
  // whose smallest new angle exceeds t's is applied. The last candidate is the
  // whole mesh, whose re-triangulation is the CDT of P (its boundary edges are
  // the input segments, its inner vertices all the Steiner points), so the pass
  // never stops below the CDT's min angle. Returns false when none helps.
  bool large_cavity(int t) {
    const double base = angle_[std::size_t(t)];
    for (std::size_t size = 4;; size *= 2) {
      const std::vector<int> region = grow(t, size);
      const RegionBorder border = border_of(region);
      std::vector<int> on_boundary;
      for (const auto& [a, b] : border.edges) {
        on_boundary.push_back(a);
        on_boundary.push_back(b);
      }
      std::sort(on_boundary.begin(), on_boundary.end());
      on_boundary.erase(std::unique(on_boundary.begin(), on_boundary.end()), on_boundary.end());
      bool inputs_on_boundary = true;  // an input vertex is on dP, never inside a cavity (checked)
      for (int v : border.vertices)
        if (v < first_steiner_ && !std::binary_search(on_boundary.begin(), on_boundary.end(), v))
          inputs_on_boundary = false;
      if (inputs_on_boundary) {
        const std::vector<std::array<int, 3>> tris =
            retriangulate_cavity(pts_, border.edges, region.size(), border.vertices.size() - on_boundary.size());
        double f = tris.empty() ? -1 : 4;
        for (const auto& x : tris)
          f = std::min(f, min_angle(pts_[std::size_t(x[0])], pts_[std::size_t(x[1])], pts_[std::size_t(x[2])]));
        if (f > base) {
          const int marker = marker_[std::size_t(t)];
          for (int r : region) alive_[std::size_t(r)] = 0;
          for (const auto& x : tris) add(x, marker);
          return true;
        }
      }
      if (region.size() < size) return false;  // the whole mesh was the last candidate
    }
  }

  // The first `size` triangles reached from t (grow). When they form a disk
  // (one simple boundary cycle, Euler characteristic 1) whose inner vertices
  // are all Steiner vertices, returns the largest min angle of a
  // triangulation of that cycle (no inner vertex: they are removed) and it in
  // `tris` when above floor (best_triangulation); else a value <= floor.
  double cavity(int t, std::size_t size, double floor, std::vector<int>& region,
                std::vector<std::array<int, 3>>& tris) {
    region = grow(t, size);
    if (region.size() < size) return -1;
    const RegionBorder border = border_of(region);
    const std::vector<std::array<int, 2>>& boundary = border.edges;
    const std::vector<int>& vertices = border.vertices;
    const std::int64_t edges = (3 * std::int64_t(region.size()) + std::int64_t(boundary.size())) / 2;
    if (std::int64_t(vertices.size()) - edges + std::int64_t(region.size()) != 1) return -1;
    std::vector<int> cycle;
    int cur = boundary[0][0];
    for (std::size_t k = 0; k < boundary.size(); ++k) {
      cycle.push_back(cur);
      int next = -1, outs = 0;
      for (const auto& [a, b] : boundary)
        if (a == cur) {
          next = b;
          ++outs;
        }
      if (outs != 1) return -1;
      cur = next;
    }
    if (cur != cycle.front()) return -1;
    std::vector<int> sorted = cycle;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return -1;
    for (int v : vertices)  // inner vertices are removed: Steiner ones only
      if (!std::binary_search(sorted.begin(), sorted.end(), v) && v < first_steiner_) return -1;
    if (cycle.size() > std::size_t(options_.max_star)) return -1;
    std::vector<Vec2> q;
    for (int v : cycle) q.push_back(pts_[std::size_t(v)]);
    std::vector<std::array<int, 3>> local;
    const double f = best_triangulation(q, floor, local, dp_);
    tris.clear();
    for (const auto& x : local)
      tris.push_back({cycle[std::size_t(x[0])], cycle[std::size_t(x[1])], cycle[std::size_t(x[2])]});
    return f;
  }

  // One change at the worst triangle t; false when none raises its angle.
  bool improve(int t, QualityPassStats& st) {
    const double base = angle_[std::size_t(t)];
    const auto tr = tri_[std::size_t(t)];
    enum class Kind { None, Flip, Remove, Move, Cavity } kind = Kind::None;
    double value = base;
    int flip_edge = -1, flip_other = -1, flip_apex = -1, vertex = -1;
    std::vector<std::array<int, 3>> removal;
    Vec2 moved{};
    Link lk;
    for (int e = 0; e < 3; ++e) {  // flips
      const int a = tr[std::size_t(e)], b = tr[std::size_t((e + 1) % 3)], c = tr[std::size_t((e + 2) % 3)];
      for (int u : star(a)) {
        if (u == t) continue;
        const auto& ut = tri_[std::size_t(u)];
        const int r = ut[0] == b ? 0 : ut[1] == b ? 1 : ut[2] == b ? 2 : -1;
        if (r < 0 || ut[std::size_t((r + 1) % 3)] != a) continue;  // u = (b, a, d)
        const int d = ut[std::size_t((r + 2) % 3)];
        const Vec2 pa = pts_[std::size_t(a)], pb = pts_[std::size_t(b)], pc = pts_[std::size_t(c)],
                   pd = pts_[std::size_t(d)];
        if (!ccw(pa, pd, pc) || !ccw(pb, pc, pd)) break;
        const double v = std::min(min_angle(pa, pd, pc), min_angle(pb, pc, pd));
        if (v > value) {
          value = v;
          kind = Kind::Flip;
          flip_edge = e;
          flip_other = u;
          flip_apex = d;
        }
        break;
      }
    }
    for (int v : tr) {  // removals
      if (!options_.coarsen || v < first_steiner_ || !link(v, lk) || int(lk.star.size()) > options_.max_star) continue;
      std::vector<Vec2> q;
      for (int w : lk.polygon) q.push_back(pts_[std::size_t(w)]);
      std::vector<std::array<int, 3>> tris;
      const double f = best_triangulation(q, value, tris, dp_);
      if (f > value) {
        value = f;
        kind = Kind::Remove;
        vertex = v;
        removal.clear();
        for (const auto& x : tris)
          removal.push_back({lk.polygon[std::size_t(x[0])], lk.polygon[std::size_t(x[1])],
                             lk.polygon[std::size_t(x[2])]});
      }
    }
    for (int v : tr) {  // moves
      if (v < first_steiner_ || !link(v, lk)) continue;
      Vec2 p;
      const double f = best_position(lk.polygon, v, p);
      if (f > value) {
        value = f;
        kind = Kind::Move;
        vertex = v;
        moved = p;
      }
    }
    std::vector<int> region;
    if (kind == Kind::None && !targeted()) {  // stuck for single changes: empty a small disk of triangles around t
      for (std::size_t size = 4; size <= 64; size *= 2) {
        std::vector<int> r;
        std::vector<std::array<int, 3>> tris;
        const double f = cavity(t, size, value, r, tris);
        if (f > value) {
          value = f;
          kind = Kind::Cavity;
          region = std::move(r);
          removal = std::move(tris);
        }
      }
    }
    const int marker = marker_[std::size_t(t)];
    switch (kind) {
      case Kind::None: return false;
      case Kind::Cavity: {
        for (int s : region) alive_[std::size_t(s)] = 0;
        for (const auto& x : removal) add(x, marker);
        ++st.cavities;
        return true;
      }
      case Kind::Flip: {
        const int a = tr[std::size_t(flip_edge)], b = tr[std::size_t((flip_edge + 1) % 3)],
                  c = tr[std::size_t((flip_edge + 2) % 3)];
        const int other_marker = marker_[std::size_t(flip_other)];
        alive_[std::size_t(t)] = alive_[std::size_t(flip_other)] = 0;
        add({a, flip_apex, c}, marker);
        add({b, c, flip_apex}, other_marker);
        ++st.flips;
        return true;
      }
      case Kind::Remove: {
        const bool ok = link(vertex, lk);
        (void)ok;
        for (int s : lk.star) alive_[std::size_t(s)] = 0;
        for (const auto& x : removal) add(x, marker);
        ++st.removals;
        return true;
      }
      case Kind::Move: {
        link(vertex, lk);
        move_vertex(vertex, lk, moved);
        ++st.moves;
        return true;
      }
    }
    return false;
  }

  // Live triangles back into the mesh; unused Steiner vertices dropped.
  void write_back() {
    std::vector<int> id(pts_.size(), -1);
    for (std::size_t v = 0; v < std::size_t(first_steiner_) && v < pts_.size(); ++v) id[v] = 0;
    for (std::size_t t = 0; t < tri_.size(); ++t)
      if (alive_[t])
        for (int v : tri_[t]) id[std::size_t(v)] = 0;
    std::vector<Vec2> vertices;
    std::vector<int> vertex_markers;
    for (std::size_t v = 0; v < pts_.size(); ++v) {
      if (id[v] < 0) continue;
      id[v] = int(vertices.size());
      vertices.push_back(pts_[v]);
      if (!mesh_.vertex_markers.empty()) vertex_markers.push_back(mesh_.vertex_markers[v]);
    }
    mesh_.triangles.clear();
    mesh_.triangle_markers.clear();
    for (std::size_t t = 0; t < tri_.size(); ++t) {
      if (!alive_[t]) continue;
      const auto& x = tri_[t];
      mesh_.triangles.push_back({id[std::size_t(x[0])], id[std::size_t(x[1])], id[std::size_t(x[2])]});
      mesh_.triangle_markers.push_back(marker_[t]);
    }
    mesh_.vertices = std::move(vertices);
    if (!mesh_.vertex_markers.empty()) mesh_.vertex_markers = std::move(vertex_markers);
    boundary_.write_back(id, mesh_);  // the vertices of live pieces are on live triangles
  }

  TriMesh2& mesh_;
  std::vector<Vec2>& pts_;
  int first_steiner_;
  QualityPassOptions options_;
  std::vector<std::array<int, 3>> tri_;
  std::vector<int> marker_;
  std::vector<char> alive_;
  std::vector<double> angle_;
  std::vector<std::vector<int>> inc_;
  std::vector<char> seen_;  // scratch of grow(), all 0 between calls
  DpTables dp_;             // scratch of best_triangulation
  std::vector<std::pair<int, int>> arcs_;  // scratch of link()
  BoundaryEdges boundary_;
  std::priority_queue<std::pair<double, int>, std::vector<std::pair<double, int>>, std::greater<>> heap_;
};

}  // namespace

QualityPassStats improve_min_angle(TriMesh2& mesh, int first_steiner, const QualityPassOptions& options) {
  return Pass(mesh, first_steiner, options).run();
}

}  // namespace pqmesh::detail
