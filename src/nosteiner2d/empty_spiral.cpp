// Stage 1-2 of thesis ch. 5: interfering points and the empty spiral of every
// (vertex V, edge E) pair (Theorems 21, 23).
//
// For each pair the eligible interfering points W (interference.hpp) define
// continuous spirals rho = L(E) s_W^phi with s_W = r^(1/omega) (the spoke
// vertices of the optimal wedge for (E, W) lie on it, Theorem 19). The empty
// spiral is the one with the smallest s (Theorem 23): no eligible point lies
// strictly inside it. Alongside, min h(E, W) = min(min omega, -1 / ln s) is
// kept with its witness (nosteiner.hpp).
//
// Enumeration order (the tie-break: the first strict minimum wins): loops in
// order, vertices in loop order, E towards next(V) then prev(V); candidate
// faces: vertices in loop order, then sides in loop order.
#include <algorithm>
#include <cmath>
#include <limits>

#include "nosteiner2d/face_grid.hpp"
#include "nosteiner2d/interference.hpp"
#include "nosteiner2d/stages.hpp"

namespace pqmesh {

namespace {

using detail::SpiralFrame;

InterferenceWitness make_witness(const SpiralFrame& fr, InterferingFace face, Vec2 w) {
  InterferenceWitness x;
  x.face = face;
  x.point = w;
  x.omega = fr.phi(w);
  x.r = std::min(1.0, norm(w - fr.V) / fr.length);
  const double lr = -std::log(x.r);
  x.h = x.omega / std::max(1.0, lr);
  return x;
}

// Keeps the minima; `order` is the candidate face's rank in the enumeration
// order, so that equal values resolve to the first face whatever order the
// candidates are examined in (pieces are searched by increasing lower bound).
struct Accumulator {
  const SpiralFrame& fr;
  EmptySpiral& out;
  double best_q = 0;  // ln s of the best spiral so far (0: s = 1)
  long h_order = -1, q_order = -1;

  void consider_point(InterferingFace face, Vec2 w, long order) {
    const InterferenceWitness x = make_witness(fr, face, w);
    if (!out.has_eligible || x.h < out.min_h || (x.h == out.min_h && order < h_order)) {
      out.has_eligible = true;
      out.min_h = x.h;
      out.h_witness = x;
      h_order = order;
    }
    if (x.r < 1 && x.omega > 0) {
      const double q = std::log(x.r) / x.omega;
      if (q < best_q || (q == best_q && order < q_order)) {
        best_q = q;
        out.spiral_witness = x;
        q_order = order;
      }
    }
  }
};

struct PendingPiece {
  double q_lower;
  long order;
  int a, b;
  detail::SidePiece piece;
};

EmptySpiral empty_spiral_of(const Domain2& domain, const detail::FaceGrid& grid, const SpiralFrame& fr, bool far_end,
                            std::vector<int>& side_ids, std::vector<int>& vertex_ids) {
  EmptySpiral out;
  out.vertex = fr.v;
  out.other = fr.u;
  out.far_vertex = fr.f;
  out.ccw = fr.ccw;
  out.length = fr.length;
  out.alpha = fr.alpha;
  out.min_h = std::numeric_limits<double>::infinity();
  Accumulator acc{fr, out};
  const auto& P = domain.pslg.vertices;
  // Only faces near the disk |VW| <= L(E) can be eligible (face_grid.hpp).
  grid.query(fr.V, fr.length * (1 + 1e-9), side_ids, vertex_ids);
  for (const int i : vertex_ids) {
    const int w = grid.vertices()[i];
    if (w != fr.v && w != fr.u && detail::eligible_vertex(fr, P[w]))
      acc.consider_point({InterferingFace::Kind::Vertex, w, -1}, P[w], i);
  }
  const double L2 = fr.length * fr.length;
  std::vector<PendingPiece> pending;
  for (const int i : side_ids) {
    const int a = grid.sides()[i][0], b = grid.sides()[i][1];
    // Not disjoint from E (with sides_at_far_end, only sides at V are skipped).
    if (a == fr.v || b == fr.v || (!far_end && (a == fr.u || b == fr.u))) continue;
    // Cheap reject (a filter, not a decision): the side is clearly farther
    // than L(E) from V. The 1e-6 margin dwarfs rounding; anything closer
    // goes to the exact clipping.
    const Vec2 A = P[a], B = P[b], D = B - A;
    const double dd = dot(D, D);
    double t = dd > 0 ? dot(fr.V - A, D) / dd : 0;
    t = std::min(1.0, std::max(0.0, t));
    const Vec2 c = A + t * D;
    if (dot(c - fr.V, c - fr.V) > L2 * (1 + 1e-6)) continue;
    const long order = static_cast<long>(grid.vertices().size()) + i;
    for (const auto piece : detail::eligible_pieces(fr, A, B)) {
      const auto m = detail::piece_start(fr, A, B, piece);
      acc.consider_point({InterferingFace::Kind::Edge, a, b}, m.min_phi_point, order);
      if (m.q_lower < 0) pending.push_back({m.q_lower, order, a, b, piece});
    }
  }
  // The expensive search for min q, most promising pieces first; a piece
  // whose lower bound cannot beat the best q found so far is skipped.
  std::sort(pending.begin(), pending.end(), [](const PendingPiece& x, const PendingPiece& y) {
    return x.q_lower < y.q_lower || (x.q_lower == y.q_lower && x.order < y.order);
  });
  for (const PendingPiece& pp : pending) {
    if (pp.q_lower > acc.best_q) break;
    Vec2 w;
    double q = 0;
    if (detail::piece_min_q(fr, P[pp.a], P[pp.b], pp.piece, w, q))
      acc.consider_point({InterferingFace::Kind::Edge, pp.a, pp.b}, w, pp.order);
  }
  out.log_shrink = acc.best_q < 0 ? acc.best_q : 0.0;
  out.shrink = std::exp(out.log_shrink);
  return out;
}

}  // namespace

std::vector<EmptySpiral> empty_spirals(const Domain2& domain, const SteinerFreeOptions& options) {
  std::vector<EmptySpiral> out;
  const detail::FaceGrid grid(domain);
  std::vector<int> side_ids, vertex_ids;
  for (int l = 0; l < static_cast<int>(domain.loops.size()); ++l)
    for (int k = 0; k < static_cast<int>(domain.loops[l].size()); ++k)
      for (const bool ccw : {true, false})
        out.push_back(empty_spiral_of(domain, grid, detail::make_frame(domain, l, k, ccw), options.sides_at_far_end,
                                      side_ids, vertex_ids));
  return out;
}

}  // namespace pqmesh
