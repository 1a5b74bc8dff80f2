// Diagnosis probe (never part of the suite: DISABLED_).
// For seeded bounded random polyhedra (tests/support/random_domains.hpp,
// bounded_feature_polyhedron_options) it runs the pipeline of tet_mesh (the
// generic-grid octree, mesh3d::plan_all_kinds, warped tet3d::mesh_boxes) and
// prints, for the worst tetrahedra by aspect ratio, the box that made them:
// job kind (empty / facet / edge / vertex = united 2x2x2 box / two-facet),
// leaf and size h, each vertex's key kind and facet with its coordinates in
// units of h relative to the leaf's low corner (a united box extends one leaf
// below it along some axes; a warped box vertex also where it came from),
// and for edge and two-facet boxes the P edge. The warp counters (conflicts = refused moves, inverting = frozen by the
// rebuild loop, shortened) say whether warping left the box alone.
//
// Run:  test_mesh3d --gtest_also_run_disabled_tests --gtest_filter='*WorstBoxProbe*'
// Env:  PQMESH_PROBE_SEEDS="58,76,122,125" (default), PQMESH_PROBE_SHOW=3
//       (tetrahedra printed per seed), PQMESH_PROBE_FAMILY=bounded (default),
//       suite, every_run or harsh (the random family the seeds index), or
//       flat (every-run seeds with every facet triangle its own facet,
//       tests/support/flat_edge_domains.hpp);
//       PQMESH_PROBE_FILE=data/3d/schoenhardt.poly probes that input file
//       instead of the seeds (its "seed" is printed as 0).
// The mesh is checked (check_mesh) like every mesh a test makes; the probe
// asserts nothing about quality (that is random_polyhedra_test.cpp's job).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "mesh3d/box_plan.hpp"
#include "mv3d/octree_builder.hpp"
#include "pqmesh/alpha.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/quality.hpp"
#include "pqmesh/read_domain.hpp"
#include "support/flat_edge_domains.hpp"
#include "support/random_domains.hpp"
#include "tet3d/facet_boxes.hpp"
#include "warped_box_mesh.hpp"

namespace pqmesh {
namespace {

const char* vertex_kind_name(tet3d::VertexKind k) {
  static constexpr const char* kNames[] = {"Grid",         "FacetCrossing",      "ChordMidpoint", "ChordProjection",
                                           "BoxOnFacet",   "FacetCentre",        "BoxClip",       "Warped",
                                           "EdgeCrossing", "CrossingProjection", "EdgeMidpoint",  "PVertex",
                                           "TwoFacetApex", "TwoFacetCentre",     "EdgeFacetPoint"};
  const auto i = static_cast<std::size_t>(k);
  return i < std::size(kNames) ? kNames[i] : "?";
}

const char* job_kind_name(const tet3d::BoxJob& j) {
  switch (j.kind) {
    case tet3d::BoxKind::FromFacet: return j.facet < 0 ? "empty" : "facet";
    case tet3d::BoxKind::Empty: return "empty";
    case tet3d::BoxKind::Facet: return "facet";
    case tet3d::BoxKind::Edge: return "edge";
    case tet3d::BoxKind::Vertex: return "vertex(united)";
    case tet3d::BoxKind::TwoFacet: return "two-facet";
    default: return "?";
  }
}

std::vector<std::uint64_t> probe_seeds() {
  const char* env = std::getenv("PQMESH_PROBE_SEEDS");
  std::vector<std::uint64_t> out;
  std::stringstream ss(env != nullptr ? env : "58,76,122,125");
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(std::strtoull(item.c_str(), nullptr, 10));
  return out;
}

test::PolyhedronOptions probe_family() {
  const char* env = std::getenv("PQMESH_PROBE_FAMILY");
  const std::string name = env != nullptr ? env : "bounded";
  if (name == "suite") return test::suite_polyhedron_options();
  if (name == "every_run") return test::every_run_polyhedron_options();
  if (name == "harsh") return test::harsh_polyhedron_options();
  if (name != "bounded") ADD_FAILURE() << "PQMESH_PROBE_FAMILY: unknown family " << name << ", using bounded";
  return test::bounded_feature_polyhedron_options();
}

Domain3 probe_domain(std::uint64_t seed) {
  const char* file = std::getenv("PQMESH_PROBE_FILE");
  if (file != nullptr) return make_domain(read_plc(file));
  const char* family = std::getenv("PQMESH_PROBE_FAMILY");
  if (family != nullptr && std::string(family) == "flat") return test::every_run_seed_as_triangles(seed);
  return make_domain(test::random_polyhedron(seed, probe_family()));
}

void probe(std::uint64_t seed, int show) {
  const Domain3 d = probe_domain(seed);
  const test::WarpedBoxRun run = test::warped_box_run(d);
  const tet3d::BoxMesh& m = run.mesh;
  const mesh3d::BoxPlan& plan = run.plan;
  const OctTree& tree = run.builder->tree();
  std::printf(
      "seed %llu: %zu tetrahedra; warped %lld, refused (conflicts) %lld, frozen (inverting) %lld in %lld "
      "rebuilds, shortened %lld, first pass %lld, two-apex edge boxes %lld, flat-cone two-apex %lld, facet fans %lld\n",
      static_cast<unsigned long long>(seed), m.mesh.tetrahedra.size(), static_cast<long long>(m.warped),
      static_cast<long long>(m.warp_conflicts), static_cast<long long>(m.warp_inverting_left),
      static_cast<long long>(m.warp_rebuilds), static_cast<long long>(m.warp_shortened),
      static_cast<long long>(m.warp_first_pass), static_cast<long long>(m.stats.edge_two_apex),
      static_cast<long long>(m.stats.edge_two_apex_flat), static_cast<long long>(m.stats.edge_facet_fans));
  std::vector<std::pair<double, std::size_t>> by_aspect;
  for (std::size_t t = 0; t < m.mesh.tetrahedra.size(); ++t) {
    const auto& T = m.mesh.tetrahedra[t];
    auto at = [&](int i) { return m.mesh.vertices[static_cast<std::size_t>(T[static_cast<std::size_t>(i)])]; };
    by_aspect.push_back({tetrahedron_quality(at(0), at(1), at(2), at(3)).aspect_ratio, t});
  }
  std::sort(by_aspect.rbegin(), by_aspect.rend());
  const double alpha = compute_alpha(d.plc).radians;
  const double worst = by_aspect.empty() ? 0.0 : by_aspect.front().first;
  std::printf("  alpha %.2f deg, aspect %.1f, aspect x alpha %.1f\n", alpha * 180 / std::numbers::pi, worst,
              worst * alpha);
  for (int s = 0; s < show && s < static_cast<int>(by_aspect.size()); ++s) {
    const std::size_t t = by_aspect[static_cast<std::size_t>(s)].second;
    const tet3d::BoxJob& j = plan.jobs[static_cast<std::size_t>(m.tet_job[t])];
    const double h = tree.side(j.leaf);
    const Vec3 lo = tet3d::grid_coordinates(tree, tet3d::key_corner(tree.key(j.leaf), 0));
    std::printf("  #%d aspect %.1f: %s box, job %d, leaf %d, h %.6g, low corner (%.6f %.6f %.6f)\n", s,
                by_aspect[static_cast<std::size_t>(s)].first, job_kind_name(j), m.tet_job[t], j.leaf, h, lo.x, lo.y,
                lo.z);
    for (const std::int32_t v : m.mesh.tetrahedra[t]) {
      const tet3d::VertexKey& key = m.keys[static_cast<std::size_t>(v)];
      const Vec3 r = (1.0 / h) * (m.mesh.vertices[static_cast<std::size_t>(v)] - lo);
      std::printf("    %-18s facet %3d at (%.5f %.5f %.5f) h", vertex_kind_name(key.kind), key.facet, r.x, r.y, r.z);
      if (key.kind == tet3d::VertexKind::Warped) {
        const Vec3 g = (1.0 / h) * (tet3d::grid_coordinates(tree, key.p) - lo);
        std::printf(", warped from (%.5f %.5f %.5f) h", g.x, g.y, g.z);
      }
      std::printf("\n");
    }
    if (j.kind == tet3d::BoxKind::Edge || j.kind == tet3d::BoxKind::TwoFacet) {
      const DomainEdge& e = d.edges[static_cast<std::size_t>(j.apex)];
      const Vec3 a = (1.0 / h) * (d.plc.vertices[static_cast<std::size_t>(e.a)] - lo);
      const Vec3 b = (1.0 / h) * (d.plc.vertices[static_cast<std::size_t>(e.b)] - lo);
      std::printf("    P edge %d (facets %d, %d): (%.4f %.4f %.4f) -> (%.4f %.4f %.4f) h\n", j.apex, e.facets[0],
                  e.facets[1], a.x, a.y, a.z, b.x, b.y, b.z);
    }
  }
  const CheckReport report = check_mesh(m.mesh, d);
  EXPECT_TRUE(report.valid()) << "seed " << seed << ": " << report.to_text();
}

TEST(WorstBoxProbe, DISABLED_BoundedSeeds) {
  const char* show_env = std::getenv("PQMESH_PROBE_SHOW");
  const int show = show_env != nullptr ? std::atoi(show_env) : 3;
  if (std::getenv("PQMESH_PROBE_FILE") != nullptr) probe(0, show);
  else
    for (const std::uint64_t seed : probe_seeds()) probe(seed, show);
}

}  // namespace
}  // namespace pqmesh
