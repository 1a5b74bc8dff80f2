#include "io/mesh_input.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

namespace pqmesh::detail {

std::string read_whole_file(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) throw ParseError(ErrorCode::Unreadable, "cannot open file", {}, path, 0);
  std::string text;
  char block[1 << 16];
  std::size_t n = 0;
  while ((n = std::fread(block, 1, sizeof block, f)) > 0) text.append(block, n);
  const bool bad = std::ferror(f) != 0;
  std::fclose(f);
  if (bad) throw ParseError(ErrorCode::Unreadable, "read error", {}, path, 0);
  return text;
}

TextReader::TextReader(std::string path, std::string text, char comment_char)
    : path_(std::move(path)), text_(std::move(text)), comment_(comment_char) {}

void TextReader::fail(ErrorCode code, const std::string& detail, std::int64_t id) const {
  throw ParseError(code, detail, {id}, path_, line_);
}

void TextReader::fail(ErrorCode code, const std::string& detail) const {
  throw ParseError(code, detail, {}, path_, line_);
}

void TextReader::skip_space() {
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == '\n') {
      ++pos_line_;
      ++pos_;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      ++pos_;
    } else if (comment_ != '\0' && c == comment_) {
      while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    } else {
      break;
    }
  }
}

bool TextReader::at_end() {
  skip_space();
  if (pos_ >= text_.size()) {
    line_ = pos_line_;
    return true;
  }
  return false;
}

std::string_view TextReader::peek() {
  skip_space();
  std::size_t end = pos_;
  while (end < text_.size() && !std::isspace(static_cast<unsigned char>(text_[end])) &&
         !(comment_ != '\0' && text_[end] == comment_))
    ++end;
  return std::string_view(text_).substr(pos_, end - pos_);
}

std::string_view TextReader::token(const char* what) {
  const std::string_view t = peek();
  line_ = pos_line_;
  if (t.empty()) fail(ErrorCode::Truncated, std::string("file ends while reading ") + what);
  pos_ += t.size();
  return t;
}

std::int64_t TextReader::integer(const char* what) {
  const std::string_view t = token(what);
  std::int64_t value = 0;
  const char* first = t.data();
  if (!t.empty() && t[0] == '+') ++first;
  auto [end, ec] = std::from_chars(first, t.data() + t.size(), value);
  if (ec != std::errc() || end != t.data() + t.size())
    fail(ErrorCode::Syntax, std::string("expected an integer for ") + what + ", found '" + std::string(t) + "'");
  return value;
}

double TextReader::real(const char* what) {
  const std::string_view t = token(what);
  double value = 0;
  const char* first = t.data();
  if (!t.empty() && t[0] == '+') ++first;
  auto [end, ec] = std::from_chars(first, t.data() + t.size(), value);
  if (ec == std::errc::result_out_of_range)
    fail(ErrorCode::NonFinite, std::string("number out of range for ") + what + ": '" + std::string(t) + "'");
  if (ec != std::errc() || end != t.data() + t.size())
    fail(ErrorCode::Syntax, std::string("expected a number for ") + what + ", found '" + std::string(t) + "'");
  if (!std::isfinite(value))
    fail(ErrorCode::NonFinite, std::string("non-finite ") + what + " '" + std::string(t) + "'");
  return value;
}

std::int64_t TextReader::integer_in(const char* what, std::int64_t lo, std::int64_t hi) {
  const std::int64_t v = integer(what);
  if (v < lo || v > hi)
    fail(ErrorCode::WrongCount, std::string(what) + " " + std::to_string(v) + " is outside [" + std::to_string(lo) +
                                    ", " + std::to_string(hi) + "]");
  return v;
}

void TextReader::expect(std::string_view expected) {
  const std::string_view t = token(std::string(expected).c_str());
  if (t != expected)
    fail(ErrorCode::Syntax, "expected '" + std::string(expected) + "', found '" + std::string(t) + "'");
}

std::string_view TextReader::rest_of_line() {
  skip_space();
  line_ = pos_line_;
  std::size_t end = pos_;
  while (end < text_.size() && text_[end] != '\n') ++end;
  std::string_view rest = std::string_view(text_).substr(pos_, end - pos_);
  pos_ = end;
  while (!rest.empty() && (rest.back() == '\r' || rest.back() == ' ' || rest.back() == '\t')) rest.remove_suffix(1);
  while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t')) rest.remove_prefix(1);
  return rest;
}

void TextReader::skip_line() {
  while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
}

}  // namespace pqmesh::detail
