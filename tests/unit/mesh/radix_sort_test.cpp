// radix_sort_by_key and ordered_key (mesh/radix_sort.hpp), and the checker's
// sort_by_coordinates built on them, against plain references: std::stable_sort
// with the same key, the < and == of doubles, and the comparison sort of
// vertex ids by (x, y[, z], id) the checker used before.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "mesh/check_common.hpp"
#include "mesh/radix_sort.hpp"

namespace pqmesh {
namespace {

struct Item {
  std::uint64_t key;
  int index;  // input position: equal keys must keep increasing indices
};

// Random keys of a given width, many repeats when the width is small; mask
// patterns make some digits constant (the skipped passes) and others not.
std::vector<Item> random_items(std::mt19937_64& rng, std::size_t n, int bits, std::uint64_t mask) {
  std::vector<Item> v(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::uint64_t k = rng();
    if (bits < 64) k &= (std::uint64_t{1} << bits) - 1;
    v[i] = {k & mask, static_cast<int>(i)};
  }
  return v;
}

TEST(RadixSort, MatchesStableSortOnRandomKeys) {
  std::mt19937_64 rng(20261202);
  const int widths[] = {1, 3, 8, 9, 17, 31, 40, 63, 64};
  const std::uint64_t masks[] = {~std::uint64_t{0}, 0xff00ff00ff00ff00ull, 0x00000000ffff0000ull, 0x8000000000000001ull};
  std::vector<Item> scratch;  // reused across calls, as the checker does
  int cases = 0;
  for (const int bits : widths)
    for (const std::uint64_t mask : masks)
      for (const std::size_t n : {0u, 1u, 2u, 3u, 17u, 256u, 1000u, 5000u}) {
        std::vector<Item> v = random_items(rng, n, bits, mask);
        std::vector<Item> ref = v;
        std::stable_sort(ref.begin(), ref.end(), [](const Item& a, const Item& b) { return a.key < b.key; });
        detail::radix_sort_by_key(v, scratch, [](const Item& x) { return x.key; });
        ASSERT_EQ(v.size(), ref.size());
        for (std::size_t i = 0; i < v.size(); ++i) {
          ASSERT_EQ(v[i].key, ref[i].key) << "bits " << bits << " n " << n << " at " << i;
          ASSERT_EQ(v[i].index, ref[i].index) << "bits " << bits << " n " << n << " at " << i;
        }
        ++cases;
      }
  EXPECT_EQ(cases, 9 * 4 * 8);
}

// Several stable passes, least significant field first, give the
// lexicographic order with ties in input order (how the checker sorts faces).
TEST(RadixSort, LexicographicByRepeatedPasses) {
  std::mt19937_64 rng(7);
  struct Triple {
    int v[3];
    int index;
  };
  for (int round = 0; round < 200; ++round) {
    const int range = 1 + static_cast<int>(rng() % 40);
    std::vector<Triple> t(1 + rng() % 700);
    for (std::size_t i = 0; i < t.size(); ++i)
      t[i] = {{static_cast<int>(rng() % range), static_cast<int>(rng() % range), static_cast<int>(rng() % range)},
              static_cast<int>(i)};
    std::vector<Triple> ref = t;
    std::sort(ref.begin(), ref.end(), [](const Triple& a, const Triple& b) {
      for (int k = 0; k < 3; ++k)
        if (a.v[k] != b.v[k]) return a.v[k] < b.v[k];
      return a.index < b.index;
    });
    for (int k = 2; k >= 0; --k)
      detail::radix_sort_by_key(t, [k](const Triple& x) { return static_cast<std::uint64_t>(x.v[k]); });
    for (std::size_t i = 0; i < t.size(); ++i) ASSERT_EQ(t[i].index, ref[i].index) << "round " << round;
  }
}

std::vector<double> special_doubles() {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> v = {0.0,  -0.0,     1.0,      -1.0,      DBL_MIN,  -DBL_MIN, DBL_MAX, -DBL_MAX,
                           inf,  -inf,     0.5,      -0.5,      1e-310,   -1e-310,  4.9e-324, -4.9e-324,
                           3.0,  -3.0,     1e300,    -1e300,    0.1,      -0.1,     2.0,     -2.0};
  const std::size_t base = v.size();
  for (std::size_t i = 0; i < base; ++i) {
    v.push_back(std::nextafter(v[i], inf));
    v.push_back(std::nextafter(v[i], -inf));
  }
  return v;
}

TEST(OrderedKey, SameOrderAsDoubles) {
  std::mt19937_64 rng(11);
  std::vector<double> v = special_doubles();
  std::uniform_real_distribution<double> u(-4, 4);
  for (int i = 0; i < 300; ++i) v.push_back(u(rng));
  for (int i = 0; i < 300; ++i) v.push_back(std::ldexp(u(rng), static_cast<int>(rng() % 2000) - 1000));
  for (const double a : v)
    for (const double b : v) {
      ASSERT_EQ(detail::ordered_key(a) < detail::ordered_key(b), a < b) << a << " " << b;
      ASSERT_EQ(detail::ordered_key(a) == detail::ordered_key(b), a == b) << a << " " << b;
    }
}

// Points from a few values per coordinate (many ties, -0.0 next to +0.0,
// infinities, tiny and huge values).
template <class V>
std::vector<V> tied_points(std::mt19937_64& rng, std::size_t n) {
  const std::vector<double> values = special_doubles();
  const std::size_t pick = 1 + rng() % values.size();
  std::vector<V> p(n);
  for (V& q : p) {
    q.x = values[rng() % pick];
    q.y = values[rng() % pick];
    if constexpr (requires { q.z; }) q.z = values[rng() % pick];
  }
  return p;
}

TEST(SortByCoordinates, MatchesComparisonSort3d) {
  std::mt19937_64 rng(3);
  for (int round = 0; round < 300; ++round) {
    const auto p = tied_points<Vec3>(rng, rng() % 2000);
    ASSERT_EQ(detail::sort_by_coordinates(p), detail::sort_by_coordinates_compared(p)) << "round " << round;
  }
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3> p(20000);
  for (Vec3& q : p) q = {u(rng), u(rng), u(rng)};
  EXPECT_EQ(detail::sort_by_coordinates(p), detail::sort_by_coordinates_compared(p));
}

TEST(SortByCoordinates, MatchesComparisonSort2d) {
  std::mt19937_64 rng(5);
  for (int round = 0; round < 300; ++round) {
    const auto p = tied_points<Vec2>(rng, rng() % 2000);
    ASSERT_EQ(detail::sort_by_coordinates(p), detail::sort_by_coordinates_compared(p)) << "round " << round;
  }
}

// A NaN coordinate takes the comparison path (no key order exists).
TEST(SortByCoordinates, NanFallsBackToComparisons) {
  std::vector<Vec3> p = {{1, 0, 0}, {std::nan(""), 0, 0}, {0, 0, 0}, {1, 0, 0}};
  EXPECT_EQ(detail::sort_by_coordinates(p), detail::sort_by_coordinates_compared(p));
}

}  // namespace
}  // namespace pqmesh
