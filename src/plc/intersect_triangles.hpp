#pragma once
// Exact intersection tests between closed segments and triangles in 3D
// (orient3d, and orient2d in an exact axis projection for coplanar cases).
// Every triangle passed here is non-degenerate, and `drop` names an axis along
// which it projects to a non-degenerate triangle.
#include <array>

#include "pqmesh/vec.hpp"

namespace pqmesh::detail {

using Tri3 = std::array<Vec3, 3>;

// The closed segment pq and the closed triangle t have a common point.
bool segment_meets_triangle(Vec3 p, Vec3 q, const Tri3& t, int drop);

// The closed triangles have a common point.
bool triangles_meet(const Tri3& t, int drop_t, const Tri3& u, int drop_u);

// Triangles (v, a, b) and (v, c, d) share the vertex v (and no other): do they
// have a common point other than v?
bool triangles_meet_beyond_vertex(Vec3 v, Vec3 a, Vec3 b, int drop_t, Vec3 c, Vec3 d, int drop_u);

// Triangles (u, w, c) and (u, w, d) share the edge uw: do they have a common
// point off that edge? (Only when coplanar with c and d on one side of uw.)
bool triangles_overlap_beyond_edge(Vec3 u, Vec3 w, Vec3 c, Vec3 d, int drop);

}  // namespace pqmesh::detail
