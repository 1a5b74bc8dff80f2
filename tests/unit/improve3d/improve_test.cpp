// improve_mesh (src/improve3d/improve.hpp) on meshes of the real mesher:
// the corpus models and every-run random polyhedra. For each: the coarsened
// mesh passes check_mesh, has fewer tetrahedra, its worst aspect ratio stays
// within the construction's (passed as aspect_cap), the boundary area per
// facet marker is unchanged, and a second run gives identical arrays.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include "improve3d/improve.hpp"
#include "improve_support.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/quality.hpp"
#include "pqmesh/read_domain.hpp"
#include "pqmesh/tetmesh.hpp"
#include "support/paths.hpp"
#include "support/random_domains.hpp"

namespace pqmesh {
namespace {

using improve3d::ImproveOptions;
using improve3d::ImproveStats;

Domain3 corpus(const std::string& name) { return make_domain(read_plc(test::data_path("3d/" + name))); }

struct Coarsened {
  TetMesh3 mesh;
  std::vector<int> face_facets;
  ImproveStats stats;
};

Coarsened coarsen(const Domain3& d, const TetMesh3& mesh, const std::vector<int>& face_facets,
                  const ImproveOptions& options) {
  Coarsened c{mesh, face_facets, {}};
  c.stats = improve3d::improve_mesh(d, c.mesh, c.face_facets, options);
  return c;
}

void expect_same_arrays(const Coarsened& a, const Coarsened& b, const std::string& what) {
  EXPECT_TRUE(a.mesh.vertices == b.mesh.vertices) << what;
  EXPECT_TRUE(a.mesh.tetrahedra == b.mesh.tetrahedra) << what;
  EXPECT_TRUE(a.mesh.tetrahedron_markers == b.mesh.tetrahedron_markers) << what;
  EXPECT_TRUE(a.mesh.faces == b.mesh.faces) << what;
  EXPECT_TRUE(a.mesh.face_markers == b.mesh.face_markers) << what;
  EXPECT_TRUE(a.face_facets == b.face_facets) << what;
}

void expect_same_areas(const TetMesh3& before, const TetMesh3& after, const std::string& what) {
  const auto a = test::area_per_marker(before), b = test::area_per_marker(after);
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].first, b[i].first) << what;
    EXPECT_NEAR(a[i].second, b[i].second, 1e-9 * a[i].second) << what << " marker " << a[i].first;
  }
}

// The checks of every model; returns the coarsened mesh.
Coarsened expect_coarsened(const std::string& what, const Domain3& d, const TetMesh3& mesh,
                           ImproveOptions options = {}) {
  const std::vector<int> facets = test::facets_of_faces(d, mesh);
  for (std::size_t i = 0; i < facets.size(); ++i) EXPECT_GE(facets[i], 0) << what << " boundary triangle " << i;
  const test::MeshFigures before = test::figures(mesh);
  options.aspect_cap = before.worst_aspect;
  const Coarsened c = coarsen(d, mesh, facets, options);
  const CheckReport report = check_mesh(c.mesh, d);
  EXPECT_TRUE(report.valid()) << what << ": " << report.to_text();
  const test::MeshFigures after = test::figures(c.mesh);
  EXPECT_LT(after.tetrahedra, before.tetrahedra) << what;
  EXPECT_LE(after.worst_aspect, options.aspect_cap) << what;
  EXPECT_EQ(after.worst_aspect, c.stats.worst_aspect_after) << what;
  EXPECT_EQ(after.tetrahedra, c.stats.tetrahedra_after) << what;
  EXPECT_EQ(c.face_facets.size(), c.mesh.faces.size()) << what;
  for (std::size_t i = 0; i < std::min(c.face_facets.size(), c.mesh.faces.size()); ++i)
    EXPECT_EQ(d.plc.facets[static_cast<std::size_t>(c.face_facets[i])].marker, c.mesh.face_markers[i]) << what;
  expect_same_areas(mesh, c.mesh, what);
  expect_same_arrays(c, coarsen(d, mesh, facets, options), what + " (second run)");
  std::printf("%-22s tets %8lld -> %8lld  aspect %8.3f -> %8.3f  min dihedral %6.2f -> %6.2f  %d passes %.3f s\n",
              what.c_str(), static_cast<long long>(before.tetrahedra), static_cast<long long>(after.tetrahedra),
              before.worst_aspect, after.worst_aspect, before.min_dihedral, after.min_dihedral,
              static_cast<int>(c.stats.passes), c.stats.seconds);
  return c;
}

class CorpusCoarsening : public ::testing::TestWithParam<const char*> {};

TEST_P(CorpusCoarsening, ValidFewerTetrahedraWithinTheConstructionsAspect) {
  const Domain3 d = corpus(GetParam());
  const TetMeshResult r = tet_mesh(d, test::construction_only(TetMeshOptions{}));
  ASSERT_TRUE(check_mesh(r.mesh, d).valid());
  expect_coarsened(GetParam(), d, r.mesh);
}

INSTANTIATE_TEST_SUITE_P(Corpus, CorpusCoarsening,
                         ::testing::Values("cube.poly", "l_block.poly", "schoenhardt.poly", "tuning_fork.poly",
                                           "cube_cavity.poly"));

TEST(RandomCoarsening, EveryRunSeedsValidFewerTetrahedraWithinTheConstructionsAspect) {
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    const Domain3 d = make_domain(test::random_polyhedron(seed, test::every_run_polyhedron_options()));
    const TetMeshResult r = tet_mesh(d, test::construction_only(TetMeshOptions{}));
    ASSERT_TRUE(check_mesh(r.mesh, d).valid()) << seed;
    expect_coarsened("every-run seed " + std::to_string(seed), d, r.mesh);
  }
}

// Edge removal inside facets happens on the corpus (cube_cavity's and
// tuning_fork's facets are axis-aligned), and each coarsened mesh still
// passes the checker with the same area per marker (expect_coarsened).
TEST(BoundaryFlips, MadeOnAxisAlignedFacetsAndTheMeshStaysValid) {
  std::int64_t boundary_flips = 0;
  for (const char* name : {"cube_cavity.poly", "tuning_fork.poly", "cube_through_hole.poly"}) {
    const Domain3 d = corpus(name);
    const TetMeshResult r = tet_mesh(d, test::construction_only(TetMeshOptions{}));
    ASSERT_TRUE(check_mesh(r.mesh, d).valid()) << name;
    boundary_flips += expect_coarsened(name, d, r.mesh).stats.boundary_flips;
  }
  EXPECT_GT(boundary_flips, 0);
}

// The quality target only refuses collapses: every check of expect_coarsened
// holds with it (validity, the cap, areas, determinism).
TEST(MinDihedralTarget, ValidWithinTheCapDeterministic) {
  for (const double target : {15.0, 25.0}) {
    ImproveOptions options;
    options.min_dihedral = target;
    for (const char* name : {"l_block.poly", "schoenhardt.poly", "cube_cavity.poly"}) {
      const Domain3 d = corpus(name);
      const TetMeshResult r = tet_mesh(d, test::construction_only(TetMeshOptions{}));
      ASSERT_TRUE(check_mesh(r.mesh, d).valid()) << name;
      expect_coarsened(std::string(name) + " min dihedral " + std::to_string(target), d, r.mesh, options);
    }
    for (std::uint64_t seed = 0; seed < 6; ++seed) {
      const Domain3 d = make_domain(test::random_polyhedron(seed, test::every_run_polyhedron_options()));
      const TetMeshResult r = tet_mesh(d, test::construction_only(TetMeshOptions{}));
      ASSERT_TRUE(check_mesh(r.mesh, d).valid()) << seed;
      expect_coarsened("every-run seed " + std::to_string(seed) + " min dihedral " + std::to_string(target), d,
                       r.mesh, options);
    }
  }
}

// With a size bound no new edge is longer than sqrt(3) max_size, so the
// longest edge stays within max(the input's longest, sqrt(3) max_size).
TEST(SizeBoundCoarsening, LongestEdgeWithinTheMaxSizeBound) {
  const Domain3 d = corpus("l_block.poly");
  TetMeshOptions mo;
  mo.max_size = 0.25;
  const TetMeshResult r = tet_mesh(d, test::construction_only(mo));
  ImproveOptions o;
  o.max_size = mo.max_size;
  const Coarsened c = expect_coarsened("l_block max 0.25", d, r.mesh, o);
  const double bound = std::max(test::figures(r.mesh).longest_edge, std::sqrt(3.0) * o.max_size);
  EXPECT_LE(test::figures(c.mesh).longest_edge, bound);
  const Coarsened free = coarsen(d, r.mesh, test::facets_of_faces(d, r.mesh), {});
  EXPECT_LT(free.mesh.tetrahedra.size(), c.mesh.tetrahedra.size());  // the bound holds some collapses back
}

// The size field bounds like max_size, locally.
TEST(SizeBoundCoarsening, SizeFieldPointKeepsEdgesShortNearIt) {
  const Domain3 d = corpus("cube.poly");
  TetMeshOptions mo;
  mo.max_size = 0.125;
  const TetMeshResult r = tet_mesh(d, test::construction_only(mo));
  ImproveOptions o;
  o.size_points = {d.bbox_min};
  o.sizes = {0.05};
  const Coarsened c = expect_coarsened("cube size point", d, r.mesh, o);
  const double longest_before = test::figures(r.mesh).longest_edge;
  for (const auto& t : c.mesh.tetrahedra)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const Vec3 p = c.mesh.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(i)])];
        const Vec3 q = c.mesh.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(j)])];
        const double h = o.sizes[0] + norm(0.5 * (p + q) - o.size_points[0]);
        EXPECT_LE(norm(q - p), std::max(std::sqrt(3.0) * h, longest_before));
      }
}

// A cap below the mesh's worst aspect ratio refuses every collapse that
// touches a tetrahedron above it, and never makes a tetrahedron above it.
TEST(QualityCap, NoNewTetrahedronAboveTheCap) {
  const Domain3 d = corpus("cube.poly");
  const TetMeshResult r = tet_mesh(d, test::construction_only(TetMeshOptions{}));
  const std::vector<int> facets = test::facets_of_faces(d, r.mesh);
  ImproveOptions o;
  o.aspect_cap = 4.5;
  o.target_aspect = 4.5;
  const Coarsened c = coarsen(d, r.mesh, facets, o);
  EXPECT_TRUE(check_mesh(c.mesh, d).valid());
  const QualityReport before = quality_report(r.mesh);
  std::int64_t above_before = 0, above_after = 0;
  for (const auto& q : element_quality(r.mesh)) above_before += q.aspect_ratio > o.aspect_cap;
  for (const auto& q : element_quality(c.mesh)) above_after += q.aspect_ratio > o.aspect_cap;
  EXPECT_LE(above_after, above_before);
  EXPECT_LE(c.stats.worst_aspect_after, before.aspect_ratio.max);
}

TEST(ImproveInput, WrongSizesAndFacetIdsThrow) {
  const Domain3 d = corpus("cube.poly");
  TetMesh3 mesh = tet_mesh(d, test::construction_only(TetMeshOptions{})).mesh;
  std::vector<int> facets(mesh.faces.size() + 1, 0);
  EXPECT_THROW(improve3d::improve_mesh(d, mesh, facets, {}), InvalidInput);
  facets.pop_back();
  mesh.tetrahedron_markers.push_back(0);
  EXPECT_THROW(improve3d::improve_mesh(d, mesh, facets, {}), InvalidInput);
  mesh.tetrahedron_markers.pop_back();
  facets[0] = static_cast<int>(d.plc.facets.size());
  EXPECT_THROW(improve3d::improve_mesh(d, mesh, facets, {}), InvalidInput);
}

// Throughput on a mesh of about a million tetrahedra (printed, not asserted).
TEST(ImprovePerf, DISABLED_MillionTetrahedra) {
  const Domain3 d = corpus("cube.poly");
  TetMeshOptions mo;
  mo.max_size = 0.03 * norm(d.bbox_max - d.bbox_min);
  const TetMeshResult r = tet_mesh(d, test::construction_only(mo));
  const std::vector<int> facets = test::facets_of_faces(d, r.mesh);
  ImproveOptions o;
  o.aspect_cap = r.stats.max_aspect;
  const std::clock_t cpu = std::clock();
  const Coarsened c = coarsen(d, r.mesh, facets, o);
  const double cpu_seconds = static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC;
  EXPECT_TRUE(check_mesh(c.mesh, d).valid());
  std::printf("cube %lld -> %lld tets, %lld passes, %.3f s (cpu %.3f s), %.0f tets/s (cpu %.0f)\n",
              static_cast<long long>(c.stats.tetrahedra_before), static_cast<long long>(c.stats.tetrahedra_after),
              static_cast<long long>(c.stats.passes), c.stats.seconds, cpu_seconds,
              static_cast<double>(c.stats.tetrahedra_before) / c.stats.seconds,
              static_cast<double>(c.stats.tetrahedra_before) / cpu_seconds);
}

}  // namespace
}  // namespace pqmesh
