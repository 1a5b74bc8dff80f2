// The octree refines by geodesic, not Euclidean, proximity (thesis §4.1.1:
// crowding and balance look at the component P ∧ ex(b), not at everything in
// ex(b)). A "tuning fork": the plate [0,1]^2 x [0,1/4] minus a square cavity
// [1/4,3/4]^2 and a neck [1/2 - w/2, 1/2 + w/2] x [3/4, 1] that opens the
// cavity to the outside. The two prongs on either side of the neck are w apart
// in space but about 1 apart inside P, and the neck has no bottom inside P, so
// P has no feature of size w: the leaf count must not grow like 1/w.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "mv3d/octree_builder.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/plc.hpp"

namespace pqmesh::mv3d {
namespace {

Plc3 tuning_fork(double w) {
  const double a = 0.5 - w / 2, b = 0.5 + w / 2;
  const double xy[12][2] = {{0, 0},       {1, 0},       {1, 1},       {b, 1},    {b, 0.75}, {0.75, 0.75},
                            {0.75, 0.25}, {0.25, 0.25}, {0.25, 0.75}, {a, 0.75}, {a, 1},    {0, 1}};
  Plc3 plc;
  for (const double z : {0.0, 0.25})
    for (const auto& p : xy) plc.vertices.push_back({p[0], p[1], z});
  Facet3 bottom, top;
  bottom.loops.emplace_back();
  top.loops.emplace_back();
  for (int i = 0; i < 12; ++i) {
    bottom.loops[0].push_back(11 - i);
    top.loops[0].push_back(12 + i);
  }
  plc.facets.push_back(bottom);
  plc.facets.push_back(top);
  for (int i = 0; i < 12; ++i) {
    const int j = (i + 1) % 12;
    Facet3 side;
    side.loops.push_back({i, j, 12 + j, 12 + i});
    plc.facets.push_back(side);
  }
  return plc;
}

std::int64_t leaves_for(double w) {
  const Domain3 d = make_domain(tuning_fork(w));
  OctreeBuilder builder(d);
  builder.build();
  const OctreeStats& s = builder.stats();
  std::printf("tuning fork w = %g: leaves %lld (outside %lld), duplicates %lld, depth of deepest leaf %d\n", w,
              static_cast<long long>(s.leaves), static_cast<long long>(s.outside_leaves),
              static_cast<long long>(s.duplicates), [&] {
                int deepest = 0;
                for (const std::int32_t n : builder.leaves_by_id())
                  deepest = std::max(deepest, builder.tree().level(n));
                return deepest;
              }());
  return s.leaves;
}

TEST(OctreeGeodesic, NarrowNeckBetweenProngsDoesNotRefine) {
  const std::int64_t wide = leaves_for(1e-1);
  const std::int64_t narrow = leaves_for(1e-3);
  EXPECT_LE(static_cast<double>(narrow), 1.5 * static_cast<double>(wide));
}

}  // namespace
}  // namespace pqmesh::mv3d
