#include "tet3d/rebuild/job_runs.hpp"

#include <string>

#include "pqmesh/errors.hpp"

namespace pqmesh::tet3d {

namespace {

void run_job(BoxAssembler& a, const OctTree& tree, std::span<const BoxJob> jobs, std::size_t ji) {
  const BoxJob& j = jobs[ji];
  a.set_job(ji, j);
  if (!tree.is_leaf(j.leaf)) throw InternalError("tet3d: node " + std::to_string(j.leaf) + " is not a leaf");
  switch (j.kind) {
    case BoxKind::FromFacet:
      if (j.facet < 0)
        a.empty_box(j.leaf);
      else
        a.facet_box(j.leaf, j.facet);
      break;
    case BoxKind::Empty: a.empty_box(j.leaf); break;
    case BoxKind::Facet: a.facet_box(j.leaf, j.apex); break;
    case BoxKind::Edge: a.edge_box(j.leaf, j.apex); break;
    case BoxKind::Vertex: a.vertex_box(j.leaf, j.apex, j.block); break;
    case BoxKind::TwoFacet: a.two_facet_box(j.leaf, j.apex); break;
  }
}

std::unique_ptr<BoxAssembler> trial_assembler(const BoxPass& pass, const WarpTable& warps) {
  auto a = std::make_unique<BoxAssembler>(pass.tree, pass.corners, pass.domain, &warps);
  a->collect_bad();
  a->allow_two_apex(pass.two_apex);
  a->allow_facet_fans(pass.facet_fans);
  a->set_empty_cells(pass.empty_cells);
  return a;
}

}  // namespace

void run_jobs(BoxAssembler& a, const OctTree& tree, std::span<const BoxJob> jobs) {
  for (std::size_t ji = 0; ji < jobs.size(); ++ji) run_job(a, tree, jobs, ji);
}

void run_jobs(BoxAssembler& a, const OctTree& tree, std::span<const BoxJob> jobs, std::span<const std::int32_t> scope) {
  for (const std::int32_t ji : scope) run_job(a, tree, jobs, static_cast<std::size_t>(ji));
}

std::unique_ptr<BoxAssembler> full_trial(const BoxPass& pass, const WarpTable& warps) {
  auto a = trial_assembler(pass, warps);
  run_jobs(*a, pass.tree, pass.jobs);
  return a;
}

std::unique_ptr<BoxAssembler> partial_trial(const BoxPass& pass, const WarpTable& warps,
                                            std::span<const std::int32_t> scope) {
  auto a = trial_assembler(pass, warps);
  run_jobs(*a, pass.tree, pass.jobs, scope);
  return a;
}

}  // namespace pqmesh::tet3d
