// Phase 3 of constrained_delaunay() (keep_inside): which triangles lie on the
// inside of the constraint loops.
//
// Every constrained piece a -> b has an inside triangle on its left and an
// outside triangle on its right. The fill starts from all left triangles and
// crosses only non-constraint edges. A valid loop set (interior on the left
// of every loop) never lets the fill reach a right triangle or a ghost
// triangle; either event means the loops are inconsistent and throws. A
// constraint given in both directions is an interior edge (inside on both
// sides).
#include <algorithm>
#include <string>

#include "cdt2d/triangulation.hpp"
#include "pqmesh/errors.hpp"

namespace pqmesh::cdt2d::detail {

std::vector<std::uint8_t> Triangulation::inside_triangles() const {
  enum : std::uint8_t { kUnknown = 0, kInside = 1, kOutside = 2 };
  std::vector<std::uint8_t> label;
  label.reserve(tris_.capacity());  // becomes inside_ of a refinement (triangulation.hpp)
  label.assign(tris_.size(), kUnknown);
  std::vector<int> stack;
  auto piece_name = [](const std::array<int, 2>& pc) { return std::to_string(pc[0]) + "->" + std::to_string(pc[1]); };
  // A piece given in both directions has the inside on both sides (an
  // interior constraint edge): its right side is no outside seed.
  auto key = [](int a, int b) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
  };
  std::vector<std::uint64_t> keys;
  keys.reserve(pieces_.size());
  for (const auto& pc : pieces_) keys.push_back(key(pc[0], pc[1]));
  std::sort(keys.begin(), keys.end());
  for (const auto& pc : pieces_) {
    const int h = find_half_edge(pc[0], pc[1]);
    if (h < 0) throw InternalError("constrained_delaunay: constraint piece " + piece_name(pc) + " is no edge");
    if (std::binary_search(keys.begin(), keys.end(), key(pc[1], pc[0]))) continue;
    label[tri_of(tris_[tri_of(h)].n[edge_of(h)])] = kOutside;
  }
  for (const auto& pc : pieces_) {
    const int t = tri_of(find_half_edge(pc[0], pc[1]));
    if (is_ghost(t))
      throw InternalError("constrained_delaunay: hull edge " + piece_name(pc) + " has the unbounded side on its left");
    if (label[t] == kOutside)
      throw InternalError("constrained_delaunay: triangle " + std::to_string(t) +
                          " lies on both sides of constraints (" + piece_name(pc) + ")");
    if (label[t] == kInside) continue;
    label[t] = kInside;
    stack.push_back(t);
    while (!stack.empty()) {
      const int s = stack.back();
      stack.pop_back();
      const unsigned bits = cons_[s];  // there are pieces, so cons_ is set up
      for (int e = 0; e < 3; ++e) {
        if ((bits >> e) & 1u) continue;  // constrained edge
        const int nb = tri_of(tris_[s].n[e]);
        if (label[nb] == kInside) continue;
        if (label[nb] == kOutside)
          throw InternalError("constrained_delaunay: inside flood fill from " + piece_name(pc) +
                              " reached a triangle on the right of a constraint");
        if (is_ghost(nb))
          throw InternalError("constrained_delaunay: inside flood fill from " + piece_name(pc) +
                              " left the convex hull (loops not closed)");
        label[nb] = kInside;
        stack.push_back(nb);
      }
    }
  }
  for (auto& l : label) l = l == kInside ? 1 : 0;
  return label;
}

}  // namespace pqmesh::cdt2d::detail
