#pragma once
// Freezing the worst box's warps (docs/algorithm/tet3d_warp.md "Freezing the
// worst box's warps"). The rebuild loop of facet_boxes.cpp stops at the first
// table on which no tetrahedron inverts; a warp it keeps can still bend a face
// of an edge box to within a sliver of the box's apex (flat-edge stress seeds
// 49 and 100: aspect ratio x alpha above 20,000). When the worst tetrahedron of
// that table is flat (tet_shape above kFlatWorst), this pass freezes every
// moved point of the worst tetrahedron's box, rebuilds the table and tries the
// jobs it changes. A round is kept only when nothing inverts and every tried
// job's worst tetrahedron is strictly better than the mesh's worst before the
// round, so the mesh's worst tetrahedron strictly improves; a trial of every
// job then decides, as in the rebuild loop. Runs below the threshold do no
// extra work and keep their bytes.
#include <cstdint>
#include <memory>
#include <span>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "tet3d/rebuild/job_runs.hpp"
#include "tet3d/rebuild/trial_scope.hpp"
#include "tet3d/warp/warp.hpp"

namespace pqmesh::tet3d {

using GridPointSet = std::unordered_set<GridPoint, GridPointHash>;

// What the rebuild loop made the accepted table from, besides its frozen set
// (the WarpOptions fields of the same names, warp.hpp).
struct WarpRecipe {
  bool reflex_copies = true;
  std::span<const EdgeBoxBounds> edge_boxes;
  const std::unordered_map<GridPoint, std::uint8_t, GridPointHash>* second_only = nullptr;
  bool out_of_face = false;
};

// A float threshold that only decides whether to look for a better table
// (tet_shape, the longest edge over the inradius: 4.9 for the regular
// tetrahedron; its ratio to the aspect ratio of pqmesh/quality.hpp varies
// with the shape, and bounded seed 38, aspect ratio 279, is above it).
inline constexpr double kFlatWorst = 4096;
// Rounds tried at most, each one table build and one partial trial.
inline constexpr int kWorstBoxRounds = 3;

struct WorstBoxFreeze {
  std::int64_t rounds = 0;               // rounds kept
  std::int32_t unfrozen_worst_job = -1;  // when rounds > 0: the worst job before the first round
};

// `done`: the trial of every job on `warps` (no inversions), or null when
// the caller will remake it. `job_shapes`: when `done` is null, the worst
// tet_shape per job of that trial (BoxAssembler::job_worst_shapes), taken by
// the caller before it dropped the trial; empty otherwise (then a null `done`
// is made here, one more trial of every job). On success `warps`, `frozen`
// and `done` are the better table, its frozen set and its trial of every job;
// otherwise `warps` and `frozen` are unchanged and `done` is null when the
// pass ran or `job_shapes` were given (the caller remakes the mesh of
// `warps`).
WorstBoxFreeze freeze_worst_boxes(const BoxPass& pass, const WarpRecipe& recipe, WarpTable& warps, GridPointSet& frozen,
                                  std::unique_ptr<BoxAssembler>& done, std::vector<double> job_shapes = {});

}  // namespace pqmesh::tet3d
