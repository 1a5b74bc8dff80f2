#include "invalid_mesh.hpp"

#include <iostream>

namespace pqmesh::cli {

bool valid_or_reported(const CheckReport& check, const std::string& what) {
  if (check.valid()) return true;
  std::cerr << "pqmesh mesh: internal error: " << what << " fails the validity check\n"
            << check.to_text() << "please report this as a bug; nothing was written\n";
  return false;
}

}  // namespace pqmesh::cli
