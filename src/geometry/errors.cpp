#include "pqmesh/errors.hpp"

#include <sstream>

namespace pqmesh {

const char* to_string(ErrorCode code) {
  switch (code) {
    case ErrorCode::Unreadable: return "unreadable";
    case ErrorCode::Truncated: return "truncated";
    case ErrorCode::Syntax: return "syntax";
    case ErrorCode::WrongCount: return "wrong-count";
    case ErrorCode::IndexOutOfRange: return "index-out-of-range";
    case ErrorCode::NonFinite: return "non-finite";
    case ErrorCode::Unsupported: return "unsupported";
    case ErrorCode::DuplicateVertex: return "duplicate-vertex";
    case ErrorCode::DegenerateFacet: return "degenerate-facet";
    case ErrorCode::NonPlanarFacet: return "non-planar-facet";
    case ErrorCode::OpenBoundary: return "open-boundary";
    case ErrorCode::NonManifoldEdge: return "non-manifold-edge";
    case ErrorCode::PinchedVertex: return "pinched-vertex";
    case ErrorCode::IntersectingFacets: return "intersecting-facets";
    case ErrorCode::SelfIntersectingFacet: return "self-intersecting-facet";
    case ErrorCode::Disconnected: return "disconnected";
    case ErrorCode::InvalidPolygon: return "invalid-polygon";
    case ErrorCode::EmptyDomain: return "empty-domain";
  }
  return "unknown";
}

namespace {

std::string compose(ErrorCode code, const std::string& detail, const std::string& file, int line) {
  std::ostringstream out;
  if (!file.empty()) {
    out << file;
    if (line > 0) out << ':' << line;
    out << ": ";
  }
  out << "error [" << to_string(code) << "]: " << detail;
  return out.str();
}

}  // namespace

InvalidInput::InvalidInput(ErrorCode code, std::string detail, std::vector<std::int64_t> ids, std::string file,
                           int line)
    : Error(compose(code, detail, file, line)),
      code_(code),
      detail_(std::move(detail)),
      ids_(std::move(ids)),
      file_(std::move(file)),
      line_(line) {}

InternalError::InternalError(const std::string& what, std::source_location where)
    : Error((std::ostringstream() << "internal error at " << where.file_name() << ':' << where.line() << ": " << what)
                .str()) {}

}  // namespace pqmesh
