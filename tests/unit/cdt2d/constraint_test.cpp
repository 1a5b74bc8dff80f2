// Constrained triangulations: random non-crossing constraints (polygon sides,
// greedy random segments on a grid with T-junctions and overlaps), nearly
// straight chains, constraints through input points, keep_inside on a star
// polygon, and the error cases.
#include <cmath>

#include "cdt_test_util.hpp"
#include "pqmesh/errors.hpp"

namespace pqmesh::cdt2d::test {
namespace {

// Open segments ab and cd cross at a point interior to both.
bool cross_properly(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  return orient2d(a, b, c) * orient2d(a, b, d) == Sign::Negative &&
         orient2d(c, d, a) * orient2d(c, d, b) == Sign::Negative;
}

// A star-shaped polygon around (0.5, 0.5): m vertices at jittered, strictly
// increasing angles (cos/sin only construct coordinates; simplicity is then
// verified exactly: the centre is strictly left of every side). Returns the
// vertex ids appended to pts, counter-clockwise, or an empty list if the
// check fails.
std::vector<int> add_star_polygon(std::vector<Vec2>& pts, std::mt19937_64& rng, int m) {
  const Vec2 c{0.5, 0.5};
  std::vector<int> ids;
  for (int k = 0; k < m; ++k) {
    const double theta = (k + 0.1 + 0.8 * unit(rng)) * 2 * 3.141592653589793 / m;
    const double r = 0.15 + 0.3 * unit(rng);
    ids.push_back(static_cast<int>(pts.size()));
    pts.push_back({c.x + r * std::cos(theta), c.y + r * std::sin(theta)});
  }
  for (int k = 0; k < m; ++k)
    if (orient2d(pts[ids[k]], pts[ids[(k + 1) % m]], c) != Sign::Positive) return {};
  return ids;
}

double area_of(const std::vector<Vec2>& pts, const Tris& tris) {
  double s = 0;
  for (const auto& t : tris) s += 0.5 * cross(pts[t[1]] - pts[t[0]], pts[t[2]] - pts[t[0]]);
  return s;
}

TEST(CdtConstraints, StarPolygonSidesAmongRandomPoints) {
  int checked = 0;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    std::mt19937_64 rng(seed);
    CdtInput in;
    in.points = random_points(seed * 7 + 1, 300);
    const std::vector<int> ids = add_star_polygon(in.points, rng, 5 + static_cast<int>(seed % 40));
    if (ids.empty()) continue;
    for (std::size_t k = 0; k < ids.size(); ++k) in.constraints.push_back({ids[k], ids[(k + 1) % ids.size()]});
    expect_cdt(in.points, in.constraints, constrained_delaunay(in, false).triangles,
               "star seed " + std::to_string(seed));

    // keep_inside: exactly the polygon, area by the shoelace formula.
    const Tris inside = constrained_delaunay(in, true).triangles;
    double shoelace = 0;
    for (std::size_t k = 0; k < ids.size(); ++k)
      shoelace +=
          0.5 * cross(in.points[ids[k]] - Vec2{0.5, 0.5}, in.points[ids[(k + 1) % ids.size()]] - Vec2{0.5, 0.5});
    EXPECT_NEAR(area_of(in.points, inside), shoelace, 1e-12);
    int outside_vertex = 0;
    for (const auto& t : inside)
      for (int v : t) {
        // Every used vertex is in the closed polygon (star-shaped from the centre).
        for (std::size_t k = 0; k < ids.size(); ++k) {
          const Vec2 a = in.points[ids[k]], b = in.points[ids[(k + 1) % ids.size()]];
          if (orient2d({0.5, 0.5}, a, in.points[v]) != Sign::Negative &&
              orient2d({0.5, 0.5}, b, in.points[v]) == Sign::Negative && orient2d(a, b, in.points[v]) == Sign::Negative)
            ++outside_vertex;
        }
      }
    EXPECT_EQ(outside_vertex, 0);
    const CheckReport report = check_mesh_topology(to_mesh(in.points, inside, true));
    EXPECT_TRUE(report.valid()) << report.to_text();
    ++checked;
  }
  EXPECT_GE(checked, 25);
}

// Draws `tries` random pairs of distinct points of `in` and adds each as a
// constraint when it crosses no constraint already there properly.
void add_greedy_segments(CdtInput& in, std::mt19937_64& rng, int tries) {
  const int n = static_cast<int>(in.points.size());
  for (int k = 0; k < tries; ++k) {
    const int a = static_cast<int>(rng() % static_cast<std::uint64_t>(n));
    const int b = static_cast<int>(rng() % static_cast<std::uint64_t>(n));
    if (a == b) continue;
    bool ok = true;
    for (const auto& c : in.constraints)
      if (cross_properly(in.points[a], in.points[b], in.points[c[0]], in.points[c[1]])) ok = false;
    if (ok) in.constraints.push_back({a, b});
  }
}

// Grid points (cocircular everywhere) with random segments between grid
// points, accepted greedily unless they cross an accepted one properly.
// Accepted segments may overlap collinearly, end in the middle of another
// (T-junction) or pass through grid points (split there).
TEST(CdtConstraints, GreedyRandomSegmentsOnGrid) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    std::mt19937_64 rng(seed);
    CdtInput in;
    const int m = 9 + static_cast<int>(seed % 5);
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j) in.points.push_back({0.25 * i, 0.25 * j});
    std::shuffle(in.points.begin(), in.points.end(), rng);
    add_greedy_segments(in, rng, 60);
    ASSERT_GE(in.constraints.size(), 5u);
    expect_cdt(in.points, in.constraints, constrained_delaunay(in, false).triangles,
               "grid segments seed " + std::to_string(seed));
  }
}

TEST(CdtConstraints, GreedyRandomSegmentsAmongRandomPoints) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    std::mt19937_64 rng(seed);
    CdtInput in;
    in.points = random_points(seed + 1000, 1500);
    sort_z_order(in.points);
    add_greedy_segments(in, rng, 200);
    expect_cdt(in.points, in.constraints, constrained_delaunay(in, false).triangles,
               "random segments seed " + std::to_string(seed));
  }
}

// A constraint along a row of grid points passes through all of them and is
// split there; a diagonal one too.
TEST(CdtConstraints, ConstraintThroughInputPointsIsSplit) {
  CdtInput in;
  const int m = 12;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) in.points.push_back({1.0 * i, 1.0 * j});
  auto id = [&](int i, int j) { return i * m + j; };
  // A row, a diagonal ending on the row (T-junction), an anti-diagonal above
  // it and a slope-2 segment below it (through (4, 2)); none cross properly.
  in.constraints = {{id(0, 5), id(11, 5)}, {id(0, 0), id(5, 5)}, {id(6, 11), id(11, 6)}, {id(3, 0), id(5, 4)}};
  const Tris t = constrained_delaunay(in, false).triangles;
  expect_cdt(in.points, in.constraints, t, "through grid points");
  EXPECT_EQ(constraint_chain(in.points, id(0, 5), id(11, 5)).size(), 12u);  // the oracle sees the split
}

// Chains of points within an ulp of a straight line, consecutive points
// constrained (the fast path), plus a few random points around them.
TEST(CdtConstraints, NearlyStraightConstrainedChains) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    std::mt19937_64 rng(seed);
    CdtInput in;
    const double slope = 0.2 + 0.2 * unit(rng);  // parallel chains 3e-10 apart never cross
    for (int c = 0; c < 4; ++c) {
      const double offset = 0.3 + c * 3e-10;
      const int first = static_cast<int>(in.points.size());
      for (int i = 0; i < 400; ++i) {
        const double x = i / 512.0;
        double y = slope * x + offset;
        const std::uint64_t r = rng() % 3;
        if (r == 0) y = std::nextafter(y, 2.0);
        if (r == 1) y = std::nextafter(y, -2.0);
        in.points.push_back({x, y});
        if (i > 0) in.constraints.push_back({first + i - 1, first + i});
      }
    }
    for (int i = 0; i < 200; ++i) in.points.push_back({unit(rng), unit(rng)});
    expect_cdt(in.points, in.constraints, constrained_delaunay(in, false).triangles,
               "chains seed " + std::to_string(seed));
  }
}

TEST(CdtConstraints, CrossingConstraintsThrow) {
  CdtInput in;
  in.points = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, -1}, {1, 3}};
  in.constraints = {{0, 2}, {1, 3}};
  EXPECT_THROW(constrained_delaunay(in, false), InternalError);
  in.constraints = {{0, 2}, {4, 5}};  // crosses 0-2 at (1, 1)
  EXPECT_THROW(constrained_delaunay(in, false), InternalError);
  // Crossing among random points (many edges in between).
  in.points = random_points(5, 400);
  in.points.insert(in.points.end(), {{-1, -1}, {2, 2}, {-1, 2}, {2, -1}});
  in.constraints = {{400, 401}, {402, 403}};
  EXPECT_THROW(constrained_delaunay(in, false), InternalError);
}

TEST(CdtConstraints, BadConstraintIdsThrow) {
  CdtInput in;
  in.points = {{0, 0}, {1, 0}, {0, 1}};
  in.constraints = {{0, 3}};
  EXPECT_THROW(constrained_delaunay(in, false), InternalError);
  in.constraints = {{1, 1}};
  EXPECT_THROW(constrained_delaunay(in, false), InternalError);
}

// keep_inside with inconsistent loops: a hole loop turning the wrong way puts
// the ring between the loops on the right of the hole loop and on the left
// of the outer loop.
TEST(CdtConstraints, InconsistentLoopsThrowInKeepInside) {
  CdtInput in;
  in.points = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {3, 1}, {3, 3}, {1, 3}};
  in.constraints = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
  EXPECT_THROW(constrained_delaunay(in, true), InternalError);
  EXPECT_NO_THROW(constrained_delaunay(in, false));
  // The correct hole orientation works and keeps 16 - 4 area units.
  in.constraints = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 7}, {7, 6}, {6, 5}, {5, 4}};
  const Tris t = constrained_delaunay(in, true).triangles;
  EXPECT_EQ(area_of(in.points, t), 12.0);
  // An open chain has no inside: the fill leaks around its end.
  in.constraints = {{0, 1}, {1, 2}, {2, 3}};
  EXPECT_THROW(constrained_delaunay(in, true), InternalError);
  // An interior edge given in both directions: inside on both sides.
  in.constraints = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 6}, {6, 0}};
  const Tris with_diagonal = constrained_delaunay(in, true).triangles;
  EXPECT_EQ(area_of(in.points, with_diagonal), 16.0);
  expect_cdt(in.points, in.constraints, constrained_delaunay(in, false).triangles, "interior edge");
  // The outer loop clockwise: its left side is the unbounded outside.
  in.constraints = {{1, 0}, {2, 1}, {3, 2}, {0, 3}};
  EXPECT_THROW(constrained_delaunay(in, true), InternalError);
}

TEST(CdtConstraints, DeterministicWithConstraints) {
  std::mt19937_64 rng(3);
  CdtInput in;
  in.points = random_points(31, 2000);
  const std::vector<int> ids = add_star_polygon(in.points, rng, 40);
  ASSERT_FALSE(ids.empty());
  for (std::size_t k = 0; k < ids.size(); ++k) in.constraints.push_back({ids[k], ids[(k + 1) % ids.size()]});
  EXPECT_EQ(constrained_delaunay(in, true).triangles, constrained_delaunay(in, true).triangles);
  EXPECT_EQ(constrained_delaunay(in, false).triangles, constrained_delaunay(in, false).triangles);
}

}  // namespace
}  // namespace pqmesh::cdt2d::test
