#include "tet3d/rebuild/stuck_corners.hpp"

#include <algorithm>
#include <cstddef>
#include <unordered_set>

#include "tet3d/rebuild/trial_scope.hpp"

namespace pqmesh::tet3d {

namespace {

// The index of WarpTable::conflicts among the journal's counts.
std::size_t conflicts_count() {
  std::size_t k = 0;
  while (WarpTable::kCounts[k] != &WarpTable::conflicts) ++k;
  return k;
}

}  // namespace

std::vector<GridPoint> stuck_points(const WarpCandidates& candidates, const WarpJournal& journal) {
  const std::size_t conflicts = conflicts_count();
  std::vector<GridPoint> out;
  for (const WarpJournal::Count& row : journal.counts)
    if (row.count == conflicts && row.delta > 0 && row.point < candidates.ring_count())
      out.push_back(candidates.point(row.point));
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

BoxMesh stuck_corner_tetrahedra(const BoxPass& pass, const WarpTable& warps, std::span<const GridPoint> stuck) {
  if (stuck.empty()) return {};
  const JobBoxes boxes(pass.tree, pass.jobs);
  const std::vector<std::int32_t> scope = boxes.touching(stuck, {});
  const auto trial = partial_trial(pass, warps, scope);
  const std::unordered_set<std::int32_t> inverted(trial->bad_jobs().begin(), trial->bad_jobs().end());
  BoxMesh all = trial->finish();
  const std::unordered_set<GridPoint, GridPointHash> at(stuck.begin(), stuck.end());
  const auto is_stuck = [&](int v) {
    const VertexKey& k = all.keys[static_cast<std::size_t>(v)];
    return k.kind == VertexKind::Grid && at.count(k.p) != 0;
  };
  BoxMesh out;
  for (std::size_t t = 0; t < all.mesh.tetrahedra.size(); ++t) {
    const auto& tet = all.mesh.tetrahedra[t];
    if (inverted.count(all.tet_job[t]) != 0 || std::none_of(tet.begin(), tet.end(), is_stuck)) continue;
    out.mesh.tetrahedra.push_back(tet);
    out.tet_job.push_back(all.tet_job[t]);
    out.tet_leaf.push_back(all.tet_leaf[t]);
  }
  out.mesh.vertices = std::move(all.mesh.vertices);
  out.keys = std::move(all.keys);
  return out;
}

}  // namespace pqmesh::tet3d
