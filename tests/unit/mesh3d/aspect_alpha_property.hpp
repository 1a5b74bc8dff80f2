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

// Measured 2026-12-02 (stop 19, the probe with check_mesh on every mesh):
// every-run seeds 0..199 max 990 (seed 45); suite seeds 0..199 max 3,947
// (seed 175; seed 67, 13,292 before, is 1,047 with two cone points);
// bounded seeds 0..199 max 20,018 (seed 172), then 11,227 (seed 167),
// 4,568 (seed 193); corpus at most 315 (cube.obj). C = 25,000 is that
// maximum with a margin of about a quarter (first set for bounded seed 20,
// 21,453 on stop 13's code, 2,558 or less since).
inline constexpr double kAspectAlphaC = kMeasuredAspectAlphaC;  // the library's copy (tetmesh.hpp)

// aspect * alpha of a mesh, for the messages.
inline double aspect_times_alpha(double max_aspect, double alpha_radians) { return max_aspect * alpha_radians; }

}  // namespace pqmesh::test
