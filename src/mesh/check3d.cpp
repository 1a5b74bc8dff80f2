// The validity checker for tetrahedral meshes (DESIGN.md §7).
//
// ---------------------------------------------------------------------------
// What is checked, and why it is enough
// ---------------------------------------------------------------------------
// Every decision below is an exact predicate on the input doubles
// (src/predicates) or an integer comparison; the one exception is the Volume
// measurement, which is reported as a measurement.
//
// Stage 2: orient3d(a, b, c, d) > 0 for every tetrahedron (mesh.hpp's
//   convention). Zero is DegenerateElement, negative is Orientation.
//
// Stage 3: the faces (sorted vertex triples) are collected by a counting sort
//   on their smallest vertex and a small sort inside each bucket. A face lies
//   on one or two tetrahedra; two tetrahedra sharing it must traverse it with
//   opposite orientation (with positive volumes this says they lie on opposite
//   sides). Writing T for the sum of the tetrahedra as oriented 3-chains and B
//   for the faces on one tetrahedron, each oriented outward (right-hand normal
//   out of the mesh), stage 3 therefore gives dT = B. B must be a closed
//   2-manifold: every edge of B on exactly two of its triangles, once in each
//   direction. A vertex lying on a triangle of B (a hanging vertex: the
//   elements there do not meet face to face) is searched for directly from the
//   triangle's corners along edges of B, which finds every vertex of a
//   subdivision of that triangle on the other side.
//
// Stage 4 (with the domain P, facets oriented outward):
//   (a) every triangle of B is assigned to a facet f: exactly coplanar with f
//       (orient3d = 0 against three non-collinear vertices of f), within f's
//       bounding box, and, only when several coplanar facets qualify, with its
//       three vertices in the closed facet polygon (exact crossing test in the
//       projection that drops the dominant axis of f's normal). Its
//       orientation must agree with f's (exact, in the same projection).
//       Exactness means that a vertex constructed in double near a slanted
//       facet, but not exactly in its plane, makes its triangles fail here.
//   (b) every input edge (DomainEdge) is walked from its first to its second
//       vertex along edges of B, each step to the unique B-neighbour lying on
//       the edge strictly closer to the end (collinear by three projected
//       orient2d = 0, between by dot_sign < 0). Failure is MissingEdge.
//   (c) for every facet f, the boundary of B_f (the triangles assigned to f)
//       is computed combinatorially as signed counts of undirected mesh edges,
//       and compared with the boundary of f: its loops, each side replaced by
//       the chain of mesh edges found in (b). They must be equal.
//
// Sufficiency. A combinatorial equality of 1-chains implies the geometric one,
// so by (c) B_f - f is a 2-chain in the plane of f without boundary, hence
// zero: B_f = f. Summing over facets, B = dP, and T - P is a 3-chain without
// boundary, hence zero. Since every tetrahedron is positive, the number of
// tetrahedra containing a point x (the winding number of T) is 1 for almost
// every x in P and 0 outside. So the tetrahedra cover P without overlaps or
// gaps; the total volume is vol(P) up to rounding; no vertex used by a
// tetrahedron lies outside P. They also meet face to face: if a vertex v lay
// in the relative interior of a face or an edge s of a tetrahedron, v not a
// vertex of s, then where s meets the interior of P the tetrahedra around s
// close up (the faces containing s are matched, since B lies in dP) and cover
// a neighbourhood of v that the tetrahedra with vertex v also cover, i.e. some
// point twice; where s lies in dP the same happens one dimension lower among
// the boundary triangles, which tile each facet exactly once (B_f = f with
// every triangle oriented like f). Finally every input vertex is found by
// exact coordinates, every input edge is a chain of mesh edges by (b), and
// every facet is a union of boundary triangles by (c).
//
// Without a domain (check_mesh_topology) only stages 1-3 run. They are local:
// a mesh that covers a region twice (winding number 2) can pass them.
//
// Redundant second opinions: the Volume measurement (relative tolerance, both
// numbers reported) and locate() on every vertex (VertexOutside).
//
// Known conservative case: if two coplanar facets share a boundary and a
// triangle has all three vertices in both closed facets, it is assigned to the
// lower-numbered one; were it geometrically in the other, (c) reports a
// MissingFacet. The checker never accepts an invalid mesh for this reason.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/check_common.hpp"
#include "plc/point_location.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/errors.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh {
namespace {

using detail::format_ids;
using detail::format_point;
using detail::IssueSink;

// Outward faces of a positive tetrahedron (a, b, c, d): the face opposite each
// vertex, ordered so that its right-hand normal points away from that vertex.
constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

double coord(Vec3 p, int axis) { return axis == 0 ? p.x : (axis == 1 ? p.y : p.z); }

// Exact: a, b, c on one line (all three coordinate projections degenerate).
bool collinear(Vec3 a, Vec3 b, Vec3 c) {
  return orient2d_projected(a, b, c, 0) == Sign::Zero && orient2d_projected(a, b, c, 1) == Sign::Zero &&
         orient2d_projected(a, b, c, 2) == Sign::Zero;
}

// p inside the closed axis-aligned box of a and b (exact comparisons).
bool in_box(Vec3 p, Vec3 a, Vec3 b) {
  return p.x >= std::min(a.x, b.x) && p.x <= std::max(a.x, b.x) && p.y >= std::min(a.y, b.y) &&
         p.y <= std::max(a.y, b.y) && p.z >= std::min(a.z, b.z) && p.z <= std::max(a.z, b.z);
}

// An axis whose projection keeps the nondegenerate triangle abc nondegenerate,
// preferring the dominant axis of its normal (a construction, only a hint: the
// choice is verified exactly). Returns -1 when abc is degenerate.
int projection_axis(Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 n = cross(b - a, c - a);
  const double m[3] = {std::abs(n.x), std::abs(n.y), std::abs(n.z)};
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int i, int j) { return m[i] > m[j] || (m[i] == m[j] && i < j); });
  for (int axis : order)
    if (orient2d_projected(a, b, c, axis) != Sign::Zero) return axis;
  return -1;
}

// The faces of a mesh, collected and matched (stage 3).
struct FaceTable {
  std::vector<std::array<int, 3>> boundary;  // faces on one tetrahedron, oriented outward
  std::vector<int> boundary_tet;
  detail::Adjacency boundary_adjacency;      // edges of the boundary triangles
};

// A facet of the domain prepared for exact containment tests.
struct FacetPlane {
  bool ok = false;
  Vec3 p0, p1, p2;  // three non-collinear vertices: the plane
  int axis = 2;     // projection axis (dropped coordinate)
  Sign turn = Sign::Zero;  // orientation of the outer loop in that projection
  Vec3 lo, hi;      // bounding box
};

// A uniform grid over facet bounding boxes. The cell of a coordinate is a
// monotone function of it, so a point inside a facet's box falls in a cell
// that the facet was entered into.
class FacetGrid {
 public:
  FacetGrid(const std::vector<FacetPlane>& planes, Vec3 lo, Vec3 hi) : lo_(lo) {
    const int nf = static_cast<int>(planes.size());
    const int per_axis = std::clamp(static_cast<int>(std::cbrt(static_cast<double>(nf))) + 1, 1, 32);
    const double ext[3] = {hi.x - lo.x, hi.y - lo.y, hi.z - lo.z};
    for (int a = 0; a < 3; ++a) {
      n_[a] = ext[a] > 0 ? per_axis : 1;
      scale_[a] = ext[a] > 0 ? n_[a] / ext[a] : 0;
    }
    offset_.assign(static_cast<std::size_t>(n_[0]) * n_[1] * n_[2] + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<int> fill;
      if (pass == 1) {
        for (std::size_t c = 1; c < offset_.size(); ++c) offset_[c] += offset_[c - 1];
        items_.resize(offset_.back());
        fill.assign(offset_.begin(), offset_.end() - 1);
      }
      for (int f = 0; f < nf; ++f) {
        if (!planes[f].ok) continue;
        const auto a = cell(planes[f].lo), b = cell(planes[f].hi);
        for (int i = a[0]; i <= b[0]; ++i)
          for (int j = a[1]; j <= b[1]; ++j)
            for (int k = a[2]; k <= b[2]; ++k) {
              const int c = index({i, j, k});
              if (pass == 0)
                ++offset_[c + 1];
              else
                items_[fill[c]++] = f;  // facets in increasing id within each cell
            }
      }
    }
  }
  std::span<const int> at(Vec3 p) const {
    const int c = index(cell(p));
    return {items_.data() + offset_[c], items_.data() + offset_[c + 1]};
  }

 private:
  std::array<int, 3> cell(Vec3 p) const {
    std::array<int, 3> out{};
    for (int a = 0; a < 3; ++a) {
      const double t = std::floor((coord(p, a) - coord(lo_, a)) * scale_[a]);
      out[a] = t <= 0 ? 0 : (t >= n_[a] - 1 ? n_[a] - 1 : static_cast<int>(t));
    }
    return out;
  }
  int index(std::array<int, 3> c) const { return (c[2] * n_[1] + c[1]) * n_[0] + c[0]; }

  Vec3 lo_;
  int n_[3] = {1, 1, 1};
  double scale_[3] = {0, 0, 0};
  std::vector<int> offset_, items_;
};

class Checker3 {
 public:
  Checker3(const TetMesh3& mesh, const CheckOptions& options, CheckReport& report)
      : m_(mesh), opt_(options), rep_(report), sink_(report, options.max_issues_per_kind) {
    rep_.dimension = 3;
    rep_.vertices = static_cast<std::int64_t>(mesh.vertices.size());
    rep_.elements = static_cast<std::int64_t>(mesh.tetrahedra.size());
  }

  // Stages 1-3 and the volume measurement; returns whether stage 3 is clean.
  bool run_topology() {
    stage1_ok_ = stage1_indices();
    if (!stage1_ok_) {
      sink_.note("orientation, conformity and domain checks skipped: the mesh has bad indices or coordinates");
      return false;
    }
    order_ = detail::sort_by_coordinates(m_.vertices);
    if (!stage2_orientation()) {
      sink_.note("conformity and domain checks skipped: not every tetrahedron is positively oriented");
      return false;
    }
    measure_volume();
    const bool ok = stage3_faces();
    if (!ok) sink_.note("domain checks of boundary faces, edges and facets skipped: the tetrahedra do not meet face to face");
    return ok;
  }

  void run_domain(const Domain3& d, bool topology_ok) {
    rep_.domain_checked = true;
    rep_.domain_volume = d.volume;
    if (!stage1_ok_) return;
    map_input_vertices(d);
    if (topology_ok) {
      prepare_facets(d);
      assign_boundary_faces(d);
      walk_edges(d);
      check_facets(d);
      if (opt_.no_boundary_steiner) check_steiner();
    }
    if (rep_.volume_measured && detail::relative_difference(rep_.mesh_volume, d.volume) > opt_.volume_tolerance) {
      sink_.add(CheckKind::Volume, {},
                "total volume " + detail::format_number(rep_.mesh_volume) + " differs from the domain's " +
                    detail::format_number(d.volume) + " (relative difference " +
                    detail::format_short(detail::relative_difference(rep_.mesh_volume, d.volume)) +
                    " > tolerance " + detail::format_short(opt_.volume_tolerance) + "; a floating-point measurement)");
    }
    if (opt_.locate_vertices) check_located(d);
  }

 private:
  // ---- stage 1 -------------------------------------------------------------
  bool stage1_indices() {
    const auto nv = static_cast<std::int64_t>(m_.vertices.size());
    const std::int64_t before = sink_.count(CheckKind::BadIndex);
    for (std::int64_t v = 0; v < nv; ++v) {
      const Vec3 p = m_.vertices[v];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        sink_.add(CheckKind::BadIndex, {v}, "vertex " + std::to_string(v) + " has a non-finite coordinate");
    }
    auto bad = [&](int i) { return i < 0 || i >= nv; };
    for (std::size_t t = 0; t < m_.tetrahedra.size(); ++t) {
      const auto& q = m_.tetrahedra[t];
      if (bad(q[0]) || bad(q[1]) || bad(q[2]) || bad(q[3]))
        sink_.add(CheckKind::BadIndex, {static_cast<std::int64_t>(t)},
                  "tetrahedron " + std::to_string(t) + " (" + format_ids(q) + ") refers to a vertex outside 0.." +
                      std::to_string(nv - 1));
    }
    for (std::size_t f = 0; f < m_.faces.size(); ++f) {
      const auto& q = m_.faces[f];
      if (bad(q[0]) || bad(q[1]) || bad(q[2]))
        sink_.add(CheckKind::BadIndex, {static_cast<std::int64_t>(f)},
                  "listed boundary face " + std::to_string(f) + " (" + format_ids(q) +
                      ") refers to a vertex outside 0.." + std::to_string(nv - 1));
    }
    auto sized = [&](std::size_t markers, std::size_t items, const char* what) {
      if (markers != 0 && markers != items)
        sink_.add(CheckKind::BadIndex, {},
                  std::string(what) + " has " + std::to_string(markers) + " entries for " + std::to_string(items) +
                      " items (must be empty or equal)");
    };
    sized(m_.vertex_markers.size(), m_.vertices.size(), "vertex_markers");
    sized(m_.tetrahedron_markers.size(), m_.tetrahedra.size(), "tetrahedron_markers");
    sized(m_.face_markers.size(), m_.faces.size(), "face_markers");
    if (m_.tetrahedra.size() >= (std::size_t{1} << 31) - 1)
      sink_.add(CheckKind::BadIndex, {}, "more tetrahedra than int indices can address");
    return sink_.count(CheckKind::BadIndex) == before;
  }

  // ---- stage 2 -------------------------------------------------------------
  bool stage2_orientation() {
    bool ok = true;
    for (std::size_t t = 0; t < m_.tetrahedra.size(); ++t) {
      const auto& q = m_.tetrahedra[t];
      const Sign s = orient3d(m_.vertices[q[0]], m_.vertices[q[1]], m_.vertices[q[2]], m_.vertices[q[3]]);
      if (s == Sign::Positive) continue;
      ok = false;
      const auto id = static_cast<std::int64_t>(t);
      if (s == Sign::Zero)
        sink_.add(CheckKind::DegenerateElement, {id},
                  "tetrahedron " + std::to_string(t) + " (" + format_ids(q) + ") has zero volume");
      else
        sink_.add(CheckKind::Orientation, {id},
                  "tetrahedron " + std::to_string(t) + " (" + format_ids(q) +
                      ") is negatively oriented (orient3d < 0)");
    }
    return ok;
  }

  void measure_volume() {
    detail::CompensatedSum sum;
    for (const auto& q : m_.tetrahedra) {
      const Vec3 a = m_.vertices[q[0]];
      sum.add(dot(m_.vertices[q[1]] - a, cross(m_.vertices[q[2]] - a, m_.vertices[q[3]] - a)) / 6.0);
    }
    rep_.volume_measured = true;
    rep_.mesh_volume = sum.value();
  }

  // ---- stage 3 -------------------------------------------------------------
  bool stage3_faces() {
    const int nv = static_cast<int>(m_.vertices.size());
    const int nt = static_cast<int>(m_.tetrahedra.size());
    const std::int64_t nonconf_before = sink_.count(CheckKind::NonConforming);

    // Face records bucketed by their smallest vertex (counting sort).
    struct Rec {
      int b, c;
      std::uint32_t code;  // (tetrahedron << 1) | parity of the sorting permutation
    };
    auto sorted_face = [&](int t, int f, int& a, int& b, int& c, std::uint32_t& parity) {
      const auto& q = m_.tetrahedra[t];
      int x[3] = {q[kFaces[f][0]], q[kFaces[f][1]], q[kFaces[f][2]]};
      parity = 0;
      if (x[0] > x[1]) std::swap(x[0], x[1]), parity ^= 1;
      if (x[1] > x[2]) std::swap(x[1], x[2]), parity ^= 1;
      if (x[0] > x[1]) std::swap(x[0], x[1]), parity ^= 1;
      a = x[0], b = x[1], c = x[2];
    };
    std::vector<int> start(static_cast<std::size_t>(nv) + 1, 0);
    for (int t = 0; t < nt; ++t)
      for (int f = 0; f < 4; ++f) {
        const auto& q = m_.tetrahedra[t];
        ++start[std::min({q[kFaces[f][0]], q[kFaces[f][1]], q[kFaces[f][2]]}) + 1];
      }
    for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
    std::vector<Rec> recs(start[nv]);
    {
      std::vector<int> fill(start.begin(), start.end() - 1);
      for (int t = 0; t < nt; ++t)
        for (int f = 0; f < 4; ++f) {
          int a, b, c;
          std::uint32_t parity;
          sorted_face(t, f, a, b, c, parity);
          recs[fill[a]++] = Rec{b, c, (static_cast<std::uint32_t>(t) << 1) | parity};
        }
    }
    std::vector<char> used(nv, 0);
    for (const auto& q : m_.tetrahedra)
      for (int v : q) used[v] = 1;

    for (int a = 0; a < nv; ++a) {
      auto first = recs.begin() + start[a], last = recs.begin() + start[a + 1];
      std::sort(first, last, [](const Rec& x, const Rec& y) {
        if (x.b != y.b) return x.b < y.b;
        if (x.c != y.c) return x.c < y.c;
        return x.code < y.code;
      });
      for (auto it = first; it != last;) {
        auto run_end = it + 1;
        while (run_end != last && run_end->b == it->b && run_end->c == it->c) ++run_end;
        const long count = run_end - it;
        const int face[3] = {a, it->b, it->c};
        if (count == 1) {
          const bool odd = (it->code & 1u) != 0;
          faces_.boundary.push_back(odd ? std::array<int, 3>{a, it->c, it->b} : std::array<int, 3>{a, it->b, it->c});
          faces_.boundary_tet.push_back(static_cast<int>(it->code >> 1));
        } else if (count == 2) {
          if ((it->code & 1u) == ((it + 1)->code & 1u)) {
            const int t1 = static_cast<int>(it->code >> 1), t2 = static_cast<int>((it + 1)->code >> 1);
            sink_.add(CheckKind::NonConforming, {t1, t2},
                      "tetrahedra " + std::to_string(t1) + " and " + std::to_string(t2) +
                          " lie on the same side of their common face (" + format_ids(face) + "): they overlap");
          }
        } else {
          std::vector<std::int64_t> ids;
          std::vector<int> tets;
          for (auto r = it; r != run_end; ++r) {
            ids.push_back(r->code >> 1);
            tets.push_back(static_cast<int>(r->code >> 1));
          }
          sink_.add(CheckKind::NonConforming, std::move(ids),
                    "face (" + format_ids(face) + ") is on " + std::to_string(count) + " tetrahedra: " +
                        format_ids(tets));
        }
        it = run_end;
      }
    }
    recs = {};
    start = {};
    rep_.boundary_faces = static_cast<std::int64_t>(faces_.boundary.size());

    for (int v = 0; v < nv; ++v)
      if (!used[v])
        sink_.add(CheckKind::UnusedVertex, {v},
                  "vertex " + std::to_string(v) + " at " + format_point(m_.vertices[v]) + " is on no tetrahedron");

    // Two vertices with exactly the same coordinates cannot be told apart by
    // geometry; elements using one or the other do not share faces.
    for (std::size_t i = 0; i + 1 < order_.size();) {
      std::size_t j = i + 1;
      while (j < order_.size() && m_.vertices[order_[j]] == m_.vertices[order_[i]]) ++j;
      if (j - i > 1) {
        std::vector<std::int64_t> ids(order_.begin() + static_cast<long>(i), order_.begin() + static_cast<long>(j));
        std::vector<int> vs(order_.begin() + static_cast<long>(i), order_.begin() + static_cast<long>(j));
        sink_.add(CheckKind::NonConforming, std::move(ids),
                  "vertices " + format_ids(vs) + " have the same coordinates " +
                      format_point(m_.vertices[order_[i]]));
      }
      i = j;
    }

    build_boundary_edges();
    find_hanging_vertices();
    const bool conforming = sink_.count(CheckKind::NonConforming) == nonconf_before;
    // A hanging vertex also breaks the manifold condition around it; report
    // the latter only when the elements meet face to face.
    const bool manifold = !conforming || check_boundary_manifold();
    check_listed_faces();
    return conforming && manifold;
  }

  // The edges of the boundary triangles, sorted, and their adjacency.
  void build_boundary_edges() {
    bedges_.clear();
    bedges_.reserve(faces_.boundary.size() * 3);
    for (const auto& f : faces_.boundary)
      for (int k = 0; k < 3; ++k) {
        const int x = f[k], y = f[(k + 1) % 3];
        bedges_.push_back(x < y ? BEdge{x, y, 1} : BEdge{y, x, 0});
      }
    std::sort(bedges_.begin(), bedges_.end(), [](const BEdge& a, const BEdge& b) {
      if (a.lo != b.lo) return a.lo < b.lo;
      if (a.hi != b.hi) return a.hi < b.hi;
      return a.forward < b.forward;
    });
    std::vector<std::array<int, 2>> unique;
    for (std::size_t i = 0; i < bedges_.size(); ++i)
      if (i == 0 || bedges_[i].lo != bedges_[i - 1].lo || bedges_[i].hi != bedges_[i - 1].hi)
        unique.push_back({bedges_[i].lo, bedges_[i].hi});
    faces_.boundary_adjacency = detail::make_adjacency(static_cast<int>(m_.vertices.size()), unique);
  }

  // Every edge of the boundary triangles on exactly two of them, once in each
  // direction (closed 2-manifold, consistently oriented).
  bool check_boundary_manifold() {
    bool ok = true;
    for (std::size_t i = 0; i < bedges_.size();) {
      std::size_t j = i;
      int fwd = 0;
      while (j < bedges_.size() && bedges_[j].lo == bedges_[i].lo && bedges_[j].hi == bedges_[i].hi)
        fwd += bedges_[j++].forward;
      const int total = static_cast<int>(j - i), bwd = total - fwd;
      if (fwd != 1 || bwd != 1) {
        ok = false;
        sink_.add(CheckKind::BoundaryFace, {bedges_[i].lo, bedges_[i].hi},
                  "boundary edge (" + std::to_string(bedges_[i].lo) + " " + std::to_string(bedges_[i].hi) +
                      ") is on " + std::to_string(total) + " boundary triangle(s) (" + std::to_string(fwd) +
                      " one way, " + std::to_string(bwd) +
                      " the other; a closed 2-manifold boundary needs exactly one each way)");
      }
      i = j;
    }
    return ok;
  }

  // A vertex on a boundary triangle other than its corners. Searched from the
  // corners along boundary edges, expanding only through vertices that lie on
  // the triangle (each one found is reported, so a valid mesh expands nothing).
  void find_hanging_vertices() {
    std::vector<char> reported(m_.vertices.size(), 0);
    std::vector<int> queue;
    constexpr std::size_t kMaxExpansion = 1024;
    bool capped = false;
    for (std::size_t i = 0; i < faces_.boundary.size(); ++i) {
      const auto& f = faces_.boundary[i];
      const Vec3 a = m_.vertices[f[0]], b = m_.vertices[f[1]], c = m_.vertices[f[2]];
      const int axis = projection_axis(a, b, c);
      if (axis < 0) continue;  // impossible for a face of a positive tetrahedron
      const Sign s = orient2d_projected(a, b, c, axis);
      const Vec3 lo{std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y}), std::min({a.z, b.z, c.z})};
      const Vec3 hi{std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y}), std::max({a.z, b.z, c.z})};
      queue.assign(f.begin(), f.end());
      for (std::size_t head = 0; head < queue.size(); ++head) {
        for (int w : faces_.boundary_adjacency.of(queue[head])) {
          if (std::find(queue.begin(), queue.end(), w) != queue.end()) continue;
          const Vec3 p = m_.vertices[w];
          if (!in_box(p, lo, hi)) continue;
          if (orient3d(a, b, c, p) != Sign::Zero) continue;
          if (orient2d_projected(a, b, p, axis) == -s || orient2d_projected(b, c, p, axis) == -s ||
              orient2d_projected(c, a, p, axis) == -s)
            continue;
          if (queue.size() >= kMaxExpansion) {
            capped = true;
            break;
          }
          queue.push_back(w);
          if (!reported[w]) {
            reported[w] = 1;
            sink_.add(CheckKind::NonConforming, {w, f[0], f[1], f[2]},
                      "vertex " + std::to_string(w) + " at " + format_point(p) + " lies on boundary triangle (" +
                          format_ids(f) + ") of tetrahedron " + std::to_string(faces_.boundary_tet[i]) +
                          " (hanging vertex: the tetrahedra there do not meet face to face)");
          }
        }
      }
    }
    if (capped) sink_.note("hanging-vertex search capped at " + std::to_string(kMaxExpansion) + " vertices per face");
  }

  // TetMesh3::faces, when given, must list every boundary triangle once,
  // oriented outward, and nothing else.
  void check_listed_faces() {
    if (m_.faces.empty()) return;
    struct K {
      std::array<int, 3> v;  // sorted
      int parity;
      int source;  // listed index, or -1 - boundary index
    };
    auto key = [](std::array<int, 3> x, int source) {
      int parity = 0;
      if (x[0] > x[1]) std::swap(x[0], x[1]), parity ^= 1;
      if (x[1] > x[2]) std::swap(x[1], x[2]), parity ^= 1;
      if (x[0] > x[1]) std::swap(x[0], x[1]), parity ^= 1;
      return K{x, parity, source};
    };
    std::vector<K> keys;
    for (std::size_t i = 0; i < faces_.boundary.size(); ++i) keys.push_back(key(faces_.boundary[i], -1 - static_cast<int>(i)));
    for (std::size_t i = 0; i < m_.faces.size(); ++i) keys.push_back(key(m_.faces[i], static_cast<int>(i)));
    std::sort(keys.begin(), keys.end(), [](const K& a, const K& b) {
      if (a.v != b.v) return a.v < b.v;
      return a.source < b.source;  // the boundary face (negative) first
    });
    for (std::size_t i = 0; i < keys.size();) {
      std::size_t j = i;
      while (j < keys.size() && keys[j].v == keys[i].v) ++j;
      const bool is_boundary = keys[i].source < 0;
      const std::size_t first_listed = is_boundary ? i + 1 : i;
      if (is_boundary && first_listed == j) {
        const auto& f = faces_.boundary[-1 - keys[i].source];
        sink_.add(CheckKind::BoundaryFace, {f[0], f[1], f[2]},
                  "boundary triangle (" + format_ids(f) + ") of tetrahedron " +
                      std::to_string(faces_.boundary_tet[-1 - keys[i].source]) + " is missing from TetMesh3::faces");
      }
      for (std::size_t k = first_listed; k < j; ++k) {
        const int l = keys[k].source;
        std::string what;
        if (!is_boundary)
          what = "is not a face on exactly one tetrahedron";
        else if (keys[k].parity != keys[i].parity)
          what = "is listed with inward orientation";
        else if (k > first_listed)
          what = "is listed more than once";
        else
          continue;
        sink_.add(CheckKind::BoundaryFace, {l},
                  "listed boundary face " + std::to_string(l) + " (" + format_ids(m_.faces[l]) + ") " + what);
      }
      i = j;
    }
  }

  // ---- stage 4 -------------------------------------------------------------
  void map_input_vertices(const Domain3& d) {
    const auto& pv = d.plc.vertices;
    in2mesh_.assign(pv.size(), -1);
    mesh2in_.assign(m_.vertices.size(), -1);
    std::vector<char> referenced(pv.size(), 0);
    for (const auto& f : d.plc.facets)
      for (const auto& loop : f.loops)
        for (int v : loop)
          if (v >= 0 && v < static_cast<int>(pv.size())) referenced[v] = 1;
    int unreferenced = 0;
    for (std::size_t i = 0; i < pv.size(); ++i) {
      const int mv = detail::find_vertex(m_.vertices, order_, pv[i]);
      in2mesh_[i] = mv;
      if (mv >= 0) mesh2in_[mv] = static_cast<int>(i);
      if (!referenced[i]) {
        ++unreferenced;
        continue;
      }
      if (mv < 0)
        sink_.add(CheckKind::MissingVertex, {static_cast<std::int64_t>(i)},
                  "input vertex " + std::to_string(i) + " at " + format_point(pv[i]) + " is not a mesh vertex");
    }
    if (unreferenced)
      sink_.note(std::to_string(unreferenced) + " input vertices on no facet were not required to be mesh vertices");
  }

  void prepare_facets(const Domain3& d) {
    const auto& pv = d.plc.vertices;
    planes_.assign(d.plc.facets.size(), FacetPlane{});
    Vec3 lo = pv.empty() ? Vec3{} : pv[0], hi = lo;
    for (const Vec3& p : pv) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    const int npv = static_cast<int>(pv.size());
    for (std::size_t f = 0; f < d.plc.facets.size(); ++f) {
      const auto& loops = d.plc.facets[f].loops;
      FacetPlane& fp = planes_[f];
      bool indices_ok = !loops.empty() && loops[0].size() >= 3;
      for (const auto& loop : loops)
        for (int v : loop) indices_ok = indices_ok && v >= 0 && v < npv;
      if (!indices_ok) {
        sink_.add(CheckKind::MissingFacet, {static_cast<std::int64_t>(f)},
                  "domain facet " + std::to_string(f) + " has an empty outer loop or bad vertex ids; cannot check it");
        continue;
      }
      // Three non-collinear vertices of the facet.
      int i0 = loops[0][0], i1 = -1, i2 = -1;
      for (const auto& loop : loops)
        for (int v : loop) {
          if (i1 < 0) {
            if (!(pv[v] == pv[i0])) i1 = v;
          } else if (i2 < 0 && !collinear(pv[i0], pv[i1], pv[v])) {
            i2 = v;
          }
        }
      if (i2 < 0) {
        sink_.add(CheckKind::MissingFacet, {static_cast<std::int64_t>(f)},
                  "domain facet " + std::to_string(f) + " is degenerate (all vertices collinear); cannot check it");
        continue;
      }
      fp.p0 = pv[i0], fp.p1 = pv[i1], fp.p2 = pv[i2];
      fp.axis = projection_axis(fp.p0, fp.p1, fp.p2);
      // Orientation of the outer loop in the projection: at its
      // lexicographically smallest projected vertex the polygon is convex.
      const auto& outer = loops[0];
      const int u = (fp.axis + 1) % 3, w = (fp.axis + 2) % 3;
      std::size_t k_min = 0;
      for (std::size_t k = 1; k < outer.size(); ++k) {
        const Vec3 p = pv[outer[k]], q = pv[outer[k_min]];
        if (coord(p, u) < coord(q, u) || (coord(p, u) == coord(q, u) && coord(p, w) < coord(q, w))) k_min = k;
      }
      const std::size_t n = outer.size();
      fp.turn = orient2d_projected(pv[outer[(k_min + n - 1) % n]], pv[outer[k_min]], pv[outer[(k_min + 1) % n]],
                                   fp.axis);
      if (fp.turn == Sign::Zero) {
        sink_.add(CheckKind::MissingFacet, {static_cast<std::int64_t>(f)},
                  "domain facet " + std::to_string(f) + " has a degenerate outer loop; cannot check it");
        continue;
      }
      fp.lo = fp.hi = pv[loops[0][0]];
      for (const auto& loop : loops)
        for (int v : loop) {
          const Vec3 p = pv[v];
          fp.lo = {std::min(fp.lo.x, p.x), std::min(fp.lo.y, p.y), std::min(fp.lo.z, p.z)};
          fp.hi = {std::max(fp.hi.x, p.x), std::max(fp.hi.y, p.y), std::max(fp.hi.z, p.z)};
        }
      fp.ok = true;
    }
    grid_lo_ = lo;
    grid_hi_ = hi;
  }

  // Exact: p (already known to be in the facet's plane) lies in the closed
  // facet polygon. Crossing parity of a ray in +u direction, after an exact
  // on-boundary test.
  bool in_closed_facet(const Domain3& d, int f, Vec3 p) const {
    const FacetPlane& fp = planes_[f];
    const auto& pv = d.plc.vertices;
    const int u = (fp.axis + 1) % 3, w = (fp.axis + 2) % 3;
    bool inside = false;
    for (const auto& loop : d.plc.facets[f].loops) {
      const std::size_t n = loop.size();
      for (std::size_t k = 0; k < n; ++k) {
        const Vec3 a = pv[loop[k]], b = pv[loop[(k + 1) % n]];
        const Sign o = orient2d_projected(a, b, p, fp.axis);
        if (o == Sign::Zero && coord(p, u) >= std::min(coord(a, u), coord(b, u)) &&
            coord(p, u) <= std::max(coord(a, u), coord(b, u)) && coord(p, w) >= std::min(coord(a, w), coord(b, w)) &&
            coord(p, w) <= std::max(coord(a, w), coord(b, w)))
          return true;  // on the loop
        const bool a_above = coord(a, w) > coord(p, w), b_above = coord(b, w) > coord(p, w);
        if (a_above != b_above && ((b_above && o == Sign::Positive) || (a_above && o == Sign::Negative)))
          inside = !inside;
      }
    }
    return inside;
  }

  void assign_boundary_faces(const Domain3& d) {
    const FacetGrid grid(planes_, grid_lo_, grid_hi_);
    const std::size_t nb = faces_.boundary.size();
    assigned_.assign(nb, -1);
    assigned_sign_.assign(nb, 0);
    for (std::size_t i = 0; i < nb; ++i) {
      const auto& t = faces_.boundary[i];
      const Vec3 a = m_.vertices[t[0]], b = m_.vertices[t[1]], c = m_.vertices[t[2]];
      // Candidates: facets whose box holds the triangle and whose plane holds
      // its vertices (exact). One candidate is taken as is; containment in
      // the facet is then enforced by (c), since a triangle assigned to f with
      // f's orientation but not inside f would leave B_f != f. Only between
      // several coplanar candidates does the exact point-in-polygon test
      // choose (the lowest-numbered facet whose closure holds all three).
      int first = -1, candidates = 0;
      for (int f : grid.at(a)) {
        const FacetPlane& fp = planes_[f];
        if (!in_box(a, fp.lo, fp.hi) || !in_box(b, fp.lo, fp.hi) || !in_box(c, fp.lo, fp.hi)) continue;
        if (orient3d(fp.p0, fp.p1, fp.p2, a) != Sign::Zero || orient3d(fp.p0, fp.p1, fp.p2, b) != Sign::Zero ||
            orient3d(fp.p0, fp.p1, fp.p2, c) != Sign::Zero)
          continue;
        if (candidates++ == 0) first = f;
      }
      if (candidates == 1) {
        assigned_[i] = first;
      } else if (candidates > 1) {
        for (int f : grid.at(a)) {
          if (f < first) continue;
          const FacetPlane& fp = planes_[f];
          if (!in_box(a, fp.lo, fp.hi) || !in_box(b, fp.lo, fp.hi) || !in_box(c, fp.lo, fp.hi)) continue;
          if (orient3d(fp.p0, fp.p1, fp.p2, a) != Sign::Zero || orient3d(fp.p0, fp.p1, fp.p2, b) != Sign::Zero ||
              orient3d(fp.p0, fp.p1, fp.p2, c) != Sign::Zero)
            continue;
          if (!in_closed_facet(d, f, a) || !in_closed_facet(d, f, b) || !in_closed_facet(d, f, c)) continue;
          assigned_[i] = f;
          break;
        }
      }
      const int tet = faces_.boundary_tet[i];
      if (assigned_[i] < 0) {
        sink_.add(CheckKind::BoundaryFace, {t[0], t[1], t[2]},
                  "boundary triangle (" + format_ids(t) + ") of tetrahedron " + std::to_string(tet) + " at " +
                      format_point(a) + " " + format_point(b) + " " + format_point(c) +
                      " is not contained in any domain facet (an exact test: a vertex only approximately in a"
                      " facet's plane fails it)");
        continue;
      }
      const FacetPlane& fp = planes_[assigned_[i]];
      const Sign s = orient2d_projected(a, b, c, fp.axis);
      assigned_sign_[i] = s == fp.turn ? 1 : -1;
      if (s != fp.turn)
        sink_.add(CheckKind::BoundaryFace, {t[0], t[1], t[2]},
                  "boundary triangle (" + format_ids(t) + ") of tetrahedron " + std::to_string(tet) +
                      " lies on facet " + std::to_string(assigned_[i]) +
                      " but its outward normal points into the domain (the mesh lies outside)");
    }
  }

  // Walk every input edge along boundary edges (see (b) above).
  void walk_edges(const Domain3& d) {
    const auto& pv = d.plc.vertices;
    const std::size_t ne = d.edges.size();
    chain_offset_.assign(ne + 1, 0);
    chain_items_.clear();
    edge_ok_.assign(ne, 0);
    int skipped = 0;
    for (std::size_t e = 0; e < ne; ++e) {
      chain_offset_[e] = static_cast<int>(chain_items_.size());
      const DomainEdge& de = d.edges[e];
      const bool ids_ok = de.a >= 0 && de.b >= 0 && de.a < static_cast<int>(pv.size()) &&
                          de.b < static_cast<int>(pv.size());
      const int A = ids_ok ? in2mesh_[de.a] : -1, B = ids_ok ? in2mesh_[de.b] : -1;
      if (A < 0 || B < 0) {
        ++skipped;
        continue;
      }
      const Vec3 pa = m_.vertices[A], pb = m_.vertices[B];
      std::vector<int> chain{A};
      int c = A;
      bool ok = true;
      while (c != B) {
        int next = -1, found = 0, other = -1;
        for (int w : faces_.boundary_adjacency.of(c)) {
          bool on = w == B;
          if (!on) {
            const Vec3 p = m_.vertices[w];
            on = in_box(p, pa, pb) && collinear(pa, pb, p) && dot_sign(p, m_.vertices[c], pb) == Sign::Negative;
          }
          if (!on) continue;
          if (found++ == 0)
            next = w;
          else
            other = w;
        }
        const std::string edge_name = "input edge (" + std::to_string(de.a) + " " + std::to_string(de.b) + ")";
        if (found == 0) {
          sink_.add(CheckKind::MissingEdge, {de.a, de.b},
                    edge_name + " is not a chain of mesh edges: no boundary edge continues along it from mesh vertex " +
                        std::to_string(c) + " at " + format_point(m_.vertices[c]) + " towards mesh vertex " +
                        std::to_string(B));
          ok = false;
          break;
        }
        if (found > 1) {
          sink_.add(CheckKind::NonConforming, {c, next, other},
                    "boundary edges from vertex " + std::to_string(c) + " to " + std::to_string(next) + " and " +
                        std::to_string(other) + " both run along " + edge_name + " (overlapping edges)");
          ok = false;
          break;
        }
        chain.push_back(next);
        c = next;
      }
      if (!ok) continue;
      edge_ok_[e] = 1;
      chain_items_.insert(chain_items_.end(), chain.begin(), chain.end());
    }
    chain_offset_[ne] = static_cast<int>(chain_items_.size());
    // Edges with failed walks keep an empty chain: make offsets consistent.
    if (skipped) sink_.note(std::to_string(skipped) + " input edge(s) not walked because an endpoint is missing");
  }

  // (c): the boundary of the triangles on each facet against the facet's
  // loops subdivided by the edge chains.
  void check_facets(const Domain3& d) {
    struct R {
      int facet, lo, hi, weight;
    };
    std::vector<R> recs;
    for (std::size_t i = 0; i < faces_.boundary.size(); ++i) {
      const int f = assigned_[i];
      if (f < 0) continue;
      const auto& t = faces_.boundary[i];
      for (int k = 0; k < 3; ++k) {
        const int x = t[k], y = t[(k + 1) % 3];
        recs.push_back(x < y ? R{f, x, y, assigned_sign_[i]} : R{f, y, x, -assigned_sign_[i]});
      }
    }
    std::vector<char> facet_checkable(d.plc.facets.size(), 0);
    int unchecked = 0;
    for (std::size_t f = 0; f < d.plc.facets.size(); ++f) {
      if (!planes_[f].ok) continue;
      bool ok = true;
      std::vector<R> mine;
      for (const auto& loop : d.plc.facets[f].loops) {
        const std::size_t n = loop.size();
        for (std::size_t k = 0; k < n && ok; ++k) {
          const int u = loop[k], v = loop[(k + 1) % n];
          const DomainEdge key{std::min(u, v), std::max(u, v), {-1, -1}};
          auto it = std::lower_bound(d.edges.begin(), d.edges.end(), key, [](const DomainEdge& x, const DomainEdge& y) {
            return x.a != y.a ? x.a < y.a : x.b < y.b;
          });
          if (it == d.edges.end() || it->a != key.a || it->b != key.b)
            throw DomainError(ErrorCode::OpenBoundary,
                              "inconsistent Domain3: side (" + std::to_string(u) + " " + std::to_string(v) +
                                  ") of facet " + std::to_string(f) +
                                  " is not in Domain3::edges (build domains with make_domain)",
                              {static_cast<std::int64_t>(f)});
          const auto e = static_cast<std::size_t>(it - d.edges.begin());
          if (!edge_ok_[e]) {
            ok = false;
            break;
          }
          // The chain runs from it->a to it->b; the loop side from u to v.
          const int s0 = chain_offset_[e], s1 = chain_offset_[e + 1];
          for (int j = s0; j + 1 < s1; ++j) {
            int x = chain_items_[j], y = chain_items_[j + 1];
            if (u != it->a) std::swap(x, y);  // side runs against the chain
            // Expected: the facet boundary runs x -> y; subtract it.
            mine.push_back(x < y ? R{static_cast<int>(f), x, y, -1} : R{static_cast<int>(f), y, x, 1});
          }
        }
        if (!ok) break;
      }
      if (!ok) {
        ++unchecked;
        continue;
      }
      facet_checkable[f] = 1;
      recs.insert(recs.end(), mine.begin(), mine.end());
    }
    std::sort(recs.begin(), recs.end(), [](const R& a, const R& b) {
      if (a.facet != b.facet) return a.facet < b.facet;
      if (a.lo != b.lo) return a.lo < b.lo;
      return a.hi < b.hi;
    });
    for (std::size_t i = 0; i < recs.size();) {
      const int f = recs[i].facet;
      std::size_t j = i;
      std::string detail;
      int bad = 0;
      while (j < recs.size() && recs[j].facet == f) {
        std::size_t k = j;
        int sum = 0;
        while (k < recs.size() && recs[k].facet == f && recs[k].lo == recs[j].lo && recs[k].hi == recs[j].hi)
          sum += recs[k++].weight;
        if (sum != 0) {
          if (bad < 4)
            detail += " (" + std::to_string(recs[j].lo) + " " + std::to_string(recs[j].hi) + "): " +
                      std::to_string(sum) + ";";
          ++bad;
        }
        j = k;
      }
      if (bad && facet_checkable[f]) {
        sink_.add(CheckKind::MissingFacet, {f},
                  "facet " + std::to_string(f) + " (marker " + std::to_string(d.plc.facets[f].marker) +
                      ") is not exactly the union of the boundary triangles on it: at " + std::to_string(bad) +
                      " mesh edge(s) their boundary differs from the facet's (net multiplicity" + detail +
                      (bad > 4 ? " ...)" : ")"));
      }
      i = j;
    }
    if (unchecked)
      sink_.note(std::to_string(unchecked) + " facet(s) not compared with their boundary triangles because an edge is missing");
  }

  void check_steiner() {
    std::vector<char> seen(m_.vertices.size(), 0);
    std::vector<int> steiner;
    for (const auto& f : faces_.boundary)
      for (int v : f)
        if (!seen[v]) {
          seen[v] = 1;
          if (mesh2in_[v] < 0) steiner.push_back(v);
        }
    std::sort(steiner.begin(), steiner.end());
    for (int v : steiner)
      sink_.add(CheckKind::SteinerOnBoundary, {v},
                "mesh vertex " + std::to_string(v) + " at " + format_point(m_.vertices[v]) +
                    " is on the domain boundary but is not an input vertex");
  }

  // The public locate(Domain3, p) scans every facet triangle; the plc
  // module's indexed locator answers the same exact question per vertex fast.
  void check_located(const Domain3& d) {
    if (d.facet_triangles.empty()) {
      sink_.note("vertex location skipped: the domain has no facet triangles (not built by make_domain?)");
      return;
    }
    const detail::DomainLocator3 locator(d);
    for (std::size_t v = 0; v < m_.vertices.size(); ++v)
      if (locator.locate(m_.vertices[v]) == Location::Outside)
        sink_.add(CheckKind::VertexOutside, {static_cast<std::int64_t>(v)},
                  "vertex " + std::to_string(v) + " at " + format_point(m_.vertices[v]) + " is outside the domain");
  }

  const TetMesh3& m_;
  const CheckOptions& opt_;
  CheckReport& rep_;
  IssueSink sink_;
  bool stage1_ok_ = false;
  std::vector<int> order_;
  FaceTable faces_;
  struct BEdge {
    int lo, hi;
    int forward;  // 1 if the boundary triangle runs lo -> hi
  };
  std::vector<BEdge> bedges_;
  std::vector<int> in2mesh_, mesh2in_;
  std::vector<FacetPlane> planes_;
  Vec3 grid_lo_, grid_hi_;
  std::vector<int> assigned_, assigned_sign_;
  std::vector<int> chain_offset_, chain_items_;
  std::vector<char> edge_ok_;
};

}  // namespace

CheckReport check_mesh_topology(const TetMesh3& mesh, const CheckOptions& options) {
  CheckReport report;
  Checker3 checker(mesh, options, report);
  checker.run_topology();
  return report;
}

CheckReport check_mesh(const TetMesh3& mesh, const Domain3& domain, const CheckOptions& options) {
  CheckReport report;
  Checker3 checker(mesh, options, report);
  const bool ok = checker.run_topology();
  checker.run_domain(domain, ok);
  return report;
}

}  // namespace pqmesh
