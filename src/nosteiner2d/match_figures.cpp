// Thesis §5.4 "Match faces" (match_figures.hpp): the trapezoids and triangles
// between dQ and dR, with the subdivision of each R side F by R's mesh.
//
// The subdivision is read off R's mesh combinatorially: the directed boundary
// edges of the mesh (a triangle edge whose reverse is on no triangle; R's
// interior on the left, like R's loops) form one cycle per R loop; R's loop
// vertices are found in it by identical coordinates (quad_mesh keeps input
// vertices exactly), and the mesh vertices between two consecutive loop
// vertices are the ones on that side. Nothing here is a geometric decision.
#include "nosteiner2d/match_figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <utility>

#include "pqmesh/errors.hpp"

namespace pqmesh::detail {

namespace {

double length(Vec2 a, Vec2 b) { return std::hypot(b.x - a.x, b.y - a.y); }

// next_on_boundary[v] = w for the directed boundary edge v -> w, -1 when v is
// not on the boundary. Throws when a vertex has two outgoing boundary edges
// (R's loops are disjoint, so the boundary is a set of disjoint cycles).
std::vector<int> boundary_successor(const TriMesh2& mesh) {
  // Every triangle edge under its undirected key, sorted: a key that occurs
  // once is a boundary edge, directed as in its triangle.
  struct Half {
    std::uint64_t key;
    int from, to;
  };
  std::vector<Half> halves;
  halves.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) {
      const int a = t[std::size_t(i)], b = t[std::size_t((i + 1) % 3)];
      const auto lo = std::uint64_t(std::min(a, b)), hi = std::uint64_t(std::max(a, b));
      halves.push_back({(lo << 32) | hi, a, b});
    }
  std::sort(halves.begin(), halves.end(), [](const Half& x, const Half& y) { return x.key < y.key; });
  std::vector<int> next(mesh.vertices.size(), -1);
  for (std::size_t i = 0; i < halves.size();) {
    std::size_t j = i;
    while (j < halves.size() && halves[j].key == halves[i].key) ++j;
    if (j - i == 1) {
      const Half& h = halves[i];
      if (next[std::size_t(h.from)] != -1)
        throw InternalError("match_figures: R's mesh boundary is not a set of simple cycles");
      next[std::size_t(h.from)] = h.to;
    }
    i = j;
  }
  return next;
}

}  // namespace

std::vector<MatchFigure> match_figures(const PolygonQ& q, const PolygonR& r, const TriMesh2& r_mesh) {
  const int nq = int(q.wedges.vertices.size());
  const std::vector<int> next = boundary_successor(r_mesh);
  std::map<std::pair<double, double>, int> on_boundary;  // coordinates -> mesh vertex, boundary only
  for (std::size_t v = 0; v < next.size(); ++v)
    if (next[v] != -1) on_boundary.emplace(std::pair{r_mesh.vertices[v].x, r_mesh.vertices[v].y}, int(v));

  std::vector<MatchFigure> figs;
  for (std::size_t l = 0; l < r.loops.size(); ++l) {
    const auto& lp = r.loops[l];
    const auto& ql = q.loops[l];
    const std::size_t m = lp.size(), n = ql.size();
    const int first = int(figs.size());
    std::vector<int> ids(m);
    for (std::size_t j = 0; j < m; ++j) {
      const auto it = on_boundary.find({lp[j].x, lp[j].y});
      if (it == on_boundary.end())
        throw InternalError("match_figures: R loop " + std::to_string(l) + " vertex " + std::to_string(j) +
                            " is not a boundary vertex of R's mesh");
      ids[j] = it->second;
    }
    for (std::size_t j = 0; j < m; ++j) {
      MatchFigure f;
      f.loop = int(l);
      f.side = int(j);
      f.a = lp[j];
      f.b = lp[(j + 1) % m];
      const int src = r.side_source[l][j];
      f.is_triangle = src < 0;
      const std::size_t kp = std::size_t(r.vertex_source[l][j]);
      const std::size_t kq = std::size_t(r.vertex_source[l][(j + 1) % m]);
      f.p_id = ql[kp];
      f.q_id = ql[kq];
      f.p = q.wedges.vertices[std::size_t(f.p_id)];
      f.q = q.wedges.vertices[std::size_t(f.q_id)];
      if (f.is_triangle != (kp == kq) || (!f.is_triangle && kq != (kp + 1) % n))
        throw InternalError("match_figures: R side sources do not match Q's sides");
      f.delta = r.side_delta[l][j];
      f.length = f.is_triangle ? length(f.a, f.b) : length(f.p, f.q);
      // The vertices of R's mesh on F: from a's mesh vertex to b's.
      int v = ids[j];
      const int stop = ids[(j + 1) % m];
      for (std::size_t guard = 0;; ++guard) {
        f.f_ids.push_back(v + nq);
        f.f.push_back(r_mesh.vertices[std::size_t(v)]);
        if (v == stop) break;
        v = next[std::size_t(v)];
        if (v < 0 || guard > next.size())
          throw InternalError("match_figures: R's mesh boundary does not run through R's loop vertices in order");
      }
      if (f.f.size() < 2) throw InternalError("match_figures: an R side has no mesh edge");
      f.prev = first + int((j + m - 1) % m);
      f.next = first + int((j + 1) % m);
      figs.push_back(std::move(f));
    }
  }
  // The angle scale of Lemmas 45-47: delta(E)/L(E) for a trapezoid; a match
  // triangle takes the smaller of its two neighbouring trapezoids' (§5.4.2).
  for (auto& f : figs)
    if (!f.is_triangle) f.scale = f.delta / f.length;
  for (auto& f : figs)
    if (f.is_triangle) {
      const auto& pr = figs[std::size_t(f.prev)];
      const auto& nx = figs[std::size_t(f.next)];
      f.scale = std::min(pr.is_triangle ? 1.0 : pr.scale, nx.is_triangle ? 1.0 : nx.scale);
    }
  return figs;
}

}  // namespace pqmesh::detail
