#include "io/read_text_tokens.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace pqmesh::detail {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

}  // namespace

bool read_whole_file(const std::string& path, std::string& out) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return false;
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) return false;
  out = std::move(buffer).str();
  return true;
}

TextSource::TextSource(std::string path, bool hash_comments) : path_(std::move(path)), hash_comments_(hash_comments) {
  if (!read_whole_file(path_, content_)) fail(ErrorCode::Unreadable, "cannot open or read the file", 0);
  count_lines();
}

TextSource::TextSource(std::string path, std::string content, bool hash_comments)
    : path_(std::move(path)), content_(std::move(content)), hash_comments_(hash_comments) {
  count_lines();
}

void TextSource::count_lines() {
  const auto newlines = std::count(content_.begin(), content_.end(), '\n');
  last_line_ = static_cast<int>(newlines);
  if (!content_.empty() && content_.back() != '\n') ++last_line_;
  last_line_ = std::max(last_line_, 1);
}

bool TextSource::next_record(TextRecord& out) {
  out.tokens.clear();
  const std::size_t n = content_.size();
  while (pos_ < n) {
    const std::size_t eol_found = content_.find('\n', pos_);
    const std::size_t eol = eol_found == std::string::npos ? n : eol_found;
    std::size_t end = eol;
    if (hash_comments_) {
      const std::size_t hash = content_.find('#', pos_);
      if (hash != std::string::npos && hash < end) end = hash;
    }
    out.line = line_;
    std::size_t i = pos_;
    while (i < end) {
      while (i < end && is_space(content_[i])) ++i;
      const std::size_t start = i;
      while (i < end && !is_space(content_[i])) ++i;
      if (i > start) out.tokens.emplace_back(content_.data() + start, i - start);
    }
    pos_ = eol < n ? eol + 1 : n;
    ++line_;
    if (!out.tokens.empty()) return true;
  }
  return false;
}

bool TextSource::next_token(TextToken& out) {
  const std::size_t n = content_.size();
  while (pos_ < n) {
    const char c = content_[pos_];
    if (c == '\n') {
      ++line_;
      ++pos_;
    } else if (is_space(c)) {
      ++pos_;
    } else if (c == '#' && hash_comments_) {
      while (pos_ < n && content_[pos_] != '\n') ++pos_;
    } else {
      const std::size_t start = pos_;
      while (pos_ < n && !is_space(content_[pos_])) ++pos_;
      out.text = std::string_view(content_.data() + start, pos_ - start);
      out.line = line_;
      return true;
    }
  }
  return false;
}

void TextSource::skip_rest_of_line() {
  const std::size_t n = content_.size();
  while (pos_ < n && content_[pos_] != '\n') ++pos_;
}

void TextSource::fail(ErrorCode code, const std::string& detail, int line, std::vector<std::int64_t> ids) const {
  throw ParseError(code, detail, std::move(ids), path_, line);
}

void TextSource::fail_truncated(const std::string& what) const {
  fail(ErrorCode::Truncated, "file ends before " + what, last_line_);
}

bool parse_double(std::string_view s, double& out) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return false;
  const char* first = s.data();
  const char* last = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(first, last, out);
  if (ptr != last) return false;
  if (ec == std::errc::result_out_of_range) {
    // Overflow is reported as non-finite; underflow rounds to a (signed) zero.
    const bool negative = s.front() == '-';
    std::string_view digits = negative ? s.substr(1) : s;
    const auto e = digits.find_first_of("eE");
    const bool big = e != std::string_view::npos && e + 1 < digits.size() && digits[e + 1] != '-';
    out = big ? (negative ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity())
              : (negative ? -0.0 : 0.0);
    return true;
  }
  return ec == std::errc();
}

bool parse_int(std::string_view s, long long& out) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return false;
  const char* last = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(s.data(), last, out);
  return ec == std::errc() && ptr == last;
}

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::string replace_extension(const std::string& path, const std::string& ext) {
  return std::filesystem::path(path).replace_extension(ext).string();
}

}  // namespace pqmesh::detail
