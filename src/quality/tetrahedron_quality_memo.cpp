// The shape memo of tetrahedron_quality(); see tetrahedron_quality_memo.hpp.
#include "quality/tetrahedron_quality_memo.hpp"

#include <bit>
#include <cstddef>

#include "quality/memo_key.hpp"

namespace pqmesh {
namespace {

using detail::exact_difference;

constexpr int kTableBits = 12;  // 4096 entries of ~330 bytes

bool exact_difference(const Vec3& p, const Vec3& q) {
  return exact_difference(p.x, q.x) && exact_difference(p.y, q.y) && exact_difference(p.z, q.z);
}

// b - a, c - a, d - a are exact (the other three differences need not be:
// see the header).
bool exact_differences(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return exact_difference(b, a) && exact_difference(c, a) && exact_difference(d, a);
}

}  // namespace

TetrahedronQualityMemo::TetrahedronQualityMemo() : table_(std::size_t{1} << kTableBits) {}

TetQuality TetrahedronQualityMemo::operator()(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  if (!exact_differences(a, b, c, d)) return tetrahedron_quality(a, b, c, d);
  const Vec3 u = b - a, v = c - a, w = d - a;
  const std::uint64_t key[9] = {
      std::bit_cast<std::uint64_t>(u.x), std::bit_cast<std::uint64_t>(u.y), std::bit_cast<std::uint64_t>(u.z),
      std::bit_cast<std::uint64_t>(v.x), std::bit_cast<std::uint64_t>(v.y), std::bit_cast<std::uint64_t>(v.z),
      std::bit_cast<std::uint64_t>(w.x), std::bit_cast<std::uint64_t>(w.y), std::bit_cast<std::uint64_t>(w.z)};
  Entry& e = table_[detail::memo_slot(key, kTableBits)];
  bool hit = e.used;
  for (int i = 0; i < 9 && hit; ++i) hit = e.key[i] == key[i];
  if (!hit) {
    e.shape = tetrahedron_shape(a, b, c, d);
    for (int i = 0; i < 9; ++i) e.key[i] = key[i];
    e.used = true;
  }
  return tetrahedron_quality(e.shape, {a, b, c, d});
}

}  // namespace pqmesh
