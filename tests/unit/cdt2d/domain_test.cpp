// keep_inside on random polygons with holes (tests/support/random_domains):
// the loop sides of the validated Domain2 are the constraints, interior on
// the left; the kept triangles must form a valid mesh of the domain
// (check_mesh), with the domain's area.
#include "pqmesh/domain.hpp"

#include <cmath>

#include "cdt_test_util.hpp"
#include "support/random_domains.hpp"

namespace pqmesh::cdt2d::test {
namespace {

double mesh_area(const TriMesh2& m) {
  double s = 0;
  for (const auto& t : m.triangles)
    s += 0.5 * cross(m.vertices[t[1]] - m.vertices[t[0]], m.vertices[t[2]] - m.vertices[t[0]]);
  return s;
}

void expect_mesh_of_domain(const Domain2& d, const CdtInput& in, const std::string& what) {
  SCOPED_TRACE(what);
  const Tris inside = constrained_delaunay(in, true).triangles;
  const TriMesh2 mesh = to_mesh(in.points, inside, false);
  const CheckReport report = check_mesh(mesh, d);
  EXPECT_TRUE(report.valid()) << report.to_text();
  EXPECT_NEAR(mesh_area(mesh), d.area, 1e-10 * std::abs(d.area));
  // The whole hull, with the loop sides, is a constrained Delaunay triangulation.
  expect_cdt(in.points, in.constraints, constrained_delaunay(in, false).triangles, what + " (whole hull)");
}

TEST(CdtDomain, PolygonsWithHolesBoundaryOnly) {
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    const Domain2 d = make_domain(pqmesh::test::random_polygon_with_holes(seed));
    expect_mesh_of_domain(d, loops_as_constraints(d), pqmesh::test::describe_polygon(seed));
  }
}

// Extra points strictly inside the domain (Steiner points for check_mesh),
// some on a grid so that ties with boundary vertices are likely.
TEST(CdtDomain, PolygonsWithHolesAndInteriorPoints) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const Domain2 d = make_domain(pqmesh::test::random_polygon_with_holes(seed));
    CdtInput in = loops_as_constraints(d);
    std::mt19937_64 rng(seed);
    const Vec2 lo = d.bbox_min, hi = d.bbox_max;
    for (int tries = 0; tries < 400; ++tries) {
      Vec2 p{lo.x + (hi.x - lo.x) * unit(rng), lo.y + (hi.y - lo.y) * unit(rng)};
      if (tries % 2 == 0) {  // snap to a coarse dyadic grid
        const double step = std::ldexp(1.0, static_cast<int>(std::floor(std::log2(hi.x - lo.x))) - 4);
        p = {std::round(p.x / step) * step, std::round(p.y / step) * step};
      }
      if (locate(d, p) != Location::Inside) continue;
      if (std::find(in.points.begin(), in.points.end(), p) != in.points.end()) continue;
      in.points.push_back(p);
    }
    expect_mesh_of_domain(d, in, pqmesh::test::describe_polygon(seed) + " + interior points");
  }
}

}  // namespace
}  // namespace pqmesh::cdt2d::test
