// The default 2D mesh's improvement stage (improve_mesh.hpp).
#include "quad2d/improve_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "improve2d/quality_pass.hpp"

namespace pqmesh::quad2d {

namespace {

// Smoothing moves the vertices of stars whose smallest angle is below the
// target plus this many degrees (the rest are left: they are good already).
constexpr double kSmoothingBand = 10;
// Rounds of (smoothing, coarsening), then smoothing sweeps (improve_mesh.hpp).
constexpr int kSmoothingRounds = 3;
constexpr int kFinalSmoothingSweeps = 2;

double radians(double degrees) { return degrees * std::numbers::pi / 180; }

detail::QualityPassOptions pass_options(double target_degrees, bool coarsen) {
  detail::QualityPassOptions options;
  options.target = radians(target_degrees);
  options.smoothing_rounds = kSmoothingRounds;
  options.final_smoothing_sweeps = kFinalSmoothingSweeps;
  options.smoothing_below = radians(target_degrees + kSmoothingBand);
  options.large_cavities = false;
  options.coarsen = coarsen;
  return options;
}

// The smallest angle of abc is below theta (< 60 degrees): it lies opposite
// the shortest side, between the other two (lengths b, c), and is acute, so it
// is below theta exactly when (2 area / (b c))^2 < sin^2 theta. A measurement
// that chooses where to work, no trigonometry per triangle.
bool smallest_angle_below(Vec2 a, Vec2 b, Vec2 c, double sin2_theta) {
  const double ab = dot(b - a, b - a), bc = dot(c - b, c - b), ca = dot(a - c, a - c);
  const double twice_area = cross(b - a, c - a);
  const double others = ab <= bc && ab <= ca ? bc * ca : bc <= ca ? ab * ca : ab * bc;
  return twice_area * twice_area < sin2_theta * others;
}

// The triangles the pass may change when it removes nothing: the stars of the
// vertices of every triangle whose smallest angle is below `below` (radians).
// The pass sees them as a mesh of their own, whose border vertices have open
// stars and stay fixed, so every vertex it moves has its whole star inside.
std::vector<char> band_stars(const TriMesh2& mesh, double below) {
  std::vector<char> vertex_in(mesh.vertices.size(), 0), in(mesh.triangles.size(), 0);
  const double sin2 = std::sin(below) * std::sin(below);
  for (const auto& t : mesh.triangles) {
    const auto& v = mesh.vertices;
    if (smallest_angle_below(v[std::size_t(t[0])], v[std::size_t(t[1])], v[std::size_t(t[2])], sin2))
      for (const int x : t) vertex_in[std::size_t(x)] = 1;
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (const int x : mesh.triangles[t])
      if (vertex_in[std::size_t(x)]) in[t] = 1;
  return in;
}

// The pass on the triangles marked `in` only (no removal: the pass keeps every
// vertex and the triangle count), written back into `mesh`.
detail::QualityPassStats improve_part(TriMesh2& mesh, const std::vector<char>& in,
                                      const detail::QualityPassOptions& options) {
  std::vector<int> local(mesh.vertices.size(), -1), global;
  std::vector<std::size_t> slots;
  TriMesh2 part;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!in[t]) continue;
    slots.push_back(t);
    std::array<int, 3> lt{};
    for (int k = 0; k < 3; ++k) {
      int& id = local[std::size_t(mesh.triangles[t][std::size_t(k)])];
      if (id < 0) {
        id = int(global.size());
        global.push_back(mesh.triangles[t][std::size_t(k)]);
        part.vertices.push_back(mesh.vertices[std::size_t(global.back())]);
      }
      lt[std::size_t(k)] = id;
    }
    part.triangles.push_back(lt);
  }
  const detail::QualityPassStats st = detail::improve_min_angle(part, 0, options);
  // No vertex was removed, so the part's vertex ids are unchanged.
  for (std::size_t i = 0; i < global.size(); ++i) mesh.vertices[std::size_t(global[i])] = part.vertices[i];
  for (std::size_t k = 0; k < slots.size(); ++k)
    for (int j = 0; j < 3; ++j)
      mesh.triangles[slots[k]][std::size_t(j)] = global[std::size_t(part.triangles[k][std::size_t(j)])];
  return st;
}

// The boundary vertices that are not input vertices (exact coordinates).
std::vector<char> boundary_steiner_points(const TriMesh2& mesh, std::vector<Vec2> input_vertices) {
  const auto before = [](Vec2 p, Vec2 q) { return p.x != q.x ? p.x < q.x : p.y < q.y; };
  std::sort(input_vertices.begin(), input_vertices.end(), before);
  std::vector<char> removable(mesh.vertices.size(), 0);
  for (const auto& e : mesh.edges)
    for (const int v : e)
      removable[std::size_t(v)] =
          !std::binary_search(input_vertices.begin(), input_vertices.end(), mesh.vertices[std::size_t(v)], before);
  return removable;
}

}  // namespace

ImproveStats improve_mesh(TriMesh2& mesh, const std::vector<Vec2>& input_vertices, double target_degrees,
                          bool coarsen) {
  detail::QualityPassOptions options = pass_options(target_degrees, coarsen);
  if (!coarsen) {
    const detail::QualityPassStats pass = improve_part(mesh, band_stars(mesh, options.smoothing_below), options);
    return {0, pass.moves, pass.flips};
  }
  options.boundary_removable = boundary_steiner_points(mesh, input_vertices);
  const bool had_markers = !mesh.triangle_markers.empty();
  // first_steiner 0: every vertex may change whose star is a disk around it,
  // i.e. every interior vertex (P's input vertices are all on its boundary).
  const detail::QualityPassStats pass = detail::improve_min_angle(mesh, 0, options);
  if (!had_markers) mesh.triangle_markers.clear();
  return {pass.coarsened + pass.removals, pass.moves, pass.flips};
}

}  // namespace pqmesh::quad2d
