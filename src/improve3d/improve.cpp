// improve_mesh (improve.hpp): passes of shortest-edge-first collapses.
#include "improve3d/improve.hpp"

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>
#include <utility>
#include <vector>

#include "improve3d/collapse_check.hpp"
#include "improve3d/collapse_mesh.hpp"
#include "improve3d/collapse_retry.hpp"
#include "improve3d/edge_queue.hpp"
#include "improve3d/flips.hpp"
#include "improve3d/improving_collapse.hpp"
#include "improve3d/size_bound.hpp"
#include "improve3d/smooth.hpp"
#include "improve3d/vertex_classes.hpp"
#include "pqmesh/errors.hpp"
#include "quality/tetrahedron_quality_memo.hpp"
#include "tet3d/rebuild/free_heap.hpp"

namespace pqmesh::improve3d {

namespace {

using detail::Collapser;
using detail::CollapseMesh;
using detail::EdgeEntry;
using detail::EdgeList;
using detail::EdgeQueue;
using detail::VertexClass;

// The passes of a round stop after a pass that collapses nothing, or after
// a pass but the round's first that collapses fewer than kMinYield of the
// edges it tried (late passes retry many edges near the previous pass's
// collapses for few collapses), or after kMaxPasses. A round's first pass
// always has a second: after the first round the first pass tries only the
// edges smoothing and flips changed, and the edges its collapses change next
// are few and often collapse. Only the running time and the number of
// tetrahedra depend on these; every outcome is a valid mesh.
constexpr int kMaxPasses = 8;
constexpr double kMinYield = 0.02;
// Smoothing passes: at most kMaxSmoothPasses; a pass tries only vertices whose
// star changed since their last try (smooth.hpp), and the run stops on a pass
// that moves nothing.
constexpr int kMaxSmoothPasses = 6;
// Rounds of smoothing then flips (at most kMaxFlipPasses passes, until one
// flips nothing); the next round smooths only around the new tetrahedra. The
// run ends after a round that flips nothing, or after kMaxRounds.
constexpr int kMaxFlipPasses = 4;
constexpr int kMaxRounds = 3;
// Passes of collapses that remove the worst tetrahedra, before each of the last smoothing and flip rounds.
constexpr int kMaxImprovingPasses = 4;

struct PassResult {
  std::int64_t edges = 0, collapses = 0;
};

template <class T>
void expect_size(const std::vector<T>& markers, std::size_t n, const char* what) {
  if (!markers.empty() && markers.size() != n)
    throw InvalidInput(ErrorCode::WrongCount, std::string("improve_mesh: ") + what + " markers: " +
                                                  std::to_string(markers.size()) + " for " + std::to_string(n));
}

void validate(const Domain3& domain, const TetMesh3& mesh, const std::vector<int>& face_facets,
              const ImproveOptions& options) {
  expect_size(mesh.vertex_markers, mesh.vertices.size(), "vertex");
  expect_size(mesh.tetrahedron_markers, mesh.tetrahedra.size(), "tetrahedron");
  expect_size(mesh.face_markers, mesh.faces.size(), "face");
  if (face_facets.size() != mesh.faces.size())
    throw InvalidInput(ErrorCode::WrongCount, "improve_mesh: " + std::to_string(face_facets.size()) +
                                                  " face facets for " + std::to_string(mesh.faces.size()) +
                                                  " boundary triangles");
  for (std::size_t f = 0; f < face_facets.size(); ++f)
    if (face_facets[f] < 0 || static_cast<std::size_t>(face_facets[f]) >= domain.plc.facets.size())
      throw InvalidInput(ErrorCode::IndexOutOfRange, "improve_mesh: boundary triangle's facet id out of range",
                         {static_cast<std::int64_t>(f), face_facets[f]});
  if (options.sizes.size() != options.size_points.size() || !(options.max_size >= 0))
    throw InvalidInput(ErrorCode::WrongCount, "improve_mesh: size points and sizes differ in number, or max_size < 0");
  for (const double s : options.sizes)
    if (!(s > 0)) throw InvalidInput(ErrorCode::NonFinite, "improve_mesh: a size is not positive");
}

double length2(const CollapseMesh& mesh, int a, int b) {
  const Vec3 d = mesh.point(b) - mesh.point(a);
  return dot(d, d);
}

// Walks the vertex neighbourhoods: marks[x] == stamp for the neighbours met.
class Neighbours {
 public:
  explicit Neighbours(int n) : marks_(static_cast<std::size_t>(n), 0) {}
  // The vertices sharing a tetrahedron with a, each once, in list order.
  const std::vector<int>& of(CollapseMesh& mesh, int a) {
    ++stamp_;
    marks_[static_cast<std::size_t>(a)] = stamp_;
    tets_.clear();
    out_.clear();
    mesh.tets_of(a, tets_);
    for (const int t : tets_)
      for (const int x : mesh.tet(t))
        if (marks_[static_cast<std::size_t>(x)] != stamp_) {
          marks_[static_cast<std::size_t>(x)] = stamp_;
          out_.push_back(x);
        }
    return out_;
  }

 private:
  std::vector<std::uint64_t> marks_;
  std::uint64_t stamp_ = 0;
  std::vector<int> tets_, out_;
};

// The passes. The first tries every edge; a collapse pushes the edges it
// creates into the running pass. Each refused edge is kept with the time
// (a count of tries) of its refusal, and each vertex with the time its star
// last changed (it was in the star of a deleted vertex). A later pass tries
// again exactly the refused edges with an end changed since the refusal. That
// loses nothing: whether (a, b) collapses depends only on the stars of a and
// b (their tetrahedra, boundary triangles and aspect ratios) and the fixed
// vertex classes, so an edge whose ends' stars have not changed since its
// refusal is refused again.
class Coarsener {
 public:
  Coarsener(CollapseMesh& mesh, const detail::VertexClasses& classes, Collapser& collapser)
      : mesh_(mesh), classes_(classes), collapser_(collapser),
        changed_at_(static_cast<std::size_t>(mesh.vertex_count()), 0) {}

  // Records that the stars of `vertices` changed by something other than a
  // collapse (smoothing, flips), so their refused edges are tried again, and
  // queues `edges` (made by flips: never tried) for the next pass.
  void stars_changed(const std::vector<int>& vertices, const std::vector<std::pair<int, int>>& edges) {
    ++clock_;
    if (changed_at_.size() < static_cast<std::size_t>(mesh_.vertex_count()))
      changed_at_.resize(static_cast<std::size_t>(mesh_.vertex_count()), 0);
    for (const int x : vertices) changed_at_[static_cast<std::size_t>(x)] = clock_;
    for (const auto& [a, b] : edges) fresh_.push_back(entry(a, b));
  }

  PassResult pass() {
    queue_.start(first_pass_ ? all_edges() : changed_edges());
    first_pass_ = false;
    PassResult result;
    while (!queue_.empty()) {
      const EdgeEntry e = queue_.pop();
      if (!mesh_.vertex_alive(e.a) || !mesh_.vertex_alive(e.b)) continue;
      ++result.edges;
      ++clock_;
      const int kept = collapse_edge(e.a, e.b);
      if (kept < 0) {
        refused_.push_back({e.a, e.b, clock_});
        continue;
      }
      ++result.collapses;
      for (const int x : collapser_.changed()) changed_at_[static_cast<std::size_t>(x)] = clock_;
      for (const int x : collapser_.new_neighbours()) queue_.push(entry(kept, x));
    }
    return result;
  }

  // Frees the spare room of the refused list and the finished pass's queue
  // (held across smoothing and flips otherwise), and gives the heap pages
  // their blocks leave free back to the system: the arrays allocated next
  // (compact_tets) are fresh mappings that would not reuse them.
  void trim() {
    refused_.shrink_to_fit();
    queue_.release();
    tet3d::release_free_heap();
  }

 private:
  struct Refused {
    int a = -1, b = -1;
    std::int64_t at = 0;
  };

  EdgeEntry entry(int a, int b) const {
    if (b < a) std::swap(a, b);
    return {length2(mesh_, a, b), a, b};
  }

  EdgeList all_edges() {
    Neighbours neighbours(mesh_.vertex_count());
    EdgeList edges;
    for (int a = 0; a < mesh_.vertex_count(); ++a) {
      if (!mesh_.vertex_alive(a)) continue;
      for (const int b : neighbours.of(mesh_, a))
        if (b > a) edges.push_back(entry(a, b));
    }
    return edges;
  }

  // The edges queued by stars_changed and the refused edges with both ends
  // alive and an end changed since the refusal; the other refused edges (both
  // ends alive) stay refused.
  EdgeList changed_edges() {
    EdgeList edges;
    for (const EdgeEntry& e : fresh_)
      if (mesh_.vertex_alive(e.a) && mesh_.vertex_alive(e.b)) edges.push_back(e);
    fresh_.clear();
    std::size_t kept = 0;
    for (const Refused& r : refused_) {
      if (!mesh_.vertex_alive(r.a) || !mesh_.vertex_alive(r.b)) continue;
      if (changed_at_[static_cast<std::size_t>(r.a)] > r.at || changed_at_[static_cast<std::size_t>(r.b)] > r.at)
        edges.push_back(entry(r.a, r.b));
      else
        refused_[kept++] = r;
    }
    refused_.resize(kept);
    return edges;
  }

  // Collapses the edge one way or the other; returns the kept vertex, or -1.
  // The vertex of the lower class goes first (an interior vertex before one
  // on a facet, on an edge); between equal classes the smaller id.
  int collapse_edge(int a, int b) {
    const bool b_first = classes_.of(b) < classes_.of(a);
    const int first = b_first ? b : a, second = b_first ? a : b;
    if (collapser_.try_collapse(first, second)) return second;
    if (!collapser_.refused_both_ways() && collapser_.try_collapse(second, first)) return first;
    return -1;
  }

  CollapseMesh& mesh_;
  const detail::VertexClasses& classes_;
  Collapser& collapser_;
  std::vector<std::int64_t> changed_at_;  // clock_ when the vertex's star last changed
  std::deque<Refused> refused_;  // millions in a first pass: grows in blocks, never copied whole
  std::vector<EdgeEntry> fresh_;  // edges made otherwise than by a collapse, for the next pass
  std::int64_t clock_ = 0;  // edges tried so far
  bool first_pass_ = true;
  EdgeQueue queue_;
};

// The collapse passes of one round. The coarsener lives across the rounds: a
// round after the first tries the edges refused before with an end whose star
// smoothing or flips changed since, and the edges flips made
// (Coarsener::stars_changed, collapse_retry.hpp). Returns the collapses.
std::int64_t collapse_passes(Coarsener& coarsener, Collapser& collapser, ImproveStats& stats) {
  collapser.forget();
  std::int64_t collapses = 0;
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    const PassResult result = coarsener.pass();
    ++stats.passes;
    collapses += result.collapses;
    if (result.collapses == 0 || (pass > 0 && static_cast<double>(result.collapses) < kMinYield * static_cast<double>(result.edges)))
      break;
  }
  coarsener.trim();
  stats.collapses += collapses;
  return collapses;
}

// Smoothing then flips, in rounds (see kMaxRounds). Returns the vertices
// moved plus the flips done.
std::int64_t smooth_and_flip(const Domain3& domain, CollapseMesh& work, const detail::VertexClasses& classes,
                             const detail::SizeBound& size, const ImproveOptions& options, detail::SmoothTries& tries,
                             ImproveStats& stats) {
  detail::VertexMobility mobility;
  if (options.smooth) mobility = detail::vertex_mobility(domain, work, classes);
  detail::BoundarySnap snap(domain);
  detail::Smoother smoother(work, std::move(mobility), &snap, size, options.aspect_cap, tries);
  detail::Flipper flipper(work, size, options.aspect_cap);
  std::int64_t flips = 0;
  for (int round = 0; round < kMaxRounds; ++round) {
    for (int pass = 0; options.smooth && pass < kMaxSmoothPasses; ++pass)
      if (smoother.pass() == 0) break;
    std::int64_t flipped = 0;
    for (int pass = 0; options.flip && pass < kMaxFlipPasses; ++pass) {
      const std::int64_t done = flipper.pass();
      if (done == 0) break;
      flipped += done;  // the flips' new stars are tried by the next smoothing round (star times)
    }
    flips += flipped;
    if (flipped == 0) break;
  }
  stats.flips += flips;
  stats.boundary_flips += flipper.boundary_flips();
  stats.smoothed += smoother.moved_vertices();
  return smoother.moved_vertices() + flips;
}

// Passes of ImprovingCollapses (improving_collapse.hpp) until one collapses
// nothing, at most kMaxImprovingPasses. Returns the collapses.
std::int64_t improving_collapses(detail::ImprovingCollapses& improving, ImproveStats& stats) {
  std::int64_t collapses = 0;
  for (int pass = 0; pass < kMaxImprovingPasses; ++pass) {
    const std::int64_t done = improving.pass();
    if (done == 0) break;
    collapses += done;
  }
  stats.collapses += collapses;
  return collapses;
}

}  // namespace

ImproveStats improve_mesh(const Domain3& domain, TetMesh3& mesh, std::vector<int>& face_facets,
                          const ImproveOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  validate(domain, mesh, face_facets, options);
  TetrahedronQualityMemo memo;
  const detail::VertexClasses classes = detail::classify_vertices(domain, mesh, face_facets);
  CollapseMesh work(std::move(mesh), std::move(face_facets), memo);  // write_back fills them again
  const detail::SizeBound size(options.max_size, options.size_points, options.sizes);
  Collapser collapser(work, classes, size, {options.aspect_cap, options.target_aspect, options.min_dihedral}, memo);

  ImproveStats stats;
  stats.tetrahedra_before = work.live_tets();
  stats.vertices_before = work.live_vertices();
  stats.worst_aspect_before = work.worst_aspect();
  stats.min_dihedral_before = work.min_dihedral();  // measured by the constructor
  Coarsener coarsener(work, classes, collapser);
  Collapser strict(work, classes, size, {options.aspect_cap, options.target_aspect, 180}, memo);
  detail::ImprovingCollapses improving(work, classes, strict);
  detail::SmoothTries tries;  // across the smoothing rounds (smooth.hpp)
  detail::StarChanges changes;
  std::vector<int> changed;
  std::vector<std::pair<int, int>> new_edges;
  for (int round = 0; round < std::max(1, options.rounds); ++round) {
    if (round > 0) {
      changes.since(work, changed, new_edges);
      coarsener.stars_changed(changed, new_edges);
    }
    const std::int64_t collapses = collapse_passes(coarsener, collapser, stats);
    if (round == 0) stats.min_dihedral_collapsed = work.min_dihedral();
    if (round > 0 && collapses == 0) break;
    work.compact_tets();  // before take(): the ids smoothing and flips see
    changes.take(work);
    if (!(options.smooth || options.flip) || smooth_and_flip(domain, work, classes, size, options, tries, stats) == 0) break;
  }
  // After the coarsening rounds, so no later collapse of the coarsening's rule follows them.
  for (int round = 0; options.improving_collapses && round < kMaxRounds; ++round) {
    if (improving_collapses(improving, stats) == 0) break;
    if (options.smooth || options.flip) smooth_and_flip(domain, work, classes, size, options, tries, stats);
  }
  stats.min_dihedral_after = work.min_dihedral();
  stats.tetrahedra_after = work.live_tets();
  stats.vertices_after = work.live_vertices();
  stats.worst_aspect_after = work.worst_aspect();
  std::move(work).write_back(mesh, face_facets);
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

}  // namespace pqmesh::improve3d
