// Phase 1 of constrained_delaunay(): incremental Delaunay triangulation with
// Lawson flips (see triangulation.hpp for the data structure and invariants).
#include "cdt2d/triangulation.hpp"

#include <algorithm>
#include <string>

#include "cdt2d/insertion_order.hpp"
#include "pqmesh/errors.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::cdt2d::detail {

Triangulation::Triangulation(const std::vector<Vec2>& points) : pts_(points) {}

namespace {

[[noreturn]] void throw_duplicate(int p, int q) {
  throw InternalError("constrained_delaunay: duplicate points " + std::to_string(q) + " and " + std::to_string(p));
}

// All points on one line: there is no triangle, but duplicates are still an
// error. Sorting a copy of the ids is fine for this rare case.
void check_duplicates_sorted(const std::vector<Vec2>& pts) {
  std::vector<int> ids(pts.size());
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<int>(i);
  std::sort(ids.begin(), ids.end(), [&](int a, int b) {
    return pts[a].x < pts[b].x || (pts[a].x == pts[b].x && (pts[a].y < pts[b].y || (pts[a].y == pts[b].y && a < b)));
  });
  for (std::size_t i = 1; i < ids.size(); ++i)
    if (pts[ids[i]] == pts[ids[i - 1]]) throw_duplicate(ids[i], ids[i - 1]);
}

// p, a, d, b (in this order around a quadrilateral) are the corners of an
// axis-parallel rectangle, p opposite d: then the four are cocircular and
// incircle is exactly zero (no flip). Exact: coordinate equalities only. The
// quadtree's grid corners make this the most common tie, and the one the
// floating-point filter of incircle cannot decide.
bool axis_rectangle(Vec2 p, Vec2 a, Vec2 d, Vec2 b) {
  return (p.x == a.x && d.x == b.x && p.y == b.y && d.y == a.y) ||
         (p.x == b.x && d.x == a.x && p.y == a.y && d.y == b.y);
}

}  // namespace

int Triangulation::random3() {
  // A fixed-seed linear congruential generator: the walk is "stochastic" only
  // to rule out cycles, and stays deterministic.
  rng_ = rng_ * 6364136223846793005ull + 1442695040888963407ull;
  return static_cast<int>(((rng_ >> 32) * 3) >> 32);
}

// Real triangle (a, b, c), counter-clockwise, and its three ghost triangles.
void Triangulation::make_first_triangle(int a, int b, int c) {
  tris_.push_back({{a, b, c}, {-1, -1, -1}});       // 0
  tris_.push_back({{b, a, kGhost}, {-1, -1, -1}});  // 1: hull edge a-b
  tris_.push_back({{c, b, kGhost}, {-1, -1, -1}});  // 2: hull edge b-c
  tris_.push_back({{a, c, kGhost}, {-1, -1, -1}});  // 3: hull edge c-a
  link(he(0, 2), he(1, 2));
  link(he(0, 0), he(2, 2));
  link(he(0, 1), he(3, 2));
  link(he(1, 0), he(3, 1));  // a -> g / g -> a
  link(he(2, 0), he(1, 1));  // b -> g / g -> b
  link(he(3, 0), he(2, 1));  // c -> g / g -> c
  last_ = 0;
}

bool Triangulation::build_delaunay() {
  // Half-edge ids 4 t + i must fit in an int: 2 n triangles < 2^29.
  if (pts_.size() >= (std::size_t{1} << 27))
    throw InternalError("constrained_delaunay: more than 2^27 points are not supported");
  const int n = static_cast<int>(pts_.size());
  if (n < 3) {
    check_duplicates_sorted(pts_);
    return false;
  }
  // Position k of the insertion sequence inserts point id(k).
  const std::vector<int> order = insertion_order(pts_);
  auto id = [&](long k) { return order.empty() ? static_cast<int>(k) : order[static_cast<std::size_t>(k)]; };
  const int p0 = id(0), p1 = id(1);
  if (pts_[p0] == pts_[p1]) throw_duplicate(p1, p0);
  long third = -1;
  Sign turn = Sign::Zero;
  for (long k = 2; k < n && third < 0; ++k) {
    turn = orient2d(pts_[p0], pts_[p1], pts_[id(k)]);
    if (turn != Sign::Zero) third = k;
  }
  if (third < 0) {
    check_duplicates_sorted(pts_);
    return false;
  }
  tris_.reserve(2 * pts_.capacity() + 2);  // capacity: see triangulation.hpp
  if (turn == Sign::Positive)
    make_first_triangle(p0, p1, id(third));
  else
    make_first_triangle(p1, p0, id(third));
  // Insertion in rounds of decreasing stride (a deterministic analogue of a
  // biased randomized insertion order): round r inserts the positions that
  // are multiples of kStride^r but not of kStride^(r+1). Each round keeps the
  // spatially coherent order, so the walk stays short, while the coarse
  // rounds spread points before the dense ones. Without them, an order that
  // completes one region before its neighbour (z-order over parallel chains
  // of close points) makes every insertion flip a long fan of triangles;
  // with them such a fan is bounded by about kStride triangles.
  constexpr long kStride = 8;
  long top = 1;
  while (top * kStride * 64 <= n) top *= kStride;
  for (long stride = top; stride >= 1; stride /= kStride) {
    // m counts k / stride modulo kStride (no division per position).
    long m = 0;
    for (long k = 0; k < n; k += stride, m = m + 1 == kStride ? 0 : m + 1)
      if ((stride == top || m != 0) && k >= 2 && k != third) insert_point(id(k));
  }
  return true;
}

// Visibility walk from last_ (a real triangle) towards point p. Each step
// leaves the current triangle through an edge that has p strictly on its
// other side; the first edge tried is chosen by random3() (the remembering
// stochastic walk, which terminates on every triangulation), and the edge we
// came through is skipped (p is known to be strictly on its inner side).
// Result: a real triangle containing p (edge >= 0 when p is in the relative
// interior of that edge), or a ghost triangle (u, v, g) with p strictly left
// of u -> v, i.e. p outside the hull and seeing that hull edge.
Triangulation::Location Triangulation::locate(int p) {
  const Vec2 q = pts_[p];
  int t = last_;
  int from = -1;
  for (;;) {
    const Tri& T = tris_[t];  // real: a ghost ends the walk below
    const int start = random3();
    const Vec2 corner[3] = {pts_[T.v[0]], pts_[T.v[1]], pts_[T.v[2]]};
    int exit_edge = -1, zeros = 0, zero_edge = -1, zero_sum = 0;
    for (int k = 0; k < 3; ++k) {
      const int e = start + k < 3 ? start + k : start + k - 3;
      if (e == from) continue;
      const Sign s = orient2d(corner[next3(e)], corner[prev3(e)], q);
      if (s == Sign::Negative) {
        exit_edge = e;
        break;
      }
      if (s == Sign::Zero) {
        ++zeros;
        zero_edge = e;
        zero_sum += e;
      }
    }
    if (exit_edge < 0) {
      // Two zero edges (three cannot be: t is strictly counter-clockwise):
      // p coincides with their shared vertex, opposite the third edge.
      if (zeros >= 2) throw_duplicate(p, T.v[3 - zero_sum]);
      return {t, zero_edge};
    }
    const int h = T.n[exit_edge];
    t = tri_of(h);
    from = edge_of(h);
    if (is_ghost(t)) return {t, -1};
  }
}

void Triangulation::insert_point(int p) {
  const Location loc = locate(p);
  if (loc.edge < 0)
    split_triangle(loc.t, p);
  else
    split_edge(he(loc.t, loc.edge), p);
  legalize(p);
}

// 1-3 split of t = (a, b, c) by a point p strictly inside it, or of a ghost
// triangle (u, v, g) by a point strictly left of u -> v (then (p, u, v) is the
// new real triangle and the two others are ghosts). New triangles keep p at
// index 0, so edge 0 is the edge opposite p that legalize() checks.
void Triangulation::split_triangle(int t, int p) {
  const Tri T = tris_[t];
  const int a = T.v[0], b = T.v[1], c = T.v[2];
  const int t0 = t;
  const int t1 = static_cast<int>(tris_.size());
  const int t2 = t1 + 1;
  // The fan (p, b, c), (p, c, a), (p, a, b) written whole: edge 0 of the i-th
  // is the old edge i (its outer twin is re-pointed below), edges 1 and 2 are
  // the spokes p-a, p-b, p-c shared inside the fan.
  tris_[t0] = {{p, b, c}, {T.n[0], he(t1, 2), he(t2, 1)}};
  tris_.push_back({{p, c, a}, {T.n[1], he(t2, 2), he(t0, 1)}});
  tris_.push_back({{p, a, b}, {T.n[2], he(t0, 2), he(t1, 1)}});
  set_twin(T.n[0], he(t0, 0));
  set_twin(T.n[1], he(t1, 0));
  set_twin(T.n[2], he(t2, 0));
  stack_.push_back(t0);
  stack_.push_back(t1);
  stack_.push_back(t2);
  last_ = !is_ghost(t0) ? t0 : (!is_ghost(t1) ? t1 : t2);
}

// 2-4 split: p in the relative interior of half-edge h = a -> b of the real
// triangle (c, a, b) whose neighbour across is (d, b, a) (d may be the ghost:
// then p lies on a hull edge and two of the new triangles are ghosts).
void Triangulation::split_edge(int h, int p) {
  const int t = tri_of(h), i = edge_of(h);
  const Tri T = tris_[t];
  const int k = T.n[i];
  const int u = tri_of(k), j = edge_of(k);
  const Tri U = tris_[u];
  const int c = T.v[i], a = T.v[next3(i)], b = T.v[prev3(i)], d = U.v[j];
  const int n_bc = T.n[next3(i)], n_ca = T.n[prev3(i)], n_ad = U.n[next3(j)], n_db = U.n[prev3(j)];
  const int t0 = t, t1 = u;
  const int t2 = static_cast<int>(tris_.size()), t3 = t2 + 1;
  // The fan written whole (edge 0: an outer edge, re-pointed below; edges 1
  // and 2: the spokes shared around p). The outer twins lie in triangles
  // other than t and u (c == d would need a sphere of two triangles).
  tris_[t0] = {{p, b, c}, {n_bc, he(t1, 2), he(t3, 1)}};
  tris_[t1] = {{p, c, a}, {n_ca, he(t2, 2), he(t0, 1)}};
  tris_.push_back({{p, a, d}, {n_ad, he(t3, 2), he(t1, 1)}});
  tris_.push_back({{p, d, b}, {n_db, he(t0, 2), he(t2, 1)}});
  set_twin(n_bc, he(t0, 0));
  set_twin(n_ca, he(t1, 0));
  set_twin(n_ad, he(t2, 0));
  set_twin(n_db, he(t3, 0));
  stack_.push_back(t0);
  stack_.push_back(t1);
  stack_.push_back(t2);
  stack_.push_back(t3);
  last_ = t0;  // (p, b, c) with c from a real triangle: real
}

// Flip the edge of half-edge h. With t = tri_of(h) = (p, a, b) (p = v[i] opposite
// the edge a -> b) and its neighbour (d, b, a), the result is t = (p, a, d)
// and u = (p, d, b): the new edge p - d is edge 1 of t and edge 2 of u, and
// p sits at index 0 of both. The caller guarantees the quadrilateral
// p, a, d, b is strictly convex. Constraint bits follow their edges.
void Triangulation::flip(int h) {
  const int t = tri_of(h), i = edge_of(h);
  const int k = tris_[t].n[i];
  const int u = tri_of(k), j = edge_of(k);
  const Tri T = tris_[t], U = tris_[u];
  const int p = T.v[i], a = T.v[next3(i)], b = T.v[prev3(i)], d = U.v[j];
  const int n_bp = T.n[next3(i)], n_pa = T.n[prev3(i)], n_ad = U.n[next3(j)], n_db = U.n[prev3(j)];
  tris_[t].v[0] = p;
  tris_[t].v[1] = a;
  tris_[t].v[2] = d;
  tris_[u].v[0] = p;
  tris_[u].v[1] = d;
  tris_[u].v[2] = b;
  link(he(t, 0), n_ad);
  link(he(t, 2), n_pa);
  link(he(u, 0), n_db);
  link(he(u, 1), n_bp);
  link(he(t, 1), he(u, 2));
  if (!cons_.empty()) {
    auto bit = [&](int tri, int e) { return (cons_[tri] >> e) & 1u; };
    const unsigned c_bp = bit(t, next3(i)), c_pa = bit(t, prev3(i)), c_ad = bit(u, next3(j)), c_db = bit(u, prev3(j));
    cons_[t] = static_cast<std::uint8_t>(c_ad | (c_pa << 2));
    cons_[u] = static_cast<std::uint8_t>(c_db | (c_bp << 1));
  }
}

// flip(he(t, 0)) for phase 1 (no constraint bits), with the edge index
// known: t = (p, a, b), its neighbour across a -> b is u = (d, b, a) (d at
// index j). Afterwards t = (p, a, d), u = (p, d, b), every half-edge twinned
// as flip() leaves it (the four outer neighbours lie in triangles other than
// t and u: d == p would need a sphere of two triangles).
void Triangulation::flip_at_apex(int t) {
  const Tri T = tris_[t];
  const int k = T.n[0], u = tri_of(k), j = edge_of(k);
  const Tri& U = tris_[u];
  const int p = T.v[0], a = T.v[1], b = T.v[2], d = U.v[j];
  const int n_bp = T.n[1], n_pa = T.n[2], n_ad = U.n[next3(j)], n_db = U.n[prev3(j)];
  tris_[t] = {{p, a, d}, {n_ad, he(u, 2), n_pa}};
  tris_[u] = {{p, d, b}, {n_db, n_bp, he(t, 1)}};
  set_twin(n_ad, he(t, 0));
  set_twin(n_pa, he(t, 2));
  set_twin(n_db, he(u, 0));
  set_twin(n_bp, he(u, 1));
}

// Lawson flips after inserting p. Every triangle on stack_ has p at index 0
// and its edge 0 opposite p; a flip keeps p at index 0 in both triangles, so
// stack entries stay valid. Flip rule (strict, so ties never flip):
//   real edge, real neighbour (b, a, d): incircle(p, a, b, d) > 0;
//   real edge, ghost neighbour: never (a hull edge with p inside the hull);
//   ghost edge (one of a, b is the ghost): the ghost rule of triangulation.hpp
//   applied to the neighbouring ghost triangle, i.e. p strictly outside the
//   next hull edge, which restores convexity of the hull.
// A strict incircle (or strict ghost) test implies the quadrilateral is
// strictly convex: d is strictly inside the circle through p, a, b and on the
// other side of a-b, so segment p-d crosses the open segment a-b.
void Triangulation::legalize(int p) {
  const Vec2 q = pts_[p];
  while (!stack_.empty()) {
    const int t = stack_.back();
    stack_.pop_back();
    const Tri& T = tris_[t];
    const int h = T.n[0];
    const int d = tris_[tri_of(h)].v[edge_of(h)];
    const int a = T.v[1], b = T.v[2];
    bool do_flip;
    if (a != kGhost && b != kGhost) {
      do_flip = d != kGhost && !axis_rectangle(q, pts_[a], pts_[d], pts_[b]) &&
                incircle(q, pts_[a], pts_[b], pts_[d]) == Sign::Positive;
    } else if (b == kGhost) {
      do_flip = orient2d(pts_[a], pts_[d], q) == Sign::Positive;  // neighbour is ghost (a, d, g)
    } else {
      do_flip = orient2d(pts_[d], pts_[b], q) == Sign::Positive;  // neighbour is ghost (d, b, g)
    }
    if (!do_flip) continue;
    const int u = tri_of(h);
    flip_at_apex(t);
    stack_.push_back(t);
    stack_.push_back(u);
    if (!is_ghost(t)) last_ = t;
  }
}

}  // namespace pqmesh::cdt2d::detail
