#pragma once
// Input plumbing shared by the mesh readers: the whole file is read into
// memory and split into whitespace-separated tokens, each with its 1-based
// line number, so every ParseError names the file line it is about.
#include <cstdint>
#include <string>
#include <string_view>

#include "pqmesh/errors.hpp"

namespace pqmesh::detail {

// Reads the whole file; throws ParseError(Unreadable) naming path.
std::string read_whole_file(const std::string& path);

class TextReader {
 public:
  // comment_char: a token starting with it skips to the end of the line
  // ('\0' for formats without comments).
  TextReader(std::string path, std::string text, char comment_char);

  const std::string& path() const { return path_; }
  // Line of the last token returned (or of the current position).
  int line() const { return line_; }
  // True when only whitespace/comments remain.
  bool at_end();
  // Next token without consuming it ("" at the end).
  std::string_view peek();
  // Next token; throws Truncated naming `what` at the end of the file.
  std::string_view token(const char* what);
  // Next token as an integer / finite double; Syntax / NonFinite otherwise.
  std::int64_t integer(const char* what);
  double real(const char* what);
  // An integer in [lo, hi]; WrongCount otherwise.
  std::int64_t integer_in(const char* what, std::int64_t lo, std::int64_t hi);
  // The token must equal `expected`.
  void expect(std::string_view expected);
  // From the next token to the end of its line (for quoted names).
  std::string_view rest_of_line();
  // Skip to the first token of the next line.
  void skip_line();

  [[noreturn]] void fail(ErrorCode code, const std::string& detail, std::int64_t id) const;
  [[noreturn]] void fail(ErrorCode code, const std::string& detail) const;

 private:
  void skip_space();
  std::string path_;
  std::string text_;
  char comment_;
  std::size_t pos_ = 0;
  int line_ = 1;      // line of the last token
  int pos_line_ = 1;  // line at pos_
};

}  // namespace pqmesh::detail
