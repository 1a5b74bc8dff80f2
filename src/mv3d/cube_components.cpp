// Components of P ∩ C (thesis §4.1.6 in 3D). See cube_components.hpp for the
// outward shift C -> C_e. Outline:
//   1. the facet triangles meeting C_e (exact: a vertex in C, a triangle side
//      crossing a face of C_e, or an edge of C_e crossing the triangle);
//   2. fast path: the facets meeting C form one cone whose apex meets C
//      (single_cone below) -> P ∩ C is connected, one component;
//   3. sheets: a triangle meets C_e in a convex piece; two pieces share a
//      point iff the triangles share a vertex in C or a side meeting C_e (the
//      facet triangles of a valid domain meet only in common sides and
//      vertices), so union-find over those gives the sheets (components of
//      ∂P ∩ C);
//   4. the cube surface: the skeleton K of ∂C_e is the 12 edges of C_e plus
//      "probe lines", axis-parallel segments across a face: one through (an
//      infinitesimal offset of) every point where a triangle side crosses the
//      face, and one through every tether exit (step 5). K is connected
//      (every probe ends on two cube edges) and every rim (closed curve of
//      ∂P ∩ ∂C_e) crosses K: either it crosses a cube edge or it lies inside
//      one face, where the probe through its topmost vertex crosses it. Each
//      K line is walked in order of its crossings with the triangles; the
//      pieces of K between consecutive events (crossings, junctions, tether
//      exits) that lie in P join the events' union-find classes. Why this
//      suffices: the regions of ∂C_e \ rims form a tree (∂C_e is a sphere);
//      take any region f in P and a rim r of f not separating f from a fixed
//      base point; a path in K from a crossing of r to the base leaves f for
//      the last time through f's parent rim, and every excursion out of f
//      returns through the rim it left by, so the pieces of the path inside
//      f chain r to the parent rim. Hence all rims of f, i.e. all sheets
//      bounding f, end in one class. Conversely every union is along a
//      connected subset of P ∩ C_e. The outer frontier of a component of
//      P ∩ C_e is connected (R^3 is unicoherent), so sheets meeting ∂C_e and
//      regions of ∂C_e are joined exactly when they lie in one component;
//   5. a sheet not meeting ∂C_e is a whole shell inside C; a floater among
//      them is joined along its tether (§4.1.6): the ray in +x from its
//      largest vertex v (lexicographic x, y, z), offset to (y + d, z + d^2),
//      to the first triangle hit inside C_e, or else to its exit point on the
//      face x = xhi + e, which is a node on a probe line. The tether lies in
//      P (points just right of v are outside the floater's cavity). The
//      exterior shell inside C needs nothing (its component is P);
//   6. status along a line: corner 0 of C_e is given (CubeHint: walked from
//      an enclosing box's corner 0 by the caller, or by parity from -infinity
//      over every triangle in the from-scratch overload); each cube edge
//      starts at a corner reached by an earlier edge walk, so every corner is
//      located exactly; a probe line starts at a junction on a cube edge whose
//      status is known from that edge's walk.
// Genericity (why no event position ties and no predicate is zero): a K line
// has two fixed coordinates; one carries e^k of a shifted plane, the other
// e^j (cube edges), the offset -d (side-crossing probes) or d^2 (tether
// probes), so the line lies in no triangle plane and passes through no
// triangle side (the orient2d of a side with the perturbed point has a
// non-zero coefficient: see line_hit). The code checks these facts and
// throws InternalError if one fails (it would mean an invalid domain).
#include "mv3d/cube_components.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <iterator>
#include <numeric>

#include "mv3d/perturbed.hpp"
#include "mv3d/shifted_cube.hpp"
#include "pqmesh/errors.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::mv3d {

using namespace detail;  // Pert and the shifted-cube geometry (shifted_cube.hpp)

namespace {

struct UnionFind {
  std::vector<int> p;
  int add() {
    p.push_back(static_cast<int>(p.size()));
    return p.back();
  }
  int find(int x) {
    while (p[static_cast<std::size_t>(x)] != x) x = p[static_cast<std::size_t>(x)] = p[static_cast<std::size_t>(p[static_cast<std::size_t>(x)])];
    return x;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) p[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
  }
};

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

std::vector<int> facet_vertex_list(const Domain3& dom, int f) {
  std::vector<int> vs;
  for (const auto& loop : dom.plc.facets[static_cast<std::size_t>(f)].loops) vs.insert(vs.end(), loop.begin(), loop.end());
  std::sort(vs.begin(), vs.end());
  return vs;
}

int edge_index(const Domain3& dom, int a, int b) {
  if (a > b) std::swap(a, b);
  const auto it = std::lower_bound(dom.edges.begin(), dom.edges.end(), std::pair{a, b},
                                   [](const DomainEdge& e, const std::pair<int, int>& k) { return std::pair{e.a, e.b} < k; });
  if (it != dom.edges.end() && it->a == a && it->b == b) return static_cast<int>(it - dom.edges.begin());
  return -1;
}

// Fills the face lists of every component from the local triangle -> component map.
void fill_faces(const Domain3& dom, const Cube& c, std::span<const int> tris, const std::vector<int>& comp_of,
                CubeComponents& out) {
  std::vector<std::pair<std::array<int, 2>, int>> sides;
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const int t = tris[i], k = comp_of[i];
    out.triangle_component.push_back({t, k});
    ComponentFaces3& f = out.components[static_cast<std::size_t>(k)];
    f.facets.push_back(dom.facet_triangle_owner[static_cast<std::size_t>(t)]);
    const auto& tri = dom.facet_triangles[static_cast<std::size_t>(t)];
    for (int j = 0; j < 3; ++j) {
      const int v = tri[static_cast<std::size_t>(j)], w = tri[static_cast<std::size_t>((j + 1) % 3)];
      if (vertex_inside(dom.plc.vertices[static_cast<std::size_t>(v)], c)) f.vertices.push_back(v);
      sides.push_back({{std::min(v, w), std::max(v, w)}, k});
    }
  }
  std::sort(sides.begin(), sides.end());
  sides.erase(std::unique(sides.begin(), sides.end()), sides.end());
  for (const auto& [s, k] : sides) {
    const int e = edge_index(dom, s[0], s[1]);
    if (e < 0) continue;
    if (!segment_meets(dom.plc.vertices[static_cast<std::size_t>(s[0])], dom.plc.vertices[static_cast<std::size_t>(s[1])], c))
      continue;
    out.components[static_cast<std::size_t>(k)].edges.push_back(e);
  }
  for (ComponentFaces3& f : out.components) {
    for (auto* v : {&f.vertices, &f.edges, &f.facets}) {
      std::sort(v->begin(), v->end());
      v->erase(std::unique(v->begin(), v->end()), v->end());
    }
  }
  std::sort(out.triangle_component.begin(), out.triangle_component.end());
}

// Step 3: joins the local triangles (union-find elements 0..m-1) of every
// sheet, a component of ∂P ∩ C: two triangles' pieces in C_e share a point iff
// they share a vertex in C or a side meeting C_e (cube_components.cpp outline).
void join_sheets(const Domain3& domain, const Cube& cube, std::span<const int> tris, UnionFind& uf) {
  const std::size_t m = tris.size();
  std::vector<std::pair<int, int>> at_vertex;                   // (vertex in C, local triangle)
  std::vector<std::pair<std::array<int, 2>, int>> at_side;      // (side, local triangle), sides with no vertex in C
  for (std::size_t i = 0; i < m; ++i) {
    const auto& tri = domain.facet_triangles[static_cast<std::size_t>(tris[i])];
    for (int j = 0; j < 3; ++j) {
      const int v = tri[static_cast<std::size_t>(j)], w = tri[static_cast<std::size_t>((j + 1) % 3)];
      const bool vin = vertex_inside(domain.plc.vertices[static_cast<std::size_t>(v)], cube);
      const bool win = vertex_inside(domain.plc.vertices[static_cast<std::size_t>(w)], cube);
      if (vin) at_vertex.push_back({v, static_cast<int>(i)});
      if (!vin && !win) at_side.push_back({{std::min(v, w), std::max(v, w)}, static_cast<int>(i)});
    }
  }
  std::sort(at_vertex.begin(), at_vertex.end());
  for (std::size_t k = 1; k < at_vertex.size(); ++k)
    if (at_vertex[k].first == at_vertex[k - 1].first) uf.unite(at_vertex[k].second, at_vertex[k - 1].second);
  std::sort(at_side.begin(), at_side.end());
  for (std::size_t k = 1; k < at_side.size(); ++k) {
    if (at_side[k].first != at_side[k - 1].first) continue;
    const auto& s = at_side[k].first;
    if (segment_meets(domain.plc.vertices[static_cast<std::size_t>(s[0])], domain.plc.vertices[static_cast<std::size_t>(s[1])], cube))
      uf.unite(at_side[k].second, at_side[k - 1].second);
  }
}

// Step 2: a vertex in C common to every facet meeting C, or -1.
int common_apex(const Domain3& dom, const Cube& c, const std::vector<int>& tris) {
  std::vector<int> facets;
  for (const int t : tris) facets.push_back(dom.facet_triangle_owner[static_cast<std::size_t>(t)]);
  std::sort(facets.begin(), facets.end());
  facets.erase(std::unique(facets.begin(), facets.end()), facets.end());
  std::vector<int> common = facet_vertex_list(dom, facets[0]);
  std::erase_if(common, [&](int v) { return !vertex_inside(dom.plc.vertices[static_cast<std::size_t>(v)], c); });
  for (std::size_t i = 1; i < facets.size() && !common.empty(); ++i) {
    const std::vector<int> vs = facet_vertex_list(dom, facets[i]);
    std::erase_if(common, [&](int v) { return !std::binary_search(vs.begin(), vs.end(), v); });
  }
  return common.empty() ? -1 : common[0];
}

// The star-shaped rule (the fast path of components()): the facets meeting C_e form one
// cone whose apex meets C, so P ∩ C is connected:
//   * a vertex v in C common to every facet meeting C (a vertex cone; P ∩ C
//     is star-shaped from v);
//   * no vertex in C, exactly one P edge meets C_e and every facet meeting
//     C_e is one of its two facets (an edge cone): the edge crosses C_e in a
//     chord, each facet meets C_e in the half of its plane on one side of the
//     chord (its other edges miss C_e), and the two half-planes split C_e
//     into two connected regions, one of them P ∩ C_e;
//   * no vertex in C, no P edge meets C_e and one facet meets it: the facet
//     meets C_e in its whole plane section, so P ∩ C_e is convex.
bool single_cone(const Domain3& dom, const Cube& c, const std::vector<int>& tris) {
  if (common_apex(dom, c, tris) >= 0) return true;
  std::vector<std::array<int, 2>> sides;
  for (const int t : tris)
    for (int j = 0; j < 3; ++j) {
      const auto& tri = dom.facet_triangles[static_cast<std::size_t>(t)];
      const int v = tri[static_cast<std::size_t>(j)], w = tri[static_cast<std::size_t>((j + 1) % 3)];
      if (vertex_inside(dom.plc.vertices[static_cast<std::size_t>(v)], c)) return false;
      sides.push_back({std::min(v, w), std::max(v, w)});
    }
  std::sort(sides.begin(), sides.end());
  sides.erase(std::unique(sides.begin(), sides.end()), sides.end());
  int edge = -1;
  for (const auto& s : sides) {
    const int e = edge_index(dom, s[0], s[1]);
    if (e < 0 || !segment_meets(dom.plc.vertices[static_cast<std::size_t>(s[0])], dom.plc.vertices[static_cast<std::size_t>(s[1])], c))
      continue;
    if (edge >= 0) return false;
    edge = e;
  }
  if (edge >= 0) {
    const DomainEdge& de = dom.edges[static_cast<std::size_t>(edge)];
    for (const int t : tris) {
      const int f = dom.facet_triangle_owner[static_cast<std::size_t>(t)];
      if (f != de.facets[0] && f != de.facets[1]) return false;
    }
    return true;
  }
  const int f0 = dom.facet_triangle_owner[static_cast<std::size_t>(tris[0])];
  for (const int t : tris)
    if (dom.facet_triangle_owner[static_cast<std::size_t>(t)] != f0) return false;
  return true;
}

}  // namespace

std::vector<int> triangles_meeting(const Domain3& domain, const Cube& cube, std::span<const int> candidates,
                                   std::span<const int> known) {
  EdgeLines edge_lines(cube);
  std::vector<int> out;
  for (const int t : candidates)
    if ((!known.empty() && std::binary_search(known.begin(), known.end(), t)) ||
        triangle_meets(domain, t, cube, edge_lines))
      out.push_back(t);
  // Candidate lists handed down the tree are sorted and unique already.
  if (!std::is_sorted(out.begin(), out.end())) std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<int> triangles_meeting(const Domain3& domain, const Cube& cube) {
  std::vector<int> all(domain.facet_triangles.size());
  std::iota(all.begin(), all.end(), 0);
  return triangles_meeting(domain, cube, all);
}

bool corner0_in(const Domain3& domain, const Cube& cube) {
  // From -infinity along x to corner 0, by parity over every triangle.
  const Line l = make_line(0, plane_pos(cube, 1, 0), plane_pos(cube, 2, 0));
  const Pos lo = plane_pos(cube, 0, 0);
  bool status = false;
  for (const auto& tri : domain.facet_triangles) {
    Pos pos;
    bool entering = false;
    if (!line_hit(l, domain.plc.vertices[static_cast<std::size_t>(tri[0])], domain.plc.vertices[static_cast<std::size_t>(tri[1])],
                  domain.plc.vertices[static_cast<std::size_t>(tri[2])], pos, entering))
      continue;
    const int r = compare(pos, lo);
    if (r == 0) throw InternalError("mv3d: a triangle passes through a corner of a shifted cube");
    if (r < 0) status = !status;
  }
  return status;
}

bool corner0_in_from(const Domain3& domain, const Cube& inner, const Cube& outer, bool outer_corner0_in,
                     std::span<const int> outer_tris) {
  return walk_status(domain, outer_tris, corner_point(outer, 0), outer_corner0_in, corner_point(inner, 0));
}

bool corner0_in_walk(const Domain3& domain, const Cube& to, const Cube& from, bool from_corner0_in,
                     std::span<const int> tris) {
  return walk_status(domain, tris, corner_point(from, 0), from_corner0_in, corner_point(to, 0));
}

FaceBounds face_bounds(const Domain3& domain, const Cube& cube, std::span<const int> tris, int t) {
  const auto it = std::lower_bound(tris.begin(), tris.end(), t);
  if (it == tris.end() || *it != t) throw InternalError("mv3d: face_bounds' triangle does not meet the box");
  const std::size_t m = tris.size();
  UnionFind uf;
  for (std::size_t i = 0; i < m; ++i) uf.add();
  join_sheets(domain, cube, tris, uf);
  // Two groups: 0 = t's sheet, 1 = every other triangle.
  const int root = uf.find(static_cast<int>(it - tris.begin()));
  std::vector<int> group(m);
  for (std::size_t i = 0; i < m; ++i) group[i] = uf.find(static_cast<int>(i)) == root ? 0 : 1;
  CubeComponents cc;
  cc.components.resize(2);
  fill_faces(domain, cube, tris, group, cc);
  FaceBounds out;
  out.sheet = std::move(cc.components[0]);
  const ComponentFaces3& rest = cc.components[1];
  const auto merge = [](const std::vector<int>& a, const std::vector<int>& b, std::vector<int>& to) {
    std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(to));
  };
  merge(out.sheet.vertices, rest.vertices, out.all.vertices);
  merge(out.sheet.edges, rest.edges, out.all.edges);
  merge(out.sheet.facets, rest.facets, out.all.facets);
  return out;
}

CubeComponents components(const Domain3& domain, const Cube& cube, bool allow_fast_path, std::span<const Vec3> marks) {
  std::vector<int> all(domain.facet_triangles.size());
  std::iota(all.begin(), all.end(), 0);
  const std::vector<int> tris = triangles_meeting(domain, cube, all);
  return components(domain, cube, CubeHint{tris, true, corner0_in(domain, cube)}, allow_fast_path, marks);
}

CubeComponents components(const Domain3& domain, const Cube& cube, const CubeHint& hint, bool allow_fast_path,
                          std::span<const Vec3> marks) {
  CubeComponents out;
  out.cube = cube;
  std::vector<int> tris;
  if (hint.candidates_exact) tris.assign(hint.candidates.begin(), hint.candidates.end());
  else tris = triangles_meeting(domain, cube, hint.candidates);
  if (tris.empty()) {
    // No P face meets C_e: C_e lies in int P or in its exterior, as its
    // corner 0 does.
    const bool in = hint.corner0_in;
    if (in) {
      out.components.emplace_back();
      out.components.back().whole_cube = true;
    }
    out.mark_component.assign(marks.size(), in ? 0 : -1);
    return out;
  }
  const std::size_t m = tris.size();
  if (allow_fast_path && single_cone(domain, cube, tris)) {
    out.fast_path = true;
    out.components.emplace_back();
    fill_faces(domain, cube, tris, std::vector<int>(m, 0), out);
    // A mark p (off ∂P) is located by the walk from corner 0 to
    // p' = (p.x + d, p.y + d^2, p.z) inside C_e: the legs' fixed coordinates
    // carry distinct infinitesimals, and p' lies on a triangle only if p does.
    const PPoint c0 = corner_point(cube, 0);
    for (const Vec3 p : marks) {
      const PPoint to{Pos::of_double(p.x, detail::kD1, 1), Pos::of_double(p.y, detail::kD2, 1), Pos::of_double(p.z)};
      out.mark_component.push_back(walk_status(domain, tris, c0, hint.corner0_in, to) ? 0 : -1);
    }
    return out;
  }

  // Step 3: sheets. Union-find elements 0..m-1 are the local triangles.
  UnionFind uf;
  for (std::size_t i = 0; i < m; ++i) uf.add();
  join_sheets(domain, cube, tris, uf);
  std::vector<int> sheet(m);
  for (std::size_t i = 0; i < m; ++i) sheet[i] = uf.find(static_cast<int>(i));

  // Nodes of K: the 8 corners.
  std::vector<signed char> node_in_p(m, -1);
  const auto add_node = [&] {
    node_in_p.push_back(-1);
    return uf.add();
  };
  std::array<int, 8> corner{};
  for (int& k : corner) k = add_node();
  std::array<KLine, 12> edges;
  for (int e = 0; e < 12; ++e) {
    edges[static_cast<std::size_t>(e)].line = cube_edge_line(cube, e);
    edges[static_cast<std::size_t>(e)].start = corner[static_cast<std::size_t>(edge_corner(e, 0))];
    edges[static_cast<std::size_t>(e)].end = corner[static_cast<std::size_t>(edge_corner(e, 1))];
  }
  // A deque: appending never moves the earlier probes (their lines stay put
  // while later probes are added).
  std::deque<KLine> probes;
  // A probe on the face (axis a, side), direction d = (a + 1) % 3, fixed
  // coordinate `fc` on axis c = (a + 2) % 3; its ends are junctions on the
  // cube edges along c with a at `side` and d at 0 / 1.
  const auto add_probe = [&](int a, int side, Pos fc) {
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
  };
  {
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

  // Step 5: tethers of floaters lying inside C. shoot(v) follows the ray
  // {(v.x + t, v.y + d, v.z + d^2) : t > 0} to the first triangle it crosses
  // inside C_e (sheet `skip` excluded), or else to its exit point on the face
  // x = xhi + e, a node on the probe along y at z = v.z + d^2 of that face.
  // The start is on no triangle unless v is on ∂P: a hit at t = 0 would put
  // (v.x, v.y + d, v.z + d^2) inside a triangle, hence v on it.
  struct Shot {
    int triangle = -1;       // local index of the first triangle crossed, or -1
    bool entering = false;   // the ray enters P there
    int exit_node = -1;      // otherwise the exit node
  };
  const auto shoot = [&](Vec3 v, int skip) {
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
  };
  std::vector<int> tether_exits;  // K nodes where a tether leaves C; they must lie in P
  {
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
    for (std::size_t r = 0; r < m; ++r) {
      if (sheet[r] != static_cast<int>(r) || !rimless[r] || is_exterior[r]) continue;
      const Shot shot = shoot(domain.plc.vertices[static_cast<std::size_t>(top_vertex[r])], static_cast<int>(r));
      if (shot.triangle >= 0) uf.unite(static_cast<int>(r), shot.triangle);
      else {
        uf.unite(static_cast<int>(r), shot.exit_node);
        tether_exits.push_back(shot.exit_node);
      }
    }
  }
  // Marked points: the same ray from each (mark_component, below).
  std::vector<Shot> mark_shots;
  for (const Vec3 p : marks) mark_shots.push_back(shoot(p, -1));

  // Step 6: walk the cube edges, then the probes (status from their start
  // junction). Corner 0's status is given (hint); an edge starting at a
  // corner with j sides at 1 is walked after the edges reaching that corner
  // (those starting at corners with j - 1 sides at 1), so every walk starts
  // at a corner of known status.
  node_in_p[static_cast<std::size_t>(corner[0])] = hint.corner0_in ? 1 : 0;
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

  // Components: classes holding a triangle or a K node in P.
  std::vector<int> comp_of_root(uf.p.size(), -1);
  std::vector<int> comp_of(m);
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
  out.components.resize(static_cast<std::size_t>(count));
  fill_faces(domain, cube, tris, comp_of, out);
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
  return out;
}

}  // namespace pqmesh::mv3d
