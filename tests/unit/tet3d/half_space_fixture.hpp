#pragma once
// A domain that is a half-space near the unit cube: a huge tetrahedron (side
// about 170) with one face F in the plane through `o` with normal `n`, and
// its fourth vertex 100 away on F's negative side, so P lies on F's negative
// side around o. `e1` is a direction in F (nonzero, orthogonal to n).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/plc.hpp"
#include "pqmesh/vec.hpp"
#include "tet3d/facet_boxes.hpp"
#include "tet3d/points/facet_plane.hpp"
#include "tet3d/points/grid_point.hpp"

namespace pqmesh::tet3d {

struct HalfSpaceDomain {
  Domain3 domain;
  int facet = -1;  // F's index in domain.plc.facets (-1: not found, a fixture bug)
};

inline HalfSpaceDomain half_space_domain(Vec3 o, Vec3 n, Vec3 e1) {
  const Vec3 e2 = cross(n, e1);
  Plc3 plc;
  plc.vertices = {o + (100 / norm(e1)) * e1, o + (-50 / norm(e1)) * e1 + (87 / norm(e2)) * e2,
                  o + (-50 / norm(e1)) * e1 + (-87 / norm(e2)) * e2, o + (-100 / norm(n)) * n};
  const int faces[4][3] = {{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  for (const auto& f : faces) {
    Facet3 fc;
    fc.loops.push_back({f[0], f[1], f[2]});
    plc.facets.push_back(fc);
  }
  HalfSpaceDomain out{make_domain(plc), -1};
  // F is the facet without the fourth vertex (make_domain may reorder facets).
  for (std::size_t f = 0; f < out.domain.plc.facets.size(); ++f) {
    const auto& loop = out.domain.plc.facets[f].loops[0];
    if (std::find(loop.begin(), loop.end(), 3) == loop.end()) out.facet = static_cast<int>(f);
  }
  return out;
}

// The jobs of the leaves with a corner on F's negative side: without a facet
// when no corner is on its positive side, with `facet` (F's index) otherwise.
inline std::vector<BoxJob> half_space_jobs(const OctTree& t, const std::vector<std::int32_t>& leaves,
                                           const FacetPlane& plane, int facet) {
  std::vector<BoxJob> jobs;
  for (const std::int32_t leaf : leaves) {
    bool in = false, out = false;
    for (int k = 0; k < 8; ++k) {
      const Sign s = plane.side(grid_coordinates(t, key_corner(t.key(leaf), k)));
      in = in || s == Sign::Negative;
      out = out || s == Sign::Positive;
    }
    if (in && !out) jobs.push_back({leaf, -1});
    if (in && out) jobs.push_back({leaf, facet});
  }
  return jobs;
}

}  // namespace pqmesh::tet3d
