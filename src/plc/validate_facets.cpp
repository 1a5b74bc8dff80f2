// Stages 3-5 of 3D validation: each facet on its own (thesis §1.4: facets are
// planar polygons, possibly with holes, that do not cross themselves).
#include <algorithm>
#include <sstream>

#include "plc/polygon2d.hpp"
#include "plc/report_error.hpp"
#include "plc/validate3.hpp"

namespace pqmesh::detail {

namespace {

// A loop with fewer than 3 vertices, a vertex repeated consecutively (also
// across the closing edge), or fewer than 3 distinct vertices.
bool degenerate_loop(const std::vector<int>& loop) {
  const std::size_t n = loop.size();
  if (n < 3) return true;
  for (std::size_t k = 0; k < n; ++k)
    if (loop[k] == loop[(k + 1) % n]) return true;
  std::vector<int> ids(loop);
  std::sort(ids.begin(), ids.end());
  return std::unique(ids.begin(), ids.end()) - ids.begin() < 3;
}

// Loops of one facet (in its exact projection) cross or touch each other or
// themselves, other than consecutive sides at their common vertex.
bool loops_conflict(const ProjectedFacet& pf) {
  std::vector<KeyedSegment> segs;
  for (const auto& loop : pf.loops)
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const int a = loop[k], b = loop[(k + 1) % loop.size()];
      segs.push_back({pf.points[a], pf.points[b], a, b});
    }
  if (find_segment_conflict(segs)) return true;
  // A vertex used twice (in one loop or in two) makes the facet touch itself
  // there even when no two sides overlap.
  std::vector<int> ids;
  for (const auto& loop : pf.loops) ids.insert(ids.end(), loop.begin(), loop.end());
  std::sort(ids.begin(), ids.end());
  return std::adjacent_find(ids.begin(), ids.end()) != ids.end();
}

struct Box2 {
  double xlo, xhi, ylo, yhi;
  bool contains(const Box2& o) const { return xlo <= o.xlo && o.xhi <= xhi && ylo <= o.ylo && o.yhi <= yhi; }
};

Box2 box_of(const std::vector<Vec2>& pts, const std::vector<int>& loop) {
  Box2 b{pts[loop[0]].x, pts[loop[0]].x, pts[loop[0]].y, pts[loop[0]].y};
  for (int v : loop) {
    b.xlo = std::min(b.xlo, pts[v].x);
    b.xhi = std::max(b.xhi, pts[v].x);
    b.ylo = std::min(b.ylo, pts[v].y);
    b.yhi = std::max(b.yhi, pts[v].y);
  }
  return b;
}

// Loop `inner` lies inside loop `outer` (loops known not to touch, so one
// vertex decides).
bool loop_inside(const ProjectedFacet& pf, const std::vector<int>& inner, const std::vector<int>& outer,
                 const Box2& inner_box, const Box2& outer_box) {
  if (!outer_box.contains(inner_box)) return false;
  return locate_in_loop(pf.points[inner[0]], pf.points, outer) == PointInLoop::Inside;
}

}  // namespace

std::vector<FacetPlane> check_facets(Plc3& plc) {
  const SourceInfo& src = plc.source;
  const auto& verts = plc.vertices;
  const int nf = static_cast<int>(plc.facets.size());
  std::vector<FacetPlane> planes(nf);

  // Stage 3: degenerate loops and facets whose vertices are all collinear.
  std::vector<int> bad;
  for (int f = 0; f < nf; ++f) {
    const Facet3& facet = plc.facets[f];
    bool degenerate = facet.loops.empty();
    for (const auto& loop : facet.loops) degenerate = degenerate || degenerate_loop(loop);
    if (!degenerate) {
      const auto basis = find_basis(verts, facet);
      if (!basis) {
        degenerate = true;
      } else {
        planes[f].basis = *basis;
        const Vec3 hint = newell_normal(verts, facet.loops[0]);
        planes[f].drop = choose_drop(verts[(*basis)[0]], verts[(*basis)[1]], verts[(*basis)[2]], hint);
      }
    }
    if (degenerate) bad.push_back(f);
  }
  if (!bad.empty())
    throw_domain_error(src, ErrorCode::DegenerateFacet,
                       "facets " + id_list(src, bad) +
                           " are degenerate (a loop with fewer than 3 distinct vertices, a vertex repeated "
                           "consecutively, or all vertices on one line)",
                       bad, IdKind::Element);

  // Stage 4: every vertex on the plane of the facet's basis (exact orient3d).
  std::ostringstream detail;
  for (int f = 0; f < nf; ++f) {
    const auto [a, b, c] = planes[f].basis;
    int off = -1;
    for (const auto& loop : plc.facets[f].loops)
      for (int v : loop)
        if (off < 0 && v != a && v != b && v != c && orient3d(verts[a], verts[b], verts[c], verts[v]) != Sign::Zero)
          off = v;
    if (off >= 0) {
      if (bad.empty()) detail << "facet " << file_id(src, f) << " is not planar: vertex " << file_id(src, off)
                              << " is off the plane of vertices " << file_id(src, a) << ", " << file_id(src, b)
                              << ", " << file_id(src, c);
      bad.push_back(f);
    }
  }
  if (!bad.empty()) {
    if (bad.size() > 1) detail << " (non-planar facets: " << id_list(src, bad) << ")";
    throw_domain_error(src, ErrorCode::NonPlanarFacet, detail.str(), bad, IdKind::Element);
  }

  // Stage 5: loops simple and mutually disjoint, holes inside the outer loop
  // and not inside one another; then fix the hole turns.
  std::vector<std::string> reasons;
  for (int f = 0; f < nf; ++f) {
    Facet3& facet = plc.facets[f];
    if (facet.loops.size() == 1 && facet.loops[0].size() == 3) {
      // A triangle of three distinct, non-collinear vertices is simple (the
      // common case for triangle soups): only its turn is needed.
      const auto& l = facet.loops[0];
      planes[f].outer_turn = orient2d_projected(verts[l[0]], verts[l[1]], verts[l[2]], planes[f].drop);
      continue;
    }
    const ProjectedFacet pf = project_facet(verts, facet, planes[f].drop);
    if (loops_conflict(pf)) {
      bad.push_back(f);
      reasons.push_back("its sides cross or touch");
      continue;
    }
    const std::size_t nl = pf.loops.size();
    std::vector<Box2> boxes;
    for (const auto& loop : pf.loops) boxes.push_back(box_of(pf.points, loop));
    std::string reason;
    for (std::size_t h = 1; h < nl && reason.empty(); ++h) {
      if (!loop_inside(pf, pf.loops[h], pf.loops[0], boxes[h], boxes[0])) reason = "a hole lies outside its outer loop";
      for (std::size_t g = 1; g < nl && reason.empty(); ++g)
        if (g != h && loop_inside(pf, pf.loops[h], pf.loops[g], boxes[h], boxes[g])) reason = "a hole lies inside another hole";
    }
    if (!reason.empty()) {
      bad.push_back(f);
      reasons.push_back(reason);
      continue;
    }
    planes[f].outer_turn = loop_turn(pf.points, pf.loops[0]);
    for (std::size_t h = 1; h < nl; ++h)
      if (loop_turn(pf.points, pf.loops[h]) == planes[f].outer_turn)
        std::reverse(facet.loops[h].begin(), facet.loops[h].end());
  }
  if (!bad.empty()) {
    std::string msg = "facet " + std::to_string(file_id(src, bad[0])) + " intersects itself: " + reasons[0];
    if (bad.size() > 1) msg += " (self-intersecting facets: " + id_list(src, bad) + ")";
    throw_domain_error(src, ErrorCode::SelfIntersectingFacet, msg, bad, IdKind::Element);
  }
  return planes;
}

}  // namespace pqmesh::detail
