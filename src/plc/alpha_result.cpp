// Text for alpha reports (include/pqmesh/alpha.hpp).
#include <cstdio>
#include <numbers>
#include <string>

#include "pqmesh/alpha.hpp"

namespace pqmesh {

std::string FaceRef::describe(int first_id) const {
  switch (kind) {
    case Kind::Vertex: return "vertex " + std::to_string(id + first_id);
    case Kind::Edge: return "edge " + std::to_string(a + first_id) + "-" + std::to_string(b + first_id);
    case Kind::Facet: return "facet " + std::to_string(id + first_id);
    case Kind::None: break;
  }
  return "none";
}

double AlphaResult::degrees() const { return radians * 180.0 / std::numbers::pi; }

std::string AlphaResult::describe(int first_id) const {
  char value[64];
  std::snprintf(value, sizeof value, "%.6g", degrees());
  return std::string("alpha = ") + value + " deg (" + kind + ") at vertex " + std::to_string(apex + first_id) + ": " +
         first.describe(first_id) + " and " + second.describe(first_id);
}

}  // namespace pqmesh
