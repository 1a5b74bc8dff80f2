// The size estimate I3(P) = integral over P of 1 / lfs^3 (pqmesh/lfs3.hpp):
// adaptive octree quadrature over the bounding cube, cells decided inside or
// outside exactly where the boundary misses them.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "lfs3d.hpp"
#include "plc/point_location.hpp"
#include "pqmesh/errors.hpp"
#include "pqmesh/lfs3.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh {
// ---------------------------------------------------------------------------
// The integral of 1 / lfs^3 over P.

namespace {

enum class CellState { Unknown, Inside, Outside };

struct Integrator {
  const LocalFeatureSize3& lfs;
  double refine;
  Vec3 lo;
  double side;
  detail::BoundaryBuckets3 buckets;
  detail::DomainLocator3 locator;
  LfsIntegral3 out{};
  // A direct-mapped cache of lfs at the face centres and edge midpoints of
  // refined cells, keyed by the point's bits: a face centre is shared by the
  // two cells across the face, an edge midpoint by up to four, and the
  // lattice construction gives a shared point identical doubles in every
  // cell (coord). lfs is a function of the point, so a cached value is the
  // value a new query returns, bit for bit (same I3, fewer queries); a
  // collision only evicts (fixed size: 2^16 slots of 40 bytes, 2.5 MiB, whatever the
  // number of cells). Depth-first order visits most sharing cells close
  // together in time.
  struct CachedLfs {
    std::uint64_t x = 0, y = 0, z = 0;
    double value = 0;
    bool used = false;
  };
  static constexpr std::size_t kCacheSlots = std::size_t{1} << 16;
  std::vector<CachedLfs> shared_lfs = std::vector<CachedLfs>(kCacheSlots);

  static constexpr int kMaxLevel = 40;
  static constexpr int kSub = 4;  // boundary leaves: kSub^3 midpoints

  Integrator(const Domain3& d, const LocalFeatureSize3& f, double r)
      : lfs(f), refine(r), lo(d.bbox_min), buckets(d), locator(d) {
    side = std::max({d.bbox_max.x - lo.x, d.bbox_max.y - lo.y, d.bbox_max.z - lo.z});
  }

  // Corner coordinate k / 2^level of the root cube; shared corners of cells
  // of different levels get identical doubles (scaling by 2 is exact).
  double coord(double l, std::int64_t k, int level) const {
    return l + std::ldexp(static_cast<double>(k) * side, -level);
  }
  Vec3 point(std::int64_t i, std::int64_t j, std::int64_t k, int level) const {
    return {coord(lo.x, i, level), coord(lo.y, j, level), coord(lo.z, k, level)};
  }

  double lfs_shared(Vec3 x) {
    const auto bx = std::bit_cast<std::uint64_t>(x.x), by = std::bit_cast<std::uint64_t>(x.y),
               bz = std::bit_cast<std::uint64_t>(x.z);
    const auto mix = [](std::uint64_t v) {  // splitmix64's finaliser
      v = (v ^ (v >> 30)) * 0xBF58476D1CE4E5B9ull;
      v = (v ^ (v >> 27)) * 0x94D049BB133111EBull;
      return v ^ (v >> 31);
    };
    const std::uint64_t h = mix(bx ^ mix(by ^ mix(bz)));
    CachedLfs& slot = shared_lfs[static_cast<std::size_t>(h) & (kCacheSlots - 1)];
    if (!slot.used || slot.x != bx || slot.y != by || slot.z != bz) slot = {bx, by, bz, lfs.at(x), true};
    return slot.value;
  }

  // f[a + 2b + 4c]: lfs at corner (i + a, j + b, k + c).
  void visit(int level, std::int64_t i, std::int64_t j, std::int64_t k, CellState state,
             const std::array<double, 8>& f) {
    const Vec3 p = point(i, j, k, level), q = point(i + 1, j + 1, k + 1, level);
    const Vec3 c = point(2 * i + 1, 2 * j + 1, 2 * k + 1, level + 1);
    const double h = std::ldexp(side, -level);
    bool meets = false;
    if (state == CellState::Unknown) {
      meets = buckets.box_meets_boundary(p, q, true);
      // A cell whose open box misses dP is (up to its boundary, a null set)
      // wholly inside or wholly outside, and its centre is not on dP. Cells
      // that only touch dP with their faces (common: dyadic input aligned
      // with the octree) need no subsampling.
      if (!meets) state = locator.locate(c) == Location::Inside ? CellState::Inside : CellState::Outside;
    }
    if (state == CellState::Outside) return;
    const double fc = lfs.at(c);
    const double m = std::min(fc, *std::min_element(f.begin(), f.end()));
    if (h > refine * m && level < kMaxLevel) {
      const CellState child = meets ? CellState::Unknown : CellState::Inside;
      // V[a][b][c]: lfs at fine lattice point (2i + a, 2j + b, 2k + c).
      double V[3][3][3];
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
          for (int cc = 0; cc < 3; ++cc) {
            if (a % 2 == 0 && b % 2 == 0 && cc % 2 == 0)
              V[a][b][cc] = f[detail::lfs_uz(a / 2 + 2 * (b / 2) + 4 * (cc / 2))];
            else if (a == 1 && b == 1 && cc == 1)
              V[a][b][cc] = fc;
            else
              V[a][b][cc] = lfs_shared(point(2 * i + a, 2 * j + b, 2 * k + cc, level + 1));
          }
      for (int dk = 0; dk < 2; ++dk)
        for (int dj = 0; dj < 2; ++dj)
          for (int di = 0; di < 2; ++di) {
            std::array<double, 8> g{};
            for (int s = 0; s < 8; ++s) g[detail::lfs_uz(s)] = V[di + (s & 1)][dj + ((s >> 1) & 1)][dk + ((s >> 2) & 1)];
            visit(level + 1, 2 * i + di, 2 * j + dj, 2 * k + dk, child, g);
          }
      return;
    }
    if (!meets) {
      // Inside leaf (its open box lies in P): 2/3 of the midpoint rule plus
      // 1/3 of the corner average, exact for quadratic integrands (the
      // midpoint rule is off by +h^2/24 * Laplacian, the corner average by
      // +h^2/8 * Laplacian; odd and mixed terms cancel by symmetry). The
      // corner values are at hand; 1/lfs^3 is convex along most lines, where
      // the midpoint rule alone underestimates.
      double corners = 0;
      for (double v : f) corners += 1 / (v * v * v);
      out.value += h * h * h * (2.0 / 3.0 / (fc * fc * fc) + corners / 24.0);
      ++out.cells;
      out.min_lfs = std::min(out.min_lfs, m);
      return;
    }
    // Boundary leaf: midpoints of a kSub^3 subdivision, located exactly.
    const double hs = h / kSub;
    bool any = false;
    for (int cz = 0; cz < kSub; ++cz)
      for (int b = 0; b < kSub; ++b)
        for (int a = 0; a < kSub; ++a) {
          const Vec3 s{p.x + (a + 0.5) * hs, p.y + (b + 0.5) * hs, p.z + (cz + 0.5) * hs};
          const Location w = locator.locate(s);
          if (w == Location::Outside) continue;
          const double fs = lfs.at(s);
          out.min_lfs = std::min(out.min_lfs, fs);
          out.value += (w == Location::Boundary ? 0.5 : 1.0) * hs * hs * hs / (fs * fs * fs);
          any = true;
        }
    if (any) ++out.cells;
  }
};

}  // namespace

LfsIntegral3 lfs_integral(const Domain3& domain, double refine) {
  if (!(refine > 0)) throw InternalError("lfs_integral: refine must be positive");
  LfsIntegral3 result;
  result.min_lfs = detail::kLfsInf;
  if (domain.facet_triangles.empty()) return result;
  const LocalFeatureSize3 lfs(domain);
  Integrator integ(domain, lfs, refine);
  integ.out.min_lfs = result.min_lfs;
  std::array<double, 8> f{};
  for (int s = 0; s < 8; ++s) f[detail::lfs_uz(s)] = lfs.at(integ.point(s & 1, (s >> 1) & 1, (s >> 2) & 1, 0));
  integ.visit(0, 0, 0, 0, CellState::Unknown, f);
  return integ.out;
}


}  // namespace pqmesh
