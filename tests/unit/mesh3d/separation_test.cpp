// TetSeparation (pqmesh/tetmesh.hpp): lighter octrees (smaller extended
// boxes, no separating splits of §4.1.7 steps 6 and 9) are meshed first and
// kept when valid and within the aspect bound; otherwise octrees separated
// near the faces the review names, then the thesis's octree. Every mesh here
// passes check_mesh and the bound C / alpha.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <string>

#include "aspect_alpha_property.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/read_domain.hpp"
#include "pqmesh/tetmesh.hpp"
#include "mesh3d/construction.hpp"
#include "mv3d/octree_builder.hpp"
#include "pqmesh/alpha.hpp"
#include "support/flat_edge_domains.hpp"
#include "support/random_domains.hpp"
#include "support/paths.hpp"

namespace pqmesh {
namespace {

TetMeshOptions with(TetSeparation separation) {
  TetMeshOptions o;
  o.separation = separation;
  return o;
}

// Valid, within C / alpha; returns aspect * alpha.
double expect_valid_and_bounded(const std::string& what, const Domain3& d, const TetMeshResult& r) {
  const CheckReport report = check_mesh(r.mesh, d);
  EXPECT_TRUE(report.valid()) << what << ": " << report.to_text();
  const double product = test::aspect_times_alpha(quality_report(r.mesh).aspect_ratio.max, compute_alpha(d.plc).radians);
  EXPECT_LE(product, test::kAspectAlphaC) << what;
  return product;
}

Domain3 corpus(const char* name) {
  return make_domain(read_plc(test::data_path(std::string("3d/") + name)));
}

TetMeshOptions construction_only(TetSeparation separation) {
  TetMeshOptions o = with(separation);
  o.improve = false;
  return o;
}

// On models the lightest octree meshes within the bound, the default keeps its
// mesh (smaller extended boxes, no separating split) and it has fewer
// tetrahedra than the thesis's octree (both unimproved).
class LightKept : public ::testing::TestWithParam<const char*> {};

TEST_P(LightKept, FewerTetrahedraThanTheThesisOctree) {
  const Domain3 d = corpus(GetParam());
  const TetMeshResult light = tet_mesh(d, construction_only(TetSeparation::Adaptive));
  const TetMeshResult thesis = tet_mesh(d, construction_only(TetSeparation::Always));
  EXPECT_EQ(light.stats.extended_margin, 1) << light.stats.light_rejected;
  EXPECT_FALSE(light.stats.separated);
  EXPECT_TRUE(light.stats.light_rejected.empty());
  EXPECT_TRUE(thesis.stats.separated);
  EXPECT_EQ(thesis.stats.extended_margin, 2);
  EXPECT_TRUE(thesis.stats.light_rejected.empty());  // never tried
  expect_valid_and_bounded(GetParam(), d, light);
  expect_valid_and_bounded(GetParam(), d, thesis);
  EXPECT_LT(light.mesh.tetrahedra.size(), thesis.mesh.tetrahedra.size());
  std::printf("%-18s lightest %8zu tets, thesis octree %9zu tets\n", GetParam(), light.mesh.tetrahedra.size(),
              thesis.mesh.tetrahedra.size());
}

INSTANTIATE_TEST_SUITE_P(Corpus, LightKept, ::testing::Values("cube.poly", "l_block.poly", "schoenhardt.poly"));

// Every-run seed 177 with every facet triangle its own facet: the lighter
// octrees have a leaf of no kind (two facets of an edge outside it); the
// octree separated near that leaf's facets and their edges meshes it, valid
// and within the bound, with fewer tetrahedra than the thesis's octree.
TEST(SeparationFallback, FlatSeed177SeparatesNearTheLeafOfNoKind) {
  const Domain3 d = test::every_run_seed_as_triangles(177);
  const TetMeshResult r = tet_mesh(d, construction_only(TetSeparation::Adaptive));
  EXPECT_FALSE(r.stats.separated);
  EXPECT_GT(r.stats.separated_faces, 0);
  EXPECT_NE(r.stats.light_rejected.find("kind other"), std::string::npos) << r.stats.light_rejected;
  EXPECT_GT(r.stats.seconds_light, 0);
  const double product = expect_valid_and_bounded("flat seed 177", d, r);
  const TetMeshResult thesis = tet_mesh(d, construction_only(TetSeparation::Always));
  expect_valid_and_bounded("flat seed 177, thesis octree", d, thesis);
  EXPECT_LT(r.mesh.tetrahedra.size(), thesis.mesh.tetrahedra.size());
  std::printf("flat seed 177: %zu tets separated near %lld faces (thesis octree %zu), aspect * alpha %.1f; "
              "dropped: %s\n",
              r.mesh.tetrahedra.size(), static_cast<long long>(r.stats.separated_faces), thesis.mesh.tetrahedra.size(),
              product, r.stats.light_rejected.c_str());
}

// The aspect review names the faces near the tetrahedra above C / alpha: with
// an alpha that puts the worst tetrahedron of the schoenhardt prism above the
// bound, the faces of its leaf are named; with the true alpha none is.
TEST(AspectReview, NamesTheFacesNearTheTetrahedraAboveTheBound) {
  const Domain3 d = corpus("schoenhardt.poly");
  const mesh3d::OctreeVariant light{2, false, {}};
  const double alpha = compute_alpha(d.plc).radians;
  const auto t0 = std::chrono::steady_clock::now();
  const mesh3d::Construction c = mesh3d::construct(d, TetMeshOptions{}, light, alpha, t0);
  EXPECT_EQ(c.review.over_bound.count(), 0);
  const double harsh_alpha = 2 * kMeasuredAspectAlphaC / c.review.max_aspect;  // the worst is 2x above
  const mesh3d::Construction h = mesh3d::construct(d, TetMeshOptions{}, light, harsh_alpha, t0);
  EXPECT_EQ(h.result.mesh.tetrahedra, c.result.mesh.tetrahedra);
  EXPECT_GT(h.review.over_bound.count(), 0);
  EXPECT_LT(h.review.over_bound.count(),
            static_cast<std::int64_t>(d.edges.size() + d.plc.facets.size()));  // not every face
}

// The review of the lightest construction's stuck corners (mesh3d.md "Light
// construction first"). On corpus models whose lightest mesh is kept it drops
// nothing and changes no tetrahedron (schoenhardt's first warp table has
// stuck corners: their tetrahedra are within the bound). With an alpha that
// puts every tetrahedron above the bound (C / alpha = 1/2, below every aspect
// ratio), schoenhardt's construction is dropped before its box stage, and
// the reason says so.
TEST(StuckCornerReview, KeepsTheLightestMeshOfCorpusModelsAndDropsAboveTheBound) {
  const auto t0 = std::chrono::steady_clock::now();
  TetMeshOptions o;
  o.improve = false;
  const mesh3d::OctreeVariant lightest{1, false, {}};
  for (const char* name : {"cube.poly", "l_block.poly", "schoenhardt.poly"}) {
    const Domain3 d = corpus(name);
    const double alpha = compute_alpha(d.plc).radians;
    const mesh3d::Construction reviewed = mesh3d::construct(d, o, lightest, alpha, t0, true);
    const mesh3d::Construction plain = mesh3d::construct(d, o, lightest, alpha, t0, false);
    EXPECT_TRUE(reviewed.stuck.empty()) << name << ": " << reviewed.stuck;
    EXPECT_EQ(reviewed.result.mesh.tetrahedra, plain.result.mesh.tetrahedra) << name;
    EXPECT_EQ(reviewed.result.mesh.vertices.size(), plain.result.mesh.vertices.size()) << name;
    expect_valid_and_bounded(name, d, reviewed.result);
  }
  const Domain3 d = corpus("schoenhardt.poly");
  const mesh3d::Construction dropped = mesh3d::construct(d, o, lightest, 2 * kMeasuredAspectAlphaC, t0, true);
  EXPECT_NE(dropped.stuck.find("box corner the warp cannot move"), std::string::npos) << dropped.stuck;
  EXPECT_TRUE(dropped.result.mesh.tetrahedra.empty());
}

// The ladder's second rung: the lightest octree's rules on the generic
// grid's second offset (mesh3d.md "Light construction first"). Its planes are
// elsewhere on every axis. What it makes is either a mesh that is valid and
// within the bound, or a refusal of the box code (InternalError, which the
// ladder catches before its next rung), never a mesh the checker rejects:
// asserted on corpus models (all meshed) and random polyhedra (the box code's
// refusals are its known limits, tet3d_boxes.md "Known limits").
TEST(SecondOffset, ValidAndBoundedOrRefusedOnCorpusAndRandomPolyhedra) {
  const auto t0 = std::chrono::steady_clock::now();
  TetMeshOptions o;
  o.improve = false;
  // True when the second offset's construction meshed `d`.
  const auto second_offset_meshes = [&](const std::string& what, const Domain3& d) {
    const double alpha = compute_alpha(d.plc).radians;
    const mesh3d::Construction first = mesh3d::construct(d, o, mesh3d::OctreeVariant{1, false, {}}, alpha, t0);
    try {
      const mesh3d::Construction second = mesh3d::construct(d, o, mesh3d::OctreeVariant{1, false, {}, 1}, alpha, t0);
      EXPECT_EQ(second.result.stats.grid_shift, 1) << what;
      for (std::size_t a = 0; a < 3; ++a)
        EXPECT_NE(first.result.stats.grid_offset[a], second.result.stats.grid_offset[a]) << what << " axis " << a;
      if (!second.unsupported.empty()) return false;
      expect_valid_and_bounded(what + ", second offset", d, second.result);
      EXPECT_LE(second.review.max_aspect * alpha, kMeasuredAspectAlphaC) << what;
      return true;
    } catch (const InternalError& e) {
      std::printf("%s, second offset: refused by the box code: %s\n", what.c_str(), e.what());
      return false;
    }
  };
  for (const char* name : {"cube.poly", "l_block.poly", "schoenhardt.poly", "cube_through_hole.poly"})
    EXPECT_TRUE(second_offset_meshes(name, corpus(name))) << name;
  int meshed = 0;
  for (std::uint64_t seed = 1; seed <= 2; ++seed)
    meshed += second_offset_meshes("random polyhedron " + std::to_string(seed),
                                   make_domain(test::random_polyhedron(seed)))
                  ? 1
                  : 0;
  std::printf("random polyhedra 1-2: %d meshed on the second offset\n", meshed);
  EXPECT_GE(meshed, 1);
}

// Separating splits near a few faces only: more leaves than none, fewer than
// the thesis's (every edge and facet).
TEST(ScopedSeparation, BetweenNoneAndEveryFace) {
  const Domain3 d = corpus("l_block.poly");
  const auto leaves = [&](const mv3d::OctreeOptions& o) {
    mv3d::OctreeBuilder b(d, o);
    b.build();
    return b.tree().leaf_count();
  };
  mv3d::OctreeOptions none, every, near;
  none.separate = false;
  near.separate_edges.assign(d.edges.size(), 0);
  near.separate_facets.assign(d.plc.facets.size(), 0);
  near.separate_facets[0] = 1;
  near.separate_edges[0] = 1;
  const auto n_none = leaves(none), n_near = leaves(near), n_every = leaves(every);
  std::printf("l_block leaves: no separation %lld, near edge 0 and facet 0 %lld, every face %lld\n",
              static_cast<long long>(n_none), static_cast<long long>(n_near), static_cast<long long>(n_every));
  EXPECT_LT(n_none, n_near);
  EXPECT_LT(n_near, n_every);
}

}  // namespace
}  // namespace pqmesh
