#include "improve3d/flips.hpp"

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <limits>
#include <utility>

#include "improve3d/permutation.hpp"
#include "improve3d/smooth.hpp"
#include "improve3d/worst_first.hpp"
#include "pqmesh/quality.hpp"
#include "predicates/predicates.hpp"
#include "quality/tetrahedron_min_dihedral.hpp"

namespace pqmesh::improve3d::detail {

namespace {

constexpr double kForbidden = -std::numeric_limits<double>::infinity();

template <std::size_t K>
bool holds(const std::array<int, K>& element, int x) {
  return std::find(element.begin(), element.end(), x) != element.end();
}

// The vertex of face f that is neither a nor b.
int third(const std::array<int, 3>& f, int a, int b) {
  for (const int x : f)
    if (x != a && x != b) return x;
  return -1;
}

// Every triangulation of the polygon 0 .. m-1 has a triangle on each side
// (s, s + 1 mod m): false when some side's triangles all score kForbidden
// (best_ring_triangulation would return kForbidden), scoring the triangles
// side by side and stopping there. score_once(x, y, z), x < y < z.
template <class Score>
bool every_side_open(int m, Score score_once) {
  for (int s = 0; s < m; ++s) {
    const int p = s, q = (s + 1) % m;
    bool open = false;
    for (int k = 0; k < m && !open; ++k) {
      if (k == p || k == q) continue;
      std::array<int, 3> tri{p, q, k};
      std::sort(tri.begin(), tri.end());
      open = score_once(tri[0], tri[1], tri[2]) != kForbidden;
    }
    if (!open) return false;
  }
  return true;
}

}  // namespace

Flipper::Flipper(CollapseMesh& mesh, const SizeBound& size, double aspect_cap)
    : mesh_(mesh), size_(size), cap_(aspect_cap) {}

std::int64_t Flipper::pass() {
  return visit_worst_first(mesh_, [this](int t) { return try_tet(t); });
}

// t was refused and the stars of its vertices have not changed since.
bool Flipper::refused_unchanged(int t) const {
  const std::size_t i = static_cast<std::size_t>(t);
  if (i >= refused_at_.size() || refused_at_[i] == 0) return false;
  const std::array<int, 4>& k = mesh_.tet(t);
  return std::all_of(k.begin(), k.end(), [&](int x) { return mesh_.star_time(x) <= refused_at_[i]; });
}

bool Flipper::try_tet(int t) {
  if (refused_unchanged(t)) return false;
  const std::array<int, 4> k = mesh_.tet(t);
  for (std::size_t i = 0; i < 4; ++i) {
    around_[i].clear();
    mesh_.tets_of(k[i], around_[i]);
  }
  bool found = false;
  const auto consider = [&](bool possible) {
    if (!possible) return;
    if (found && !(trial_.min_dihedral > best_.min_dihedral)) return;
    std::swap(best_, trial_);
    found = true;
  };
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) consider(edge_removal(t, i, j, trial_));
  for (int i = 0; i < 4; ++i) consider(face_flip(t, i, trial_));
  if (!found) {
    if (refused_at_.size() < static_cast<std::size_t>(mesh_.tet_count()))
      refused_at_.resize(static_cast<std::size_t>(mesh_.tet_count()) + static_cast<std::size_t>(mesh_.tet_count()) / 4, 0);
    refused_at_[static_cast<std::size_t>(t)] = mesh_.time();
    return false;
  }
  apply(best_);
  return true;
}

// The edge removal of edge (k[i], k[j]) of t, with the best triangulation of its ring; false when
// the edge may not be removed (flips.hpp) or no triangulation has only positive, good enough tetrahedra.
bool Flipper::edge_removal(int t, int i, int j, Flip& flip) {
  const int a = mesh_.tet(t)[static_cast<std::size_t>(i)], b = mesh_.tet(t)[static_cast<std::size_t>(j)];
  if (!gather_edge_ring(mesh_, a, b, around_[static_cast<std::size_t>(i)], kMaxRingVertices, ring_)) return false;
  const std::vector<int>& r = ring_.ring;
  const int m = static_cast<int>(r.size());
  if (m < 3 || m > kMaxRingVertices || !one_region(ring_.tets)) return false;
  flip.old_tets = ring_.tets;
  flip.old_faces.clear();
  flip.faces.clear();
  if (ring_.closed ? on_boundary(a, b, -1) : !boundary_pair(flip)) return false;
  const Bounds limits = bounds(ring_.tets);
  RingScores scores(m);
  figures_.resize(static_cast<std::size_t>(m * m * m));
  std::array<bool, kMaxRingVertices * kMaxRingVertices * kMaxRingVertices> scored{};
  const auto score_once = [&](int x, int y, int z) {
    bool& done = scored[static_cast<std::size_t>((x * m + y) * m + z)];
    if (!done) scores.set(x, y, z, score(x, y, z, limits));
    done = true;
    return scores.at(x, y, z);
  };
  if (!every_side_open(m, score_once)) return false;
  for (int x = 0; x < m; ++x)
    for (int y = x + 1; y < m; ++y)
      for (int z = y + 1; z < m; ++z) score_once(x, y, z);
  if (best_ring_triangulation(scores, triangles_) == kForbidden) return false;
  flip.tets.clear();
  flip.aspect.clear();
  flip.dihedral.clear();
  flip.min_dihedral = 180;
  int apex = -1;  // of the triangle on the side (r_0, r_m-1)
  for (const auto& [x, y, z] : triangles_) {
    const int rx = r[static_cast<std::size_t>(x)], ry = r[static_cast<std::size_t>(y)],
              rz = r[static_cast<std::size_t>(z)];
    const auto& q = figures_[static_cast<std::size_t>((x * m + y) * m + z)];
    take({a, rx, ry, rz}, q[0], flip);
    take({rx, ry, rz, b}, q[1], flip);
    if (x == 0 && z == m - 1) apex = ry;
  }
  if (!ring_.closed) replacement_faces(apex, flip);
  return true;
}

// The two boundary triangles abc, abd of the open ring's edge into flip.old_faces; true when
// they may be flipped: same facet, same marker, c and d the ring's ends, a, b, c, d coplanar (exact).
bool Flipper::boundary_pair(Flip& flip) {
  const int a = ring_.a, b = ring_.b;
  faces_.clear();
  mesh_.faces_of(a, faces_);
  for (const int f : faces_)
    if (holds(mesh_.face(f), b)) flip.old_faces.push_back(f);
  if (flip.old_faces.size() != 2) return false;
  const int f = flip.old_faces[0], g = flip.old_faces[1];
  if (mesh_.face_facet(f) != mesh_.face_facet(g) || mesh_.face_marker(f) != mesh_.face_marker(g)) return false;
  const int c = third(mesh_.face(f), a, b), d = third(mesh_.face(g), a, b);
  const int first = ring_.ring.front(), last = ring_.ring.back();
  if (!((c == first && d == last) || (c == last && d == first))) return false;
  return orient3d(mesh_.point(a), mesh_.point(b), mesh_.point(c), mesh_.point(d)) == Sign::Zero;
}

// The boundary triangles (a, c, d) and (b, c, d), c, d the ring's ends, both tetrahedra of the
// triangle (c, apex, d) behind them, each facing out as the first old boundary triangle does.
void Flipper::replacement_faces(int apex, Flip& flip) {
  const std::vector<int>& r = ring_.ring;
  const int c = r.front(), d = r.back();
  const std::array<int, 3>& old = mesh_.face(flip.old_faces[0]);
  const int old_apex = holds(old, c) ? r[1] : r[r.size() - 2];  // of the old tetrahedron behind it
  const Sign outward =
      orient3d(mesh_.point(old[0]), mesh_.point(old[1]), mesh_.point(old[2]), mesh_.point(old_apex));
  for (const int end : {ring_.a, ring_.b}) {
    const bool keep = orient3d(mesh_.point(end), mesh_.point(c), mesh_.point(d), mesh_.point(apex)) == outward;
    flip.faces.push_back(keep ? std::array<int, 3>{end, c, d} : std::array<int, 3>{end, d, c});
  }
}

// The 2-3 flip of the face of t opposite k[i]; false when that face is on the boundary.
bool Flipper::face_flip(int t, int i, Flip& flip) {
  const auto [a, b, c, d] = ending_with(mesh_.tet(t), i);
  const std::size_t at_a = static_cast<std::size_t>(
      std::distance(mesh_.tet(t).begin(), std::find(mesh_.tet(t).begin(), mesh_.tet(t).end(), a)));
  int other = -1;
  for (const int s : around_[at_a])
    if (s != t && holds(mesh_.tet(s), b) && holds(mesh_.tet(s), c)) other = s;
  if (other < 0 || on_boundary(a, b, c)) return false;
  int e = -1;
  for (const int x : mesh_.tet(other))
    if (x != a && x != b && x != c) e = x;
  flip.old_tets = {t, other};
  if (!one_region(flip.old_tets)) return false;
  flip.old_faces.clear();
  flip.faces.clear();
  flip.tets.clear();
  flip.aspect.clear();
  flip.dihedral.clear();
  flip.min_dihedral = 180;
  const Bounds limits = bounds(flip.old_tets);
  TetQuality q;
  for (const std::array<int, 4>& k : {std::array<int, 4>{a, b, e, d}, {b, c, e, d}, {c, a, e, d}}) {
    if (!admissible(k, limits, q)) return false;
    take(k, q, flip);
  }
  return true;
}

// A boundary triangle holds a and b (and c, unless c < 0).
bool Flipper::on_boundary(int a, int b, int c) {
  faces_.clear();
  mesh_.faces_of(a, faces_);
  return std::any_of(faces_.begin(), faces_.end(),
                     [&](int f) { return holds(mesh_.face(f), b) && (c < 0 || holds(mesh_.face(f), c)); });
}

bool Flipper::one_region(const std::vector<int>& tets) const {
  return std::all_of(tets.begin(), tets.end(), [&](int s) { return mesh_.tet_marker(s) == mesh_.tet_marker(tets[0]); });
}

// Rules 3 and 5 of flips.hpp for new tetrahedra replacing old_tets: aspect ratio at most the old
// ones' worst and aspect_cap, minimum dihedral angle at least the old ones' least + kMinDihedralGain.
Flipper::Bounds Flipper::bounds(const std::vector<int>& old_tets) const {
  double old_worst = 0, old_min = 180;
  for (const int s : old_tets) {
    old_worst = std::max(old_worst, mesh_.aspect(s));
    old_min = std::min(old_min, mesh_.dihedral(s));
  }
  return {std::min(old_worst, cap_), old_min + kMinDihedralGain};
}

// Rules 1, 3, 4 and 5 of flips.hpp for one new tetrahedron k, its quality into q: positive
// (exact), within the size bound, minimum dihedral angle at least the floor, aspect ratio at most
// the limit (NaN passes neither).
bool Flipper::admissible(const std::array<int, 4>& k, const Bounds& limits, TetQuality& q) const {
  const std::array<Vec3, 4> p = {mesh_.point(k[0]), mesh_.point(k[1]), mesh_.point(k[2]), mesh_.point(k[3])};
  if (orient3d(p[0], p[1], p[2], p[3]) != Sign::Positive) return false;
  if (size_.bounded() && !size_.allows(p)) return false;
  if (!(tetrahedron_min_dihedral(p[0], p[1], p[2], p[3], Sign::Positive) >= limits.dihedral)) return false;
  q = tetrahedron_quality(p[0], p[1], p[2], p[3]);
  return q.aspect_ratio <= limits.aspect;
}

// The score of ring triangle (x, y, z) of edge (a, b): the smaller minimum dihedral angle of its
// tetrahedra (a, r_x, r_y, r_z) and (r_x, r_y, r_z, b), kept in figures_, or kForbidden when one
// is not admissible.
double Flipper::score(int x, int y, int z, const Bounds& limits) {
  const std::vector<int>& r = ring_.ring;
  const int m = static_cast<int>(r.size());
  const int rx = r[static_cast<std::size_t>(x)], ry = r[static_cast<std::size_t>(y)],
            rz = r[static_cast<std::size_t>(z)];
  auto& q = figures_[static_cast<std::size_t>((x * m + y) * m + z)];
  if (!admissible({ring_.a, rx, ry, rz}, limits, q[0]) || !admissible({rx, ry, rz, ring_.b}, limits, q[1]))
    return kForbidden;
  return std::min(q[0].min_dihedral_deg, q[1].min_dihedral_deg);
}

// Appends new tetrahedron k with its measured quality q to the flip.
void Flipper::take(const std::array<int, 4>& k, const TetQuality& q, Flip& flip) const {
  flip.tets.push_back(k);
  flip.aspect.push_back(q.aspect_ratio);
  flip.dihedral.push_back(q.min_dihedral_deg);
  flip.min_dihedral = std::min(flip.min_dihedral, q.min_dihedral_deg);
}

void Flipper::apply(const Flip& flip) {
  const int marker = mesh_.tet_marker(flip.old_tets[0]);
  for (const int s : flip.old_tets) mesh_.remove_tet(s);
  for (std::size_t x = 0; x < flip.tets.size(); ++x)
    mesh_.add_tet(flip.tets[x], marker, flip.aspect[x], flip.dihedral[x]);
  if (flip.faces.empty()) return;
  const int face_marker = mesh_.face_marker(flip.old_faces[0]), facet = mesh_.face_facet(flip.old_faces[0]);
  for (const int f : flip.old_faces) mesh_.remove_face(f);
  for (const auto& f : flip.faces) mesh_.add_face(f, face_marker, facet);
  ++boundary_flips_;
}

}  // namespace pqmesh::improve3d::detail
