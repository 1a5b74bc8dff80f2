#include "tet3d/facet_boxes.hpp"

#include <algorithm>
#include <utility>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <string>

#include "pqmesh/errors.hpp"
#include "tet3d/cut_square.hpp"
#include "tet3d/facet_plane.hpp"
#include "tet3d/point_book.hpp"
#include "tet3d/warp.hpp"

namespace pqmesh::tet3d {

namespace {

using Tri = std::array<int, 3>;

int dominant_axis(Vec3 n) {
  const double ax = std::fabs(n.x), ay = std::fabs(n.y), az = std::fabs(n.z);
  return ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
}

class Assembler {
 public:
  Assembler(const OctTree& tree, const CornerSet& corners, const Domain3& domain, const WarpTable* warps)
      : tree_(tree), corners_(corners), domain_(domain), warps_(warps) {}

  void empty_box(std::int32_t leaf) {
    const BoxKey<3>& key = tree_.key(leaf);
    std::vector<GridTriangle> tris;
    for (int axis = 0; axis < 3; ++axis)
      for (const bool upper : {false, true}) triangulate_box_face(key, axis, upper, corners_, tris);
    const int c = centre_vertex(key_centre(key));
    for (const GridTriangle& t : tris) cone(leaf, {grid(t[0]), grid(t[1]), grid(t[2])}, c);
    ++out_.stats.empty;
  }

  void facet_box(std::int32_t leaf, int facet) {
    const FacetPlane& plane = plane_of(facet);
    const BoxKey<3>& key = tree_.key(leaf);
    // Face triangles of P ∧ b, right-hand normal out of the box (cut_square
    // gives +n; a lower face's outward normal is -n).
    std::vector<Tri> tris;
    for (int axis = 0; axis < 3; ++axis)
      for (const bool upper : {false, true}) {
        std::vector<FaceSquare> squares;
        face_squares(key, axis, upper, corners_, squares);
        const std::size_t first = tris.size();
        for (const FaceSquare& s : squares) triangulate_cut_square(s, corners_, tree_, plane, book_, tris, warps_);
        if (!upper)
          for (std::size_t i = first; i < tris.size(); ++i) std::swap(tris[i][1], tris[i][2]);
      }
    // Edges of face triangles on F: the boundary of the polygon F ∩ b, keyed
    // by (smaller id, larger id), each kept with the direction a -> b it has
    // in its face triangle. Every such edge lies on the face triangles' side
    // of one box face, so it is in exactly one of them (the part of a face
    // beyond F yields no triangles).
    std::map<std::pair<int, int>, std::pair<int, int>> chord;
    for (const Tri& t : tris)
      for (int i = 0; i < 3; ++i) {
        const int a = t[static_cast<std::size_t>(i)], b = t[static_cast<std::size_t>((i + 1) % 3)];
        if (!on_facet(a, plane) || !on_facet(b, plane)) continue;
        if (!chord.emplace(std::pair{std::min(a, b), std::max(a, b)}, std::pair{a, b}).second)
          throw InternalError("tet3d: edge on F in two face triangles of leaf " + std::to_string(leaf));
      }
    const GridPoint centre = key_centre(key);
    const Vec3 C = grid_coordinates(tree_, centre);
    const double h = tree_.side(leaf);
    const double d = plane.distance(C);
    if (d <= -h / 4) {
      const int v = centre_vertex(centre);
      for (const Tri& t : tris) cone(leaf, t, v);
      std::set<int> poly;
      for (const auto& [edge, directed] : chord) poly.insert({edge.first, edge.second});
      Vec3 mean;
      for (const int p : poly) mean = mean + book_.point(p);
      mean = (1.0 / static_cast<double>(poly.size())) * mean;
      const VertexKey gk{VertexKind::FacetCentre, centre, {}, facet};
      const int g = book_.id(gk, [&] { return plane.settle(mean, dominant_axis(plane.normal())); });
      // Fan of F ∩ b from g, coned to v. P ∧ b is convex and bounded by the
      // outward face triangles and F ∩ b, so edge a -> b of a face triangle
      // runs b -> a in F ∩ b oriented outward (away from v): (b, a, g) is an
      // outward triangle with v inside, hence (a, b, g, v) is positive.
      for (const auto& [edge, directed] : chord) tet(leaf, "fan", directed.first, directed.second, g, v);
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

  BoxMesh finish() {
    out_.mesh.vertices = book_.points();
    out_.keys.clear();
    for (int i = 0; i < book_.size(); ++i) out_.keys.push_back(book_.key(i));
    out_.mesh.tetrahedron_markers.assign(out_.mesh.tetrahedra.size(), 0);
    return std::move(out_);
  }

 private:
  int grid(const GridPoint& p) { return grid_vertex(p, tree_, warps_, book_); }
  // Box centres are never box vertices, so never warped.
  int centre_vertex(const GridPoint& p) {
    return book_.id(grid_key(p), [&] { return grid_coordinates(tree_, p); });
  }

  const FacetPlane& plane_of(int facet) {
    auto it = planes_.find(facet);
    if (it == planes_.end()) it = planes_.emplace(facet, std::make_unique<FacetPlane>(domain_, facet)).first;
    return *it->second;
  }

  bool on_facet(int id, const FacetPlane& plane) const {
    const VertexKey& k = book_.key(id);
    if (on_its_facet(k)) return k.facet == plane.facet();
    return k.kind == VertexKind::Grid && plane.side(book_.point(id)) == Sign::Zero;
  }

  // Appends (a, b, c, d), positively oriented by construction (mesh.hpp: d
  // on the side of the right-hand normal of (a, b, c)). Exact orient3d on the
  // final (rounded or warped) coordinates must agree; a flat or inverted
  // tetrahedron is a bug (or a warp that bent a face past the apex) and
  // throws naming the leaf, never flipped (ALGORITHM.md §12.2, rule 3).
  void tet(std::int32_t leaf, const char* what, int a, int b, int c, int d) {
    const Sign s = orient3d(book_.point(a), book_.point(b), book_.point(c), book_.point(d));
    if (s != Sign::Positive)
      throw InternalError(std::string("tet3d: ") + what + " tetrahedron of leaf " + std::to_string(leaf) + " is " +
                          (s == Sign::Zero ? "flat" : "inverted"));
    out_.mesh.tetrahedra.push_back({a, b, c, d});
    out_.tet_leaf.push_back(leaf);
  }

  // The cone from an apex inside the box over a face triangle with outward
  // normal: the reversed triangle followed by the apex is positive.
  void cone(std::int32_t leaf, const Tri& t, int apex) { tet(leaf, "cone", t[0], t[2], t[1], apex); }

  bool key_less(int a, int b) const { return book_.key(a) < book_.key(b); }

  // Cuts quad (a, b, c, d) (cyclic) into two triangles by the diagonal from its smallest key.
  std::array<Tri, 2> split_quad(int a, int b, int c, int d) const {
    std::array<int, 4> q{a, b, c, d};
    std::size_t lo = 0;
    for (std::size_t m = 1; m < 4; ++m)
      if (key_less(q[m], q[lo])) lo = m;
    const int p0 = q[lo], p1 = q[(lo + 1) % 4], p2 = q[(lo + 2) % 4], p3 = q[(lo + 3) % 4];
    return {Tri{p0, p1, p2}, Tri{p0, p2, p3}};
  }

  // §4.5.4 third case: the cone from the centre (beyond F) over face triangle
  // t, clipped by F. Orientations by construction: t is outward, so every
  // other prism vertex is on its inner side; top[i] lies on the segment from
  // t[i] towards the centre, so the top triangle in index order is a shrunk
  // copy of t (same normal, pointing from the top towards t), and a side
  // (t[i], t[j], top[j], top[i]) with j = i + 1 lies in the plane of the
  // centre, t[i] and t[j], its right-hand normal pointing into the prism
  // (edge t[i] -> t[j] runs the other way in the outward surface).
  void prism(std::int32_t leaf, const Tri& t, const GridPoint& centre, Vec3 C, const FacetPlane& plane) {
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

  const OctTree& tree_;
  const CornerSet& corners_;
  const Domain3& domain_;
  const WarpTable* warps_;
  PointBook book_;
  std::map<int, std::unique_ptr<FacetPlane>> planes_;
  BoxMesh out_;
};

}  // namespace

BoxMesh mesh_boxes(const OctTree& tree, const CornerSet& corners, const Domain3& domain,
                   std::span<const BoxJob> jobs, const BoxMeshOptions& options) {
  WarpTable warps;
  if (options.warp) {
    std::vector<FacetLeaf> boxes;
    for (const BoxJob& j : jobs)
      if (j.facet >= 0) boxes.push_back({j.leaf, j.facet});
    warps = warp_facet_vertices(tree, corners, domain, boxes);
  }
  Assembler a(tree, corners, domain, options.warp ? &warps : nullptr);
  for (const BoxJob& j : jobs) {
    if (!tree.is_leaf(j.leaf)) throw InternalError("tet3d: node " + std::to_string(j.leaf) + " is not a leaf");
    if (j.facet < 0)
      a.empty_box(j.leaf);
    else
      a.facet_box(j.leaf, j.facet);
  }
  BoxMesh out = a.finish();
  out.warped = static_cast<std::int64_t>(warps.size());
  out.warp_conflicts = warps.conflicts;
  return out;
}

}  // namespace pqmesh::tet3d
