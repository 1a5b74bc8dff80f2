// mesh_polygon, the default 2D mesh, over the random polygons with holes of
// tests/support/random_domains.hpp (the family of quad_mesh_property_test)
// and the 2D corpus: every mesh passes the checker, its smallest angle meets
// quad_mesh_angle_bound (the runtime certificate of mesh_polygon), and it has
// at most as many triangles as quad_mesh's mesh of the same polygon, so the
// quadtree mesher's size bound carries over.
#include <gtest/gtest.h>

#include <cstdint>
#include <iostream>
#include <string>

#include "pqmesh/alpha.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/quadmesh.hpp"
#include "pqmesh/quadmesh_bound.hpp"
#include "pqmesh/quality.hpp"
#include "pqmesh/read_domain.hpp"
#include "support/paths.hpp"
#include "support/random_domains.hpp"

namespace pqmesh {
namespace {

struct Tally {
  int refined_input = 0;
  std::int64_t triangles = 0, quadtree_triangles = 0;
};

// The checks of the file header for one domain; `what` names it in failures.
void expect_certified(const Domain2& d, const std::string& what, Tally& tally) {
  const QuadMeshResult r = mesh_polygon(d);
  const CheckReport check = check_mesh(r.mesh, d);
  ASSERT_TRUE(check.valid()) << what << "\n" << check.to_text();
  const double alpha = compute_alpha(d.pslg.vertices, d.loops).degrees();
  EXPECT_GE(quality_report(r.mesh).min_angle.min, quad_mesh_angle_bound(alpha)) << what << " alpha " << alpha;
  const QuadMeshResult quadtree = quad_mesh(d);
  EXPECT_LE(r.mesh.triangles.size(), quadtree.mesh.triangles.size()) << what;
  if (!d.pslg.segment_markers.empty()) {
    EXPECT_EQ(r.mesh.edge_markers.size(), r.mesh.edges.size()) << what << ": a marker per boundary piece";
  }
  tally.refined_input += r.stats.refined_input ? 1 : 0;
  tally.triangles += static_cast<std::int64_t>(r.mesh.triangles.size());
  tally.quadtree_triangles += static_cast<std::int64_t>(quadtree.mesh.triangles.size());
}

TEST(MeshPolygonProperty, RandomPolygonsCertifiedAndNoLargerThanTheQuadtreeMesh) {
  constexpr int kPolygons = 300;
  Tally tally;
  for (std::uint64_t seed = 1; seed <= kPolygons; ++seed)
    expect_certified(make_domain(test::random_polygon_with_holes(seed)), test::describe_polygon(seed), tally);
  std::cout << kPolygons << " polygons: " << tally.refined_input << " meshed by the refined CDT of the input; "
            << tally.triangles << " triangles against the quadtree's " << tally.quadtree_triangles << "\n";
  EXPECT_GT(tally.refined_input, 0);
}

// The hard generator settings (test::hard_polygon_options), seeds 1 to 30 each.
TEST(MeshPolygonProperty, HardGeneratorSettingsCertified) {
  Tally tally;
  for (const test::PolygonOptions& o : test::hard_polygon_options())
    for (std::uint64_t seed = 1; seed <= 30; ++seed)
      expect_certified(make_domain(test::random_polygon_with_holes(seed, o)), test::describe_polygon(seed, o), tally);
  std::cout << "90 polygons: " << tally.refined_input << " meshed by the refined CDT of the input; "
            << tally.triangles << " triangles against the quadtree's " << tally.quadtree_triangles << "\n";
}

TEST(MeshPolygonProperty, CorpusCertifiedAndNoLargerThanTheQuadtreeMesh) {
  Tally tally;
  for (const char* name : {"comb", "l_shape", "regions", "spike_10deg", "spike_1deg", "spike_5deg", "square",
                           "square_holes"}) {
    const std::string path = test::data_path(std::string("2d/") + name + ".poly");
    expect_certified(make_domain(read_pslg(path)), path, tally);
  }
  EXPECT_EQ(tally.refined_input, 8);
}

TEST(MeshPolygonProperty, SizeBoundAndQuadtreeOptionUseTheQuadtree) {
  const Domain2 d = make_domain(read_pslg(test::data_path("2d/comb.poly")));
  for (int variant = 0; variant < 2; ++variant) {
    QuadMeshOptions options;
    if (variant == 0) options.max_size = 0.25;
    if (variant == 1) options.quadtree = true;
    const QuadMeshResult r = mesh_polygon(d, options);
    EXPECT_FALSE(r.stats.refined_input) << variant;
    EXPECT_EQ(r.mesh.triangles, quad_mesh(d, options).mesh.triangles) << variant;
    EXPECT_TRUE(check_mesh(r.mesh, d).valid()) << variant;
  }
}

}  // namespace
}  // namespace pqmesh
