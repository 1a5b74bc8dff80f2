// The 2D meshers' drivers (docs/algorithm/quad2d.md): quad_mesh (quadtree
// phases, mesh vertices, then the triangulation of the boxes) and
// mesh_polygon (the refined CDT of the input, certified against quad_mesh's
// angle bound, else quad_mesh).
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <numeric>

#include "cdt2d/constrained_delaunay.hpp"
#include "cdt2d/refine.hpp"
#include "pqmesh/alpha.hpp"
#include "pqmesh/errors.hpp"
#include "pqmesh/quadmesh.hpp"
#include "pqmesh/quadmesh_bound.hpp"
#include "pqmesh/quality.hpp"
#include "quad2d/improve_mesh.hpp"
#include "quad2d/mesh_points.hpp"
#include "quad2d/quadtree_builder.hpp"
#include "quad2d/radix_sort.hpp"
#include "quad2d/size_function.hpp"

namespace pqmesh {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Spreads the low 21 bits of v to the even bit positions 0, 2, ..., 40.
std::uint64_t spread21(std::uint32_t v) {
  std::uint64_t x = v & 0x1FFFFFu;
  x = (x | (x << 16)) & 0x0000FFFF0000FFFFull;
  x = (x | (x << 8)) & 0x00FF00FF00FF00FFull;
  x = (x | (x << 4)) & 0x0F0F0F0F0F0F0F0Full;
  x = (x | (x << 2)) & 0x3333333333333333ull;
  x = (x | (x << 1)) & 0x5555555555555555ull;
  return x;
}

// Interleaves the low 21 bits of x and y (x least significant).
std::uint64_t morton(std::uint32_t x, std::uint32_t y) { return spread21(x) | (spread21(y) << 1); }

// A spatially coherent order of the points (z-order on a 2^21 grid over the
// bounding box, ties by coordinates): the triangulation's point location walks
// from the last triangle, so this keeps insertion near linear.
std::vector<int> z_order(const std::vector<Vec2>& pts, Vec2 lo, Vec2 hi) {
  const double span = std::max({hi.x - lo.x, hi.y - lo.y, 1e-300});
  const double scale = static_cast<double>((1u << 21) - 1) / span;
  std::vector<std::pair<std::uint64_t, int>> keyed;
  keyed.reserve(pts.size());  // filled in order: no zeroing pass
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto qx = static_cast<std::uint32_t>(std::clamp((pts[i].x - lo.x) * scale, 0.0, 2097151.0));
    const auto qy = static_cast<std::uint32_t>(std::clamp((pts[i].y - lo.y) * scale, 0.0, 2097151.0));
    keyed.push_back({morton(qx, qy), static_cast<int>(i)});
  }
  // Points are sorted by (x, y) already, so ties by index are ties by
  // coordinates; the radix sort is stable, which keeps ties in index order.
  std::vector<std::pair<std::uint64_t, int>> scratch;
  quad2d::radix_sort(keyed, 42, [](const std::pair<std::uint64_t, int>& k) { return k.first; }, scratch);
  std::vector<int> order;
  order.reserve(keyed.size());
  for (const auto& k : keyed) order.push_back(k.second);
  return order;
}

// The region attribute for the triangles: P has no internal segments, so it is
// one region; its attribute is that of the first region point inside P.
bool region_attribute(const Domain2& d, int& attribute) {
  for (const Region2& r : d.pslg.regions)
    if (locate(d, r.point) == Location::Inside) {
      attribute = static_cast<int>(r.attribute);
      return true;
    }
  return false;
}

// The mesh vertices in z-order (the mesh keeps that order) and every loop
// side as the chain of its points, interior on the left. new_id maps a
// MeshPoints index to its mesh id; constraint_segment gives each constraint's
// input segment.
// The point array has room for `spare` more points (the refinement's).
cdt2d::CdtInput ordered_input(const Domain2& domain, const quad2d::MeshPoints& mp, std::size_t spare,
                              std::vector<int>& new_id, std::vector<int>& constraint_segment) {
  const std::vector<int> order = z_order(mp.points, domain.bbox_min, domain.bbox_max);
  new_id.assign(order.size(), -1);
  cdt2d::CdtInput in;
  in.points.reserve(order.size() + spare);
  for (std::size_t i = 0; i < order.size(); ++i) {
    new_id[static_cast<std::size_t>(order[i])] = static_cast<int>(i);
    in.points.push_back(mp.points[static_cast<std::size_t>(order[i])]);
  }
  for (std::size_t l = 0; l < domain.loops.size(); ++l) {
    const auto& loop = domain.loops[l];
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const int s = domain.loop_segments[l][k];
      const auto& chain = mp.segment_chain[static_cast<std::size_t>(s)];
      const bool forward = domain.pslg.segments[static_cast<std::size_t>(s)][0] == loop[k];
      for (std::size_t j = 0; j + 1 < chain.size(); ++j) {
        int u = new_id[static_cast<std::size_t>(chain[j])], w = new_id[static_cast<std::size_t>(chain[j + 1])];
        if (!forward) std::swap(u, w);
        in.constraints.push_back({u, w});
        constraint_segment.push_back(s);
      }
    }
  }
  return in;
}

// The refinement's options for n points: at most max(n, 1000) new points
// after the quadtree (its points already grade the mesh), or 64 n + 100000
// from the input alone (mesh_polygon: the refinement does all the grading).
cdt2d::RefineOptions refine_options(const QuadMeshOptions& options, std::size_t n, bool from_input) {
  cdt2d::RefineOptions ro;
  ro.min_angle_degrees = options.refine_angle_degrees;
  ro.max_new_points = from_input ? 64 * n + 100000 : std::max<std::size_t>(n, 1000);
  return ro;
}

// The constrained Delaunay triangulation of the points, refined when asked
// (docs/algorithm/quad2d.md "Triangulating the boxes", "Delaunay refinement
// pass"). Fills the mesh's vertices, triangles and boundary pieces;
// piece_segment gives each piece's input segment.
void triangulate(const Domain2& domain, cdt2d::CdtInput in, const std::vector<int>& constraint_segment,
                 const cdt2d::RefineOptions& ro, QuadMeshStats& stats, TriMesh2& mesh,
                 std::vector<int>& piece_segment) {
  if (ro.min_angle_degrees <= 0) {
    cdt2d::CdtOutput out = cdt2d::constrained_delaunay(in, true);
    mesh.vertices = std::move(in.points);
    mesh.triangles = std::move(out.triangles);
    mesh.edges = std::move(in.constraints);
    piece_segment = constraint_segment;
    return;
  }
  // Steiner points on a side are rounded onto its input segment, which the
  // support tells the refiner.
  cdt2d::SegmentSupport support;
  support.constraint_segment = constraint_segment;
  for (const auto& seg : domain.pslg.segments)
    support.segment_ends.push_back(
        {domain.pslg.vertices[static_cast<std::size_t>(seg[0])], domain.pslg.vertices[static_cast<std::size_t>(seg[1])]});
  cdt2d::RefineResult rr = cdt2d::refine_constrained_delaunay(std::move(in), ro, support);
  stats.refine_points = static_cast<std::int64_t>(rr.inserted);
  stats.refine_target_reached = rr.target_reached;
  mesh.vertices = std::move(rr.points);
  mesh.triangles = std::move(rr.triangles);
  mesh.edges = std::move(rr.constraints);
  for (const int origin : rr.constraint_origin)
    piece_segment.push_back(constraint_segment[static_cast<std::size_t>(origin)]);
}

// Markers: boundary pieces take their segment's marker; input vertices keep
// theirs, Steiner points on a segment take the segment's (Triangle's
// convention), interior points get 0; the triangles take the region attribute.
void assign_markers(const Domain2& domain, const quad2d::MeshPoints& mp, const std::vector<int>& new_id,
                    const std::vector<int>& piece_segment, TriMesh2& mesh) {
  const auto& seg_markers = domain.pslg.segment_markers;
  if (!seg_markers.empty())
    for (const int s : piece_segment) mesh.edge_markers.push_back(seg_markers[static_cast<std::size_t>(s)]);
  if (!domain.pslg.vertex_markers.empty()) {
    mesh.vertex_markers.assign(mesh.vertices.size(), 0);
    if (!seg_markers.empty())
      for (std::size_t e = 0; e < mesh.edges.size(); ++e)
        for (const int v : mesh.edges[e])
          mesh.vertex_markers[static_cast<std::size_t>(v)] = seg_markers[static_cast<std::size_t>(piece_segment[e])];
    for (std::size_t i = 0; i < mp.points.size(); ++i)
      if (mp.input_vertex[i] >= 0)
        mesh.vertex_markers[static_cast<std::size_t>(new_id[i])] =
            domain.pslg.vertex_markers[static_cast<std::size_t>(mp.input_vertex[i])];
  }
  int attribute = 0;
  if (region_attribute(domain, attribute)) mesh.triangle_markers.assign(mesh.triangles.size(), attribute);
}

// The mesh of P with the points mp (every point of mp a vertex, each segment
// the chain of its points): their CDT, refined when asked, with markers.
void triangulate_points(const Domain2& domain, const quad2d::MeshPoints& mp, const QuadMeshOptions& options,
                        bool from_input, QuadMeshResult& result) {
  const auto t0 = Clock::now();
  std::vector<int> new_id, constraint_segment, piece_segment;
  const std::size_t n = mp.points.size();
  const cdt2d::RefineOptions ro = refine_options(options, n, from_input);
  const std::size_t spare = options.refine_angle_degrees > 0 ? cdt2d::new_point_allowance(n, ro) : 0;
  cdt2d::CdtInput in = ordered_input(domain, mp, spare, new_id, constraint_segment);
  triangulate(domain, std::move(in), constraint_segment, ro, result.stats, result.mesh, piece_segment);
  result.stats.seconds_triangulate = seconds_since(t0);
  assign_markers(domain, mp, new_id, piece_segment, result.mesh);
}

// The input alone as MeshPoints: its vertices (sorted by (x, y), as
// generate_points sorts), each segment the chain of its two ends.
quad2d::MeshPoints input_points(const Domain2& domain) {
  const std::vector<Vec2>& v = domain.pslg.vertices;
  std::vector<int> order(v.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const Vec2 p = v[static_cast<std::size_t>(a)], q = v[static_cast<std::size_t>(b)];
    return p.x != q.x ? p.x < q.x : p.y < q.y;
  });
  quad2d::MeshPoints mp;
  std::vector<int> point_of(v.size());
  for (const int i : order) {
    point_of[static_cast<std::size_t>(i)] = static_cast<int>(mp.points.size());
    mp.points.push_back(v[static_cast<std::size_t>(i)]);
    mp.input_vertex.push_back(i);
  }
  for (const auto& seg : domain.pslg.segments)
    mp.segment_chain.push_back({point_of[static_cast<std::size_t>(seg[0])], point_of[static_cast<std::size_t>(seg[1])]});
  return mp;
}

// The smallest angle of the mesh in degrees (triangle_quality's measure).
double smallest_angle_degrees(const TriMesh2& mesh) {
  double smallest = 180;
  for (const auto& t : mesh.triangles) {
    const auto& v = mesh.vertices;
    smallest = std::min(smallest, triangle_quality(v[static_cast<std::size_t>(t[0])], v[static_cast<std::size_t>(t[1])],
                                                   v[static_cast<std::size_t>(t[2])]).min_angle_deg);
  }
  return smallest;
}

}  // namespace

QuadMeshResult quad_mesh(const Domain2& domain, const QuadMeshOptions& options) {
  const quad2d::SizeFunction2 size(options);
  QuadMeshResult result;
  QuadMeshStats& stats = result.stats;

  auto t0 = Clock::now();
  quad2d::MeshPoints mp;
  {  // the tree is released before the triangulation (peak memory)
    quad2d::QuadtreeBuilder builder(domain, size, options.protect_edges, stats);
    builder.build();
    stats.seconds_tree = seconds_since(t0);
    t0 = Clock::now();
    mp = quad2d::generate_points(builder, stats);
    stats.seconds_points = seconds_since(t0);
  }

  triangulate_points(domain, mp, options, false, result);
  return result;
}

namespace {

// The improvement stage's target angle (degrees): the refinement's angle, or
// 20 when refinement is off, raised to the angle bound the construction meets
// (quad_mesh_angle_bound): the output's smallest angle is at least min(target,
// the construction's), hence at least that bound.
double improve_target(const Domain2& domain, const QuadMeshOptions& options) {
  if (options.refine_angle_degrees <= 0) return 20;
  const double alpha = compute_alpha(domain.pslg.vertices, domain.loops).degrees();
  return std::max(options.refine_angle_degrees, quad_mesh_angle_bound(alpha, options.refine_angle_degrees));
}

// The improvement stage of mesh_polygon (quad2d/improve_mesh.hpp) on result's
// mesh, with its figures in the stats. No removal under a size bound.
void improve(const Domain2& domain, const QuadMeshOptions& options, bool sized, QuadMeshResult& result) {
  QuadMeshStats& stats = result.stats;
  const QualityReport before = quality_report(result.mesh);
  stats.constructed_triangles = before.elements;
  stats.constructed_min_angle = before.min_angle.min;
  stats.constructed_angle_counts = before.min_angle_hist.counts;
  if (!options.improve) return;
  const auto t0 = Clock::now();
  const double target = improve_target(domain, options);
  stats.improve_target_degrees = target;
  const quad2d::ImproveStats is = quad2d::improve_mesh(result.mesh, domain.pslg.vertices, target, !sized);
  stats.improved = true;
  stats.improve_removed = is.removed;
  stats.improve_moved = is.moved;
  stats.improve_flips = is.flips;
  stats.seconds_improve = seconds_since(t0);
}

// The construction of mesh_polygon (its header in pqmesh/quadmesh.hpp).
QuadMeshResult construct(const Domain2& domain, const QuadMeshOptions& options, bool sized) {
  if (options.quadtree || sized || options.protect_edges || options.refine_angle_degrees <= 0)
    return quad_mesh(domain, options);
  QuadMeshResult refined;
  triangulate_points(domain, input_points(domain), options, true, refined);
  refined.stats.refined_input = true;
  refined.stats.refined_input_min_angle = smallest_angle_degrees(refined.mesh);
  const double alpha = compute_alpha(domain.pslg.vertices, domain.loops).degrees();
  if (refined.stats.refined_input_min_angle >= quad_mesh_angle_bound(alpha, options.refine_angle_degrees))
    return refined;
  QuadMeshResult fallback = quad_mesh(domain, options);
  fallback.stats.refined_input_min_angle = refined.stats.refined_input_min_angle;
  fallback.stats.refined_input_triangles = static_cast<std::int64_t>(refined.mesh.triangles.size());
  return fallback;
}

}  // namespace

QuadMeshResult mesh_polygon(const Domain2& domain, const QuadMeshOptions& options) {
  const bool sized = options.max_size > 0 || !options.size_field.points.empty();
  QuadMeshResult result = construct(domain, options, sized);
  improve(domain, options, sized, result);
  return result;
}

}  // namespace pqmesh
