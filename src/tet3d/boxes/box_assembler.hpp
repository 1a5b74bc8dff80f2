#pragma once
// One pass of box meshing (facet_boxes.hpp, mesh_boxes): the tetrahedra of
// every box job, on one point book and one square dispatcher, so that two
// boxes sharing a square build the same vertices and triangles. Each box
// kind is made in its own file:
//   empty_box.cpp       empty boxes (§4.5.1), Kuhn faces and Kuhn boxes
//   box_assembler.cpp   tetrahedra checked by exact orient3d, the rebuild
//                       loop's reports, shared helpers
//   facet_box.cpp       facet boxes (§4.5.4) and their prisms
//   facet_polygon.cpp   the polygon F ∩ b, its central points and its fan
//   edge_box.cpp        edge boxes (§4.5.3), the apex on E, two cone points
//   edge_box_fans.cpp   edge boxes with flat cones: F ∩ b, G ∩ b fanned
//   vertex_box.cpp      united vertex boxes (§4.5.2)
//   two_facet_box.cpp   two-facet boxes (§4.5.5)
// The constructions are stated in facet_boxes.hpp and
// docs/algorithm/tet3d_boxes.md.
#include <array>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <map>
#include <utility>
#include <vector>

#include "tet3d/boxes/empty_cells.hpp"
#include "tet3d/facet_boxes.hpp"
#include "tet3d/points/facet_plane.hpp"
#include "tet3d/points/point_book.hpp"
#include "tet3d/squares/square_cases.hpp"

namespace pqmesh::tet3d {

class BoxAssembler {
 public:
  BoxAssembler(const OctTree& tree, const CornerSet& corners, const Domain3& domain, const WarpTable* warps)
      : tree_(tree), corners_(corners), domain_(domain), warps_(warps) {
    book_.set_warps(warps);
  }

  // The box jobs, one call each (facet_boxes.cpp run_jobs).
  void empty_box(std::int32_t leaf);
  void facet_box(std::int32_t leaf, int facet);
  void edge_box(std::int32_t leaf, int edge);
  void vertex_box(std::int32_t leaf, int vertex, std::uint8_t block);
  void two_facet_box(std::int32_t leaf, int edge);

  // The empty boxes of the whole run (every pass of one run gets the same
  // set): faces between two empty boxes of one size may be cut by their Kuhn
  // diagonal (empty_box.cpp). Without it every empty box is coned from its
  // centre over four triangles per square.
  void set_empty_cells(const EmptyCells* cells) { empty_cells_ = cells; }
  void set_job(std::size_t j, const BoxJob& job) {
    job_ = static_cast<std::int32_t>(j);
    job_box_ = job;
  }
  // Collect mode: a non-positive tetrahedron with moved points is reported
  // (bad(), bad_axes(), bad_jobs()) instead of thrown.
  void collect_bad() { collect_ = true; }
  // Edge boxes whose apex on E does not see every face triangle are made
  // from two cone points (two_apex_box) only when allowed; either way
  // two_apex_points() lists the box vertices (grid points, repeats allowed)
  // of every box that had a valid such construction.
  void allow_two_apex(bool on) { two_apex_ = on; }
  const std::vector<GridPoint>& two_apex_points() const { return two_apex_points_; }
  // Edge boxes with flat cones may be made by edge_box_fans.cpp (on by default).
  void allow_facet_fans(bool on) { facet_fans_ = on; }
  // The largest tet_shape over the tetrahedra made so far (+infinity for one
  // flat in floating point).
  double worst_shape() const;
  // Per job (of `job_count`), the largest tet_shape of its tetrahedra made
  // so far; 0 for a job without any.
  std::vector<double> job_worst_shapes(std::size_t job_count) const;
  const std::vector<GridPoint>& bad() const { return bad_; }
  // Per bad() point: bit a set when it lies on the low face of the inverted
  // tetrahedron's box with normal axis a, bit 3 + a on its high face.
  const std::vector<std::uint8_t>& bad_axes() const { return bad_axes_; }
  // The jobs of the inverted tetrahedra (collect mode), in order, repeats allowed.
  const std::vector<std::int32_t>& bad_jobs() const { return bad_jobs_; }

  void count_squares();
  // The mesh made (the assembler is spent afterwards).
  BoxMesh finish();

 private:
  using Tri = std::array<int, 3>;

  // Empty boxes (empty_box.cpp).
  bool kuhn_face(const BoxKey<3>& key, int axis, bool upper) const;
  void kuhn_box(std::int32_t leaf, const BoxKey<3>& key);
  // The boundary of F ∩ b: (smaller id, larger id) -> the edge as directed
  // in its face triangle (chords in facet_polygon.cpp).
  using Chords = std::map<std::pair<int, int>, std::pair<int, int>>;

  // Shared (box_assembler.cpp).
  void square_tris(const std::vector<FaceSquare>& squares, const BoxFaces& faces, bool upper, std::vector<Tri>& tris);
  void box_tris(const BoxKey<3>& key, const BoxFaces& faces, std::vector<Tri>& tris);
  double worst_cone(const std::vector<Tri>& tris, Vec3 apex, const FacetPlane* skip = nullptr) const;
  bool on_facet(int id, const FacetPlane& plane) const;
  void tet(std::int32_t leaf, const char* what, int a, int b, int c, int d);
  bool report_moved(std::initializer_list<int> vertices);
  std::array<Tri, 2> split_quad(int a, int b, int c, int d) const;
  int grid(const GridPoint& p) { return grid_vertex(p, tree_, warps_, book_); }
  // Box centres are never box vertices, so never warped.
  int centre_vertex(const GridPoint& p) {
    return book_.id(grid_key(p), [&] { return grid_coordinates(tree_, p); });
  }
  // The cone from an apex inside the box over a face triangle with outward
  // normal: the reversed triangle followed by the apex is positive.
  void cone(std::int32_t leaf, const Tri& t, int apex) { tet(leaf, "cone", t[0], t[2], t[1], apex); }
  bool key_less(int a, int b) const { return book_.key(a) < book_.key(b); }
  // Whether the apex sees face triangle t from inside (exact orient3d).
  bool seen(const Tri& t, Vec3 apex) const {
    return orient3d(book_.point(t[0]), book_.point(t[2]), book_.point(t[1]), apex) == Sign::Positive;
  }

  // F ∩ b (facet_polygon.cpp).
  Chords chords(std::int32_t leaf, const std::vector<Tri>& tris, const FacetPlane& plane, int edge = -1) const;
  Vec3 vertex_mean(const Chords& chord) const;
  Vec3 polygon_point(const Chords& chord, const FacetPlane& plane) const;
  std::vector<Vec3> central_points(const Chords& chord, const FacetPlane& plane) const;
  double worst_fan(const Chords& chord, Vec3 g, Vec3 apex, bool exact) const;
  Vec3 fan_centre(const Chords& chord, const FacetPlane& plane, int v, double bar) const;
  void fan(std::int32_t leaf, const Chords& chord, const FacetPlane& plane, VertexKind kind, const GridPoint& centre,
           int v, double bar = std::numeric_limits<double>::infinity());

  // Facet boxes (facet_box.cpp).
  void prism(std::int32_t leaf, const Tri& t, const GridPoint& centre, Vec3 C, const FacetPlane& plane);

  // Edge boxes (edge_box.cpp).
  // Edge boxes whose worst single-apex cone is flatter than this (tet_shape,
  // about twice the aspect ratio) try flat_edge_box. A float threshold
  // that only decides whether to look for another valid construction.
  static constexpr double kFlatCone = 4096;
  // The best two-point construction for far-set seed far0 (see two_apex_box):
  // shape +infinity when no candidate w is valid.
  struct TwoApex {
    double shape = std::numeric_limits<double>::infinity();
    GridPoint w{};
    std::vector<char> far;
  };
  bool two_apex_box(std::int32_t leaf, const std::vector<Tri>& tris, int v);
  bool flat_edge_box(std::int32_t leaf, int edge, const std::vector<Tri>& tris, int v, double single);
  TwoApex flat_two_apex(std::int32_t leaf, const std::vector<Tri>& tris, int v);
  TwoApex best_two_apex(std::int32_t leaf, const std::vector<Tri>& tris, int v, const std::vector<char>& far0);
  static std::vector<std::pair<int, int>> rim_of(const std::vector<Tri>& tris,
                                                 const std::map<std::pair<int, int>, std::size_t>& owner,
                                                 const std::vector<char>& far);
  void make_two_apex(std::int32_t leaf, const std::vector<Tri>& tris, int v, const TwoApex& c);
  Vec3 apex_on_edge(const std::vector<Tri>& tris, Vec3 a, Vec3 b, const std::vector<int>& ends, Vec3 mid, double t0,
                    double t1);

  // Edge boxes with F ∩ b and G ∩ b fanned from points of their facets
  // (edge_box_fans.cpp): the best construction found (see best_facet_fans);
  // shape +infinity when none is valid.
  struct FacetFans {
    double shape = std::numeric_limits<double>::infinity();
    bool centred = false;  // true: coned from w, both polygons fanned; false: apex on[apex_facet]
    int apex_facet = 0;    // index into E's facets (0: the cone's f(), 1: its g())
    Vec3 on[2];            // the points of the two facets used (on their planes)
    bool from_v[2] = {};   // centred: that facet's polygon fanned from v (the chords alone), not on[f]
    GridPoint w{};         // centred: the interior grid point
  };
  Chords edge_polygon(const Chords& chord, int v) const;
  FacetFans best_facet_fans(std::int32_t leaf, int edge, const std::vector<Tri>& tris, int v);
  void make_facet_fans(std::int32_t leaf, int edge, const std::vector<Tri>& tris, int v, const FacetFans& c);

  // Vertex boxes (vertex_box.cpp).
  std::vector<Sign> vertex_box_hints(const std::vector<FaceSquare>& squares, const BoxFaces& faces);

  // Two-facet boxes (two_facet_box.cpp): the apex on one facet's plane.
  struct FacetApex {
    int facet = 0;  // index into the two planes
    Vec3 at;        // on that facet's plane (rounded onto it)
  };
  FacetApex two_facet_apex(const std::vector<Tri>& tris, const FacetPlane* const pl[2], const Chords* const ch[2],
                           int near) const;

  const OctTree& tree_;
  const CornerSet& corners_;
  const Domain3& domain_;
  const WarpTable* warps_;
  const EmptyCells* empty_cells_ = nullptr;
  std::int32_t job_ = -1;
  BoxJob job_box_;
  bool collect_ = false;
  bool two_apex_ = false;
  bool facet_fans_ = true;
  std::vector<GridPoint> two_apex_points_;  // two_apex_points()
  std::vector<GridPoint> bad_;              // moved grid points of inverted tetrahedra (collect_ mode)
  std::vector<std::uint8_t> bad_axes_;      // parallel to bad_ (bad_axes())
  std::vector<std::int32_t> bad_jobs_;
  PointBook book_;
  SquareDispatcher squares_{tree_, corners_, domain_, book_, warps_};
  BoxMesh out_;
};

}  // namespace pqmesh::tet3d
