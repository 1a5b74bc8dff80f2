#pragma once
#include <string>

namespace pqmesh::cli {

// Writes text to path through a temporary file renamed into place, so a
// failure never leaves a partial file. Throws pqmesh::OutputError on failure.
void write_text_file_atomic(const std::string& path, const std::string& text);

// Throws pqmesh::OutputError unless the directory that would hold `path`
// exists and is writable: the commands call it before any work, so a long run
// does not end in a failed write. (The write itself can still fail later, on
// a full disk say, and then throws OutputError too; nothing partial is left.)
void check_output_directory(const std::string& path);

}  // namespace pqmesh::cli
