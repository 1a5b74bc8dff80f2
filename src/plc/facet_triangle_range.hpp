// The facet triangles of one facet, found without scanning them all.
#pragma once

#include <algorithm>
#include <ranges>

#include "pqmesh/domain.hpp"

namespace pqmesh::detail {

// Purpose: the indices into domain.facet_triangles of the triangles owned by
// `facet`. Contract: make_domain triangulates facet after facet, so
// facet_triangle_owner is non-decreasing and a facet's triangles are one
// contiguous run; the range is empty for an id owning no triangle. Cost:
// O(log T) for T facet triangles.
inline auto facet_triangle_range(const Domain3& domain, int facet) {
  const auto& owner = domain.facet_triangle_owner;
  const auto [lo, hi] = std::equal_range(owner.begin(), owner.end(), facet);
  return std::views::iota(static_cast<std::size_t>(lo - owner.begin()), static_cast<std::size_t>(hi - owner.begin()));
}

}  // namespace pqmesh::detail
