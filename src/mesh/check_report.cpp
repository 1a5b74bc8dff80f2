// CheckReport: names, verdict and the readable text form.
#include <string>

#include "mesh/check_common.hpp"
#include "pqmesh/check.hpp"

namespace pqmesh {

const char* to_string(CheckKind kind) {
  switch (kind) {
    case CheckKind::BadIndex: return "bad-index";
    case CheckKind::DegenerateElement: return "degenerate-element";
    case CheckKind::Orientation: return "orientation";
    case CheckKind::NonConforming: return "non-conforming";
    case CheckKind::UnusedVertex: return "unused-vertex";
    case CheckKind::BoundaryFace: return "boundary-face";
    case CheckKind::Volume: return "volume";
    case CheckKind::MissingVertex: return "missing-vertex";
    case CheckKind::MissingEdge: return "missing-edge";
    case CheckKind::MissingFacet: return "missing-facet";
    case CheckKind::VertexOutside: return "vertex-outside";
    case CheckKind::SteinerOnBoundary: return "steiner-on-boundary";
  }
  return "unknown";
}

bool CheckReport::valid() const {
  for (std::int64_t c : count_per_kind)
    if (c != 0) return false;
  return true;
}

std::vector<CheckKind> CheckReport::kinds() const {
  std::vector<CheckKind> out;
  for (int k = 0; k < kCheckKindCount; ++k)
    if (count_per_kind[k] != 0) out.push_back(static_cast<CheckKind>(k));
  return out;
}

std::string CheckReport::to_text() const {
  const bool three = dimension == 3;
  std::string out = valid() ? "valid: " : "invalid: ";
  out += std::to_string(elements) + (three ? " tetrahedra, " : " triangles, ");
  out += std::to_string(vertices) + " vertices, ";
  out += std::to_string(boundary_faces) + (three ? " boundary triangles" : " boundary edges");
  if (volume_measured) {
    out += three ? "; volume " : "; area ";
    out += detail::format_number(mesh_volume);
    if (domain_checked) out += " (domain " + detail::format_number(domain_volume) + ", measured)";
  }
  if (!domain_checked) out += "; topology only (no domain)";
  out += '\n';
  if (!valid()) {
    std::int64_t total = 0;
    for (std::int64_t c : count_per_kind) total += c;
    out += "  " + std::to_string(total) + " issue(s):";
    for (CheckKind k : kinds()) out += std::string(" ") + to_string(k) + "=" + std::to_string(count(k));
    out += '\n';
  }
  std::vector<std::int64_t> shown(kCheckKindCount, 0);
  for (const CheckIssue& issue : issues) {
    ++shown[static_cast<int>(issue.kind)];
    out += "  [";
    out += to_string(issue.kind);
    out += "] " + issue.message + '\n';
  }
  for (int k = 0; k < kCheckKindCount; ++k) {
    if (count_per_kind[k] > shown[k]) {
      out += "  [" + std::string(to_string(static_cast<CheckKind>(k))) + "] ... and " +
             std::to_string(count_per_kind[k] - shown[k]) + " more not listed\n";
    }
  }
  for (const std::string& n : notes) out += "  note: " + n + '\n';
  return out;
}

}  // namespace pqmesh
