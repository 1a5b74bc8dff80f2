#pragma once
// The mesh while it is coarsened: flat arrays (docs/DESIGN_RULES.md "Data
// layout and speed") that a collapse edits in place.
//
// Vertex -> tetrahedra and vertex -> boundary triangles adjacency: one
// segment per vertex (adjacency.hpp). A dead element has vertex -1 first.
//
// Star times: the mesh keeps a time, advanced by every change (collapse,
// vertex move, tetrahedron or boundary triangle added or removed), and per
// vertex the time its star last changed: a change stamps every vertex of
// every tetrahedron and boundary triangle it adds, removes, re-points or
// reshapes. So star_time(x) <= t means the star of x (its tetrahedra and
// boundary triangles, the positions of their vertices, their stored
// qualities) is the same as at time t: a try whose outcome depends only on
// stars (smoothing a vertex, the flips of a tetrahedron) and that was
// refused at time t is refused again while no star it reads is newer.
//
// Element ids never change while collapsing; write_back() renumbers the
// survivors compactly in their old order (deterministic). After the
// collapses, smoothing (smooth.hpp) moves vertices and flips (flips.hpp)
// replace tetrahedra: a new tetrahedron always gets a new id (appended), so
// the survivors keep their order and the new ones follow in creation order;
// so does a boundary triangle made by a flip.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "improve3d/adjacency.hpp"
#include "pqmesh/mesh.hpp"
#include "pqmesh/vec.hpp"
#include "quality/tetrahedron_quality_memo.hpp"

namespace pqmesh::improve3d::detail {

class CollapseMesh {
 public:
  // Computes every tetrahedron's aspect ratio and minimum dihedral angle (tetrahedron_quality, through memo).
  CollapseMesh(const TetMesh3& mesh, std::span<const int> face_facets, TetrahedronQualityMemo& memo);
  // The same mesh, taking over the arrays of mesh (left empty) and face_facets
  // instead of copying them: one copy of the mesh at a time (peak memory).
  CollapseMesh(TetMesh3&& mesh, std::vector<int>&& face_facets, TetrahedronQualityMemo& memo);

  int vertex_count() const { return static_cast<int>(points_.size()); }
  bool vertex_alive(int v) const { return vertex_alive_[static_cast<std::size_t>(v)] != 0; }
  const Vec3& point(int v) const { return points_[static_cast<std::size_t>(v)]; }
  const std::array<int, 4>& tet(int t) const { return tets_[static_cast<std::size_t>(t)]; }
  int tet_marker(int t) const { return one_region_ ? region_marker_ : tet_markers_[static_cast<std::size_t>(t)]; }
  bool one_region() const { return one_region_; }  // every tetrahedron has the same marker
  double aspect(int t) const { return aspect_[static_cast<std::size_t>(t)]; }
  // The minimum dihedral angle (degrees) of t, kept by every change.
  double dihedral(int t) const { return dihedral_[static_cast<std::size_t>(t)]; }
  int tet_count() const { return static_cast<int>(tets_.size()); }  // ids, live or dead
  const std::array<int, 3>& face(int f) const { return faces_[static_cast<std::size_t>(f)]; }
  int face_facet(int f) const { return face_facets_[static_cast<std::size_t>(f)]; }
  int face_marker(int f) const { return face_markers_[static_cast<std::size_t>(f)]; }
  std::int64_t live_tets() const { return live_tets_; }
  std::int64_t live_vertices() const { return live_vertices_; }
  std::int64_t live_faces() const;  // O(boundary triangles)
  // The mesh time (advanced by every change, starts at 1) and the time the star of v last changed (see above).
  std::uint64_t time() const { return time_; }
  std::uint64_t star_time(int v) const { return star_time_[static_cast<std::size_t>(v)]; }

  // Appends the live tetrahedra (boundary triangles) of v to out, in list
  // order, unlinking dead ones met on the way.
  void tets_of(int v, std::vector<int>& out);
  void faces_of(int v, std::vector<int>& out);

  struct Collapse {
    int u = -1, v = -1;
    std::span<const int> dying_tets;     // hold u and v
    std::span<const int> moving_tets;    // hold u, not v: u becomes v
    std::span<const double> new_aspect;    // of moving_tets[i] after the change
    std::span<const double> new_dihedral;  // its minimum dihedral angle
    std::span<const int> dying_faces;    // boundary triangles holding u and v
    std::span<const int> moving_faces;   // boundary triangles holding u, not v
  };
  // Deletes u as described; the caller has checked the rules (collapse_check.hpp).
  void apply(const Collapse& c);

  double worst_aspect() const;
  double min_dihedral() const;  // over the live tetrahedra

  // Smoothing: v goes to p; tets[i] (the star of v) gets aspect[i], dihedral[i].
  void move_vertex(int v, Vec3 p, std::span<const int> tets, std::span<const double> aspect,
                   std::span<const double> dihedral);
  // Flips: a new tetrahedron (new id, returned) and the deletion of one.
  int add_tet(const std::array<int, 4>& k, int marker, double aspect, double dihedral);
  void remove_tet(int t);
  // Boundary flips: a new boundary triangle (new id, returned) and the deletion of one.
  int add_face(const std::array<int, 3>& k, int marker, int facet);
  void remove_face(int f);
  // Drops the dead tetrahedra: the live ones are renumbered in their order
  // (so write_back's order is unchanged) and every vertex's list keeps its
  // order. The per-tetrahedron arrays are reallocated to the live count with a
  // little room for flips. Tetrahedron ids held elsewhere are void after it.
  // O(tetrahedra + adjacency).
  void compact_tets();
  // The survivors, renumbered in their old order, into mesh and face_facets.
  // Consumes the working mesh: each array is freed once read (the adjacency
  // and the qualities first), so the output and the working mesh are not
  // both whole at any time (peak memory).
  void write_back(TetMesh3& mesh, std::vector<int>& face_facets) &&;

 private:
  std::vector<Vec3> points_;
  std::vector<int> vertex_markers_;
  std::vector<std::uint8_t> vertex_alive_;
  std::vector<std::array<int, 4>> tets_;
  std::vector<int> tet_markers_;  // empty while one_region_ (every marker is region_marker_)
  int region_marker_ = 0;
  std::vector<double> aspect_, dihedral_;
  Adjacency tets_of_vertex_;
  std::vector<std::array<int, 3>> faces_;
  std::vector<int> face_markers_, face_facets_;
  Adjacency faces_of_vertex_;
  bool one_region_ = true;
  bool has_vertex_markers_ = false, has_tet_markers_ = false, has_face_markers_ = false;
  std::int64_t live_tets_ = 0, live_vertices_ = 0;
  std::uint64_t time_ = 1;
  std::vector<std::uint64_t> star_time_;

  // The adjacency, one_region_ (freeing tet_markers_ if so) and the
  // qualities, from the arrays above.
  void derive(TetrahedronQualityMemo& memo);

  auto tet_alive() const {
    return [this](int t) { return tets_[static_cast<std::size_t>(t)][0] >= 0; };
  }
  auto face_alive() const {
    return [this](int f) { return faces_[static_cast<std::size_t>(f)][0] >= 0; };
  }

  // Advances the time (once per change; stamp then marks its elements' vertices).
  void tick() { ++time_; }
  template <std::size_t K>
  void stamp(const std::array<int, K>& element) {
    for (const int x : element) star_time_[static_cast<std::size_t>(x)] = time_;
  }
};

}  // namespace pqmesh::improve3d::detail
