#include "mv3d/united_overlap.hpp"

#include <algorithm>
#include <numeric>

namespace pqmesh::mv3d {

GridBlock united_grid_block(const BoxKey<3>& k, unsigned below) {
  GridBlock b;
  const std::int64_t h = k.fine_side();
  for (int a = 0; a < 3; ++a) {
    const auto i = static_cast<std::size_t>(a);
    b.lo[i] = k.fine_lo(a) - (((below >> a) & 1u) ? h : 0);
    b.hi[i] = b.lo[i] + 2 * h;
  }
  return b;
}

bool meets_block(const BoxKey<3>& k, const GridBlock& block) {
  for (int a = 0; a < 3; ++a) {
    const auto i = static_cast<std::size_t>(a);
    if (k.fine_lo(a) >= block.hi[i] || k.fine_lo(a) + k.fine_side() <= block.lo[i]) return false;
  }
  return true;
}

std::vector<std::size_t> overlapping_blocks(const std::vector<GridBlock>& blocks) {
  std::vector<std::size_t> order(blocks.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return blocks[a].lo[0] != blocks[b].lo[0] ? blocks[a].lo[0] < blocks[b].lo[0] : a < b;
  });
  std::vector<char> hit(blocks.size(), 0);
  for (std::size_t i = 0; i < order.size(); ++i) {
    const GridBlock& p = blocks[order[i]];
    for (std::size_t j = i + 1; j < order.size() && blocks[order[j]].lo[0] < p.hi[0]; ++j) {
      const GridBlock& q = blocks[order[j]];
      if (p.lo[1] < q.hi[1] && q.lo[1] < p.hi[1] && p.lo[2] < q.hi[2] && q.lo[2] < p.hi[2])
        hit[order[i]] = hit[order[j]] = 1;
    }
  }
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < hit.size(); ++i)
    if (hit[i]) out.push_back(i);
  return out;
}

}  // namespace pqmesh::mv3d
