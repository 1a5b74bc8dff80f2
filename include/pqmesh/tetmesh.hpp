#pragma once
// The 3D tetrahedral mesher, end to end (thesis ch. 4): a validated
// polyhedral domain in, a tetrahedral mesh out, with the input facet markers
// on the boundary triangles and a region attribute per tetrahedron.
//
// Pipeline (docs/algorithm/mesh3d.md): the octree of thesis §4.1 (generic grid,
// the user size function of §1.1; the separating splits of §4.1.7 steps 6 and
// 9 only where the mesh without them misses the bound, see TetSeparation),
// the kind of every leaf (empty, vertex / edge / facet cone, two facets), one
// box job per leaf, the box tetrahedra of §4.5 (src/tet3d), then the boundary
// triangles (faces of exactly one tetrahedron) with the marker of the input
// facet each lies on.
//
// On the generic grid every leaf kind becomes tetrahedra (tet3d/boxes/box_jobs.hpp),
// warped (§4.3); the aspect ratio bound of Theorem 7 holds with the measured
// constant below, not a proved one. A configuration the box code does not
// cover (box_jobs' problems, e.g. a second component inside a united
// vertex box) stops the run with MeshNotSupported naming the leaf; nothing is
// returned, never a partial mesh. On the aligned grid (generic_grid = false)
// only empty and facet boxes are meshed: a domain whose facets all lie on box
// planes (a box-aligned cube, the L-block) is the union of "flush" leaves
// (tet3d/boxes/empty_boxes.hpp) and meshes completely.
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/errors.hpp"
#include "pqmesh/mesh.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh {

// Theorem 7 as measured: max aspect ratio * alpha (radians) <= this over
// the corpus models and the random polyhedra of the test suite (asserted
// there). A measured ceiling, not a proved constant (the thesis's C is not
// numeric): on the thesis's octree (TetSeparation::Always) the maximum
// measured over the corpus, the every-run, suite and bounded random families
// (seeds 0..199 each), the flat-edge family (seeds 12..199) and the harsh
// family's seeds 0..19 is 4,568 (bounded seed 193), so C keeps 20% above it
// (docs/algorithm/mesh3d.md). The default (Adaptive) keeps a lighter mesh
// only when it is within C / alpha. The summary of `pqmesh mesh` prints
// C / alpha next to the achieved aspect ratio.
inline constexpr double kMeasuredAspectAlphaC = 5500;

// The user size function (thesis §1.1), as for `pqmesh octree`: the size
// asked for at x is min(max_size, min_i sizes[i] + |x - points[i]|).
struct TetSizeField {
  std::vector<Vec3> points;
  std::vector<double> sizes;  // > 0, one per point
  std::vector<int> lines;     // 1-based file line of each point (error messages); may be empty
  std::string path;           // file it came from, empty when built in memory
};

// Reads a size field file, one 'x y z size' per line ('#' comments); throws
// ParseError (WrongCount, Syntax, NonFinite) naming the file line. The 2D
// reader and the format are in pqmesh/quadmesh.hpp and docs/FORMATS.md.
TetSizeField read_size_field3(const std::string& path);

// Progress of one run, reported at the start and end of every phase.
struct TetMeshProgress {
  // "octree", "classify", "tetrahedra", "boundary" (once per construction
  // tried, TetSeparation), "improve", "done"
  const char* phase = "";
  std::int64_t boxes = 0;          // leaves of the octree (from "classify" on)
  std::int64_t jobs = 0;           // boxes turned into tetrahedra (from "tetrahedra" on)
  std::int64_t tetrahedra = 0;     // from the end of "tetrahedra" on
  double seconds = 0;              // since tet_mesh started
};

// The separating splits of §4.1.7 steps 6 and 9 (every edge / facet box and
// its balance-adjacent boxes split once more before protection) make every
// leaf one of the thesis's kinds, at 10 to 25 times the tetrahedra
// (docs/algorithm/mesh3d.md "Light construction first").
enum class TetSeparation {
  // Lighter octrees are meshed first: without them and with extended boxes
  // of 3 times the side instead of the thesis's 5, then without them, then
  // (up to twice) with them only near the P faces of the leaves that failed.
  // A mesh is returned when every leaf became tetrahedra, the checker
  // (pqmesh/check.hpp) finds it valid and max aspect * alpha <=
  // kMeasuredAspectAlphaC.
  // When none is kept, the thesis's construction (Always) is returned, so the
  // bound the summary prints is met whenever the thesis's construction meets
  // it.
  Adaptive,
  Always,  // the thesis's construction only. CLI --full-separation
};

// The improvement's quality target when TetMeshOptions::min_dihedral is unset
// and no size bound is given (degrees). On the corpus it gives a minimum
// dihedral angle of at least 20 degrees on every model whose input angles
// are all at least 60 degrees (docs/MEASUREMENTS.md "3D mesher").
inline constexpr double kDefaultMinDihedral = 20;

struct TetMeshOptions {
  double max_size = 0;         // largest box side anywhere; 0: no limit. CLI --max-size
  TetSizeField size_field;     // empty: none. CLI --size-field
  // Shift the octree grid off every input coordinate
  // (docs/algorithm/octree3d.md "Generic grid"); false: the aligned grid. CLI
  // --aligned-grid sets false.
  bool generic_grid = true;
  // Warping of §4.3, both passes, for every box kind (tet3d/warp/warp.hpp).
  bool warp = true;
  TetSeparation separation = TetSeparation::Adaptive;
  // Improvement after the construction (docs/algorithm/improve3d.md): edge
  // collapses, then vertex smoothing and flips (2-3, edge removal, and
  // edge removal inside a facet, which re-triangulates it), none of which
  // raises the worst aspect ratio above the construction's; input vertices,
  // edges, facets and markers are kept and max_size / size_field respected.
  // CLI --no-improve sets false.
  bool improve = true;
  // A collapse may leave the tetrahedra it changes as bad as the worse of
  // their worst before and this aspect ratio (3: the regular tetrahedron).
  // Larger: fewer tetrahedra, worse typical shapes. CLI --target-aspect.
  double target_aspect = 8;
  // Quality target of the improvement (degrees, 0: none; below 70.53, the
  // regular tetrahedron's): in a region whose tetrahedra all meet
  // target_aspect, a collapse may not make a tetrahedron whose minimum
  // dihedral angle is below the smaller of this and the region's least
  // before. Coarsening then stops earlier where the mesh is good; nothing
  // guarantees the target is reached. Unset: kDefaultMinDihedral without a
  // size bound, none with max_size or a size field (there the size asked
  // for sets the count). TetMeshStats::min_dihedral_target is the one used.
  // CLI --min-dihedral.
  std::optional<double> min_dihedral;
  // Called at phase boundaries (may be empty).
  std::function<void(const TetMeshProgress&)> progress;
};

// Leaf kinds in the order of mv3d::LeafKind (src/mv3d/leaf_kind.hpp).
inline constexpr int kTetLeafKinds = 7;
// "outside", "empty", "vertex", "edge", "facet", "two-facet", "other".
const char* tet_leaf_kind_name(int kind);

struct TetMeshStats {
  std::int64_t leaves = 0;                                // octree leaves (all duplicates)
  std::array<std::int64_t, kTetLeafKinds> leaves_per_kind{};
  std::int64_t flush_leaves = 0;                          // meshed as empty boxes although P faces touch them
  std::int64_t touching_leaves = 0;                       // P faces on their boundary only, outside P: skipped
  std::int64_t empty_jobs = 0, facet_jobs = 0;            // box jobs per kind
  std::int64_t edge_jobs = 0, vertex_jobs = 0, two_facet_jobs = 0;
  std::int64_t facet_inside = 0, facet_on = 0, facet_beyond = 0;  // facet boxes per §4.5.4 case
  std::int64_t warped = 0;                                // vertices moved by warping (§4.3, both passes)
  // Warp tables rebuilt because a warp inverted a tetrahedron (the rebuild loop
  // of tet3d, docs/algorithm/tet3d_warp.md "The rebuild loop"); 0 when none
  // inverted.
  std::int64_t warp_rebuilds = 0;
  // Rounds of the worst-box freeze kept: after the rebuild loop, a mesh whose
  // worst tetrahedron is flat has the warps of that tetrahedron's box frozen
  // while its worst tetrahedron strictly improves
  // (docs/algorithm/tet3d_warp.md "Freezing the worst box's warps").
  std::int64_t worst_box_rounds = 0;
  // Box stages run: 1; 2 when the run with two-cone-point edge boxes was made
  // and kept; 3 when it lost and the first run's mesh was remade
  // (docs/algorithm/tet3d_warp.md "Two cone points").
  std::int64_t box_runs = 1;
  // The out-of-face table of the kept run (docs/algorithm/tet3d_warp.md "One
  // decision per shared face"): 0 not tried, 1 tried and lost, 2 kept.
  std::int64_t wider_table = 0;
  // Squares of united vertex boxes triangulated in one piece per plane group
  // (coplanar facets joined by flat edges; docs/algorithm/tet3d_boxes.md "The
  // square dispatcher").
  std::int64_t split_squares = 0;
  // Warping was asked for but the warped boxes threw (a warp that inverts a
  // tetrahedron the freeze loop of tet3d cannot attribute): the mesh is the
  // unwarped one, and this says why. Empty when warping succeeded or was off.
  std::string warp_failure;
  std::int64_t boundary_faces = 0;
  // Which octree made the returned mesh (TetSeparation): separated, the
  // thesis's (every separating split); else separated_faces > 0, the octree
  // separated near that many P edges and facets only; else the light octree.
  // With Adaptive, when a lighter mesh was dropped, light_rejected says why
  // the last one was (a leaf no box job covers, a failed box invariant, the
  // checker, or the aspect bound) and seconds_light is what the dropped
  // constructions cost; both stay empty / 0 when the light mesh was kept.
  bool separated = false;
  std::int64_t separated_faces = 0;
  // The extended boxes' margin of that octree in box sides: 2 is the
  // thesis's ex(b) (5 times the side), 1 the lightest octree (3 times).
  int extended_margin = 2;
  std::string light_rejected;
  double seconds_light = 0;
  double max_aspect = 0;  // of the returned mesh (tetrahedron_quality)
  // The construction's mesh before improvement: tetrahedra, worst aspect
  // ratio, dihedral extremes (degrees); and the improvement's collapses,
  // vertices moved by smoothing, flips (of which boundary_flips changed
  // boundary triangles), time and, when the improved mesh
  // failed the checker (then the construction's mesh is returned), the
  // checker's first line.
  std::int64_t constructed_tetrahedra = 0;
  double constructed_max_aspect = 0, constructed_min_dihedral = 0, constructed_max_dihedral = 0;
  std::int64_t collapses = 0, smoothed = 0, flips = 0, boundary_flips = 0;
  double min_dihedral_target = 0;  // the improvement's quality target (degrees, 0: none)
  double seconds_improve = 0;
  std::string improve_failure;
  int depth = 0;                                          // deepest leaf level
  double root_size = 0;
  std::array<double, 3> grid_offset{};                    // the generic grid's shift (0 when aligned)
  int grid_shift = 0;  // which of the generic grid's offsets (0 the first; mesh3d.md "Light construction first")
  double seconds_octree = 0, seconds_classify = 0, seconds_tetrahedra = 0, seconds_boundary = 0;
};

struct TetMeshResult {
  TetMesh3 mesh;  // faces: the boundary triangles with their input facet markers
  TetMeshStats stats;
};

// A leaf the box tetrahedra do not handle. An InvalidInput
// of code Unsupported ("a valid input using a feature we do not handle"):
// ids() = the leaf node ids; the message names the first leaf, its kind and
// its box.
class MeshNotSupported : public InvalidInput {
 public:
  MeshNotSupported(std::int64_t leaf, std::string kind, const std::string& detail);
  MeshNotSupported(std::vector<std::int64_t> leaves, std::string kind, const std::string& detail);
  const std::string& kind() const { return kind_; }

 private:
  std::string kind_;
};

// Throws InvalidInput for a bad size field or max_size, MeshNotSupported as
// above, InternalError when an invariant breaks (a boundary triangle on no
// input facet, a tetrahedron of wrong orientation).
TetMeshResult tet_mesh(const Domain3& domain, const TetMeshOptions& options = {});

}  // namespace pqmesh
