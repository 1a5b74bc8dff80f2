// Delaunay refinement on the constrained triangulation (see refine.hpp for the
// algorithm, its rules and what is exact).
#include "cdt2d/refine.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <unordered_set>
#include <utility>

#include "cdt2d/refiner.hpp"
#include "pqmesh/errors.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::cdt2d {

std::optional<Vec2> round_onto_segment(Vec2 p, Vec2 a, Vec2 b) {
  const double inf = std::numeric_limits<double>::infinity();
  const double nx = a.y - b.y, ny = b.x - a.x;  // left normal of ab
  const bool move_x = std::fabs(nx) >= std::fabs(ny);
  for (int step = 0; step < 64; ++step) {
    if (within_ulp_of_segment(p, a, b)) return p;
    const double dir = orient2d(a, b, p) == Sign::Positive ? -1.0 : 1.0;  // towards the line
    if (move_x)
      p.x = std::nextafter(p.x, dir * nx > 0 ? inf : -inf);
    else
      p.y = std::nextafter(p.y, dir * ny > 0 ? inf : -inf);
  }
  return std::nullopt;
}

namespace detail {


// Edge m of t (opposite v[m]) is the shortest (squared lengths in double,
// ties to the lowest index).
int Refiner::shortest_edge(int t) const {
  const auto& v = tri_.tri(t).v;
  double best = std::numeric_limits<double>::infinity();
  int m = 0;
  for (int i = 0; i < 3; ++i) {
    const Vec2 d = pts_[v[next3(i)]] - pts_[v[prev3(i)]];
    const double l = dot(d, d);
    if (l < best) {
      best = l;
      m = i;
    }
  }
  return m;
}

// Smallest angle (opposite the shortest edge) below the target, by the law of
// cosines in double.
// The edge vectors and squared lengths of shortest_edge are reused: with m
// the shortest edge, p = v[m+1] - v[m] is the negated vector of edge m+2 and
// q = v[m+2] - v[m] the vector of edge m+1 (negation is exact), so the
// values below are bit for bit those of p and q formed anew.
// The smallest angle of t, at the vertex opposite its shortest side
// (shortest_edge's choice: ties to the lowest index), as the dot product of
// its two sides and the product of their lengths: cos = dot / lengths.
std::pair<double, double> Refiner::smallest_angle_terms(int t) const {
  const auto& v = tri_.tri(t).v;
  Vec2 d[3];
  double l[3];
  int m = 0;
  for (int i = 0; i < 3; ++i) {
    d[i] = pts_[v[next3(i)]] - pts_[v[prev3(i)]];
    l[i] = dot(d[i], d[i]);
    if (l[i] < l[m]) m = i;
  }
  const Vec2 p{-d[prev3(m)].x, -d[prev3(m)].y}, q = d[next3(m)];
  return {dot(p, q), std::sqrt(l[prev3(m)] * l[next3(m)])};
}

// The queue's key: the cosine of t's smallest angle.
double Refiner::cos_smallest(int t) const {
  const auto [d, lengths] = smallest_angle_terms(t);
  return d / lengths;
}

bool Refiner::small_angle(int t) const {
  const auto [d, lengths] = smallest_angle_terms(t);
  return d > cos_target_ * lengths;
}

// Inside triangles are never ghosts (refine_ops.cpp); the ghost test is a guard.
bool Refiner::is_bad(int t) const { return tri_.inside(t) && !tri_.is_ghost(t) && small_angle(t); }

bool Refiner::is_excused(int t) const {
  const auto& v = tri_.tri(t).v;
  const int m = shortest_edge(t);
  if (v[m] < n_in_ && sharp_[static_cast<std::size_t>(v[m])] && tri_.constrained(he(t, next3(m))) &&
      tri_.constrained(he(t, prev3(m))))
    return true;  // the triangle fills the corner: its small angle is the input angle
  const int s1 = vgroup_[static_cast<std::size_t>(v[next3(m)])], s2 = vgroup_[static_cast<std::size_t>(v[prev3(m)])];
  return s1 >= 0 && s2 >= 0 && s1 != s2 && std::binary_search(sharp_pairs_.begin(), sharp_pairs_.end(), pair_key(s1, s2));
}

// Circumcenter, or Ungor's off-center: on the bisector of the shortest edge
// pq, at distance 0.475 cot(theta / 2) |pq| from its midpoint when the
// circumcenter is farther (then the triangle on pq with the new point has
// apex angle a little above theta).
Vec2 Refiner::new_point_for(int t) const {
  const auto& v = tri_.tri(t).v;
  const Vec2 a = pts_[v[0]];
  const Vec2 ab = pts_[v[1]] - a, ac = pts_[v[2]] - a;
  const double d = 2 * cross(ab, ac);
  const double ab2 = dot(ab, ab), ac2 = dot(ac, ac);
  const Vec2 cc = a + Vec2{(ac.y * ab2 - ab.y * ac2) / d, (ab.x * ac2 - ac.x * ab2) / d};
  const int m = shortest_edge(t);
  const Vec2 p = pts_[v[next3(m)]], q = pts_[v[prev3(m)]];
  const Vec2 mid = 0.5 * (p + q);
  const double dist = norm(cc - mid), h = off_factor_ * norm(q - p);
  if (!(dist > h)) return cc;
  return mid + (h / dist) * (cc - mid);
}

// Walk from triangle t towards c across non-constrained edges. Leaves each
// triangle through an edge with c strictly beyond it; when there are two,
// the one the line from the source vertex s to c crosses (a straight walk;
// s is the vertex opposite the first exit). Capped by the triangle count (a
// degenerate line through a vertex makes it a visibility walk).
Walk Refiner::walk_to(int t, Vec2 c) {
  const int cap = tri_.triangle_count() + 16;
  int from = -1;  // edge of t we entered through
  Vec2 s{};
  bool have_source = false;
  for (int step = 0; step < cap; ++step) {
    const auto& T = tri_.tri(t);
    Sign o[3];
    int neg = 0, zeros = 0, zero_edge = -1;
    for (int e = 0; e < 3; ++e) {
      o[e] = e == from ? Sign::Positive : orient2d(pts_[T.v[next3(e)]], pts_[T.v[prev3(e)]], c);
      if (o[e] == Sign::Negative) ++neg;
      if (o[e] == Sign::Zero) {
        ++zeros;
        zero_edge = e;
      }
    }
    if (neg == 0) {
      if (zeros >= 2) return {Walk::End::Vertex, t, -1};
      if (zeros == 1) {
        const int h = he(t, zero_edge);
        if (tri_.constrained(h)) return {Walk::End::Constraint, t, h};
        return {Walk::End::Edge, t, h};
      }
      return {Walk::End::Triangle, t, -1};
    }
    int exit = -1;
    if (neg == 1 || !have_source) {
      for (int e = 0; e < 3 && exit < 0; ++e)
        if (o[e] == Sign::Negative) exit = e;
    } else {
      // Two candidates; the entry edge is `from`, the apex x = v[from].
      const int x = T.v[from];
      const Sign side = orient2d(s, c, pts_[x]);
      // Entry edge runs l -> r seen from this triangle, l = v[from + 1] left of s -> c.
      exit = side == Sign::Negative ? prev3(from) : next3(from);
    }
    if (!have_source) {
      s = pts_[T.v[exit]];
      have_source = true;
    }
    const int h = he(t, exit);
    if (tri_.constrained(h)) return {Walk::End::Constraint, t, h};
    const int k = T.n[exit];
    t = tri_of(k);
    from = edge_of(k);
    if (tri_.is_ghost(t) || !tri_.inside(t)) return {Walk::End::Failed, -1, -1};
  }
  return {Walk::End::Failed, -1, -1};
}

// Bowyer-Watson cavity of c (triangles whose circumcircle strictly contains
// it, connected through non-constrained edges, from the located triangles);
// its constrained boundary edges that c encroaches go to encroached_.
bool Refiner::collect_encroached(const Walk& w, Vec2 c) {
  encroached_.clear();
  cavity_.clear();
  // Visited triangles: a linear search of cavity_ while it is small (the
  // usual cavity has a handful of triangles), per-slot stamps once it grows
  // beyond kSmallCavity. The stamp array (one int per triangle slot) is made
  // by the first large cavity only, so most runs never allocate it.
  constexpr std::size_t kSmallCavity = 32;
  auto visited = [&](int t) {
    if (cavity_.size() <= kSmallCavity) return std::find(cavity_.begin(), cavity_.end(), t) != cavity_.end();
    return stamp_[static_cast<std::size_t>(t)] == stamp_now_;
  };
  auto visit = [&](int t) {
    cavity_.push_back(t);
    if (cavity_.size() <= kSmallCavity) return;
    if (cavity_.size() == kSmallCavity + 1) {  // switch to stamps: stamp the whole cavity so far
      if (stamp_.size() < static_cast<std::size_t>(tri_.triangle_count()))
        stamp_.resize(static_cast<std::size_t>(tri_.triangle_count()) + tri_.triangle_count() / 8 + 64, 0);
      ++stamp_now_;
      for (const int k : cavity_) stamp_[static_cast<std::size_t>(k)] = stamp_now_;
      return;
    }
    stamp_[static_cast<std::size_t>(t)] = stamp_now_;
  };
  visit(w.t);
  if (w.end == Walk::End::Edge) visit(tri_of(tri_.tri(w.t).n[edge_of(w.h)]));
  for (std::size_t i = 0; i < cavity_.size(); ++i) {
    const int t = cavity_[i];
    const auto& T = tri_.tri(t);
    for (int e = 0; e < 3; ++e) {
      const int u = T.v[next3(e)], v = T.v[prev3(e)];
      if (tri_.constrained(he(t, e))) {
        if (dot_sign(c, pts_[u], pts_[v]) != Sign::Positive) encroached_.push_back({u, v});
        continue;
      }
      const int s = tri_of(T.n[e]);
      if (!tri_.inside(s) || tri_.is_ghost(s) || visited(s)) continue;
      const auto& S = tri_.tri(s);
      if (incircle(pts_[S.v[0]], pts_[S.v[1]], pts_[S.v[2]], c) == Sign::Positive) visit(s);
    }
  }
  return !encroached_.empty();
}

bool Refiner::splittable(int u, int v) const {
  if (!split_) return false;
  if (!refused_set_.empty() && refused_set_.count(pair_key(u, v)) != 0) return false;
  const auto [A, B] = ends_of(origin_of(u, v));
  return norm(pts_[v] - pts_[u]) >= kMinPieceFraction * norm(B - A);
}

// Split the subsegment u-v (if it still is one); false when refused.
bool Refiner::split_subsegment(int u, int v) {
  int h = tri_.half_edge(u, v);
  if (h < 0 || !tri_.constrained(h)) return true;  // already split
  if (tri_.is_ghost(tri_of(h)) || !tri_.inside(tri_of(h))) {
    h = tri_.tri(tri_of(h)).n[edge_of(h)];
    std::swap(u, v);
  }
  if (!splittable(u, v)) {
    ++refused_;
    return false;
  }
  const int k = origin_of(u, v);
  const auto [A, B] = ends_of(k);
  const Vec2 pu = pts_[u], pv = pts_[v];
  const bool su = u < n_in_ && sharp_[static_cast<std::size_t>(u)], sv = v < n_in_ && sharp_[static_cast<std::size_t>(v)];
  Vec2 p = 0.5 * (pu + pv);
  if (su != sv) {  // concentric shells around the sharp end
    const Vec2 apex = su ? pu : pv, far = su ? pv : pu;
    const double len = norm(far - apex);
    const double r = std::exp2(std::floor(std::log2(2 * len / 3)));
    p = apex + (r / len) * (far - apex);
  }
  const std::optional<Vec2> r = round_onto_segment(p, A, B);
  if (!r) {
    refused_set_.insert(pair_key(u, v));
    ++refused_;
    return false;
  }
  // u -> v has the inside on its left. Unless the far side is inside or a
  // trusted outside triangle, the point must not be strictly right of u -> v
  // (see split_constrained_edge): among the rounding and its neighbours up to
  // three ulps away along either axis, take the first that is still on AB
  // (within_ulp_of_segment) and not right of u -> v. (The rounding may sit at
  // the far edge of the band of AB while the chord u -> v, whose ends are
  // rounded too, runs an ulp or two inside it.)
  const int far = tri_of(tri_.tri(tri_of(h)).n[edge_of(h)]);
  const bool far_ok = tri_.inside(far) || tri_.trusted_outside(far);
  std::optional<Vec2> q;
  bool allow_right = false;  // first pass: on or left of u -> v only
  auto accept = [&](Vec2 x) {
    if ((allow_right || orient2d(pu, pv, x) != Sign::Negative) && within_ulp_of_segment(x, A, B) &&
        dot_sign(x, pu, pv) == Sign::Negative)
      q = x;
    return q.has_value();
  };
  auto shifted = [](double x, int steps) {
    const double inf = std::numeric_limits<double>::infinity();
    for (; steps > 0; --steps) x = std::nextafter(x, inf);
    for (; steps < 0; ++steps) x = std::nextafter(x, -inf);
    return x;
  };
  const Vec2 c0 = *r;
  for (int pass = 0; pass < (far_ok ? 2 : 1) && !q; ++pass) {
    allow_right = pass == 1;
    if (accept(c0)) break;
    for (int step = 1; step <= 3 && !q; ++step)
      for (int sgn : {1, -1})
        if (accept({shifted(c0.x, sgn * step), c0.y}) || accept({c0.x, shifted(c0.y, sgn * step)})) break;
  }
  if (!q) {
    refused_set_.insert(pair_key(u, v));
    ++refused_;
    return false;
  }
  const int id = static_cast<int>(pts_.size());
  pts_.push_back(*q);
  seg_of_.push_back(k);
  vgroup_.push_back(group_of(k));
  if (!tri_.split_constrained_edge(h, id)) {
    pts_.pop_back();
    seg_of_.pop_back();
    vgroup_.pop_back();
    refused_set_.insert(pair_key(u, v));
    ++refused_;
    return false;
  }
  ++inserted_;
  ++on_constraints_;
  after_insertion(id);
  return true;
}

// Insert c, located by w (End::Triangle or End::Edge), as a free vertex.
void Refiner::insert_interior(Vec2 c, const Walk& w) {
  const int id = static_cast<int>(pts_.size());
  pts_.push_back(c);
  seg_of_.push_back(-1);
  vgroup_.push_back(-1);
  tri_.insert_interior_point(id, w.t, w.end == Walk::End::Edge ? edge_of(w.h) : -1);
  ++inserted_;
  after_insertion(id);
}

// Queue the bad triangles around the new vertex p and the subsegments that
// p encroaches (edges opposite p) or that are encroached by the apex of an
// inside triangle (p's own subsegments). All changed triangles are around p.
void Refiner::after_insertion(int p) {
  const int t0 = tri_.vertex_triangle(p);
  int t = t0;
  do {
    const int i = tri_.index_of(t, p);
    const auto& T = tri_.tri(t);
    if (tri_.inside(t) && !tri_.is_ghost(t)) {
      if (is_bad(t)) push_tri(t);
      const int a = T.v[next3(i)], b = T.v[prev3(i)];
      if (tri_.constrained(he(t, i)) && encroaches(p, a, b) && splittable(a, b)) segq_.push_back({a, b});
      if (tri_.constrained(he(t, prev3(i))) && encroaches(b, p, a) && splittable(p, a)) segq_.push_back({p, a});
      if (tri_.constrained(he(t, next3(i))) && encroaches(a, b, p) && splittable(b, p)) segq_.push_back({b, p});
    }
    t = tri_of(T.n[next3(i)]);
  } while (t != t0);
}

void Refiner::run(RefineResult& out) {
  // Initial queues: subsegments encroached by the apex of an inside triangle,
  // then every bad inside triangle in slot order.
  const int nt = tri_.triangle_count();
  for (int t = 0; t < nt; ++t) {
    if (!tri_.inside(t) || tri_.is_ghost(t)) continue;
    const auto& T = tri_.tri(t);
    if (tri_.any_constrained(t))
      for (int e = 0; e < 3; ++e)
        if (tri_.constrained(he(t, e)) && encroaches(T.v[e], T.v[next3(e)], T.v[prev3(e)]) &&
            splittable(T.v[next3(e)], T.v[prev3(e)]))
          segq_.push_back({T.v[next3(e)], T.v[prev3(e)]});
    if (small_angle(t)) push_tri(t);
  }
  bool capped = false;
  for (;;) {
    if (inserted_ >= cap_) {
      capped = seg_head_ < segq_.size() || !worst_.empty();
      break;
    }
    if (seg_head_ < segq_.size()) {
      const auto [u, v] = segq_[seg_head_++];
      split_subsegment(u, v);
      continue;
    }
    if (worst_.empty()) break;
    const QueuedTri q = bad_[static_cast<std::size_t>(-worst_.top().second)];
    worst_.pop();
    if (!still_there(q) || !is_bad(q.t) || is_excused(q.t)) continue;
    const Vec2 c = new_point_for(q.t);
    if (!std::isfinite(c.x) || !std::isfinite(c.y)) continue;
    const Walk w = walk_to(q.t, c);
    if (!split_) {  // refine_inside.cpp
      refine_inside(q, c, w);
      continue;
    }
    if (w.end == Walk::End::Failed || w.end == Walk::End::Vertex) continue;  // give up on this triangle
    if (w.end == Walk::End::Constraint) {
      const auto& T = tri_.tri(tri_of(w.h));
      const int u = T.v[next3(edge_of(w.h))], v = T.v[prev3(edge_of(w.h))];
      if (split_subsegment(u, v) && still_there(q)) requeue(q);
      continue;
    }
    if (collect_encroached(w, c)) {
      bool any = false;
      for (const auto& e : encroached_)
        if (splittable(e[0], e[1])) {
          segq_.push_back(e);
          any = true;
        }
      if (any) requeue(q);  // re-examined after the splits
      continue;
    }
    insert_interior(c, w);
  }
  out.cap_reached = capped;
  out.inserted = inserted_;
  out.inserted_on_constraints = on_constraints_;
  out.refused_splits = refused_;
  out.given_up_outside = given_up_outside_;
  out.given_up_near = given_up_near_;
  out.given_up_flat = given_up_flat_;
  out.apex_points = apex_points_;
  out.halfway_points = halfway_points_;
  // The triangles bad at the end are among the queued slots: the initial scan
  // queued every bad inside triangle, and a triangle changes (vertices or
  // label) only by an insertion at a point p that it then has as a vertex
  // (refine_ops.cpp: the splits and their Lawson flips make triangles around
  // p only), after which after_insertion(p) queued it if bad. So the final
  // check visits the queued slots, each once, instead of every triangle.
  std::vector<int> slots;
  slots.reserve(bad_.size());
  for (const QueuedTri& q : bad_) slots.push_back(q.t);
  std::sort(slots.begin(), slots.end());
  slots.erase(std::unique(slots.begin(), slots.end()), slots.end());
  bool reached = true;
  for (const int t : slots) {
    if (!is_bad(t)) continue;
    if (is_excused(t))
      ++out.excused;
    else
      reached = false;
  }
  out.target_reached = reached;
  output(out);
}

}  // namespace detail

std::size_t new_point_allowance(std::size_t n, const RefineOptions& options) {
  const std::size_t cap = options.max_new_points != 0 ? options.max_new_points : 2 * n;
  return std::min(cap, n / 8 + 1024);
}

namespace {

// refine_constrained_delaunay with the input points given separately (pts is
// in.points, copied or moved; in.points is not read).
RefineResult refine(const CdtInput& in, std::vector<Vec2> pts, const RefineOptions& options,
                    const SegmentSupport& support) {
  const int n = static_cast<int>(pts.size());
  for (std::size_t c = 0; c < in.constraints.size(); ++c) {
    const auto [a, b] = in.constraints[c];
    if (a < 0 || a >= n || b < 0 || b >= n || a == b)
      throw InternalError("refine_constrained_delaunay: constraint " + std::to_string(c) + " is out of range or degenerate");
  }
  if (!support.constraint_segment.empty()) {
    if (support.constraint_segment.size() != in.constraints.size())
      throw InternalError("refine_constrained_delaunay: constraint_segment needs one entry per constraint");
    for (int s : support.constraint_segment)
      if (s < 0 || static_cast<std::size_t>(s) >= support.segment_ends.size())
        throw InternalError("refine_constrained_delaunay: segment id " + std::to_string(s) + " out of range");
  }
  RefineResult out;
  const std::size_t allowance = new_point_allowance(pts.size(), options);
  pts.reserve(pts.size() + allowance);
  {
    detail::Triangulation tri(pts);
    if (tri.build_delaunay() && !in.constraints.empty()) {
      std::vector<std::size_t> piece_begin;
      piece_begin.reserve(in.constraints.size() + 1);
      for (const auto& c : in.constraints) {
        piece_begin.push_back(tri.pieces().size());
        tri.insert_constraint(c[0], c[1]);
      }
      piece_begin.push_back(tri.pieces().size());
      tri.begin_refinement(tri.inside_triangles());
      detail::Refiner r(in, options, support, pts, tri, std::move(piece_begin));
      r.run(out);
    } else {
      out.constraints = in.constraints;
      for (std::size_t c = 0; c < in.constraints.size(); ++c) out.constraint_origin.push_back(static_cast<int>(c));
      out.target_reached = true;
    }
  }
  out.points = std::move(pts);
  return out;
}

}  // namespace

RefineResult refine_constrained_delaunay(const CdtInput& in, const RefineOptions& options,
                                         const SegmentSupport& support) {
  std::vector<Vec2> pts;
  pts.reserve(in.points.size() + new_point_allowance(in.points.size(), options));
  pts.assign(in.points.begin(), in.points.end());
  return refine(in, std::move(pts), options, support);
}

RefineResult refine_constrained_delaunay(CdtInput&& in, const RefineOptions& options, const SegmentSupport& support) {
  std::vector<Vec2> pts = std::move(in.points);
  return refine(in, std::move(pts), options, support);
}

}  // namespace pqmesh::cdt2d
