#include "improve3d/collapse_check.hpp"

#include <algorithm>
#include <cstddef>
#include <utility>

#include "predicates/predicates.hpp"

namespace pqmesh::improve3d::detail {

namespace {

template <std::size_t K>
bool holds(const std::array<int, K>& element, int x) {
  return std::find(element.begin(), element.end(), x) != element.end();
}

}  // namespace

Collapser::Collapser(CollapseMesh& mesh, const VertexClasses& classes, const SizeBound& size, QualityLimits limits,
                     TetrahedronQualityMemo& memo)
    : mesh_(mesh), classes_(classes), size_(size), limits_(limits), memo_(memo) {
  const std::size_t n = static_cast<std::size_t>(mesh.vertex_count());
  for (auto* marks : {&near_u_, &ring_, &near_v_, &boundary_near_u_, &boundary_ring_}) marks->assign(n, 0);
}

bool Collapser::refuse(Refusal why) {
  ++refusals_[static_cast<std::size_t>(why)];
  last_refusal_ = why;
  return false;
}

// Sets x's mark to the current stamp; returns whether it was not set yet.
bool Collapser::mark(std::vector<std::uint32_t>& marks, int x) const {
  std::uint32_t& m = marks[static_cast<std::size_t>(x)];
  if (m == stamp_) return false;
  m = stamp_;
  return true;
}

bool Collapser::marked(const std::vector<std::uint32_t>& marks, int x) const {
  return marks[static_cast<std::size_t>(x)] == stamp_;
}

bool Collapser::try_collapse(int u, int v) {
  if (++stamp_ == 0) {  // wrapped: clear every mark so no old mark equals a new stamp
    for (auto* marks : {&near_u_, &ring_, &near_v_, &boundary_near_u_, &boundary_ring_})
      std::fill(marks->begin(), marks->end(), 0);
    stamp_ = 1;
  }
  // The same edge the other way: the gathered lists swap roles.
  if (u_tets_.owner == v || v_tets_.owner == u) std::swap(u_tets_, v_tets_);
  if (u_faces_.owner == v || v_faces_.owner == u) std::swap(u_faces_, v_faces_);
  u_ = u;
  v_ = v;
  if (!class_allows()) return refuse(Refusal::Class);
  if (!split_u()) return refuse(Refusal::NoEdge);
  if (!new_edges_within_uniform_size()) return refuse(Refusal::Size);
  if (!moved_positive()) return refuse(Refusal::Orientation);
  if (!one_region()) return refuse(Refusal::Region);
  split_v();
  if (!link_condition()) return refuse(Refusal::Link);
  split_faces();
  if (!boundary_allows()) return refuse(Refusal::Boundary);
  if (!within_size()) return refuse(Refusal::Size);
  if (!quality_allows()) return refuse(Refusal::Quality);
  list_new_neighbours();
  mesh_.apply({u_, v_, dying_, moving_, new_aspect_, new_dihedral_, dying_faces_, moving_faces_});
  forget();
  return true;
}

// Rule 1 without the boundary triangles (edge_vertex_moves_along_edge has the
// rest): u is no input vertex and facets(u) lies in facets(v); a vertex on an
// input edge goes to an input vertex or to a vertex on the same edge.
bool Collapser::class_allows() const {
  const VertexClass cu = classes_.of(u_);
  if (cu == VertexClass::Input || !classes_.facets_within(u_, v_)) return false;
  if (cu != VertexClass::Edge) return true;
  return classes_.of(v_) == VertexClass::Input || classes_.same_facets(u_, v_);
}

// The live tetrahedra (faces: boundary triangles) of x into g, walked only
// when g does not hold them yet: a refused collapse changes nothing, so the
// lists of the edge tried the other way just before are still exact.
void Collapser::gather_tets(Gathered& g, int x) {
  if (g.owner == x) return;
  g.owner = x;
  g.list.clear();
  mesh_.tets_of(x, g.list);
}

void Collapser::gather_faces(Gathered& g, int x) {
  if (g.owner == x) return;
  g.owner = x;
  g.list.clear();
  mesh_.faces_of(x, g.list);
}

// The star of u into dying and moving; false when no tetrahedron holds both
// u and v (the edge is gone).
bool Collapser::split_u() {
  gather_tets(u_tets_, u_);
  dying_.clear();
  moving_.clear();
  for (const int t : u_tets_.list) (holds(mesh_.tet(t), v_) ? dying_ : moving_).push_back(t);
  return !dying_.empty();
}

void Collapser::split_v() {
  gather_tets(v_tets_, v_);
  resting_.clear();
  for (const int t : v_tets_.list)
    if (!holds(mesh_.tet(t), u_)) resting_.push_back(t);
}

void Collapser::split_faces() {
  gather_faces(u_faces_, u_);
  gather_faces(v_faces_, v_);
  for (auto* list : {&dying_faces_, &moving_faces_, &resting_faces_}) list->clear();
  for (const int f : u_faces_.list) (holds(mesh_.face(f), v_) ? dying_faces_ : moving_faces_).push_back(f);
  for (const int f : v_faces_.list)
    if (!holds(mesh_.face(f), u_)) resting_faces_.push_back(f);
}

// Tetrahedra keep their region: re-pointing u's tetrahedra to v moves the
// region boundary unless the star of u lies in one region.
bool Collapser::one_region() const {
  if (mesh_.one_region()) return true;
  const int marker = mesh_.tet_marker(u_tets_.list.front());
  return std::all_of(u_tets_.list.begin(), u_tets_.list.end(), [&](int t) { return mesh_.tet_marker(t) == marker; });
}

bool Collapser::link_condition() { return vertex_links_agree() && edge_links_agree(); }

// Lk(u) and Lk(v) share no vertex outside Lk(uv) (the ring); the virtual
// vertex is virtual_vertex_links_agree's.
bool Collapser::vertex_links_agree() {
  near_u_list_.clear();
  for (const int t : u_tets_.list)
    for (const int x : mesh_.tet(t))
      if (x != u_ && mark(near_u_, x)) near_u_list_.push_back(x);
  ring_edges_.clear();
  for (const int t : dying_) {
    std::array<int, 2> edge{};
    std::size_t n = 0;
    for (const int x : mesh_.tet(t))
      if (x != u_ && x != v_) {
        mark(ring_, x);
        edge[n++] = x;
      }
    ring_edges_.push_back(std::minmax(edge[0], edge[1]));
  }
  for (const int t : resting_)
    for (const int x : mesh_.tet(t)) {
      if (x == v_ || !mark(near_v_, x)) continue;
      if (marked(near_u_, x) && !marked(ring_, x)) return false;
    }
  return true;
}

// An edge ab of Lk(u) and of Lk(v) is an edge of Lk(uv): if a moving
// tetrahedron (u a b .) and a resting one (v a b .) exist, a dying one
// (u v a b) does, that is ab is a ring edge. Both ends are then in Lk(u) and
// Lk(v), hence (after vertex_links_agree) in the ring, which filters the
// candidates; ring edges are looked up first (most candidates are ring edges).
bool Collapser::edge_links_agree() const {
  for (const int t : resting_) {
    std::array<int, 3> in_ring{};
    std::size_t n = 0;
    for (const int x : mesh_.tet(t))
      if (x != v_ && marked(ring_, x)) in_ring[n++] = x;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j)
        if (!ring_edge_or_outside_lk_u(in_ring[i], in_ring[j])) return false;
  }
  return true;
}

// ab is a ring edge, or no moving tetrahedron holds a and b.
bool Collapser::ring_edge_or_outside_lk_u(int a, int b) const {
  if (std::find(ring_edges_.begin(), ring_edges_.end(), std::pair<int, int>(std::minmax(a, b))) != ring_edges_.end())
    return true;
  return std::none_of(moving_.begin(), moving_.end(),
                      [&](int m) { return holds(mesh_.tet(m), a) && holds(mesh_.tet(m), b); });
}

bool Collapser::boundary_allows() {
  return virtual_vertex_links_agree() && edge_vertex_moves_along_edge() && no_duplicate_face();
}

// The link condition at the virtual vertex w joined to every boundary
// triangle: w is in Lk(u) and Lk(v) when both are boundary vertices, and then
// in Lk(uv) only when uv is a boundary edge; an edge xw is in Lk(u) and Lk(v)
// when ux and vx are boundary edges, and then in Lk(uv) only when uvx is a
// boundary triangle.
bool Collapser::virtual_vertex_links_agree() {
  if (u_faces_.list.empty()) return true;
  if (!v_faces_.list.empty() && dying_faces_.empty()) return false;
  for (const int f : u_faces_.list)
    for (const int x : mesh_.face(f))
      if (x != u_) mark(boundary_near_u_, x);
  for (const int f : dying_faces_)
    for (const int x : mesh_.face(f))
      if (x != u_ && x != v_) mark(boundary_ring_, x);
  for (const int f : resting_faces_)
    for (const int x : mesh_.face(f))
      if (x != v_ && marked(boundary_near_u_, x) && !marked(boundary_ring_, x)) return false;
  return true;
}

// A vertex on an input edge collapses along it: every facet of u has a
// boundary triangle on uv (the dying triangles lie on facets of u, as all of
// u's do). For u inside a facet, dying triangles exist after
// virtual_vertex_links_agree and all lie on its one facet.
bool Collapser::edge_vertex_moves_along_edge() const {
  if (classes_.of(u_) != VertexClass::Edge) return true;
  const auto on_uv = [&](int facet) {
    return std::any_of(dying_faces_.begin(), dying_faces_.end(), [&](int f) { return mesh_.face_facet(f) == facet; });
  };
  const auto facets = classes_.facets_of(u_);
  return std::all_of(facets.begin(), facets.end(), on_uv);
}

// A moving boundary triangle (u a b) becomes (v a b), which must not exist yet.
bool Collapser::no_duplicate_face() const {
  for (const int f : moving_faces_) {
    const auto& k = mesh_.face(f);
    for (const int g : resting_faces_) {
      const auto& h = mesh_.face(g);
      bool same = true;
      for (const int x : k) same = same && (x == u_ || holds(h, x));
      if (same) return false;
    }
  }
  return true;
}

// Rule 5: every moved tetrahedron within the bound.
bool Collapser::within_size() const {
  if (!size_.bounded()) return true;
  for (const int t : moving_) {
    const auto k = moved(t);
    if (!size_.allows({mesh_.point(k[0]), mesh_.point(k[1]), mesh_.point(k[2]), mesh_.point(k[3])})) return false;
  }
  return true;
}

// Rule 5 early, for a uniform bound (size_bound.hpp): no new edge vx (x a
// vertex of a moving tetrahedron) longer than the bound. Cheaper than the
// orientation and link tests it precedes; refuses only collapses that
// within_size() refuses too, so the decisions do not change.
bool Collapser::new_edges_within_uniform_size() const {
  if (!size_.bounded() || !size_.uniform()) return true;
  const double bound = size_.longest_edge_bound();
  const Vec3 pv = mesh_.point(v_);
  for (const int t : moving_)
    for (const int x : mesh_.tet(t))
      if (x != u_ && !(norm(pv - mesh_.point(x)) <= bound)) return false;
  return true;
}

// x becomes a neighbour of v by the collapse (vertex_links_agree has marked
// the neighbours of u and of v and the ring).
bool Collapser::is_new_neighbour(int x) const { return x != v_ && !marked(near_v_, x) && !marked(ring_, x); }

void Collapser::list_new_neighbours() {
  new_neighbours_.clear();
  for (const int x : near_u_list_)
    if (is_new_neighbour(x)) new_neighbours_.push_back(x);
}

std::array<int, 4> Collapser::moved(int t) const {
  std::array<int, 4> k = mesh_.tet(t);
  for (int& x : k)
    if (x == u_) x = v_;
  return k;
}

// Rule 3: exact orientation of every moved tetrahedron.
bool Collapser::moved_positive() const {
  for (const int t : moving_) {
    const auto k = moved(t);
    if (orient3d(mesh_.point(k[0]), mesh_.point(k[1]), mesh_.point(k[2]), mesh_.point(k[3])) != Sign::Positive)
      return false;
  }
  return true;
}

// Rules 4 and 6 (improve.hpp): the new region (resting and moved tetrahedra)
// stays within min(cap, max(old region worst, target)); the old region is the
// tetrahedra of u and v. When the old region is within target, every moved
// tetrahedron's minimum dihedral angle is at least min(limits_.min_dihedral,
// the old region's least). NaN never passes (the comparisons fail).
bool Collapser::quality_allows() {
  double old_worst = 0, resting_worst = 0, old_least = 180;
  for (const int t : u_tets_.list) {
    old_worst = std::max(old_worst, mesh_.aspect(t));
    old_least = std::min(old_least, mesh_.dihedral(t));
  }
  for (const int t : resting_) {
    resting_worst = std::max(resting_worst, mesh_.aspect(t));
    old_least = std::min(old_least, mesh_.dihedral(t));
  }
  old_worst = std::max(old_worst, resting_worst);
  const double limit = std::min(limits_.cap, std::max(old_worst, limits_.target));
  const double floor = old_worst > limits_.target ? 0 : std::min(limits_.min_dihedral, old_least);
  if (!(resting_worst <= limit)) return false;
  new_aspect_.clear();
  new_dihedral_.clear();
  for (const int t : moving_) {
    const auto k = moved(t);
    const TetQuality q = memo_(mesh_.point(k[0]), mesh_.point(k[1]), mesh_.point(k[2]), mesh_.point(k[3]));
    if (!(q.aspect_ratio <= limit) || !(q.min_dihedral_deg >= floor)) return false;
    new_aspect_.push_back(q.aspect_ratio);
    new_dihedral_.push_back(q.min_dihedral_deg);
  }
  return true;
}

}  // namespace pqmesh::improve3d::detail
