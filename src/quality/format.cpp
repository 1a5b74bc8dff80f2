// Locale-independent number formatting; see format.hpp.
#include "quality/format.hpp"

#include <charconv>
#include <cmath>

namespace pqmesh::detail {
namespace {

std::string format(double value, std::chars_format style, int precision) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[512];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, style, precision);
  if (result.ec != std::errc()) return "?";  // cannot happen with 512 bytes for finite doubles
  return std::string(buffer, result.ptr);
}

}  // namespace

std::string format_general(double value, int precision) {
  return format(value, std::chars_format::general, precision);
}

std::string format_fixed(double value, int precision) { return format(value, std::chars_format::fixed, precision); }

std::string pad(const std::string& text, int width) {
  const bool left = width < 0;
  const auto w = static_cast<std::size_t>(left ? -width : width);
  if (text.size() >= w) return text;
  const std::string fill(w - text.size(), ' ');
  return left ? text + fill : fill + text;
}

}  // namespace pqmesh::detail
