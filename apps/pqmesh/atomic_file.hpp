#pragma once
#include <string>

namespace pqmesh::cli {

// Writes text to path through a temporary file renamed into place, so a
// failure never leaves a partial file. Throws std::runtime_error on failure.
void write_text_file_atomic(const std::string& path, const std::string& text);

}  // namespace pqmesh::cli
