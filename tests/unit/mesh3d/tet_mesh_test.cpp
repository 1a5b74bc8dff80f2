// tet_mesh (pqmesh/tetmesh.hpp) end to end on the grid-aligned corpus models,
// which mesh completely today (every leaf meeting P is flush, tet3d/boxes/empty_boxes.hpp),
// and the clear error for leaf kinds the box tetrahedra do not handle yet.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/mesh_io.hpp"
#include "pqmesh/quality.hpp"
#include "pqmesh/read_domain.hpp"
#include "pqmesh/tetmesh.hpp"
#include "predicates/predicates.hpp"
#include "support/paths.hpp"

namespace pqmesh {
namespace {

Plc3 load_plc(const std::string& name) { return read_plc(test::data_path("3d/" + name)); }

TetMeshOptions aligned() {
  TetMeshOptions o;
  o.generic_grid = false;
  return o;
}

void print_run(const char* name, const TetMeshResult& r) {
  const QualityReport q = quality_report(r.mesh);
  const TetMeshStats& s = r.stats;
  std::printf("%-14s %zu tets, %zu vertices, %zu boundary triangles; aspect max %.3f, dihedral %.2f..%.2f deg; "
              "%lld empty jobs (%lld flush), %lld touching skipped; %.3f s\n",
              name, r.mesh.tetrahedra.size(), r.mesh.vertices.size(), r.mesh.faces.size(), q.aspect_ratio.max,
              q.min_angle.min, q.max_angle.max, static_cast<long long>(s.empty_jobs),
              static_cast<long long>(s.flush_leaves), static_cast<long long>(s.touching_leaves),
              s.seconds_octree + s.seconds_classify + s.seconds_tetrahedra + s.seconds_boundary);
}

class AlignedCorpus : public ::testing::TestWithParam<const char*> {};

// The whole mesh passes the checker (volume, conformity, every facet
// recovered by the listed boundary triangles), and every boundary triangle
// carries the marker of a facet whose plane holds its three vertices exactly
// (exact orient3d = 0: on the aligned grid the boundary vertices are grid
// points on the facet planes), checked independently of the
// within_ulp_of_plane rule the mesher uses.
TEST_P(AlignedCorpus, MeshesCompletelyWithFacetMarkers) {
  const Domain3 d = make_domain(load_plc(GetParam()));
  const TetMeshResult r = tet_mesh(d, aligned());
  print_run(GetParam(), r);
  const CheckReport c = check_mesh(r.mesh, d);
  ASSERT_TRUE(c.valid()) << c.to_text();
  ASSERT_FALSE(r.mesh.faces.empty());
  EXPECT_EQ(static_cast<std::int64_t>(r.mesh.faces.size()), c.boundary_faces);
  ASSERT_EQ(r.mesh.face_markers.size(), r.mesh.faces.size());
  ASSERT_EQ(r.mesh.tetrahedron_markers.size(), r.mesh.tetrahedra.size());
  // Markers of the input: the boundary uses every one of them.
  std::set<int> input_markers, used;
  for (const Facet3& f : d.plc.facets) input_markers.insert(f.marker);
  const auto& P = d.plc.vertices;
  for (std::size_t i = 0; i < r.mesh.faces.size(); ++i) {
    const int m = r.mesh.face_markers[i];
    used.insert(m);
    bool on_some = false;
    for (std::size_t f = 0; f < d.plc.facets.size() && !on_some; ++f) {
      if (d.plc.facets[f].marker != m) continue;
      const auto& loop = d.plc.facets[f].loops[0];
      // Three loop vertices spanning the plane (the first non-collinear triple).
      for (std::size_t k = 2; k < loop.size() && !on_some; ++k) {
        const Vec3 a = P[loop[0]], b = P[loop[1]], e = P[loop[k]];
        if (norm(cross(b - a, e - a)) == 0) continue;
        bool all = true;
        for (const int v : r.mesh.faces[i]) all = all && orient3d(a, b, e, r.mesh.vertices[v]) == Sign::Zero;
        on_some = all;
        break;
      }
    }
    EXPECT_TRUE(on_some) << "boundary triangle " << i << " marker " << m << " is not on a facet with that marker";
  }
  EXPECT_EQ(used, input_markers);
  EXPECT_EQ(r.stats.facet_jobs, 0);  // aligned models: every leaf meeting P is flush
  EXPECT_GT(r.stats.flush_leaves, 0);
}

INSTANTIATE_TEST_SUITE_P(Corpus, AlignedCorpus, ::testing::Values("cube.poly", "l_block.poly"));

std::string slurp(const std::string& path) { return test::file_bytes(path); }

// Determinism: mesh twice, write, compare bytes.
TEST(TetMeshDeterminism, ByteIdenticalFiles) {
  const Domain3 d = make_domain(load_plc("l_block.poly"));
  const auto dir = std::filesystem::temp_directory_path() / ("pqmesh_mesh3d_det_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const TetMeshResult r1 = tet_mesh(d, aligned());
  ASSERT_TRUE(check_mesh(r1.mesh, d).valid());
  const TetMeshResult r2 = tet_mesh(d, aligned());
  ASSERT_TRUE(check_mesh(r2.mesh, d).valid());
  for (const char* ext : {".vtu", ".msh", ".mesh"}) {
    const std::string a = (dir / (std::string("a") + ext)).string(), b = (dir / (std::string("b") + ext)).string();
    write_mesh(r1.mesh, a);
    write_mesh(r2.mesh, b);
    const std::string sa = slurp(a), sb = slurp(b);
    EXPECT_FALSE(sa.empty());
    EXPECT_TRUE(sa == sb) << ext << " files differ";
  }
  std::filesystem::remove_all(dir);
}

// Region attributes: the first region point inside P gives every tetrahedron
// its attribute; a region point outside P is ignored (as TetGen does).
TEST(TetMeshRegions, AttributeOfTheRegionInsideP) {
  Plc3 plc = load_plc("cube.poly");
  plc.regions.push_back({{5, 5, 5}, 3, -1});        // outside the unit cube
  plc.regions.push_back({{0.3, 0.6, 0.2}, 7, -1});  // inside
  const Domain3 d = make_domain(std::move(plc));
  const TetMeshResult r = tet_mesh(d, aligned());
  ASSERT_TRUE(check_mesh(r.mesh, d).valid());
  ASSERT_EQ(r.mesh.tetrahedron_markers.size(), r.mesh.tetrahedra.size());
  for (const int m : r.mesh.tetrahedron_markers) ASSERT_EQ(m, 7);
  const Domain3 plain = make_domain(load_plc("cube.poly"));
  const TetMeshResult r0 = tet_mesh(plain, aligned());
  for (const int m : r0.mesh.tetrahedron_markers) ASSERT_EQ(m, 0);
}

// A size field refining around a point. Every tetrahedron of
// an empty box lies in its box, whose side h is at most the size function's
// minimum over the box (octree phase 0), so its longest edge is at most
// sqrt(3) h <= sqrt(3) f(x) for any x in it, e.g. its centroid.
TEST(TetMeshSizeField, ElementsAtMostTheAskedSize) {
  const Domain3 d = make_domain(load_plc("cube.poly"));
  TetMeshOptions o = aligned();
  o.max_size = 0.25;
  const Vec3 p{0.5, 0.5, 0.5};
  o.size_field.points = {p};
  o.size_field.sizes = {1.0 / 64};
  const TetMeshResult r = tet_mesh(d, o);
  print_run("cube refined", r);
  ASSERT_TRUE(check_mesh(r.mesh, d).valid());
  const TetMeshResult coarse = tet_mesh(d, aligned());
  EXPECT_GT(r.mesh.tetrahedra.size(), coarse.mesh.tetrahedra.size());
  double smallest_near = 1e300;
  for (const auto& t : r.mesh.tetrahedra) {
    const Vec3 a = r.mesh.vertices[t[0]], b = r.mesh.vertices[t[1]], c = r.mesh.vertices[t[2]],
               e = r.mesh.vertices[t[3]];
    const Vec3 g = 0.25 * (a + b + c + e);
    const double f = std::min(o.max_size, o.size_field.sizes[0] + norm(g - p));
    const double longest = std::max({norm(b - a), norm(c - a), norm(e - a), norm(c - b), norm(e - b), norm(e - c)});
    ASSERT_LE(longest, std::sqrt(3.0) * f * (1 + 1e-12));
    if (norm(g - p) < 0.05) smallest_near = std::min(smallest_near, longest);
  }
  // Elements next to the point are as small as asked there (up to the grid).
  EXPECT_LE(smallest_near, 4.0 / 64);
}

// Progress: the phases in order, with the counts of the run.
TEST(TetMeshProgress, PhasesInOrder) {
  const Domain3 d = make_domain(load_plc("cube.poly"));
  TetMeshOptions o = aligned();
  std::vector<std::string> phases;
  std::int64_t last_tets = -1, boxes = -1;
  o.progress = [&](const TetMeshProgress& p) {
    phases.push_back(p.phase);
    last_tets = p.tetrahedra;
    boxes = p.boxes;
  };
  const TetMeshResult r = tet_mesh(d, o);
  const std::vector<std::string> want = {"octree", "classify", "tetrahedra", "boundary", "improve", "done"};
  EXPECT_EQ(phases, want);
  EXPECT_EQ(last_tets, static_cast<std::int64_t>(r.mesh.tetrahedra.size()));
  EXPECT_EQ(boxes, r.stats.leaves);
}

// A model not aligned with the grid has vertex, edge and two-facet boxes:
// the run stops with MeshNotSupported naming the leaf and its kind, and
// returns nothing.
TEST(TetMeshUnsupported, ClearErrorForOtherLeafKinds) {
  const Domain3 d = make_domain(load_plc("schoenhardt.poly"));
  try {
    (void)tet_mesh(d, aligned());
    FAIL() << "schoenhardt meshed on the aligned grid, which has no vertex or edge boxes";
  } catch (const MeshNotSupported& e) {
    const std::string what = e.what();
    std::printf("schoenhardt: %s\n", what.c_str());
    EXPECT_NE(what.find("not supported by the 3D mesher"), std::string::npos) << what;
    EXPECT_NE(what.find("leaf " + std::to_string(e.ids().at(0))), std::string::npos) << what;
    EXPECT_NE(what.find(e.kind()), std::string::npos) << what;
    EXPECT_TRUE(e.kind() == "vertex-cone" || e.kind() == "edge-cone" || e.kind() == "two-facet" ||
                e.kind() == "other")
        << e.kind();
    EXPECT_EQ(e.code(), ErrorCode::Unsupported);
  }
}

}  // namespace
}  // namespace pqmesh
