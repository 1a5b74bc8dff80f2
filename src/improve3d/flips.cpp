#include "improve3d/flips.hpp"

#include <algorithm>
#include <cstddef>
#include <utility>

#include "improve3d/smooth.hpp"
#include "pqmesh/quality.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::improve3d::detail {

namespace {

template <std::size_t K>
bool holds(const std::array<int, K>& element, int x) {
  return std::find(element.begin(), element.end(), x) != element.end();
}

bool odd(const std::array<int, 4>& p) {
  int inversions = 0;
  for (std::size_t a = 0; a < 4; ++a)
    for (std::size_t b = a + 1; b < 4; ++b) inversions += p[a] > p[b];
  return (inversions & 1) != 0;
}

// The vertices of k as an even permutation (so as positive as k) with k[i]
// first and k[j] second.
std::array<int, 4> starting_with(const std::array<int, 4>& k, int i, int j) {
  std::array<int, 4> p{i, j, -1, -1};
  std::size_t n = 2;
  for (int x = 0; x < 4; ++x)
    if (x != i && x != j) p[n++] = x;
  if (odd(p)) std::swap(p[2], p[3]);
  return {k[static_cast<std::size_t>(p[0])], k[static_cast<std::size_t>(p[1])], k[static_cast<std::size_t>(p[2])],
          k[static_cast<std::size_t>(p[3])]};
}

// The vertices of k as an even permutation with k[i] last.
std::array<int, 4> ending_with(const std::array<int, 4>& k, int i) {
  std::array<int, 4> p{-1, -1, -1, i};
  std::size_t n = 0;
  for (int x = 0; x < 4; ++x)
    if (x != i) p[n++] = x;
  if (odd(p)) std::swap(p[0], p[1]);
  return {k[static_cast<std::size_t>(p[0])], k[static_cast<std::size_t>(p[1])], k[static_cast<std::size_t>(p[2])],
          k[static_cast<std::size_t>(p[3])]};
}

}  // namespace

Flipper::Flipper(CollapseMesh& mesh, const SizeBound& size, double aspect_cap)
    : mesh_(mesh), size_(size), cap_(aspect_cap) {}

std::int64_t Flipper::pass() {
  created_.clear();
  std::vector<std::pair<double, int>> order;
  for (int t = 0; t < mesh_.tet_count(); ++t)
    if (mesh_.tet(t)[0] >= 0 && mesh_.dihedral(t) < kWorkBelowDihedral) order.emplace_back(mesh_.dihedral(t), t);
  std::sort(order.begin(), order.end());
  std::int64_t flips = 0;
  for (const auto& [key, t] : order)
    if (mesh_.tet(t)[0] >= 0 && try_tet(t)) ++flips;
  return flips;
}

bool Flipper::try_tet(int t) {
  const std::array<int, 4> k = mesh_.tet(t);
  for (std::size_t i = 0; i < 4; ++i) {
    around_[i].clear();
    mesh_.tets_of(k[i], around_[i]);
  }
  Flip best, trial;
  bool found = false;
  const auto consider = [&](bool possible) {
    if (!possible || !measure(trial)) return;
    if (found && !(trial.min_dihedral > best.min_dihedral)) return;
    best = trial;
    found = true;
  };
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) consider(edge_flip(t, i, j, trial));
  for (int i = 0; i < 4; ++i) consider(face_flip(t, i, trial));
  if (!found) return false;
  apply(best);
  return true;
}

// The 3-2 flip of edge (k[i], k[j]) of t; false when it is not interior with exactly three tetrahedra.
bool Flipper::edge_flip(int t, int i, int j, Flip& flip) {
  const auto [a, b, c, d] = starting_with(mesh_.tet(t), i, j);
  flip.old_count = 0;
  for (const int s : around_[static_cast<std::size_t>(i)])
    if (holds(mesh_.tet(s), b)) {
      if (flip.old_count == 3) return false;
      flip.old_tets[static_cast<std::size_t>(flip.old_count++)] = s;
    }
  if (flip.old_count != 3) return false;
  // The other two are abde and abec: each holds one of c, d and the same e.
  int e = -1;
  for (const int s : flip.old_tets) {
    if (s == t) continue;
    const auto& h = mesh_.tet(s);
    if (holds(h, c) == holds(h, d)) return false;
    for (const int x : h)
      if (x != a && x != b && x != c && x != d) {
        if (e >= 0 && e != x) return false;
        e = x;
      }
  }
  if (e < 0 || on_boundary(a, b, -1)) return false;
  flip.count = 2;
  flip.tets[0] = {e, b, c, d};
  flip.tets[1] = {a, e, c, d};
  return true;
}

// The 2-3 flip of the face of t opposite k[i]; false when that face is on the boundary.
bool Flipper::face_flip(int t, int i, Flip& flip) {
  const auto [a, b, c, d] = ending_with(mesh_.tet(t), i);
  const std::size_t at_a = static_cast<std::size_t>(std::find(mesh_.tet(t).begin(), mesh_.tet(t).end(), a) -
                                                    mesh_.tet(t).begin());
  int other = -1;
  for (const int s : around_[at_a])
    if (s != t && holds(mesh_.tet(s), b) && holds(mesh_.tet(s), c)) other = s;
  if (other < 0 || on_boundary(a, b, c)) return false;
  int e = -1;
  for (const int x : mesh_.tet(other))
    if (x != a && x != b && x != c) e = x;
  flip.old_count = 2;
  flip.old_tets[0] = t;
  flip.old_tets[1] = other;
  flip.count = 3;
  flip.tets[0] = {a, b, e, d};
  flip.tets[1] = {b, c, e, d};
  flip.tets[2] = {c, a, e, d};
  return true;
}

// A boundary triangle holds a and b (and c, unless c < 0).
bool Flipper::on_boundary(int a, int b, int c) {
  faces_.clear();
  mesh_.faces_of(a, faces_);
  return std::any_of(faces_.begin(), faces_.end(),
                     [&](int f) { return holds(mesh_.face(f), b) && (c < 0 || holds(mesh_.face(f), c)); });
}

// Rules 1, 3, 5 of flips.hpp and the region part of rule 2.
bool Flipper::measure(Flip& flip) const {
  double old_worst = 0, old_min = 180;
  const int marker = mesh_.tet_marker(flip.old_tets[0]);
  for (int n = 0; n < flip.old_count; ++n) {
    const int s = flip.old_tets[static_cast<std::size_t>(n)];
    if (mesh_.tet_marker(s) != marker) return false;
    old_worst = std::max(old_worst, mesh_.aspect(s));
    old_min = std::min(old_min, mesh_.dihedral(s));
  }
  for (int n = 0; n < flip.count; ++n) {
    const auto& k = flip.tets[static_cast<std::size_t>(n)];
    const std::array<Vec3, 4> p = {mesh_.point(k[0]), mesh_.point(k[1]), mesh_.point(k[2]), mesh_.point(k[3])};
    if (orient3d(p[0], p[1], p[2], p[3]) != Sign::Positive) return false;
    if (size_.bounded() && !size_.allows(p)) return false;  // rule 4
  }
  const double limit = std::min(old_worst, cap_);
  flip.worst_aspect = 0;
  flip.min_dihedral = 180;
  for (int n = 0; n < flip.count; ++n) {
    const std::size_t x = static_cast<std::size_t>(n);
    const auto& k = flip.tets[x];
    const TetQuality q = tetrahedron_quality(mesh_.point(k[0]), mesh_.point(k[1]), mesh_.point(k[2]), mesh_.point(k[3]));
    if (!(q.aspect_ratio <= limit)) return false;  // NaN never passes
    flip.aspect[x] = q.aspect_ratio;
    flip.dihedral[x] = q.min_dihedral_deg;
    flip.worst_aspect = std::max(flip.worst_aspect, q.aspect_ratio);
    flip.min_dihedral = std::min(flip.min_dihedral, q.min_dihedral_deg);
  }
  return flip.min_dihedral >= old_min + kMinDihedralGain;
}

void Flipper::apply(const Flip& flip) {
  const int marker = mesh_.tet_marker(flip.old_tets[0]);
  for (int n = 0; n < flip.old_count; ++n) mesh_.remove_tet(flip.old_tets[static_cast<std::size_t>(n)]);
  for (int n = 0; n < flip.count; ++n) {
    const std::size_t x = static_cast<std::size_t>(n);
    created_.push_back(mesh_.add_tet(flip.tets[x], marker, flip.aspect[x], flip.dihedral[x]));
  }
}

}  // namespace pqmesh::improve3d::detail
