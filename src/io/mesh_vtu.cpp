// VTK XML UnstructuredGrid (.vtu), version 1.0, little endian, UInt64 block
// headers. Only the elements are written (VTK type 5 triangle, 10 tetra), as
// one cell block; boundary edges/faces are not part of a .vtu. Arrays, in
// document order:
//   PointData "vertex_marker" (Int32, when present)
//   CellData  "marker" (Int32, when present), then every CellField (Float64,
//             or Float32 when the field asks for single precision)
//   Points (Float64 x3, z = 0 in 2D); Cells connectivity/offsets (Int32 when
//   every offset, at most nodes * cells, fits in 31 bits, else Int64; VTK XML
//   allows any integer type there), types (UInt8).
// binary = true: every array is appended raw after "_" in <AppendedData>,
// each preceded by its byte count as UInt64 (compress = true: as a
// vtkZLibDataCompressor array instead, vtu_compression.hpp); false: inline
// ASCII.
//
// The appended arrays are stored in REVERSE document order (the last
// DataArray of the XML at offset 0). Readers locate arrays by offset, so VTK
// does not care; the order is for meshio 5, whose raw-appended reader
// (_parse_raw_binary) walks the blocks in file order and, for the block at
// raw offset i, takes the FIRST DataArray in document order whose offset
// attribute is "i", then overwrites that attribute with the array's offset in
// a base64 re-encoding (about 4/3 of the raw offset). With blocks in
// document order, an array already re-encoded can carry a rewritten offset
// equal to the raw offset of a later block; meshio then rewrites the wrong
// array, and the later array decodes from the wrong place ("size of the data
// array 'Points' ... doesn't fit the number of components 3", "buffer size
// must be a multiple of element size"): whether it happens depends on the
// array sizes, so some meshes failed and others did not. In reverse order
// every array already rewritten comes after the one being looked up in the
// document, so the first match is always the right one.
//
// meshio also takes the first "</AppendedData>" in the file as the end of
// the data, so raw data containing those 15 bytes would cut it short: this
// cannot come from coordinates, connectivity, offsets or types of any mesh
// pqmesh can hold, only from Int32 markers or field values chosen to spell
// the text (VTK reads such a file correctly).
// VTK's tetrahedron has positive volume for pqmesh's orientation (its
// reference tetrahedron is (0,0,0), (1,0,0), (0,1,0), (0,0,1)).
#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "io/mesh_common.hpp"
#include "io/mesh_input.hpp"
#include "io/mesh_output.hpp"
#include "io/vtu_compression.hpp"

namespace pqmesh::detail {

namespace {

enum class Scalar { Int32, Int64, UInt8, Float32, Float64 };

const char* vtk_name(Scalar s) {
  switch (s) {
    case Scalar::Int32: return "Int32";
    case Scalar::Int64: return "Int64";
    case Scalar::UInt8: return "UInt8";
    case Scalar::Float32: return "Float32";
    case Scalar::Float64: return "Float64";
  }
  return "";
}

std::size_t scalar_size(Scalar s) {
  switch (s) {
    case Scalar::Int32: return 4;
    case Scalar::Int64: return 8;
    case Scalar::UInt8: return 1;
    case Scalar::Float32: return 4;
    case Scalar::Float64: return 8;
  }
  return 0;
}

// The Float32 stored for a single-precision field value (CellField): the
// nearest float, except that a value beyond the float range (an infinity
// included) becomes +-FLT_MAX, which the readers accept. NaN stays NaN.
float single_precision(double v) {
  constexpr double kMax = std::numeric_limits<float>::max();
  return static_cast<float>(std::clamp(v, -kMax, kMax));
}

// One array to write: `count` values produced by value(i).
struct ArraySpec {
  std::string name;
  Scalar scalar;
  int components;
  std::size_t count;  // number of scalars (tuples * components)
};

// Writes `items` items of Per scalars of type S each, as raw native bytes:
// fill(w, i) stores the Per scalars of item i at w. Each item goes straight
// into the writer's buffer (claimed in blocks of about 64 KiB), so neither an
// array-sized copy nor a staging copy is made.
template <class S, std::size_t Per, class Fill>
void put_items(std::size_t items, Fill fill, BufferedWriter& out) {
  constexpr std::size_t kItemBytes = sizeof(S) * Per;
  constexpr std::size_t kBlockItems = std::max<std::size_t>(1, (std::size_t{1} << 16) / kItemBytes);
  for (std::size_t first = 0; first < items; first += kBlockItems) {
    const std::size_t n = std::min(kBlockItems, items - first);
    char* bytes = out.claim(kItemBytes * n);
    for (std::size_t i = first; i < first + n; ++i, bytes += kItemBytes) {
      S item[Per];
      fill(item, i);
      std::memcpy(bytes, item, kItemBytes);  // the buffer has no alignment for S
    }
  }
}

// Binary (appended, raw) array `array` (numbering as in write_body) on a
// little-endian machine: the bytes put_value(array, spec, i, true) would
// write for every i, produced block by block in the writer's buffer (put_items).
// Arrays already stored in the file's layout (markers, Float64 fields, Int32
// connectivity) go out straight from the mesh in one piece.
template <class M>
void put_raw_array(const M& mesh, const WriteOptions& options, int array, const ArraySpec& spec,
                   BufferedWriter& out) {
  using T = MeshTraits<M>;
  constexpr int D = T::dim;
  constexpr int N = T::cell_nodes;
  const auto& cells = T::cells(mesh);
  const int num_fields = static_cast<int>(options.cell_fields.size());
  const std::size_t count = spec.count;
  // Int32 markers and indices (int is 32 bits on every platform we build for;
  // checked), a cell being N ints with no padding.
  static_assert(sizeof(int) == 4);
  static_assert(sizeof(cells[0]) == 4 * N);
  if (count == 0) return;
  if (array == 0) return out.put_bytes(mesh.vertex_markers.data(), 4 * count);
  if (array == 1) return out.put_bytes(T::cell_markers(mesh).data(), 4 * count);
  if (array < 2 + num_fields) {
    const std::vector<double>& values = options.cell_fields[static_cast<std::size_t>(array - 2)].values;
    if (spec.scalar == Scalar::Float64) return out.put_bytes(values.data(), 8 * count);
    return put_items<float, 1>(count, [&](float* w, std::size_t i) { w[0] = single_precision(values[i]); }, out);
  }
  const int rest = array - 2 - num_fields;
  if (rest == 0) {  // points: x, y, z (z = 0 in 2D)
    return put_items<double, 3>(count / 3, [&](double* w, std::size_t i) {
      for (int k = 0; k < 3; ++k) w[k] = coord(mesh.vertices[i], k);
    }, out);
  }
  const bool wide = spec.scalar == Scalar::Int64;
  if (rest == 1) {  // connectivity
    if (!wide) return out.put_bytes(cells.data(), 4 * count);
    return put_items<std::int64_t, N>(count / N, [&](std::int64_t* w, std::size_t i) {
      for (int k = 0; k < N; ++k) w[k] = cells[i][static_cast<std::size_t>(k)];
    }, out);
  }
  if (rest == 2) {  // offsets: the end of cell i's nodes
    if (wide)
      return put_items<std::int64_t, 1>(count, [&](std::int64_t* w, std::size_t i) {
        w[0] = static_cast<std::int64_t>((i + 1) * N);
      }, out);
    return put_items<std::int32_t, 1>(count, [&](std::int32_t* w, std::size_t i) {
      w[0] = static_cast<std::int32_t>((i + 1) * N);
    }, out);
  }
  // types: one byte per cell
  return put_items<std::uint8_t, 1>(count, [&](std::uint8_t* w, std::size_t) {
    w[0] = static_cast<std::uint8_t>(D == 2 ? 5 : 10);
  }, out);
}

// Array k as a vtkZLibDataCompressor array (vtu_compress_zlib): put_bytes(k,
// writer) writes its uncompressed bytes, which are gathered in memory first.
template <class PutBytes>
std::string compressed_array(std::size_t k, const PutBytes& put_bytes, const std::string& path) {
  struct Memory {
    char* data = nullptr;
    std::size_t size = 0;
    std::FILE* file = nullptr;
    ~Memory() {
      if (file) std::fclose(file);
      std::free(data);
    }
  } memory;
  memory.file = open_memstream(&memory.data, &memory.size);
  if (memory.file == nullptr) throw_write_error(path, errno);
  BufferedWriter to(memory.file, path);
  put_bytes(k, to);
  to.flush();
  if (std::fflush(memory.file) != 0) throw_write_error(path, errno);
  return vtu_compress_zlib(memory.data, memory.size);
}

template <class M>
void write_body(const M& mesh, BufferedWriter& out, const WriteOptions& options, const std::string& path) {
  using T = MeshTraits<M>;
  constexpr int D = T::dim;
  constexpr int N = T::cell_nodes;
  const auto& cells = T::cells(mesh);
  const auto& markers = T::cell_markers(mesh);
  const std::size_t nv = mesh.vertices.size(), nc = cells.size();
  const bool binary = options.binary;

  // Scalar i of each array, in the order they are written, as spec.scalar.
  auto put_value = [&](BufferedWriter& w, int array, const ArraySpec& spec, std::size_t i, bool raw) {
    auto emit_int = [&](std::int64_t v) {
      if (!raw) {
        w.put_int(v);
      } else if (spec.scalar == Scalar::Int32) {
        w.put_le(static_cast<std::int32_t>(v));
      } else if (spec.scalar == Scalar::Int64) {
        w.put_le(v);
      } else {
        w.put_le(static_cast<std::uint8_t>(v));
      }
    };
    auto emit_real = [&](double v) {
      if (spec.scalar == Scalar::Float32) {
        if (raw)
          w.put_le(single_precision(v));
        else
          w.put_float(single_precision(v));
      } else if (raw) {
        w.put_le(v);
      } else {
        w.put_double(v);
      }
    };
    const int num_fields = static_cast<int>(options.cell_fields.size());
    // Array numbering: 0 vertex_marker, 1 marker, 2..2+F-1 fields, then
    // points, connectivity, offsets, types.
    if (array == 0) return emit_int(mesh.vertex_markers[i]);
    if (array == 1) return emit_int(markers[i]);
    if (array < 2 + num_fields) return emit_real(options.cell_fields[array - 2].values[i]);
    const int rest = array - 2 - num_fields;
    if (rest == 0) return emit_real(coord(mesh.vertices[i / 3], static_cast<int>(i % 3)));
    if (rest == 1) return emit_int(cells[i / N][i % N]);
    if (rest == 2) return emit_int(static_cast<std::int64_t>((i + 1) * N));
    return emit_int(D == 2 ? 5 : 10);
  };

  // Connectivity and offsets: Int32 when the largest offset, N * nc, fits
  // (every connectivity entry is an int below nv, so it fits then too).
  const Scalar index_scalar =
      static_cast<std::uint64_t>(N) * nc <= static_cast<std::uint64_t>(INT32_MAX) ? Scalar::Int32 : Scalar::Int64;
  std::vector<std::pair<int, ArraySpec>> arrays;  // (array number, spec)
  if (!mesh.vertex_markers.empty()) arrays.push_back({0, {"vertex_marker", Scalar::Int32, 1, nv}});
  if (!markers.empty()) arrays.push_back({1, {"marker", Scalar::Int32, 1, nc}});
  for (std::size_t f = 0; f < options.cell_fields.size(); ++f) {
    const CellField& field = options.cell_fields[f];
    arrays.push_back(
        {2 + static_cast<int>(f), {field.name, field.single_precision ? Scalar::Float32 : Scalar::Float64, 1, nc}});
  }
  const int base = 2 + static_cast<int>(options.cell_fields.size());
  arrays.push_back({base, {"Points", Scalar::Float64, 3, 3 * nv}});
  arrays.push_back({base + 1, {"connectivity", index_scalar, 1, N * nc}});
  arrays.push_back({base + 2, {"offsets", index_scalar, 1, nc}});
  arrays.push_back({base + 3, {"types", Scalar::UInt8, 1, nc}});

  // The bytes of array k as stored uncompressed (without the size header).
  auto put_array_bytes = [&](std::size_t k, BufferedWriter& to) {
    const auto& [number, spec] = arrays[k];
    if constexpr (std::endian::native == std::endian::little) {
      put_raw_array(mesh, options, number, spec, to);
    } else {
      for (std::size_t i = 0; i < spec.count; ++i) put_value(to, number, spec, i, true);
    }
  };
  const bool compress = binary && options.compress;
  std::vector<std::string> packed(compress ? arrays.size() : 0);  // the compressed arrays
  for (std::size_t k = 0; k < packed.size(); ++k) packed[k] = compressed_array(k, put_array_bytes, path);
  // Offsets in reverse document order (header comment).
  std::vector<std::uint64_t> offsets(arrays.size());
  std::uint64_t offset = 0;
  for (std::size_t k = arrays.size(); k-- > 0;) {
    offsets[k] = offset;
    offset += compress ? packed[k].size() : 8 + arrays[k].second.count * scalar_size(arrays[k].second.scalar);
  }

  auto put_array = [&](std::size_t k) {
    const ArraySpec& spec = arrays[k].second;
    out.put("<DataArray type=\"").put(vtk_name(spec.scalar)).put("\" Name=\"").put(spec.name).put('"');
    if (spec.components != 1) out.put(" NumberOfComponents=\"").put_int(spec.components).put('"');
    if (binary) {
      out.put(" format=\"appended\" offset=\"").put_int(static_cast<std::int64_t>(offsets[k])).put("\"/>\n");
      return;
    }
    out.put(" format=\"ascii\">\n");
    for (std::size_t i = 0; i < spec.count; ++i) {
      put_value(out, arrays[k].first, spec, i, false);
      out.put((i + 1) % 12 == 0 || i + 1 == spec.count ? '\n' : ' ');
    }
    out.put("</DataArray>\n");
  };

  out.put("<?xml version=\"1.0\"?>\n");
  out.put("<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\"");
  out.put(compress ? " compressor=\"vtkZLibDataCompressor\">\n" : ">\n");
  out.put("<UnstructuredGrid>\n<Piece NumberOfPoints=\"").put_int(static_cast<std::int64_t>(nv));
  out.put("\" NumberOfCells=\"").put_int(static_cast<std::int64_t>(nc)).put("\">\n");
  std::size_t k = 0;
  if (!mesh.vertex_markers.empty()) {
    out.put("<PointData>\n");
    put_array(k++);
    out.put("</PointData>\n");
  }
  if (!markers.empty() || !options.cell_fields.empty()) {
    out.put("<CellData>\n");
    if (!markers.empty()) put_array(k++);
    for (std::size_t f = 0; f < options.cell_fields.size(); ++f) put_array(k++);
    out.put("</CellData>\n");
  }
  out.put("<Points>\n");
  put_array(k++);
  out.put("</Points>\n<Cells>\n");
  put_array(k++);
  put_array(k++);
  put_array(k++);
  out.put("</Cells>\n</Piece>\n</UnstructuredGrid>\n");
  if (binary) {
    out.put("<AppendedData encoding=\"raw\">\n_");
    for (std::size_t a = arrays.size(); a-- > 0;) {
      if (compress) {
        out.put(packed[a]);
        continue;
      }
      const ArraySpec& spec = arrays[a].second;
      out.put_le(static_cast<std::uint64_t>(spec.count * scalar_size(spec.scalar)));
      put_array_bytes(a, out);
    }
    out.put("\n</AppendedData>\n");
  }
  out.put("</VTKFile>\n");
}

// ---------------------------------------------------------------- reading

struct XmlArray {
  std::string section;  // PointData, CellData, Points, Cells
  std::string name, type, format;
  int components = 1;
  std::int64_t offset = -1;
  std::string_view content;
  int line = 0;
};

class VtuReader {
 public:
  VtuReader(const std::string& path, int dim) : path_(path), dim_(dim), text_(read_whole_file(path)) {}

  RawMesh run();

 private:
  [[noreturn]] void fail(ErrorCode code, const std::string& detail, int line) const {
    throw ParseError(code, detail, {}, path_, line);
  }
  int line_at(std::size_t pos) const {
    return 1 + static_cast<int>(std::count(text_.begin(), text_.begin() + static_cast<std::ptrdiff_t>(pos), '\n'));
  }
  void parse_xml(std::size_t end);
  std::vector<double> values(const XmlArray& a, std::size_t expected);
  std::vector<unsigned char> decode_base64(std::string_view text, std::size_t header_bytes, int line) const;
  std::vector<unsigned char> binary_payload(const XmlArray& a, std::size_t expected_bytes, std::size_t value_size);
  std::vector<unsigned char> compressed_payload(const XmlArray& a, std::size_t expected_bytes);

  std::string path_;
  int dim_;
  std::string text_;
  std::string header_type_ = "UInt32";
  VtuCompressor compressor_ = VtuCompressor::None;
  std::string appended_encoding_;
  std::size_t appended_start_ = 0;  // first byte after '_'
  std::int64_t num_points_ = -1, num_cells_ = -1;
  std::vector<XmlArray> arrays_;
};

// Attribute value of `name` in the tag text [begin, end), or "".
std::string_view attribute(std::string_view tag, std::string_view name) {
  std::size_t pos = 0;
  while ((pos = tag.find(name, pos)) != std::string_view::npos) {
    const bool starts = pos > 0 && std::isspace(static_cast<unsigned char>(tag[pos - 1]));
    std::size_t p = pos + name.size();
    while (p < tag.size() && std::isspace(static_cast<unsigned char>(tag[p]))) ++p;
    if (starts && p < tag.size() && tag[p] == '=') {
      ++p;
      while (p < tag.size() && std::isspace(static_cast<unsigned char>(tag[p]))) ++p;
      if (p < tag.size() && (tag[p] == '"' || tag[p] == '\'')) {
        const std::size_t close = tag.find(tag[p], p + 1);
        if (close != std::string_view::npos) return tag.substr(p + 1, close - p - 1);
      }
    }
    pos += name.size();
  }
  return {};
}

void VtuReader::parse_xml(std::size_t end) {
  std::string_view text(text_.data(), end);
  std::string section;
  std::size_t pos = 0;
  bool seen_root = false;
  while ((pos = text.find('<', pos)) != std::string_view::npos) {
    const std::size_t close = text.find('>', pos);
    if (close == std::string_view::npos) fail(ErrorCode::Truncated, "unterminated XML tag", line_at(pos));
    const std::string_view tag = text.substr(pos + 1, close - pos - 1);
    const int line = line_at(pos);
    std::size_t name_end = 0;
    while (name_end < tag.size() && !std::isspace(static_cast<unsigned char>(tag[name_end])) && tag[name_end] != '/')
      ++name_end;
    const std::string_view name = tag.substr(0, name_end);
    const bool self_closing = !tag.empty() && tag.back() == '/';
    pos = close + 1;
    if (name.empty() || name[0] == '?' || name[0] == '!') continue;
    if (name == "VTKFile") {
      seen_root = true;
      if (attribute(tag, "type") != "UnstructuredGrid")
        fail(ErrorCode::Unsupported, "VTK file type '" + std::string(attribute(tag, "type")) + "'", line);
      const std::string_view compressor = attribute(tag, "compressor");
      if (!vtu_compressor_from_name(compressor, compressor_))
        fail(ErrorCode::Unsupported, "VTU compressor '" + std::string(compressor) +
                                         "' (vtkZLibDataCompressor, vtkLZ4DataCompressor and vtkLZMADataCompressor are read)",
             line);
      const std::string_view order = attribute(tag, "byte_order");
      if (!order.empty() && order != "LittleEndian") fail(ErrorCode::Unsupported, "big-endian VTU data", line);
      if (!attribute(tag, "header_type").empty()) header_type_ = std::string(attribute(tag, "header_type"));
      if (header_type_ != "UInt32" && header_type_ != "UInt64")
        fail(ErrorCode::Unsupported, "header_type " + header_type_, line);
    } else if (name == "Piece") {
      if (num_points_ >= 0) fail(ErrorCode::Unsupported, "more than one Piece", line);
      auto number = [&](const char* attr) {
        const std::string_view v = attribute(tag, attr);
        std::int64_t n = -1;
        auto [p, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
        if (ec != std::errc() || p != v.data() + v.size() || n < 0 || n > INT32_MAX - 1)
          fail(ErrorCode::Syntax, std::string("bad ") + attr + " '" + std::string(v) + "'", line);
        return n;
      };
      num_points_ = number("NumberOfPoints");
      num_cells_ = number("NumberOfCells");
    } else if (name == "PointData" || name == "CellData" || name == "Points" || name == "Cells") {
      section = self_closing ? "" : std::string(name);
    } else if (name == "/PointData" || name == "/CellData" || name == "/Points" || name == "/Cells") {
      section.clear();
    } else if (name == "DataArray") {
      XmlArray a;
      a.section = section;
      a.name = std::string(attribute(tag, "Name"));
      a.type = std::string(attribute(tag, "type"));
      a.format = std::string(attribute(tag, "format"));
      a.line = line;
      const std::string_view comps = attribute(tag, "NumberOfComponents");
      if (!comps.empty()) {
        auto [p, ec] = std::from_chars(comps.data(), comps.data() + comps.size(), a.components);
        if (ec != std::errc() || a.components < 1 || a.components > 9)
          fail(ErrorCode::Syntax, "bad NumberOfComponents", line);
      }
      if (a.format == "appended") {
        const std::string_view off = attribute(tag, "offset");
        auto [p, ec] = std::from_chars(off.data(), off.data() + off.size(), a.offset);
        if (ec != std::errc() || a.offset < 0) fail(ErrorCode::Syntax, "bad appended offset", line);
      } else if (!self_closing) {
        const std::size_t end_tag = text.find("</DataArray>", pos);
        if (end_tag == std::string_view::npos) fail(ErrorCode::Truncated, "DataArray is not closed", line);
        // The data ends at the first '<': VTK puts <InformationKey> elements
        // after the numbers, inside the DataArray.
        a.content = text.substr(pos, std::min(text.find('<', pos), end_tag) - pos);
        pos = end_tag + 12;
      }
      if (!a.section.empty()) arrays_.push_back(std::move(a));
    }
  }
  if (!seen_root) fail(ErrorCode::Syntax, "not a VTK XML file (no <VTKFile>)", 1);
  if (num_points_ < 0) fail(ErrorCode::Truncated, "no <Piece>", line_at(end));
}

// Decodes base64 in independent 4-character groups, so that streams made of
// separately encoded (padded) blocks decode as well as a single block.
std::vector<unsigned char> VtuReader::decode_base64(std::string_view text, std::size_t max_bytes, int line) const {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    if (c == '=') return -2;
    return -1;
  };
  std::vector<unsigned char> bytes;
  int group[4];
  int n = 0;
  for (char c : text) {
    if (bytes.size() >= max_bytes) break;
    const int v = value(c);
    if (v == -1) {
      if (std::isspace(static_cast<unsigned char>(c))) continue;
      fail(ErrorCode::Syntax, "invalid base64 character", line);
    }
    group[n++] = v;
    if (n < 4) continue;
    n = 0;
    if (group[0] < 0 || group[1] < 0) fail(ErrorCode::Syntax, "invalid base64 padding", line);
    bytes.push_back(static_cast<unsigned char>((group[0] << 2) | (group[1] >> 4)));
    if (group[2] >= 0) bytes.push_back(static_cast<unsigned char>(((group[1] & 15) << 4) | (group[2] >> 2)));
    if (group[2] >= 0 && group[3] >= 0) bytes.push_back(static_cast<unsigned char>(((group[2] & 3) << 6) | group[3]));
  }
  return bytes;
}

// The data bytes of a binary (inline base64) or appended (raw or base64)
// DataArray, without the size header; compressed arrays decompressed. The
// byte count must be a multiple of value_size; whether it matches
// expected_bytes is checked by the caller (except for compressed arrays,
// whose header must announce exactly expected_bytes).
std::vector<unsigned char> VtuReader::binary_payload(const XmlArray& a, std::size_t expected_bytes,
                                                     std::size_t value_size) {
  if (a.format != "binary" && a.format != "appended")
    fail(ErrorCode::Unsupported, "DataArray format '" + a.format + "'", a.line);
  if (a.format == "appended" && appended_encoding_.empty())
    fail(ErrorCode::Syntax, "appended DataArray without <AppendedData>", a.line);
  if (compressor_ != VtuCompressor::None) return compressed_payload(a, expected_bytes);
  const std::size_t header = header_type_ == "UInt64" ? 8 : 4;
  std::vector<unsigned char> bytes;
  if (a.format == "binary") {
    bytes = decode_base64(a.content, SIZE_MAX, a.line);
  } else {
    const std::size_t start = appended_start_ + static_cast<std::size_t>(a.offset);
    if (start > text_.size()) fail(ErrorCode::Truncated, "appended offset beyond the end of the file", a.line);
    if (appended_encoding_ == "raw") {
      if (start + header > text_.size()) fail(ErrorCode::Truncated, "appended data ends early", a.line);
      std::uint64_t size = 0;
      for (std::size_t k = 0; k < header; ++k)
        size |= static_cast<std::uint64_t>(static_cast<unsigned char>(text_[start + k])) << (8 * k);
      if (size > text_.size() - start - header) fail(ErrorCode::Truncated, "appended data ends early", a.line);
      bytes.assign(text_.begin() + static_cast<std::ptrdiff_t>(start),
                   text_.begin() + static_cast<std::ptrdiff_t>(start + header + size));
    } else {
      bytes = decode_base64(std::string_view(text_).substr(start), header + expected_bytes, a.line);
    }
  }
  if (bytes.size() < header) fail(ErrorCode::Truncated, "binary DataArray without header", a.line);
  std::uint64_t size = 0;
  for (std::size_t k = 0; k < header; ++k) size |= static_cast<std::uint64_t>(bytes[k]) << (8 * k);
  if (size % value_size != 0 || size > bytes.size() - header)
    fail(ErrorCode::WrongCount, "binary DataArray '" + a.name + "' has a bad byte count", a.line);
  bytes.erase(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(header));
  bytes.resize(static_cast<std::size_t>(size));
  return bytes;
}

// A compressed array (vtu_compression.hpp): inline base64, appended raw or
// appended base64. Only the bytes the header accounts for are decoded.
std::vector<unsigned char> VtuReader::compressed_payload(const XmlArray& a, std::size_t expected_bytes) {
  const std::size_t header = header_type_ == "UInt64" ? 8 : 4;
  const VtuArraySite site{path_, a.line, a.name};
  if (a.format == "appended" && appended_encoding_ == "raw") {
    const std::size_t start = appended_start_ + static_cast<std::size_t>(a.offset);
    if (start > text_.size()) fail(ErrorCode::Truncated, "appended offset beyond the end of the file", a.line);
    const std::span<const unsigned char> rest(reinterpret_cast<const unsigned char*>(text_.data()) + start,
                                              text_.size() - start);
    const std::size_t n = vtu_compressed_array_bytes(rest, header, rest.size(), site);
    return vtu_decompress(rest.first(n), header, compressor_, expected_bytes, site);
  }
  std::string_view text = a.content;
  if (a.format == "appended") {
    const std::size_t start = appended_start_ + static_cast<std::size_t>(a.offset);
    if (start > text_.size()) fail(ErrorCode::Truncated, "appended offset beyond the end of the file", a.line);
    text = std::string_view(text_).substr(start);
  }
  // base64: 3 bytes per 4 characters bound what the text can hold.
  const std::size_t available = text.size() / 4 * 3 + 3;
  std::vector<unsigned char> bytes = decode_base64(text, header, a.line);
  const std::size_t head = vtu_compressed_header_bytes(bytes, header, available, site);
  bytes = decode_base64(text, head, a.line);
  const std::size_t n = vtu_compressed_array_bytes(bytes, header, available, site);
  bytes = decode_base64(text, n, a.line);
  if (bytes.size() < n) fail(ErrorCode::Truncated, "compressed DataArray '" + a.name + "' ends early", a.line);
  return vtu_decompress(std::span<const unsigned char>(bytes).first(n), header, compressor_, expected_bytes, site);
}

std::vector<double> VtuReader::values(const XmlArray& a, std::size_t expected) {
  struct TypeInfo {
    const char* name;
    std::size_t size;
    bool is_float, is_signed;
  };
  static const TypeInfo kTypes[] = {{"Int8", 1, false, true},    {"UInt8", 1, false, false},  {"Int16", 2, false, true},
                                    {"UInt16", 2, false, false}, {"Int32", 4, false, true},   {"UInt32", 4, false, false},
                                    {"Int64", 8, false, true},   {"UInt64", 8, false, false}, {"Float32", 4, true, true},
                                    {"Float64", 8, true, true}};
  const TypeInfo* type = nullptr;
  for (const TypeInfo& t : kTypes)
    if (a.type == t.name) type = &t;
  if (type == nullptr) fail(ErrorCode::Unsupported, "DataArray type '" + a.type + "'", a.line);
  std::vector<double> out;
  // expected comes from NumberOfPoints/NumberOfCells; every value takes at
  // least one byte of the file, so reserve no more than the file can hold (an
  // absurd count then fails the size check below instead of allocating).
  out.reserve(std::min(expected, text_.size() + 1));
  if (a.format == "ascii") {
    const char* p = a.content.data();
    const char* end = p + a.content.size();
    while (true) {
      while (p < end && std::isspace(static_cast<unsigned char>(*p))) ++p;
      if (p >= end) break;
      double v = 0;
      auto [q, ec] = std::from_chars(p, end, v);
      if (ec != std::errc() || (q < end && !std::isspace(static_cast<unsigned char>(*q))))
        fail(ErrorCode::Syntax, "bad number in DataArray '" + a.name + "'", a.line);
      if (!std::isfinite(v)) fail(ErrorCode::NonFinite, "non-finite value in DataArray '" + a.name + "'", a.line);
      out.push_back(v);
      p = q;
    }
  } else {
    const std::vector<unsigned char> bytes = binary_payload(a, expected * type->size, type->size);
    const std::size_t n = bytes.size() / type->size;
    for (std::size_t i = 0; i < n; ++i) {
      const unsigned char* b = bytes.data() + i * type->size;
      std::uint64_t bits = 0;
      for (std::size_t k = 0; k < type->size; ++k) bits |= static_cast<std::uint64_t>(b[k]) << (8 * k);
      double v = 0;
      if (type->is_float && type->size == 8) {
        std::memcpy(&v, &bits, 8);
      } else if (type->is_float) {
        const std::uint32_t bits32 = static_cast<std::uint32_t>(bits);
        float f = 0;
        std::memcpy(&f, &bits32, 4);
        v = f;
      } else if (type->is_signed) {
        const unsigned shift = static_cast<unsigned>(64 - 8 * type->size);
        v = static_cast<double>(static_cast<std::int64_t>(bits << shift) >> shift);
      } else {
        v = static_cast<double>(bits);
      }
      if (!std::isfinite(v)) fail(ErrorCode::NonFinite, "non-finite value in DataArray '" + a.name + "'", a.line);
      out.push_back(v);
    }
  }
  if (out.size() != expected)
    fail(ErrorCode::WrongCount,
         "DataArray '" + a.name + "' has " + std::to_string(out.size()) + " values, expected " +
             std::to_string(expected),
         a.line);
  return out;
}

int to_int(double v, const std::string& what, const std::string& path, int line) {
  if (v != std::floor(v) || v < INT32_MIN || v > INT32_MAX)
    throw ParseError(ErrorCode::Syntax, what + " value is not a 32-bit integer", {}, path, line);
  return static_cast<int>(v);
}

RawMesh VtuReader::run() {
  const std::size_t appended = text_.find("<AppendedData");
  const std::size_t xml_end = appended == std::string::npos ? text_.size() : appended;
  if (appended != std::string::npos) {
    const std::size_t close = text_.find('>', appended);
    if (close == std::string::npos) fail(ErrorCode::Truncated, "unterminated <AppendedData>", line_at(appended));
    const std::string_view tag(text_.data() + appended + 1, close - appended - 1);
    appended_encoding_ = std::string(attribute(tag, "encoding"));
    if (appended_encoding_ != "raw" && appended_encoding_ != "base64")
      fail(ErrorCode::Unsupported, "AppendedData encoding '" + appended_encoding_ + "'", line_at(appended));
    const std::size_t underscore = text_.find('_', close);
    if (underscore == std::string::npos) fail(ErrorCode::Truncated, "AppendedData without '_'", line_at(close));
    appended_start_ = underscore + 1;
  }
  parse_xml(xml_end);
  const auto np = static_cast<std::size_t>(num_points_);
  const auto nc = static_cast<std::size_t>(num_cells_);
  const XmlArray *points = nullptr, *conn = nullptr, *offs = nullptr, *types = nullptr, *marker = nullptr,
                 *vmarker = nullptr;
  for (const XmlArray& a : arrays_) {
    if (a.section == "Points" && !points) points = &a;
    if (a.section == "Cells" && a.name == "connectivity") conn = &a;
    if (a.section == "Cells" && a.name == "offsets") offs = &a;
    if (a.section == "Cells" && a.name == "types") types = &a;
    if (a.section == "CellData" && a.name == "marker") marker = &a;
    if (a.section == "PointData" && a.name == "vertex_marker") vmarker = &a;
  }
  if (!points || !conn || !offs || !types)
    fail(ErrorCode::Truncated, "missing Points or Cells connectivity/offsets/types", line_at(xml_end));
  if (points->components != 3) fail(ErrorCode::Unsupported, "Points must have 3 components", points->line);
  RawMesh raw;
  raw.xyz = values(*points, 3 * np);
  const std::vector<double> offsets = values(*offs, nc);
  const std::vector<double> type_values = values(*types, nc);
  const std::size_t total = nc == 0 ? 0 : static_cast<std::size_t>(std::max(0.0, offsets.back()));
  const std::vector<double> connectivity = values(*conn, total);
  std::vector<double> markers;
  if (marker) markers = values(*marker, nc);
  if (vmarker) {
    for (double v : values(*vmarker, np)) raw.vertex_markers.push_back(to_int(v, "vertex_marker", path_, vmarker->line));
  }
  const int cell_type = dim_ == 2 ? 5 : 10, face_type = dim_ == 2 ? 3 : 5, ignored_type = dim_ == 2 ? 1 : 3;
  double previous = 0;
  for (std::size_t c = 0; c < nc; ++c) {
    const int type = static_cast<int>(type_values[c]);
    const double end = offsets[c];
    const double count = end - previous;
    const int expected = type == cell_type ? dim_ + 1 : type == face_type ? dim_ : -1;
    if (type != cell_type && type != face_type && type != ignored_type && type != 1)
      fail(ErrorCode::Unsupported, "cell " + std::to_string(c) + " has VTK type " + std::to_string(type), types->line);
    if (end < previous || end > static_cast<double>(total) || (expected > 0 && count != expected))
      fail(ErrorCode::WrongCount, "cell " + std::to_string(c) + " has a bad offset", offs->line);
    for (auto k = static_cast<std::size_t>(previous); k < static_cast<std::size_t>(end); ++k) {
      const double v = connectivity[k];
      if (v < 0 || v >= static_cast<double>(np) || v != std::floor(v))
        fail(ErrorCode::IndexOutOfRange, "cell " + std::to_string(c) + " refers to point " + std::to_string(v),
             conn->line);
      if (expected > 0) (type == cell_type ? raw.cells : raw.faces).push_back(static_cast<int>(v));
    }
    if (expected > 0) {
      const int m = marker ? to_int(markers[c], "marker", path_, marker->line) : 0;
      (type == cell_type ? raw.cell_markers : raw.face_markers).push_back(m);
    }
    previous = end;
  }
  return raw;
}

}  // namespace

template <class M>
void write_vtu(const M& mesh, const std::string& path, const WriteOptions& options) {
  AtomicFile file(path);
  BufferedWriter out(file.file(), path);
  write_body(mesh, out, options, path);
  out.flush();
  file.commit();
}

template void write_vtu(const TriMesh2&, const std::string&, const WriteOptions&);
template void write_vtu(const TetMesh3&, const std::string&, const WriteOptions&);

RawMesh read_vtu(const std::string& path, int dim) { return VtuReader(path, dim).run(); }

}  // namespace pqmesh::detail
