#pragma once
// Helpers shared by the reader tests: fixture paths, temporary files, and a
// check that a call throws the expected ParseError.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "pqmesh/errors.hpp"

namespace pqmesh::test {

inline std::string fixture(const std::string& name) {
  return (std::filesystem::path(__FILE__).parent_path() / "fixtures" / name).string();
}

// Writes `content` to a fresh file in the system temp directory.
inline std::string write_temp(const std::string& name, const std::string& content) {
  const auto dir = std::filesystem::temp_directory_path() / "pqmesh_io_read_test";
  std::filesystem::create_directories(dir);
  const auto path = dir / name;
  std::ofstream out(path, std::ios::binary);
  out << content;
  return path.string();
}

struct ExpectedError {
  ErrorCode code;
  int line;
  std::vector<std::int64_t> ids;
};

inline void expect_parse_error(const std::function<void()>& call, const ExpectedError& want, const std::string& path) {
  try {
    call();
    ADD_FAILURE() << "no ParseError for " << path;
  } catch (const ParseError& e) {
    EXPECT_EQ(e.code(), want.code) << e.what();
    EXPECT_EQ(e.line(), want.line) << e.what();
    EXPECT_EQ(e.ids(), want.ids) << e.what();
    EXPECT_EQ(e.file(), path) << e.what();
  }
}

}  // namespace pqmesh::test
