#pragma once
// Turning a polygon soup read from a file (STL, OFF, OBJ, Medit) into a Plc3,
// merging coplanar polygons per ReadOptions (src/plc/soup_merge.hpp).
#include <string>
#include <vector>

#include "plc/soup_merge.hpp"
#include "pqmesh/read_domain.hpp"

namespace pqmesh::detail {

struct SoupFile {
  PolygonSoup soup;
  std::vector<int> vertex_lines;    // line of each vertex, or empty
  std::vector<int> vertex_markers;  // one per vertex, or empty
  std::vector<int> polygon_lines;   // line of each polygon, or empty
  std::string path;
  int first_id = 0;
};

// Vertices that input polygons used but that no merged facet loop uses (they
// lay strictly inside a merged facet) are dropped and the rest renumbered in
// their original order; vertex_line and vertex_markers follow. A merged
// facet's element_line is the line of its first polygon. With
// options.merge_coplanar false every polygon is its own facet and
// merge_angle_degrees is ignored.
Plc3 soup_to_plc(SoupFile&& file, const ReadOptions& options, ReadReport& report);

}  // namespace pqmesh::detail
