#include "support/paths.hpp"

#include <fstream>
#include <iterator>

namespace pqmesh::test {

std::string data_path(const std::string& relative) { return std::string(PQMESH_DATA_DIR) + "/" + relative; }

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace pqmesh::test
