#pragma once
// The square dispatcher: thesis §4.4 on one box-face square S for any box kind
// (empty, facet, edge, vertex, two-facet), so that every box shares one
// triangulation of every square.
//
// The asking box's component P ∧ b is described by its P faces (BoxFaces,
// derived from the box kind and apex: §4.1.7 guarantees that a leaf's
// component holds exactly these faces, mv3d/leaf_kind.hpp). The dispatcher
// first decides EXACTLY which of them meet the closed prewarped square S
// within the closure of the component (square_meets.hpp: the P vertex as a
// point, P edges as segments; a facet of a facet box by its plane, of an edge
// or two-facet box by its half-plane from E, of a vertex box v by its sector
// at v (the angle of the facet at v, spanned by its two edges at v, in its
// plane): in each case the part of the facet on the component's closure,
// by the box's model below), giving the set M. A facet shared by two
// components of a duplicated cube (the floor under a slot) thus counts only
// for the component whose side of S it crosses. Then:
//   M = {}                        S lies wholly inside or wholly outside P ∧ b:
//                                 Case A (centre joined to the ring) or
//                                 nothing, by the exact status of S's centre
//                                 in the box's model (below);
//   M = {F}                       Case C (cut_square.hpp);
//   M = {F, G} or {E, F, G},      Cases B / D (cut_square_edge.hpp) with the
//     F, G the facets of edge E   cone of E; B iff E crosses S. F and G may
//                                 share several edges, all on the line where
//                                 their planes meet (a P vertex in the middle
//                                 of a straight edge, thesis §1.4 allows it):
//                                 E is the one whose closed segment meets S
//                                 (at most one: two would put their common P
//                                 vertex on S), else any of them, which all
//                                 give the same wedge (edge_for_square);
//   M with k >= 2 edges, vertex box: one Case B per edge, each on its own
//                                 piece S ∩ wedge(E) (a notch between two
//                                 edges leaving the united box through S;
//                                 conditions in separate_edge_pieces);
//   M in several pieces,          one piece per plane group, groups joined
//     vertex box                  across the creases in M, each triangulated
//                                 by the rules above with its own facets and
//                                 edges (crease_pieces: the groups are the
//                                 facets at v joined by flat edges, one plane
//                                 split into marker patches; every two
//                                 pieces meet at v in reflex creases only, or
//                                 lie beyond each other's regions, exact; the
//                                 neighbour cells hold them as separate
//                                 components, docs/algorithm/tet3d_boxes.md
//                                 "Plane groups and crease pieces");
//   anything else                 InternalError naming S and M (a P vertex in
//                                 S, two facets without a common edge, two
//                                 edges, ...: the octree's separation, §4.1.7,
//                                 excludes them for leaves of the thesis's kinds).
// Since M is a property of S and of the piece of P on it (not of the asking
// box: the components of the two boxes sharing S meet S in the same pieces,
// and both face lists hold the faces there), and each
// branch depends only on (S, M, corner set, warps), the two boxes sharing S
// produce identical triangles whatever their kinds. The edge of {F, G} is
// looked up from the domain (the unique edge on both), never from the asking
// box, for the same reason.
//
// Models (exact status of a point of the box off its faces):
//   empty box    inside;
//   facet box    P's side of F's plane (P ∧ b = cube ∩ half-space);
//   edge and two-facet boxes   the wedge of E (EdgeCone::status);
//   vertex box   the status of a ring point shared with a square of the
//                united box that meets a face (its local model, exact there:
//                vertex_box.cpp propagates it over the box surface); exact
//                locate() in the domain if none is given. The vertex box's
//                component is cone(v) ∩ B (Lemma 1); another component of P
//                may pass through B (the far wall of a narrow slot at its
//                mouth): its leaves get their own jobs (box_jobs.hpp), and
//                the sector test keeps its part of a facet shared with v
//                (the slot's top) off v's squares.
// Duplicates (§4.1.1): the model of each component of a duplicated cube is
// exact on its own closed cube, so each component's π is S ∩ that component:
// a square meets P in one piece per component, and each piece is triangulated
// by the boxes of that component on both sides.
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "pqmesh/domain.hpp"
#include "tet3d/squares/box_faces.hpp"
#include "tet3d/squares/cut_square.hpp"
#include "tet3d/squares/cut_square_edge.hpp"
#include "tet3d/points/point_book.hpp"
#include "tet3d/squares/square_meets.hpp"
#include "tet3d/warp/warp.hpp"

namespace pqmesh::tet3d {

// Kinds of box jobs (facet_boxes.hpp). FromFacet: a job given as {leaf,
// facet} (plan_boxes on the aligned grid, empty_boxes.hpp), an empty box when
// facet < 0, else a facet box.
enum class BoxKind : std::uint8_t { FromFacet, Empty, Facet, Edge, Vertex, TwoFacet };
const char* to_string(BoxKind kind);

// The P faces of one box's component (sorted ids) and its kind / apex
// (Facet: facet id; Edge, TwoFacet: edge index into Domain3::edges; Vertex:
// P vertex id; Empty: -1).
struct BoxFaces {
  BoxKind kind = BoxKind::Empty;
  int apex = -1;
  std::vector<int> vertices, edges, facets;
};

// Pieces: a vertex-box square split by plane groups (each piece is counted
// under its own case too).
enum class SquareCase : std::uint8_t { Nothing, A, C, BD, Pieces };

class SquareDispatcher {
 public:
  SquareDispatcher(const OctTree& tree, const CornerSet& corners, const Domain3& domain, PointBook& book,
                   const WarpTable* warps);

  BoxFaces faces_of(BoxKind kind, int apex) const;

  // The faces of `faces` meeting the closed square (exact; see above).
  struct Incidence {
    std::vector<int> vertices, edges, facets;
    bool none() const { return vertices.empty() && edges.empty() && facets.empty(); }
  };
  Incidence incidences(const FaceSquare& s, const BoxFaces& faces);
  // Exact status of a point of S (Negative: inside P, Zero: on dP, Positive:
  // outside) under the local model of a square with incidences m, one facet
  // (its plane) or two facets of an edge (its wedge); the model is exact on
  // the closed square. Throws for other incidences.
  Sign local_status(const Incidence& m, Vec3 p);

  // Appends the triangles of π = S ∩ P ∧ b (PointBook ids, right-hand normal
  // +S.n) and returns the case taken (see above). `inside` decides a square
  // meeting no face of a vertex box when not Zero (Negative: inside P, from
  // the statuses of neighbouring squares, vertex_box.cpp); else locate().
  SquareCase triangulate(const FaceSquare& s, const BoxFaces& faces, std::vector<std::array<int, 3>>& out,
                         Sign inside = Sign::Zero);

  // The facets at P vertex v joined by flat edges at v (coplanar facets with
  // different markers: one plane split into patches), each group sorted,
  // groups ordered by their smallest facet; every facet of v is in one.
  const std::vector<std::vector<int>>& plane_groups(int vertex);
  // For a square of v's united box whose facets lie in two or more pieces
  // at v: one incidence per piece (its facets and edges in m). The pieces are
  // the plane groups met by m, joined across the creases of v in m; the split
  // is made when every two of them meet at v in reflex creases only (so their
  // parts of S are disjoint: the exterior wedge of the crease lies between
  // them), or when each lies beyond the other's region (beyond_region).
  // Empty otherwise.
  std::vector<Incidence> crease_pieces(int vertex, const Incidence& m);
  // Every facet of `piece` lies strictly outside, v excepted, the region of
  // S that `other` (one facet, or one non-flat edge with its two facets) is
  // triangulated as: P's side of the facet's plane, or the edge's wedge.
  // Exact (orient3d on the facets' vertices); false for other incidences.
  bool beyond_region(int vertex, const Incidence& piece, const Incidence& other);

  const FacetPlane& plane(int facet);
  const EdgeCone& cone(int edge);
  // An edge of Domain3::edges on both facets, -1 if none: the unique one, or,
  // when F and G share several (collinear: on the line where their planes
  // meet), the smallest id. All of them then have the same local model (the
  // same two planes and convexity, checked at construction; InternalError if
  // not), so local_status() may use any.
  int edge_of_facets(int f, int g) const;
  // The shared edge that triangulates square S: the one whose closed segment
  // meets the closed (prewarped) square, else edge_of_facets(f, g).
  // InternalError if two meet S (their common P vertex lies on S).
  int edge_for_square(int f, int g, const SquareGeometry& geo) const;
  const std::vector<int>& vertex_edges(int v) const { return vertex_edges_[static_cast<std::size_t>(v)]; }
  const std::vector<int>& vertex_facets(int v) const { return vertex_facets_[static_cast<std::size_t>(v)]; }
  std::int64_t count(SquareCase c) const { return counts_[static_cast<std::size_t>(c)]; }
  // Vertex-box squares meeting no face decided by locate() / by a hint.
  std::int64_t located() const { return located_; }
  std::int64_t located_by_neighbours() const { return located_by_neighbours_; }

 private:
  bool facet_meets(int facet, const SquareGeometry& g);
  bool plane_meets(int facet, const SquareGeometry& g);
  bool half_plane_meets(const EdgeCone& cone, int facet, const SquareGeometry& g);
  // Facet F's edges at P vertex v (vertex_edges order): the first two, and
  // how many F has there (two on a valid PLC).
  struct FacetEdgesAt {
    std::array<int, 2> edges{-1, -1};
    int count = 0;
  };
  FacetEdgesAt facet_edges_at(int vertex, int facet) const;
  bool sector_meets(int vertex, int facet, const SquareGeometry& g);
  bool reflex_at(int vertex, int facet);
  bool separate_edge_pieces(int vertex, const Incidence& m);
  SquareCase triangulate_incidence(const FaceSquare& s, const BoxFaces& faces, const Incidence& m,
                                   std::vector<std::array<int, 3>>& out, Sign inside_hint);
  std::string describe(const FaceSquare& s, const BoxFaces& faces, const Incidence& m) const;
  // For each pair of facets sharing several edges: equal convexity.
  void check_collinear_edges();

  const OctTree& tree_;
  const CornerSet& corners_;
  const Domain3& domain_;
  PointBook& book_;
  const WarpTable* warps_;
  std::vector<std::vector<int>> facet_tris_;                  // facet triangles per facet
  std::vector<std::vector<int>> vertex_edges_, vertex_facets_;  // sorted, per vertex
  std::map<std::pair<int, int>, std::vector<int>> pair_edges_;  // (f < g) -> edges on both
  std::map<int, std::unique_ptr<FacetPlane>> planes_;
  std::map<int, std::unique_ptr<EdgeCone>> cones_;
  std::map<int, std::vector<std::vector<int>>> plane_groups_;  // per vertex, built on first use
  std::array<std::int64_t, 5> counts_{};
  std::int64_t located_ = 0, located_by_neighbours_ = 0;
};

}  // namespace pqmesh::tet3d
