// BoxAssembler: checked tetrahedra, reports for the rebuild loop, shared helpers.
#include "tet3d/boxes/box_assembler.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "pqmesh/errors.hpp"
#include "tet3d/squares/cut_square.hpp"
#include "tet3d/boxes/tet_shape.hpp"
#include "tet3d/warp/warp.hpp"

namespace pqmesh::tet3d {

// The largest tet_shape over the tetrahedra made so far (+infinity for one
// flat in floating point).
double BoxAssembler::worst_shape() const {
  double worst = 0;
  for (const auto& t : out_.mesh.tetrahedra)
    worst = std::max(worst, tet_shape(book_.point(t[0]), book_.point(t[1]), book_.point(t[2]), book_.point(t[3])));
  return worst;
}

std::vector<double> BoxAssembler::job_worst_shapes(std::size_t job_count) const {
  std::vector<double> worst(job_count, 0.0);
  for (std::size_t i = 0; i < out_.mesh.tetrahedra.size(); ++i) {
    const auto& t = out_.mesh.tetrahedra[i];
    double& w = worst.at(static_cast<std::size_t>(out_.tet_job[i]));
    w = std::max(w, tet_shape(book_.point(t[0]), book_.point(t[1]), book_.point(t[2]), book_.point(t[3])));
  }
  return worst;
}

void BoxAssembler::count_squares() {
  out_.stats.squares_nothing = squares_.count(SquareCase::Nothing);
  out_.stats.squares_a = squares_.count(SquareCase::A);
  out_.stats.squares_c = squares_.count(SquareCase::C);
  out_.stats.squares_bd = squares_.count(SquareCase::BD);
  out_.stats.squares_pieces = squares_.count(SquareCase::Pieces);
  out_.stats.vertex_squares_located = squares_.located();
  out_.stats.vertex_squares_by_neighbours = squares_.located_by_neighbours();
}

BoxMesh BoxAssembler::finish() {
  // The book is not used after this: its tables are moved, not copied.
  out_.mesh.vertices = book_.take_points();
  out_.keys = book_.take_keys();
  out_.mesh.tetrahedron_markers.assign(out_.mesh.tetrahedra.size(), 0);
  return std::move(out_);
}

// π-triangles of the given squares, right-hand normal out of the box
// (the dispatcher gives +n; a lower face's outward normal is -n).
void BoxAssembler::square_tris(const std::vector<FaceSquare>& squares, const BoxFaces& faces, bool upper,
                               std::vector<Tri>& tris) {
  const std::size_t first = tris.size();
  for (const FaceSquare& s : squares) squares_.triangulate(s, faces, tris);
  if (!upper)
    for (std::size_t i = first; i < tris.size(); ++i) std::swap(tris[i][1], tris[i][2]);
}

void BoxAssembler::box_tris(const BoxKey<3>& key, const BoxFaces& faces, std::vector<Tri>& tris) {
  for (int axis = 0; axis < 3; ++axis)
    for (const bool upper : {false, true}) {
      std::vector<FaceSquare> squares;
      face_squares(key, axis, upper, corners_, squares);
      square_tris(squares, faces, upper, tris);
    }
}

// The worst tet_shape of the cones from `apex` over the face triangles
// (those with all three vertices on `skip` left out, when given); +infinity
// if one of them is not positive by exact orient3d.
double BoxAssembler::worst_cone(const std::vector<Tri>& tris, Vec3 apex, const FacetPlane* skip) const {
  double w = 0;
  for (const Tri& t : tris) {
    if (skip != nullptr && on_facet(t[0], *skip) && on_facet(t[1], *skip) && on_facet(t[2], *skip)) continue;
    const Vec3 x = book_.point(t[0]), y = book_.point(t[2]), z = book_.point(t[1]);
    if (orient3d(x, y, z, apex) != Sign::Positive) return std::numeric_limits<double>::infinity();
    w = std::max(w, tet_shape(x, y, z, apex));
  }
  return w;
}

bool BoxAssembler::on_facet(int id, const FacetPlane& plane) const {
  const VertexKey& k = book_.key(id);
  if (on_its_facet(k)) return k.facet == plane.facet();
  return k.kind == VertexKind::Grid && plane.side(book_.point(id)) == Sign::Zero;
}

// Appends (a, b, c, d), positively oriented by construction (mesh.hpp: d
// on the side of the right-hand normal of (a, b, c)). Exact orient3d on the
// final (rounded or warped) coordinates must agree; a flat or inverted
// tetrahedron is a bug (or a warp that bent a face past the apex) and
// throws naming the leaf, never flipped (docs/algorithm/tet3d_boxes.md "Vertex
// identities", rule 3).
void BoxAssembler::tet(std::int32_t leaf, const char* what, int a, int b, int c, int d) {
  const Sign s = orient3d(book_.point(a), book_.point(b), book_.point(c), book_.point(d));
  if (s != Sign::Positive && warps_ != nullptr && collect_) {
    // A warp bent a face past the apex: the moved grid points this
    // tetrahedron depends on are reported, frozen and the mesh rebuilt
    // (mesh_boxes); none found: a bug, thrown below.
    if (report_moved({a, b, c, d})) {
      bad_jobs_.push_back(job_);
      return;
    }
  }
  if (s != Sign::Positive)
    throw InternalError(std::string("tet3d: ") + what + " tetrahedron of leaf " + std::to_string(leaf) + " is " +
                        (s == Sign::Zero ? "flat" : "inverted"));
  out_.mesh.tetrahedra.push_back({a, b, c, d});
  out_.tet_leaf.push_back(leaf);
  out_.tet_job.push_back(job_);
}

// The moved grid points the vertices depend on, appended to bad_: those
// their keys name (a warped box vertex or square centre, the ends of a
// crossed ring segment, a clipped ring point); for a point constructed on
// a square (chord midpoint, projections, Case B crossing: keyed by the
// square's centre only) the moved ring points of that square of the job's
// box; if still none (points constructed from the whole box: facet
// polygon centres), every moved ring point of the job's box. Returns
// whether any was found.
bool BoxAssembler::report_moved(std::initializer_list<int> vertices) {
  const std::size_t before = bad_.size();
  std::vector<FaceSquare> squares;
  job_squares(tree_, corners_, job_box_, squares);
  // The job's box (a united vertex box spans 2x2x2 leaves): bad_axes_ gets
  // bit a when g lies on its low face along axis a, bit 3 + a on its high
  // face (warp.cpp, `second_only`).
  const BoxKey<3>& key = tree_.key(job_box_.leaf);
  const bool united = job_box_.kind == BoxKind::Vertex;
  const GridPoint lo = united ? united_lo(key, job_box_.block) : key_corner(key, 0);
  const std::int64_t side = (united ? 2 : 1) * key.fine_side();
  auto add = [&](const GridPoint& g) {
    std::uint8_t axes = 0;
    for (std::size_t a = 0; a < 3; ++a) {
      if (g.f[a] == lo.f[a]) axes = static_cast<std::uint8_t>(axes | (1u << a));
      if (g.f[a] == lo.f[a] + side) axes = static_cast<std::uint8_t>(axes | (8u << a));
    }
    bad_.push_back(g);
    bad_axes_.push_back(axes);
  };
  auto report_square = [&](const FaceSquare& sq) {
    for (const GridPoint& g : square_ring(sq, corners_))
      if (warps_->moved(g)) add(g);
  };
  for (const int v : vertices) {
    const VertexKey& k = book_.key(v);
    for (const GridPoint& g : {k.p, k.q})
      if (warps_->moved(g)) add(g);
    if (k.kind == VertexKind::Grid || k.kind == VertexKind::Warped || k.kind == VertexKind::PVertex ||
        k.kind == VertexKind::EdgeMidpoint)
      continue;
    for (const FaceSquare& sq : squares)
      if (sq.centre() == k.p) report_square(sq);
  }
  if (bad_.size() == before)
    for (const FaceSquare& sq : squares) report_square(sq);
  return bad_.size() > before;
}

// Cuts quad (a, b, c, d) (cyclic) into two triangles by the diagonal from its smallest key.
std::array<BoxAssembler::Tri, 2> BoxAssembler::split_quad(int a, int b, int c, int d) const {
  std::array<int, 4> q{a, b, c, d};
  std::size_t lo = 0;
  for (std::size_t m = 1; m < 4; ++m)
    if (key_less(q[m], q[lo])) lo = m;
  const int p0 = q[lo], p1 = q[(lo + 1) % 4], p2 = q[(lo + 2) % 4], p3 = q[(lo + 3) % 4];
  return {Tri{p0, p1, p2}, Tri{p0, p2, p3}};
}

}  // namespace pqmesh::tet3d
