#pragma once
// Locale-independent number formatting (std::to_chars) for the text and SVG
// reports, so that output is byte-identical whatever the process locale.
#include <string>

namespace pqmesh::detail {

// Shortest-style "general" formatting with `precision` significant digits
// (like %.*g), or `fixed` with `precision` decimals (like %.*f). Infinities
// print as "inf" / "-inf", NaN as "nan".
std::string format_general(double value, int precision);
std::string format_fixed(double value, int precision);

// `text` right-aligned (left-aligned when width < 0) in |width| columns.
std::string pad(const std::string& text, int width);

}  // namespace pqmesh::detail
