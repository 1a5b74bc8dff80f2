#pragma once
// The one message every meshing command prints when its own mesh fails
// check_mesh: the mesher promised a valid mesh, so this is a bug, and the
// caller writes nothing and exits kExitInternal.
#include <string>

#include "pqmesh/check.hpp"

namespace pqmesh::cli {

// True when `check` is valid. Otherwise prints "pqmesh mesh: internal error:
// <what> fails the validity check", the report and the bug notice on stderr,
// and returns false.
bool valid_or_reported(const CheckReport& check, const std::string& what);

}  // namespace pqmesh::cli
