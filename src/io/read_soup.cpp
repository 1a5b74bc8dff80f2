#include "io/read_soup.hpp"

namespace pqmesh::detail {

Plc3 soup_to_plc(SoupFile&& file, const ReadOptions& options, ReadReport& report) {
  PolygonSoup& soup = file.soup;
  SoupMergeResult merged = options.merge_coplanar ? merge_soup(soup, options.merge_angle_degrees)
                                                  : soup_without_merging(soup);
  Plc3 out;
  out.source.path = file.path;
  out.source.first_id = file.first_id;
  const int nv = static_cast<int>(soup.vertices.size());
  // 0: unused by the input, 1: used by an input polygon, 2: used by an output loop.
  std::vector<char> use(static_cast<std::size_t>(nv), 0);
  for (int v : soup.indices) use[v] = 1;
  for (const Facet3& f : merged.facets)
    for (const auto& loop : f.loops)
      for (int v : loop) use[v] = 2;
  std::vector<int> new_id(static_cast<std::size_t>(nv), -1);
  const bool keep_lines = static_cast<int>(file.vertex_lines.size()) == nv;
  const bool keep_markers = static_cast<int>(file.vertex_markers.size()) == nv;
  for (int v = 0; v < nv; ++v) {
    if (use[v] == 1) continue;  // swallowed by a merged facet
    new_id[v] = static_cast<int>(out.vertices.size());
    out.vertices.push_back(soup.vertices[v]);
    if (keep_lines) out.source.vertex_line.push_back(file.vertex_lines[v]);
    if (keep_markers) out.vertex_markers.push_back(file.vertex_markers[v]);
  }
  const bool keep_polygon_lines = static_cast<int>(file.polygon_lines.size()) == soup.polygon_count();
  for (std::size_t i = 0; i < merged.facets.size(); ++i) {
    Facet3& f = merged.facets[i];
    for (auto& loop : f.loops)
      for (int& v : loop) v = new_id[v];
    if (keep_polygon_lines) out.source.element_line.push_back(file.polygon_lines[merged.first_polygon[i]]);
    out.facets.push_back(std::move(f));
  }
  report.input_polygons = soup.polygon_count();
  report.facets = static_cast<int>(out.facets.size());
  report.merged_exact = merged.merged_exact;
  report.merged_near = merged.merged_near;
  return out;
}

}  // namespace pqmesh::detail
