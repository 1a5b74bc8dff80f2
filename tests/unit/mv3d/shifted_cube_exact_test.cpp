// The GMP-free shortcuts of shifted_cube.cpp against the plain rational
// (detail::Pert) computation they replace:
//   * compare(Pos, Pos) of a plane-kind Pos (a double plus s * term) with a
//     given Pert or a crossing, without making the plane kind's Pert;
//   * segment_crosses_face: the infinitesimal tie-break when the crossing's
//     constant part lies on a plane of the cube, by comparisons of doubles,
//     and the one coordinate it returns;
//   * line_hit: the side tests' infinitesimal coefficients by products of
//     signs, and the crossing with an axis-aligned triangle as the constant
//     a_d.
// Coordinates come from a coarse dyadic grid (ties on every plane: the
// degenerate cases) and from random doubles; the references below are
// written from the definitions (cube_components.hpp: C_e with planes
// lo_k - e^(k+1), hi_k + e^(k+1); a Pert's sign is its first non-zero
// coefficient).
#include <gtest/gtest.h>

#include <array>
#include <optional>
#include <random>

#include "mv3d/perturbed.hpp"
#include "mv3d/shifted_cube.hpp"
#include "pqmesh/errors.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::mv3d::detail {
namespace {

mpq_class q(double v) { return mpq_class(v); }

Pert ref_plane(const Cube& c, int axis, int side) {
  Pert p = Pert::constant(side == 0 ? axis_coord(c.lo, axis) : axis_coord(c.hi, axis));
  p.c[static_cast<std::size_t>(kE1 + axis)] = side == 0 ? -1 : 1;
  return p;
}

bool same(const Pert& a, const Pert& b) {
  for (std::size_t k = 0; k < a.c.size(); ++k)
    if (cmp(a.c[k], b.c[k]) != 0) return false;
  return true;
}

// Reference: the crossing of segment uv with the shifted face plane, every
// coordinate a Pert, compared with the shifted planes of the other axes.
bool ref_crosses(Vec3 u, Vec3 v, const Cube& c, int axis, int side, Pert* w) {
  const Pert a = ref_plane(c, axis, side);
  const auto beyond = [&](Vec3 p) { return Pert::constant(axis_coord(p, axis)) - a; };
  const int bu = side == 1 ? beyond(u).sign() : -beyond(u).sign();
  const int bv = side == 1 ? beyond(v).sign() : -beyond(v).sign();
  if ((bu > 0) == (bv > 0)) return false;
  const Pert off = a - Pert::constant(axis_coord(u, axis));
  const mpq_class den = q(axis_coord(v, axis)) - q(axis_coord(u, axis));
  for (int j = 0; j < 3; ++j) {
    if (j == axis) continue;
    Pert x = off * mpq_class((q(axis_coord(v, j)) - q(axis_coord(u, j))) / den);
    x.c[0] += q(axis_coord(u, j));
    if (compare(x, ref_plane(c, j, 0)) <= 0 || compare(x, ref_plane(c, j, 1)) >= 0) return false;
    if (w && j == (axis + 2) % 3) *w = x;
  }
  return true;
}

struct Rng {
  std::mt19937_64 gen{20261202};
  double grid() { return 0.25 * static_cast<double>(std::uniform_int_distribution<int>(0, 8)(gen)); }
  double real() { return std::uniform_real_distribution<double>(-0.2, 2.2)(gen); }
  double coord(bool on_grid) { return on_grid ? grid() : real(); }
  Vec3 point(bool on_grid) { return {coord(on_grid), coord(on_grid), coord(on_grid)}; }
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(gen); }
  Cube cube() {
    const Vec3 lo{0.25 * pick(5), 0.25 * pick(5), 0.25 * pick(5)};
    return cube_of(lo, 0.25 * (1 + pick(4)));
  }
};

TEST(ShiftedCubeExact, SegmentCrossesFaceMatchesRationalReference) {
  Rng rng;
  int crossings = 0, ties = 0;
  for (int it = 0; it < 20000; ++it) {
    const bool on_grid = it % 4 != 3;
    const Cube c = rng.cube();
    const Vec3 u = rng.point(on_grid), v = rng.point(on_grid && it % 8 != 2);
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side) {
        Pert got, want;
        const bool g = segment_crosses_face(u, v, c, axis, side, &got);
        const bool r = ref_crosses(u, v, c, axis, side, &want);
        ASSERT_EQ(g, r) << "it " << it << " axis " << axis << " side " << side;
        if (!g) continue;
        ++crossings;
        EXPECT_TRUE(same(got, want)) << "it " << it;
        const int j = (axis + 2) % 3;
        if (cmp(want.c[0], axis_coord(c.lo, j)) == 0 || cmp(want.c[0], axis_coord(c.hi, j)) == 0) ++ties;
      }
  }
  EXPECT_GT(crossings, 1000);
  EXPECT_GT(ties, 100);  // the infinitesimal tie-break was exercised
}

// A Pos of each kind with its reference Pert.
struct Sample {
  Pos pos;
  Pert value;
};

Sample plane_sample(Rng& rng) {
  const double v = rng.grid();
  const int term = rng.pick(6) == 0 ? -1 : rng.pick(5) + 1;  // -1: a plain double; else kE1 .. kD2
  const int s = term < 0 ? 0 : (rng.pick(2) == 0 ? -1 : 1);
  Pert p = Pert::constant(v);
  if (term >= 0) p.c[static_cast<std::size_t>(term)] = s;
  return {Pos::of_double(v, term, s), p};
}

Sample pert_sample(Rng& rng) {
  Pert p;
  // Constant part: a grid value, or a third of one (not a double).
  p.c[0] = rng.pick(3) == 0 ? mpq_class(q(rng.grid()) / 3) : q(rng.grid());
  for (std::size_t k = 1; k < p.c.size(); ++k)
    if (rng.pick(3) == 0) p.c[k] = mpq_class(rng.pick(7) - 3, 1 + rng.pick(3));
  return {Pos::of_pert(p), p};
}

TEST(ShiftedCubeExact, ComparePlaneKindMatchesRationalReference) {
  Rng rng;
  int exact_ties = 0;
  for (int it = 0; it < 50000; ++it) {
    const Sample x = plane_sample(rng);
    const Sample y = rng.pick(2) == 0 ? pert_sample(rng) : plane_sample(rng);
    const int want = compare(x.value, y.value);
    EXPECT_EQ(compare(x.pos, y.pos), want) << "it " << it;
    EXPECT_EQ(compare(y.pos, x.pos), -want) << "it " << it;
    if (cmp(x.value.c[0], y.value.c[0]) == 0) ++exact_ties;
  }
  EXPECT_GT(exact_ties, 1000);
}

// Reference side test of line_hit: the sign of orient2d(u, v, P) for the
// perturbed point P = (f1, f2), coefficient by coefficient in GMP.
int ref_side(const Pert& f1, const Pert& f2, Vec3 u, Vec3 v, int o1, int o2) {
  const mpq_class b1 = q(axis_coord(v, o1)) - q(axis_coord(u, o1)), b2 = q(axis_coord(v, o2)) - q(axis_coord(u, o2));
  const mpq_class c0 = (f2.c[0] - q(axis_coord(u, o2))) * b1 - (f1.c[0] - q(axis_coord(u, o1))) * b2;
  if (sgn(c0) != 0) return sgn(c0) > 0 ? 1 : -1;
  for (std::size_t k = 1; k < f1.c.size(); ++k) {
    const mpq_class ck = f2.c[k] * b1 - f1.c[k] * b2;
    if (sgn(ck) != 0) return sgn(ck) > 0 ? 1 : -1;
  }
  return 0;
}

// Reference crossing of the line with the triangle's plane (as crossing()).
Pert ref_crossing(int d, const Pert& f1, const Pert& f2, Vec3 a, Vec3 b, Vec3 c) {
  const int o1 = (d + 1) % 3, o2 = (d + 2) % 3;
  std::array<mpq_class, 3> ab, ac;
  for (int k = 0; k < 3; ++k) {
    ab[static_cast<std::size_t>(k)] = q(axis_coord(b, k)) - q(axis_coord(a, k));
    ac[static_cast<std::size_t>(k)] = q(axis_coord(c, k)) - q(axis_coord(a, k));
  }
  const std::array<mpq_class, 3> n{ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2],
                                   ab[0] * ac[1] - ab[1] * ac[0]};
  const mpq_class m1 = -n[static_cast<std::size_t>(o1)] / n[static_cast<std::size_t>(d)];
  const mpq_class m2 = -n[static_cast<std::size_t>(o2)] / n[static_cast<std::size_t>(d)];
  Pert p = (f1 - Pert::constant(axis_coord(a, o1))) * m1 + (f2 - Pert::constant(axis_coord(a, o2))) * m2;
  p.c[0] += q(axis_coord(a, d));
  return p;
}

TEST(ShiftedCubeExact, LineHitMatchesRationalReference) {
  Rng rng;
  int hits = 0, axis_aligned_hits = 0, general_lines = 0;
  for (int it = 0; it < 30000; ++it) {
    const bool on_grid = it % 4 != 3;
    const Cube cube = rng.cube();
    // Lines: a cube edge, a tether ray (y + d, z + d^2), or a probe whose
    // fixed coordinate is a Pert with a -d term.
    const int kind = rng.pick(3);
    Line line;
    Pert f1, f2;
    if (kind == 0) {
      const int e = rng.pick(12);
      line = cube_edge_line(cube, e);
      const int d = e / 4;
      f1 = ref_plane(cube, (d + 1) % 3, (e / 2) % 2);
      f2 = ref_plane(cube, (d + 2) % 3, e % 2);
    } else if (kind == 1) {
      const double y = rng.grid(), z = rng.grid();
      line = make_line(0, Pos::of_double(y, kD1, 1), Pos::of_double(z, kD2, 1));
      f1 = Pert::constant(y);
      f1.c[kD1] = 1;
      f2 = Pert::constant(z);
      f2.c[kD2] = 1;
    } else {
      const int d = rng.pick(3), a = (d + 2) % 3, side = rng.pick(2);
      f1 = pert_sample(rng).value;
      f1.c[kD1] = -1;
      f2 = ref_plane(cube, a, side);
      line = make_line(d, Pos::of_pert(f1), plane_pos(cube, a, side));
      ++general_lines;
    }
    const int d = line.d, o1 = (d + 1) % 3, o2 = (d + 2) % 3;
    Vec3 ta = rng.point(on_grid), tb = rng.point(on_grid), tc = rng.point(on_grid);
    if (it % 5 == 0) {  // an axis-aligned triangle across the line
      const double h = rng.grid();
      (d == 0 ? ta.x : d == 1 ? ta.y : ta.z) = h;
      (d == 0 ? tb.x : d == 1 ? tb.y : tb.z) = h;
      (d == 0 ? tc.x : d == 1 ? tc.y : tc.z) = h;
    }
    const int nd = static_cast<int>(orient2d_projected(ta, tb, tc, d));
    // Reference verdict.
    std::optional<bool> want;  // empty: the reference finds P on a side (line_hit throws)
    bool want_hit = nd != 0;
    if (want_hit) {
      const std::array<Vec3, 3> t{ta, tb, tc};
      bool degenerate = false;
      for (int i = 0; i < 3 && want_hit; ++i) {
        const int s =
            ref_side(f1, f2, t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>((i + 1) % 3)], o1, o2);
        if (s == 0)
          degenerate = true;
        else if (s != nd)
          want_hit = false;
      }
      if (degenerate && want_hit) want_hit = false;
      if (!degenerate) want = want_hit;
    } else {
      want = false;
    }
    Pos pos;
    bool entering = false;
    std::optional<bool> got;
    try {
      got = line_hit(line, ta, tb, tc, pos, entering);
    } catch (const InternalError&) {
    }
    if (!want) {  // P on a side line of the triangle in the reference
      if (got) {
        EXPECT_FALSE(*got) << "it " << it;  // line_hit may reject it earlier (another side)
      }
      continue;
    }
    ASSERT_TRUE(got.has_value()) << "it " << it;
    ASSERT_EQ(*got, *want) << "it " << it << " kind " << kind;
    if (!*got) continue;
    ++hits;
    EXPECT_EQ(entering, nd < 0);
    const Pert cross = ref_crossing(d, f1, f2, ta, tb, tc);
    EXPECT_TRUE(same(pos.value(), cross)) << "it " << it;
    const bool aligned = axis_coord(ta, d) == axis_coord(tb, d) && axis_coord(ta, d) == axis_coord(tc, d);
    if (aligned) {
      ++axis_aligned_hits;
      EXPECT_TRUE(pos.plane_kind());
    }
    // Against other positions along the line, with and without their Perts.
    for (int r = 0; r < 4; ++r) {
      const Sample other = r % 2 == 0 ? plane_sample(rng) : pert_sample(rng);
      EXPECT_EQ(compare(pos, other.pos), compare(cross, other.value)) << "it " << it;
      EXPECT_EQ(compare(other.pos, pos), compare(other.value, cross)) << "it " << it;
    }
  }
  EXPECT_GT(hits, 1000);
  EXPECT_GT(axis_aligned_hits, 100);
  EXPECT_GT(general_lines, 1000);
}

}  // namespace
}  // namespace pqmesh::mv3d::detail
