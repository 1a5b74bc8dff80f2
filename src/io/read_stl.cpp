// STL, ASCII or binary. A binary file is recognised by its size (84 + 50 n
// bytes for the n triangles its header announces), even when its 80-byte
// header starts with "solid"; anything else must be ASCII
// ("solid ... facet normal ... outer loop vertex x y z ... endloop endfacet
// endsolid", keywords case-insensitive, several solids allowed).
//
// STL repeats coordinates instead of sharing vertices, so vertices with exactly
// equal coordinates (bitwise equal doubles, -0.0 taken as 0.0; binary floats
// converted exactly to double) are welded. Vertices are numbered by first
// appearance; ReadReport::welded_vertices counts the repeats removed. Binary
// files have no lines: their errors carry line 0 and SourceInfo lines stay empty.
#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "io/read_formats.hpp"
#include "io/read_soup.hpp"
#include "io/read_text_tokens.hpp"

namespace pqmesh::detail {

namespace {

std::uint32_t load_u32(const char* p) {
  std::uint32_t v = 0;
  std::memcpy(&v, p, 4);
  if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap32(v);
  return v;
}

float load_f32(const char* p) { return std::bit_cast<float>(load_u32(p)); }

bool keyword_is(std::string_view token, std::string_view word) {
  if (token.size() != word.size()) return false;
  for (std::size_t i = 0; i < token.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(token[i])) != word[i]) return false;
  return true;
}

// Raw triangle-soup corners before welding.
struct RawSoup {
  std::vector<Vec3> corners;
  std::vector<int> corner_lines;  // empty for binary
  std::vector<int> offsets{0};    // polygon p owns corners[offsets[p] .. offsets[p+1])
  std::vector<int> polygon_lines;
};

// Welds exactly equal corners; vertices numbered by first appearance.
SoupFile weld(RawSoup&& raw, const std::string& path, ReadReport& report) {
  const int n = static_cast<int>(raw.corners.size());
  std::vector<int> order(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) order[i] = i;
  const auto& c = raw.corners;
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    if (c[a].x != c[b].x) return c[a].x < c[b].x;
    if (c[a].y != c[b].y) return c[a].y < c[b].y;
    if (c[a].z != c[b].z) return c[a].z < c[b].z;
    return a < b;
  });
  // representative[i]: first corner (lowest index) with the same coordinates.
  std::vector<int> representative(static_cast<std::size_t>(n));
  for (int i = 0; i < n;) {
    int j = i;
    while (j < n && c[order[j]] == c[order[i]]) representative[order[j++]] = order[i];
    i = j;
  }
  SoupFile out;
  out.path = path;
  std::vector<int> id(static_cast<std::size_t>(n), -1);
  out.soup.indices.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const int r = representative[i];
    if (id[r] < 0) {
      id[r] = static_cast<int>(out.soup.vertices.size());
      out.soup.vertices.push_back(c[r]);
      if (!raw.corner_lines.empty()) out.vertex_lines.push_back(raw.corner_lines[r]);
    }
    out.soup.indices.push_back(id[r]);
  }
  out.soup.offsets = std::move(raw.offsets);
  out.soup.markers.assign(out.soup.offsets.size() - 1, 0);
  out.polygon_lines = std::move(raw.polygon_lines);
  report.welded_vertices = n - static_cast<int>(out.soup.vertices.size());
  return out;
}

RawSoup read_binary(const std::string& path, const std::string& bytes, std::uint32_t count) {
  RawSoup raw;
  raw.corners.reserve(std::size_t{3} * count);
  raw.offsets.reserve(std::size_t{count} + 1);
  for (std::uint32_t t = 0; t < count; ++t) {
    const char* rec = bytes.data() + 84 + std::size_t{50} * t + 12;  // skip the normal
    for (int k = 0; k < 3; ++k) {
      Vec3 p{load_f32(rec + 12 * k), load_f32(rec + 12 * k + 4), load_f32(rec + 12 * k + 8)};
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw ParseError(ErrorCode::NonFinite,
                         "triangle " + std::to_string(t) + " has a non-finite coordinate at corner " + std::to_string(k),
                         {static_cast<std::int64_t>(t)}, path, 0);
      raw.corners.push_back({p.x + 0.0, p.y + 0.0, p.z + 0.0});  // + 0.0 turns -0.0 into 0.0
    }
    raw.offsets.push_back(static_cast<int>(raw.corners.size()));
  }
  return raw;
}

RawSoup read_ascii(TextSource& src) {
  RawSoup raw;
  TextToken tok;
  auto need = [&](const char* what) {
    if (!src.next_token(tok)) src.fail_truncated(std::string("'") + what + "'");
    return tok;
  };
  auto expect = [&](const char* word) {
    need(word);
    if (!keyword_is(tok.text, word))
      src.fail(ErrorCode::Syntax, std::string("expected '") + word + "', found '" + std::string(tok.text) + "'", tok.line);
  };
  expect("solid");
  src.skip_rest_of_line();
  int facet_id = 0;
  while (src.next_token(tok)) {
    if (keyword_is(tok.text, "endsolid")) {
      src.skip_rest_of_line();
      if (!src.next_token(tok)) break;
      if (!keyword_is(tok.text, "solid"))
        src.fail(ErrorCode::Syntax, "expected 'solid' or end of file, found '" + std::string(tok.text) + "'", tok.line);
      src.skip_rest_of_line();
      continue;
    }
    if (!keyword_is(tok.text, "facet"))
      src.fail(ErrorCode::Syntax, "expected 'facet' or 'endsolid', found '" + std::string(tok.text) + "'", tok.line);
    const int line = tok.line;
    expect("normal");
    for (int k = 0; k < 3; ++k) need("normal");  // normals are recomputed from the vertices
    expect("outer");
    expect("loop");
    int corners = 0;
    for (;;) {
      need("endloop");
      if (keyword_is(tok.text, "endloop")) break;
      if (!keyword_is(tok.text, "vertex"))
        src.fail(ErrorCode::Syntax, "expected 'vertex' or 'endloop', found '" + std::string(tok.text) + "'", tok.line);
      const int vline = tok.line;
      double xyz[3];
      for (double& value : xyz) {
        need("vertex coordinates");
        if (!parse_double(tok.text, value))
          src.fail(ErrorCode::Syntax, "coordinate '" + std::string(tok.text) + "' is not a number", tok.line, {facet_id});
        if (!std::isfinite(value))
          src.fail(ErrorCode::NonFinite, "facet " + std::to_string(facet_id) + " has a non-finite coordinate", tok.line,
                   {facet_id});
      }
      raw.corners.push_back({xyz[0] + 0.0, xyz[1] + 0.0, xyz[2] + 0.0});
      raw.corner_lines.push_back(vline);
      ++corners;
    }
    if (corners < 3)
      src.fail(ErrorCode::WrongCount, "facet " + std::to_string(facet_id) + " has " + std::to_string(corners) + " vertices",
               line, {facet_id});
    expect("endfacet");
    raw.offsets.push_back(static_cast<int>(raw.corners.size()));
    raw.polygon_lines.push_back(line);
    ++facet_id;
  }
  return raw;
}

}  // namespace

Plc3 read_stl(const std::string& path, const ReadOptions& options, ReadReport& report) {
  std::string bytes;
  if (!read_whole_file(path, bytes))
    throw ParseError(ErrorCode::Unreadable, "cannot open or read the file", {}, path, 0);
  const std::uint64_t size = bytes.size();
  RawSoup raw;
  std::uint32_t count = 0;
  if (size >= 84) count = load_u32(bytes.data() + 80);
  const bool binary = size >= 84 && size == 84 + std::uint64_t{50} * count;
  if (binary) {
    raw = read_binary(path, bytes, count);
  } else {
    const auto first = bytes.find_first_not_of(" \t\r\n");
    const bool ascii = first != std::string::npos && bytes.size() - first >= 5 && keyword_is(std::string_view(bytes).substr(first, 5), "solid");
    if (!ascii) {
      if (size < 84)
        throw ParseError(ErrorCode::Truncated, "binary STL shorter than its 84-byte header", {}, path, 0);
      const std::uint64_t need = 84 + std::uint64_t{50} * count;
      throw ParseError(size < need ? ErrorCode::Truncated : ErrorCode::WrongCount,
                       "binary STL announces " + std::to_string(count) + " triangles (" + std::to_string(need) +
                           " bytes) but has " + std::to_string(size) + " bytes",
                       {}, path, 0);
    }
    TextSource src(path, std::move(bytes), false);
    raw = read_ascii(src);
  }
  return soup_to_plc(weld(std::move(raw), path, report), options, report);
}

}  // namespace pqmesh::detail
