// Seed points of the seeded refined candidates; see seed_points.hpp.
#include "nosteiner2d/seed_points.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "nosteiner2d/fan_bound.hpp"
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

void fan_spokes(const Domain2& domain, double target, std::vector<Vec2>& out) {
  int located = 0;
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

std::vector<Vec2> seed_points(const Domain2& domain, double target_degrees) {
  const double target = target_degrees * std::numbers::pi / 180;
  std::vector<Vec2> out;
  segment_apexes(domain, target, out);
  fan_spokes(domain, target, out);
  std::sort(out.begin(), out.end(), [](Vec2 p, Vec2 q) { return p.x < q.x || (p.x == q.x && p.y < q.y); });
  out.erase(std::unique(out.begin(), out.end(), [](Vec2 p, Vec2 q) { return p.x == q.x && p.y == q.y; }), out.end());
  return out;
}

}  // namespace pqmesh::detail
