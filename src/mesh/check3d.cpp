// The validity checker for tetrahedral meshes (docs/algorithm/quality.md "The
// validity checker").
//
// ---------------------------------------------------------------------------
// What is checked, and why it is enough
// ---------------------------------------------------------------------------
// Every decision below is an exact predicate on the input doubles
// (src/predicates) or an integer comparison; the one exception is the Volume
// measurement, which is reported as a measurement.
//
// Stage 2: orient3d(a, b, c, d) > 0 for every tetrahedron (mesh.hpp's
//   convention). Zero is DegenerateElement, negative is Orientation.
//
// Stage 3: the faces (sorted vertex triples) are collected by a counting sort
//   on their smallest vertex and a small sort inside each bucket. A face lies
//   on one or two tetrahedra; two tetrahedra sharing it must traverse it with
//   opposite orientation (with positive volumes this says they lie on opposite
//   sides). Writing T for the sum of the tetrahedra as oriented 3-chains and B
//   for the faces on one tetrahedron, each oriented outward (right-hand normal
//   out of the mesh), stage 3 therefore gives dT = B. B must be a closed
//   2-manifold: every edge of B on exactly two of its triangles, once in each
//   direction. A vertex lying on a triangle of B (a hanging vertex: the
//   elements there do not meet face to face) is searched for directly from the
//   triangle's corners along edges of B, which finds every vertex of a
//   subdivision of that triangle on the other side.
//
// Stage 4 (with the domain P, facets oriented outward):
//   (a) every triangle of B is assigned to a facet f: its vertices lie in f's
//       plane, exactly or as faithful roundings (f's plane meets the box of
//       neighbouring doubles of the vertex, within_ulp_of_plane;
//       docs/algorithm/quality.md "The validity checker"), within f's bounding
//       box, and, only when several coplanar facets qualify, in the closed
//       facet polygon (exact crossing test in the projection that drops the
//       dominant axis of f's normal; a vertex within an ulp of a loop side is
//       on it). Its orientation must agree with f's (exact, in the same
//       projection). A vertex farther than an ulp from every facet plane makes
//       its triangles fail here.
//   (b) every input edge (DomainEdge) is walked from its first to its second
//       vertex along edges of B, each step to the unique B-neighbour lying on
//       the edge, exactly or within an ulp (within_ulp_of_segment), strictly
//       closer to the end (dot_sign < 0). Failure is MissingEdge.
//   (c) for every facet f, the boundary of B_f (the triangles assigned to f)
//       is computed combinatorially as signed counts of undirected mesh edges,
//       and compared with the boundary of f: its loops, each side replaced by
//       the chain of mesh edges found in (b). They must be equal.
//
// Sufficiency. A combinatorial equality of 1-chains implies the geometric one,
// so by (c) B_f - f is a 2-chain in the plane of f without boundary, hence
// zero: B_f = f. Summing over facets, B = dP, and T - P is a 3-chain without
// boundary, hence zero. Since every tetrahedron is positive, the number of
// tetrahedra containing a point x (the winding number of T) is 1 for almost
// every x in P and 0 outside. So the tetrahedra cover P without overlaps or
// gaps; the total volume is vol(P) up to rounding; no vertex used by a
// tetrahedron lies outside P. They also meet face to face: if a vertex v lay
// in the relative interior of a face or an edge s of a tetrahedron, v not a
// vertex of s, then where s meets the interior of P the tetrahedra around s
// close up (the faces containing s are matched, since B lies in dP) and cover
// a neighbourhood of v that the tetrahedra with vertex v also cover, i.e. some
// point twice; where s lies in dP the same happens one dimension lower among
// the boundary triangles, which tile each facet exactly once (B_f = f with
// every triangle oriented like f). Finally every input vertex is found by
// exact coordinates, every input edge is a chain of mesh edges by (b), and
// every facet is a union of boundary triangles by (c).
// With rounded vertices, the argument holds for the mesh whose rounded
// vertices are replaced by the exact points of P's facets and edges they
// stand for; the stored mesh differs from it by under an ulp per coordinate
// at those vertices (docs/algorithm/quality.md "The validity checker"). Such
// vertices are on dP by (a) and are not passed to locate() (a rounding may lie
// an ulp outside P).
//
// Without a domain (check_mesh_topology) only stages 1-3 run. They are local:
// a mesh that covers a region twice (winding number 2) can pass them.
//
// Redundant second opinions: the Volume measurement (relative tolerance, both
// numbers reported) and locate() on every vertex (VertexOutside).
//
// Known conservative case: if two coplanar facets share a boundary and a
// triangle has all three vertices in both closed facets, it is assigned to the
// lower-numbered one; were it geometrically in the other, (c) reports a
// MissingFacet. The checker never accepts an invalid mesh for this reason.
//
// The stages live in check3d_topology.cpp (1-3), check3d_domain.cpp and
// check3d_facets.cpp (4); check3d_stages.hpp holds their shared state.
#include <cstdint>

#include "mesh/check3d_stages.hpp"
#include "mesh/check_common.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"

namespace pqmesh {
namespace detail::check3d {

Checker3::Checker3(const TetMesh3& mesh, const CheckOptions& options, CheckReport& report)
    : m_(mesh), opt_(options), rep_(report), sink_(report, options.max_issues_per_kind) {
  rep_.dimension = 3;
  rep_.vertices = static_cast<std::int64_t>(mesh.vertices.size());
  rep_.elements = static_cast<std::int64_t>(mesh.tetrahedra.size());
}

bool Checker3::run_topology() {
  stage1_ok_ = stage1_indices();
  if (!stage1_ok_) {
    sink_.note("orientation, conformity and domain checks skipped: the mesh has bad indices or coordinates");
    return false;
  }
  order_ = sort_by_coordinates(m_.vertices);
  if (!stage2_orientation()) {
    sink_.note("conformity and domain checks skipped: not every tetrahedron is positively oriented");
    return false;
  }
  measure_volume();
  const bool ok = stage3_faces();
  if (!ok) sink_.note("domain checks of boundary faces, edges and facets skipped: the tetrahedra do not meet face to face");
  return ok;
}

void Checker3::run_domain(const Domain3& d, bool topology_ok) {
  rep_.domain_checked = true;
  rep_.domain_volume = d.volume;
  if (!stage1_ok_) return;
  map_input_vertices(d);
  if (topology_ok) {
    prepare_facets(d);
    assign_boundary_faces(d);
    walk_edges(d);
    check_facets(d);
    if (opt_.no_boundary_steiner) check_steiner();
  }
  if (rep_.volume_measured) compare_volume(sink_, "volume", rep_.mesh_volume, d.volume, opt_.volume_tolerance);
  if (opt_.locate_vertices) check_located(d);
}

}  // namespace detail::check3d

CheckReport check_mesh_topology(const TetMesh3& mesh, const CheckOptions& options) {
  return detail::run_topology_check<detail::check3d::Checker3>(mesh, options);
}

CheckReport check_mesh(const TetMesh3& mesh, const Domain3& domain, const CheckOptions& options) {
  return detail::run_full_check<detail::check3d::Checker3>(mesh, domain, options);
}

}  // namespace pqmesh
