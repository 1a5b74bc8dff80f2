#pragma once
#include <string>

namespace pqmesh::test {

// Absolute path of a file under the project's data/ directory.
std::string data_path(const std::string& relative);

}  // namespace pqmesh::test
