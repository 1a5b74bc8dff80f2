// Hand cases for mv3d::components (components of P ∩ C, thesis §4.1.6).
// Expected values are read off the corpus files: data/3d/cube.poly is [0,1]^3
// with vertex ids 0..7 = (0,0,0) (1,0,0) (1,1,0) (0,1,0) (0,0,1) (1,0,1)
// (1,1,1) (0,1,1) and facets z=0, z=1, y=0, x=1, y=1, x=0 (ids 0..5);
// cube_cavity.poly is [0,4]^3 minus the cavity [1,3]^3 (vertices 8..15,
// facets 6..11); prongs_slot.poly is a plate [0,1]^2 x [0,1/4] with a slot
// of width 1/1024 at x = 1/2 for y >= 1/4.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "mv3d/cube_components.hpp"
#include "support/random_domains.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/read_domain.hpp"
#include "support/paths.hpp"

namespace pqmesh::mv3d {
namespace {

Domain3 load(const char* name) { return make_domain(read_plc(test::data_path(std::string("3d/") + name))); }

std::vector<int> iota_vec(int a, int b) {
  std::vector<int> v;
  for (int i = a; i < b; ++i) v.push_back(i);
  return v;
}

TEST(CubeComponents, CubeEqualToDomainIsOneComponentWithAllFaces) {
  const Domain3 d = load("cube.poly");
  const CubeComponents r = components(d, cube_of({0, 0, 0}, 1));
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_FALSE(r.fast_path);  // no vertex is common to all six facets
  EXPECT_EQ(r.components[0].vertices, iota_vec(0, 8));
  EXPECT_EQ(r.components[0].facets, iota_vec(0, 6));
  EXPECT_EQ(r.components[0].edges.size(), 12u);
}

TEST(CubeComponents, TouchingAtACornerFromOutside) {
  const Domain3 d = load("cube.poly");
  const CubeComponents r = components(d, cube_of({1, 1, 1}, 1));
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_TRUE(r.fast_path);
  EXPECT_EQ(r.components[0].vertices, std::vector<int>({6}));
  EXPECT_EQ(r.components[0].facets, std::vector<int>({1, 3, 4}));
  EXPECT_EQ(r.components[0].edges.size(), 3u);
}

TEST(CubeComponents, TouchingAlongAFacetFromOutside) {
  const Domain3 d = load("cube.poly");
  const CubeComponents r = components(d, {{1, 0, 0}, {2, 1, 1}});
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_EQ(r.components[0].vertices, std::vector<int>({1, 2, 5, 6}));
  EXPECT_EQ(r.components[0].facets, std::vector<int>({0, 1, 2, 3, 4}));
  EXPECT_EQ(r.components[0].edges.size(), 8u);  // the 4 sides of x = 1 and the 4 edges along x
}

TEST(CubeComponents, DisjointInsideAndCornerCubes) {
  const Domain3 d = load("cube.poly");
  EXPECT_TRUE(components(d, cube_of({2, 2, 2}, 1)).components.empty());
  const CubeComponents in = components(d, cube_of({0.25, 0.25, 0.25}, 0.5));
  ASSERT_EQ(in.components.size(), 1u);
  EXPECT_TRUE(in.components[0].whole_cube);
  const CubeComponents corner = components(d, cube_of({-1, -1, -1}, 1.5));
  ASSERT_EQ(corner.components.size(), 1u);
  EXPECT_TRUE(corner.fast_path);
  EXPECT_EQ(corner.components[0].vertices, std::vector<int>({0}));
  EXPECT_EQ(corner.components[0].facets, std::vector<int>({0, 2, 5}));
}

TEST(CubeComponents, SlotSeparatesTheProngs) {
  const Domain3 d = load("prongs_slot.poly");
  EXPECT_EQ(components(d, cube_of({0.25, 0.5, 0}, 0.5)).components.size(), 2u);
  EXPECT_EQ(components(d, cube_of({0.25, 0, 0}, 0.5)).components.size(), 1u);  // joined below the slot
}

TEST(CubeComponents, FloaterInsideTheCubeIsTethered) {
  const Domain3 d = load("cube_cavity.poly");
  const CubeComponents r = components(d, cube_of({0.5, 0.5, 0.5}, 3));
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_EQ(r.components[0].facets, iota_vec(6, 12));
  EXPECT_EQ(r.components[0].vertices, iota_vec(8, 16));
  // C equal to the cavity: P ∩ C is the cavity's surface, one component.
  const CubeComponents s = components(d, cube_of({1, 1, 1}, 2));
  ASSERT_EQ(s.components.size(), 1u);
  EXPECT_EQ(s.components[0].facets, iota_vec(6, 12));
  // The whole domain.
  const CubeComponents w = components(d, cube_of({0, 0, 0}, 4));
  ASSERT_EQ(w.components.size(), 1u);
  EXPECT_EQ(w.components[0].facets, iota_vec(0, 12));
  EXPECT_EQ(w.components[0].vertices, iota_vec(0, 16));
}

TEST(CubeComponents, RimInsideOneFaceIsJoinedThroughTheFace) {
  // C = [2,5] x [0.5,3.5]^2 cuts the cavity at x = 2: the cavity's rim is a
  // square loop inside the face x = 2 (it crosses no cube edge), so only a
  // probe line across that face joins the cavity walls to the rest. Facets
  // meeting C: x = 4 (id 3) and the cavity walls z = 1, z = 3, y = 1, x = 3,
  // y = 3 (ids 6..10); vertices in C: the cavity corners with x = 3.
  const Domain3 d = load("cube_cavity.poly");
  const CubeComponents r = components(d, cube_of({2, 0.5, 0.5}, 3));
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_FALSE(r.fast_path);
  EXPECT_EQ(r.components[0].facets, std::vector<int>({3, 6, 7, 8, 9, 10}));
  EXPECT_EQ(r.components[0].vertices, std::vector<int>({9, 10, 13, 14}));
}

// The octree calls components() with the candidate triangles
// of an enclosing box and corner 0's status walked from that box's corner 0
// (CubeHint), instead of scanning all T triangles and walking from -infinity.
// Both must give the same answer on every cube: compared here on the 8
// octants of random dyadic parents (as the octree makes them) and on random
// boxes inside 5x boxes (extended boxes), with marked points checked against
// exact point location.
void compare_hinted(const Domain3& d, const std::string& name, std::uint64_t seed, int parents, int& fast, int& multi) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> dist(0, 1);
  const auto uni = [&] { return dist(rng); };
  const Vec3 lo = d.bbox_min, hi = d.bbox_max;
  const double ext = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  const double side0 = std::exp2(std::ceil(std::log2(ext)));
  for (int i = 0; i < parents; ++i) {
    const int level = static_cast<int>(rng() % 6);
    const double side = side0 / static_cast<double>(1 << level);
    const auto cell = [&](double l) { return std::floor((l - side + (ext + side) * uni()) / side) * side; };
    const Cube parent = i % 2 == 0 ? cube_of({cell(lo.x), cell(lo.y), cell(lo.z)}, side)
                                   : cube_of({cell(lo.x) - 2 * side, cell(lo.y) - 2 * side, cell(lo.z) - 2 * side}, 5 * side);
    const std::vector<int> ptris = triangles_meeting(d, parent);
    const bool pin = corner0_in(d, parent);
    Cube prev = parent;
    bool prev_in = pin;
    for (int k = 0; k < 8; ++k) {
      // An octant of the parent, or (odd i) a box of random size at a random
      // dyadic spot inside it, as ex(child) inside ex(parent).
      const double h = i % 2 == 0 ? side / 2 : side / static_cast<double>(2 << (rng() % 3));
      const double cells = (parent.hi.x - parent.lo.x) / h;
      const auto pick = [&](double l) {
        return i % 2 == 0 ? l + ((k >> 0) & 1) * h : l + std::floor(uni() * cells) * h;
      };
      Cube c = cube_of({pick(parent.lo.x), i % 2 == 0 ? parent.lo.y + ((k >> 1) & 1) * h : pick(parent.lo.y),
                        i % 2 == 0 ? parent.lo.z + ((k >> 2) & 1) * h : pick(parent.lo.z)},
                       h);
      const bool cin = corner0_in_from(d, c, parent, pin, ptris);
      ASSERT_EQ(cin, corner0_in(d, c)) << name << " cube " << c.lo.x << " " << c.lo.y << " " << c.lo.z << " side " << h;
      // The walk from the previous box of this parent (the octree walks from
      // child to child in Gray-code order), with the parent's list.
      EXPECT_EQ(corner0_in_walk(d, c, prev, prev_in, ptris), cin) << name << " walk from the previous box";
      prev = c;
      prev_in = cin;
      // Triangles known to meet c (those meeting its low octant) are not retested.
      const std::vector<int> octant_tris = triangles_meeting(d, cube_of(c.lo, h / 2), ptris);
      EXPECT_EQ(triangles_meeting(d, c, ptris, octant_tris), triangles_meeting(d, c, ptris)) << name;
      std::vector<Vec3> marks;
      for (int m = 0; m < 3; ++m)
        marks.push_back({c.lo.x + h * uni(), c.lo.y + h * uni(), c.lo.z + h * uni()});
      const CubeComponents full = components(d, c, true, marks);
      const CubeComponents hinted = components(d, c, CubeHint{ptris, false, cin}, true, marks);
      fast += hinted.fast_path;
      multi += hinted.components.size() > 1;
      ASSERT_EQ(full.components.size(), hinted.components.size()) << name;
      EXPECT_EQ(full.fast_path, hinted.fast_path) << name;
      EXPECT_EQ(full.triangle_component, hinted.triangle_component) << name;
      EXPECT_EQ(full.mark_component, hinted.mark_component) << name;
      for (std::size_t j = 0; j < full.components.size(); ++j) {
        EXPECT_EQ(full.components[j].vertices, hinted.components[j].vertices) << name;
        EXPECT_EQ(full.components[j].edges, hinted.components[j].edges) << name;
        EXPECT_EQ(full.components[j].facets, hinted.components[j].facets) << name;
        EXPECT_EQ(full.components[j].whole_cube, hinted.components[j].whole_cube) << name;
      }
      // Marks outside P are nowhere, marks inside P in some component.
      for (std::size_t m = 0; m < marks.size(); ++m)
        EXPECT_EQ(hinted.mark_component[m] >= 0, locate(d, marks[m]) == Location::Inside) << name << " mark " << m;
      // The fast path agrees with the full computation.
      if (hinted.fast_path) {
        const CubeComponents slow = components(d, c, CubeHint{ptris, false, cin}, false, marks);
        ASSERT_EQ(slow.components.size(), 1u) << name;
        EXPECT_EQ(slow.triangle_component, hinted.triangle_component) << name;
        EXPECT_EQ(slow.mark_component, hinted.mark_component) << name;
        EXPECT_EQ(slow.components[0].edges, hinted.components[0].edges) << name;
      }
    }
  }
}

TEST(CubeComponents, CandidatesAndWalkedCornerMatchTheFullScan) {
  int fast = 0, multi = 0;
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(test::data_path("3d")))
    if (e.path().extension() == ".poly") files.push_back(e.path().filename().string());
  std::sort(files.begin(), files.end());
  for (const std::string& f : files) compare_hinted(load(f.c_str()), f, std::hash<std::string>{}(f), 48, fast, multi);
  for (std::uint64_t seed = 0; seed < 8; ++seed)
    compare_hinted(make_domain(test::random_polyhedron(seed)), test::describe_polyhedron(seed), 500 + seed, 48, fast, multi);
  EXPECT_GT(fast, 50);   // the fast path was exercised...
  EXPECT_GT(multi, 10);  // ...and so were cubes with several components
  std::printf("hinted vs full: fast path %d, several components %d\n", fast, multi);
}

}  // namespace
}  // namespace pqmesh::mv3d
