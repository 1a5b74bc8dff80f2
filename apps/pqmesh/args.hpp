#pragma once
// A small command-line parser: positional arguments plus --flag and
// --option VALUE (or --option=VALUE). Unknown options are errors, so a typo
// never silently changes what a run does.
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace pqmesh::cli {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Args {
 public:
  // flags: options without a value; options: options that take one value.
  Args(const std::vector<std::string>& argv, const std::set<std::string>& flags, const std::set<std::string>& options);

  bool flag(const std::string& name) const { return flags_.count(name) > 0; }
  std::optional<std::string> option(const std::string& name) const;
  double number(const std::string& name, double fallback) const;
  const std::vector<std::string>& positional() const { return positional_; }
  // Throws UsageError unless there are between min and max positional arguments.
  void expect_positional(std::size_t min, std::size_t max) const;

 private:
  std::set<std::string> flags_;
  std::map<std::string, std::string> options_;
  std::vector<std::string> positional_;
};

// The output path of a command: -o OUTPUT or --output OUTPUT, required, one of
// the two. Throws UsageError otherwise.
std::string output_option(const Args& args);

}  // namespace pqmesh::cli
