// The mesher's integer sorts (quad2d/radix_sort.hpp) and its corner handling
// in trees deeper than one 64-bit word of packed corner coordinates holds
// (mesh_points.cpp: NarrowCorners up to about 30 levels below the domain's
// extent, WideCorners beyond).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/quadmesh.hpp"
#include "quad2d/radix_sort.hpp"

namespace pqmesh {
namespace {

using Item = std::pair<std::uint64_t, int>;

std::vector<Item> random_items(std::size_t n, std::uint64_t key_mask, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::vector<Item> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = {rng() & key_mask, static_cast<int>(i)};
  return v;
}

TEST(RadixSort, MatchesStableSortOnKeysWithDuplicates) {
  for (const int bits : {1, 11, 12, 40, 64}) {
    const std::uint64_t mask = bits == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1;
    // Few distinct keys for small widths: many ties, whose input order must survive.
    std::vector<Item> v = random_items(20000, mask, static_cast<unsigned>(bits));
    std::vector<Item> expected = v;
    std::stable_sort(expected.begin(), expected.end(), [](const Item& a, const Item& b) { return a.first < b.first; });
    std::vector<Item> scratch;
    quad2d::radix_sort(v, bits, [](const Item& x) { return x.first; }, scratch);
    EXPECT_EQ(v, expected) << bits << " bits";
  }
}

TEST(RadixSort, TwoPassesOrderBySecondKeyThenFirst) {
  std::vector<Item> v = random_items(5000, 0xFF, 7);
  for (Item& x : v) x.second = static_cast<int>(x.first >> 4);  // second key: the high nibble
  std::vector<Item> expected = v;
  std::sort(expected.begin(), expected.end(),
            [](const Item& a, const Item& b) { return std::pair(a.second, a.first) < std::pair(b.second, b.first); });
  std::vector<Item> scratch;
  quad2d::radix_sort(v, 8, [](const Item& x) { return x.first; }, scratch);
  quad2d::radix_sort(v, 4, [](const Item& x) { return static_cast<std::uint64_t>(x.second); }, scratch);
  for (std::size_t i = 0; i < v.size(); ++i) {
    EXPECT_EQ(v[i].first, expected[i].first);
    EXPECT_EQ(v[i].second, expected[i].second);
  }
}

TEST(RadixSort, ZeroBitsAndTinyInputsAreLeftAsGiven) {
  std::vector<Item> v = {{5, 0}, {3, 1}, {5, 2}};
  std::vector<Item> scratch;
  quad2d::radix_sort(v, 0, [](const Item& x) { return x.first; }, scratch);
  EXPECT_EQ(v, (std::vector<Item>{{5, 0}, {3, 1}, {5, 2}}));
  std::vector<Item> one = {{9, 0}};
  quad2d::radix_sort(one, 64, [](const Item& x) { return x.first; }, scratch);
  EXPECT_EQ(one, (std::vector<Item>{{9, 0}}));
}

// Unit square with a V notch from the top whose tip is 2^-34 above the
// bottom side: the leaves near the tip are about 34 levels below the root,
// so the packed corner coordinates need more than 64 bits.
Pslg2 deep_notch() {
  Pslg2 p;
  p.vertices = {{0, 0}, {1, 0}, {1, 1}, {0.625, 1}, {0.5, std::ldexp(1.0, -34)}, {0.375, 1}, {0, 1}};
  const int n = static_cast<int>(p.vertices.size());
  for (int i = 0; i < n; ++i) p.segments.push_back({i, (i + 1) % n});
  return p;
}

TEST(DeepTree, NotchTwoToTheMinus34IsMeshedValidlyAndDeterministically) {
  const Domain2 d = make_domain(deep_notch());
  const QuadMeshResult a = quad_mesh(d, QuadMeshOptions{});
  const CheckReport report = check_mesh(a.mesh, d);
  EXPECT_TRUE(report.valid()) << report.to_text();
  // The tree did go that deep: some mesh edge is shorter than 2^-30.
  double shortest = 1;
  for (const auto& t : a.mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const Vec2 u = a.mesh.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])];
      const Vec2 w = a.mesh.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>((k + 1) % 3)])];
      shortest = std::min(shortest, std::hypot(u.x - w.x, u.y - w.y));
    }
  EXPECT_LT(shortest, std::ldexp(1.0, -30));
  const QuadMeshResult b = quad_mesh(d, QuadMeshOptions{});
  EXPECT_EQ(a.mesh.vertices, b.mesh.vertices);
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
}

}  // namespace
}  // namespace pqmesh
