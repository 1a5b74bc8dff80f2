// TriangleQualityMemo gives triangle_quality()'s numbers bit for bit: on
// translated copies of grid triangles (the memo's hits, including table
// collisions between many shapes), on triangles with inexact differences
// (measured directly), and on degenerate ones.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include "pqmesh/quality.hpp"
#include "quality/triangle_quality_memo.hpp"

namespace pqmesh {
namespace {

void expect_same_bits(const TriQuality& got, const TriQuality& want) {
  EXPECT_EQ(std::bit_cast<std::uint64_t>(got.min_angle_deg), std::bit_cast<std::uint64_t>(want.min_angle_deg));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(got.max_angle_deg), std::bit_cast<std::uint64_t>(want.max_angle_deg));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(got.aspect_ratio), std::bit_cast<std::uint64_t>(want.aspect_ratio));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(got.sphere_ratio), std::bit_cast<std::uint64_t>(want.sphere_ratio));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(got.radius_edge), std::bit_cast<std::uint64_t>(want.radius_edge));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(got.area), std::bit_cast<std::uint64_t>(want.area));
}

TEST(TriangleQualityMemo, TranslatedGridTriangles) {
  std::mt19937_64 rng(21);
  TriangleQualityMemo memo;
  for (int trial = 0; trial < 200000; ++trial) {
    // Corners on a dyadic grid (unit 2^-12) inside [0, 1)^2: differences
    // exact. Offsets 0..9 per axis for b and c: 10^4 shapes, so repeats
    // (hits) and more shapes than table slots (collisions).
    const double unit = 0x1p-12;
    const auto g = [&](std::uint64_t r) { return static_cast<double>(r) * unit; };
    const Vec2 a{g(rng() % 4000), g(rng() % 4000)};
    const Vec2 b{a.x + g(rng() % 10), a.y + g(rng() % 10)}, c{a.x + g(rng() % 10), a.y + g(rng() % 10)};
    expect_same_bits(memo(a, b, c), triangle_quality(a, b, c));
  }
}

TEST(TriangleQualityMemo, FullPrecisionAndDegenerate) {
  std::mt19937_64 rng(22);
  std::uniform_real_distribution<double> u(-1, 1);
  TriangleQualityMemo memo;
  for (int trial = 0; trial < 50000; ++trial) {
    const Vec2 a{u(rng), u(rng)}, b{u(rng), u(rng)};
    const Vec2 c = trial % 3 == 0 ? b : Vec2{u(rng), u(rng)};  // every third one degenerate
    expect_same_bits(memo(a, b, c), triangle_quality(a, b, c));
    expect_same_bits(memo(a, b, c), triangle_quality(a, b, c));  // again: never a stale entry
  }
}

}  // namespace
}  // namespace pqmesh
