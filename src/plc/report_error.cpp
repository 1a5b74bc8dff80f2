#include "plc/report_error.hpp"

#include <sstream>

namespace pqmesh::detail {

std::string id_list(const SourceInfo& source, const std::vector<int>& indices) {
  std::ostringstream out;
  for (std::size_t i = 0; i < indices.size(); ++i) {
    if (i == kMaxReportedIds) {
      out << ", ... (" << indices.size() << " in all)";
      break;
    }
    if (i > 0) out << ", ";
    out << file_id(source, indices[i]);
  }
  return out.str();
}

void throw_domain_error(const SourceInfo& source, ErrorCode code, const std::string& detail,
                        const std::vector<int>& indices, IdKind kind) {
  std::vector<std::int64_t> ids;
  for (std::size_t i = 0; i < indices.size() && i < kMaxReportedIds; ++i) ids.push_back(file_id(source, indices[i]));
  int line = 0;
  if (!indices.empty()) {
    if (kind == IdKind::Vertex) line = source.line_of_vertex(indices[0]);
    if (kind == IdKind::Element) line = source.line_of_element(indices[0]);
  }
  throw DomainError(code, detail, std::move(ids), source.path, line);
}

}  // namespace pqmesh::detail
