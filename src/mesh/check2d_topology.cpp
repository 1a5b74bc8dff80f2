// Stages 1-3 of the triangle-mesh checker: indices and coordinates,
// orientation (and the area measurement), edge matching, hanging vertices,
// boundary made of simple closed curves, listed edges. Why these are the right
// conditions: check2d.cpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "mesh/check2d_stages.hpp"
#include "geometry/large_page_allocator.hpp"

namespace pqmesh::detail::check2d {

// ---- stage 1 -------------------------------------------------------------
bool Checker2::stage1_indices() {
  const auto nv = static_cast<std::int64_t>(m_.vertices.size());
  const std::int64_t before = sink_.count(CheckKind::BadIndex);
  for (std::int64_t v = 0; v < nv; ++v) {
    const Vec2 p = m_.vertices[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      sink_.add(CheckKind::BadIndex, {v}, "vertex " + std::to_string(v) + " has a non-finite coordinate");
  }
  auto bad = [&](int i) { return i < 0 || i >= nv; };
  for (std::size_t t = 0; t < m_.triangles.size(); ++t) {
    const auto& q = m_.triangles[t];
    if (bad(q[0]) || bad(q[1]) || bad(q[2]))
      sink_.add(CheckKind::BadIndex, {static_cast<std::int64_t>(t)},
                "triangle " + std::to_string(t) + " (" + format_ids(q) + ") refers to a vertex outside 0.." +
                    std::to_string(nv - 1));
  }
  for (std::size_t e = 0; e < m_.edges.size(); ++e) {
    const auto& q = m_.edges[e];
    if (bad(q[0]) || bad(q[1]))
      sink_.add(CheckKind::BadIndex, {static_cast<std::int64_t>(e)},
                "listed edge " + std::to_string(e) + " (" + format_ids(q) + ") refers to a vertex outside 0.." +
                    std::to_string(nv - 1));
  }
  check_marker_count(sink_, m_.vertex_markers.size(), m_.vertices.size(), "vertex_markers");
  check_marker_count(sink_, m_.triangle_markers.size(), m_.triangles.size(), "triangle_markers");
  check_marker_count(sink_, m_.edge_markers.size(), m_.edges.size(), "edge_markers");
  if (m_.triangles.size() >= (std::size_t{1} << 31) - 1)
    sink_.add(CheckKind::BadIndex, {}, "more triangles than int indices can address");
  return sink_.count(CheckKind::BadIndex) == before;
}

// ---- stage 2 -------------------------------------------------------------
// One read of the triangles and their corners for both the orientation test
// and the area sum (the sum in triangle order, as a separate pass would add
// it); the area counts only when every triangle is positively oriented
// (run_topology stops otherwise).
bool Checker2::stage2_orientation() {
  bool ok = true;
  CompensatedSum sum;
  for (std::size_t t = 0; t < m_.triangles.size(); ++t) {
    const auto& q = m_.triangles[t];
    const Vec2 a = m_.vertices[q[0]], b = m_.vertices[q[1]], c = m_.vertices[q[2]];
    sum.add(cross(b - a, c - a) / 2.0);
    const Sign s = orient2d(a, b, c);
    if (s == Sign::Positive) continue;
    ok = false;
    const auto id = static_cast<std::int64_t>(t);
    if (s == Sign::Zero)
      sink_.add(CheckKind::DegenerateElement, {id},
                "triangle " + std::to_string(t) + " (" + format_ids(q) + ") has zero area");
    else
      sink_.add(CheckKind::Orientation, {id},
                "triangle " + std::to_string(t) + " (" + format_ids(q) + ") is clockwise (orient2d < 0)");
  }
  if (ok) {
    rep_.volume_measured = true;
    rep_.mesh_volume = sum.value();
  }
  return ok;
}

// ---- stage 3 -------------------------------------------------------------

bool Checker2::stage3_edges() {
  const int nv = static_cast<int>(m_.vertices.size());
  const int nt = static_cast<int>(m_.triangles.size());
  const std::int64_t nonconf_before = sink_.count(CheckKind::NonConforming);
  struct Rec {
    int hi;
    std::uint32_t code;  // (triangle << 1) | 1 when the triangle runs hi -> lo
  };
  std::vector<int> start(static_cast<std::size_t>(nv) + 1, 0);
  for (const auto& q : m_.triangles)
    for (int k = 0; k < 3; ++k) ++start[std::min(q[k], q[(k + 1) % 3]) + 1];
  for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<Rec, LargePageAllocator<Rec>> recs(start[nv]);
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int t = 0; t < nt; ++t) {
      const auto& q = m_.triangles[t];
      for (int k = 0; k < 3; ++k) {
        const int x = q[k], y = q[(k + 1) % 3];
        const std::uint32_t code = (static_cast<std::uint32_t>(t) << 1) | (x > y ? 1u : 0u);
        recs[fill[std::min(x, y)]++] = Rec{std::max(x, y), code};
      }
    }
  }
  // Each vertex's records sorted by (hi, code): most lists are a handful of
  // records (insertion sort), a long fan goes to std::sort. The distinct
  // edges (a, b), a < b, are counted per vertex for the adjacency, which is
  // then filled in the order (a, b) of the edges: the neighbours of v arrive
  // in increasing order (first the w < v of the edges (w, v), by w, then the
  // w > v of the edges (v, w), by w), so the lists come out sorted and
  // without repeats with no sorting.
  const auto rec_less = [](const Rec& x, const Rec& y) { return x.hi != y.hi ? x.hi < y.hi : x.code < y.code; };
  Adjacency adj;
  adj.offset.assign(static_cast<std::size_t>(nv) + 1, 0);
  for (int a = 0; a < nv; ++a) {
    const auto first = recs.begin() + start[a], last = recs.begin() + start[a + 1];
    if (last - first > 16) {
      std::sort(first, last, rec_less);
    } else {
      for (auto i = first + (first != last); i < last; ++i)
        for (auto j = i; j != first && rec_less(*j, *(j - 1)); --j) std::iter_swap(j, j - 1);
    }
    for (auto it = first; it != last; ++it)
      if (it == first || it->hi != (it - 1)->hi) {
        ++adj.offset[static_cast<std::size_t>(a) + 1];
        ++adj.offset[static_cast<std::size_t>(it->hi) + 1];
      }
  }
  for (std::size_t v = 0; v < static_cast<std::size_t>(nv); ++v) adj.offset[v + 1] += adj.offset[v];
  adj.items.resize(static_cast<std::size_t>(adj.offset[static_cast<std::size_t>(nv)]));
  std::vector<int> fill(adj.offset.begin(), adj.offset.end() - 1);
  for (int a = 0; a < nv; ++a) {
    auto first = recs.begin() + start[a], last = recs.begin() + start[a + 1];
    for (auto it = first; it != last;) {
      auto run_end = it + 1;
      while (run_end != last && run_end->hi == it->hi) ++run_end;
      const long count = run_end - it;
      const int b = it->hi;
      adj.items[static_cast<std::size_t>(fill[static_cast<std::size_t>(a)]++)] = b;
      adj.items[static_cast<std::size_t>(fill[static_cast<std::size_t>(b)]++)] = a;
      if (count == 1) {
        const bool reversed = (it->code & 1u) != 0;
        boundary_.push_back(reversed ? std::array<int, 2>{b, a} : std::array<int, 2>{a, b});
        boundary_tri_.push_back(static_cast<int>(it->code >> 1));
      } else if (count == 2) {
        if ((it->code & 1u) == ((it + 1)->code & 1u)) {
          const int t1 = static_cast<int>(it->code >> 1), t2 = static_cast<int>((it + 1)->code >> 1);
          sink_.add(CheckKind::NonConforming, {t1, t2},
                    "triangles " + std::to_string(t1) + " and " + std::to_string(t2) +
                        " lie on the same side of their common edge (" + std::to_string(a) + " " +
                        std::to_string(b) + "): they overlap");
        }
      } else {
        std::vector<std::int64_t> ids;
        std::vector<int> tris;
        for (auto r = it; r != run_end; ++r) {
          ids.push_back(r->code >> 1);
          tris.push_back(static_cast<int>(r->code >> 1));
        }
        sink_.add(CheckKind::NonConforming, std::move(ids),
                  "edge (" + std::to_string(a) + " " + std::to_string(b) + ") is on " + std::to_string(count) +
                      " triangles: " + format_ids(tris));
      }
      it = run_end;
    }
  }
  recs = {};
  fill = {};
  rep_.boundary_faces = static_cast<std::int64_t>(boundary_.size());
  adjacency_ = std::move(adj);

  report_unused_vertices(sink_, m_.vertices, m_.triangles, "triangle");
  report_coincident_vertices(sink_, m_.vertices, order_);

  boundary_adjacency_ = make_adjacency(nv, boundary_);
  find_hanging_vertices();
  const bool conforming = sink_.count(CheckKind::NonConforming) == nonconf_before;
  // A hanging vertex also unbalances the boundary at the vertices around it;
  // report the manifold condition only when the elements meet edge to edge.
  const bool manifold = !conforming || check_boundary_manifold();
  check_listed_edges();
  return conforming && manifold;
}

bool Checker2::check_boundary_manifold() {
  const int nv = static_cast<int>(m_.vertices.size());
  std::vector<int> out(nv, 0), in(nv, 0);
  for (const auto& e : boundary_) {
    ++out[e[0]];
    ++in[e[1]];
  }
  bool ok = true;
  for (int v = 0; v < nv; ++v) {
    if (out[v] == in[v] && out[v] <= 1) continue;
    ok = false;
    sink_.add(CheckKind::BoundaryFace, {v},
              "vertex " + std::to_string(v) + " at " + format_point(m_.vertices[v]) + " has " +
                  std::to_string(out[v]) + " outgoing and " + std::to_string(in[v]) +
                  " incoming boundary edges (a boundary made of simple closed curves needs one each)");
  }
  return ok;
}

void Checker2::find_hanging_vertices() {
  std::vector<char> reported(m_.vertices.size(), 0);
  std::vector<int> queue;
  bool capped = false;
  for (std::size_t i = 0; i < boundary_.size(); ++i) {
    const auto& e = boundary_[i];
    const Vec2 a = m_.vertices[e[0]], b = m_.vertices[e[1]];
    auto on = [&](int w) { return on_segment(m_.vertices[w], a, b); };
    auto found = [&](int w) {
      sink_.add(CheckKind::NonConforming, {w, e[0], e[1]},
                "vertex " + std::to_string(w) + " at " + format_point(m_.vertices[w]) + " lies on boundary edge (" +
                    format_ids(e) + ") of triangle " + std::to_string(boundary_tri_[i]) +
                    " (hanging vertex: the triangles there do not meet edge to edge)");
    };
    if (!search_hanging_vertices(boundary_adjacency_, e, reported, queue, on, found)) capped = true;
  }
  if (capped)
    sink_.note("hanging-vertex search capped at " + std::to_string(kMaxHangingExpansion) + " vertices per edge");
}

// TriMesh2::edges, when given, may list input segments inside the domain
// too, so: every listed edge is a mesh edge (once), and every boundary edge
// is listed. Direction is not prescribed.
void Checker2::check_listed_edges() {
  if (m_.edges.empty()) return;
  // Listed edges as (lo, hi, index), sorted; the adjacency lists are sorted,
  // so both directions are binary searches (no sort of every mesh edge).
  std::vector<std::array<int, 3>> listed;
  listed.reserve(m_.edges.size());
  for (std::size_t i = 0; i < m_.edges.size(); ++i) {
    const auto& e = m_.edges[i];
    listed.push_back({std::min(e[0], e[1]), std::max(e[0], e[1]), static_cast<int>(i)});
  }
  std::sort(listed.begin(), listed.end());
  for (const auto& e : boundary_) {
    const std::array<int, 3> lo{std::min(e[0], e[1]), std::max(e[0], e[1]), -1};
    const auto it = std::lower_bound(listed.begin(), listed.end(), lo);
    if (it == listed.end() || (*it)[0] != lo[0] || (*it)[1] != lo[1])
      sink_.add(CheckKind::BoundaryFace, {lo[0], lo[1]},
                "boundary edge (" + std::to_string(lo[0]) + " " + std::to_string(lo[1]) +
                    ") is missing from TriMesh2::edges");
  }
  for (std::size_t k = 0; k < listed.size(); ++k) {
    const int l = listed[k][2];
    const std::string head = "listed edge " + std::to_string(l) + " (" + format_ids(m_.edges[l]) + ") ";
    const std::array<int, 2> key{listed[k][0], listed[k][1]};
    const std::span<const int> around = adjacency_.of(key[0]);
    if (!std::binary_search(around.begin(), around.end(), key[1]))
      sink_.add(CheckKind::BoundaryFace, {l}, head + "is not an edge of the mesh");
    else if (k > 0 && listed[k - 1][0] == key[0] && listed[k - 1][1] == key[1])
      sink_.add(CheckKind::BoundaryFace, {l}, head + "is listed more than once");
  }
}

}  // namespace pqmesh::detail::check2d
