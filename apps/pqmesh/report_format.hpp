#pragma once
// Number formatting for the CLI's human-readable summaries.
#include <cstdio>
#include <numbers>
#include <string>

#include "pqmesh/vec.hpp"

namespace pqmesh::cli {

// Up to 10 significant digits, no trailing noise ("1", "0.125", "3.14159265").
inline std::string fmt(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", v);
  return buffer;
}

inline std::string fmt(Vec2 p) { return "(" + fmt(p.x) + ", " + fmt(p.y) + ")"; }
inline std::string fmt(Vec3 p) { return "(" + fmt(p.x) + ", " + fmt(p.y) + ", " + fmt(p.z) + ")"; }

inline std::string fmt_degrees(double radians) { return fmt(radians * 180.0 / std::numbers::pi); }

}  // namespace pqmesh::cli
