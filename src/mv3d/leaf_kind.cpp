// Leaf kinds (thesis §4.1.7); see leaf_kind.hpp.
#include "mv3d/leaf_kind.hpp"

#include <algorithm>
#include <utility>

#include "plc/edge_topology.hpp"

namespace pqmesh::mv3d {

const char* to_string(LeafKind kind) {
  switch (kind) {
    case LeafKind::Outside: return "outside";
    case LeafKind::EmptyInside: return "empty-inside";
    case LeafKind::VertexCone: return "vertex-cone";
    case LeafKind::EdgeCone: return "edge-cone";
    case LeafKind::FacetCone: return "facet-cone";
    case LeafKind::TwoFacet: return "two-facet";
    case LeafKind::Other: return "other";
  }
  return "?";
}

LeafFaces leaf_faces(const OctreeBuilder& builder, std::int32_t node) {
  const NodeData3& d = builder.data(node);
  return {d.has_component, d.vertices, d.edges, d.facets, d.vertex_owner};
}

std::string faces_text(const Domain3& domain, const LeafFaces& faces) {
  const int first = domain.plc.source.first_id;
  std::string s;
  const auto list = [&](const char* name, std::span<const int> ids, auto&& text) {
    s += s.empty() ? "" : "; ";
    s += name;
    if (ids.empty()) s += " none";
    for (std::size_t i = 0; i < ids.size(); ++i) s += (i == 0 ? " " : ", ") + text(ids[i]);
  };
  list("vertices", faces.vertices, [&](int v) { return std::to_string(v + first); });
  list("edges", faces.edges, [&](int e) {
    const DomainEdge& de = domain.edges[static_cast<std::size_t>(e)];
    return std::to_string(de.a + first) + "-" + std::to_string(de.b + first);
  });
  list("facets", faces.facets, [&](int f) { return std::to_string(f + first); });
  return s;
}

LeafClassifier::LeafClassifier(const Domain3& domain) : domain_(domain), facet_pair_edges_(domain) {
  pqmesh::detail::VertexIncidence incidence = pqmesh::detail::vertex_incidence(domain);
  vertex_edges_ = std::move(incidence.edges);
  vertex_facets_ = std::move(incidence.facets);
}

bool LeafClassifier::is_superface_set(int v, const LeafFaces& faces) const {
  const auto& ve = vertex_edges_[static_cast<std::size_t>(v)];
  const auto& vf = vertex_facets_[static_cast<std::size_t>(v)];
  for (const int x : faces.vertices)
    if (x != v) return false;
  for (const int e : faces.edges)
    if (!std::binary_search(ve.begin(), ve.end(), e)) return false;
  for (const int f : faces.facets)
    if (!std::binary_search(vf.begin(), vf.end(), f)) return false;
  return true;
}

LeafClass LeafClassifier::classify(const LeafFaces& faces) const {
  auto same = [](std::span<const int> a, const std::vector<int>& b) { return std::ranges::equal(a, b); };
  if (!faces.meets_p) return {LeafKind::Outside, -1};
  if (faces.vertices.empty() && faces.edges.empty() && faces.facets.empty()) return {LeafKind::EmptyInside, -1};
  if (faces.vertices.size() == 1) {
    // §4.1.3 (a): one vertex and ALL of its superfaces. Each superface
    // contains v, which lies in P ∧ b, so a complete face list has them all.
    const int v = faces.vertices[0];
    const bool cone = same(faces.edges, vertex_edges_[static_cast<std::size_t>(v)]) &&
                      same(faces.facets, vertex_facets_[static_cast<std::size_t>(v)]);
    return cone ? LeafClass{LeafKind::VertexCone, v} : LeafClass{LeafKind::Other, -1};
  }
  if (!faces.vertices.empty()) return {LeafKind::Other, -1};
  // A piece of a united vertex box B: B, not the piece, is the thesis' box.
  if (faces.vertex_owner >= 0)
    return is_superface_set(faces.vertex_owner, faces) ? LeafClass{LeafKind::VertexCone, faces.vertex_owner}
                                                       : LeafClass{LeafKind::Other, -1};
  if (faces.edges.size() == 1) {
    const int e = faces.edges[0];
    const DomainEdge& de = domain_.edges[static_cast<std::size_t>(e)];
    const auto fs = std::minmax(de.facets[0], de.facets[1]);
    const bool cone = faces.facets.size() == 2 && faces.facets[0] == fs.first && faces.facets[1] == fs.second;
    return cone ? LeafClass{LeafKind::EdgeCone, e} : LeafClass{LeafKind::Other, -1};
  }
  if (!faces.edges.empty()) return {LeafKind::Other, -1};
  if (faces.facets.size() == 1) return {LeafKind::FacetCone, faces.facets[0]};
  if (faces.facets.size() == 2) {
    const int e = facet_pair_edges_.edge_between(faces.facets[0], faces.facets[1]);
    if (e >= 0) return {LeafKind::TwoFacet, e};
  }
  return {LeafKind::Other, -1};
}

}  // namespace pqmesh::mv3d
