#pragma once
// Errors thrown by the library (docs/DESIGN_RULES.md "Conventions"). The
// library never prints or exits: bad input throws an InvalidInput subclass that
// carries the offending ids and, where the input came from a file, the file and
// line; broken internal invariants throw InternalError with the source
// location.
#include <cstdint>
#include <source_location>
#include <stdexcept>
#include <string>
#include <vector>

namespace pqmesh {

enum class ErrorCode {
  // Reading (ParseError)
  Unreadable,       // file missing or not readable
  Truncated,        // file ends before the announced data
  Syntax,           // token that does not parse as what the format requires
  WrongCount,       // a count that contradicts the data or is impossible
  IndexOutOfRange,  // element refers to a vertex id that does not exist
  NonFinite,        // NaN or infinite coordinate
  Unsupported,      // valid file using a feature we do not handle
  // Domain validation (DomainError)
  DuplicateVertex,
  DegenerateFacet,        // zero area, or fewer than 3 distinct vertices
  NonPlanarFacet,
  OpenBoundary,           // edge on only one facet
  NonManifoldEdge,        // edge on more than two facets
  PinchedVertex,          // vertex whose link is not connected (thesis §1.4)
  IntersectingFacets,     // facets meet other than in shared edges/vertices
  SelfIntersectingFacet,  // a facet polygon crosses itself
  Disconnected,           // the domain has more than one component
  InvalidPolygon,         // 2D: segments do not form a polygon with holes
  EmptyDomain,
};

// Stable lower-case name of an error code, used in messages and tests.
const char* to_string(ErrorCode code);

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Something wrong with what the user gave us.
class InvalidInput : public Error {
 public:
  InvalidInput(ErrorCode code, std::string detail, std::vector<std::int64_t> ids = {}, std::string file = {},
               int line = 0);
  ErrorCode code() const { return code_; }
  const std::string& detail() const { return detail_; }
  // Offending ids (vertices, facets, segments: which kind is said in detail()),
  // in the file's own numbering when the input came from a file.
  const std::vector<std::int64_t>& ids() const { return ids_; }
  const std::string& file() const { return file_; }
  int line() const { return line_; }  // 1-based; 0 when unknown

 private:
  ErrorCode code_;
  std::string detail_;
  std::vector<std::int64_t> ids_;
  std::string file_;
  int line_;
};

// The file could not be read as the format it claims.
class ParseError : public InvalidInput {
 public:
  using InvalidInput::InvalidInput;
};

// The file was read, but the domain violates the assumptions of thesis §1.4.
class DomainError : public InvalidInput {
 public:
  using InvalidInput::InvalidInput;
};

// An output file could not be created or written (a missing directory, no
// permission, a full disk): the user's environment, not a bug. what() is
// "cannot write PATH: REASON".
class OutputError : public Error {
 public:
  using Error::Error;
};

// A broken internal invariant: a bug in pqmesh, never the user's fault.
class InternalError : public Error {
 public:
  explicit InternalError(const std::string& what, std::source_location where = std::source_location::current());
};

}  // namespace pqmesh
