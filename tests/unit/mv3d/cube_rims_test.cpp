// Tests of mv3d::adjacent_duplicates and mv3d::cube_rims (cube_rims.hpp).
//
// Oracle (random neighbouring cube pairs over the corpus and random
// polyhedra): each cube is voxelised (n^3 cell centres; a centre's status is
// carried from its x-neighbour when the segment between them meets no facet
// triangle or crosses exactly one at an interior point, else decided by
// locate()); inside centres whose segment meets no triangle are joined
// (union-find), so each oracle component lies in one true component. The
// common face F (small's face) is sampled on a (2n)^2 grid; a sample q that
// locate() puts strictly inside P is attached in each cube to the cell
// centre nearest to it when the closed segment between them meets no
// triangle. A sample on ∂P inside a facet triangle lying in F gives the pair
// of that triangle's components (the rule of cube_rims.hpp). Oracle components are mapped to the module's numbering by
// components()'s marked points (one centre each; mark location is itself
// checked against a flood fill in cube_components_oracle_test). Each sample
// attached in both cubes yields an oracle pair, which must be among the
// module's pairs ("mismatch" otherwise). A module pair the oracle does not
// see is retried on grids 2 and 4 times as fine, then counted "skipped" (a region
// of F thinner than the grid). Independently of the grids, every sample the
// module reports must be located by locate() inside P (off a facet lying in
// F) or on ∂P (inside a facet triangle lying in F), and the hinted overload
// must give the same pairs.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "mv3d/cube_components.hpp"
#include "mv3d/cube_rims.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/read_domain.hpp"
#include "predicates/predicates.hpp"
#include "support/paths.hpp"
#include "support/random_domains.hpp"

namespace pqmesh::mv3d {
namespace {

double co(Vec3 p, int k) { return k == 0 ? p.x : (k == 1 ? p.y : p.z); }
Vec3 with(Vec3 p, int k, double v) {
  if (k == 0) p.x = v;
  else if (k == 1) p.y = v;
  else p.z = v;
  return p;
}

Domain3 load(const std::string& name) { return make_domain(read_plc(test::data_path("3d/" + name))); }

// 0: pq misses the closed triangle; 1: crosses it at one interior point with
// p, q strictly on opposite sides; 2: any other contact.
int segment_triangle(Vec3 p, Vec3 q, Vec3 a, Vec3 b, Vec3 c) {
  const Sign sp = orient3d(a, b, c, p), sq = orient3d(a, b, c, q);
  if (sp == sq && sp != Sign::Zero) return 0;
  if (sp == Sign::Zero && sq == Sign::Zero) {
    // Coplanar: conservative (bounding boxes).
    for (int k = 0; k < 3; ++k)
      if (std::max(co(p, k), co(q, k)) < std::min({co(a, k), co(b, k), co(c, k)}) ||
          std::min(co(p, k), co(q, k)) > std::max({co(a, k), co(b, k), co(c, k)}))
        return 0;
    return 2;
  }
  const Sign e1 = orient3d(p, q, a, b), e2 = orient3d(p, q, b, c), e3 = orient3d(p, q, c, a);
  const bool all_pos = e1 != Sign::Negative && e2 != Sign::Negative && e3 != Sign::Negative;
  const bool all_neg = e1 != Sign::Positive && e2 != Sign::Positive && e3 != Sign::Positive;
  if (!all_pos && !all_neg) return 0;
  return sp != Sign::Zero && sq != Sign::Zero && e1 != Sign::Zero && e2 != Sign::Zero && e3 != Sign::Zero ? 1 : 2;
}

struct Near {
  const Domain3& d;
  std::vector<int> tris;
  Near(const Domain3& dom, const Cube& c) : d(dom) {
    for (std::size_t t = 0; t < d.facet_triangles.size(); ++t) {
      bool out = false;
      for (int k = 0; k < 3 && !out; ++k) {
        double mn = 1e300, mx = -1e300;
        for (const int v : d.facet_triangles[t]) {
          mn = std::min(mn, co(d.plc.vertices[static_cast<std::size_t>(v)], k));
          mx = std::max(mx, co(d.plc.vertices[static_cast<std::size_t>(v)], k));
        }
        out = mx < co(c.lo, k) || mn > co(c.hi, k);
      }
      if (!out) tris.push_back(static_cast<int>(t));
    }
  }
  // (number of triangles met, capped at 2; whether the single one is crossed strictly)
  std::pair<int, bool> segment(Vec3 p, Vec3 q) const {
    int count = 0;
    bool strict = false;
    for (const int t : tris) {
      const auto& tri = d.facet_triangles[static_cast<std::size_t>(t)];
      const int r = segment_triangle(p, q, d.plc.vertices[static_cast<std::size_t>(tri[0])], d.plc.vertices[static_cast<std::size_t>(tri[1])],
                                     d.plc.vertices[static_cast<std::size_t>(tri[2])]);
      if (r == 0) continue;
      if (++count == 1) strict = r == 1;
      else return {2, false};
    }
    return {count, strict};
  }
};

int root(std::vector<int>& p, int x) {
  while (p[static_cast<std::size_t>(x)] != x) x = p[static_cast<std::size_t>(x)] = p[static_cast<std::size_t>(p[static_cast<std::size_t>(x)])];
  return x;
}

// Voxel components of P ∩ C, mapped to components()'s numbering.
struct Voxels {
  Cube c;
  int n = 0;
  std::vector<Vec3> pts;
  std::vector<int> module_comp;  // per cell: module component, -1 outside P
  Voxels(const Domain3& d, const Near& near, const Cube& cube, int cells) : c(cube), n(cells) {
    const std::size_t total = static_cast<std::size_t>(n) * static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
    pts.resize(total);
    std::vector<signed char> in(total, -1);
    std::vector<int> parent(total);
    std::iota(parent.begin(), parent.end(), 0);
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) pts[index(i, j, k)] = centre(i, j, k);
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const std::size_t me = index(i, j, k);
          const std::array<std::pair<bool, std::size_t>, 3> back{std::pair{i > 0, i > 0 ? index(i - 1, j, k) : 0},
                                                                 std::pair{j > 0, j > 0 ? index(i, j - 1, k) : 0},
                                                                 std::pair{k > 0, k > 0 ? index(i, j, k - 1) : 0}};
          for (const auto& [ok, o] : back) {
            if (!ok) continue;
            const auto [count, strict] = near.segment(pts[o], pts[me]);
            if (in[me] < 0 && count == 0) in[me] = in[o];
            if (in[me] < 0 && count == 1 && strict) in[me] = static_cast<signed char>(1 - in[o]);
            if (in[me] == 1 && in[o] == 1 && count == 0) parent[static_cast<std::size_t>(root(parent, static_cast<int>(me)))] = root(parent, static_cast<int>(o));
            if (in[me] < 0) {
              in[me] = locate(d, pts[me]) == Location::Inside ? 1 : 0;
              if (in[me] == 1 && in[o] == 1 && count == 0) parent[static_cast<std::size_t>(root(parent, static_cast<int>(me)))] = root(parent, static_cast<int>(o));
            }
          }
          if (in[me] < 0) in[me] = locate(d, pts[me]) == Location::Inside ? 1 : 0;
        }
    std::vector<int> rep;  // one cell per oracle component
    std::vector<int> comp_of_root(total, -1);
    for (std::size_t x = 0; x < total; ++x) {
      if (in[x] != 1) continue;
      int& r = comp_of_root[static_cast<std::size_t>(root(parent, static_cast<int>(x)))];
      if (r < 0) {
        r = static_cast<int>(rep.size());
        rep.push_back(static_cast<int>(x));
      }
    }
    std::vector<Vec3> marks;
    for (const int x : rep) marks.push_back(pts[static_cast<std::size_t>(x)]);
    const CubeComponents cc = components(d, cube, true, marks);
    module_comp.assign(total, -1);
    for (std::size_t x = 0; x < total; ++x)
      if (in[x] == 1) module_comp[x] = cc.mark_component[static_cast<std::size_t>(comp_of_root[static_cast<std::size_t>(root(parent, static_cast<int>(x)))])];
  }
  std::size_t index(int i, int j, int k) const { return static_cast<std::size_t>((k * n + j) * n + i); }
  Vec3 centre(int i, int j, int k) const {
    const auto f = [&](int a, int idx) { return co(c.lo, a) + (co(c.hi, a) - co(c.lo, a)) * (idx + 0.5) / n; };
    return {f(0, i), f(1, j), f(2, k)};
  }
  // The module component of the cell nearest to q if [q, centre] meets no triangle, else -2.
  int attach(const Near& near, Vec3 q) const {
    std::array<int, 3> idx{};
    for (int a = 0; a < 3; ++a) {
      const double t = (co(q, a) - co(c.lo, a)) / (co(c.hi, a) - co(c.lo, a)) * n;
      idx[static_cast<std::size_t>(a)] = std::clamp(static_cast<int>(std::floor(t)), 0, n - 1);
    }
    const std::size_t x = index(idx[0], idx[1], idx[2]);
    if (near.segment(q, pts[x]).first != 0) return -2;
    return module_comp[x];
  }
};

struct Tally {
  int with_p = 0, multi_compared = 0;  // pairs whose F meets P in area; of those, with several components on a side
  int pairs = 0, compared = 0, skipped = 0, mismatched = 0, multi = 0, oracle_pairs = 0, samples_checked = 0, unresolved = 0, in_plane = 0;
};

int of_triangle(const CubeComponents& cc, int t) {
  for (const auto& [tri, k] : cc.triangle_component)
    if (tri == t) return k;
  ADD_FAILURE() << "a facet triangle lying in F is not among a cube's triangles";
  return -1;
}

// Oracle pairs on grid n (module numbering).
std::set<std::pair<int, int>> oracle_pairs(const Domain3& d, const Cube& big, const Cube& small, int axis, double w, int n) {
  const Near nb(d, big), ns(d, small);
  const Voxels vb(d, nb, big, n), vs(d, ns, small, n);
  const CubeComponents cb = components(d, big), cs = components(d, small);
  std::set<std::pair<int, int>> out;
  const int ua = (axis + 1) % 3, va = (axis + 2) % 3, m = 2 * n;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      Vec3 q = with(with(with(Vec3{0, 0, 0}, axis, w), ua, co(small.lo, ua) + (co(small.hi, ua) - co(small.lo, ua)) * (i + 0.5) / m), va,
                    co(small.lo, va) + (co(small.hi, va) - co(small.lo, va)) * (j + 0.5) / m);
      const Location l = locate(d, q);
      if (l == Location::Boundary) {
        // On a facet triangle lying in F (strictly inside it, else skipped):
        // both closed cubes hold it, in one component each.
        for (const int t : ns.tris) {
          const auto& tri = d.facet_triangles[static_cast<std::size_t>(t)];
          std::array<Vec2, 3> p2;
          bool flat = true;
          for (std::size_t k = 0; k < 3; ++k) {
            const Vec3 v = d.plc.vertices[static_cast<std::size_t>(tri[k])];
            flat = flat && co(v, axis) == w;
            p2[k] = {co(v, ua), co(v, va)};
          }
          if (!flat) continue;
          const Vec2 q2{co(q, ua), co(q, va)};
          const Sign s0 = orient2d(p2[0], p2[1], q2), s1 = orient2d(p2[1], p2[2], q2), s2 = orient2d(p2[2], p2[0], q2);
          if (s0 == Sign::Zero || s0 != s1 || s1 != s2) continue;
          out.insert({of_triangle(cb, t), of_triangle(cs, t)});
          break;
        }
        continue;
      }
      if (l != Location::Inside) continue;
      const int kb = vb.attach(nb, q), ks = vs.attach(ns, q);
      if (kb == -2 || ks == -2) continue;
      out.insert({kb, ks});
    }
  return out;
}

void check_pair(const Domain3& d, const std::string& name, const Cube& big, const Cube& small, Tally& t) {
  ++t.pairs;
  const DuplicateAdjacency adj = adjacent_duplicates(d, big, small);
  t.unresolved += adj.unresolved;
  {
    // The hinted overload (candidates: the triangles meeting a cube twice as
    // large around each, corner 0 walked from its corner 0) gives the same answer.
    const auto parent_hint = [&](const Cube& c, std::vector<int>& cand) {
      const double h = c.hi.x - c.lo.x;
      const Cube parent = cube_of({c.lo.x - h / 2, c.lo.y - h / 4, c.lo.z - h}, 2 * h);  // contains c
      cand = triangles_meeting(d, parent);
      return CubeHint{cand, false, corner0_in_from(d, c, parent, corner0_in(d, parent), cand)};
    };
    std::vector<int> cb, cs;
    const CubeHint hb = parent_hint(big, cb), hs = parent_hint(small, cs);
    EXPECT_EQ(adjacent_duplicates(d, big, hb, small, hs).pairs, adj.pairs) << name;
  }
  const std::set<std::pair<int, int>> got(adj.pairs.begin(), adj.pairs.end());
  const std::size_t nb = components(d, big).components.size(), ns = components(d, small).components.size();
  t.multi += nb > 1 || ns > 1;
  for (const auto& [kb, ks] : got)
    if (kb < 0 || ks < 0 || static_cast<std::size_t>(kb) >= nb || static_cast<std::size_t>(ks) >= ns) {
      ++t.mismatched;
      ADD_FAILURE() << name << ": pair out of range";
      return;
    }
  for (const RimSample& s : adj.samples_small) {
    ++t.samples_checked;
    const Location l = locate(d, s.point);
    t.in_plane += s.in_plane_triangle >= 0;
    if (l != (s.in_plane_triangle >= 0 ? Location::Boundary : Location::Inside)) {
      ++t.mismatched;
      ADD_FAILURE() << name << ": a sample is not where the module says";
      return;
    }
  }
  bool all_seen = false;
  for (const int n : {10, 20, 40}) {
    const std::set<std::pair<int, int>> want = oracle_pairs(d, big, small, adj.axis, adj.value, n);
    t.oracle_pairs += static_cast<int>(want.size());
    for (const auto& p : want)
      if (!got.count(p)) {
        ++t.mismatched;
        ADD_FAILURE() << name << ": oracle pair (" << p.first << ", " << p.second << ") not reported; big lo (" << big.lo.x << ", "
                      << big.lo.y << ", " << big.lo.z << ") side " << big.hi.x - big.lo.x << ", small lo (" << small.lo.x << ", "
                      << small.lo.y << ", " << small.lo.z << ") side " << small.hi.x - small.lo.x;
        return;
      }
    all_seen = want.size() == got.size();
    if (all_seen) break;
  }
  ++(all_seen ? t.compared : t.skipped);
  t.with_p += all_seen && !got.empty();
  t.multi_compared += all_seen && !got.empty() && (nb > 1 || ns > 1);
  if (!all_seen && std::getenv("MV3D_VERBOSE"))
    std::cout << "skip " << name << " big lo (" << big.lo.x << ", " << big.lo.y << ", " << big.lo.z << ") side " << big.hi.x - big.lo.x
              << ", small lo (" << small.lo.x << ", " << small.lo.y << ", " << small.lo.z << ") side " << small.hi.x - small.lo.x << "\n";
}

// A random small cube near the domain's features and a face neighbour of
// size 1 or 2 times it whose face contains small's face.
std::vector<std::pair<Cube, Cube>> random_pairs(const Domain3& d, std::uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  const auto uni = [&] { return static_cast<double>(rng() >> 11) * 0x1p-53; };
  const Vec3 lo = d.bbox_min, hi = d.bbox_max;
  const double ext = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  std::vector<std::pair<Cube, Cube>> out;
  for (int i = 0; i < count; ++i) {
    Cube small;
    // Sides and positions on a dyadic grid of the domain's extent, as octree boxes have.
    double unit = 1;
    while (unit < ext) unit *= 2;
    while (unit / 2 >= ext) unit /= 2;
    const double side = unit / static_cast<double>(1 << (2 + rng() % 4));
    const auto snap = [&](double v) { return std::floor(v / side) * side; };
    if (i % 2 == 0) {
      const Vec3 v = d.plc.vertices[static_cast<std::size_t>(rng() % d.plc.vertices.size())];
      small = cube_of({snap(v.x - side * uni()), snap(v.y - side * uni()), snap(v.z - side * uni())}, side);
    } else {
      small = cube_of({snap(lo.x + ext * uni()), snap(lo.y + ext * uni()), snap(lo.z + ext * uni())}, side);
    }
    const int axis = static_cast<int>(rng() % 3), s = static_cast<int>(rng() % 2);
    const double bside = rng() % 2 ? side : 2 * side;
    Vec3 blo = small.lo;
    for (int a = 0; a < 3; ++a) {
      if (a == axis) blo = with(blo, a, s == 0 ? co(small.lo, a) - bside : co(small.hi, a));
      else if (bside > side && rng() % 2) blo = with(blo, a, co(small.lo, a) - side);
    }
    out.push_back({cube_of(blo, bside), small});
  }
  return out;
}

void report(const char* what, const Tally& t) {
  std::cout << what << ": pairs " << t.pairs << " (several components on a side " << t.multi << "), compared " << t.compared
            << " (F meets P in area " << t.with_p << ", of which several components on a side " << t.multi_compared << ")"
            << ", skipped " << t.skipped << ", mismatched " << t.mismatched << ", oracle pairs " << t.oracle_pairs
            << ", module samples checked " << t.samples_checked << " (in a facet lying in F " << t.in_plane
            << "), unresolved slabs " << t.unresolved << "\n";
}

TEST(CubeRimsOracle, Corpus) {
  Tally t;
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(test::data_path("3d")))
    if (e.path().extension() == ".poly") files.push_back(e.path().filename().string());
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 5u);
  std::uint64_t seed = 7;
  for (const std::string& f : files) {
    const Domain3 d = load(f);
    for (const auto& [big, small] : random_pairs(d, seed++, 40)) check_pair(d, f, big, small, t);
  }
  report("corpus", t);
  EXPECT_EQ(t.mismatched, 0);
  EXPECT_EQ(t.unresolved, 0);
  // Coverage floors (measured with these seeds: 520 compared, 173 with P on
  // F, 17 with duplicates; 40 pairs per file keep the test near 4 s).
  EXPECT_GT(t.compared, 500);
  EXPECT_GT(t.with_p, 150);
  EXPECT_GT(t.multi_compared, 12);
  EXPECT_LT(t.skipped * 50, t.pairs);  // under 2 %
}

TEST(CubeRimsOracle, RandomPolyhedra) {
  Tally t;
  for (std::uint64_t seed = 0; seed < 8; ++seed) {
    const Domain3 d = make_domain(test::random_polyhedron(seed));
    for (const auto& [big, small] : random_pairs(d, 500 + seed, 40)) check_pair(d, test::describe_polyhedron(seed), big, small, t);
  }
  report("random polyhedra", t);
  EXPECT_EQ(t.mismatched, 0);
  EXPECT_EQ(t.unresolved, 0);
  // Coverage floors (measured: 318 compared, 108 with P on F, 9 with
  // duplicates; 24 seeds gave 952 / 302 / 32 with 0 mismatches).
  EXPECT_GT(t.compared, 300);
  EXPECT_GT(t.with_p, 90);
  EXPECT_GT(t.multi_compared, 6);
  EXPECT_LT(t.skipped * 50, t.pairs);  // under 2 %
}

// The module component of a point (off ∂P) of the cube.
int comp_at(const Domain3& d, const Cube& c, Vec3 p) {
  const std::vector<Vec3> marks{p};
  return components(d, c, true, marks).mark_component[0];
}

TEST(CubeRims, SlotBetweenProngs) {
  // prongs_slot: prongs x < 0.49951 and x > 0.50049 for y in [0.25, 1],
  // z in [0, 0.25]. Both boxes cut the two prongs above the base: two
  // duplicates each, adjacent across the common face y = 0.5 only prong to
  // prong.
  const Domain3 d = load("prongs_slot.poly");
  const Cube big = cube_of({0.25, 0.5, -0.125}, 0.5), small = cube_of({0.4375, 0.375, 0.0625}, 0.125);
  ASSERT_EQ(components(d, big).components.size(), 2u);
  ASSERT_EQ(components(d, small).components.size(), 2u);
  const int bl = comp_at(d, big, {0.45, 0.7, 0.1}), br = comp_at(d, big, {0.55, 0.7, 0.1});
  const int sl = comp_at(d, small, {0.45, 0.4, 0.1}), sr = comp_at(d, small, {0.55, 0.4, 0.1});
  ASSERT_NE(bl, br);
  ASSERT_NE(sl, sr);
  const DuplicateAdjacency adj = adjacent_duplicates(d, big, small);
  EXPECT_EQ(adj.axis, 1);
  EXPECT_EQ(adj.value, 0.5);
  const std::vector<std::pair<int, int>> want = [&] {
    std::vector<std::pair<int, int>> w{{bl, sl}, {br, sr}};
    std::sort(w.begin(), w.end());
    return w;
  }();
  EXPECT_EQ(adj.pairs, want);
  // Same-size neighbours with the face the other way round.
  const Cube upper = cube_of({0.4375, 0.5, 0.0625}, 0.125);
  const DuplicateAdjacency adj2 = adjacent_duplicates(d, upper, small);
  EXPECT_EQ(adj2.pairs.size(), 2u);
  // Rims: each prong duplicate of `small` meets faces y = lo, y = hi and its
  // side wall faces (z = lo/hi), but not the other prong's side x.
  const CubeRims rims = cube_rims(d, small);
  const std::vector<int> mask = rims.face_mask();
  ASSERT_EQ(mask.size(), 2u);
  EXPECT_TRUE(mask[static_cast<std::size_t>(sl)] & (1 << 0));         // x = lo face: left prong only
  EXPECT_FALSE(mask[static_cast<std::size_t>(sl)] & (1 << 1));
  EXPECT_TRUE(mask[static_cast<std::size_t>(sr)] & (1 << 1));
  EXPECT_FALSE(mask[static_cast<std::size_t>(sr)] & (1 << 0));
  for (int f = 2; f < 6; ++f) {
    EXPECT_TRUE(mask[static_cast<std::size_t>(sl)] & (1 << f)) << f;
    EXPECT_TRUE(mask[static_cast<std::size_t>(sr)] & (1 << f)) << f;
  }
}

TEST(CubeRims, Cavity) {
  // cube_cavity: [0, 4]^3 minus the cavity [1, 3]^3. The face x = 2 of the
  // small box cuts the cavity's corner: an L-shaped region, one pair; a box
  // inside the cavity has no components and no pairs.
  const Domain3 d = load("cube_cavity.poly");
  const Cube big = cube_of({1, 0.5, 0.5}, 1), small = cube_of({2, 0.75, 0.75}, 0.5);
  const DuplicateAdjacency adj = adjacent_duplicates(d, big, small);
  EXPECT_EQ(adj.pairs, (std::vector<std::pair<int, int>>{{0, 0}}));
  const Cube hollow = cube_of({1.5, 1.5, 1.5}, 0.5), next = cube_of({2, 1.5, 1.5}, 0.5);
  EXPECT_TRUE(components(d, hollow).components.empty());
  EXPECT_TRUE(adjacent_duplicates(d, hollow, next).pairs.empty());
  // A face straddling the cavity wall x = 1 from inside the wall.
  const Cube wall = cube_of({0.5, 1.5, 1.5}, 0.5), into = cube_of({1, 1.5, 1.5}, 0.5);
  const DuplicateAdjacency w = adjacent_duplicates(d, wall, into);
  ASSERT_EQ(components(d, into).components.size(), 1u);  // the thin sliver of the wall kept by the shift
  EXPECT_EQ(w.pairs, (std::vector<std::pair<int, int>>{{0, 0}}));  // a facet lying in F: adjacent
  EXPECT_FALSE(w.samples_small.empty());
  for (const RimSample& s : w.samples_small) EXPECT_GE(s.in_plane_triangle, 0);
}

TEST(CubeRims, CurveAndPointContact) {
  // Unit cube P. `a` touches P along its facet x = 1 (a thin component), `b`
  // along the edge x = 1, y = 1 only; their common face y = 1 meets P in
  // that edge: no region of positive area, not adjacent.
  const Domain3 d = load("cube.poly");
  const Cube a = cube_of({1, 0.5, 0.25}, 0.5), b = cube_of({1, 1, 0.25}, 0.5);
  ASSERT_EQ(components(d, a).components.size(), 1u);
  ASSERT_EQ(components(d, b).components.size(), 1u);
  EXPECT_TRUE(adjacent_duplicates(d, a, b).pairs.empty());
  // Touching at the corner (1, 1, 1) only.
  const Cube c = cube_of({1, 1, 1}, 0.5), e = cube_of({1, 1, 0.5}, 0.5);
  ASSERT_EQ(components(d, c).components.size(), 1u);
  EXPECT_TRUE(adjacent_duplicates(d, e, c).pairs.empty());
  // A facet lying in F: adjacent (the inside box and the thin component).
  const Cube in = cube_of({0.5, 0.25, 0.25}, 0.5), out = cube_of({1, 0.375, 0.375}, 0.25);
  EXPECT_EQ(adjacent_duplicates(d, in, out).pairs, (std::vector<std::pair<int, int>>{{0, 0}}));
  // Not face neighbours.
  EXPECT_THROW(adjacent_duplicates(d, in, cube_of({2, 2, 2}, 0.25)), std::invalid_argument);
}

}  // namespace
}  // namespace pqmesh::mv3d
