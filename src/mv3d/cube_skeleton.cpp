// Steps 3-6 of the cube_components.cpp outline: sheets, the skeleton K of
// ∂C_e, tethers and the walks along K (cube_skeleton.hpp).
#include "mv3d/cube_skeleton.hpp"

#include <algorithm>
#include <array>
#include <deque>
#include <numeric>
#include <utility>

#include "mv3d/cube_sheets.hpp"
#include "mv3d/perturbed.hpp"
#include "mv3d/shifted_cube.hpp"
#include "pqmesh/errors.hpp"

namespace pqmesh::mv3d::detail {

namespace {

struct Event {
  Pos pos;
  int node = -1;      // union-find element
  bool crossing = false;
  bool entering = false;
};

// A line of K with its range [lo, hi] along d and the union-find nodes at its
// two ends.
struct KLine {
  Line line;
  int start = -1, end = -1;
  std::vector<Event> nodes;  // junctions and tether exits strictly inside the range
};

// Walk a K line from its start node with the given status (true: in P),
// joining consecutive events across pieces in P. Records the status of every
// non-crossing node in node_in_p. `triangles` are the local triangles with
// their global ids (the crossings inside the range are with them).
void walk(const Domain3& dom, const Cube& c, KLine& kl, bool status, const std::vector<int>& triangles, UnionFind& uf,
          std::vector<signed char>& node_in_p) {
  const Pos lo = plane_pos(c, kl.line.d, 0), hi = plane_pos(c, kl.line.d, 1);
  std::vector<Event> ev = std::move(kl.nodes);
  // Room for every crossing up front (one allocation per walk).
  ev.reserve(ev.size() + triangles.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const auto& tri = dom.facet_triangles[static_cast<std::size_t>(triangles[i])];
    Event e;
    if (!line_hit(kl.line, dom.plc.vertices[static_cast<std::size_t>(tri[0])], dom.plc.vertices[static_cast<std::size_t>(tri[1])],
                  dom.plc.vertices[static_cast<std::size_t>(tri[2])], e.pos, e.entering))
      continue;
    const int rl = compare(e.pos, lo), rh = compare(e.pos, hi);
    if (rl == 0 || rh == 0) throw InternalError("mv3d: a triangle meets a K line at its end");
    if (rl < 0 || rh > 0) continue;
    e.node = static_cast<int>(i);
    e.crossing = true;
    ev.push_back(std::move(e));
  }
  std::vector<std::size_t> order(ev.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    const int r = compare(ev[i].pos, ev[j].pos);
    if (r != 0) return r < 0;
    return i < j;
  });
  int prev = kl.start;
  node_in_p[static_cast<std::size_t>(kl.start)] = status ? 1 : 0;
  for (const std::size_t i : order) {
    const Event& e = ev[i];
    if (status) uf.unite(prev, e.node);
    if (e.crossing) {
      if (e.entering == status) throw InternalError("mv3d: crossings along a line do not alternate");
      status = e.entering;
    } else {
      node_in_p[static_cast<std::size_t>(e.node)] = status ? 1 : 0;
    }
    prev = e.node;
  }
  if (status) uf.unite(prev, kl.end);
  const signed char end_status = status ? 1 : 0;
  if (node_in_p[static_cast<std::size_t>(kl.end)] >= 0 && node_in_p[static_cast<std::size_t>(kl.end)] != end_status)
    throw InternalError("mv3d: two walks disagree on the status of a node");
  node_in_p[static_cast<std::size_t>(kl.end)] = end_status;
}

// Where a tether ray ends (Skeleton::shoot).
struct Shot {
  int triangle = -1;       // local index of the first triangle crossed, or -1
  bool entering = false;   // the ray enters P there
  int exit_node = -1;      // otherwise the exit node
};

// The state shared by steps 3-6: union-find elements 0..m-1 are the local
// triangles, the K nodes follow; node_in_p holds every element's status
// (-1 unknown, 0 out of P, 1 in P; only K nodes get one).
struct Skeleton {
  const Domain3& domain;
  const Cube& cube;
  const std::vector<int>& tris;
  std::size_t m;
  UnionFind uf;
  std::vector<int> sheet;              // local triangle -> root of its sheet
  std::vector<signed char> node_in_p;
  std::array<int, 8> corner{};
  std::array<KLine, 12> edges;
  // A deque: appending never moves the earlier probes (their lines stay put
  // while later probes are added).
  std::deque<KLine> probes;
  std::vector<int> tether_exits;  // K nodes where a tether leaves C; they must lie in P

  Skeleton(const Domain3& d, const Cube& c, const std::vector<int>& t) : domain(d), cube(c), tris(t), m(t.size()) {}

  // A new K node (union-find element) of unknown status.
  int add_node() {
    node_in_p.push_back(-1);
    return uf.add();
  }

  // Step 3: sheets. Union-find elements 0..m-1 are the local triangles.
  void join_triangle_sheets() {
    for (std::size_t i = 0; i < m; ++i) uf.add();
    join_sheets(domain, cube, tris, uf);
    sheet.resize(m);
    for (std::size_t i = 0; i < m; ++i) sheet[i] = uf.find(static_cast<int>(i));
    node_in_p.assign(m, -1);
  }

  // Nodes of K: the 8 corners; the 12 cube edges run between them.
  void add_cube_edges() {
    for (int& k : corner) k = add_node();
    for (int e = 0; e < 12; ++e) {
      edges[static_cast<std::size_t>(e)].line = cube_edge_line(cube, e);
      edges[static_cast<std::size_t>(e)].start = corner[static_cast<std::size_t>(edge_corner(e, 0))];
      edges[static_cast<std::size_t>(e)].end = corner[static_cast<std::size_t>(edge_corner(e, 1))];
    }
  }

  // A probe on the face (axis a, side), direction d = (a + 1) % 3, fixed
  // coordinate `fc` on axis c = (a + 2) % 3; its ends are junctions on the
  // cube edges along c with a at `side` and d at 0 / 1. Returns its index.
  std::size_t add_probe(int a, int side, Pos fc) {
    const int d = (a + 1) % 3, c = (a + 2) % 3;
    KLine kl;
    kl.line = make_line(d, std::move(fc), plane_pos(cube, a, side));  // f1 on (d+1)%3 = c, f2 on (d+2)%3 = a
    kl.start = add_node();
    kl.end = add_node();
    for (int s = 0; s < 2; ++s) {
      Event j;
      j.pos = kl.line.f1;
      j.node = s == 0 ? kl.start : kl.end;
      edges[static_cast<std::size_t>(c * 4 + side * 2 + s)].nodes.push_back(std::move(j));
    }
    probes.push_back(std::move(kl));
    return probes.size() - 1;
  }

  // Step 4: a probe through (an offset -d of) every point where a triangle
  // side crosses a face of C_e.
  void add_side_probes() {
    std::vector<std::array<int, 2>> sides;
    for (const int t : tris) {
      const auto& tri = domain.facet_triangles[static_cast<std::size_t>(t)];
      for (int j = 0; j < 3; ++j) {
        const int v = tri[static_cast<std::size_t>(j)], w = tri[static_cast<std::size_t>((j + 1) % 3)];
        sides.push_back({std::min(v, w), std::max(v, w)});
      }
    }
    std::sort(sides.begin(), sides.end());
    sides.erase(std::unique(sides.begin(), sides.end()), sides.end());
    // One crossing buffer for all sides and faces: segment_crosses_face
    // assigns the wanted coordinate whenever it returns true, so nothing of
    // an earlier crossing survives (rationals made once, not per side and face).
    Pert w;
    for (const auto& s : sides) {
      const Vec3 u = domain.plc.vertices[static_cast<std::size_t>(s[0])], v = domain.plc.vertices[static_cast<std::size_t>(s[1])];
      if (vertex_inside(u, cube) && vertex_inside(v, cube)) continue;
      for (int a = 0; a < 3; ++a)
        for (int side = 0; side < 2; ++side) {
          if (!segment_crosses_face(u, v, cube, a, side, &w)) continue;
          Pert fc = w;
          fc.c[detail::kD1] -= 1;
          add_probe(a, side, Pos::of_pert(std::move(fc)));
        }
    }
  }

  // Step 5: shoot(v) follows the ray {(v.x + t, v.y + d, v.z + d^2) : t > 0}
  // to the first triangle it crosses inside C_e (sheet `skip` excluded), or
  // else to its exit point on the face x = xhi + e, a node on the probe along
  // y at z = v.z + d^2 of that face (added here).
  // The start is on no triangle unless v is on ∂P: a hit at t = 0 would put
  // (v.x, v.y + d, v.z + d^2) inside a triangle, hence v on it.
  Shot shoot(Vec3 v, int skip) {
    const Line ray = make_line(0, Pos::of_double(v.y, detail::kD1, 1), Pos::of_double(v.z, detail::kD2, 1));
    const Pos xmax = plane_pos(cube, 0, 1), start = Pos::of_double(v.x);
    Shot shot;
    Pos best_pos;
    for (std::size_t i = 0; i < m; ++i) {
      if (sheet[i] == skip) continue;
      const auto& tri = domain.facet_triangles[static_cast<std::size_t>(tris[i])];
      Pos pos;
      bool entering = false;
      if (!line_hit(ray, domain.plc.vertices[static_cast<std::size_t>(tri[0])], domain.plc.vertices[static_cast<std::size_t>(tri[1])],
                    domain.plc.vertices[static_cast<std::size_t>(tri[2])], pos, entering))
        continue;
      const int s = compare(start, pos);  // sign(v.x - pos)
      if (s == 0) throw InternalError("mv3d: a ray starts on the boundary of P");
      if (s > 0 || compare(pos, xmax) >= 0) continue;
      if (shot.triangle < 0 || compare(pos, best_pos) < 0) {
        shot.triangle = static_cast<int>(i);
        shot.entering = entering;
        best_pos = std::move(pos);
      }
    }
    if (shot.triangle >= 0) return shot;
    const std::size_t p = add_probe(0, 1, Pos::of_double(v.z, detail::kD2, 1));
    Event exit_node;
    exit_node.pos = Pos::of_double(v.y, detail::kD1, 1);
    exit_node.node = add_node();
    shot.exit_node = exit_node.node;
    probes[p].nodes.push_back(std::move(exit_node));
    return shot;
  }

  // Step 5: (sheet root, largest vertex) of every floater, a sheet with all
  // its vertices in C and not on the exterior shell, by increasing root.
  std::vector<std::pair<std::size_t, int>> floaters() const {
    std::vector<char> exterior_facet(domain.plc.facets.size(), 0);
    if (!domain.shells.empty())
      for (const int f : domain.shells[0].facets) exterior_facet[static_cast<std::size_t>(f)] = 1;
    std::vector<char> rimless(m, 1), is_exterior(m, 0);
    std::vector<std::array<double, 3>> top(m, {0, 0, 0});
    std::vector<int> top_vertex(m, -1);
    for (std::size_t i = 0; i < m; ++i) {
      const auto& tri = domain.facet_triangles[static_cast<std::size_t>(tris[i])];
      const auto r = static_cast<std::size_t>(sheet[i]);
      if (exterior_facet[static_cast<std::size_t>(domain.facet_triangle_owner[static_cast<std::size_t>(tris[i])])]) is_exterior[r] = 1;
      for (const int v : tri) {
        const Vec3 p = domain.plc.vertices[static_cast<std::size_t>(v)];
        if (!vertex_inside(p, cube)) rimless[r] = 0;
        const std::array<double, 3> key{p.x, p.y, p.z};
        if (top_vertex[r] < 0 || key > top[r]) {
          top[r] = key;
          top_vertex[r] = v;
        }
      }
    }
    std::vector<std::pair<std::size_t, int>> out;
    for (std::size_t r = 0; r < m; ++r) {
      if (sheet[r] != static_cast<int>(r) || !rimless[r] || is_exterior[r]) continue;
      out.push_back({r, top_vertex[r]});
    }
    return out;
  }

  // Step 5: joins every floater to where its tether ends (a triangle, or an
  // exit node recorded in tether_exits).
  void tether_floaters() {
    for (const auto& [r, top_vertex] : floaters()) {
      const Shot shot = shoot(domain.plc.vertices[static_cast<std::size_t>(top_vertex)], static_cast<int>(r));
      if (shot.triangle >= 0) uf.unite(static_cast<int>(r), shot.triangle);
      else {
        uf.unite(static_cast<int>(r), shot.exit_node);
        tether_exits.push_back(shot.exit_node);
      }
    }
  }

  // Step 6: walk the cube edges, then the probes (status from their start
  // junction). Corner 0's status is given (hint); an edge starting at a
  // corner with j sides at 1 is walked after the edges reaching that corner
  // (those starting at corners with j - 1 sides at 1), so every walk starts
  // at a corner of known status.
  void walk_skeleton(bool corner0_in) {
    node_in_p[static_cast<std::size_t>(corner[0])] = corner0_in ? 1 : 0;
    for (int ones = 0; ones < 3; ++ones)
      for (int e = 0; e < 12; ++e) {
        if ((e / 2) % 2 + e % 2 != ones) continue;
        KLine& kl = edges[static_cast<std::size_t>(e)];
        const signed char s = node_in_p[static_cast<std::size_t>(kl.start)];
        if (s < 0) throw InternalError("mv3d: a cube edge starts at a corner of unknown status");
        walk(domain, cube, kl, s == 1, tris, uf, node_in_p);
      }
    for (KLine& kl : probes) {
      const signed char s = node_in_p[static_cast<std::size_t>(kl.start)];
      if (s < 0) throw InternalError("mv3d: a probe starts at an unvisited junction");
      walk(domain, cube, kl, s == 1, tris, uf, node_in_p);
    }
    for (const int n : tether_exits)
      if (node_in_p[static_cast<std::size_t>(n)] != 1) throw InternalError("mv3d: a tether leaves P");
  }

  // Components: classes holding a triangle or a K node in P, numbered in
  // element order. Fills comp_of_root (per root) and comp_of (per local
  // triangle); returns their count.
  int number_components(std::vector<int>& comp_of_root, std::vector<int>& comp_of) {
    comp_of_root.assign(uf.p.size(), -1);
    comp_of.resize(m);
    int count = 0;
    for (std::size_t i = 0; i < m; ++i) {
      int& k = comp_of_root[static_cast<std::size_t>(uf.find(static_cast<int>(i)))];
      if (k < 0) k = count++;
      comp_of[i] = k;
    }
    for (std::size_t n = m; n < uf.p.size(); ++n) {
      if (node_in_p[n] != 1) continue;
      int& k = comp_of_root[static_cast<std::size_t>(uf.find(static_cast<int>(n)))];
      if (k < 0) k = count++;
    }
    return count;
  }

  // The component of each marked point from its shot, or -1 outside P.
  void locate_marks(const std::vector<Shot>& mark_shots, const std::vector<int>& comp_of_root,
                    const std::vector<int>& comp_of, CubeComponents& out) {
    for (const Shot& shot : mark_shots) {
      int k = -1;
      if (shot.triangle >= 0) {
        // Just before the hit the ray is in P iff it leaves P there.
        if (!shot.entering) k = comp_of[static_cast<std::size_t>(shot.triangle)];
      } else if (node_in_p[static_cast<std::size_t>(shot.exit_node)] == 1) {
        k = comp_of_root[static_cast<std::size_t>(uf.find(shot.exit_node))];
      }
      out.mark_component.push_back(k);
    }
  }
};

}  // namespace

void components_by_skeleton(const Domain3& domain, const Cube& cube, const std::vector<int>& tris, bool corner0_in,
                            std::span<const Vec3> marks, CubeComponents& out) {
  Skeleton k(domain, cube, tris);
  k.join_triangle_sheets();
  k.add_cube_edges();
  k.add_side_probes();
  k.tether_floaters();
  // Marked points: the same ray from each (located by locate_marks).
  std::vector<Shot> mark_shots;
  for (const Vec3 p : marks) mark_shots.push_back(k.shoot(p, -1));
  k.walk_skeleton(corner0_in);
  std::vector<int> comp_of_root, comp_of;
  out.components.resize(static_cast<std::size_t>(k.number_components(comp_of_root, comp_of)));
  fill_faces(domain, cube, tris, comp_of, out);
  k.locate_marks(mark_shots, comp_of_root, comp_of, out);
}

}  // namespace pqmesh::mv3d::detail
