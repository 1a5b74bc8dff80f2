#pragma once
// A small whole-file text reader shared by the domain readers (read_*.cpp).
//
// Two ways to walk a file:
//   next_record(): one non-blank line at a time, split on whitespace, with an
//                  optional '#' comment stripped (Triangle, TetGen, OFF, OBJ);
//   next_token():  one whitespace-separated token at a time across lines
//                  (ASCII STL, Medit).
// Both report 1-based line numbers. fail() throws the ParseError every reader
// uses, carrying the file path and line (docs/DESIGN_RULES.md "Bad input and errors").
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "pqmesh/errors.hpp"

namespace pqmesh::detail {

struct TextRecord {
  int line = 0;
  std::vector<std::string_view> tokens;
};

struct TextToken {
  std::string_view text;
  int line = 0;
};

// Reads the whole file into `out`; false when it cannot be opened or read.
bool read_whole_file(const std::string& path, std::string& out);

class TextSource {
 public:
  // Loads the file; throws ParseError(Unreadable) when it cannot.
  explicit TextSource(std::string path, bool hash_comments = true);
  // Uses already-loaded content (for example a binary-sniffed STL).
  TextSource(std::string path, std::string content, bool hash_comments);

  const std::string& path() const { return path_; }
  const std::string& content() const { return content_; }

  // Next line with at least one token; false at end of file.
  bool next_record(TextRecord& out);
  // Next token; false at end of file.
  bool next_token(TextToken& out);
  // Token mode: discard what is left of the current line.
  void skip_rest_of_line();

  // Number of the last line of the file (at least 1): where a truncated file ended.
  int last_line() const { return last_line_; }

  [[noreturn]] void fail(ErrorCode code, const std::string& detail, int line,
                         std::vector<std::int64_t> ids = {}) const;
  // The file ended while `what` was still expected.
  [[noreturn]] void fail_truncated(const std::string& what) const;

 private:
  void count_lines();

  std::string path_;
  std::string content_;
  std::size_t pos_ = 0;
  int line_ = 1;  // line of content_[pos_]
  int last_line_ = 1;
  bool hash_comments_ = true;
};

// Whole-token number parsing. parse_double accepts what std::from_chars does
// (plus a leading '+'); an overflowing literal yields an infinity so that the
// caller reports it as NonFinite. Both return false when the token is not a number.
bool parse_double(std::string_view s, double& out);
bool parse_int(std::string_view s, long long& out);

// Lower-case file extension including the dot ("" when none).
std::string lower_extension(const std::string& path);
// `path` with its extension replaced by `ext` (which includes the dot).
std::string replace_extension(const std::string& path, const std::string& ext);

}  // namespace pqmesh::detail
