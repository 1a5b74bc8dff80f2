// QualityReport::to_text(): a compact, deterministic human-readable report.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "pqmesh/quality.hpp"
#include "quality/format.hpp"

namespace pqmesh {
namespace {

using detail::format_general;
using detail::pad;

constexpr int kBarWidth = 40;

void append_stat_row(std::string& out, const char* name, const Stat& s) {
  out += pad(name, -20);
  out += pad(format_general(s.min, 6), 13);
  out += pad(format_general(s.mean, 6), 13);
  out += pad(format_general(s.max, 6), 13);
  out += pad(std::to_string(s.argmin), 10);
  out += pad(std::to_string(s.argmax), 10);
  out += '\n';
}

// The histogram as ASCII bars, one line per bin, leading and trailing empty
// bins trimmed (an all-empty histogram prints just its title line).
void append_histogram(std::string& out, const Histogram& h) {
  out += h.measure;
  out += ":\n";
  std::size_t first = 0, last = h.counts.size();
  while (first < last && h.counts[first] == 0) ++first;
  while (last > first && h.counts[last - 1] == 0) --last;
  if (first == last) {
    out += "  (no elements)\n";
    return;
  }
  const std::int64_t peak = *std::max_element(h.counts.begin(), h.counts.end());
  for (std::size_t i = first; i < last; ++i) {
    const bool closed = i + 1 == h.counts.size() && !std::isinf(h.edges[i + 1]);
    out += "  [";
    out += pad(format_general(h.edges[i], 4), 6);
    out += ", ";
    out += pad(format_general(h.edges[i + 1], 4), 6);
    out += closed ? "] " : ") ";
    out += pad(std::to_string(h.counts[i]), 10);
    out += ' ';
    // Bar length proportional to the count; any nonzero count shows at least one '#'.
    std::int64_t bar = (h.counts[i] * kBarWidth + peak / 2) / peak;
    if (h.counts[i] > 0 && bar == 0) bar = 1;
    out += std::string(static_cast<std::size_t>(bar), '#');
    out += '\n';
  }
}

}  // namespace

std::string QualityReport::to_text() const {
  const bool tri = dimension == 2;
  std::string out;
  out += "quality of " + std::to_string(elements) + (tri ? " triangles" : " tetrahedra");
  out += " (degenerate " + std::to_string(degenerate) + ", inverted " + std::to_string(inverted) + ")\n";
  out += std::string(tri ? "total area " : "total volume ") + format_general(total_size, 10) + "\n\n";
  out += pad("measure", -20) + pad("min", 13) + pad("mean", 13) + pad("max", 13) + pad("argmin", 10) +
         pad("argmax", 10) + "\n";
  append_stat_row(out, tri ? "min angle (deg)" : "min dihedral (deg)", min_angle);
  append_stat_row(out, tri ? "max angle (deg)" : "max dihedral (deg)", max_angle);
  append_stat_row(out, "aspect ratio", aspect_ratio);
  append_stat_row(out, "sphere ratio", sphere_ratio);
  append_stat_row(out, "radius-edge ratio", radius_edge);
  append_stat_row(out, tri ? "area" : "volume", size);
  out += '\n';
  append_histogram(out, min_angle_hist);
  out += '\n';
  append_histogram(out, max_angle_hist);
  out += '\n';
  append_histogram(out, aspect_hist);
  return out;
}

}  // namespace pqmesh
