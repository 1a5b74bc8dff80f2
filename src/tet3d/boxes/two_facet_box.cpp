// Two-facet boxes (thesis §4.5.5).
#include <cmath>
#include <limits>
#include <string>

#include "pqmesh/errors.hpp"
#include "tet3d/boxes/box_assembler.hpp"

namespace pqmesh::tet3d {

// Two-facet box (§4.5.5; see facet_boxes.hpp for the construction).
void BoxAssembler::two_facet_box(std::int32_t leaf, int edge) {
  const EdgeCone& ec = squares_.cone(edge);
  // A flat edge's facets are one plane: a box meeting both but not E would
  // meet other features between them (the octree makes it another kind).
  if (ec.flat())
    throw InternalError("tet3d: two-facet box " + std::to_string(leaf) + " at flat edge " + std::to_string(edge));
  const BoxKey<3>& key = tree_.key(leaf);
  std::vector<Tri> tris;
  box_tris(key, squares_.faces_of(BoxKind::TwoFacet, edge), tris);
  const GridPoint centre = key_centre(key);
  const Vec3 C = grid_coordinates(tree_, centre);
  const double h = tree_.side(leaf);
  const FacetPlane* pl[2] = {&ec.f(), &ec.g()};
  const auto chord0 = chords(leaf, tris, *pl[0]);
  const auto chord1 = chords(leaf, tris, *pl[1]);
  if (chord0.empty() || chord1.empty())
    throw InternalError("tet3d: two-facet box " + std::to_string(leaf) + " without both facets on its faces");
  // The centre strictly on P's side of both planes: for a convex edge it is
  // inside P, for a reflex one in the kernel H_F ∩ H_G of the star-shaped
  // P ∧ b; it sees every boundary triangle from inside.
  const bool kernel = pl[0]->side(C) == Sign::Negative && pl[1]->side(C) == Sign::Negative;
  const bool far = std::fabs(pl[0]->distance(C)) >= h / 4 && std::fabs(pl[1]->distance(C)) >= h / 4;
  if (kernel && (far || !ec.convex())) {
    const int v = centre_vertex(centre);
    for (const Tri& t : tris) cone(leaf, t, v);
    fan(leaf, chord0, *pl[0], VertexKind::TwoFacetCentre, centre, v);
    fan(leaf, chord1, *pl[1], VertexKind::TwoFacetCentre, centre, v);
    ++out_.stats.two_facet_centre;
    out_.stats.two_facet_reflex += ec.convex() ? 0 : 1;
    ++out_.stats.two_facet;
    return;
  }
  if (!ec.convex())
    throw InternalError("tet3d: two-facet box " + std::to_string(leaf) + " at reflex edge " + std::to_string(edge) +
                        " with its centre outside the kernel (not done)");
  // The apex: the vertex mean of the polygon of the facet whose plane is
  // nearer the box centre, or another central point of either polygon when
  // it makes the better valid box (two_facet_apex).
  const Chords* ch[2] = {&chord0, &chord1};
  const int near = std::fabs(pl[0]->distance(C)) <= std::fabs(pl[1]->distance(C)) ? 0 : 1;
  const FacetApex apex = two_facet_apex(tris, pl, ch, near);
  out_.stats.two_facet_apex_farther += apex.facet != near ? 1 : 0;
  const FacetPlane& f = *pl[apex.facet];
  const FacetPlane& g = *pl[1 - apex.facet];
  const Chords& chord_g = *ch[1 - apex.facet];
  const int v = book_.id({VertexKind::TwoFacetApex, centre, {}, f.facet()}, [&] { return apex.at; });
  for (const Tri& t : tris)
    if (!(on_facet(t[0], f) && on_facet(t[1], f) && on_facet(t[2], f))) cone(leaf, t, v);
  fan(leaf, chord_g, g, VertexKind::TwoFacetCentre, centre, v);
  ++out_.stats.two_facet;
}

// The apex of a two-facet box at a convex edge (our choice within §4.5.5,
// docs/algorithm/tet3d_warp.md "Apexes close to a box face"): a central point
// of F ∩ b for one of the two facets F, coned to the face triangles not on F,
// with the other facet's polygon fanned from its vertex mean (as fan with no
// bar). The first candidate is `near` (the facet whose plane is nearer the box
// centre) with its vertex mean (polygon_point); the others are the other
// central points of that polygon (central_points), then the same for the other
// facet. A later candidate is taken only if every one of its tetrahedra is
// positive by exact orient3d and its worst tet_shape is strictly better; the
// float shapes only choose between valid constructions (an invalid first
// candidate counts as +infinity, exactly decided), and when none is valid the
// first is kept and the rebuild loop (mesh_boxes) freezes the warp that caused
// it, as before. Why both: the nearer plane's polygon can be a sliver lying
// almost in a box face (every-run seed 197: 0.002 h from face x = 1, whose
// warped corners then made its cones flat or inverted); the vertex mean is
// pulled towards a face split into small squares, and can lie almost on the
// line of a chord of that face (harsh seed 17: a 5 degree wedge's box beside
// boxes 16 and 32 times smaller, aspect 466,599).
BoxAssembler::FacetApex BoxAssembler::two_facet_apex(const std::vector<Tri>& tris, const FacetPlane* const pl[2],
                                                     const Chords* const ch[2], int near) const {
  FacetApex best{near, polygon_point(*ch[near], *pl[near])};
  double best_shape = std::numeric_limits<double>::infinity();
  for (const int i : {near, 1 - near}) {
    const FacetPlane& f = *pl[i];
    const FacetPlane& g = *pl[1 - i];
    const Vec3 fan_point = polygon_point(*ch[1 - i], g);
    for (const Vec3& apex : central_points(*ch[i], f)) {
      const double shape = std::max(worst_cone(tris, apex, &f), worst_fan(*ch[1 - i], fan_point, apex, true));
      if (shape < best_shape) {
        best = {i, apex};
        best_shape = shape;
      }
    }
  }
  return best;
}

}  // namespace pqmesh::tet3d
