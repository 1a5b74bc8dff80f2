// Stage 3 of the tetrahedral-mesh checker, face matching: every face lies on
// one tetrahedron (a boundary face, oriented outward) or on two with opposite
// orientations; anything else is NonConforming. Why this is the right
// condition: check3d.cpp.
#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/check3d_stages.hpp"

namespace pqmesh::detail::check3d {
namespace {

// Outward faces of a positive tetrahedron (a, b, c, d): the face opposite each
// vertex, ordered so that its right-hand normal points away from that vertex.
constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

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
// tetrahedron): collect_records relies on 0, 1, 0, 1.
constexpr int face_parity(int k) {
  const int x = kFaces[k][0], y = kFaces[k][1], z = kFaces[k][2];
  return ((x > y) + (x > z) + (y > z)) % 2;  // inversions
}
static_assert(face_parity(0) == 0 && face_parity(1) == 1 && face_parity(2) == 0 && face_parity(3) == 1);

constexpr std::uint32_t kEmptySlot = 0xffffffffu;

// Hash-table slot of a packed face key (b << 32) | c: the high half of a
// multiplicative (Fibonacci) hash, so that masking keeps well-mixed bits.
inline std::size_t bc_slot(std::uint64_t bc) { return static_cast<std::size_t>((bc * 0x9e3779b97f4a7c15ull) >> 32); }

// One face (a, b, c), a < b < c, of one tetrahedron, filed under a.
struct Rec {
  std::uint64_t bc;    // (b << 32) | c: the face (a, b, c), a < b < c (ids >= 0 after stage 1)
  std::uint32_t code;  // (tetrahedron << 1) | parity of the sorting permutation
  int b() const { return static_cast<int>(bc >> 32); }
  int c() const { return static_cast<int>(bc & 0xffffffffu); }
};

// The two smallest vertex ids of a tetrahedron, in increasing order.
std::array<int, 2> two_smallest(const std::array<int, 4>& q) {
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
}

// Tetrahedra filed by vertex: those of vertex v are filed[start[v] .. start[v + 1]).
struct FiledTets {
  std::vector<int> start, filed;
};

// Faces bucketed by their smallest vertex. A positive tetrahedron has four
// distinct vertices m1 < m2 < m3 < m4; its three faces through m1 have
// smallest vertex m1 and the face (m2, m3, m4) has m2. So the tetrahedra are
// filed (counting sort) under their two smallest vertices only, and each
// vertex's bucket of face records is built from its filed tetrahedra when
// its turn comes: 8 bytes per tetrahedron instead of a table of all faces.
FiledTets file_by_two_smallest(const std::vector<std::array<int, 4>>& tetrahedra, int nv) {
  const int nt = static_cast<int>(tetrahedra.size());
  FiledTets ft;
  std::vector<int>& start = ft.start;
  start.assign(static_cast<std::size_t>(nv) + 1, 0);
  for (int t = 0; t < nt; ++t) {
    const auto ab = two_smallest(tetrahedra[t]);
    ++start[ab[0] + 1];
    ++start[ab[1] + 1];
  }
  for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
  ft.filed.resize(static_cast<std::size_t>(start[nv]));
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int t = 0; t < nt; ++t) {
    const auto ab = two_smallest(tetrahedra[t]);
    ft.filed[fill[ab[0]]++] = t;
    ft.filed[fill[ab[1]]++] = t;
  }
  return ft;
}

// The records of vertex a into recs (cleared first).
// The tetrahedron sorted once, s0 < s1 < s2 < s3 (distinct: stage 2 found
// it positive), with the parity P of that permutation. Its outward faces
// are kFaces of (s0, s1, s2, s3) when P is even and their reverses when
// odd; sorted, the face opposite s3 is (s0 s1 s2) from (s0 s2 s1): parity
// 1 ^ P; opposite s2, (s0 s1 s3): P; opposite s1, (s0 s2 s3) from
// (s0 s3 s2): 1 ^ P; opposite s0, (s1 s2 s3): P. Those through s0 have
// smallest vertex s0, the last one s1: the records of vertex a are the
// faces whose smallest vertex is a, as sorting each face would give.
void collect_records(const std::vector<std::array<int, 4>>& tetrahedra, const FiledTets& ft, int a,
                     std::vector<Rec>& recs) {
  recs.clear();
  const auto record = [&](int b, int c, std::uint32_t t, int parity) {
    recs.push_back(Rec{(std::uint64_t{static_cast<std::uint32_t>(b)} << 32) | static_cast<std::uint32_t>(c),
                       (t << 1) | static_cast<std::uint32_t>(parity)});
  };
  for (int j = ft.start[a]; j < ft.start[a + 1]; ++j) {
    const int t = ft.filed[j];
    std::array<int, 4> s = tetrahedra[t];
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
}

// Fast path: the records counted by (b, c) in a small open-addressing
// table (linear probing, at most half full). When every face of a is on
// one tetrahedron, or on two with opposite parities, the outcome is the
// single faces in increasing (b, c) order (sorted here into `singles`; few),
// exactly what the sorted scan gives; returns true then. Anything else (a
// face on the same side of two tetrahedra, or on three or more) returns
// false and takes the sorted scan, which reports in (b, c, tetrahedron)
// order. slot and paired are scratch buffers reused across vertices.
bool match_regular(const std::vector<Rec>& recs, std::vector<std::uint32_t>& slot, std::vector<unsigned char>& paired,
                   std::vector<Rec>& singles) {
  std::size_t cap = 16;
  while (cap < 2 * recs.size()) cap *= 2;
  if (slot.size() < cap) slot.resize(cap);
  std::fill(slot.begin(), slot.begin() + static_cast<std::ptrdiff_t>(cap), kEmptySlot);
  if (paired.size() < recs.size()) paired.resize(recs.size());
  const std::size_t mask = cap - 1;
  for (std::size_t i = 0; i < recs.size(); ++i) {
    std::size_t h = bc_slot(recs[i].bc) & mask;
    while (slot[h] != kEmptySlot && recs[slot[h]].bc != recs[i].bc) h = (h + 1) & mask;
    if (slot[h] == kEmptySlot) {
      slot[h] = static_cast<std::uint32_t>(i);
      paired[i] = 0;
      continue;
    }
    const std::uint32_t j = slot[h];
    if (paired[j] || ((recs[j].code ^ recs[i].code) & 1u) == 0) return false;
    paired[j] = 1;
    paired[i] = 1;
  }
  singles.clear();
  for (std::size_t i = 0; i < recs.size(); ++i)
    if (!paired[i]) singles.push_back(recs[i]);
  std::sort(singles.begin(), singles.end(), [](const Rec& x, const Rec& y) { return x.bc < y.bc; });
  return true;
}

// Appends the face (a, b, c) of record r, oriented outward, to the boundary.
void add_boundary(FaceTable& faces, int a, const Rec& r) {
  const bool odd = (r.code & 1u) != 0;
  faces.boundary.push_back(odd ? std::array<int, 3>{a, r.c(), r.b()} : std::array<int, 3>{a, r.b(), r.c()});
  faces.boundary_tet.push_back(static_cast<int>(r.code >> 1));
}

// The sorted scan: runs of equal (b, c) in (b, c, tetrahedron) order; a face
// on one tetrahedron joins the boundary, two on the same side or three or
// more are reported as NonConforming.
void match_sorted(int a, std::vector<Rec>& recs, FaceTable& faces, IssueSink& sink) {
  auto first = recs.begin(), last = recs.end();
  std::sort(first, last, [](const Rec& x, const Rec& y) { return x.bc != y.bc ? x.bc < y.bc : x.code < y.code; });
  for (auto it = first; it != last;) {
    auto run_end = it + 1;
    while (run_end != last && run_end->bc == it->bc) ++run_end;
    const long count = run_end - it;
    const int face[3] = {a, it->b(), it->c()};
    if (count == 1) {
      add_boundary(faces, a, *it);
    } else if (count == 2) {
      if ((it->code & 1u) == ((it + 1)->code & 1u)) {
        const int t1 = static_cast<int>(it->code >> 1), t2 = static_cast<int>((it + 1)->code >> 1);
        sink.add(CheckKind::NonConforming, {t1, t2},
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
      sink.add(CheckKind::NonConforming, std::move(ids),
               "face (" + format_ids(face) + ") is on " + std::to_string(count) + " tetrahedra: " + format_ids(tets));
    }
    it = run_end;
  }
}

}  // namespace

void Checker3::match_faces() {
  const int nv = static_cast<int>(m_.vertices.size());
  const FiledTets ft = file_by_two_smallest(m_.tetrahedra, nv);
  std::vector<Rec> recs, singles;
  std::vector<std::uint32_t> slot;     // fast path: record index per table slot, or kEmptySlot
  std::vector<unsigned char> paired;  // fast path: per record, its face met a second time
  for (int a = 0; a < nv; ++a) {
    collect_records(m_.tetrahedra, ft, a, recs);
    if (match_regular(recs, slot, paired, singles)) {
      for (const Rec& r : singles) add_boundary(faces_, a, r);
      continue;
    }
    match_sorted(a, recs, faces_, sink_);
  }
}

}  // namespace pqmesh::detail::check3d
