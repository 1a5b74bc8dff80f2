#pragma once
#include <string>

namespace pqmesh::test {

// Absolute path of a file under the project's data/ directory.
std::string data_path(const std::string& relative);

// The whole content of a file, byte for byte ("" when it cannot be read).
std::string file_bytes(const std::string& path);

}  // namespace pqmesh::test
