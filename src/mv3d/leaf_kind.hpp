#pragma once
// The kind of an octree leaf at the end of the octree (thesis §4.1.7: "every
// leaf box is either empty, lying entirely inside P, or contains a vertex,
// edge, or facet cone"; a fifth kind is the one the facet phase leaves next
// to protected edge boxes: two facets of an edge whose edge is outside the
// box).
//
// Decided exactly, from the P faces incident on the leaf's component P ∧ b
// (NodeData3 / ComponentFaces3: integer ids, themselves exact) and the
// incidences of the domain; no geometry is recomputed. Rules, in order:
//   Outside      the leaf carries no component (its cube misses P);
//   EmptyInside  no P face meets P ∧ b (then P ∧ b is the whole cube);
//   VertexCone   P ∧ b holds exactly one vertex v, and its edges and facets
//                are exactly all the superfaces of v (§4.1.3 (a)-(b)); or
//                the leaf is a piece of v's united box B (vertex_owner = v,
//                §4.1.3 "uniting": B is one box of the thesis, a vertex cone)
//                and every face of P ∧ b is v or a superface of v;
//   EdgeCone     no vertex, exactly one edge e, and the facets are exactly
//                e's two facets (§4.1.4 (a)-(b));
//   FacetCone    no vertex, no edge, exactly one facet (§4.1.5 (a));
//   TwoFacet     no vertex, no edge, exactly two facets, and they are the two
//                facets of one P edge (which then does not meet P ∧ b);
//   Other        anything else: an invariant of §4.1.7 is violated.
// Condition (c) of the cone definitions (the faces of P ∧ ex(b)) is not part
// of the kind; tests/unit/mv3d/octree_corpus_test.cpp checks it.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "mv3d/facet_pair_edges.hpp"
#include "mv3d/octree_builder.hpp"
#include "pqmesh/domain.hpp"

namespace pqmesh::mv3d {

enum class LeafKind : std::uint8_t { Outside, EmptyInside, VertexCone, EdgeCone, FacetCone, TwoFacet, Other };
inline constexpr int kLeafKinds = 7;

const char* to_string(LeafKind kind);

// The P faces of one leaf's component (sorted, unique ids; see ComponentFaces3).
struct LeafFaces {
  bool meets_p = false;           // false: the cube misses P
  std::span<const int> vertices;  // P vertex ids
  std::span<const int> edges;     // indices into Domain3::edges
  std::span<const int> facets;    // facet ids
  int vertex_owner = -1;          // v if the leaf is a piece of v's united box
};

// The faces of an octree leaf as the builder recorded them.
LeafFaces leaf_faces(const OctreeBuilder& builder, std::int32_t node);

// The faces in the input file's numbering (vertices and facets by id, edges by
// their two vertices), e.g. "vertices none; edges 3-7; facets 2, 5", so that a
// refused leaf can be found in the input.
std::string faces_text(const Domain3& domain, const LeafFaces& faces);

struct LeafClass {
  LeafKind kind = LeafKind::Other;
  // VertexCone: the vertex; EdgeCone and TwoFacet: the edge (index into
  // Domain3::edges); FacetCone: the facet; -1 otherwise.
  int apex = -1;
};

// Precomputes, per vertex, its sorted incident edges and facets, and the edge
// of every pair of facets that share one. O(size of P) memory.
class LeafClassifier {
 public:
  explicit LeafClassifier(const Domain3& domain);
  LeafClass classify(const LeafFaces& faces) const;

 private:
  bool is_superface_set(int v, const LeafFaces& faces) const;  // every face of `faces` contains v

  const Domain3& domain_;
  std::vector<std::vector<int>> vertex_edges_, vertex_facets_;  // sorted, per vertex
  FacetPairEdges facet_pair_edges_;
};

}  // namespace pqmesh::mv3d
