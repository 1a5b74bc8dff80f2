// pqmesh mesh on a 3D domain (thesis ch. 4): tet_mesh (pqmesh/tetmesh.hpp), check
// the result against the domain, write it, print a one-screen summary. As for
// 2D (cmd_mesh.cpp): nothing is written unless the mesh passed check_mesh, and
// write_mesh is atomic, so a failure never leaves a partial output file.
// Exit codes: 0 written; 2 invalid input, or a leaf the box tetrahedra do
// not handle (MeshNotSupported); 64 usage; 70 a mesh that
// fails the check (a bug; nothing written).
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "args.hpp"
#include "atomic_file.hpp"
#include "commands.hpp"
#include "format_option.hpp"
#include "invalid_mesh.hpp"
#include "load.hpp"
#include "pqmesh/alpha.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/lfs3.hpp"
#include "pqmesh/mesh_io.hpp"
#include "pqmesh/quality.hpp"
#include "pqmesh/tetmesh.hpp"
#include "quality_fields.hpp"
#include "report_format.hpp"

namespace pqmesh::cli {

namespace {

struct Mesh3Run {
  std::string input, output;
  MeshFormat format = MeshFormat::Vtu;
  TetMeshOptions options;
  TetMeshResult result;
  CheckReport check;
  bool lfs_integral = false;  // --lfs-integral: compute and print I3
  LfsIntegral3 lfs;
  double seconds_mesh = 0, seconds_check = 0, seconds_lfs = 0, seconds_write = 0;
};

// The summary's quality line: the largest aspect ratio (first tetrahedron
// attaining it), the smallest minimum and the largest maximum dihedral angle,
// as quality_report gives them. When the .vtu quality fields were computed
// (quality_fields.hpp: the same tetrahedron_quality values, in tetrahedron
// order) they are scanned instead of evaluating every tetrahedron again; the
// scan keeps quality_report's rule (first element, then strict comparisons).
struct SummaryQuality {
  double max_aspect = 0, min_dihedral = 0, max_dihedral = 0;
  std::int64_t argmax_aspect = -1;
};

SummaryQuality summary_quality(const TetMesh3& mesh, const std::vector<CellField>& fields) {
  const CellField *aspect = nullptr, *min_d = nullptr, *max_d = nullptr;
  for (const CellField& f : fields) {
    if (f.values.size() != mesh.tetrahedra.size()) continue;
    if (f.name == "aspect_ratio") aspect = &f;
    if (f.name == "min_dihedral") min_d = &f;
    if (f.name == "max_dihedral") max_d = &f;
  }
  SummaryQuality out;
  if (aspect == nullptr || min_d == nullptr || max_d == nullptr) {
    const QualityReport q = quality_report(mesh);
    out.max_aspect = q.aspect_ratio.max;
    out.argmax_aspect = q.aspect_ratio.argmax;
    out.min_dihedral = q.min_angle.min;
    out.max_dihedral = q.max_angle.max;
    return out;
  }
  for (std::size_t e = 0; e < mesh.tetrahedra.size(); ++e) {
    const double a = aspect->values[e], lo = min_d->values[e], hi = max_d->values[e];
    if (e == 0 || a > out.max_aspect) {
      out.max_aspect = a;
      out.argmax_aspect = static_cast<std::int64_t>(e);
    }
    if (e == 0 || lo < out.min_dihedral) out.min_dihedral = lo;
    if (e == 0 || hi > out.max_dihedral) out.max_dihedral = hi;
  }
  return out;
}

// Quadrature refinement of I3(P) for the summary (lfs_integral's `refine`):
// twice the library default 1/4, an eighth of the cells. On data/3d the
// estimate stays within 1.5% of the one at 1/8 (the unit cube, whose lfs
// varies most inside a cell, 5.1% below: 4.382 against 4.616; the bound
// tests/cli/mesh3d_test.sh asserts there is 5.8%), and the quadrature of a
// tessellated part costs less than meshing it (pipe.off: 247,488 cells, 11 s,
// against 1,546,240 cells, 40 s at 1/4).
constexpr double kLfsRefine3 = 0.5;

// TetMeshStats::wider_table on the "boxes" line.
constexpr std::array<const char*, 3> kWiderTable = {"no out-of-face table", "out-of-face table lost",
                                                    "out-of-face table kept"};

// The "size" line, printed when --lfs-integral asked for I3(P), the integral of
// 1/lfs^3 over P (pqmesh/lfs3.hpp): up to a constant, a lower bound on the
// tetrahedra of any bounded-aspect mesh of P (thesis §4.8, Theorem 14).
void print_lfs_integral_line(const Mesh3Run& run) {
  if (!run.lfs_integral) return;
  const bool sized = run.options.max_size > 0 || !run.options.size_field.points.empty();
  const double tetrahedra = static_cast<double>(run.result.mesh.tetrahedra.size());
  const double constructed = static_cast<double>(run.result.stats.constructed_tetrahedra);
  const auto per_i3 = [&](double count) { return run.lfs.value > 0 ? fmt4(count / run.lfs.value) : std::string("-"); };
  std::cout << "size       I3 = integral of 1/lfs^3 over P = " << fmt4(run.lfs.value) << " (" << run.lfs.cells
            << " cells); tetrahedra / I3 = " << per_i3(tetrahedra);
  if (constructed != tetrahedra) std::cout << " (construction " << per_i3(constructed) << ")";
  std::cout << (sized ? " (I3 ignores the sizing)" : "") << '\n';
}

// Which octree made the mesh (TetSeparation) and, when lighter ones were
// dropped, why and what they cost.
void print_octree_line(const Domain3& domain, const TetMeshStats& s) {
  std::cout << "octree     ";
  if (s.extended_margin == 1)
    std::cout << "lightest (extended boxes 3 times the side, no separating splits)";
  else if (!s.separated && s.separated_faces == 0)
    std::cout << "light (no separating splits, thesis 4.1.7 steps 6 and 9)";
  else if (!s.separated)
    std::cout << "separating splits (thesis 4.1.7 steps 6 and 9) near " << s.separated_faces << " of "
              << domain.edges.size() + domain.plc.facets.size() << " edges and facets only";
  else
    std::cout << "separated (thesis 4.1.7 steps 6 and 9)";
  if (!s.light_rejected.empty())
    std::cout << "; the lighter octrees' meshes were dropped after " << fmt_seconds(s.seconds_light)
              << " s: " << s.light_rejected;
  std::cout << '\n';
}

// The improvement stage: before / after counts and shapes, or why it is off.
void print_improve_line(const TetMesh3& mesh, const TetMeshStats& s, const Mesh3Run& run) {
  std::cout << "improve    ";
  if (!run.options.improve) {
    std::cout << "off (--no-improve)\n";
    return;
  }
  std::cout << s.collapses << " edge collapses (target aspect " << fmt4(run.options.target_aspect);
  if (s.min_dihedral_target > 0) std::cout << ", min dihedral " << fmt4(s.min_dihedral_target) << " deg";
  std::cout << "), "
            << s.smoothed << " vertices smoothed, " << s.flips << " flips (" << s.boundary_flips
            << " on the boundary): tetrahedra " << s.constructed_tetrahedra
            << " -> " << mesh.tetrahedra.size() << ", max aspect ratio " << fmt4(s.constructed_max_aspect) << " -> "
            << fmt4(s.max_aspect) << ", dihedral min " << fmt4(s.constructed_min_dihedral) << " deg before\n";
  if (!s.improve_failure.empty())
    std::cout << "warning    the improved mesh failed the checker, the construction's mesh is written: "
              << s.improve_failure << "\n";
}

void print_summary(const Domain3& domain, const Mesh3Run& run, const std::vector<CellField>& fields) {
  const TetMesh3& mesh = run.result.mesh;
  const TetMeshStats& s = run.result.stats;
  std::cout << "input      " << run.input << " (3D, " << domain.plc.vertices.size() << " vertices, "
            << domain.edges.size() << " edges, " << domain.plc.facets.size() << " facets, volume "
            << fmt(domain.volume) << ")\n";
  const TetSizeField& field = run.options.size_field;
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
  const AlphaResult alpha = compute_alpha(domain.plc);
  const SummaryQuality q = summary_quality(mesh, fields);
  std::cout << "alpha      " << alpha.describe(domain.plc.source.first_id) << '\n'
            << "mesh       " << mesh.tetrahedra.size() << " tetrahedra, " << mesh.vertices.size() << " vertices, "
            << mesh.faces.size() << " boundary triangles\n"
            << "quality    max aspect ratio " << fmt4(q.max_aspect) << " (tetrahedron " << q.argmax_aspect
            << "; measured bound C / alpha = " << fmt4(kMeasuredAspectAlphaC / alpha.radians) << ", C = "
            << fmt4(kMeasuredAspectAlphaC) << "), dihedral min " << fmt4(q.min_dihedral) << " deg, max "
            << fmt4(q.max_dihedral) << " deg\n";
  print_improve_line(mesh, s, run);
  print_lfs_integral_line(run);
  std::cout << "grid       "
            << (run.options.generic_grid ? "generic, planes shifted by " +
                                               fmt(Vec3{s.grid_offset[0], s.grid_offset[1], s.grid_offset[2]})
                                         : std::string("aligned"))
            << (s.grid_shift > 0 ? " (offset " + std::to_string(s.grid_shift + 1) + ")" : std::string())
            << "; root side " << fmt(s.root_size) << ", depth " << s.depth << '\n';
  print_octree_line(domain, s);
  std::cout << "leaves     " << s.leaves << ":";
  for (int k = 0; k < kTetLeafKinds; ++k)
    std::cout << (k ? ", " : " ") << tet_leaf_kind_name(k) << ' ' << s.leaves_per_kind[static_cast<std::size_t>(k)];
  std::cout << '\n'
            << "boxes      " << s.empty_jobs << " empty (" << s.flush_leaves << " flush), " << s.facet_jobs
            << " facet (inside " << s.facet_inside << ", on F " << s.facet_on << ", beyond " << s.facet_beyond << "), "
            << s.edge_jobs << " edge, " << s.vertex_jobs << " vertex, " << s.two_facet_jobs << " two-facet; "
            << s.touching_leaves << " touching leaves skipped; " << s.warped << " warped vertices (" << s.warp_rebuilds
            << " warp rebuilds, " << s.worst_box_rounds << " worst-box rounds, " << s.box_runs << " box runs, "
            << kWiderTable[static_cast<std::size_t>(s.wider_table)] << ")\n"
            << (s.warp_failure.empty() ? ""
                                       : "warning    warping failed, the mesh is unwarped: " + s.warp_failure + "\n")
            << "time (s)   octree " << fmt_seconds(s.seconds_octree) << ", classify " << fmt_seconds(s.seconds_classify)
            << ", tetrahedra " << fmt_seconds(s.seconds_tetrahedra) << ", boundary " << fmt_seconds(s.seconds_boundary)
            << ", improve " << fmt_seconds(s.seconds_improve)
            << "; mesh " << fmt_seconds(run.seconds_mesh) << ", check " << fmt_seconds(run.seconds_check)
            << (run.lfs_integral ? ", lfs " + fmt_seconds(run.seconds_lfs) : std::string()) << ", write "
            << fmt_seconds(run.seconds_write) << '\n'
            << "check      " << run.check.to_text().substr(0, run.check.to_text().find('\n')) << '\n'
            << "output     " << run.output << " (" << to_string(run.format) << ")\n";
}

// Progress on stderr, one line rewritten in place (only on a terminal).
void show_progress(const TetMeshProgress& p) {
  std::fprintf(stderr, "\r%-10s boxes %lld, jobs %lld, tetrahedra %lld, %.1f s   ", p.phase,
               static_cast<long long>(p.boxes), static_cast<long long>(p.jobs), static_cast<long long>(p.tetrahedra),
               p.seconds);
  if (std::string(p.phase) == "done") std::fprintf(stderr, "\n");
  std::fflush(stderr);
}

}  // namespace

int run_mesh3(const std::vector<std::string>& argv) {
  const Args args(argv, kMeshFlagsAnyMode, kMeshOptionsAnyMode);
  args.expect_positional(1, 1);
  for (const char* flag : {"--protect-edges", "--fixed-boundary"})
    if (args.flag(flag)) throw UsageError(std::string(flag) + " is for 2D input only");
  if (args.option("--refine-angle")) throw UsageError("--refine-angle is for 2D input only");
  if (args.option("--min-angle")) throw UsageError("--min-angle is for --no-boundary-steiner (2D) only");
  Mesh3Run run;
  run.input = args.positional()[0];
  run.output = output_option(args);
  check_output_directory(run.output);
  if (args.option("--max-size")) {
    run.options.max_size = args.number("--max-size", 0);  // throws UsageError unless a finite number
    if (!(run.options.max_size > 0))
      throw UsageError("--max-size must be a positive number, got '" + *args.option("--max-size") + "'");
  }
  run.options.generic_grid = !args.flag("--aligned-grid");
  if (args.flag("--full-separation")) run.options.separation = TetSeparation::Always;
  run.options.improve = !args.flag("--no-improve");
  if (args.option("--target-aspect")) {
    run.options.target_aspect = args.number("--target-aspect", 0);  // throws UsageError unless a finite number
    if (!(run.options.target_aspect >= 3))
      throw UsageError("--target-aspect must be at least 3 (the regular tetrahedron), got '" +
                       *args.option("--target-aspect") + "'");
  }
  if (args.option("--min-dihedral")) {
    run.options.min_dihedral = args.number("--min-dihedral", 0);  // throws UsageError unless a finite number
    if (!(*run.options.min_dihedral >= 0 && *run.options.min_dihedral < 70.5))
      throw UsageError("--min-dihedral must be at least 0 (none) and below 70.5 degrees (the regular tetrahedron's), got '" +
                       *args.option("--min-dihedral") + "'");
  }
  const std::optional<MeshFormat> forced = format_option(args, /*allow_svg=*/false);
  run.format = forced ? *forced : mesh_format_from_path(run.output);  // unknown extension: exit 2 before work
  const bool compress = compress_option(args, run.format);
  if (run.format == MeshFormat::Svg) throw UsageError("a 3D mesh cannot be written as .svg");
  const bool quiet = args.flag("--quiet");

  const LoadedDomain loaded = load_domain(run.input, read_options_from(args));
  const Domain3& domain = std::get<Domain3>(loaded.domain);
  if (const auto path = args.option("--size-field")) {
    run.options.size_field = read_size_field3(*path);
  }
  if (!quiet && isatty(fileno(stderr))) run.options.progress = show_progress;

  auto start = Clock::now();
  run.result = tet_mesh(domain, run.options);
  run.seconds_mesh = seconds_since(start);

  start = Clock::now();
  run.check = check_mesh(run.result.mesh, domain);
  run.seconds_check = seconds_since(start);
  if (!valid_or_reported(run.check, "the mesh of " + run.input)) return kExitInternal;
  run.lfs_integral = args.flag("--lfs-integral") && !quiet;
  if (run.lfs_integral) {  // the size estimate is for the summary only, on request
    start = Clock::now();
    run.lfs = lfs_integral(domain, kLfsRefine3);
    run.seconds_lfs = seconds_since(start);
  }
  start = Clock::now();
  WriteOptions write;
  write.format = run.format;
  write.compress = compress;
  if (run.format == MeshFormat::Vtu) write.cell_fields = quality_cell_fields(run.result.mesh);
  write_mesh(run.result.mesh, run.output, write);
  run.seconds_write = seconds_since(start);
  if (!quiet) print_summary(domain, run, write.cell_fields);
  return kExitOk;
}

}  // namespace pqmesh::cli
