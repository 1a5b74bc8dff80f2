#pragma once
// Compressed binary arrays of VTK XML files (the `compressor` attribute of
// <VTKFile>). One compressed array is
//   header: H-byte little-endian unsigned integers (H = 4 for header_type
//           UInt32, 8 for UInt64)
//             [number of blocks n, uncompressed block size B,
//              uncompressed size of the last block (0: a full B),
//              compressed size of block 0, ..., of block n - 1]
//   data:   the n compressed blocks back to back.
// Every block but the last decompresses to exactly B bytes. Block formats:
// vtkZLibDataCompressor a zlib stream, vtkLZ4DataCompressor an LZ4 block
// (LZ4_compress_* output, no frame), vtkLZMADataCompressor an .xz stream.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace pqmesh::detail {

enum class VtuCompressor { None, Zlib, Lz4, Lzma };

// The compressor named by a `compressor` attribute: "" -> None, the three VTK
// class names above; anything else -> false (unknown).
bool vtu_compressor_from_name(std::string_view name, VtuCompressor& out);

// Where a compressed array sits, for error messages: ParseError(code, ...,
// path, line) naming the DataArray.
struct VtuArraySite {
  const std::string& path;
  int line;
  const std::string& name;
};

// Size of the whole header of the array whose first header_size bytes are at
// bytes[0..header_size): (3 + n) * header_size. Throws ParseError(WrongCount)
// when that exceeds `available` (the bytes the file still holds), so no
// header larger than the file is ever read or allocated.
std::size_t vtu_compressed_header_bytes(std::span<const unsigned char> bytes, std::size_t header_size,
                                        std::size_t available, const VtuArraySite& site);

// Size of header plus data, given the whole header in `bytes`. Throws
// ParseError(Truncated) when that exceeds `available`.
std::size_t vtu_compressed_array_bytes(std::span<const unsigned char> bytes, std::size_t header_size,
                                       std::size_t available, const VtuArraySite& site);

// Decompresses the array whose header and data are `bytes` (as measured by
// vtu_compressed_array_bytes). The result has exactly expected_bytes bytes;
// otherwise ParseError: WrongCount when the header's sizes disagree with
// expected_bytes or with what a block decompresses to, Syntax when a block is
// not a valid stream of the compressor. Memory grows with the bytes actually
// decompressed, never with a size the header merely claims.
std::vector<unsigned char> vtu_decompress(std::span<const unsigned char> bytes, std::size_t header_size,
                                          VtuCompressor compressor, std::size_t expected_bytes,
                                          const VtuArraySite& site);

// The zlib-compressed array (UInt64 header, blocks of kVtuWriteBlock bytes,
// zlib level 1) holding data[0..size).
inline constexpr std::size_t kVtuWriteBlock = std::size_t{1} << 16;
std::string vtu_compress_zlib(const char* data, std::size_t size);

}  // namespace pqmesh::detail
