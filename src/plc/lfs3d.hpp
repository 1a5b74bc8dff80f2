#pragma once
// Internals of the 3D local feature size (pqmesh/lfs3.hpp): the feature
// model, the distance constructions shared by the brute force and the grid
// evaluator (so both compute bit-identical distances), and the exact
// box-versus-boundary test of the integral.
#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <vector>

#include "plc/lfs_distance.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh::detail {

// Small helpers shared by lfs3d*.cpp.
inline constexpr double kLfsInf = std::numeric_limits<double>::infinity();
inline std::size_t lfs_uz(int i) { return static_cast<std::size_t>(i); }

// Squared distance from x to the closed, non-degenerate triangle abc whose
// plane has the unit normal n (the facet's normal, oriented so that
// (b - a) x (c - a) . n > 0). When x projects into the triangle (three side
// tests against n) it is the squared distance to the plane, otherwise the
// nearest side's. Using the facet's normal instead of the triangle's cross
// product keeps the rounding error a few ulps of |x - a| even for the slivers
// of a fan triangulation (the grid's pruning margin relies on that).
inline double lfs_dist2_triangle(Vec3 x, Vec3 a, Vec3 b, Vec3 c, Vec3 n) {
  const Vec3 ax = x - a;
  if (dot(cross(b - a, ax), n) >= 0 && dot(cross(c - b, x - b), n) >= 0 && dot(cross(a - c, x - c), n) >= 0) {
    const double h = dot(ax, n);
    return h * h / dot(n, n);
  }
  return std::min({lfs_dist2_segment(x, a, b), lfs_dist2_segment(x, b, c), lfs_dist2_segment(x, c, a)});
}

// A feature of P: an input vertex, an edge (index into Domain3::edges) or a
// closed facet.
struct LfsFeature3 {
  enum class Kind : unsigned char { Vertex, Edge, Facet };
  Kind kind = Kind::Vertex;
  int id = -1;
};

// What the lfs needs of a Domain3, by value.
struct LfsModel3 {
  explicit LfsModel3(const Domain3& domain);

  std::vector<Vec3> points;
  std::vector<std::array<int, 2>> edges;            // Domain3::edges (a < b)
  std::vector<std::array<int, 3>> triangles;        // Domain3::facet_triangles
  std::vector<int> owner;                           // facet of each triangle
  std::vector<Vec3> tri_normal;                     // facet normal, oriented like the triangle
  std::vector<char> tri_degenerate;                 // collinear corners (exact): sides only
  std::vector<std::array<int, 3>> tri_edges;        // edge id of each side (ab, bc, ca), -1: a diagonal
  std::vector<std::vector<int>> facet_vertices;     // sorted
  std::vector<std::vector<int>> facet_neighbours;   // sorted facets sharing a vertex, itself excluded
  std::vector<int> facet_tri_start, facet_tris;     // CSR: facet -> its triangles
  std::vector<char> vertex_used;                    // 1 when the vertex lies on a facet
  Vec3 bbox_min{}, bbox_max{};

  int vertex_count() const { return static_cast<int>(points.size()); }
  // Dense feature index: vertices, then edges, then facets.
  int index(LfsFeature3 f) const;
  int feature_count() const;

  // The features share no point (decided from vertex ids; see lfs3.hpp).
  bool disjoint(LfsFeature3 f, LfsFeature3 g) const;

  double triangle_dist2(Vec3 x, int t) const;
  // Squared distance from x to the feature; a facet's is the minimum over its
  // triangles (the minimum of doubles does not depend on their order).
  double dist2(Vec3 x, LfsFeature3 f) const;

  // Every feature: the used vertices, the edges, the facets.
  std::vector<LfsFeature3> features() const;
};

// Exact: does the closed segment ab meet the closed axis-aligned box [lo, hi]?
bool segment_meets_box(Vec3 a, Vec3 b, Vec3 lo, Vec3 hi);

// Exact: does the closed segment pq meet the closed non-degenerate triangle abc?
bool segment_meets_triangle(Vec3 p, Vec3 q, Vec3 a, Vec3 b, Vec3 c);

// Exact: does the closed non-degenerate triangle abc meet the closed box [lo, hi]?
bool triangle_meets_box(Vec3 a, Vec3 b, Vec3 c, Vec3 lo, Vec3 hi);

// Exact separating-axis test of a triangle (possibly degenerate: collinear
// corners) against the closed box [lo, hi] or, with open_box, its interior
// (the box must have positive extent on every axis then). Independent of
// triangle_meets_box (the tests compare the two).
bool triangle_meets_box_sat(Vec3 a, Vec3 b, Vec3 c, Vec3 lo, Vec3 hi, bool open_box);

// The boundary test of the I3 quadrature, accelerated by a uniform n^3
// bucket grid over the bounding cube; every triangle is listed in every
// bucket of its bounding-box range inflated by a tiny margin, so the listing
// is conservative. The grid only prunes; decisions are exact. Not
// thread-safe (visit stamps). Keeps a reference to the domain.
class BoundaryBuckets3 {
 public:
  explicit BoundaryBuckets3(const Domain3& domain);
  // Does dP meet the closed box [lo, hi] (or, with open_box, its interior)?
  bool box_meets_boundary(Vec3 lo, Vec3 hi, bool open_box);

 private:
  int gi(double v, int axis) const;
  const Domain3& domain_;
  Vec3 glo_{};
  double gw_ = 1, margin_ = 0;
  int gn_ = 1;
  std::vector<std::vector<int>> bucket_;
  std::vector<int> stamp_;
  int stamp_id_ = 0;
};

}  // namespace pqmesh::detail
