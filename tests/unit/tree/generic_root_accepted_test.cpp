// choose_generic_root_cube (root_cube.hpp) applies the Tree constructor's own
// check (tree_impl.hpp, the extended box's plane range, also for negative
// origins) to every candidate, so a returned root is accepted by
// construction: the constructor never throws "root offset ... too fine for
// exact box planes" on it (as on harsh random polyhedra 101 and 103).
// The boxes below are the domains' kind of placement: bounding boxes on the
// negative side of 0, straddling it, and far from it, at several scales.
// Every coordinate set is the box's two corners (so the chooser also has
// coordinates to keep off the planes).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <span>
#include <vector>

#include "tree/root_cube.hpp"
#include "tree/tree.hpp"

namespace pqmesh {
namespace {

void expect_accepted(std::array<double, 3> lo, std::array<double, 3> hi) {
  std::array<std::vector<double>, 3> c;
  for (int a = 0; a < 3; ++a) c[a] = {lo[a], hi[a]};
  const GenericRoot<3> g = choose_generic_root_cube<3>(lo, hi, {std::span<const double>(c[0]),
                                                                std::span<const double>(c[1]),
                                                                std::span<const double>(c[2])},
                                                       kTreeMaxLevel);
  SCOPED_TRACE(::testing::Message() << "box " << lo[0] << " " << lo[1] << " " << lo[2] << " .. " << hi[0] << " "
                                    << hi[1] << " " << hi[2] << ", root size " << g.root.size);
  ASSERT_NO_THROW({ Tree<3> t(g.root); });
  const Tree<3> t(g.root);
  for (int a = 0; a < 3; ++a) {
    // The root's lower plane is origin + offset exactly, and the input box
    // lies strictly inside the shifted root.
    EXPECT_EQ(t.key_plane(t.key(0), a, false), g.root.origin[a] + g.root.offset[a]);
    EXPECT_LT(t.key_plane(t.key(0), a, false), lo[a]);
    EXPECT_GT(t.key_plane(t.key(0), a, true), hi[a]);
    EXPECT_NE(g.root.offset[a], 0.0);
  }
  EXPECT_GE(t.max_level(), 1);
}

TEST(GenericRootAccepted, NegativeStraddlingAndFarBoxesAtManyScales) {
  // The bounding boxes of harsh seeds 101 and 103 (printed from
  // random_polyhedron with harsh_options(); their roots have origins
  // (-3, -3, -1) and (-8, 0, -4)).
  expect_accepted({-2.6426882743835449, -1.96875, 0}, {-2.3037536144256592, -1.5285723209381104, 0.453125});
  expect_accepted({-4.4831314086914062, 2.1640625, 0}, {-1.078125, 4.6187858581542969, 0.765625});
  for (int e = -30; e <= 30; e += 6) {
    const double s = std::ldexp(1.0, e);
    expect_accepted({-1.7 * s, -0.3 * s, -5.2 * s}, {-0.9 * s, 0.4 * s, -4.1 * s});
    expect_accepted({1e3 * s, -1e3 * s, 0.1 * s}, {1e3 * s + 0.7 * s, -1e3 * s + 0.2 * s, 0.9 * s});
  }
}

}  // namespace
}  // namespace pqmesh
