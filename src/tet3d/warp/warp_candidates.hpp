#pragma once
// The candidates of §4.3's warping (warp.hpp): every ring point of every box
// job's face squares, with the facets of the boxes using it, its neighbours
// along those rings, the deepest level of those boxes and the whole box edges
// through it; then every square centre with its square's four corners.
//
// Layout: one flat list, not one object with three heap vectors per point (the
// candidates are a large part of the peak memory). Points, levels and three
// compressed rows (facets, neighbours as candidate ids, box edges) in arrays
// indexed by candidate id. Every row lists its entries without repeats in the
// order of their first use (the warp's sums depend on that order). While
// building, neighbours and box edges sit in fixed inline rows (RowBuilder; a
// point is used ~18 times on plate_holes, so a per-use log would be large),
// facets in a per-use log (most jobs have none) grouped by a stable counting
// sort.
//
// Order: candidate ids are first uses, ring points in job order (squares in
// job_squares order, ring order within a square), then square centres in
// order of first use. Deterministic: two builds from the same jobs give the
// same list. warp_candidates lists only the points the warp can move (ring
// points of a box with a facet), their ring neighbours and the centres of
// squares with such a corner: leaving out the others keeps the order of
// those listed.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <span>
#include <utility>
#include <vector>

#include "pqmesh/domain.hpp"
#include "tet3d/squares/box_faces.hpp"
#include "tet3d/points/first_use_index.hpp"
#include "tet3d/warp/row_builder.hpp"
#include "tet3d/points/grid_point.hpp"

namespace pqmesh::tet3d {

struct BoxJob;  // facet_boxes.hpp (which includes warp.hpp, hence this header)

// A whole box edge through a candidate p along `axis`: p with that
// coordinate replaced by lo and by hi.
struct BoxEdgeSpan {
  std::int64_t lo = 0, hi = 0;
  std::int32_t axis = 0;
  std::pair<GridPoint, GridPoint> ends(const GridPoint& p) const {
    std::pair<GridPoint, GridPoint> e{p, p};
    e.first.f[static_cast<std::size_t>(axis)] = lo;
    e.second.f[static_cast<std::size_t>(axis)] = hi;
    return e;
  }
  friend bool operator==(const BoxEdgeSpan&, const BoxEdgeSpan&) = default;
};

// Grid points named by candidate ids, iterated as points.
class CandidatePoints {
 public:
  class iterator {
   public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = GridPoint;
    using difference_type = std::ptrdiff_t;
    using pointer = const GridPoint*;
    using reference = const GridPoint&;
    iterator() = default;
    iterator(const std::int32_t* id, const GridPoint* points) : id_(id), points_(points) {}
    const GridPoint& operator*() const { return points_[*id_]; }
    iterator& operator++() {
      ++id_;
      return *this;
    }
    iterator operator++(int) {
      iterator old = *this;
      ++id_;
      return old;
    }
    friend bool operator==(const iterator& a, const iterator& b) { return a.id_ == b.id_; }

   private:
    const std::int32_t* id_ = nullptr;
    const GridPoint* points_ = nullptr;
  };
  CandidatePoints() = default;
  CandidatePoints(std::span<const std::int32_t> ids, const GridPoint* points) : ids_(ids), points_(points) {}
  iterator begin() const { return {ids_.data(), points_}; }
  iterator end() const { return {ids_.data() + ids_.size(), points_}; }
  std::size_t size() const { return ids_.size(); }
  bool empty() const { return ids_.empty(); }
  const GridPoint& operator[](std::size_t k) const { return points_[ids_[k]]; }
  std::span<const std::int32_t> ids() const { return ids_; }

 private:
  std::span<const std::int32_t> ids_;
  const GridPoint* points_ = nullptr;
};

// One candidate, a view into its WarpCandidates (valid while the list lives
// and is not moved from). Rows have no repeats.
// A box vertex: the facets of the boxes using it and its neighbours along the
// rings of the squares using it. Or the centre of a face square (Case A / C2
// / D2 centre, §4.4), with the square's four corners: it is carried with
// them (warp.hpp).
struct WarpCandidate {
  GridPoint p;
  std::span<const int> facets;
  CandidatePoints neighbours;
  std::span<const GridPoint> square_corners;  // non-empty: p is this square's centre
  // The deepest level of a box whose faces use p (a vertex job's united box
  // counts one level up); with CornerSet::finest_level it gives §4.3's h,
  // the smallest box containing p (a united box's ring point need not be a
  // leaf corner). -1 for a centre.
  std::int32_t level = -1;
  // The whole box edges through p of the boxes using it (§4.3's first pass
  // looks at box edges, not at the pieces between ring points:
  // docs/algorithm/tet3d_warp.md "The first pass on whole box edges").
  std::span<const BoxEdgeSpan> box_edges;
};

// A candidate written out field by field (hand-made lists in tests). The
// neighbours need not be candidates; every box edge must run through p along
// one axis.
struct WarpCandidateRecord {
  GridPoint p;
  std::vector<int> facets;
  std::vector<GridPoint> neighbours;
  std::vector<GridPoint> square_corners;  // 4 or none (then before every centre)
  std::int32_t level = -1;
  std::vector<std::pair<GridPoint, GridPoint>> box_edges;
};

class WarpCandidates {
 public:
  std::size_t size() const { return count_; }
  WarpCandidate operator[](std::size_t i) const;
  const GridPoint& point(std::size_t i) const { return points_[i]; }
  // Candidates [0, ring_count()) are ring points, the rest square centres.
  std::size_t ring_count() const { return ring_count_; }

  class iterator {
   public:
    using iterator_category = std::input_iterator_tag;
    using value_type = WarpCandidate;
    using difference_type = std::ptrdiff_t;
    iterator(const WarpCandidates* list, std::size_t i) : list_(list), i_(i) {}
    WarpCandidate operator*() const { return (*list_)[i_]; }
    iterator& operator++() {
      ++i_;
      return *this;
    }
    friend bool operator==(const iterator& a, const iterator& b) { return a.i_ == b.i_; }

   private:
    const WarpCandidates* list_;
    std::size_t i_;
  };
  iterator begin() const { return {this, 0}; }
  iterator end() const { return {this, size()}; }

 private:
  friend class WarpCandidateBuilder;
  friend WarpCandidates make_warp_candidates(std::span<const WarpCandidateRecord> records);
  std::size_t count_ = 0;
  // By id; beyond count_: neighbours that are no candidates (hand-made lists).
  std::vector<GridPoint> points_;
  std::vector<std::int32_t> level_;      // by id
  std::vector<std::uint32_t> facet_row_, neighbour_row_, edge_row_;  // size() + 1 row starts
  std::vector<int> facets_;
  std::vector<std::int32_t> neighbours_;  // candidate ids (ring points)
  std::vector<BoxEdgeSpan> edges_;
  std::vector<GridPoint> corners_;        // 4 per centre, by id - ring_count_
  std::size_t ring_count_ = 0;
};

// Collects uses of points, then makes the list (finish, once).
class WarpCandidateBuilder {
 public:
  using PointIndex = FirstUseIndex<GridPoint, GridPointHash>;
  // One square's ring, used by a box at `level` with `facets`, whose bounds
  // box_lo <= box_hi give the box edges through its points. With `warped`
  // (the only points that can be warped: those with a facet), a point
  // outside it gets no row and no id unless it is a ring neighbour of one
  // inside (the warp skips every point without a facet; warp.hpp).
  void add_ring(std::span<const GridPoint> ring, std::span<const int> facets, std::int32_t level,
                const GridPoint& box_lo, const GridPoint& box_hi, const PointIndex* warped = nullptr);
  // Points used by boxes with `facets` (no rings, no level, no box edges).
  void add_points(std::span<const GridPoint> points, std::span<const int> facets);
  // The centre of square s, used by a box with `facets`. With `warped`: not
  // added when no corner of s is in it (no corner moves, so the centre
  // never does).
  void add_centre(const FaceSquare& s, std::span<const int> facets, const PointIndex* warped = nullptr);
  // Throws InternalError if a centre is also a ring point.
  WarpCandidates finish();

 private:
  std::int32_t ring_id(const GridPoint& p);
  FirstUseIndex<GridPoint, GridPointHash> index_, centre_index_;
  std::vector<std::int32_t> level_;
  // Facets are few (jobs of empty boxes have none): (id, facet) per use,
  // grouped at the end; centre ids counted from 0.
  std::vector<std::pair<std::int32_t, int>> facet_log_, centre_facet_log_;
  RowBuilder<std::int32_t, 6> neighbours_;
  RowBuilder<BoxEdgeSpan, 6> edges_;
  std::vector<GridPoint> corners_;
  std::vector<std::int32_t> ids_;  // one ring's ids, reused
  std::vector<bool> keep_;         // one ring's points with rows, reused
};

// The list of hand-made records, in their order. Throws InternalError for a
// box edge not through p along one axis, or a centre before a ring point.
WarpCandidates make_warp_candidates(std::span<const WarpCandidateRecord> records);

// The candidates of the box jobs (each job's squares and P faces, as the
// box stage meshes them).
WarpCandidates warp_candidates(const OctTree& tree, const CornerSet& corners, const Domain3& domain,
                               std::span<const BoxJob> jobs);

}  // namespace pqmesh::tet3d
