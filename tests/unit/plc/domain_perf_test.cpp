// Scale test: a closed UV sphere of ~20,000 triangles validates and answers many
// locate queries correctly (times are printed for information, not asserted).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

#include "domain_fixtures.hpp"
#include "plc/point_location.hpp"
#include "pqmesh/domain.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

TEST(DomainPerf, SphereOf20000Triangles) {
  const Plc3 plc = test::uv_sphere(100, 100);  // 2 * 100 * 99 = 19,800 triangles
  ASSERT_EQ(plc.facets.size(), 19800u);
  auto t0 = std::chrono::steady_clock::now();
  const Domain3 d = make_domain(plc);
  const double validate = seconds_since(t0);
  std::printf("[ perf ] make_domain, %zu facets: %.3f s\n", plc.facets.size(), validate);
  // make_domain merges the two triangles of a band quad when its four
  // vertices happen to be exactly coplanar in doubles (one marker everywhere;
  // merge_coplanar.hpp): each such quad is one facet less and one edge (its
  // diagonal) less. Counted here independently with orient3d. Two quads of
  // one band, or of two bands, are never coplanar with each other (they
  // meet at an angle), so no group has more than two triangles.
  std::size_t planar_quads = 0;
  for (std::size_t f = 2 * 100; f + 1 < plc.facets.size(); f += 2) {
    const auto& a = plc.facets[f].loops[0];      // at(i, j), at(i + 1, j), at(i + 1, j + 1)
    const auto& b = plc.facets[f + 1].loops[0];  // at(i, j), at(i + 1, j + 1), at(i, j + 1)
    const auto& P = plc.vertices;
    planar_quads += orient3d(P[a[0]], P[a[1]], P[a[2]], P[b[2]]) == Sign::Zero;
  }
  std::printf("[ perf ] %zu band quads exactly planar, merged\n", planar_quads);
  EXPECT_EQ(d.plc.facets.size(), 19800u - planar_quads);
  EXPECT_EQ(d.edges.size(), 19800u * 3 / 2 - planar_quads);
  // The inscribed polyhedron's volume is a little below 4 pi / 3.
  EXPECT_GT(d.volume, 4.18);
  EXPECT_LT(d.volume, 4.0 * std::acos(-1.0) / 3);

  // 100,000 random queries: points clearly inside (|p| < 0.99) or outside
  // (|p| > 1.01) the sphere have a known answer.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  t0 = std::chrono::steady_clock::now();
  const detail::DomainLocator3 locator(d);
  int checked = 0;
  for (int k = 0; k < 100000; ++k) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    const double r = norm(p);
    const Location got = locator.locate(p);
    if (r < 0.99) {
      ASSERT_EQ(got, Location::Inside);
      ++checked;
    } else if (r > 1.01) {
      ASSERT_EQ(got, Location::Outside);
      ++checked;
    }
  }
  const double queries = seconds_since(t0);
  std::printf("[ perf ] 100000 locate queries: %.3f s (%d with known answers)\n", queries, checked);
}

}  // namespace
}  // namespace pqmesh
