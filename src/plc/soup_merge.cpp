// Polygon-soup merging; the rules are stated in soup_merge.hpp.
//
// Exactness: every branch that decides coplanarity, facing, loop orientation
// or the turn taken at a pinch vertex is an exact predicate on input
// coordinates (orient3d, orient2d_projected, dot_sign). Doubles appear only in
// constructions: the choice of projection axis (verified exactly to be a
// non-degenerate projection), the normals compared against the near-merge
// angle (a user tolerance by definition), and snapped vertex positions (whose
// coplanarity is then verified exactly).
#include "plc/soup_merge.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "predicates/predicates.hpp"

namespace pqmesh::detail {

namespace {

// The projection that drops `drop` keeps the other axes in cyclic order (as orient2d_projected).
int u_axis(int drop) { return (drop + 1) % 3; }
int v_axis(int drop) { return (drop + 2) % 3; }

bool collinear(const Vec3& a, const Vec3& b, const Vec3& c) {
  // Exactly collinear in 3D iff collinear in all three coordinate projections.
  return orient2d_projected(a, b, c, 0) == Sign::Zero && orient2d_projected(a, b, c, 1) == Sign::Zero &&
         orient2d_projected(a, b, c, 2) == Sign::Zero;
}

// Newell's normal (twice the vector area) of a cyclic vertex list, taken
// relative to its first vertex to limit cancellation. A construction.
Vec3 newell_normal(const std::vector<Vec3>& V, const int* ids, int k) {
  const Vec3 o = V[ids[0]];
  Vec3 n;
  for (int i = 0; i < k; ++i) {
    const Vec3 p = V[ids[i]] - o;
    const Vec3 q = V[ids[(i + 1) % k]] - o;
    n = n + cross(p, q);
  }
  return n;
}

// Exact orientation of a simple cyclic vertex list in the projection dropping
// `drop`: the turn at its lexicographically smallest projected vertex (a hull
// vertex, so the turn there is the turn of the whole polygon). Zero for spikes
// or repeated points.
Sign cyclic_orientation(const std::vector<Vec3>& V, const int* ids, int k, int drop) {
  const int ua = u_axis(drop), va = v_axis(drop);
  int m = 0;
  for (int i = 1; i < k; ++i) {
    const Vec3& p = V[ids[i]];
    const Vec3& q = V[ids[m]];
    const double pu = axis_coord(p, ua), qu = axis_coord(q, ua);
    if (pu < qu || (pu == qu && axis_coord(p, va) < axis_coord(q, va))) m = i;
  }
  return orient2d_projected(V[ids[(m + k - 1) % k]], V[ids[m]], V[ids[(m + 1) % k]], drop);
}

struct PolyInfo {
  bool valid = false;          // simple enough to merge: distinct ids, not collinear, planar
  int a = -1, b = -1, c = -1;  // three non-collinear vertices spanning its plane
  int drop = 2;                // projection axis; the plane is not perpendicular to it (exact)
  Sign facing = Sign::Zero;    // orientation in that projection
  Vec3 normal;                 // Newell normal (construction)
};

PolyInfo polygon_info(const PolygonSoup& soup, int p, std::vector<int>& scratch) {
  PolyInfo info;
  const int k = soup.polygon_size(p);
  const int* ids = soup.indices.data() + soup.offsets[p];
  if (k < 3) return info;
  scratch.assign(ids, ids + k);
  std::sort(scratch.begin(), scratch.end());
  if (std::adjacent_find(scratch.begin(), scratch.end()) != scratch.end()) return info;
  const auto& V = soup.vertices;
  info.a = ids[0];
  info.b = ids[1];
  for (int j = 2; j < k && info.c < 0; ++j)
    if (!collinear(V[info.a], V[info.b], V[ids[j]])) info.c = ids[j];
  if (info.c < 0) return info;
  for (int j = 2; j < k; ++j)
    if (orient3d(V[info.a], V[info.b], V[info.c], V[ids[j]]) != Sign::Zero) return info;
  info.normal = newell_normal(V, ids, k);
  info.drop = dominant_axis(info.normal);
  // The double normal only suggests the axis; confirm exactly that the plane
  // projects onto it without collapsing.
  for (int t = 0; t < 3 && orient2d_projected(V[info.a], V[info.b], V[info.c], info.drop) == Sign::Zero; ++t)
    info.drop = t;
  info.facing = cyclic_orientation(V, ids, k, info.drop);
  info.valid = info.facing != Sign::Zero;
  return info;
}

// Per polygon slot (one per directed edge) the polygon across that edge, or -1
// when the edge is not shared by exactly two polygons in opposite directions.
std::vector<int> edge_neighbours(const PolygonSoup& soup, const std::vector<int>& slot_poly) {
  struct Use {
    int lo, hi, slot;
  };
  const int n_slots = static_cast<int>(soup.indices.size());
  std::vector<int> next_slot(static_cast<std::size_t>(n_slots));
  std::vector<Use> uses;
  uses.reserve(static_cast<std::size_t>(n_slots));
  for (int p = 0; p < soup.polygon_count(); ++p) {
    const int o = soup.offsets[p], k = soup.polygon_size(p);
    for (int j = 0; j < k; ++j) {
      const int s = o + j;
      next_slot[s] = o + (j + 1) % k;
      const int a = soup.indices[s], b = soup.indices[next_slot[s]];
      if (a != b) uses.push_back({std::min(a, b), std::max(a, b), s});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const Use& x, const Use& y) {
    return x.lo != y.lo ? x.lo < y.lo : (x.hi != y.hi ? x.hi < y.hi : x.slot < y.slot);
  });
  std::vector<int> neighbour(static_cast<std::size_t>(n_slots), -1);
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi) ++j;
    if (j - i == 2) {
      const int s = uses[i].slot, t = uses[i + 1].slot;
      const bool opposite = soup.indices[s] == soup.indices[next_slot[t]];
      if (opposite && slot_poly[s] != slot_poly[t]) {
        neighbour[s] = slot_poly[t];
        neighbour[t] = slot_poly[s];
      }
    }
    i = j;
  }
  return neighbour;
}

// Compressed lists: items of list g are items[start[g] .. start[g+1]).
struct Lists {
  std::vector<int> start, items;
  int size(int g) const { return start[g + 1] - start[g]; }
};

Lists invert(const std::vector<int>& owner, int n_owners) {
  Lists out;
  out.start.assign(static_cast<std::size_t>(n_owners) + 1, 0);
  for (int o : owner) ++out.start[o + 1];
  for (int g = 0; g < n_owners; ++g) out.start[g + 1] += out.start[g];
  out.items.resize(owner.size());
  std::vector<int> fill(out.start.begin(), out.start.end() - 1);
  for (int i = 0; i < static_cast<int>(owner.size()); ++i) out.items[fill[owner[i]]++] = i;
  return out;
}

class Merger {
 public:
  Merger(PolygonSoup& soup, double angle_degrees) : soup_(soup), angle_degrees_(angle_degrees) {}

  SoupMergeResult run() {
    const int np = soup_.polygon_count();
    slot_poly_.resize(soup_.indices.size());
    for (int p = 0; p < np; ++p)
      for (int s = soup_.offsets[p]; s < soup_.offsets[p + 1]; ++s) slot_poly_[s] = p;
    neighbour_ = edge_neighbours(soup_, slot_poly_);
    position_.assign(soup_.vertices.size(), -1);
    info_.resize(static_cast<std::size_t>(np));
    std::vector<int> scratch;
    for (int p = 0; p < np; ++p) info_[p] = polygon_info(soup_, p, scratch);
    exact_groups();
    label_ = group_;
    std::vector<bool> absorbed(static_cast<std::size_t>(n_groups_), false);
    if (angle_degrees_ > 0) near_groups(absorbed);
    for (int g = 0; g < n_groups_; ++g)
      if (!absorbed[g]) emit_exact_group(g);
    std::stable_sort(items_.begin(), items_.end(),
                     [](const Item& x, const Item& y) { return x.first_polygon < y.first_polygon; });
    for (Item& item : items_) {
      result_.facets.push_back(std::move(item.facet));
      result_.first_polygon.push_back(item.first_polygon);
    }
    return std::move(result_);
  }

 private:
  struct Item {
    int first_polygon;
    Facet3 facet;
  };

  bool coplanar_with(const PolyInfo& seed, int r) const {
    const auto& V = soup_.vertices;
    for (int s = soup_.offsets[r]; s < soup_.offsets[r + 1]; ++s)
      if (orient3d(V[seed.a], V[seed.b], V[seed.c], V[soup_.indices[s]]) != Sign::Zero) return false;
    return true;
  }

  Sign facing_in(int r, int drop) const {
    return cyclic_orientation(soup_.vertices, soup_.indices.data() + soup_.offsets[r], soup_.polygon_size(r), drop);
  }

  // Breadth-first growth of exactly coplanar, same-facing, same-marker groups.
  void exact_groups() {
    const int np = soup_.polygon_count();
    group_.assign(static_cast<std::size_t>(np), -1);
    std::vector<int> queue;
    for (int p = 0; p < np; ++p) {
      if (group_[p] >= 0) continue;
      const int g = n_groups_++;
      group_[p] = g;
      if (!info_[p].valid) continue;
      const PolyInfo& seed = info_[p];
      queue.assign(1, p);
      for (std::size_t qi = 0; qi < queue.size(); ++qi) {
        const int q = queue[qi];
        for (int s = soup_.offsets[q]; s < soup_.offsets[q + 1]; ++s) {
          const int r = neighbour_[s];
          if (r < 0 || group_[r] >= 0 || !info_[r].valid || soup_.markers[r] != soup_.markers[p]) continue;
          if (!coplanar_with(seed, r) || facing_in(r, seed.drop) != seed.facing) continue;
          group_[r] = g;
          queue.push_back(r);
        }
      }
    }
    members_ = invert(group_, n_groups_);  // members listed in increasing polygon order
  }

  // At vertex v reached from p, is the counter-clockwise angle (in the facet's
  // own orientation, sign s) from direction p - v to w1 - v smaller than to w2 - v?
  bool smaller_turn(int v, int p, int w1, int w2, int drop, Sign s) const {
    const auto& V = soup_.vertices;
    auto half = [&](int w) {
      const Sign o = s * orient2d_projected(V[v], V[p], V[w], drop);
      if (o != Sign::Zero) return o == Sign::Positive ? 0 : 1;
      return dot_sign(V[v], V[p], V[w]) == Sign::Negative ? 1 : 0;
    };
    const int h1 = half(w1), h2 = half(w2);
    if (h1 != h2) return h1 < h2;
    return s * orient2d_projected(V[v], V[w1], V[w2], drop) == Sign::Positive;
  }

  // Splits a closed walk that may pass a vertex several times into simple
  // cycles: whenever the walk returns to a vertex still on the stack, the part
  // since that visit is a closed cycle of its own. At a vertex where the
  // facet's boundary touches itself this separates, for example, a hole loop
  // from the outer loop it touches, whichever way the chaining turned there.
  void split_closed_walk(const std::vector<int>& walk, std::vector<std::vector<int>>& loops) const {
    std::vector<int> stack;
    for (int v : walk) {
      const int at = position_[v];
      if (at < 0) {
        position_[v] = static_cast<int>(stack.size());
        stack.push_back(v);
        continue;
      }
      loops.emplace_back(stack.begin() + at, stack.end());
      for (std::size_t i = static_cast<std::size_t>(at) + 1; i < stack.size(); ++i) position_[stack[i]] = -1;
      stack.resize(static_cast<std::size_t>(at) + 1);
    }
    for (int v : stack) position_[v] = -1;
    loops.push_back(std::move(stack));
  }

  // Boundary loops of the polygons `members` (all with label_ == label).
  // Returns false when they do not form one outer loop plus simple hole loops.
  bool build_loops(const int* members, int count, int drop, Sign facing, std::vector<std::vector<int>>& loops) const {
    struct Edge {
      int from, to;
    };
    std::vector<Edge> edges;
    const int label = label_[members[0]];
    for (int i = 0; i < count; ++i) {
      const int p = members[i];
      const int o = soup_.offsets[p], k = soup_.polygon_size(p);
      for (int j = 0; j < k; ++j) {
        const int r = neighbour_[o + j];
        if (r >= 0 && label_[r] == label) continue;
        edges.push_back({soup_.indices[o + j], soup_.indices[o + (j + 1) % k]});
      }
    }
    std::vector<int> by_from(edges.size());
    for (std::size_t i = 0; i < edges.size(); ++i) by_from[i] = static_cast<int>(i);
    std::sort(by_from.begin(), by_from.end(),
              [&](int x, int y) { return edges[x].from != edges[y].from ? edges[x].from < edges[y].from : x < y; });
    std::vector<bool> used(edges.size(), false);
    loops.clear();
    std::vector<int> candidates;
    for (std::size_t e0 = 0; e0 < edges.size(); ++e0) {
      if (used[e0]) continue;
      std::vector<int> loop;
      int cur = static_cast<int>(e0);
      const int start = cur;
      for (;;) {
        used[cur] = true;
        loop.push_back(edges[cur].from);
        if (loop.size() > edges.size()) return false;
        const int t = edges[cur].to;
        candidates.clear();
        auto it = std::lower_bound(by_from.begin(), by_from.end(), t,
                                   [&](int x, int value) { return edges[x].from < value; });
        for (; it != by_from.end() && edges[*it].from == t; ++it)
          if (!used[*it] || *it == start) candidates.push_back(*it);
        if (candidates.empty()) return false;  // open chain
        int best = candidates[0];
        // Sharpest turn towards the interior (largest counter-clockwise angle
        // from the way back): where two pieces of the facet touch at t, this
        // keeps their loops apart; split_closed_walk handles the other case.
        for (std::size_t c = 1; c < candidates.size(); ++c)
          if (smaller_turn(t, edges[cur].from, edges[best].to, edges[candidates[c]].to, drop, facing))
            best = candidates[c];
        if (best == start) break;
        cur = best;
      }
      split_closed_walk(loop, loops);
    }
    int outer = -1;
    std::vector<int> sorted;
    for (std::size_t i = 0; i < loops.size(); ++i) {
      sorted = loops[i];
      std::sort(sorted.begin(), sorted.end());
      if (sorted.size() < 3 || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return false;
      const Sign o =
          facing * cyclic_orientation(soup_.vertices, loops[i].data(), static_cast<int>(loops[i].size()), drop);
      if (o == Sign::Zero) return false;
      if (o == Sign::Positive) {
        if (outer >= 0) return false;
        outer = static_cast<int>(i);
      }
    }
    if (outer < 0) return false;
    std::rotate(loops.begin(), loops.begin() + outer, loops.begin() + outer + 1);
    return true;
  }

  void emit_single(int p) {
    Facet3 f;
    f.loops.emplace_back(soup_.indices.begin() + soup_.offsets[p], soup_.indices.begin() + soup_.offsets[p + 1]);
    f.marker = soup_.markers[p];
    items_.push_back({p, std::move(f)});
  }

  void emit_exact_group(int g) {
    const int* members = members_.items.data() + members_.start[g];
    const int count = members_.size(g);
    if (count == 1) {
      emit_single(members[0]);
      return;
    }
    const PolyInfo& seed = info_[members[0]];
    Facet3 f;
    if (build_loops(members, count, seed.drop, seed.facing, f.loops)) {
      f.marker = soup_.markers[members[0]];
      items_.push_back({members[0], std::move(f)});
      result_.merged_exact += count - 1;
      return;
    }
    for (int i = 0; i < count; ++i) emit_single(members[i]);
  }

  // Normal of exact group g (sum of its polygons' Newell normals; they all face
  // the same way), or zero for a group that cannot merge.
  Vec3 group_normal(int g) const {
    Vec3 n;
    for (int i = members_.start[g]; i < members_.start[g + 1]; ++i) n = n + info_[members_.items[i]].normal;
    return n;
  }

  void near_groups(std::vector<bool>& absorbed) {
    const double limit = angle_degrees_ * std::numbers::pi / 180.0;
    std::vector<Vec3> normal(static_cast<std::size_t>(n_groups_));
    for (int g = 0; g < n_groups_; ++g) normal[g] = group_normal(g);
    auto mergeable = [&](int g) { return info_[members_.items[members_.start[g]]].valid && norm(normal[g]) > 0; };
    // Vertex -> polygons, to find vertices used outside a group.
    std::vector<int> slot_vertex(soup_.indices.begin(), soup_.indices.end());
    const Lists vertex_slots = invert(slot_vertex, static_cast<int>(soup_.vertices.size()));
    std::vector<int> near(static_cast<std::size_t>(n_groups_), -1);
    std::vector<int> queue;
    int n_near = 0;
    for (int g0 = 0; g0 < n_groups_; ++g0) {
      if (near[g0] >= 0) continue;
      const int id = n_near++;
      near[g0] = id;
      if (!mergeable(g0)) continue;
      const int marker = soup_.markers[members_.items[members_.start[g0]]];
      queue.assign(1, g0);
      for (std::size_t qi = 0; qi < queue.size(); ++qi) {
        const int g = queue[qi];
        for (int i = members_.start[g]; i < members_.start[g + 1]; ++i) {
          const int q = members_.items[i];
          for (int s = soup_.offsets[q]; s < soup_.offsets[q + 1]; ++s) {
            const int r = neighbour_[s];
            if (r < 0) continue;
            const int h = group_[r];
            if (near[h] >= 0 || !mergeable(h) || soup_.markers[r] != marker) continue;
            if (angle_between(normal[g0], normal[h]) > limit) continue;
            near[h] = id;
            queue.push_back(h);
          }
        }
      }
      if (queue.size() > 1) try_near_group(queue, normal, vertex_slots, absorbed);
    }
  }

  // Attempts to turn the exact groups `groups` into one facet (rules in soup_merge.hpp).
  void try_near_group(std::vector<int> groups, const std::vector<Vec3>& normal, const Lists& vertex_slots,
                      std::vector<bool>& absorbed) {
    std::sort(groups.begin(), groups.end());
    std::vector<int> polys;
    Vec3 n;
    for (int g : groups) {
      for (int i = members_.start[g]; i < members_.start[g + 1]; ++i) polys.push_back(members_.items[i]);
      n = n + normal[g];
    }
    std::sort(polys.begin(), polys.end());
    const int label = n_groups_ + groups[0];  // unique, distinct from every exact group id
    for (int p : polys) label_[p] = label;
    auto restore = [&] {
      for (int p : polys) label_[p] = group_[p];
    };
    const PolyInfo& seed = info_[polys[0]];
    Facet3 f;
    if (!build_loops(polys.data(), static_cast<int>(polys.size()), seed.drop, seed.facing, f.loops)) {
      restore();
      return;
    }
    std::vector<int> loop_vertices;
    for (const auto& loop : f.loops) loop_vertices.insert(loop_vertices.end(), loop.begin(), loop.end());
    std::sort(loop_vertices.begin(), loop_vertices.end());
    if (!exactly_coplanar(loop_vertices)) {
      // Moving is allowed only for loop vertices that no polygon outside uses.
      for (int v : loop_vertices)
        for (int i = vertex_slots.start[v]; i < vertex_slots.start[v + 1]; ++i)
          if (label_[slot_poly_[vertex_slots.items[i]]] != label) {
            restore();
            return;
          }
      std::vector<Vec3> saved;
      for (int v : loop_vertices) saved.push_back(soup_.vertices[v]);
      bool ok = snap_to_plane(loop_vertices, n) && exactly_coplanar(loop_vertices);
      // The snap must not change how any loop turns.
      for (std::size_t i = 0; ok && i < f.loops.size(); ++i) {
        const Sign o = seed.facing * cyclic_orientation(soup_.vertices, f.loops[i].data(),
                                                        static_cast<int>(f.loops[i].size()), seed.drop);
        ok = o == (i == 0 ? Sign::Positive : Sign::Negative);
      }
      if (!ok) {
        for (std::size_t i = 0; i < loop_vertices.size(); ++i) soup_.vertices[loop_vertices[i]] = saved[i];
        restore();
        return;
      }
    }
    f.marker = soup_.markers[polys[0]];
    items_.push_back({polys[0], std::move(f)});
    for (int g : groups) {
      absorbed[g] = true;
      result_.merged_exact += members_.size(g) - 1;
    }
    result_.merged_near += static_cast<int>(groups.size()) - 1;
  }

  bool exactly_coplanar(const std::vector<int>& vs) const {
    const auto& V = soup_.vertices;
    int a = vs[0], b = -1, c = -1;
    for (int v : vs)
      if (!(V[v] == V[a])) {
        b = v;
        break;
      }
    if (b < 0) return false;
    for (int v : vs)
      if (!collinear(V[a], V[b], V[v])) {
        c = v;
        break;
      }
    if (c < 0) return false;
    for (int v : vs)
      if (orient3d(V[a], V[b], V[c], V[v]) != Sign::Zero) return false;
    return true;
  }

  // Moves the vertices `vs` onto a plane close to their least-squares-free
  // average plane with normal n, choosing dyadic coefficients so that every
  // snapped coordinate is computed without rounding: with the dominant axis w
  // of n and the other two (u, v), the plane is w = w0 + c1 (u - u0) + c2 (v - v0)
  // where c1, c2 are multiples of 2^-20 with |c| <= 1, u and v are snapped to
  // multiples of q = 2^(e-30) (2^e > every |coordinate|), and w0 to a multiple
  // of q 2^-20. Then c (u - u0) is an integer below 2^51 times q 2^-20 and the
  // sum stays below 2^53 such units, so each w is exact and the snapped points
  // are exactly coplanar (the caller re-checks with orient3d anyway).
  bool snap_to_plane(const std::vector<int>& vs, Vec3 n) {
    auto& V = soup_.vertices;
    const int w = dominant_axis(n), u = u_axis(w), v = v_axis(w);
    const double nw = axis_coord(n, w);
    if (nw == 0) return false;
    auto grid = [](double x, double step) { return std::nearbyint(x / step) * step; };
    const double c1 = grid(-axis_coord(n, u) / nw, std::ldexp(1.0, -20));
    const double c2 = grid(-axis_coord(n, v) / nw, std::ldexp(1.0, -20));
    double m = 0, d = 0;
    for (int i : vs) {
      m = std::max({m, std::abs(V[i].x), std::abs(V[i].y), std::abs(V[i].z)});
      d += dot(n, V[i]);
    }
    d /= static_cast<double>(vs.size());
    if (m == 0) return false;
    int e = 0;
    std::frexp(m, &e);
    const double q = std::ldexp(1.0, e - 30);
    const double u0 = grid(axis_coord(V[vs[0]], u), q), v0 = grid(axis_coord(V[vs[0]], v), q);
    const double w0 = grid((d - axis_coord(n, u) * u0 - axis_coord(n, v) * v0) / nw, q * std::ldexp(1.0, -20));
    for (int i : vs) {
      const double ui = grid(axis_coord(V[i], u), q), vi = grid(axis_coord(V[i], v), q);
      axis_ref(V[i], u) = ui;
      axis_ref(V[i], v) = vi;
      axis_ref(V[i], w) = w0 + (c1 * (ui - u0) + c2 * (vi - v0));
    }
    return true;
  }

  PolygonSoup& soup_;
  double angle_degrees_;
  std::vector<int> slot_poly_, neighbour_;
  std::vector<PolyInfo> info_;
  std::vector<int> group_, label_;
  mutable std::vector<int> position_;  // scratch for split_closed_walk, all -1 between calls
  int n_groups_ = 0;
  Lists members_;
  std::vector<Item> items_;
  SoupMergeResult result_;
};

}  // namespace

SoupMergeResult merge_soup(PolygonSoup& soup, double merge_angle_degrees) {
  return Merger(soup, merge_angle_degrees).run();
}

SoupMergeResult soup_without_merging(const PolygonSoup& soup) {
  SoupMergeResult out;
  for (int p = 0; p < soup.polygon_count(); ++p) {
    Facet3 f;
    f.loops.emplace_back(soup.indices.begin() + soup.offsets[p], soup.indices.begin() + soup.offsets[p + 1]);
    f.marker = soup.markers[p];
    out.facets.push_back(std::move(f));
    out.first_polygon.push_back(p);
  }
  return out;
}

}  // namespace pqmesh::detail
