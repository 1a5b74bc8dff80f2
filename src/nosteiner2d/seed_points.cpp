// Seed points of the seeded refined candidates; see seed_points.hpp.
#include "nosteiner2d/seed_points.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "nosteiner2d/face_grid.hpp"
#include "nosteiner2d/fan_bound.hpp"
#include "nosteiner2d/sector_obstacles.hpp"
#include "nosteiner2d/segment_bound.hpp"
#include "nosteiner2d/spiral_frame.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::detail {

namespace {

constexpr int kMaxLocated = 4096;

void segment_apexes(const Domain2& domain, double target, std::vector<Vec2>& out) {
  const auto& P = domain.pslg.vertices;
  const SegmentBound sb = segment_bound(domain);
  for (std::size_t l = 0; l < domain.loops.size(); ++l) {
    const auto& loop = domain.loops[l];
    for (std::size_t k = 0; k < loop.size(); ++k) {
      if (!(sb.side_angle[l][k] < target)) continue;
      // The corner angles at a and b bound the empty isosceles triangle too (the sides at a, b).
      const int count = static_cast<int>(loop.size()), ki = static_cast<int>(k);
      const double t = std::min({sb.side_angle[l][k], make_frame(domain, int(l), ki, true).alpha,
                                 make_frame(domain, int(l), (ki + 1) % count, true).alpha});
      const Vec2 a = P[static_cast<std::size_t>(loop[k])], b = P[static_cast<std::size_t>(loop[(k + 1) % loop.size()])];
      const Vec2 u = b - a, n = {-u.y, u.x};
      const Vec2 p = a + 0.5 * u + (0.5 * std::tan(0.5 * t)) * n;
      if (orient2d(a, b, p) == Sign::Positive && segment_apex_angle(a, b, p) <= 0.75 * t) out.push_back(p);
    }
  }
}

// The inner spoke ends of the fan from side E of V towards each vertex q of dP in V's closed
// sector closer than |E| whose obstacle fan bound A is below the target: k = clamp(floor(omega /
// A), 1, 64) equal angles up to q's direction, lengths geometric from |E| to |Vq|. Each located.
void obstacle_spokes(const Domain2& domain, double target, int& located, std::vector<Vec2>& out) {
  const FaceGrid grid(domain);
  std::vector<int> side_ids, vertex_ids;
  for (int l = 0; l < static_cast<int>(domain.loops.size()); ++l)
    for (int k = 0; k < static_cast<int>(domain.loops[static_cast<std::size_t>(l)].size()); ++k)
      for (const bool ccw : {true, false}) {
        const SpiralFrame e = make_frame(domain, l, k, ccw);
        const bool all = for_each_sector_obstacle(domain, grid, e, side_ids, vertex_ids, [&](int, Vec2 Q, double r) {
          const double omega = e.phi(Q), a = obstacle_fan_bound(omega, e.length / r);
          if (!(a < target)) return true;
          const int steps = static_cast<int>(std::clamp(std::floor(omega / a), 1.0, 64.0));
          for (int i = 1; i < steps; ++i) {
            if (located++ >= kMaxLocated) return false;
            const Vec2 p = e.point_at(e.length * std::pow(r / e.length, double(i) / steps), omega * i / steps);
            if (locate(domain, p) == Location::Inside) out.push_back(p);
          }
          return true;
        });
        if (!all) return;
      }
}

void fan_spokes(const Domain2& domain, double target, int& located, std::vector<Vec2>& out) {
  for (int l = 0; l < static_cast<int>(domain.loops.size()); ++l)
    for (int k = 0; k < static_cast<int>(domain.loops[static_cast<std::size_t>(l)].size()); ++k) {
      const SpiralFrame fr = make_frame(domain, l, k, true);
      const double l1 = fr.length, l2 = norm(fr.F - fr.V);
      const double a = fan_bound(fr.alpha, std::max(l1, l2) / std::min(l1, l2));
      if (!(a < target)) continue;
      const int steps = static_cast<int>(std::clamp(std::floor(fr.alpha / a), 1.0, 64.0));
      for (int i = 1; i < steps; ++i) {
        if (located++ >= kMaxLocated) return;
        const Vec2 p = fr.point_at(l1 * std::pow(l2 / l1, double(i) / steps), fr.alpha * i / steps);
        if (locate(domain, p) == Location::Inside) out.push_back(p);
      }
    }
}

}  // namespace

std::vector<Vec2> seed_points(const Domain2& domain, double target_degrees, bool obstacles) {
  const double target = target_degrees * std::numbers::pi / 180;
  std::vector<Vec2> out;
  segment_apexes(domain, target, out);
  int located = 0;
  fan_spokes(domain, target, located, out);
  if (obstacles) obstacle_spokes(domain, target, located, out);
  std::sort(out.begin(), out.end(), [](Vec2 p, Vec2 q) { return p.x < q.x || (p.x == q.x && p.y < q.y); });
  out.erase(std::unique(out.begin(), out.end(), [](Vec2 p, Vec2 q) { return p.x == q.x && p.y == q.y; }), out.end());
  return out;
}

}  // namespace pqmesh::detail
