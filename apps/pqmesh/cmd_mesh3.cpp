// pqmesh mesh on a 3D domain (issue 5): not available yet.
#include <iostream>

#include "args.hpp"
#include "commands.hpp"

namespace pqmesh::cli {

int run_mesh3(const std::vector<std::string>& argv) {
  const Args args(argv, kMeshFlagsAnyMode, kMeshOptionsAnyMode);
  std::cerr << "pqmesh mesh: " << args.positional()[0] << ": 3D meshing is not available yet (issue 5)\n";
  return kExitInvalidInput;
}

}  // namespace pqmesh::cli
