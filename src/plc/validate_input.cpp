// Stages 1 and 2 of 3D validation: basic sanity and duplicate vertices.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "plc/report_error.hpp"
#include "plc/validate3.hpp"

namespace pqmesh::detail {

void check_basic(const Plc3& plc) {
  const SourceInfo& src = plc.source;
  if (plc.facets.empty()) throw_domain_error(src, ErrorCode::EmptyDomain, "the domain has no facets", {}, IdKind::None);
  std::vector<int> bad;
  for (int v = 0; v < int(plc.vertices.size()); ++v) {
    const Vec3 p = plc.vertices[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) bad.push_back(v);
  }
  if (!bad.empty())
    throw_domain_error(src, ErrorCode::NonFinite, "vertices " + id_list(src, bad) + " have non-finite coordinates",
                       bad, IdKind::Vertex);
  const int nv = static_cast<int>(plc.vertices.size());
  for (int f = 0; f < int(plc.facets.size()); ++f)
    for (const auto& loop : plc.facets[f].loops)
      for (int v : loop)
        if (v < 0 || v >= nv) {
          if (bad.empty() || bad.back() != f) bad.push_back(f);
        }
  if (!bad.empty())
    throw_domain_error(src, ErrorCode::IndexOutOfRange,
                       "facets " + id_list(src, bad) + " refer to vertex ids that do not exist", bad,
                       IdKind::Element);
}

void check_duplicate_vertices(const Plc3& plc) {
  std::vector<char> used(plc.vertices.size(), 0);
  for (const auto& f : plc.facets)
    for (const auto& loop : f.loops)
      for (int v : loop) used[v] = 1;
  std::vector<int> order;
  for (int v = 0; v < int(used.size()); ++v)
    if (used[v]) order.push_back(v);
  auto key = [&](int v) {
    const Vec3 p = plc.vertices[v];
    return std::array<double, 3>{p.x, p.y, p.z};
  };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return key(a) < key(b) || (key(a) == key(b) && a < b); });
  std::vector<int> bad;
  std::ostringstream groups;  // "3 = 7; 5 = 9 = 11"
  int group_count = 0;
  for (std::size_t k = 0; k + 1 < order.size(); ++k) {
    if (key(order[k]) != key(order[k + 1])) continue;
    const bool starts = bad.empty() || bad.back() != order[k];
    if (starts) {
      bad.push_back(order[k]);
      if (group_count++ > 0) groups << "; ";
      groups << file_id(plc.source, order[k]);
    }
    bad.push_back(order[k + 1]);
    groups << " = " << file_id(plc.source, order[k + 1]);
  }
  if (bad.empty()) return;
  throw_domain_error(plc.source, ErrorCode::DuplicateVertex,
                     "vertices with exactly equal coordinates: " + groups.str(), bad, IdKind::Vertex);
}

}  // namespace pqmesh::detail
