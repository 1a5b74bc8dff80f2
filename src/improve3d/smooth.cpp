#include "improve3d/smooth.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>

#include "pqmesh/quality.hpp"
#include "predicates/predicates.hpp"
#include "quality/tetrahedron_aspect_within.hpp"
#include "quality/tetrahedron_min_dihedral.hpp"

namespace pqmesh::improve3d::detail {

namespace {

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

// Mobility codes (vertex_mobility): -1 fixed; 0..2 in the plane where that
// axis's coordinate is fixed; kFree anywhere; kAlongAxis + k only along axis k;
// kOnSlantedFacet / kOnSlantedEdge settled onto their feature.
constexpr int kFree = 3;
constexpr int kAlongAxis = 4;
constexpr int kOnSlantedFacet = 7;
constexpr int kOnSlantedEdge = 8;

bool slanted(int mobility) { return mobility >= kOnSlantedFacet; }

bool moves_along(int mobility, int axis) {
  if (mobility < 0) return false;
  if (mobility < kFree) return axis != mobility;
  if (mobility == kFree || slanted(mobility)) return true;
  return axis == mobility - kAlongAxis;
}

// The axis whose coordinate every PLC vertex of the facet shares bit for bit; -1 when none.
int facet_axis(const Domain3& domain, const Facet3& facet) {
  for (int axis = 0; axis < 3; ++axis) {
    bool first = true, same = true;
    double c = 0;
    for (const auto& loop : facet.loops)
      for (const int x : loop) {
        const double y = axis_coord(domain.plc.vertices[static_cast<std::size_t>(x)], axis);
        if (first) c = y;
        same = same && same_bits(c, y);
        first = false;
      }
    if (!first && same) return axis;
  }
  return -1;
}

// The input edge with facets {f, g} whose line holds p exactly (its end points
// share two coordinates bit for bit, and so does p): the axis it runs along,
// or -1 when there is none.
int edge_axis(const Domain3& domain, int f, int g, Vec3 p) {
  for (const DomainEdge& e : domain.edges) {
    const bool pair = (e.facets[0] == f && e.facets[1] == g) || (e.facets[0] == g && e.facets[1] == f);
    if (!pair) continue;
    const Vec3 a = domain.plc.vertices[static_cast<std::size_t>(e.a)], b = domain.plc.vertices[static_cast<std::size_t>(e.b)];
    int along = -1, shared = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const bool same = same_bits(axis_coord(a, axis), axis_coord(b, axis)) &&
                        same_bits(axis_coord(a, axis), axis_coord(p, axis));
      if (same) ++shared;
      else along = axis;
    }
    if (shared == 2) return along;
  }
  return -1;
}

// The domain edge with facets {f, g} within an ulp of which p lies (exact), or -1.
int slanted_edge(const Domain3& domain, int f, int g, Vec3 p) {
  for (std::size_t e = 0; e < domain.edges.size(); ++e) {
    const DomainEdge& edge = domain.edges[e];
    const bool pair = (edge.facets[0] == f && edge.facets[1] == g) || (edge.facets[0] == g && edge.facets[1] == f);
    if (pair && within_ulp_of_segment(p, domain.plc.vertices[static_cast<std::size_t>(edge.a)],
                                      domain.plc.vertices[static_cast<std::size_t>(edge.b)]))
      return static_cast<int>(e);
  }
  return -1;
}

std::array<Vec3, 4> corners(const CollapseMesh& mesh, const std::array<int, 4>& k, int v, Vec3 q) {
  std::array<Vec3, 4> p{};
  for (std::size_t i = 0; i < 4; ++i) p[i] = k[i] == v ? q : mesh.point(k[i]);
  return p;
}

double min_dihedral_at(const CollapseMesh& mesh, int t, int v, Vec3 q) {
  const auto p = corners(mesh, mesh.tet(t), v, q);
  return tetrahedron_min_dihedral(p[0], p[1], p[2], p[3]);
}

// Keeps the coordinates a vertex of this mobility may not change at p's.
void pin(Vec3& q, Vec3 p, int mobility) {
  for (int axis = 0; axis < 3; ++axis)
    if (!moves_along(mobility, axis)) axis_ref(q, axis) = axis_coord(p, axis);
}

// The steps along the ascent direction, in units of the mean edge length of the star.
constexpr std::array<double, 5> kAscentSteps = {0.1, 0.05, 0.025, 0.0125, 0.00625};

}  // namespace

VertexMobility vertex_mobility(const Domain3& domain, CollapseMesh& mesh, const VertexClasses& classes) {
  std::vector<int> axis(domain.plc.facets.size());
  for (std::size_t f = 0; f < axis.size(); ++f) axis[f] = facet_axis(domain, domain.plc.facets[f]);
  VertexMobility mobility{std::vector<std::int8_t>(static_cast<std::size_t>(mesh.vertex_count()), -1),
                          std::vector<int>(static_cast<std::size_t>(mesh.vertex_count()), -1)};
  std::vector<int> faces;
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    if (!mesh.vertex_alive(v)) continue;
    faces.clear();
    mesh.faces_of(v, faces);
    std::int8_t& m = mobility.code[static_cast<std::size_t>(v)];
    int& feature = mobility.feature[static_cast<std::size_t>(v)];
    if (classes.of(v) == VertexClass::Interior) {
      if (faces.empty()) m = kFree;
    } else if (classes.of(v) == VertexClass::Facet && !faces.empty()) {
      const int f = classes.facets_of(v)[0];
      const bool one_facet =
          std::all_of(faces.begin(), faces.end(), [&](int b) { return mesh.face_facet(b) == f; });
      if (one_facet) {
        const int a = axis[static_cast<std::size_t>(f)];
        m = static_cast<std::int8_t>(a >= 0 ? a : kOnSlantedFacet);
        feature = a >= 0 ? -1 : f;
      }
    } else if (classes.of(v) == VertexClass::Edge && classes.facets_of(v).size() == 2) {
      const int f = classes.facets_of(v)[0], g = classes.facets_of(v)[1];
      const int along = edge_axis(domain, f, g, mesh.point(v));
      if (along >= 0) {
        m = static_cast<std::int8_t>(kAlongAxis + along);
      } else if ((feature = slanted_edge(domain, f, g, mesh.point(v))) >= 0) {
        m = kOnSlantedEdge;
      }
    }
  }
  return mobility;
}

Smoother::Smoother(CollapseMesh& mesh, VertexMobility mobility, BoundarySnap* snap, const SizeBound& size,
                   double aspect_cap, SmoothTries& tries)
    : mesh_(mesh), mobility_(std::move(mobility.code)), feature_(std::move(mobility.feature)), snap_(snap),
      size_(size), cap_(aspect_cap), tries_(tries),
      moved_(static_cast<std::size_t>(mesh.vertex_count()), 0),
      marks_(static_cast<std::size_t>(mesh.vertex_count()), 0) {
  mobility_.resize(static_cast<std::size_t>(mesh.vertex_count()), -1);  // none given: nothing moves
  feature_.resize(mobility_.size(), -1);
  tries_.at.resize(mobility_.size(), 0);
  tries_.code.resize(mobility_.size(), -1);
  tries_.feature.resize(mobility_.size(), -1);
}

// v was tried with its present mobility and refused, and its star has not changed since.
bool Smoother::refused_unchanged(int v) const {
  const std::size_t x = static_cast<std::size_t>(v);
  return tries_.at[x] != 0 && mesh_.star_time(v) <= tries_.at[x] && tries_.code[x] == mobility_[x] &&
         tries_.feature[x] == feature_[x];
}

double Smoother::star_min_dihedral(int v) {
  star_.clear();
  mesh_.tets_of(v, star_);
  double least = 180;
  for (const int t : star_) least = std::min(least, mesh_.dihedral(t));
  return least;
}

std::int64_t Smoother::pass() {
  std::vector<std::pair<double, int>> order;
  for (int v = 0; v < mesh_.vertex_count(); ++v) {
    const std::size_t x = static_cast<std::size_t>(v);
    if (!mesh_.vertex_alive(v) || mobility_[x] < 0) continue;
    if (!first_pass_ && refused_unchanged(v)) continue;
    const double least = star_min_dihedral(v);
    if (least < kWorkBelowDihedral) order.emplace_back(least, v);
  }
  first_pass_ = false;
  std::sort(order.begin(), order.end());
  std::int64_t moved = 0;
  for (const auto& [key, v] : order) {
    if (refused_unchanged(v)) continue;  // tried by an earlier Smoother (first pass only)
    const std::size_t x = static_cast<std::size_t>(v);
    tries_.at[x] = mesh_.time();
    tries_.code[x] = mobility_[x];
    tries_.feature[x] = feature_[x];
    if (!try_vertex(v)) continue;  // a move advances the time past the try: star_time(v) > tries_.at[x]
    ++moved;
    if (moved_[static_cast<std::size_t>(v)] == 0) ++moved_vertices_;
    moved_[static_cast<std::size_t>(v)] = 1;
  }
  return moved;
}

// Whether v may go to q as far as the star's shape goes, and the star's
// least minimum dihedral angle there (trial.min_dihedral): false when a
// tetrahedron is not positive, or has a minimum dihedral angle below `floor`
// (at or below it when `strict`), or an aspect ratio above `limit`. The
// orientation and the dihedral floor are tested first, the star's tetrahedra
// in increasing order of their minimum dihedral angle before the move
// (by_dihedral_: the likeliest to stay below the floor come first), with
// tetrahedron_min_dihedral (the same doubles as tetrahedron_quality's), so
// most refused candidates stop at their first tetrahedra; the aspect ratios
// then by tetrahedron_aspect_within (the same answers as
// tetrahedron_quality's), which skips the enclosing ball of every tetrahedron
// whose sphere ratio is within the limit. Every test must pass, so their
// order does not change the outcome.
bool Smoother::evaluate(int v, Vec3 q, double floor, bool strict, double limit, Trial& trial) {
  trial.q = q;
  trial.min_dihedral = 180;
  for (const int t : by_dihedral_) {
    const auto p = corners(mesh_, mesh_.tet(t), v, q);
    const Sign s = orient3d(p[0], p[1], p[2], p[3]);
    if (s != Sign::Positive) return false;
    const double least = tetrahedron_min_dihedral(p[0], p[1], p[2], p[3], s);
    if (least < floor || (strict && least == floor)) return false;  // a NaN angle fails neither (std::min skips it)
    trial.min_dihedral = std::min(trial.min_dihedral, least);
  }
  if (slanted(mobility_[static_cast<std::size_t>(v)]) && !fan_keeps_orientation(v, mesh_.point(v), q)) return false;
  for (const int t : star_) {
    const auto p = corners(mesh_, mesh_.tet(t), v, q);
    if (!tetrahedron_aspect_within(p[0], p[1], p[2], p[3], Sign::Positive, limit)) return false;  // NaN never passes
  }
  return true;
}

// The full quality of every tetrahedron of v's star with v at q, into
// best_aspect_ and best_dihedral_ (star_ order).
void Smoother::measure_star(int v, Vec3 q) {
  best_aspect_.clear();
  best_dihedral_.clear();
  for (const int t : star_) {
    const auto p = corners(mesh_, mesh_.tet(t), v, q);
    const TetQuality tq = tetrahedron_quality(p[0], p[1], p[2], p[3]);
    best_aspect_.push_back(tq.aspect_ratio);
    best_dihedral_.push_back(tq.min_dihedral_deg);
  }
}

// Each boundary triangle of v (faces_, gathered by try_vertex) has the same
// nonzero orientation with v at q as at p, in the projection dropping its
// facet's dominant normal axis (exact).
bool Smoother::fan_keeps_orientation(int v, Vec3 p, Vec3 q) {
  for (const int f : faces_) {
    const std::array<int, 3>& k = mesh_.face(f);
    std::array<Vec3, 3> before{}, after{};
    for (std::size_t i = 0; i < 3; ++i) {
      before[i] = k[i] == v ? p : mesh_.point(k[i]);
      after[i] = k[i] == v ? q : mesh_.point(k[i]);
    }
    const int drop = snap_->drop_axis(mesh_.face_facet(f));
    const Sign s = orient2d_projected(after[0], after[1], after[2], drop);
    if (s == Sign::Zero || s != orient2d_projected(before[0], before[1], before[2], drop)) return false;
  }
  return true;
}

// q made a place v may take: the pinned coordinates kept (axis-aligned
// features), or settled onto v's slanted facet or edge; false when that fails.
bool Smoother::place(int v, Vec3 p, Vec3& q) {
  const int code = mobility_[static_cast<std::size_t>(v)];
  if (!slanted(code)) {
    pin(q, p, code);
    return true;
  }
  const int feature = feature_[static_cast<std::size_t>(v)];
  const std::optional<Vec3> placed = code == kOnSlantedFacet ? snap_->onto_facet(feature, q) : snap_->onto_edge(feature, q);
  if (!placed) return false;
  q = *placed;
  return true;
}

// Rule 4 of smooth.hpp for every tetrahedron of v's star with v moved from p
// to q (one already beyond the bound at p may stay beyond it if its longest
// edge does not grow).
bool Smoother::within_size(int v, Vec3 p, Vec3 q) const {
  if (!size_.bounded()) return true;
  for (const int t : star_) {
    const auto after = corners(mesh_, mesh_.tet(t), v, q);
    if (size_.allows(after)) continue;
    const auto before = corners(mesh_, mesh_.tet(t), v, p);
    if (size_.allows(before) || SizeBound::longest_edge(after) > SizeBound::longest_edge(before)) return false;
  }
  return true;
}

// A step of length `step` from v along the gradient (central differences)
// of the minimum dihedral angle of worst_tet; v itself when the gradient vanishes.
Vec3 Smoother::ascent(int v, int worst_tet, double step) const {
  const Vec3 p = mesh_.point(v);
  const int fixed = mobility_[static_cast<std::size_t>(v)];
  const double h = 1e-6 * step;
  Vec3 g{};
  for (int axis = 0; axis < 3; ++axis) {
    if (!moves_along(fixed, axis)) continue;
    Vec3 plus = p, minus = p;
    axis_ref(plus, axis) += h;
    axis_ref(minus, axis) -= h;
    axis_ref(g, axis) = min_dihedral_at(mesh_, worst_tet, v, plus) - min_dihedral_at(mesh_, worst_tet, v, minus);
  }
  const double length = norm(g);
  if (!(length > 0) || !std::isfinite(length)) return p;
  Vec3 q = p + (step / length) * g;
  pin(q, p, fixed);
  return q;
}

bool Smoother::try_vertex(int v) {
  const int fixed = mobility_[static_cast<std::size_t>(v)];
  star_.clear();
  mesh_.tets_of(v, star_);
  if (star_.empty()) return false;
  const int marker = mesh_.tet_marker(star_.front());
  if (!mesh_.one_region() &&
      !std::all_of(star_.begin(), star_.end(), [&](int t) { return mesh_.tet_marker(t) == marker; }))
    return false;
  double old_worst = 0, old_min = 180;
  int worst_tet = star_.front();
  for (const int t : star_) {
    old_worst = std::max(old_worst, mesh_.aspect(t));
    if (mesh_.dihedral(t) < old_min) {
      old_min = mesh_.dihedral(t);
      worst_tet = t;
    }
  }
  // The neighbours (every vertex of the star) and the point they average:
  // on a facet the boundary neighbours only.
  ++stamp_;
  marks_[static_cast<std::size_t>(v)] = stamp_;
  neighbours_.clear();
  for (const int t : star_)
    for (const int x : mesh_.tet(t))
      if (marks_[static_cast<std::size_t>(x)] != stamp_) {
        marks_[static_cast<std::size_t>(x)] = stamp_;
        neighbours_.push_back(x);
      }
  const Vec3 p = mesh_.point(v);
  Vec3 sum{};
  double count = 0, edge_sum = 0;
  for (const int x : neighbours_) edge_sum += norm(mesh_.point(x) - p);
  if (fixed == kFree) {
    for (const int x : neighbours_) sum = sum + mesh_.point(x);
    count = static_cast<double>(neighbours_.size());
  } else {
    faces_.clear();
    mesh_.faces_of(v, faces_);
    for (const int f : faces_)
      for (const int x : mesh_.face(f))
        if (x != v) sum = sum + 0.5 * mesh_.point(x);  // each boundary neighbour lies on two of v's triangles
    count = static_cast<double>(faces_.size());
  }
  if (count == 0) return false;
  const Vec3 mean = (1.0 / count) * sum;
  const double mean_edge = edge_sum / static_cast<double>(neighbours_.size());

  std::array<Vec3, 3 + kAscentSteps.size()> candidates{};
  candidates[0] = mean;
  candidates[1] = p + 0.5 * (mean - p);
  candidates[2] = p + 0.25 * (mean - p);
  for (std::size_t i = 0; i < kAscentSteps.size(); ++i) candidates[3 + i] = ascent(v, worst_tet, kAscentSteps[i] * mean_edge);
  std::array<bool, candidates.size()> placed{};
  for (std::size_t i = 0; i < candidates.size(); ++i)
    placed[i] = place(v, p, candidates[i]);  // on the facet's plane or the edge's line

  by_dihedral_.assign(star_.begin(), star_.end());
  for (std::size_t i = 1; i < by_dihedral_.size(); ++i)  // insertion sort: a star is a few dozen, no allocation
    for (std::size_t j = i; j > 0 && mesh_.dihedral(by_dihedral_[j]) < mesh_.dihedral(by_dihedral_[j - 1]); --j)
      std::swap(by_dihedral_[j], by_dihedral_[j - 1]);
  const double limit = std::min(old_worst, cap_);
  Trial best{p, old_min + kMinDihedralGain};
  bool found = false;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const Vec3 q = candidates[i];
    if (!placed[i] || q == p) continue;
    Trial trial{q, 0};
    if (!evaluate(v, q, best.min_dihedral, found, limit, trial)) continue;
    if (!(trial.min_dihedral >= best.min_dihedral) || (found && trial.min_dihedral == best.min_dihedral)) continue;
    if (!within_size(v, p, q)) continue;
    best = trial;
    found = true;
  }
  if (!found) return false;
  measure_star(v, best.q);
  mesh_.move_vertex(v, best.q, star_, best_aspect_, best_dihedral_);
  return true;
}

}  // namespace pqmesh::improve3d::detail
