// Stages 1-3 of the tetrahedral-mesh checker: indices and coordinates,
// orientation (and the volume measurement), face matching, hanging vertices,
// closed manifold boundary, listed boundary faces. Why these are the right
// conditions: check3d.cpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/check3d_stages.hpp"
#include "mesh/radix_sort.hpp"

namespace pqmesh::detail::check3d {
namespace {

// Sorts a vertex triple in place; returns the parity of the permutation (1:
// odd, i.e. the sorted triple has the opposite orientation).
int sort_with_parity(std::array<int, 3>& x) {
  int parity = 0;
  if (x[0] > x[1]) std::swap(x[0], x[1]), parity ^= 1;
  if (x[1] > x[2]) std::swap(x[1], x[2]), parity ^= 1;
  if (x[0] > x[1]) std::swap(x[0], x[1]), parity ^= 1;
  return parity;
}

}  // namespace

// ---- stage 1 -------------------------------------------------------------
bool Checker3::stage1_indices() {
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
  check_marker_count(sink_, m_.vertex_markers.size(), m_.vertices.size(), "vertex_markers");
  check_marker_count(sink_, m_.tetrahedron_markers.size(), m_.tetrahedra.size(), "tetrahedron_markers");
  check_marker_count(sink_, m_.face_markers.size(), m_.faces.size(), "face_markers");
  if (m_.tetrahedra.size() >= (std::size_t{1} << 31) - 1)
    sink_.add(CheckKind::BadIndex, {}, "more tetrahedra than int indices can address");
  return sink_.count(CheckKind::BadIndex) == before;
}

// ---- stage 2 -------------------------------------------------------------
bool Checker3::stage2_orientation() {
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

void Checker3::measure_volume() {
  CompensatedSum sum;
  for (const auto& q : m_.tetrahedra) {
    const Vec3 a = m_.vertices[q[0]];
    sum.add(dot(m_.vertices[q[1]] - a, cross(m_.vertices[q[2]] - a, m_.vertices[q[3]] - a)) / 6.0);
  }
  rep_.volume_measured = true;
  rep_.mesh_volume = sum.value();
}

// ---- stage 3 -------------------------------------------------------------
bool Checker3::stage3_faces() {
  const std::int64_t nonconf_before = sink_.count(CheckKind::NonConforming);
  match_faces();  // check3d_faces.cpp
  rep_.boundary_faces = static_cast<std::int64_t>(faces_.boundary.size());

  report_unused_vertices(sink_, m_.vertices, m_.tetrahedra, "tetrahedron");
  report_coincident_vertices(sink_, m_.vertices, order_);

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
void Checker3::build_boundary_edges() {
  bedges_.clear();
  bedges_.reserve(faces_.boundary.size() * 3);
  for (const auto& f : faces_.boundary)
    for (int k = 0; k < 3; ++k) {
      const int x = f[k], y = f[(k + 1) % 3];
      bedges_.push_back(x < y ? BEdge{x, y, 1} : BEdge{y, x, 0});
    }
  // Order (lo, hi, forward): ids >= 0 after stage 1, so the packed key
  // lo * 2^33 + hi * 2^1 + forward (ids < 2^31) orders like the triple.
  radix_sort_by_key(bedges_, [](const BEdge& e) {
    return (std::uint64_t{static_cast<std::uint32_t>(e.lo)} << 33) |
           (std::uint64_t{static_cast<std::uint32_t>(e.hi)} << 1) | static_cast<std::uint64_t>(e.forward);
  });
  std::vector<std::array<int, 2>> unique;
  for (std::size_t i = 0; i < bedges_.size(); ++i)
    if (i == 0 || bedges_[i].lo != bedges_[i - 1].lo || bedges_[i].hi != bedges_[i - 1].hi)
      unique.push_back({bedges_[i].lo, bedges_[i].hi});
  faces_.boundary_adjacency = make_adjacency(static_cast<int>(m_.vertices.size()), unique);
}

// Every edge of the boundary triangles on exactly two of them, once in each
// direction (closed 2-manifold, consistently oriented).
bool Checker3::check_boundary_manifold() {
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
void Checker3::find_hanging_vertices() {
  std::vector<char> reported(m_.vertices.size(), 0);
  std::vector<int> queue;
  bool capped = false;
  for (std::size_t i = 0; i < faces_.boundary.size(); ++i) {
    const auto& f = faces_.boundary[i];
    const Vec3 a = m_.vertices[f[0]], b = m_.vertices[f[1]], c = m_.vertices[f[2]];
    const int axis = projection_axis(a, b, c);
    if (axis < 0) continue;  // impossible for a face of a positive tetrahedron
    const Sign s = orient2d_projected(a, b, c, axis);
    const Vec3 lo{std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y}), std::min({a.z, b.z, c.z})};
    const Vec3 hi{std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y}), std::max({a.z, b.z, c.z})};
    // On the closed triangle: in its box, in its plane, and on no edge's
    // outer side in the projection.
    auto on = [&](int w) {
      const Vec3 p = m_.vertices[w];
      return in_box(p, lo, hi) && orient3d(a, b, c, p) == Sign::Zero && orient2d_projected(a, b, p, axis) != -s &&
             orient2d_projected(b, c, p, axis) != -s && orient2d_projected(c, a, p, axis) != -s;
    };
    auto found = [&](int w) {
      sink_.add(CheckKind::NonConforming, {w, f[0], f[1], f[2]},
                "vertex " + std::to_string(w) + " at " + format_point(m_.vertices[w]) + " lies on boundary triangle (" +
                    format_ids(f) + ") of tetrahedron " + std::to_string(faces_.boundary_tet[i]) +
                    " (hanging vertex: the tetrahedra there do not meet face to face)");
    };
    if (!search_hanging_vertices(faces_.boundary_adjacency, f, reported, queue, on, found)) capped = true;
  }
  if (capped)
    sink_.note("hanging-vertex search capped at " + std::to_string(kMaxHangingExpansion) + " vertices per face");
}

// TetMesh3::faces, when given, must list every boundary triangle once,
// oriented outward, and nothing else.
void Checker3::check_listed_faces() {
  if (m_.faces.empty()) return;
  struct K {
    std::array<int, 3> v;  // sorted
    int parity;
    int source;  // listed index, or -1 - boundary index
  };
  auto key = [](std::array<int, 3> x, int source) {
    const int parity = sort_with_parity(x);
    return K{x, parity, source};
  };
  // Order: sorted triple, then source (the boundary face, negative, first;
  // listed faces by index). The keys are made in increasing source order
  // (boundary faces from the last one, then the listed ones) and sorted
  // stably on v[2], then v[1], then v[0] (ids >= 0 after stage 1).
  std::vector<K> keys, scratch;
  keys.reserve(faces_.boundary.size() + m_.faces.size());
  for (std::size_t i = faces_.boundary.size(); i-- > 0;) keys.push_back(key(faces_.boundary[i], -1 - static_cast<int>(i)));
  for (std::size_t i = 0; i < m_.faces.size(); ++i) keys.push_back(key(m_.faces[i], static_cast<int>(i)));
  // Compared element by element (std::array's == and < call memcmp here).
  const auto same = [](const K& a, const K& b) { return a.v[0] == b.v[0] && a.v[1] == b.v[1] && a.v[2] == b.v[2]; };
  for (int k = 2; k >= 0; --k)
    radix_sort_by_key(keys, scratch, [k](const K& x) { return static_cast<std::uint64_t>(static_cast<std::uint32_t>(x.v[k])); });
  std::vector<K>().swap(scratch);
  for (std::size_t i = 0; i < keys.size();) {
    std::size_t j = i;
    while (j < keys.size() && same(keys[j], keys[i])) ++j;
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

}  // namespace pqmesh::detail::check3d
