// Hand cases for mv3d::components (components of P ∩ C, thesis §4.1.6).
// Expected values are read off the corpus files: data/3d/cube.poly is [0,1]^3
// with vertex ids 0..7 = (0,0,0) (1,0,0) (1,1,0) (0,1,0) (0,0,1) (1,0,1)
// (1,1,1) (0,1,1) and facets z=0, z=1, y=0, x=1, y=1, x=0 (ids 0..5);
// cube_cavity.poly is [0,4]^3 minus the cavity [1,3]^3 (vertices 8..15,
// facets 6..11); prongs_slot.poly is a plate [0,1]^2 x [0,1/4] with a slot
// of width 1/1024 at x = 1/2 for y >= 1/4.
#include <gtest/gtest.h>

#include <vector>

#include "mv3d/cube_components.hpp"
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

}  // namespace
}  // namespace pqmesh::mv3d
