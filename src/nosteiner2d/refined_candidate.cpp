// Refined candidate (refined_candidate.hpp): the input's loops as closed
// constraint loops (interior on their left, as make_domain orients them),
// refined with split_constraints = false.
#include "nosteiner2d/refined_candidate.hpp"

#include <numbers>
#include <utility>

#include "cdt2d/refine.hpp"
#include "pqmesh/nosteiner.hpp"

namespace pqmesh::detail {

std::size_t refined_point_cap(const Domain2& domain) { return 32 * domain.pslg.vertices.size() + 4096; }

RefinedCandidate refined_candidate(const Domain2& domain, double target_degrees, std::size_t max_new_points,
                                   const std::vector<Vec2>& seeds) {
  cdt2d::CdtInput in;
  in.points = domain.pslg.vertices;
  in.points.insert(in.points.end(), seeds.begin(), seeds.end());
  for (const auto& loop : domain.loops)
    for (std::size_t k = 0; k < loop.size(); ++k) in.constraints.push_back({loop[k], loop[(k + 1) % loop.size()]});
  cdt2d::RefineOptions options;
  options.min_angle_degrees = target_degrees;
  options.max_new_points = max_new_points;
  options.split_constraints = false;
  cdt2d::RefineResult r = cdt2d::refine_constrained_delaunay(std::move(in), options);
  RefinedCandidate out;
  out.target_degrees = target_degrees;
  out.inserted = seeds.size() + r.inserted;
  out.seeds = seeds.size();
  out.target_reached = r.target_reached;
  out.cap_reached = r.cap_reached;
  out.given_up_outside = r.given_up_outside;
  out.given_up_near = r.given_up_near;
  out.given_up_flat = r.given_up_flat;
  out.apex_points = r.apex_points;
  out.mesh.vertices = std::move(r.points);
  out.mesh.triangles = std::move(r.triangles);
  out.mesh.triangle_markers.assign(out.mesh.triangles.size(), kRegionRefined);
  return out;
}

std::vector<QualityPassOptions> refined_pass_variants(double target_degrees) {
  QualityPassOptions keep;
  keep.coarsen = false;
  QualityPassOptions smooth = keep;
  smooth.smoothing_rounds = 2;
  smooth.final_smoothing_sweeps = 2;
  smooth.smoothing_below = target_degrees * std::numbers::pi / 180;
  return {QualityPassOptions{}, keep, smooth};
}

}  // namespace pqmesh::detail
