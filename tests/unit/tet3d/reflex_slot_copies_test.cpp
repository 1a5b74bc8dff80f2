// Fig. 4.7 of the thesis (§4.3, "the special sharing case"): a box vertex in
// the thin exterior slot of a reflex edge E, within h/16 of both facets F and
// G of E, gets one copy per facet, each warped h/16 away from its own facet
// (warp.hpp, warp_table.hpp); a cut by F constructs its crossing from F's
// copy. Domains: a block with a thin V-shaped slot cut from its top (a prism
// over an x-z polygon), the reflex edge E at the slot's bottom. With the
// copies turned off (detail::BoxMeshTestHooks) such a vertex stays in place
// (reflex_left > 0), which shows that the domain puts vertices in the slot.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "../plc/domain_fixtures.hpp"
#include "mv3d/octree_builder.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/quality.hpp"
#include "predicates/predicates.hpp"
#include "tet3d/squares/box_faces.hpp"
#include "tet3d/boxes/box_jobs.hpp"
#include "tet3d/squares/cut_square.hpp"
#include "tet3d/facet_boxes.hpp"
#include "tet3d/points/facet_plane.hpp"
#include "tet3d/warp/warp.hpp"
#include "tree/tree.hpp"

namespace pqmesh::tet3d {
namespace {

// Block [0.1, 0.9] (x) x [y0, y1] x [0.1, 0.9] (z) with a V slot from its top:
// apex (ax, az), opening 2w wide at z = 0.9.
Plc3 slotted_block(double ax, double az, double w, double y0, double y1) {
  return test::prism_xz({{0.1, 0.1}, {0.9, 0.1}, {0.9, 0.9}, {ax + w, 0.9}, {ax, az}, {ax - w, 0.9}, {0.1, 0.9}}, y0, y1);
}

struct SlotRun {
  bool ok = false;
  BoxMesh mesh;
  double worst = 0;
};

SlotRun run(const Domain3& d, bool separate, bool generic, bool copies) {
  mv3d::OctreeOptions opt;
  opt.separate = separate;
  opt.generic_grid = generic;
  mv3d::OctreeBuilder b(d, opt);
  b.build();
  const BoxJobs jobs = box_jobs(b);
  SlotRun r;
  if (!jobs.problems.empty()) return r;
  const CornerSet corners(b);
  BoxMeshOptions mo;
  mo.warp = true;
  detail::BoxMeshTestHooks hooks;
  hooks.reflex_copies = copies;
  try {
    r.mesh = mesh_boxes(b.tree(), corners, d, jobs.jobs, mo, hooks);
  } catch (const std::exception& e) {
    std::printf("  threw: %s\n", e.what());
    return r;
  }
  r.ok = true;
  r.worst = quality_report(r.mesh.mesh).aspect_ratio.max;
  return r;
}

// The facet of d nearest to x (x is a point of the wanted wall, up to rounding).
int facet_nearest(const Domain3& d, Vec3 x) {
  int best = -1;
  for (int f = 0; f < static_cast<int>(d.plc.facets.size()); ++f)
    if (best < 0 || facet_distance(d, f, x) < facet_distance(d, best, x)) best = f;
  return best;
}

TEST(ReflexSlotCopies, OneCopyPerFacetEachMovedOffItsOwnFacet) {
  // Root cube [0, 1]^3 (h = 1). P: the block [-1, 1.3] x [-1, 2] x [-1, 1.2]
  // minus a slot from its top, apex line E at (x, z) = (0.0003, -0.4), walls
  // F (left) and G (right) reaching z = 1.2 at x = 0.0003 -/+ 0.05: a reflex
  // edge of about 356.4 deg. At z = 0 the slot is 0.05 * 0.4 / 1.6 = 0.0125
  // wide on each side of its bisector, so v = (0, 0, 0) lies inside it,
  // about 0.0125 -/+ 0.0003 from each wall: within h/16 of both, beyond both
  // planes (outside P), 0.4 from E (no first pass).
  const OctTree t(RootCube<3>{{0, 0, 0}, 1});
  const CornerSet corners(t, t.leaves());
  const Domain3 d = make_domain(test::prism_xz(
      {{-1, -1}, {1.3, -1}, {1.3, 1.2}, {0.0503, 1.2}, {0.0003, -0.4}, {-0.0497, 1.2}, {-1, 1.2}}, -1, 2));
  // Points of the walls halfway up (z = 0.4: 0.025 beside the bisector).
  const int f = facet_nearest(d, {0.0003 - 0.025, 0.5, 0.4}), g = facet_nearest(d, {0.0003 + 0.025, 0.5, 0.4});
  ASSERT_NE(f, g);
  ASSERT_LT(facet_distance(d, f, {0.0003 - 0.025, 0.5, 0.4}), 1e-12);
  ASSERT_LT(facet_distance(d, g, {0.0003 + 0.025, 0.5, 0.4}), 1e-12);
  const GridPoint v = key_corner(t.key(0), 0), wx = key_corner(t.key(0), 1), wy = key_corner(t.key(0), 2);
  const Vec3 x0 = grid_coordinates(t, v);
  const FacetPlane pf(d, f), pg(d, g);
  ASSERT_EQ(pf.side(x0), Sign::Positive);
  ASSERT_EQ(pg.side(x0), Sign::Positive);
  ASSERT_LE(facet_distance(d, f, x0), 1.0 / 16);
  ASSERT_LE(facet_distance(d, g, x0), 1.0 / 16);
  const std::vector<WarpCandidateRecord> cand = {{v, {f, g}, {wx, wy}, {}, 0, {}}};

  // Without copies (reflex_copies false): v stays, counted.
  WarpOptions no_copies;
  no_copies.reflex_copies = false;
  const WarpTable before = warp_box_vertices(t, corners, d, make_warp_candidates(cand), no_copies);
  EXPECT_EQ(before.reflex_left, 1);
  EXPECT_EQ(before.find(v), nullptr);
  EXPECT_EQ(before.copy_count(), 0u);

  const WarpTable w = warp_box_vertices(t, corners, d, make_warp_candidates(cand));
  EXPECT_EQ(w.reflex_left, 0);
  EXPECT_EQ(w.reflex_copied, 1);
  EXPECT_EQ(w.find(v), nullptr) << "a slot vertex has copies, no single entry";
  for (const FacetPlane* p : {&pf, &pg}) {
    const Vec3* c = w.find_copy(v, p->facet());
    ASSERT_NE(c, nullptr) << "facet " << p->facet();
    // h/16 along the facet's unit normal, away from it: the exact side is kept.
    EXPECT_EQ(p->side(*c), Sign::Positive);
    EXPECT_NEAR(p->distance(*c) - p->distance(x0), 1.0 / 16, 1e-12);
    EXPECT_NEAR(norm(*c - x0), 1.0 / 16, 1e-12);
  }
  // The copy for F crosses G's plane (it serves F's cuts only), and the
  // other way round: the thesis's "each is warped separately".
  EXPECT_EQ(pg.side(*w.find_copy(v, f)), Sign::Negative);
  EXPECT_EQ(pf.side(*w.find_copy(v, g)), Sign::Negative);

  // G cuts the bottom face square at the ring segment [v, wx] (wx inside
  // P): the crossing is constructed from G's copy of v, not from v.
  std::vector<FaceSquare> squares;
  face_squares(t.key(0), 2, false, corners, squares);
  ASSERT_EQ(squares.size(), 1u);
  PointBook book;
  book.set_warps(&w);
  std::vector<std::array<int, 3>> tris;
  triangulate_cut_square(squares[0], corners, t, pg, book, tris, &w);
  const int id = book.find({VertexKind::FacetCrossing, std::min(v, wx), std::max(v, wx), g});
  ASSERT_GE(id, 0);
  const Vec3 from_copy = v < wx ? pg.crossing(*w.find_copy(v, g), grid_coordinates(t, wx))
                                : pg.crossing(grid_coordinates(t, wx), *w.find_copy(v, g));
  EXPECT_EQ(book.point(id).x, from_copy.x);
  EXPECT_EQ(book.point(id).y, from_copy.y);
  EXPECT_EQ(book.point(id).z, from_copy.z);
  const Vec3 from_v = pg.crossing(x0, grid_coordinates(t, wx));
  EXPECT_NE(book.point(id).z, from_v.z);
}

// The slotted block with the slot's bisector just beside a grid plane of
// level 6 (the generic grid's offset included), so grid points on that
// plane lie inside the slot (delta: the bisector's offset from that plane
// in units of the level's box side).
Domain3 slot_on_grid_line(double az, double w, int level, double delta) {
  const Domain3 probe = make_domain(slotted_block(0.5, az, w, 0.13, 0.87));
  mv3d::OctreeOptions opt;
  opt.generic_grid = true;
  const mv3d::OctreeBuilder b(probe, opt);
  const auto& root = b.tree().root();
  const double step = root.size / (1 << level);
  const double lo = root.origin[0] + root.offset[0];
  const double ax = lo + std::round((0.5 - lo) / step) * step + delta * step;
  return make_domain(slotted_block(ax, az, w, 0.13, 0.87));
}

TEST(ReflexSlotCopies, WholeMeshWithCopiesIsValidAndNoWorse) {
  // tet_mesh's pipeline (separating splits, generic grid, every box kind,
  // warped). Slot apex z = 0.3113, half-width 0.019 at z = 0.9 (a reflex
  // edge of 356.3 deg), bisector 1e-4 steps of level 6 beside a grid plane.
  const Domain3 d = slot_on_grid_line(0.3113, 0.019, 6, 1e-4);
  const SlotRun before = run(d, true, true, false);
  ASSERT_TRUE(before.ok);
  ASSERT_GT(before.mesh.warp_reflex_left, 0) << "the domain must put box vertices in the slot";
  const SlotRun after = run(d, true, true, true);
  ASSERT_TRUE(after.ok);
  EXPECT_EQ(after.mesh.warp_reflex_left, 0);
  EXPECT_EQ(after.mesh.warp_reflex_copied, before.mesh.warp_reflex_left);
  const CheckReport r = check_mesh(after.mesh.mesh, d);
  EXPECT_TRUE(r.valid()) << r.to_text();
  EXPECT_TRUE(check_mesh(before.mesh.mesh, d).valid());
  EXPECT_LE(after.worst, before.worst);
  // The copies changed the mesh: some FacetCrossing moved.
  std::size_t moved = 0;
  ASSERT_EQ(after.mesh.keys.size(), before.mesh.keys.size());
  for (std::size_t i = 0; i < after.mesh.keys.size(); ++i) {
    const Vec3 a = after.mesh.mesh.vertices[i], b = before.mesh.mesh.vertices[i];
    moved += a.x != b.x || a.y != b.y || a.z != b.z ? 1 : 0;
  }
  std::printf("slot vertices %lld, mesh vertices moved by the copies %zu of %zu; worst aspect %.1f -> %.1f\n",
              static_cast<long long>(before.mesh.warp_reflex_left), moved, after.mesh.keys.size(), before.worst,
              after.worst);
  EXPECT_GT(moved, 0u);
}

// The scan that found the configuration of the test above (run by hand:
// --gtest_also_run_disabled_tests --gtest_filter='*ProbeOnGridLine*'); slot
// vertices occur only with the bisector near a grid plane (a scan of apexes
// and widths off the grid planes found none, as on every model measured).
TEST(ReflexSlotCopies, DISABLED_ProbeOnGridLine) {
  // The slot's bisector (x = ax) placed just beside a grid plane x = X of
  // level 5, 6 or 7, so that grid points on it lie inside the slot.
  for (const double az : {0.3113, 0.4427, 0.5291})
    for (const double w : {0.0071, 0.013, 0.019})
      for (const int level : {5, 6, 7})
        for (const double delta : {1e-4, -3e-4}) {
          const Domain3 d = slot_on_grid_line(az, w, level, delta);
          std::printf("az %.4f w %.4f level %d delta %g\n", az, w, level, delta);
          const SlotRun before = run(d, true, true, false);
          if (!before.ok) continue;
          std::printf("  before: left %lld worst %.1f\n", static_cast<long long>(before.mesh.warp_reflex_left), before.worst);
          if (before.mesh.warp_reflex_left == 0) continue;
          const SlotRun after = run(d, true, true, true);
          std::printf("  after ok %d left %lld copied %lld worst %.1f valid %d\n", after.ok,
                      static_cast<long long>(after.mesh.warp_reflex_left),
                      static_cast<long long>(after.mesh.warp_reflex_copied), after.worst,
                      after.ok ? check_mesh(after.mesh.mesh, d).valid() : 0);
        }
}

}  // namespace
}  // namespace pqmesh::tet3d
