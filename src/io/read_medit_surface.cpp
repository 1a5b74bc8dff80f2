// Medit .mesh (ASCII) surfaces: keywords MeshVersionFormatted <v>,
// Dimension 3, Vertices <n> then "x y z ref", Triangles <n> then "a b c ref",
// Quadrilaterals <n> then "a b c d ref", End. Ids are 1-based; a vertex ref
// becomes its vertex marker and an element ref its facet marker. Other known
// sections with a fixed number of integers per entry (Edges, Corners, Ridges,
// Required*, Tetrahedra, ...) are skipped; unknown keywords are Unsupported.
#include <cmath>
#include <cstring>

#include "io/read_formats.hpp"
#include "io/read_node_section.hpp"
#include "io/read_soup.hpp"

namespace pqmesh::detail {

namespace {

// Values per entry of the sections we skip.
int skipped_section_width(std::string_view key) {
  struct Entry {
    const char* name;
    int width;
  };
  static const Entry table[] = {{"Edges", 3},           {"Corners", 1},          {"Ridges", 1},
                                {"RequiredVertices", 1}, {"RequiredEdges", 1},    {"RequiredTriangles", 1},
                                {"RequiredQuadrilaterals", 1}, {"Tetrahedra", 5}, {"Hexahedra", 9},
                                {"Prisms", 7},          {"Normals", 3},          {"NormalAtVertices", 2},
                                {"Tangents", 3},        {"TangentAtVertices", 2}, {"TangentAtEdges", 3}};
  for (const Entry& e : table)
    if (key == e.name) return e.width;
  return 0;
}

}  // namespace

Plc3 read_medit_surface(const std::string& path, const ReadOptions& options, ReadReport& report) {
  TextSource src(path);
  TextToken tok;
  SoupFile file;
  file.path = path;
  file.first_id = 1;
  PolygonSoup& soup = file.soup;
  std::vector<long long> written;  // element vertex ids as written, checked at the end
  std::vector<long long> element_id;  // per polygon: its id within its section
  std::vector<std::string> element_kind;
  auto need = [&](const std::string& what) {
    if (!src.next_token(tok)) src.fail_truncated(what);
  };
  auto integer = [&](const std::string& what) {
    need(what);
    long long v = 0;
    if (!parse_int(tok.text, v))
      src.fail(ErrorCode::Syntax, "expected an integer " + what + ", found '" + std::string(tok.text) + "'", tok.line);
    return v;
  };
  auto count = [&](const std::string& what) {
    const long long n = integer(what);
    if (n < 0 || n > 2'000'000'000) src.fail(ErrorCode::WrongCount, "impossible " + what + " " + std::to_string(n), tok.line);
    return n;
  };
  long long dimension = 0;
  while (src.next_token(tok)) {
    const std::string key(tok.text);
    const int key_line = tok.line;
    if (key == "End") break;
    if (key == "MeshVersionFormatted") {
      integer("mesh version");
    } else if (key == "Dimension") {
      dimension = integer("dimension");
      if (dimension != 3)
        src.fail(ErrorCode::WrongCount, "dimension " + std::to_string(dimension) + " (a surface in 3D needs 3)", tok.line);
    } else if (key == "Vertices") {
      if (dimension != 3) src.fail(ErrorCode::Syntax, "'Vertices' before 'Dimension 3'", key_line);
      const long long n = count("vertex count");
      for (long long i = 0; i < n; ++i) {
        const long long id = static_cast<long long>(soup.vertices.size()) + 1;
        double xyz[3];
        int line = 0;
        for (double& value : xyz) {
          need("all " + std::to_string(n) + " vertices are listed");
          if (line == 0) line = tok.line;
          if (!parse_double(tok.text, value))
            src.fail(ErrorCode::Syntax,
                     "coordinate '" + std::string(tok.text) + "' of vertex " + std::to_string(id) + " is not a number",
                     tok.line, {id});
          if (!std::isfinite(value))
            src.fail(ErrorCode::NonFinite, "vertex " + std::to_string(id) + " has a non-finite coordinate", tok.line, {id});
        }
        soup.vertices.push_back({xyz[0], xyz[1], xyz[2]});
        file.vertex_lines.push_back(line);
        file.vertex_markers.push_back(static_cast<int>(integer("vertex reference")));
      }
    } else if (key == "Triangles" || key == "Quadrilaterals") {
      const int k = key == "Triangles" ? 3 : 4;
      const long long n = count(key == "Triangles" ? "triangle count" : "quadrilateral count");
      for (long long i = 0; i < n; ++i) {
        int line = 0;
        for (int j = 0; j < k; ++j) {
          written.push_back(integer("vertex id (all " + std::to_string(n) + " elements are listed)"));
          if (j == 0) line = tok.line;
        }
        soup.markers.push_back(static_cast<int>(integer("element reference")));
        soup.offsets.push_back(static_cast<int>(written.size()));
        file.polygon_lines.push_back(line);
        element_id.push_back(i + 1);
        element_kind.push_back(k == 3 ? "triangle" : "quadrilateral");
      }
    } else if (const int width = skipped_section_width(key); width > 0) {
      const long long n = count(key + " count");
      for (long long i = 0; i < n * width; ++i) need("all " + std::to_string(n) + " " + key + " are listed");
    } else {
      src.fail(ErrorCode::Unsupported, "Medit keyword '" + key + "' is not supported", key_line);
    }
  }
  const auto nv = static_cast<int>(soup.vertices.size());
  soup.indices.resize(written.size());
  for (int p = 0; p < soup.polygon_count(); ++p)
    for (int s = soup.offsets[p]; s < soup.offsets[p + 1]; ++s)
      soup.indices[s] = vertex_index(src, written[s], 1, nv, file.polygon_lines[p], element_kind[p], element_id[p]);
  return soup_to_plc(std::move(file), options, report);
}

}  // namespace pqmesh::detail
