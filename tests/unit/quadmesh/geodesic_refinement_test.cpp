// Geodesic, not Euclidean, refinement (thesis §4.1.1 duplicates, §4.1.6): in a
// comb whose teeth are separated by exterior slots of width w, the two sides
// of a slot are far apart inside P, so the quadtree must not refine to the
// slot width along the teeth. Checked: the triangle count for
// w = 1e-4 is at most 1.3 times the count for w = 1e-2. A mesher that used
// Euclidean distance would grow roughly like 1/w here.
#include <gtest/gtest.h>

#include <iostream>

#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/quadmesh.hpp"

namespace pqmesh {
namespace {

// A comb of `teeth` teeth of width 1/teeth - w, length 1, on a spine of height
// 0.25; slot width w (outside P). Counter-clockwise outer loop only.
Pslg2 comb(int teeth, double w) {
  Pslg2 p;
  const double pitch = 1.0 / teeth;
  p.vertices.push_back({0, 0});
  p.vertices.push_back({1, 0});
  // Right edge up, then the teeth from right to left.
  for (int t = teeth - 1; t >= 0; --t) {
    const double x0 = t * pitch, x1 = (t + 1) * pitch - (t == teeth - 1 ? 0 : w);
    p.vertices.push_back({x1, 1.25});
    p.vertices.push_back({x0, 1.25});
    if (t > 0) {
      p.vertices.push_back({x0, 0.25});
      p.vertices.push_back({x0 - w, 0.25});
    }
  }
  const int n = static_cast<int>(p.vertices.size());
  for (int i = 0; i < n; ++i) p.segments.push_back({i, (i + 1) % n});
  return p;
}

std::size_t mesh_count(int teeth, double w, double max_size) {
  const Domain2 d = make_domain(comb(teeth, w));
  QuadMeshOptions options;
  options.max_size = max_size;
  const QuadMeshResult r = quad_mesh(d, options);
  const CheckReport check = check_mesh(r.mesh, d);
  EXPECT_TRUE(check.valid()) << "w = " << w << "\n" << check.to_text();
  return r.mesh.triangles.size();
}

// Each slot bottom is a feature of size w, and any bounded-angle mesh needs
// about log(1/w) triangles around it; the teeth need a count that does not
// depend on w. The ratio therefore depends on how fine the teeth are meshed:
// at the default size (teeth meshed with boxes of 1/8 to 1/4 of their width)
// our 4-tooth comb gives 1.9 (printed below), with boxes capped at 1/64 of the
// part 1.14 (asserted); docs/algorithm/quad2d.md "Element count" has the
// series.
TEST(GeodesicRefinement, CombCountBarelyDependsOnSlotWidth) {
  const double max_size = 1.0 / 64;
  const std::size_t wide = mesh_count(4, 1e-2, max_size), narrow = mesh_count(4, 1e-4, max_size);
  std::cout << "comb, 4 teeth, max size 1/64: " << wide << " triangles at w = 1e-2, " << narrow
            << " at w = 1e-4 (ratio " << static_cast<double>(narrow) / static_cast<double>(wide) << ")\n";
  EXPECT_LE(static_cast<double>(narrow), 1.3 * static_cast<double>(wide));
  const std::size_t wide0 = mesh_count(4, 1e-2, 0), narrow0 = mesh_count(4, 1e-4, 0);
  std::cout << "comb, 4 teeth, default size: " << wide0 << " and " << narrow0 << " (ratio "
            << static_cast<double>(narrow0) / static_cast<double>(wide0) << ")\n";
}

// The Euclidean alternative would refine every tooth side to the slot width:
// about 1/w boxes per side. Ours grows by a constant per halving of w.
TEST(GeodesicRefinement, CombCountGrowsLogarithmically) {
  std::size_t previous = mesh_count(4, 1e-2, 0);
  for (const double w : {1e-3, 1e-4, 1e-5, 1e-6}) {
    const std::size_t now = mesh_count(4, w, 0);
    std::cout << "w = " << w << ": " << now << " triangles (+" << now - previous << ")\n";
    EXPECT_LE(now, previous + previous / 2) << "a tenfold narrower slot must not cost half the mesh again";
    previous = now;
  }
}

}  // namespace
}  // namespace pqmesh
