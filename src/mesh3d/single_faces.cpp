#include "mesh3d/single_faces.hpp"

#include <algorithm>
#include <cstddef>
#include <utility>

namespace pqmesh::mesh3d {

std::array<int, 3> outward_face(const std::array<int, 4>& k, int i) {
  switch (i) {
    case 0: return {k[0], k[2], k[1]};
    case 1: return {k[0], k[1], k[3]};
    case 2: return {k[1], k[2], k[3]};
    default: return {k[0], k[3], k[2]};
  }
}

namespace {

// The two smallest ids of a tetrahedron (equal when the smallest repeats).
std::array<int, 2> two_smallest(const std::array<int, 4>& k) {
  int a = std::min(k[0], k[1]), b = std::max(k[0], k[1]);
  for (int i = 2; i < 4; ++i) {
    const int v = k[static_cast<std::size_t>(i)];
    if (v < a) {
      b = a;
      a = v;
    } else if (v < b) {
      b = v;
    }
  }
  return {a, b};
}

// The three ids in increasing order (a sorting network: the same triple
// std::sort gives, without its call; this runs four times per filed
// tetrahedron).
std::array<int, 3> sorted3(std::array<int, 3> f) {
  if (f[0] > f[1]) std::swap(f[0], f[1]);
  if (f[1] > f[2]) std::swap(f[1], f[2]);
  if (f[0] > f[1]) std::swap(f[0], f[1]);
  return f;
}

constexpr std::uint32_t kEmpty = 0xffffffffu;

// Table slot of a packed (b, c) key: the high bits of a multiplicative hash
// (Fibonacci hashing) folded to the low end, so masking keeps good bits.
inline std::size_t slot_hash(std::uint64_t bc) {
  const std::uint64_t h = bc * 0x9e3779b97f4a7c15ull;
  return static_cast<std::size_t>(h >> 32);
}

struct FiledFace {
  std::uint64_t bc;   // (b << 32) | c: the other two vertex ids, b <= c (ids >= 0)
  std::int64_t code;  // 4 t + i
};

FiledFace filed_face(int b, int c, std::int64_t code) {
  return {(std::uint64_t{static_cast<std::uint32_t>(b)} << 32) | static_cast<std::uint32_t>(c), code};
}

// outward_face's index of the face opposite position j of the tetrahedron:
// face 0 omits k3, 1 omits k2, 2 omits k0, 3 omits k1.
constexpr int kFaceOpposite[4] = {2, 3, 1, 0};

// The vertex positions 0..3 of tetrahedron k in increasing order of their ids
// (a five-comparator network); false when an id repeats.
bool sorted_positions(const std::array<int, 4>& k, std::array<int, 4>& pos) {
  pos = {0, 1, 2, 3};
  const auto order = [&](int i, int j) {
    if (k[static_cast<std::size_t>(pos[i])] > k[static_cast<std::size_t>(pos[j])]) std::swap(pos[i], pos[j]);
  };
  order(0, 1);
  order(2, 3);
  order(0, 2);
  order(1, 3);
  order(1, 2);
  for (int i = 0; i < 3; ++i)
    if (k[static_cast<std::size_t>(pos[i])] == k[static_cast<std::size_t>(pos[i + 1])]) return false;
  return true;
}

}  // namespace

std::vector<std::int64_t> single_faces(const std::vector<std::array<int, 4>>& tetrahedra, int vertex_count) {
  const auto nv = static_cast<std::size_t>(std::max(vertex_count, 0));
  // Counting sort of the tetrahedra under their two smallest ids (one entry
  // when they are equal): offset[v] .. offset[v + 1] lists v's tetrahedra.
  std::vector<std::size_t> offset(nv + 1, 0);
  for (const auto& k : tetrahedra) {
    const auto [a, b] = two_smallest(k);
    ++offset[static_cast<std::size_t>(a) + 1];
    if (b != a) ++offset[static_cast<std::size_t>(b) + 1];
  }
  for (std::size_t v = 0; v < nv; ++v) offset[v + 1] += offset[v];
  std::vector<std::int32_t> filed(offset[nv]);
  {
    std::vector<std::size_t> fill(offset.begin(), offset.end() - 1);
    for (std::size_t t = 0; t < tetrahedra.size(); ++t) {
      const auto [a, b] = two_smallest(tetrahedra[t]);
      filed[fill[static_cast<std::size_t>(a)]++] = static_cast<std::int32_t>(t);
      if (b != a) filed[fill[static_cast<std::size_t>(b)]++] = static_cast<std::int32_t>(t);
    }
  }
  std::vector<std::int64_t> singles;
  std::vector<FiledFace> here;
  std::vector<std::uint32_t> slot;  // record index per table slot, or kEmpty
  std::vector<unsigned char> seen;  // per record: 1 alone so far, 2 shared
  for (std::size_t v = 0; v < nv; ++v) {
    here.clear();
    for (std::size_t j = offset[v]; j < offset[v + 1]; ++j) {
      const auto t = static_cast<std::size_t>(filed[j]);
      const auto& k = tetrahedra[t];
      const auto code = [&](int opposite) { return static_cast<std::int64_t>(4 * t) + kFaceOpposite[opposite]; };
      std::array<int, 4> pos{};
      if (sorted_positions(k, pos)) {
        // Distinct ids s0 < s1 < s2 < s3 (s_i = k[pos[i]]): the faces with
        // smallest vertex s0 omit s3, s2, s1; the one with smallest s1 omits
        // s0 (the tetrahedron is filed under s0 and s1 only).
        const int s1 = k[static_cast<std::size_t>(pos[1])], s2 = k[static_cast<std::size_t>(pos[2])],
                  s3 = k[static_cast<std::size_t>(pos[3])];
        if (k[static_cast<std::size_t>(pos[0])] == static_cast<int>(v)) {
          here.push_back(filed_face(s1, s2, code(pos[3])));
          here.push_back(filed_face(s1, s3, code(pos[2])));
          here.push_back(filed_face(s2, s3, code(pos[1])));
        } else {
          here.push_back(filed_face(s2, s3, code(pos[0])));
        }
        continue;
      }
      for (int i = 0; i < 4; ++i) {  // a repeated id: each face sorted on its own
        const std::array<int, 3> f = sorted3(outward_face(k, i));
        if (f[0] == static_cast<int>(v)) here.push_back(filed_face(f[1], f[2], static_cast<std::int64_t>(4 * t) + i));
      }
    }
    // A face is single when no other record of v has its (b, c): counted in
    // a small open-addressing table keyed by bc (linear probing, at most half
    // full), cleared per vertex. The order does not matter here: singles are
    // sorted at the end.
    if (seen.size() < here.size()) seen.resize(here.size());
    std::size_t cap = 16;
    while (cap < 2 * here.size()) cap *= 2;
    if (slot.size() < cap) slot.resize(cap);
    std::fill(slot.begin(), slot.begin() + static_cast<std::ptrdiff_t>(cap), kEmpty);
    const std::size_t mask = cap - 1;
    for (std::size_t i = 0; i < here.size(); ++i) {
      std::size_t h = slot_hash(here[i].bc) & mask;
      while (slot[h] != kEmpty && here[slot[h]].bc != here[i].bc) h = (h + 1) & mask;
      if (slot[h] == kEmpty) {
        slot[h] = static_cast<std::uint32_t>(i);
        seen[i] = 1;
      } else {
        seen[slot[h]] = 2;  // the first record of the face now has company
        seen[i] = 2;
      }
    }
    for (std::size_t i = 0; i < here.size(); ++i)
      if (seen[i] == 1) singles.push_back(here[i].code);
  }
  std::sort(singles.begin(), singles.end());
  return singles;
}

}  // namespace pqmesh::mesh3d
