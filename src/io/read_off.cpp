// OFF: an optional header line "OFF" (COFF/NOFF/STOFF variants read the same
// way; their extra per-vertex values are ignored), the counts "nv nf [ne]"
// (possibly on the header line), nv lines "x y z ...", nf lines
// "k v1 .. vk [colour]". Vertices are 0-based; '#' starts a comment.
// 4OFF/nOFF (other dimensions) and binary OFF are Unsupported.
#include <cmath>

#include "io/read_formats.hpp"
#include "io/read_node_section.hpp"
#include "io/read_soup.hpp"

namespace pqmesh::detail {

Plc3 read_off(const std::string& path, const ReadOptions& options, ReadReport& report) {
  TextSource src(path);
  TextRecord record;
  if (!src.next_record(record)) src.fail_truncated("the OFF header");
  std::size_t first_count = 0;
  const std::string head(record.tokens[0]);
  if (head.size() >= 3 && head.compare(head.size() - 3, 3, "OFF") == 0) {
    if (head[0] == '4' || head[0] == 'n')
      src.fail(ErrorCode::Unsupported, "OFF variant '" + head + "' (only 3D OFF is read)", record.line);
    if (record.tokens.size() > 1 && record.tokens[1] == "BINARY")
      src.fail(ErrorCode::Unsupported, "binary OFF", record.line);
    if (record.tokens.size() > 1) {
      first_count = 1;  // counts on the header line
    } else if (!src.next_record(record)) {
      src.fail_truncated("the OFF counts");
    }
  }
  if (record.tokens.size() < first_count + 2)
    src.fail(ErrorCode::Syntax, "expected the counts 'vertices faces [edges]'", record.line);
  const long long nv = count_token(src, record, first_count, "vertex count");
  const long long nf = count_token(src, record, first_count + 1, "face count");

  SoupFile file;
  file.path = path;
  file.first_id = 0;
  PolygonSoup& soup = file.soup;
  for (long long i = 0; i < nv; ++i) {
    if (!src.next_record(record))
      src.fail_truncated("all " + std::to_string(nv) + " vertices are listed (found " + std::to_string(i) + ")");
    const Vec3 p{coord_token(src, record, 0, "vertex", i), coord_token(src, record, 1, "vertex", i),
                 coord_token(src, record, 2, "vertex", i)};
    soup.vertices.push_back(p);
    file.vertex_lines.push_back(record.line);
  }
  for (long long f = 0; f < nf; ++f) {
    if (!src.next_record(record))
      src.fail_truncated("all " + std::to_string(nf) + " faces are listed (found " + std::to_string(f) + ")");
    const long long k = count_token(src, record, 0, "face size");
    if (k < 3)
      src.fail(ErrorCode::WrongCount, "face " + std::to_string(f) + " has " + std::to_string(k) + " vertices", record.line,
               {f});
    if (static_cast<long long>(record.tokens.size()) < k + 1)
      src.fail(ErrorCode::WrongCount,
               "face " + std::to_string(f) + " announces " + std::to_string(k) + " vertices but lists " +
                   std::to_string(record.tokens.size() - 1),
               record.line, {f});
    for (long long j = 1; j <= k; ++j) {
      const long long id = int_token(src, record, static_cast<std::size_t>(j), "vertex id");
      soup.indices.push_back(vertex_index(src, id, 0, static_cast<int>(nv), record.line, "face", f));
    }
    soup.offsets.push_back(static_cast<int>(soup.indices.size()));
    soup.markers.push_back(0);
    file.polygon_lines.push_back(record.line);
  }
  return soup_to_plc(std::move(file), options, report);
}

}  // namespace pqmesh::detail
