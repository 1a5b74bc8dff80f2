// BoxAssembler: empty boxes (thesis §4.5.1), with Kuhn faces and Kuhn boxes
// (docs/algorithm/tet3d_boxes.md "Empty boxes").
#include <array>
#include <vector>

#include "tet3d/boxes/box_assembler.hpp"
#include "tet3d/warp/warp_table.hpp"

namespace pqmesh::tet3d {

namespace {

// The corners of face (axis, upper) of the aligned box `key`, counter-
// clockwise seen from +axis (FaceSquare's frame: u = axis + 1, v = axis + 2),
// starting at the face's lower corner: c0, c0 + s·u, c0 + s·(u + v), c0 + s·v.
std::array<GridPoint, 4> face_corners(const BoxKey<3>& key, int axis, bool upper) {
  const std::int64_t s = key.fine_side();
  const auto u = static_cast<std::size_t>((axis + 1) % 3), v = static_cast<std::size_t>((axis + 2) % 3);
  GridPoint lo = key_corner(key, 0);
  if (upper) lo.f[static_cast<std::size_t>(axis)] += s;
  std::array<GridPoint, 4> c{lo, lo, lo, lo};
  c[1].f[u] += s;
  c[2].f[u] += s;
  c[2].f[v] += s;
  c[3].f[v] += s;
  return c;
}

GridPoint midpoint(const GridPoint& a, const GridPoint& b) {
  GridPoint m;
  for (std::size_t i = 0; i < 3; ++i) m.f[i] = (a.f[i] + b.f[i]) / 2;
  return m;
}

}  // namespace

// A Kuhn face: the box asking is an empty box (a job of kind Empty: a flush
// leaf meshed by empty_box keeps its fans) and the leaf across face
// (axis, upper) is an empty box of the same level, the face is one square with no split point on its sides (its
// centre and its sides' midpoints are no corners, box_faces.hpp), and none
// of its four corners is warped. Both boxes sharing the face decide this
// alike (one set of empty boxes, one corner set, one warp table per pass),
// and both cut it by the same diagonal c0–c2 (face_corners), whose direction
// e_u + e_v does not depend on the side asking.
// Cost: eight hash lookups.
bool BoxAssembler::kuhn_face(const BoxKey<3>& key, int axis, bool upper) const {
  if (empty_cells_ == nullptr || !empty_cells_->holds(key_centre(key), key.level)) return false;
  GridPoint across = key_centre(key);
  across.f[static_cast<std::size_t>(axis)] += upper ? key.fine_side() : -key.fine_side();
  if (!empty_cells_->holds(across, key.level)) return false;
  const std::array<GridPoint, 4> c = face_corners(key, axis, upper);
  if (corners_.contains(midpoint(c[0], c[2]))) return false;
  for (std::size_t i = 0; i < 4; ++i)
    if (corners_.contains(midpoint(c[i], c[(i + 1) % 4]))) return false;
  if (warps_ != nullptr)
    for (const GridPoint& g : c)
      if (warps_->moved(g)) return false;
  return true;
}

// The six Kuhn (Freudenthal) tetrahedra of the box along its main diagonal
// L → L + s·(1, 1, 1): for each permutation (i, j, k) of the axes,
// (L, L + s·e_i, L + s·(e_i + e_j), L + s·(1, 1, 1)), whose orientation is the
// permutation's sign (odd ones are written with two vertices swapped). The
// two of them on face (axis, upper) cut it by its diagonal c0–c2 of
// face_corners, so they meet the neighbour's Kuhn-face triangles exactly.
void BoxAssembler::kuhn_box(std::int32_t leaf, const BoxKey<3>& key) {
  static constexpr int kPerm[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {1, 0, 2}, {2, 1, 0}};
  const int a = grid(key_corner(key, 0)), d = grid(key_corner(key, 7));
  for (int p = 0; p < 6; ++p) {
    const int i = 1 << kPerm[p][0], j = 1 << kPerm[p][1];
    const int b = grid(key_corner(key, i)), c = grid(key_corner(key, i | j));
    if (p < 3)
      tet(leaf, "Kuhn", a, b, c, d);
    else
      tet(leaf, "Kuhn", a, c, b, d);
  }
}

// An empty box: six Kuhn tetrahedra when all six faces are Kuhn faces;
// otherwise its centre coned to the triangles of its faces, a Kuhn face
// cut into two by its diagonal c0–c2, every other face into the squares
// and centre fans of triangulate_box_face (box_faces.hpp).
void BoxAssembler::empty_box(std::int32_t leaf) {
  const BoxKey<3>& key = tree_.key(leaf);
  ++out_.stats.empty;
  bool kuhn[6];
  int count = 0;
  for (int f = 0; f < 6; ++f) count += (kuhn[f] = kuhn_face(key, f / 2, (f % 2) != 0)) ? 1 : 0;
  out_.stats.kuhn_faces += count;
  if (count == 6) {
    kuhn_box(leaf, key);
    ++out_.stats.empty_kuhn;
    return;
  }
  std::vector<GridTriangle> tris;
  for (int f = 0; f < 6; ++f) {
    const int axis = f / 2;
    const bool upper = (f % 2) != 0;
    if (!kuhn[f]) {
      triangulate_box_face(key, axis, upper, corners_, tris);
      continue;
    }
    // (c0, c1, c2) and (c0, c2, c3) have normal +axis; a lower face's
    // outward normal is -axis.
    const std::array<GridPoint, 4> c = face_corners(key, axis, upper);
    if (upper) {
      tris.push_back({c[0], c[1], c[2]});
      tris.push_back({c[0], c[2], c[3]});
    } else {
      tris.push_back({c[0], c[2], c[1]});
      tris.push_back({c[0], c[3], c[2]});
    }
  }
  const int centre = centre_vertex(key_centre(key));
  for (const GridTriangle& t : tris) cone(leaf, {grid(t[0]), grid(t[1]), grid(t[2])}, centre);
}

}  // namespace pqmesh::tet3d
