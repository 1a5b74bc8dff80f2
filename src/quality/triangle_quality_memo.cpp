// The shape memo of triangle_quality(); see triangle_quality_memo.hpp.
#include "quality/triangle_quality_memo.hpp"

#include <bit>
#include <cstddef>

namespace pqmesh {
namespace {

constexpr int kTableBits = 11;  // 2048 entries, ~180 KB: stays in cache

// x - y is exact: Knuth's two-difference leaves no rounding error. (NaN or
// infinite inputs give a non-zero or NaN error: not exact.)
bool exact_difference(double x, double y) {
  const double d = x - y;
  const double y_virtual = x - d, x_virtual = d + y_virtual;
  const double error = (x - x_virtual) + (y_virtual - y);
  return error == 0;
}

bool exact_differences(Vec2 a, Vec2 b, Vec2 c) {
  return exact_difference(b.x, a.x) && exact_difference(b.y, a.y) && exact_difference(c.x, a.x) &&
         exact_difference(c.y, a.y) && exact_difference(c.x, b.x) && exact_difference(c.y, b.y);
}

std::size_t slot_of(const std::uint64_t (&key)[4]) {
  std::uint64_t h = 0x9E3779B97F4A7C15ull;
  for (const std::uint64_t k : key) {
    h ^= k;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 31;
  }
  return static_cast<std::size_t>(h >> (64 - kTableBits));
}

}  // namespace

TriangleQualityMemo::TriangleQualityMemo() : table_(std::size_t{1} << kTableBits) {}

TriQuality TriangleQualityMemo::operator()(Vec2 a, Vec2 b, Vec2 c) {
  if (!exact_differences(a, b, c)) return triangle_quality(a, b, c);
  const std::uint64_t key[4] = {std::bit_cast<std::uint64_t>(b.x - a.x), std::bit_cast<std::uint64_t>(b.y - a.y),
                                std::bit_cast<std::uint64_t>(c.x - a.x), std::bit_cast<std::uint64_t>(c.y - a.y)};
  Entry& e = table_[slot_of(key)];
  if (e.used && e.key[0] == key[0] && e.key[1] == key[1] && e.key[2] == key[2] && e.key[3] == key[3])
    return e.quality;
  e.quality = triangle_quality(a, b, c);
  for (int i = 0; i < 4; ++i) e.key[i] = key[i];
  e.used = true;
  return e.quality;
}

}  // namespace pqmesh
