// The validity checker for triangle meshes (DESIGN.md §7).
//
// The 2D analogue of check3d.cpp, whose comment block gives the argument in
// full; here one dimension lower:
//
// Stage 2: orient2d(a, b, c) > 0 for every triangle (mesh.hpp's convention).
//
// Stage 3: edges (sorted vertex pairs) are collected by a counting sort on the
//   smaller vertex. An edge lies on one or two triangles, and two triangles
//   sharing it traverse it in opposite directions (they lie on opposite sides).
//   With T the sum of the triangles as oriented 2-chains and B the edges on one
//   triangle, directed with the triangle on their left, this gives dT = B. B
//   must be a union of closed curves through distinct vertices: every vertex
//   of B has exactly one outgoing and one incoming edge of B. A vertex lying on
//   an edge of B other than its ends (a hanging vertex) is searched for from
//   the edge's ends along edges of B.
//
// Stage 4 (with the domain: loops with the interior on their left):
//   (a) every input segment is walked from its first to its second vertex
//       along mesh edges, each step to the unique neighbour on the segment
//       strictly closer to the end (orient2d = 0, dot_sign < 0); failure is
//       MissingEdge. Interior segments, if a domain has them, are walked the
//       same way.
//   (b) B, as signed counts of undirected mesh edges, must equal the loops
//       with every side replaced by its chain from (a).
//
// Sufficiency: by (b) B = dP as 1-chains (a combinatorial equality implies the
// geometric one), so T - P is a 2-chain without boundary, hence zero: with all
// triangles positive, almost every point of P is covered exactly once and no
// point outside P is covered. As in 3D this also excludes hanging vertices
// (a vertex in the relative interior of an edge s: if s is interior, the two
// triangles on s cover a neighbourhood of the vertex that its own triangles
// cover too; if s is on dP, s is a union of chain pieces from (a), and the
// vertex would be on the boundary twice), every input vertex is found by exact
// coordinates and every input segment is a chain of mesh edges by (a).
// Without a domain only stages 1-3 run (local conditions).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/check_common.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/errors.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh {
namespace {

using detail::format_ids;
using detail::format_point;
using detail::IssueSink;

bool in_box(Vec2 p, Vec2 a, Vec2 b) {
  return p.x >= std::min(a.x, b.x) && p.x <= std::max(a.x, b.x) && p.y >= std::min(a.y, b.y) &&
         p.y <= std::max(a.y, b.y);
}

// p on the closed segment ab (exact).
bool on_segment(Vec2 p, Vec2 a, Vec2 b) { return in_box(p, a, b) && orient2d(a, b, p) == Sign::Zero; }

class Checker2 {
 public:
  Checker2(const TriMesh2& mesh, const CheckOptions& options, CheckReport& report)
      : m_(mesh), opt_(options), rep_(report), sink_(report, options.max_issues_per_kind) {
    rep_.dimension = 2;
    rep_.vertices = static_cast<std::int64_t>(mesh.vertices.size());
    rep_.elements = static_cast<std::int64_t>(mesh.triangles.size());
  }

  bool run_topology() {
    stage1_ok_ = stage1_indices();
    if (!stage1_ok_) {
      sink_.note("orientation, conformity and domain checks skipped: the mesh has bad indices or coordinates");
      return false;
    }
    order_ = detail::sort_by_coordinates(m_.vertices);
    if (!stage2_orientation()) {
      sink_.note("conformity and domain checks skipped: not every triangle is positively oriented");
      return false;
    }
    measure_area();
    const bool ok = stage3_edges();
    if (!ok) sink_.note("domain checks of boundary edges and segments skipped: the triangles do not meet edge to edge");
    return ok;
  }

  void run_domain(const Domain2& d, bool topology_ok) {
    rep_.domain_checked = true;
    rep_.domain_volume = d.area;
    if (!stage1_ok_) return;
    map_input_vertices(d);
    if (topology_ok) {
      walk_segments(d);
      check_boundary_chain(d);
      if (opt_.no_boundary_steiner) check_steiner();
    }
    if (rep_.volume_measured && detail::relative_difference(rep_.mesh_volume, d.area) > opt_.volume_tolerance) {
      sink_.add(CheckKind::Volume, {},
                "total area " + detail::format_number(rep_.mesh_volume) + " differs from the domain's " +
                    detail::format_number(d.area) + " (relative difference " +
                    detail::format_short(detail::relative_difference(rep_.mesh_volume, d.area)) + " > tolerance " +
                    detail::format_short(opt_.volume_tolerance) + "; a floating-point measurement)");
    }
    if (opt_.locate_vertices) check_located(d);
  }

 private:
  // ---- stage 1 -------------------------------------------------------------
  bool stage1_indices() {
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
    auto sized = [&](std::size_t markers, std::size_t items, const char* what) {
      if (markers != 0 && markers != items)
        sink_.add(CheckKind::BadIndex, {},
                  std::string(what) + " has " + std::to_string(markers) + " entries for " + std::to_string(items) +
                      " items (must be empty or equal)");
    };
    sized(m_.vertex_markers.size(), m_.vertices.size(), "vertex_markers");
    sized(m_.triangle_markers.size(), m_.triangles.size(), "triangle_markers");
    sized(m_.edge_markers.size(), m_.edges.size(), "edge_markers");
    if (m_.triangles.size() >= (std::size_t{1} << 31) - 1)
      sink_.add(CheckKind::BadIndex, {}, "more triangles than int indices can address");
    return sink_.count(CheckKind::BadIndex) == before;
  }

  // ---- stage 2 -------------------------------------------------------------
  bool stage2_orientation() {
    bool ok = true;
    for (std::size_t t = 0; t < m_.triangles.size(); ++t) {
      const auto& q = m_.triangles[t];
      const Sign s = orient2d(m_.vertices[q[0]], m_.vertices[q[1]], m_.vertices[q[2]]);
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
    return ok;
  }

  void measure_area() {
    detail::CompensatedSum sum;
    for (const auto& q : m_.triangles) {
      const Vec2 a = m_.vertices[q[0]];
      sum.add(cross(m_.vertices[q[1]] - a, m_.vertices[q[2]] - a) / 2.0);
    }
    rep_.volume_measured = true;
    rep_.mesh_volume = sum.value();
  }

  // ---- stage 3 -------------------------------------------------------------
  bool stage3_edges() {
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
    std::vector<Rec> recs(start[nv]);
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
    std::vector<char> used(nv, 0);
    for (const auto& q : m_.triangles)
      for (int v : q) used[v] = 1;

    std::vector<std::array<int, 2>> all_edges;
    for (int a = 0; a < nv; ++a) {
      auto first = recs.begin() + start[a], last = recs.begin() + start[a + 1];
      std::sort(first, last, [](const Rec& x, const Rec& y) { return x.hi != y.hi ? x.hi < y.hi : x.code < y.code; });
      for (auto it = first; it != last;) {
        auto run_end = it + 1;
        while (run_end != last && run_end->hi == it->hi) ++run_end;
        const long count = run_end - it;
        const int b = it->hi;
        all_edges.push_back({a, b});
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
    rep_.boundary_faces = static_cast<std::int64_t>(boundary_.size());
    adjacency_ = detail::make_adjacency(nv, all_edges);
    all_edges_ = std::move(all_edges);

    for (int v = 0; v < nv; ++v)
      if (!used[v])
        sink_.add(CheckKind::UnusedVertex, {v},
                  "vertex " + std::to_string(v) + " at " + format_point(m_.vertices[v]) + " is on no triangle");

    for (std::size_t i = 0; i + 1 < order_.size();) {
      std::size_t j = i + 1;
      while (j < order_.size() && m_.vertices[order_[j]] == m_.vertices[order_[i]]) ++j;
      if (j - i > 1) {
        std::vector<std::int64_t> ids(order_.begin() + static_cast<long>(i), order_.begin() + static_cast<long>(j));
        std::vector<int> vs(order_.begin() + static_cast<long>(i), order_.begin() + static_cast<long>(j));
        sink_.add(CheckKind::NonConforming, std::move(ids),
                  "vertices " + format_ids(vs) + " have the same coordinates " +
                      format_point(m_.vertices[order_[i]]));
      }
      i = j;
    }

    boundary_adjacency_ = detail::make_adjacency(nv, boundary_);
    find_hanging_vertices();
    const bool conforming = sink_.count(CheckKind::NonConforming) == nonconf_before;
    // A hanging vertex also unbalances the boundary at the vertices around it;
    // report the manifold condition only when the elements meet edge to edge.
    const bool manifold = !conforming || check_boundary_manifold();
    check_listed_edges();
    return conforming && manifold;
  }

  bool check_boundary_manifold() {
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

  void find_hanging_vertices() {
    std::vector<char> reported(m_.vertices.size(), 0);
    std::vector<int> queue;
    constexpr std::size_t kMaxExpansion = 1024;
    bool capped = false;
    for (std::size_t i = 0; i < boundary_.size(); ++i) {
      const auto& e = boundary_[i];
      const Vec2 a = m_.vertices[e[0]], b = m_.vertices[e[1]];
      queue.assign(e.begin(), e.end());
      for (std::size_t head = 0; head < queue.size(); ++head) {
        for (int w : boundary_adjacency_.of(queue[head])) {
          if (std::find(queue.begin(), queue.end(), w) != queue.end()) continue;
          const Vec2 p = m_.vertices[w];
          if (!on_segment(p, a, b)) continue;
          if (queue.size() >= kMaxExpansion) {
            capped = true;
            break;
          }
          queue.push_back(w);
          if (!reported[w]) {
            reported[w] = 1;
            sink_.add(CheckKind::NonConforming, {w, e[0], e[1]},
                      "vertex " + std::to_string(w) + " at " + format_point(p) + " lies on boundary edge (" +
                          format_ids(e) + ") of triangle " + std::to_string(boundary_tri_[i]) +
                          " (hanging vertex: the triangles there do not meet edge to edge)");
          }
        }
      }
    }
    if (capped) sink_.note("hanging-vertex search capped at " + std::to_string(kMaxExpansion) + " vertices per edge");
  }

  // TriMesh2::edges, when given, may list input segments inside the domain
  // too, so: every listed edge is a mesh edge (once), and every boundary edge
  // is listed. Direction is not prescribed.
  void check_listed_edges() {
    if (m_.edges.empty()) return;
    struct K {
      int lo, hi;
      int source;  // listed index >= 0; -1 mesh edge on one triangle; -2 on two
    };
    std::vector<K> keys;
    for (const auto& e : boundary_) keys.push_back({std::min(e[0], e[1]), std::max(e[0], e[1]), -1});
    {
      std::vector<std::array<int, 2>> b = boundary_;
      for (auto& e : b)
        if (e[0] > e[1]) std::swap(e[0], e[1]);
      std::sort(b.begin(), b.end());
      for (const auto& e : all_edges_)
        if (!std::binary_search(b.begin(), b.end(), e)) keys.push_back({e[0], e[1], -2});
    }
    for (std::size_t i = 0; i < m_.edges.size(); ++i) {
      const auto& e = m_.edges[i];
      keys.push_back({std::min(e[0], e[1]), std::max(e[0], e[1]), static_cast<int>(i)});
    }
    std::sort(keys.begin(), keys.end(), [](const K& a, const K& b) {
      if (a.lo != b.lo) return a.lo < b.lo;
      if (a.hi != b.hi) return a.hi < b.hi;
      return a.source < b.source;  // mesh edge records first
    });
    for (std::size_t i = 0; i < keys.size();) {
      std::size_t j = i;
      while (j < keys.size() && keys[j].lo == keys[i].lo && keys[j].hi == keys[i].hi) ++j;
      const bool mesh_edge = keys[i].source < 0;
      const std::size_t first_listed = mesh_edge ? i + 1 : i;
      if (mesh_edge && keys[i].source == -1 && first_listed == j)
        sink_.add(CheckKind::BoundaryFace, {keys[i].lo, keys[i].hi},
                  "boundary edge (" + std::to_string(keys[i].lo) + " " + std::to_string(keys[i].hi) +
                      ") is missing from TriMesh2::edges");
      for (std::size_t k = first_listed; k < j; ++k) {
        const int l = keys[k].source;
        const std::string head =
            "listed edge " + std::to_string(l) + " (" + format_ids(m_.edges[l]) + ") ";
        if (!mesh_edge)
          sink_.add(CheckKind::BoundaryFace, {l}, head + "is not an edge of the mesh");
        else if (k > first_listed)
          sink_.add(CheckKind::BoundaryFace, {l}, head + "is listed more than once");
      }
      i = j;
    }
  }

  // ---- stage 4 -------------------------------------------------------------
  void map_input_vertices(const Domain2& d) {
    const auto& pv = d.pslg.vertices;
    in2mesh_.assign(pv.size(), -1);
    mesh2in_.assign(m_.vertices.size(), -1);
    std::vector<char> referenced(pv.size(), 0);
    for (const auto& s : d.pslg.segments)
      for (int v : s)
        if (v >= 0 && v < static_cast<int>(pv.size())) referenced[v] = 1;
    for (const auto& loop : d.loops)
      for (int v : loop)
        if (v >= 0 && v < static_cast<int>(pv.size())) referenced[v] = 1;
    int unreferenced = 0;
    for (std::size_t i = 0; i < pv.size(); ++i) {
      const int mv = detail::find_vertex(m_.vertices, order_, pv[i]);
      in2mesh_[i] = mv;
      if (mv >= 0) mesh2in_[mv] = static_cast<int>(i);
      if (!referenced[i]) {
        ++unreferenced;
        continue;
      }
      if (mv < 0)
        sink_.add(CheckKind::MissingVertex, {static_cast<std::int64_t>(i)},
                  "input vertex " + std::to_string(i) + " at " + format_point(pv[i]) + " is not a mesh vertex");
    }
    if (unreferenced)
      sink_.note(std::to_string(unreferenced) + " input vertices on no segment were not required to be mesh vertices");
  }

  void walk_segments(const Domain2& d) {
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
      std::vector<int> chain{A};
      int c = A;
      bool ok = true;
      const std::string name = "input segment " + std::to_string(s) + " (" + format_ids(seg) + ")";
      while (c != B) {
        int next = -1, found = 0, other = -1;
        for (int w : adjacency_.of(c)) {
          bool on = w == B;
          if (!on) {
            const Vec2 p = m_.vertices[w];
            on = on_segment(p, pa, pb) && dot_sign(p, m_.vertices[c], pb) == Sign::Negative;
          }
          if (!on) continue;
          if (found++ == 0)
            next = w;
          else
            other = w;
        }
        if (found == 0) {
          sink_.add(CheckKind::MissingEdge, {static_cast<std::int64_t>(s)},
                    name + " is not a chain of mesh edges: no mesh edge continues along it from mesh vertex " +
                        std::to_string(c) + " at " + format_point(m_.vertices[c]) + " towards mesh vertex " +
                        std::to_string(B));
          ok = false;
          break;
        }
        if (found > 1) {
          sink_.add(CheckKind::NonConforming, {c, next, other},
                    "mesh edges from vertex " + std::to_string(c) + " to " + std::to_string(next) + " and " +
                        std::to_string(other) + " both run along " + name + " (overlapping edges)");
          ok = false;
          break;
        }
        chain.push_back(next);
        c = next;
      }
      if (!ok) continue;
      segment_ok_[s] = 1;
      chain_items_.insert(chain_items_.end(), chain.begin(), chain.end());
    }
    chain_offset_[ns] = static_cast<int>(chain_items_.size());
    if (skipped) sink_.note(std::to_string(skipped) + " input segment(s) not walked because an endpoint is missing");
  }

  // (b): the boundary edges against the loops, sides replaced by their chains.
  void check_boundary_chain(const Domain2& d) {
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
  void check_steiner() {
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

  void check_located(const Domain2& d) {
    if (d.loops.empty()) {
      sink_.note("vertex location skipped: the domain has no loops (not built by make_domain?)");
      return;
    }
    for (std::size_t v = 0; v < m_.vertices.size(); ++v)
      if (locate(d, m_.vertices[v]) == Location::Outside)
        sink_.add(CheckKind::VertexOutside, {static_cast<std::int64_t>(v)},
                  "vertex " + std::to_string(v) + " at " + format_point(m_.vertices[v]) + " is outside the domain");
  }

  const TriMesh2& m_;
  const CheckOptions& opt_;
  CheckReport& rep_;
  IssueSink sink_;
  bool stage1_ok_ = false;
  std::vector<int> order_;
  std::vector<std::array<int, 2>> boundary_;  // directed, triangle on the left
  std::vector<int> boundary_tri_;
  std::vector<std::array<int, 2>> all_edges_;  // unique, (lo, hi), sorted
  detail::Adjacency adjacency_, boundary_adjacency_;
  std::vector<int> in2mesh_, mesh2in_;
  std::vector<int> chain_offset_, chain_items_;
  std::vector<char> segment_ok_;
};

}  // namespace

CheckReport check_mesh_topology(const TriMesh2& mesh, const CheckOptions& options) {
  CheckReport report;
  Checker2 checker(mesh, options, report);
  checker.run_topology();
  return report;
}

CheckReport check_mesh(const TriMesh2& mesh, const Domain2& domain, const CheckOptions& options) {
  CheckReport report;
  Checker2 checker(mesh, options, report);
  const bool ok = checker.run_topology();
  checker.run_domain(domain, ok);
  return report;
}

}  // namespace pqmesh
