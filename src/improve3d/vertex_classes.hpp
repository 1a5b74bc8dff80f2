#pragma once
// The classes of rule 1 of improve.hpp, computed once from the input mesh.
//
// An input vertex is a mesh vertex whose coordinates equal some
// domain.plc.vertices[i] bit for bit; it never disappears. The facet set of a
// vertex is the set of facet ids (face_facets) of its boundary triangles.
// A non-input vertex with two or more facets lies on an input edge, with one
// inside that facet, with none in the interior.
//
// Computed once: vertices never move, so every facet in facets(v) keeps
// holding v (the checker's ulp rule) whatever collapses happen later; and a
// collapse of u onto v gives v only triangles on facets(u), a subset of
// facets(v), so no vertex ever lies on a facet outside its set.
#include <cstdint>
#include <span>
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/mesh.hpp"

namespace pqmesh::improve3d::detail {

enum class VertexClass : std::uint8_t { Interior = 0, Facet = 1, Edge = 2, Input = 3 };

struct VertexClasses {
  std::vector<VertexClass> kind;
  // Facets of vertex v: facets[begin[v] .. begin[v + 1]), increasing.
  std::vector<int> begin;
  std::vector<int> facets;

  std::span<const int> facets_of(int v) const {
    return {facets.data() + begin[static_cast<std::size_t>(v)],
            static_cast<std::size_t>(begin[static_cast<std::size_t>(v) + 1] - begin[static_cast<std::size_t>(v)])};
  }
  VertexClass of(int v) const { return kind[static_cast<std::size_t>(v)]; }
  // facets(u) is a subset of facets(v).
  bool facets_within(int u, int v) const;
  bool same_facets(int u, int v) const;
};

VertexClasses classify_vertices(const Domain3& domain, const TetMesh3& mesh, std::span<const int> face_facets);

}  // namespace pqmesh::improve3d::detail
