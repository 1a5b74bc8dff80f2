#include "tet3d/rebuild/worst_box_freeze.hpp"

#include <algorithm>
#include <optional>
#include <vector>

#include "tet3d/rebuild/free_heap.hpp"
#include "tet3d/warp/warp_candidates.hpp"

namespace pqmesh::tet3d {

namespace {

// The moved points (an entry or a Fig. 4.7 copy) of `warps` in job j's
// closed box that `frozen` lacks, sorted.
std::vector<GridPoint> moved_in_box(const WarpTable& warps, const JobBoxes& boxes, std::int32_t j,
                                    const GridPointSet& frozen) {
  std::vector<GridPoint> out;
  auto take = [&](const GridPoint& p) {
    if (boxes.holds(j, p) && frozen.count(p) == 0) out.push_back(p);
  };
  warps.for_each([&](const GridPoint& p, const Warp&) { take(p); });
  warps.for_each_copy([&](const GridPoint& p, int, Vec3) { take(p); });
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace

WorstBoxFreeze freeze_worst_boxes(const BoxPass& pass, const WarpRecipe& recipe, WarpTable& warps, GridPointSet& frozen,
                                  std::unique_ptr<BoxAssembler>& done, std::vector<double> job_shapes) {
  std::vector<double> shapes = std::move(job_shapes);
  if (shapes.empty()) {
    if (!done) {
      done = full_trial(pass, warps);
      if (!done->bad().empty()) {  // not the caller's clean table: leave it to the final pass
        done.reset();
        return {};
      }
    }
    shapes = done->job_worst_shapes(pass.jobs.size());
  }
  // The mesh's worst shape is the largest job's worst (every tetrahedron has
  // a job; the shapes of a trial without inversions are finite).
  const auto first_worst = std::max_element(shapes.begin(), shapes.end());
  if (first_worst == shapes.end() || *first_worst <= kFlatWorst) return {};
  const double start = *first_worst;
  const auto unfrozen_worst_job = static_cast<std::int32_t>(first_worst - shapes.begin());
  const JobBoxes boxes(pass.tree, pass.jobs);
  // The rounds need the candidates (flat seed 107, 13M tetrahedra: peak
  // 1.48 GB with both, 0.94 GB without the pass), so the trial goes first;
  // when no round is kept, the caller remakes it.
  done.reset();
  release_free_heap();
  std::optional<WarpCandidates> candidates;
  // The table of the last kept round (none yet: `warps`) and its frozen set.
  std::optional<WarpTable> kept;
  GridPointSet kept_frozen = frozen;
  std::int64_t rounds = 0;
  for (int round = 0; round < kWorstBoxRounds; ++round) {
    const WarpTable& table = kept ? *kept : warps;
    // The first job of the largest shape.
    const auto worst_job = static_cast<std::int32_t>(std::max_element(shapes.begin(), shapes.end()) - shapes.begin());
    const double worst = shapes[static_cast<std::size_t>(worst_job)];
    if (worst <= kFlatWorst) break;
    const std::vector<GridPoint> points = moved_in_box(table, boxes, worst_job, kept_frozen);
    if (points.empty()) break;
    GridPointSet next_frozen = kept_frozen;
    next_frozen.insert(points.begin(), points.end());
    if (!candidates) candidates = warp_candidates(pass.tree, pass.corners, pass.domain, pass.jobs);
    WarpTable next = warp_box_vertices(pass.tree, pass.corners, pass.domain, *candidates,
                                       {.frozen = &next_frozen,
                                        .reflex_copies = recipe.reflex_copies,
                                        .edge_boxes = recipe.edge_boxes,
                                        .second_only = recipe.second_only,
                                        .out_of_face = recipe.out_of_face});
    const std::vector<std::int32_t> scope = boxes.touching(changed_points(table, next), {});
    const auto trial = partial_trial(pass, next, scope);
    if (!trial->bad().empty()) break;
    const std::vector<double> tried = trial->job_worst_shapes(pass.jobs.size());
    if (!std::all_of(scope.begin(), scope.end(),
                     [&](std::int32_t j) { return tried[static_cast<std::size_t>(j)] < worst; }))
      break;
    for (const std::int32_t j : scope) shapes[static_cast<std::size_t>(j)] = tried[static_cast<std::size_t>(j)];
    kept = std::move(next);
    kept_frozen = std::move(next_frozen);
    ++rounds;
  }
  if (rounds == 0) return {};
  // The trial of every job decides (the partial trials rely on
  // trial_scope.hpp's locality, as the rebuild loop does).
  candidates.reset();
  release_free_heap();
  std::swap(warps, *kept);  // the trial's assembler keeps a pointer to `warps`
  auto full = full_trial(pass, warps);
  if (!full->bad().empty() || !(full->worst_shape() < start)) {
    full.reset();
    std::swap(warps, *kept);
    return {};  // `done` stays null: the caller remakes it
  }
  frozen = std::move(kept_frozen);
  done = std::move(full);
  return {rounds, unfrozen_worst_job};
}

}  // namespace pqmesh::tet3d
