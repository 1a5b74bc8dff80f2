#include "io/vtu_compression.hpp"

#include <lz4.h>
#include <lzma.h>
#include <zlib.h>

#include <algorithm>
#include <limits>

#include "pqmesh/errors.hpp"

namespace pqmesh::detail {

namespace {

[[noreturn]] void fail(ErrorCode code, const std::string& what, const VtuArraySite& site) {
  throw ParseError(code, "compressed DataArray '" + site.name + "': " + what, {}, site.path, site.line);
}

std::uint64_t header_item(std::span<const unsigned char> bytes, std::size_t header_size, std::size_t i) {
  std::uint64_t v = 0;
  for (std::size_t k = 0; k < header_size; ++k) v |= static_cast<std::uint64_t>(bytes[i * header_size + k]) << (8 * k);
  return v;
}

// How much a block may grow, so that a header claiming a huge block cannot
// make the LZ4 decoder allocate it: an LZ4 block expands at most about 255
// times (each extra length byte adds at most 255 bytes of output).
constexpr std::uint64_t kLz4MaxRatio = 256;

// Appends the decompression of one zlib stream `in` to out; it must give
// exactly `want` bytes and end there. out grows with the bytes produced.
void inflate_block(std::span<const unsigned char> in, std::size_t want, std::size_t block,
                   std::vector<unsigned char>& out, const VtuArraySite& site) {
  z_stream z{};
  if (inflateInit(&z) != Z_OK) fail(ErrorCode::Unsupported, "zlib cannot start", site);
  const std::size_t start = out.size();
  z.next_in = const_cast<unsigned char*>(in.data());
  int status = Z_OK;
  std::size_t fed = 0;
  while (status == Z_OK) {
    const std::size_t produced = out.size() - start;
    if (z.avail_in == 0 && fed < in.size()) {
      const std::size_t n = std::min<std::size_t>(in.size() - fed, std::numeric_limits<uInt>::max());
      z.next_in = const_cast<unsigned char*>(in.data()) + fed;
      z.avail_in = static_cast<uInt>(n);
      fed += n;
    }
    // One byte past `want` is room to notice a stream that gives too much.
    const std::size_t room = std::min<std::size_t>({want + 1 - produced, std::max<std::size_t>(produced, 1 << 16),
                                                    std::numeric_limits<uInt>::max()});
    out.resize(out.size() + room);
    z.next_out = out.data() + start + produced;
    z.avail_out = static_cast<uInt>(room);
    status = inflate(&z, Z_NO_FLUSH);
    out.resize(start + produced + (room - z.avail_out));
    if (status == Z_BUF_ERROR && z.avail_in == 0 && fed == in.size()) break;  // input ended mid-stream
    if (status == Z_BUF_ERROR) status = Z_OK;
    if (out.size() - start > want) break;
  }
  inflateEnd(&z);
  const std::size_t got = out.size() - start;
  if (got > want || (status == Z_STREAM_END && got != want))
    fail(ErrorCode::WrongCount, "block " + std::to_string(block) + " decompresses to more or fewer than the " +
                                    std::to_string(want) + " bytes of its header", site);
  if (status != Z_STREAM_END || z.avail_in != 0)
    fail(ErrorCode::Syntax, "block " + std::to_string(block) + " is not a complete zlib stream", site);
}

// The same for one .xz stream (vtkLZMADataCompressor).
void unxz_block(std::span<const unsigned char> in, std::size_t want, std::size_t block,
                std::vector<unsigned char>& out, const VtuArraySite& site) {
  lzma_stream z = LZMA_STREAM_INIT;
  constexpr std::uint64_t kMemLimit = std::uint64_t{1} << 28;  // dictionaries of VTK's presets fit
  if (lzma_stream_decoder(&z, kMemLimit, 0) != LZMA_OK) fail(ErrorCode::Unsupported, "liblzma cannot start", site);
  const std::size_t start = out.size();
  z.next_in = in.data();
  z.avail_in = in.size();
  lzma_ret status = LZMA_OK;
  while (status == LZMA_OK && out.size() - start <= want) {
    const std::size_t produced = out.size() - start;
    const std::size_t room = std::min<std::size_t>(want + 1 - produced, std::max<std::size_t>(produced, 1 << 16));
    out.resize(out.size() + room);
    z.next_out = out.data() + start + produced;
    z.avail_out = room;
    status = lzma_code(&z, LZMA_FINISH);
    out.resize(start + produced + (room - z.avail_out));
  }
  lzma_end(&z);
  const std::size_t got = out.size() - start;
  if (got > want || (status == LZMA_STREAM_END && got != want))
    fail(ErrorCode::WrongCount, "block " + std::to_string(block) + " decompresses to more or fewer than the " +
                                    std::to_string(want) + " bytes of its header", site);
  if (status != LZMA_STREAM_END || z.avail_in != 0)
    fail(ErrorCode::Syntax, "block " + std::to_string(block) + " is not a complete .xz stream", site);
}

void lz4_block(std::span<const unsigned char> in, std::size_t want, std::size_t block, std::vector<unsigned char>& out,
               const VtuArraySite& site) {
  if (want > kLz4MaxRatio * in.size() + 64 || want > static_cast<std::size_t>(LZ4_MAX_INPUT_SIZE) ||
      in.size() > static_cast<std::size_t>(LZ4_MAX_INPUT_SIZE))
    fail(ErrorCode::WrongCount, "block " + std::to_string(block) + " cannot decompress to the " +
                                    std::to_string(want) + " bytes of its header", site);
  const std::size_t start = out.size();
  out.resize(start + want);
  const int got = LZ4_decompress_safe(reinterpret_cast<const char*>(in.data()),
                                      reinterpret_cast<char*>(out.data() + start), static_cast<int>(in.size()),
                                      static_cast<int>(want));
  if (got < 0) fail(ErrorCode::Syntax, "block " + std::to_string(block) + " is not a valid LZ4 block", site);
  if (static_cast<std::size_t>(got) != want)
    fail(ErrorCode::WrongCount, "block " + std::to_string(block) + " decompresses to " + std::to_string(got) +
                                    " bytes, its header says " + std::to_string(want), site);
}

}  // namespace

bool vtu_compressor_from_name(std::string_view name, VtuCompressor& out) {
  if (name.empty()) out = VtuCompressor::None;
  else if (name == "vtkZLibDataCompressor") out = VtuCompressor::Zlib;
  else if (name == "vtkLZ4DataCompressor") out = VtuCompressor::Lz4;
  else if (name == "vtkLZMADataCompressor") out = VtuCompressor::Lzma;
  else return false;
  return true;
}

std::size_t vtu_compressed_header_bytes(std::span<const unsigned char> bytes, std::size_t header_size,
                                        std::size_t available, const VtuArraySite& site) {
  if (bytes.size() < header_size) fail(ErrorCode::Truncated, "the block count is cut off", site);
  const std::uint64_t blocks = header_item(bytes, header_size, 0);
  if (blocks > available / header_size || 3 + blocks > available / header_size)
    fail(ErrorCode::WrongCount, "header announces " + std::to_string(blocks) + " blocks, more than the file can hold",
         site);
  return static_cast<std::size_t>((3 + blocks) * header_size);
}

std::size_t vtu_compressed_array_bytes(std::span<const unsigned char> bytes, std::size_t header_size,
                                       std::size_t available, const VtuArraySite& site) {
  const std::size_t head = vtu_compressed_header_bytes(bytes, header_size, available, site);
  if (bytes.size() < head) fail(ErrorCode::Truncated, "the block header is cut off", site);
  std::uint64_t total = head;
  for (std::size_t k = 3; k < head / header_size; ++k) {
    const std::uint64_t size = header_item(bytes, header_size, k);
    if (size > available || total + size > available)
      fail(ErrorCode::Truncated, "block " + std::to_string(k - 3) + " of " + std::to_string(size) +
                                     " bytes runs past the end of the file", site);
    total += size;
  }
  return static_cast<std::size_t>(total);
}

std::vector<unsigned char> vtu_decompress(std::span<const unsigned char> bytes, std::size_t header_size,
                                          VtuCompressor compressor, std::size_t expected_bytes,
                                          const VtuArraySite& site) {
  const std::size_t head = vtu_compressed_header_bytes(bytes, header_size, bytes.size(), site);
  const std::uint64_t blocks = header_item(bytes, header_size, 0);
  const std::uint64_t block_size = header_item(bytes, header_size, 1);
  const std::uint64_t last = header_item(bytes, header_size, 2);
  // Uncompressed total (n - 1) * B + (last ? last : B), without overflow.
  bool sizes_ok = blocks == 0 ? expected_bytes == 0 : last <= block_size;
  if (blocks > 0 && sizes_ok) {
    const std::uint64_t tail = last != 0 ? last : block_size;
    sizes_ok = tail <= expected_bytes &&
               (blocks == 1 ? tail == expected_bytes
                            : block_size != 0 && (expected_bytes - tail) % block_size == 0 &&
                                  (expected_bytes - tail) / block_size == blocks - 1);
  }
  if (!sizes_ok)
    fail(ErrorCode::WrongCount, "header (" + std::to_string(blocks) + " blocks of " + std::to_string(block_size) +
                                    ", last " + std::to_string(last) + ") does not give the expected " +
                                    std::to_string(expected_bytes) + " bytes", site);
  std::vector<unsigned char> out;
  std::size_t at = head;
  for (std::size_t k = 0; k < blocks; ++k) {
    const std::uint64_t size = header_item(bytes, header_size, 3 + k);
    if (size > bytes.size() - at) fail(ErrorCode::Truncated, "block " + std::to_string(k) + " is cut off", site);
    const std::span<const unsigned char> in = bytes.subspan(at, static_cast<std::size_t>(size));
    const std::size_t want = static_cast<std::size_t>(k + 1 == blocks && last != 0 ? last : block_size);
    if (compressor == VtuCompressor::Zlib) inflate_block(in, want, k, out, site);
    else if (compressor == VtuCompressor::Lzma) unxz_block(in, want, k, out, site);
    else lz4_block(in, want, k, out, site);
    at += static_cast<std::size_t>(size);
  }
  return out;
}

std::string vtu_compress_zlib(const char* data, std::size_t size) {
  const std::size_t blocks = (size + kVtuWriteBlock - 1) / kVtuWriteBlock;
  std::vector<std::uint64_t> header = {blocks, kVtuWriteBlock, size % kVtuWriteBlock};
  std::string body;
  std::vector<unsigned char> buffer(compressBound(kVtuWriteBlock));
  for (std::size_t k = 0; k < blocks; ++k) {
    const std::size_t n = std::min(kVtuWriteBlock, size - k * kVtuWriteBlock);
    uLongf length = static_cast<uLongf>(buffer.size());
    compress2(buffer.data(), &length, reinterpret_cast<const Bytef*>(data + k * kVtuWriteBlock),
              static_cast<uLong>(n), 1);  // cannot fail: the buffer has compressBound bytes
    header.push_back(length);
    body.append(reinterpret_cast<const char*>(buffer.data()), length);
  }
  std::string out;
  for (std::uint64_t v : header)
    for (int k = 0; k < 8; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
  return out + body;
}

}  // namespace pqmesh::detail
