// The quadtree phases of the 2D mesher; see quadtree_builder.hpp and
// docs/algorithm/quad2d.md.
#include "quad2d/quadtree_builder.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "pqmesh/errors.hpp"

namespace pqmesh::quad2d {

namespace {

RootCube<2> root_for(const Domain2& d) {
  return choose_root_cube<2>({d.bbox_min.x, d.bbox_min.y}, {d.bbox_max.x, d.bbox_max.y});
}

std::vector<LoopEdge> all_loop_edges(const Domain2& d) {
  std::vector<LoopEdge> out;
  for (std::size_t l = 0; l < d.loops.size(); ++l)
    for (std::size_t k = 0; k < d.loops[l].size(); ++k) out.push_back({static_cast<int>(l), static_cast<int>(k)});
  return out;
}

// The vertex two segments share, or -1.
int shared_vertex(const std::array<int, 2>& s, const std::array<int, 2>& t) {
  if (s[0] == t[0] || s[0] == t[1]) return s[0];
  if (s[1] == t[0] || s[1] == t[1]) return s[1];
  return -1;
}

}  // namespace

QuadtreeBuilder::QuadtreeBuilder(const Domain2& domain, const SizeFunction2& size, bool protect_edges,
                                 QuadMeshStats& stats)
    : domain_(domain), size_(size), stats_(stats), tree_(root_for(domain)), protect_edges_(protect_edges) {
  const Vec2 nowhere_lo{1, 1}, nowhere_hi{0, 0};  // lo > hi: empty
  vertex_box_.assign(domain.pslg.vertices.size(), Rect{nowhere_lo, nowhere_hi});
  segment_edge_.assign(domain.pslg.segments.size(), LoopEdge{});
  for (std::size_t l = 0; l < domain.loop_segments.size(); ++l)
    for (std::size_t k = 0; k < domain.loop_segments[l].size(); ++k)
      segment_edge_[static_cast<std::size_t>(domain.loop_segments[l][k])] = {static_cast<int>(l), static_cast<int>(k)};
}

std::vector<std::int32_t> QuadtreeBuilder::leaves_by_id() const {
  std::vector<std::int32_t> out;
  out.reserve(static_cast<std::size_t>(tree_.leaf_count()));
  for (std::int32_t n = 0; n < tree_.size(); ++n)
    if (tree_.is_leaf(n)) out.push_back(n);
  return out;
}

std::vector<std::int32_t> QuadtreeBuilder::recorded_leaves() const {
  std::vector<std::int32_t> out;
  for (std::size_t r = 0; r < record_node_.size(); ++r) {
    const std::int32_t n = record_node_[r];
    if (n >= 0 && tree_.is_leaf(n) && tree_.payload(n) == static_cast<std::int32_t>(r)) out.push_back(n);
  }
  std::sort(out.begin(), out.end());  // records of older nodes come later (own_data)
  return out;
}

Square QuadtreeBuilder::square(std::int32_t node) const {
  const auto b = tree_.box(node);
  return {{b.lo[0], b.lo[1]}, b.hi[0] - b.lo[0]};
}

SquareComponents QuadtreeBuilder::components_of(std::int32_t node) const {
  const NodeData& d = data(node);
  if (d.square_edges.empty()) {
    // No P edge meets the square: it lies inside P (it has a component) or outside.
    SquareComponents sc;
    sc.square = square(node);
    if (d.has_component) {
      sc.components.emplace_back();
      sc.components.back().whole_square = true;
    }
    return sc;
  }
  return components(domain_, square(node), d.square_edges);
}

NodeData& QuadtreeBuilder::own_data(std::int32_t node) {
  if (tree_.payload(node) == kInterior) {
    tree_.set_payload(node, static_cast<std::int32_t>(data_.size()));
    data_.push_back(data_[kInterior]);
    record_node_.push_back(node);
  }
  return data_[static_cast<std::size_t>(tree_.payload(node))];
}

void QuadtreeBuilder::init_root() {
  tree_.set_payload(0, 0);
  data_.emplace_back();
  data_.emplace_back();  // kInterior: a square inside P with no faces and no vertex box
  record_node_ = {0, -1};
  data_[kInterior].has_component = true;
  data_[0].square_edges = all_loop_edges(domain_);
  data_[0].ex_edges = data_[0].square_edges;
  const SquareComponents sc = components(domain_, square(0), data_[0].square_edges);
  if (sc.components.size() != 1)
    throw InternalError("quad2d: the root square meets P in " + std::to_string(sc.components.size()) +
                        " components (P is connected and inside it)");
  data_[0].has_component = true;
  data_[0].vertices = sc.components[0].vertices;
  data_[0].segments = sc.components[0].edges;
}

void QuadtreeBuilder::assign_children(std::int32_t parent, std::int32_t first_child) {
  const NodeData pd = data(parent);  // copy: data_ grows below
  const int parent_component = tree_.component(parent);
  const bool interior = pd.square_edges.empty();  // the parent square lies in P
  SquareComponents parent_sc;
  if (!interior) parent_sc = components_of(parent);
  for (int k = 0; k < QuadTree::kChildren; ++k) {
    const std::int32_t child = first_child + k;
    const Square sq = square(child);
    NodeData cd;
    cd.vertex_owner = pd.vertex_owner;
    if (interior) {
      cd.has_component = true;
      if (cd.vertex_owner < 0) {
        tree_.set_payload(child, kInterior);
        continue;
      }
      tree_.set_payload(child, static_cast<std::int32_t>(data_.size()));
      data_.push_back(std::move(cd));
      record_node_.push_back(child);
      continue;
    }
    cd.square_edges = edges_meeting(domain_, sq, pd.square_edges);
    cd.ex_edges = edges_meeting(domain_, extended(sq), pd.ex_edges);
    const SquareComponents sc = components(domain_, sq, cd.square_edges, &parent_sc);
    std::vector<int> mine;  // components of P ∩ child inside P ∧ parent
    for (std::size_t c = 0; c < sc.components.size(); ++c)
      if (containing_component(domain_, parent_sc, sc, sc.components[c]) == parent_component)
        mine.push_back(static_cast<int>(c));
    std::int32_t node = child;
    for (std::size_t i = 0; i < std::max<std::size_t>(mine.size(), 1); ++i) {
      if (i > 0) {
        node = tree_.duplicate(child, mine[i]);
        ++stats_.duplicates;
      }
      NodeData nd = cd;
      if (!mine.empty()) {
        const ComponentFaces& f = sc.components[static_cast<std::size_t>(mine[i])];
        nd.has_component = true;
        nd.vertices = f.vertices;
        nd.segments = f.edges;
        tree_.set_component(node, mine[i]);
      }
      tree_.set_payload(node, static_cast<std::int32_t>(data_.size()));
      data_.push_back(std::move(nd));
      record_node_.push_back(node);
    }
  }
}

std::int32_t QuadtreeBuilder::split(std::int32_t node) {
  const std::int32_t first = tree_.split(node);
  assign_children(node, first);
  return first;
}

// Thesis §4.1.1: b1, b2 are balance-adjacent iff (P ∧ ex(b1)) ∩ (P ∧ b2) or
// (P ∧ ex(b2)) ∩ (P ∧ b1) is non-empty. For neighbours big, small with
// h(big) >= 2 h(small), ex(small) ⊂ ex(big), so the second condition implies the
// first, which holds iff P ∧ small lies in the component P ∧ ex(big).
bool QuadtreeBuilder::balance_adjacent(std::int32_t big, std::int32_t small) const {
  const NodeData& db = data(big);
  const NodeData& ds = data(small);
  if (!db.has_component || !ds.has_component) return false;
  if (db.ex_edges.empty()) return true;  // ex(big) lies in P: one component
  const SquareComponents ex = components(domain_, extended(square(big)), db.ex_edges);
  const int big_in_ex = extended_component(big, ex);
  const SquareComponents small_sc = components_of(small);
  return containing_component(domain_, ex, small_sc,
                              small_sc.components[static_cast<std::size_t>(tree_.component(small))]) == big_in_ex;
}

int QuadtreeBuilder::extended_component(std::int32_t node, const SquareComponents& ex) const {
  const SquareComponents sc = components_of(node);
  const int c = containing_component(domain_, ex, sc, sc.components[static_cast<std::size_t>(tree_.component(node))]);
  if (c < 0) throw InternalError("quad2d: a box's component is in no component of its extended box");
  return c;
}

ExtendedFaces QuadtreeBuilder::extended_faces(std::int32_t node) const {
  const NodeData& d = data(node);
  if (d.ex_edges.empty()) return {};
  const SquareComponents ex = components(domain_, extended(square(node)), d.ex_edges);
  const ComponentFaces& f = ex.components[static_cast<std::size_t>(extended_component(node, ex))];
  return {f.vertices, f.edges};
}

std::int32_t QuadtreeBuilder::split_and_balance(std::int32_t node) {
  const std::int32_t before = tree_.size();
  split(node);
  std::vector<std::int32_t> fresh;
  for (std::int32_t id = before; id < tree_.size(); ++id)
    if (tree_.is_leaf(id)) fresh.push_back(id);
  balance(fresh);
  return before;
}

void QuadtreeBuilder::balance(std::span<const std::int32_t> seeds) {
  stats_.splits_balance += tree_.balance(
      seeds, [this](std::int32_t big, std::int32_t small) { return balance_adjacent(big, small); },
      [this](std::int32_t n, std::int32_t first) { assign_children(n, first); });
}

bool QuadtreeBuilder::size_crowded(std::int32_t node) const {
  return size_.active() && data(node).has_component && tree_.side(node) > size_.min_over(square(node));
}

// Thesis §4.1.3 "Vertex crowded": b holds a P vertex v and P ∧ ex(b) has a face
// that is not v or one of its superfaces (another vertex, or an edge not ending at v).
bool QuadtreeBuilder::vertex_crowded(std::int32_t node) const {
  const NodeData& d = data(node);
  if (d.vertices.empty()) return false;
  if (d.vertices.size() > 1) return true;
  const int v = d.vertices[0];
  const ExtendedFaces ex = extended_faces(node);
  if (ex.vertices.size() > 1) return true;
  for (const int s : ex.segments) {
    const auto& seg = domain_.pslg.segments[static_cast<std::size_t>(s)];
    if (seg[0] != v && seg[1] != v) return true;
  }
  return false;
}

// The 2D analog of "facet crowded" (§4.1.5, with §4.1.4's rule that extended
// boxes of this phase do not extend into protected boxes): b (unprotected, no
// vertex) holds an edge e, and another edge e' interferes with it:
//   * e' shares no vertex with e and lies in P ∧ ex(b) (the thesis' rule);
//   * e' shares the vertex v with e and meets the closed square of b itself
//     outside the open protected box of v.
// The second rule is our deviation (docs/algorithm/quad2d.md "What the tree
// guarantees"): the thesis measures it in ex(b) minus the protected boxes, which
// splits the boxes next to a vertex box down to about 1/8 of the distance between e
// and e' there (for a right angle: boxes 1/16 of the vertex box), and the triangles
// that join those small boxes to the vertex are needlessly thin. Measured in b, the
// boxes along e at distance rho from v end at a size proportional to rho sin(theta)
// (theta the angle between e and e'), which is the grading the angle needs and
// still a constant times alpha times the vertex box (Lemma 2-5's form). The faces
// of P ∧ ex(b) come from the whole extended box, which can only add faces (more
// splitting, never less).
bool QuadtreeBuilder::edge_crowded(std::int32_t node) const {
  if (tree_.is_protected(node)) return false;
  const NodeData& d = data(node);
  if (!d.vertices.empty() || d.segments.empty() || d.vertex_owner >= 0) return false;
  const ExtendedFaces ex = extended_faces(node);
  const Square sq = square(node);
  const Rect own{sq.lo, {sq.lo.x + sq.side, sq.lo.y + sq.side}};
  for (const int other : ex.segments) {
    const auto& so = domain_.pslg.segments[static_cast<std::size_t>(other)];
    for (const int mine : d.segments) {
      if (mine == other) continue;
      const int v = shared_vertex(domain_.pslg.segments[static_cast<std::size_t>(mine)], so);
      if (v < 0) return true;
      const Vec2 a = domain_.pslg.vertices[static_cast<std::size_t>(so[0])];
      const Vec2 c = domain_.pslg.vertices[static_cast<std::size_t>(so[1])];
      if (segment_meets_rect_outside(a, c, own, vertex_box(v))) return true;
    }
  }
  return false;
}

// With a global size cap h, the size phase alone leaves boxes of side at most
// h over all of P: about area(P) / s^2 leaves for s the largest power-of-two
// fraction of the root side that is <= h, and a third more inner nodes.
// Reserving that much up front spares the tree's key index its rehashing as
// it grows (a capacity hint: the tree is the same without it).
void QuadtreeBuilder::reserve_for_size_phase() {
  const double h = size_.max_size();
  if (!(h > 0)) return;
  const double root = tree_.side(0);
  if (!(h < root)) return;
  const double s = std::ldexp(root, -static_cast<int>(std::ceil(std::log2(root / h))));
  const double nodes = std::min(4.0 / 3.0 * domain_.area / (s * s), 0x1p26);
  if (nodes > 1024) tree_.reserve(static_cast<std::int32_t>(nodes));
}

void QuadtreeBuilder::run_phase(Phase phase, bool (QuadtreeBuilder::*crowded)(std::int32_t) const) {
  // A leaf sharing the kInterior record has no vertex and no edge, so it is
  // neither vertex nor edge crowded: those phases start from the leaves with
  // records of their own, in the same (id) order, and split exactly the boxes
  // the full list would have split.
  std::vector<std::int32_t> work = phase == Phase::Size ? leaves_by_id() : recorded_leaves();
  std::int64_t& counter = phase == Phase::Size     ? stats_.splits_size
                          : phase == Phase::Vertex ? stats_.splits_vertex
                                                   : stats_.splits_edge;
  // The size phase under a uniform cap needs no balancing: the work list is
  // first in, first out and starts from the leaves of the root, so when a
  // leaf of level L is split every leaf with a component has level L or L + 1
  // (all of level L are crowded alike, and those of level L + 1 were made by
  // this phase); the children, of level L + 1, are then at most twice smaller
  // than any box they can be balance-adjacent to (both need a component), and
  // balance() would split nothing. Skipping it leaves the tree and its ids
  // exactly as they were.
  const bool balance_free = phase == Phase::Size && size_.uniform() && work.size() == 1;
  // Splits insert keys at random places of the tree's key index (a cache miss
  // each); a hint a few work items ahead overlaps those misses with the work in
  // between. It changes nothing in the tree.
  constexpr std::size_t kPrefetchAhead = 32;
  for (std::size_t next = 0; next < work.size(); ++next) {
    if (next + kPrefetchAhead < work.size()) {
      const std::int32_t m = work[next + kPrefetchAhead];
      if (tree_.is_leaf(m) && data(m).has_component) tree_.prefetch_split(m);
    }
    const std::int32_t n = work[next];
    if (!tree_.is_leaf(n) || !data(n).has_component || !(this->*crowded)(n)) continue;
    if (tree_.level(n) >= tree_.max_level())
      throw InternalError("quad2d: refinement reached the deepest representable level (phase " +
                          std::to_string(static_cast<int>(phase)) + ")");
    const std::int32_t before = balance_free ? tree_.size() : split_and_balance(n);
    if (balance_free) split(n);
    ++counter;
    for (std::int32_t id = before; id < tree_.size(); ++id)
      if (tree_.is_leaf(id)) work.push_back(id);
  }
}

// §4.1.3 "The vertex centering step". Part 1: split the balance-adjacent boxes
// twice the size of each vertex box (and rebalance). Part 2: the thesis unites b
// with the three boxes of the 2x2 block whose centre is the grid corner nearest
// the vertex, so that the vertex is at least h(b)/2 from the sides of the united
// box B (Lemma 1). We record B as the vertex's protected box and protect the
// leaves of the vertex's component inside it instead of uniting them in the
// tree (docs/algorithm/quad2d.md says why); the mesh sees the united box: no
// grid corner strictly inside B becomes a mesh vertex.
void QuadtreeBuilder::center_vertices() {
  const auto& pv = domain_.pslg.vertices;
  std::vector<std::int32_t> vertex_leaf(pv.size(), -1);
  for (const std::int32_t n : recorded_leaves())  // id order: only these hold vertices
    for (const int v : data(n).vertices) vertex_leaf[static_cast<std::size_t>(v)] = n;
  std::vector<std::int32_t> big;
  for (std::size_t v = 0; v < pv.size(); ++v) {
    std::int32_t b = vertex_leaf[v];
    if (b < 0) continue;
    // Part 1 (may have to be repeated: a split can create duplicates).
    for (bool again = true; again;) {
      again = false;
      tree_.larger_neighbours(b, big);
      for (const std::int32_t n : big) {
        if (!tree_.is_leaf(n) || tree_.is_protected(n) || !balance_adjacent(n, b)) continue;
        split_and_balance(n);
        ++stats_.splits_centering;
        again = true;
      }
      if (!tree_.is_leaf(b)) throw InternalError("quad2d: a vertex box was split during centering");
    }
    // Part 2: the 2x2 block around the grid corner nearest v.
    const Square s = square(b);
    const double h = s.side;
    const Vec2 p = pv[v];
    const double x0 = p.x < s.lo.x + 0.5 * h ? s.lo.x - h : s.lo.x;
    const double y0 = p.y < s.lo.y + 0.5 * h ? s.lo.y - h : s.lo.y;
    vertex_box_[v] = {{x0, y0}, {x0 + 2 * h, y0 + 2 * h}};
    ++stats_.vertex_boxes;
    ++stats_.centered;
    tree_.set_protected(b, true);
  }
  // Mark the leaves inside each vertex box whose component is connected to the
  // vertex's within ex(b) (the leaves the thesis unites into B). Only b, the
  // leaf holding the vertex, is protected; the other three may be split by the
  // balance condition (their descendants keep the mark), which grades the
  // united box towards small outside neighbours instead of leaving one large
  // box with a finely divided boundary (docs/algorithm/quad2d.md "Phases"). The
  // mesh still sees Lemma 1: no mesh vertex within h(b)/2 of the vertex
  // (mesh_points.cpp).
  std::vector<std::int32_t> found;
  for (std::size_t v = 0; v < pv.size(); ++v) {
    const std::int32_t b = vertex_leaf[v];
    if (b < 0) continue;
    const Rect& r = vertex_box_[v];
    const double h = tree_.side(b);
    for (int k = 0; k < 4; ++k) {
      tree_.leaves_containing({r.lo.x + (0.5 + (k & 1)) * h, r.lo.y + (0.5 + (k >> 1)) * h}, found);
      for (const std::int32_t n : found) {
        const Square s = square(n);
        const bool inside_box = s.lo.x >= r.lo.x && s.lo.y >= r.lo.y && s.lo.x + s.side <= r.hi.x &&
                                s.lo.y + s.side <= r.hi.y;
        if (inside_box && data(n).has_component && (n == b || balance_adjacent(b, n))) {
          own_data(n).vertex_owner = static_cast<int>(v);
        }
      }
    }
  }
}

// The 2D analog of facet protection (§4.1.5): every unprotected box on an edge
// is split once, the balance condition restored, and the boxes on edges are
// protected (exempt from later splitting).
void QuadtreeBuilder::protect_edges() {
  std::vector<std::int32_t> targets;  // leaves on an edge have records of their own
  for (const std::int32_t n : recorded_leaves())
    if (data(n).has_component && !data(n).segments.empty() && !tree_.is_protected(n)) targets.push_back(n);
  for (const std::int32_t n : targets) {
    if (!tree_.is_leaf(n)) continue;
    split_and_balance(n);
    ++stats_.splits_protection;
  }
  for (const std::int32_t n : recorded_leaves())
    if (data(n).has_component && !data(n).segments.empty()) tree_.set_protected(n, true);
}

void QuadtreeBuilder::build() {
  init_root();
  reserve_for_size_phase();
  if (size_.active()) run_phase(Phase::Size, &QuadtreeBuilder::size_crowded);
  run_phase(Phase::Vertex, &QuadtreeBuilder::vertex_crowded);
  center_vertices();
  run_phase(Phase::Edge, &QuadtreeBuilder::edge_crowded);
  if (protect_edges_) protect_edges();
  stats_.leaves += tree_.leaf_count();
  for (const std::int32_t n : recorded_leaves())  // kInterior leaves have a component
    if (!data(n).has_component) ++stats_.outside_leaves;
}

}  // namespace pqmesh::quad2d
