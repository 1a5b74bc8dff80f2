// A warp table made from the last one (warp.hpp rewarp_box_vertices) is the
// table a whole build makes with the same options: entries in the same
// order, the same Fig. 4.7 copies and every count equal. Checked on the
// lightest octree of every-run seeds 38 and 185, with and without edge boxes
// (face translations), over two rounds of newly held points: points frozen
// and points given a reported-point entry (second_only), chosen among the
// moved ones so that the tables differ from the last.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "pqmesh/domain.hpp"
#include "support/random_domains.hpp"
#include "tet3d/facet_boxes.hpp"
#include "tet3d/warp/warp.hpp"
#include "tet3d/warp/warp_candidates.hpp"
#include "warped_box_mesh.hpp"

namespace pqmesh::tet3d {
namespace {

using PointSet = std::unordered_set<GridPoint, GridPointHash>;
using Reported = std::unordered_map<GridPoint, std::uint8_t, GridPointHash>;

void expect_same_table(const WarpTable& a, const WarpTable& b) {
  std::vector<std::tuple<GridPoint, int, double, double, double>> ea, eb;
  a.for_each([&](const GridPoint& p, const Warp& w) { ea.emplace_back(p, w.facet, w.at.x, w.at.y, w.at.z); });
  b.for_each([&](const GridPoint& p, const Warp& w) { eb.emplace_back(p, w.facet, w.at.x, w.at.y, w.at.z); });
  EXPECT_TRUE(ea == eb) << ea.size() << " and " << eb.size() << " entries";
  std::vector<std::tuple<GridPoint, int, double, double, double>> ca, cb;
  a.for_each_copy([&](const GridPoint& p, int f, Vec3 at) { ca.emplace_back(p, f, at.x, at.y, at.z); });
  b.for_each_copy([&](const GridPoint& p, int f, Vec3 at) { cb.emplace_back(p, f, at.x, at.y, at.z); });
  std::sort(ca.begin(), ca.end());
  std::sort(cb.begin(), cb.end());
  EXPECT_TRUE(ca == cb);
  for (std::size_t k = 0; k < std::size(WarpTable::kCounts); ++k)
    EXPECT_EQ(a.*WarpTable::kCounts[k], b.*WarpTable::kCounts[k]) << "count " << k;
}

// Every `stride`-th moved point (from `offset`) not yet held: frozen when
// `freeze`, else reported on its low x face.
void hold_more(const WarpTable& t, int offset, int stride, bool freeze, PointSet& frozen, Reported& reported,
               PointSet& changed) {
  int k = 0;
  t.for_each([&](const GridPoint& p, const Warp&) {
    if (k++ % stride != offset || frozen.count(p) != 0 || reported.count(p) != 0) return;
    if (freeze) frozen.insert(p);
    else reported.emplace(p, std::uint8_t{1});
    changed.insert(p);
  });
}

void check_rewarp(std::uint64_t seed, bool with_edge_boxes) {
  const Domain3 d = make_domain(test::random_polyhedron(seed, test::every_run_polyhedron_options()));
  const test::PlannedOctree o = test::planned_octree(d, test::lightest_octree_options());
  const mesh3d::BoxPlan& plan = o.plan;
  const CornerSet& corners = *o.corners;
  const OctTree& tree = o.tree();
  std::vector<EdgeBoxBounds> edge_boxes;
  if (with_edge_boxes)
    for (const BoxJob& j : plan.jobs)
      if (j.kind == BoxKind::Edge && edge_boxes.size() < 8)
        edge_boxes.push_back({key_corner(tree.key(j.leaf), 0), key_corner(tree.key(j.leaf), 7), j.apex});
  const WarpCandidates candidates = warp_candidates(tree, corners, d, plan.jobs);
  PointSet frozen;
  Reported reported;
  const WarpOptions options{.frozen = &frozen, .edge_boxes = edge_boxes, .second_only = &reported};
  WarpJournal journal;
  WarpTable last = warp_box_vertices(tree, corners, d, candidates, options, &journal);
  ASSERT_GT(last.size(), 20u);
  for (int round = 0; round < 2; ++round) {
    PointSet changed;
    hold_more(last, round, 9, true, frozen, reported, changed);
    hold_more(last, round + 4, 9, false, frozen, reported, changed);
    ASSERT_FALSE(changed.empty());
    const WarpTable whole = warp_box_vertices(tree, corners, d, candidates, options);
    WarpTable next = rewarp_box_vertices(tree, corners, d, candidates, options, last, changed, journal);
    expect_same_table(next, whole);
    EXPECT_NE(next.frozen_left, last.frozen_left);  // the rounds change the table
    last = std::move(next);
  }
}

TEST(Rewarp, SameTableAsAWholeBuild) {
  check_rewarp(38, false);
  check_rewarp(185, false);
}

TEST(Rewarp, SameTableAsAWholeBuildWithFaceTranslations) {
  check_rewarp(38, true);
  check_rewarp(185, true);
}

}  // namespace
}  // namespace pqmesh::tet3d
