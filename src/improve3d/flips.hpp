#pragma once
// 2-3 and 3-2 flips after the collapses, monotone in quality (improve.hpp,
// ../shared/IMPROVEMENT.md "The rule that keeps a guarantee").
//
// 2-3: an interior triangle abc shared by tetrahedra abcd and abce becomes
// the edge de and three tetrahedra abde, bcde, cade. 3-2: an interior edge ab
// with exactly three tetrahedra abcd, abde, abec becomes the triangle cde and
// two tetrahedra cdea, cdeb. A flip is accepted only when
//   1. every new tetrahedron is positively oriented (exact orient3d). The new
//      tetrahedra then fill exactly the old ones' union (de crosses abc, or ab
//      crosses cde, in its interior), so the mesh stays a valid triangulation;
//      the new edge de (2-3) or triangle cde (3-2) cannot exist elsewhere,
//      since it crosses a face (an edge) of the old mesh;
//   2. the triangle abc (2-3) is no boundary triangle and the edge ab (3-2) is
//      on none, and the old tetrahedra share one region marker: vertices and
//      boundary triangles never change;
//   3. the new tetrahedra's worst aspect ratio is at most the old ones' and at
//      most aspect_cap;
//   4. every new tetrahedron is within the size bound (size_bound.hpp);
//   5. their minimum dihedral angle exceeds the old ones' by at least
//      kMinDihedralGain (smooth.hpp): strict progress, so the passes end.
// Order: a pass visits the live tetrahedra whose minimum dihedral angle is
// below kWorkBelowDihedral (smooth.hpp), smallest first, ties by id; at each it evaluates the 3-2 flips of its six
// edges and the 2-3 flips of its four faces, in that enumeration order, and
// does the best accepted one (largest new minimum dihedral, ties: the first).
// New tetrahedra get new ids (collapse_mesh.hpp) and wait for the next pass.
#include <array>
#include <cstdint>
#include <vector>

#include "improve3d/collapse_mesh.hpp"
#include "improve3d/size_bound.hpp"

namespace pqmesh::improve3d::detail {

class Flipper {
 public:
  // mesh: after measure_dihedrals().
  Flipper(CollapseMesh& mesh, const SizeBound& size, double aspect_cap);

  // One pass; returns the number of flips.
  std::int64_t pass();
  // The tetrahedra made by the last pass (live or not).
  const std::vector<int>& created() const { return created_; }

 private:
  struct Flip {
    std::array<int, 3> old_tets{};
    int old_count = 0;
    std::array<std::array<int, 4>, 3> tets{};
    int count = 0;
    std::array<double, 3> aspect{}, dihedral{};
    double worst_aspect = 0, min_dihedral = 0;
  };
  bool try_tet(int t);
  bool edge_flip(int t, int i, int j, Flip& flip);
  bool face_flip(int t, int i, Flip& flip);
  bool on_boundary(int a, int b, int c);
  bool measure(Flip& flip) const;
  void apply(const Flip& flip);

  CollapseMesh& mesh_;
  const SizeBound& size_;
  double cap_;
  std::array<std::vector<int>, 4> around_;  // tetrahedra of each vertex of the current tetrahedron
  std::vector<int> faces_, created_;
};

}  // namespace pqmesh::improve3d::detail
