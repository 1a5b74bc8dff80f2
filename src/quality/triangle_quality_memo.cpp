// The shape memo of triangle_quality(); see triangle_quality_memo.hpp.
#include "quality/triangle_quality_memo.hpp"

#include <bit>
#include <cstddef>

#include "quality/memo_key.hpp"

namespace pqmesh {
namespace {

using detail::exact_difference;

constexpr int kTableBits = 11;  // 2048 entries, ~180 KB: stays in cache

bool exact_differences(Vec2 a, Vec2 b, Vec2 c) {
  return exact_difference(b.x, a.x) && exact_difference(b.y, a.y) && exact_difference(c.x, a.x) &&
         exact_difference(c.y, a.y) && exact_difference(c.x, b.x) && exact_difference(c.y, b.y);
}

}  // namespace

TriangleQualityMemo::TriangleQualityMemo() : table_(std::size_t{1} << kTableBits) {}

TriQuality TriangleQualityMemo::operator()(Vec2 a, Vec2 b, Vec2 c) {
  if (!exact_differences(a, b, c)) return triangle_quality(a, b, c);
  const std::uint64_t key[4] = {std::bit_cast<std::uint64_t>(b.x - a.x), std::bit_cast<std::uint64_t>(b.y - a.y),
                                std::bit_cast<std::uint64_t>(c.x - a.x), std::bit_cast<std::uint64_t>(c.y - a.y)};
  Entry& e = table_[detail::memo_slot(key, kTableBits)];
  if (e.used && e.key[0] == key[0] && e.key[1] == key[1] && e.key[2] == key[2] && e.key[3] == key[3])
    return e.quality;
  e.quality = triangle_quality(a, b, c);
  for (int i = 0; i < 4; ++i) e.key[i] = key[i];
  e.used = true;
  return e.quality;
}

}  // namespace pqmesh
