#pragma once
// The mesh validity checker (docs/algorithm/quality.md "The validity checker").
// Every test and benchmark runs it on every mesh, so its decisions are exact
// (src/predicates) and its running time is linear up to sorting (one sort of
// the element faces, bucketed by vertex).
//
// What "valid" means, and why the checks below are sufficient, is argued in the
// comment block at the top of src/mesh/check3d.cpp (2D: src/mesh/check2d.cpp).
// In short, with a domain: every element is positively oriented; every face
// (edge in 2D) lies on one or two elements, and two elements sharing it lie on
// opposite sides; the faces on one element, as an oriented chain, equal the
// domain boundary subdivided at mesh vertices (an exact, combinatorial
// comparison). Together these imply that the elements tile the domain exactly
// once and meet face to face, and that every input vertex, edge and facet is
// recovered. The total volume is also measured and compared (a measurement with
// a relative tolerance, reported as such).
//
// Stages. A later stage relies on the invariants an earlier one established, so
// it is skipped (and a note says so) when the earlier one found problems:
//   1. indices and coordinates (BadIndex);
//   2. element orientation (Orientation, DegenerateElement);
//   3. face matching, hanging vertices, manifold boundary (NonConforming,
//      UnusedVertex, BoundaryFace), listed boundary faces (BoundaryFace);
//   4. against the domain: boundary faces on facets, input edges and facets
//      recovered, Steiner points on the boundary (BoundaryFace, MissingEdge,
//      MissingFacet, SteinerOnBoundary).
// Vertex-level checks (MissingVertex, VertexOutside) run whenever stage 1
// passed; Volume runs whenever stage 2 passed.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/mesh.hpp"

namespace pqmesh {

// The meaning of CheckIssue::ids for each kind ("element" = triangle in 2D,
// tetrahedron in 3D; "face" = edge in 2D, triangle in 3D; vertex ids are mesh
// vertex ids unless said otherwise):
enum class CheckKind : int {
  BadIndex,           // malformed mesh: an index out of range, a non-finite coordinate, a
                      // marker array of the wrong size. ids: the element / listed face / vertex.
  DegenerateElement,  // element of exactly zero volume (area). ids: {element}
  Orientation,        // element of negative volume (area). ids: {element}
  NonConforming,      // elements that do not meet face to face. ids by message:
                      //   face on more than two elements: the elements;
                      //   two elements on the same side of their common face: {e1, e2};
                      //   hanging vertex: {vertex, face vertices...};
                      //   two mesh vertices with the same coordinates: the vertices.
  UnusedVertex,       // a mesh vertex on no element. ids: {vertex}
  BoundaryFace,       // the faces on one element: not a closed manifold ({face vertices} of the
                      // offending boundary edge (3D) / {vertex} (2D)); not on the domain
                      // boundary or oriented inward ({face vertices}); a listed boundary
                      // face (TetMesh3::faces, TriMesh2::edges) that is not one ({listed
                      // index}) or a boundary face missing from a non-empty list ({face vertices}).
  Volume,             // total volume (area) differs from the domain's beyond the relative
                      // tolerance. A floating-point measurement, not an exact decision. ids: {}
  MissingVertex,      // an input vertex that is no mesh vertex. ids: {input vertex}
  MissingEdge,        // an input edge that is not a chain of mesh edges.
                      // ids: 3D {input vertex a, input vertex b}; 2D {input segment}
  MissingFacet,       // an input facet that is not exactly the union of the boundary
                      // triangles on it. ids: {input facet}
  VertexOutside,      // a mesh vertex outside the domain (locate()). ids: {vertex}
  SteinerOnBoundary,  // only with CheckOptions::no_boundary_steiner: a mesh vertex on the
                      // domain boundary that is not an input vertex. ids: {vertex}
};
inline constexpr int kCheckKindCount = 12;

// Stable lower-case name ("bad-index", "orientation", ...), used in reports.
const char* to_string(CheckKind kind);

struct CheckIssue {
  CheckKind kind = CheckKind::BadIndex;
  std::vector<std::int64_t> ids;
  std::string message;
};

struct CheckOptions {
  // Flag mesh vertices on the domain boundary that are not input vertices
  // (the no-boundary-Steiner triangulator's guarantee, thesis ch. 5).
  bool no_boundary_steiner = false;
  // Issues stored per kind; count_per_kind still counts all of them.
  std::size_t max_issues_per_kind = 20;
  // Run the domain's exact locate() on every mesh vertex. The exact stages
  // already imply that no vertex is outside when they pass (see check3d.cpp);
  // this is an independent second opinion that costs one locate() per vertex.
  bool locate_vertices = true;
  // Relative tolerance of the Volume measurement (the only non-exact check).
  double volume_tolerance = 1e-9;
};

struct CheckReport {
  int dimension = 0;
  std::int64_t vertices = 0;
  std::int64_t elements = 0;
  std::int64_t boundary_faces = 0;  // faces on exactly one element (when stage 3 ran)
  bool domain_checked = false;      // false for check_mesh_topology
  bool volume_measured = false;
  double mesh_volume = 0;           // sum of element volumes (areas in 2D), when measured
  double domain_volume = 0;
  std::vector<CheckIssue> issues;   // in stage order, at most max_issues_per_kind per kind
  std::vector<std::int64_t> count_per_kind = std::vector<std::int64_t>(kCheckKindCount, 0);
  std::vector<std::string> notes;   // stages skipped and why, other remarks

  bool valid() const;
  std::int64_t count(CheckKind kind) const { return count_per_kind[static_cast<int>(kind)]; }
  // The kinds with a nonzero count, in enum order.
  std::vector<CheckKind> kinds() const;
  // "valid: 6 tetrahedra, 8 vertices, 12 boundary triangles; volume 1 (domain 1)"
  // or "invalid: ..." followed by one line per stored issue and the notes.
  std::string to_text() const;
};

// Full check against the validated input domain (as make_domain returns it).
// Mesh problems are reported, never thrown; a Domain2/Domain3 that is itself
// inconsistent (a loop side that is no input segment, a facet side missing
// from Domain3::edges) throws DomainError.
CheckReport check_mesh(const TriMesh2& mesh, const Domain2& domain, const CheckOptions& options = {});
CheckReport check_mesh(const TetMesh3& mesh, const Domain3& domain, const CheckOptions& options = {});

// Domain-free part (stages 1-3): orientation, face-to-face conformity, closed
// manifold boundary. Local conditions only: without a domain a mesh that covers
// some region twice can pass (see check3d.cpp).
CheckReport check_mesh_topology(const TriMesh2& mesh, const CheckOptions& options = {});
CheckReport check_mesh_topology(const TetMesh3& mesh, const CheckOptions& options = {});

}  // namespace pqmesh
