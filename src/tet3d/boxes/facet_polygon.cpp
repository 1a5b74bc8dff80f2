// The polygon F ∩ b of a box on facet F: its chords, central points and fan (§4.5.4, §4.5.5).
#include <algorithm>
#include <limits>
#include <set>
#include <string>

#include "pqmesh/errors.hpp"
#include "tet3d/boxes/box_assembler.hpp"
#include "tet3d/boxes/tet_shape.hpp"

namespace pqmesh::tet3d {

// Edges of face triangles on F: the boundary of the polygon F ∩ b, keyed
// by (smaller id, larger id), each kept with the direction a -> b it has
// in its face triangle. Every such edge lies on the face triangles' side
// of one box face, so it is in exactly one of them (the part of a face
// beyond F yields no triangles). In an edge box, `edge` is E (one of F's
// edges): its crossings with the box faces are on F too.
BoxAssembler::Chords BoxAssembler::chords(std::int32_t leaf, const std::vector<Tri>& tris, const FacetPlane& plane,
                                          int edge) const {
  auto on = [&](int id) {
    const VertexKey& k = book_.key(id);
    return on_facet(id, plane) || (edge >= 0 && k.kind == VertexKind::EdgeCrossing && k.facet == edge);
  };
  Chords chord;
  for (const Tri& t : tris)
    for (int i = 0; i < 3; ++i) {
      const int a = t[static_cast<std::size_t>(i)], b = t[static_cast<std::size_t>((i + 1) % 3)];
      if (!on(a) || !on(b)) continue;
      if (!chord.emplace(std::pair{std::min(a, b), std::max(a, b)}, std::pair{a, b}).second)
        throw InternalError("tet3d: edge on F in two face triangles of leaf " + std::to_string(leaf));
    }
  return chord;
}

// The mean of the polygon's vertices (a point of the relative interior of
// the convex polygon F ∩ b; not yet rounded onto F).
Vec3 BoxAssembler::vertex_mean(const Chords& chord) const {
  std::set<int> poly;
  for (const auto& [edge, directed] : chord) poly.insert({edge.first, edge.second});
  Vec3 mean;
  for (const int p : poly) mean = mean + book_.point(p);
  return (1.0 / static_cast<double>(poly.size())) * mean;
}

// The vertex mean rounded onto F.
Vec3 BoxAssembler::polygon_point(const Chords& chord, const FacetPlane& plane) const {
  return plane.settle(vertex_mean(chord), dominant_axis(plane.normal()));
}

// Central points of the convex polygon F ∩ b (its chords), each rounded
// onto F: [0] the vertex mean (polygon_point), then the area centroid (the
// fan triangles (a, b, mean) weighted by their signed area along F's
// normal: the chords turn one way around F ∩ b) and the boundary's
// length-weighted centroid (chord midpoints), when defined.
std::vector<Vec3> BoxAssembler::central_points(const Chords& chord, const FacetPlane& plane) const {
  const int axis = dominant_axis(plane.normal());
  const Vec3 mean = vertex_mean(chord);
  std::vector<Vec3> out = {plane.settle(mean, axis)};
  Vec3 area_sum, length_sum;
  double area = 0, length = 0;
  for (const auto& [edge, directed] : chord) {
    const Vec3 a = book_.point(directed.first), b = book_.point(directed.second);
    const double s = dot(cross(a - mean, b - mean), plane.normal());
    area_sum = area_sum + (s / 3) * (a + b + mean);
    area += s;
    const double l = norm(b - a);
    length_sum = length_sum + (l / 2) * (a + b);
    length += l;
  }
  if (area != 0) out.push_back(plane.settle((1 / area) * area_sum, axis));
  if (length > 0) out.push_back(plane.settle((1 / length) * length_sum, axis));
  return out;
}

// The worst tet_shape of the fan of F ∩ b (its chords) from g, coned to
// `apex` (the tetrahedra of fan); with `exact`, +infinity if one of them is
// not positive by exact orient3d.
double BoxAssembler::worst_fan(const Chords& chord, Vec3 g, Vec3 apex, bool exact) const {
  double w = 0;
  for (const auto& [edge, directed] : chord) {
    const Vec3 a = book_.point(directed.first), b = book_.point(directed.second);
    if (exact && orient3d(a, b, g, apex) != Sign::Positive) return std::numeric_limits<double>::infinity();
    w = std::max(w, tet_shape(a, b, g, apex));
  }
  return w;
}

// §4.5.4 asks for "a centrally located point" of F ∩ I(b). The vertex mean is
// pulled towards the side with more vertices: on a long thin polygon (F
// clipping a box edge, one face beside it split into small squares: bounded
// random seed 58, docs/algorithm/tet3d_warp.md "The facet box's fan point") it
// lies almost on the line of a chord and that fan tetrahedron is flat (aspect
// 16,433). So when the worst fan tetrahedron from the mean is worse (tet_shape,
// compared only) than `bar` (the worst cone of the box: only then is the fan
// the box's weakest part), the polygon's area centroid and its boundary's
// length-weighted centroid are tried, each rounded onto F and taken only if
// every one of its fan tetrahedra is positive by exact orient3d and its worst
// is better. Returns the point (rounded onto F).
Vec3 BoxAssembler::fan_centre(const Chords& chord, const FacetPlane& plane, int v, double bar) const {
  const Vec3 apex = book_.point(v);
  auto worst = [&](Vec3 g, bool exact) { return worst_fan(chord, g, apex, exact); };
  Vec3 best = polygon_point(chord, plane);
  if (!(bar < std::numeric_limits<double>::infinity())) return best;
  double best_shape = worst(best, false);
  if (!(best_shape > bar)) return best;
  const std::vector<Vec3> candidates = central_points(chord, plane);
  for (std::size_t k = 1; k < candidates.size(); ++k) {
    const double s = worst(candidates[k], true);
    if (s < best_shape) {
      best = candidates[k];
      best_shape = s;
    }
  }
  return best;
}

// Fan of F ∩ b from its central point g, coned to v. P ∧ b is convex and
// bounded by the outward face triangles and F ∩ b, so edge a -> b of a face
// triangle runs b -> a in F ∩ b oriented outward (away from v): (b, a, g) is
// an outward triangle with v inside, hence (a, b, g, v) is positive.
// `bar` (facet boxes): see fan_centre; +infinity keeps the vertex mean.
void BoxAssembler::fan(std::int32_t leaf, const Chords& chord, const FacetPlane& plane, VertexKind kind,
                       const GridPoint& centre, int v, double bar) {
  const VertexKey gk{kind, centre, {}, plane.facet()};
  const int g = book_.id(gk, [&] { return fan_centre(chord, plane, v, bar); });
  for (const auto& [edge, directed] : chord) tet(leaf, "fan", directed.first, directed.second, g, v);
}

}  // namespace pqmesh::tet3d
