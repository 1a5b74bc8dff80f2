#include "tet3d/squares/cut_square.hpp"

#include <algorithm>
#include <cmath>

#include "pqmesh/errors.hpp"

namespace pqmesh::tet3d {

namespace {

struct PiPoint {
  int id;
  bool on_facet;
};

}  // namespace

int settle_axis(const FaceSquare& s, const FacetPlane& plane) {
  return std::fabs(axis_coord(plane.normal(), s.u)) >= std::fabs(axis_coord(plane.normal(), s.v)) ? s.u : s.v;
}

CutCase triangulate_cut_square(const FaceSquare& s, const CornerSet& corners, const OctTree& tree,
                               const FacetPlane& plane, PointBook& book, std::vector<std::array<int, 3>>& out,
                               const WarpTable* warps) {
  const std::vector<GridPoint> ring = square_ring(s, corners);
  const std::size_t k = ring.size();
  std::vector<Vec3> xyz(k);
  std::vector<Sign> side(k);
  bool any_in = false, any_out = false;
  for (std::size_t i = 0; i < k; ++i) {
    // Coordinates only: a ring point becomes a vertex when a triangle uses it.
    const Warp* w = warps != nullptr ? warps->find(ring[i]) : nullptr;
    xyz[i] = w != nullptr ? w->at : grid_coordinates(tree, ring[i]);
    side[i] = plane.side(xyz[i]);
    any_in = any_in || side[i] == Sign::Negative;
    any_out = any_out || side[i] == Sign::Positive;
  }
  auto grid_id = [&](std::size_t i) { return grid_vertex(ring[i], tree, warps, book); };
  const GridPoint centre = s.centre();
  auto centre_id = [&] { return book.id(grid_key(centre), [&] { return grid_coordinates(tree, centre); }); };
  if (!any_in) return CutCase::Empty;
  if (!any_out) {
    const int c = centre_id();
    for (std::size_t i = 0; i < k; ++i) out.push_back({c, grid_id(i), grid_id((i + 1) % k)});
    return CutCase::Whole;
  }
  // Start the walk at a ring point beyond F whose predecessor is not.
  std::size_t i0 = k;
  for (std::size_t i = 0; i < k && i0 == k; ++i)
    if (side[i] == Sign::Positive && side[(i + k - 1) % k] != Sign::Positive) i0 = i;
  // π's boundary from the entry y to the exit x, counter-clockwise (+n).
  std::vector<PiPoint> walk;
  int runs = 0;  // changes from beyond F to not beyond, around the ring
  for (std::size_t j = 0; j < k; ++j) {
    const std::size_t i = (i0 + j) % k, i1 = (i + 1) % k;
    if (side[i] != Sign::Positive) walk.push_back({grid_id(i), side[i] == Sign::Zero});
    if (side[i] == Sign::Positive && side[i1] != Sign::Positive) ++runs;
    if (side[i] * side[i1] == Sign::Negative) {
      const GridPoint& a = std::min(ring[i], ring[i1]);
      const GridPoint& b = std::max(ring[i], ring[i1]);
      const VertexKey key{VertexKind::FacetCrossing, a, b, plane.facet()};
      // End points as F's cut sees them (a Fig. 4.7 copy for F, warp_table.hpp).
      const auto end = [&](std::size_t n) {
        return warps != nullptr ? warps->at_for_cut(ring[n], plane.facet(), xyz[n]) : xyz[n];
      };
      walk.push_back({book.id(key, [&] { return plane.crossing(end(i), end(i1)); }), true});
    }
  }
  // A line meets the convex ring in one run of points beyond it, and the walk
  // then starts and ends on F.
  if (runs != 1 || walk.size() < 3 || !walk.front().on_facet || !walk.back().on_facet)
    throw InternalError("tet3d: facet " + std::to_string(plane.facet()) + " does not cut a box-face square in a chord");
  for (std::size_t j = 1; j + 1 < walk.size(); ++j)
    if (walk[j].on_facet) throw InternalError("tet3d: chord point inside the walk of a cut square");
  const Vec3 X = book.point(walk.back().id), Y = book.point(walk.front().id);
  const Vec3 C = grid_coordinates(tree, centre);
  const Vec3 M = 0.5 * (X + Y);
  // Side length in world units: the square's lower corner to its (1, 0) corner.
  GridPoint c1 = s.lo;
  c1.f[s.u] += s.side;
  const double side_len = axis_coord(grid_coordinates(tree, c1), s.u) - axis_coord(grid_coordinates(tree, s.lo), s.u);
  auto fan = [&](int apex, bool close_chord) {
    for (std::size_t j = 0; j + 1 < walk.size(); ++j) out.push_back({apex, walk[j].id, walk[j + 1].id});
    if (close_chord) out.push_back({apex, walk.back().id, walk.front().id});
  };
  if (in_square_distance(s, M, C) <= side_len / 4) {
    const VertexKey key{VertexKind::ChordMidpoint, centre, {}, plane.facet()};
    fan(book.id(key, [&] { return plane.settle(M, settle_axis(s, plane)); }), false);
    return CutCase::C1;
  }
  const Sign cs = plane.side(C);
  if (cs == Sign::Negative) {
    fan(centre_id(), true);
    return CutCase::C2Inside;
  }
  if (cs == Sign::Zero) {
    fan(centre_id(), false);
    return CutCase::C2On;
  }
  // Centre beyond F: clip the segments from the centre at the chord. The
  // segments start at the centre where it is (warped with its corners,
  // warp.hpp, which keeps its side of F): from the prewarped centre the
  // projections left the bent face and the chord's line slanted past an
  // edge-box apex (docs/algorithm/tet3d_warp.md "Chord projections from the
  // warped centre", bounded seed 76). A construction only: which points are
  // projected was decided above.
  const Warp* cw = warps != nullptr ? warps->find(centre) : nullptr;
  const Vec3 from = cw != nullptr ? cw->at : C;
  auto projection = [&](const PiPoint& p) {
    if (p.on_facet) return p.id;
    const VertexKey key{VertexKind::ChordProjection, centre, book.key(p.id).p, plane.facet()};
    return book.id(key, [&] { return plane.crossing(from, book.point(p.id)); });
  };
  for (std::size_t j = 0; j + 1 < walk.size(); ++j) {
    const int p = walk[j].id, q = walk[j + 1].id;
    const int pp = projection(walk[j]), qq = projection(walk[j + 1]);
    if (pp == p) {
      out.push_back({p, q, qq});
    } else if (qq == q) {
      out.push_back({p, q, pp});
    } else {
      // Quadrilateral p q qq pp, cut by the diagonal from its smallest key.
      append_quad_from_smallest_key(book, {p, q, qq, pp}, out);
    }
  }
  return CutCase::C2Outside;
}

}  // namespace pqmesh::tet3d
