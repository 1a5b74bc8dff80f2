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
  // mesh_polygon only: skip the refined CDT of the input and mesh with the
  // quadtree (quad_mesh). CLI --quadtree.
  bool quadtree = false;
  // mesh_polygon only: the improvement stage after the construction
  // (docs/algorithm/quad2d.md "Improvement"): coarsening, smoothing and flips
  // towards a target angle theta (refine_angle_degrees, or 20 when refinement
  // is off, and at least quad_mesh_angle_bound) that never take the smallest
  // angle below min(theta, the construction's) and never replace a triangle
  // at theta or above by a worse one, so the angle bound still holds. CLI
  // --no-improve.
  bool improve = true;
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
  // mesh_polygon: the mesh is the refined CDT of the input (no quadtree); its
  // smallest angle in degrees (also when it fell short of the bound and the
  // quadtree meshed P, whose stats these are then), and, in that case, its
  // triangle count.
  bool refined_input = false;
  double refined_input_min_angle = 0;
  std::int64_t refined_input_triangles = 0;
  // mesh_polygon's improvement stage (QuadMeshOptions::improve): the
  // construction's triangle count and min-angle histogram (quality_report's
  // 5-degree bins) before it, and its changes. improved is false when it did
  // not run.
  bool improved = false;
  std::int64_t constructed_triangles = 0;
  double constructed_min_angle = 0;  // degrees
  std::vector<std::int64_t> constructed_angle_counts;
  std::int64_t improve_removed = 0, improve_moved = 0, improve_flips = 0;
  double improve_target_degrees = 0;  // theta (QuadMeshOptions::improve)
  double seconds_improve = 0;
};

struct QuadMeshResult {
  TriMesh2 mesh;  // edges: the boundary pieces with the input segment markers
  QuadMeshStats stats;
};

// Throws InvalidInput (a bad size field) naming the offending entry; never
// returns a mesh that fails check_mesh (an internal failure throws InternalError).
QuadMeshResult quad_mesh(const Domain2& domain, const QuadMeshOptions& options = {});

// The default 2D mesh (`pqmesh mesh`): without a size bound (no max_size, no
// size field), no edge protection and with refinement on, first the
// constrained Delaunay triangulation of the input alone, refined towards
// refine_angle_degrees (cdt2d/refine.hpp: Ruppert's algorithm with
// Shewchuk's small-angle rules, the same refinement quad_mesh ends with). It
// is kept when its smallest angle is at least quad_mesh_angle_bound(alpha,
// refine_angle_degrees) (pqmesh/quadmesh_bound.hpp), the bound quad_mesh
// meets; otherwise, and in every other case, the result is quad_mesh's. So the
// angle bound holds for every output. Boundary pieces carry the segment
// markers as in quad_mesh. Cost: the refinement is capped at 64 n + 100000
// new points for n input vertices (a run that hits the cap falls short of the
// target and the quadtree meshes P); errors as quad_mesh.
QuadMeshResult mesh_polygon(const Domain2& domain, const QuadMeshOptions& options = {});

// Parses a size-field file: one point per line "x y size" ('#' starts a
// comment, blank lines ignored). Throws ParseError with the line on bad input.
SizeField2 read_size_field2(const std::string& path);

}  // namespace pqmesh
