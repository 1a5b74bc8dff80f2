// Whole meshes from every leaf of the octree (thesis §4.5: empty, facet, edge,
// vertex and two-facet boxes; box_jobs.hpp, facet_boxes.hpp) for polyhedra in
// general position with respect to the octree grid (non-dyadic coordinates):
// random tetrahedra, random star-shaped, generally nonconvex, polyhedra (a
// subdivided octahedron with random vertex radii; every facet a triangle, so
// planar exactly) and random rotated L-shaped prisms (a reflex edge; vertical
// sides planar exactly). Every square shared by two boxes is also
// triangulated from both sides by the square dispatcher and compared. The
// octree is built without the separating splits (OctreeOptions::separate =
// false) for test time. Every mesh must pass
// pqmesh::check_mesh against the domain (orientation, conformity, boundary =
// dP subdivided, every input vertex, edge and facet recovered, volume). A
// domain whose octree has a leaf no job covers (box_jobs problems, e.g. kind
// Other without the separating splits) is skipped and counted; the test
// asserts that most are meshed. Counts per box kind, per square case, the
// worst aspect ratio and the min dihedral angle are printed.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

#include "../plc/domain_fixtures.hpp"
#include "mv3d/octree_builder.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/errors.hpp"
#include "pqmesh/read_domain.hpp"
#include "support/paths.hpp"
#include "pqmesh/plc.hpp"
#include "pqmesh/quality.hpp"
#include "tet3d/boxes/box_jobs.hpp"
#include "tet3d/squares/cut_square_edge.hpp"
#include "tet3d/facet_boxes.hpp"
#include "tet3d/points/grid_point.hpp"
#include "tet3d/squares/square_cases.hpp"

namespace pqmesh::tet3d {
namespace {

Plc3 triangles_plc(const std::vector<Vec3>& v, const std::vector<std::array<int, 3>>& t) {
  Plc3 plc;
  plc.vertices = v;
  for (const auto& tri : t) {
    Facet3 f;
    f.loops = {{tri[0], tri[1], tri[2]}};
    plc.facets.push_back(f);
  }
  return plc;
}

// A random tetrahedron in [0.1, 0.9]^3, not too flat: every vertex at least
// 0.25 from the opposite face's plane (a construction; only the test's input).
Plc3 random_tetrahedron(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.1, 0.9);
  for (;;) {
    std::vector<Vec3> v(4);
    for (Vec3& p : v) p = {u(rng), u(rng), u(rng)};
    bool ok = true;
    for (int i = 0; i < 4 && ok; ++i) {
      const Vec3 a = v[static_cast<std::size_t>((i + 1) % 4)], b = v[static_cast<std::size_t>((i + 2) % 4)],
                 c = v[static_cast<std::size_t>((i + 3) % 4)];
      const Vec3 n = cross(b - a, c - a);
      const double h = std::fabs(dot(n, v[static_cast<std::size_t>(i)] - a)) / norm(n);
      ok = h >= 0.25;
    }
    if (ok) return triangles_plc(v, {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}});
  }
}

// The octahedron with each face split at its centre (14 vertices, 24
// triangles), vertex i at centre + r_i d_i with random radii in [0.6, 1] times
// 0.4 around a random centre: star-shaped from the centre, generally nonconvex.
Plc3 random_star(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> r(0.6, 1.0), c(0.45, 0.55);
  const Vec3 centre{c(rng), c(rng), c(rng)};
  std::vector<Vec3> dirs = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const int oct[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  std::vector<std::array<int, 3>> tris;
  for (const auto& f : oct) {
    const Vec3 m = dirs[static_cast<std::size_t>(f[0])] + dirs[static_cast<std::size_t>(f[1])] +
                   dirs[static_cast<std::size_t>(f[2])];
    dirs.push_back((1.0 / norm(m)) * m);
    const int k = static_cast<int>(dirs.size()) - 1;
    for (int i = 0; i < 3; ++i) tris.push_back({f[i], f[(i + 1) % 3], k});
  }
  std::vector<Vec3> v;
  for (const Vec3& d : dirs) v.push_back(centre + (0.4 * r(rng)) * d);
  return triangles_plc(v, tris);
}

// Every square of every job's faces, triangulated by the square dispatcher
// from each side with one PointBook (so equal vertex keys give equal ids): the
// triangles (as sorted id triples) from the lower side (the box below S, its
// face at S an upper face) must equal those from the upper side. Duplicates
// of a cube contribute their pieces to their side's union. Returns the
// number of squares compared; counts the kind pairs of the two sides.
std::int64_t squares_agree(const mv3d::OctreeBuilder& b, const CornerSet& corners, const Domain3& d,
                           const std::vector<BoxJob>& jobs, std::map<std::string, std::int64_t>& pairs) {
  PointBook book;
  SquareDispatcher squares(b.tree(), corners, d, book, nullptr);
  using Key = std::tuple<int, GridPoint, std::int64_t>;
  struct Sides {
    std::vector<std::array<int, 3>> tris[2];
    std::set<std::string> kinds[2];
  };
  std::map<Key, Sides> seen;
  for (const BoxJob& j : jobs) {
    std::vector<FaceSquare> list;
    job_squares(b.tree(), corners, j, list);
    const BoxFaces faces = job_faces(squares, j);
    for (const FaceSquare& s : list) {
      std::vector<std::array<int, 3>> out;
      squares.triangulate(s, faces, out);
      Sides& e = seen[Key{s.n, s.lo, s.side}];
      const int side = s.upper ? 0 : 1;  // the box lies below S when its face is an upper face
      for (auto t : out) {
        std::sort(t.begin(), t.end());
        e.tris[side].push_back(t);
      }
      e.kinds[side].insert(to_string(j.kind == BoxKind::FromFacet ? BoxKind::Facet : j.kind));
    }
  }
  std::int64_t compared = 0;
  for (auto& [key, e] : seen) {
    if (e.kinds[0].empty() || e.kinds[1].empty()) continue;
    for (auto& t : e.tris) std::sort(t.begin(), t.end());
    EXPECT_EQ(e.tris[0], e.tris[1]) << "square axis " << std::get<0>(key) << " side " << std::get<2>(key);
    ++compared;
    std::vector<std::string> k{*e.kinds[0].begin(), *e.kinds[1].begin()};
    std::sort(k.begin(), k.end());
    ++pairs[k[0] + "|" + k[1]];
  }
  return compared;
}

// The polygon `pts`, centred on its a x b bounding box, rotated by `angle`
// about z and moved to (cx, cy).
template <std::size_t N>
std::vector<Vec2> rotated(const double (&pts)[N][2], double a, double b, double angle, double cx, double cy) {
  std::vector<Vec2> out;
  for (const auto& p : pts) {
    const double x = p[0] - a / 2, y = p[1] - b / 2;
    out.push_back({cx + std::cos(angle) * x - std::sin(angle) * y, cy + std::sin(angle) * x + std::cos(angle) * y});
  }
  return out;
}

// A prism over an L-shaped polygon (random arm lengths and widths, rotated
// by a random angle about z, random z range): nonconvex, one reflex edge.
// Vertical sides are planar exactly (two points repeated at two heights).
Plc3 random_l_prism(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  const double a = 0.3 + 0.2 * u(rng), b = 0.3 + 0.2 * u(rng), w = 0.1 + 0.15 * u(rng), t = 0.1 + 0.15 * u(rng);
  const double angle = 6.283185307179586 * u(rng);
  const double cx = 0.45 + 0.1 * u(rng), cy = 0.45 + 0.1 * u(rng), z0 = 0.2 + 0.1 * u(rng), z1 = 0.7 + 0.1 * u(rng);
  const double l[6][2] = {{0, 0}, {a, 0}, {a, t}, {w, t}, {w, b}, {0, b}};
  return test::prism(rotated(l, a, b, angle, cx, cy), z0, z1);
}

// A prism over a square-ish polygon with a narrow V notch (a reflex edge of
// nearly 360 degrees at the notch tip), rotated about z: the notch splits
// cubes at its mouth into two components that share the bottom and top
// facets (duplicates whose facet crosses a shared square on the other
// component's side only).
Plc3 random_notch_prism(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  const double a = 0.4 + 0.1 * u(rng), b = 0.4 + 0.1 * u(rng), t = 0.1 + 0.1 * u(rng), e = 0.03 + 0.05 * u(rng);
  const double angle = 6.283185307179586 * u(rng);
  const double cx = 0.45 + 0.1 * u(rng), cy = 0.45 + 0.1 * u(rng), z0 = 0.2 + 0.1 * u(rng), z1 = 0.7 + 0.1 * u(rng);
  const double l[7][2] = {{0, 0}, {a, 0}, {a, b}, {a / 2 + e, b}, {a / 2 + 0.01 * u(rng), t}, {a / 2 - e, b}, {0, b}};
  return test::prism(rotated(l, a, b, angle, cx, cy), z0, z1);
}

// Worst shapes per box kind (empty, facet, edge, vertex, two-facet).
constexpr int kKinds = 5;
const char* const kKindNames[kKinds] = {"empty", "facet", "edge", "vertex", "two-facet"};
int kind_index(const BoxJob& j) {
  switch (j.kind) {
    case BoxKind::FromFacet: return j.facet < 0 ? 0 : 1;
    case BoxKind::Empty: return 0;
    case BoxKind::Facet: return 1;
    case BoxKind::Edge: return 2;
    case BoxKind::Vertex: return 3;
    case BoxKind::TwoFacet: return 4;
  }
  return 0;
}

struct KindShapes {
  std::array<double, kKinds> aspect{}, dihedral{180, 180, 180, 180, 180};
  std::array<std::int64_t, kKinds> tets{};
  // Lemma 6: min over distinct I-vertices x, y of one tetrahedron (box
  // vertices, P facet x box edge, P edge x box face) of |xy| / h, h the
  // side of the smallest box containing x or y (PairBoxSide).
  std::array<double, kKinds> lemma6{INFINITY, INFINITY, INFINITY, INFINITY, INFINITY};
};

// Lemma 6's form (thesis §4.3): distinct I-vertices x, y are at least
// min(t, h/16) apart, h the smallest box containing x or y (PairBoxSide),
// t = k1 h a defined only when x, y lie on the two facets F, G of a sharp
// interior angle a in a protected edge box (or one is a box vertex between
// them); we apply the same t to the wedges at a vertex box's P vertex.
// Measured over the pairs closer than h/16: how many are such sharp-edge
// pairs and their smallest d / (h a); how many pair a crossing with a box
// vertex or ring segment the warp left short of that facet or edge (the side
// rule's refusals, which the thesis's proof does not have); how many are two
// crossings of one facet from a box vertex left short; the smallest d / h of the
// others, and the key kinds and box kind of that pair.
struct Lemma6Pairs {
  std::int64_t under = 0, sharp = 0;
  double sharp_min = INFINITY;  // d / (h a), a in radians
  double other_min = INFINITY;  // d / h
  // Pairs of a crossing and a box vertex or ring segment the warp left
  // nearer than h/16 to that facet's plane or h/8 to that edge, and their
  // smallest d / h.
  std::int64_t short_warp = 0;
  double short_min = INFINITY;
  // Pairs of crossings of one facet on two ring segments from one box vertex
  // the warp left short of that facet (Fig. 4.8), and their smallest d / h.
  std::int64_t one_vertex = 0;
  double one_vertex_min = INFINITY;
  std::string other_what;
};

struct Totals {
  int meshed = 0, skipped = 0;
  bool warp = false;
  KindShapes kinds;
  Lemma6Pairs l6;
  std::int64_t warped = 0, bisected = 0, fallback = 0, conflicts = 0, reflex_left = 0, crowded_left = 0, on_plane = 0, inverting_left = 0, first_pass = 0, parallel_left = 0, rebuilds = 0, max_rebuilds = 0;
  std::int64_t squares_compared = 0, duplicates = 0;
  std::map<std::string, std::int64_t> pairs;
  std::int64_t tets = 0;
  FacetBoxStats s;
  double worst_aspect = 0, min_dihedral = 180;
};

// Distance from point p to segment [a, b] (a measurement).
double point_segment_distance(Vec3 p, Vec3 a, Vec3 b) {
  const Vec3 u = b - a;
  const double uu = dot(u, u);
  const double s = uu > 0 ? std::clamp(dot(p - a, u) / uu, 0.0, 1.0) : 0.0;
  return norm(p - (a + s * u));
}

// Lemma 6's h for a pair of I-vertices (thesis §4.3): "the size of the
// smallest box containing x, y", read as the smallest box containing x or y,
// which is what the proof uses (the second pass moves a box vertex v by
// h(v)/16, h(v) the smallest box containing v). Boxes are the octree's
// leaves, the cells of a united vertex box included: the same h(v) as the
// warp's (CornerSet::finest_level). Each I-vertex is located by its defining
// feature on the prewarped grid: a box vertex by its grid point, a facet
// crossing by the midpoint of its ring segment, an edge crossing by the
// centre of its square (the open segment and the open square lie in the same
// leaves as those points).
class PairBoxSide {
 public:
  explicit PairBoxSide(const OctTree& tree) : tree_(tree) {}
  double operator()(const VertexKey& x, const VertexKey& y) { return std::min(smallest(x), smallest(y)); }

 private:
  double smallest(const VertexKey& k) {
    auto [it, fresh] = memo_.try_emplace(k, INFINITY);
    if (!fresh) return it->second;
    Vec3 at = grid_coordinates(tree_, k.p);
    if (k.kind == VertexKind::FacetCrossing) at = 0.5 * (at + grid_coordinates(tree_, k.q));
    tree_.leaves_containing({at.x, at.y, at.z}, leaves_);
    for (const std::int32_t n : leaves_) it->second = std::min(it->second, tree_.side(n));
    return it->second;
  }
  const OctTree& tree_;
  std::unordered_map<VertexKey, double, VertexKeyHash> memo_;
  std::vector<std::int32_t> leaves_;
};

// Shapes per kind and the Lemma 6 ratios of mesh m.
void measure_kinds(const BoxMesh& m, const std::vector<BoxJob>& jobs, const OctTree& tree, const CornerSet& corners,
                   const Domain3& d, KindShapes& k, Lemma6Pairs& l6) {
  PairBoxSide pair_side(tree);
  const char* kind_names[] = {"Grid", "FacetCrossing", "ChordMidpoint", "ChordProjection", "BoxOnFacet",
                              "FacetCentre", "BoxClip", "Warped", "EdgeCrossing", "CrossingProjection",
                              "EdgeMidpoint", "PVertex", "TwoFacetApex", "TwoFacetCentre"};
  // Interior dihedral angle at edge e (radians) from the outward unit normals.
  auto interior_angle = [&](const EdgeCone& ec) {
    const double c = std::clamp(dot(ec.f().normal(), ec.g().normal()), -1.0, 1.0);
    return ec.convex() ? std::acos(-1.0) - std::acos(c) : std::acos(-1.0) + std::acos(c);
  };
  // Whether I-vertex v lies on the wedge of edge box e: on F or G, on E, or a
  // box vertex strictly inside P's wedge (between the facets).
  auto on_wedge = [&](int v, const EdgeCone& ec) {
    const VertexKey& key = m.keys[static_cast<std::size_t>(v)];
    if (key.kind == VertexKind::FacetCrossing) return key.facet == ec.f().facet() || key.facet == ec.g().facet();
    if (key.kind == VertexKind::EdgeCrossing) return key.facet == ec.edge();
    return ec.status(m.mesh.vertices[static_cast<std::size_t>(v)]) == Sign::Negative;
  };
  // Whether box vertex v ended nearer than h(v)/16 to the plane of the facet
  // that crossing x lies on: the second pass's clearance was refused or
  // shortened there (warp.hpp acceptance rules; docs/algorithm/tet3d_warp.md
  // "Side rules").
  auto short_of_its_facet = [&](int x, int v) {
    const VertexKey& kx = m.keys[static_cast<std::size_t>(x)];
    const VertexKey& kv = m.keys[static_cast<std::size_t>(v)];
    if (kx.kind != VertexKind::FacetCrossing || (kv.kind != VertexKind::Grid && kv.kind != VertexKind::Warped))
      return false;
    const Vec3 along = m.mesh.vertices[static_cast<std::size_t>(v)] - m.mesh.vertices[static_cast<std::size_t>(x)];
    const double to_plane = std::abs(dot(along, d.facet_normals[static_cast<std::size_t>(kx.facet)]));
    return to_plane < pair_side(kv, kv) / 16;
  };
  // Whether x, y are crossings of one facet F with two ring segments from a
  // common box vertex v (the case of the thesis's Fig. 4.8, bounded there by
  // v's clearance from F) and v, as warped (often outside P, so read from
  // the warp table, its Fig. 4.7 copy for F if it has one), ended nearer than
  // h(v)/16 to F's plane.
  auto one_vertex_short = [&](int x, int y) {
    const VertexKey& kx = m.keys[static_cast<std::size_t>(x)];
    const VertexKey& ky = m.keys[static_cast<std::size_t>(y)];
    if (kx.kind != VertexKind::FacetCrossing || ky.kind != VertexKind::FacetCrossing || kx.facet != ky.facet ||
        m.warps == nullptr)
      return false;
    for (const GridPoint& v : {kx.p, kx.q}) {
      if (v != ky.p && v != ky.q) continue;
      const Warp* w = m.warps->find(v);
      const Vec3 at = m.warps->at_for_cut(v, kx.facet, w != nullptr ? w->at : grid_coordinates(tree, v));
      const Vec3 along = at - m.mesh.vertices[static_cast<std::size_t>(x)];
      const double to_plane = std::abs(dot(along, d.facet_normals[static_cast<std::size_t>(kx.facet)]));
      if (to_plane < pair_side(grid_key(v), grid_key(v)) / 16) return true;
    }
    return false;
  };
  // Whether facet crossing y lies nearer than h(y)/8 to P edge E: y lies on
  // its warped ring segment, so that segment stayed nearer than h/8 to E,
  // the first pass's clearance refused there (warp.hpp).
  auto short_of_edge = [&](int y, int edge) {
    const VertexKey& ky = m.keys[static_cast<std::size_t>(y)];
    if (edge < 0 || ky.kind != VertexKind::FacetCrossing) return false;
    const DomainEdge& e = d.edges[static_cast<std::size_t>(edge)];
    const Vec3 at = m.mesh.vertices[static_cast<std::size_t>(y)];
    const double to_edge = point_segment_distance(at, d.plc.vertices[static_cast<std::size_t>(e.a)],
                                                  d.plc.vertices[static_cast<std::size_t>(e.b)]);
    return to_edge < pair_side(ky, ky) / 8;
  };
  // The P edges a pair x, y of a box with job j meets: an edge crossing's
  // edge, and the edge of an edge or two-facet box; either of x, y left
  // short of one of them.
  auto short_of_an_edge = [&](int x, int y, const BoxJob& j) {
    const int box_edge = j.kind == BoxKind::Edge || j.kind == BoxKind::TwoFacet ? j.apex : -1;
    for (const int a : {x, y}) {
      const int b = a == x ? y : x;
      const VertexKey& ka = m.keys[static_cast<std::size_t>(a)];
      if (ka.kind == VertexKind::EdgeCrossing && short_of_edge(b, ka.facet)) return true;
      if (short_of_edge(a, box_edge)) return true;
    }
    return false;
  };
  ASSERT_EQ(m.tet_job.size(), m.mesh.tetrahedra.size());
  auto is_i_vertex = [&](int v) {
    const VertexKey& key = m.keys[static_cast<std::size_t>(v)];
    switch (key.kind) {
      case VertexKind::Grid:
      case VertexKind::Warped: return corners.finest_level(key.p) >= 0;  // a box vertex (not a square or box centre)
      case VertexKind::FacetCrossing:
      case VertexKind::EdgeCrossing: return true;
      default: return false;
    }
  };
  for (std::size_t t = 0; t < m.mesh.tetrahedra.size(); ++t) {
    const BoxJob& j = jobs[static_cast<std::size_t>(m.tet_job[t])];
    const int ki = kind_index(j);
    const auto& tet = m.mesh.tetrahedra[t];
    const auto p = [&](int i) { return m.mesh.vertices[static_cast<std::size_t>(tet[static_cast<std::size_t>(i)])]; };
    const TetQuality q = tetrahedron_quality(p(0), p(1), p(2), p(3));
    k.aspect[static_cast<std::size_t>(ki)] = std::max(k.aspect[static_cast<std::size_t>(ki)], q.aspect_ratio);
    k.dihedral[static_cast<std::size_t>(ki)] = std::min(k.dihedral[static_cast<std::size_t>(ki)], q.min_dihedral_deg);
    ++k.tets[static_cast<std::size_t>(ki)];
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) {
        if (!is_i_vertex(tet[static_cast<std::size_t>(a)]) || !is_i_vertex(tet[static_cast<std::size_t>(b)])) continue;
        const int va = tet[static_cast<std::size_t>(a)], vb = tet[static_cast<std::size_t>(b)];
        const double r = norm(p(a) - p(b)) /
                         pair_side(m.keys[static_cast<std::size_t>(va)], m.keys[static_cast<std::size_t>(vb)]);
        k.lemma6[static_cast<std::size_t>(ki)] = std::min(k.lemma6[static_cast<std::size_t>(ki)], r);
        if (!(r < 1.0 / 16)) continue;
        ++l6.under;
        // The sharp wedges this box holds: its edge (edge and two-facet
        // boxes), or every edge at its P vertex (vertex boxes; the thesis
        // states t for protected edge boxes only,
        // docs/algorithm/tet3d_warp.md "Lemma 6").
        double sharpest = INFINITY;
        const auto try_wedge = [&](int edge) {
          const EdgeCone ec(d, edge);
          const double angle = interior_angle(ec);
          if (ec.convex() && angle < std::acos(-1.0) / 2 && on_wedge(va, ec) && on_wedge(vb, ec))
            sharpest = std::min(sharpest, angle);
        };
        if (j.kind == BoxKind::Edge || j.kind == BoxKind::TwoFacet) try_wedge(j.apex);
        if (j.kind == BoxKind::Vertex)
          for (std::size_t e = 0; e < d.edges.size(); ++e)
            if (d.edges[e].a == j.apex || d.edges[e].b == j.apex) try_wedge(static_cast<int>(e));
        if (std::isfinite(sharpest)) {
          ++l6.sharp;
          l6.sharp_min = std::min(l6.sharp_min, r / sharpest);
          continue;
        }
        if (short_of_its_facet(va, vb) || short_of_its_facet(vb, va) || short_of_an_edge(va, vb, j)) {
          ++l6.short_warp;
          l6.short_min = std::min(l6.short_min, r);
          continue;
        }
        if (one_vertex_short(va, vb)) {
          ++l6.one_vertex;
          l6.one_vertex_min = std::min(l6.one_vertex_min, r);
          continue;
        }
        if (r < l6.other_min) {
          l6.other_min = r;
          l6.other_what = std::string(kKindNames[ki]) + " box: " +
                          kind_names[static_cast<int>(m.keys[static_cast<std::size_t>(va)].kind)] + " - " +
                          kind_names[static_cast<int>(m.keys[static_cast<std::size_t>(vb)].kind)];
        }
      }
  }
}

// Meshes every leaf of d's octree; returns false (skipped) when a leaf has no job.
bool mesh_whole(const Domain3& d, const char* what, int seed, Totals& tot, bool separate = false, bool generic = false) {
  mv3d::OctreeOptions opt;
  opt.separate = separate;
  opt.generic_grid = generic;
  mv3d::OctreeBuilder b(d, opt);
  b.build();
  const BoxJobs jobs = box_jobs(b);
  if (!jobs.problems.empty()) {
    std::printf("%s %d: skipped, %zu leaves without a job, e.g. %s\n", what, seed, jobs.problems.size(),
                jobs.problems[0].c_str());
    ++tot.skipped;
    return false;
  }
  const CornerSet corners(b);
  BoxMesh m;
  BoxMeshOptions mo;
  mo.warp = tot.warp;
  mo.keep_warp_table = true;
  try {
    m = mesh_boxes(b.tree(), corners, d, jobs.jobs, mo);
  } catch (const InternalError& e) {
    // The dispatcher's refusal of a square crowded beyond the thesis's cases
    // (possible without the separating splits) is a skip; any other
    // InternalError (an inverted tetrahedron, ...) is a failure.
    if (separate || std::string(e.what()).find(" meets vertices {") == std::string::npos) throw;
    std::printf("%s %d: skipped, %s\n", what, seed, e.what());
    ++tot.skipped;
    return false;
  }
  // Not on the generic grid (the corpus probe below only measures): on
  // prongs_slot one side of some squares lists each triangle twice there
  // (duplicated cube components; check_mesh below still runs).
  if (!generic) tot.squares_compared += squares_agree(b, corners, d, jobs.jobs, tot.pairs);
  if (tot.meshed == 0) {  // determinism: the same arrays from a second run
    const BoxMesh again = mesh_boxes(b.tree(), corners, d, jobs.jobs, mo);
    EXPECT_EQ(m.mesh.tetrahedra, again.mesh.tetrahedra);
    EXPECT_EQ(m.keys, again.keys);
    bool same = m.mesh.vertices.size() == again.mesh.vertices.size();
    for (std::size_t i = 0; same && i < m.mesh.vertices.size(); ++i)
      same = m.mesh.vertices[i].x == again.mesh.vertices[i].x && m.mesh.vertices[i].y == again.mesh.vertices[i].y &&
             m.mesh.vertices[i].z == again.mesh.vertices[i].z;
    EXPECT_TRUE(same);
  }
  tot.duplicates += b.stats().duplicates;
  const CheckReport r = check_mesh(m.mesh, d);
  EXPECT_TRUE(r.valid()) << what << " " << seed << ": " << r.to_text();
  const QualityReport q = quality_report(m.mesh);
  measure_kinds(m, jobs.jobs, b.tree(), corners, d, tot.kinds, tot.l6);
  tot.warped += m.warped;
  tot.bisected += m.warp_bisected;
  tot.fallback += m.warp_fallback;
  tot.conflicts += m.warp_conflicts;
  tot.reflex_left += m.warp_reflex_left;
  tot.crowded_left += m.warp_crowded_left;
  tot.on_plane += m.warp_on_plane;
  tot.inverting_left += m.warp_inverting_left;
  tot.first_pass += m.warp_first_pass;
  tot.rebuilds += m.warp_rebuilds;
  tot.max_rebuilds = std::max(tot.max_rebuilds, m.warp_rebuilds);
  tot.parallel_left += m.warp_parallel_left;
  ++tot.meshed;
  tot.tets += static_cast<std::int64_t>(m.mesh.tetrahedra.size());
  const FacetBoxStats& s = m.stats;
  tot.s.empty += s.empty;
  tot.s.inside += s.inside;
  tot.s.on_facet += s.on_facet;
  tot.s.beyond += s.beyond;
  tot.s.edge += s.edge;
  tot.s.edge_apex_moved += s.edge_apex_moved;
  tot.s.vertex += s.vertex;
  tot.s.two_facet += s.two_facet;
  tot.s.two_facet_centre += s.two_facet_centre;
  tot.s.two_facet_reflex += s.two_facet_reflex;
  tot.s.vertex_squares_by_neighbours += s.vertex_squares_by_neighbours;
  tot.s.vertex_squares_located += s.vertex_squares_located;
  tot.s.squares_nothing += s.squares_nothing;
  tot.s.squares_a += s.squares_a;
  tot.s.squares_c += s.squares_c;
  tot.s.squares_bd += s.squares_bd;
  tot.worst_aspect = std::max(tot.worst_aspect, q.aspect_ratio.max);
  tot.min_dihedral = std::min(tot.min_dihedral, q.min_angle.min);
  return true;
}

void print(const char* what, const Totals& t) {
  std::printf("%s, %s:", what, t.warp ? "WARPED" : "unwarped");
  for (int k = 0; k < kKinds; ++k) {
    const std::size_t i = static_cast<std::size_t>(k);
    if (t.kinds.tets[i] > 0)
      std::printf(" %s aspect %.1f dihedral %.2f lemma6 %.4f;", kKindNames[k], t.kinds.aspect[i], t.kinds.dihedral[i],
                  t.kinds.lemma6[i]);
  }
  std::printf("\n  Lemma 6 pairs under h/16: %lld, of which sharp-edge pairs %lld (min d / (h a) %.4f), at a box vertex "
              "or edge left short %lld (min d / h %.4f), crossings of one facet from a box vertex left short %lld (min d / h "
              "%.4f); others: min d / h %.4f (%s)",
              static_cast<long long>(t.l6.under), static_cast<long long>(t.l6.sharp), t.l6.sharp_min,
              static_cast<long long>(t.l6.short_warp), t.l6.short_min, static_cast<long long>(t.l6.one_vertex),
              t.l6.one_vertex_min, t.l6.other_min, t.l6.other_what.c_str());
  std::printf("\n  warping: moved %lld (first pass %lld, parallel left %lld; bisector %lld, fallback %lld), left: side conflict %lld, reflex %lld, crowded %lld, inverting %lld (tables rebuilt %lld, at most %lld per mesh); on a plane %lld\n",
              static_cast<long long>(t.warped), static_cast<long long>(t.first_pass),
              static_cast<long long>(t.parallel_left), static_cast<long long>(t.bisected), static_cast<long long>(t.fallback),
              static_cast<long long>(t.conflicts),
              static_cast<long long>(t.reflex_left), static_cast<long long>(t.crowded_left),
              static_cast<long long>(t.inverting_left), static_cast<long long>(t.rebuilds),
              static_cast<long long>(t.max_rebuilds),
              static_cast<long long>(t.on_plane));
  std::printf(
      "%s: %d meshed, %d skipped; %lld tets; boxes: empty %lld, facet %lld (inside %lld / on F %lld / beyond %lld), "
      "edge %lld, vertex %lld, two-facet %lld; squares: nothing %lld, A %lld, C %lld, B/D %lld; worst aspect %.1f, "
      "min dihedral %.2f deg\n",
      what, t.meshed, t.skipped, static_cast<long long>(t.tets), static_cast<long long>(t.s.empty),
      static_cast<long long>(t.s.inside + t.s.on_facet + t.s.beyond), static_cast<long long>(t.s.inside),
      static_cast<long long>(t.s.on_facet), static_cast<long long>(t.s.beyond), static_cast<long long>(t.s.edge),
      static_cast<long long>(t.s.vertex), static_cast<long long>(t.s.two_facet),
      static_cast<long long>(t.s.squares_nothing), static_cast<long long>(t.s.squares_a),
      static_cast<long long>(t.s.squares_c), static_cast<long long>(t.s.squares_bd), t.worst_aspect, t.min_dihedral);
  std::printf(
      "  two-facet boxes coned from the centre %lld (reflex %lld); duplicate leaves %lld; squares compared from both "
      "sides: %lld;",
      static_cast<long long>(t.s.two_facet_centre), static_cast<long long>(t.s.two_facet_reflex),
      static_cast<long long>(t.duplicates),
              static_cast<long long>(t.squares_compared));
  for (const auto& [k, n] : t.pairs) std::printf(" %s %lld", k.c_str(), static_cast<long long>(n));
  std::printf("\n  vertex-box squares meeting no face: %lld decided from neighbouring squares, %lld by locate()\n",
              static_cast<long long>(t.s.vertex_squares_by_neighbours),
              static_cast<long long>(t.s.vertex_squares_located));
}

// Every test runs unwarped and warped (§4.3 second pass, warp.hpp).
class AllBoxes : public ::testing::TestWithParam<bool> {};

// Lemma 6's k1 (t = k1 h a): the smallest d / (h a) measured over the warped
// sets below is 0.0112 (random tetrahedra), rounded down.
constexpr double kLemma6K1 = 0.01;

// Lemma 6 over a warped run (Lemma6Pairs).
void expect_lemma6(const Totals& t) {
  // Lemma 6 in the thesis's form: every pair closer than h/16 is a sharp-edge
  // pair with d >= k1 h a, or one of the two forms where our warp may stop
  // short of the thesis's clearances (the side rule's refusals), each held
  // to a flat floor of 0.0015 h: a crossing with a box vertex or ring
  // segment left short of that facet or edge (measured 0.0051 h, stars), and
  // two crossings of one facet from a box vertex left short of it (0.0106 h,
  // stars).
  EXPECT_FALSE(t.l6.other_min < 1.0 / 16) << "a pair closer than h/16 of no listed form: " << t.l6.other_min
                                          << " h, " << t.l6.other_what;
  EXPECT_GE(t.l6.sharp_min, kLemma6K1) << "sharp-edge pairs: d / (h a)";
  EXPECT_GE(t.l6.short_min, 0.0015) << "pairs at a box vertex or segment left short: d / h";
  EXPECT_GE(t.l6.one_vertex_min, 0.0015) << "crossings of one facet from a box vertex left short: d / h";
}

// Measured floors with warping on (§4.3 both passes, warp.hpp; they fail
// unwarped): Lemma 6 in the form of expect_lemma6 (every pair of I-vertices
// under h/16 is of a form listed in Lemma6Pairs), and ceilings on the worst
// aspect ratio per box kind, each above the largest measured value (facet
// 740, vertex 173, two-facet 375, edge 1,520 on the stars). Edge boxes get
// the highest: E clipping a box within h/8 of a box edge puts two Case B
// vertices close together (docs/algorithm/tet3d_warp.md).
void expect_warp_floors(const Totals& t) {
  if (!t.warp) return;
  EXPECT_GT(t.warped, 0);
  expect_lemma6(t);
  EXPECT_LE(t.kinds.aspect[1], 1000.0) << "worst facet-box aspect ratio";
  EXPECT_LE(t.kinds.aspect[3], 500.0) << "worst vertex-box aspect ratio";
  EXPECT_LE(t.kinds.aspect[4], 800.0) << "worst two-facet-box aspect ratio";
  EXPECT_LE(t.kinds.aspect[2], 1600.0) << "worst edge-box aspect ratio";
}

// Meshes `count` domains drawn in turn from one random stream (make(rng)),
// prints their totals under `title` and checks the warping floors.
template <class MakePlc>
Totals mesh_stream(std::uint64_t stream, int count, bool warp, const char* what, const char* title, MakePlc make) {
  std::mt19937_64 rng(stream);
  Totals t;
  t.warp = warp;
  for (int seed = 0; seed < count; ++seed) {
    const Domain3 d = make_domain(make(rng));
    mesh_whole(d, what, seed, t);
  }
  print(title, t);
  expect_warp_floors(t);
  return t;
}

TEST_P(AllBoxes, RandomTetrahedra) {
  const Totals t = mesh_stream(20261130, 8, GetParam(), "tetrahedron", "random tetrahedra", random_tetrahedron);
  EXPECT_GE(t.meshed, 6);
  EXPECT_GT(t.s.edge, 0);
  // Some edge box takes a point of E other than the midpoint (both runs).
  EXPECT_GT(t.s.edge_apex_moved, 0);
  EXPECT_GT(t.s.vertex, 0);
}

TEST_P(AllBoxes, RandomStarPolyhedra) {
  const Totals t = mesh_stream(77, 2, GetParam(), "star", "random star polyhedra", random_star);
  EXPECT_GE(t.meshed, 1);
}

TEST_P(AllBoxes, RandomLPrisms) {
  const Totals t = mesh_stream(5, 3, GetParam(), "L-prism", "random L-prisms", random_l_prism);
  EXPECT_GE(t.meshed, 2);
  EXPECT_GT(t.duplicates, 0);  // duplicated cubes occur (each component meshed on its own)
  EXPECT_GT(t.s.two_facet, 0);
}

// Regression: the fifth notch prism of this stream has duplicated edge boxes
// at the notch mouth whose shared bottom facet crosses a square on one
// component's side only; testing facets by their triangles gave that square
// to both components (overlapping tetrahedra, hanging vertices). Facets of
// edge boxes are now tested by their half-plane from the edge.
TEST_P(AllBoxes, NotchPrismDuplicatesShareAFacet) {
  std::mt19937_64 rng(20261130);
  Plc3 plc;
  for (int seed = 0; seed < 5; ++seed) plc = random_notch_prism(rng);
  Totals t;
  t.warp = GetParam();
  EXPECT_TRUE(mesh_whole(make_domain(plc), "notch prism", 4, t));
  print("notch prism 4", t);
  expect_warp_floors(t);
  EXPECT_GT(t.duplicates, 0);
}

// With the separating splits of §4.1.7 steps 6 and 9 every leaf is of a
// thesis kind (no "other" leaf), so every tetrahedron must be meshed; one
// tetrahedron only (about 50k tets, for test time).
TEST_P(AllBoxes, SeparatedOctreeTetrahedron) {
  std::mt19937_64 rng(20261130);
  Plc3 plc;
  for (int seed = 0; seed < 3; ++seed) plc = random_tetrahedron(rng);
  Totals t;
  t.warp = GetParam();
  EXPECT_TRUE(mesh_whole(make_domain(plc), "separated tetrahedron", 2, t, true));
  print("separated octree, tetrahedron 2", t);
  expect_warp_floors(t);
}

// Lemma 6 on the corpus (docs/algorithm/tet3d_warp.md "Lemma 6"): tet_mesh's
// octree (separating splits, generic grid), warped; prints the pairs under h/16
// (Lemma6Pairs). A measurement, run by hand: test_tet3d
// --gtest_also_run_disabled_tests --gtest_filter='*CorpusLemma6*'
TEST(AllBoxesProbe, DISABLED_CorpusLemma6) {
  for (const char* model : {"cube.poly", "l_block.poly", "star_vertex.poly", "wedge_5deg.poly", "schoenhardt.poly",
                            "tuning_fork.poly", "heat_sink.poly", "plate_holes.poly", "prongs_slot.poly", "fins.poly"}) {
    const Domain3 d = make_domain(read_plc(test::data_path(std::string("3d/") + model)));
    Totals t;
    t.warp = true;
    if (mesh_whole(d, model, 0, t, true, true)) print(model, t);
  }
}

// Lemma 6 on the corpus models with sharp or crowded features (the others
// have no pair under h/16: docs/algorithm/tet3d_warp.md "Lemma 6"), on
// tet_mesh's octree (separating splits, generic grid), warped.
class CorpusLemma6 : public ::testing::TestWithParam<const char*> {};

TEST_P(CorpusLemma6, PairsUnderHOver16AreSharpOrLeftShort) {
  const Domain3 d = make_domain(read_plc(test::data_path(std::string("3d/") + GetParam())));
  Totals t;
  t.warp = true;
  ASSERT_TRUE(mesh_whole(d, GetParam(), 0, t, true, true));
  print(GetParam(), t);
  expect_lemma6(t);
}

INSTANTIATE_TEST_SUITE_P(Warp, CorpusLemma6,
                         ::testing::Values("star_vertex.poly", "wedge_5deg.poly", "schoenhardt.poly", "l_block.poly"));

// The corpus models have dyadic coordinates: P edges and vertices lie on box
// planes of the octree, which the square dispatcher refuses (Cases B/D throw
// "the edge meets the square's boundary": the first warping pass, §4.3, or a
// grid in general position, is needed). Each is either meshed (then valid)
// or throws that InternalError with one of the named reasons (recorded as the
// test's "refused" property): both outcomes pass, any other fails.
class AlignedCorpus : public ::testing::TestWithParam<const char*> {};

TEST_P(AlignedCorpus, MeshedOrRefusedAsAligned) {
  const Domain3 d = make_domain(read_plc(test::data_path(std::string("3d/") + GetParam())));
  Totals t;
  try {
    mesh_whole(d, GetParam(), 0, t);
  } catch (const InternalError& e) {
    const std::string what = e.what();
    EXPECT_TRUE(what.find("meets the square's boundary") != std::string::npos ||
                what.find("lies in the square's plane") != std::string::npos ||
                what.find("lies on the edge") != std::string::npos)
        << what;
    RecordProperty("refused", what);
  }
}

INSTANTIATE_TEST_SUITE_P(Warp, AllBoxes, ::testing::Bool(),
                         [](const ::testing::TestParamInfo<bool>& i) { return i.param ? "warped" : "unwarped"; });

INSTANTIATE_TEST_SUITE_P(Corpus, AlignedCorpus, ::testing::Values("schoenhardt.poly", "star_vertex.poly"));

}  // namespace
}  // namespace pqmesh::tet3d
