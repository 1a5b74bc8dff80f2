// pqmesh check: the validity checker against an input domain.
#include <iostream>

#include "commands.hpp"
#include "load.hpp"
#include "pqmesh/check.hpp"

namespace pqmesh::cli {

int run_check(const std::vector<std::string>& argv) {
  const Args args(argv, {"--no-merge", "--no-boundary-steiner"}, {"--domain", "--merge-angle", "--max-issues"});
  args.expect_positional(1, 1);
  const auto domain_path = args.option("--domain");
  if (!domain_path) throw UsageError("--domain INPUT is required");
  CheckOptions options;
  options.no_boundary_steiner = args.flag("--no-boundary-steiner");
  const double max_issues = args.number("--max-issues", 20);
  if (max_issues < 1) throw UsageError("--max-issues must be at least 1");
  options.max_issues_per_kind = static_cast<std::size_t>(max_issues);

  const LoadedDomain loaded = load_domain(*domain_path, read_options_from(args));
  const AnyMesh mesh = load_mesh(args.positional()[0], loaded.dimension());
  const CheckReport report = loaded.dimension() == 3
                                 ? check_mesh(std::get<TetMesh3>(mesh), std::get<Domain3>(loaded.domain), options)
                                 : check_mesh(std::get<TriMesh2>(mesh), std::get<Domain2>(loaded.domain), options);
  std::cout << report.to_text();
  if (!report.to_text().empty() && report.to_text().back() != '\n') std::cout << '\n';
  return report.valid() ? kExitOk : kExitCheckFailed;
}

}  // namespace pqmesh::cli
