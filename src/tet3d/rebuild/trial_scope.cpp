#include "tet3d/rebuild/trial_scope.hpp"

#include <algorithm>

namespace pqmesh::tet3d {

namespace {

bool same_warp(const Warp& a, const Warp& b) { return a.facet == b.facet && a.at == b.at; }

// The points of `from` whose entry or copy `other` lacks or holds otherwise.
void differing(const WarpTable& from, const WarpTable& other, std::vector<GridPoint>& out) {
  from.for_each([&](const GridPoint& p, const Warp& w) {
    const Warp* o = other.find(p);
    if (o == nullptr || !same_warp(w, *o)) out.push_back(p);
  });
  from.for_each_copy([&](const GridPoint& p, int facet, Vec3 at) {
    const Vec3* o = other.find_copy(p, facet);
    if (o == nullptr || !(*o == at)) out.push_back(p);
  });
}

}  // namespace

std::vector<GridPoint> changed_points(const WarpTable& before, const WarpTable& after) {
  std::vector<GridPoint> out;
  differing(before, after, out);
  differing(after, before, out);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

JobBoxes::JobBoxes(const OctTree& tree, std::span<const BoxJob> jobs) {
  lo_.reserve(jobs.size());
  hi_.reserve(jobs.size());
  for (const BoxJob& j : jobs) {
    const BoxKey<3>& key = tree.key(j.leaf);
    if (j.kind == BoxKind::Vertex) {
      GridPoint lo = united_lo(key, j.block), hi = lo;
      for (auto& f : hi.f) f += 2 * key.fine_side();
      lo_.push_back(lo);
      hi_.push_back(hi);
    } else {
      lo_.push_back(key_corner(key, 0));
      hi_.push_back(key_corner(key, 7));
    }
  }
}

bool JobBoxes::holds(std::int32_t j, const GridPoint& p) const {
  const GridPoint &lo = lo_.at(static_cast<std::size_t>(j)), &hi = hi_.at(static_cast<std::size_t>(j));
  for (std::size_t a = 0; a < 3; ++a)
    if (p.f[a] < lo.f[a] || hi.f[a] < p.f[a]) return false;
  return true;
}

std::vector<std::int32_t> JobBoxes::touching(std::span<const GridPoint> points,
                                             std::span<const std::int32_t> also) const {
  std::vector<std::int32_t> out(also.begin(), also.end());
  for (std::size_t j = 0; j < lo_.size(); ++j) {
    const GridPoint &lo = lo_[j], &hi = hi_[j];
    // points is sorted, so those with lo.f[0] <= f[0] <= hi.f[0] are one run.
    auto it = std::lower_bound(points.begin(), points.end(), lo.f[0],
                               [](const GridPoint& p, std::int64_t x) { return p.f[0] < x; });
    for (; it != points.end() && it->f[0] <= hi.f[0]; ++it)
      if (lo.f[1] <= it->f[1] && it->f[1] <= hi.f[1] && lo.f[2] <= it->f[2] && it->f[2] <= hi.f[2]) {
        out.push_back(static_cast<std::int32_t>(j));
        break;
      }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace pqmesh::tet3d
