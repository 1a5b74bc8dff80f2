#include "support/paths.hpp"

namespace pqmesh::test {

std::string data_path(const std::string& relative) { return std::string(PQMESH_DATA_DIR) + "/" + relative; }

}  // namespace pqmesh::test
