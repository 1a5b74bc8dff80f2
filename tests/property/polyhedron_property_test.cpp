// Property tests of the 3D foundation (make_domain, Domain3, locate,
// compute_alpha, facet triangulation) over 200 seeded random polyhedra
// (tests/support/random_domains.hpp: right prisms and frustums over random
// polygons with holes, so with through-holes, sharp vertical edges from the
// polygon's spikes, and box or prism cavities). Expected values come from the
// generator's structured description (RandomPolyhedron), never from Domain3.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "pqmesh/alpha.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/errors.hpp"
#include "predicates/predicates.hpp"
#include "support/random_domains.hpp"

namespace pqmesh::test {
namespace {

constexpr std::uint64_t kPolyhedra = 200;

using Loop = std::vector<Vec2>;


double polygon_area(const std::vector<Loop>& loops) {  // outer CCW, holes CW
  double a = 0;
  for (const Loop& L : loops) a += shoelace(L);
  return a;
}

// Volume of the solid {(c + lambda(z)(p - c), z)}: the section at height z is
// the base scaled by lambda(z) = 1 + (s - 1) z / h, so its area is
// A lambda(z)^2 and the integral over [0, h] is A h (1 + s + s^2) / 3 (s = 1:
// A h). Cavities are right prisms: footprint area times height.
double expected_volume(const RandomPolyhedron& R) {
  const double s = R.top_scale;
  double v = polygon_area(R.base.loops) * R.height * (1 + s + s * s) / 3;
  for (const Cavity& c : R.cavities) v -= shoelace(c.footprint) * (c.z1 - c.z0);
  return v;
}

// --- an independent exact point-in-polygon-with-holes ---------------------

bool on_segment(Vec2 p, Vec2 a, Vec2 b) {
  return orient2d(a, b, p) == Sign::Zero && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
         std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

// Crossing parity over all loops with the half-open rule (a side counts when
// p.y is in [min y, max y) and p is strictly on the side's left when walking
// upwards); Boundary when p is on a side.
Location locate2(const std::vector<Loop>& loops, Vec2 p) {
  bool in = false;
  for (const Loop& L : loops)
    for (std::size_t i = 0; i < L.size(); ++i) {
      const Vec2 a = L[i], b = L[(i + 1) % L.size()];
      if (on_segment(p, a, b)) return Location::Boundary;
      if (a.y <= p.y && p.y < b.y && orient2d(a, b, p) == Sign::Positive) in = !in;
      if (b.y <= p.y && p.y < a.y && orient2d(a, b, p) == Sign::Negative) in = !in;
    }
  return in ? Location::Inside : Location::Outside;
}

// Right prisms only: P = base x [0, h] minus the closed cavities
// footprint x [z0, z1], so p is on dP when it is on the prism's boundary or on
// a cavity's boundary, inside when strictly inside the prism and outside every
// closed cavity.
Location prism_oracle(const RandomPolyhedron& R, Vec3 p) {
  const Vec2 q{p.x, p.y};
  if (p.z < 0 || p.z > R.height) return Location::Outside;
  const Location in_base = locate2(R.base.loops, q);
  if (in_base == Location::Outside) return Location::Outside;
  if (in_base == Location::Boundary || p.z == 0 || p.z == R.height) return Location::Boundary;
  for (const Cavity& c : R.cavities) {
    if (p.z < c.z0 || p.z > c.z1) continue;
    const Location in_cavity = locate2({c.footprint}, q);
    if (in_cavity == Location::Outside) continue;
    return in_cavity == Location::Boundary || p.z == c.z0 || p.z == c.z1 ? Location::Boundary : Location::Outside;
  }
  return Location::Inside;
}

const char* name(Location l) {
  return l == Location::Inside ? "inside" : l == Location::Boundary ? "boundary" : "outside";
}

// Dyadic uniform draw in [lo, hi] on a grid of 2^-bits (relative to hi - lo),
// from a small xorshift stream (the test needs no particular distribution).
struct Points {
  std::uint64_t state;
  explicit Points(std::uint64_t seed) : state(seed * 0x9e3779b97f4a7c15ULL + 1) {}
  std::uint64_t next() {
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return state;
  }
  double in(double lo, double hi) {
    const double t = std::ldexp(static_cast<double>(next() >> 44), -20);  // k / 2^20
    const double v = lo + t * (hi - lo);
    return std::ldexp(std::round(std::ldexp(v, 30)), -30);  // dyadic (and near [lo, hi])
  }
  template <class T>
  const T& pick(const std::vector<T>& v) { return v[next() % v.size()]; }
};

// ---------------------------------------------------------------------------

// Property 1 (3D), 4 and 6: validity, shells, volume, alpha, triangulation.
TEST(PolyhedronProperty, DomainVolumeAlphaAndFacetTriangles) {
  int alpha_checked = 0;
  for (std::uint64_t seed = 0; seed < kPolyhedra; ++seed) {
    SCOPED_TRACE(describe_polyhedron(seed));
    const RandomPolyhedron R = random_polyhedron_detail(seed);
    EXPECT_EQ(R.split_quads, 0);
    Domain3 d;
    try {
      d = make_domain(R.plc);
    } catch (const Error& e) {
      ADD_FAILURE() << "make_domain rejected a generated polyhedron: " << e.what();
      continue;
    }
    // One exterior shell plus one floater per cavity (thesis §4.1.6).
    ASSERT_EQ(d.shells.size(), 1 + R.cavities.size());
    EXPECT_TRUE(d.shells[0].exterior);

    // Property 4: volume.
    const double volume = expected_volume(R);
    EXPECT_NEAR(d.volume, volume, 1e-12 * volume);

    // Property 6: per facet, the triangles' areas add up to the facet's area
    // (Newell's vector area of the outer loop minus those of the holes, each
    // relative to the loop's first vertex); every triangle faces the same way
    // as its facet's outward normal; and the signed volumes of the tetrahedra
    // (apex, triangle) add up to the domain's volume (divergence theorem: the
    // apex is arbitrary). The apex is vertex 0 rather than the origin: the
    // generator translates domains by up to 4 units, and from the origin the
    // cancellation (diameter of |coordinates|^3 over the volume) would cost
    // more than the 1e-12 tolerance.
    const auto& V = d.plc.vertices;
    const std::size_t nf = d.plc.facets.size();
    std::vector<double> tri_area(nf, 0);
    double six_volume = 0;
    const Vec3 apex = V[0];
    ASSERT_EQ(d.facet_triangles.size(), d.facet_triangle_owner.size());
    EXPECT_TRUE(std::is_sorted(d.facet_triangle_owner.begin(), d.facet_triangle_owner.end()));
    for (std::size_t t = 0; t < d.facet_triangles.size(); ++t) {
      const auto& T = d.facet_triangles[t];
      const int f = d.facet_triangle_owner[t];
      const Vec3 n = cross(V[T[1]] - V[T[0]], V[T[2]] - V[T[0]]);
      tri_area[f] += norm(n) / 2;
      EXPECT_GT(dot(n, d.facet_normals[f]), 0) << "triangle " << t << " of facet " << f << " faces inwards";
      six_volume += dot(V[T[0]] - apex, cross(V[T[1]] - apex, V[T[2]] - apex));
    }
    for (std::size_t f = 0; f < nf; ++f) {
      double area = 0;
      for (std::size_t l = 0; l < d.plc.facets[f].loops.size(); ++l) {
        const auto& L = d.plc.facets[f].loops[l];
        Vec3 twice{};
        for (std::size_t i = 1; i + 1 < L.size(); ++i) twice = twice + cross(V[L[i]] - V[L[0]], V[L[i + 1]] - V[L[0]]);
        area += (l == 0 ? 0.5 : -0.5) * norm(twice);
      }
      EXPECT_NEAR(tri_area[f], area, 1e-12 * area) << "facet " << f;
    }
    EXPECT_NEAR(six_volume / 6, d.volume, 1e-12 * volume);

    // Property 4: alpha. For a right prism over a polygon with smallest
    // interior angle a2: at a bottom (or top) vertex v with polygon corner
    // angle theta, the faces are the bottom facet, the two side facets, the
    // vertical edge u and the two horizontal edges e1, e2. Edge-edge pairs:
    // (e1, e2) make theta (a corner of the bottom facet), (e_i, u) make 90
    // degrees (corners of the rectangular side facets). Edge-facet pairs:
    // u against the bottom facet is 90; e1 against the side facet of e2 (the
    // vertical quarter plane spanned by e2 and u) makes min over rays
    // r = cos(phi) e2 + sin(phi) u of angle(e1, r), with cos = cos(phi)
    // cos(theta), so theta when theta <= 90 and 90 otherwise (for a reflex
    // theta the rays with phi < 90 do not even see e1: their sector crosses
    // the exterior wedge). Dihedral angles: theta at vertical edges, 90 at
    // horizontal edges. So alpha = min(a2, 90 deg). A box cavity adds only
    // right angles (edge-edge 90 inside its facets, dihedral 270 through P,
    // edge-facet 90), so the formula holds with box cavities; prism cavities
    // with sharp corners are excluded here. For a frustum the bottom facet
    // still has the polygon's corners (edge-edge candidates, the smallest one
    // convex), and one ring of horizontal edges has an acute dihedral (the
    // walls lean in for s < 1, out for s > 1), so alpha <= min(a2, 90 deg).
    const double a2 = smallest_corner_angle(R.base.loops);
    const double expected = std::min(a2, std::numbers::pi / 2);
    AlphaResult alpha;
    try {
      alpha = compute_alpha(d.plc);
    } catch (const Error& e) {
      ADD_FAILURE() << "compute_alpha threw: " << e.what();
      continue;
    }
    EXPECT_GT(alpha.radians, 0);
    EXPECT_LE(alpha.radians, alpha.min_dihedral_radians + 1e-12);
    const bool only_boxes =
        std::all_of(R.cavities.begin(), R.cavities.end(), [](const Cavity& c) { return c.box; });
    if (R.right_prism() && only_boxes) {
      ++alpha_checked;
      EXPECT_NEAR(alpha.radians, expected, 1e-12) << alpha.describe(0) << "; expected min(" << a2 * 180 / std::numbers::pi
                                                  << ", 90) deg";
    } else {
      EXPECT_LE(alpha.radians, expected + 1e-12) << alpha.describe(0);
    }
  }
  EXPECT_GE(alpha_checked, 80);
}

// Property 5: locate() against the independent oracle on right prisms.
TEST(PolyhedronProperty, LocateAgreesWithPrismOracle) {
  int checked = 0, counts[3] = {0, 0, 0};
  for (std::uint64_t seed = 0; seed < kPolyhedra; ++seed) {
    const RandomPolyhedron R = random_polyhedron_detail(seed);
    if (!R.right_prism()) continue;
    SCOPED_TRACE(describe_polyhedron(seed));
    Domain3 d;
    try {
      d = make_domain(R.plc);
    } catch (const Error& e) {
      ADD_FAILURE() << "make_domain: " << e.what();
      continue;
    }
    ++checked;
    const double h = R.height;
    auto expect_at = [&](Vec3 p, const char* what) {
      const Location want = prism_oracle(R, p), got = locate(d, p);
      ++counts[static_cast<int>(want)];
      EXPECT_EQ(got, want) << what << " (" << p.x << ", " << p.y << ", " << p.z << "): locate says " << name(got)
                           << ", oracle " << name(want);
      return want;
    };
    auto expect_boundary = [&](Vec3 p, const char* what) {
      // The oracle must agree that these constructed points are on dP.
      EXPECT_EQ(expect_at(p, what), Location::Boundary) << what << " (oracle)";
    };

    // Boundary points by construction: vertices, edge midpoints (exact for
    // dyadic coordinates), side-facet centres, and the same for cavities.
    std::vector<double> levels{0, h, h / 2, h / 4};
    for (const Cavity& c : R.cavities) levels.insert(levels.end(), {c.z0, c.z1, (c.z0 + c.z1) / 2});
    for (const Loop& L : R.base.loops)
      for (std::size_t i = 0; i < L.size(); ++i) {
        const Vec2 a = L[i], b = L[(i + 1) % L.size()], m = 0.5 * (a + b);
        expect_boundary({a.x, a.y, 0}, "base vertex");
        expect_boundary({a.x, a.y, h}, "top vertex");
        expect_boundary({m.x, m.y, 0}, "bottom edge midpoint");
        expect_boundary({m.x, m.y, h}, "top edge midpoint");
        expect_boundary({a.x, a.y, h / 2}, "vertical edge midpoint");
        expect_boundary({m.x, m.y, h / 2}, "side facet centre");
      }
    for (const Cavity& c : R.cavities)
      for (std::size_t i = 0; i < c.footprint.size(); ++i) {
        const Vec2 a = c.footprint[i], m = 0.5 * (a + c.footprint[(i + 1) % c.footprint.size()]);
        expect_boundary({a.x, a.y, c.z0}, "cavity vertex");
        expect_boundary({m.x, m.y, c.z1}, "cavity edge midpoint");
        expect_boundary({m.x, m.y, (c.z0 + c.z1) / 2}, "cavity side facet centre");
        expect_boundary({c.inner_point.x, c.inner_point.y, c.z0}, "cavity floor point");
      }
    for (std::size_t i = 0; i < R.plc.holes.size(); ++i)
      EXPECT_EQ(expect_at(R.plc.holes[i], "cavity hole point"), Location::Outside);
    for (Vec2 hp : R.base.hole_points) EXPECT_EQ(expect_at({hp.x, hp.y, h / 2}, "through-hole point"), Location::Outside);

    // Random dyadic points in the (slightly enlarged) bounding box; some of
    // them on the levels above or on vertex coordinates, so that the
    // boundary and the degenerate ray cases (the perturbed +x ray passing
    // through vertices and edges) are hit often.
    Points rnd(seed);
    std::vector<Vec2> corners;
    for (const Loop& L : R.base.loops) corners.insert(corners.end(), L.begin(), L.end());
    const Vec3 lo = d.bbox_min, hi = d.bbox_max, pad = 0.05 * (hi - lo);
    for (int k = 0; k < 120; ++k) {
      Vec3 p{rnd.in(lo.x - pad.x, hi.x + pad.x), rnd.in(lo.y - pad.y, hi.y + pad.y), rnd.in(-pad.z, h + pad.z)};
      const std::uint64_t mode = rnd.next() % 4;
      if (mode == 1) p.z = rnd.pick(levels);
      if (mode == 2) p.y = rnd.pick(corners).y;  // the +x ray through a vertex's y
      if (mode == 3) {
        const Vec2 c = rnd.pick(corners);
        p.y = c.y;
        p.z = rnd.pick(levels);
      }
      expect_at(p, "random point");
    }
  }
  EXPECT_GE(checked, 100);
  EXPECT_GT(counts[0], 1000);  // inside
  EXPECT_GT(counts[2], 1000);  // outside
}

// Vertices and edge midpoints are on the boundary of frustums too (the
// oracle above covers right prisms only); cavity hole points are outside.
TEST(PolyhedronProperty, LocateOnFrustumBoundary) {
  int checked = 0;
  for (std::uint64_t seed = 0; seed < kPolyhedra; ++seed) {
    const RandomPolyhedron R = random_polyhedron_detail(seed);
    if (R.right_prism()) continue;
    SCOPED_TRACE(describe_polyhedron(seed));
    const Domain3 d = make_domain(R.plc);
    ++checked;
    const auto& V = d.plc.vertices;
    for (std::size_t v = 0; v < V.size(); ++v) EXPECT_EQ(locate(d, V[v]), Location::Boundary) << "vertex " << v;
    for (const DomainEdge& e : d.edges)
      EXPECT_EQ(locate(d, 0.5 * (V[e.a] + V[e.b])), Location::Boundary) << "edge " << e.a << "-" << e.b;
    for (Vec3 p : d.plc.holes) EXPECT_EQ(locate(d, p), Location::Outside);
  }
  EXPECT_GE(checked, 20);
}

// The corpus has the advertised 3D features.
TEST(PolyhedronProperty, CorpusCoversTheHardCases) {
  int frustums = 0, cavities = 0, prism_cavities = 0, through = 0, sharp = 0, two_shells = 0, tiny_gap = 0;
  for (std::uint64_t seed = 0; seed < kPolyhedra; ++seed) {
    const RandomPolyhedron R = random_polyhedron_detail(seed);
    frustums += !R.right_prism();
    cavities += !R.cavities.empty();
    two_shells += R.cavities.size() == 2;
    through += R.base.loops.size() > 1;
    sharp += smallest_corner_angle(R.base.loops) < 5 * std::numbers::pi / 180;
    for (const Cavity& c : R.cavities) {
      prism_cavities += !c.box;
      tiny_gap += c.z0 < 0.01 * R.height || c.z1 > 0.99 * R.height;
    }
  }
  EXPECT_GE(frustums, 30);
  EXPECT_GE(cavities, 60);
  EXPECT_GE(prism_cavities, 15);
  EXPECT_GE(two_shells, 15);
  EXPECT_GE(through, 120);
  EXPECT_GE(sharp, 30);
  EXPECT_GE(tiny_gap, 10);
}

// The knobs: every polyhedron a frustum with cavities, or plain right prisms
// without shuffling; all valid, with the requested features.
TEST(PolyhedronProperty, OptionVariantsAreValid) {
  PolyhedronOptions frustums;
  frustums.frustum_probability = 1;
  frustums.cavity_probability = 1;
  PolyhedronOptions plain;
  plain.frustum_probability = 0;
  plain.cavity_probability = 0;
  plain.shuffle_ids = false;
  plain.polygon.shuffle_ids = false;
  for (std::uint64_t seed = 0; seed < 30; ++seed) {
    const RandomPolyhedron f = random_polyhedron_detail(seed, frustums), r = random_polyhedron_detail(seed, plain);
    EXPECT_FALSE(f.right_prism());
    EXPECT_TRUE(r.right_prism());
    EXPECT_TRUE(r.cavities.empty());
    for (const RandomPolyhedron* R : {&f, &r}) {
      try {
        const Domain3 d = make_domain(R->plc);
        EXPECT_EQ(d.shells.size(), 1 + R->cavities.size()) << seed;
        EXPECT_NEAR(d.volume, expected_volume(*R), 1e-12 * expected_volume(*R)) << seed;
      } catch (const Error& e) {
        ADD_FAILURE() << "seed " << seed << ": " << e.what();
      }
    }
  }
}

// Property 7 (3D): the same seed gives a bitwise identical Plc3.
TEST(PolyhedronProperty, Deterministic) {
  auto same = [](Vec3 a, Vec3 b) {
    return std::bit_cast<std::uint64_t>(a.x) == std::bit_cast<std::uint64_t>(b.x) &&
           std::bit_cast<std::uint64_t>(a.y) == std::bit_cast<std::uint64_t>(b.y) &&
           std::bit_cast<std::uint64_t>(a.z) == std::bit_cast<std::uint64_t>(b.z);
  };
  for (std::uint64_t seed = 0; seed < kPolyhedra; seed += 5) {
    const Plc3 a = random_polyhedron(seed), b = random_polyhedron(seed);
    ASSERT_EQ(a.vertices.size(), b.vertices.size()) << seed;
    for (std::size_t i = 0; i < a.vertices.size(); ++i) EXPECT_TRUE(same(a.vertices[i], b.vertices[i])) << seed;
    ASSERT_EQ(a.facets.size(), b.facets.size()) << seed;
    for (std::size_t f = 0; f < a.facets.size(); ++f) {
      EXPECT_EQ(a.facets[f].loops, b.facets[f].loops) << seed;
      EXPECT_EQ(a.facets[f].marker, b.facets[f].marker) << seed;
    }
    ASSERT_EQ(a.holes.size(), b.holes.size()) << seed;
    for (std::size_t i = 0; i < a.holes.size(); ++i) EXPECT_TRUE(same(a.holes[i], b.holes[i])) << seed;
    EXPECT_EQ(describe_polyhedron(seed), describe_polyhedron(seed));
  }
}

// Pinned fingerprint of the first outputs. Seeds quoted in bug reports and
// regression tests must keep naming the same domains, on every platform and
// standard library (the generator uses no std distribution and no libm
// function). If the generator is changed ON PURPOSE, print the new values and
// update them here, and say so in the change.
TEST(RandomDomains, PinnedFingerprint) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;  // FNV-1a over the coordinate bits and ids
  auto mix = [&](std::uint64_t word) {
    for (int k = 0; k < 8; ++k) {
      hash ^= (word >> (8 * k)) & 0xff;
      hash *= 0x100000001b3ULL;
    }
  };
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    const Pslg2 p = random_polygon_with_holes(seed);
    for (Vec2 v : p.vertices) mix(std::bit_cast<std::uint64_t>(v.x)), mix(std::bit_cast<std::uint64_t>(v.y));
    for (const auto& s : p.segments) mix(static_cast<std::uint64_t>(s[0]) << 32 | static_cast<std::uint64_t>(s[1]));
  }
  const std::uint64_t polygons = hash;
  for (std::uint64_t seed = 0; seed < 10; ++seed) {
    const Plc3 p = random_polyhedron(seed);
    for (Vec3 v : p.vertices)
      mix(std::bit_cast<std::uint64_t>(v.x)), mix(std::bit_cast<std::uint64_t>(v.y)), mix(std::bit_cast<std::uint64_t>(v.z));
    for (const Facet3& f : p.facets)
      for (const auto& loop : f.loops)
        for (int v : loop) mix(static_cast<std::uint64_t>(v));
  }
  EXPECT_EQ(polygons, 0xe8451964b3a440d0ULL) << std::hex << "polygon fingerprint 0x" << polygons;
  EXPECT_EQ(hash, 0xdcb338382277281aULL) << std::hex << "total fingerprint 0x" << hash;
}

}  // namespace
}  // namespace pqmesh::test
