#include "tet3d/warp.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "tet3d/cut_square_edge.hpp"
#include "tet3d/facet_plane.hpp"

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
  for (std::size_t t = 0; t < domain.facet_triangles.size(); ++t) {
    if (domain.facet_triangle_owner[t] != facet) continue;
    const auto& tri = domain.facet_triangles[t];
    best = std::min(best, triangle_distance(x, pv[static_cast<std::size_t>(tri[0])], pv[static_cast<std::size_t>(tri[1])],
                                            pv[static_cast<std::size_t>(tri[2])]));
  }
  return best;
}

WarpTable warp_box_vertices(const OctTree& tree, const CornerSet& corners, const Domain3& domain,
                            const WarpCandidates& candidates,
                            const std::unordered_set<GridPoint, GridPointHash>* frozen, bool reflex_copies,
                            std::span<const EdgeBoxBounds> edge_boxes,
                            const std::unordered_map<GridPoint, std::uint8_t, GridPointHash>* second_only,
                            bool out_of_face) {
  WarpTable table;
  std::map<int, std::unique_ptr<FacetPlane>> planes;
  auto plane_of = [&](int f) -> const FacetPlane& {
    auto it = planes.find(f);
    if (it == planes.end()) it = planes.emplace(f, std::make_unique<FacetPlane>(domain, f)).first;
    return *it->second;
  };
  std::map<int, std::unique_ptr<EdgeCone>> cones;
  auto cone_of = [&](int e) -> const EdgeCone& {
    auto it = cones.find(e);
    if (it == cones.end()) it = cones.emplace(e, std::make_unique<EdgeCone>(domain, e)).first;
    return *it->second;
  };
  std::map<std::pair<int, int>, std::vector<int>> pair_edges;
  for (std::size_t e = 0; e < domain.edges.size(); ++e) {
    const auto& f = domain.edges[e].facets;
    pair_edges[{std::min(f[0], f[1]), std::max(f[0], f[1])}].push_back(static_cast<int>(e));
  }
  auto edges_between = [&](std::span<const int> facets) {
    std::vector<int> out;
    for (std::size_t i = 0; i < facets.size(); ++i)
      for (std::size_t j = i + 1; j < facets.size(); ++j) {
        const auto it = pair_edges.find({std::min(facets[i], facets[j]), std::max(facets[i], facets[j])});
        if (it != pair_edges.end()) out.insert(out.end(), it->second.begin(), it->second.end());
      }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  };
  const auto& pv = domain.plc.vertices;
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
    int n = 0;                      // face normal axis
    std::int64_t at = 0;            // the face's grid coordinate along n
    std::array<std::int64_t, 4> uv{};  // B's extent along (n + 1) % 3 and (n + 2) % 3
    int edge = -1;
    Vec3 unit;                      // c n: the move per unit h/8 (c > 0 the component)
    double h = INFINITY;            // the smallest box using a point of l
    GridPoint l0, l1;               // l's ends
  };
  std::vector<FaceShift> shifts;
  for (const EdgeBoxBounds& B : edge_boxes) {
    const DomainEdge& de = domain.edges[static_cast<std::size_t>(B.edge)];
    const Vec3 ea = pv[static_cast<std::size_t>(de.a)], eb = pv[static_cast<std::size_t>(de.b)];
    const double hb = std::fabs(grid_coordinates(tree, B.hi).x - grid_coordinates(tree, B.lo).x);
    for (int axis = 0; axis < 3; ++axis)
      for (int k = 0; k < 4; ++k) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        const auto ui = static_cast<std::size_t>(u), vi = static_cast<std::size_t>(v);
        GridPoint l0 = B.lo;
        l0.f[ui] = ((k & 1) ? B.hi : B.lo).f[ui];
        l0.f[vi] = ((k & 2) ? B.hi : B.lo).f[vi];
        GridPoint l1 = l0;
        l1.f[static_cast<std::size_t>(axis)] = B.hi.f[static_cast<std::size_t>(axis)];
        const auto [ps, pe] = closest_points(grid_coordinates(tree, l0), grid_coordinates(tree, l1), ea, eb);
        if (!(norm(ps - pe) < hb / 8)) continue;
        Vec3 ax;
        (axis == 0 ? ax.x : axis == 1 ? ax.y : ax.z) = 1;
        Vec3 d = cross(eb - ea, ax);
        const double len = norm(d);
        if (!(len > 0)) continue;  // E parallel to l (exactly): the line move as before
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
  auto on_face = [](const FaceShift& f, const GridPoint& p) {
    const auto a = static_cast<std::size_t>((f.n + 1) % 3), b = static_cast<std::size_t>((f.n + 2) % 3);
    return p.f[static_cast<std::size_t>(f.n)] == f.at && f.uv[0] <= p.f[a] && p.f[a] <= f.uv[1] &&
           f.uv[2] <= p.f[b] && p.f[b] <= f.uv[3];
  };
  auto on_line = [](const FaceShift& f, const GridPoint& p) {
    int same = 0;
    for (std::size_t i = 0; i < 3; ++i)
      same += (f.l0.f[i] == f.l1.f[i] && p.f[i] == f.l0.f[i]) ? 1 : 0;
    for (std::size_t i = 0; i < 3; ++i)
      if (f.l0.f[i] != f.l1.f[i] && (p.f[i] < f.l0.f[i] || p.f[i] > f.l1.f[i])) return false;
    return same == 2;
  };
  // The ring points of each translated face (indices into candidates).
  std::vector<std::vector<std::size_t>> face_points(shifts.size());
  if (!shifts.empty())
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      const WarpCandidate& c = candidates[i];
      if (c.facets.empty() || !c.square_corners.empty()) continue;
      const std::int32_t level = std::max(c.level, corners.finest_level(c.p));
      if (level < 0) continue;
      const double hc = std::ldexp(tree.side(0), -level);
      for (std::size_t s = 0; s < shifts.size(); ++s) {
        if (on_line(shifts[s], c.p)) shifts[s].h = std::min(shifts[s].h, hc);
        if (on_face(shifts[s], c.p)) face_points[s].push_back(i);
      }
    }
  // Adaptive length (beyond the thesis; suite seeds 135 and 67,
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
  //     side rule of `accept`);
  //   * for every ring segment [v, w] crossed by F or G of a P edge between
  //     two of those facets, the exact side of E's line it passes, w moved
  //     alike when it lies on the face (the crossing rule of `accept`);
  //   * its clearance to each of those facets: above h'/16 if it was, else
  //     no smaller (a facet nearly parallel to G: seed 135's facet 3 at
  //     11.6°), and to each of those P edges: above h'/8 if it was, else no
  //     smaller (the box across G may be an edge box of another P edge).
  // The length is one per face, so the face stays planar; no fraction
  // qualifies: the face is not translated (the first pass's line moves, as
  // without the box). The clearances are constructions (thresholds, either
  // outcome valid); the side tests are exact.
  for (std::size_t s = 0; s < shifts.size(); ++s) {
    FaceShift& f = shifts[s];
    if (!(f.h < INFINITY)) continue;
    double fraction = 0;
    for (double t = 1.0; t >= 1.0 / 16 && fraction == 0; t /= 2) {
      const Vec3 m = (t * f.h / 8) * f.unit;
      bool fits = true;
      for (std::size_t k = 0; k < face_points[s].size() && fits; ++k) {
        const WarpCandidate& c = candidates[face_points[s][k]];
        const Vec3 x0 = grid_coordinates(tree, c.p), y = x0 + m;
        const double hp = std::ldexp(tree.side(0), -std::max(c.level, corners.finest_level(c.p)));
        for (const int g : c.facets) {
          const FacetPlane& plane = plane_of(g);
          if (plane.side(x0) == Sign::Zero) continue;  // not moved (exact boundary point)
          if (plane.side(y) != plane.side(x0)) fits = false;
          const double d0 = facet_distance(domain, g, x0), d1 = facet_distance(domain, g, y);
          if (!(d1 >= std::min(d0, hp / 16)) || (d0 > hp / 16 && !(d1 > hp / 16))) fits = false;
        }
        for (const int e : edges_between(c.facets)) {
          const DomainEdge& de = domain.edges[static_cast<std::size_t>(e)];
          const Vec3 ea = pv[static_cast<std::size_t>(de.a)], eb = pv[static_cast<std::size_t>(de.b)];
          const double d0 = segment_distance(x0, ea, eb), d1 = segment_distance(y, ea, eb);
          if (!(d1 >= std::min(d0, hp / 8)) || (d0 > hp / 8 && !(d1 > hp / 8))) fits = false;
          // The crossing rule of `accept` below, with the face's ring
          // neighbours translated alike: a ring segment crossed by F or G
          // keeps the side of E's line it passes. E runs nearly in the face
          // and crosses its plane inside B (seed 135: 2°), so beyond that
          // crossing the face moves towards E's line and would pass it.
          const EdgeCone& ec = cone_of(e);
          for (const GridPoint& w : c.neighbours) {
            const Vec3 w0 = grid_coordinates(tree, w), w1 = on_face(f, w) ? w0 + m : w0;
            const bool crossed = ec.f().side(x0) * ec.f().side(w0) == Sign::Negative ||
                                 ec.g().side(x0) * ec.g().side(w0) == Sign::Negative;
            if (crossed && orient3d(ec.a(), ec.b(), x0, w0) != orient3d(ec.a(), ec.b(), y, w1)) fits = false;
          }
        }
      }
      if (fits) fraction = t;
    }
    if (fraction == 0)
      f.h = INFINITY;  // not translated
    else
      f.unit = fraction * f.unit;
  }
  // The translation of p: per (face plane, E) the largest of the shifts
  // whose face holds p; and the P edges it answers for (their line moves
  // are not added again).
  auto face_move = [&](const GridPoint& p, std::vector<int>& shifted_edges) {
    Vec3 total;
    std::vector<std::pair<std::array<std::int64_t, 3>, Vec3>> best;  // (n, at, edge) -> move
    for (const FaceShift& f : shifts) {
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
  };
  // Out-of-face moves of a reported point (`second_only` with `out_of_face`,
  // docs/algorithm/tet3d_warp.md): p lies on a face of the box whose
  // tetrahedron inverted (the reporting box) with normal axis a, and its second
  // pass has the component m along a. Kept only when it points out of the
  // reporting box, so that box's face moves away from its own cone apex (p
  // reported from boxes on both sides of the plane has no such direction).
  // Whether the box across takes it well is decided by the caller (mesh_boxes
  // compares the two meshes). Without `out_of_face` such components are dropped
  // and the points counted (out_of_face_left), so the caller knows whether the
  // other table would differ.
  auto out_of_reporting_box = [](int a, std::uint8_t sides, double m) {
    const bool low = (sides & (1u << a)) != 0, high = (sides & (8u << a)) != 0;
    return m != 0 && low != high && (m > 0) == high;
  };
  for (const WarpCandidate& c : candidates) {
    if (c.facets.empty() || !c.square_corners.empty()) continue;
    const Vec3 x0 = grid_coordinates(tree, c.p);
    const std::int32_t level = std::max(c.level, corners.finest_level(c.p));
    if (level < 0) continue;
    const double h = std::ldexp(tree.side(0), -level);
    bool on_some = false;
    for (const int f : c.facets) on_some = on_some || plane_of(f).side(x0) == Sign::Zero;
    // Exactly on a facet plane: an exact boundary point already, not moved.
    if (on_some) {
      ++table.on_plane;
      continue;
    }
    const std::vector<int> edges = edges_between(c.facets);
    // First pass: every ring segment [v, w] from v (a piece of a box edge)
    // closer than h/8 to a P edge E of the boxes using v moves by h/8
    // orthogonally to both, away from E; moves of distinct (axis, E) pairs
    // add up (a box corner near E on two or three box edges). The direction
    // is taken from the segment's pair of closest points, computed from the
    // sorted end points, so both ends of a segment move alike.
    std::vector<int> shifted_edges;
    Vec3 x = x0 + face_move(c.p, shifted_edges);
    std::vector<std::pair<int, int>> seen;  // (axis, edge)
    for (const int e : shifted_edges)
      for (int axis = 0; axis < 3; ++axis) seen.push_back({axis, e});
    // Whole box edges first (§4.3 looks at box edges), then ring segments
    // (pieces of box edges, or edges of smaller neighbouring squares): a ring
    // point far from E on a box edge that passes near E moves with that edge's
    // other points (same direction; the same length when they share h), so the
    // edge stays straight (beyond the thesis: moving only the pieces near E
    // bends the box edge, the apex's cones onto the far squares invert and the
    // rebuild loop freezes the whole edge: bounded random seed 122,
    // docs/algorithm/tet3d_warp.md "The first pass on whole box edges").
    std::vector<std::pair<GridPoint, GridPoint>> segments;
    segments.reserve(c.box_edges.size() + c.neighbours.size());
    for (const BoxEdgeSpan& be : c.box_edges) segments.push_back(be.ends(c.p));
    for (const GridPoint& w : c.neighbours) segments.push_back({std::min(c.p, w), std::max(c.p, w)});
    for (const int e : edges) {
      const DomainEdge& de = domain.edges[static_cast<std::size_t>(e)];
      const Vec3 ea = pv[static_cast<std::size_t>(de.a)], eb = pv[static_cast<std::size_t>(de.b)];
      for (const auto& [lo, hi] : segments) {
        int axis = 0;
        while (axis < 2 && lo.f[static_cast<std::size_t>(axis)] == hi.f[static_cast<std::size_t>(axis)]) ++axis;
        if (std::find(seen.begin(), seen.end(), std::pair{axis, e}) != seen.end()) continue;
        const auto [ps, pe] = closest_points(grid_coordinates(tree, lo), grid_coordinates(tree, hi), ea, eb);
        if (!(norm(ps - pe) < h / 8)) continue;
        Vec3 ax;
        (axis == 0 ? ax.x : axis == 1 ? ax.y : ax.z) = 1;
        Vec3 d = cross(eb - ea, ax);
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
    const bool first = !seen.empty();
    // Second pass from `from`; sets the facet of the key, whether the
    // bisector rule was used, and the reason a close vertex stays (0: none,
    // 1: crowded, 2: in a reflex edge's slot, copies per facet below; then
    // `slot_other` is the slot's second facet, `facet` its first).
    int slot_other = -1;
    auto second_pass = [&](Vec3 from, int& facet, bool& bisect, int& left) {
      facet = -1;
      slot_other = -1;
      bisect = false;
      left = 0;
      std::vector<int> close;
      for (const int f : c.facets)
        if (std::fabs(plane_of(f).distance(from)) <= h / 16 && facet_distance(domain, f, from) <= h / 16)
          close.push_back(f);
      if (close.empty()) return from;
      facet = close[0];
      if (close.size() == 1) {
        const FacetPlane& plane = plane_of(close[0]);
        return from + ((plane.side(from) == Sign::Positive ? 1.0 : -1.0) * h / 16) * plane.normal();
      }
      int edge = -1;
      if (close.size() == 2) {
        const auto it = pair_edges.find({std::min(close[0], close[1]), std::max(close[0], close[1])});
        if (it != pair_edges.end() && it->second.size() == 1) edge = it->second[0];
      }
      const EdgeCone* ec = edge < 0 ? nullptr : &cone_of(edge);
      const Sign sf = ec ? ec->f().side(from) : Sign::Zero, sg = ec ? ec->g().side(from) : Sign::Zero;
      if (ec == nullptr || sf == Sign::Zero || sg == Sign::Zero) {
        left = 1;
        return from;
      }
      if (ec->flat()) {
        // A flat edge: F and G are one plane, moved off as one facet.
        return from + ((sf == Sign::Positive ? 1.0 : -1.0) * h / 16) * ec->f().normal();
      }
      if (ec->convex() && sf == Sign::Negative && sg == Sign::Negative) {
        // Acute interior wedge: orthogonal projection onto its bisector plane.
        const Vec3 m = ec->f().normal() - ec->g().normal();
        bisect = true;
        return from - (dot(m, from - ec->a()) / dot(m, m)) * m;
      }
      if (!ec->convex() && sf == Sign::Positive && sg == Sign::Positive) {
        // In the thin exterior slot of a reflex edge: Fig. 4.7's copies,
        // one per facet (built by the caller).
        left = 2;
        slot_other = close[1];
        return from;
      }
      // Elsewhere near E (outside a convex edge, or on one side of each
      // plane): h/16 along the sum of the normals oriented to v's sides,
      // which increases v's distance from both planes (a gap the thesis
      // leaves to the first pass; docs/algorithm/tet3d_warp.md).
      const Vec3 d = (sf == Sign::Positive ? 1.0 : -1.0) * ec->f().normal() +
                     (sg == Sign::Positive ? 1.0 : -1.0) * ec->g().normal();
      const double len = norm(d);
      if (!(len > 0.25)) {
        left = 1;
        return from;
      }
      return from + (h / 16 / len) * d;
    };
    // A move is accepted when it changes no decision made on the prewarped
    // points: v's side of every facet of every box using v, and, for the
    // ring segments from v crossed by F or G of a P edge E between two of
    // v's facets, the side of E's line they pass (orient3d(a, b, v, w)
    // decides the crossing's dP membership and order, cut_square_edge.hpp),
    // against w's current (possibly moved) position. Sides of the planes
    // are kept, so the same segments are crossed before and after.
    // `skip` (a Fig. 4.7 copy's partner facet, else -1): a facet whose side
    // is not checked.
    auto accept_except = [&](Vec3 y, int skip) {
      for (const int f : c.facets)
        if (f != skip && plane_of(f).side(y) != plane_of(f).side(x0)) return false;
      for (const int e : edges) {
        const EdgeCone& ec = cone_of(e);
        for (const GridPoint& w : c.neighbours) {
          const Vec3 w0 = grid_coordinates(tree, w);
          const Warp* ww = table.find(w);
          const Vec3 w1 = ww != nullptr ? ww->at : w0;
          const bool crossed = ec.f().side(x0) * ec.f().side(w0) == Sign::Negative ||
                               ec.g().side(x0) * ec.g().side(w0) == Sign::Negative;
          if (crossed && orient3d(ec.a(), ec.b(), x0, w0) != orient3d(ec.a(), ec.b(), y, w1)) return false;
        }
      }
      return true;
    };
    auto accept = [&](Vec3 y) { return accept_except(y, -1); };
    // How far z is from what warping moves v away from, as fractions of the
    // targets, each capped at 1: h/16 from each facet of v's boxes, h/8
    // between each P edge between two of them and each ring segment [z, w]
    // (w where the table has put it so far).
    auto clearances = [&](Vec3 z) {
      std::vector<double> q;
      for (const int f : c.facets) q.push_back(std::min(1.0, facet_distance(domain, f, z) / (h / 16)));
      for (const int e : edges) {
        const DomainEdge& de = domain.edges[static_cast<std::size_t>(e)];
        const Vec3 ea = pv[static_cast<std::size_t>(de.a)], eb = pv[static_cast<std::size_t>(de.b)];
        for (const GridPoint& w : c.neighbours) {
          const Warp* ww = table.find(w);
          const auto [zs, ze] = closest_points(z, ww != nullptr ? ww->at : grid_coordinates(tree, w), ea, eb);
          q.push_back(std::min(1.0, norm(zs - ze) / (h / 8)));
        }
      }
      return q;
    };
    int facet = -1, left = 0;
    bool bisect = false;
    // A point whose move inverted a tetrahedron once (`second_only`, the
    // rebuild loop in facet_boxes.cpp): the first-pass and face moves, which
    // bend a box face past a cone apex near it (an apex on a P edge running
    // nearly in that face), are dropped; the second pass alone from the
    // prewarped point is kept without its components along the axes on which
    // the point lies on a face of the inverted tetrahedron's box (`axes`, bit a
    // for axis a), so that box's faces stay in their planes and its cones keep
    // their heights, while the point still moves off its close facet within
    // them (for a one-facet move, each component kept is the full move's, so
    // the distance to the facet's plane does not drop; the side rules decide as
    // for every move). Frozen with the face, such a point would span a Case C1
    // triangle 0.02 h wide on a face 0.004 h below an edge-box apex (every-run
    // seed 30, docs/algorithm/tet3d_warp.md "Apexes close to a box face"). A
    // point with a second pass only is treated alike (freezing it whole would
    // leave it where it is, which on harsh seed 17 is a grid point 1e-5 h from
    // F under a two-facet apex). A point with nothing left of its move, or
    // whose move a rule refuses, is left in place (frozen); reported again, it
    // is frozen.
    if (second_only != nullptr) {
      const auto it = second_only->find(c.p);
      if (it != second_only->end()) {
        Vec3 z = second_pass(x0, facet, bisect, left);
        const std::uint8_t sides = it->second;
        const auto axes = static_cast<std::uint8_t>(left == 0 ? (sides & 7) | (sides >> 3) : 7);
        int kept = 0, dropped = 0;
        for (int a = 0; a < 3; ++a) {
          if ((axes & (1u << a)) == 0) continue;
          double& za = axis_ref(z, a);
          const double xa = axis_coord(x0, a);
          const bool outward = left == 0 && out_of_reporting_box(a, sides, za - xa);
          if (outward && out_of_face) {
            ++kept;
            continue;
          }
          dropped += outward ? 1 : 0;
          za = xa;
        }
        table.out_of_face_left += dropped > 0 ? 1 : 0;
        const bool same_point = z.x == x0.x && z.y == x0.y && z.z == x0.z;
        if (same_point || (frozen != nullptr && frozen->count(c.p) != 0) || !accept(z)) {
          ++table.frozen_left;
          continue;
        }
        table.insert(c.p, Warp{facet, z});
        table.bisected += bisect ? 1 : 0;
        table.out_of_face += kept > 0 ? 1 : 0;
        continue;
      }
    }
    const Vec3 y = second_pass(x, facet, bisect, left);
    table.crowded_left += left == 1;
    // Without copies (reflex_copies false, a test hook): v keeps its
    // first-pass move only, counted.
    table.reflex_left += left == 2 && !reflex_copies;
    if (left == 2 && reflex_copies) {
      // Fig. 4.7 (§4.3): v lies in the exterior slot of reflex edge E,
      // within h/16 of both F and G. v is outside P (beyond both planes),
      // never a mesh vertex; it matters only as the end of ring segments cut
      // by F (in the boxes on F's side and in E's box) or by G. One copy per
      // facet, each warped h/16 away from its own facet along its normal
      // (from the first pass's position, else from the prewarped point, else
      // 1/2 .. 1/16 of that move), accepted by the rules above except the
      // side of the partner facet: the copy for F serves only F's cuts,
      // whose decisions (F's side of v, E's line against [v, w]) it keeps;
      // every decision stays on the prewarped point, which has no entry.
      if (frozen != nullptr && frozen->count(c.p) != 0) {
        ++table.frozen_left;
        continue;
      }
      int built = 0;
      for (const int f : {facet, slot_other}) {
        const int partner = f == facet ? slot_other : facet;
        const FacetPlane& plane = plane_of(f);
        const Vec3 away = ((plane.side(x0) == Sign::Positive ? 1.0 : -1.0) * h / 16) * plane.normal();
        std::vector<Vec3> targets = {x + away};
        if (first) targets.push_back(x0 + away);
        for (double t = 0.5; t >= 1.0 / 16; t /= 2) targets.push_back(x0 + t * away);
        for (const Vec3& z : targets)
          if (accept_except(z, partner)) {
            table.insert_copy(c.p, f, z);
            ++built;
            break;
          }
      }
      ++(built == 2 ? table.reflex_copied : table.reflex_left);
      continue;
    }
    auto same = [](Vec3 p, Vec3 q) { return p.x == q.x && p.y == q.y && p.z == q.z; };
    if (same(y, x0)) continue;
    // Fallbacks when the full move is refused: the first pass alone, then
    // the second pass alone from the prewarped point.
    Vec3 chosen = y;
    bool ok = accept(y);
    // Refused second-pass moves (target, key facet): the shortening below
    // applies to them only (shortened first-pass moves moved edge-box
    // apexes nearer flat cones: a random frustum went 5,772 -> 14,766).
    std::vector<std::pair<Vec3, int>> refused;
    if (!first) refused.push_back({y, facet});
    if (!ok && first) {
      ok = accept(x);
      chosen = x;
      bisect = false;
      if (!ok) {
        int l2 = 0;
        chosen = second_pass(x0, facet, bisect, l2);
        ok = !same(chosen, x0) && accept(chosen);
        if (!same(chosen, x0)) refused.push_back({chosen, facet});
      }
      table.fallback += ok ? 1 : 0;
    }
    // Shortened moves (beyond the thesis): every refused move crosses a plane (or
    // an edge's line) that lies closer than the move's length, typically a
    // second facet of a thin wedge whose plane, not the facet itself, is
    // near v. The thesis moves v regardless; we keep every side decision and
    // take 1/2, 1/4, 1/8 or 1/16 of a refused second-pass move (alone, from
    // the prewarped point) when it is accepted and improves on the
    // prewarped point: no clearance smaller, the smallest not met larger;
    // of those, the one with the largest smallest clearance (a vertex
    // 0.0003 h from F otherwise stays there: aspect 6,629 on a random
    // prism; docs/algorithm/tet3d_warp.md).
    // Moves along a ring segment's line (beyond the thesis): v = x0 moved away from
    // a ring neighbour w, along the axis of [v, w], by h/16 or a fraction of
    // it. For the segment [v, w] itself the line is unchanged (only one
    // coordinate of v changes), so orient3d(a, b, v, w) keeps its sign
    // exactly and F's crossing of it stays the same point; when v lies near
    // F and the segment leaves F at an angle, this is the part of the
    // thesis's move along F's normal that the side rules allow (a box corner
    // clipped by F at 5e-7 h, whose h/16 move along the normal changes the
    // side of E's line a crossed segment passes: bounded random seed 58,
    // docs/algorithm/tet3d_warp.md). The same rules and the same "improves
    // every clearance" test as the shortened moves decide; these are tried at
    // full length too (the refused second-pass moves were tried already). Key
    // facet: -1 (no facet's move).
    const std::size_t first_line_move = refused.size();
    if (!ok)
      for (const GridPoint& w : c.neighbours) {
        const Vec3 away = x0 - grid_coordinates(tree, w);
        const double len = norm(away);
        if (len > 0) refused.push_back({x0 + (h / 16 / len) * away, -1});
      }
    if (!ok) {
      const std::vector<double> q0 = clearances(x0);
      auto smallest = [](const std::vector<double>& q) { return q.empty() ? 1.0 : *std::min_element(q.begin(), q.end()); };
      double best = smallest(q0);
      for (double t = 1.0; t >= 1.0 / 16; t /= 2)
        for (std::size_t r = t == 1.0 ? first_line_move : 0; r < refused.size(); ++r) {
          const auto& [target, key_facet] = refused[r];
          const Vec3 z = x0 + t * (target - x0);
          const std::vector<double> q = clearances(z);
          bool no_worse = true;
          for (std::size_t i = 0; i < q.size(); ++i) no_worse = no_worse && q[i] >= q0[i];
          if (!no_worse || !(smallest(q) > best) || !accept(z)) continue;
          best = smallest(q);
          chosen = z;
          facet = key_facet;
          ok = true;
        }
      if (ok) bisect = false;
      table.shortened += ok ? 1 : 0;
    }
    if (!ok) {
      ++table.conflicts;
      continue;
    }
    if (frozen != nullptr && frozen->count(c.p) != 0) {
      ++table.frozen_left;
      continue;
    }
    table.insert(c.p, Warp{facet, chosen});
    table.bisected += bisect ? 1 : 0;
    table.first_pass += first && (same(chosen, y) || same(chosen, x)) ? 1 : 0;
  }
  // Square centres, after every ring point: the mean of the corners' moves.
  for (const WarpCandidate& c : candidates) {
    if (c.square_corners.empty()) continue;
    Vec3 move;
    bool moved = false;
    for (const GridPoint& q : c.square_corners)
      if (const Warp* w = table.find(q)) {
        move = move + (w->at - grid_coordinates(tree, q));
        moved = true;
      }
    if (!moved) continue;
    const Vec3 x0 = grid_coordinates(tree, c.p);
    const Vec3 y = x0 + (1.0 / static_cast<double>(c.square_corners.size())) * move;
    bool on_some = false, kept = true;
    for (const int f : c.facets) {
      const Sign s0 = plane_of(f).side(x0);
      on_some = on_some || s0 == Sign::Zero;
      kept = kept && plane_of(f).side(y) == s0;
    }
    if (on_some) {
      ++table.on_plane;
      continue;
    }
    if (!kept) {
      ++table.conflicts;
      continue;
    }
    if (frozen != nullptr && frozen->count(c.p) != 0) {
      ++table.frozen_left;
      continue;
    }
    table.insert(c.p, Warp{-1, y});
    ++table.centres;
  }
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
