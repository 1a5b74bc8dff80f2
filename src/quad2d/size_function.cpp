#include "quad2d/size_function.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "pqmesh/errors.hpp"

namespace pqmesh::quad2d {

namespace {
[[noreturn]] void bad_entry(const SizeField2& f, std::size_t i, ErrorCode code, const std::string& what) {
  const int line = i < f.lines.size() ? f.lines[i] : 0;
  std::string where = f.path.empty() ? "size field" : f.path;
  if (line > 0) where += ":" + std::to_string(line);
  throw InvalidInput(code, where + ": size field entry " + std::to_string(i) + " " + what,
                     {static_cast<std::int64_t>(i)}, f.path, line);
}
}  // namespace

SizeFunction2::SizeFunction2(const QuadMeshOptions& options) : max_size_(options.max_size), field_(options.size_field) {
  if (!std::isfinite(max_size_) || max_size_ < 0)
    throw InvalidInput(ErrorCode::Syntax, "max size must be a positive finite number (0: none)", {});
  if (field_.sizes.size() != field_.points.size())
    throw InvalidInput(ErrorCode::Syntax, "size field: " + std::to_string(field_.points.size()) + " points but " +
                                                 std::to_string(field_.sizes.size()) + " sizes",
                       {});
  for (std::size_t i = 0; i < field_.points.size(); ++i) {
    if (!std::isfinite(field_.points[i].x) || !std::isfinite(field_.points[i].y))
      bad_entry(field_, i, ErrorCode::NonFinite, "has a non-finite point");
    if (!std::isfinite(field_.sizes[i]) || !(field_.sizes[i] > 0))
      bad_entry(field_, i, ErrorCode::Syntax, "has a size that is not a positive finite number");
  }
}

double SizeFunction2::min_over(const Square& square) const {
  double best = max_size_ > 0 ? max_size_ : std::numeric_limits<double>::infinity();
  const double x0 = square.lo.x, y0 = square.lo.y, x1 = x0 + square.side, y1 = y0 + square.side;
  for (std::size_t i = 0; i < field_.points.size(); ++i) {
    const Vec2 p = field_.points[i];
    const double dx = std::max({x0 - p.x, 0.0, p.x - x1}), dy = std::max({y0 - p.y, 0.0, p.y - y1});
    best = std::min(best, field_.sizes[i] + std::hypot(dx, dy));
  }
  return best;
}

}  // namespace pqmesh::quad2d
