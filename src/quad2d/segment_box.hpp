#pragma once
// Exact segment-versus-box tests for the quadtree phases.
#include <algorithm>

#include "pqmesh/vec.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::quad2d {

struct Rect {
  Vec2 lo, hi;  // closed, lo <= hi
};

// The closed segment [a, c] meets the closed rectangle r. Exact: the segment and
// the rectangle are convex, so they are disjoint iff one of the separating axes
// x, y or the segment's normal separates them; the last is decided by orient2d
// on the four corners.
inline bool segment_meets_rect(Vec2 a, Vec2 c, const Rect& r) {
  if (std::max(a.x, c.x) < r.lo.x || std::min(a.x, c.x) > r.hi.x || std::max(a.y, c.y) < r.lo.y ||
      std::min(a.y, c.y) > r.hi.y)
    return false;
  int pos = 0, neg = 0;
  for (const Vec2 q : {r.lo, Vec2{r.hi.x, r.lo.y}, r.hi, Vec2{r.lo.x, r.hi.y}}) {
    const Sign s = orient2d(a, c, q);
    pos += s == Sign::Positive;
    neg += s == Sign::Negative;
  }
  return pos < 4 && neg < 4;
}

// The closed segment [a, c] meets the closed rectangle outer outside the OPEN
// rectangle hole: it meets one of the (up to four) closed strips of outer that
// lie outside hole.
inline bool segment_meets_rect_outside(Vec2 a, Vec2 c, const Rect& outer, const Rect& hole) {
  const Rect strips[4] = {
      {outer.lo, {std::min(hole.lo.x, outer.hi.x), outer.hi.y}},  // left of hole
      {{std::max(hole.hi.x, outer.lo.x), outer.lo.y}, outer.hi},  // right of hole
      {outer.lo, {outer.hi.x, std::min(hole.lo.y, outer.hi.y)}},  // below hole
      {{outer.lo.x, std::max(hole.hi.y, outer.lo.y)}, outer.hi},  // above hole
  };
  for (const Rect& s : strips)
    if (s.lo.x <= s.hi.x && s.lo.y <= s.hi.y && segment_meets_rect(a, c, s)) return true;
  return false;
}

}  // namespace pqmesh::quad2d
