// Size control of the octree (thesis §1.1): OctreeOptions'
// max_size and size field. The expected bounds come from the definition of
// the size function, f(x) = min(max_size, min_i s_i + |x - p_i|), evaluated
// here independently of the builder.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "mv3d/octree_builder.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/errors.hpp"
#include "pqmesh/read_domain.hpp"
#include "support/paths.hpp"

namespace pqmesh::mv3d {
namespace {

Domain3 load(const std::string& name) { return make_domain(read_plc(test::data_path("3d/" + name))); }

double distance_to_box(Vec3 p, const Cube& c) {
  const double dx = std::max({c.lo.x - p.x, 0.0, p.x - c.hi.x});
  const double dy = std::max({c.lo.y - p.y, 0.0, p.y - c.hi.y});
  const double dz = std::max({c.lo.z - p.z, 0.0, p.z - c.hi.z});
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

bool contains(const Cube& c, Vec3 p) {
  return p.x >= c.lo.x && p.x <= c.hi.x && p.y >= c.lo.y && p.y <= c.hi.y && p.z >= c.lo.z && p.z <= c.hi.z;
}

TEST(OctreeSize, MaxSizeCapsEveryLeafMeetingP) {
  const Domain3 d = load("l_block.poly");
  OctreeBuilder plain(d);
  plain.build();
  double largest = 0;
  for (const std::int32_t n : plain.leaves_by_id())
    if (plain.data(n).has_component) largest = std::max(largest, plain.tree().side(n));
  const double h = largest / 4;  // strictly smaller than what the phases alone produce
  OctreeOptions o;
  o.max_size = h;
  OctreeBuilder b(d, o);
  b.build();
  EXPECT_GT(b.stats().splits_size, 0);
  EXPECT_GT(b.stats().leaves, plain.stats().leaves);
  for (const std::int32_t n : b.leaves_by_id()) {
    if (b.data(n).has_component) {
      EXPECT_LE(b.tree().side(n), h) << "leaf " << n;
    }
  }
}

TEST(OctreeSize, SizeFieldRefinesAroundAPointOnly) {
  const Domain3 d = load("cube.poly");  // [0, 1]^3
  const Vec3 p{0.3, 0.6, 0.4};
  const double s = 1.0 / 256;
  OctreeOptions o;
  o.size_field.points = {p};
  o.size_field.sizes = {s};
  OctreeBuilder b(d, o);
  b.build();
  EXPECT_EQ(b.stats().leaves, b.tree().leaf_count());
  double near = 0, far = 0;
  for (const std::int32_t n : b.leaves_by_id()) {
    if (!b.data(n).has_component) continue;
    const Cube c = b.cube(n);
    const double h = b.tree().side(n);
    // The definition: no box larger than f anywhere in it.
    EXPECT_LE(h, s + distance_to_box(p, c)) << "leaf " << n;
    if (contains(c, p)) near = std::max(near, h);
    if (distance_to_box(p, c) > 0.25) far = std::max(far, h);
  }
  EXPECT_GT(near, 0);          // some leaf holds p...
  EXPECT_LE(near, s);          // ...and it is as small as asked
  EXPECT_GE(far, 64 * s);      // graded: far from p the boxes stay large
  // Grading keeps the count far below a uniform grid of side s (256^3 boxes).
  EXPECT_LT(b.stats().leaves, 1000000);
}

TEST(OctreeSize, InvalidOptionsAreRejected) {
  const Domain3 d = load("cube.poly");
  OctreeOptions neg;
  neg.max_size = -1;
  EXPECT_THROW(OctreeBuilder(d, neg), InvalidInput);
  OctreeOptions bad;
  bad.size_field.points = {{0, 0, 0}, {1, 1, 1}};
  bad.size_field.sizes = {0.1, 0};
  bad.size_field.lines = {3, 7};
  bad.size_field.path = "f.txt";
  try {
    OctreeBuilder b(d, bad);
    ADD_FAILURE() << "a zero size was accepted";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("f.txt:7"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pqmesh::mv3d
