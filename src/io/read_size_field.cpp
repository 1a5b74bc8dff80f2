// read_size_field2: the point-size file of `pqmesh mesh --size-field`.
//
// Format (one point per line):   x y size
//   '#' starts a comment that runs to the end of the line; blank lines and
//   comment-only lines are ignored. Numbers are whatever parse_double accepts
//   (decimal or exponent form, optional sign).
// Errors (ParseError with the file path and the 1-based line):
//   a line with other than three fields   WrongCount
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
// |x - p_i|, thesis §1.1's size function) is quad_mesh's business.
#include <cmath>
#include <string>

#include "io/read_text_tokens.hpp"
#include "pqmesh/quadmesh.hpp"

namespace pqmesh {

SizeField2 read_size_field2(const std::string& path) {
  detail::TextSource src(path);
  SizeField2 field;
  field.path = path;
  static constexpr const char* kNames[3] = {"x", "y", "size"};
  detail::TextRecord record;
  while (src.next_record(record)) {
    if (record.tokens.size() != 3) {
      src.fail(ErrorCode::WrongCount,
               "expected 3 fields 'x y size', found " + std::to_string(record.tokens.size()), record.line);
    }
    double values[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i) {
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
    if (!(values[2] > 0)) {
      src.fail(ErrorCode::Syntax, "size must be positive, found '" + std::string(record.tokens[2]) + "'",
               record.line);
    }
    field.points.push_back({values[0], values[1]});
    field.sizes.push_back(values[2]);
    field.lines.push_back(record.line);
  }
  if (field.points.empty()) src.fail(ErrorCode::WrongCount, "the size field lists no points", src.last_line());
  return field;
}

}  // namespace pqmesh
