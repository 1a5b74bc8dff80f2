// Theorem 5 size ratio report; see size_ratio.hpp.
#include "mv3d/size_ratio.hpp"

#include <algorithm>
#include <vector>

#include "pqmesh/alpha.hpp"
#include "pqmesh/errors.hpp"

namespace pqmesh::mv3d {

namespace {

// Closed cubes with disjoint interiors share a facet portion of positive area
// iff their extents overlap with positive length along exactly two axes.
bool share_facet_portion(const Cube& a, const Cube& b) {
  int overlapping = 0;
  const double alo[3] = {a.lo.x, a.lo.y, a.lo.z}, ahi[3] = {a.hi.x, a.hi.y, a.hi.z};
  const double blo[3] = {b.lo.x, b.lo.y, b.lo.z}, bhi[3] = {b.hi.x, b.hi.y, b.hi.z};
  for (int k = 0; k < 3; ++k)
    if (std::min(ahi[k], bhi[k]) > std::max(alo[k], blo[k])) ++overlapping;
  return overlapping == 2;
}

}  // namespace

SizeRatioReport size_ratio(const OctreeBuilder& builder, double alpha) {
  if (!(alpha > 0)) throw InternalError("size_ratio: alpha must be positive");
  const OctTree& t = builder.tree();
  SizeRatioReport r;
  r.alpha = alpha;
  // The side of the thesis' box a leaf stands for (united box for its pieces).
  auto side = [&](std::int32_t n) {
    const int owner = builder.data(n).vertex_owner;
    if (owner < 0) return t.side(n);
    const Cube& c = builder.vertex_box(owner);
    return c.hi.x - c.lo.x;
  };
  std::vector<std::int32_t> near;
  for (const std::int32_t n : builder.leaves_by_id()) {
    const NodeData3& dn = builder.data(n);
    if (!dn.has_component) continue;
    t.neighbours(n, near);
    const Cube cn = builder.cube(n);
    for (const std::int32_t m : near) {
      if (m < n) continue;  // each unordered pair once
      const NodeData3& dm = builder.data(m);
      if (!dm.has_component) continue;
      if (dn.vertex_owner >= 0 && dn.vertex_owner == dm.vertex_owner) continue;
      if (!share_facet_portion(cn, builder.cube(m))) continue;
      const bool m_big = t.level(m) <= t.level(n);
      if (!(m_big ? builder.balance_adjacent(m, n) : builder.balance_adjacent(n, m))) continue;
      ++r.pairs;
      double hs = side(n), hb = side(m);
      std::int32_t s = n, b = m;
      if (hs > hb) {
        std::swap(hs, hb);
        std::swap(s, b);
      }
      const double plain = hs / hb;
      r.min_plain = std::min(r.min_plain, plain);
      const double ratio = plain / alpha;
      if (ratio < r.min_ratio) {
        r.min_ratio = ratio;
        r.small = s;
        r.big = b;
        r.h_small = hs;
        r.h_big = hb;
      }
    }
  }
  return r;
}

SizeRatioReport size_ratio(const OctreeBuilder& builder) {
  return size_ratio(builder, compute_alpha(builder.domain().plc).radians);
}

}  // namespace pqmesh::mv3d
