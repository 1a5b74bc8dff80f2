// The validity checker for triangle meshes (docs/algorithm/quality.md "The
// validity checker").
//
// The 2D analogue of check3d.cpp, whose comment block gives the argument in
// full; here one dimension lower:
//
// Stage 2: orient2d(a, b, c) > 0 for every triangle (mesh.hpp's convention).
//
// Stage 3: edges (sorted vertex pairs) are collected by a counting sort on the
//   smaller vertex. An edge lies on one or two triangles, and two triangles
//   sharing it traverse it in opposite directions (they lie on opposite sides).
//   With T the sum of the triangles as oriented 2-chains and B the edges on one
//   triangle, directed with the triangle on their left, this gives dT = B. B
//   must be a union of closed curves through distinct vertices: every vertex
//   of B has exactly one outgoing and one incoming edge of B. A vertex lying on
//   an edge of B other than its ends (a hanging vertex) is searched for from
//   the edge's ends along edges of B.
//
// Stage 4 (with the domain: loops with the interior on their left):
//   (a) every input segment is walked from its first to its second vertex
//       along mesh edges, each step to the unique neighbour on the segment
//       strictly closer to the end (orient2d = 0, dot_sign < 0); failure is
//       MissingEdge. Interior segments, if a domain has them, are walked the
//       same way.
//   (b) B, as signed counts of undirected mesh edges, must equal the loops
//       with every side replaced by its chain from (a).
//
// Sufficiency: by (b) B = dP as 1-chains (a combinatorial equality implies the
// geometric one), so T - P is a 2-chain without boundary, hence zero: with all
// triangles positive, almost every point of P is covered exactly once and no
// point outside P is covered. As in 3D this also excludes hanging vertices
// (a vertex in the relative interior of an edge s: if s is interior, the two
// triangles on s cover a neighbourhood of the vertex that its own triangles
// cover too; if s is on dP, s is a union of chain pieces from (a), and the
// vertex would be on the boundary twice), every input vertex is found by exact
// coordinates and every input segment is a chain of mesh edges by (a).
// Without a domain only stages 1-3 run (local conditions).
//
// The stages live in check2d_topology.cpp (1-3) and check2d_domain.cpp (4);
// check2d_stages.hpp holds their shared state.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesh/check2d_stages.hpp"
#include "mesh/check_common.hpp"
#include "mesh/radix_sort.hpp"
#include "geometry/large_page_allocator.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"

namespace pqmesh {
namespace detail::check2d {

namespace {

// The vertex ids sorted by (x, y), ties by id: exactly sort_by_coordinates
// (check_common.hpp), computed by a stable radix sort (radix_sort.hpp) on the
// order keys, y first, then x, which is linear in the vertex count. Every
// coordinate is finite (stage 1 passed).
std::vector<int> vertex_order(const std::vector<Vec2>& pts) {
  struct Item {
    std::uint64_t kx, ky;
    int id;
  };
  std::vector<Item> v(pts.size()), scratch;
  for (std::size_t i = 0; i < pts.size(); ++i)
    v[i] = {ordered_key(pts[i].x), ordered_key(pts[i].y), static_cast<int>(i)};
  radix_sort_by_key(v, scratch, [](const Item& it) { return it.ky; });
  radix_sort_by_key(v, scratch, [](const Item& it) { return it.kx; });
  std::vector<int> order(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) order[i] = v[i].id;
  return order;
}

// Whether two vertices have exactly the same coordinates: one pass over an
// open-addressing table of vertex ids (linear probing, at most half full),
// comparing coordinates exactly on every probe. Linear in the vertex count
// and much cheaper than the coordinate sort, which is only needed to report
// the coincident groups when there are some.
bool has_coincident_vertices(const std::vector<Vec2>& pts) {
  std::size_t size = 16;
  while (size < 2 * pts.size()) size *= 2;
  const std::size_t mask = size - 1;
  std::vector<int, LargePageAllocator<int>> table(size, -1);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Vec2 p = pts[i];
    for (std::size_t s = coordinate_hash(p) & mask;; s = (s + 1) & mask) {
      const int id = table[s];
      if (id < 0) {
        table[s] = static_cast<int>(i);
        break;
      }
      if (pts[static_cast<std::size_t>(id)] == p) return true;
    }
  }
  return false;
}

}  // namespace

Checker2::Checker2(const TriMesh2& mesh, const CheckOptions& options, CheckReport& report)
    : m_(mesh), opt_(options), rep_(report), sink_(report, options.max_issues_per_kind) {
  rep_.dimension = 2;
  rep_.vertices = static_cast<std::int64_t>(mesh.vertices.size());
  rep_.elements = static_cast<std::int64_t>(mesh.triangles.size());
}

bool Checker2::run_topology() {
  stage1_ok_ = stage1_indices();
  if (!stage1_ok_) {
    sink_.note("orientation, conformity and domain checks skipped: the mesh has bad indices or coordinates");
    return false;
  }
  coincident_ = has_coincident_vertices(m_.vertices);
  if (coincident_) order_ = vertex_order(m_.vertices);
  if (!stage2_orientation()) {
    sink_.note("conformity and domain checks skipped: not every triangle is positively oriented");
    return false;
  }
  const bool ok = stage3_edges();
  if (!ok) sink_.note("domain checks of boundary edges and segments skipped: the triangles do not meet edge to edge");
  return ok;
}

void Checker2::run_domain(const Domain2& d, bool topology_ok) {
  rep_.domain_checked = true;
  rep_.domain_volume = d.area;
  if (!stage1_ok_) return;
  map_input_vertices(d);
  if (topology_ok) {
    walk_segments(d);
    check_boundary_chain(d);
    if (opt_.no_boundary_steiner) check_steiner();
  }
  if (rep_.volume_measured) compare_volume(sink_, "area", rep_.mesh_volume, d.area, opt_.volume_tolerance);
  if (opt_.locate_vertices) check_located(d);
}

}  // namespace detail::check2d

CheckReport check_mesh_topology(const TriMesh2& mesh, const CheckOptions& options) {
  return detail::run_topology_check<detail::check2d::Checker2>(mesh, options);
}

CheckReport check_mesh(const TriMesh2& mesh, const Domain2& domain, const CheckOptions& options) {
  return detail::run_full_check<detail::check2d::Checker2>(mesh, domain, options);
}

}  // namespace pqmesh
