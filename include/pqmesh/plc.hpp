#pragma once
// Input domains (docs/algorithm/input.md, thesis §1.4).
//
//   Pslg2 — a planar straight-line graph as Triangle's .poly describes it; the
//           2D meshers accept the ones that bound a polygon with holes.
//   Plc3  — a polyhedral region given by its boundary: vertices and planar
//           polygonal facets, each facet an outer loop with optional hole loops.
//
// Ids are 0-based indices into the arrays. Readers record where each entity came
// from (SourceInfo) so validation errors can name the file line; `first_id`
// converts back to the numbering the file used (0 or 1 based).
#include <array>
#include <string>
#include <vector>

#include "pqmesh/vec.hpp"

namespace pqmesh {

struct SourceInfo {
  std::string path;                // empty when built in memory
  int first_id = 0;                // the file's numbering base: id in file = index + first_id
  std::vector<int> vertex_line;    // 1-based line of each vertex, empty if unknown
  std::vector<int> element_line;   // 1-based line of each segment (2D) / facet (3D)
  int line_of_vertex(int v) const { return v >= 0 && v < int(vertex_line.size()) ? vertex_line[v] : 0; }
  int line_of_element(int e) const { return e >= 0 && e < int(element_line.size()) ? element_line[e] : 0; }
};

struct Region2 {
  Vec2 point;
  double attribute = 0;
  double max_area = -1;  // negative: no constraint
};

struct Pslg2 {
  std::vector<Vec2> vertices;
  std::vector<int> vertex_markers;               // empty or one per vertex
  std::vector<std::array<int, 2>> segments;      // vertex ids
  std::vector<int> segment_markers;              // empty or one per segment
  std::vector<Vec2> holes;                       // points inside holes
  std::vector<Region2> regions;
  SourceInfo source;
};

// A planar facet: loops[0] is the outer boundary, loops[1..] bound holes. Each
// loop lists vertex ids in cyclic order (the closing edge is implicit). After
// orient_domain() (src/plc), loops[0] turns counter-clockwise seen from outside
// P (right-hand normal points out of P) and hole loops turn the other way.
struct Facet3 {
  std::vector<std::vector<int>> loops;
  int marker = 0;
};

struct Region3 {
  Vec3 point;
  double attribute = 0;
  double max_volume = -1;  // negative: no constraint
};

struct Plc3 {
  std::vector<Vec3> vertices;
  std::vector<int> vertex_markers;  // empty or one per vertex
  std::vector<Facet3> facets;
  std::vector<Vec3> holes;          // TetGen hole points (outside P)
  std::vector<Region3> regions;
  SourceInfo source;
};

}  // namespace pqmesh
