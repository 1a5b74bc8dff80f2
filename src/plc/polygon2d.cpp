#include "plc/polygon2d.hpp"

#include <algorithm>
#include <numeric>

namespace pqmesh::detail {

namespace {

bool lex_less(Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

}  // namespace

bool on_segment(Vec2 p, Vec2 a, Vec2 b) {
  if (orient2d(a, b, p) != Sign::Zero) return false;
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

bool segments_intersect(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  if (std::max(a.x, b.x) < std::min(c.x, d.x) || std::max(c.x, d.x) < std::min(a.x, b.x) ||
      std::max(a.y, b.y) < std::min(c.y, d.y) || std::max(c.y, d.y) < std::min(a.y, b.y))
    return false;
  const Sign o1 = orient2d(a, b, c), o2 = orient2d(a, b, d);
  const Sign o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
  if (o1 * o2 == Sign::Negative && o3 * o4 == Sign::Negative) return true;
  // Touching or collinear cases: some endpoint lies on the other segment.
  return (o1 == Sign::Zero && on_segment(c, a, b)) || (o2 == Sign::Zero && on_segment(d, a, b)) ||
         (o3 == Sign::Zero && on_segment(a, c, d)) || (o4 == Sign::Zero && on_segment(b, c, d));
}

bool in_closed_triangle(Vec2 p, Vec2 a, Vec2 b, Vec2 c) {
  const Sign s = orient2d(a, b, c);
  const Sign s1 = orient2d(a, b, p) * s, s2 = orient2d(b, c, p) * s, s3 = orient2d(c, a, p) * s;
  return s1 != Sign::Negative && s2 != Sign::Negative && s3 != Sign::Negative;
}

bool segments_conflict(const KeyedSegment& s, const KeyedSegment& t) {
  const bool aa = s.ka == t.ka, ab = s.ka == t.kb, ba = s.kb == t.ka, bb = s.kb == t.kb;
  const int shared = int(aa || ab) + int(ba || bb);
  if (shared == 2) return true;  // the same edge twice
  if (shared == 1) {
    // Common endpoint v; they meet elsewhere iff collinear and pointing the same way.
    const Vec2 v = (aa || ab) ? s.a : s.b;
    const Vec2 x = (aa || ab) ? s.b : s.a;
    const Vec2 y = (aa || ba) ? t.b : t.a;
    return orient2d(v, x, y) == Sign::Zero && dot_sign(v, x, y) == Sign::Positive;
  }
  return segments_intersect(s.a, s.b, t.a, t.b);
}

std::optional<std::pair<int, int>> find_segment_conflict(const std::vector<KeyedSegment>& segments) {
  const int n = static_cast<int>(segments.size());
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  auto min_x = [&](int i) { return std::min(segments[i].a.x, segments[i].b.x); };
  auto max_x = [&](int i) { return std::max(segments[i].a.x, segments[i].b.x); };
  std::sort(order.begin(), order.end(), [&](int i, int j) { return min_x(i) < min_x(j) || (min_x(i) == min_x(j) && i < j); });
  std::optional<std::pair<int, int>> best;
  for (int oi = 0; oi < n; ++oi) {
    const int i = order[oi];
    const KeyedSegment& s = segments[i];
    const double xi = max_x(i);
    const double ylo = std::min(s.a.y, s.b.y), yhi = std::max(s.a.y, s.b.y);
    for (int oj = oi + 1; oj < n && min_x(order[oj]) <= xi; ++oj) {
      const KeyedSegment& t = segments[order[oj]];
      if (std::max(t.a.y, t.b.y) < ylo || std::min(t.a.y, t.b.y) > yhi) continue;
      if (segments_conflict(s, t)) {
        const std::pair<int, int> p{std::min(i, order[oj]), std::max(i, order[oj])};
        if (!best || p < *best) best = p;
      }
    }
    if (best) return best;  // the first row that conflicts (deterministic)
  }
  return best;
}

PointInLoop locate_in_loop(Vec2 p, const std::vector<Vec2>& pts, const std::vector<int>& loop) {
  bool inside = false;
  const std::size_t n = loop.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 u = pts[loop[k]], w = pts[loop[(k + 1) % n]];
    if (on_segment(p, u, w)) return PointInLoop::Boundary;
    if (ray_crosses_edge(p, u, w)) inside = !inside;
  }
  return inside ? PointInLoop::Inside : PointInLoop::Outside;
}

bool ray_crosses_edge(Vec2 p, Vec2 u, Vec2 w) {
  const bool u_above = u.y > p.y, w_above = w.y > p.y;  // y == p.y counts as below (p.y + eps)
  if (u_above == w_above) return false;
  // The edge crosses the line y = p.y + eps; the crossing is right of p iff
  // p is left of the edge directed upwards.
  return (u_above ? orient2d(w, u, p) : orient2d(u, w, p)) == Sign::Positive;
}

Sign loop_turn(const std::vector<Vec2>& pts, const std::vector<int>& loop) {
  const std::size_t n = loop.size();
  std::size_t m = 0;
  for (std::size_t k = 1; k < n; ++k)
    if (lex_less(pts[loop[k]], pts[loop[m]])) m = k;
  return orient2d(pts[loop[(m + n - 1) % n]], pts[loop[m]], pts[loop[(m + 1) % n]]);
}

double loop_signed_area(const std::vector<Vec2>& pts, const std::vector<int>& loop) {
  const std::size_t n = loop.size();
  if (n == 0) return 0;
  const Vec2 o = pts[loop[0]];
  double twice = 0;
  for (std::size_t k = 1; k + 1 < n; ++k) twice += cross(pts[loop[k]] - o, pts[loop[k + 1]] - o);
  return 0.5 * twice;
}

}  // namespace pqmesh::detail
