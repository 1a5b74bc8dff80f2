// pqmesh octree: build the octree of thesis §4.1 (pqmesh/octree.hpp) for a 3D
// domain and write its leaves as VTK hexahedra (.vtu, ASCII) with per-leaf data.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "atomic_file.hpp"
#include "commands.hpp"
#include "load.hpp"
#include "pqmesh/errors.hpp"
#include "pqmesh/octree.hpp"
#include "report_format.hpp"

namespace pqmesh::cli {
namespace {

template <class F>
void int_array(std::ostringstream& s, const char* name, const char* type, const std::vector<OctreeLeaf>& leaves,
               F value) {
  s << "        <DataArray type=\"" << type << "\" Name=\"" << name << "\" format=\"ascii\">\n         ";
  for (const OctreeLeaf& leaf : leaves) s << ' ' << value(leaf);
  s << "\n        </DataArray>\n";
}

// The leaves as an unstructured grid of hexahedra (VTK cell type 12), eight
// points per leaf (not shared), corners in VTK order: the lower face
// (0,0,0) (1,0,0) (1,1,0) (0,1,0), then the upper face in the same order.
std::string leaves_vtu(const std::vector<OctreeLeaf>& leaves) {
  std::ostringstream s;
  s.precision(std::numeric_limits<double>::max_digits10);
  s << "<?xml version=\"1.0\"?>\n"
    << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
    << "  <UnstructuredGrid>\n"
    << "    <Piece NumberOfPoints=\"" << 8 * leaves.size() << "\" NumberOfCells=\"" << leaves.size() << "\">\n"
    << "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  static const int kCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                    {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (const OctreeLeaf& leaf : leaves) {
    for (const auto& c : kCorner)
      s << "          " << (c[0] ? leaf.hi[0] : leaf.lo[0]) << ' ' << (c[1] ? leaf.hi[1] : leaf.lo[1]) << ' '
        << (c[2] ? leaf.hi[2] : leaf.lo[2]) << '\n';
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
  int_array(s, "level", "Int32", leaves, [](const OctreeLeaf& l) { return l.level; });
  int_array(s, "component", "Int32", leaves, [](const OctreeLeaf& l) { return l.component; });
  int_array(s, "duplicate", "UInt8", leaves, [](const OctreeLeaf& l) { return l.duplicate ? 1 : 0; });
  int_array(s, "protected", "UInt8", leaves, [](const OctreeLeaf& l) { return l.protected_box ? 1 : 0; });
  int_array(s, "phase", "Int32", leaves, [](const OctreeLeaf& l) { return l.phase; });
  int_array(s, "vertex_owner", "Int32", leaves, [](const OctreeLeaf& l) { return l.vertex_owner; });
  int_array(s, "cone_kind", "Int32", leaves, [](const OctreeLeaf& l) { return l.cone_kind; });
  int_array(s, "protected_by", "Int32", leaves, [](const OctreeLeaf& l) { return l.protected_by; });
  s << "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return s.str();
}

struct OctreeRun {
  std::string input, output;
  bool generic = false;
  double seconds = 0;  // build_octree, leaf description included
};

void print_octree_summary(const OctreeRun& run, const Domain3& domain, const OctreeReport& r) {
  std::int64_t protected_leaves = 0, duplicate_leaves = 0;
  std::int64_t per_kind[kOctreeLeafKinds] = {};
  for (const OctreeLeaf& leaf : r.leaves) {
    protected_leaves += leaf.protected_box ? 1 : 0;
    duplicate_leaves += leaf.duplicate ? 1 : 0;
    ++per_kind[leaf.cone_kind];
  }
  std::cout << "input      " << run.input << " (3D, " << domain.plc.vertices.size() << " vertices, "
            << domain.edges.size() << " edges, " << domain.plc.facets.size() << " facets)\n"
            << "leaves     " << r.leaves.size() << " (" << r.outside_leaves << " outside P, " << protected_leaves
            << " protected, " << duplicate_leaves << " on duplicated cubes)\n"
            << "depth      " << r.depth << " (root side " << r.root_size << ")\n"
            << "grid       "
            << (run.generic ? "generic, planes shifted by " + fmt(Vec3{r.grid_offset[0], r.grid_offset[1], r.grid_offset[2]})
                        : std::string("aligned"))
            << '\n'
            << "splits     size " << r.splits_size << ", vertex " << r.splits_vertex << ", centering "
            << r.splits_centering << ", edge " << r.splits_edge << ", edge-separate " << r.splits_edge_separate
            << ", facet " << r.splits_facet << ", facet-separate " << r.splits_facet_separate << ", balance "
            << r.splits_balance << ", united " << r.splits_united << " (edge splits of leaves holding two edges "
            << r.splits_edge_two_edges << ")\n"
            << "duplicates " << r.duplicates_created << " created\n"
            << "components " << r.components_split << " at splits, " << r.components_extended
            << " extended boxes, " << r.components_adjacency << " adjacency queries\n"
            << "vertex boxes " << r.vertex_boxes << '\n';
  std::cout << "kinds     ";
  for (int k = 0; k < kOctreeLeafKinds; ++k)
    std::cout << (k ? ", " : " ") << octree_leaf_kind_name(k) << ' ' << per_kind[k];
  std::cout << '\n' << "phases     (leaves at the end, seconds)";
  for (std::size_t p = 0; p < r.phases.size(); ++p)
    std::cout << (p % 3 == 0 ? "\n          " : ",") << ' ' << r.phases[p].name << ' ' << r.phases[p].leaves_at_end
              << ' ' << r.phases[p].seconds << " s";
  std::cout << '\n'
            << "time       " << run.seconds << " s\n"
            << "output     " << run.output << " (VTK hexahedra; cell data level, component, duplicate, protected,\n"
            << "           phase " << octree_phase_name(0) << "=0 vertex=1 centering=2 edge=3 facet=4 "
            << "balance=5 size=6\n"
            << "           edge-separate=7 facet-separate=8, vertex_owner, cone_kind (0 outside, 1 empty,\n"
            << "           2 vertex cone, 3 edge cone, 4 facet cone, 5 two facets, 6 other), protected_by (the\n"
            << "           phase number of the step that protected it, 0 if unprotected))\n";
}

}  // namespace

int run_octree(const std::vector<std::string>& argv) {
  const Args args(argv, {"--quiet", "--no-merge", "--generic-grid", "--light"},
                  {"-o", "--output", "--merge-angle", "--max-size", "--size-field"});
  args.expect_positional(1, 1);
  const std::string& input = args.positional()[0];
  const std::string output = output_option(args);
  if (output.size() < 4 || output.compare(output.size() - 4, 4, ".vtu") != 0)
    throw UsageError("the octree is written as .vtu; OUTPUT must end in .vtu");
  check_output_directory(output);

  OctreeOptions3 options;
  if (args.option("--max-size")) {
    options.max_size = args.number("--max-size", 0);  // throws UsageError unless a finite number
    if (!(options.max_size > 0))
      throw UsageError("--max-size must be a positive number, got '" + *args.option("--max-size") + "'");
  }
  if (const auto field = args.option("--size-field")) options.size_field = read_size_field3(*field);
  options.generic_grid = args.flag("--generic-grid");
  options.light = args.flag("--light");

  const LoadedDomain loaded = load_domain(input, read_options_from(args));
  const auto* domain = std::get_if<Domain3>(&loaded.domain);
  if (!domain) {
    std::cerr << "pqmesh octree: " << input << " is a 2D domain; the octree is for 3D domains\n";
    return kExitInvalidInput;
  }
  const auto start = std::chrono::steady_clock::now();
  const OctreeReport report = build_octree(*domain, options);
  const OctreeRun run{input, output, options.generic_grid,
                      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
  write_text_file_atomic(output, leaves_vtu(report.leaves));
  if (!args.flag("--quiet")) print_octree_summary(run, *domain, report);
  return kExitOk;
}

}  // namespace pqmesh::cli
