// The 3D pipeline of pqmesh/tetmesh.hpp: which octree makes the mesh
// (TetSeparation; docs/algorithm/mesh3d.md "Light construction first"), each
// construction in mesh3d/construction.hpp.
#include <chrono>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "improve3d/improve.hpp"
#include "mesh3d/construction.hpp"
#include "pqmesh/alpha.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/tetmesh.hpp"
#include "tet3d/rebuild/free_heap.hpp"

namespace pqmesh {

const char* tet_leaf_kind_name(int kind) {
  static constexpr const char* kNames[kTetLeafKinds] = {"outside", "empty", "vertex", "edge",
                                                        "facet",   "two-facet", "other"};
  return kind >= 0 && kind < kTetLeafKinds ? kNames[kind] : "?";
}

MeshNotSupported::MeshNotSupported(std::int64_t leaf, std::string kind, const std::string& detail)
    : InvalidInput(ErrorCode::Unsupported, detail, {leaf}), kind_(std::move(kind)) {}

MeshNotSupported::MeshNotSupported(std::vector<std::int64_t> leaves, std::string kind, const std::string& detail)
    : InvalidInput(ErrorCode::Unsupported, detail, std::move(leaves)), kind_(std::move(kind)) {}

namespace {

using Clock = std::chrono::steady_clock;
using mesh3d::Construction;
using mesh3d::OctreeVariant;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Why a construction's mesh is not kept (TetSeparation::Adaptive): some
// leaf without a box job, the checker (pqmesh/check.hpp), or the aspect bound.
// `why` is empty when it is kept; separate_near: the review names the faces
// the next octree should separate near (not for the checker); regrid: the
// aspect bound failed or the box code refused a configuration (InternalError),
// both local to where the box planes fall.
struct Verdict {
  std::string why;
  bool separate_near = false;
  bool regrid = false;
};

Verdict verdict(const Domain3& domain, const Construction& c, double alpha) {
  if (!c.unsupported.empty()) return {c.unsupported, true};
  if (!c.stuck.empty()) return {c.stuck, false, true};
  const CheckReport check = check_mesh(c.result.mesh, domain);
  if (!check.valid()) return {"the checker: " + check.to_text().substr(0, check.to_text().find('\n')), false};
  if (c.review.max_aspect * alpha <= kMeasuredAspectAlphaC) return {};
  return {"max aspect ratio " + std::to_string(c.review.max_aspect) + " above C / alpha = " +
              std::to_string(kMeasuredAspectAlphaC / alpha),
          true, true};
}

// One construction of the adaptive ladder and what became of it: kept, or
// the verdict and the faces its review names.
struct Attempt {
  std::optional<Construction> kept;
  Verdict verdict;
  mesh3d::FaceFlags named;
};

Attempt attempt(const Domain3& domain, const TetMeshOptions& options, const OctreeVariant& variant, double alpha,
                Clock::time_point t0, bool review_stuck) {
  Attempt a;
  try {
    Construction c = construct(domain, options, variant, alpha, t0, review_stuck);
    a.verdict = verdict(domain, c, alpha);
    if (a.verdict.why.empty()) a.kept = std::move(c);
    else a.named = std::move(c.review.over_bound);
  } catch (const MeshNotSupported& e) {  // the aligned grid's plan
    a.verdict = {e.what(), false};
  } catch (const InternalError& e) {
    a.verdict = {e.what(), false, true};
  }
  return a;
}

// TetSeparation::Adaptive, lightest first: extended boxes of margin 1 without
// separating splits; when its worst tetrahedron is above the aspect bound or
// the box code refused one of its boxes, the same octree rules on the generic
// grid's second offset (a box corner within a sliver of a facet it cannot be
// warped off stays a corner in every finer octree of the same grid, and so
// does a square the box code has no model for; another offset puts the
// planes elsewhere); then margin 2 (the thesis's ex(b)) without separating
// splits; then up to kLocalRounds octrees separated near the faces the
// reviews name (the set grows each round). The first mesh kept is returned, with the reason the last dropped
// one was dropped and the time the dropped ones cost. None kept: `rejected`
// says why the last was dropped.
constexpr int kLocalRounds = 2;

std::optional<Construction> adaptive(const Domain3& domain, const TetMeshOptions& options, double alpha,
                                     Clock::time_point t0, std::string& rejected) {
  const auto run = [&](const OctreeVariant& variant, bool review_stuck = false) {
    const double before = since(t0);
    Attempt a = attempt(domain, options, variant, alpha, t0, review_stuck);
    if (a.kept) {
      a.kept->result.stats.light_rejected = rejected;
      a.kept->result.stats.seconds_light = before;
    } else {
      rejected = a.verdict.why;
    }
    return a;
  };
  Attempt lightest = run(OctreeVariant{1, false, {}}, true);
  if (lightest.kept) return std::move(lightest.kept);
  if (lightest.verdict.regrid)
    if (Attempt shifted = run(OctreeVariant{1, false, {}, 1}); shifted.kept) return std::move(shifted.kept);
  OctreeVariant variant{2, false, {}};
  for (int round = 0; round <= kLocalRounds; ++round) {
    Attempt a = run(variant);
    if (a.kept) return std::move(a.kept);
    if (!a.verdict.separate_near || a.named.count() == 0) return std::nullopt;
    if (!variant.separate) variant = {2, true, std::move(a.named)};
    else if (!variant.faces.merge(a.named)) return std::nullopt;
  }
  return std::nullopt;
}

// The improvement stage (TetMeshOptions::improve): edge collapses, smoothing
// and flips capped by the construction's worst aspect ratio, so the bound the construction met
// still holds. The improved mesh is checked; if the checker rejects it, the
// failure is recorded and the construction is rebuilt unimproved (same input,
// same options: the same mesh).
void improve(const Domain3& domain, const TetMeshOptions& options, Construction& c) {
  TetMeshStats& s = c.result.stats;
  s.constructed_tetrahedra = static_cast<std::int64_t>(c.result.mesh.tetrahedra.size());
  s.constructed_max_aspect = c.review.max_aspect;
  s.constructed_min_dihedral = c.review.min_dihedral;
  s.constructed_max_dihedral = c.review.max_dihedral;
  if (!options.improve) return;
  tet3d::release_free_heap();  // the construction's freed pages: the working mesh's arrays are fresh mappings
  improve3d::ImproveOptions io;
  io.aspect_cap = c.review.max_aspect;
  io.target_aspect = options.target_aspect;
  const bool sized = options.max_size > 0 || !options.size_field.points.empty();
  io.min_dihedral = options.min_dihedral ? *options.min_dihedral : (sized ? 0 : kDefaultMinDihedral);
  s.min_dihedral_target = io.min_dihedral;
  io.max_size = options.max_size;
  io.size_points = options.size_field.points;
  io.sizes = options.size_field.sizes;
  const improve3d::ImproveStats is = improve3d::improve_mesh(domain, c.result.mesh, c.face_facets, io);
  s.collapses = is.collapses;
  s.smoothed = is.smoothed;
  s.flips = is.flips;
  s.boundary_flips = is.boundary_flips;
  s.seconds_improve = is.seconds;
  s.max_aspect = is.worst_aspect_after;
  const CheckReport check = check_mesh(c.result.mesh, domain);
  if (check.valid()) return;
  s.improve_failure = check.to_text().substr(0, check.to_text().find('\n'));
}

}  // namespace

TetMeshResult tet_mesh(const Domain3& domain, const TetMeshOptions& options) {
  const auto t0 = Clock::now();
  const double alpha = compute_alpha(domain.plc).radians;
  std::string rejected;
  std::optional<Construction> c;
  if (options.separation == TetSeparation::Adaptive) c = adaptive(domain, options, alpha, t0, rejected);
  if (!c) {
    const double rejected_seconds = since(t0);
    c = construct(domain, options, OctreeVariant{2, true, {}}, alpha, t0);
    c->result.stats.light_rejected = rejected;
    c->result.stats.seconds_light = options.separation == TetSeparation::Adaptive ? rejected_seconds : 0;
  }
  if (options.progress && options.improve) {
    const auto tetrahedra = static_cast<std::int64_t>(c->result.mesh.tetrahedra.size());
    options.progress(TetMeshProgress{"improve", c->result.stats.leaves, 0, tetrahedra, since(t0)});
  }
  improve(domain, options, *c);
  if (!c->result.stats.improve_failure.empty()) {
    TetMeshOptions unimproved = options;
    unimproved.improve = false;
    TetMeshResult r = tet_mesh(domain, unimproved);
    r.stats.improve_failure = c->result.stats.improve_failure;
    return r;
  }
  const TetMeshStats& s = c->result.stats;
  const std::int64_t jobs = s.empty_jobs + s.facet_jobs + s.edge_jobs + s.vertex_jobs + s.two_facet_jobs;
  const auto tetrahedra = static_cast<std::int64_t>(c->result.mesh.tetrahedra.size());
  if (options.progress) options.progress(TetMeshProgress{"done", s.leaves, jobs, tetrahedra, since(t0)});
  return std::move(c->result);
}

}  // namespace pqmesh
