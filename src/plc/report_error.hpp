#pragma once
// Building DomainError exceptions for validation failures (docs/DESIGN_RULES.md
// "Bad input and errors": bad input names the offending ids in the file's
// numbering and the file line).
#include <cstdint>
#include <string>
#include <vector>

#include "pqmesh/errors.hpp"
#include "pqmesh/plc.hpp"

namespace pqmesh::detail {

// At most this many ids are listed in a message and carried by the exception.
inline constexpr std::size_t kMaxReportedIds = 16;

// What the first offending index refers to, to look up its file line.
enum class IdKind { Vertex, Element, None };

// Index -> id in the file's numbering.
inline std::int64_t file_id(const SourceInfo& source, int index) {
  return static_cast<std::int64_t>(index) + source.first_id;
}

// "3, 7, 9" in file numbering, capped at kMaxReportedIds (then ", ...").
std::string id_list(const SourceInfo& source, const std::vector<int>& indices);

// Throws DomainError(code, detail) carrying `indices` in file numbering and the
// file line of indices[0] interpreted as `kind`.
[[noreturn]] void throw_domain_error(const SourceInfo& source, ErrorCode code, const std::string& detail,
                                     const std::vector<int>& indices, IdKind kind);

}  // namespace pqmesh::detail
