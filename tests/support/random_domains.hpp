#pragma once
// Seeded random input domains for property tests (docs/DESIGN_RULES.md "Exact
// decisions", "Conventions": the corpus x invariants tests of tests/property).
//
// Every generator is a pure function of its seed and options: the random bits
// come from std::mt19937_64 (whose output sequence the C++ standard fixes) and
// are mapped to numbers by the small functions in random_domains.cpp (not by
// std::uniform_*_distribution, whose results differ between standard
// libraries). Directions use a polynomial sin/cos built from + - * / only, so
// no libm function reaches a coordinate either. Every output coordinate is a
// dyadic rational k * 2^-grid_bits (times a power of two scale, plus a dyadic
// offset), hence exactly representable, and derived points such as edge
// midpoints are exact too.
//
// Validity is by construction plus exact verification (orient2d) inside the
// generator: a candidate that fails is rejected and redrawn from the same
// random stream, so the result is still deterministic. The property tests run
// make_domain on every output as an independent check.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "pqmesh/plc.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh::test {

struct PolygonOptions {
  int min_vertices = 5;          // outer loop, before spikes are added
  int max_vertices = 24;
  int max_holes = 4;             // 0..max_holes holes
  int min_hole_vertices = 3;
  int max_hole_vertices = 9;
  double spike_probability = 0.35;   // 1-max_spikes sharp spikes in the outer loop; half as often a notch in a hole
  int max_spikes = 2;
  // Spike/notch corner angles are drawn in [min, max], biased towards min
  // (min + (max - min) u^3), and hit the drawn value within a few percent.
  // The smallest corner of the polygon is never below ~min: coarse snapping
  // leaves spike vertices and their neighbours alone. (Frustums can make 3D
  // edge-facet angles smaller than this, down to ~0.3 deg in the default corpus.)
  double min_spike_degrees = 1.0;
  double max_spike_degrees = 20.0;
  double near_touch_probability = 0.4;  // per hole: push it to a tiny gap from its neighbour
  double min_gap = 1e-3;             // relative to the outer radius; gaps drawn in [min_gap, 30 min_gap]
  double snap_probability = 0.15;    // per vertex: snap to the coarse dyadic grid (multiples of 1/8)
  // Hole radii (star loops about a random centre) drawn in [min, max],
  // relative to the outer radius (~1).
  double min_hole_radius = 0.04;
  double max_hole_radius = 0.25;
  double notch_probability = 0.12;   // per outer vertex: radius x 0.3 (a deep notch)
  // Holes of >= 4 vertices get a notch (a sharp wedge of the domain poking
  // into the hole) with probability spike_probability / 2 when true. When
  // false the notch is still drawn (so the stream is the same) but never
  // inserted.
  bool hole_notches = true;
  // A hole (or cavity footprint) drawn closer than this to another loop is
  // redrawn (relative to the outer radius; 0: only disjointness is asked).
  // Near-touching moves still go down to min_gap.
  double min_clearance = 0;
  int grid_bits = 20;                // fine grid: coordinates are multiples of 2^-grid_bits (before scaling)
  bool shuffle_ids = true;           // random vertex numbering, segment order and loop directions
  bool random_scale = true;          // multiply by 2^j, j in [-3, 3], and translate by a dyadic offset
};

// The structured form: loops[0] is the outer loop, counter-clockwise; loops[1..]
// are holes, clockwise (interior of the domain on the left of every loop).
// hole_points[i] lies strictly inside hole loop i + 1. Every loop is simple,
// no two loops touch, every hole is strictly inside the outer loop.
struct PolygonWithHoles {
  std::vector<std::vector<Vec2>> loops;
  std::vector<Vec2> hole_points;
  int spikes = 0;            // how many spikes were inserted (for describe())
  int notches = 0;           // how many outer vertices were pulled in to a deep notch
  int near_touching = 0;     // how many holes were pushed to a tiny gap
  int snapped = 0;           // how many vertices were snapped to the coarse grid
};

PolygonWithHoles random_polygon_loops(std::uint64_t seed, const PolygonOptions& options = {});

// As a Pslg2: vertices (numbered in a seeded random order when
// options.shuffle_ids), segments (random order and direction), segment
// markers (1 on the outer loop, 2 + i on hole i), vertex markers (same scheme)
// and one hole point per hole.
Pslg2 to_pslg(const PolygonWithHoles& polygon, std::uint64_t seed, bool shuffle_ids);
Pslg2 random_polygon_with_holes(std::uint64_t seed, const PolygonOptions& options = {});

// The harder generator settings of the 2D property tests, in this order: many
// holes (up to 12, 60 outer vertices) with gaps down to 1e-5 of the part;
// spikes down to 0.5 degrees with vertices often snapped; vertices snapped to
// a coarse dyadic grid (2^-8), so edges pass through box corners and sides.
std::array<PolygonOptions, 3> hard_polygon_options();

struct PolyhedronOptions {
  PolygonOptions polygon{};           // the extruded cross-section
  double frustum_probability = 0.3;   // top = centre + s (p - centre), s dyadic != 1
  double cavity_probability = 0.5;    // 1 or 2 cavities (closed floating shells)
  double polygon_cavity_probability = 0.4;  // a cavity is a small prism instead of a box (right prisms only)
  double near_touch_probability = 0.3;      // a cavity placed at a tiny gap from the boundary
  bool shuffle_ids = true;            // random vertex numbering, facet order and loop directions
  // Height (before the random scale; the base's outer radius is <= 1.15):
  // with thin_probability in [1/16, 1/4] (a thin slab), else in
  // [min_height, max_height]; raised for flat frustum walls (see the .cpp).
  double thin_probability = 0.2;
  double min_height = 0.25;
  double max_height = 2.0;
  // Frustum top scales are taken from {1/4, 3/8, ..., 7/8, 5/4, 3/2, 2}; a
  // draw outside [min_top_scale, max_top_scale] becomes a right prism.
  double min_top_scale = 0.25;
  double max_top_scale = 2.0;
  // Cavity size: box half-widths in [min, max] (a polygonal cavity's radii
  // in [1.5 min, max]), and the cavity's height as a fraction of the
  // solid's height in [min, max].
  double min_cavity_half_width = 0.02;
  double max_cavity_half_width = 0.15;
  double min_cavity_height = 0.1;
  double max_cavity_height = 0.35;
  // A cavity whose floor or roof would be thinner than this fraction of the
  // solid's height is redrawn (0: any z0 > 0, z1 < height).
  double min_cavity_wall = 0;
};

// Options of the "bounded feature" family: every feature (edge, gap, hole,
// cavity, wall thickness) is at least about 1/16 of the bounding box, corner
// and dihedral angles at least ~10 degrees (spikes 12-30 degrees, frustum
// walls at most 1/2 off vertical), still nonconvex (notches, spikes),
// with through-holes and cavities. Cheap to mesh (see
// tests/unit/mesh3d/random_polyhedra_test.cpp for the measured cost).
PolyhedronOptions bounded_feature_polyhedron_options();

// Options of the "suite" family, the one the default test suite meshes for
// 200 seeds on every run (tests/unit/mesh3d/random_polyhedra_test.cpp), so
// each seed must cost about a cube's worth of tetrahedra, not millions.
// tet_mesh's cost grows with the volume over which the local feature size is
// small, so what is bounded is every narrow region, relative to the outer
// radius (~1) of the base polygon:
//  - gaps: holes and cavity footprints at least 3/16 from every other loop
//    (a near-touching move stops no closer than 3/16), cavity floors and roofs at
//    least 1/4 of the height, heights in [1, 1.25] (no thin slabs);
//  - spikes: at most one per outer loop (probability 1/4), 20-30 degrees
//    (a sliver wedge costs roughly 1/angle^2);
//  - frustum walls: top scales 3/4, 7/8 or 5/4 only;
//  - holes (at most 1, radius 0.12-0.2) and cavities (1-2, box or prism,
//    half-width 0.08-0.15) are small, so their own surface is cheap.
// Still nonconvex (4-6 outer vertices, notches, spikes), with through-holes,
// box and prism cavities, frustums, random scale 2^-3..2^3 and offset.
PolyhedronOptions suite_polyhedron_options();

// Options of the "every-run" family: the one the default test suite meshes
// for ALL seeds 0..199 on every run (tests/unit/mesh3d/random_polyhedra_test.cpp),
// so the 200 must cost about 100 cpu s in Release together,
// about half a second (a cube's worth of tetrahedra) per seed. The suite
// family above is valid on all 200 seeds but 6.5x too slow. tet_mesh's cost
// grows with the volume over which the local feature size is small, and
// there the volume came from: small through-holes (radius 0.12-0.2, short
// sides, sometimes a notch: small lfs along the full height; 48 seeds, 61% of
// the time), then spikes (a wedge of small lfs along the full height) and
// cavities. So this family starts from suite_polyhedron_options() and bounds
// further, relative to the outer radius (~1):
//  - holes: at most 1, radius 0.25-0.35, 4-5 vertices, no notch
//    (hole_notches off), at least 1/4 from the outer loop;
//  - gaps: every hole and cavity footprint at least 1/4 from every other
//    loop, no near-touching moves (near_touch_probability 0);
//  - outer loop 4-5 vertices, deep notch per vertex with probability 0.08,
//    a 20-30 degree spike with probability 1/8 (a spike seed cost 3 s on
//    average, a plain one 0.4 s);
//  - cavities (1-2, box or prism) with probability 1/2, half-width 0.1-0.15;
//  - height 0.75-1 (less volume at the same lfs), no thin slabs.
// It keeps every feature of the random families: nonconvex outlines with notches,
// 20-30 degree spikes, through-holes, box and prism cavities, frustums (top
// scale 3/4, 7/8 or 5/4), random scale 2^-3..2^3 and dyadic offset (the
// test counts them over the 200 seeds).
PolyhedronOptions every_run_polyhedron_options();

// The "harsh" family: the defaults above
// made cheaper, keeping every feature the issue asks for (nonconvex outlines
// with deep notches, up to 2 through-holes, cavities, spikes and notches of
// 5-20 degrees, near-touching gaps of 1e-2..0.3 relative to the outer radius,
// frustums, thin slabs, random scale and offset). Measured 2026-12-01 on
// seeds 0-3 and 100-103 (Release, shared machine): 1.0M-6.1M tetrahedra and
// 15-84 s cpu per meshed seed, so ~2-3 cpu hours for all 200. With the
// generator defaults (24 outer vertices, 4 holes, 1-degree spikes, 1e-3 gaps)
// single seeds take minutes.
PolyhedronOptions harsh_polyhedron_options();

// A cavity: the prism footprint x [z0, z1]; footprint counter-clockwise.
struct Cavity {
  std::vector<Vec2> footprint;
  double z0 = 0, z1 = 0;
  bool box = false;  // footprint is an axis-aligned rectangle
  Vec2 inner_point;  // strictly inside the footprint (a TetGen hole point sits above it)
};

// The solid {(centre + lambda(z) (p - centre), z) : p in base, 0 <= z <= height}
// with lambda(z) = 1 + (top_scale - 1) z / height, minus the cavities. Every
// horizontal section is a homothetic copy of the base polygon with holes, so
// it is a valid polyhedron; a side face (p_i, p_i+1, top_i+1, top_i) is a
// trapezoid (top side parallel to the bottom side), planar, and exactly so
// because the scaled coordinates are computed without rounding (checked by
// orient3d; a non-planar quad would be split, which never happened).
struct RandomPolyhedron {
  Plc3 plc;
  PolygonWithHoles base;     // at z = 0, in the same coordinates as plc
  double height = 1;
  double top_scale = 1;      // 1: right prism
  Vec2 centre;               // homothety centre (dyadic)
  std::vector<Cavity> cavities;
  int split_quads = 0;       // side quads that had to be split (expected 0)
  bool right_prism() const { return top_scale == 1; }
};

RandomPolyhedron random_polyhedron_detail(std::uint64_t seed, const PolyhedronOptions& options = {});
Plc3 random_polyhedron(std::uint64_t seed, const PolyhedronOptions& options = {});

// One line for failure messages, e.g.
// "seed 17: polygon, outer 19 vertices, 3 holes, 2 spikes, 1 near-touching, 4 snapped".
std::string describe_polygon(std::uint64_t seed, const PolygonOptions& options = {});
std::string describe_polyhedron(std::uint64_t seed, const PolyhedronOptions& options = {});

// Independent area oracle for the property tests: the shoelace sum, each term
// relative to the loop's first vertex (less cancellation for translated
// polygons). Positive for a counter-clockwise loop.
double shoelace(const std::vector<Vec2>& loop);

// Independent oracle for compute_alpha: the smallest interior corner angle
// (radians) over the loops, interior on the left of each loop. At every
// corner, the angle turning counter-clockwise from the next side to the
// previous one, in (0, 2 pi): atan2 of (cross, dot) gives it in (-pi, pi],
// and a negative value is a reflex corner, which gets 2 pi added.
double smallest_corner_angle(const std::vector<std::vector<Vec2>>& loops);

}  // namespace pqmesh::test
