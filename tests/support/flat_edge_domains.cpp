#include "support/flat_edge_domains.hpp"

#include "support/random_domains.hpp"

namespace pqmesh::test {

Plc3 facet_triangles_as_facets(const Domain3& d) {
  Plc3 p;
  p.vertices = d.plc.vertices;
  for (std::size_t t = 0; t < d.facet_triangles.size(); ++t) {
    const auto& tri = d.facet_triangles[t];
    p.facets.push_back({{{tri[0], tri[1], tri[2]}}, 100 + static_cast<int>(t)});
  }
  return p;
}

Domain3 every_run_seed_as_triangles(std::uint64_t seed) {
  return make_domain(facet_triangles_as_facets(make_domain(random_polyhedron(seed, every_run_polyhedron_options()))));
}

}  // namespace pqmesh::test
