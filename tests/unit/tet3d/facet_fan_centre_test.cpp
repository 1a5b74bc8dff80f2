// §4.5.4, first case (box centre inside P): the fan of F ∩ b from "a
// centrally located point" of it (facet_boxes.cpp, fan_centre). Input: F
// with bounded random seed 58's normal and offset in units of the box
// b = [1/2, 1] x [0, 1/2] x [0, 1/2], clipping b's box edge x = 1/2,
// y = 1/2, the neighbour across face x = 1/2 split twice (so F ∩ b's vertex
// mean lies near the line of a chord on that face). Checked: the mesh is
// valid (check_mesh_topology), the fan point lies on F, b's worst fan
// tetrahedron is strictly better than the vertex mean's, and no warped
// point is frozen.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/plc.hpp"
#include "pqmesh/quality.hpp"
#include "predicates/predicates.hpp"
#include "tet3d/facet_boxes.hpp"
#include "tet3d/points/facet_plane.hpp"
#include "half_space_fixture.hpp"

namespace pqmesh::tet3d {
namespace {

TEST(FacetFanCentre, ThinPolygonAlongABoxEdgeGetsACentralFanPoint) {
  // F: n . q + c = 0 in b's local coordinates q = (p - (1/2, 0, 0)) / h,
  // n and c from seed 58's facet 6 and its box (leaf 31842).
  const double h = 0.5;
  const Vec3 o{0.5, 0, 0};
  const Vec3 n{-0.891341, 0.446725, -0.077117};
  const double c = -0.36280;
  // A point of F: q0 = -c n / |n|^2, then p0 = o + h q0; P is the huge
  // tetrahedron with F as a face and its fourth vertex far on F's negative
  // side (as facet_boxes_test.cpp).
  const Vec3 p0 = o + (-c * h / dot(n, n)) * n;
  const HalfSpaceDomain half = half_space_domain(p0, n, cross(n, Vec3{0, 0, 1}));
  ASSERT_GE(half.facet, 0);
  const Domain3& dom = half.domain;
  const FacetPlane plane(dom, half.facet);

  OctTree t(RootCube<3>{{0, 0, 0}, 1});
  const std::int32_t first = t.split(0);
  const std::int32_t b = first + 1;  // x in [1/2, 1], y and z in [0, 1/2]
  const std::int32_t nb = t.split(first + 0);  // its neighbour across x = 1/2, split twice there
  for (const int k : {1, 3, 5, 7}) t.split(nb + k);
  const std::vector<std::int32_t> leaves = t.leaves();
  const CornerSet corners(t, leaves);
  const std::vector<BoxJob> jobs = half_space_jobs(t, leaves, plane, half.facet);
  ASSERT_TRUE(std::any_of(jobs.begin(), jobs.end(), [&](const BoxJob& j) { return j.leaf == b && j.facet == half.facet; }));
  BoxMeshOptions opt;
  opt.warp = true;
  const BoxMesh m = mesh_boxes(t, corners, dom, jobs, opt);
  const CheckReport r = check_mesh_topology(m.mesh);
  ASSERT_TRUE(r.valid()) << r.to_text();
  EXPECT_GT(m.stats.inside, 0);

  // b's tetrahedra: the fan ones (one vertex the fan point g, kind
  // FacetCentre; the box centre v; a chord (a, b) of F ∩ b) and the cones.
  double worst_fan = 0, worst_cone = 0;
  std::vector<std::array<int, 2>> chords;
  int g = -1, v = -1;
  auto aspect = [&](int a, int b2, int c2, int d2) {
    const auto& V = m.mesh.vertices;
    return tetrahedron_quality(V[static_cast<std::size_t>(a)], V[static_cast<std::size_t>(b2)],
                               V[static_cast<std::size_t>(c2)], V[static_cast<std::size_t>(d2)])
        .aspect_ratio;
  };
  for (std::size_t i = 0; i < m.mesh.tetrahedra.size(); ++i) {
    if (m.tet_leaf[i] != b) continue;
    const auto& T = m.mesh.tetrahedra[i];
    const double a = aspect(T[0], T[1], T[2], T[3]);
    if (m.keys[static_cast<std::size_t>(T[2])].kind != VertexKind::FacetCentre) {
      worst_cone = std::max(worst_cone, a);
      continue;
    }
    worst_fan = std::max(worst_fan, a);  // fan(): (a, b, g, v)
    chords.push_back({T[0], T[1]});
    g = T[2];
    v = T[3];
  }
  ASSERT_GE(chords.size(), 6u);
  // g lies on F (rounded within an ulp of its plane, docs/algorithm/tet3d_boxes.md
  // "Vertex identities").
  const Vec3 G = m.mesh.vertices[static_cast<std::size_t>(g)];
  EXPECT_TRUE(within_ulp_of_plane(G, dom.plc.vertices[0], dom.plc.vertices[1], dom.plc.vertices[2]));
  // The vertex mean of F ∩ b (the fan point before), settled onto F along
  // the dominant axis of F's normal (x here) as facet_boxes.cpp does, and
  // the worst of the fan it would have made.
  std::vector<int> poly;
  for (const auto& ch : chords)
    for (const int p : ch)
      if (std::find(poly.begin(), poly.end(), p) == poly.end()) poly.push_back(p);
  Vec3 mean;
  for (const int p : poly) mean = mean + m.mesh.vertices[static_cast<std::size_t>(p)];
  mean = (1.0 / static_cast<double>(poly.size())) * mean;
  const Vec3 M = plane.settle(mean, 0);
  double worst_mean = 0;
  const Vec3 Vc = m.mesh.vertices[static_cast<std::size_t>(v)];
  for (const auto& ch : chords)
    worst_mean = std::max(worst_mean, tetrahedron_quality(m.mesh.vertices[static_cast<std::size_t>(ch[0])],
                                                          m.mesh.vertices[static_cast<std::size_t>(ch[1])], M, Vc)
                                          .aspect_ratio);
  std::printf("box b: %zu chords; worst fan from the vertex mean %.1f, from the chosen point %.1f; worst cone %.1f; "
              "rebuilds %lld, frozen %lld\n",
              chords.size(), worst_mean, worst_fan, worst_cone, static_cast<long long>(m.warp_rebuilds),
              static_cast<long long>(m.warp_inverting_left));
  // The rule applies here (the mean's fan is the box's weakest part) and the
  // chosen point is strictly better than the mean.
  EXPECT_GT(worst_mean, worst_cone);
  EXPECT_LT(worst_fan, worst_mean);
  // With the mean, a fan tetrahedron over the chord from the warped corner
  // (0.0068 h from F, moved h/16) inverts and the rebuild loop freezes that
  // corner; the chosen point has every fan tetrahedron positive.
  EXPECT_EQ(m.warp_inverting_left, 0);
}

}  // namespace
}  // namespace pqmesh::tet3d
