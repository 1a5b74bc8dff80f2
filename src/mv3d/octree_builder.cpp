// The octree phases of the 3D mesher; see octree_builder.hpp.
#include "mv3d/octree_builder.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "mv3d/united_overlap.hpp"
#include "pqmesh/errors.hpp"

namespace pqmesh::mv3d {

namespace {

// The aligned root (choose_root_cube), or with generic_grid the shifted root
// of choose_generic_root_cube over every input vertex coordinate, offset
// number `shift`.
RootCube<3> root_for(const Domain3& d, bool generic, int shift) {
  const std::array<double, 3> lo{d.bbox_min.x, d.bbox_min.y, d.bbox_min.z};
  const std::array<double, 3> hi{d.bbox_max.x, d.bbox_max.y, d.bbox_max.z};
  if (!generic) return choose_root_cube<3>(lo, hi);
  std::array<std::vector<double>, 3> coords;
  for (auto& c : coords) c.reserve(d.plc.vertices.size());
  for (const Vec3& p : d.plc.vertices) {
    coords[0].push_back(p.x);
    coords[1].push_back(p.y);
    coords[2].push_back(p.z);
  }
  return choose_generic_root_cube<3>(lo, hi, {coords[0], coords[1], coords[2]}, kTreeMaxLevel, shift).root;
}

Vec3 centre_of(const Cube& c) { return 0.5 * (c.lo + c.hi); }

// The component of cc holding facet triangle t (t must meet cc's cube), or
// the component of mark `mark` when t < 0.
int locate(const CubeComponents& cc, int t, std::size_t mark) {
  if (t < 0) return cc.mark_component.at(mark);
  const auto it =
      std::lower_bound(cc.triangle_component.begin(), cc.triangle_component.end(), std::pair<int, int>{t, -1});
  if (it == cc.triangle_component.end() || it->first != t)
    throw InternalError("mv3d octree: a component's triangle does not meet the enclosing box");
  return it->second;
}

bool contains(const std::vector<int>& sorted, int x) { return std::binary_search(sorted.begin(), sorted.end(), x); }

bool share(const std::vector<int>& a, const std::vector<int>& b) {
  for (const int x : a)
    if (contains(b, x)) return true;
  return false;
}

// P ∧ n is the whole closed cube (C_e ⊂ P): no facet triangle meets it.
bool whole_cube(const NodeData3& n) { return n.has_component && n.rep_triangle < 0; }

// P ∩ n (closed cube) is connected, so it is P ∧ n. Children of a cube inside
// P and the shared kInterior record leave cube_single unset; they are whole cubes.
bool connected(const NodeData3& n) { return n.has_component && (n.cube_single || n.rep_triangle < 0); }

// The closed boxes intersect (exact: comparisons of doubles).
bool touch(const Cube& a, const Cube& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y && a.lo.z <= b.hi.z &&
         b.lo.z <= a.hi.z;
}

// Is some facet triangle known to meet both P ∧ a and P ∧ b? Known triangles
// of P ∧ n: its rep_triangle, and when P ∩ n is connected (cube_single) every
// triangle of cube_tris (each meets the closed cube, so lies in its one
// component). A sufficient condition only: false says nothing.
bool share_triangle(const NodeData3& a, const NodeData3& b) {
  if (a.rep_triangle < 0 || b.rep_triangle < 0) return false;  // a whole cube meets no triangle
  if (a.rep_triangle == b.rep_triangle) return true;
  if (a.cube_single && contains(a.cube_tris, b.rep_triangle)) return true;
  if (b.cube_single && contains(b.cube_tris, a.rep_triangle)) return true;
  if (!a.cube_single || !b.cube_single) return false;
  // Both connected: any common triangle of the sorted lists.
  auto i = a.cube_tris.begin();
  auto j = b.cube_tris.begin();
  while (i != a.cube_tris.end() && j != b.cube_tris.end()) {
    if (*i == *j) return true;
    if (*i < *j) ++i;
    else ++j;
  }
  return false;
}

}  // namespace

OctreeBuilder::OctreeBuilder(const Domain3& domain, OctreeOptions options)
    : domain_(domain),
      options_(std::move(options)),
      tree_(root_for(domain, options_.generic_grid, options_.grid_shift)),
      facet_pair_edges_(domain) {
  // The tree must honour RootCube::offset: its root planes are origin + offset.
  // (A Tree without offset support would silently mesh on the aligned grid.)
  for (int a = 0; a < 3; ++a)
    if (tree_.key_plane(tree_.key(0), a, false) != tree_.root().origin[a] + tree_.root().offset[a])
      throw InternalError("mv3d octree: the generic grid needs RootCube::offset support in tree/tree_impl.hpp "
                          "(key_plane ignores the offset)");
  const SizeField3& sf = options_.size_field;
  if (!std::isfinite(options_.max_size) || options_.max_size < 0)
    throw InvalidInput(ErrorCode::Syntax, "max size must be a positive finite number (0: none)", {});
  if (sf.sizes.size() != sf.points.size())
    throw InvalidInput(ErrorCode::Syntax, "size field: " + std::to_string(sf.points.size()) + " points but " +
                                                 std::to_string(sf.sizes.size()) + " sizes",
                       {});
  for (std::size_t i = 0; i < sf.points.size(); ++i) {
    const bool finite = std::isfinite(sf.points[i].x) && std::isfinite(sf.points[i].y) && std::isfinite(sf.points[i].z);
    const bool positive = std::isfinite(sf.sizes[i]) && sf.sizes[i] > 0;
    if (finite && positive) continue;
    const int line = i < sf.lines.size() ? sf.lines[i] : 0;
    std::string where = sf.path.empty() ? "size field" : sf.path;
    if (line > 0) where += ":" + std::to_string(line);
    throw InvalidInput(finite ? ErrorCode::Syntax : ErrorCode::NonFinite,
                       where + ": size field entry " + std::to_string(i) +
                           (finite ? " has a size that is not a positive finite number" : " has a non-finite point"),
                       {static_cast<std::int64_t>(i)}, sf.path, line);
  }
  if (options_.extended_margin != 1 && options_.extended_margin != 2)
    throw InternalError("mv3d octree: extended_margin must be 1 or 2");
  const bool scoped = !options_.separate_edges.empty() || !options_.separate_facets.empty();
  if (scoped && (options_.separate_edges.size() != domain.edges.size() ||
                 options_.separate_facets.size() != domain.plc.facets.size()))
    throw InternalError("mv3d octree: separate_edges / separate_facets need one flag per edge / facet");
  const Cube nowhere{{1, 1, 1}, {0, 0, 0}};
  vertex_box_.assign(domain.plc.vertices.size(), nowhere);
  facet_vertices_.resize(domain.plc.facets.size());
  for (std::size_t f = 0; f < domain.plc.facets.size(); ++f) {
    auto& fv = facet_vertices_[f];
    for (const auto& loop : domain.plc.facets[f].loops) fv.insert(fv.end(), loop.begin(), loop.end());
    std::sort(fv.begin(), fv.end());
    fv.erase(std::unique(fv.begin(), fv.end()), fv.end());
  }
}

void OctreeBuilder::record_phase(std::int32_t node) {
  if (phase_.size() <= static_cast<std::size_t>(node))
    phase_.resize(static_cast<std::size_t>(node) + 1, OctPhase::Root);
  phase_[static_cast<std::size_t>(node)] = current_phase_;
}

OctPhase OctreeBuilder::phase(std::int32_t node) const {
  return static_cast<std::size_t>(node) < phase_.size() ? phase_[static_cast<std::size_t>(node)] : OctPhase::Root;
}

OctPhase OctreeBuilder::protected_by(std::int32_t node) const {
  const auto i = static_cast<std::size_t>(node);
  return i < protected_by_.size() ? protected_by_[i] : OctPhase::Root;
}

// Protects a node not yet protected, recording the step.
void OctreeBuilder::protect(std::int32_t node, OctPhase step) {
  if (tree_.is_protected(node)) return;
  tree_.set_protected(node, true);
  const auto i = static_cast<std::size_t>(node);
  if (protected_by_.size() <= i) protected_by_.resize(i + 1, OctPhase::Root);
  protected_by_[i] = step;
}

bool OctreeBuilder::facet_has_vertex(int facet, int v) const {
  return contains(facet_vertices_[static_cast<std::size_t>(facet)], v);
}

std::vector<std::int32_t> OctreeBuilder::leaves_by_id() const {
  std::vector<std::int32_t> out;
  out.reserve(static_cast<std::size_t>(tree_.leaf_count()));
  for (std::int32_t n = 0; n < tree_.size(); ++n)
    if (tree_.is_leaf(n)) out.push_back(n);
  return out;
}

Cube OctreeBuilder::cube(std::int32_t node) const {
  const auto b = tree_.box(node);
  return {{b.lo[0], b.lo[1], b.lo[2]}, {b.hi[0], b.hi[1], b.hi[2]}};
}

NodeData3& OctreeBuilder::own_data(std::int32_t node) {
  if (tree_.payload(node) == kInterior) {
    tree_.set_payload(node, static_cast<std::int32_t>(data_.size()));
    data_.push_back(data_[kInterior]);
  }
  return data_[static_cast<std::size_t>(tree_.payload(node))];
}

void OctreeBuilder::init_root() {
  tree_.set_payload(0, 0);
  data_.emplace_back();
  data_.emplace_back();  // kInterior: a cube inside P with no faces and no vertex box
  data_[kInterior].has_component = true;
  data_[kInterior].cube_corner0_in = data_[kInterior].ex_corner0_in = true;
  const CubeComponents cc = components(domain_, cube(0));
  if (cc.components.size() != 1)
    throw InternalError("mv3d octree: the root cube meets P in " + std::to_string(cc.components.size()) +
                        " components (P is connected and inside it)");
  NodeData3& d = data_[0];
  d.cube_tris = triangles_meeting(domain_, cube(0));
  d.ex_tris = d.cube_tris;  // P lies in the root cube, so ex(root) meets the same triangles
  d.cube_corner0_in = corner0_in(domain_, cube(0));
  d.ex_corner0_in = corner0_in(domain_, ex_cube(0));
  d.has_component = true;
  d.cube_single = true;
  d.vertices = cc.components[0].vertices;
  d.edges = cc.components[0].edges;
  d.facets = cc.components[0].facets;
  if (!cc.triangle_component.empty()) d.rep_triangle = cc.triangle_component.front().first;
}

// Thesis §4.1.1: "Whenever a box is split, we immediately determine whether any
// of its children contains more than one component of P, and if so, we make
// duplicates of the child box." Children get the components of P ∩ child that
// lie in P ∧ parent: a component with a facet triangle lies in the parent
// component of that triangle; a whole-cube child is located by its centre.
void OctreeBuilder::assign_children(std::int32_t parent, std::int32_t first_child) {
  const NodeData3 pd = data(parent);  // copy: data_ grows below
  const int parent_component = tree_.component(parent);
  const bool interior = pd.has_component && pd.cube_tris.empty();  // the parent cube lies in P
  // Children meeting no facet triangle lie inside P or outside it: their
  // centres are located in the parent's components (marks), which is much
  // cheaper than components() of the child.
  std::vector<CubeComponents> child_cc(OctTree::kChildren);
  std::vector<std::vector<int>> child_tris(OctTree::kChildren);
  std::vector<Vec3> marks;
  std::vector<std::size_t> mark_of(OctTree::kChildren, 0);
  // Corner 0 of each child's shifted cube and extended box, by walks inside
  // the parent's (ex(child) ⊂ ex(parent)): the first child from the parent,
  // then each child from the previous one in Gray-code order (one coordinate
  // differs: one line per step instead of up to three from the parent's corner).
  const Cube pcube = cube(parent), pex = ex_cube(parent);
  std::array<bool, OctTree::kChildren> corner_in{}, ex_corner_in{};
  int prev = -1;
  for (int i = 0; i < OctTree::kChildren; ++i) {
    const int k = i ^ (i >> 1);
    const auto ku = static_cast<std::size_t>(k);
    const Cube from = prev < 0 ? pcube : cube(first_child + prev);
    const Cube ex_from = prev < 0 ? pex : ex_cube(first_child + prev);
    const bool in = prev < 0 ? pd.cube_corner0_in : corner_in[static_cast<std::size_t>(prev)];
    const bool ex_in = prev < 0 ? pd.ex_corner0_in : ex_corner_in[static_cast<std::size_t>(prev)];
    corner_in[ku] = corner0_in_walk(domain_, cube(first_child + k), from, in, pd.cube_tris);
    ex_corner_in[ku] = corner0_in_walk(domain_, ex_cube(first_child + k), ex_from, ex_in, pd.ex_tris);
    prev = k;
  }
  if (!interior && pd.has_component) {
    for (int k = 0; k < OctTree::kChildren; ++k) {
      const auto ku = static_cast<std::size_t>(k);
      const Cube c = cube(first_child + k);
      child_tris[ku] = triangles_meeting(domain_, c, pd.cube_tris);
      if (!child_tris[ku].empty()) {
        child_cc[ku] = components(domain_, c, CubeHint{child_tris[ku], true, corner_in[ku]});
        ++stats_.components_split;
        continue;
      }
      mark_of[ku] = marks.size();
      marks.push_back(centre_of(c));
    }
  }
  // When the parent's cube meets P in one component, every component of a
  // child lies in it, and exact point location places the centres.
  CubeComponents parent_cc;
  if (!interior && pd.has_component) {
    if (pd.cube_single) {
      // A child missing ∂P lies in P iff its corner 0 does.
      parent_cc.components.emplace_back();
      for (int k = 0; k < OctTree::kChildren; ++k)
        if (child_tris[static_cast<std::size_t>(k)].empty())
          parent_cc.mark_component.push_back(corner_in[static_cast<std::size_t>(k)] ? 0 : -1);
    } else {
      parent_cc = components(domain_, pcube, CubeHint{pd.cube_tris, true, pd.cube_corner0_in}, true, marks);
      ++stats_.components_split;
    }
  }
  for (int k = 0; k < OctTree::kChildren; ++k) {
    const auto ku = static_cast<std::size_t>(k);
    if (interior || !pd.has_component || !child_tris[ku].empty()) continue;
    // The child misses ∂P: it is the whole cube (inside P) or misses P.
    if (parent_cc.mark_component[mark_of[ku]] >= 0) {
      child_cc[ku].components.emplace_back();
      child_cc[ku].components.back().whole_cube = true;
    }
  }
  for (int k = 0; k < OctTree::kChildren; ++k) record_phase(first_child + k);
  const bool single_parent = !interior && parent_cc.components.size() == 1;
  for (int k = 0; k < OctTree::kChildren; ++k) {
    const std::int32_t child = first_child + k;
    NodeData3 cd;
    cd.vertex_owner = pd.vertex_owner;
    cd.cube_corner0_in = corner_in[static_cast<std::size_t>(k)];
    cd.ex_corner0_in = ex_corner_in[static_cast<std::size_t>(k)];
    if (!pd.has_component) {  // never split in practice: crowding and balance need a component
      tree_.set_payload(child, static_cast<std::int32_t>(data_.size()));
      data_.push_back(std::move(cd));
      continue;
    }
    const Cube ex = ex_cube(child);
    if (interior) {
      cd.has_component = true;
      if (!pd.ex_tris.empty()) cd.ex_tris = triangles_meeting(domain_, ex, pd.ex_tris);
      if (cd.vertex_owner < 0 && cd.ex_tris.empty()) {  // ex(child) ⊂ P, no vertex box: the shared record
        tree_.set_payload(child, kInterior);
        continue;
      }
      tree_.set_payload(child, static_cast<std::int32_t>(data_.size()));
      data_.push_back(std::move(cd));
      continue;
    }
    cd.cube_tris = std::move(child_tris[static_cast<std::size_t>(k)]);
    cd.ex_tris = triangles_meeting(domain_, ex, pd.ex_tris, cd.cube_tris);  // child ⊂ ex(child)
    const CubeComponents& sc = child_cc[static_cast<std::size_t>(k)];
    std::vector<int> mine, rep;  // components of P ∩ child inside P ∧ parent, and their triangles
    for (std::size_t ci = 0; ci < sc.components.size(); ++ci) {
      int t = -1;
      for (const auto& [tri, comp] : sc.triangle_component)
        if (comp == static_cast<int>(ci)) {
          t = tri;
          break;
        }
      const int pc = single_parent ? 0 : locate(parent_cc, t, mark_of[static_cast<std::size_t>(k)]);
      if (pc == parent_component) {
        mine.push_back(static_cast<int>(ci));
        rep.push_back(t);
      }
    }
    std::int32_t node = child;
    for (std::size_t i = 0; i < std::max<std::size_t>(mine.size(), 1); ++i) {
      if (i > 0) {
        node = tree_.duplicate(child, mine[i]);
        ++stats_.duplicates;
        record_phase(node);
      }
      NodeData3 nd = cd;
      nd.cube_single = sc.components.size() == 1;
      if (!mine.empty()) {
        const ComponentFaces3& f = sc.components[static_cast<std::size_t>(mine[i])];
        nd.has_component = true;
        nd.vertices = f.vertices;
        nd.edges = f.edges;
        nd.facets = f.facets;
        nd.rep_triangle = rep[i];
        tree_.set_component(node, mine[i]);
      }
      tree_.set_payload(node, static_cast<std::int32_t>(data_.size()));
      data_.push_back(std::move(nd));
    }
  }
}

Cube OctreeBuilder::ex_cube(std::int32_t node) const {
  const auto eb = tree_.extended_box(node, options_.extended_margin);
  return Cube{{eb.lo[0], eb.lo[1], eb.lo[2]}, {eb.hi[0], eb.hi[1], eb.hi[2]}};
}

CubeComponents OctreeBuilder::extended_components(std::int32_t node, std::span<const Vec3> marks) const {
  const NodeData3& d = data(node);
  return components(domain_, ex_cube(node), CubeHint{d.ex_tris, true, d.ex_corner0_in}, true, marks);
}

int OctreeBuilder::component_in(std::int32_t node, const CubeComponents& ex) const {
  const int c = locate(ex, data(node).rep_triangle, 0);
  if (c < 0) throw InternalError("mv3d octree: a box's component is in no component of an enclosing box");
  return c;
}

// Thesis §4.1.1: b1, b2 are balance-adjacent iff (P ∧ ex(b1)) ∩ (P ∧ b2) or
// (P ∧ ex(b2)) ∩ (P ∧ b1) is non-empty. For neighbours with h(big) >= h(small),
// ex(small) ⊂ ex(big), so this holds iff P ∧ small ⊂ P ∧ ex(big).
bool OctreeBuilder::balance_adjacent(std::int32_t big, std::int32_t small) const {
  const NodeData3& db = data(big);
  const NodeData3& ds = data(small);
  if (!db.has_component || !ds.has_component) return false;
  if (db.ex_tris.empty()) return true;  // ex(big) lies in P: one component
  // A facet triangle meeting both P ∧ big and P ∧ small meets the shifted
  // ex(big) (it holds both shifted cubes) in one convex piece, which lies in
  // one component of P ∩ ex(big): the two share it. No components() needed.
  if (share_triangle(db, ds)) return true;
  // One of the two is a whole cube inside P and the other meets P in one
  // component: a point common to both closed cubes lies in P, hence in both
  // P ∧ big and P ∧ small, which therefore touch inside ex(big).
  if (((whole_cube(db) && connected(ds)) || (connected(db) && whole_cube(ds))) && touch(cube(big), cube(small)))
    return true;
  const CubeComponents& cached = cached_extended(big);
  // P ∩ ex(big) connected: it holds P ∧ small (small ⊂ ex(big)).
  if (cached.components.size() == 1) return true;
  if (ds.rep_triangle >= 0) return locate(cached, ds.rep_triangle, 0) == component_in(big, cached);
  // Marks only for whole-cube components: their centres are off ∂P (a box
  // meeting ∂P may have its centre on it).
  std::vector<Vec3> marks;
  if (db.rep_triangle < 0) marks.push_back(centre_of(cube(big)));
  const std::size_t small_mark = marks.size();
  if (ds.rep_triangle < 0) marks.push_back(centre_of(cube(small)));
  const CubeComponents ex = extended_components(big, marks);
  ++stats_.components_adjacency;
  const int cb = locate(ex, db.rep_triangle, 0);
  const int cs = locate(ex, ds.rep_triangle, small_mark);
  if (cb < 0) throw InternalError("mv3d octree: a box's component is in no component of its extended box");
  return cs == cb;
}

const CubeComponents& OctreeBuilder::cached_extended(std::int32_t node) const {
  if (ex_cache_.size() <= static_cast<std::size_t>(node)) ex_cache_.resize(static_cast<std::size_t>(node) + 1);
  auto& slot = ex_cache_[static_cast<std::size_t>(node)];
  if (!slot) {
    const Vec3 mark = centre_of(cube(node));  // used only when P ∧ node is the whole cube
    const std::span<const Vec3> marks =
        data(node).rep_triangle >= 0 ? std::span<const Vec3>() : std::span<const Vec3>(&mark, 1);
    slot = std::make_unique<CubeComponents>(extended_components(node, marks));
    ++stats_.components_extended;
  }
  return *slot;
}

ExtendedFaces3 OctreeBuilder::extended_faces(std::int32_t node) const {
  const NodeData3& d = data(node);
  if (d.ex_tris.empty()) return {};
  const CubeComponents& ex = cached_extended(node);
  const ComponentFaces3& f = ex.components[static_cast<std::size_t>(component_in(node, ex))];
  return {f.vertices, f.edges, f.facets};
}

std::int32_t OctreeBuilder::split_and_balance(std::int32_t node, OctPhase which) {
  const std::int32_t before = tree_.size();
  current_phase_ = which;
  assign_children(node, tree_.split(node));
  std::vector<std::int32_t> fresh;
  for (std::int32_t id = before; id < tree_.size(); ++id)
    if (tree_.is_leaf(id)) fresh.push_back(id);
  balance(fresh);
  return before;
}

void OctreeBuilder::balance(std::span<const std::int32_t> seeds) {
  const OctPhase saved = current_phase_;
  current_phase_ = OctPhase::Balance;
  stats_.splits_balance += tree_.balance(
      seeds, [this](std::int32_t big, std::int32_t small) { return balance_adjacent(big, small); },
      // Tree::split throws InternalError below max_level(): refinement cannot run away silently.
      [this](std::int32_t n, std::int32_t first) { assign_children(n, first); });
  current_phase_ = saved;
}

// f(x) = min(max_size, min_i s_i + |x - p_i|) has its minimum over the cube
// where each term does: at the point of the cube nearest p_i.
double OctreeBuilder::size_over(const Cube& c) const {
  double best = options_.max_size > 0 ? options_.max_size : std::numeric_limits<double>::infinity();
  const SizeField3& f = options_.size_field;
  for (std::size_t i = 0; i < f.points.size(); ++i) {
    const Vec3 p = f.points[i];
    const double dx = std::max({c.lo.x - p.x, 0.0, p.x - c.hi.x});
    const double dy = std::max({c.lo.y - p.y, 0.0, p.y - c.hi.y});
    const double dz = std::max({c.lo.z - p.z, 0.0, p.z - c.hi.z});
    best = std::min(best, f.sizes[i] + std::sqrt(dx * dx + dy * dy + dz * dz));
  }
  return best;
}

// Thesis §1.1: a box meeting P is split while it is larger than the size
// function asks anywhere in it (phase 0, before the vertex phase, so later
// phases only refine further and protection never blocks it).
bool OctreeBuilder::size_crowded(std::int32_t node) const {
  if (options_.max_size <= 0 && options_.size_field.points.empty()) return false;
  return tree_.side(node) > size_over(cube(node));
}

// The crowding tests below ask whether some face of P ∧ ex(b) interferes.
// face_bounds brackets the faces of P ∧ ex(b) between those of the sheet
// holding rep_triangle (a part of P ∧ ex(b)) and those of every triangle
// meeting ex(b): the rule's answer on the two bounds decides it when they
// agree; only the rest computes (and caches) the components of P ∩ ex(b).
// A cached result is used directly.
template <class Rule>
bool OctreeBuilder::extended_interferes(std::int32_t node, const Rule& rule) const {
  const NodeData3& d = data(node);
  const bool cached = static_cast<std::size_t>(node) < ex_cache_.size() && ex_cache_[static_cast<std::size_t>(node)];
  if (!cached && !d.ex_tris.empty() && d.rep_triangle >= 0) {
    const FaceBounds fb = face_bounds(domain_, ex_cube(node), d.ex_tris, d.rep_triangle);
    if (!rule(fb.all)) return false;
    if (rule(fb.sheet)) return true;
  }
  return rule(extended_faces(node));
}

// Thesis §4.1.3 "Vertex crowded": b holds a P vertex v and P ∧ ex(b) has a face
// that interferes with v (is not v nor a superface of v).
bool OctreeBuilder::vertex_crowded(std::int32_t node) const {
  const NodeData3& d = data(node);
  if (d.vertices.empty()) return false;
  if (d.vertices.size() > 1) return true;
  const int v = d.vertices[0];
  return extended_interferes(node, [&](const auto& ex) {
    if (ex.vertices.size() > 1) return true;
    for (const int e : ex.edges) {
      const DomainEdge& de = domain_.edges[static_cast<std::size_t>(e)];
      if (de.a != v && de.b != v) return true;
    }
    for (const int f : ex.facets)
      if (!facet_has_vertex(f, v)) return true;
    return false;
  });
}

// Thesis §4.1.4 "Edge crowded": b (unprotected, no vertex, outside every united
// vertex box) holds an edge e, and a face G of P ∧ ex(b) other than e and its
// two superfacets interferes. Vertices are ignored (§4.1.4). Like the 2D edge
// rule (docs/algorithm/quad2d.md "What the tree guarantees"), a G that shares a
// vertex with e interferes only if it meets P ∧ b itself, or, for a facet, a
// balance-adjacent box (see neighbour_would_be_of_no_kind); the thesis instead
// removes the protected vertex boxes from ex(b), which we do not construct.
bool OctreeBuilder::edge_crowded(std::int32_t node) const {
  if (tree_.is_protected(node)) return false;
  const NodeData3& d = data(node);
  if (!d.vertices.empty() || d.edges.empty() || d.vertex_owner >= 0) return false;
  // Two edges in P ∧ b interfere with each other: both lie in P ∧ ex(b), and
  // one sharing a vertex with the other meets P ∧ b itself.
  if (d.edges.size() > 1) return true;
  const DomainEdge& e = domain_.edges[static_cast<std::size_t>(d.edges[0])];
  return extended_interferes(node, [&](const auto& ex) {
    for (const int g : ex.edges) {
      if (g == d.edges[0]) continue;
      const DomainEdge& ge = domain_.edges[static_cast<std::size_t>(g)];
      const bool shares = ge.a == e.a || ge.a == e.b || ge.b == e.a || ge.b == e.b;
      if (!shares) return true;
    }
    for (const int f : ex.facets) {
      if (f == e.facets[0] || f == e.facets[1]) continue;
      const bool shares = facet_has_vertex(f, e.a) || facet_has_vertex(f, e.b);
      if (!shares || contains(d.facets, f)) return true;
    }
    return false;
  }) || neighbour_would_be_of_no_kind(node, e);
}

// The part of §4.1.4's rule that our edge rule above leaves out: a facet f of
// an endpoint w of e may meet ex(b) outside w's united box without meeting
// P ∧ b. The thesis then splits b; we split it only when f lies in a box that
// §4.1.7 step 7 would protect with b and that would then be of no kind of
// leaf_kind.hpp: an unshielded leaf, balance-adjacent to b, holding no vertex
// and no edge, and facets other than e's that are neither one facet nor the
// two facets of one edge (harsh seed 9: f beside e's two facets, three facets
// of w's cone). The boxes protected with b descend from b and its present
// neighbours (splits only shrink them, and balance-adjacency of two boxes
// implies that of their ancestors), so the test made now still holds when b
// is protected. It terminates: outside w's united box, f and e are a positive
// distance apart (they meet only at w, Lemma 1).
bool OctreeBuilder::neighbour_would_be_of_no_kind(std::int32_t node, const DomainEdge& e) const {
  const auto one_edge_pair = [&](const std::vector<int>& fs) {
    return fs.size() == 2 && facet_pair_edges_.edge_between(fs[0], fs[1]) >= 0;
  };
  std::vector<std::int32_t> near;
  tree_.neighbours(node, near);
  for (const std::int32_t m : near) {
    const NodeData3& dm = data(m);
    if (!tree_.is_leaf(m) || !dm.has_component || shielded(m) || !dm.vertices.empty() || !dm.edges.empty()) continue;
    const bool other = std::any_of(dm.facets.begin(), dm.facets.end(),
                                   [&](int f) { return f != e.facets[0] && f != e.facets[1]; });
    if (!other || dm.facets.size() == 1 || one_edge_pair(dm.facets)) continue;
    if (tree_.level(m) <= tree_.level(node) ? balance_adjacent(m, node) : balance_adjacent(node, m)) return true;
  }
  return false;
}

// Thesis §4.1.5 "Facet crowded": b (unprotected: no vertex, no edge, outside
// every united vertex box — boxes holding edges are the protected edge boxes)
// holds a facet f, and another facet g lies in P ∧ ex(b). As for edges, a g
// sharing a vertex with f interferes only if it meets P ∧ b itself.
bool OctreeBuilder::facet_crowded(std::int32_t node) const {
  if (tree_.is_protected(node)) return false;
  const NodeData3& d = data(node);
  if (!d.vertices.empty() || !d.edges.empty() || d.facets.empty() || d.vertex_owner >= 0) return false;
  if (d.facets.size() > 1) return true;
  const int f = d.facets[0];
  return extended_interferes(node, [&](const auto& ex) {
    for (const int g : ex.facets) {
      if (g == f) continue;
      if (!share(facet_vertices_[static_cast<std::size_t>(f)], facet_vertices_[static_cast<std::size_t>(g)]))
        return true;
    }
    return false;
  });
}

void OctreeBuilder::run_phase(OctPhase which, bool (OctreeBuilder::*crowded)(std::int32_t) const) {
  std::vector<std::int32_t> work = leaves_by_id();
  std::int64_t& counter = which == OctPhase::Vertex ? stats_.splits_vertex
                          : which == OctPhase::Edge ? stats_.splits_edge
                          : which == OctPhase::Size ? stats_.splits_size
                                                    : stats_.splits_facet;
  for (std::size_t next = 0; next < work.size(); ++next) {
    const std::int32_t n = work[next];
    if (!tree_.is_leaf(n) || !data(n).has_component || !(this->*crowded)(n)) continue;
    if (tree_.level(n) >= tree_.max_level())
      throw InternalError("mv3d octree: refinement reached the deepest representable level (phase " +
                          std::to_string(static_cast<int>(which)) + ")");
    if (which == OctPhase::Edge && data(n).edges.size() > 1) ++stats_.splits_edge_two_edges;
    const std::int32_t before = split_and_balance(n, which);
    ++counter;
    for (std::int32_t id = before; id < tree_.size(); ++id)
      if (tree_.is_leaf(id)) work.push_back(id);
  }
}

// §4.1.3 "The vertex centering step", as in 2D (quadtree_builder.cpp): part 1
// splits the larger balance-adjacent boxes of each vertex box; part 2 records
// the 2x2x2 block B whose centre is the grid corner nearest v (v is then at
// least h(b)/2 from every facet of B, Lemma 1), protects the leaf holding v and
// marks the leaves of v's component inside B with vertex_owner.
void OctreeBuilder::center_vertices() {
  const auto& pv = domain_.plc.vertices;
  const std::vector<std::int32_t> vertex_leaf = vertex_leaves();
  std::vector<std::int32_t> big;
  for (std::size_t v = 0; v < pv.size(); ++v) {
    const std::int32_t b = vertex_leaf[v];
    if (b < 0) continue;
    // Margin 1: only the larger leaves (with a component) reaching into the
    // united block, so that its eight cells are leaves no larger than b
    // (find_united_intruders); b's other larger neighbours stay, at most
    // twice b's side by balance. The thesis's rule (margin 2) splits every
    // larger balance-adjacent box; measured on curved tessellated surfaces,
    // the narrower rule saves 3 to 12% of the leaves
    // (docs/MEASUREMENTS.md "Real parts").
    const GridBlock block = united_grid_block(tree_.key(b), united_below(b, static_cast<int>(v)));
    const bool margin1 = options_.extended_margin == 1;
    for (bool again = true; again;) {
      again = false;
      tree_.larger_neighbours(b, big);
      for (const std::int32_t n : big) {
        if (!tree_.is_leaf(n) || tree_.is_protected(n)) continue;
        const bool in_block = data(n).has_component && meets_block(tree_.key(n), block);
        if (margin1 ? !in_block : !balance_adjacent(n, b)) continue;
        split_and_balance(n, OctPhase::Centering);
        ++stats_.splits_centering;
        again = true;
      }
      if (!tree_.is_leaf(b)) throw InternalError("mv3d octree: a vertex box was split during centering");
    }
    const Cube s = cube(b);
    const double h = tree_.side(b);
    const unsigned below = united_below(b, static_cast<int>(v));
    const double x0 = (below & 1u) ? s.lo.x - h : s.lo.x;
    const double y0 = (below & 2u) ? s.lo.y - h : s.lo.y;
    const double z0 = (below & 4u) ? s.lo.z - h : s.lo.z;
    vertex_box_[v] = {{x0, y0, z0}, {x0 + 2 * h, y0 + 2 * h, z0 + 2 * h}};
    ++stats_.vertex_boxes;
    protect(b, OctPhase::Centering);
  }
  std::vector<std::int32_t> found, cell;
  for (std::size_t v = 0; v < pv.size(); ++v) {
    const std::int32_t b = vertex_leaf[v];
    if (b < 0) continue;
    const Cube& r = vertex_box_[v];
    const double h = tree_.side(b);
    // The leaves holding the centres of B's eight cells; margin 1: every leaf
    // meeting B (deeper leaves in a corner of a cell included).
    found.clear();
    if (options_.extended_margin == 1) found = leaves_in_block(b, static_cast<int>(v));
    for (int k = 0; k < 8 && options_.extended_margin != 1; ++k) {
      tree_.leaves_containing(
          {r.lo.x + (0.5 + (k & 1)) * h, r.lo.y + (0.5 + ((k >> 1) & 1)) * h, r.lo.z + (0.5 + (k >> 2)) * h}, cell);
      found.insert(found.end(), cell.begin(), cell.end());
    }
    for (const std::int32_t n : found) {
      const Cube s = cube(n);
      const bool inside = s.lo.x >= r.lo.x && s.lo.y >= r.lo.y && s.lo.z >= r.lo.z && s.hi.x <= r.hi.x &&
                          s.hi.y <= r.hi.y && s.hi.z <= r.hi.z;
      if (!inside || !data(n).has_component || (n != b && !balance_adjacent(b, n))) continue;
      const int owner = data(n).vertex_owner;
      if (owner >= 0 && owner != static_cast<int>(v)) united_clashes_.push_back({n, owner, static_cast<int>(v)});
      own_data(n).vertex_owner = static_cast<int>(v);
    }
  }
}

std::vector<std::int32_t> OctreeBuilder::vertex_leaves() const {
  std::vector<std::int32_t> vertex_leaf(domain_.plc.vertices.size(), -1);
  for (const std::int32_t n : leaves_by_id())
    for (const int v : data(n).vertices) vertex_leaf[static_cast<std::size_t>(v)] = n;
  return vertex_leaf;
}

// Lemma 1: the block's centre is the grid corner nearest v, per axis the
// lower one when v lies below the middle of leaf b.
unsigned OctreeBuilder::united_below(std::int32_t b, int v) const {
  const Cube s = cube(b);
  const double h = tree_.side(b);
  const Vec3 p = domain_.plc.vertices[static_cast<std::size_t>(v)];
  return (p.x < s.lo.x + 0.5 * h ? 1u : 0u) | (p.y < s.lo.y + 0.5 * h ? 2u : 0u) | (p.z < s.lo.z + 0.5 * h ? 4u : 0u);
}

// With extended boxes of margin 1 two vertices may end two leaves apart, and
// the united blocks centering would record for them overlap
// (united_overlap.hpp). Until none do: split the leaves holding the vertices
// of the overlapping blocks (phase Vertex) and run the vertex phase again.
void OctreeBuilder::separate_united_boxes() {
  for (;;) {
    const std::vector<std::int32_t> vertex_leaf = vertex_leaves();
    std::vector<GridBlock> blocks;
    std::vector<std::int32_t> leaf_of_block;
    for (std::size_t v = 0; v < vertex_leaf.size(); ++v) {
      const std::int32_t b = vertex_leaf[v];
      if (b < 0) continue;
      blocks.push_back(united_grid_block(tree_.key(b), united_below(b, static_cast<int>(v))));
      leaf_of_block.push_back(b);
    }
    const std::vector<std::size_t> hits = overlapping_blocks(blocks);
    if (hits.empty()) return;
    for (const std::size_t i : hits) {
      const std::int32_t n = leaf_of_block[i];
      if (!tree_.is_leaf(n)) continue;  // split meanwhile by balancing
      if (tree_.level(n) >= tree_.max_level())
        throw InternalError("mv3d octree: refinement reached the deepest representable level (united boxes)");
      split_and_balance(n, OctPhase::Vertex);
      ++stats_.splits_united;
    }
    run_phase(OctPhase::Vertex, &OctreeBuilder::vertex_crowded);
  }
}

bool OctreeBuilder::shielded(std::int32_t node) const {
  return tree_.is_protected(node) || data(node).vertex_owner >= 0;
}

// §4.1.4 "we begin by splitting every unprotected box containing a P edge and
// its balance-adjacent boxes" (§4.1.5 the same for facets), or only the boxes
// of the edges (facets) OctreeOptions::separate_edges (separate_facets) names.
// The set is fixed before any of them is split, so that every box is split at
// most once.
std::vector<std::int32_t> OctreeBuilder::separation_set(bool facets) const {
  const std::vector<char>& only = facets ? options_.separate_facets : options_.separate_edges;
  const bool every = options_.separate_edges.empty() && options_.separate_facets.empty();
  const auto starts = [&](const NodeData3& d) {  // holds a face the options separate
    const std::vector<int>& faces = facets ? d.facets : d.edges;
    if (every) return !faces.empty();
    return std::any_of(faces.begin(), faces.end(), [&](int f) { return only[static_cast<std::size_t>(f)] != 0; });
  };
  std::vector<std::int32_t> out, near;
  for (const std::int32_t n : leaves_by_id()) {
    const NodeData3& d = data(n);
    if (!d.has_component || shielded(n) || !starts(d)) continue;
    out.push_back(n);
    tree_.neighbours(n, near);
    for (const std::int32_t m : near) {
      if (!tree_.is_leaf(m) || !data(m).has_component || shielded(m)) continue;
      if (tree_.level(m) <= tree_.level(n) ? balance_adjacent(m, n) : balance_adjacent(n, m)) out.push_back(m);
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// §4.1.7 steps 6 and 9: split each box of the separation set once (balance
// restored after each split). A box split meanwhile by balancing is no longer
// a leaf and is skipped: its children are not split again. Afterwards a box
// (other than a protected one) balance-adjacent to a box holding an edge E
// (facet F) is balance-adjacent to no box holding another edge (facet) (§4.1.4).
void OctreeBuilder::separate(OctPhase which) {
  std::int64_t& counter = which == OctPhase::EdgeSeparate ? stats_.splits_edge_separate : stats_.splits_facet_separate;
  for (const std::int32_t n : separation_set(which == OctPhase::FacetSeparate)) {
    if (!tree_.is_leaf(n)) continue;
    if (tree_.level(n) >= tree_.max_level())
      throw InternalError("mv3d octree: a separating split reached the deepest representable level");
    split_and_balance(n, which);
    ++counter;
  }
}

// §4.1.4 "Protecting edge cone boxes": every box containing a P edge, and
// every box balance-adjacent to one, is protected (never split again). Without
// it the facet phase would split the boxes along an edge with a small dihedral
// angle through the balance condition without end. §4.1.5: the same for facet
// boxes after the facet phase ("for the sake of consistent terminology"; no
// split follows).
void OctreeBuilder::protect_boxes(bool facets) {
  std::vector<std::int32_t> near;
  for (const std::int32_t n : leaves_by_id()) {
    const NodeData3& d = data(n);
    if (!d.has_component || (facets ? d.facets.empty() : d.edges.empty())) continue;
    const OctPhase step = facets ? OctPhase::Facet : OctPhase::Edge;
    protect(n, step);
    tree_.neighbours(n, near);
    for (const std::int32_t m : near) {
      const bool adjacent = tree_.level(m) <= tree_.level(n) ? balance_adjacent(m, n) : balance_adjacent(n, m);
      if (adjacent) protect(m, step);
    }
  }
}

void OctreeBuilder::build() {
  init_root();
  int phase = 0;
  auto t0 = std::chrono::steady_clock::now();
  const auto done = [&] {  // per-phase time and leaf count (OctreeStats)
    const auto t1 = std::chrono::steady_clock::now();
    stats_.phase_seconds[phase] = std::chrono::duration<double>(t1 - t0).count();
    stats_.phase_leaves[phase] = tree_.leaf_count();
    ++phase;
    t0 = t1;
  };
  run_phase(OctPhase::Size, &OctreeBuilder::size_crowded);
  done();
  run_phase(OctPhase::Vertex, &OctreeBuilder::vertex_crowded);
  if (options_.extended_margin == 1) separate_united_boxes();
  done();
  center_vertices();
  done();
  run_phase(OctPhase::Edge, &OctreeBuilder::edge_crowded);
  done();
  if (options_.separate) separate(OctPhase::EdgeSeparate);
  done();
  protect_boxes(false);
  done();
  run_phase(OctPhase::Facet, &OctreeBuilder::facet_crowded);
  done();
  if (options_.separate) separate(OctPhase::FacetSeparate);
  done();
  protect_boxes(true);
  if (options_.extended_margin == 1) find_united_intruders();
  done();
  for (const std::int32_t n : leaves_by_id()) {
    ++stats_.leaves;
    if (!data(n).has_component) ++stats_.outside_leaves;
  }
}

}  // namespace pqmesh::mv3d
