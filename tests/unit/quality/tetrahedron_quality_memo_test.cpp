// TetrahedronQualityMemo gives tetrahedron_quality()'s numbers bit for bit:
// on translated copies of grid tetrahedra (the memo's hits, with table
// collisions between more shapes than slots; translations large enough to
// change the rounding of the face-ball centres and to switch the face-ball
// filter off), on full-precision shapes translated within a binade (exact
// differences that are not few-bit dyadics), on right-angle (Kuhn) and
// degenerate grid quadruples (flat, collinear faces, coincident points), on
// tetrahedra with inexact differences, and on copies whose ROUNDED
// differences equal a flat tetrahedron's while their exact ones do not.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "pqmesh/quality.hpp"
#include "quality/tetrahedron_quality_memo.hpp"

namespace pqmesh {
namespace {

using Tet = std::array<Vec3, 4>;

void expect_same_bits(const TetQuality& got, const TetQuality& want) {
  EXPECT_EQ(std::bit_cast<std::uint64_t>(got.min_dihedral_deg), std::bit_cast<std::uint64_t>(want.min_dihedral_deg));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(got.max_dihedral_deg), std::bit_cast<std::uint64_t>(want.max_dihedral_deg));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(got.aspect_ratio), std::bit_cast<std::uint64_t>(want.aspect_ratio));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(got.sphere_ratio), std::bit_cast<std::uint64_t>(want.sphere_ratio));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(got.radius_edge), std::bit_cast<std::uint64_t>(want.radius_edge));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(got.volume), std::bit_cast<std::uint64_t>(want.volume));
}

// Counts failures instead of stopping: a broken memo fails thousands of cases.
int check(TetrahedronQualityMemo& memo, const Tet& t) {
  const TetQuality want = tetrahedron_quality(t[0], t[1], t[2], t[3]);
  const TetQuality got = memo(t[0], t[1], t[2], t[3]);
  const bool same = std::bit_cast<std::uint64_t>(got.min_dihedral_deg) == std::bit_cast<std::uint64_t>(want.min_dihedral_deg) &&
                    std::bit_cast<std::uint64_t>(got.max_dihedral_deg) == std::bit_cast<std::uint64_t>(want.max_dihedral_deg) &&
                    std::bit_cast<std::uint64_t>(got.aspect_ratio) == std::bit_cast<std::uint64_t>(want.aspect_ratio) &&
                    std::bit_cast<std::uint64_t>(got.sphere_ratio) == std::bit_cast<std::uint64_t>(want.sphere_ratio) &&
                    std::bit_cast<std::uint64_t>(got.radius_edge) == std::bit_cast<std::uint64_t>(want.radius_edge) &&
                    std::bit_cast<std::uint64_t>(got.volume) == std::bit_cast<std::uint64_t>(want.volume);
  if (!same) expect_same_bits(got, want);  // reports the first differing field
  return same ? 0 : 1;
}

Tet translated(const Tet& t, Vec3 offset) {
  return {t[0] + offset, t[1] + offset, t[2] + offset, t[3] + offset};
}

// Grid shapes: corners of a 4^3 grid of unit 2^-10 (right angles, equal
// diagonals, coplanar / collinear / coincident quadruples), and the six Kuhn
// tetrahedra of boxes with power-of-two sides, in random vertex orders.
std::vector<Tet> grid_shapes(std::mt19937_64& rng, int count) {
  std::vector<Tet> shapes;
  const double unit = 0x1p-10;
  for (int i = 0; i < count; ++i) {
    Tet t;
    if (i % 3 == 0) {
      double side[3], p[3] = {0, 0, 0};
      for (double& length : side) length = unit * static_cast<double>(1 << (rng() % 3));
      std::array<int, 3> axis = {0, 1, 2};
      std::shuffle(axis.begin(), axis.end(), rng);
      t[0] = {0, 0, 0};
      for (std::size_t k = 0; k < 3; ++k) {  // a monotone path along the box's edges
        const auto i_axis = static_cast<std::size_t>(axis[k]);
        p[i_axis] += side[i_axis];
        t[k + 1] = {p[0], p[1], p[2]};
      }
    } else {
      for (Vec3& p : t)
        p = {unit * static_cast<double>(rng() % 4), unit * static_cast<double>(rng() % 4),
             unit * static_cast<double>(rng() % 4)};
    }
    std::shuffle(t.begin(), t.end(), rng);
    shapes.push_back(t);
  }
  return shapes;
}

TEST(TetrahedronQualityMemo, TranslatedGridTetrahedra) {
  std::mt19937_64 rng(31);
  const std::vector<Tet> shapes = grid_shapes(rng, 6000);  // more shapes than the 4096 slots
  TetrahedronQualityMemo memo;
  int failures = 0;
  for (int trial = 0; trial < 300000; ++trial) {
    const Tet& shape = shapes[rng() % (trial < 100000 ? 300 : shapes.size())];  // first many repeats, then collisions
    // Offsets on the grid unit, up to 2^40: differences stay exact, the
    // rounding of the face-ball centres o + x changes, and beyond ~2^12 times
    // the size the face-ball filter is off.
    const int magnitude = static_cast<int>(rng() % 5) * 10;
    const auto offset = [&] {
      return std::ldexp(static_cast<double>(rng() % (std::uint64_t{1} << 20)), magnitude - 10) *
             (rng() % 2 == 0 ? 1.0 : -1.0);
    };
    failures += check(memo, translated(shape, {offset(), offset(), offset()}));
  }
  EXPECT_EQ(failures, 0);
}

TEST(TetrahedronQualityMemo, ShapesDifferingInOneVertexOnly) {
  // 3 x 8,000 shapes that share two of the key's three vectors: colliding
  // slots then hold shapes that differ in the third vector only.
  std::mt19937_64 rng(34);
  const double unit = 0x1p-8;
  const auto g = [&] { return unit * static_cast<double>(1 + rng() % 20); };
  TetrahedronQualityMemo memo;
  int failures = 0;
  for (std::size_t moved = 1; moved < 4; ++moved) {
    Tet base = {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
    for (int trial = 0; trial < 40000; ++trial) {
      Tet t = base;
      const std::uint64_t pick = rng() % 8000;  // shape number: the moved vertex's position
      t[moved] = {unit * static_cast<double>(pick % 20), unit * static_cast<double>(pick / 20 % 20),
                  unit * static_cast<double>(1 + pick / 400)};
      failures += check(memo, translated(t, {g(), g(), g()}));
    }
  }
  EXPECT_EQ(failures, 0);
}

TEST(TetrahedronQualityMemo, FullPrecisionShapesTranslatedWithinABinade) {
  // Coordinates in [1, 2): every difference is exact (Sterbenz), yet the
  // differences use all 52 fraction bits. 500 shapes, each met many times.
  std::mt19937_64 rng(32);
  const auto fine = [&](double range) { return std::ldexp(static_cast<double>(rng() % (std::uint64_t{1} << 50)), -52) * range; };
  std::vector<Tet> shapes;
  for (int i = 0; i < 500; ++i) {
    Tet t{};
    for (std::size_t k = 1; k < 4; ++k) t[k] = {fine(1.0), fine(1.0), fine(1.0)};
    if (i % 5 == 0) t[3] = t[1] + 0.5 * (t[2] - t[1]);  // flat: exact midpoint of two dyadics
    if (i % 7 == 0) t[3] = {t[1].x, t[2].y, t[1].z};    // right angles
    shapes.push_back(t);
  }
  TetrahedronQualityMemo memo;
  int failures = 0;
  for (int trial = 0; trial < 100000; ++trial) {
    const Tet& shape = shapes[rng() % shapes.size()];
    failures += check(memo, translated(shape, {1 + fine(0.5), 1 + fine(0.5), 1 + fine(0.5)}));
  }
  EXPECT_EQ(failures, 0);
}

TEST(TetrahedronQualityMemo, InexactDifferencesAndNearlyFlatCopies) {
  std::mt19937_64 rng(33);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  TetrahedronQualityMemo memo;
  int failures = 0;
  // Grid tetrahedra with right angles and coplanar quadruples (a at the
  // origin, b, c, d with coordinates in {-2, -1, 1, 2}), met before copies
  // whose a is moved by 2^-60 per axis: the moved copy's rounded differences
  // are the grid one's (its key is equal), its exact ones are not, so the
  // exact predicates (right angle -> slightly acute or obtuse, coplanar ->
  // not) may answer differently. Such a copy must not take the grid entry.
  for (int trial = 0; trial < 40000; ++trial) {
    const auto i = [&] {
      const double k = static_cast<double>(1 + rng() % 2);
      return rng() % 2 == 0 ? k : -k;
    };
    const Tet grid = {Vec3{0, 0, 0}, Vec3{i(), i(), i()}, Vec3{i(), i(), i()}, Vec3{i(), i(), i()}};
    Tet moved = grid;
    const auto eps = [&] { return (rng() % 2 == 0 ? 1.0 : -1.0) * 0x1p-60; };
    moved[0] = Vec3{eps(), eps(), eps()};
    failures += check(memo, grid) + check(memo, moved);
  }
  for (int trial = 0; trial < 50000; ++trial) {
    Tet t = {Vec3{coordinate(rng), coordinate(rng), coordinate(rng)}, Vec3{coordinate(rng), coordinate(rng), coordinate(rng)},
             Vec3{coordinate(rng), coordinate(rng), coordinate(rng)}, Vec3{coordinate(rng), coordinate(rng), coordinate(rng)}};
    if (trial % 4 == 0) t[3] = t[1];  // coincident points
    if (trial % 4 == 1) t[3] = t[0] + 0.5 * (t[1] - t[0]) + 0.25 * (t[2] - t[0]);  // (nearly) flat
    failures += check(memo, t);
    failures += check(memo, t);  // again: never a stale entry
  }
  EXPECT_EQ(failures, 0);
}

}  // namespace
}  // namespace pqmesh
