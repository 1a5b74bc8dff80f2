#include "mesh/check_common.hpp"

#include <cmath>
#include <cstdio>

namespace pqmesh::detail {

void IssueSink::add(CheckKind kind, std::vector<std::int64_t> ids, std::string message) {
  const int k = static_cast<int>(kind);
  ++report_.count_per_kind[k];
  if (stored_[k] >= cap_) return;
  ++stored_[k];
  report_.issues.push_back(CheckIssue{kind, std::move(ids), std::move(message)});
}

Adjacency make_adjacency(int n, const std::vector<std::array<int, 2>>& edges) {
  Adjacency adj;
  adj.offset.assign(static_cast<std::size_t>(n) + 1, 0);
  for (const auto& e : edges) {
    ++adj.offset[e[0] + 1];
    ++adj.offset[e[1] + 1];
  }
  for (int v = 0; v < n; ++v) adj.offset[v + 1] += adj.offset[v];
  adj.items.resize(adj.offset[n]);
  std::vector<int> fill(adj.offset.begin(), adj.offset.end() - 1);
  for (const auto& e : edges) {
    adj.items[fill[e[0]]++] = e[1];
    adj.items[fill[e[1]]++] = e[0];
  }
  // Sort and deduplicate each list, compacting in place.
  int write = 0;
  for (int v = 0; v < n; ++v) {
    const int begin = adj.offset[v], end = adj.offset[v + 1];
    std::sort(adj.items.begin() + begin, adj.items.begin() + end);
    adj.offset[v] = write;
    for (int i = begin; i < end; ++i) {
      if (i > begin && adj.items[i] == adj.items[i - 1]) continue;
      adj.items[write++] = adj.items[i];
    }
  }
  adj.offset[n] = write;
  adj.items.resize(write);
  return adj;
}

std::string format_number(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// (Built with append: GCC 12 warns falsely (-Wrestrict) on chains of
// operator+ that start with a string literal.)
std::string format_short(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

std::string format_point(Vec2 p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g)", p.x, p.y);
  return buf;
}

std::string format_point(Vec3 p) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g, %.17g)", p.x, p.y, p.z);
  return buf;
}

std::string format_ids(std::span<const int> ids) {
  std::string out;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (i) out += ' ';
    out += std::to_string(ids[i]);
  }
  return out;
}

double relative_difference(double a, double b) {
  const double scale = std::max(std::abs(a), std::abs(b));
  if (scale == 0) return 0;
  return std::abs(a - b) / scale;
}

void check_marker_count(IssueSink& sink, std::size_t markers, std::size_t items, const char* what) {
  if (markers != 0 && markers != items)
    sink.add(CheckKind::BadIndex, {},
             std::string(what) + " has " + std::to_string(markers) + " entries for " + std::to_string(items) +
                 " items (must be empty or equal)");
}

void compare_volume(IssueSink& sink, const char* quantity, double mesh_volume, double domain_volume,
                    double tolerance) {
  const double diff = relative_difference(mesh_volume, domain_volume);
  if (!(diff > tolerance)) return;  // (a NaN difference is not reported, as before)
  sink.add(CheckKind::Volume, {},
           "total " + std::string(quantity) + " " + format_number(mesh_volume) + " differs from the domain's " +
               format_number(domain_volume) + " (relative difference " + format_short(diff) + " > tolerance " +
               format_short(tolerance) + "; a floating-point measurement)");
}

}  // namespace pqmesh::detail
