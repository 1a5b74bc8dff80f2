// read_size_field2: a good file read back value for value, and every error
// the reader promises (src/io/read_size_field.cpp), each with the file path
// and the line counted by hand in the test's own string.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "pqmesh/errors.hpp"
#include "pqmesh/quadmesh.hpp"

namespace pqmesh {
namespace {

// A directory of this process (tests may run in parallel), removed at exit.
struct TempDir {
  std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("pqmesh_size_field_test_" + std::to_string(::getpid()));
  TempDir() { std::filesystem::create_directories(path); }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

std::string write_temp(const std::string& name, const std::string& content) {
  static const TempDir dir;
  const auto path = dir.path / name;
  std::ofstream out(path, std::ios::binary);
  out << content;
  return path.string();
}

// Reads `content` and expects a ParseError with this code and line whose
// message starts with "path:line: ".
void expect_error(const std::string& name, const std::string& content, ErrorCode code, int line) {
  const std::string path = write_temp(name, content);
  try {
    read_size_field2(path);
    ADD_FAILURE() << "no ParseError for " << name;
  } catch (const ParseError& e) {
    EXPECT_EQ(e.code(), code) << e.what();
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.file(), path) << e.what();
    const std::string where = path + ":" + std::to_string(line) + ": ";
    EXPECT_EQ(std::string(e.what()).rfind(where, 0), 0u) << e.what();
  }
}

TEST(ReadSizeField, GoodFile) {
  const std::string content =
      "# size field for a unit square\n"   // 1
      "\n"                                  // 2
      "0 0 0.125\n"                         // 3
      "  1\t0   0.5   # a trailing note\n"  // 4
      "   # indented comment\n"             // 5
      "-2.5e-1 +3 1e-3\r\n"                 // 6 (CRLF)
      "0.5 0.5 4";                          // 7 (no final newline)
  const std::string path = write_temp("good.txt", content);
  const SizeField2 f = read_size_field2(path);
  EXPECT_EQ(f.path, path);
  ASSERT_EQ(f.points.size(), 4u);
  ASSERT_EQ(f.sizes.size(), 4u);
  ASSERT_EQ(f.lines.size(), 4u);
  EXPECT_EQ(f.points[0], (Vec2{0, 0}));
  EXPECT_EQ(f.points[1], (Vec2{1, 0}));
  EXPECT_EQ(f.points[2], (Vec2{-0.25, 3}));
  EXPECT_EQ(f.points[3], (Vec2{0.5, 0.5}));
  EXPECT_EQ(f.sizes[0], 0.125);
  EXPECT_EQ(f.sizes[1], 0.5);
  EXPECT_EQ(f.sizes[2], 1e-3);
  EXPECT_EQ(f.sizes[3], 4.0);
  EXPECT_EQ(f.lines, (std::vector<int>{3, 4, 6, 7}));
}

TEST(ReadSizeField, Unreadable) {
  const std::string missing = "/nonexistent/dir/sizes.txt";
  try {
    read_size_field2(missing);
    ADD_FAILURE() << "no ParseError for a missing file";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.code(), ErrorCode::Unreadable) << e.what();
    EXPECT_EQ(e.file(), missing) << e.what();
  }
}

TEST(ReadSizeField, WrongNumberOfFields) {
  expect_error("two.txt", "0 0 1\n# c\n1 1\n", ErrorCode::WrongCount, 3);
  expect_error("four.txt", "0 0 1 7\n", ErrorCode::WrongCount, 1);
  expect_error("one.txt", "\n\n5\n", ErrorCode::WrongCount, 3);
  // The comment is not a field: only two fields remain.
  expect_error("hash.txt", "0 0 1\n0 #0 1\n", ErrorCode::WrongCount, 2);
}

TEST(ReadSizeField, NonNumeric) {
  expect_error("x.txt", "zero 0 1\n", ErrorCode::Syntax, 1);
  expect_error("y.txt", "0 0 1\n0 0y 1\n", ErrorCode::Syntax, 2);
  expect_error("size.txt", "0 0 1\n\n1 1 big\n", ErrorCode::Syntax, 3);
  expect_error("comma.txt", "0,5 0 1\n", ErrorCode::Syntax, 1);
}

TEST(ReadSizeField, NonFinite) {
  expect_error("nan.txt", "nan 0 1\n", ErrorCode::NonFinite, 1);
  expect_error("inf.txt", "0 0 1\n0 inf 1\n", ErrorCode::NonFinite, 2);
  expect_error("infsize.txt", "# c\n0 0 inf\n", ErrorCode::NonFinite, 2);
  expect_error("overflow.txt", "0 0 1e999\n", ErrorCode::NonFinite, 1);
}

TEST(ReadSizeField, SizeNotPositive) {
  expect_error("zero.txt", "0 0 1\n1 1 0\n", ErrorCode::Syntax, 2);
  expect_error("negative.txt", "0 0 -1\n", ErrorCode::Syntax, 1);
  expect_error("negzero.txt", "0 0 -0\n", ErrorCode::Syntax, 1);
  // Underflows to zero: not a positive size.
  expect_error("underflow.txt", "0 0 1e-999\n", ErrorCode::Syntax, 1);
}

TEST(ReadSizeField, NoPoints) {
  expect_error("empty.txt", "", ErrorCode::WrongCount, 1);
  expect_error("comments.txt", "# nothing\n\n# here\n", ErrorCode::WrongCount, 3);
}

}  // namespace
}  // namespace pqmesh
