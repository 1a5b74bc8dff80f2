// Stage 4 of the triangle-mesh checker (see check2d.cpp): input vertices found
// by exact coordinates, input segments walked along mesh edges, the boundary
// compared with the domain's loops, Steiner points on the boundary, and the
// locate() second opinion.
#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/check2d_stages.hpp"
#include "plc/point_location2.hpp"
#include "pqmesh/errors.hpp"

namespace pqmesh::detail::check2d {

void Checker2::map_input_vertices(const Domain2& d) {
  const auto& pv = d.pslg.vertices;
  std::vector<char> referenced(pv.size(), 0);
  for (const auto& s : d.pslg.segments)
    for (int v : s)
      if (v >= 0 && v < static_cast<int>(pv.size())) referenced[v] = 1;
  for (const auto& loop : d.loops)
    for (int v : loop)
      if (v >= 0 && v < static_cast<int>(pv.size())) referenced[v] = 1;
  const int unreferenced =
      map_input_vertices_by_coordinates(sink_, m_.vertices, order_, pv, referenced, in2mesh_, mesh2in_);
  if (unreferenced)
    sink_.note(std::to_string(unreferenced) + " input vertices on no segment were not required to be mesh vertices");
}

void Checker2::walk_segments(const Domain2& d) {
  const auto& pv = d.pslg.vertices;
  const std::size_t ns = d.pslg.segments.size();
  chain_offset_.assign(ns + 1, 0);
  chain_items_.clear();
  segment_ok_.assign(ns, 0);
  int skipped = 0;
  for (std::size_t s = 0; s < ns; ++s) {
    chain_offset_[s] = static_cast<int>(chain_items_.size());
    const auto& seg = d.pslg.segments[s];
    const bool ids_ok = seg[0] >= 0 && seg[1] >= 0 && seg[0] < static_cast<int>(pv.size()) &&
                        seg[1] < static_cast<int>(pv.size());
    const int A = ids_ok ? in2mesh_[seg[0]] : -1, B = ids_ok ? in2mesh_[seg[1]] : -1;
    if (A < 0 || B < 0) {
      ++skipped;
      continue;
    }
    const Vec2 pa = m_.vertices[A], pb = m_.vertices[B];
    const std::string name = "input segment " + std::to_string(s) + " (" + format_ids(seg) + ")";
    const ChainWalk walk = walk_chain(adjacency_, A, B, [&](int c, int w) {
      const Vec2 p = m_.vertices[w];
      return near_segment(p, pa, pb) && dot_sign(p, m_.vertices[c], pb) == Sign::Negative;
    });
    const int c = walk.chain.back();
    if (walk.end == ChainWalk::End::Stuck) {
      sink_.add(CheckKind::MissingEdge, {static_cast<std::int64_t>(s)},
                name + " is not a chain of mesh edges: no mesh edge continues along it from mesh vertex " +
                    std::to_string(c) + " at " + format_point(m_.vertices[c]) + " towards mesh vertex " +
                    std::to_string(B));
      continue;
    }
    if (walk.end == ChainWalk::End::Forked) {
      sink_.add(CheckKind::NonConforming, {c, walk.next, walk.other},
                "mesh edges from vertex " + std::to_string(c) + " to " + std::to_string(walk.next) + " and " +
                    std::to_string(walk.other) + " both run along " + name + " (overlapping edges)");
      continue;
    }
    segment_ok_[s] = 1;
    chain_items_.insert(chain_items_.end(), walk.chain.begin(), walk.chain.end());
  }
  chain_offset_[ns] = static_cast<int>(chain_items_.size());
  if (skipped) sink_.note(std::to_string(skipped) + " input segment(s) not walked because an endpoint is missing");
}

// Stage 4 (b) of check2d.cpp: the boundary edges against the loops, sides replaced by their chains.
void Checker2::check_boundary_chain(const Domain2& d) {
  // Segment lookup by endpoints.
  std::vector<std::array<int, 3>> seg_index;  // lo, hi, segment
  for (std::size_t s = 0; s < d.pslg.segments.size(); ++s) {
    const auto& e = d.pslg.segments[s];
    seg_index.push_back({std::min(e[0], e[1]), std::max(e[0], e[1]), static_cast<int>(s)});
  }
  std::sort(seg_index.begin(), seg_index.end());
  struct R {
    int lo, hi, weight;
    int source;  // >= 0: boundary edge index; < 0: -1 - segment id
  };
  std::vector<R> recs;
  for (const auto& loop : d.loops) {
    const std::size_t n = loop.size();
    for (std::size_t k = 0; k < n; ++k) {
      const int u = loop[k], v = loop[(k + 1) % n];
      const std::array<int, 3> key{std::min(u, v), std::max(u, v), -1};
      auto it = std::lower_bound(seg_index.begin(), seg_index.end(), key);
      if (it == seg_index.end() || (*it)[0] != key[0] || (*it)[1] != key[1])
        throw DomainError(ErrorCode::InvalidPolygon,
                          "inconsistent Domain2: loop side (" + std::to_string(u) + " " + std::to_string(v) +
                              ") is not an input segment (build domains with make_domain)",
                          {u, v});
      const int s = (*it)[2];
      if (!segment_ok_[s]) {
        sink_.note("boundary not compared with the domain: input segment " + std::to_string(s) + " is missing");
        return;
      }
      const bool along = d.pslg.segments[s][0] == u;
      for (int j = chain_offset_[s]; j + 1 < chain_offset_[s + 1]; ++j) {
        int x = chain_items_[j], y = chain_items_[j + 1];
        if (!along) std::swap(x, y);
        recs.push_back(x < y ? R{x, y, -1, -1 - s} : R{y, x, 1, -1 - s});
      }
    }
  }
  for (std::size_t i = 0; i < boundary_.size(); ++i) {
    const int x = boundary_[i][0], y = boundary_[i][1];
    recs.push_back(x < y ? R{x, y, 1, static_cast<int>(i)} : R{y, x, -1, static_cast<int>(i)});
  }
  std::sort(recs.begin(), recs.end(), [](const R& a, const R& b) {
    if (a.lo != b.lo) return a.lo < b.lo;
    if (a.hi != b.hi) return a.hi < b.hi;
    return a.source < b.source;
  });
  for (std::size_t i = 0; i < recs.size();) {
    std::size_t j = i;
    int sum = 0, edge = -1, segment = -1;
    while (j < recs.size() && recs[j].lo == recs[i].lo && recs[j].hi == recs[i].hi) {
      sum += recs[j].weight;
      if (recs[j].source >= 0)
        edge = recs[j].source;
      else
        segment = -1 - recs[j].source;
      ++j;
    }
    if (sum != 0) {
      const std::string pair = "(" + std::to_string(recs[i].lo) + " " + std::to_string(recs[i].hi) + ")";
      std::string what;
      if (segment < 0)
        what = "boundary edge " + pair + " of triangle " + std::to_string(boundary_tri_[edge]) +
               " is not on the domain boundary";
      else if (edge < 0)
        what = "domain boundary piece " + pair + " of input segment " + std::to_string(segment) +
               " is not a boundary edge of the mesh";
      else
        what = "boundary edge " + pair + " of triangle " + std::to_string(boundary_tri_[edge]) +
               " runs against the domain boundary (input segment " + std::to_string(segment) +
               "): the mesh lies outside";
      sink_.add(CheckKind::BoundaryFace, {recs[i].lo, recs[i].hi}, what);
    }
    i = j;
  }
}

// No mesh vertex in the relative interior of an input segment: the interior
// vertices of every segment chain, and any boundary vertex that is not an
// input vertex (the boundary is the union of the loop segments).
void Checker2::check_steiner() {
  std::vector<char> flag(m_.vertices.size(), 0);
  for (std::size_t s = 0; s + 1 < chain_offset_.size(); ++s)
    for (int j = chain_offset_[s] + 1; j + 1 < chain_offset_[s + 1]; ++j) flag[chain_items_[j]] = 1;
  for (const auto& e : boundary_)
    for (int v : e)
      if (mesh2in_[v] < 0) flag[v] = 1;
  for (std::size_t v = 0; v < flag.size(); ++v)
    if (flag[v])
      sink_.add(CheckKind::SteinerOnBoundary, {static_cast<std::int64_t>(v)},
                "mesh vertex " + std::to_string(v) + " at " + format_point(m_.vertices[v]) +
                    " lies in the relative interior of an input segment");
}

void Checker2::check_located(const Domain2& d) {
  if (d.loops.empty()) {
    sink_.note("vertex location skipped: the domain has no loops (not built by make_domain?)");
    return;
  }
  // Vertices of the segment chains are on the boundary by stage 4 (a rounded
  // Steiner point may lie an ulp outside; near_segment accepted it).
  std::vector<char> on_chain(m_.vertices.size(), 0);
  for (const int v : chain_items_) on_chain[static_cast<std::size_t>(v)] = 1;
  const DomainLocator2 locator(d);
  for (std::size_t v = 0; v < m_.vertices.size(); ++v)
    if (!on_chain[v] && locator.locate(m_.vertices[v]) == Location::Outside)
      sink_.add(CheckKind::VertexOutside, {static_cast<std::int64_t>(v)},
                "vertex " + std::to_string(v) + " at " + format_point(m_.vertices[v]) + " is outside the domain");
}

}  // namespace pqmesh::detail::check2d
