#pragma once
// Exact point location in a polygon with holes, for many queries (the
// checker's locate() second opinion on every mesh vertex). The same decision
// as locate(const Domain2&, Vec2) (src/plc/domain2.cpp: +x ray from p shifted
// by +eps in y, parity of crossings, boundary first), restricted to the edges
// whose y-range holds p.y. Those are found in horizontal bands: an edge is
// listed in every band its closed y-range meets, and the band of a y value
// is a monotone function of y, so every edge that can touch the ray or hold
// p lies in p's band. Cost per query: the edges of one band.
#include <vector>

#include "pqmesh/domain.hpp"

namespace pqmesh::detail {

class DomainLocator2 {
 public:
  explicit DomainLocator2(const Domain2& domain);
  Location locate(Vec2 p) const;

 private:
  int band(double y) const;

  const Domain2& domain_;
  double y0_ = 0, band_height_ = 1;
  int bands_ = 1;
  std::vector<int> offsets_;                  // band b: edges [offsets_[b], offsets_[b + 1])
  std::vector<std::array<int, 2>> edges_;     // vertex ids, in loop direction
};

}  // namespace pqmesh::detail
