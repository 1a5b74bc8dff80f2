#pragma once
// Private to the triangle-mesh checker: the state shared by its stages and the
// exact helpers they use. The argument that the stages suffice is the comment
// block at the top of check2d.cpp (and, in full, check3d.cpp).
//
//   check2d.cpp           entry points and the stage driver
//   check2d_topology.cpp  stages 1-3: indices, orientation, edge matching,
//                         hanging vertices, boundary curves, listed edges
//   check2d_domain.cpp    stage 4: input vertices, segment walks, boundary
//                         against the loops, Steiner points, locate()
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <vector>

#include "mesh/check_common.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/mesh.hpp"
#include "pqmesh/vec.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::detail::check2d {

inline bool in_box(Vec2 p, Vec2 a, Vec2 b) {
  return p.x >= std::min(a.x, b.x) && p.x <= std::max(a.x, b.x) && p.y >= std::min(a.y, b.y) &&
         p.y <= std::max(a.y, b.y);
}

// p on the closed segment ab (exact).
inline bool on_segment(Vec2 p, Vec2 a, Vec2 b) { return in_box(p, a, b) && orient2d(a, b, p) == Sign::Zero; }

// Rounded Steiner points on slanted segments: see within_ulp_of_segment in
// src/predicates/predicates.hpp and docs/algorithm/quality.md "The validity
// checker".
inline bool near_segment(Vec2 p, Vec2 a, Vec2 b) { return within_ulp_of_segment(p, a, b); }

// A hash of a point's exact coordinates: equal points (also with -0 against
// +0) hash equally. It only places points in hash tables, whose lookups then
// compare coordinates exactly; no decision depends on its value.
inline std::uint64_t coordinate_hash(Vec2 p) {
  auto mix = [](std::uint64_t h) {
    h ^= h >> 31;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 29;
    h *= 0x94D049BB133111EBull;
    return h ^ (h >> 32);
  };
  return mix(mix(std::bit_cast<std::uint64_t>(p.x + 0.0)) ^ std::bit_cast<std::uint64_t>(p.y + 0.0));  // -0 + 0 = +0
}

class Checker2 {
 public:
  Checker2(const TriMesh2& mesh, const CheckOptions& options, CheckReport& report);

  // Stages 1-3 (stage 2 also measures the area); returns whether stage 3 is clean.
  bool run_topology();
  // Stage 4, the Volume comparison and locate(); `topology_ok` is what
  // run_topology returned.
  void run_domain(const Domain2& d, bool topology_ok);

 private:
  // check2d_topology.cpp
  bool stage1_indices();
  bool stage2_orientation();  // and the area, when every triangle is positive
  bool stage3_edges();
  bool check_boundary_manifold();
  void find_hanging_vertices();
  void check_listed_edges();

  // check2d_domain.cpp
  void map_input_vertices(const Domain2& d);
  void walk_segments(const Domain2& d);
  void check_boundary_chain(const Domain2& d);
  void check_steiner();
  void check_located(const Domain2& d);

  const TriMesh2& m_;
  const CheckOptions& opt_;
  CheckReport& rep_;
  IssueSink sink_;
  bool stage1_ok_ = false;
  // The vertex ids by coordinates (sort_by_coordinates), computed only when
  // two vertices coincide (a hash table finds out, check2d.cpp): then the
  // coincident groups are reported in that order and input vertices are
  // looked up in it. Otherwise every point is one vertex, found by a scan.
  bool coincident_ = false;
  std::vector<int> order_;
  std::vector<std::array<int, 2>> boundary_;  // directed, triangle on the left
  std::vector<int> boundary_tri_;
  Adjacency adjacency_, boundary_adjacency_;  // adjacency_: every mesh edge, lists sorted
  std::vector<int> in2mesh_, mesh2in_;
  std::vector<int> chain_offset_, chain_items_;
  std::vector<char> segment_ok_;
};

}  // namespace pqmesh::detail::check2d
