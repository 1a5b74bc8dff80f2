// TetGen .poly and .smesh (3D piecewise linear complexes).
//
// Both start with the node section (read_node_section.hpp, dimension 3; a
// count of 0 reads the .node file of the same base name), then the facet list
// "<#facets> <#markers 0|1>", then volume holes "<#holes>" + "<id> x y z" and
// regions "<#regions>" + "<id> x y z <attribute> <max volume>" (both optional).
//   .poly facet:  "<#polygons> [#holes] [marker]", then #polygons lines
//                 "<k> v1 .. vk", then #holes lines "<id> x y z" (facet holes);
//   .smesh facet: one line "<k> v1 .. vk [marker]".
// A facet of several polygons is split by split_tetgen_facet(). Polygons with
// fewer than 3 corners (segments or points constrained inside a facet) are
// Unsupported. Facet ids in messages are ordinals in the file's numbering
// (first facet = first vertex id).
#include "io/read_formats.hpp"
#include "io/read_node_section.hpp"
#include "io/read_tetgen_facets.hpp"

namespace pqmesh::detail {

namespace {

Plc3 read_tetgen(const std::string& path, bool smesh, ReadReport& report) {
  TextSource src(path);
  Plc3 out;
  out.source.path = path;
  TextRecord record;
  if (!src.next_record(record)) src.fail_truncated("the vertex header");
  const NodeSection nodes = read_node_section(src, record, 3);
  const int nv = nodes.count();
  const int first = nodes.first_id;
  for (int i = 0; i < nv; ++i) out.vertices.push_back({nodes.coords[3 * i], nodes.coords[3 * i + 1], nodes.coords[3 * i + 2]});
  out.vertex_markers = nodes.markers;
  out.source.vertex_line = nodes.lines;
  out.source.first_id = first;

  const long long nf = read_count(src, record, "facet header");
  const bool markers = record.tokens.size() > 1 && int_token(src, record, 1, "facet marker count") != 0;
  std::vector<std::vector<int>> polygons;
  std::vector<Vec3> facet_holes;
  for (long long f = 0; f < nf; ++f) {
    const long long fid = f + first;
    const std::string facet_name = "facet " + std::to_string(fid);
    if (!src.next_record(record))
      src.fail_truncated("all " + std::to_string(nf) + " facets are listed (found " + std::to_string(f) + ")");
    const int facet_line = record.line;
    polygons.clear();
    facet_holes.clear();
    int marker = 0;
    auto read_polygon = [&](const TextRecord& r, std::size_t& next) {
      const long long k = count_token(src, r, 0, "polygon size");
      if (k < 3)
        src.fail(ErrorCode::Unsupported,
                 facet_name + " has a polygon with " + std::to_string(k) +
                     " corners (segments and points inside facets are not supported)",
                 r.line, {fid});
      if (static_cast<long long>(r.tokens.size()) < k + 1)
        src.fail(ErrorCode::WrongCount,
                 facet_name + ": polygon announces " + std::to_string(k) + " corners but lists " +
                     std::to_string(r.tokens.size() - 1),
                 r.line, {fid});
      std::vector<int> poly;
      for (long long j = 1; j <= k; ++j)
        poly.push_back(vertex_index(src, int_token(src, r, static_cast<std::size_t>(j), "vertex id"), first, nv, r.line,
                                    "facet", fid));
      polygons.push_back(std::move(poly));
      next = static_cast<std::size_t>(k + 1);
    };
    if (smesh) {
      std::size_t next = 0;
      read_polygon(record, next);
      if (markers && next < record.tokens.size()) marker = static_cast<int>(int_token(src, record, next, "facet marker"));
    } else {
      const long long np = count_token(src, record, 0, "polygon count");
      if (np < 1) src.fail(ErrorCode::WrongCount, facet_name + " has no polygon", record.line, {fid});
      const long long nh = record.tokens.size() > 1 ? count_token(src, record, 1, "facet hole count") : 0;
      if (markers && record.tokens.size() > 2) marker = static_cast<int>(int_token(src, record, 2, "facet marker"));
      TextRecord sub;
      for (long long p = 0; p < np; ++p) {
        if (!src.next_record(sub)) src.fail_truncated("all polygons of " + facet_name + " are listed");
        std::size_t next = 0;
        read_polygon(sub, next);
      }
      for (long long h = 0; h < nh; ++h) {
        if (!src.next_record(sub)) src.fail_truncated("all holes of " + facet_name + " are listed");
        const long long hid = int_token(src, sub, 0, "facet hole id");
        facet_holes.push_back({coord_token(src, sub, 1, "facet hole", hid), coord_token(src, sub, 2, "facet hole", hid),
                               coord_token(src, sub, 3, "facet hole", hid)});
      }
    }
    const std::string why = split_tetgen_facet(out.vertices, polygons, facet_holes, marker, out.facets);
    if (!why.empty()) src.fail(ErrorCode::Unsupported, facet_name + ": " + why, facet_line, {fid});
    out.source.element_line.resize(out.facets.size(), facet_line);
  }
  std::vector<double> values;
  read_holes(src, 3, values);
  for (std::size_t i = 0; i + 2 < values.size(); i += 3) out.holes.push_back({values[i], values[i + 1], values[i + 2]});
  values.clear();
  read_regions(src, 3, values);
  for (std::size_t i = 0; i + 4 < values.size(); i += 5)
    out.regions.push_back({{values[i], values[i + 1], values[i + 2]}, values[i + 3], values[i + 4]});
  report.input_polygons = static_cast<int>(nf);
  report.facets = static_cast<int>(out.facets.size());
  return out;
}

}  // namespace

Plc3 read_tetgen_poly(const std::string& path, ReadReport& report) { return read_tetgen(path, false, report); }
Plc3 read_tetgen_smesh(const std::string& path, ReadReport& report) { return read_tetgen(path, true, report); }

}  // namespace pqmesh::detail
