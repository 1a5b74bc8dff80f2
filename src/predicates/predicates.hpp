#pragma once
// Exact geometric predicates (DESIGN.md §3).
//
// Every predicate returns the exact sign of a polynomial in the input
// coordinates, which are taken as the exact binary values of the doubles.
// Implementation: the determinant is evaluated in double together with a
// bound on its rounding error (a constant times machine epsilon times the
// permanent, the same expression with every term replaced by its absolute
// value); when the double result does not clear the bound, the determinant is
// recomputed exactly with GMP rationals. There are no tolerances: Zero means
// exactly degenerate.
//
// Tie-break: the predicates report Zero honestly. A caller that must decide a
// degenerate case does so by a symbolic perturbation documented at the call
// site (docs/ALGORITHM.md lists them), never by a tolerance.
#include "pqmesh/vec.hpp"

namespace pqmesh {

enum class Sign : int { Negative = -1, Zero = 0, Positive = 1 };

constexpr Sign operator-(Sign s) { return static_cast<Sign>(-static_cast<int>(s)); }
constexpr Sign sign_of(double v) { return v > 0 ? Sign::Positive : (v < 0 ? Sign::Negative : Sign::Zero); }
constexpr Sign operator*(Sign a, Sign b) { return static_cast<Sign>(static_cast<int>(a) * static_cast<int>(b)); }

// Positive when a, b, c turn counter-clockwise: sign of det(b - a, c - a).
Sign orient2d(Vec2 a, Vec2 b, Vec2 c);

// Positive when det(b - a, c - a, d - a) > 0: d lies on the side of triangle
// abc that its right-hand normal points to (positive tetrahedron volume).
Sign orient3d(Vec3 a, Vec3 b, Vec3 c, Vec3 d);

// orient2d of the projections of a, b, c onto the coordinate plane that drops
// axis `drop` (0 = x, 1 = y, 2 = z); the remaining axes keep their cyclic
// order (drop x -> (y, z), drop y -> (z, x), drop z -> (x, y)), so for a planar
// polygon with normal n the sign equals sign(n[drop]) times its true turn.
Sign orient2d_projected(Vec3 a, Vec3 b, Vec3 c, int drop);

// Positive when d lies strictly inside the circle through a, b, c, which must
// be counter-clockwise (the sign flips for a clockwise triangle).
Sign incircle(Vec2 a, Vec2 b, Vec2 c, Vec2 d);

// Positive when e lies strictly inside the sphere through a, b, c, d, which
// must have orient3d(a, b, c, d) > 0 (the sign flips otherwise).
Sign insphere(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 e);

// Sign of the dot product (b - a) . (c - a): Positive when the angle bac is
// acute, Zero when right, Negative when obtuse.
Sign dot_sign(Vec2 a, Vec2 b, Vec2 c);
Sign dot_sign(Vec3 a, Vec3 b, Vec3 c);

// Sign of (b - a) . (d - c) for two independent directions.
Sign dot_sign(Vec3 a, Vec3 b, Vec3 c, Vec3 d);

// Sign of a - b for two coordinates (trivially exact; named for clarity).
constexpr Sign compare(double a, double b) { return a > b ? Sign::Positive : (a < b ? Sign::Negative : Sign::Zero); }

}  // namespace pqmesh
