#pragma once
// The subcommands of the pqmesh tool. Each returns the process exit code and
// may throw: UsageError, InvalidInput (bad input file), InternalError; main()
// turns those into a message on stderr and the documented exit code.
#include <string>
#include <vector>

namespace pqmesh::cli {

// Exit codes, documented in `pqmesh --help`.
inline constexpr int kExitOk = 0;
inline constexpr int kExitCheckFailed = 1;   // the command ran, and the answer is "not valid"
inline constexpr int kExitInvalidInput = 2;  // an input file is unreadable or violates the domain rules
inline constexpr int kExitUsage = 64;        // bad command line
inline constexpr int kExitInternal = 70;     // a bug in pqmesh

struct Command {
  const char* name;
  const char* summary;
  const char* help;  // full text for `pqmesh NAME --help`
  int (*run)(const std::vector<std::string>& args);
};

int run_info(const std::vector<std::string>& args);
int run_mesh(const std::vector<std::string>& args);
int run_check(const std::vector<std::string>& args);
int run_quality(const std::vector<std::string>& args);
int run_convert(const std::vector<std::string>& args);
int run_octree(const std::vector<std::string>& args);

const std::vector<Command>& commands();

}  // namespace pqmesh::cli
