#include "plc/facet_triangulation.hpp"

#include <algorithm>
#include <numeric>

#include "pqmesh/errors.hpp"
#include "plc/facet_geometry.hpp"
#include "plc/polygon2d.hpp"

namespace pqmesh::detail {

namespace {

bool lex_less(Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

// Direction v -> p points strictly into the polygon's interior at the corner
// (a, v, b) of a loop that has the interior on its left. At a convex corner
// the interior wedge is the intersection of the open left half-planes of the
// two edges, otherwise their union.
bool in_wedge(Vec2 a, Vec2 v, Vec2 b, Vec2 p) {
  const bool left1 = orient2d(a, v, p) == Sign::Positive;
  const bool left2 = orient2d(v, b, p) == Sign::Positive;
  if (orient2d(a, v, b) == Sign::Positive) return left1 && left2;
  return left1 || left2;
}

// Segment mv (keys m, v) meets the edge (s, t) anywhere but at a shared key.
bool bridge_blocked(const std::vector<Vec2>& pts, int m, int v, int s, int t) {
  return segments_conflict(KeyedSegment{pts[m], pts[v], m, v}, KeyedSegment{pts[s], pts[t], s, t});
}

// Splices every hole into the outer loop through a bridge (a doubled segment
// from the hole's lexicographically largest vertex M to a vertex V of the
// current polygon). Holes are taken in decreasing order of M, so when a hole is
// bridged all remaining holes lie left of (or level with and below) M, and the
// ray from M towards +x first hits the current polygon: some vertex of it is
// visible from M (the argument of Eberly's hole-bridging). We search the
// visible vertex directly: candidates by distance, accepted when the segment
// enters the interior at both ends (in_wedge) and meets no edge elsewhere.
std::vector<int> bridge_holes(const std::vector<Vec2>& pts, std::vector<std::vector<int>> loops) {
  std::vector<int> poly = std::move(loops[0]);
  std::vector<std::vector<int>> holes(loops.begin() + 1, loops.end());
  std::vector<int> rightmost(holes.size());
  for (std::size_t h = 0; h < holes.size(); ++h) {
    int m = 0;
    for (int k = 1; k < int(holes[h].size()); ++k)
      if (lex_less(pts[holes[h][m]], pts[holes[h][k]])) m = k;
    rightmost[h] = m;
  }
  std::vector<int> order(holes.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int i, int j) {
    return lex_less(pts[holes[j][rightmost[j]]], pts[holes[i][rightmost[i]]]);
  });
  std::vector<bool> pending(holes.size(), true);
  for (int h : order) {
    const std::vector<int>& hole = holes[h];
    const int hn = static_cast<int>(hole.size());
    const int mpos = rightmost[h];
    const int m = hole[mpos];
    const Vec2 mp = pts[m];
    const Vec2 m_prev = pts[hole[(mpos + hn - 1) % hn]], m_next = pts[hole[(mpos + 1) % hn]];
    const int pn = static_cast<int>(poly.size());
    std::vector<int> cand(pn);
    std::iota(cand.begin(), cand.end(), 0);
    std::vector<double> dist(pn);
    for (int k = 0; k < pn; ++k) {
      const Vec2 d = pts[poly[k]] - mp;
      dist[k] = dot(d, d);  // heuristic order only
    }
    std::sort(cand.begin(), cand.end(), [&](int i, int j) { return dist[i] < dist[j] || (dist[i] == dist[j] && i < j); });
    int chosen = -1;
    for (int k : cand) {
      const int v = poly[k];
      const Vec2 vp = pts[v];
      if (!in_wedge(m_prev, mp, m_next, vp)) continue;
      if (!in_wedge(pts[poly[(k + pn - 1) % pn]], vp, pts[poly[(k + 1) % pn]], mp)) continue;
      bool blocked = false;
      for (int e = 0; e < pn && !blocked; ++e) blocked = bridge_blocked(pts, m, v, poly[e], poly[(e + 1) % pn]);
      for (std::size_t g = 0; g < holes.size() && !blocked; ++g) {
        if (!pending[g]) continue;
        const int gn = static_cast<int>(holes[g].size());
        for (int e = 0; e < gn && !blocked; ++e) blocked = bridge_blocked(pts, m, v, holes[g][e], holes[g][(e + 1) % gn]);
      }
      if (!blocked) {
        chosen = k;
        break;
      }
    }
    if (chosen < 0) throw InternalError("facet triangulation: no visible vertex to bridge a hole");
    std::vector<int> splice;
    splice.reserve(hole.size() + 2);
    for (int i = 0; i <= hn; ++i) splice.push_back(hole[(mpos + i) % hn]);  // M ... M
    splice.push_back(poly[chosen]);                                          // back to V
    poly.insert(poly.begin() + chosen + 1, splice.begin(), splice.end());
    pending[h] = false;
  }
  return poly;
}

// Ear clipping of a weakly simple counter-clockwise polygon (bridges repeat
// vertices). An ear (p, i, q) is a strictly convex corner whose closed triangle
// contains no other polygon point except copies of p, i, q: then no edge can
// cross the triangle (it would have to cross pi or iq, or end inside), so the
// diagonal pq lies in the polygon.
std::vector<std::array<int, 3>> clip_ears(const std::vector<Vec2>& pts, const std::vector<int>& poly) {
  std::vector<std::array<int, 3>> out;
  const int n = static_cast<int>(poly.size());
  if (n < 3) return out;
  std::vector<int> prv(n), nxt(n);
  for (int k = 0; k < n; ++k) {
    prv[k] = (k + n - 1) % n;
    nxt[k] = (k + 1) % n;
  }
  auto is_ear = [&](int p, int i, int q) {
    const int ip = poly[p], ii = poly[i], iq = poly[q];
    const Vec2 a = pts[ip], b = pts[ii], c = pts[iq];
    if (orient2d(a, b, c) != Sign::Positive) return false;
    const double xlo = std::min({a.x, b.x, c.x}), xhi = std::max({a.x, b.x, c.x});
    const double ylo = std::min({a.y, b.y, c.y}), yhi = std::max({a.y, b.y, c.y});
    for (int r = nxt[q]; r != p; r = nxt[r]) {
      const int ir = poly[r];
      if (ir == ip || ir == ii || ir == iq) continue;
      const Vec2 x = pts[ir];
      if (x.x < xlo || x.x > xhi || x.y < ylo || x.y > yhi) continue;
      if (in_closed_triangle(x, a, b, c)) return false;
    }
    return true;
  };
  int remaining = n, cur = 0, stall = 0;
  while (remaining > 3) {
    const int p = prv[cur], q = nxt[cur];
    if (is_ear(p, cur, q)) {
      out.push_back({poly[p], poly[cur], poly[q]});
      nxt[p] = q;
      prv[q] = p;
      --remaining;
      stall = 0;
      cur = q;
    } else {
      cur = q;
      if (++stall > remaining) throw InternalError("facet triangulation: no ear found");
    }
  }
  const int p = prv[cur], q = nxt[cur];
  if (orient2d(pts[poly[p]], pts[poly[cur]], pts[poly[q]]) == Sign::Positive) out.push_back({poly[p], poly[cur], poly[q]});
  return out;
}

}  // namespace

std::vector<std::array<int, 3>> triangulate_polygon(const std::vector<Vec2>& points,
                                                    std::vector<std::vector<int>> loops) {
  if (loops.empty()) return {};
  // Outer loop counter-clockwise, holes clockwise: the interior is on the left of every loop.
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const Sign want = l == 0 ? Sign::Positive : Sign::Negative;
    if (loop_turn(points, loops[l]) != want) std::reverse(loops[l].begin(), loops[l].end());
  }
  return clip_ears(points, bridge_holes(points, std::move(loops)));
}

std::vector<std::array<int, 3>> triangulate_facet(const std::vector<Vec3>& vertices, const Facet3& facet,
                                                  int drop) {
  if (facet.loops.size() == 1 && facet.loops[0].size() == 3) {
    const auto& l = facet.loops[0];
    return {{l[0], l[1], l[2]}};
  }
  const ProjectedFacet pf = project_facet(vertices, facet, drop);
  const Sign outer = loop_turn(pf.points, pf.loops[0]);
  auto tris = triangulate_polygon(pf.points, pf.loops);
  for (auto& t : tris) {
    for (int& v : t) v = pf.vertex_of[v];
    if (outer == Sign::Negative) std::swap(t[1], t[2]);  // follow loops[0]'s turn
  }
  return tris;
}

}  // namespace pqmesh::detail
