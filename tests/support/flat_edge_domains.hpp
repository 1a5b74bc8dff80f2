#pragma once
// The flat-edge stress construction (tests/unit/mesh3d/flat_edge_test.cpp,
// worst_box_freeze_test.cpp): a domain whose every facet triangle is a facet
// of its own marker, so every diagonal of a facet becomes a flat edge (a
// 180-degree edge of P the mesh must recover).
#include <cstdint>

#include "pqmesh/domain.hpp"
#include "pqmesh/plc.hpp"

namespace pqmesh::test {

// The facet triangles of `d` (make_domain's triangulation), each a facet
// with marker 100 + its index.
Plc3 facet_triangles_as_facets(const Domain3& d);

// Every-run random polyhedron `seed` (random_domains.hpp) so split.
Domain3 every_run_seed_as_triangles(std::uint64_t seed);

}  // namespace pqmesh::test
