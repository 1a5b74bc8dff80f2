// The passes after the collapses (src/improve3d/smooth.hpp, flips.hpp) on
// the inputs of improve_test.cpp: each model is coarsened once with the
// collapses alone (smooth and flip off) and once with everything. With
// everything the mesh passes check_mesh, its worst aspect ratio stays within
// the cap and is no worse than after the collapses alone, its minimum
// dihedral angle is at least the one after the collapses alone, a second run
// gives identical arrays, the collapses are the same, the boundary is the
// same (the same triangles, or, after flips inside a facet, as many triangles
// per facet on the same vertices: the checker then confirms they cover each
// facet exactly), and only movable vertices moved: interior vertices, vertices
// inside one axis-aligned facet within its plane, vertices on an axis-parallel
// input edge along it, and vertices of a slanted facet or edge within an ulp
// of it; input vertices are bit-identical.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "improve3d/improve.hpp"
#include "improve_support.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/read_domain.hpp"
#include "pqmesh/tetmesh.hpp"
#include "predicates/predicates.hpp"
#include "support/paths.hpp"
#include "support/random_domains.hpp"

namespace pqmesh {
namespace {

using improve3d::ImproveOptions;
using improve3d::ImproveStats;

Domain3 corpus(const std::string& name) { return make_domain(read_plc(test::data_path("3d/" + name))); }

struct Improved {
  TetMesh3 mesh;
  std::vector<int> face_facets;
  ImproveStats stats;
};

Improved run(const Domain3& d, const TetMesh3& mesh, const std::vector<int>& facets, const ImproveOptions& options) {
  Improved r{mesh, facets, {}};
  r.stats = improve3d::improve_mesh(d, r.mesh, r.face_facets, options);
  return r;
}

// Sorted facet ids of the boundary triangles, and sorted vertices on the boundary.
std::pair<std::vector<int>, std::vector<int>> boundary_summary(const Improved& r) {
  std::vector<int> facets = r.face_facets, vertices;
  for (const auto& f : r.mesh.faces) vertices.insert(vertices.end(), f.begin(), f.end());
  std::sort(facets.begin(), facets.end());
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  return {facets, vertices};
}

// `after` has the boundary of `before`: identical triangles when it made no boundary flip,
// otherwise as many triangles per facet on the same boundary vertices.
void expect_same_boundary(const Improved& before, const Improved& after, const std::string& what) {
  if (after.stats.boundary_flips == 0) {
    EXPECT_TRUE(after.mesh.faces == before.mesh.faces) << what;
    EXPECT_TRUE(after.face_facets == before.face_facets) << what;
  }
  EXPECT_TRUE(boundary_summary(after) == boundary_summary(before)) << what;
}

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

// The axis whose coordinate all PLC vertices of facet f share bit for bit, or -1.
int facet_axis(const Domain3& d, int f) {
  for (int axis = 0; axis < 3; ++axis) {
    bool same = true;
    const double c = axis_coord(d.plc.vertices[static_cast<std::size_t>(d.plc.facets[static_cast<std::size_t>(f)].loops[0][0])], axis);
    for (const auto& loop : d.plc.facets[static_cast<std::size_t>(f)].loops)
      for (const int x : loop) same = same && same_bits(c, axis_coord(d.plc.vertices[static_cast<std::size_t>(x)], axis));
    if (same) return axis;
  }
  return -1;
}

struct Moves {
  std::int64_t interior = 0, on_facet = 0, on_edge = 0, slanted = 0;  // slanted: of on_facet + on_edge
};

// A vertex moved onto a slanted feature: within an ulp of the plane of facet f, or of an input
// edge between facets f and g (exact; the checker's rule for rounded points).
bool within_ulp_of_facet(const Domain3& d, int f, Vec3 p) {
  for (std::size_t t = 0; t < d.facet_triangles.size(); ++t) {
    if (d.facet_triangle_owner[t] != f) continue;
    const auto& k = d.facet_triangles[t];
    return within_ulp_of_plane(p, d.plc.vertices[static_cast<std::size_t>(k[0])],
                               d.plc.vertices[static_cast<std::size_t>(k[1])],
                               d.plc.vertices[static_cast<std::size_t>(k[2])]);
  }
  return false;
}

bool within_ulp_of_edge(const Domain3& d, int f, int g, Vec3 p) {
  for (const DomainEdge& e : d.edges)
    if (((e.facets[0] == f && e.facets[1] == g) || (e.facets[0] == g && e.facets[1] == f)) &&
        within_ulp_of_segment(p, d.plc.vertices[static_cast<std::size_t>(e.a)], d.plc.vertices[static_cast<std::size_t>(e.b)]))
      return true;
  return false;
}

// A moved vertex on the input edge between facets f and g: on a slanted edge, within an ulp of
// it; otherwise it changed one coordinate only, and that edge runs along that axis through it
// (its end points share the other two coordinates with the vertex, bit for bit).
void expect_moved_along_its_edge(const Domain3& d, int f, int g, Vec3 a, Vec3 b, const std::string& what) {
  int differing = 0;
  for (int axis = 0; axis < 3; ++axis) differing += !same_bits(axis_coord(a, axis), axis_coord(b, axis));
  if (differing > 1) {
    EXPECT_TRUE(within_ulp_of_edge(d, f, g, b)) << what << ": a vertex moved off its slanted edge";
    return;
  }
  int changed = -1, changes = 0;
  for (int axis = 0; axis < 3; ++axis)
    if (!same_bits(axis_coord(a, axis), axis_coord(b, axis))) changed = axis, ++changes;
  EXPECT_EQ(changes, 1) << what << ": an edge vertex changed " << changes << " coordinates";
  bool on_line = false;
  for (const DomainEdge& e : d.edges) {
    if (!((e.facets[0] == f && e.facets[1] == g) || (e.facets[0] == g && e.facets[1] == f))) continue;
    const Vec3 p = d.plc.vertices[static_cast<std::size_t>(e.a)], q = d.plc.vertices[static_cast<std::size_t>(e.b)];
    bool all = true;
    for (int axis = 0; axis < 3; ++axis)
      if (axis != changed)
        all = all && same_bits(axis_coord(p, axis), axis_coord(b, axis)) && same_bits(axis_coord(q, axis), axis_coord(b, axis));
    on_line = on_line || all;
  }
  EXPECT_TRUE(on_line) << what << ": an edge vertex left its edge's line";
}

// Every vertex of `smoothed` that differs from `collapsed` (same vertices in
// the same order: the later passes delete none) is interior, or lies inside one
// axis-aligned facet and kept that coordinate bit for bit.
Moves expect_only_movable_moved(const Domain3& d, const Improved& collapsed, const Improved& smoothed, const std::string& what) {
  Moves moves;
  EXPECT_EQ(collapsed.mesh.vertices.size(), smoothed.mesh.vertices.size()) << what;
  if (collapsed.mesh.vertices.size() != smoothed.mesh.vertices.size()) return moves;
  std::vector<std::vector<int>> facets(smoothed.mesh.vertices.size());
  for (std::size_t f = 0; f < smoothed.mesh.faces.size(); ++f)
    for (const int v : smoothed.mesh.faces[f]) facets[static_cast<std::size_t>(v)].push_back(smoothed.face_facets[f]);
  for (std::size_t v = 0; v < smoothed.mesh.vertices.size(); ++v) {
    const Vec3 a = collapsed.mesh.vertices[v], b = smoothed.mesh.vertices[v];
    const bool moved = !(same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z));
    if (!moved) continue;
    auto& fs = facets[v];
    std::sort(fs.begin(), fs.end());
    fs.erase(std::unique(fs.begin(), fs.end()), fs.end());
    if (fs.empty()) {
      ++moves.interior;
      continue;
    }
    if (fs.size() == 2) {
      ++moves.on_edge;
      expect_moved_along_its_edge(d, fs[0], fs[1], a, b, what + ": vertex " + std::to_string(v));
      moves.slanted += facet_axis(d, fs[0]) < 0 || facet_axis(d, fs[1]) < 0;
      continue;
    }
    ++moves.on_facet;
    EXPECT_EQ(fs.size(), 1u) << what << ": vertex " << v << " on several facets moved";
    if (fs.size() != 1) continue;
    const int axis = facet_axis(d, fs[0]);
    if (axis >= 0) {
      EXPECT_TRUE(same_bits(axis_coord(a, axis), axis_coord(b, axis))) << what << ": vertex " << v << " left its plane";
    } else {
      EXPECT_TRUE(within_ulp_of_facet(d, fs[0], b)) << what << ": vertex " << v << " left slanted facet " << fs[0];
      ++moves.slanted;
    }
  }
  return moves;
}

// The same run with the improving collapses after it (improving_collapse.hpp):
// valid, no more tetrahedra, the worst aspect ratio within the cap, and its
// boundary triangles on the same facets (a collapse removes boundary
// triangles only with a vertex).
void expect_improving_collapses(const std::string& what, const Domain3& d, const TetMesh3& mesh,
                                const std::vector<int>& facets, ImproveOptions options, const Improved& without) {
  options.improving_collapses = true;
  const Improved with = run(d, mesh, facets, options);
  const CheckReport report = check_mesh(with.mesh, d);
  EXPECT_TRUE(report.valid()) << what << ": " << report.to_text();
  EXPECT_LE(with.mesh.tetrahedra.size(), without.mesh.tetrahedra.size()) << what;
  EXPECT_LE(with.stats.worst_aspect_after, options.aspect_cap) << what;
  EXPECT_GE(with.stats.collapses, without.stats.collapses) << what;
}

Moves expect_better_than_collapses(const std::string& what, const Domain3& d, const TetMesh3& mesh,
                                   ImproveOptions options = {}) {
  const std::vector<int> facets = test::facets_of_faces(d, mesh);
  options.aspect_cap = test::figures(mesh).worst_aspect;
  options.rounds = 1;  // one round: the stages compare on the same collapses
  options.improving_collapses = false;
  ImproveOptions only = options;
  only.smooth = false;
  only.flip = false;
  const Improved collapsed = run(d, mesh, facets, only);
  only.smooth = true;
  const Improved smoothed = run(d, mesh, facets, only);
  only.smooth = false;
  only.flip = true;
  const Improved flipped = run(d, mesh, facets, only);
  const Improved full = run(d, mesh, facets, options);
  for (const Improved* r : {&smoothed, &flipped}) {
    EXPECT_TRUE(check_mesh(r->mesh, d).valid()) << what;
    EXPECT_LE(r->stats.worst_aspect_after, collapsed.stats.worst_aspect_after) << what;
    EXPECT_GE(r->stats.min_dihedral_after, collapsed.stats.min_dihedral_after) << what;
  }
  EXPECT_EQ(smoothed.stats.flips, 0) << what;
  EXPECT_EQ(flipped.stats.smoothed, 0) << what;
  EXPECT_TRUE(flipped.mesh.vertices == collapsed.mesh.vertices) << what;
  expect_same_boundary(collapsed, flipped, what);
  const CheckReport report = check_mesh(full.mesh, d);
  EXPECT_TRUE(report.valid()) << what << ": " << report.to_text();
  const test::MeshFigures c = test::figures(collapsed.mesh), f = test::figures(full.mesh);
  EXPECT_LE(f.worst_aspect, options.aspect_cap) << what;
  EXPECT_LE(f.worst_aspect, c.worst_aspect) << what;
  EXPECT_GE(f.min_dihedral, c.min_dihedral) << what;
  EXPECT_EQ(full.stats.min_dihedral_collapsed, c.min_dihedral) << what;
  EXPECT_EQ(full.stats.min_dihedral_after, f.min_dihedral) << what;
  EXPECT_EQ(full.stats.worst_aspect_after, f.worst_aspect) << what;
  EXPECT_EQ(full.stats.collapses, collapsed.stats.collapses) << what;
  EXPECT_EQ(collapsed.stats.smoothed, 0) << what;
  EXPECT_EQ(collapsed.stats.flips, 0) << what;
  expect_same_boundary(collapsed, full, what);
  const Moves moves = expect_only_movable_moved(d, collapsed, full, what);
  EXPECT_EQ(moves.interior + moves.on_facet + moves.on_edge, full.stats.smoothed) << what;
  expect_improving_collapses(what, d, mesh, facets, options, full);
  const Improved again = run(d, mesh, facets, options);
  EXPECT_TRUE(again.mesh.vertices == full.mesh.vertices) << what;
  EXPECT_TRUE(again.mesh.tetrahedra == full.mesh.tetrahedra) << what;
  EXPECT_TRUE(again.mesh.faces == full.mesh.faces) << what;
  EXPECT_TRUE(again.face_facets == full.face_facets) << what;
  std::printf("%-17s tets %6lld -> %6lld  min dihedral: input %5.2f, collapses %5.2f, +smooth %5.2f, +flips %5.2f, "
              "both %5.2f (moved %lld: %lld interior %lld facet; %lld flips, %lld on the boundary)  aspect %7.3f -> %7.3f  %.3f s "
              "(collapses alone %.3f s)\n",
              what.c_str(), static_cast<long long>(c.tetrahedra), static_cast<long long>(f.tetrahedra),
              full.stats.min_dihedral_before, c.min_dihedral, smoothed.stats.min_dihedral_after,
              flipped.stats.min_dihedral_after, f.min_dihedral, static_cast<long long>(full.stats.smoothed),
              static_cast<long long>(moves.interior), static_cast<long long>(moves.on_facet),
              static_cast<long long>(full.stats.flips), static_cast<long long>(full.stats.boundary_flips), c.worst_aspect, f.worst_aspect, full.stats.seconds,
              collapsed.stats.seconds);
  return moves;
}

class CorpusSmoothing : public ::testing::TestWithParam<const char*> {};

TEST_P(CorpusSmoothing, ValidNoWorseThanCollapsesAloneOnlyMovableVerticesMoved) {
  const Domain3 d = corpus(GetParam());
  const TetMeshResult r = tet_mesh(d, test::construction_only(TetMeshOptions{}));
  ASSERT_TRUE(check_mesh(r.mesh, d).valid());
  expect_better_than_collapses(GetParam(), d, r.mesh);
}

INSTANTIATE_TEST_SUITE_P(Corpus, CorpusSmoothing,
                         ::testing::Values("cube.poly", "l_block.poly", "schoenhardt.poly", "tuning_fork.poly",
                                           "cube_cavity.poly"));

// The random polyhedra's facets are slanted: vertices on them move too.
TEST(RandomSmoothing, EveryRunSeedsValidNoWorseThanCollapsesAlone) {
  std::int64_t slanted = 0;
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    const Domain3 d = make_domain(test::random_polyhedron(seed, test::every_run_polyhedron_options()));
    const TetMeshResult r = tet_mesh(d, test::construction_only(TetMeshOptions{}));
    ASSERT_TRUE(check_mesh(r.mesh, d).valid()) << seed;
    slanted += expect_better_than_collapses("seed " + std::to_string(seed), d, r.mesh).slanted;
  }
  EXPECT_GT(slanted, 0);
}

// With a size bound, smoothing makes no edge longer than the bound allows.
TEST(SizeBoundSmoothing, LongestEdgeWithinTheMaxSizeBound) {
  const Domain3 d = corpus("l_block.poly");
  TetMeshOptions mo;
  mo.max_size = 0.25;
  const TetMeshResult r = tet_mesh(d, test::construction_only(mo));
  ImproveOptions o;
  o.max_size = mo.max_size;
  expect_better_than_collapses("l_block max 0.25", d, r.mesh, o);
  o.aspect_cap = test::figures(r.mesh).worst_aspect;
  const Improved full = run(d, r.mesh, test::facets_of_faces(d, r.mesh), o);
  const double bound = std::max(test::figures(r.mesh).longest_edge, std::sqrt(3.0) * o.max_size);
  EXPECT_LE(test::figures(full.mesh).longest_edge, bound);
}

TEST(SizeBoundSmoothing, SizeFieldPoint) {
  const Domain3 d = corpus("cube.poly");
  TetMeshOptions mo;
  mo.max_size = 0.125;
  const TetMeshResult r = tet_mesh(d, test::construction_only(mo));
  ImproveOptions o;
  o.size_points = {d.bbox_min};
  o.sizes = {0.05};
  expect_better_than_collapses("cube size point", d, r.mesh, o);
}

}  // namespace
}  // namespace pqmesh
