#pragma once
// Reading input domains from files. Readers throw ParseError (naming the file
// line) for anything that is not a well-formed file of the format; they do not
// validate geometry — pass the result to make_domain() (pqmesh/domain.hpp).
#include <string>

#include "pqmesh/plc.hpp"

namespace pqmesh {

// Options for 3D reading; they matter for triangle soups (STL, OFF, OBJ, Medit),
// whose triangles are merged into polygonal facets.
struct ReadOptions {
  // Merge adjacent triangles that are exactly coplanar into one facet.
  bool merge_coplanar = true;
  // Also merge adjacent triangles whose planes differ by at most this angle in
  // degrees (0: exact coplanarity only). See ReadReport::merged_near.
  double merge_angle_degrees = 0;
};

struct ReadReport {
  int input_polygons = 0;   // triangles/polygons in the file
  int facets = 0;           // facets after merging
  int merged_exact = 0;     // polygons merged into a neighbour that is exactly coplanar
  int merged_near = 0;      // polygons merged within merge_angle_degrees but not exactly coplanar
  int welded_vertices = 0;  // vertices removed because they repeated another's exact coordinates (STL)
};

// 2 or 3: the dimension of the domain a file describes (by extension, and by
// the header of a .poly file, which Triangle and TetGen share).
int domain_dimension(const std::string& path);

// Triangle .poly (2D).
Pslg2 read_pslg(const std::string& path);

// TetGen .poly/.smesh, OFF, STL (ASCII or binary), OBJ, Medit .mesh surface.
Plc3 read_plc(const std::string& path, const ReadOptions& options = {}, ReadReport* report = nullptr);

}  // namespace pqmesh
