#pragma once
// Output plumbing shared by the mesh writers: a temporary file that becomes
// the real file only on success (atomic writes: never a partial output file,
// docs/DESIGN_RULES.md "Bad input and errors") and a buffered writer that
// formats numbers with std::to_chars (no per-line string streams; shortest
// round-trip form for doubles, so the same mesh always gives the same bytes
// and ASCII coordinates read back bit-exactly).
#include <bit>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <cstring>
#include <utility>
#include <vector>

namespace pqmesh::detail {

// "<path>.tmp-<pid>", created on construction. finish() flushes and closes it
// (throwing pqmesh::Error on any I/O error), commit() renames it onto path.
// The destructor removes the temporary if commit() did not happen, so every
// exit by exception cleans up.
class AtomicFile {
 public:
  explicit AtomicFile(std::string path);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();

  std::FILE* file() const { return file_; }
  const std::string& path() const { return path_; }
  void finish();
  void commit();

 private:
  std::string path_;
  std::string temp_path_;
  std::FILE* file_ = nullptr;
  bool committed_ = false;
};

// Appends text and binary data to a buffer and hands it to a FILE in large
// blocks. Throws pqmesh::Error (naming path) when the FILE reports an error.
class BufferedWriter {
 public:
  BufferedWriter(std::FILE* file, std::string path);
  BufferedWriter(const BufferedWriter&) = delete;
  BufferedWriter& operator=(const BufferedWriter&) = delete;

  BufferedWriter& put(std::string_view text);
  BufferedWriter& put(char c);
  BufferedWriter& put_int(std::int64_t value);
  // Shortest decimal form that reads back to the same double.
  BufferedWriter& put_double(double value);
  // Shortest decimal form that reads back to the same float.
  BufferedWriter& put_float(float value);
  // Fixed-point with `decimals` digits (used for SVG coordinates only).
  BufferedWriter& put_fixed(double value, int decimals);
  // Raw bytes in little-endian order (binary VTU).
  void put_bytes(const void* data, std::size_t size);
  // n bytes at the end of the buffer, counted as written: the caller fills
  // all of them before the next call on this writer (binary VTU arrays are
  // produced in place this way, without a staging copy).
  char* claim(std::size_t n);
  template <class T>
  void put_le(T value);
  // Writes everything buffered so far to the FILE.
  void flush();

 private:
  void reserve(std::size_t n);
  std::FILE* file_;
  std::string path_;
  std::vector<char> buffer_;
  std::size_t used_ = 0;
};

// Throws pqmesh::Error "cannot write <path>: <errno text>".
[[noreturn]] void throw_write_error(const std::string& path, int err);

template <class T>
void BufferedWriter::put_le(T value) {
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) {
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
  }
  put_bytes(bytes, sizeof(T));
}

}  // namespace pqmesh::detail
