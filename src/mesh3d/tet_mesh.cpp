// The 3D pipeline of pqmesh/tetmesh.hpp: which octree makes the mesh
// (TetSeparation; docs/algorithm/mesh3d.md "Light construction first"), each
// construction in mesh3d/construction.hpp.
#include <chrono>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mesh3d/construction.hpp"
#include "pqmesh/alpha.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/tetmesh.hpp"

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
using mesh3d::Separation;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Why a construction's mesh is not kept (TetSeparation::Adaptive): some
// leaf without a box job, the checker (pqmesh/check.hpp), or the aspect bound.
// `why` is empty when it is kept; separate_near: the review names the faces
// the next octree should separate near (not for the checker).
struct Verdict {
  std::string why;
  bool separate_near = false;
};

Verdict verdict(const Domain3& domain, const Construction& c, double alpha) {
  if (!c.unsupported.empty()) return {c.unsupported, true};
  const CheckReport check = check_mesh(c.result.mesh, domain);
  if (!check.valid()) return {"the checker: " + check.to_text().substr(0, check.to_text().find('\n')), false};
  if (c.review.max_aspect * alpha <= kMeasuredAspectAlphaC) return {};
  return {"max aspect ratio " + std::to_string(c.review.max_aspect) + " above C / alpha = " +
              std::to_string(kMeasuredAspectAlphaC / alpha),
          true};
}

// TetSeparation::Adaptive: the light octree, then up to kLocalRounds octrees
// separated near the faces the reviews name (the set grows each round); the
// first mesh kept is returned, with the reason the last dropped one was
// dropped and the time the dropped ones cost. None kept: `rejected` says why
// the last was dropped.
constexpr int kLocalRounds = 2;

std::optional<TetMeshResult> adaptive(const Domain3& domain, const TetMeshOptions& options, double alpha,
                                      Clock::time_point t0, std::string& rejected) {
  Separation separation;
  for (int round = 0; round <= kLocalRounds; ++round) {
    try {
      const double before = since(t0);
      Construction c = construct(domain, options, separation, alpha, t0);
      Verdict v = verdict(domain, c, alpha);
      if (v.why.empty()) {
        c.result.stats.light_rejected = rejected;
        c.result.stats.seconds_light = before;
        return std::move(c.result);
      }
      rejected = std::move(v.why);
      if (!v.separate_near || c.review.over_bound.count() == 0) return std::nullopt;
      if (!separation.separate) separation = {true, std::move(c.review.over_bound)};
      else if (!separation.faces.merge(c.review.over_bound)) return std::nullopt;
    } catch (const MeshNotSupported& e) {  // the aligned grid's plan
      rejected = e.what();
      return std::nullopt;
    } catch (const InternalError& e) {
      rejected = e.what();
      return std::nullopt;
    }
  }
  return std::nullopt;
}

}  // namespace

TetMeshResult tet_mesh(const Domain3& domain, const TetMeshOptions& options) {
  const auto t0 = Clock::now();
  const double alpha = compute_alpha(domain.plc).radians;
  auto finish = [&](TetMeshResult& r) {
    const TetMeshStats& s = r.stats;
    const std::int64_t jobs = s.empty_jobs + s.facet_jobs + s.edge_jobs + s.vertex_jobs + s.two_facet_jobs;
    const auto tetrahedra = static_cast<std::int64_t>(r.mesh.tetrahedra.size());
    if (options.progress) options.progress(TetMeshProgress{"done", s.leaves, jobs, tetrahedra, since(t0)});
    return std::move(r);
  };
  std::string rejected;
  if (options.separation == TetSeparation::Adaptive) {
    std::optional<TetMeshResult> kept = adaptive(domain, options, alpha, t0, rejected);
    if (kept) return finish(*kept);
  }
  const double rejected_seconds = since(t0);
  TetMeshResult full = construct(domain, options, Separation{true, {}}, alpha, t0).result;
  full.stats.light_rejected = rejected;
  full.stats.seconds_light = options.separation == TetSeparation::Adaptive ? rejected_seconds : 0;
  return finish(full);
}

}  // namespace pqmesh
