#pragma once
// Private to the tetrahedral-mesh checker: the state shared by its stages and
// the exact geometric helpers they use. The argument that the stages suffice
// is the comment block at the top of check3d.cpp.
//
//   check3d.cpp           entry points and the stage driver
//   check3d_topology.cpp  stages 1-3: indices, orientation, conformity /
//                         hanging vertices / manifold boundary, listed faces
//   check3d_faces.cpp     stage 3 face matching: the boundary faces, faces on
//                         the same side of two tetrahedra or on three or more
//   check3d_domain.cpp    stage 4 without facets: input vertices, input-edge
//                         walks, Steiner points, locate()
//   check3d_facets.cpp    stage 4 (a) and (c): boundary triangles on facets,
//                         facet boundaries against the edge chains
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "mesh/check3d_plane.hpp"
#include "mesh/check_common.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/mesh.hpp"
#include "pqmesh/vec.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::detail::check3d {


// Exact: a, b, c on one line (all three coordinate projections degenerate).
inline bool collinear(Vec3 a, Vec3 b, Vec3 c) {
  return orient2d_projected(a, b, c, 0) == Sign::Zero && orient2d_projected(a, b, c, 1) == Sign::Zero &&
         orient2d_projected(a, b, c, 2) == Sign::Zero;
}

// p inside the closed axis-aligned box of a and b (exact comparisons).
inline bool in_box(Vec3 p, Vec3 a, Vec3 b) {
  return p.x >= std::min(a.x, b.x) && p.x <= std::max(a.x, b.x) && p.y >= std::min(a.y, b.y) &&
         p.y <= std::max(a.y, b.y) && p.z >= std::min(a.z, b.z) && p.z <= std::max(a.z, b.z);
}

// An axis whose projection keeps the nondegenerate triangle abc nondegenerate,
// preferring the dominant axis of its normal (a construction, only a hint: the
// choice is verified exactly). Returns -1 when abc is degenerate.
inline int projection_axis(Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 n = cross(b - a, c - a);
  const double m[3] = {std::abs(n.x), std::abs(n.y), std::abs(n.z)};
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int i, int j) { return m[i] > m[j] || (m[i] == m[j] && i < j); });
  for (int axis : order)
    if (orient2d_projected(a, b, c, axis) != Sign::Zero) return axis;
  return -1;
}

// The faces of a mesh, collected and matched (stage 3).
struct FaceTable {
  std::vector<std::array<int, 3>> boundary;  // faces on one tetrahedron, oriented outward
  std::vector<int> boundary_tet;
  Adjacency boundary_adjacency;              // edges of the boundary triangles
};

// A facet of the domain prepared for exact containment tests.
struct FacetPlane {
  bool ok = false;
  Vec3 p0, p1, p2;  // three non-collinear vertices: the plane
  int axis = 2;     // projection axis (dropped coordinate)
  Sign turn = Sign::Zero;  // orientation of the outer loop in that projection
  Vec3 lo, hi;      // bounding box
  std::array<Sign, 3> normal{};  // plane_normal_signs(p0, p1, p2) (check3d_plane.hpp)
};

// p lies in the facet's plane, or is a faithful rounding of a point of it
// (within_ulp_of_plane, docs/algorithm/quality.md "The validity checker"), and
// in its bounding box widened by an ulp. Exact. (A point on the plane lies
// inside its ulp box, so the plane meets the box: no separate orient3d(p) == 0
// test.)
inline bool on_facet_plane(const FacetPlane& fp, Vec3 p) {
  const Vec3 lo{next_down(p.x), next_down(p.y), next_down(p.z)};
  const Vec3 hi{next_up(p.x), next_up(p.y), next_up(p.z)};
  if (hi.x < fp.lo.x || lo.x > fp.hi.x || hi.y < fp.lo.y || lo.y > fp.hi.y || hi.z < fp.lo.z || lo.z > fp.hi.z)
    return false;
  return within_ulp_of_plane_at_extremes(p, fp.p0, fp.p1, fp.p2, fp.normal);
}

class Checker3 {
 public:
  Checker3(const TetMesh3& mesh, const CheckOptions& options, CheckReport& report);

  // Stages 1-3 and the volume measurement; returns whether stage 3 is clean.
  bool run_topology();
  // Stage 4, the Volume comparison and locate(); `topology_ok` is what
  // run_topology returned.
  void run_domain(const Domain3& d, bool topology_ok);

 private:
  // check3d_topology.cpp
  bool stage1_indices();
  bool stage2_orientation();
  void measure_volume();
  bool stage3_faces();
  void build_boundary_edges();
  bool check_boundary_manifold();
  void find_hanging_vertices();
  void check_listed_faces();

  // check3d_faces.cpp
  // Stage 3 face matching: fills faces_.boundary (and boundary_tet), reports
  // NonConforming faces.
  void match_faces();

  // check3d_domain.cpp
  void map_input_vertices(const Domain3& d);
  void walk_edges(const Domain3& d);
  void check_steiner();
  void check_located(const Domain3& d);

  // check3d_facets.cpp
  void prepare_facets(const Domain3& d);
  bool in_closed_facet(const Domain3& d, int f, Vec3 p) const;
  void assign_boundary_faces(const Domain3& d);
  void check_facets(const Domain3& d);

  const TetMesh3& m_;
  const CheckOptions& opt_;
  CheckReport& rep_;
  IssueSink sink_;
  bool stage1_ok_ = false;
  std::vector<int> order_;
  FaceTable faces_;
  struct BEdge {
    int lo, hi;
    int forward;  // 1 if the boundary triangle runs lo -> hi
  };
  std::vector<BEdge> bedges_;
  std::vector<int> in2mesh_, mesh2in_;
  std::vector<FacetPlane> planes_;
  Vec3 grid_lo_, grid_hi_;
  std::vector<int> assigned_, assigned_sign_;
  std::vector<int> chain_offset_, chain_items_;
  std::vector<char> edge_ok_;
};

}  // namespace pqmesh::detail::check3d
