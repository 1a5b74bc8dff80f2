#pragma once
// The aspect-ratio property of thesis Theorem 7 (ch. 4) as the tests state
// it: every tetrahedron of tet_mesh (default options) has aspect ratio
// <= C / alpha, alpha the sharpest interior angle of P (compute_alpha,
// radians), with ONE constant C for every test input (the random polyhedra
// of random_polyhedra_test.cpp and the corpus models of
// generic_corpus_test.cpp).
//
// C is a MEASURED CEILING, not a derived value: the thesis proves the bound
// with an unspecified constant. Value and margin are stated where it is
// defined (below); lower it when the worst tetrahedra improve, never raise it
// silently.
#include <cmath>
#include <cstdio>
#include <string>

#include "pqmesh/alpha.hpp"
#include "pqmesh/quality.hpp"
#include "pqmesh/tetmesh.hpp"

namespace pqmesh::test {

// Measured 2026-12-02 (stops 19 and 20, the probe with check_mesh on every
// mesh): every-run seeds 0..199 max 990 (seed 45); suite seeds 0..199 max
// 2,911 (seed 175, 3,947 before the flat-cone construction); bounded seeds
// 0..199 max 17,198 (seed 172, 20,018 before), then 4,568 (seed 193); seed
// 167 11,227 -> 1,154; corpus at most 315 (cube.obj); harsh seeds 0..6 and
// 10..19 (stop 21) max 41,579 (seed 17, alpha 5.1 deg, 53M tetrahedra; a
// disabled measurement shard), 1,308 after stop 22. Stop 24: harsh seeds 0..9
// max 1,233 (seed 9), every family re-run, bounded 172 still the maximum.
// Stop 30 (facet fans in flat edge boxes): bounded 172 1,482, suite 175 803,
// harsh 10 1,972 and 12 347; the maximum is bounded 193 (4,568). C = 5,500 is 20% above it (25,000 from
// stop 13 to stop 19, 20,000 in stop 20 and from stop 25 to stop 29, 50,000
// from stop 21 to stop 24).
inline constexpr double kAspectAlphaC = kMeasuredAspectAlphaC;  // the library's copy (tetmesh.hpp)

// aspect * alpha of a mesh, for the messages.
inline double aspect_times_alpha(double max_aspect, double alpha_radians) { return max_aspect * alpha_radians; }

}  // namespace pqmesh::test
