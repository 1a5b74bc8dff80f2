#pragma once
// Exact comparison of squared distances (docs/DESIGN_RULES.md "Exact
// decisions"). The eligibility tests of thesis Theorem 21 (|VW| <= L(E), |VW|
// <= |UW|) are decisions, so they are made on the exact binary values of the
// input doubles.
#include "pqmesh/vec.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::detail {

// Sign of |a - b|^2 - |c - d|^2, exact: a double evaluation with a bound on
// its rounding error, and GMP rationals when the bound is not cleared.
Sign compare_squared_distances(Vec2 a, Vec2 b, Vec2 c, Vec2 d);

}  // namespace pqmesh::detail
