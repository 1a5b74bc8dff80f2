// pqmesh info: validate an input domain and print its summary and alpha.
#include <iostream>

#include "commands.hpp"
#include "load.hpp"
#include "pqmesh/alpha.hpp"
#include "report_format.hpp"

namespace pqmesh::cli {
namespace {

void print_domain3(const std::string& path, const Domain3& d, const ReadReport& report) {
  const Plc3& plc = d.plc;
  std::size_t holes = 0;
  for (const Facet3& f : plc.facets) holes += f.loops.size() - 1;
  std::cout << "input      " << path << " (3D)\n"
            << "vertices   " << plc.vertices.size() << '\n'
            << "edges      " << d.edges.size() << '\n'
            << "facets     " << plc.facets.size() << " (" << holes << " facet holes)\n";
  if (report.input_polygons != report.facets || report.welded_vertices > 0) {
    std::cout << "merged     " << report.input_polygons << " input polygons into " << report.facets << " facets ("
              << report.merged_exact << " exactly coplanar, " << report.merged_near << " within the merge angle";
    if (report.welded_vertices > 0) std::cout << "; " << report.welded_vertices << " repeated vertices welded";
    std::cout << ")\n";
  }
  std::cout << "shells     " << d.shells.size() << " (1 exterior, " << d.shells.size() - 1 << " cavities)\n"
            << "volume     " << fmt(d.volume) << '\n'
            << "bbox       " << fmt(d.bbox_min) << " - " << fmt(d.bbox_max) << '\n'
            << "valid      yes\n";
  const AlphaResult alpha = compute_alpha(plc);
  std::cout << "alpha      " << alpha.describe(plc.source.first_id) << '\n'
            << "dihedral   min " << fmt_degrees(alpha.min_dihedral_radians) << " deg\n";
}

void print_domain2(const std::string& path, const Domain2& d) {
  std::size_t segments = 0;
  for (const auto& loop : d.loops) segments += loop.size();
  std::cout << "input      " << path << " (2D polygon with holes)\n"
            << "vertices   " << d.pslg.vertices.size() << '\n'
            << "segments   " << segments << '\n'
            << "loops      " << d.loops.size() << " (1 outer, " << d.loops.size() - 1 << " holes)\n"
            << "area       " << fmt(d.area) << '\n'
            << "bbox       " << fmt(d.bbox_min) << " - " << fmt(d.bbox_max) << '\n'
            << "valid      yes\n";
  const AlphaResult alpha = compute_alpha(d.pslg.vertices, d.loops);
  std::cout << "alpha      " << alpha.describe(d.pslg.source.first_id) << '\n';
}

}  // namespace

int run_info(const std::vector<std::string>& argv) {
  const Args args(argv, {"--no-merge"}, {"--merge-angle"});
  args.expect_positional(1, 1);
  const std::string& path = args.positional()[0];
  const LoadedDomain loaded = load_domain(path, read_options_from(args));
  if (const auto* d3 = std::get_if<Domain3>(&loaded.domain)) {
    print_domain3(path, *d3, loaded.report);
  } else {
    print_domain2(path, std::get<Domain2>(loaded.domain));
  }
  return kExitOk;
}

}  // namespace pqmesh::cli
