// pqmesh mesh INPUT -o OUT --no-boundary-steiner (thesis ch. 5):
// triangulate a polygon with holes adding points only strictly inside it
// (triangulate_without_boundary_steiner, include/pqmesh/nosteiner.hpp), check
// the result with the no-boundary-Steiner check, write it, print a summary.
// Nothing is written unless the mesh passed check_mesh; write_mesh is atomic.
//
// There is no separate --fixed-boundary mode: this mode already keeps every
// input vertex and segment exactly (a subdivided boundary, straight angles
// included, is kept as given), which is what local remeshing needs
// (docs/algorithm/nosteiner2d.md "Fixed-boundary mode"). The flag is accepted
// as a synonym.
#include <cstdio>
#include <iostream>
#include <numbers>
#include <string>

#include "args.hpp"
#include "atomic_file.hpp"
#include "commands.hpp"
#include "format_option.hpp"
#include "invalid_mesh.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/mesh_io.hpp"
#include "pqmesh/nosteiner.hpp"
#include "pqmesh/read_domain.hpp"
#include "quality_fields.hpp"
#include "report_format.hpp"

namespace pqmesh::cli {
namespace {

// The summary's "refined" line: the best refined candidate (after its quality pass), or why there is none.
std::string refined_line(const NoSteinerStats& s) {
  if (s.refined_target == 0) return "no refined candidate (--pipeline, --thesis-fans, or none passed the check)";
  return "best refined candidate (CDT refined towards " + fmt4(s.refined_target) +
         " deg, interior points only, + quality pass): min " + fmt4_degrees(s.refined_min_angle) + " deg, " +
         std::to_string(s.refined_inserted) + " points inserted (" + std::to_string(s.refined_seeds) +
         " seeds where the upper bound places the best triangles), target " +
         (s.refined_target_reached ? "met by the refinement" : "not met by the refinement");
}

// The summary's "target" line (--min-angle A); empty without a target.
std::string target_line(const NoSteinerStats& s) {
  if (s.target <= 0) return "";
  const double bound_deg = s.upper_bound * 180 / std::numbers::pi;
  const std::string line = "target     " + fmt4(s.target) + " deg: ";
  if (s.target_reached) return line + "reached (min " + fmt4_degrees(s.min_angle) + " deg)\n";
  const std::string best = line + "not reached; best " + fmt4_degrees(s.min_angle) + " deg";
  if (bound_deg < s.target) return best + "; " + fmt4(s.target) + " not reachable: upper bound " + fmt4(bound_deg) + " deg\n";
  return best + " (upper bound " + fmt4(bound_deg) + " deg, not proven unreachable)\n";
}

}  // namespace

int run_mesh_no_steiner(const std::vector<std::string>& argv) {
  const Args args(argv, {"--quiet", "--no-boundary-steiner", "--fixed-boundary", "--pipeline", "--thesis-fans", "--no-quality-pass",
                   "--compress"},
                  {"-o", "--output", "--format", "--refine-angle", "--min-angle"});
  args.expect_positional(1, 1);
  const std::string input = args.positional()[0];
  const std::string output = output_option(args);
  check_output_directory(output);
  NoSteinerOptions options;
  if (args.option("--refine-angle")) {
    const double a = args.number("--refine-angle", 0);
    if (!(a >= 0 && a <= 30))
      throw UsageError("--refine-angle must be between 0 (off) and 30 degrees, got '" + *args.option("--refine-angle") + "'");
    options.r_mesh.refine_angle_degrees = a;
  }
  if (args.option("--min-angle")) {
    const double a = args.number("--min-angle", 0);
    if (!(a > 0 && a <= 60))
      throw UsageError("--min-angle must be above 0 and at most 60 degrees, got '" + *args.option("--min-angle") + "'");
    options.min_angle_target = a;
    options.refine_targets = {a};
  }
  options.keep_better_cdt = !args.flag("--pipeline");
  if (args.flag("--pipeline")) options.refine_targets.clear();  // the thesis pipeline's own mesh
  options.thesis_fans = args.flag("--thesis-fans");
  if (options.thesis_fans) options.refine_targets.clear();  // keeps the fans' mesh
  options.quality_pass = !args.flag("--no-quality-pass");
  const std::optional<MeshFormat> forced = format_option(args, /*allow_svg=*/true);
  const MeshFormat format = forced ? *forced : mesh_format_from_path(output);
  const bool compress = compress_option(args, format);
  const bool quiet = args.flag("--quiet");

  const Domain2 domain = make_domain(read_pslg(input));
  const NoSteinerResult result = triangulate_without_boundary_steiner(domain, options);
  const NoSteinerStats& s = result.stats;

  const CheckReport check = check_mesh(result.mesh, domain, CheckOptions{.no_boundary_steiner = true});
  if (!valid_or_reported(check, "the no-boundary-Steiner triangulation of " + input)) return kExitInternal;
  WriteOptions write;
  write.format = format;
  write.compress = compress;
  if (format == MeshFormat::Vtu) write.cell_fields = quality_cell_fields(result.mesh);
  write_mesh(result.mesh, output, write);
  if (quiet) return kExitOk;

  std::size_t segments = 0;
  for (const auto& loop : domain.loops) segments += loop.size();
  std::cout << "input      " << input << " (2D polygon with holes)\n"
            << "domain     " << domain.pslg.vertices.size() << " vertices, " << segments << " segments, "
            << domain.loops.size() - 1 << " holes, area " << fmt(domain.area) << '\n'
            << "mode       no boundary Steiner points (thesis ch. 5): every point added lies strictly inside"
            << (options.thesis_fans ? "; Q to R connected by the thesis's fans" : "") << '\n'
            << "bound g    g(P) = " << fmt4_degrees(s.g) << " deg; any Steiner-free-boundary triangulation has min angle <= "
            << "min(60, " << fmt4(s.constant) << " * g, alpha = " << fmt4_degrees(s.alpha)
            << ", segment = " << fmt4_degrees(s.segment_bound) << ", fan = " << fmt4_degrees(s.fan_bound)
            << ") = " << fmt4_degrees(s.upper_bound) << " deg\n"
            << "angles     min " << fmt4_degrees(s.min_angle) << " deg; achieved / upper bound = "
            << fmt4(s.min_angle / s.upper_bound) << " (upper bound " << fmt4_degrees(s.upper_bound)
            << " deg); achieved / g = " << fmt4(s.ratio) << '\n'
            << "pipeline   " << to_string(s.pipeline_path) << ": min " << fmt4_degrees(s.pipeline_min_angle) << " deg, / g = "
            << fmt4(s.pipeline_min_angle / s.g) << ", " << s.pipeline_triangles << " triangles, "
            << s.pipeline_vertices << " vertices"
            << (s.pipeline_path == NoSteinerPath::Full ? " (wedges + Q to R + mesh of R; no fallback)"
                                                       : " (FALLBACK)")
            << '\n'
            << "post-pass  construction min " << fmt4_degrees(s.construction_min_angle) << " deg, "
            << s.construction_triangles << " triangles -> " << fmt4_degrees(s.pipeline_min_angle) << " deg ("
            << s.pass_flips << " flips, " << s.pass_removals << " removals, " << s.pass_moves << " moves, "
            << s.pass_cavities << " cavities; quality pass " << (options.quality_pass ? "on" : "off")
            << ", docs/algorithm/nosteiner2d.md \"Fallbacks and the CDT comparison\")\n"
            << "cdt        constrained Delaunay of the input (no point added): min " << fmt4_degrees(s.cdt_min_angle)
            << " deg; pipeline / cdt = "
            << (s.cdt_min_angle > 0 ? fmt4(s.pipeline_min_angle / s.cdt_min_angle) : "-") << '\n'
            << "refined    " << refined_line(s) << '\n'
            << target_line(s)
            << "path       " << to_string(s.path)
            << (s.path == NoSteinerPath::CdtBetter ? " (output is the CDT: larger min angle)" : "")
            << (s.fallback_reason.empty() ? "" : "\nreason     " + s.fallback_reason) << '\n'
            << "mesh       " << s.triangles << " triangles, " << s.vertices << " vertices (" << s.wedge_triangles
            << " wedge, " << s.between_triangles << " Q-to-R, " << s.r_triangles << " in R, " << s.cdt_triangles
            << " CDT, " << s.refined_triangles << " refined)\n"
            << "regions    min angle wedges " << fmt4_degrees(s.wedge_min_angle) << ", Q-to-R " << fmt4_degrees(s.between_min_angle)
            << ", R " << fmt4_degrees(s.r_min_angle) << " deg; dQ " << s.q_vertices << " vertices, dR " << s.r_vertices
            << " vertices\n"
            << "time (s)   bound " << fmt_seconds(s.seconds_bound) << ", Q " << fmt_seconds(s.seconds_q) << ", R "
            << fmt_seconds(s.seconds_r) << ", Q-to-R " << fmt_seconds(s.seconds_between) << ", pass " << fmt_seconds(s.seconds_pass) << ", verify " << fmt_seconds(s.seconds_verify)
            << ", refined " << fmt_seconds(s.seconds_refine) << ", cdt " << fmt_seconds(s.seconds_cdt) << "; total " << fmt_seconds(s.seconds_total) << '\n'
            << "check      valid (no boundary Steiner): " << check.elements << " triangles, " << check.vertices
            << " vertices, " << check.boundary_faces << " boundary edges; area " << fmt(check.mesh_volume)
            << " (domain " << fmt(check.domain_volume) << ")\n"
            << "output     " << output << " (" << to_string(format) << ")\n";
  return kExitOk;
}

}  // namespace pqmesh::cli
