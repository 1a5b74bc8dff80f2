#pragma once
// Coarsening of a valid tetrahedral mesh by edge collapse, monotone in quality
// (../shared/IMPROVEMENT.md "The rule that keeps a guarantee").
//
// A collapse of edge (u, v) deletes u: every tetrahedron of u is re-pointed to
// v and the tetrahedra holding both vanish. Collapses never move a vertex, so
// every remaining vertex keeps the exact coordinates the checker accepted. A
// collapse is accepted only when all of these hold (collapse_check.hpp):
//   1. vertex classes (vertex_classes.hpp): u is no input vertex, its facet
//      set lies in v's, and a vertex on an input edge moves along that edge;
//   2. the link condition on the mesh closed by a virtual vertex joined to
//      every boundary triangle, and no duplicate boundary triangle;
//   3. every new tetrahedron is positively oriented (exact orient3d);
//   4. the worst aspect ratio of the changed region (the tetrahedra of v
//      after) is at most min(aspect_cap, max(old region worst, target_aspect)),
//      the old region being the tetrahedra of u and v before;
//   5. every new tetrahedron's longest edge is within the size bound
//      (size_bound.hpp: sqrt(3) times the size asked at its centroid);
//   6. when the old region's worst aspect ratio is at most target_aspect,
//      every new tetrahedron's minimum dihedral angle is at least
//      min(min_dihedral, the old region's least): a quality target that
//      stops coarsening from spoiling good regions (0: off).
// With aspect_cap = the construction's worst aspect ratio, the coarsened
// mesh's worst never exceeds it, so every bound proved for the construction
// holds for the result.
//
// After the collapses, passes of vertex smoothing (smooth.hpp) and of flips
// (2-3, and edge removal of interior edges and of edges inside a facet;
// flips.hpp) raise the minimum dihedral
// angle; then the collapses run again (smoothing and flips make room for
// them), for ImproveOptions::rounds rounds or until a round collapses
// nothing. Smoothing and flips: each accepted operation keeps every changed tetrahedron positive
// (exact orient3d), does not raise the changed region's worst aspect ratio
// (and keeps it <= aspect_cap), raises its minimum dihedral angle by a fixed
// least gain, and keeps the boundary (smoothing moves only interior vertices
// and vertices inside an axis-aligned facet, within its plane; flips never
// change a vertex, and change boundary triangles only by re-triangulating two
// exactly coplanar ones of one facet). So the minimum dihedral angle never falls and
// the worst aspect ratio never rises in these passes.
//
// Last, collapses that remove the worst tetrahedra (improving_collapse.hpp:
// an edge of a tetrahedron below the work threshold, with rule 6 at
// min_dihedral = 180, so where the region is within target_aspect no new
// tetrahedron is worse in minimum dihedral angle than the region's least),
// each batch followed by smoothing and flips, at most kMaxRounds times.
#include <cstdint>
#include <limits>
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/mesh.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh::improve3d {

struct ImproveOptions {
  // No accepted collapse makes any tetrahedron's aspect ratio exceed this (the caller passes the
  // construction's worst aspect ratio, so the mesh's worst never gets worse: the guarantee survives).
  double aspect_cap = std::numeric_limits<double>::infinity();
  // A collapse may raise the worst aspect ratio of the region it changes up to
  // max(the old region's worst, target_aspect), never above aspect_cap.
  double target_aspect = 6.0;
  // Where the tetrahedra of u and v all meet target_aspect, a collapse may not make a tetrahedron whose
  // minimum dihedral angle (degrees) is below the smaller of this and their least.
  double min_dihedral = 0;
  // Size bound (the user's --max-size and size field): an operation is refused if a new tetrahedron's longest
  // edge exceeds sqrt(3) * min(max_size, min_i sizes[i] + |g - points[i]|) at its centroid g (max_size 0 and
  // no points: no bound).
  double max_size = 0;
  std::vector<Vec3> size_points;
  std::vector<double> sizes;
  // Vertex smoothing and flips after the collapses (see above).
  bool smooth = true;
  bool flip = true;
  // Collapses that remove the worst tetrahedra after the rounds (see above); counted in collapses.
  bool improving_collapses = true;
  // Rounds of (collapses, smoothing and flips); a round after the first runs
  // only when the one before collapsed something (and smoothed or flipped).
  int rounds = 3;
};

struct ImproveStats {
  std::int64_t tetrahedra_before = 0, tetrahedra_after = 0, vertices_before = 0, vertices_after = 0;
  std::int64_t collapses = 0, passes = 0;
  double worst_aspect_before = 0, worst_aspect_after = 0, seconds = 0;
  // Vertices moved by smoothing (each counted once per round); flips done (2-3 and edge removals), of
  // which boundary_flips changed boundary triangles (edge removals inside a facet).
  std::int64_t smoothed = 0, flips = 0, boundary_flips = 0;
  // Minimum dihedral angle (degrees) of the input mesh, after the first round's collapses, and at the end.
  double min_dihedral_before = 0, min_dihedral_collapsed = 0, min_dihedral_after = 0;
};

// mesh: a valid mesh of domain (check_mesh passes) with mesh.faces = its boundary triangles (outward),
// mesh.face_markers, mesh.tetrahedron_markers; face_facets[i] = the Domain3 facet id (domain.plc.facets index)
// that boundary triangle i lies on. On return mesh (vertices, tetrahedra, faces, markers) and face_facets
// describe the coarsened mesh, vertices and tetrahedra renumbered compactly in a deterministic order
// (the surviving ones in their old order; tetrahedra made by flips after the surviving ones, in
// creation order).
// Throws InvalidInput when face_facets or a marker array has the wrong size or a facet id is out of range
// (mesh untouched). Memory: the mesh's vertex and tetrahedron arrays are freed once copied into the working
// mesh (an exception after that leaves them empty); the working mesh drops its dead tetrahedra after each
// round's collapses.
ImproveStats improve_mesh(const Domain3& domain, TetMesh3& mesh, std::vector<int>& face_facets,
                          const ImproveOptions& options);

}  // namespace pqmesh::improve3d
