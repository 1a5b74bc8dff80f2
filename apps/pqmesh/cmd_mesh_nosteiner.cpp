// pqmesh mesh --no-boundary-steiner (thesis ch. 5, issue 6): not available yet.
#include <iostream>

#include "args.hpp"
#include "commands.hpp"

namespace pqmesh::cli {

int run_mesh_no_steiner(const std::vector<std::string>& argv) {
  const Args args(argv, kMeshFlagsAnyMode, kMeshOptionsAnyMode);
  std::cerr << "pqmesh mesh: " << args.positional()[0] << ": --no-boundary-steiner is not available yet (issue 6)\n";
  return kExitInvalidInput;
}

}  // namespace pqmesh::cli
