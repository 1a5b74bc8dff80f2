// pqmesh octree: build the octree of thesis §4.1 (mv3d::OctreeBuilder) for a 3D
// domain and write its leaves as VTK hexahedra (.vtu, ASCII) with per-leaf data.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "atomic_file.hpp"
#include "io/read_text_tokens.hpp"
#include "commands.hpp"
#include "load.hpp"
#include "mv3d/leaf_kind.hpp"
#include "mv3d/octree_builder.hpp"
#include "pqmesh/errors.hpp"
#include "report_format.hpp"

namespace pqmesh::cli {
namespace {

const char* phase_name(mv3d::OctPhase p) {
  switch (p) {
    case mv3d::OctPhase::Root: return "root";
    case mv3d::OctPhase::Vertex: return "vertex";
    case mv3d::OctPhase::Centering: return "centering";
    case mv3d::OctPhase::Edge: return "edge";
    case mv3d::OctPhase::Facet: return "facet";
    case mv3d::OctPhase::Balance: return "balance";
    case mv3d::OctPhase::Size: return "size";
    case mv3d::OctPhase::EdgeSeparate: return "edge-separate";
    case mv3d::OctPhase::FacetSeparate: return "facet-separate";
  }
  return "?";
}

// A leaf is a duplicate when another node carries its key (thesis §4.1.1).
bool is_duplicate(const OctTree& t, std::int32_t n) {
  const std::int32_t head = t.find(t.key(n));
  return head != n || t.next_same_key(n) >= 0;
}

template <class F>
void int_array(std::ostringstream& s, const char* name, const char* type, const std::vector<std::int32_t>& leaves,
               F value) {
  s << "        <DataArray type=\"" << type << "\" Name=\"" << name << "\" format=\"ascii\">\n         ";
  for (const std::int32_t n : leaves) s << ' ' << value(n);
  s << "\n        </DataArray>\n";
}

// The leaves as an unstructured grid of hexahedra (VTK cell type 12), eight
// points per leaf (not shared), corners in VTK order: the lower face
// counter-clockwise seen from below... i.e. (0,0,0) (1,0,0) (1,1,0) (0,1,0), then
// the upper face in the same order.
// The kind of every leaf (mv3d/leaf_kind.hpp), indexed by node id.
std::vector<mv3d::LeafKind> leaf_kinds(const mv3d::OctreeBuilder& b, const std::vector<std::int32_t>& leaves) {
  const mv3d::LeafClassifier classifier(b.domain());
  std::vector<mv3d::LeafKind> kinds(static_cast<std::size_t>(b.tree().size()), mv3d::LeafKind::Other);
  for (const std::int32_t n : leaves)
    kinds[static_cast<std::size_t>(n)] = classifier.classify(mv3d::leaf_faces(b, n)).kind;
  return kinds;
}

std::string leaves_vtu(const mv3d::OctreeBuilder& b, const std::vector<std::int32_t>& leaves,
                       const std::vector<mv3d::LeafKind>& kinds /* by node id */) {
  const OctTree& t = b.tree();
  std::ostringstream s;
  s.precision(std::numeric_limits<double>::max_digits10);
  s << "<?xml version=\"1.0\"?>\n"
    << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
    << "  <UnstructuredGrid>\n"
    << "    <Piece NumberOfPoints=\"" << 8 * leaves.size() << "\" NumberOfCells=\"" << leaves.size() << "\">\n"
    << "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  static const int kCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                    {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (const std::int32_t n : leaves) {
    const auto box = t.box(n);
    for (const auto& c : kCorner)
      s << "          " << (c[0] ? box.hi[0] : box.lo[0]) << ' ' << (c[1] ? box.hi[1] : box.lo[1]) << ' '
        << (c[2] ? box.hi[2] : box.lo[2]) << '\n';
  }
  s << "        </DataArray>\n      </Points>\n      <Cells>\n"
    << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < leaves.size(); ++i) {
    s << "         ";
    for (std::size_t k = 0; k < 8; ++k) s << ' ' << 8 * i + k;
    s << '\n';
  }
  s << "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n         ";
  for (std::size_t i = 0; i < leaves.size(); ++i) s << ' ' << 8 * (i + 1);
  s << "\n        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n         ";
  for (std::size_t i = 0; i < leaves.size(); ++i) s << " 12";
  s << "\n        </DataArray>\n      </Cells>\n      <CellData>\n";
  int_array(s, "level", "Int32", leaves, [&](std::int32_t n) { return t.level(n); });
  int_array(s, "component", "Int32", leaves,
            [&](std::int32_t n) { return b.data(n).has_component ? t.component(n) : -1; });
  int_array(s, "duplicate", "UInt8", leaves, [&](std::int32_t n) { return is_duplicate(t, n) ? 1 : 0; });
  int_array(s, "protected", "UInt8", leaves, [&](std::int32_t n) { return t.is_protected(n) ? 1 : 0; });
  int_array(s, "phase", "Int32", leaves, [&](std::int32_t n) { return static_cast<int>(b.phase(n)); });
  int_array(s, "vertex_owner", "Int32", leaves, [&](std::int32_t n) { return b.data(n).vertex_owner; });
  // Cone kind (LeafKind order) and the step that protected the leaf (its
  // OctPhase; 0 when unprotected).
  int_array(s, "cone_kind", "Int32", leaves,
            [&](std::int32_t n) { return static_cast<int>(kinds[static_cast<std::size_t>(n)]); });
  int_array(s, "protected_by", "Int32", leaves, [&](std::int32_t n) {
    return t.is_protected(n) ? static_cast<int>(b.protected_by(n)) : 0;
  });
  s << "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return s.str();
}

}  // namespace

// The 3D size field of `pqmesh octree --size-field` and of `pqmesh mesh` on 3D
// input (cmd_mesh3.cpp declares it; docs/FORMATS.md "3D size fields"): one
// point per line, `x y z size`; the errors of the 2D reader
// (src/io/read_size_field.cpp), with four fields instead of three.
mv3d::SizeField3 read_size_field3(const std::string& path) {
  detail::TextSource src(path);
  mv3d::SizeField3 field;
  field.path = path;
  static constexpr const char* kNames[4] = {"x", "y", "z", "size"};
  detail::TextRecord record;
  while (src.next_record(record)) {
    if (record.tokens.size() != 4)
      src.fail(ErrorCode::WrongCount, "expected 4 fields 'x y z size', found " + std::to_string(record.tokens.size()),
               record.line);
    double v[4] = {0, 0, 0, 0};
    for (int i = 0; i < 4; ++i) {
      const std::string_view token = record.tokens[static_cast<std::size_t>(i)];
      if (!detail::parse_double(token, v[i]))
        src.fail(ErrorCode::Syntax, std::string(kNames[i]) + " is not a number: '" + std::string(token) + "'", record.line);
      if (!std::isfinite(v[i]))
        src.fail(ErrorCode::NonFinite, std::string(kNames[i]) + " is not finite: '" + std::string(token) + "'", record.line);
    }
    if (!(v[3] > 0))
      src.fail(ErrorCode::Syntax, "size must be positive, found '" + std::string(record.tokens[3]) + "'", record.line);
    field.points.push_back({v[0], v[1], v[2]});
    field.sizes.push_back(v[3]);
    field.lines.push_back(record.line);
  }
  if (field.points.empty()) src.fail(ErrorCode::WrongCount, "the size field lists no points", src.last_line());
  return field;
}

int run_octree(const std::vector<std::string>& argv) {
  const Args args(argv, {"--quiet", "--no-merge", "--generic-grid"},
                  {"-o", "--output", "--merge-angle", "--max-size", "--size-field"});
  args.expect_positional(1, 1);
  const std::string& input = args.positional()[0];
  const std::string output = output_option(args);
  if (output.size() < 4 || output.compare(output.size() - 4, 4, ".vtu") != 0)
    throw UsageError("the octree is written as .vtu; OUTPUT must end in .vtu");
  check_output_directory(output);

  mv3d::OctreeOptions options;
  if (args.option("--max-size")) {
    options.max_size = args.number("--max-size", 0);  // throws UsageError unless a finite number
    if (!(options.max_size > 0))
      throw UsageError("--max-size must be a positive number, got '" + *args.option("--max-size") + "'");
  }
  if (const auto field = args.option("--size-field")) options.size_field = read_size_field3(*field);
  options.generic_grid = args.flag("--generic-grid");

  const LoadedDomain loaded = load_domain(input, read_options_from(args));
  const auto* domain = std::get_if<Domain3>(&loaded.domain);
  if (!domain) {
    std::cerr << "pqmesh octree: " << input << " is a 2D domain; the octree is for 3D domains\n";
    return kExitInvalidInput;
  }
  const auto start = std::chrono::steady_clock::now();
  const bool generic = options.generic_grid;
  mv3d::OctreeBuilder builder(*domain, std::move(options));
  builder.build();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::vector<std::int32_t> leaves = builder.leaves_by_id();
  const std::vector<mv3d::LeafKind> kinds = leaf_kinds(builder, leaves);
  write_text_file_atomic(output, leaves_vtu(builder, leaves, kinds));

  if (!args.flag("--quiet")) {
    const mv3d::OctreeStats& s = builder.stats();
    std::int64_t protected_leaves = 0, duplicate_leaves = 0;
    int deepest = 0;
    for (const std::int32_t n : leaves) {
      protected_leaves += builder.tree().is_protected(n) ? 1 : 0;
      duplicate_leaves += is_duplicate(builder.tree(), n) ? 1 : 0;
      deepest = std::max(deepest, builder.tree().level(n));
    }
    std::cout << "input      " << input << " (3D, " << domain->plc.vertices.size() << " vertices, "
              << domain->edges.size() << " edges, " << domain->plc.facets.size() << " facets)\n"
              << "leaves     " << s.leaves << " (" << s.outside_leaves << " outside P, " << protected_leaves
              << " protected, " << duplicate_leaves << " on duplicated cubes)\n"
              << "depth      " << deepest << " (root side " << builder.tree().root().size << ")\n"
              << "grid       "
              << (generic ? "generic, planes shifted by " + fmt(Vec3{builder.tree().root().offset[0],
                                                                     builder.tree().root().offset[1],
                                                                     builder.tree().root().offset[2]})
                          : std::string("aligned"))
              << '\n'
              << "splits     size " << s.splits_size << ", vertex " << s.splits_vertex << ", centering " << s.splits_centering << ", edge "
              << s.splits_edge << ", edge-separate " << s.splits_edge_separate << ", facet " << s.splits_facet
              << ", facet-separate " << s.splits_facet_separate << ", balance " << s.splits_balance << '\n'
              << "duplicates " << s.duplicates << " created\n"
              << "components " << s.components_split << " at splits, " << s.components_extended
              << " extended boxes, " << s.components_adjacency << " adjacency queries\n"
              << "vertex boxes " << s.vertex_boxes << '\n';
    std::int64_t per_kind[mv3d::kLeafKinds] = {};
    for (const std::int32_t n : leaves) ++per_kind[static_cast<int>(kinds[static_cast<std::size_t>(n)])];
    std::cout << "kinds     ";
    for (int k = 0; k < mv3d::kLeafKinds; ++k)
      std::cout << (k ? ", " : " ") << mv3d::to_string(static_cast<mv3d::LeafKind>(k)) << ' ' << per_kind[k];
    std::cout << '\n';
    std::cout << "phases     (leaves at the end, seconds)";
    for (int p = 0; p < mv3d::OctreeStats::kPhases; ++p)
      std::cout << (p % 3 == 0 ? "\n          " : ",") << ' ' << mv3d::OctreeStats::kPhaseNames[p] << ' '
                << s.phase_leaves[p] << ' ' << s.phase_seconds[p] << " s";
    std::cout << '\n'
              << "time       " << seconds << " s\n"
              << "output     " << output << " (VTK hexahedra; cell data level, component, duplicate, protected,\n"
              << "           phase " << phase_name(mv3d::OctPhase::Root) << "=0 vertex=1 centering=2 edge=3 facet=4 "
              << "balance=5 size=6\n"
              << "           edge-separate=7 facet-separate=8, vertex_owner, cone_kind (0 outside, 1 empty,\n"
              << "           2 vertex cone, 3 edge cone, 4 facet cone, 5 two facets, 6 other), protected_by (the\n"
              << "           phase number of the step that protected it, 0 if unprotected))\n";
  }
  return kExitOk;
}

}  // namespace pqmesh::cli
