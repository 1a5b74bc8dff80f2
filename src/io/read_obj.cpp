// Wavefront OBJ geometry: "v x y z [w]" and "f a b c ..." where each corner is
// "a", "a/t", "a/t/n" or "a//n". Positive ids are 1-based (they may refer to
// vertices listed later); negative ids count back from the last vertex read so
// far (-1 is the latest). Everything else (vt, vn, g, o, s, usemtl, mtllib, l,
// p, ...) is ignored. Faces need at least 3 corners.
#include <cmath>

#include "io/read_formats.hpp"
#include "io/read_node_section.hpp"
#include "io/read_soup.hpp"

namespace pqmesh::detail {

Plc3 read_obj(const std::string& path, const ReadOptions& options, ReadReport& report) {
  TextSource src(path);
  TextRecord record;
  SoupFile file;
  file.path = path;
  file.first_id = 1;
  PolygonSoup& soup = file.soup;
  // Ids as written (negative ones already resolved to 1-based), checked at the end.
  std::vector<long long> written;
  long long face = 0;
  while (src.next_record(record)) {
    const std::string_view key = record.tokens[0];
    if (key == "v") {
      const auto id = static_cast<long long>(soup.vertices.size()) + 1;
      soup.vertices.push_back({coord_token(src, record, 1, "vertex", id), coord_token(src, record, 2, "vertex", id),
                               coord_token(src, record, 3, "vertex", id)});
      file.vertex_lines.push_back(record.line);
    } else if (key == "f") {
      ++face;
      if (record.tokens.size() < 4)
        src.fail(ErrorCode::WrongCount,
                 "face " + std::to_string(face) + " has " + std::to_string(record.tokens.size() - 1) + " corners",
                 record.line, {face});
      for (std::size_t j = 1; j < record.tokens.size(); ++j) {
        const std::string_view corner = record.tokens[j];
        long long id = 0;
        if (!parse_int(corner.substr(0, corner.find('/')), id))
          src.fail(ErrorCode::Syntax, "face corner '" + std::string(corner) + "' does not start with a vertex id",
                   record.line, {face});
        const auto nv = static_cast<long long>(soup.vertices.size());
        if (id < 0) id = nv + 1 + id;  // -1 -> the latest vertex
        if (id <= 0)
          src.fail(ErrorCode::IndexOutOfRange,
                   "face " + std::to_string(face) + " refers to vertex " + std::string(corner.substr(0, corner.find('/'))) +
                       ", which does not exist",
                   record.line, {face, id});
        written.push_back(id);
      }
      soup.offsets.push_back(static_cast<int>(written.size()));
      soup.markers.push_back(0);
      file.polygon_lines.push_back(record.line);
    }
  }
  const auto nv = static_cast<int>(soup.vertices.size());
  soup.indices.resize(written.size());
  for (int p = 0; p < soup.polygon_count(); ++p)
    for (int s = soup.offsets[p]; s < soup.offsets[p + 1]; ++s)
      soup.indices[s] = vertex_index(src, written[s], 1, nv, file.polygon_lines[p], "face", p + 1);
  return soup_to_plc(std::move(file), options, report);
}

}  // namespace pqmesh::detail
