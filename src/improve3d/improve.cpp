// improve_mesh (improve.hpp): passes of shortest-edge-first collapses.
#include "improve3d/improve.hpp"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "improve3d/collapse_check.hpp"
#include "improve3d/collapse_mesh.hpp"
#include "improve3d/edge_queue.hpp"
#include "improve3d/size_bound.hpp"
#include "improve3d/vertex_classes.hpp"
#include "pqmesh/errors.hpp"
#include "quality/tetrahedron_quality_memo.hpp"

namespace pqmesh::improve3d {

namespace {

using detail::Collapser;
using detail::CollapseMesh;
using detail::EdgeEntry;
using detail::EdgeQueue;
using detail::VertexClass;

// A pass that collapses fewer than this fraction of the live vertices ends
// the run (only the running time depends on it).
constexpr double kMinPassYield = 0.002;
constexpr int kMaxPasses = 8;

void validate(const Domain3& domain, const TetMesh3& mesh, const std::vector<int>& face_facets,
              const ImproveOptions& options) {
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

class Coarsener {
 public:
  Coarsener(CollapseMesh& mesh, const detail::VertexClasses& classes, Collapser& collapser)
      : mesh_(mesh), classes_(classes), collapser_(collapser), neighbours_(mesh.vertex_count()),
        version_(static_cast<std::size_t>(mesh.vertex_count()), 0) {}

  // One pass over every live edge; returns the number of collapses.
  std::int64_t pass() {
    queue_.start(all_edges());
    std::int64_t collapses = 0;
    while (!queue_.empty()) {
      const EdgeEntry e = queue_.pop();
      if (!current(e)) continue;
      const int kept = collapse_edge(e.a, e.b);
      if (kept < 0) continue;
      ++collapses;
      ++version_[static_cast<std::size_t>(kept)];
      push_edges_of(kept);
    }
    return collapses;
  }

 private:
  EdgeEntry entry(int a, int b) const {
    if (b < a) std::swap(a, b);
    return {length2(mesh_, a, b), a, b, version_[static_cast<std::size_t>(a)], version_[static_cast<std::size_t>(b)]};
  }

  bool current(const EdgeEntry& e) const {
    return mesh_.vertex_alive(e.a) && mesh_.vertex_alive(e.b) && version_[static_cast<std::size_t>(e.a)] == e.version_a &&
           version_[static_cast<std::size_t>(e.b)] == e.version_b;
  }

  std::vector<EdgeEntry> all_edges() {
    std::vector<EdgeEntry> edges;
    edges.reserve(static_cast<std::size_t>(mesh_.live_tets()) * 6 / 5 + 16);
    for (int a = 0; a < mesh_.vertex_count(); ++a) {
      if (!mesh_.vertex_alive(a)) continue;
      for (const int b : neighbours_.of(mesh_, a))
        if (b > a) edges.push_back(entry(a, b));
    }
    return edges;
  }

  void push_edges_of(int v) {
    for (const int x : neighbours_.of(mesh_, v))
      if (x != v) queue_.push(entry(v, x));
  }

  // Collapses the edge one way or the other; returns the kept vertex, or -1.
  // The vertex of the lower class goes first (an interior vertex before one
  // on a facet, on an edge); between equal classes the smaller id.
  int collapse_edge(int a, int b) {
    const bool b_first = classes_.of(b) < classes_.of(a);
    const int first = b_first ? b : a, second = b_first ? a : b;
    if (collapser_.try_collapse(first, second)) return second;
    if (collapser_.try_collapse(second, first)) return first;
    return -1;
  }

  CollapseMesh& mesh_;
  const detail::VertexClasses& classes_;
  Collapser& collapser_;
  Neighbours neighbours_;
  std::vector<std::uint32_t> version_;
  EdgeQueue queue_;
};

}  // namespace

ImproveStats improve_mesh(const Domain3& domain, TetMesh3& mesh, std::vector<int>& face_facets,
                          const ImproveOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  validate(domain, mesh, face_facets, options);
  TetrahedronQualityMemo memo;
  CollapseMesh work(mesh, face_facets, memo);
  const detail::VertexClasses classes = detail::classify_vertices(domain, mesh, face_facets);
  const detail::SizeBound size(options.max_size, options.size_points, options.sizes);
  Collapser collapser(work, classes, size, {options.aspect_cap, options.target_aspect}, memo);
  Coarsener coarsener(work, classes, collapser);

  ImproveStats stats;
  stats.tetrahedra_before = work.live_tets();
  stats.vertices_before = work.live_vertices();
  stats.worst_aspect_before = work.worst_aspect();
  while (stats.passes < kMaxPasses) {
    const std::int64_t done = coarsener.pass();
    ++stats.passes;
    stats.collapses += done;
    if (static_cast<double>(done) <= kMinPassYield * static_cast<double>(work.live_vertices())) break;
  }
  stats.tetrahedra_after = work.live_tets();
  stats.vertices_after = work.live_vertices();
  stats.worst_aspect_after = work.worst_aspect();
  work.write_back(mesh, face_facets);
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

}  // namespace pqmesh::improve3d
