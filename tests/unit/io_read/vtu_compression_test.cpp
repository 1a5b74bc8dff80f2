// Compressed VTK XML arrays (src/io/vtu_compression.hpp) built here with
// zlib, LZ4 and liblzma directly: every compressor and header width reads
// back to the original bytes over several blocks with a partial last block,
// and every inconsistency is a ParseError with the code the contract names.
#include <gtest/gtest.h>
#include <lz4.h>
#include <lzma.h>
#include <zlib.h>

#include <cstdint>
#include <string>
#include <vector>

#include "io/vtu_compression.hpp"
#include "pqmesh/errors.hpp"

namespace pqmesh::detail {
namespace {

using Bytes = std::vector<unsigned char>;

Bytes compress_block(VtuCompressor c, const unsigned char* data, std::size_t n) {
  Bytes out;
  if (c == VtuCompressor::Zlib) {
    uLongf size = compressBound(static_cast<uLong>(n));
    out.resize(size);
    EXPECT_EQ(compress2(out.data(), &size, data, static_cast<uLong>(n), 6), Z_OK);
    out.resize(size);
  } else if (c == VtuCompressor::Lz4) {
    out.resize(static_cast<std::size_t>(LZ4_compressBound(static_cast<int>(n))));
    const int size = LZ4_compress_default(reinterpret_cast<const char*>(data), reinterpret_cast<char*>(out.data()),
                                          static_cast<int>(n), static_cast<int>(out.size()));
    EXPECT_GT(size, 0);
    out.resize(static_cast<std::size_t>(size));
  } else {
    out.resize(lzma_stream_buffer_bound(n));
    std::size_t size = 0;
    EXPECT_EQ(lzma_easy_buffer_encode(6, LZMA_CHECK_CRC64, nullptr, data, n, out.data(), &size, out.size()), LZMA_OK);
    out.resize(size);
  }
  return out;
}

void put(Bytes& out, std::uint64_t v, std::size_t width) {
  for (std::size_t k = 0; k < width; ++k) out.push_back(static_cast<unsigned char>((v >> (8 * k)) & 0xff));
}

// The array [n, block, last, sizes...] + blocks for `data`.
Bytes compressed_array(VtuCompressor c, const Bytes& data, std::size_t block, std::size_t width) {
  const std::size_t n = (data.size() + block - 1) / block;
  std::vector<Bytes> blocks;
  for (std::size_t k = 0; k < n; ++k)
    blocks.push_back(compress_block(c, data.data() + k * block, std::min(block, data.size() - k * block)));
  Bytes out;
  put(out, n, width);
  put(out, block, width);
  put(out, data.size() % block, width);
  for (const Bytes& b : blocks) put(out, b.size(), width);
  for (const Bytes& b : blocks) out.insert(out.end(), b.begin(), b.end());
  return out;
}

Bytes sample_data(std::size_t n) {
  Bytes data(n);
  for (std::size_t i = 0; i < n; ++i) data[i] = static_cast<unsigned char>((i * 2654435761u) >> 13);
  return data;
}

const std::string kPath = "test.vtu", kName = "Points";
const VtuArraySite kSite{kPath, 7, kName};

ErrorCode code_of(const Bytes& array, std::size_t width, VtuCompressor c, std::size_t expected) {
  try {
    vtu_decompress(array, width, c, expected, kSite);
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), kPath);
    EXPECT_EQ(e.line(), 7);
    EXPECT_NE(std::string(e.what()).find("'Points'"), std::string::npos) << e.what();
    return e.code();
  }
  ADD_FAILURE() << "no ParseError";
  return ErrorCode::Unreadable;
}

TEST(VtuCompression, EveryCompressorAndHeaderWidthRoundTrips) {
  const Bytes data = sample_data(3 * 1000 + 123);  // three full blocks of 1000 and a partial one
  for (VtuCompressor c : {VtuCompressor::Zlib, VtuCompressor::Lz4, VtuCompressor::Lzma})
    for (std::size_t width : {4u, 8u}) {
      const Bytes array = compressed_array(c, data, 1000, width);
      EXPECT_EQ(vtu_compressed_header_bytes(array, width, array.size(), kSite), (3 + 4) * width);
      EXPECT_EQ(vtu_compressed_array_bytes(array, width, array.size(), kSite), array.size());
      EXPECT_EQ(vtu_decompress(array, width, c, data.size(), kSite), data) << static_cast<int>(c) << ' ' << width;
    }
}

TEST(VtuCompression, WriterOutputReadsBack) {
  const Bytes data = sample_data(kVtuWriteBlock * 2 + 5);
  const std::string packed = vtu_compress_zlib(reinterpret_cast<const char*>(data.data()), data.size());
  const Bytes array(packed.begin(), packed.end());
  EXPECT_EQ(vtu_decompress(array, 8, VtuCompressor::Zlib, data.size(), kSite), data);
}

TEST(VtuCompression, CountsThatDisagreeWithTheExpectedSize) {
  const Bytes data = sample_data(2500);
  const Bytes array = compressed_array(VtuCompressor::Zlib, data, 1000, 8);
  EXPECT_EQ(code_of(array, 8, VtuCompressor::Zlib, 2499), ErrorCode::WrongCount);
  EXPECT_EQ(code_of(array, 8, VtuCompressor::Zlib, 3500), ErrorCode::WrongCount);
  // Header claims block size 1001: then blocks 0 and 1 decompress to 1000, not 1001.
  Bytes wrong = array;
  wrong[8] = static_cast<unsigned char>(1001 & 0xff);
  wrong[9] = static_cast<unsigned char>(1001 >> 8);
  wrong[16] = static_cast<unsigned char>(498 & 0xff);  // last 498: 2 * 1001 + 498 = 2500
  wrong[17] = static_cast<unsigned char>(498 >> 8);
  EXPECT_EQ(code_of(wrong, 8, VtuCompressor::Zlib, 2500), ErrorCode::WrongCount);
}

TEST(VtuCompression, BlockCountBeyondTheFile) {
  Bytes array = compressed_array(VtuCompressor::Zlib, sample_data(100), 1000, 4);
  array[3] = 0x40;  // 2^30 + 1 blocks
  try {
    vtu_compressed_header_bytes(array, 4, array.size(), kSite);
    ADD_FAILURE() << "no ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.code(), ErrorCode::WrongCount) << e.what();
  }
}

TEST(VtuCompression, CorruptStreamsAreSyntaxErrors) {
  const Bytes data = sample_data(1000);
  for (VtuCompressor c : {VtuCompressor::Zlib, VtuCompressor::Lz4, VtuCompressor::Lzma}) {
    Bytes array = compressed_array(c, data, 1000, 8);
    for (std::size_t k = 32; k < array.size(); k += 3) array[k] = 0xff;
    const ErrorCode code = code_of(array, 8, c, data.size());
    // A garbled stream is rejected as such, or decodes to a different size.
    EXPECT_TRUE(code == ErrorCode::Syntax || code == ErrorCode::WrongCount) << static_cast<int>(c);
  }
  Bytes cut = compressed_array(VtuCompressor::Zlib, data, 1000, 8);
  cut.resize(cut.size() - 5);  // the stream ends early; the header's size is adjusted to match
  cut[24] = static_cast<unsigned char>(cut.size() - 32);
  cut[25] = static_cast<unsigned char>((cut.size() - 32) >> 8);
  EXPECT_EQ(code_of(cut, 8, VtuCompressor::Zlib, data.size()), ErrorCode::Syntax);
}

TEST(VtuCompression, Lz4BlockClaimingMoreThanItCanHold) {
  // 8 compressed bytes cannot give 1 MiB (an LZ4 block expands at most ~255x):
  // refused before anything is allocated.
  Bytes array;
  put(array, 1, 8);
  put(array, 1 << 20, 8);
  put(array, 0, 8);
  put(array, 8, 8);
  for (int k = 0; k < 8; ++k) array.push_back(0);
  EXPECT_EQ(code_of(array, 8, VtuCompressor::Lz4, 1 << 20), ErrorCode::WrongCount);
}

TEST(VtuCompression, CompressorNames) {
  VtuCompressor c = VtuCompressor::Zlib;
  EXPECT_TRUE(vtu_compressor_from_name("", c));
  EXPECT_EQ(c, VtuCompressor::None);
  EXPECT_TRUE(vtu_compressor_from_name("vtkLZ4DataCompressor", c));
  EXPECT_EQ(c, VtuCompressor::Lz4);
  EXPECT_TRUE(vtu_compressor_from_name("vtkLZMADataCompressor", c));
  EXPECT_EQ(c, VtuCompressor::Lzma);
  EXPECT_TRUE(vtu_compressor_from_name("vtkZLibDataCompressor", c));
  EXPECT_EQ(c, VtuCompressor::Zlib);
  EXPECT_FALSE(vtu_compressor_from_name("vtkZstdDataCompressor", c));
}

}  // namespace
}  // namespace pqmesh::detail
