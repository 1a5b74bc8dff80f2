#include "tet3d/squares/box_faces.hpp"

#include <algorithm>

#include "pqmesh/errors.hpp"
#include "tet3d/boxes/box_jobs.hpp"
#include "tet3d/facet_boxes.hpp"

namespace pqmesh::tet3d {

namespace {

// Every leaf, also those missing P: the nesting argument of box_faces.hpp
// needs the corners of all leaves tiling a split cell (a leaf outside P may be
// the one with the square's centre as its corner; with only the leaves meeting
// P, the two sides of a face could cut it into different squares).
std::vector<std::int32_t> all_leaves(const mv3d::OctreeBuilder& builder) { return builder.leaves_by_id(); }

}  // namespace

// Also the 27 lattice points of every united vertex box B (§4.1.3): B is
// 2x2x2 cells of its leaf's size, but a cell may lie inside a larger leaf of
// another component (or of none) — the far side of a narrow slot at its mouth
// (box_jobs.hpp) — so some of B's cell corners are no leaf corner. Without
// them a square of that larger leaf whose centre is B's corner stays whole,
// and the centre is then also a ring point of B's squares (warping threw
// "a square centre is a ring point" on a slot of half-width 0.027,
// slot_square_centre_test.cpp). With them every
// corner of a job's face square (leaf face or B face) is in the set, and so
// is every split point; a final square's centre is not (box_faces.hpp
// subdivision), hence never a ring point. The set stays global, so both
// sides of every square still split it alike.
CornerSet::CornerSet(const mv3d::OctreeBuilder& builder) : CornerSet(builder.tree(), all_leaves(builder)) {
  const OctTree& tree = builder.tree();
  for (const std::int32_t n : builder.leaves_by_id()) {
    const mv3d::NodeData3& d = builder.data(n);
    const int v = d.vertex_owner;
    if (!d.has_component || v < 0 || !std::binary_search(d.vertices.begin(), d.vertices.end(), v)) continue;
    const BoxKey<3>& key = tree.key(n);
    const GridPoint lo = united_lo(key, united_block(builder, n, v));
    for (int k = 0; k < 27; ++k) {
      GridPoint p = lo;
      p.f[0] += (k % 3) * key.fine_side();
      p.f[1] += (k / 3 % 3) * key.fine_side();
      p.f[2] += (k / 9) * key.fine_side();
      add(p, key.level);
    }
  }
}

CornerSet::CornerSet(const OctTree& tree, std::span<const std::int32_t> leaves) {
  for (const std::int32_t n : leaves) {
    const BoxKey<3>& key = tree.key(n);
    if (!key.aligned()) throw InternalError("tet3d: merged (unaligned) leaf " + std::to_string(n));
    for (int k = 0; k < 8; ++k) add(key_corner(key, k), key.level);
  }
}

void CornerSet::add(const GridPoint& p, std::int32_t level) {
  const auto [id, fresh] = index_.insert(p);
  if (fresh) {
    levels_.push_back(level);
  } else {
    std::int32_t& deepest = levels_[static_cast<std::size_t>(id)];
    deepest = std::max(deepest, level);
  }
}

namespace {

// Appends the split points strictly between a and b (an axis-parallel segment
// of `length` fine units), in order from a to b.
void split_edge(const GridPoint& a, const GridPoint& b, int axis, std::int64_t length, const CornerSet& corners,
                std::vector<GridPoint>& out) {
  if (length < 2) return;
  GridPoint m = a;
  m.f[axis] += (b.f[axis] > a.f[axis] ? 1 : -1) * (length / 2);
  if (!corners.contains(m)) return;
  split_edge(a, m, axis, length / 2, corners, out);
  out.push_back(m);
  split_edge(m, b, axis, length / 2, corners, out);
}

void collect_squares(FaceSquare s, const CornerSet& corners, std::vector<FaceSquare>& out) {
  if (s.side >= 4 && corners.contains(s.centre())) {
    const std::int64_t half = s.side / 2;
    for (int k = 0; k < 4; ++k) {
      FaceSquare sub = s;
      sub.side = half;
      sub.lo.f[s.u] += (k & 1) ? half : 0;
      sub.lo.f[s.v] += (k & 2) ? half : 0;
      collect_squares(sub, corners, out);
    }
    return;
  }
  out.push_back(s);
}

}  // namespace

void split_square(const FaceSquare& s, const CornerSet& corners, std::vector<FaceSquare>& out) {
  collect_squares(s, corners, out);
}

void face_squares(const BoxKey<3>& key, int axis, bool upper, const CornerSet& corners, std::vector<FaceSquare>& out) {
  if (!key.aligned()) throw InternalError("tet3d: face_squares on a merged (unaligned) key");
  if (axis < 0 || axis > 2) throw InternalError("tet3d: bad face axis");
  FaceSquare s;
  s.n = axis;
  s.u = (axis + 1) % 3;
  s.v = (axis + 2) % 3;
  s.upper = upper;
  s.lo = key_corner(key, 0);
  if (upper) s.lo.f[axis] += key.fine_side();
  s.side = key.fine_side();
  collect_squares(s, corners, out);
}

void square_ring(const FaceSquare& s, const CornerSet& corners, std::vector<GridPoint>& ring) {
  // Corners counter-clockwise seen from +n: (0,0), (1,0), (1,1), (0,1) in (u, v).
  std::array<GridPoint, 4> c{s.lo, s.lo, s.lo, s.lo};
  c[1].f[s.u] += s.side;
  c[2].f[s.u] += s.side;
  c[2].f[s.v] += s.side;
  c[3].f[s.v] += s.side;
  ring.clear();
  for (int i = 0; i < 4; ++i) {
    ring.push_back(c[i]);
    split_edge(c[i], c[(i + 1) % 4], (i % 2 == 0) ? s.u : s.v, s.side, corners, ring);
  }
}

std::vector<GridPoint> square_ring(const FaceSquare& s, const CornerSet& corners) {
  std::vector<GridPoint> ring;
  ring.reserve(8);  // one allocation for the usual ring (4 corners, up to one split point a side)
  square_ring(s, corners, ring);
  return ring;
}

void triangulate_box_face(const BoxKey<3>& key, int axis, bool upper, const CornerSet& corners,
                          std::vector<GridTriangle>& out) {
  // Scratch kept per thread across calls (every empty box triangulates its
  // six faces here; fresh vectors cost four allocations a face). Nothing
  // survives a call but the capacity: both are cleared before use.
  thread_local std::vector<FaceSquare> squares;
  thread_local std::vector<GridPoint> ring;
  squares.clear();
  face_squares(key, axis, upper, corners, squares);
  for (const FaceSquare& sq : squares) {
    const GridPoint centre = sq.centre();
    square_ring(sq, corners, ring);
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const GridPoint& p = ring[i];
      const GridPoint& q = ring[(i + 1) % ring.size()];
      // (centre, p, q) has normal +n; the lower face's outward normal is -n.
      out.push_back(sq.upper ? GridTriangle{centre, p, q} : GridTriangle{centre, q, p});
    }
  }
}

}  // namespace pqmesh::tet3d
