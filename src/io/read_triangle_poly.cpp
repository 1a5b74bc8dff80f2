// Triangle .poly (2D PSLG): vertices, segments, holes, optional regions.
// Layout (Triangle's documentation): the node section (read_node_section.hpp)
// with dimension 2; "<#segments> <#markers 0|1>" then "<id> <a> <b> [marker]";
// "<#holes>" then "<id> <x> <y>"; optionally "<#regions>" then
// "<id> <x> <y> <attribute> <max area>". The hole section may be omitted.
#include "io/read_formats.hpp"
#include "io/read_node_section.hpp"

namespace pqmesh::detail {

int poly_dimension(const std::string& path) {
  TextSource src(path);
  TextRecord header;
  if (!src.next_record(header)) src.fail_truncated("the vertex header");
  const long long n = count_token(src, header, 0, "vertex count");
  if (n == 0) {
    TextSource node_file(replace_extension(path, ".node"));
    if (!node_file.next_record(header)) node_file.fail_truncated("the vertex header");
    const long long dim = header.tokens.size() > 1 ? int_token(node_file, header, 1, "dimension") : 0;
    if (dim != 2 && dim != 3)
      node_file.fail(ErrorCode::WrongCount, "dimension must be 2 or 3, found " + std::to_string(dim), header.line);
    return static_cast<int>(dim);
  }
  if (header.tokens.size() < 2) src.fail(ErrorCode::Syntax, "the vertex header names no dimension", header.line);
  const long long dim = int_token(src, header, 1, "dimension");
  if (dim != 2 && dim != 3)
    src.fail(ErrorCode::WrongCount, "dimension must be 2 or 3, found " + std::to_string(dim), header.line);
  return static_cast<int>(dim);
}

Pslg2 read_triangle_poly(const std::string& path) {
  TextSource src(path);
  Pslg2 out;
  out.source.path = path;
  TextRecord record;
  if (!src.next_record(record)) src.fail_truncated("the vertex header");
  const NodeSection nodes = read_node_section(src, record, 2);
  const int nv = nodes.count();
  out.vertices.resize(static_cast<std::size_t>(nv));
  for (int i = 0; i < nv; ++i) out.vertices[i] = {nodes.coords[2 * i], nodes.coords[2 * i + 1]};
  out.vertex_markers = nodes.markers;
  out.source.vertex_line = nodes.lines;
  out.source.first_id = nodes.first_id;

  const long long ns = read_count(src, record, "segment header");
  const bool seg_markers = record.tokens.size() > 1 && int_token(src, record, 1, "segment marker count") != 0;
  out.segments.reserve(static_cast<std::size_t>(std::min<long long>(ns, static_cast<long long>(src.content().size()))));
  for (long long s = 0; s < ns; ++s) {
    if (!src.next_record(record))
      src.fail_truncated("all " + std::to_string(ns) + " segments are listed (found " + std::to_string(s) + ")");
    const long long id = int_token(src, record, 0, "segment id");
    const long long a = int_token(src, record, 1, "segment endpoint");
    const long long b = int_token(src, record, 2, "segment endpoint");
    out.segments.push_back({vertex_index(src, a, nodes.first_id, nv, record.line, "segment", id),
                            vertex_index(src, b, nodes.first_id, nv, record.line, "segment", id)});
    if (seg_markers)
      out.segment_markers.push_back(record.tokens.size() > 3 ? static_cast<int>(int_token(src, record, 3, "segment marker")) : 0);
    out.source.element_line.push_back(record.line);
  }

  std::vector<double> values;
  read_holes(src, 2, values);
  for (std::size_t i = 0; i + 1 < values.size(); i += 2) out.holes.push_back({values[i], values[i + 1]});
  values.clear();
  read_regions(src, 2, values);
  for (std::size_t i = 0; i + 3 < values.size(); i += 4)
    out.regions.push_back({{values[i], values[i + 1]}, values[i + 2], values[i + 3]});
  return out;
}

}  // namespace pqmesh::detail
