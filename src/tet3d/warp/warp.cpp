#include "tet3d/warp/warp.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <unordered_set>
#include <utility>
#include <vector>

#include "plc/facet_triangle_range.hpp"
#include "pqmesh/errors.hpp"
#include "tet3d/squares/cut_square_edge.hpp"
#include "tet3d/warp/warp_journal.hpp"
#include "tet3d/points/facet_plane.hpp"

namespace pqmesh::tet3d {

namespace {

// Distance from p to triangle abc (closest point by the Voronoi regions of
// the triangle's features; a construction, used only for thresholds).
double triangle_distance(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return norm(p - a);
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return norm(p - b);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return norm(p - (a + (d1 / (d1 - d3)) * ab));
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return norm(p - c);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return norm(p - (a + (d2 / (d2 - d6)) * ac));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return norm(p - (b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b)));
  const double den = 1 / (va + vb + vc);
  return norm(p - (a + (vb * den) * ab + (vc * den) * ac));
}

// Closest points of segments [p, q] and [a, b] (a construction, for the
// h/8 threshold and the direction of the first pass).
std::pair<Vec3, Vec3> closest_points(Vec3 p, Vec3 q, Vec3 a, Vec3 b) {
  const Vec3 d1 = q - p, d2 = b - a, r = p - a;
  const double A = dot(d1, d1), E = dot(d2, d2), F = dot(d2, r), C = dot(d1, r), B = dot(d1, d2);
  const double den = A * E - B * B;
  double s = den > 0 ? std::clamp((B * F - C * E) / den, 0.0, 1.0) : 0.0;
  double t = (B * s + F) / E;
  if (t < 0) {
    t = 0;
    s = std::clamp(-C / A, 0.0, 1.0);
  } else if (t > 1) {
    t = 1;
    s = std::clamp((B - C) / A, 0.0, 1.0);
  }
  return {p + s * d1, a + t * d2};
}

// Distance from p to segment [a, b] (a construction, for thresholds).
double segment_distance(Vec3 p, Vec3 a, Vec3 b) {
  const Vec3 d = b - a;
  const double len2 = dot(d, d);
  const double t = len2 > 0 ? std::clamp(dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
  return norm(p - (a + t * d));
}

}  // namespace

double facet_distance(const Domain3& domain, int facet, Vec3 x) {
  double best = INFINITY;
  const auto& pv = domain.plc.vertices;
  for (const std::size_t t : pqmesh::detail::facet_triangle_range(domain, facet)) {
    const auto& tri = domain.facet_triangles[t];
    best = std::min(best, triangle_distance(x, pv[static_cast<std::size_t>(tri[0])], pv[static_cast<std::size_t>(tri[1])],
                                            pv[static_cast<std::size_t>(tri[2])]));
  }
  return best;
}

namespace {

// The facet planes and P-edge cones warping asks about (built on first use,
// owned here), and the P edges of each facet pair. Purpose: one place for the
// domain queries of every step below. Contract: plane(f) and cone(e) return
// the same object for the life of the warp; edges_between lists the P edges
// between two of the given facets, sorted and unique; pair_edges(f, g) is
// null when f and g share no P edge. Thesis §4.3 (facets and P edges of the
// boxes using a vertex).
class WarpGeometry {
 public:
  WarpGeometry(const OctTree& tree_in, const CornerSet& corners_in, const Domain3& domain_in)
      : tree(tree_in), corners(corners_in), domain(domain_in) {
    for (std::size_t e = 0; e < domain.edges.size(); ++e) {
      const auto& f = domain.edges[e].facets;
      pair_edges_[{std::min(f[0], f[1]), std::max(f[0], f[1])}].push_back(static_cast<int>(e));
    }
  }

  const FacetPlane& plane(int f) {
    auto it = planes_.find(f);
    if (it == planes_.end()) it = planes_.emplace(f, std::make_unique<FacetPlane>(domain, f)).first;
    return *it->second;
  }

  const EdgeCone& cone(int e) {
    auto it = cones_.find(e);
    if (it == cones_.end()) it = cones_.emplace(e, std::make_unique<EdgeCone>(domain, e)).first;
    return *it->second;
  }

  const std::vector<int>* pair_edges(int f, int g) const {
    const auto it = pair_edges_.find({std::min(f, g), std::max(f, g)});
    return it == pair_edges_.end() ? nullptr : &it->second;
  }

  std::vector<int> edges_between(std::span<const int> facets) const {
    std::vector<int> out;
    for (std::size_t i = 0; i < facets.size(); ++i)
      for (std::size_t j = i + 1; j < facets.size(); ++j)
        if (const std::vector<int>* edges = pair_edges(facets[i], facets[j]))
          out.insert(out.end(), edges->begin(), edges->end());
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  // The end points of P edge e.
  std::pair<Vec3, Vec3> edge_ends(int e) const {
    const auto& pv = domain.plc.vertices;
    const DomainEdge& de = domain.edges[static_cast<std::size_t>(e)];
    return {pv[static_cast<std::size_t>(de.a)], pv[static_cast<std::size_t>(de.b)]};
  }

  const OctTree& tree;
  const CornerSet& corners;
  const Domain3& domain;

 private:
  std::map<int, std::unique_ptr<FacetPlane>> planes_;
  std::map<int, std::unique_ptr<EdgeCone>> cones_;
  std::map<std::pair<int, int>, std::vector<int>> pair_edges_;
};

bool same_point(Vec3 p, Vec3 q) { return p.x == q.x && p.y == q.y && p.z == q.z; }

bool is_frozen(const WarpOptions& options, const GridPoint& p) {
  return options.frozen != nullptr && options.frozen->count(p) != 0;
}

// The unit vector along axis a.
Vec3 axis_unit(int axis) {
  Vec3 ax;
  (axis == 0 ? ax.x : axis == 1 ? ax.y : ax.z) = 1;
  return ax;
}

// ---------------------------------------------------------------------------
// Face translations (beyond the thesis; bounded random seed 33,
// docs/algorithm/tet3d_warp.md "Face translations"). §4.3's first pass moves
// a box edge l close to a P edge E by h/8 along d (orthogonal to both, away
// from E) and bends the two box faces through l. When E clips the column
// along l of its edge box B (E ∩ B a few thousandths of h long), the apex on
// E ∩ I(B) then lies beyond the prewarped plane of the faces' unmoved parts
// and its cones onto them invert (the rebuild loop would freeze l: apex 0.002
// h from both faces). Here each of those two faces of B is translated
// instead, by the component of the move along its outward normal n (only when
// positive: B grows): l gets exactly the move (h/8) d, every face of B stays
// planar (a face translated along its normal; the four faces beside it only
// stretch in their own planes), and the apex sees them all. h: the smallest
// box using a point of l (§4.3). The moves go through the same side and
// crossing rules and the same fallbacks as every first-pass move.
struct FaceShift {
  int n = 0;                         // face normal axis
  std::int64_t at = 0;               // the face's grid coordinate along n
  std::array<std::int64_t, 4> uv{};  // B's extent along (n + 1) % 3 and (n + 2) % 3
  int edge = -1;
  Vec3 unit;                         // c n: the move per unit h/8 (c > 0 the component)
  double h = INFINITY;               // the smallest box using a point of l; INFINITY: not translated
  GridPoint l0, l1;                  // l's ends
};

// Whether grid point p lies on the translated face of f.
bool on_face(const FaceShift& f, const GridPoint& p) {
  const auto a = static_cast<std::size_t>((f.n + 1) % 3), b = static_cast<std::size_t>((f.n + 2) % 3);
  return p.f[static_cast<std::size_t>(f.n)] == f.at && f.uv[0] <= p.f[a] && p.f[a] <= f.uv[1] && f.uv[2] <= p.f[b] &&
         p.f[b] <= f.uv[3];
}

// Whether grid point p lies on f's box edge l.
bool on_line(const FaceShift& f, const GridPoint& p) {
  int same = 0;
  for (std::size_t i = 0; i < 3; ++i) same += (f.l0.f[i] == f.l1.f[i] && p.f[i] == f.l0.f[i]) ? 1 : 0;
  for (std::size_t i = 0; i < 3; ++i)
    if (f.l0.f[i] != f.l1.f[i] && (p.f[i] < f.l0.f[i] || p.f[i] > f.l1.f[i])) return false;
  return same == 2;
}

// The face translations with an index by face plane, (n, at): the shifts
// whose plane holds a grid point p are the only ones for which on_face or
// on_line can hold (l lies in its face's plane), found by three binary
// searches. Edge boxes accumulate over the rebuild loop's rounds (one per
// inverted cone), so a scan of every shift for every ring point would grow
// with the product of the two (rotor.off: half of its box stage).
class FaceShifts {
 public:
  explicit FaceShifts(std::vector<FaceShift> list) : list_(std::move(list)) {
    by_plane_.reserve(list_.size());
    for (std::size_t i = 0; i < list_.size(); ++i) by_plane_.push_back({list_[i].n, list_[i].at, i});
    std::sort(by_plane_.begin(), by_plane_.end());
  }
  std::vector<FaceShift>& list() { return list_; }
  const std::vector<FaceShift>& list() const { return list_; }
  // The indices of the shifts whose face plane holds p, ascending (the
  // order of `list`).
  void on_planes_of(const GridPoint& p, std::vector<std::size_t>& out) const {
    out.clear();
    for (int n = 0; n < 3; ++n) {
      const PlaneKey lo{n, p.f[static_cast<std::size_t>(n)], 0};
      for (auto it = std::lower_bound(by_plane_.begin(), by_plane_.end(), lo);
           it != by_plane_.end() && it->n == lo.n && it->at == lo.at; ++it)
        out.push_back(it->index);
    }
    std::sort(out.begin(), out.end());
  }

 private:
  struct PlaneKey {
    int n = 0;
    std::int64_t at = 0;
    std::size_t index = 0;
    friend auto operator<=>(const PlaneKey&, const PlaneKey&) = default;
  };
  std::vector<FaceShift> list_;
  std::vector<PlaneKey> by_plane_;  // sorted
};

// Step "find the face translations" (docs/algorithm/tet3d_warp.md "Face
// translations"). Purpose: for every edge box B and each of its twelve box
// edges l closer than h_B/8 to B's P edge E (E not parallel to l), the faces
// of B through l whose outward normal has a positive component c along the
// first pass's direction d; each gets the move c n per unit h/8. Contract:
// the shifts come in the order (box, axis of l, corner k, face n), h not yet
// set (INFINITY). Thesis §4.3, first pass.
std::vector<FaceShift> find_face_shifts(const WarpGeometry& geo, std::span<const EdgeBoxBounds> edge_boxes) {
  std::vector<FaceShift> shifts;
  for (const EdgeBoxBounds& B : edge_boxes) {
    const auto [ea, eb] = geo.edge_ends(B.edge);
    const double hb = std::fabs(grid_coordinates(geo.tree, B.hi).x - grid_coordinates(geo.tree, B.lo).x);
    for (int axis = 0; axis < 3; ++axis)
      for (int k = 0; k < 4; ++k) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        const auto ui = static_cast<std::size_t>(u), vi = static_cast<std::size_t>(v);
        GridPoint l0 = B.lo;
        l0.f[ui] = ((k & 1) ? B.hi : B.lo).f[ui];
        l0.f[vi] = ((k & 2) ? B.hi : B.lo).f[vi];
        GridPoint l1 = l0;
        l1.f[static_cast<std::size_t>(axis)] = B.hi.f[static_cast<std::size_t>(axis)];
        const auto [ps, pe] = closest_points(grid_coordinates(geo.tree, l0), grid_coordinates(geo.tree, l1), ea, eb);
        if (!(norm(ps - pe) < hb / 8)) continue;
        Vec3 d = cross(eb - ea, axis_unit(axis));
        const double len = norm(d);
        if (!(len > 0)) continue;  // E parallel to l (exactly): the line move of the first pass
        d = (1 / len) * d;
        if (dot(d, ps - pe) < 0) d = -1.0 * d;
        for (const int n : {u, v}) {
          const bool upper = (n == u ? (k & 1) : (k & 2)) != 0;
          const double c = (n == 0 ? d.x : n == 1 ? d.y : d.z) * (upper ? 1.0 : -1.0);
          if (!(c > 0)) continue;
          FaceShift f;
          f.n = n;
          f.at = (upper ? B.hi : B.lo).f[static_cast<std::size_t>(n)];
          const int a = (n + 1) % 3, b = (n + 2) % 3;
          f.uv = {B.lo.f[static_cast<std::size_t>(a)], B.hi.f[static_cast<std::size_t>(a)],
                  B.lo.f[static_cast<std::size_t>(b)], B.hi.f[static_cast<std::size_t>(b)]};
          f.edge = B.edge;
          (n == 0 ? f.unit.x : n == 1 ? f.unit.y : f.unit.z) = (upper ? 1.0 : -1.0) * c;
          f.l0 = l0;
          f.l1 = l1;
          shifts.push_back(f);
        }
      }
  }
  return shifts;
}

// Step "measure the translated faces". Purpose: set each shift's h, the
// smallest box using a ring point of its box edge l (§4.3's h), and list the
// ring points on each translated face. Contract: only ring points (not
// square centres) with a facet and a level count; the lists hold indices into
// `candidates`, increasing; a shift whose l holds no such point keeps h =
// INFINITY (not translated).
std::vector<std::vector<std::size_t>> measure_face_shifts(const WarpGeometry& geo, const WarpCandidates& candidates,
                                                          FaceShifts& face_shifts) {
  std::vector<FaceShift>& shifts = face_shifts.list();
  std::vector<std::vector<std::size_t>> face_points(shifts.size());
  if (shifts.empty()) return face_points;
  std::vector<std::size_t> on_planes;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const WarpCandidate& c = candidates[i];
    if (c.facets.empty() || !c.square_corners.empty()) continue;
    const std::int32_t level = std::max(c.level, geo.corners.finest_level(c.p));
    if (level < 0) continue;
    const double hc = std::ldexp(geo.tree.side(0), -level);
    face_shifts.on_planes_of(c.p, on_planes);
    for (const std::size_t s : on_planes) {
      if (on_line(shifts[s], c.p)) shifts[s].h = std::min(shifts[s].h, hc);
      if (on_face(shifts[s], c.p)) face_points[s].push_back(i);
    }
  }
  return face_points;
}

// Whether translating face f by m keeps every decision and clearance of its
// ring point c (the rules listed at fit_face_shifts). Contract: the
// conjunction of every rule over c's facets, P edges and ring neighbours,
// with h' the smallest box using c.
bool face_point_fits(WarpGeometry& geo, const FaceShift& f, const WarpCandidate& c, Vec3 m) {
  bool fits = true;
  const Vec3 x0 = grid_coordinates(geo.tree, c.p), y = x0 + m;
  const double hp = std::ldexp(geo.tree.side(0), -std::max(c.level, geo.corners.finest_level(c.p)));
  for (const int g : c.facets) {
    const FacetPlane& plane = geo.plane(g);
    if (plane.side(x0) == Sign::Zero) continue;  // not moved (exact boundary point)
    if (plane.side(y) != plane.side(x0)) fits = false;
    const double d0 = facet_distance(geo.domain, g, x0), d1 = facet_distance(geo.domain, g, y);
    if (!(d1 >= std::min(d0, hp / 16)) || (d0 > hp / 16 && !(d1 > hp / 16))) fits = false;
  }
  for (const int e : geo.edges_between(c.facets)) {
    const auto [ea, eb] = geo.edge_ends(e);
    const double d0 = segment_distance(x0, ea, eb), d1 = segment_distance(y, ea, eb);
    if (!(d1 >= std::min(d0, hp / 8)) || (d0 > hp / 8 && !(d1 > hp / 8))) fits = false;
    // The crossing rule of keeps_decisions, with the face's ring neighbours
    // translated alike: a ring segment crossed by F or G keeps the side of
    // E's line it passes. E runs nearly in the face and crosses its plane
    // inside B (seed 135: 2°), so beyond that crossing the face moves
    // towards E's line and would pass it.
    const EdgeCone& ec = geo.cone(e);
    for (const GridPoint& w : c.neighbours) {
      const Vec3 w0 = grid_coordinates(geo.tree, w), w1 = on_face(f, w) ? w0 + m : w0;
      const bool crossed = ec.f().side(x0) * ec.f().side(w0) == Sign::Negative ||
                           ec.g().side(x0) * ec.g().side(w0) == Sign::Negative;
      if (crossed && orient3d(ec.a(), ec.b(), x0, w0) != orient3d(ec.a(), ec.b(), y, w1)) fits = false;
    }
  }
  return fits;
}

// Step "adaptive length" (beyond the thesis; suite seeds 135 and 67,
// docs/algorithm/tet3d_warp.md "Face translations"). When E runs nearly in
// the translated face G and crosses its plane inside B (seed 135: 2.1°), the
// face moves away from E below that crossing but towards E's line beyond it:
// the full translation (h/8) c n would carry ring segments of G across E's
// line, those moves would be refused point by point, G would bend past the
// apex on E, and the rebuild loop would freeze the box back to the cube. §4.3
// moves points away from what they are near, never onto it, so G takes the
// largest 2^-k (k = 0..4) of its translation under which every ring point v
// of it keeps, with h' the smallest box using v:
//   * its exact side of every facet of the boxes using v (orient3d, the
//     side rule of keeps_decisions);
//   * for every ring segment [v, w] crossed by F or G of a P edge between
//     two of those facets, the exact side of E's line it passes, w moved
//     alike when it lies on the face (the crossing rule of keeps_decisions);
//   * its clearance to each of those facets: above h'/16 if it was, else
//     no smaller (a facet nearly parallel to G: seed 135's facet 3 at
//     11.6°), and to each of those P edges: above h'/8 if it was, else no
//     smaller (the box across G may be an edge box of another P edge).
// Contract: the length is one per face, so the face stays planar; no
// fraction qualifies: h = INFINITY (not translated; the first pass's line
// moves, as without the box). The clearances are constructions (thresholds,
// either outcome valid); the side tests are exact.
void fit_face_shifts(WarpGeometry& geo, const WarpCandidates& candidates,
                     const std::vector<std::vector<std::size_t>>& face_points, std::vector<FaceShift>& shifts) {
  for (std::size_t s = 0; s < shifts.size(); ++s) {
    FaceShift& f = shifts[s];
    if (!(f.h < INFINITY)) continue;
    double fraction = 0;
    for (double t = 1.0; t >= 1.0 / 16 && fraction == 0; t /= 2) {
      const Vec3 m = (t * f.h / 8) * f.unit;
      bool fits = true;
      for (std::size_t k = 0; k < face_points[s].size() && fits; ++k)
        fits = face_point_fits(geo, f, candidates[face_points[s][k]], m);
      if (fits) fraction = t;
    }
    if (fraction == 0)
      f.h = INFINITY;  // not translated
    else
      f.unit = fraction * f.unit;
  }
}

// The translation of p by the faces that hold it: per (face plane, E) the
// largest of the shifts, summed. Contract: appends to shifted_edges the P
// edges it answers for (their line moves are not added again by the first
// pass), in the order of `shifts`, each once.
Vec3 face_move(const FaceShifts& shifts, const GridPoint& p, std::vector<int>& shifted_edges) {
  Vec3 total;
  std::vector<std::pair<std::array<std::int64_t, 3>, Vec3>> best;  // (n, at, edge) -> move
  std::vector<std::size_t> on_planes;
  shifts.on_planes_of(p, on_planes);
  for (const std::size_t s : on_planes) {
    const FaceShift& f = shifts.list()[s];
    if (!(f.h < INFINITY) || !on_face(f, p)) continue;
    const Vec3 m = (f.h / 8) * f.unit;
    const std::array<std::int64_t, 3> key{f.n, f.at, f.edge};
    auto it = std::find_if(best.begin(), best.end(), [&](const auto& e) { return e.first == key; });
    if (it == best.end())
      best.push_back({key, m});
    else if (norm(m) > norm(it->second))
      it->second = m;
    if (std::find(shifted_edges.begin(), shifted_edges.end(), f.edge) == shifted_edges.end())
      shifted_edges.push_back(f.edge);
  }
  for (const auto& e : best) total = total + e.second;
  return total;
}

// ---------------------------------------------------------------------------
// One ring point v being warped: its candidate, prewarped position x0, §4.3's
// h (the smallest box containing v) and the P edges between two facets of
// the boxes using v.
struct RingPoint {
  const WarpCandidate& c;
  Vec3 x0;
  double h = 0;
  std::vector<int> edges;
};

// Step "first pass" (§4.3; docs/algorithm/tet3d_warp.md "The two passes",
// "The first pass on whole box edges"). Purpose: v's position after the face
// translations and the first pass. Every ring segment [v, w] from v (a piece
// of a box edge) closer than h/8 to a P edge E of the boxes using v moves by
// h/8 orthogonally to both, away from E; moves of distinct (axis, E) pairs
// add up (a box corner near E on two or three box edges). The direction is
// taken from the segment's pair of closest points, computed from the sorted
// end points, so both ends of a segment move alike. Whole box edges come
// first (§4.3 looks at box edges), then ring segments (pieces of box edges,
// or edges of smaller neighbouring squares): a ring point far from E on a box
// edge that passes near E moves with that edge's other points (same
// direction; the same length when they share h), so the edge stays straight
// (beyond the thesis: moving only the pieces near E bends the box edge, the
// apex's cones onto the far squares invert and the rebuild loop freezes the
// whole edge: bounded random seed 122). Contract: `moved` is true when a
// face translation or a line move applied; counts `parallel` and
// `parallel_left` in the table.
struct FirstPass {
  Vec3 x;
  bool moved = false;
};

FirstPass first_pass(const WarpGeometry& geo, const FaceShifts& shifts, const RingPoint& v,
                     WarpTable& table) {
  const WarpCandidate& c = v.c;
  const double h = v.h;
  std::vector<int> shifted_edges;
  Vec3 x = v.x0 + face_move(shifts, c.p, shifted_edges);
  std::vector<std::pair<int, int>> seen;  // (axis, edge)
  for (const int e : shifted_edges)
    for (int axis = 0; axis < 3; ++axis) seen.push_back({axis, e});
  // The box-edge pieces through p as (axis, end coordinates), made once for
  // every P edge below (none without one).
  struct Segment {
    int axis;
    Vec3 lo, hi;
  };
  std::vector<Segment> segments;
  auto add_segment = [&](const GridPoint& lo, const GridPoint& hi) {
    int axis = 0;
    while (axis < 2 && lo.f[static_cast<std::size_t>(axis)] == hi.f[static_cast<std::size_t>(axis)]) ++axis;
    segments.push_back({axis, grid_coordinates(geo.tree, lo), grid_coordinates(geo.tree, hi)});
  };
  if (!v.edges.empty()) {
    segments.reserve(c.box_edges.size() + c.neighbours.size());
    for (const BoxEdgeSpan& be : c.box_edges) {
      const auto [lo, hi] = be.ends(c.p);
      add_segment(lo, hi);
    }
    for (const GridPoint& w : c.neighbours) add_segment(std::min(c.p, w), std::max(c.p, w));
  }
  for (const int e : v.edges) {
    const auto [ea, eb] = geo.edge_ends(e);
    for (const auto& [axis, lo, hi] : segments) {
      if (std::find(seen.begin(), seen.end(), std::pair{axis, e}) != seen.end()) continue;
      const auto [ps, pe] = closest_points(lo, hi, ea, eb);
      if (!(norm(ps - pe) < h / 8)) continue;
      Vec3 d = cross(eb - ea, axis_unit(axis));
      double len = norm(d);
      const bool parallel = !(len > 1e-9 * norm(eb - ea));
      if (parallel) {
        // E parallel to the box edge (a construction decides "parallel";
        // either outcome is a valid move): along the common perpendicular,
        // the closest-point difference without its component on the axis.
        d = ps - pe;
        (axis == 0 ? d.x : axis == 1 ? d.y : d.z) = 0;
        len = norm(d);
        if (!(len > 0)) {
          ++table.parallel_left;  // E on the box edge's line: no direction
          continue;
        }
      }
      d = (1 / len) * d;
      if (dot(d, ps - pe) < 0) d = -1.0 * d;
      table.parallel += parallel ? 1 : 0;
      x = x + (h / 8) * d;
      seen.push_back({axis, e});
    }
  }
  return {x, !seen.empty()};
}

// Why a close vertex stays where the second pass found it.
enum class Stay {
  None,        // moved, or not close to any facet
  Crowded,     // close to two facets without a common edge, or to three (crowded_left)
  ReflexSlot,  // in the exterior slot of a reflex edge: Fig. 4.7's copies per facet
};

// The second pass's result: the target, the facet of the key (the first close
// facet, or -1), whether the bisector rule was used, why v stays, and for
// Stay::ReflexSlot the slot's second facet (`facet` is its first).
struct SecondPass {
  Vec3 to;
  int facet = -1;
  bool bisect = false;
  Stay stay = Stay::None;
  int slot_other = -1;
};

// The second pass near two close facets of one P edge E (§4.3, Fig. 4.7;
// docs/algorithm/tet3d_warp.md "The two passes"). Contract: `r.facet` is
// set; fills in the target and the rule used.
void two_facet_move(WarpGeometry& geo, const RingPoint& v, Vec3 from, const std::vector<int>& close, SecondPass& r) {
  const double h = v.h;
  int edge = -1;
  if (close.size() == 2)
    if (const std::vector<int>* edges = geo.pair_edges(close[0], close[1]); edges != nullptr && edges->size() == 1)
      edge = (*edges)[0];
  const EdgeCone* ec = edge < 0 ? nullptr : &geo.cone(edge);
  const Sign sf = ec ? ec->f().side(from) : Sign::Zero, sg = ec ? ec->g().side(from) : Sign::Zero;
  r.to = from;
  if (ec == nullptr || sf == Sign::Zero || sg == Sign::Zero) {
    r.stay = Stay::Crowded;
  } else if (ec->flat()) {
    // A flat edge: F and G are one plane, moved off as one facet.
    r.to = from + ((sf == Sign::Positive ? 1.0 : -1.0) * h / 16) * ec->f().normal();
  } else if (ec->convex() && sf == Sign::Negative && sg == Sign::Negative) {
    // Acute interior wedge: orthogonal projection onto its bisector plane.
    const Vec3 m = ec->f().normal() - ec->g().normal();
    r.bisect = true;
    r.to = from - (dot(m, from - ec->a()) / dot(m, m)) * m;
  } else if (!ec->convex() && sf == Sign::Positive && sg == Sign::Positive) {
    // In the thin exterior slot of a reflex edge: Fig. 4.7's copies, one per
    // facet (built by copy_into_reflex_slot).
    r.stay = Stay::ReflexSlot;
    r.slot_other = close[1];
  } else {
    // Elsewhere near E (outside a convex edge, or on one side of each
    // plane): h/16 along the sum of the normals oriented to v's sides,
    // which increases v's distance from both planes (a gap the thesis
    // leaves to the first pass; docs/algorithm/tet3d_warp.md).
    const Vec3 d = (sf == Sign::Positive ? 1.0 : -1.0) * ec->f().normal() +
                   (sg == Sign::Positive ? 1.0 : -1.0) * ec->g().normal();
    const double len = norm(d);
    if (!(len > 0.25))
      r.stay = Stay::Crowded;
    else
      r.to = from + (h / 16 / len) * d;
  }
}

// Step "second pass" (§4.3; docs/algorithm/tet3d_warp.md "The two passes").
// Purpose: v's target from `from`: no close facet (distance to the facet
// itself and to its plane <= h/16): stays; one: h/16 along its normal, away
// from it; two of one P edge: two_facet_move. Contract: a pure function of
// its arguments (planes and cones are built on first use only).
SecondPass second_pass(WarpGeometry& geo, const RingPoint& v, Vec3 from) {
  const double h = v.h;
  SecondPass r;
  r.to = from;
  std::vector<int> close;
  for (const int f : v.c.facets)
    if (std::fabs(geo.plane(f).distance(from)) <= h / 16 && facet_distance(geo.domain, f, from) <= h / 16)
      close.push_back(f);
  if (close.empty()) return r;
  r.facet = close[0];
  if (close.size() == 1) {
    const FacetPlane& plane = geo.plane(close[0]);
    r.to = from + ((plane.side(from) == Sign::Positive ? 1.0 : -1.0) * h / 16) * plane.normal();
    return r;
  }
  two_facet_move(geo, v, from, close, r);
  return r;
}

// Step "side rules" (docs/algorithm/tet3d_warp.md "Side rules"). A move of v
// to y is accepted when it changes no decision made on the prewarped points:
// v's side of every facet of every box using v, and, for the ring segments
// from v crossed by F or G of a P edge E between two of v's facets, the side
// of E's line they pass (orient3d(a, b, v, w) decides the crossing's dP
// membership and order, cut_square_edge.hpp), against w's current (possibly
// moved) position in `table`. Sides of the planes are kept, so the same
// segments are crossed before and after. `skip` (a Fig. 4.7 copy's partner
// facet, else -1): a facet whose side is not checked.
bool keeps_decisions(WarpGeometry& geo, const RingPoint& v, const WarpTable& table, Vec3 y, int skip = -1) {
  for (const int f : v.c.facets)
    if (f != skip && geo.plane(f).side(y) != geo.plane(f).side(v.x0)) return false;
  for (const int e : v.edges) {
    const EdgeCone& ec = geo.cone(e);
    for (const GridPoint& w : v.c.neighbours) {
      const Vec3 w0 = grid_coordinates(geo.tree, w);
      const Warp* ww = table.find(w);
      const Vec3 w1 = ww != nullptr ? ww->at : w0;
      const bool crossed = ec.f().side(v.x0) * ec.f().side(w0) == Sign::Negative ||
                           ec.g().side(v.x0) * ec.g().side(w0) == Sign::Negative;
      if (crossed && orient3d(ec.a(), ec.b(), v.x0, w0) != orient3d(ec.a(), ec.b(), y, w1)) return false;
    }
  }
  return true;
}

// Where the table has put each neighbour w of v so far (its entry, else the
// prewarped point), in neighbour order; empty when v has no P edge (the
// clearances below read them only per edge).
std::vector<Vec3> neighbour_ends(const WarpGeometry& geo, const RingPoint& v, const WarpTable& table) {
  std::vector<Vec3> out;
  if (v.edges.empty()) return out;
  out.reserve(v.c.neighbours.size());
  for (const GridPoint& w : v.c.neighbours) {
    const Warp* ww = table.find(w);
    out.push_back(ww != nullptr ? ww->at : grid_coordinates(geo.tree, w));
  }
  return out;
}

// How far z is from what warping moves v away from, as fractions of the
// targets, each capped at 1: h/16 from each facet of v's boxes, h/8 between
// each P edge between two of them and each ring segment [z, w] (w at
// `ends`, neighbour_ends). Contract: one entry per (facet), then per (edge,
// neighbour), in that order, so two calls compare entry by entry.
std::vector<double> clearances(const WarpGeometry& geo, const RingPoint& v, std::span<const Vec3> ends, Vec3 z) {
  const double h = v.h;
  std::vector<double> q;
  for (const int f : v.c.facets) q.push_back(std::min(1.0, facet_distance(geo.domain, f, z) / (h / 16)));
  for (const int e : v.edges) {
    const auto [ea, eb] = geo.edge_ends(e);
    for (const Vec3& w : ends) {
      const auto [zs, ze] = closest_points(z, w, ea, eb);
      q.push_back(std::min(1.0, norm(zs - ze) / (h / 8)));
    }
  }
  return q;
}

// The clearances of z against those of the unmoved point, entry by entry
// (same entries and order as clearances()). Purpose: the test of a shortened
// move without building its vector. Contract: the smallest entry when every
// entry is at least q0's, nullopt at the first entry below it. Cost: at most
// one clearances() call, less on a refusal.
std::optional<double> clearance_if_no_worse(const WarpGeometry& geo, const RingPoint& v, std::span<const Vec3> ends,
                                            Vec3 z, const std::vector<double>& q0) {
  const double h = v.h;
  double smallest = 1.0;
  std::size_t i = 0;
  auto take = [&](double q) {
    smallest = std::min(smallest, q);
    return q >= q0[i++];
  };
  for (const int f : v.c.facets)
    if (!take(std::min(1.0, facet_distance(geo.domain, f, z) / (h / 16)))) return std::nullopt;
  for (const int e : v.edges) {
    const auto [ea, eb] = geo.edge_ends(e);
    for (const Vec3& w : ends) {
      const auto [zs, ze] = closest_points(z, w, ea, eb);
      if (!take(std::min(1.0, norm(zs - ze) / (h / 8)))) return std::nullopt;
    }
  }
  return smallest;
}

// Out-of-face moves of a reported point (WarpOptions::second_only with
// out_of_face, docs/algorithm/tet3d_warp.md "One decision per shared face"):
// p lies on a face of the box whose tetrahedron inverted (the reporting box)
// with normal axis a, and its second pass has the component m along a. Kept
// only when it points out of the reporting box, so that box's face moves away
// from its own cone apex (p reported from boxes on both sides of the plane
// has no such direction).
bool out_of_reporting_box(int a, std::uint8_t sides, double m) {
  const bool low = (sides & (1u << a)) != 0, high = (sides & (8u << a)) != 0;
  return m != 0 && low != high && (m > 0) == high;
}

// Step "reported point" (WarpOptions::second_only; the rebuild loop in
// facet_boxes.cpp; docs/algorithm/tet3d_warp.md "Apexes close to a box
// face"). Purpose: a point whose move inverted a tetrahedron once drops its
// first-pass and face moves, which bend a box face past a cone apex near it
// (an apex on a P edge running nearly in that face); the second pass alone
// from the prewarped point is kept without its components along the axes on
// which the point lies on a face of the inverted tetrahedron's box (`sides`:
// bit a for the low face along axis a, 3 + a for the high face), so that
// box's faces stay in their planes and its cones keep their heights, while
// the point still moves off its close facet within them (for a one-facet
// move, each component kept is the full move's, so the distance to the
// facet's plane does not drop). Frozen with the face, such a point would span
// a Case C1 triangle 0.02 h wide on a face 0.004 h below an edge-box apex
// (every-run seed 30). A point with a second pass only is treated alike
// (freezing it whole would leave it where it is, which on harsh seed 17 is a
// grid point 1e-5 h from F under a two-facet apex). Contract: a point with
// nothing left of its move, frozen, or whose move keeps_decisions refuses
// stays (frozen_left); an outward component is kept only with out_of_face,
// else dropped and counted (out_of_face_left), so the caller knows whether
// the other table would differ (mesh_boxes compares the two meshes).
void warp_reported_point(WarpGeometry& geo, const RingPoint& v, std::uint8_t sides, const WarpOptions& options,
                         WarpTable& table) {
  const SecondPass sp = second_pass(geo, v, v.x0);
  Vec3 z = sp.to;
  const bool moved = sp.stay == Stay::None;
  const auto axes = static_cast<std::uint8_t>(moved ? (sides & 7) | (sides >> 3) : 7);
  int kept = 0, dropped = 0;
  for (int a = 0; a < 3; ++a) {
    if ((axes & (1u << a)) == 0) continue;
    double& za = axis_ref(z, a);
    const double xa = axis_coord(v.x0, a);
    const bool outward = moved && out_of_reporting_box(a, sides, za - xa);
    if (outward && options.out_of_face) {
      ++kept;
      continue;
    }
    dropped += outward ? 1 : 0;
    za = xa;
  }
  table.out_of_face_left += dropped > 0 ? 1 : 0;
  if (same_point(z, v.x0) || is_frozen(options, v.c.p) || !keeps_decisions(geo, v, table, z)) {
    ++table.frozen_left;
    return;
  }
  table.insert(v.c.p, Warp{sp.facet, z});
  table.bisected += sp.bisect ? 1 : 0;
  table.out_of_face += kept > 0 ? 1 : 0;
}

// Step "copies per facet in a reflex slot" (Fig. 4.7, §4.3;
// docs/algorithm/tet3d_warp.md "Copies per facet in a reflex slot"): v lies
// in the exterior slot of reflex edge E, within h/16 of both F and G. v is
// outside P (beyond both planes), never a mesh vertex; it matters only as
// the end of ring segments cut by F (in the boxes on F's side and in E's box)
// or by G. One copy per facet, each warped h/16 away from its own facet
// along its normal (from the first pass's position x, else from the
// prewarped point, else 1/2 .. 1/16 of that move), accepted by the side rules
// except the side of the partner facet: the copy for F serves only F's cuts,
// whose decisions (F's side of v, E's line against [v, w]) it keeps. Contract:
// every decision stays on the prewarped point, which has no entry; counts
// reflex_copied (both copies built), reflex_left or frozen_left.
void copy_into_reflex_slot(WarpGeometry& geo, const RingPoint& v, const FirstPass& fp, const SecondPass& sp,
                           const WarpOptions& options, WarpTable& table) {
  if (is_frozen(options, v.c.p)) {
    ++table.frozen_left;
    return;
  }
  int built = 0;
  for (const int f : {sp.facet, sp.slot_other}) {
    const int partner = f == sp.facet ? sp.slot_other : sp.facet;
    const FacetPlane& plane = geo.plane(f);
    const Vec3 away = ((plane.side(v.x0) == Sign::Positive ? 1.0 : -1.0) * v.h / 16) * plane.normal();
    std::vector<Vec3> targets = {fp.x + away};
    if (fp.moved) targets.push_back(v.x0 + away);
    for (double t = 0.5; t >= 1.0 / 16; t /= 2) targets.push_back(v.x0 + t * away);
    for (const Vec3& z : targets)
      if (keeps_decisions(geo, v, table, z, partner)) {
        table.insert_copy(v.c.p, f, z);
        ++built;
        break;
      }
  }
  ++(built == 2 ? table.reflex_copied : table.reflex_left);
}

// The move a ring point settles on: target, key facet, bisector rule used.
struct Move {
  Vec3 at;
  int facet = -1;
  bool bisect = false;
};

// A refused move's target and key facet, for shortening.
using RefusedMove = std::pair<Vec3, int>;

// Step "fallbacks" (docs/algorithm/tet3d_warp.md "The two passes"). Purpose:
// when the full move y (first pass then second pass) is refused, try the
// first pass alone, then the second pass alone from the prewarped point.
// Contract: returns whether `move` is accepted; `move` starts as the full
// move. Appends the refused second-pass moves to `refused` (the shortening
// applies to them only: shortened first-pass moves moved edge-box apexes
// nearer flat cones, a random frustum went 5,772 -> 14,766). Counts
// `fallback` when a fallback is taken.
bool full_move_or_fallback(WarpGeometry& geo, const RingPoint& v, const FirstPass& fp, WarpTable& table, Move& move,
                           std::vector<RefusedMove>& refused) {
  bool ok = keeps_decisions(geo, v, table, move.at);
  if (!fp.moved) refused.push_back({move.at, move.facet});
  if (ok || !fp.moved) return ok;
  ok = keeps_decisions(geo, v, table, fp.x);
  move.at = fp.x;
  move.bisect = false;
  if (!ok) {
    const SecondPass alone = second_pass(geo, v, v.x0);
    move = Move{alone.to, alone.facet, alone.bisect};
    ok = !same_point(move.at, v.x0) && keeps_decisions(geo, v, table, move.at);
    if (!same_point(move.at, v.x0)) refused.push_back({move.at, move.facet});
  }
  table.fallback += ok ? 1 : 0;
  return ok;
}

// Step "shortened moves" and "moves along a ring segment's line" (beyond the
// thesis; docs/algorithm/tet3d_warp.md "Shortened moves", "Moves along a ring
// segment's line"). Every refused move crosses a plane (or an edge's line)
// that lies closer than the move's length, typically a second facet of a
// thin wedge whose plane, not the facet itself, is near v. The thesis moves
// v regardless; we keep every side decision and take 1/2, 1/4, 1/8 or 1/16
// of a refused second-pass move (alone, from the prewarped point) when it is
// accepted and improves on the prewarped point: no clearance smaller, the
// smallest not met larger; of those, the one with the largest smallest
// clearance (a vertex 0.0003 h from F otherwise stays there: aspect 6,629 on
// a random prism). Line moves: v = x0 moved away from a ring neighbour w,
// along the axis of [v, w], by h/16 or a fraction of it. For the segment
// [v, w] itself the line is unchanged (only one coordinate of v changes), so
// orient3d(a, b, v, w) keeps its sign exactly and F's crossing of it stays
// the same point; when v lies near F and the segment leaves F at an angle,
// this is the part of the thesis's move along F's normal that the side rules
// allow (a box corner clipped by F at 5e-7 h, whose h/16 move along the
// normal changes the side of E's line a crossed segment passes: bounded
// random seed 58). The same rules and the same clearance test decide; line
// moves are tried at full length too (the refused second-pass moves were
// tried already). Key facet of a line move: -1. Contract: returns whether a
// shortened move was found (then `move` holds it, without the bisector
// flag); counts `shortened`.
bool shortened_move(WarpGeometry& geo, const RingPoint& v, WarpTable& table, Move& move,
                    std::vector<RefusedMove>& refused) {
  const std::size_t first_line_move = refused.size();
  for (const GridPoint& w : v.c.neighbours) {
    const Vec3 away = v.x0 - grid_coordinates(geo.tree, w);
    const double len = norm(away);
    if (len > 0) refused.push_back({v.x0 + (v.h / 16 / len) * away, -1});
  }
  bool ok = false;
  // The table does not change during the search: the neighbours' places
  // are looked up once.
  const std::vector<Vec3> ends = neighbour_ends(geo, v, table);
  const std::vector<double> q0 = clearances(geo, v, ends, v.x0);
  double best = q0.empty() ? 1.0 : *std::min_element(q0.begin(), q0.end());
  for (double t = 1.0; t >= 1.0 / 16; t /= 2)
    for (std::size_t r = t == 1.0 ? first_line_move : 0; r < refused.size(); ++r) {
      const auto& [target, key_facet] = refused[r];
      const Vec3 z = v.x0 + t * (target - v.x0);
      const std::optional<double> q = clearance_if_no_worse(geo, v, ends, z, q0);
      if (!q || !(*q > best) || !keeps_decisions(geo, v, table, z)) continue;
      best = *q;
      move.at = z;
      move.facet = key_facet;
      ok = true;
    }
  if (ok) move.bisect = false;
  table.shortened += ok ? 1 : 0;
  return ok;
}

// Step "settle a moved point" (§4.3 acceptance; docs/algorithm/tet3d_warp.md
// "Side rules"). Purpose: enter the full move y (= sp.to) of v, or a fallback
// or shortened move when it is refused. Contract: y equal to the prewarped
// point: no entry, no count; no move accepted: `conflicts`; v frozen:
// `frozen_left`; else one entry keyed (v, facet) and the counts `bisected`
// and `first_pass` (the full move or the first pass alone taken).
void settle_move(WarpGeometry& geo, const RingPoint& v, const FirstPass& fp, const SecondPass& sp,
                 const WarpOptions& options, WarpTable& table) {
  const Vec3 y = sp.to;
  if (same_point(y, v.x0)) return;
  Move move{y, sp.facet, sp.bisect};
  std::vector<RefusedMove> refused;
  bool ok = full_move_or_fallback(geo, v, fp, table, move, refused);
  if (!ok) ok = shortened_move(geo, v, table, move, refused);
  if (!ok) {
    ++table.conflicts;
    return;
  }
  if (is_frozen(options, v.c.p)) {
    ++table.frozen_left;
    return;
  }
  table.insert(v.c.p, Warp{move.facet, move.at});
  table.bisected += move.bisect ? 1 : 0;
  table.first_pass += fp.moved && (same_point(move.at, y) || same_point(move.at, fp.x)) ? 1 : 0;
}

// Step "warp one ring point" (§4.3, both passes). Purpose: the table entry
// (or copies, or counts) of ring point c. Contract: points without a level
// are skipped; a point exactly on a facet plane of its boxes is an exact
// boundary point already, not moved (`on_plane`); a reported point
// (options.second_only) takes warp_reported_point; a point in a reflex slot
// takes its copies (options.reflex_copies; without them it keeps its full
// move's fallbacks and counts reflex_left); every other one settle_move.
void warp_ring_point(WarpGeometry& geo, const FaceShifts& shifts, const WarpCandidate& c,
                     const WarpOptions& options, WarpTable& table) {
  const Vec3 x0 = grid_coordinates(geo.tree, c.p);
  const std::int32_t level = std::max(c.level, geo.corners.finest_level(c.p));
  if (level < 0) return;
  RingPoint v{c, x0, std::ldexp(geo.tree.side(0), -level), {}};
  bool on_some = false;
  for (const int f : c.facets) on_some = on_some || geo.plane(f).side(x0) == Sign::Zero;
  if (on_some) {
    ++table.on_plane;
    return;
  }
  v.edges = geo.edges_between(c.facets);
  const FirstPass fp = first_pass(geo, shifts, v, table);
  if (options.second_only != nullptr)
    if (const auto it = options.second_only->find(c.p); it != options.second_only->end()) {
      warp_reported_point(geo, v, it->second, options, table);
      return;
    }
  const SecondPass sp = second_pass(geo, v, fp.x);
  table.crowded_left += sp.stay == Stay::Crowded;
  table.reflex_left += sp.stay == Stay::ReflexSlot && !options.reflex_copies;
  if (sp.stay == Stay::ReflexSlot && options.reflex_copies) {
    copy_into_reflex_slot(geo, v, fp, sp, options, table);
    return;
  }
  settle_move(geo, v, fp, sp, options, table);
}

// Step "square centre" (beyond the thesis; docs/algorithm/tet3d_warp.md
// "Square centres move with their corners"). Purpose: a square's centre c is
// moved by the mean of its four corners' moves (the centre of the bilinear
// patch through the warped corners). Contract: runs after every ring point;
// c on a facet plane of the boxes using the square is not moved (`on_plane`);
// a move changing c's exact side of such a plane is refused (`conflicts`);
// frozen: `frozen_left`; else one entry keyed (c, -1), counted `centres`.
void warp_square_centre(WarpGeometry& geo, const WarpCandidate& c, const WarpOptions& options, WarpTable& table) {
  Vec3 move;
  bool moved = false;
  for (const GridPoint& q : c.square_corners)
    if (const Warp* w = table.find(q)) {
      move = move + (w->at - grid_coordinates(geo.tree, q));
      moved = true;
    }
  if (!moved) return;
  const Vec3 x0 = grid_coordinates(geo.tree, c.p);
  const Vec3 y = x0 + (1.0 / static_cast<double>(c.square_corners.size())) * move;
  bool on_some = false, kept = true;
  for (const int f : c.facets) {
    const Sign s0 = geo.plane(f).side(x0);
    on_some = on_some || s0 == Sign::Zero;
    kept = kept && geo.plane(f).side(y) == s0;
  }
  if (on_some) {
    ++table.on_plane;
    return;
  }
  if (!kept) {
    ++table.conflicts;
    return;
  }
  if (is_frozen(options, c.p)) {
    ++table.frozen_left;
    return;
  }
  table.insert(c.p, Warp{-1, y});
  ++table.centres;
}

// Candidate i decided: a ring point (with a facet; warp_ring_point) or a
// square centre (warp_square_centre), recorded in `journal` if any.
void decide(WarpGeometry& geo, const FaceShifts& shifts, std::uint32_t i, const WarpCandidate& c,
            const WarpOptions& options, WarpTable& table, WarpJournal* journal) {
  const bool centre = !c.square_corners.empty();
  if (!centre && c.facets.empty()) return;
  const WarpCounts before = journal != nullptr ? warp_counts(table) : WarpCounts{};
  const std::size_t copies_before = table.copy_count();
  if (centre)
    warp_square_centre(geo, c, options, table);
  else
    warp_ring_point(geo, shifts, c, options, table);
  if (journal != nullptr) record_point(i, c, before, copies_before, table, *journal);
}

bool same_warp(const Warp* a, const Warp* b) {
  if (a == nullptr || b == nullptr) return a == b;
  return a->facet == b->facet && a->at == b->at;
}

// The face translations of the edge boxes, each at its fitted length.
FaceShifts fitted_face_shifts(WarpGeometry& geo, const WarpCandidates& candidates, const WarpOptions& options) {
  FaceShifts shifts(find_face_shifts(geo, options.edge_boxes));
  const std::vector<std::vector<std::size_t>> face_points = measure_face_shifts(geo, candidates, shifts);
  fit_face_shifts(geo, candidates, face_points, shifts.list());
  return shifts;
}

}  // namespace

// A journal's face translations: a rebuild with the same edge boxes has the
// same ones.
struct JournalShifts {
  FaceShifts shifts;
};

// §4.3, both passes, as a list of steps (warp.hpp; docs/algorithm/tet3d_warp.md
// "The two passes"): the face translations of the edge boxes, their adaptive
// length, every ring point in candidate order (first pass, second pass, side
// rules, fallbacks), then the square centres (the candidates after the ring
// points).
WarpTable warp_box_vertices(const OctTree& tree, const CornerSet& corners, const Domain3& domain,
                            const WarpCandidates& candidates, const WarpOptions& options, WarpJournal* journal) {
  WarpGeometry geo(tree, corners, domain);
  auto shifts = std::make_shared<const JournalShifts>(JournalShifts{fitted_face_shifts(geo, candidates, options)});
  if (journal != nullptr) {
    *journal = WarpJournal{};
    journal->edge_boxes = options.edge_boxes.size();
    journal->shifts = shifts;
  }
  WarpTable table;
  for (std::size_t i = 0; i < candidates.size(); ++i)
    decide(geo, shifts->shifts, static_cast<std::uint32_t>(i), candidates[i], options, table, journal);
  return table;
}

// The steps of warp_box_vertices with the journal's face translations, each
// candidate either decided again or given its old outcome (warp.hpp: when
// that is the same table). A ring point depends on its own options and its
// ring neighbours' entries, a centre on its own options and its corners'
// entries: `differs` collects the candidates whose entry or copies changed.
WarpTable rewarp_box_vertices(const OctTree& tree, const CornerSet& corners, const Domain3& domain,
                              const WarpCandidates& candidates, const WarpOptions& options, const WarpTable& old,
                              const std::unordered_set<GridPoint, GridPointHash>& changed, WarpJournal& journal) {
  if (journal.edge_boxes != options.edge_boxes.size() || !journal.shifts)
    throw InternalError("tet3d: a warp rebuild with other edge boxes than its journal's");
  WarpGeometry geo(tree, corners, domain);
  WarpJournal next;
  next.edge_boxes = journal.edge_boxes;
  next.shifts = journal.shifts;
  JournalCursor cursor(journal);
  std::unordered_set<GridPoint, GridPointHash> differs;
  const auto any_differs = [&](const auto& points) {
    if (differs.empty()) return false;
    for (const GridPoint& w : points)
      if (differs.count(w) != 0) return true;
    return false;
  };
  WarpTable table;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const WarpCandidate c = candidates[i];
    const bool centre = !c.square_corners.empty();
    if (!centre && c.facets.empty()) continue;
    const auto point = static_cast<std::uint32_t>(i);
    if (changed.count(c.p) == 0 && !(centre ? any_differs(c.square_corners) : any_differs(c.neighbours))) {
      if (const Warp* w = old.find(c.p)) table.insert(c.p, *w);
      cursor.replay(point, c, table, next);
      continue;
    }
    decide(geo, next.shifts->shifts, point, c, options, table, &next);
    // Both tests run: same_copies moves the cursor past the old copies.
    if (!same_warp(table.find(c.p), old.find(c.p)) | !cursor.same_copies(point, next)) differs.insert(c.p);
  }
  journal = std::move(next);
  return table;
}

WarpTable warp_facet_vertices(const OctTree& tree, const CornerSet& corners, const Domain3& domain,
                              std::span<const FacetLeaf> boxes) {
  WarpCandidateBuilder builder;
  std::vector<FaceSquare> squares;
  std::vector<GridPoint> ring;
  for (const FacetLeaf& fb : boxes) {
    squares.clear();
    for (int axis = 0; axis < 3; ++axis)
      for (const bool upper : {false, true}) face_squares(tree.key(fb.leaf), axis, upper, corners, squares);
    for (const FaceSquare& s : squares) {
      square_ring(s, corners, ring);
      builder.add_points(ring, std::span<const int>(&fb.facet, 1));
    }
  }
  const WarpCandidates candidates = builder.finish();
  return warp_box_vertices(tree, corners, domain, candidates);
}

int grid_vertex(const GridPoint& p, const OctTree& tree, const WarpTable* warps, PointBook& book) {
  // A book resolving through the same table does this lookup itself (id()):
  // one probe per grid point instead of two.
  if (warps != nullptr && warps != book.warps())
    if (const Warp* w = warps->find(p)) return book.id({VertexKind::Warped, p, {}, w->facet}, [&] { return w->at; });
  return book.id(grid_key(p), [&] { return grid_coordinates(tree, p); });
}

}  // namespace pqmesh::tet3d
