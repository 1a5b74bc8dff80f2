#pragma once
// The faces of a tetrahedral mesh that lie on exactly one tetrahedron (the
// boundary triangles of a conforming mesh), found combinatorially: faces are
// compared by their vertex ids, never by coordinates.
//
// Method (memory 8 bytes per tetrahedron plus 8 per vertex, no global sort):
// every face is filed under its smallest vertex. For a tetrahedron with
// vertex ids m1 < m2 < m3 < m4 the three faces through m1 have smallest
// vertex m1 and the fourth face (m2, m3, m4) has m2, so the tetrahedron is
// listed under m1 and m2 only (a counting sort, two entries per tetrahedron).
// Then, vertex by vertex, the faces filed under it (a few dozen) are counted
// by their other two ids in a small hash table and the faces met once are
// kept; the result is sorted once at the end.
// A tetrahedron with a repeated vertex id is filed under its smallest id and
// each of its faces is compared like any other (never single with itself).
#include <array>
#include <cstdint>
#include <vector>

namespace pqmesh::mesh3d {

// Face i of tetrahedron k, as the outward face of a positive tetrahedron:
// 0 -> (k0, k2, k1), 1 -> (k0, k1, k3), 2 -> (k1, k2, k3), 3 -> (k0, k3, k2)
// (right-hand normal pointing away from the fourth vertex).
std::array<int, 3> outward_face(const std::array<int, 4>& k, int i);

// Codes 4 t + i (tetrahedron t, face i as in outward_face) of the faces whose
// sorted vertex triple occurs exactly once among all 4 n faces, in increasing
// order (by tetrahedron, then face). Vertex ids must lie in [0, vertex_count).
std::vector<std::int64_t> single_faces(const std::vector<std::array<int, 4>>& tetrahedra, int vertex_count);

}  // namespace pqmesh::mesh3d
