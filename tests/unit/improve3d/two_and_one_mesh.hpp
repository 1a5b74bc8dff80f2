#pragma once
// The hand-built mesh of the CollapseMesh tests (collapse_retry_test.cpp,
// star_time_test.cpp): two tetrahedra sharing face 0 1 2 (apexes 3 and 4) and
// a third one, 5 6 7 8, apart from them, so the stars a change touches are
// known by hand.
#include "pqmesh/mesh.hpp"

namespace pqmesh::test {

inline TetMesh3 two_and_one() {
  TetMesh3 m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.3, 0.3, -1},
                {5, 0, 0}, {6, 0, 0}, {5, 1, 0}, {5, 0, 1}};
  m.tetrahedra = {{0, 1, 2, 3}, {0, 2, 1, 4}, {5, 6, 7, 8}};
  return m;
}

}  // namespace pqmesh::test
