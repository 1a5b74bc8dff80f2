// Issue 5 items 4 and 5: the whole 3D pipeline (tet_mesh with its defaults:
// generic grid, every box kind, warping on) on 200 seeded random polyhedra
// (tests/support/random_domains.hpp: right prisms and frustums over random
// nonconvex polygons with through-holes, sharp spikes and notches, box and
// prism cavities, holes and cavities at a tiny gap from a wall), and the
// aspect-ratio property of thesis Theorem 7 (ch. 4): every tetrahedron has
// aspect ratio <= C / alpha, alpha the sharpest interior angle of P
// (compute_alpha, radians), C one constant for every input.
//
// Every seed is a check, never a silent skip: make_domain must accept the
// generator's output, tet_mesh must return (an exception is a failure,
// MeshNotSupported included), check_mesh must say valid, and the aspect bound
// must hold. A failing seed is either reported by an EXPECT or listed, with
// its failure class, in kKnownFailures below (the lead's decision; the list
// may only shrink: a seed failing outside it, or failing with another class,
// fails the test).
//
// Test time. The seeds are sharded (kShards TEST_P instances of kSeedsPerShard
// seeds; gtest_discover_tests in tests/CMakeLists.txt makes each instance its
// own ctest, so `ctest -j` runs shards in parallel). The random solids cost
// 15-84 s cpu each in Release (a pentagonal prism is already ~3 s and 300k
// tetrahedra), far above the ~0.3 s a seed may take in the default suite, so
// only the Smoke test (2 seeds of cheaper options) runs by default; the 200
// seeds run with --gtest_also_run_disabled_tests (as the slow corpus models
// of generic_corpus_test.cpp). Per-seed lines and a summary per shard are
// printed; when several shards run in one process an overall summary is
// printed at the end.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "pqmesh/alpha.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/errors.hpp"
#include "pqmesh/quality.hpp"
#include "pqmesh/tetmesh.hpp"
#include "support/random_domains.hpp"

namespace pqmesh::test {
namespace {

// Generator settings for the 200 seeds: the defaults of random_domains.hpp
// made cheaper, keeping every feature the issue asks for (nonconvex outlines
// with deep notches, up to 2 through-holes, cavities, spikes and notches of
// 5-20 degrees, near-touching gaps of 1e-2..0.3 relative to the outer radius,
// frustums, thin slabs, random scale and offset). Measured 2026-12-01 on
// seeds 0-3 and 100-103 (Release, shared machine): 1.0M-6.1M tetrahedra and
// 15-84 s cpu per meshed seed, so ~2-3 cpu hours for all 200. With the
// generator defaults (24 outer vertices, 4 holes, 1-degree spikes, 1e-3 gaps)
// single seeds take minutes.
PolyhedronOptions corpus_options() {
  PolyhedronOptions o;
  o.polygon.max_vertices = 10;
  o.polygon.max_holes = 2;
  o.polygon.max_hole_vertices = 6;
  o.polygon.min_spike_degrees = 5;
  o.polygon.min_gap = 1e-2;
  return o;
}

// The default-suite smoke run: 5-6 vertex outlines, no holes, no cavities,
// spikes >= 10 degrees, gaps >= 0.1 (still frustums, thin slabs, random
// scale). Measured 2026-12-01 on seeds 0-19: 160k-2.8M tetrahedra, 2.8-33 s
// cpu per seed; seeds 0 and 1 take ~3.7 s each.
PolyhedronOptions smoke_options() {
  PolyhedronOptions o;
  o.polygon.max_vertices = 6;
  o.polygon.max_holes = 0;
  o.polygon.min_spike_degrees = 10;
  o.polygon.min_gap = 1e-1;
  o.polygon.max_hole_vertices = 6;
  o.cavity_probability = 0;
  return o;
}

constexpr int kShards = 20;
constexpr int kSeedsPerShard = 10;  // kShards * kSeedsPerShard = 200 seeds: 0..199
constexpr int kSmokeSeeds = 2;      // the default-suite instance: seeds 0..kSmokeSeeds-1

// C of the property max aspect ratio <= C / alpha (alpha in radians). A
// MEASURED CEILING, not a derived value: the largest aspect * alpha over the
// seeds that mesh validly, rounded up with a margin of ~10%, measured
// 2026-12-01 (build of that day, before the "sliver" work on src/tet3d;
// the lead lowers it as the worst tetrahedra improve). The bound the thesis
// proves (Theorem 7) has an unspecified "true constant" k; this is ours.
// Measured maxima: 187,044 (smoke options, seed 12: alpha 9.89 deg, aspect
// 1.08e6, unwarped fallback), 23,967 (smoke options, seed 6, warped), 7,323
// (corpus options, seed 0). The median over the 22 valid seeds measured is
// ~300: the ceiling is set by a few slivers.
constexpr double kAspectAlphaCeiling = 2.1e5;

// Seeds that fail today, with the class of their failure (failure_class
// below). Listed so that the lead can decide; the test fails on any seed that
// fails outside this list or with a different class, and prints the seeds of
// the list that now pass (remove them). From the measurement of 2026-12-01,
// which covered only seeds 0-3 and 100-103 of corpus_options (the time box):
// the other seeds are unmeasured, and by the smoke-options rate (6 of 20
// seeds threw) about a quarter of them can be expected to fail.
//   "InternalError tree_impl.hpp:46": "root offset along axis a is too fine
//   for exact box planes". The Tree's exactness bound (|origin| + 3S + |off|)
//   is stricter than the one choose_generic_root_cube ensures
//   (max(|origin|, |origin + S|) + 2S + S/32) when the root origin is
//   negative, i.e. for inputs translated to negative coordinates.
const std::map<std::uint64_t, std::string>& known_failures() {
  static const std::map<std::uint64_t, std::string> k = {
      {101, "InternalError tree_impl.hpp:46"},
      {103, "InternalError tree_impl.hpp:46"},
  };
  return k;
}

struct SeedRecord {
  std::uint64_t seed = 0;
  enum class Status { Valid, Invalid, Threw } status = Status::Threw;
  std::string failure;         // class: "" when valid; see failure_class
  std::string detail;          // first lines of the message or check report
  std::int64_t tets = 0;
  double alpha = 0;            // radians (compute_alpha of the validated domain)
  double aspect = 0;           // max over the tetrahedra
  bool warp_fallback = false;  // TetMeshStats::warp_failure non-empty: the unwarped mesh was returned
  double cpu_seconds = 0;
  double aspect_alpha() const { return aspect * alpha; }
};

// "internal error at /path/src/tree/tree_impl.hpp:46: message" -> the
// "tree_impl.hpp:46" part, which names the failing check.
std::string internal_error_site(const std::string& what) {
  const std::size_t at = what.find(" at ");
  if (at == std::string::npos) return what.substr(0, 60);
  const std::size_t colon_after_line = what.find(": ", at);
  std::string site = what.substr(at + 4, colon_after_line == std::string::npos ? 60 : colon_after_line - at - 4);
  const std::size_t slash = site.find_last_of('/');
  return slash == std::string::npos ? site : site.substr(slash + 1);
}

std::string first_line(const std::string& s, std::size_t max_chars = 160) {
  const std::string line = s.substr(0, s.find('\n'));
  return line.size() > max_chars ? line.substr(0, max_chars) + "..." : line;
}

SeedRecord mesh_seed(std::uint64_t seed, const PolyhedronOptions& options) {
  SeedRecord r;
  r.seed = seed;
  const std::clock_t start = std::clock();
  try {
    const Domain3 d = make_domain(random_polyhedron(seed, options));
    r.alpha = compute_alpha(d.plc).radians;
    const TetMeshResult m = tet_mesh(d);
    r.tets = static_cast<std::int64_t>(m.mesh.tetrahedra.size());
    r.warp_fallback = !m.stats.warp_failure.empty();
    const CheckReport c = check_mesh(m.mesh, d);
    if (c.valid()) {
      r.status = SeedRecord::Status::Valid;
      r.aspect = quality_report(m.mesh).aspect_ratio.max;
    } else {
      r.status = SeedRecord::Status::Invalid;
      std::string kinds;
      for (const CheckKind k : c.kinds()) kinds += std::string(kinds.empty() ? "" : ",") + to_string(k);
      r.failure = "invalid mesh: " + kinds;
      r.detail = c.to_text();
    }
  } catch (const MeshNotSupported& e) {
    r.failure = "MeshNotSupported " + e.kind();
    r.detail = e.what();
  } catch (const InvalidInput& e) {  // DomainError from make_domain: a generator bug
    r.failure = std::string("InvalidInput ") + to_string(e.code());
    r.detail = e.what();
  } catch (const InternalError& e) {
    r.failure = "InternalError " + internal_error_site(e.what());
    r.detail = e.what();
  } catch (const std::exception& e) {
    r.failure = "exception";
    r.detail = e.what();
  }
  r.cpu_seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  return r;
}

void print_record(const SeedRecord& r) {
  const double deg = r.alpha * 180 / std::numbers::pi;
  if (r.status == SeedRecord::Status::Valid)
    std::printf("seed %3llu: %9lld tets, alpha %6.2f deg, aspect %10.1f, aspect*alpha %10.1f%s, %.2f s cpu\n",
                static_cast<unsigned long long>(r.seed), static_cast<long long>(r.tets), deg, r.aspect,
                r.aspect_alpha(), r.warp_fallback ? ", WARP FALLBACK" : "", r.cpu_seconds);
  else
    std::printf("seed %3llu: FAILED (%s), alpha %.2f deg, %.2f s cpu: %s\n", static_cast<unsigned long long>(r.seed),
                r.failure.c_str(), deg, r.cpu_seconds, first_line(r.detail).c_str());
}

void print_summary(const char* title, const std::vector<SeedRecord>& records) {
  int valid = 0, invalid = 0, threw = 0, fallback = 0;
  std::map<std::string, std::vector<std::uint64_t>> by_class;
  std::vector<double> products;
  std::vector<std::int64_t> tets;
  const SeedRecord* worst = nullptr;
  const SeedRecord* slowest = nullptr;
  double cpu = 0;
  for (const SeedRecord& r : records) {
    cpu += r.cpu_seconds;
    if (!slowest || r.cpu_seconds > slowest->cpu_seconds) slowest = &r;
    if (r.status != SeedRecord::Status::Valid) {
      (r.status == SeedRecord::Status::Invalid ? invalid : threw) += 1;
      by_class[r.failure].push_back(r.seed);
      continue;
    }
    ++valid;
    fallback += r.warp_fallback;
    products.push_back(r.aspect_alpha());
    tets.push_back(r.tets);
    if (!worst || r.aspect_alpha() > worst->aspect_alpha()) worst = &r;
  }
  std::printf("=== %s: %zu seeds, %d meshed valid (%d with the unwarped fallback), %d invalid, %d threw; "
              "%.1f s cpu",
              title, records.size(), valid, fallback, invalid, threw, cpu);
  if (slowest) std::printf(" (slowest seed %llu: %.1f s)", static_cast<unsigned long long>(slowest->seed), slowest->cpu_seconds);
  std::printf("\n");
  for (const auto& [cls, seeds] : by_class) {
    std::printf("  failure class \"%s\": %zu seeds:", cls.c_str(), seeds.size());
    for (const std::uint64_t s : seeds) std::printf(" %llu", static_cast<unsigned long long>(s));
    std::printf("\n");
  }
  if (products.empty()) return;
  std::sort(products.begin(), products.end());
  std::sort(tets.begin(), tets.end());
  const auto pct = [&](double p) { return products[static_cast<std::size_t>(p * static_cast<double>(products.size() - 1))]; };
  std::printf("  aspect*alpha: min %.1f, median %.1f, 90%% %.1f, max %.1f (seed %llu, alpha %.2f deg, aspect %.1f)\n",
              products.front(), pct(0.5), pct(0.9), products.back(), static_cast<unsigned long long>(worst->seed),
              worst->alpha * 180 / std::numbers::pi, worst->aspect);
  static constexpr std::array<double, 9> kEdges = {10, 30, 100, 300, 1e3, 3e3, 1e4, 1e5, 1e6};
  std::printf("  aspect*alpha histogram:");
  double lo = 0;
  for (const double hi : kEdges) {
    const auto n = std::count_if(products.begin(), products.end(), [&](double v) { return lo <= v && v < hi; });
    if (n > 0) std::printf(" [%g,%g):%lld", lo, hi, static_cast<long long>(n));
    lo = hi;
  }
  const auto above = std::count_if(products.begin(), products.end(), [&](double v) { return v >= lo; });
  if (above > 0) std::printf(" >=%g:%lld", lo, static_cast<long long>(above));
  std::printf("\n  tetrahedra: min %lld, median %lld, max %lld\n", static_cast<long long>(tets.front()),
              static_cast<long long>(tets[tets.size() / 2]), static_cast<long long>(tets.back()));
}

// Every record of this process, for the overall summary.
std::vector<SeedRecord>& all_records() {
  static std::vector<SeedRecord> records;
  return records;
}

class OverallSummary : public ::testing::Environment {
 public:
  void TearDown() override {
    if (all_records().size() > static_cast<std::size_t>(kSeedsPerShard)) print_summary("all shards run", all_records());
  }
};
[[maybe_unused]] ::testing::Environment* const kOverallSummary = ::testing::AddGlobalTestEnvironment(new OverallSummary);

void run_seeds(std::uint64_t first, std::uint64_t count, const PolyhedronOptions& options, bool use_known_failures,
               const char* title) {
  std::vector<SeedRecord> records;
  for (std::uint64_t seed = first; seed < first + count; ++seed) {
    const SeedRecord r = mesh_seed(seed, options);
    print_record(r);
    std::fflush(stdout);
    records.push_back(r);
    all_records().push_back(r);

    const auto known = use_known_failures ? known_failures().find(seed) : known_failures().end();
    if (r.status != SeedRecord::Status::Valid) {
      if (known != known_failures().end() && known->second == r.failure) continue;  // listed, same class
      ADD_FAILURE() << "seed " << seed << " failed: " << r.failure << "\n"
                    << describe_polyhedron(seed, options) << "\n"
                    << r.detail;
      continue;
    }
    if (known != known_failures().end())
      std::printf("seed %llu is in kKnownFailures (%s) but now meshes validly: remove it\n",
                  static_cast<unsigned long long>(seed), known->second.c_str());
    // Theorem 7: aspect ratio <= C / alpha for every tetrahedron.
    EXPECT_LE(r.aspect_alpha(), kAspectAlphaCeiling)
        << "seed " << seed << ": max aspect " << r.aspect << " at alpha " << r.alpha << " rad\n"
        << describe_polyhedron(seed, options);
  }
  print_summary(title, records);
}

class RandomPolyhedra : public ::testing::TestWithParam<int> {};

TEST_P(RandomPolyhedra, MeshValidWithAspectBelowCOverAlpha) {
  const int shard = GetParam();
  const std::uint64_t first = static_cast<std::uint64_t>(shard) * kSeedsPerShard;
  const std::string title = "shard " + std::to_string(shard) + " (seeds " + std::to_string(first) + ".." +
                            std::to_string(first + kSeedsPerShard - 1) + ")";
  run_seeds(first, kSeedsPerShard, corpus_options(), true, title.c_str());
}

INSTANTIATE_TEST_SUITE_P(DISABLED_Shards, RandomPolyhedra, ::testing::Range(0, kShards));

TEST(RandomPolyhedraSmoke, FirstSeedsMeshValidWithAspectBelowCOverAlpha) {
  run_seeds(0, kSmokeSeeds, smoke_options(), false, "smoke (seeds 0..1, smoke options)");
}

// The list of known failures may only shrink: its size is pinned here, so
// adding a seed is a visible change of this number.
TEST(RandomPolyhedraSmoke, KnownFailureListDoesNotGrow) {
  constexpr std::size_t kKnownFailureCount = 2;
  std::printf("known failures listed: %zu\n", known_failures().size());
  EXPECT_LE(known_failures().size(), kKnownFailureCount);
}

}  // namespace
}  // namespace pqmesh::test
