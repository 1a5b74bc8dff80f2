// read_size_field2 / read_size_field3: the point-size files of
// `pqmesh mesh --size-field` (and `pqmesh octree --size-field`).
//
// Format (one point per line):   x y size   (2D)   or   x y z size   (3D)
//   '#' starts a comment that runs to the end of the line; blank lines and
//   comment-only lines are ignored. Numbers are whatever parse_double accepts
//   (decimal or exponent form, optional sign).
// Errors (ParseError with the file path and the 1-based line):
//   a line with other than D + 1 fields   WrongCount
//   a field that is not a number          Syntax
//   a NaN or infinite value (also an      NonFinite
//     overflowing literal such as 1e999)
//   size <= 0 (also -0 and an underflow   Syntax (the format requires a
//     that rounds to 0)                     positive size)
//   a file with no point at all           WrongCount (on the last line): an
//                                          empty field would silently mean "no
//                                          size field", which is not what the
//                                          user asked for.
// The reader only checks the file; what the sizes mean (f(x) = min_i size_i +
// |x - p_i|, thesis §1.1's size function) is the mesher's business.
#include <cmath>
#include <string>

#include "io/read_text_tokens.hpp"
#include "pqmesh/quadmesh.hpp"
#include "pqmesh/tetmesh.hpp"

namespace pqmesh {
namespace {

// Reads D coordinates and a size per line into `field` (points, sizes, lines, path).
template <int D, class Field>
Field read_point_sizes(const std::string& path) {
  static constexpr const char* kNames[4] = {"x", "y", D == 2 ? "size" : "z", "size"};
  static constexpr const char* kFormat = D == 2 ? "'x y size'" : "'x y z size'";
  detail::TextSource src(path);
  Field field;
  field.path = path;
  detail::TextRecord record;
  while (src.next_record(record)) {
    if (record.tokens.size() != D + 1) {
      src.fail(ErrorCode::WrongCount, "expected " + std::to_string(D + 1) + " fields " + kFormat + ", found " +
                                          std::to_string(record.tokens.size()), record.line);
    }
    double values[D + 1] = {};
    for (int i = 0; i <= D; ++i) {
      const std::string_view token = record.tokens[static_cast<std::size_t>(i)];
      if (!detail::parse_double(token, values[i])) {
        src.fail(ErrorCode::Syntax, std::string(kNames[i]) + " is not a number: '" + std::string(token) + "'",
                 record.line);
      }
      if (!std::isfinite(values[i])) {
        src.fail(ErrorCode::NonFinite, std::string(kNames[i]) + " is not finite: '" + std::string(token) + "'",
                 record.line);
      }
    }
    if (!(values[D] > 0)) {
      src.fail(ErrorCode::Syntax, "size must be positive, found '" + std::string(record.tokens[D]) + "'",
               record.line);
    }
    if constexpr (D == 2) field.points.push_back({values[0], values[1]});
    if constexpr (D == 3) field.points.push_back({values[0], values[1], values[2]});
    field.sizes.push_back(values[D]);
    field.lines.push_back(record.line);
  }
  if (field.points.empty()) src.fail(ErrorCode::WrongCount, "the size field lists no points", src.last_line());
  return field;
}

}  // namespace

SizeField2 read_size_field2(const std::string& path) { return read_point_sizes<2, SizeField2>(path); }

TetSizeField read_size_field3(const std::string& path) { return read_point_sizes<3, TetSizeField>(path); }

}  // namespace pqmesh
