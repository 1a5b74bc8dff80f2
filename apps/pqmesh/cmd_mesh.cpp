// pqmesh mesh: mesh a 2D domain with the quadtree mesher (quad_mesh), check
// the result against the domain, write it, and print a one-screen summary.
// Nothing is written unless the mesh passed check_mesh; write_mesh itself is
// atomic (pqmesh/mesh_io.hpp), so no failure leaves a partial output file.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "commands.hpp"
#include "pqmesh/alpha.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/lfs.hpp"
#include "pqmesh/mesh_io.hpp"
#include "pqmesh/quadmesh.hpp"
#include "pqmesh/quadmesh_bound.hpp"
#include "pqmesh/quality.hpp"
#include "pqmesh/read_domain.hpp"
#include "args.hpp"
#include "atomic_file.hpp"
#include "format_option.hpp"
#include "invalid_mesh.hpp"
#include "large_page_new.hpp"
#include "quality_fields.hpp"
#include "report_format.hpp"

namespace pqmesh::cli {
namespace {

// The largest --min-angle: Delaunay refinement ends in practice up to about
// 33 degrees (Triangle's and CGAL's limit too); at 34 it already stops at its
// point cap on the 2D benchmark's generated shapes (the mesh then comes from
// the quadtree).
constexpr double kMaxMinAngle = 33;

// Quadrature refinement of the size estimate I(P) (lfs_integral's `refine`),
// computed on request only (--lfs-integral): it costs more than meshing.
// Twice the library default 1/8: a quarter of the cells for about 1% change
// (data/2d/comb.poly: I = 1883 with 62171 cells at 1/4, 1892 with 243860 at
// 1/8; square.poly: 2.410 against 2.442).
constexpr double kLfsRefine = 0.25;

// --max-size S: a positive finite number (0 would mean "no limit" in
// QuadMeshOptions, but on the command line that is said by leaving it out).
double max_size_option(const Args& args) {
  if (!args.option("--max-size")) return 0;
  const double s = args.number("--max-size", 0);  // throws UsageError unless a finite number
  if (!(s > 0)) throw UsageError("--max-size must be a positive number, got '" + *args.option("--max-size") + "'");
  return s;
}

// Everything the summary reports, gathered by run_mesh.
struct MeshRun {
  std::string input, output;
  MeshFormat format = MeshFormat::Vtu;
  QuadMeshOptions options;
  QuadMeshResult result;
  CheckReport check;
  bool lfs_integral = false;  // --lfs-integral: compute and print I
  LfsIntegral lfs;
  double seconds_mesh = 0, seconds_check = 0, seconds_lfs = 0;
  // The summary's angle extremes (quality_report's min_angle.min/argmin and
  // max_angle.max/argmax) and min-angle histogram counts (its 5-degree bins).
  Stat min_angle, max_angle;
  std::vector<std::int64_t> min_angle_counts;
};

// Counts of the values in quality_report's min-angle bins: [5 i, 5 i + 5)
// degrees for i = 0..17, everything from 85 degrees up in the last.
std::vector<std::int64_t> min_angle_counts(const std::vector<double>& min_angles) {
  std::vector<std::int64_t> counts(18, 0);
  for (const double a : min_angles) ++counts[std::min<std::size_t>(17, static_cast<std::size_t>(std::max(0.0, a) / 5))];
  return counts;
}

// The angle extremes of quality_report(mesh), taken from the fields of
// quality_cell_fields instead of a second evaluation of every triangle: the
// values are the same bits (both go through TriangleQualityMemo) and the tie-break is
// quality_report's (the first triangle attaining the extreme). Only min/argmin
// of min_angle and max/argmax of max_angle are set.
void angle_extremes(const std::vector<CellField>& fields, Stat& min_angle, Stat& max_angle) {
  const std::vector<double>& lo = fields[1].values;
  const std::vector<double>& hi = fields[2].values;
  for (std::size_t e = 0; e < lo.size(); ++e) {
    if (e == 0 || lo[e] < min_angle.min) {
      min_angle.min = lo[e];
      min_angle.argmin = static_cast<std::int64_t>(e);
    }
    if (e == 0 || hi[e] > max_angle.max) {
      max_angle.max = hi[e];
      max_angle.argmax = static_cast<std::int64_t>(e);
    }
  }
}

// The "size" line, printed when --lfs-integral asked for I(P), the integral of
// 1/lfs^2 over P with the Euclidean lfs (pqmesh/lfs.hpp): up to a constant, a
// lower bound on the triangles of any bounded-angle mesh of P, except across
// exterior slots, where the Euclidean lfs makes it an overestimate.
void print_lfs_integral_line(const MeshRun& run) {
  if (!run.lfs_integral) return;
  const bool sized = run.options.max_size > 0 || !run.options.size_field.points.empty();
  const double triangles = static_cast<double>(run.result.mesh.triangles.size());
  std::cout << "size       I = integral of 1/lfs^2 over P = " << fmt4(run.lfs.value) << " (Euclidean lfs, "
            << run.lfs.cells << " cells); triangles / I = "
            << (run.lfs.value > 0 ? fmt4(triangles / run.lfs.value) : "-") << (sized ? " (I ignores the sizing)" : "")
            << '\n';
}

// Which construction made the mesh (mesh_polygon) and its counters: the
// refined CDT of the input, or the quadtree (with the refined CDT's shortfall
// when it was tried first), then the refinement.
void print_construction(const MeshRun& run) {
  const QuadMeshStats& s = run.result.stats;
  if (s.refined_input) {
    std::cout << "construct  refined CDT of the input (no quadtree): smallest angle " << fmt4(s.refined_input_min_angle)
              << " deg, at least the bound\n";
  } else {
    std::cout << "construct  quadtree";
    if (s.refined_input_triangles > 0)
      std::cout << " (the refined CDT of the input, " << s.refined_input_triangles << " triangles, reached "
                << fmt4(s.refined_input_min_angle) << " deg, below the bound)";
    std::cout << '\n'
              << "tree       " << s.leaves << " leaves (" << s.duplicates << " duplicates, " << s.outside_leaves
              << " outside P)\n"
              << "splits     size " << s.splits_size << ", vertex " << s.splits_vertex << ", edge " << s.splits_edge
              << ", balance " << s.splits_balance << ", centering " << s.splits_centering << ", protection "
              << s.splits_protection << '\n'
              << "boxes      " << s.vertex_boxes << " vertex boxes (" << s.centered << " centered), " << s.warped
              << " warped corners, " << s.edge_points << " edge points\n";
  }
  std::cout << "refine     "
            << (run.options.refine_angle_degrees > 0
                    ? "target " + fmt(run.options.refine_angle_degrees) + " deg: " + std::to_string(s.refine_points) +
                          " points added, " +
                          (s.refine_target_reached ? "reached (triangles at input angles < 60 deg excused)"
                                                   : "not reached everywhere")
                    : std::string("off"))
            << '\n';
}

// The improvement stage's line and the min-angle histogram before and after
// it (bins of 5 degrees from 0 to 60: a smallest angle is at most 60).
void print_improvement(const MeshRun& run) {
  const QuadMeshStats& s = run.result.stats;
  if (s.improved)
    std::cout << "improve    target " << fmt(s.improve_target_degrees) << " deg: " << s.constructed_triangles << " -> "
              << run.result.mesh.triangles.size() << " triangles (" << s.improve_removed << " vertices removed, "
              << s.improve_moved << " moved, " << s.improve_flips << " flips); min angle "
              << fmt4(s.constructed_min_angle) << " -> " << fmt4(run.min_angle.min) << " deg\n";
  else
    std::cout << "improve    off (--no-improve)\n";
  auto row = [](const std::vector<std::int64_t>& counts) {
    std::string text;
    for (std::size_t i = 0; i < 12 && i < counts.size(); ++i) text += " " + std::to_string(counts[i]);
    return text;
  };
  std::cout << "histogram  triangles by min angle, 5-deg bins 0-5 ... 55-60:\n";
  if (s.improved) std::cout << "  built   " << row(s.constructed_angle_counts) << '\n';
  std::cout << "  output  " << row(run.min_angle_counts) << '\n';
}

// One screen, labels padded to 11 columns as in `pqmesh info`.
void print_summary(const Domain2& domain, const MeshRun& run) {
  const TriMesh2& mesh = run.result.mesh;
  const QuadMeshStats& s = run.result.stats;
  std::size_t segments = 0;
  for (const auto& loop : domain.loops) segments += loop.size();
  std::cout << "input      " << run.input << " (2D polygon with holes)\n"
            << "domain     " << domain.pslg.vertices.size() << " vertices, " << segments << " segments, "
            << domain.loops.size() - 1 << " holes, area " << fmt(domain.area) << '\n';
  const SizeField2& field = run.options.size_field;
  if (run.options.max_size > 0 || !field.points.empty()) {
    std::string sizing;
    if (run.options.max_size > 0) sizing = "max size " + fmt(run.options.max_size);
    if (!field.points.empty()) {
      sizing += sizing.empty() ? "" : "; ";
      sizing += "size field " + field.path + " (" + std::to_string(field.points.size()) +
                (field.points.size() == 1 ? " point)" : " points)");
    }
    std::cout << "sizing     " << sizing << '\n';
  }

  const AlphaResult alpha = compute_alpha(domain.pslg.vertices, domain.loops);
  // The measured angle guarantee (include/pqmesh/quadmesh_bound.hpp).
  const bool refined = run.options.refine_angle_degrees >= 20;
  const double c = refined ? kQuadMeshBoundC : kQuadMeshUnrefinedBoundC;
  const double theta0 = refined ? kQuadMeshBoundTheta0Degrees : kQuadMeshUnrefinedBoundTheta0Degrees;
  const double bound = quad_mesh_angle_bound(alpha.degrees(), run.options.refine_angle_degrees);
  std::cout << "alpha      " << alpha.describe(domain.pslg.source.first_id) << '\n'
            << "bound      min angle >= min(" << fmt(c) << " * alpha, " << fmt(theta0) << " deg) = " << fmt4(std::min(c * alpha.degrees(), theta0))
            << " deg" << (refined && alpha.degrees() >= 60 ? " (20 deg: alpha >= 60)" : "")
            << (refined ? "" : " (without refinement)") << '\n'
            << "angles     min " << fmt4(run.min_angle.min) << " deg (triangle " << run.min_angle.argmin << "), max "
            << fmt4(run.max_angle.max) << " deg (triangle " << run.max_angle.argmax << "); "
            << (run.min_angle.min >= bound - 1e-9 ? "bound holds" : "BELOW THE BOUND") << '\n'
            << "mesh       " << mesh.triangles.size() << " triangles, " << mesh.vertices.size() << " vertices\n";
  print_lfs_integral_line(run);
  print_construction(run);
  print_improvement(run);
  std::cout << "time (s)   tree " << fmt_seconds(s.seconds_tree) << ", points " << fmt_seconds(s.seconds_points)
            << ", triangulate " << fmt_seconds(s.seconds_triangulate) << ", improve " << fmt_seconds(s.seconds_improve)
            << "; mesh " << fmt_seconds(run.seconds_mesh)
            << ", check " << fmt_seconds(run.seconds_check)
            << (run.lfs_integral ? ", lfs " + fmt_seconds(run.seconds_lfs) : std::string()) << '\n'
            << "check      valid: " << run.check.elements << " triangles, " << run.check.vertices << " vertices, "
            << run.check.boundary_faces << " boundary edges; area " << fmt(run.check.mesh_volume) << " (domain "
            << fmt(run.check.domain_volume) << ")\n"
            << "output     " << run.output << " (" << to_string(run.format) << ")\n";
}

}  // namespace

const std::set<std::string> kMeshFlagsAnyMode = {"--quiet", "--protect-edges", "--no-boundary-steiner",
                                                 "--fixed-boundary", "--pipeline", "--thesis-fans", "--no-quality-pass",
                                                 "--aligned-grid", "--full-separation", "--no-improve", "--compress",
                                                 "--lfs-integral", "--quadtree"};
const std::set<std::string> kMeshOptionsAnyMode = {"-o", "--output", "--max-size", "--size-field", "--format", "--target-aspect",
                                                   "--min-dihedral", "--refine-angle", "--min-angle"};

int run_mesh(const std::vector<std::string>& argv) {
#if defined(__GLIBC__)
  // Peak memory: glibc raises its mmap threshold each time a large block is
  // freed, after which the big arrays of the later stages come from the heap
  // and freed ones stay resident. A fixed threshold keeps every array above
  // 1 MiB in its own mapping, returned to the system when freed (the mesher
  // frees its tree and point tables before triangulating): about 70 MB less
  // peak at 1.7 million triangles.
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
#endif
  {
    // Route by mode and input dimension before the 2D options are checked:
    // the 3D and chapter-5 runs have options of their own.
    const Args any(argv, kMeshFlagsAnyMode, kMeshOptionsAnyMode);
    any.expect_positional(1, 1);
    if (any.flag("--no-boundary-steiner")) return run_mesh_no_steiner(argv);
    if (domain_dimension(any.positional()[0]) == 3) {
      // 3D: the heap of small blocks (octree node data, GMP limbs, the box
      // jobs' lists) grows in huge pages. On data/3d/plate_holes.poly: 36.7k
      // page faults become 8.5k, 0.2-0.3 s less system time, 3 MB more peak
      // (2D: its faults are already few, and its peak rose by 8 MB).
      grow_heap_in_huge_pages();
      return run_mesh3(argv);
    }
  }
  // 2D: every block from the mmap threshold up gets huge pages. The quadtree's
  // nodes are in huge-page slabs that go back to the system with the tree
  // (tree/chunked_vector.hpp), so the later stages' tables are fresh mappings:
  // on the plate of docs/algorithm/quad2d.md "Speed and memory" this takes the
  // run from 24.9k to 6.9k page faults at no higher peak. (3D keeps the
  // default: a 1 MiB threshold raised data/3d/plate_holes.poly's peak by about
  // 2 MB.)
  set_large_page_threshold(std::size_t{1} << 20);
  const Args args(argv, {"--quiet", "--protect-edges", "--compress", "--lfs-integral", "--quadtree", "--no-improve"},
                  {"-o", "--output", "--max-size", "--size-field", "--format", "--refine-angle", "--min-angle"});
  args.expect_positional(1, 1);
  MeshRun run;
  run.input = args.positional()[0];
  run.output = output_option(args);
  check_output_directory(run.output);
  run.options.max_size = max_size_option(args);
  run.options.protect_edges = args.flag("--protect-edges");
  run.options.quadtree = args.flag("--quadtree");
  if (args.option("--refine-angle")) {
    const double a = args.number("--refine-angle", 0);  // throws UsageError unless a finite number
    if (!(a >= 0 && a <= 30))
      throw UsageError("--refine-angle must be between 0 (off) and 30 degrees, got '" + *args.option("--refine-angle") + "'");
    run.options.refine_angle_degrees = a;
  }
  if (args.option("--min-angle")) {
    if (args.option("--refine-angle")) throw UsageError("give --min-angle or --refine-angle, not both");
    const double a = args.number("--min-angle", 0);
    if (!(a > 0 && a <= kMaxMinAngle))
      throw UsageError("--min-angle must be above 0 and at most " + fmt(kMaxMinAngle) + " degrees, got '" +
                       *args.option("--min-angle") + "'");
    run.options.refine_angle_degrees = a;
  }
  run.options.improve = !args.flag("--no-improve");
  const std::optional<MeshFormat> forced = format_option(args, /*allow_svg=*/true);
  // Unknown extension: ParseError(Unsupported), exit 2 before any work is done.
  run.format = forced ? *forced : mesh_format_from_path(run.output);
  const bool compress = compress_option(args, run.format);
  const bool quiet = args.flag("--quiet");

  const Domain2 domain = make_domain(read_pslg(run.input));
  if (const auto field = args.option("--size-field")) run.options.size_field = read_size_field2(*field);

  auto start = Clock::now();
  run.result = mesh_polygon(domain, run.options);
  run.seconds_mesh = seconds_since(start);

  start = Clock::now();
  run.check = check_mesh(run.result.mesh, domain);
  run.seconds_check = seconds_since(start);
  if (!valid_or_reported(run.check, "the mesh of " + run.input)) return kExitInternal;

  run.lfs_integral = args.flag("--lfs-integral") && !quiet;
  if (run.lfs_integral) {  // the size estimate is for the summary only, on request
    start = Clock::now();
    run.lfs = lfs_integral(domain, kLfsRefine);
    run.seconds_lfs = seconds_since(start);
  }

  WriteOptions write;
  write.format = run.format;
  write.compress = compress;
  if (run.format == MeshFormat::Vtu) {
    write.cell_fields = quality_cell_fields(run.result.mesh);
    if (!quiet) {
      angle_extremes(write.cell_fields, run.min_angle, run.max_angle);
      run.min_angle_counts = min_angle_counts(write.cell_fields[1].values);
    }
  } else if (!quiet) {
    const QualityReport q = quality_report(run.result.mesh);
    run.min_angle = q.min_angle;
    run.max_angle = q.max_angle;
    run.min_angle_counts = q.min_angle_hist.counts;
  }
  write_mesh(run.result.mesh, run.output, write);
  if (!quiet) print_summary(domain, run);
  return kExitOk;
}

}  // namespace pqmesh::cli
