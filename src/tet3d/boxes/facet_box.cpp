// Facet boxes (thesis §4.5.4): centre inside, on F, or beyond F (prisms).
#include <algorithm>
#include <string>

#include "pqmesh/errors.hpp"
#include "tet3d/boxes/box_assembler.hpp"
#include "tet3d/boxes/tet_shape.hpp"

namespace pqmesh::tet3d {

void BoxAssembler::facet_box(std::int32_t leaf, int facet) {
  const FacetPlane& plane = squares_.plane(facet);
  const BoxKey<3>& key = tree_.key(leaf);
  // Face triangles of P ∧ b, right-hand normal out of the box.
  std::vector<Tri> tris;
  box_tris(key, squares_.faces_of(BoxKind::Facet, facet), tris);
  // Edges of face triangles on F: the boundary of the polygon F ∩ b, keyed
  // by (smaller id, larger id), each kept with the direction a -> b it has
  // in its face triangle. Every such edge lies on the face triangles' side
  // of one box face, so it is in exactly one of them (the part of a face
  // beyond F yields no triangles).
  const auto chord = chords(leaf, tris, plane);
  const GridPoint centre = key_centre(key);
  const Vec3 C = grid_coordinates(tree_, centre);
  const double h = tree_.side(leaf);
  const double d = plane.distance(C);
  if (d <= -h / 4) {
    const int v = centre_vertex(centre);
    double cone_worst = 0;
    for (const Tri& t : tris) {
      cone(leaf, t, v);
      cone_worst =
          std::max(cone_worst, tet_shape(book_.point(t[0]), book_.point(t[2]), book_.point(t[1]), book_.point(v)));
    }
    fan(leaf, chord, plane, VertexKind::FacetCentre, centre, v, cone_worst);
    ++out_.stats.inside;
  } else if (d < h / 4) {
    const VertexKey vk{VertexKind::BoxOnFacet, centre, {}, facet};
    const int v = book_.id(vk, [&] { return plane.settle(C - d * plane.normal(), dominant_axis(plane.normal())); });
    for (const Tri& t : tris) cone(leaf, t, v);
    ++out_.stats.on_facet;
  } else {
    for (const Tri& t : tris) prism(leaf, t, centre, C, plane);
    ++out_.stats.beyond;
  }
}

// §4.5.4 third case: the cone from the centre (beyond F) over face triangle
// t, clipped by F. Orientations by construction: t is outward, so every
// other prism vertex is on its inner side; top[i] lies on the segment from
// t[i] towards the centre, so the top triangle in index order is a shrunk
// copy of t (same normal, pointing from the top towards t), and a side
// (t[i], t[j], top[j], top[i]) with j = i + 1 lies in the plane of the
// centre, t[i] and t[j], its right-hand normal pointing into the prism
// (edge t[i] -> t[j] runs the other way in the outward surface).
void BoxAssembler::prism(std::int32_t leaf, const Tri& t, const GridPoint& centre, Vec3 C, const FacetPlane& plane) {
  std::array<int, 3> top{};
  int shared = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    if (on_facet(t[i], plane)) {
      top[i] = t[i];
      ++shared;
      continue;
    }
    const VertexKey& tk = book_.key(t[i]);
    if (tk.kind != VertexKind::Grid && tk.kind != VertexKind::Warped)
      throw InternalError("tet3d: prism bottom vertex off F is not a box vertex or square centre");
    const VertexKey ck{VertexKind::BoxClip, centre, tk.p, plane.facet()};
    const Vec3 p = book_.point(t[i]);
    top[i] = book_.id(ck, [&] { return plane.crossing(C, p); });
  }
  if (shared == 3) throw InternalError("tet3d: face triangle lies on F in leaf " + std::to_string(leaf));
  if (shared == 2) {
    for (std::size_t i = 0; i < 3; ++i)
      if (top[i] != t[i]) cone(leaf, t, top[i]);
    return;
  }
  if (shared == 1) {
    std::size_t s = 0;
    while (top[s] != t[s]) ++s;
    const int apex = t[s], b1 = t[(s + 1) % 3], b2 = t[(s + 2) % 3];
    // The side quad's triangles have inward normals and apex on their inner side.
    for (const Tri& q : split_quad(b1, b2, top[(s + 2) % 3], top[(s + 1) % 3]))
      tet(leaf, "prism", q[0], q[1], q[2], apex);
    return;
  }
  // Full prism: the smallest of its six vertices is the apex of the two
  // quads through it; cut off the tetrahedron of the opposite triangle's
  // edge... (bottom t, top `top`).
  std::array<int, 6> all{t[0], t[1], t[2], top[0], top[1], top[2]};
  std::size_t m = 0;
  for (std::size_t i = 1; i < 6; ++i)
    if (key_less(all[i], all[m])) m = i;
  const std::size_t i0 = m % 3, i1 = (i0 + 1) % 3, i2 = (i0 + 2) % 3;
  const bool bottom = m < 3;
  // The minimum vertex and the whole triangle (top or bottom) it is not in.
  const int apex = all[m];
  const int o0 = bottom ? top[i0] : t[i0], o1 = bottom ? top[i1] : t[i1], o2 = bottom ? top[i2] : t[i2];
  // The top's normal points towards the bottom, t's away from the top.
  if (bottom)
    tet(leaf, "prism", o0, o1, o2, apex);
  else
    tet(leaf, "prism", o0, o2, o1, apex);
  // Remaining pyramid: apex over the side quad t[i1] t[i2] top[i2] top[i1].
  for (const Tri& q : split_quad(t[i1], t[i2], top[i2], top[i1])) tet(leaf, "prism", q[0], q[1], q[2], apex);
}

}  // namespace pqmesh::tet3d
