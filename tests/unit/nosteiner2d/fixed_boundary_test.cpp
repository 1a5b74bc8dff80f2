// Fixed-boundary mode for local remeshing (thesis §1.2): cut
// the triangles of a disk out of a quad_mesh mesh, take the cut boundary as a
// polygon (its subdivision kept exactly: many consecutive sides are collinear,
// i.e. straight angles, which make_domain accepts), triangulate it without
// boundary Steiner points, stitch it back, and check the whole mesh against
// the original domain. The plain mode is the fixed-boundary mode: the output
// keeps every input vertex (ids 0..n-1, same coordinates) and every input
// segment as one mesh edge, so stitching is a renumbering.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "nosteiner_run.hpp"
#include "pqmesh/quadmesh.hpp"
#include "pqmesh/read_domain.hpp"
#include "predicates/predicates.hpp"
#include "support/paths.hpp"

namespace pqmesh {
namespace {

struct Cut {
  std::vector<int> loop;  // mesh vertex ids, the cut region on the left
  std::vector<char> cut;  // per triangle
  int straight = 0;       // loop vertices with a straight angle (exact orient2d = 0)
};

// The triangles whose centroid lies in the disk form the cut; its boundary
// must be one simple loop (every boundary vertex on exactly two boundary
// edges), else the caller tries another radius.
bool cut_disk(const TriMesh2& m, Vec2 c, double radius, Cut& out) {
  out = Cut{};
  out.cut.assign(m.triangles.size(), 0);
  for (std::size_t i = 0; i < m.triangles.size(); ++i) {
    Vec2 g{0, 0};
    for (int v : m.triangles[i]) g = g + m.vertices[std::size_t(v)];
    g = Vec2{g.x / 3, g.y / 3};
    out.cut[i] = (g.x - c.x) * (g.x - c.x) + (g.y - c.y) * (g.y - c.y) < radius * radius;
  }
  std::map<std::pair<int, int>, int> edges;  // directed edge -> count within the cut
  for (std::size_t i = 0; i < m.triangles.size(); ++i)
    if (out.cut[i])
      for (int k = 0; k < 3; ++k) ++edges[{m.triangles[i][std::size_t(k)], m.triangles[i][std::size_t((k + 1) % 3)]}];
  std::map<int, int> next;
  for (const auto& [e, n] : edges)
    if (!edges.contains({e.second, e.first})) {
      if (next.contains(e.first)) return false;  // pinch vertex
      next[e.first] = e.second;
    }
  if (next.empty()) return false;
  int v = next.begin()->first;
  do {
    out.loop.push_back(v);
    v = next[v];
  } while (v != out.loop.front() && out.loop.size() <= next.size());
  if (out.loop.size() != next.size()) return false;  // more than one loop
  const std::size_t n = out.loop.size();
  for (std::size_t k = 0; k < n; ++k)
    out.straight += orient2d(m.vertices[std::size_t(out.loop[(k + n - 1) % n])], m.vertices[std::size_t(out.loop[k])],
                             m.vertices[std::size_t(out.loop[(k + 1) % n])]) == Sign::Zero;
  return true;
}

void remesh_disk(const std::string& name, Vec2 centre, const NoSteinerOptions& options) {
  SCOPED_TRACE(name);
  const Domain2 domain = make_domain(read_pslg(test::data_path("2d/" + name + ".poly")));
  QuadMeshOptions qo;
  qo.max_size = 1.0 / 16;
  const TriMesh2 outer = quad_mesh(domain, qo).mesh;
  Cut cut;
  bool found = false;
  for (double radius : {0.3, 0.29, 0.31, 0.28, 0.32, 0.27, 0.33})  // first radius giving one simple loop
    if (cut_disk(outer, centre, radius, cut)) {
      found = true;
      break;
    }
  ASSERT_TRUE(found);
  Pslg2 hole;
  const int n = int(cut.loop.size());
  for (int k = 0; k < n; ++k) {
    hole.vertices.push_back(outer.vertices[std::size_t(cut.loop[std::size_t(k)])]);
    hole.segments.push_back({k, (k + 1) % n});
  }
  const Domain2 hole_domain = make_domain(hole);  // straight angles accepted
  test::RunStats st;
  const NoSteinerResult res = test::run_and_check(hole_domain, name + " disk", st, options);
  // Stitch: hole vertex k is outer vertex cut.loop[k]; interior vertices are new.
  TriMesh2 whole;
  whole.vertices = outer.vertices;
  std::vector<int> map(res.mesh.vertices.size());
  for (std::size_t v = 0; v < map.size(); ++v) {
    if (v < std::size_t(n)) {
      map[v] = cut.loop[v];
      EXPECT_EQ(res.mesh.vertices[v].x, outer.vertices[std::size_t(cut.loop[v])].x);
      EXPECT_EQ(res.mesh.vertices[v].y, outer.vertices[std::size_t(cut.loop[v])].y);
    } else {
      map[v] = int(whole.vertices.size());
      whole.vertices.push_back(res.mesh.vertices[v]);
    }
  }
  for (std::size_t i = 0; i < outer.triangles.size(); ++i)
    if (!cut.cut[i]) whole.triangles.push_back(outer.triangles[i]);
  for (auto t : res.mesh.triangles) {
    for (int& v : t) v = map[std::size_t(v)];
    whole.triangles.push_back(t);
  }
  // Outer vertices strictly inside the cut are on no triangle now: renumber.
  std::vector<int> used(whole.vertices.size(), -1);
  TriMesh2 compact;
  for (auto& t : whole.triangles)
    for (int& v : t) {
      if (used[std::size_t(v)] < 0) {
        used[std::size_t(v)] = int(compact.vertices.size());
        compact.vertices.push_back(whole.vertices[std::size_t(v)]);
      }
      v = used[std::size_t(v)];
    }
  compact.triangles = std::move(whole.triangles);
  whole = std::move(compact);
  const CheckReport r = check_mesh(whole, domain);
  EXPECT_TRUE(r.valid()) << r.to_text();
  std::cout << "[fixed boundary] " << name << ": cut " << n << " boundary vertices (" << cut.straight
            << " straight angles), " << std::count(cut.cut.begin(), cut.cut.end(), 1) << " triangles -> "
            << res.mesh.triangles.size() << " (" << to_string(res.stats.path) << ", pipeline "
            << to_string(res.stats.pipeline_path) << "); stitched mesh " << whole.triangles.size()
            << " triangles, valid " << r.valid() << "\n";
}

TEST(NoSteinerFixedBoundary, DiskCutFromQuadMesh) {
  remesh_disk("square", {0.5, 0.5}, test::raw_options());
  const NoSteinerOptions defaults;
  remesh_disk("square", {0.5, 0.5}, defaults);
  remesh_disk("regions", {1.0, 0.7}, test::raw_options());
}

}  // namespace
}  // namespace pqmesh
