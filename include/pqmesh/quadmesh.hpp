#pragma once
// The 2D quadtree quality mesher: the two-dimensional analog of thesis ch. 4
// (§1.2, §5.3, §5.5.1). A polygon with holes in, a conforming triangle mesh
// out, with every angle bounded below in terms of the smallest input angle
// and a triangle count within a constant of the fewest a bounded-angle mesh
// needs. Stages and the places where we deviate from the thesis:
// docs/algorithm/quad2d.md.
#include <cstdint>
#include <string>
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/mesh.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh {

// A user size function (thesis §1.1: "the largest desired box containing that
// point"), given as points with sizes. The size asked for at x is
//     f(x) = min over i of ( sizes[i] + |x - points[i]| ),
// a 1-Lipschitz function, so the mesh it asks for is graded.
struct SizeField2 {
  std::vector<Vec2> points;
  std::vector<double> sizes;  // > 0, one per point
  std::vector<int> lines;     // 1-based file line of each point (error messages); may be empty
  std::string path;           // file it came from, empty when built in memory
};

struct QuadMeshOptions {
  // Largest allowed box side anywhere (0: no limit). CLI --max-size.
  double max_size = 0;
  // Optional size field (empty: none). CLI --size-field FILE.
  SizeField2 size_field;
  // The edge protection step of thesis §4.1.4-4.1.5 (split every box on an
  // edge once more). Off by default: the triangulation does not need it, and
  // it doubles the boundary resolution and lowers the min angle next to
  // vertex boxes (measurements: docs/algorithm/quad2d.md "Termination"). CLI
  // --protect-edges.
  bool protect_edges = false;
  // Delaunay refinement of the quadtree's triangulation towards this smallest
  // angle, in degrees (0: off). Triangles at input angles below 60 degrees are
  // excused (docs/algorithm/quad2d.md "Delaunay refinement pass"). CLI
  // --refine-angle DEG.
  double refine_angle_degrees = 20;
};

// Counters and timings of one run, for the CLI summary and the benchmark.
struct QuadMeshStats {
  std::int64_t leaves = 0;            // leaves of the final quadtree (all components)
  std::int64_t duplicates = 0;        // leaves that are duplicates of another leaf's cube (§4.1.1)
  std::int64_t outside_leaves = 0;    // leaves whose cube does not meet P
  std::int64_t splits_size = 0;       // splits asked by the size function
  std::int64_t splits_vertex = 0;     // vertex-crowded splits (§4.1.3)
  std::int64_t splits_edge = 0;       // edge-crowded splits (2D analog of §4.1.5)
  std::int64_t splits_balance = 0;    // splits forced by the balance condition
  std::int64_t splits_centering = 0;  // first part of vertex centering
  std::int64_t splits_protection = 0; // edge protection
  std::int64_t vertex_boxes = 0;      // input vertices given a protected vertex box
  std::int64_t centered = 0;          // of those, united into a 2x2 box around the vertex (Lemma 1)
  std::int64_t warped = 0;            // box corners moved onto an input edge (§4.3 analog)
  std::int64_t edge_points = 0;       // crossings of box sides with input edges kept as vertices
  std::int64_t refine_points = 0;     // vertices added by the refinement pass
  bool refine_target_reached = false; // every triangle not excused meets refine_angle_degrees
  double seconds_tree = 0, seconds_points = 0, seconds_triangulate = 0;
};

struct QuadMeshResult {
  TriMesh2 mesh;  // edges: the boundary pieces with the input segment markers
  QuadMeshStats stats;
};

// Throws InvalidInput (a bad size field) naming the offending entry; never
// returns a mesh that fails check_mesh (an internal failure throws InternalError).
QuadMeshResult quad_mesh(const Domain2& domain, const QuadMeshOptions& options = {});

// Parses a size-field file: one point per line "x y size" ('#' starts a
// comment, blank lines ignored). Throws ParseError with the line on bad input.
SizeField2 read_size_field2(const std::string& path);

}  // namespace pqmesh
