#pragma once
// triangle_quality() with a memo of recent triangle shapes, for measuring
// every triangle of a large mesh (the .vtu quality fields, the quality
// report). Same numbers as triangle_quality(), bit for bit:
//
// triangle_quality(a, b, c) reads its points only through the differences
// b - a, c - a, c - b (and their negations) and through orient2d / dot_sign,
// which are exact signs of polynomials in those differences. When the three
// differences are computed exactly (no rounding; always so for the
// quadtree's dyadic grid corners), every double it produces is therefore a
// function of the exact vectors b - a and c - a alone: two translated copies
// of a triangle get the same TriQuality. The memo keys on those two vectors
// (bit patterns) and stores the result; a triangle with an inexact
// difference is measured directly and not stored. A quadtree mesh consists
// largely of a few shapes repeated (each box size and split pattern), met in
// runs along the z-order, so a small direct-mapped table catches most.
#include <cstdint>
#include <vector>

#include "pqmesh/quality.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh {

class TriangleQualityMemo {
 public:
  TriangleQualityMemo();
  TriQuality operator()(Vec2 a, Vec2 b, Vec2 c);

 private:
  struct Entry {
    std::uint64_t key[4] = {0, 0, 0, 0};  // bit patterns of (b - a).x, .y, (c - a).x, .y
    bool used = false;
    TriQuality quality{};
  };
  std::vector<Entry> table_;
};

}  // namespace pqmesh
