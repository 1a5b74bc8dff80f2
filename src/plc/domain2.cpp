// make_domain(Pslg2) and locate(Domain2): a polygon with holes
// (docs/algorithm/input.md "Reading input domains", thesis §1.4 in 2D). Checks,
// in order: EmptyDomain, NonFinite, IndexOutOfRange, DegenerateFacet (a segment
// from a vertex to itself), DuplicateVertex (used vertices), InvalidPolygon
// (duplicate segments; unused vertices, which Triangle would keep as mesh
// vertices; vertices not on exactly two segments), SelfIntersectingFacet
// (segments meeting other than at a shared endpoint), Disconnected (no loop
// containing all others, or a loop inside a hole), Unsupported (a hole point
// inside the polygon).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "plc/polygon2d.hpp"
#include "plc/report_error.hpp"
#include "pqmesh/domain.hpp"

namespace pqmesh {

using namespace detail;

namespace {

struct LoopBox {
  double xlo, xhi, ylo, yhi;
  bool contains(const LoopBox& o) const { return xlo <= o.xlo && o.xhi <= xhi && ylo <= o.ylo && o.yhi <= yhi; }
};

std::string seg_name(const SourceInfo& src, int s) { return std::to_string(file_id(src, s)); }

// EmptyDomain, NonFinite, IndexOutOfRange, DegenerateFacet, in that order.
void check_segments_and_coordinates(const Pslg2& pslg) {
  const SourceInfo& src = pslg.source;
  const auto& P = pslg.vertices;
  const int nv = static_cast<int>(P.size()), ns = static_cast<int>(pslg.segments.size());
  if (ns == 0) throw_domain_error(src, ErrorCode::EmptyDomain, "the domain has no segments", {}, IdKind::None);
  std::vector<int> bad;
  for (int v = 0; v < nv; ++v)
    if (!std::isfinite(P[v].x) || !std::isfinite(P[v].y)) bad.push_back(v);
  if (!bad.empty())
    throw_domain_error(src, ErrorCode::NonFinite, "vertices " + id_list(src, bad) + " have non-finite coordinates",
                       bad, IdKind::Vertex);
  for (int s = 0; s < ns; ++s)
    for (int v : pslg.segments[s])
      if ((v < 0 || v >= nv) && (bad.empty() || bad.back() != s)) bad.push_back(s);
  if (!bad.empty())
    throw_domain_error(src, ErrorCode::IndexOutOfRange,
                       "segments " + id_list(src, bad) + " refer to vertex ids that do not exist", bad,
                       IdKind::Element);
  for (int s = 0; s < ns; ++s)
    if (pslg.segments[s][0] == pslg.segments[s][1]) bad.push_back(s);
  if (!bad.empty())
    throw_domain_error(src, ErrorCode::DegenerateFacet,
                       "segments " + id_list(src, bad) + " have zero length (both ends the same vertex)", bad,
                       IdKind::Element);
}

// DuplicateVertex: no two used vertices (degree > 0) with equal coordinates.
void check_duplicate_vertices(const Pslg2& pslg, const std::vector<int>& degree) {
  const SourceInfo& src = pslg.source;
  const auto& P = pslg.vertices;
  const int nv = static_cast<int>(P.size());
  std::vector<int> bad;
  std::vector<int> order;
  for (int v = 0; v < nv; ++v)
    if (degree[v] > 0) order.push_back(v);
  auto key = [&](int v) { return std::pair<double, double>{P[v].x, P[v].y}; };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return key(a) < key(b) || (key(a) == key(b) && a < b); });
  std::ostringstream groups;
  for (std::size_t k = 0; k + 1 < order.size(); ++k) {
    if (key(order[k]) != key(order[k + 1])) continue;
    if (bad.empty() || bad.back() != order[k]) {
      if (!bad.empty()) groups << "; ";
      bad.push_back(order[k]);
      groups << file_id(src, order[k]);
    }
    bad.push_back(order[k + 1]);
    groups << " = " << file_id(src, order[k + 1]);
  }
  if (!bad.empty())
    throw_domain_error(src, ErrorCode::DuplicateVertex, "vertices with exactly equal coordinates: " + groups.str(),
                       bad, IdKind::Vertex);
}

// InvalidPolygon: no two segments join the same two vertices.
void check_duplicate_segments(const Pslg2& pslg) {
  const SourceInfo& src = pslg.source;
  const int ns = static_cast<int>(pslg.segments.size());
  std::vector<std::pair<std::pair<int, int>, int>> keyed;
  for (int s = 0; s < ns; ++s) {
    const auto [a, b] = pslg.segments[s];
    keyed.push_back({{std::min(a, b), std::max(a, b)}, s});
  }
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t k = 0; k + 1 < keyed.size(); ++k)
    if (keyed[k].first == keyed[k + 1].first) {
      std::ostringstream msg;
      msg << "segments " << seg_name(src, keyed[k].second) << " and " << seg_name(src, keyed[k + 1].second)
          << " join the same two vertices";
      throw_domain_error(src, ErrorCode::InvalidPolygon, msg.str(), {keyed[k].second, keyed[k + 1].second},
                         IdKind::Element);
    }
}

// InvalidPolygon: every vertex is on exactly two segments (isolated ones
// reported first).
void check_degrees(const SourceInfo& src, const std::vector<int>& degree) {
  const int nv = static_cast<int>(degree.size());
  std::vector<int> bad;
  for (int v = 0; v < nv; ++v)
    if (degree[v] == 0) bad.push_back(v);
  if (!bad.empty())
    throw_domain_error(src, ErrorCode::InvalidPolygon,
                       "vertices " + id_list(src, bad) +
                           " are on no segment (isolated vertices are not supported: the domain must be a polygon "
                           "with holes)",
                       bad, IdKind::Vertex);
  for (int v = 0; v < nv; ++v)
    if (degree[v] != 2) bad.push_back(v);
  if (!bad.empty())
    throw_domain_error(src, ErrorCode::InvalidPolygon,
                       "vertices " + id_list(src, bad) +
                           " are not on exactly two segments (dangling or branching segments are not supported: the "
                           "segments must form closed loops)",
                       bad, IdKind::Vertex);
}

// SelfIntersectingFacet: segments meet only at shared endpoints.
void check_no_intersections(const Pslg2& pslg) {
  const SourceInfo& src = pslg.source;
  const auto& P = pslg.vertices;
  std::vector<KeyedSegment> keyed;
  for (const auto& s : pslg.segments) keyed.push_back({P[s[0]], P[s[1]], s[0], s[1]});
  if (const auto hit = find_segment_conflict(keyed)) {
    std::ostringstream msg;
    msg << "segments " << seg_name(src, hit->first) << " and " << seg_name(src, hit->second)
        << " intersect (other than at a shared endpoint)";
    throw_domain_error(src, ErrorCode::SelfIntersectingFacet, msg.str(), {hit->first, hit->second}, IdKind::Element);
  }
}

// The closed loops of the segments: vertices and segments in walking order.
struct Loops {
  std::vector<std::vector<int>> vertices, segments;
};

// Chain into loops: every vertex has exactly two segments.
Loops chain_loops(const Pslg2& pslg) {
  const int nv = static_cast<int>(pslg.vertices.size()), ns = static_cast<int>(pslg.segments.size());
  std::vector<std::array<int, 2>> seg_at(nv, {-1, -1});
  for (int s = 0; s < ns; ++s)
    for (int v : pslg.segments[s]) seg_at[v][seg_at[v][0] < 0 ? 0 : 1] = s;
  std::vector<char> used(ns, 0);
  Loops out;
  for (int s0 = 0; s0 < ns; ++s0) {
    if (used[s0]) continue;
    std::vector<int> lv, ls;
    int s = s0, v = pslg.segments[s0][0];
    while (!used[s]) {
      used[s] = 1;
      lv.push_back(v);
      ls.push_back(s);
      v = pslg.segments[s][0] == v ? pslg.segments[s][1] : pslg.segments[s][0];
      s = seg_at[v][0] == s ? seg_at[v][1] : seg_at[v][0];
    }
    out.vertices.push_back(std::move(lv));
    out.segments.push_back(std::move(ls));
  }
  return out;
}

// Nesting (loops do not touch, so one vertex decides containment): the one
// loop inside no other, else Disconnected; Disconnected also for a loop
// inside a hole.
int outer_loop(const Pslg2& pslg, const Loops& loops) {
  const SourceInfo& src = pslg.source;
  const auto& P = pslg.vertices;
  const auto& loop_segs = loops.segments;
  const int nl = static_cast<int>(loops.vertices.size());
  std::vector<LoopBox> boxes;
  for (const auto& l : loops.vertices) {
    LoopBox b{P[l[0]].x, P[l[0]].x, P[l[0]].y, P[l[0]].y};
    for (int v : l) b = {std::min(b.xlo, P[v].x), std::max(b.xhi, P[v].x), std::min(b.ylo, P[v].y), std::max(b.yhi, P[v].y)};
    boxes.push_back(b);
  }
  std::vector<std::vector<int>> containers(nl);
  for (int i = 0; i < nl; ++i)
    for (int j = 0; j < nl; ++j)
      if (i != j && boxes[j].contains(boxes[i]) &&
          locate_in_loop(P[loops.vertices[i][0]], P, loops.vertices[j]) == PointInLoop::Inside)
        containers[i].push_back(j);
  std::vector<int> outer;
  for (int i = 0; i < nl; ++i)
    if (containers[i].empty()) outer.push_back(i);
  if (outer.size() != 1) {
    std::ostringstream msg;
    msg << "the domain is disconnected: the loops through segments " << seg_name(src, loop_segs[outer[0]][0])
        << " and " << seg_name(src, loop_segs[outer[1]][0]) << " bound disjoint regions";
    throw_domain_error(src, ErrorCode::Disconnected, msg.str(), {loop_segs[outer[0]][0], loop_segs[outer[1]][0]},
                       IdKind::Element);
  }
  for (int i = 0; i < nl; ++i)
    if (containers[i].size() > 1) {
      const int hole = containers[i][0] == outer[0] ? containers[i][1] : containers[i][0];
      std::ostringstream msg;
      msg << "the domain is disconnected: the loop through segment " << seg_name(src, loop_segs[i][0])
          << " lies inside the hole bounded by the loop through segment " << seg_name(src, loop_segs[hole][0]);
      throw_domain_error(src, ErrorCode::Disconnected, msg.str(), {loop_segs[i][0], loop_segs[hole][0]},
                         IdKind::Element);
    }
  return outer[0];
}

// The loops into d, outer loop first and counter-clockwise, holes clockwise;
// d.area sums their signed areas.
void add_oriented_loops(const std::vector<Vec2>& P, const Loops& loops, int outer, Domain2& d) {
  const int nl = static_cast<int>(loops.vertices.size());
  std::vector<int> order{outer};
  for (int i = 0; i < nl; ++i)
    if (i != outer) order.push_back(i);
  for (int i : order) {
    std::vector<int> lv = loops.vertices[i], ls = loops.segments[i];
    const Sign want = i == outer ? Sign::Positive : Sign::Negative;
    if (loop_turn(P, lv) != want) {
      // Reverse: new vertex k is old vertex (n - k) mod n, and the new side k
      // (from new k to new k+1) is old side (n - k - 1) mod n.
      const int n = static_cast<int>(lv.size());
      std::vector<int> rv(n), rs(n);
      for (int k = 0; k < n; ++k) {
        rv[k] = lv[(n - k) % n];
        rs[k] = ls[(n - k - 1) % n];
      }
      lv = std::move(rv);
      ls = std::move(rs);
    }
    d.area += loop_signed_area(P, lv);
    d.loops.push_back(std::move(lv));
    d.loop_segments.push_back(std::move(ls));
  }
}

// Unsupported: every hole point lies outside the polygon.
void check_hole_points(const Domain2& d) {
  for (int h = 0; h < int(d.pslg.holes.size()); ++h) {
    const Location where = locate(d, d.pslg.holes[h]);
    if (where == Location::Outside) continue;
    std::ostringstream msg;
    msg << "hole point " << file_id(d.pslg.source, h) << " (" << d.pslg.holes[h].x << ", " << d.pslg.holes[h].y
        << ") lies " << (where == Location::Inside ? "inside" : "on the boundary of")
        << " the polygon; holes are given by hole loops, so hole points must lie in a hole or outside";
    throw_domain_error(d.pslg.source, ErrorCode::Unsupported, msg.str(), {h}, IdKind::None);
  }
}

}  // namespace

Domain2 make_domain(Pslg2 pslg) {
  check_segments_and_coordinates(pslg);
  const auto& P = pslg.vertices;
  std::vector<int> degree(P.size(), 0);
  for (const auto& s : pslg.segments) ++degree[s[0]], ++degree[s[1]];
  check_duplicate_vertices(pslg, degree);
  check_duplicate_segments(pslg);
  check_degrees(pslg.source, degree);
  check_no_intersections(pslg);

  const Loops loops = chain_loops(pslg);
  const int outer = outer_loop(pslg, loops);
  Domain2 d;
  add_oriented_loops(P, loops, outer, d);
  d.bbox_min = d.bbox_max = P[d.loops[0][0]];
  for (int v : d.loops[0]) {  // the outer loop bounds everything
    d.bbox_min = {std::min(d.bbox_min.x, P[v].x), std::min(d.bbox_min.y, P[v].y)};
    d.bbox_max = {std::max(d.bbox_max.x, P[v].x), std::max(d.bbox_max.y, P[v].y)};
  }
  d.pslg = std::move(pslg);
  check_hole_points(d);
  return d;
}

// Even-odd over all loops with the tie rule of locate_in_loop (the ray towards
// +x at height p.y + eps); Boundary when p is on a segment (exact).
Location locate(const Domain2& domain, Vec2 p) {
  const auto& P = domain.pslg.vertices;
  if (domain.loops.empty() || p.x < domain.bbox_min.x || p.x > domain.bbox_max.x || p.y < domain.bbox_min.y ||
      p.y > domain.bbox_max.y)
    return Location::Outside;
  bool inside = false;
  for (const auto& loop : domain.loops) {
    const PointInLoop w = locate_in_loop(p, P, loop);
    if (w == PointInLoop::Boundary) return Location::Boundary;
    if (w == PointInLoop::Inside) inside = !inside;
  }
  return inside ? Location::Inside : Location::Outside;
}

}  // namespace pqmesh
