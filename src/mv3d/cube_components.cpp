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
#include <iterator>
#include <numeric>

#include "mv3d/cube_sheets.hpp"
#include "mv3d/cube_skeleton.hpp"
#include "mv3d/perturbed.hpp"
#include "mv3d/shifted_cube.hpp"
#include "pqmesh/errors.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::mv3d {

using namespace detail;  // Pert and the shifted-cube geometry (shifted_cube.hpp)

namespace {

std::vector<int> facet_vertex_list(const Domain3& dom, int f) {
  std::vector<int> vs;
  for (const auto& loop : dom.plc.facets[static_cast<std::size_t>(f)].loops) vs.insert(vs.end(), loop.begin(), loop.end());
  std::sort(vs.begin(), vs.end());
  return vs;
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


// Step 1: the facet triangles meeting C_e, sorted (the hint's candidates as
// they are when exact).
std::vector<int> triangles_of_hint(const Domain3& domain, const Cube& cube, const CubeHint& hint) {
  std::vector<int> tris;
  if (hint.candidates_exact) tris.assign(hint.candidates.begin(), hint.candidates.end());
  else tris = triangles_meeting(domain, cube, hint.candidates);
  return tris;
}

// No P face meets C_e: C_e lies in int P or in its exterior, as its corner 0
// does (one whole-cube component or none).
void no_face_components(bool corner0_in, std::span<const Vec3> marks, CubeComponents& out) {
  const bool in = corner0_in;
  if (in) {
    out.components.emplace_back();
    out.components.back().whole_cube = true;
  }
  out.mark_component.assign(marks.size(), in ? 0 : -1);
}

// Step 2, the fast path (single_cone holds): one component holding every
// triangle meeting C_e.
void fast_path_components(const Domain3& domain, const Cube& cube, const std::vector<int>& tris, bool corner0_in,
                          std::span<const Vec3> marks, CubeComponents& out) {
  out.fast_path = true;
  out.components.emplace_back();
  fill_faces(domain, cube, tris, std::vector<int>(tris.size(), 0), out);
  // A mark p (off ∂P) is located by the walk from corner 0 to
  // p' = (p.x + d, p.y + d^2, p.z) inside C_e: the legs' fixed coordinates
  // carry distinct infinitesimals, and p' lies on a triangle only if p does.
  const PPoint c0 = corner_point(cube, 0);
  for (const Vec3 p : marks) {
    const PPoint to{Pos::of_double(p.x, detail::kD1, 1), Pos::of_double(p.y, detail::kD2, 1), Pos::of_double(p.z)};
    out.mark_component.push_back(walk_status(domain, tris, c0, corner0_in, to) ? 0 : -1);
  }
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
  const std::vector<int> tris = triangles_of_hint(domain, cube, hint);
  if (tris.empty()) {
    no_face_components(hint.corner0_in, marks, out);
    return out;
  }
  if (allow_fast_path && single_cone(domain, cube, tris)) {
    fast_path_components(domain, cube, tris, hint.corner0_in, marks, out);
    return out;
  }
  components_by_skeleton(domain, cube, tris, hint.corner0_in, marks, out);
  return out;
}

}  // namespace pqmesh::mv3d
