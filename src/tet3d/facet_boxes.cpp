#include "tet3d/facet_boxes.hpp"

#include <algorithm>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "pqmesh/errors.hpp"
#include "tet3d/boxes/box_assembler.hpp"
#include "tet3d/rebuild/free_heap.hpp"
#include "tet3d/rebuild/job_runs.hpp"
#include "tet3d/rebuild/stuck_corners.hpp"
#include "tet3d/boxes/tet_shape.hpp"
#include "tet3d/rebuild/trial_scope.hpp"
#include "tet3d/warp/warp.hpp"
#include "tet3d/warp/warp_candidates.hpp"
#include "tet3d/rebuild/worst_box_freeze.hpp"

namespace pqmesh::tet3d {

GridPoint united_lo(const BoxKey<3>& key, std::uint8_t block) {
  GridPoint lo = key_corner(key, 0);
  for (int a = 0; a < 3; ++a)
    if ((block >> a) & 1) lo.f[static_cast<std::size_t>(a)] -= key.fine_side();
  return lo;
}

void united_face_squares(const BoxKey<3>& key, std::uint8_t block, int axis, bool upper, const CornerSet& corners,
                         std::vector<FaceSquare>& out) {
  const std::int64_t fs = key.fine_side();
  for (int k = 0; k < 4; ++k) {
    FaceSquare s;
    s.n = axis;
    s.u = (axis + 1) % 3;
    s.v = (axis + 2) % 3;
    s.upper = upper;
    s.lo = united_lo(key, block);
    if (upper) s.lo.f[static_cast<std::size_t>(axis)] += 2 * fs;
    s.lo.f[static_cast<std::size_t>(s.u)] += (k & 1) ? fs : 0;
    s.lo.f[static_cast<std::size_t>(s.v)] += (k & 2) ? fs : 0;
    s.side = fs;
    split_square(s, corners, out);
  }
}

void job_squares(const OctTree& tree, const CornerSet& corners, const BoxJob& job, std::vector<FaceSquare>& out) {
  for (int axis = 0; axis < 3; ++axis)
    for (const bool upper : {false, true}) {
      if (job.kind == BoxKind::Vertex)
        united_face_squares(tree.key(job.leaf), job.block, axis, upper, corners, out);
      else
        face_squares(tree.key(job.leaf), axis, upper, corners, out);
    }
}

BoxFaces job_faces(const SquareDispatcher& squares, const BoxJob& job) {
  if (job.kind == BoxKind::FromFacet)
    return squares.faces_of(job.facet < 0 ? BoxKind::Empty : BoxKind::Facet, job.facet);
  return squares.faces_of(job.kind, job.apex);
}

namespace {

// Table rebuilds the warped run may make before it gives up (tet_mesh then
// keeps the unwarped mesh).
constexpr std::int64_t kMaxWarpRebuilds = 64;

// What one run tells mesh_boxes besides its mesh: `wanted`, the box
// vertices of the boxes for which a trial or the final pass had a valid
// two-point construction (allowed or not); `held`, the grid points the
// rebuild loop froze or limited to their box faces; `unfrozen_worst_job`,
// the job of the worst tetrahedron before the worst-box freeze when it kept
// a round (-1 otherwise).
// `table`, the table the mesh was made with (null for an unwarped run).
struct PassNotes {
  std::unordered_set<GridPoint, GridPointHash> wanted, held;
  std::int32_t unfrozen_worst_job = -1;
  std::shared_ptr<const WarpTable> table;
};

// Whether the mesh of `wider` inverts nothing and has a strictly smaller
// worst tet_shape than the accepted trial, whose per-job worst shapes are
// `shapes`, judged by a partial trial of `scope`: the jobs whose closed box
// holds a point the two tables place differently. Every other job makes the
// same tetrahedra on both tables (docs/algorithm/tet3d_warp.md "Partial
// trials"), so its worst shape is the accepted one's. A win is confirmed by a
// trial of every job (the caller's), a loss keeps the accepted trial. Cost:
// one trial of the scope, beside the accepted mesh.
bool partial_trial_scores_better(const BoxPass& pass, const WarpTable& wider, const std::vector<std::int32_t>& scope,
                                 const std::vector<double>& shapes, PassNotes& notes) {
  const auto trial = partial_trial(pass, wider, scope);
  notes.wanted.insert(trial->two_apex_points().begin(), trial->two_apex_points().end());
  if (!trial->bad().empty()) return false;
  double worst_before = 0.0, worst_after = trial->worst_shape();
  std::size_t next = 0;  // scope is ascending
  for (std::size_t j = 0; j < shapes.size(); ++j) {
    worst_before = std::max(worst_before, shapes[j]);
    const bool in_scope = next < scope.size() && static_cast<std::size_t>(scope[next]) == j;
    if (in_scope) ++next;
    else worst_after = std::max(worst_after, shapes[j]);
  }
  return worst_after < worst_before;
}

// The mesh of a finished assembler and the counts of its table.
BoxMesh finish_pass(BoxAssembler& a, const WarpTable& warps) {
  a.count_squares();
  BoxMesh out = a.finish();
  out.warped = static_cast<std::int64_t>(warps.size());
  out.warp_conflicts = warps.conflicts;
  out.warp_bisected = warps.bisected;
  out.warp_fallback = warps.fallback;
  out.warp_reflex_left = warps.reflex_left;
  out.warp_reflex_copied = warps.reflex_copied;
  out.warp_crowded_left = warps.crowded_left;
  out.warp_on_plane = warps.on_plane;
  out.warp_inverting_left = warps.frozen_left;
  out.warp_first_pass = warps.first_pass;
  out.warp_parallel_left = warps.parallel_left;
  out.warp_parallel = warps.parallel;
  out.warp_centres = warps.centres;
  out.warp_shortened = warps.shortened;
  return out;
}

// The final pass of a run: every job once with `warps` (null: unwarped).
std::unique_ptr<BoxAssembler> final_pass(const BoxPass& pass, const WarpTable* warps) {
  auto a = std::make_unique<BoxAssembler>(pass.tree, pass.corners, pass.domain, warps);
  a->allow_two_apex(pass.two_apex);
  a->allow_facet_fans(pass.facet_fans);
  a->set_empty_cells(pass.empty_cells);
  run_jobs(*a, pass.tree, pass.jobs);
  return a;
}

// One run of the warped (or unwarped) box meshing; `two_apex` allows the
// two-cone-point edge boxes.
BoxMesh mesh_boxes_pass(const OctTree& tree, const CornerSet& corners, const Domain3& domain,
                        std::span<const BoxJob> jobs, const BoxMeshOptions& options,
                        const detail::BoxMeshTestHooks& hooks, bool two_apex, PassNotes& notes) {
  const EmptyCells empty_cells(tree, jobs);
  const BoxPass pass{tree, corners, domain, jobs, two_apex, hooks.facet_fans, &empty_cells};
  WarpTable warps;
  std::int64_t rebuilds = 0, worst_box_rounds = 0, wider_table = 0;
  // The warped run's trial pass (collect mode) that inverted nothing: it made
  // exactly the tetrahedra the final pass would make (same table, same job
  // order; collect mode differs only where a tetrahedron inverts), so it is
  // the result and the final pass is skipped.
  std::unique_ptr<BoxAssembler> done;
  if (options.warp) {
    WarpOptions first_warp;
    first_warp.reflex_copies = hooks.reflex_copies;
    // The journal of the loop's last table: a rebuild with the same edge
    // boxes decides again only what the newly held points can change
    // (warp.hpp rewarp_box_vertices; the same table).
    WarpJournal journal;
    // BoxMeshOptions::stuck_review, on the first table's stuck corners (read
    // from its journal, stuck_corners.hpp); not in the two-cone-point run,
    // which follows a run the review let through.
    const bool review = options.stuck_review && !two_apex;
    std::optional<WarpCandidates> candidates = warp_candidates(tree, corners, domain, jobs);
    warps = warp_box_vertices(tree, corners, domain, *candidates, first_warp,
                              hooks.incremental_tables || review ? &journal : nullptr);
    if (review) {
      const std::vector<GridPoint> stuck = stuck_points(*candidates, journal);
      std::string why = options.stuck_review(stuck_corner_tetrahedra(pass, warps, stuck));
      if (!why.empty()) {
        BoxMesh out;
        out.stuck = std::move(why);
        return out;
      }
    }
    candidates.reset();
    release_free_heap();
    // A warp may bend a box face past a cone apex near it (an apex on a P
    // edge or facet close to the box face; the thesis's first pass and
    // vertex centring keep them apart, not done here): the moved points of
    // every inverted tetrahedron are frozen (left in place, counted) and the
    // table rebuilt, until no tetrahedron inverts. Deterministic.
    // After a rebuild the trial runs only the jobs the new table can change
    // (trial_scope.hpp) and those that inverted; when that trial is clean, a
    // trial of every job decides, and it is the result. The candidates
    // (plate_holes: ~36 MB of a 130 MB peak) are dropped before every full
    // trial and kept through the partial ones.
    std::unordered_set<GridPoint, GridPointHash> frozen;
    std::unordered_map<GridPoint, std::uint8_t, GridPointHash> second_only;
    std::vector<EdgeBoxBounds> edge_boxes;
    std::set<std::int32_t> shifted_jobs;
    std::optional<JobBoxes> job_boxes;  // made at the first rebuild
    std::vector<std::int32_t> scope;  // the partial trial's jobs
    // The wider table (out_of_face, below) of the current frozen set and
    // second passes.
    auto wider_of = [&](const WarpCandidates& c) {
      return warp_box_vertices(tree, corners, domain, c,
                               {.frozen = &frozen,
                                .reflex_copies = hooks.reflex_copies,
                                .edge_boxes = edge_boxes,
                                .second_only = &second_only,
                                .out_of_face = true});
    };
    // The wider table of `warps`, made from the candidates before they are
    // dropped for the full trial (a table is small beside the candidates);
    // dropped at every rebuild.
    std::optional<WarpTable> wider_ready;
    bool full = true;
    for (;;) {
      auto trial = full ? full_trial(pass, warps) : partial_trial(pass, warps, scope);
      notes.wanted.insert(trial->two_apex_points().begin(), trial->two_apex_points().end());
      if (trial->bad().empty()) {
        if (full) {
          done = std::move(trial);
          break;
        }
        full = true;
        if (warps.out_of_face_left > 0) wider_ready = wider_of(*candidates);
        candidates.reset();
        release_free_heap();
        continue;
      }
      if (rebuilds == kMaxWarpRebuilds)
        throw InternalError("tet3d: warp rebuild loop: tetrahedra of job " + std::to_string(trial->bad_jobs().front()) +
                            " still invert after " + std::to_string(rebuilds) + " rebuilds");
      ++rebuilds;
      wider_ready.reset();
      // Edge boxes with an inverted cone get their faces through a close
      // box edge translated (warp.cpp, face translations; once per box) and
      // the table is rebuilt without freezing anything; when no such box is
      // new, the moved points of the inverted tetrahedra are frozen.
      bool translated = false;
      std::unordered_set<GridPoint, GridPointHash> newly_held;
      for (const std::int32_t ji : trial->bad_jobs()) {
        const BoxJob& j = jobs[static_cast<std::size_t>(ji)];
        if (j.kind != BoxKind::Edge || !shifted_jobs.insert(ji).second) continue;
        edge_boxes.push_back({key_corner(tree.key(j.leaf), 0), key_corner(tree.key(j.leaf), 7), j.apex});
        translated = true;
      }
      if (!translated) {
        // A point reported for the first time keeps the part of its second
        // pass within the inverted tetrahedra's box faces (warp.cpp,
        // `second_only`); reported again, it is frozen.
        std::unordered_map<GridPoint, std::uint8_t, GridPointHash> now;
        for (std::size_t i = 0; i < trial->bad().size(); ++i) now[trial->bad()[i]] |= trial->bad_axes()[i];
        for (const auto& [g, axes] : now)
          if (second_only.emplace(g, axes).second || frozen.insert(g).second) newly_held.insert(g);
      }
      const std::vector<std::int32_t> inverted = trial->bad_jobs();
      trial.reset();
      if (!candidates) candidates = warp_candidates(tree, corners, domain, jobs);
      const WarpOptions held{.frozen = &frozen,
                             .reflex_copies = hooks.reflex_copies,
                             .edge_boxes = edge_boxes,
                             .second_only = &second_only,
                             .out_of_face = false};
      WarpTable next =
          hooks.incremental_tables && journal.edge_boxes == edge_boxes.size()
              ? rewarp_box_vertices(tree, corners, domain, *candidates, held, warps, newly_held, journal)
              : warp_box_vertices(tree, corners, domain, *candidates, held, hooks.incremental_tables ? &journal : nullptr);
      if (hooks.partial_trials) {
        if (!job_boxes) job_boxes.emplace(tree, jobs);
        scope = job_boxes->touching(changed_points(warps, next), inverted);
      }
      warps = std::move(next);
      full = !hooks.partial_trials;
      if (full) candidates.reset();
      release_free_heap();
    }
    // One decision per shared face (docs/algorithm/tet3d_warp.md "One decision
    // per shared face"): a reported point keeps only the part of its second
    // pass within the reporting box's faces, which leaves a face near a P edge
    // unwarped. Its move out of the reporting box (away from that box's apex)
    // helps that box but bends the face of the box across, whose own apex may
    // lie near it (every-run seed 30: 1,833 -> 393; seed 100: 304 -> 675). Both
    // tables give valid meshes when the trial inverts nothing (exact orient3d);
    // the one with the better worst tetrahedron (tet_shape, only compared) is
    // kept, the table without those moves on a tie. Runs without such a move
    // are unchanged. The other table is made in the rebuild loop while its
    // candidates live (`wider_ready`; from fresh candidates when the loop made
    // none). A partial trial of the jobs it changes decides first, beside the
    // finished trial (partial_trial_scores_better); only when it wins is the
    // finished trial dropped (a mesh is a large part of the peak memory) and
    // a trial of every job made on the other table, which must confirm the
    // win; when it does not, the final pass below remakes this mesh.
    bool wider_won = false;
    // When the wider table's trial of every job loses: the per-job worst
    // shapes of the dropped trial, which is all the worst-box freeze reads of it.
    std::vector<double> clean_shapes;
    if (done && warps.out_of_face_left > 0) {
      WarpTable wider =
          wider_ready ? std::move(*wider_ready) : wider_of(warp_candidates(tree, corners, domain, jobs));
      wider_ready.reset();
      release_free_heap();
      if (wider.out_of_face > 0) {
        std::vector<double> shapes = done->job_worst_shapes(jobs.size());
        const double worst_before = shapes.empty() ? 0.0 : *std::max_element(shapes.begin(), shapes.end());
        const auto changed_jobs = [&] {
          if (!job_boxes) job_boxes.emplace(tree, jobs);
          return job_boxes->touching(changed_points(warps, wider), {});
        };
        wider_table = 1;
        if (!hooks.partial_trials || partial_trial_scores_better(pass, wider, changed_jobs(), shapes, notes)) {
          clean_shapes = std::move(shapes);
          done.reset();
          release_free_heap();
          std::swap(warps, wider);  // the trial's assembler keeps a pointer to `warps`
          auto trial = full_trial(pass, warps);
          notes.wanted.insert(trial->two_apex_points().begin(), trial->two_apex_points().end());
          if (trial->bad().empty() && trial->worst_shape() < worst_before) {
            done = std::move(trial);
            wider_won = true;
            wider_table = 2;
            clean_shapes.clear();
          } else {
            trial.reset();
            std::swap(warps, wider);
          }
        }
      }
    }
    // The notes are the rebuild loop's, not the freeze's: mesh_boxes asks
    // them about the box that was worst before the freeze, whose moved points
    // the freeze holds by construction.
    for (const GridPoint& g : frozen) notes.held.insert(g);
    for (const auto& [g, axes] : second_only) notes.held.insert(g);
    if (hooks.freeze_worst_box) {
      const WarpRecipe recipe{hooks.reflex_copies, edge_boxes, &second_only, wider_won};
      const WorstBoxFreeze freeze = freeze_worst_boxes(pass, recipe, warps, frozen, done, std::move(clean_shapes));
      worst_box_rounds = freeze.rounds;
      notes.unfrozen_worst_job = freeze.unfrozen_worst_job;
    }
  }
  if (!done) {
    done = final_pass(pass, options.warp ? &warps : nullptr);
    notes.wanted.insert(done->two_apex_points().begin(), done->two_apex_points().end());
  }
  BoxMesh out = finish_pass(*done, warps);
  done.reset();
  out.warp_rebuilds = rebuilds;
  out.worst_box_rounds = worst_box_rounds;
  out.wider_table = wider_table;
  if (options.warp) notes.table = std::make_shared<const WarpTable>(std::move(warps));
  if (options.keep_warp_table) out.warps = notes.table;
  return out;
}

// The mesh of a finished run remade from its final table alone: the rebuild
// loop, the wider table and the worst-box freeze are deterministic, so the
// final table determines the run's mesh (every trial pass that ends a run
// made exactly the tetrahedra a final pass with its table makes: collect mode
// differs only where a tetrahedron inverts, and the kept trial inverted none).
// Costs one pass over the jobs instead of the run's tables and trials.
BoxMesh remake_pass(const OctTree& tree, const CornerSet& corners, const Domain3& domain, std::span<const BoxJob> jobs,
                    const BoxMeshOptions& options, const detail::BoxMeshTestHooks& hooks, const BoxMesh& counts,
                    const std::shared_ptr<const WarpTable>& table) {
  const EmptyCells empty_cells(tree, jobs);
  const BoxPass pass{tree, corners, domain, jobs, false, hooks.facet_fans, &empty_cells};
  const WarpTable unwarped;
  const std::unique_ptr<BoxAssembler> a = final_pass(pass, table.get());
  BoxMesh out = finish_pass(*a, table ? *table : unwarped);
  out.warp_rebuilds = counts.warp_rebuilds;
  out.worst_box_rounds = counts.worst_box_rounds;
  out.wider_table = counts.wider_table;
  if (options.keep_warp_table) out.warps = table;
  return out;
}

// The worst tet_shape of a finished mesh (only compared) and the index of
// its first tetrahedron of that shape.
std::pair<double, std::size_t> worst_tet_shape(const BoxMesh& m) {
  std::pair<double, std::size_t> worst{0, 0};
  for (std::size_t i = 0; i < m.mesh.tetrahedra.size(); ++i) {
    const auto& t = m.mesh.tetrahedra[i];
    const double s =
        tet_shape(m.mesh.vertices[static_cast<std::size_t>(t[0])], m.mesh.vertices[static_cast<std::size_t>(t[1])],
                  m.mesh.vertices[static_cast<std::size_t>(t[2])], m.mesh.vertices[static_cast<std::size_t>(t[3])]);
    if (s > worst.first) worst = {s, i};
  }
  return worst;
}

// Whether a tetrahedron of job `job` has a grid point or warped box vertex
// in both `held` and `wanted` (by its key).
bool job_touches(const BoxMesh& m, std::int32_t job, const std::unordered_set<GridPoint, GridPointHash>& held,
                 const std::unordered_set<GridPoint, GridPointHash>& wanted) {
  for (std::size_t i = 0; i < m.mesh.tetrahedra.size(); ++i) {
    if (m.tet_job[i] != job) continue;
    for (const int v : m.mesh.tetrahedra[i]) {
      const VertexKey& k = m.keys[static_cast<std::size_t>(v)];
      if ((k.kind == VertexKind::Grid || k.kind == VertexKind::Warped) && held.count(k.p) > 0 && wanted.count(k.p) > 0)
        return true;
    }
  }
  return false;
}

}  // namespace

// Two-cone-point edge boxes (BoxAssembler::two_apex_box,
// docs/algorithm/tet3d_warp.md "Two cone points") keep an edge box valid where
// the single apex on E inverts, so the rebuild loop does not freeze the warp
// that caused it; but the warp left in place can make another box worse than
// the frozen run does (suite seeds 5, 27). So the run without them is made
// first. Only if the box of that run's worst tetrahedron has a point that the
// rebuild loop held back (frozen or kept within its box faces) and that is a
// vertex of a box which had a valid two-point construction in some trial
// (otherwise a held point of a two-point box did not make the worst box, and
// the second run costs a whole run for nothing: bounded seed 58 took 2.7x cpu),
// the run with them is made too, and kept only when its worst tetrahedron
// (tet_shape, only compared; both meshes are valid by exact orient3d) is
// strictly better. Otherwise the first run's mesh is remade from its final
// table in one pass over the jobs (remake_pass; the mesh is not kept
// meanwhile: it is about half the peak memory). Every other run does no extra work and
// keeps its bytes; no run gets a worse worst tetrahedron. When the worst-box
// freeze kept a round, the box asked about is the one that was worst before it,
// so the freeze never adds a run (flat seed 70: the freeze's new worst box
// holds such a point, and asking about it took the box stage from 14 s to 63 s
// for a two-point run that lost).
BoxMesh mesh_boxes(const OctTree& tree, const CornerSet& corners, const Domain3& domain, std::span<const BoxJob> jobs,
                   const BoxMeshOptions& options, const detail::BoxMeshTestHooks& hooks) {
  PassNotes notes;
  BoxMesh single = mesh_boxes_pass(tree, corners, domain, jobs, options, hooks, false, notes);
  if (notes.wanted.empty() || single.mesh.tetrahedra.empty()) return single;
  const auto [single_worst, worst_tet] = worst_tet_shape(single);
  const std::int32_t worst_job = notes.unfrozen_worst_job >= 0 ? notes.unfrozen_worst_job : single.tet_job[worst_tet];
  if (!job_touches(single, worst_job, notes.held, notes.wanted)) return single;
  const std::shared_ptr<const WarpTable> single_table = std::move(notes.table);
  BoxMesh counts;  // the single run's loop counts, for the remake
  counts.warp_rebuilds = single.warp_rebuilds;
  counts.worst_box_rounds = single.worst_box_rounds;
  counts.wider_table = single.wider_table;
  single = BoxMesh{};
  notes = PassNotes{};
  release_free_heap();
  BoxMesh two = mesh_boxes_pass(tree, corners, domain, jobs, options, hooks, true, notes);
  two.box_runs = 2;
  if (worst_tet_shape(two).first < single_worst) return two;
  two = BoxMesh{};
  notes = PassNotes{};
  release_free_heap();
  BoxMesh out = hooks.remake_from_table ? remake_pass(tree, corners, domain, jobs, options, hooks, counts, single_table)
                                        : mesh_boxes_pass(tree, corners, domain, jobs, options, hooks, false, notes);
  out.box_runs = 3;
  return out;
}

}  // namespace pqmesh::tet3d
