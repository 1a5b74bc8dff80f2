#pragma once
// The subcommands of the pqmesh tool. Each returns the process exit code and
// may throw: UsageError, InvalidInput (bad input file), InternalError; main()
// turns those into a message on stderr and the documented exit code.
#include <set>
#include <string>
#include <vector>

namespace pqmesh::cli {

// Exit codes, documented in `pqmesh --help`.
inline constexpr int kExitOk = 0;
inline constexpr int kExitCheckFailed = 1;   // the command ran, and the answer is "not valid"
inline constexpr int kExitInvalidInput = 2;  // an input file is unreadable or violates the domain rules
inline constexpr int kExitUsage = 64;        // bad command line
inline constexpr int kExitInternal = 70;     // a bug in pqmesh
inline constexpr int kExitCannotWrite = 73;  // an output file cannot be created or written (sysexits EX_CANTCREAT)

struct Command {
  const char* name;
  const char* summary;
  const char* help;  // full text for `pqmesh NAME --help`
  int (*run)(const std::vector<std::string>& args);
};

int run_info(const std::vector<std::string>& args);
int run_mesh(const std::vector<std::string>& args);
// `pqmesh mesh` on a 3D input (cmd_mesh3.cpp) and with --no-boundary-steiner
// (cmd_mesh_nosteiner.cpp); run_mesh routes to them.
int run_mesh3(const std::vector<std::string>& args);
int run_mesh_no_steiner(const std::vector<std::string>& args);
// Every flag and option any mode of `pqmesh mesh` accepts; each mode then
// checks its own subset.
extern const std::set<std::string> kMeshFlagsAnyMode, kMeshOptionsAnyMode;
int run_check(const std::vector<std::string>& args);
int run_quality(const std::vector<std::string>& args);
int run_convert(const std::vector<std::string>& args);
int run_octree(const std::vector<std::string>& args);

const std::vector<Command>& commands();

}  // namespace pqmesh::cli
