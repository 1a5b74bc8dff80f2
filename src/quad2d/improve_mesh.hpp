#pragma once
// The improvement stage of the default 2D mesh (docs/algorithm/quad2d.md
// "Improvement"): the shared quality pass (improve2d/quality_pass.hpp) in its
// target mode on a mesh of a polygon with holes.
//
// Contract: `mesh` is a valid mesh of P whose boundary vertices are on
// boundary edges (every input vertex is: P's vertices lie on exactly two
// segments). Changes interior vertices, Steiner points exactly on a segment
// (removals only) and the triangles around them: a coarsening sweep (a vertex goes when its star has a re-triangulation
// above min(target, the star's smallest angle)), three rounds of a smoothing
// sweep and a coarsening sweep, two more smoothing sweeps (each over the
// vertices of stars below target + 10 degrees), then flips / removals / moves
// at the worst triangle while it is below the target. So the smallest angle
// never falls below min(target, its value before), no triangle at the target
// or above is replaced by one below it, the triangle count never grows, the
// input vertices stay and the boundary keeps its shape and markers; vertices
// are renumbered (mesh.edges with them). Triangle markers
// are kept (each new triangle takes the marker of the triangle its change
// started from; P is one region, so they are equal).
// Deterministic: vertex id order, ties to the first candidate.
// Cost: O(n) stars re-triangulated per coarsening sweep (cubic in the star
// size, at most 64) and 48 star evaluations per smoothed vertex per sweep.
// Without coarsening only the stars below target + 10 degrees are handed to
// the pass (a part of the mesh whose border stays fixed): at 1.7 million
// quadtree triangles it costs a few hundredths of a second.
#include <cstdint>
#include <vector>

#include "pqmesh/mesh.hpp"

namespace pqmesh::quad2d {

struct ImproveStats {
  std::int64_t removed = 0, moved = 0, flips = 0;
};

// No removal when `coarsen` is false (a size bound was asked: a removal
// could make a triangle larger than it allows). input_vertices: P's vertices;
// every other boundary vertex is a Steiner point inside a segment, which a
// coarsening sweep may remove when it lies exactly on the line through its
// two boundary neighbours (their pieces merge into one, with its marker).
ImproveStats improve_mesh(TriMesh2& mesh, const std::vector<Vec2>& input_vertices, double target_degrees,
                          bool coarsen);

}  // namespace pqmesh::quad2d
