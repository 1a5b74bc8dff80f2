// Stage 4 (a) and (c) of the tetrahedral-mesh checker (see check3d.cpp): each
// boundary triangle assigned to the domain facet that holds it (exactly), and
// each facet's boundary compared with the boundary of its triangles.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "mesh/check3d_stages.hpp"
#include "mesh/radix_sort.hpp"
#include "pqmesh/errors.hpp"

namespace pqmesh::detail::check3d {
namespace {

// A uniform grid over facet bounding boxes. The cell of a coordinate is a
// monotone function of it, so a point inside a facet's box falls in a cell
// that the facet was entered into.
class FacetGrid {
 public:
  // Cells per axis: as fine as 4 cbrt(nf) + 1 (at most 32) while the cell
  // lists hold at most 64 nf + 2^16 entries in all, else coarser, down to
  // cbrt(nf) + 1. Any resolution lists every facet whose box holds the point
  // (cell() is monotone), in increasing id: only the number of facets asked
  // about per point changes (a large facet's box covers a whole layer of
  // cells, so finer cells separate parallel facets), never an answer.
  FacetGrid(const std::vector<FacetPlane>& planes, Vec3 lo, Vec3 hi) : lo_(lo) {
    const int nf = static_cast<int>(planes.size());
    const double root = std::cbrt(static_cast<double>(nf));
    const int coarse = std::clamp(static_cast<int>(root) + 1, 1, 32);
    const int fine = std::clamp(static_cast<int>(4 * root) + 1, coarse, 32);
    const double ext[3] = {hi.x - lo.x, hi.y - lo.y, hi.z - lo.z};
    const std::int64_t budget = 64 * std::int64_t{nf} + (std::int64_t{1} << 16);
    for (int per_axis = fine; per_axis >= coarse; --per_axis) {
      for (int a = 0; a < 3; ++a) {
        n_[a] = ext[a] > 0 ? per_axis : 1;
        scale_[a] = ext[a] > 0 ? n_[a] / ext[a] : 0;
      }
      std::int64_t items = 0;
      for (int f = 0; f < nf; ++f) {
        if (!planes[f].ok) continue;
        const auto a = cell(planes[f].lo), b = cell(planes[f].hi);
        items += std::int64_t{b[0] - a[0] + 1} * (b[1] - a[1] + 1) * (b[2] - a[2] + 1);
      }
      if (items <= budget) break;  // the coarsest is taken whatever its size
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
      const double t = std::floor((axis_coord(p, a) - axis_coord(lo_, a)) * scale_[a]);
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

}  // namespace

void Checker3::prepare_facets(const Domain3& d) {
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
    fp.normal = plane_normal_signs(fp.p0, fp.p1, fp.p2);
    fp.axis = projection_axis(fp.p0, fp.p1, fp.p2);
    // Orientation of the outer loop in the projection: at its
    // lexicographically smallest projected vertex the polygon is convex.
    const auto& outer = loops[0];
    const int u = (fp.axis + 1) % 3, w = (fp.axis + 2) % 3;
    std::size_t k_min = 0;
    for (std::size_t k = 1; k < outer.size(); ++k) {
      const Vec3 p = pv[outer[k]], q = pv[outer[k_min]];
      if (axis_coord(p, u) < axis_coord(q, u) || (axis_coord(p, u) == axis_coord(q, u) && axis_coord(p, w) < axis_coord(q, w))) k_min = k;
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

// Exact: p (already known to be in the facet's plane, or within an ulp of it)
// lies in the closed facet polygon. A point within an ulp of a loop side is on
// the loop (the rounding rule of docs/algorithm/quality.md "The validity
// checker"); otherwise the crossing parity of a ray in the +u direction of the
// projection decides.
bool Checker3::in_closed_facet(const Domain3& d, int f, Vec3 p) const {
  const FacetPlane& fp = planes_[f];
  const auto& pv = d.plc.vertices;
  const int w = (fp.axis + 2) % 3;
  bool inside = false;
  for (const auto& loop : d.plc.facets[f].loops) {
    const std::size_t n = loop.size();
    for (std::size_t k = 0; k < n; ++k) {
      const Vec3 a = pv[loop[k]], b = pv[loop[(k + 1) % n]];
      // On the loop (docs/algorithm/quality.md "The validity checker").
      if (within_ulp_of_segment(p, a, b)) return true;
      const Sign o = orient2d_projected(a, b, p, fp.axis);
      const bool a_above = axis_coord(a, w) > axis_coord(p, w), b_above = axis_coord(b, w) > axis_coord(p, w);
      if (a_above != b_above && ((b_above && o == Sign::Positive) || (a_above && o == Sign::Negative)))
        inside = !inside;
    }
  }
  return inside;
}

void Checker3::assign_boundary_faces(const Domain3& d) {
  const FacetGrid grid(planes_, grid_lo_, grid_hi_);
  const std::size_t nb = faces_.boundary.size();
  assigned_.assign(nb, -1);
  assigned_sign_.assign(nb, 0);
  // on_facet_plane per (vertex, facet), remembered for the first three
  // facets asked about each vertex (a boundary vertex is on about six
  // boundary triangles, each of which asks about every facet listed in the
  // grid cell of its first vertex: the vertex's own facet or two or three
  // along an input edge, plus nearby ones); further facets are recomputed.
  // A cache of the same exact answer. Entries are 2 f + on, kNoEntry when
  // unused (facet 2^31 - 1 on its plane would read as unused: merely not
  // remembered): 12 bytes per vertex, as the two-entry memo had.
  constexpr std::uint32_t kNoEntry = 0xffffffffu;
  using PlaneMemo = std::array<std::uint32_t, 3>;
  std::vector<PlaneMemo> memo(m_.vertices.size(), PlaneMemo{kNoEntry, kNoEntry, kNoEntry});
  auto on_plane = [&](int f, int v) {
    PlaneMemo& mm = memo[static_cast<std::size_t>(v)];
    const auto fu = static_cast<std::uint32_t>(f);
    for (const std::uint32_t e : mm)
      if ((e >> 1) == fu && e != kNoEntry) return (e & 1u) != 0;
    const bool on = on_facet_plane(planes_[static_cast<std::size_t>(f)], m_.vertices[static_cast<std::size_t>(v)]);
    for (std::uint32_t& e : mm)
      if (e == kNoEntry) {
        e = (fu << 1) | static_cast<std::uint32_t>(on);
        break;
      }
    return on;
  };
  for (std::size_t i = 0; i < nb; ++i) {
    const auto& t = faces_.boundary[i];
    const Vec3 a = m_.vertices[t[0]], b = m_.vertices[t[1]], c = m_.vertices[t[2]];
    // Candidates: facets whose box and plane hold the triangle's vertices
    // (exactly, or within an ulp: on_facet_plane). One candidate is taken as is; containment in
    // the facet is then enforced by (c), since a triangle assigned to f with
    // f's orientation but not inside f would leave B_f != f. Only between
    // several coplanar candidates does the exact point-in-polygon test
    // choose: the lowest-numbered facet whose closure holds all three
    // vertices and the triangle's centroid. The vertices alone do not
    // decide: a triangle inside a facet that fills a hole of a coplanar one
    // can have all three on the hole's loop, in both closures; its centroid
    // (rounded, a point well inside any triangle that is not a sliver) is in
    // one only. A choice the rounding gets wrong makes (c) fail: the checker
    // may then reject a valid mesh, never accept an invalid one.
    int first = -1, candidates = 0;
    for (int f : grid.at(a)) {
      if (!on_plane(f, t[0]) || !on_plane(f, t[1]) || !on_plane(f, t[2])) continue;
      if (candidates++ == 0) first = f;
    }
    if (candidates == 1) {
      assigned_[i] = first;
    } else if (candidates > 1) {
      for (int f : grid.at(a)) {
        if (f < first) continue;
        if (!on_plane(f, t[0]) || !on_plane(f, t[1]) || !on_plane(f, t[2])) continue;
        if (!in_closed_facet(d, f, a) || !in_closed_facet(d, f, b) || !in_closed_facet(d, f, c) ||
            !in_closed_facet(d, f, (1.0 / 3.0) * (a + b + c)))
          continue;
        assigned_[i] = f;
        break;
      }
    }
    const int tet = faces_.boundary_tet[i];
    if (assigned_[i] < 0) {
      sink_.add(CheckKind::BoundaryFace, {t[0], t[1], t[2]},
                "boundary triangle (" + format_ids(t) + ") of tetrahedron " + std::to_string(tet) + " at " +
                    format_point(a) + " " + format_point(b) + " " + format_point(c) +
                    " is not contained in any domain facet (an exact test: a vertex farther than an ulp from a"
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

// Stage 4 (c) of check3d.cpp: the boundary of the triangles on each facet
// against the facet's loops subdivided by the edge chains.
void Checker3::check_facets(const Domain3& d) {
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
  // Order (facet, lo, hi); records with equal triples only add up their
  // weights, so their order does not matter (all fields >= 0). Stable passes
  // on (lo, hi) packed, then on the facet.
  {
    std::vector<R> scratch;
    radix_sort_by_key(recs, scratch, [](const R& r) {
      return (std::uint64_t{static_cast<std::uint32_t>(r.lo)} << 32) | static_cast<std::uint32_t>(r.hi);
    });
    radix_sort_by_key(recs, scratch, [](const R& r) { return std::uint64_t{static_cast<std::uint32_t>(r.facet)}; });
  }
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

}  // namespace pqmesh::detail::check3d
