#include "tet3d/boxes/box_jobs.hpp"

#include <algorithm>
#include <string>

namespace pqmesh::tet3d {

std::uint8_t united_block(const mv3d::OctreeBuilder& builder, std::int32_t n, int v) {
  const mv3d::Cube& b = builder.vertex_box(v);
  const mv3d::Cube s = builder.cube(n);
  const double blo[3] = {b.lo.x, b.lo.y, b.lo.z}, slo[3] = {s.lo.x, s.lo.y, s.lo.z};
  std::uint8_t block = 0;
  for (int a = 0; a < 3; ++a)
    if (blo[a] < slo[a]) block = static_cast<std::uint8_t>(block | (1u << a));
  return block;
}

BoxJobs box_jobs(const mv3d::OctreeBuilder& builder) {
  const OctTree& tree = builder.tree();
  const Domain3& domain = builder.domain();
  const mv3d::LeafClassifier classifier(domain);
  BoxJobs out;
  std::vector<char> vertex_done(domain.plc.vertices.size(), 0);
  auto problem = [&](std::int32_t n, const std::string& why) {
    out.problem_leaves.push_back(n);
    out.problems.push_back("leaf " + std::to_string(n) + " (level " + std::to_string(tree.level(n)) + "; " +
                           mv3d::faces_text(domain, mv3d::leaf_faces(builder, n)) + "): " + why);
  };
  for (const std::int32_t n : builder.leaves_by_id()) {
    const mv3d::NodeData3& d = builder.data(n);
    const mv3d::LeafClass c = classifier.classify(mv3d::leaf_faces(builder, n));
    ++out.leaves[static_cast<std::size_t>(c.kind)];
    if (!d.has_component) continue;
    if (d.vertex_owner >= 0) {
      ++out.united_pieces;
      const int v = d.vertex_owner;
      // A piece holds v's cone only (kind VertexCone by the united-box rule,
      // or EmptyInside); anything else would be left unmeshed by the cone.
      if (c.kind != mv3d::LeafKind::VertexCone && c.kind != mv3d::LeafKind::EmptyInside)
        problem(n, std::string("a piece of the united box of vertex ") +
                       std::to_string(v + domain.plc.source.first_id) + " of kind " + mv3d::to_string(c.kind));
      if (!std::binary_search(d.vertices.begin(), d.vertices.end(), v)) continue;
      if (vertex_done[static_cast<std::size_t>(v)]++) continue;
      // The united box: 2x2x2 leaves of n's size; which side per axis.
      out.jobs.push_back({n, -1, BoxKind::Vertex, v, united_block(builder, n, v)});
      // Leaves of another component inside B (the far wall of a narrow slot
      // at its mouth) are not pieces of it: they get their own jobs by kind
      // (below); the vertex box's squares see only v's sectors of its facets
      // (square_cases.hpp), so both mesh their own component of each square.
      continue;
    }
    switch (c.kind) {
      case mv3d::LeafKind::EmptyInside: out.jobs.push_back({n, -1, BoxKind::Empty, -1, 0}); break;
      case mv3d::LeafKind::FacetCone: out.jobs.push_back({n, -1, BoxKind::Facet, c.apex, 0}); break;
      case mv3d::LeafKind::EdgeCone: out.jobs.push_back({n, -1, BoxKind::Edge, c.apex, 0}); break;
      case mv3d::LeafKind::TwoFacet: out.jobs.push_back({n, -1, BoxKind::TwoFacet, c.apex, 0}); break;
      case mv3d::LeafKind::VertexCone: problem(n, "a vertex cone outside every united box"); break;
      default: problem(n, std::string("kind ") + mv3d::to_string(c.kind)); break;
    }
  }
  const int first_id = domain.plc.source.first_id;
  for (const mv3d::OctreeBuilder::UnitedClash& c : builder.united_clashes())
    problem(c.leaf, c.second >= 0 ? "a piece of the united boxes of vertices " + std::to_string(c.first + first_id) +
                                        " and " + std::to_string(c.second + first_id)
                                  : "in the component of vertex " + std::to_string(c.first + first_id) +
                                        " in its united box, not a piece of it");
  std::sort(out.problems.begin(), out.problems.end());
  out.problems.erase(std::unique(out.problems.begin(), out.problems.end()), out.problems.end());
  std::sort(out.problem_leaves.begin(), out.problem_leaves.end());
  out.problem_leaves.erase(std::unique(out.problem_leaves.begin(), out.problem_leaves.end()), out.problem_leaves.end());
  return out;
}

}  // namespace pqmesh::tet3d
