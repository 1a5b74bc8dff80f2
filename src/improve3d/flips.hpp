#pragma once
// Flips after the collapses, monotone in quality (improve.hpp,
// ../shared/IMPROVEMENT.md "The rule that keeps a guarantee").
//
// 2-3: an interior triangle abc shared by tetrahedra abcd and abce becomes
// the edge de and three tetrahedra abde, bcde, cade.
// Edge removal (edge_ring.hpp, ring_triangulation.hpp): the tetrahedra around
// edge ab, (a, b, r_i, r_i+1), are replaced, for a triangulation of the
// polygon r_0 .. r_m-1, by the tetrahedra (a, r_i, r_k, r_j) and (r_i, r_k,
// r_j, b) of each of its triangles (i < k < j); the triangulation chosen is
// the one whose tetrahedra have the largest least minimum dihedral angle.
//   * an interior edge (closed ring of 3 to kMaxRingVertices tetrahedra;
//     three: the 3-2 flip, four: the 4-4 flips);
//   * an edge inside a facet (open ring of 2 to kMaxRingVertices - 1
//     tetrahedra between the two boundary triangles abc and abd, c = r_0,
//     d = r_m-1): the polygon's side cd becomes a boundary edge, abc and abd
//     become acd and bcd (two tetrahedra: the 2-2 flip). Only when abc and abd
//     lie on the same facet, carry the same marker, and a, b, c, d are exactly
//     coplanar (exact orient3d = 0), so acd and bcd cover exactly what abc and
//     abd covered; each new triangle faces out as the old ones did (exact
//     orient3d against its tetrahedron's fourth vertex).
// A flip is accepted only when
//   1. every new tetrahedron is positively oriented (exact orient3d). The new
//      tetrahedra then fill exactly the old ones' union (Shewchuk 2002: both
//      fans of the polygon's triangles, seen from a and from b, are
//      positive), so the mesh stays a valid triangulation; a new edge or
//      triangle crosses the removed edge or face, so it exists nowhere else;
//   2. the old tetrahedra share one region marker; a 2-3 flip's triangle is
//      no boundary triangle; vertices never change, nor does any boundary
//      triangle except as above;
//   3. the new tetrahedra's worst aspect ratio is at most the old ones' and at
//      most aspect_cap;
//   4. every new tetrahedron is within the size bound (size_bound.hpp);
//   5. their minimum dihedral angle exceeds the old ones' by at least
//      kMinDihedralGain (smooth.hpp): strict progress, so the passes end.
// Order: a pass visits the live tetrahedra whose minimum dihedral angle is
// below kWorkBelowDihedral (smooth.hpp), smallest first, ties by id
// (worst_first.hpp); at each it evaluates the edge removals of its six edges
// and the 2-3 flips of its four faces, in that enumeration order, and does
// the best accepted one (largest new minimum dihedral, ties: the first).
// New tetrahedra and boundary triangles get new ids (collapse_mesh.hpp); new
// tetrahedra wait for the next pass. A tetrahedron refused (no flip accepted)
// is skipped by the later passes of the Flipper while no star of its four
// vertices changed since (collapse_mesh.hpp "Star times"): every candidate
// and rule above reads only those stars (the rings of its edges, the
// tetrahedra across its faces, the boundary triangles at its vertices), so
// the skipped try would be refused again. Rules 1, 3, 4 and 5 are decided once per
// candidate tetrahedron (rule 5 as a floor on each new tetrahedron's angle:
// the flip's least angle is the least of its tetrahedra'): for an edge
// removal while scoring the ring's triangles (each triangle's two tetrahedra,
// kept for the triangulation chosen; a triangle below the floor is forbidden,
// which leaves the program's choice unchanged whenever that choice passes
// rule 5), for a 2-3 flip on its three tetrahedra. An edge removal first
// scores the triangles on each side of the polygon and stops when a side has
// no admissible one (no triangulation can avoid that side), before scoring
// the other triangles (each triangle is scored once). The angle is measured
// before the aspect ratio (tetrahedron_min_dihedral, the same double), so a
// tetrahedron below the floor costs no enclosing ball. Cost per tetrahedron
// visited: O(1) ring gathers and 2 * C(kMaxRingVertices, 3) quality
// evaluations per edge at most.
#include <array>
#include <cstdint>
#include <vector>

#include "improve3d/collapse_mesh.hpp"
#include "improve3d/edge_ring.hpp"
#include "improve3d/ring_triangulation.hpp"
#include "improve3d/size_bound.hpp"
#include "pqmesh/quality.hpp"

namespace pqmesh::improve3d::detail {

class Flipper {
 public:
  Flipper(CollapseMesh& mesh, const SizeBound& size, double aspect_cap);

  // One pass; returns the number of flips.
  std::int64_t pass();
  // Flips that changed boundary triangles, so far.
  std::int64_t boundary_flips() const { return boundary_flips_; }

 private:
  struct Flip {
    std::vector<int> old_tets;
    std::vector<std::array<int, 4>> tets;
    std::vector<double> aspect, dihedral;
    std::vector<int> old_faces;              // boundary triangles replaced
    std::vector<std::array<int, 3>> faces;   // their replacements
    double min_dihedral = 0;
  };
  bool try_tet(int t);
  bool refused_unchanged(int t) const;
  bool edge_removal(int t, int i, int j, Flip& flip);
  bool boundary_pair(Flip& flip);
  void replacement_faces(int apex, Flip& flip);
  bool face_flip(int t, int i, Flip& flip);
  bool on_boundary(int a, int b, int c);
  bool one_region(const std::vector<int>& tets) const;
  // What a new tetrahedron must meet: rule 3's aspect ratio limit, rule 5's angle floor.
  struct Bounds {
    double aspect = 0, dihedral = 0;
  };
  Bounds bounds(const std::vector<int>& old_tets) const;
  bool admissible(const std::array<int, 4>& k, const Bounds& bounds, TetQuality& q) const;
  double score(int x, int y, int z, const Bounds& bounds);
  void take(const std::array<int, 4>& k, const TetQuality& q, Flip& flip) const;
  void apply(const Flip& flip);

  CollapseMesh& mesh_;
  const SizeBound& size_;
  double cap_;
  std::array<std::vector<int>, 4> around_;  // tetrahedra of each vertex of the current tetrahedron
  std::vector<int> faces_;
  EdgeRing ring_;
  std::vector<std::array<int, 3>> triangles_;
  // The two tetrahedra of each ring triangle (x, y, z) as score() measured them, at (x * m + y) * m + z.
  std::vector<std::array<TetQuality, 2>> figures_;
  Flip best_, trial_;
  std::vector<std::uint64_t> refused_at_;  // per tetrahedron id: mesh time of its last refusal, 0: none
  std::int64_t boundary_flips_ = 0;
};

}  // namespace pqmesh::improve3d::detail
