// The generic grid (tree/root_cube.hpp choose_generic_root_cube, OctreeOptions::
// generic_grid): no input vertex coordinate lies on a box plane of any level
// the tree may use, checked over the corpus with exact rational arithmetic
// (GMP), independently of the floating-point test the chooser uses.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "mv3d/octree_builder.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/read_domain.hpp"
#include "pqmesh/tetmesh.hpp"
#include "support/paths.hpp"
#include "tree/root_cube.hpp"
#include "tree/tree.hpp"

namespace pqmesh {
namespace {

using Coords = std::array<std::vector<double>, 3>;

Coords coords_of(const Plc3& plc) {
  Coords c;
  for (const Vec3& p : plc.vertices) {
    c[0].push_back(p.x);
    c[1].push_back(p.y);
    c[2].push_back(p.z);
  }
  return c;
}

GenericRoot<3> choose(const Coords& c, const std::array<double, 3>& lo, const std::array<double, 3>& hi,
                      int shift = 0) {
  return choose_generic_root_cube<3>(lo, hi, {std::span<const double>(c[0]), c[1], c[2]}, kTreeMaxLevel, shift);
}

// Exact: x - (origin + off) is not an integer multiple of the spacing of the
// finest level's planes, S / 2^(max_level + 1) (planes of coarser levels are
// among them).
bool on_some_plane(double x, double origin, double off, double size, int max_level) {
  const mpq_class diff = mpq_class(x) - mpq_class(origin) - mpq_class(off);
  mpq_class q = diff / mpq_class(std::ldexp(size, -(max_level + 1)));
  q.canonicalize();
  return q.get_den() == 1;
}

void expect_generic(const std::string& what, const Coords& c, const GenericRoot<3>& g,
                    const std::array<double, 3>& lo, const std::array<double, 3>& hi) {
  EXPECT_GE(g.max_level, 45) << what;
  for (int a = 0; a < 3; ++a) {
    const double off = g.root.offset[a], o = g.root.origin[a], s = g.root.size;
    EXPECT_GT(off, 0) << what;
    EXPECT_LT(off, s / 32) << what;
    // The offset itself is off the finest planes of the aligned grid.
    EXPECT_FALSE(on_some_plane(off, 0, 0, s, g.max_level)) << what;
    // The root (with its offset) holds the input box strictly.
    EXPECT_LT(mpq_class(o) + mpq_class(off), mpq_class(lo[a])) << what;
    EXPECT_GT(mpq_class(o) + mpq_class(off) + mpq_class(s), mpq_class(hi[a])) << what;
    for (const double x : c[static_cast<std::size_t>(a)])
      EXPECT_FALSE(on_some_plane(x, o, off, s, g.max_level)) << what << ": coordinate " << x << " axis " << a;
  }
}

TEST(GenericGrid, NoCorpusCoordinateOnAPlane) {
  int models = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::data_path("3d"))) {
    const Domain3 d = make_domain(read_plc(entry.path().string()));
    const Coords c = coords_of(d.plc);
    const std::array<double, 3> lo{d.bbox_min.x, d.bbox_min.y, d.bbox_min.z}, hi{d.bbox_max.x, d.bbox_max.y, d.bbox_max.z};
    const GenericRoot<3> g = choose(c, lo, hi);
    std::printf("%-22s root side %g, max level %d, candidate %d, offset (%.17g, %.17g, %.17g)\n",
                entry.path().filename().string().c_str(), g.root.size, g.max_level, g.candidate, g.root.offset[0],
                g.root.offset[1], g.root.offset[2]);
    expect_generic(entry.path().filename().string(), c, g, lo, hi);
    // The second offset (the adaptive ladder's second rung) is generic too,
    // and its planes differ from the first's on every axis.
    const GenericRoot<3> g2 = choose(c, lo, hi, 1);
    expect_generic(entry.path().filename().string() + ", offset 2", c, g2, lo, hi);
    for (int a = 0; a < 3; ++a) EXPECT_NE(g2.root.offset[a], g.root.offset[a]) << entry.path().filename().string();
    // The aligned grid of the same box puts corpus coordinates on planes
    // (that is why the generic grid exists): not asserted per model, counted.
    ++models;
  }
  EXPECT_GE(models, 15);
}

// A coordinate placed exactly on a plane of the first candidate (an odd
// multiple of its finest unit g) forces the next one, one level coarser;
// the result is still generic.
TEST(GenericGrid, CoincidenceMovesToTheNextCandidate) {
  Coords c{{{0.0, 1.0}, {0.0, 1.0}, {0.0, 1.0}}};
  const std::array<double, 3> lo{0, 0, 0}, hi{1, 1, 1};
  const GenericRoot<3> g0 = choose(c, lo, hi);
  ASSERT_EQ(g0.candidate, 0);
  // A plane of candidate 0 inside the box along y: origin + off + k * spacing.
  const double spacing = std::ldexp(g0.root.size, -(g0.max_level + 1));
  const double base = g0.root.origin[1] + g0.root.offset[1];
  const double k = std::ceil((0.5 - base) / spacing);
  const double plane = base + k * spacing;
  ASSERT_TRUE(on_some_plane(plane, g0.root.origin[1], g0.root.offset[1], g0.root.size, g0.max_level));
  c[1].push_back(plane);
  const GenericRoot<3> g1 = choose(c, lo, hi);
  EXPECT_GE(g1.candidate, 1);
  EXPECT_LT(g1.max_level, g0.max_level);
  expect_generic("forced", c, g1, lo, hi);
}

// Tree<3> adds RootCube::offset to its planes (tree/tree_impl.hpp key_plane).
TEST(GenericGrid, TreePlanesCarryTheOffset) {
  RootCube<3> r;
  r.origin = {-2, -2, -2};
  r.size = 4;
  r.offset = {0x1p-40, 0x1p-40, 0x1p-40};
  const OctTree t(r);
  EXPECT_EQ(t.key_plane(t.key(0), 0, false), -2 + 0x1p-40);
  EXPECT_EQ(t.key_plane(t.key(0), 2, true), 2 + 0x1p-40);
}

// On the generic grid every leaf plane misses every input coordinate; the
// cube's octree (the thesis's, unimproved) then has vertex, edge and facet
// boxes, and its mesh is valid.
TEST(GenericGrid, OctreeLeavesMissCoordinatesAndTheMeshIsValid) {
  const Domain3 d = make_domain(read_plc(test::data_path("3d/cube.poly")));
  mv3d::OctreeOptions oo;
  oo.generic_grid = true;
  mv3d::OctreeBuilder b(d, oo);
  b.build();
  const auto& V = d.plc.vertices;
  std::int64_t leaves = 0;
  for (const std::int32_t n : b.leaves_by_id()) {
    ++leaves;
    const mv3d::Cube c = b.cube(n);
    for (const Vec3& p : V) {
      ASSERT_NE(p.x, c.lo.x);
      ASSERT_NE(p.x, c.hi.x);
      ASSERT_NE(p.y, c.lo.y);
      ASSERT_NE(p.y, c.hi.y);
      ASSERT_NE(p.z, c.lo.z);
      ASSERT_NE(p.z, c.hi.z);
    }
  }
  std::printf("cube on the generic grid: %lld leaves\n", static_cast<long long>(leaves));
  TetMeshOptions thesis_octree;
  thesis_octree.separation = TetSeparation::Always;
  thesis_octree.improve = false;
  const TetMeshResult r = tet_mesh(d, thesis_octree);
  const CheckReport rep = check_mesh(r.mesh, d);
  EXPECT_TRUE(rep.valid()) << rep.to_text();
  EXPECT_GT(r.stats.edge_jobs, 0);
  EXPECT_GT(r.stats.vertex_jobs, 0);
}

}  // namespace
}  // namespace pqmesh
