// make_domain(Plc3) and locate(Domain3): docs/algorithm/input.md "Validation,
// orientation and shells", thesis §1.4 and §4.1.6. The stages (validate3.hpp)
// run in order; each throws DomainError on the first class of violation it
// finds.
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "plc/merge_coplanar.hpp"
#include "plc/report_error.hpp"
#include "plc/validate3.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/errors.hpp"

namespace pqmesh {

using namespace detail;

namespace {

// Stages 1-10 on the facets as given.
Domain3 build_domain(Plc3 plc) {
  check_basic(plc);                                   // stage 1
  check_duplicate_vertices(plc);                      // stage 2
  const std::vector<FacetPlane> planes = check_facets(plc);  // stages 3-5
  EdgeTopology topo = build_edge_topology(plc);       // stages 6-7
  FacetTriangles ft = triangulate_facets(plc, planes);
  const SurfaceLocator surface(plc.vertices, ft.triangles);
  check_intersections(plc, topo.edges, ft, surface);  // stage 8
  ShellOrientation orientation = orient_shells(plc, topo, ft, surface);  // stage 9

  Domain3 d;
  const int nf = static_cast<int>(plc.facets.size());
  for (int f = 0; f < nf; ++f)
    if (orientation.flip[f])
      for (auto& loop : plc.facets[f].loops) std::reverse(loop.begin(), loop.end());
  for (std::size_t t = 0; t < ft.triangles.size(); ++t)
    if (orientation.flip[ft.owner[t]]) std::swap(ft.triangles[t][1], ft.triangles[t][2]);

  // Unit outward normals (constructions). Newell's vector of the outer loop,
  // its sign corrected by the exact turn: the right-hand normal of loops[0]
  // has a component along `drop` of sign outer_turn (before any flip).
  d.facet_normals.resize(nf);
  for (int f = 0; f < nf; ++f) {
    Vec3 n = newell_normal(plc.vertices, plc.facets[f].loops[0]);
    const Sign turn = orientation.flip[f] ? -planes[f].outer_turn : planes[f].outer_turn;
    if (sign_of(axis_coord(n, planes[f].drop)) != turn) n = -1.0 * n;
    const double len = norm(n);
    d.facet_normals[f] = len > 0 ? (1.0 / len) * n : n;
  }

  // Bounding box of the used vertices; volume from the oriented triangles,
  // relative to the box corner to limit cancellation.
  bool any = false;
  for (const auto& t : ft.triangles)
    for (int v : t) {
      const Vec3 p = plc.vertices[v];
      if (!any) d.bbox_min = d.bbox_max = p;
      any = true;
      d.bbox_min = {std::min(d.bbox_min.x, p.x), std::min(d.bbox_min.y, p.y), std::min(d.bbox_min.z, p.z)};
      d.bbox_max = {std::max(d.bbox_max.x, p.x), std::max(d.bbox_max.y, p.y), std::max(d.bbox_max.z, p.z)};
    }
  double six_volume = 0;
  for (const auto& t : ft.triangles) {
    const Vec3 a = plc.vertices[t[0]] - d.bbox_min, b = plc.vertices[t[1]] - d.bbox_min,
               c = plc.vertices[t[2]] - d.bbox_min;
    six_volume += dot(a, cross(b, c));
  }
  d.volume = six_volume / 6;

  d.edges = std::move(topo.edges);
  d.shells = std::move(orientation.shells);
  d.facet_triangles = std::move(ft.triangles);
  d.facet_triangle_owner = std::move(ft.owner);
  d.plc = std::move(plc);

  // Stage 10: TetGen hole points must lie outside P (outside the exterior
  // shell or inside a cavity): we mesh the single region P.
  if (!d.plc.holes.empty()) {
    const DomainLocator3 locator(d);
    const SourceInfo& src = d.plc.source;
    for (int h = 0; h < int(d.plc.holes.size()); ++h) {
      const Location where = locator.locate(d.plc.holes[h]);
      if (where == Location::Outside) continue;
      std::ostringstream msg;
      const Vec3 p = d.plc.holes[h];
      msg << "hole point " << file_id(src, h) << " (" << p.x << ", " << p.y << ", " << p.z << ") lies "
          << (where == Location::Inside ? "inside" : "on the boundary of")
          << " the domain; pqmesh meshes one region bounded by the facets, so hole points must lie outside it "
             "or in a cavity";
      throw_domain_error(src, ErrorCode::Unsupported, msg.str(), {h}, IdKind::None);
    }
  }
  return d;
}

}  // namespace

// Stage 11 (merge_coplanar.hpp): coplanar neighbours with equal markers become
// one facet, and the merged PLC is validated afresh. Merging keeps every
// vertex on a loop and builds loops that neither touch nor cross (the groups
// where it could not are left alone), so the second pass cannot fail on a
// valid first pass: if it does, that is a bug in the merge.
Domain3 make_domain(Plc3 plc) {
  Domain3 d = build_domain(std::move(plc));
  std::optional<CoplanarMerge> merged = merge_coplanar_facets(d);
  if (!merged) return d;
  try {
    return build_domain(std::move(merged->plc));
  } catch (const DomainError& e) {
    throw InternalError(std::string("merging coplanar facets made the domain invalid: ") + e.what());
  }
}

// Linear scan over the facet triangles (no index is stored in Domain3); for
// many queries use detail::DomainLocator3 (point_location.hpp). Same exact
// method: Boundary test, then the perturbed +x ray parity.
Location locate(const Domain3& domain, Vec3 p) {
  const auto& V = domain.plc.vertices;
  const auto& T = domain.facet_triangles;
  if (T.empty() || p.x < domain.bbox_min.x || p.x > domain.bbox_max.x || p.y < domain.bbox_min.y ||
      p.y > domain.bbox_max.y || p.z < domain.bbox_min.z || p.z > domain.bbox_max.z)
    return Location::Outside;
  bool inside = false;
  for (const auto& t : T) {
    const Vec3 a = V[t[0]], b = V[t[1]], c = V[t[2]];
    if (std::max({a.y, b.y, c.y}) < p.y || std::min({a.y, b.y, c.y}) > p.y) continue;
    if (std::max({a.z, b.z, c.z}) < p.z || std::min({a.z, b.z, c.z}) > p.z) continue;
    if (std::max({a.x, b.x, c.x}) < p.x) continue;
    // The box of t contains p's (y, z); p on t requires also a.x..c.x range, checked exactly by point_on_triangle.
    if (std::min({a.x, b.x, c.x}) <= p.x && point_on_triangle(p, a, b, c, triangle_drop(a, b, c)))
      return Location::Boundary;
    if (perturbed_ray_crosses(p, a, b, c)) inside = !inside;
  }
  return inside ? Location::Inside : Location::Outside;
}

}  // namespace pqmesh
