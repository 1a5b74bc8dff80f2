#pragma once
// Triangulation without boundary Steiner points (thesis ch. 5): the entry
// point, its options, statistics and result. The mesh's vertices on dP are the
// input vertices and its boundary edges the input segments; its min angle is
// at least a constant times g(P), the upper bound of thesis Theorems 17 and
// 21 on the min angle of any such triangulation (docs/algorithm/nosteiner2d.md
// defines g and proves the constant below).
#include <string>
#include <utility>
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/mesh.hpp"
#include "pqmesh/quadmesh.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh {

// pi * (1 + ln 2): optimal min angle <= kSteinerFreeBoundConstant * g(P).
inline constexpr double kSteinerFreeBoundConstant = 3.14159265358979323846 * (1.0 + 0.69314718055994530942);

// The construction (src/nosteiner2d/triangulate_nosteiner.cpp; the stages are
// declared in src/nosteiner2d/stages.hpp; docs/algorithm/nosteiner2d.md
// "Matching R to Q" to "Benchmark").
//
// The mesh of P is Q^c (the welded wedges and edge triangles, §5.1.1) + the
// region between dQ and dR (§5.4) + the mesh of R (§5.3). Every vertex other
// than the input vertices lies strictly inside P: the spoke ends and dQ by
// construction of the wedges, R strictly inside Q (§5.2). The region between
// dQ and dR is triangulated by the matching of §5.4, `detail::match_q_to_r`
// (src/nosteiner2d/match_qr.hpp): match trapezoids and triangles, square
// drawing, Steiner points strictly inside Q \ R only.
//
// Fallbacks (never silent; NoSteinerStats::path and fallback_reason say which
// and why). Where a stage cannot be built in doubles (the spiral-depth limit
// and R below resolution: docs/algorithm/nosteiner2d.md "Known limits", "Delta
// and the shrink to R") or a built stage fails the final check:
//   QOnly: Q^c + the constrained Delaunay triangulation of Q (no point added
//          inside Q); used when R cannot be built or the full mesh fails.
//   Cdt:   the constrained Delaunay triangulation of P (steiner_free_cdt); used
//          when Q cannot be built or the QOnly mesh fails.
// Both keep dP exactly as given: the mesh vertices on dP are the input
// vertices, the boundary edges are the input segments.

// Region attribute (TriMesh2::triangle_markers) of each triangle: the stage that made it.
inline constexpr int kRegionWedges = 1;   // Q^c: vertex wedges and edge welds (§5.1.1)
inline constexpr int kRegionBetween = 2;  // between dQ and dR (§5.4)
inline constexpr int kRegionR = 3;        // R meshed by quad_mesh (§5.3)
inline constexpr int kRegionQCdt = 4;     // QOnly fallback: the CDT of Q
inline constexpr int kRegionPCdt = 5;     // Cdt fallback: the CDT of P
inline constexpr int kRegionRefined = 6;  // a refined candidate (NoSteinerOptions::refine_targets)

struct NoSteinerOptions {
  // The mesher for R (§5.3). Default: refinement towards 20 degrees
  // (docs/algorithm/nosteiner2d.md "Meshing R": both settings have the
  // properties of §5.5.1; refined angles are better).
  QuadMeshOptions r_mesh;
  // Run check_mesh (no_boundary_steiner) on the assembled mesh and fall back
  // (QOnly, then Cdt) when it fails. Off only for timing the stages alone.
  bool verify = true;
  // Also compute the Steiner-free CDT's min angle for the report.
  bool compare_cdt = true;
  // Output the CDT of P instead when its min angle is strictly larger (path
  // CdtBetter; needs compare_cdt). Both are triangulations without boundary
  // Steiner points; the pipeline's min angle stays in pipeline_min_angle.
  // The last safety net: with quality_pass the pipeline itself is never below
  // the CDT (the pass's last candidate re-triangulates the whole mesh to the
  // CDT of P; asserted on every test input, docs/algorithm/nosteiner2d.md
  // "Fallbacks and the CDT comparison"), so this fires only with quality_pass
  // off (the construction alone is below the CDT on most inputs: the thesis's
  // constants are small), a pass stopped by its step bound, or a pass output
  // that failed verify. On by default.
  bool keep_better_cdt = true;
  // Q \ R (§5.4) connected by the thesis's per-piece fans (Figs. 5.17,
  // 5.19-5.21) instead of the CDT of the same vertices. The CDT's min angle
  // is never smaller (Lawson: same vertices, same constraints); measured
  // about half on the test inputs (docs/algorithm/nosteiner2d.md "Matching R to
  // Q"). For comparison with the thesis's construction.
  bool thesis_fans = false;
  // Quality post-pass on the Full / QOnly mesh (a deviation beyond the
  // thesis, docs/algorithm/nosteiner2d.md "Fallbacks and the CDT comparison";
  // src/improve2d/quality_pass.hpp): flips, removals and moves of Steiner points
  // at the worst triangle while that raises its angle, then CDT re-triangulated
  // cavities up to the whole mesh. Never lowers the min angle, never stops below
  // the CDT of P, adds no point, keeps dP exactly at the input vertices.
  // construction_min_angle keeps the thesis construction's value (the one bounded
  // by k g(P)).
  bool quality_pass = true;
  // Refined candidates (beyond the thesis; docs/algorithm/nosteiner2d.md
  // "Refined candidates"): the CDT of P refined towards each target (degrees,
  // in this order) with points strictly inside P only, never on a segment
  // (src/nosteiner2d/refined_candidate.hpp; Triangle's -Y), each followed by
  // the quality pass when quality_pass is on. The output is the candidate
  // with the largest min angle, in this order: the pipeline (thesis + pass),
  // the refined candidates, the CDT of P (keep_better_cdt); a later one
  // replaces an earlier one only when its min angle is strictly larger
  // (NoSteinerPath::Refined). Empty: the pipeline alone.
  std::vector<double> refine_targets = {20, 25, 30};
  std::size_t refine_max_points = 0;  // cap per refinement; 0: detail::refined_point_cap (32 n + 4096)
  // A target min angle in degrees (0: none), only reported: NoSteinerStats::target_reached
  // (the CLI's --min-angle A also sets refine_targets = {A}).
  double min_angle_target = 0;
};

// Cdt: fallback (a stage could not be built); CdtBetter: the pipeline ran,
// and the CDT of P had the larger min angle (keep_better_cdt); Refined: a
// refined candidate had the larger min angle (refine_targets).
enum class NoSteinerPath { Full, QOnly, Cdt, CdtBetter, Refined };
const char* to_string(NoSteinerPath path);  // "full", "q-only", "cdt", "cdt-better", "refined"

struct NoSteinerStats {
  // The bound (thesis Theorems 17, 21; SteinerFreeBound with default options).
  double g = 0;                    // radians
  double constant = kSteinerFreeBoundConstant;
  double alpha = 0;                // the smallest interior angle of P at an input vertex, radians
  // The segment bound: the smallest, over the input segments ab, of the
  // largest base angle of an isosceles triangle on ab whose interior meets no
  // point of dP (capped at pi/3), radians; the triangle on ab in every
  // triangulation without boundary Steiner points has min angle <= it
  // (docs/algorithm/nosteiner2d.md "The segment bound").
  double segment_bound = 0;
  // The fan bound: the smallest, over the input vertices V, of the largest
  // min angle a fan of triangles filling V's corner can have when its end
  // spokes are V's two sides, and when it must pass a vertex of dP closer to
  // V than the side it starts from (radians; docs/algorithm/nosteiner2d.md
  // "The fan bound"); it is <= alpha and <= pi/3.
  double fan_bound = 0;
  // min(pi/3, constant * g, alpha, segment_bound, fan_bound): no triangulation without
  // boundary Steiner points does better (alpha: every input vertex stays a
  // vertex, and the angles at V of the triangles in its corner sum to alpha_V;
  // docs/algorithm/nosteiner2d.md "Refined candidates", "The segment bound",
  // "The fan bound").
  double upper_bound = 0;
  double min_angle = 0;            // achieved, radians (of the output)
  double pipeline_min_angle = 0;   // of the Full / QOnly / Cdt mesh before keep_better_cdt (after quality_pass)
  double construction_min_angle = 0;  // the same before quality_pass (the thesis's construction)
  std::int64_t construction_triangles = 0;  // its size (the output size m of §5.5.2)
  std::int64_t pass_flips = 0, pass_removals = 0, pass_moves = 0, pass_cavities = 0;  // quality_pass changes
  bool pass_stuck = false;         // quality_pass stopped at a triangle no change improves (else: step bound)
  NoSteinerPath pipeline_path = NoSteinerPath::Full;  // its path
  std::int64_t pipeline_triangles = 0, pipeline_vertices = 0;  // its size (the output size m of §5.5.2)
  double ratio = 0;                // min_angle / g
  double cdt_min_angle = 0;        // the CDT of P (when compare_cdt), radians
  // The best refined candidate (refine_targets; first maximum in target order), after its quality pass.
  double refined_min_angle = 0;    // radians; 0 when none ran
  double refined_target = 0;       // its target, degrees
  std::int64_t refined_inserted = 0;  // its interior points (before the pass)
  std::int64_t refined_seeds = 0;     // of which seed points (0: the plain candidate; docs "Refined candidates")
  bool refined_target_reached = false;  // its refinement met the target (sharp input corners excused), before the pass
  // NoSteinerOptions::min_angle_target (degrees) and whether the output's min angle reaches it.
  double target = 0;
  bool target_reached = false;
  NoSteinerPath path = NoSteinerPath::Full;
  std::string fallback_reason;     // empty for Full; for CdtBetter and Refined, the two angles
  // Counts (triangles by region; vertices of Q and R loops).
  std::int64_t triangles = 0, vertices = 0;
  std::int64_t wedge_triangles = 0, between_triangles = 0, r_triangles = 0, cdt_triangles = 0, refined_triangles = 0;
  std::int64_t q_vertices = 0, r_vertices = 0;
  // Smallest angle per region (radians; 0 when the region is empty).
  double wedge_min_angle = 0, between_min_angle = 0, r_min_angle = 0;
  // Wall-clock seconds per stage.
  double seconds_bound = 0, seconds_q = 0, seconds_r = 0, seconds_between = 0, seconds_verify = 0,
         seconds_cdt = 0, seconds_pass = 0, seconds_refine = 0, seconds_total = 0;
};

struct NoSteinerResult {
  // vertices: the input vertices first, in input order (ids preserved), then
  // the interior ones; triangles counter-clockwise with triangle_markers =
  // kRegion*; edges = the input segments (loop order) with the input segment
  // markers when the input has them.
  TriMesh2 mesh;
  NoSteinerStats stats;
};

NoSteinerResult triangulate_without_boundary_steiner(const Domain2& domain, const NoSteinerOptions& options = {});

}  // namespace pqmesh
