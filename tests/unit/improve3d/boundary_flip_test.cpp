// Boundary flips (src/improve3d/flips.hpp, edge removal of an edge inside a
// facet): the quadrilateral a c b d on the facet z = 0 with the long diagonal
// ab, and m - 1 tetrahedra (a, b, r_i, r_i+1) above it, r_0 = c .. r_m-1 = d
// on a half ellipse in the plane x = 0. Its two boundary triangles abc, abd
// are flat, so the tetrahedra on them are poor; the flip makes the short
// diagonal cd, the boundary triangles acd and bcd. For m = 3 (the 2-2 flip),
// 6 and 7: after the flip passes the facet holds exactly acd and bcd, with the
// facet's marker and facet id, each facing out (exact orient3d negative
// against its tetrahedron's fourth vertex and against a point inside the
// union: check3d's outward orientation), every tetrahedron positive, the
// volume unchanged.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "improve3d/collapse_mesh.hpp"
#include "improve3d/flips.hpp"
#include "improve3d/size_bound.hpp"
#include "pqmesh/quality.hpp"
#include "predicates/predicates.hpp"
#include "quality/tetrahedron_quality_memo.hpp"

namespace pqmesh::improve3d::detail {
namespace {

constexpr int kA = 0, kB = 1, kC = 2;  // r_i is vertex 2 + i
constexpr int kBottomMarker = 7, kBottomFacet = 0;
const Vec3 kInside{0, 0, 0.1};

struct HalfBipyramid {
  TetMesh3 mesh;
  std::vector<int> face_facets;
  int d = -1;
};

Vec3 at(const TetMesh3& m, int v) { return m.vertices[static_cast<std::size_t>(v)]; }

// Appends face (x, y, z), turned to face away from kInside, with its marker and facet.
void add_face(HalfBipyramid& h, int x, int y, int z, int marker, int facet) {
  std::array<int, 3> f{x, y, z};
  if (orient3d(at(h.mesh, x), at(h.mesh, y), at(h.mesh, z), kInside) != Sign::Negative) std::swap(f[1], f[2]);
  h.mesh.faces.push_back(f);
  h.mesh.face_markers.push_back(marker);
  h.face_facets.push_back(facet);
}

HalfBipyramid half_bipyramid(int m) {
  HalfBipyramid h;
  const double pi = std::acos(-1.0);
  h.mesh.vertices = {{-1, 0, 0}, {1, 0, 0}};
  for (int i = 0; i < m; ++i) {
    const bool end = i == 0 || i == m - 1;  // exactly on the facet: sin(pi) is not 0 in floating point
    h.mesh.vertices.push_back({0, -0.2 * std::cos(pi * i / (m - 1)), end ? 0 : 0.5 * std::sin(pi * i / (m - 1))});
  }
  h.d = kC + m - 1;
  for (int i = 0; i + 1 < m; ++i) {
    std::array<int, 4> k{kA, kB, kC + i, kC + i + 1};
    if (orient3d(at(h.mesh, k[0]), at(h.mesh, k[1]), at(h.mesh, k[2]), at(h.mesh, k[3])) != Sign::Positive)
      std::swap(k[0], k[1]);
    h.mesh.tetrahedra.push_back(k);
    h.mesh.tetrahedron_markers.push_back(3);
    add_face(h, kA, kC + i, kC + i + 1, 1, 1 + 2 * i);  // the upper faces: one facet each
    add_face(h, kB, kC + i, kC + i + 1, 1, 2 + 2 * i);
  }
  add_face(h, kA, kB, kC, kBottomMarker, kBottomFacet);
  add_face(h, kA, kB, h.d, kBottomMarker, kBottomFacet);
  return h;
}

double volume(const TetMesh3& m) {
  double v = 0;
  for (const auto& k : m.tetrahedra) v += tetrahedron_quality(at(m, k[0]), at(m, k[1]), at(m, k[2]), at(m, k[3])).volume;
  return v;
}

// The vertex of tetrahedron k not on face f.
int fourth(const std::array<int, 4>& k, const std::array<int, 3>& f) {
  for (const int x : k)
    if (std::find(f.begin(), f.end(), x) == f.end()) return x;
  return -1;
}

TEST(BoundaryFlip, NewBoundaryTrianglesFaceOutAndKeepTheFacet) {
  for (const int m : {3, 6, 7}) {
    const std::string what = "ring of " + std::to_string(m);
    HalfBipyramid h = half_bipyramid(m);
    const double before = volume(h.mesh);
    TetrahedronQualityMemo memo;
    CollapseMesh work(h.mesh, h.face_facets, memo);
    const std::vector<Vec3> no_points;  // SizeBound keeps references
    const std::vector<double> no_sizes;
    const SizeBound size(0, no_points, no_sizes);
    Flipper flipper(work, size, 1e9);
    for (int pass = 0; pass < 10 && flipper.pass() > 0;) ++pass;
    EXPECT_EQ(flipper.boundary_flips(), 1) << what;
    TetMesh3 out = h.mesh;
    std::vector<int> facets;
    std::move(work).write_back(out, facets);  // flipper is done with work
    EXPECT_NEAR(volume(out), before, 1e-12) << what;
    std::vector<std::array<int, 3>> bottom;
    for (std::size_t f = 0; f < out.faces.size(); ++f) {
      std::array<int, 3> s = out.faces[f];
      const int marker = out.face_markers[f];
      if (facets[f] != kBottomFacet) {
        EXPECT_NE(marker, kBottomMarker) << what;
        continue;
      }
      EXPECT_EQ(marker, kBottomMarker) << what;
      // Outward: the tetrahedron holding the face lies on its negative side.
      const Vec3 p = at(out, s[0]), q = at(out, s[1]), r = at(out, s[2]);
      EXPECT_EQ(orient3d(p, q, r, kInside), Sign::Negative) << what;
      int holders = 0;
      for (const auto& k : out.tetrahedra) {
        if (!std::all_of(s.begin(), s.end(), [&](int x) { return std::find(k.begin(), k.end(), x) != k.end(); }))
          continue;
        ++holders;
        EXPECT_EQ(orient3d(p, q, r, at(out, fourth(k, s))), Sign::Negative) << what;
      }
      EXPECT_EQ(holders, 1) << what;
      std::sort(s.begin(), s.end());
      bottom.push_back(s);
    }
    std::sort(bottom.begin(), bottom.end());
    std::array<int, 3> acd{kA, kC, h.d}, bcd{kB, kC, h.d};
    std::sort(bcd.begin(), bcd.end());
    EXPECT_EQ(bottom, (std::vector<std::array<int, 3>>{acd, bcd})) << what;
    for (const auto& k : out.tetrahedra)
      EXPECT_EQ(orient3d(at(out, k[0]), at(out, k[1]), at(out, k[2]), at(out, k[3])), Sign::Positive) << what;
    for (const int marker : out.tetrahedron_markers) EXPECT_EQ(marker, 3) << what;
  }
}

}  // namespace
}  // namespace pqmesh::improve3d::detail
