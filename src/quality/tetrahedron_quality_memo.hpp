#pragma once
// tetrahedron_quality() with a memo of recent tetrahedron shapes, for the
// quality fields of a large mesh (the CLI's .vtu output). Same numbers as
// tetrahedron_quality(), bit for bit. The 3D counterpart of
// TriangleQualityMemo (triangle_quality_memo.hpp).
//
// Why a shape determines the numbers: tetrahedron_shape(a, b, c, d)
// (tetrahedron_shape.hpp) reads the points only through
//   * the six differences b - a, c - a, d - a, c - b, d - b, d - c (and their
//     negations, which round the same way), and
//   * the exact predicates orient3d(a, b, c, d) and dot_sign of three of the
//     points: exact signs of polynomials in the exact differences.
// When the three differences u = b - a, v = c - a, w = d - a are computed
// exactly (Knuth's two-difference leaves no error), the four points are
// a, a + u, a + v, a + w as real numbers: the key (u, v, w) fixes them up to
// an exact translation. Then the exact predicates' signs, the exact other
// differences (c - b = v - u, ...) and hence their rounded doubles are
// functions of the bit patterns of u, v, w alone, and so is every double the
// shape holds: two translated copies with equal (u, v, w) get the same shape.
// The memo keys on those nine bit patterns and stores the shape; the
// remaining step, tetrahedron_quality(shape, {a, b, c, d}), runs the face-ball
// tests with the copy's own coordinates, as the one-step function does. A
// tetrahedron with an inexact u, v or w (or a NaN / infinite coordinate) is
// measured directly and not stored.
//
// The octree's tetrahedra are a few thousand shapes repeated (box sizes and
// split patterns; plate_holes: 6,552 shapes among 1.23 M tetrahedra), met in
// runs along the box order, so a direct-mapped table of 4,096 entries
// (~1.4 MB, a fixed size) catches nearly all of them.
#include <cstdint>
#include <vector>

#include "pqmesh/quality.hpp"
#include "pqmesh/vec.hpp"
#include "quality/tetrahedron_shape.hpp"

namespace pqmesh {

class TetrahedronQualityMemo {
 public:
  TetrahedronQualityMemo();
  TetQuality operator()(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

 private:
  struct Entry {
    std::uint64_t key[9] = {};  // bit patterns of (b - a), (c - a), (d - a): x, y, z each
    bool used = false;
    TetShape shape{};
  };
  std::vector<Entry> table_;
};

}  // namespace pqmesh
