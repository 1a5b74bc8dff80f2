#pragma once
// Number formatting for the CLI's human-readable summaries.
#include <chrono>
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

// Four significant digits, for angles, ratios and size estimates in summaries.
inline std::string fmt4(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", v);
  return buffer;
}
inline std::string fmt4_degrees(double radians) { return fmt4(radians * 180.0 / std::numbers::pi); }

// Seconds with millisecond digits.
inline std::string fmt_seconds(double s) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f", s);
  return buffer;
}

using Clock = std::chrono::steady_clock;
inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace pqmesh::cli
