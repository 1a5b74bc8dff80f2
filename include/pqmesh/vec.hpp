#pragma once
// Small value types for points and vectors. Arithmetic here is plain double:
// these are constructions, never decisions (docs/DESIGN_RULES.md "Exact
// decisions"; decisions go through src/predicates).
#include <cmath>

namespace pqmesh {

struct Vec2 {
  double x = 0, y = 0;
  friend constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  friend constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  friend constexpr Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
  friend constexpr bool operator==(Vec2 a, Vec2 b) = default;
};

struct Vec3 {
  double x = 0, y = 0, z = 0;
  friend constexpr Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend constexpr Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend constexpr Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
  friend constexpr bool operator==(Vec3 a, Vec3 b) = default;
};

constexpr double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
constexpr double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
inline double norm(Vec2 a) { return std::sqrt(dot(a, a)); }

constexpr double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline double norm(Vec3 a) { return std::sqrt(dot(a, a)); }

// Coordinate number `axis` (0 = x, 1 = y, 2 = z) of p, for code that loops
// over the axes; axis_ref gives it as an lvalue.
constexpr double axis_coord(Vec3 p, int axis) { return axis == 0 ? p.x : (axis == 1 ? p.y : p.z); }
constexpr double& axis_ref(Vec3& p, int axis) { return axis == 0 ? p.x : (axis == 1 ? p.y : p.z); }

// The axis of n's largest absolute coordinate, ties to the lower axis: the
// axis to drop when a plane with normal n is projected to 2D, or to move
// along when settling a point onto it.
inline int dominant_axis(Vec3 n) {
  const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
  return ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
}

// Angle in radians between two nonzero vectors, robust near 0 and pi
// (atan2 of |a x b| and a.b instead of acos).
inline double angle_between(Vec2 a, Vec2 b) { return std::atan2(std::abs(cross(a, b)), dot(a, b)); }
inline double angle_between(Vec3 a, Vec3 b) { return std::atan2(norm(cross(a, b)), dot(a, b)); }

}  // namespace pqmesh
