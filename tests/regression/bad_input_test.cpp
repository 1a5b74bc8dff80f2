// Every row of data/bad/MANIFEST.tsv: reading and validating the file must throw InvalidInput
// with the listed ErrorCode, the listed file line (when not 0) and ids that include the listed
// ones. The expectations are derived in data/generate_corpus.py next to the code that builds
// each file; they are a specification, so a failure here means a reader or make_domain()
// disagrees with it (or the manifest is wrong: fix the generator, never just the row).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <ostream>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/errors.hpp"
#include "pqmesh/mesh_io.hpp"
#include "pqmesh/read_domain.hpp"
#include "support/paths.hpp"

namespace pqmesh {
namespace {

struct BadCase {
  std::string file;                // relative to data/
  std::string code;                // to_string(ErrorCode)
  int line = 0;                    // 0: not checked
  std::vector<std::int64_t> ids;   // must all be among the error's ids
  int manifest_line = 0;           // for messages
};

// GoogleTest prints parameters of failing cases with this.
void PrintTo(const BadCase& c, std::ostream* out) { *out << c.file << " [" << c.code << "]"; }

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string field;
  std::istringstream in(s);
  while (std::getline(in, field, sep)) out.push_back(field);
  if (!s.empty() && s.back() == sep) out.emplace_back();
  return out;
}

// Parses the manifest; a malformed row becomes a case with code "<malformed row>" so that it
// fails loudly instead of disappearing.
std::vector<BadCase> load_manifest() {
  std::vector<BadCase> cases;
  std::ifstream in(test::data_path("bad/MANIFEST.tsv"));
  std::string row;
  int n = 0;
  while (std::getline(in, row)) {
    ++n;
    if (row.empty() || row[0] == '#') continue;
    const auto fields = split(row, '\t');
    if (n == 1 && !fields.empty() && fields[0] == "file") continue;  // header
    BadCase c;
    c.manifest_line = n;
    if (fields.size() != 4) {
      c.file = row;
      c.code = "<malformed row>";
      cases.push_back(c);
      continue;
    }
    c.file = fields[0];
    c.code = fields[1];
    c.line = std::stoi(fields[2]);
    if (fields[3] != "-") {
      for (const auto& id : split(fields[3], ',')) c.ids.push_back(std::stoll(id));
    }
    cases.push_back(c);
  }
  return cases;
}

const std::vector<BadCase>& manifest() {
  static const std::vector<BadCase> cases = load_manifest();
  return cases;
}

bool is_read_error(ErrorCode code) { return static_cast<int>(code) <= static_cast<int>(ErrorCode::Unsupported); }

// All ErrorCode names (the enum is contiguous from Unreadable to EmptyDomain).
std::set<std::string> all_code_names() {
  std::set<std::string> names;
  for (int c = static_cast<int>(ErrorCode::Unreadable); c <= static_cast<int>(ErrorCode::EmptyDomain); ++c) {
    names.insert(to_string(static_cast<ErrorCode>(c)));
  }
  return names;
}

// What the CLI does with an input path: pick the dimension, read, validate.
// A .vtu is a mesh (pqmesh check/convert/quality read it): read as a 3D mesh.
void read_and_validate(const std::string& path) {
  if (path.size() > 4 && path.compare(path.size() - 4, 4, ".vtu") == 0) {
    (void)read_tetmesh(path);
  } else if (domain_dimension(path) == 2) {
    (void)make_domain(read_pslg(path));
  } else {
    (void)make_domain(read_plc(path));
  }
}

std::string join(const std::vector<std::int64_t>& ids) {
  std::ostringstream out;
  for (std::size_t i = 0; i < ids.size(); ++i) out << (i ? "," : "") << ids[i];
  return out.str();
}

class BadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadInput, ThrowsTheManifestError) {
  const BadCase& c = GetParam();
  ASSERT_NE(c.code, "<malformed row>") << "MANIFEST.tsv line " << c.manifest_line << ": " << c.file;
  const std::string path = test::data_path(c.file);
  SCOPED_TRACE(c.file + " (MANIFEST.tsv line " + std::to_string(c.manifest_line) + ")");
  try {
    read_and_validate(path);
    ADD_FAILURE() << "no error thrown; expected [" << c.code << "]";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(to_string(e.code()), c.code) << "message: " << e.what();
    // Reading errors are ParseError, validation errors DomainError (errors.hpp).
    if (is_read_error(e.code())) {
      EXPECT_NE(dynamic_cast<const ParseError*>(&e), nullptr) << e.what();
    } else {
      EXPECT_NE(dynamic_cast<const DomainError*>(&e), nullptr) << e.what();
    }
    if (c.line != 0) {
      EXPECT_EQ(e.line(), c.line) << "message: " << e.what();
    }
    for (const std::int64_t id : c.ids) {
      EXPECT_NE(std::find(e.ids().begin(), e.ids().end(), id), e.ids().end())
          << "id " << id << " not among the error's ids {" << join(e.ids()) << "}; message: " << e.what();
    }
    // The message names the file (docs/DESIGN_RULES.md "Bad input and errors":
    // validation names the file line).
    const std::string name = std::filesystem::path(c.file).filename().string();
    EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << "message does not name the file: " << e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected InvalidInput [" << c.code << "], got another exception: " << e.what();
  }
}

std::string case_name(const ::testing::TestParamInfo<BadCase>& p) {
  std::string name = p.param.file;
  for (char& ch : name) {
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  }
  return name + "_" + std::to_string(p.index);
}

INSTANTIATE_TEST_SUITE_P(Manifest, BadInput, ::testing::ValuesIn(manifest()), case_name);

// The manifest is well formed and complete: every code is a real ErrorCode name, every listed
// file exists except the deliberately missing unreadable ones, and every file in data/bad/ is
// listed (a new bad file without an expectation would otherwise go untested).
TEST(BadInputManifest, ListsEveryFileWithARealCode) {
  const auto& cases = manifest();
  ASSERT_GE(cases.size(), 20u) << "MANIFEST.tsv missing or nearly empty";
  const auto names = all_code_names();
  std::set<std::string> listed;
  for (const auto& c : cases) {
    EXPECT_TRUE(names.count(c.code)) << c.file << ": unknown error code '" << c.code << "'";
    EXPECT_TRUE(listed.insert(c.file).second) << c.file << " listed twice";
    const bool exists = std::filesystem::exists(test::data_path(c.file));
    EXPECT_EQ(exists, c.code != "unreadable") << c.file;
    EXPECT_GE(c.line, 0) << c.file;
  }
  for (const auto& entry : std::filesystem::directory_iterator(test::data_path("bad"))) {
    const std::string name = entry.path().filename().string();
    if (name == "MANIFEST.tsv") continue;
    EXPECT_TRUE(listed.count("bad/" + name)) << "data/bad/" << name << " is not in MANIFEST.tsv";
  }
  // Every required class of error is exercised at least once.
  std::set<std::string> used;
  for (const auto& c : cases) used.insert(c.code);
  for (const char* code : {"unreadable", "truncated", "syntax", "wrong-count", "index-out-of-range", "non-finite",
                           "duplicate-vertex", "degenerate-facet", "non-planar-facet", "open-boundary",
                           "non-manifold-edge", "pinched-vertex", "intersecting-facets", "self-intersecting-facet",
                           "disconnected", "invalid-polygon"}) {
    EXPECT_TRUE(used.count(code)) << "no bad input for [" << code << "]";
  }
}

}  // namespace
}  // namespace pqmesh
