#include "args.hpp"

#include <charconv>
#include <cmath>

namespace pqmesh::cli {

Args::Args(const std::vector<std::string>& argv, const std::set<std::string>& flags,
           const std::set<std::string>& options) {
  for (std::size_t i = 0; i < argv.size(); ++i) {
    const std::string& a = argv[i];
    if (a.size() < 2 || a[0] != '-' || a == "-") {
      positional_.push_back(a);
      continue;
    }
    std::string name = a, value;
    bool has_value = false;
    if (const auto eq = a.find('='); eq != std::string::npos) {
      name = a.substr(0, eq);
      value = a.substr(eq + 1);
      has_value = true;
    }
    if (flags.count(name)) {
      if (has_value) throw UsageError("option " + name + " takes no value");
      flags_.insert(name);
    } else if (options.count(name)) {
      if (!has_value) {
        if (i + 1 >= argv.size()) throw UsageError("option " + name + " needs a value");
        value = argv[++i];
      }
      options_[name] = value;
    } else {
      throw UsageError("unknown option " + name);
    }
  }
}

std::optional<std::string> Args::option(const std::string& name) const {
  const auto it = options_.find(name);
  if (it == options_.end()) return std::nullopt;
  return it->second;
}

double Args::number(const std::string& name, double fallback) const {
  const auto text = option(name);
  if (!text) return fallback;
  double value = 0;
  const auto [end, error] = std::from_chars(text->data(), text->data() + text->size(), value);
  if (error != std::errc() || end != text->data() + text->size() || !std::isfinite(value))
    throw UsageError("option " + name + " needs a number, got '" + *text + "'");
  return value;
}

void Args::expect_positional(std::size_t min, std::size_t max) const {
  if (positional_.size() < min) throw UsageError("missing argument");
  if (positional_.size() > max) throw UsageError("unexpected argument '" + positional_[max] + "'");
}

std::string output_option(const Args& args) {
  const auto short_form = args.option("-o"), long_form = args.option("--output");
  if (short_form && long_form) throw UsageError("give -o or --output, not both");
  if (!short_form && !long_form) throw UsageError("-o OUTPUT is required");
  return short_form ? *short_form : *long_form;
}

}  // namespace pqmesh::cli
