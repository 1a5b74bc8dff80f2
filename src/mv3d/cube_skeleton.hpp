#pragma once
// Components of P ∩ C off the fast path: steps 3-6 of the cube_components.cpp
// outline (sheets, the skeleton K of ∂C_e with its probe lines, the tethers
// of floaters, and the walks along K).
#include <span>
#include <vector>

#include "mv3d/cube_components.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh::mv3d::detail {

// Fills out.components, out.triangle_component and out.mark_component.
// tris: exactly the facet triangles meeting C_e, sorted, not empty;
// corner0_in: corner 0 of C_e lies in P.
void components_by_skeleton(const Domain3& domain, const Cube& cube, const std::vector<int>& tris, bool corner0_in,
                            std::span<const Vec3> marks, CubeComponents& out);

}  // namespace pqmesh::mv3d::detail
