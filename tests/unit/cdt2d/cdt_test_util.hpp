#pragma once
// Independent oracles for the cdt2d tests: a convex hull by Andrew's monotone
// chain, edge bookkeeping by sorting, brute-force constraint chains, and a
// seeded point generator. Every decision is an exact predicate; nothing here
// uses the module under test.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "cdt2d/constrained_delaunay.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/mesh.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::cdt2d::test {

using Tris = std::vector<std::array<int, 3>>;

// Uniform double in [0, 1) with 53 random bits (portable, unlike
// std::uniform_real_distribution).
// A validated domain's vertices with its loop sides as constraints (interior on the left).
inline CdtInput loops_as_constraints(const Domain2& d) {
  CdtInput in;
  in.points = d.pslg.vertices;
  for (const auto& loop : d.loops)
    for (std::size_t k = 0; k < loop.size(); ++k) in.constraints.push_back({loop[k], loop[(k + 1) % loop.size()]});
  return in;
}

inline double unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }

inline std::vector<Vec2> random_points(std::uint64_t seed, int n) {
  std::mt19937_64 rng(seed);
  std::vector<Vec2> p(static_cast<std::size_t>(n));
  for (auto& q : p) q = {unit(rng), unit(rng)};
  return p;
}

// Reorder points along the z-order (Morton) curve of their bounding box.
inline void sort_z_order(std::vector<Vec2>& pts) {
  if (pts.empty()) return;
  Vec2 lo = pts[0], hi = pts[0];
  for (Vec2 p : pts) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  auto spread = [](std::uint64_t v) {
    v = (v | (v << 16)) & 0x0000FFFF0000FFFFull;
    v = (v | (v << 8)) & 0x00FF00FF00FF00FFull;
    v = (v | (v << 4)) & 0x0F0F0F0F0F0F0F0Full;
    v = (v | (v << 2)) & 0x3333333333333333ull;
    v = (v | (v << 1)) & 0x5555555555555555ull;
    return v;
  };
  auto quant = [](double v, double a, double b) {
    const double t = b > a ? (v - a) / (b - a) : 0.0;
    return static_cast<std::uint64_t>(std::clamp(t, 0.0, 1.0) * 4294967295.0);
  };
  std::vector<std::pair<std::uint64_t, Vec2>> keyed;
  keyed.reserve(pts.size());
  for (Vec2 p : pts) keyed.push_back({spread(quant(p.x, lo.x, hi.x)) | (spread(quant(p.y, lo.y, hi.y)) << 1), p});
  std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::size_t i = 0; i < pts.size(); ++i) pts[i] = keyed[i].second;
}

// Number of input points on the boundary of the convex hull (corners and
// points in the relative interior of hull sides). Strict hull by the monotone
// chain (pops on non-left turns), then every point is tested against every
// hull side. Requires at least three non-collinear points.
inline int hull_boundary_count(const std::vector<Vec2>& pts) {
  std::vector<Vec2> s = pts;
  std::sort(s.begin(), s.end(), [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  std::vector<Vec2> h(2 * s.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    while (k >= 2 && orient2d(h[k - 2], h[k - 1], s[i]) != Sign::Positive) --k;
    h[k++] = s[i];
  }
  for (std::size_t i = s.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && orient2d(h[k - 2], h[k - 1], s[i]) != Sign::Positive) --k;
    h[k++] = s[i];
  }
  h.resize(k - 1);  // corners, counter-clockwise
  int count = 0;
  for (Vec2 p : pts) {
    for (std::size_t i = 0; i < h.size(); ++i) {
      const Vec2 a = h[i], b = h[(i + 1) % h.size()];
      if (orient2d(a, b, p) == Sign::Zero && dot_sign(p, a, b) != Sign::Positive) {  // on the closed side
        ++count;
        break;
      }
    }
  }
  return count;
}

inline std::uint64_t edge_key(int a, int b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

// Brute-force: the input points on the closed segment a-b, ordered from a to
// b. A constraint must appear as the chain of edges between them.
inline std::vector<int> constraint_chain(const std::vector<Vec2>& pts, int a, int b) {
  std::vector<int> on;
  const Vec2 lo{std::min(pts[a].x, pts[b].x), std::min(pts[a].y, pts[b].y)};
  const Vec2 hi{std::max(pts[a].x, pts[b].x), std::max(pts[a].y, pts[b].y)};
  for (int i = 0; i < static_cast<int>(pts.size()); ++i) {
    if (i == a || i == b) continue;
    const Vec2 p = pts[i];
    if (p.x < lo.x || p.x > hi.x || p.y < lo.y || p.y > hi.y) continue;  // exact comparisons
    if (orient2d(pts[a], pts[b], pts[i]) == Sign::Zero && dot_sign(pts[i], pts[a], pts[b]) == Sign::Negative)
      on.push_back(i);  // angle a-i-b is straight: i strictly between a and b
  }
  const Vec2 A = pts[a];
  std::sort(on.begin(), on.end(), [&](int i, int j) {
    // Along the segment: i before j when j lies beyond i seen from a.
    return dot_sign(pts[i], A, pts[j]) == Sign::Negative;
  });
  on.insert(on.begin(), a);
  on.push_back(b);
  return on;
}

// Undirected edge keys (min, max) of all constraint chains.
inline std::vector<std::uint64_t> constraint_edge_keys(const std::vector<Vec2>& pts,
                                                       const std::vector<std::array<int, 2>>& constraints) {
  std::vector<std::uint64_t> keys;
  for (const auto& c : constraints) {
    const std::vector<int> chain = constraint_chain(pts, c[0], c[1]);
    for (std::size_t i = 0; i + 1 < chain.size(); ++i)
      keys.push_back(edge_key(std::min(chain[i], chain[i + 1]), std::max(chain[i], chain[i + 1])));
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

inline TriMesh2 to_mesh(const std::vector<Vec2>& pts, const Tris& tris, bool compact) {
  TriMesh2 m;
  if (!compact) {
    m.vertices = pts;
    m.triangles = tris;
    return m;
  }
  std::vector<int> id(pts.size(), -1);
  for (const auto& t : tris)
    for (int v : t)
      if (id[v] < 0) {
        id[v] = static_cast<int>(m.vertices.size());
        m.vertices.push_back(pts[v]);
      }
  for (const auto& t : tris) m.triangles.push_back({id[t[0]], id[t[1]], id[t[2]]});
  return m;
}

// Everything a constrained Delaunay triangulation of the whole hull must
// satisfy: counter-clockwise triangles, each directed edge at most once,
// boundary = hull (count 2n - h - 2 and h boundary edges), every constraint
// chain present, every interior non-constraint edge locally Delaunay (exact
// incircle <= 0), and the library's topology checker agrees.
inline void expect_cdt(const std::vector<Vec2>& pts, const std::vector<std::array<int, 2>>& constraints,
                       const Tris& tris, const std::string& what) {
  SCOPED_TRACE(what);
  const int n = static_cast<int>(pts.size());
  const int h = hull_boundary_count(pts);
  EXPECT_EQ(static_cast<long>(tris.size()), 2L * n - h - 2);
  struct Half {
    std::uint64_t key;
    int opposite;
  };
  std::vector<Half> halves;
  halves.reserve(3 * tris.size());
  int bad_orientation = 0;
  for (const auto& t : tris) {
    if (orient2d(pts[t[0]], pts[t[1]], pts[t[2]]) != Sign::Positive) ++bad_orientation;
    for (int i = 0; i < 3; ++i) halves.push_back({edge_key(t[(i + 1) % 3], t[(i + 2) % 3]), t[i]});
  }
  EXPECT_EQ(bad_orientation, 0);
  std::sort(halves.begin(), halves.end(), [](const Half& a, const Half& b) { return a.key < b.key; });
  auto find = [&](std::uint64_t key) -> const Half* {
    auto it =
        std::lower_bound(halves.begin(), halves.end(), key, [](const Half& a, std::uint64_t k) { return a.key < k; });
    return it != halves.end() && it->key == key ? &*it : nullptr;
  };
  int repeated = 0, boundary = 0, not_delaunay = 0;
  for (std::size_t i = 0; i + 1 < halves.size(); ++i)
    if (halves[i].key == halves[i + 1].key) ++repeated;
  const std::vector<std::uint64_t> cons = constraint_edge_keys(pts, constraints);
  for (const Half& e : halves) {
    const int a = static_cast<int>(e.key >> 32), b = static_cast<int>(e.key & 0xffffffffu);
    const Half* twin = find(edge_key(b, a));
    if (!twin) {
      ++boundary;
      continue;
    }
    if (std::binary_search(cons.begin(), cons.end(), edge_key(std::min(a, b), std::max(a, b)))) continue;
    // Triangle (e.opposite, a, b) is counter-clockwise; its twin's apex must
    // not be strictly inside the circumcircle.
    if (incircle(pts[e.opposite], pts[a], pts[b], pts[twin->opposite]) == Sign::Positive) ++not_delaunay;
  }
  EXPECT_EQ(repeated, 0);
  EXPECT_EQ(boundary, h);
  EXPECT_EQ(not_delaunay, 0);
  int missing = 0;
  for (std::uint64_t k : cons) {
    const int a = static_cast<int>(k >> 32), b = static_cast<int>(k & 0xffffffffu);
    if (!find(edge_key(a, b)) && !find(edge_key(b, a))) ++missing;
  }
  EXPECT_EQ(missing, 0);
  const CheckReport report = check_mesh_topology(to_mesh(pts, tris, false));
  EXPECT_TRUE(report.valid()) << report.to_text();
}

}  // namespace pqmesh::cdt2d::test
