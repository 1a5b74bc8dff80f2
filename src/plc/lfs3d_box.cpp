// Exact incidence tests between triangles, segments and axis-aligned boxes,
// and the bucket grid of boundary triangles that the I3 quadrature uses to
// find cells meeting dP (pqmesh/lfs3.hpp, src/plc/lfs3d.hpp). Every decision
// is a coordinate comparison, orient2d or orient3d of input coordinates.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "lfs3d.hpp"
#include "pqmesh/errors.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh {
namespace detail {
// ---------------------------------------------------------------------------
// Exact incidence tests (every decision a coordinate comparison, orient2d or
// orient3d of input coordinates).

namespace {

// 2D coordinates of v in the plane that drops `drop`, in the cyclic order of
// orient2d_projected.
Vec2 project(Vec3 v, int drop) { return {axis_coord(v, (drop + 1) % 3), axis_coord(v, (drop + 2) % 3)}; }


// p lies on the closed 2D segment uv, given orient2d(u, v, p) == 0.
bool on_collinear_segment(Vec2 p, Vec2 u, Vec2 v) {
  return std::min(u.x, v.x) <= p.x && p.x <= std::max(u.x, v.x) && std::min(u.y, v.y) <= p.y &&
         p.y <= std::max(u.y, v.y);
}

// Closed 2D segments pq and uv meet.
bool segments_meet(Vec2 p, Vec2 q, Vec2 u, Vec2 v) {
  const Sign o1 = orient2d(p, q, u), o2 = orient2d(p, q, v), o3 = orient2d(u, v, p), o4 = orient2d(u, v, q);
  if (o1 * o2 == Sign::Negative && o3 * o4 == Sign::Negative) return true;
  return (o1 == Sign::Zero && on_collinear_segment(u, p, q)) || (o2 == Sign::Zero && on_collinear_segment(v, p, q)) ||
         (o3 == Sign::Zero && on_collinear_segment(p, u, v)) || (o4 == Sign::Zero && on_collinear_segment(q, u, v));
}

// p lies in the closed 2D triangle abc (counter-clockwise).
bool in_triangle(Vec2 p, Vec2 a, Vec2 b, Vec2 c) {
  return orient2d(a, b, p) != Sign::Negative && orient2d(b, c, p) != Sign::Negative &&
         orient2d(c, a, p) != Sign::Negative;
}

}  // namespace

// Segment against box: separating axes are the box's face normals and the
// cross products of the segment with the three axes. In the projection that
// drops axis d, the 2D test covers the two remaining face normals and the
// axis e_d x (b - a) (orient2d of the projection is the triple product with
// e_d), on which the segment projects to one value.
bool segment_meets_box(Vec3 a, Vec3 b, Vec3 lo, Vec3 hi) {
  for (int d = 0; d < 3; ++d)
    if (!segment_meets_rect(project(a, d), project(b, d), project(lo, d), project(hi, d))) return false;
  return true;
}

bool segment_meets_triangle(Vec3 p, Vec3 q, Vec3 a, Vec3 b, Vec3 c) {
  const Sign sp = orient3d(a, b, c, p), sq = orient3d(a, b, c, q);
  if (sp == sq && sp != Sign::Zero) return false;  // strictly on one side
  if (sp == Sign::Zero && sq == Sign::Zero) {
    // Coplanar: decide in a projection in which the triangle is not
    // degenerate (injective on the common plane, so incidences are kept).
    int drop = 0;
    while (drop < 3 && orient2d_projected(a, b, c, drop) == Sign::Zero) ++drop;
    if (drop == 3) throw InternalError("segment_meets_triangle: degenerate triangle");
    Vec2 A = project(a, drop), B = project(b, drop), C = project(c, drop);
    if (orient2d(A, B, C) == Sign::Negative) std::swap(B, C);
    const Vec2 P = project(p, drop), Q = project(q, drop);
    if (in_triangle(P, A, B, C) || in_triangle(Q, A, B, C)) return true;
    // Both ends outside: pq meets the triangle iff it crosses a side.
    return segments_meet(P, Q, A, B) || segments_meet(P, Q, B, C) || segments_meet(P, Q, C, A);
  }
  // pq meets the plane in exactly one point, which lies on pq; it is in the
  // closed triangle iff the line pq passes on no strict wrong side of a side.
  const Sign s1 = orient3d(p, q, a, b), s2 = orient3d(p, q, b, c), s3 = orient3d(p, q, c, a);
  const bool pos = s1 == Sign::Positive || s2 == Sign::Positive || s3 == Sign::Positive;
  const bool neg = s1 == Sign::Negative || s2 == Sign::Negative || s3 == Sign::Negative;
  return !(pos && neg);
}

// If a triangle and a box meet, either a side of the triangle meets the box
// (this covers a corner in the box), or the triangle's boundary misses the
// box; then the polygon (plane of the triangle) cap box, which is connected
// and meets the triangle, lies in the triangle's interior, and its corners
// lie on box edges: a box edge meets the triangle.
bool triangle_meets_box(Vec3 a, Vec3 b, Vec3 c, Vec3 lo, Vec3 hi) {
  if (std::max({a.x, b.x, c.x}) < lo.x || std::min({a.x, b.x, c.x}) > hi.x || std::max({a.y, b.y, c.y}) < lo.y ||
      std::min({a.y, b.y, c.y}) > hi.y || std::max({a.z, b.z, c.z}) < lo.z || std::min({a.z, b.z, c.z}) > hi.z)
    return false;
  std::array<Vec3, 8> corner;
  for (int k = 0; k < 8; ++k)
    corner[lfs_uz(k)] = {(k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z};
  int pos = 0, neg = 0;
  for (const Vec3& v : corner) {
    const Sign s = orient3d(a, b, c, v);
    pos += s == Sign::Positive;
    neg += s == Sign::Negative;
  }
  if (pos == 8 || neg == 8) return false;  // the plane separates
  if (segment_meets_box(a, b, lo, hi) || segment_meets_box(b, c, lo, hi) || segment_meets_box(c, a, lo, hi))
    return true;
  for (int k = 0; k < 8; ++k)
    for (int bit = 1; bit < 8; bit <<= 1)
      if (!(k & bit) && segment_meets_triangle(corner[lfs_uz(k)], corner[lfs_uz(k | bit)], a, b, c)) return true;
  return false;
}

// Separating axes of a triangle (or a degenerate, collinear one) and a box:
// for convex polytopes A, B, the facets of the Minkowski difference A - B are
// a facet of A plus a vertex of B, a vertex of A plus a facet of B, or an edge
// of A plus an edge of B. If 0 is not in A - B (closed A and B) or not in its
// interior (A closed, B open), one such facet's plane separates (weakly), and
// it can be taken through the feature of A (the plane of the triangle, or a
// plane through a side of the triangle supporting it and parallel to a box
// edge) or along a box face. Each test is exact: coordinate comparisons, the
// sign of orient3d on the box corners, and orient2d in the projection that
// drops the box-edge direction (that orient2d is the triple product with the
// axis, a fixed linear function on the projected box corners).
bool triangle_meets_box_sat(Vec3 a, Vec3 b, Vec3 c, Vec3 lo, Vec3 hi, bool open_box) {
  const std::array<Vec3, 3> t{a, b, c};
  // Box faces.
  for (int ax = 0; ax < 3; ++ax) {
    const double mn = std::min({axis_coord(a, ax), axis_coord(b, ax), axis_coord(c, ax)});
    const double mx = std::max({axis_coord(a, ax), axis_coord(b, ax), axis_coord(c, ax)});
    const double l = axis_coord(lo, ax), h = axis_coord(hi, ax);
    if (open_box ? (mx <= l || mn >= h) : (mx < l || mn > h)) return false;
  }
  std::array<Vec3, 8> corner;
  for (int k = 0; k < 8; ++k)
    corner[lfs_uz(k)] = {(k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z};
  bool degenerate = true;
  for (int drop = 0; drop < 3 && degenerate; ++drop) degenerate = orient2d_projected(a, b, c, drop) == Sign::Zero;
  // Plane of the triangle.
  if (!degenerate) {
    int pos = 0, neg = 0;
    for (const Vec3& v : corner) {
      const Sign s = orient3d(a, b, c, v);
      pos += s == Sign::Positive;
      neg += s == Sign::Negative;
    }
    if (open_box ? (pos == 0 || neg == 0) : (pos == 8 || neg == 8)) return false;
  }
  // A side of the triangle and a box-edge direction (the drop axis).
  for (int e = 0; e < 3; ++e) {
    const Vec3 p = t[lfs_uz(e)], q = t[lfs_uz((e + 1) % 3)], r = t[lfs_uz((e + 2) % 3)];
    for (int drop = 0; drop < 3; ++drop) {
      if (project(p, drop) == project(q, drop)) continue;  // side parallel to the axis: no plane
      const Sign sr = orient2d_projected(p, q, r, drop);
      int pos = 0, neg = 0;
      // The projected box has 4 distinct corners: k = 0..3 over the two kept axes.
      for (int k = 0; k < 4; ++k) {
        Vec3 v = lo;
        const int u = (drop + 1) % 3, w = (drop + 2) % 3;
        auto set = [&](int axis, bool high) {
          const double val = axis_coord(high ? hi : lo, axis);
          if (axis == 0) v.x = val;
          else if (axis == 1) v.y = val;
          else v.z = val;
        };
        set(u, (k & 1) != 0);
        set(w, (k & 2) != 0);
        const Sign s = orient2d_projected(p, q, v, drop);
        pos += s == Sign::Positive;
        neg += s == Sign::Negative;
      }
      bool separated;
      if (sr == Sign::Positive) separated = open_box ? pos == 0 : neg == 4;
      else if (sr == Sign::Negative) separated = open_box ? neg == 0 : pos == 4;
      else separated = open_box ? (pos == 0 || neg == 0) : (pos == 4 || neg == 4);
      if (separated) return false;
    }
  }
  return true;
}

// ---------------------------------------------------------------------------

BoundaryBuckets3::BoundaryBuckets3(const Domain3& d) : domain_(d) {
  const Vec3 lo = d.bbox_min, hi = d.bbox_max;
  const double side = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  const double mag = std::max({std::abs(lo.x), std::abs(lo.y), std::abs(lo.z), std::abs(hi.x), std::abs(hi.y),
                               std::abs(hi.z)});
  margin_ = 1e-10 * (mag + side);
  const auto nt = d.facet_triangles.size();
  gn_ = std::clamp(static_cast<int>(std::cbrt(2.0 * static_cast<double>(nt))), 1, 64);
  glo_ = lo;
  gw_ = side > 0 ? side / gn_ : 1.0;
  bucket_.assign(lfs_uz(gn_) * lfs_uz(gn_) * lfs_uz(gn_), {});
  const auto& P = d.plc.vertices;
  for (std::size_t t = 0; t < nt; ++t) {
    const auto& tr = d.facet_triangles[t];
    std::array<int, 3> i0{}, i1{};
    for (int ax = 0; ax < 3; ++ax) {
      const double v0 = axis_coord(P[lfs_uz(tr[0])], ax), v1 = axis_coord(P[lfs_uz(tr[1])], ax), v2 = axis_coord(P[lfs_uz(tr[2])], ax);
      i0[lfs_uz(ax)] = gi(std::min({v0, v1, v2}) - margin_, ax);
      i1[lfs_uz(ax)] = gi(std::max({v0, v1, v2}) + margin_, ax);
    }
    for (int k = i0[2]; k <= i1[2]; ++k)
      for (int j = i0[1]; j <= i1[1]; ++j)
        for (int i = i0[0]; i <= i1[0]; ++i) bucket_[lfs_uz((k * gn_ + j) * gn_ + i)].push_back(static_cast<int>(t));
  }
  stamp_.assign(nt, -1);
}

int BoundaryBuckets3::gi(double v, int axis) const {
  const double t = std::floor((v - axis_coord(glo_, axis)) / gw_);
  return static_cast<int>(std::clamp(t, 0.0, static_cast<double>(gn_ - 1)));
}

bool BoundaryBuckets3::box_meets_boundary(Vec3 lo, Vec3 hi, bool open_box) {
  ++stamp_id_;
  const auto& P = domain_.plc.vertices;
  std::array<int, 3> i0{}, i1{};
  for (int ax = 0; ax < 3; ++ax) {
    i0[lfs_uz(ax)] = gi(axis_coord(lo, ax) - margin_, ax);
    i1[lfs_uz(ax)] = gi(axis_coord(hi, ax) + margin_, ax);
  }
  for (int k = i0[2]; k <= i1[2]; ++k)
    for (int j = i0[1]; j <= i1[1]; ++j)
      for (int i = i0[0]; i <= i1[0]; ++i)
        for (int t : bucket_[lfs_uz((k * gn_ + j) * gn_ + i)]) {
          if (stamp_[lfs_uz(t)] == stamp_id_) continue;
          stamp_[lfs_uz(t)] = stamp_id_;
          const auto& tr = domain_.facet_triangles[lfs_uz(t)];
          const Vec3 a = P[lfs_uz(tr[0])], b = P[lfs_uz(tr[1])], c = P[lfs_uz(tr[2])];
          if (triangle_meets_box_sat(a, b, c, lo, hi, open_box)) return true;
        }
  return false;
}


}  // namespace detail
}  // namespace pqmesh
