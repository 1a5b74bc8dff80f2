#include "mesh3d/aspect_review.hpp"

#include <algorithm>
#include <cstddef>
#include <unordered_set>

#include "pqmesh/tetmesh.hpp"
#include "quality/tetrahedron_quality_memo.hpp"

namespace pqmesh::mesh3d {

namespace {

void flag(std::vector<char>& flags, int id) { flags[static_cast<std::size_t>(id)] = 1; }

}  // namespace

std::int64_t FaceFlags::count() const {
  return std::count(edges.begin(), edges.end(), 1) + std::count(facets.begin(), facets.end(), 1);
}

bool FaceFlags::merge(const FaceFlags& more) {
  bool grew = false;
  const auto merge_into = [&](std::vector<char>& to, const std::vector<char>& from) {
    for (std::size_t i = 0; i < from.size(); ++i) {
      grew = grew || (from[i] != 0 && to[i] == 0);
      to[i] = static_cast<char>(to[i] | from[i]);
    }
  };
  merge_into(edges, more.edges);
  merge_into(facets, more.facets);
  return grew;
}

void FaceFlags::add_edges_of_facets(const Domain3& domain) {
  for (std::size_t e = 0; e < domain.edges.size(); ++e)
    for (const int f : domain.edges[e].facets)
      if (f >= 0 && facets[static_cast<std::size_t>(f)] != 0) edges[e] = 1;
}

FaceFlags no_faces(const Domain3& domain) {
  FaceFlags out;
  out.edges.assign(domain.edges.size(), 0);
  out.facets.assign(domain.plc.facets.size(), 0);
  return out;
}

void flag_leaf_faces(const mv3d::OctreeBuilder& builder, std::int32_t leaf, FaceFlags& out) {
  const Domain3& domain = builder.domain();
  const mv3d::NodeData3& d = builder.data(leaf);
  for (const int e : d.edges) flag(out.edges, e);
  for (const int f : d.facets) flag(out.facets, f);
  for (const int v : d.vertices)
    for (std::size_t e = 0; e < domain.edges.size(); ++e) {
      const DomainEdge& edge = domain.edges[e];
      if (edge.a != v && edge.b != v) continue;
      flag(out.edges, static_cast<int>(e));
      for (const int f : edge.facets)
        if (f >= 0) flag(out.facets, f);
    }
}

AspectReview review_aspect(const mv3d::OctreeBuilder& builder, const std::vector<std::int32_t>& tet_leaf,
                           const TetMesh3& mesh, double alpha) {
  AspectReview out;
  out.over_bound = no_faces(builder.domain());
  TetrahedronQualityMemo memo;
  std::unordered_set<std::int32_t> flagged_leaves;
  const auto& v = mesh.vertices;
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) {
    const auto& tet = mesh.tetrahedra[t];
    const TetQuality q = memo(v[tet[0]], v[tet[1]], v[tet[2]], v[tet[3]]);
    const double a = q.aspect_ratio;
    if (!(a <= out.max_aspect)) out.max_aspect = a;  // NaN counts as worst
    out.min_dihedral = std::min(out.min_dihedral, q.min_dihedral_deg);
    out.max_dihedral = std::max(out.max_dihedral, q.max_dihedral_deg);
    if (a * alpha <= kMeasuredAspectAlphaC) continue;
    const std::int32_t leaf = tet_leaf[t];
    if (flagged_leaves.insert(leaf).second) flag_leaf_faces(builder, leaf, out.over_bound);
  }
  return out;
}

std::string review_stuck_corners(const tet3d::BoxMesh& stuck, double alpha) {
  TetrahedronQualityMemo memo;
  const auto& v = stuck.mesh.vertices;
  double worst = 0;
  for (const auto& tet : stuck.mesh.tetrahedra) {
    const double a = memo(v[tet[0]], v[tet[1]], v[tet[2]], v[tet[3]]).aspect_ratio;
    if (!(a <= worst)) worst = a;  // NaN counts as worst
  }
  if (worst * alpha <= kMeasuredAspectAlphaC) return {};
  return "max aspect ratio " + std::to_string(worst) + " above C / alpha = " +
         std::to_string(kMeasuredAspectAlphaC / alpha) + " at a box corner the warp cannot move (before the box stage)";
}

}  // namespace pqmesh::mesh3d
