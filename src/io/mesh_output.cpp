#include "io/mesh_output.hpp"

#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>

#include "pqmesh/errors.hpp"

namespace pqmesh::detail {

void throw_write_error(const std::string& path, int err) {
  throw OutputError("cannot write " + path + ": " + (err != 0 ? std::strerror(err) : "I/O error"));
}

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  temp_path_ = path_ + ".tmp-" + std::to_string(static_cast<long long>(::getpid()));
  file_ = std::fopen(temp_path_.c_str(), "wb");
  if (file_ == nullptr) throw_write_error(path_, errno);
}

AtomicFile::~AtomicFile() {
  if (file_ != nullptr) std::fclose(file_);
  if (!committed_) std::remove(temp_path_.c_str());
}

void AtomicFile::finish() {
  if (file_ == nullptr) return;
  const bool bad = std::fflush(file_) != 0 || std::ferror(file_) != 0;
  const int err = errno;
  const bool close_failed = std::fclose(file_) != 0;
  file_ = nullptr;
  if (bad || close_failed) throw_write_error(path_, err);
}

void AtomicFile::commit() {
  finish();
  if (std::rename(temp_path_.c_str(), path_.c_str()) != 0) throw_write_error(path_, errno);
  committed_ = true;
}

namespace {
constexpr std::size_t kBlock = std::size_t{1} << 20;  // bytes handed to fwrite at once
}

BufferedWriter::BufferedWriter(std::FILE* file, std::string path)
    : file_(file), path_(std::move(path)), buffer_(kBlock + 64) {}

void BufferedWriter::flush() {
  if (used_ == 0) return;
  if (std::fwrite(buffer_.data(), 1, used_, file_) != used_) throw_write_error(path_, errno);
  used_ = 0;
}

void BufferedWriter::reserve(std::size_t n) {
  if (used_ + n > buffer_.size()) flush();
  if (n > buffer_.size()) buffer_.resize(n);
}

BufferedWriter& BufferedWriter::put(std::string_view text) {
  if (text.size() > kBlock) {
    flush();
    if (std::fwrite(text.data(), 1, text.size(), file_) != text.size()) throw_write_error(path_, errno);
    return *this;
  }
  reserve(text.size());
  std::memcpy(buffer_.data() + used_, text.data(), text.size());
  used_ += text.size();
  return *this;
}

BufferedWriter& BufferedWriter::put(char c) {
  reserve(1);
  buffer_[used_++] = c;
  return *this;
}

BufferedWriter& BufferedWriter::put_int(std::int64_t value) {
  reserve(24);
  auto [end, ec] = std::to_chars(buffer_.data() + used_, buffer_.data() + used_ + 24, value);
  (void)ec;
  used_ = static_cast<std::size_t>(end - buffer_.data());
  return *this;
}

BufferedWriter& BufferedWriter::put_double(double value) {
  reserve(32);
  auto [end, ec] = std::to_chars(buffer_.data() + used_, buffer_.data() + used_ + 32, value);
  (void)ec;
  used_ = static_cast<std::size_t>(end - buffer_.data());
  return *this;
}

BufferedWriter& BufferedWriter::put_float(float value) {
  reserve(32);
  auto [end, ec] = std::to_chars(buffer_.data() + used_, buffer_.data() + used_ + 32, value);
  (void)ec;
  used_ = static_cast<std::size_t>(end - buffer_.data());
  return *this;
}

BufferedWriter& BufferedWriter::put_fixed(double value, int decimals) {
  reserve(64);
  // Large magnitudes fall back to the shortest form, which always fits.
  auto [end, ec] = std::abs(value) < 1e30
                       ? std::to_chars(buffer_.data() + used_, buffer_.data() + used_ + 64, value,
                                       std::chars_format::fixed, decimals)
                       : std::to_chars(buffer_.data() + used_, buffer_.data() + used_ + 64, value);
  (void)ec;
  used_ = static_cast<std::size_t>(end - buffer_.data());
  return *this;
}

char* BufferedWriter::claim(std::size_t n) {
  reserve(n);
  char* at = buffer_.data() + used_;
  used_ += n;
  return at;
}

void BufferedWriter::put_bytes(const void* data, std::size_t size) {
  put(std::string_view(static_cast<const char*>(data), size));
}

}  // namespace pqmesh::detail
