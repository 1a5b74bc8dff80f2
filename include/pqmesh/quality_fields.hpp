#pragma once
// Per-element quality of a whole mesh, one array per measure, element order.
// The values are those of triangle_quality / tetrahedron_quality
// (pqmesh/quality.hpp) bit for bit; they are computed through a memo of
// recent element shapes, since the quadtree and octree meshes repeat a few
// thousand shapes by translation (a fraction of the time of measuring every
// element afresh).
//
// Contract: every element's indices are valid vertex indices (the mesh passed
// check_mesh, or was read and validated). Cost: O(elements), three arrays of
// doubles as the only allocation.
#include <vector>

#include "pqmesh/mesh.hpp"

namespace pqmesh {

struct QualityFields {
  std::vector<double> aspect_ratio;  // TriQuality / TetQuality::aspect_ratio
  std::vector<double> min_angle;     // degrees: smallest angle (2D) or dihedral angle (3D)
  std::vector<double> max_angle;     // degrees: largest angle (2D) or dihedral angle (3D)
};

QualityFields quality_fields(const TriMesh2& mesh);
QualityFields quality_fields(const TetMesh3& mesh);

}  // namespace pqmesh
