#pragma once
// The whole-mesh check every tet_mesh test runs: check_mesh valid (volume,
// conformity, every facet recovered by boundary triangles), and every boundary
// triangle carries the marker of a facet whose plane passes through each of
// its vertices' ulp boxes (within_ulp_of_plane, the checker's rule for rounded
// boundary points, docs/algorithm/quality.md "The validity checker"), decided
// here independently of the mesher's own choice; every input marker is used.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>

#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/tetmesh.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::test {

// Which octree made a mesh (TetSeparation), for the tests' lines: "lightest",
// "light", "near N faces" or "thesis", with the reason the last lighter mesh was
// dropped.
inline std::string octree_used(const TetMeshStats& s) {
  std::string out = s.separated                 ? "thesis octree"
                    : s.separated_faces > 0       ? "octree separated near " + std::to_string(s.separated_faces) + " faces"
                    : s.extended_margin == 1      ? "lightest octree"
                                                  : "light octree";
  if (!s.light_rejected.empty()) out += " (dropped: " + s.light_rejected.substr(0, 100) + ")";
  return out;
}

// Three non-collinear vertices of facet f's outer loop (exact: some
// projection of the three points is not collinear).
inline bool facet_plane(const Domain3& d, std::size_t f, Vec3& a, Vec3& b, Vec3& c) {
  const auto& loop = d.plc.facets[f].loops[0];
  const auto& P = d.plc.vertices;
  for (std::size_t k = 2; k < loop.size(); ++k) {
    a = P[loop[0]], b = P[loop[1]], c = P[loop[k]];
    if (orient2d_projected(a, b, c, 0) != Sign::Zero || orient2d_projected(a, b, c, 1) != Sign::Zero ||
        orient2d_projected(a, b, c, 2) != Sign::Zero)
      return true;
  }
  return false;
}

inline void expect_valid_with_markers(const std::string& what, const TetMeshResult& r, const Domain3& d) {
  const CheckReport c = check_mesh(r.mesh, d);
  EXPECT_TRUE(c.valid()) << what << "\n" << c.to_text();
  EXPECT_EQ(r.mesh.face_markers.size(), r.mesh.faces.size());
  std::set<int> used, input;
  for (const Facet3& f : d.plc.facets) input.insert(f.marker);
  for (std::size_t i = 0; i < r.mesh.faces.size(); ++i) {
    const int m = r.mesh.face_markers[i];
    used.insert(m);
    bool on_some = false;
    for (std::size_t f = 0; f < d.plc.facets.size() && !on_some; ++f) {
      Vec3 a, b, e;
      if (d.plc.facets[f].marker != m || !facet_plane(d, f, a, b, e)) continue;
      bool all = true;
      for (const int v : r.mesh.faces[i]) all = all && within_ulp_of_plane(r.mesh.vertices[v], a, b, e);
      on_some = all;
    }
    EXPECT_TRUE(on_some) << what << ": boundary triangle " << i << " (marker " << m
                         << ") is not within an ulp of a facet with that marker";
    if (!on_some) break;
  }
  EXPECT_EQ(used, input) << what;
}

// Stronger marker check for coplanar facets with different markers (flat
// edges): every boundary triangle's centroid lies in a facet triangle (closed,
// exact orient2d in the projection dropping the facet normal's dominant axis)
// of a facet with its marker, and the boundary area per marker equals the
// input area of the facets with that marker (relative 1e-9: sums of rounded
// areas). Both are derived from the input, not from the mesher.
inline void expect_markers_in_their_facets(const std::string& what, const TetMeshResult& r, const Domain3& d) {
  auto area = [](Vec3 a, Vec3 b, Vec3 c) { return 0.5 * norm(cross(b - a, c - a)); };
  const auto& P = d.plc.vertices;
  std::map<int, double> input_area, mesh_area;
  for (std::size_t t = 0; t < d.facet_triangles.size(); ++t) {
    const auto& tri = d.facet_triangles[t];
    input_area[d.plc.facets[static_cast<std::size_t>(d.facet_triangle_owner[t])].marker] +=
        area(P[tri[0]], P[tri[1]], P[tri[2]]);
  }
  std::size_t misplaced = 0;
  for (std::size_t i = 0; i < r.mesh.faces.size(); ++i) {
    const int m = r.mesh.face_markers[i];
    const auto& f = r.mesh.faces[i];
    const Vec3 a = r.mesh.vertices[f[0]], b = r.mesh.vertices[f[1]], c = r.mesh.vertices[f[2]];
    mesh_area[m] += area(a, b, c);
    const Vec3 g = (1.0 / 3) * (a + b + c);
    bool inside = false;
    for (std::size_t t = 0; t < d.facet_triangles.size() && !inside; ++t) {
      const std::size_t owner = static_cast<std::size_t>(d.facet_triangle_owner[t]);
      if (d.plc.facets[owner].marker != m) continue;
      const int drop = dominant_axis(d.facet_normals[owner]);
      const auto& tri = d.facet_triangles[t];
      const Sign s = orient2d_projected(P[tri[0]], P[tri[1]], P[tri[2]], drop);
      inside = s != Sign::Zero && orient2d_projected(P[tri[0]], P[tri[1]], g, drop) != -s &&
               orient2d_projected(P[tri[1]], P[tri[2]], g, drop) != -s &&
               orient2d_projected(P[tri[2]], P[tri[0]], g, drop) != -s;
    }
    misplaced += inside ? 0 : 1;
  }
  EXPECT_EQ(misplaced, 0u) << what << ": boundary triangles whose centroid lies in no facet with their marker";
  for (const auto& [m, want] : input_area)
    EXPECT_NEAR(mesh_area[m], want, 1e-9 * want) << what << ": boundary area with marker " << m;
}

}  // namespace pqmesh::test
