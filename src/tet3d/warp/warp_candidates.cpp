#include "tet3d/warp/warp_candidates.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "pqmesh/errors.hpp"
#include "tet3d/facet_boxes.hpp"
#include "tet3d/points/point_book.hpp"
#include "tet3d/squares/square_cases.hpp"

namespace pqmesh::tet3d {

namespace {

// Rows of `log` (entries (id, value), ids < n) as row starts `row` (n + 1)
// and values `out`: a stable counting sort by id, then within each row the
// repeats dropped, the first use kept. Frees the log.
template <class Entry, class Value, class IdOf, class ValueOf>
void rows_of(std::vector<Entry>& log, std::size_t n, IdOf id_of, ValueOf value_of, std::vector<std::uint32_t>& row,
             std::vector<Value>& out) {
  std::vector<std::uint32_t> start(n + 1, 0);
  for (const Entry& e : log) ++start[static_cast<std::size_t>(id_of(e)) + 1];
  for (std::size_t i = 0; i < n; ++i) start[i + 1] += start[i];
  std::vector<Value> sorted(log.size());
  {
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (const Entry& e : log) sorted[next[static_cast<std::size_t>(id_of(e))]++] = value_of(e);
  }
  std::vector<Entry>().swap(log);
  // In place: the write position never passes the read position.
  row.assign(n + 1, 0);
  std::size_t w = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t first = w;
    for (std::size_t k = start[i]; k < start[i + 1]; ++k) {
      const auto kept = sorted.begin() + static_cast<std::ptrdiff_t>(first);
      const auto written = sorted.begin() + static_cast<std::ptrdiff_t>(w);
      if (std::find(kept, written, sorted[k]) == written) sorted[w++] = sorted[k];
    }
    row[i + 1] = static_cast<std::uint32_t>(w);
  }
  sorted.resize(w);
  sorted.shrink_to_fit();
  out = std::move(sorted);
}

}  // namespace

WarpCandidate WarpCandidates::operator[](std::size_t i) const {
  WarpCandidate c;
  c.p = points_[i];
  c.level = level_[i];
  c.facets = std::span<const int>(facets_).subspan(facet_row_[i], facet_row_[i + 1] - facet_row_[i]);
  c.neighbours = CandidatePoints(
      std::span<const std::int32_t>(neighbours_).subspan(neighbour_row_[i], neighbour_row_[i + 1] - neighbour_row_[i]),
      points_.data());
  c.box_edges = std::span<const BoxEdgeSpan>(edges_).subspan(edge_row_[i], edge_row_[i + 1] - edge_row_[i]);
  if (i >= ring_count_) c.square_corners = std::span<const GridPoint>(corners_).subspan(4 * (i - ring_count_), 4);
  return c;
}

std::int32_t WarpCandidateBuilder::ring_id(const GridPoint& p) {
  const auto [id, fresh] = index_.insert(p);
  if (fresh) {
    level_.push_back(-1);
    neighbours_.add_id();
    edges_.add_id();
  }
  return id;
}

void WarpCandidateBuilder::add_ring(std::span<const GridPoint> ring, std::span<const int> facets, std::int32_t level,
                                    const GridPoint& box_lo, const GridPoint& box_hi, const PointIndex* warped) {
  const std::size_t n = ring.size();
  const auto kept = [&](std::size_t i) { return warped == nullptr || warped->find(ring[i]) >= 0; };
  ids_.clear();
  keep_.clear();
  for (std::size_t i = 0; i < n; ++i) keep_.push_back(kept(i));
  for (std::size_t i = 0; i < n; ++i) {
    const bool listed = keep_[i] || keep_[(i + 1) % n] || keep_[(i + n - 1) % n];
    ids_.push_back(listed ? ring_id(ring[i]) : -1);
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!keep_[i]) continue;
    const GridPoint& p = ring[i];
    const std::int32_t id = ids_[i];
    std::int32_t& l = level_[static_cast<std::size_t>(id)];
    l = std::max(l, level);
    for (const int f : facets) facet_log_.push_back({id, f});
    // Next, then previous: the order of the rows' first uses.
    neighbours_.add(id, ids_[(i + 1) % n]);
    neighbours_.add(id, ids_[(i + n - 1) % n]);
    // p lies on the box edge along `axis` when its other two coordinates
    // are box bounds.
    auto on_bound = [&](int a) {
      const auto k = static_cast<std::size_t>(a);
      return p.f[k] == box_lo.f[k] || p.f[k] == box_hi.f[k];
    };
    for (int axis = 0; axis < 3; ++axis) {
      if (!on_bound((axis + 1) % 3) || !on_bound((axis + 2) % 3)) continue;
      const auto k = static_cast<std::size_t>(axis);
      edges_.add(id, {box_lo.f[k], box_hi.f[k], axis});
    }
  }
}

void WarpCandidateBuilder::add_points(std::span<const GridPoint> points, std::span<const int> facets) {
  for (const GridPoint& p : points) {
    const std::int32_t id = ring_id(p);
    for (const int f : facets) facet_log_.push_back({id, f});
  }
}

void WarpCandidateBuilder::add_centre(const FaceSquare& s, std::span<const int> facets, const PointIndex* warped) {
  GridPoint c1 = s.lo, c2 = s.lo, c3 = s.lo;
  c1.f[static_cast<std::size_t>(s.u)] += s.side;
  c2.f[static_cast<std::size_t>(s.u)] += s.side;
  c2.f[static_cast<std::size_t>(s.v)] += s.side;
  c3.f[static_cast<std::size_t>(s.v)] += s.side;
  if (warped != nullptr && warped->find(s.lo) < 0 && warped->find(c1) < 0 && warped->find(c2) < 0 &&
      warped->find(c3) < 0)
    return;
  const auto [cid, fresh] = centre_index_.insert(s.centre());
  if (fresh) corners_.insert(corners_.end(), {s.lo, c1, c2, c3});
  for (const int f : facets) centre_facet_log_.push_back({cid, f});
}

WarpCandidates WarpCandidateBuilder::finish() {
  WarpCandidates out;
  const std::size_t rings = static_cast<std::size_t>(index_.size());
  const std::size_t centres = static_cast<std::size_t>(centre_index_.size());
  std::vector<GridPoint> centre_points = centre_index_.take_keys();
  // A final square's centre is in no CornerSet point (leaf corners and the
  // cell corners of united boxes, box_faces.cpp), so never a ring point.
  for (const GridPoint& c : centre_points)
    if (index_.find(c) >= 0) throw InternalError("tet3d: a square centre is a ring point");
  out.count_ = rings + centres;
  out.points_ = index_.take_keys();
  out.points_.insert(out.points_.end(), centre_points.begin(), centre_points.end());
  std::vector<GridPoint>().swap(centre_points);
  out.level_ = std::move(level_);
  out.level_.resize(rings + centres, -1);
  out.ring_count_ = rings;
  out.corners_ = std::move(corners_);
  const std::size_t n = rings + centres;
  for (const auto& [cid, f] : centre_facet_log_) facet_log_.push_back({static_cast<std::int32_t>(rings) + cid, f});
  std::vector<std::pair<std::int32_t, int>>().swap(centre_facet_log_);
  const auto first = [](const auto& e) { return e.first; };
  rows_of(facet_log_, n, first, [](const auto& e) { return e.second; }, out.facet_row_, out.facets_);
  neighbours_.finish(n, out.neighbour_row_, out.neighbours_);
  edges_.finish(n, out.edge_row_, out.edges_);
  return out;
}

WarpCandidates make_warp_candidates(std::span<const WarpCandidateRecord> records) {
  WarpCandidates out;
  out.count_ = records.size();
  out.facet_row_.push_back(0);
  out.neighbour_row_.push_back(0);
  out.edge_row_.push_back(0);
  std::vector<GridPoint> others;  // neighbours that are no candidates
  for (const WarpCandidateRecord& r : records) out.points_.push_back(r.p);
  for (const WarpCandidateRecord& r : records) {
    out.level_.push_back(r.level);
    out.facets_.insert(out.facets_.end(), r.facets.begin(), r.facets.end());
    out.facet_row_.push_back(static_cast<std::uint32_t>(out.facets_.size()));
    for (const GridPoint& w : r.neighbours) {
      auto it = std::find(out.points_.begin(), out.points_.begin() + static_cast<std::ptrdiff_t>(records.size()), w);
      std::size_t id = static_cast<std::size_t>(it - out.points_.begin());
      if (id == records.size()) {
        id = records.size() + static_cast<std::size_t>(std::find(others.begin(), others.end(), w) - others.begin());
        if (id == records.size() + others.size()) others.push_back(w);
      }
      out.neighbours_.push_back(static_cast<std::int32_t>(id));
    }
    out.neighbour_row_.push_back(static_cast<std::uint32_t>(out.neighbours_.size()));
    for (const auto& [lo, hi] : r.box_edges) {
      int axis = -1, same = 0;
      for (int a = 0; a < 3; ++a) {
        const auto k = static_cast<std::size_t>(a);
        if (lo.f[k] != hi.f[k]) axis = a;
        same += (lo.f[k] == r.p.f[k] && hi.f[k] == r.p.f[k]) ? 1 : 0;
      }
      if (axis < 0 || same != 2) throw InternalError("tet3d: a hand-made box edge not through its point");
      const auto k = static_cast<std::size_t>(axis);
      out.edges_.push_back({lo.f[k], hi.f[k], axis});
    }
    out.edge_row_.push_back(static_cast<std::uint32_t>(out.edges_.size()));
    if (r.square_corners.empty()) {
      if (!out.corners_.empty()) throw InternalError("tet3d: a hand-made ring point after a centre");
      ++out.ring_count_;
    } else {
      if (r.square_corners.size() != 4) throw InternalError("tet3d: a hand-made centre without 4 corners");
      out.corners_.insert(out.corners_.end(), r.square_corners.begin(), r.square_corners.end());
    }
  }
  out.points_.insert(out.points_.end(), others.begin(), others.end());
  return out;
}

WarpCandidates warp_candidates(const OctTree& tree, const CornerSet& corners, const Domain3& domain,
                               std::span<const BoxJob> jobs) {
  PointBook scratch;
  const SquareDispatcher faces_only(tree, corners, domain, scratch, nullptr);
  std::vector<FaceSquare> squares;
  std::vector<GridPoint> ring;  // one square's ring, reused
  // The points the warp can move: the ring points of jobs with a facet.
  WarpCandidateBuilder::PointIndex warped;
  for (const BoxJob& j : jobs) {
    if (job_faces(faces_only, j).facets.empty()) continue;
    squares.clear();
    job_squares(tree, corners, j, squares);
    for (const FaceSquare& s : squares) {
      square_ring(s, corners, ring);
      for (const GridPoint& p : ring) warped.insert(p);
    }
  }
  WarpCandidateBuilder builder;
  for (const BoxJob& j : jobs) {
    squares.clear();
    job_squares(tree, corners, j, squares);
    const BoxFaces faces = job_faces(faces_only, j);
    // A job with a facet holds only points of `warped`.
    const WarpCandidateBuilder::PointIndex* filter = faces.facets.empty() ? &warped : nullptr;
    const std::int32_t level = tree.level(j.leaf) - (j.kind == BoxKind::Vertex ? 1 : 0);
    // The job's box (a vertex job's united box) for its whole edges.
    const BoxKey<3>& jkey = tree.key(j.leaf);
    const GridPoint box_lo = j.kind == BoxKind::Vertex ? united_lo(jkey, j.block) : key_corner(jkey, 0);
    GridPoint box_hi = box_lo;
    for (std::int64_t& x : box_hi.f) x += (j.kind == BoxKind::Vertex ? 2 : 1) * jkey.fine_side();
    for (const FaceSquare& s : squares) {
      // The square's centre, carried with its four corners (warp.hpp).
      builder.add_centre(s, faces.facets, &warped);
      square_ring(s, corners, ring);
      builder.add_ring(ring, faces.facets, level, box_lo, box_hi, filter);
    }
  }
  return builder.finish();
}

}  // namespace pqmesh::tet3d
