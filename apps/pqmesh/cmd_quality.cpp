// pqmesh quality: element quality report and histograms of a mesh.
#include <iostream>

#include "atomic_file.hpp"
#include "commands.hpp"
#include "load.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/quality.hpp"

namespace pqmesh::cli {

int run_quality(const std::vector<std::string>& argv) {
  const Args args(argv, {}, {"--dim", "--svg"});
  args.expect_positional(1, 1);
  const AnyMesh mesh = load_mesh(args.positional()[0], dimension_option(args));
  const auto [report, topology] = std::visit(
      [](const auto& m) { return std::make_pair(quality_report(m), check_mesh_topology(m)); }, mesh);
  std::cout << report.to_text();
  std::cout << "topology   " << (topology.valid() ? "valid (orientation, conformity)" : "INVALID") << '\n';
  if (!topology.valid()) std::cout << topology.to_text() << '\n';
  if (const auto svg = args.option("--svg")) {
    const char* title = report.dimension == 3 ? "minimum dihedral angle (degrees)" : "minimum angle (degrees)";
    write_text_file_atomic(*svg, histogram_svg(report.min_angle_hist, title));
    std::cout << "histogram  " << *svg << '\n';
  }
  return topology.valid() ? kExitOk : kExitCheckFailed;
}

}  // namespace pqmesh::cli
