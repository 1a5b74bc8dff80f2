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

// Outward faces of a positive tetrahedron (a, b, c, d): the face opposite each
// vertex, ordered so that its right-hand normal points away from that vertex.
constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

// Sorts a vertex triple in place; returns the parity of the permutation (1:
// odd, i.e. the sorted triple has the opposite orientation).
int sort_with_parity(std::array<int, 3>& x) {
  int parity = 0;
  if (x[0] > x[1]) std::swap(x[0], x[1]), parity ^= 1;
  if (x[1] > x[2]) std::swap(x[1], x[2]), parity ^= 1;
  if (x[0] > x[1]) std::swap(x[0], x[1]), parity ^= 1;
  return parity;
}

// Sorts the four vertex ids of a tetrahedron in place (a five-comparator
// network); returns the parity of the permutation (1: odd, i.e. the sorted
// tetrahedron has the opposite orientation).
int sort4_with_parity(std::array<int, 4>& x) {
  int parity = 0;
  const auto order = [&](int i, int j) {
    if (x[i] > x[j]) std::swap(x[i], x[j]), parity ^= 1;
  };
  order(0, 1);
  order(2, 3);
  order(0, 2);
  order(1, 3);
  order(1, 2);
  return parity;
}

// Parity of sorting row k of kFaces (the face opposite vertex k of a sorted
// tetrahedron): stage3_faces relies on 0, 1, 0, 1.
constexpr int face_parity(int k) {
  const int x = kFaces[k][0], y = kFaces[k][1], z = kFaces[k][2];
  return ((x > y) + (x > z) + (y > z)) % 2;  // inversions
}
static_assert(face_parity(0) == 0 && face_parity(1) == 1 && face_parity(2) == 0 && face_parity(3) == 1);

constexpr std::uint32_t kEmptySlot = 0xffffffffu;

// Hash-table slot of a packed face key (b << 32) | c: the high half of a
// multiplicative (Fibonacci) hash, so that masking keeps well-mixed bits.
inline std::size_t bc_slot(std::uint64_t bc) { return static_cast<std::size_t>((bc * 0x9e3779b97f4a7c15ull) >> 32); }

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
  const int nv = static_cast<int>(m_.vertices.size());
  const int nt = static_cast<int>(m_.tetrahedra.size());
  const std::int64_t nonconf_before = sink_.count(CheckKind::NonConforming);

  // Faces bucketed by their smallest vertex. A positive tetrahedron has four
  // distinct vertices m1 < m2 < m3 < m4; its three faces through m1 have
  // smallest vertex m1 and the face (m2, m3, m4) has m2. So the tetrahedra are
  // filed (counting sort) under their two smallest vertices only, and each
  // vertex's bucket of face records is built from its filed tetrahedra when
  // its turn comes: 8 bytes per tetrahedron instead of a table of all faces.
  struct Rec {
    std::uint64_t bc;    // (b << 32) | c: the face (a, b, c), a < b < c (ids >= 0 after stage 1)
    std::uint32_t code;  // (tetrahedron << 1) | parity of the sorting permutation
    int b() const { return static_cast<int>(bc >> 32); }
    int c() const { return static_cast<int>(bc & 0xffffffffu); }
  };
  auto two_smallest = [](const std::array<int, 4>& q) {
    int a = std::min(q[0], q[1]), b = std::max(q[0], q[1]);
    for (int i = 2; i < 4; ++i) {
      if (q[i] < a) {
        b = a;
        a = q[i];
      } else if (q[i] < b) {
        b = q[i];
      }
    }
    return std::array<int, 2>{a, b};
  };
  std::vector<int> start(static_cast<std::size_t>(nv) + 1, 0);
  for (int t = 0; t < nt; ++t) {
    const auto ab = two_smallest(m_.tetrahedra[t]);
    ++start[ab[0] + 1];
    ++start[ab[1] + 1];
  }
  for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<int> filed(static_cast<std::size_t>(start[nv]));
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int t = 0; t < nt; ++t) {
      const auto ab = two_smallest(m_.tetrahedra[t]);
      filed[fill[ab[0]]++] = t;
      filed[fill[ab[1]]++] = t;
    }
  }
  std::vector<Rec> recs, singles;
  std::vector<std::uint32_t> slot;     // fast path: record index per table slot, or kEmptySlot
  std::vector<unsigned char> paired;  // fast path: per record, its face met a second time
  for (int a = 0; a < nv; ++a) {
    recs.clear();
    // The tetrahedron sorted once, s0 < s1 < s2 < s3 (distinct: stage 2 found
    // it positive), with the parity P of that permutation. Its outward faces
    // are kFaces of (s0, s1, s2, s3) when P is even and their reverses when
    // odd; sorted, the face opposite s3 is (s0 s1 s2) from (s0 s2 s1): parity
    // 1 ^ P; opposite s2, (s0 s1 s3): P; opposite s1, (s0 s2 s3) from
    // (s0 s3 s2): 1 ^ P; opposite s0, (s1 s2 s3): P. Those through s0 have
    // smallest vertex s0, the last one s1: the records of vertex a are the
    // faces whose smallest vertex is a, as sorting each face would give.
    const auto record = [&](int b, int c, std::uint32_t t, int parity) {
      recs.push_back(Rec{(std::uint64_t{static_cast<std::uint32_t>(b)} << 32) | static_cast<std::uint32_t>(c),
                         (t << 1) | static_cast<std::uint32_t>(parity)});
    };
    for (int j = start[a]; j < start[a + 1]; ++j) {
      const int t = filed[j];
      std::array<int, 4> s = m_.tetrahedra[t];
      const int parity = sort4_with_parity(s);
      const auto tu = static_cast<std::uint32_t>(t);
      if (s[0] == a) {
        record(s[1], s[2], tu, 1 ^ parity);
        record(s[1], s[3], tu, parity);
        record(s[2], s[3], tu, 1 ^ parity);
      } else {  // filed under its second smallest vertex
        record(s[2], s[3], tu, parity);
      }
    }
    const auto add_boundary = [&](const Rec& r) {
      const bool odd = (r.code & 1u) != 0;
      faces_.boundary.push_back(odd ? std::array<int, 3>{a, r.c(), r.b()} : std::array<int, 3>{a, r.b(), r.c()});
      faces_.boundary_tet.push_back(static_cast<int>(r.code >> 1));
    };
    // Fast path: the records counted by (b, c) in a small open-addressing
    // table (linear probing, at most half full). When every face of a is on
    // one tetrahedron, or on two with opposite parities, the outcome is the
    // single faces in increasing (b, c) order (sorted here; few), exactly
    // what the sorted scan below gives. Anything else (a face on the same
    // side of two tetrahedra, or on three or more) takes the sorted scan,
    // which reports in (b, c, tetrahedron) order.
    std::size_t cap = 16;
    while (cap < 2 * recs.size()) cap *= 2;
    if (slot.size() < cap) slot.resize(cap);
    std::fill(slot.begin(), slot.begin() + static_cast<std::ptrdiff_t>(cap), kEmptySlot);
    if (paired.size() < recs.size()) paired.resize(recs.size());
    const std::size_t mask = cap - 1;
    bool regular = true;
    for (std::size_t i = 0; i < recs.size() && regular; ++i) {
      std::size_t h = bc_slot(recs[i].bc) & mask;
      while (slot[h] != kEmptySlot && recs[slot[h]].bc != recs[i].bc) h = (h + 1) & mask;
      if (slot[h] == kEmptySlot) {
        slot[h] = static_cast<std::uint32_t>(i);
        paired[i] = 0;
        continue;
      }
      const std::uint32_t j = slot[h];
      if (paired[j] || ((recs[j].code ^ recs[i].code) & 1u) == 0) {
        regular = false;
      } else {
        paired[j] = 1;
        paired[i] = 1;
      }
    }
    if (regular) {
      singles.clear();
      for (std::size_t i = 0; i < recs.size(); ++i)
        if (!paired[i]) singles.push_back(recs[i]);
      std::sort(singles.begin(), singles.end(), [](const Rec& x, const Rec& y) { return x.bc < y.bc; });
      for (const Rec& r : singles) add_boundary(r);
      continue;
    }
    auto first = recs.begin(), last = recs.end();
    std::sort(first, last, [](const Rec& x, const Rec& y) { return x.bc != y.bc ? x.bc < y.bc : x.code < y.code; });
    for (auto it = first; it != last;) {
      auto run_end = it + 1;
      while (run_end != last && run_end->bc == it->bc) ++run_end;
      const long count = run_end - it;
      const int face[3] = {a, it->b(), it->c()};
      if (count == 1) {
        add_boundary(*it);
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
  std::vector<Rec>().swap(recs);
  std::vector<Rec>().swap(singles);
  std::vector<std::uint32_t>().swap(slot);
  std::vector<unsigned char>().swap(paired);
  std::vector<int>().swap(filed);
  std::vector<int>().swap(start);
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
