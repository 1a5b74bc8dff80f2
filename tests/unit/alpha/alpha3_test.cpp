// Hand-built outward-oriented domains for the alpha tests. Every facet loop is
// written so that its right-hand normal points out of P; the tests check this
// with signed_volume() > 0 (and compute_alpha itself rejects inconsistently
// oriented neighbours).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "pqmesh/alpha.hpp"
#include "pqmesh/errors.hpp"
#include "pqmesh/plc.hpp"

namespace pqmesh::test_alpha {
namespace {

Facet3 facet(std::vector<int> outer, std::vector<std::vector<int>> holes = {}) {
  Facet3 f;
  f.loops.push_back(std::move(outer));
  for (auto& h : holes) f.loops.push_back(std::move(h));
  return f;
}

// Volume by the divergence theorem: (1/3) sum over facets of q . A, with A the
// facet's vector area (hole loops turn the other way and subtract) and q any
// point of the facet's plane.
double signed_volume(const Plc3& p) {
  double vol = 0;
  for (const auto& f : p.facets) {
    Vec3 area{};
    for (const auto& L : f.loops)
      for (std::size_t i = 0; i < L.size(); ++i)
        area = area + 0.5 * cross(p.vertices[L[i]], p.vertices[L[(i + 1) % L.size()]]);
    vol += dot(p.vertices[f.loops[0][0]], area) / 3.0;
  }
  return vol;
}

// Axis-aligned box; vertex base + (x + 2y + 4z) for corner bits. outward =
// false reverses every loop (a cavity: its facets face into the box).
void add_box(Plc3& p, Vec3 lo, Vec3 hi, bool outward) {
  const int base = int(p.vertices.size());
  for (int k = 0; k < 8; ++k)
    p.vertices.push_back({(k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z});
  // Outward normals: -z, +z, -y, +y, -x, +x.
  const int loops[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& l : loops) {
    std::vector<int> L{base + l[0], base + l[1], base + l[2], base + l[3]};
    if (!outward) L = {L[3], L[2], L[1], L[0]};
    p.facets.push_back(facet(L));
  }
}

Plc3 unit_cube() {
  Plc3 p;
  add_box(p, {0, 0, 0}, {1, 1, 1}, true);
  return p;
}

Plc3 cube_with_cavity() {
  Plc3 p;
  add_box(p, {0, 0, 0}, {3, 3, 3}, true);
  add_box(p, {1, 1, 1}, {2, 2, 2}, false);
  return p;
}

Plc3 regular_tetrahedron(Vec3 shift = {}) {
  Plc3 p;
  p.vertices = {Vec3{1, 1, 1} + shift, Vec3{1, -1, -1} + shift, Vec3{-1, 1, -1} + shift, Vec3{-1, -1, 1} + shift};
  p.facets = {facet({1, 3, 2}), facet({0, 2, 3}), facet({0, 3, 1}), facet({0, 1, 2})};
  return p;
}

// Triangular prism along y whose cross-section (in xz) has a `deg` degree
// corner at the origin: O = (0, 0), A = (1, 0), B = (cos, sin). Facets:
// 0 cap y=0, 1 cap y=1, 2 bottom (z=0), 3 slanted top, 4 far side A-B.
Plc3 wedge(double deg) {
  const double t = deg * std::numbers::pi / 180, c = std::cos(t), s = std::sin(t);
  Plc3 p;
  p.vertices = {{0, 0, 0}, {1, 0, 0}, {c, 0, s}, {0, 1, 0}, {1, 1, 0}, {c, 1, s}};
  p.facets = {facet({0, 1, 2}), facet({3, 5, 4}), facet({0, 3, 4, 1}), facet({0, 2, 5, 3}), facet({1, 4, 5, 2})};
  return p;
}

// Prism over a counter-clockwise xy polygon, z in [0, 1]. Vertices: polygon
// i at z=0 is i, at z=1 is i + n. Facets: 0 bottom, 1 top, then side i over
// polygon edge i -> i+1.
Plc3 extrude(const std::vector<Vec2>& poly) {
  const int n = int(poly.size());
  Plc3 p;
  for (double z : {0.0, 1.0})
    for (auto q : poly) p.vertices.push_back({q.x, q.y, z});
  std::vector<int> bottom, top;
  for (int i = n - 1; i >= 0; --i) bottom.push_back(i);
  for (int i = 0; i < n; ++i) top.push_back(i + n);
  p.facets = {facet(bottom), facet(top)};
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    p.facets.push_back(facet({i, j, j + n, i + n}));
  }
  return p;
}

// L-block: [0,2]^2 x [0,1] minus [1,2]^2 x [0,1]; reflex vertical edge 3-9.
Plc3 l_block() { return extrude({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}); }

// 10x10x1 slab with a thin triangular notch cut from its top side down to the
// tip (5, 5) (vertex 4 / 11): the notch's two walls meet at 2*atan(0.1) ~ 11.42
// degrees measured OUTSIDE P, so no pair there may count.
Plc3 notched_slab() {
  return extrude({{0, 0}, {10, 0}, {10, 10}, {5.5, 10}, {5, 5}, {4.5, 10}, {0, 10}});
}

// Square pyramid: base (+-1, +-1, 0) (vertices 0..3), apex (0, 0, h) (vertex 4).
// Facets: 0 base, then lateral 1..4 over base edges 0-1, 1-2, 2-3, 3-0.
Plc3 square_pyramid(double h) {
  Plc3 p;
  p.vertices = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, h}};
  p.facets = {facet({0, 3, 2, 1}), facet({0, 1, 4}), facet({1, 2, 4}), facet({2, 3, 4}), facet({3, 0, 4})};
  return p;
}

constexpr double kPi = std::numbers::pi;
double deg(double d) { return d * kPi / 180; }

// Common checks: outward orientation of the literal, the thesis' remark
// alpha <= min dihedral, and a non-empty description.
AlphaResult alpha_of(const Plc3& p) {
  EXPECT_GT(signed_volume(p), 0) << "fixture is not oriented outward";
  AlphaResult r = compute_alpha(p);
  EXPECT_LE(r.radians, r.min_dihedral_radians + 1e-12);
  EXPECT_FALSE(r.describe(0).empty());
  return r;
}

bool has_vertex(const FaceRef& f, int v) { return f.kind == FaceRef::Kind::Edge && (f.a == v || f.b == v); }

TEST(Alpha3, UnitCubeIsRightAngle) {
  // Every face angle, dihedral and edge-edge angle of a cube is 90 degrees;
  // every edge-facet pair at a corner is an edge perpendicular to the facet.
  const AlphaResult r = alpha_of(unit_cube());
  EXPECT_NEAR(r.radians, kPi / 2, 1e-12);
  EXPECT_NEAR(r.min_dihedral_radians, kPi / 2, 1e-12);
  EXPECT_EQ(r.kind, "edge-edge");
}

TEST(Alpha3, RegularTetrahedronIsEdgeFacetAngle) {
  // At a vertex v the three edges pairwise make 60 degrees (face angles) and
  // each dihedral is acos(1/3) ~ 70.53 degrees. The edge e = v->a and the face
  // g = (v, b, c) not containing it: the angle between e and g's plane has
  // sine = (distance from a to plane vbc) / |va| = height / side = sqrt(2/3),
  // i.e. acos(1/sqrt(3)) ~ 54.7356 degrees; the projection of e into g is the
  // bisector of g's corner at v (inside the sector) and the sector between e
  // and it lies inside the tetrahedron. So alpha is that edge-facet angle.
  const double expected = std::acos(1 / std::sqrt(3.0));
  for (Vec3 shift : {Vec3{}, Vec3{1000.5, -3.25, 7}}) {
    const AlphaResult r = alpha_of(regular_tetrahedron(shift));
    EXPECT_NEAR(r.radians, expected, 1e-12);
    EXPECT_NEAR(r.degrees(), 54.735610317245346, 1e-9);
    EXPECT_EQ(r.kind, "edge-facet");
    EXPECT_TRUE(has_vertex(r.first, r.apex));
    EXPECT_EQ(r.second.kind, FaceRef::Kind::Facet);
    EXPECT_NEAR(r.min_dihedral_radians, std::acos(1.0 / 3.0), 1e-12);
  }
  const AlphaResult r = compute_alpha(regular_tetrahedron());
  EXPECT_NE(r.describe(1).find("alpha = 54.7356 deg (edge-facet) at vertex"), std::string::npos) << r.describe(1);
}

TEST(Alpha3, ThinWedgeIsFiveDegrees) {
  // Cross-section corner of 5 degrees at the prism edge 0-3: the dihedral
  // there, the cap corner angles at 0 and 3, and the cap edges against the
  // other long facet are all exactly 5 degrees; everything else is >= 87.5.
  const AlphaResult r = alpha_of(wedge(5));
  EXPECT_NEAR(r.degrees(), 5.0, 1e-9);
  EXPECT_NEAR(r.min_dihedral_radians, deg(5), 1e-12);
  EXPECT_TRUE(r.apex == 0 || r.apex == 3) << r.describe(0);
}

TEST(Alpha3, LBlockReflexEdgeDoesNotCount) {
  // All angles are 90 or 270 degrees (the reflex edge 3-9 has dihedral 270 and
  // the L caps a 270 degree corner); the 90 degree convex sector between the
  // two cap edges at the reflex vertex lies outside P.
  const AlphaResult r = alpha_of(l_block());
  EXPECT_NEAR(r.radians, kPi / 2, 1e-12);
  EXPECT_NEAR(r.min_dihedral_radians, kPi / 2, 1e-12);
}

TEST(Alpha3, CubeWithCubicalCavity) {
  // Cavity edges are reflex (270), cavity corners see the complement of an
  // octant; every angle is 90 or 270.
  const AlphaResult r = alpha_of(cube_with_cavity());
  EXPECT_NEAR(r.radians, kPi / 2, 1e-12);
  EXPECT_NEAR(r.min_dihedral_radians, kPi / 2, 1e-12);
}

TEST(Alpha3, NotchOutsideDoesNotCount) {
  // At the notch tip (vertices 4, 11) the two notch edges make 2*atan(0.1) ~
  // 11.42 degrees, but through the notch, i.e. outside P; inside P they make
  // 348.6. The remaining angles are 90 (slab corners, caps against walls)
  // and 90 + atan(0.1) ~ 95.71 (notch mouth corners and their vertical
  // dihedrals). Hence alpha = 90: a visibility test that let the sector
  // through the notch count would give 11.42.
  const AlphaResult r = alpha_of(notched_slab());
  EXPECT_NEAR(r.radians, kPi / 2, 1e-12) << r.describe(0);
}

TEST(Alpha3, TallSquarePyramidApexAngle) {
  // Apex (0,0,10), base (+-1,+-1,0). Adjacent lateral edges (1,1,-10) and
  // (1,-1,-10): cos = 100/102, ~11.37 degrees (face angle at the apex). The
  // opposite pair sees itself through the interior at acos(98/102) ~ 16.1.
  // Dihedrals: base edges atan(10) ~ 84.3, lateral edges 180 - acos(1/101) ~
  // 90.6; base corners: lateral edge vs base asin(10/sqrt(102)) ~ 81.9. The
  // projection of a lateral edge into a non-adjacent lateral face falls outside
  // that face's corner, so its edge-facet angle is an edge-edge one.
  const AlphaResult r = alpha_of(square_pyramid(10));
  EXPECT_NEAR(r.radians, std::acos(100.0 / 102.0), 1e-12);
  EXPECT_EQ(r.kind, "edge-edge");
  EXPECT_EQ(r.apex, 4);
  ASSERT_TRUE(has_vertex(r.first, 4) && has_vertex(r.second, 4));
  const int p = r.first.a == 4 ? r.first.b : r.first.a, q = r.second.a == 4 ? r.second.b : r.second.a;
  EXPECT_EQ((p - q + 4) % 4 == 1 || (q - p + 4) % 4 == 1, true) << r.describe(0);
  EXPECT_NEAR(r.min_dihedral_radians, std::atan(10.0), 1e-12);
}

TEST(Alpha3, LowSquarePyramidEdgeFacetBelowDihedral) {
  // Apex (0,0,1): base dihedrals are 45 degrees, face angles at the apex
  // acos(1/3) ~ 70.5, lateral dihedrals 120. At a base corner the lateral
  // edge (-1,-1,1) projects onto the base diagonal (inside the base corner)
  // and makes atan(1/sqrt(2)) ~ 35.26 degrees with the base: alpha, strictly
  // below the smallest dihedral as the thesis' remark allows.
  const AlphaResult r = alpha_of(square_pyramid(1));
  EXPECT_NEAR(r.radians, std::atan(1 / std::sqrt(2.0)), 1e-12);
  EXPECT_EQ(r.kind, "edge-facet");
  EXPECT_EQ(r.second.kind, FaceRef::Kind::Facet);
  EXPECT_EQ(r.second.id, 0);
  EXPECT_TRUE(r.apex >= 0 && r.apex < 4);
  EXPECT_NEAR(r.min_dihedral_radians, kPi / 4, 1e-12);
}

TEST(Alpha3, RejectsOpenOrInconsistentInput) {
  Plc3 open = unit_cube();
  open.facets.pop_back();
  try {
    compute_alpha(open);
    ADD_FAILURE() << "open boundary accepted";
  } catch (const DomainError& e) {
    EXPECT_EQ(e.code(), ErrorCode::OpenBoundary);
  }
  Plc3 flipped = unit_cube();
  auto& L = flipped.facets[0].loops[0];
  std::reverse(L.begin(), L.end());
  EXPECT_THROW(compute_alpha(flipped), DomainError);
  EXPECT_THROW(compute_alpha(Plc3{}), DomainError);
}

}  // namespace
}  // namespace pqmesh::test_alpha
