#include "atomic_file.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "pqmesh/errors.hpp"

namespace pqmesh::cli {

void write_text_file_atomic(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".tmp-" + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary);
    if (out) out << text;
    if (!out || !out.flush()) {
      std::remove(temporary.c_str());
      throw OutputError("cannot write " + path);
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::remove(temporary.c_str());
    throw OutputError("cannot write " + path + ": " + error.message());
  }
}

void check_output_directory(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  const std::string directory = parent.empty() ? "." : parent.string();
  std::error_code error;
  if (!std::filesystem::is_directory(directory, error))
    throw OutputError("cannot write " + path + ": no directory " + directory);
  if (::access(directory.c_str(), W_OK) != 0) throw OutputError("cannot write " + path + ": directory " + directory + " is not writable");
}

}  // namespace pqmesh::cli
