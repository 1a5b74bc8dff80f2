// pqmesh: mesh generation with provable quality bounds (Mitchell 1993).
// Dispatches to the subcommands of commands.cpp and maps errors to exit codes.
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "args.hpp"
#include "commands.hpp"
#include "pqmesh/errors.hpp"

namespace {

using namespace pqmesh::cli;

constexpr const char* kVersion = "pqmesh 0.1.0";

void print_overview(std::ostream& out) {
  out << kVersion << " - mesh generation with provable quality bounds (S. A. Mitchell, 1993)\n\n"
      << "usage: pqmesh COMMAND [ARGS]   (pqmesh COMMAND --help for details)\n\ncommands:\n";
  for (const Command& c : commands()) {
    out << "  " << c.name;
    for (std::size_t pad = std::string(c.name).size(); pad < 10; ++pad) out << ' ';
    out << c.summary << '\n';
  }
  out << "\nexit codes: 0 ok; 1 the checked mesh is not valid; 2 invalid input (the message names the\n"
         "offending ids and file line); 64 bad command line; 70 internal error; 73 an output file\n"
         "cannot be written (nothing is left behind).\n";
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> all(argv + 1, argv + argc);
  if (all.empty() || all[0] == "--help" || all[0] == "-h" || all[0] == "help") {
    print_overview(std::cout);
    return all.empty() ? kExitUsage : kExitOk;
  }
  if (all[0] == "--version") {
    std::cout << kVersion << '\n';
    return kExitOk;
  }
  for (const Command& c : commands()) {
    if (all[0] != c.name) continue;
    const std::vector<std::string> rest(all.begin() + 1, all.end());
    for (const std::string& a : rest) {
      if (a == "--help" || a == "-h") {
        std::cout << c.help;
        return kExitOk;
      }
    }
    try {
      return c.run(rest);
    } catch (const UsageError& e) {
      std::cerr << "pqmesh " << c.name << ": " << e.what() << " (see pqmesh " << c.name << " --help)\n";
      return kExitUsage;
    } catch (const pqmesh::InvalidInput& e) {
      std::cerr << "pqmesh " << c.name << ": " << e.what() << '\n';
      return kExitInvalidInput;
    } catch (const pqmesh::OutputError& e) {
      std::cerr << "pqmesh " << c.name << ": " << e.what() << '\n';
      return kExitCannotWrite;
    } catch (const pqmesh::InternalError& e) {
      std::cerr << "pqmesh " << c.name << ": " << e.what() << "\nplease report this as a bug\n";
      return kExitInternal;
    } catch (const std::exception& e) {
      std::cerr << "pqmesh " << c.name << ": internal error: " << e.what() << '\n';
      return kExitInternal;
    }
  }
  std::cerr << "pqmesh: unknown command '" << all[0] << "'\n\n";
  print_overview(std::cerr);
  return kExitUsage;
}
