// The whole 3D pipeline (tet_mesh with its defaults:
// generic grid, every box kind, warping on) on 200 seeded random polyhedra
// (tests/support/random_domains.hpp: right prisms and frustums over random
// nonconvex polygons with through-holes, sharp spikes and notches, box and
// prism cavities), and the aspect-ratio property of thesis Theorem 7
// (ch. 4): every tetrahedron has aspect ratio <= C / alpha, alpha the
// sharpest interior angle of P (compute_alpha, radians), C one constant for
// every input (kAspectAlphaC, aspect_alpha_property.hpp).
//
// Every seed is a check, never a silent skip: make_domain must accept the
// generator's output, tet_mesh must return (an exception is a failure,
// MeshNotSupported included), check_mesh must say valid, and the aspect bound
// must hold. A failing seed is either reported by an EXPECT or listed, with
// its failure class, in known_failures() below (the lead's decision; the list
// may only shrink: a seed failing outside it, or failing with another class,
// fails the test). Every seed prints one result line and its
// describe_polyhedron() line (the features it has).
//
// Four families (tests/support/random_domains.hpp):
//  - "every-run": every_run_polyhedron_options() (the rationale is at its
//    declaration: the suite family below with larger 4-5-vertex holes and no
//    hole notch, gaps >= 1/4 of the outer radius, 4-5 outer vertices, fewer
//    spikes and cavities); seeds 0..199, ALL of them, in the DEFAULT suite:
//    kEveryRunShards TEST_P instances of kEveryRunSeedsPerShard, each its own
//    ctest (gtest_discover_tests), in the Release and the sanitizer build
//    alike (measured in CI: the sanitizer build takes about 2.3 times the
//    Release time per shard, about 750 s of ctest time for all 40).
//    RandomPolyhedraEveryRun.SeedsCoverEveryFeature counts the features over
//    the 200 seeds (no meshing) and fails if one disappears.
//  - "suite": suite_polyhedron_options(), gaps >= 3/16 of the outer radius,
//    small holes (radius 0.12-0.2, 3-5 vertices, notches), at most one
//    20-30 degree spike, mild frustums; seeds 0..199 in kSuiteFamilyShards
//    DISABLED instances of kSuiteFamilySeedsPerShard (kept as measurement
//    shards; its seeds 67, 92 and 135 are reproducers quoted by the docs).
//  - "bounded": bounded_feature_polyhedron_options(), every feature at least
//    ~1/16 of the bounding box, spikes 12-30 deg, through-holes and cavities;
//    seeds 0..199 in kBoundedShards DISABLED instances of
//    kBoundedSeedsPerShard.
//  - "harsh": test::harsh_polyhedron_options() (random_domains.hpp), 1e-2 gaps and 5-degree spikes; seeds
//    0..199 in kHarshShards DISABLED instances of kHarshSeedsPerShard.
// Test time. Measured 2026-12-01 (Release; cpu s per seed including
// check_mesh and quality_report):
//  - every-run seeds 0..199, one process: all 200 valid, none threw, no
//    unwarped fallback; about 160 cpu s in all (about 180 s of ctest time
//    at -j2, 90 s wall): median 0.46 s, max 13.3 s (seed 70, frustum + hole
//    + spike); 15k-1.6M tetrahedra, median 130k.
//  - suite seeds 0..199: ALL 200 valid, none threw; 652 cpu s in all (median 1.45 s, max 45.1 s, seed
//    92; 26k-3.9M tetrahedra, median 311k), 6.5x the ~100 s budget of the
//    default suite, hence the every-run family (the cost is a heavy tail:
//    the 48 seeds with a small through-hole take 397 s).
//  - bounded seeds 0-10: 0.9-34 s, median 5.5 s, 177k-4.4M tetrahedra (a
//    cube is 0.33 s and 51k), so ~20-30 cpu minutes for the 200; harsh seeds 15-84 s. Both are
//    DISABLED (run them with --gtest_also_run_disabled_tests, e.g.
//    --gtest_filter='*Bounded*'); the default suite also keeps kSuiteSeeds,
//    a FIXED hand-picked list of cheap bounded seeds (picked for cost only;
//    the other seeds are not known to fail).
// Per-seed lines and a summary per shard are printed; when several shards
// run in one process an overall summary is printed at the end.
#include <gtest/gtest.h>

#include "aspect_alpha_property.hpp"
#include "mesh_check_util.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "pqmesh/alpha.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/errors.hpp"
#include "pqmesh/quality.hpp"
#include "pqmesh/tetmesh.hpp"
#include "predicates/predicates.hpp"
#include "support/random_domains.hpp"

namespace pqmesh::test {
namespace {


constexpr int kBoundedShards = 40;
constexpr int kBoundedSeedsPerShard = 5;  // 200 seeds: 0..199
// The "suite" family: 40 ctests of 5 seeds (when enabled), so
// ctest -j2 balances them and a shard stays far below the 600 s ctest timeout
// under ASan (see the header for the measured cost).
constexpr int kSuiteFamilyShards = 40;
constexpr int kSuiteFamilySeedsPerShard = 5;  // 200 seeds: 0..199
// The "every-run" family: ALL seeds 0..199 in the default suite, 40 ctests
// of 5 seeds, so ctest -j2 balances them (see the header for the cost).
constexpr int kEveryRunShards = 40;
constexpr int kEveryRunSeedsPerShard = 5;  // 200 seeds: 0..199
constexpr int kHarshShards = 20;
constexpr int kHarshSeedsPerShard = 10;   // 200 seeds: 0..199
// The default-suite seeds of the bounded family, picked for cost (measured
// 2026-12-01, Release, cpu s including check_mesh: seed 7 a frustum, 177k
// tets, 2.1 s; seed 9 a slab with a box cavity, 606k tets, 2.9 s, the
// largest aspect * alpha measured, see aspect_alpha_property.hpp; seed 10 a
// 5-gon prism, 248k tets, 1.4 s).
constexpr std::array<std::uint64_t, 3> kSuiteSeeds = {7, 9, 10};

// Seeds expected to fail, per family, with the class of their failure
// (failure_class below). The test fails on any seed that fails outside this
// list or with a different class, and prints the listed seeds that pass
// (remove them). The list is empty: every seed of every family meshes
// validly. A seed above kAspectAlphaC fails its shard through the aspect
// check; quality failures are never listed here.
const std::map<std::pair<std::string, std::uint64_t>, std::string>& known_failures() {
  static const std::map<std::pair<std::string, std::uint64_t>, std::string> k = {};
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
  std::int64_t worst_box_rounds = 0;  // TetMeshStats::worst_box_rounds (printed when not 0)
  bool separated = false;      // TetMeshStats::separated: the thesis's octree made the mesh
  std::string octree;          // test::octree_used
  double constructed_aspect = 0;  // TetMeshStats::constructed_max_aspect (before improvement)
  std::int64_t constructed_tets = 0;
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
    r.worst_box_rounds = m.stats.worst_box_rounds;
    r.separated = m.stats.separated;
    r.octree = test::octree_used(m.stats);
    r.constructed_aspect = m.stats.constructed_max_aspect;
    r.constructed_tets = m.stats.constructed_tetrahedra;
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
  const std::string rounds =
      r.worst_box_rounds > 0 ? ", " + std::to_string(r.worst_box_rounds) + " worst-box rounds" : "";
  if (r.status == SeedRecord::Status::Valid)
    std::printf("seed %3llu: %9lld tets (%lld constructed), alpha %6.2f deg, aspect %10.1f (%.1f constructed), "
                "aspect*alpha %10.1f, %s%s%s, %.2f s cpu\n",
                static_cast<unsigned long long>(r.seed), static_cast<long long>(r.tets),
                static_cast<long long>(r.constructed_tets), deg, r.aspect, r.constructed_aspect,
                r.aspect_alpha(), r.octree.c_str(), r.warp_fallback ? ", WARP FALLBACK" : "",
                rounds.c_str(), r.cpu_seconds);
  else
    std::printf("seed %3llu: FAILED (%s), alpha %.2f deg, %.2f s cpu: %s\n", static_cast<unsigned long long>(r.seed),
                r.failure.c_str(), deg, r.cpu_seconds, first_line(r.detail).c_str());
}

void print_summary(const char* title, const std::vector<SeedRecord>& records) {
  int valid = 0, invalid = 0, threw = 0, fallback = 0, separated = 0;
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
    separated += r.separated;
    products.push_back(r.aspect_alpha());
    tets.push_back(r.tets);
    if (!worst || r.aspect_alpha() > worst->aspect_alpha()) worst = &r;
  }
  std::printf("=== %s: %zu seeds, %d meshed valid (%d on the separated octree, %d with the unwarped fallback), "
              "%d invalid, %d threw; %.1f s cpu",
              title, records.size(), valid, separated, fallback, invalid, threw, cpu);
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
    if (all_records().size() > static_cast<std::size_t>(kHarshSeedsPerShard)) print_summary("all shards run", all_records());
  }
};
[[maybe_unused]] ::testing::Environment* const kOverallSummary = ::testing::AddGlobalTestEnvironment(new OverallSummary);

void run_seeds(const std::vector<std::uint64_t>& seeds, const std::string& family, const PolyhedronOptions& options,
               const std::string& title) {
  std::vector<SeedRecord> records;
  for (const std::uint64_t seed : seeds) {
    const SeedRecord r = mesh_seed(seed, options);
    print_record(r);
    std::printf("  %s\n", describe_polyhedron(seed, options).c_str());
    std::fflush(stdout);
    records.push_back(r);
    all_records().push_back(r);

    const auto known = known_failures().find({family, seed});
    if (r.status != SeedRecord::Status::Valid) {
      if (known != known_failures().end() && known->second == r.failure) continue;  // listed, same class
      ADD_FAILURE() << family << " seed " << seed << " failed: " << r.failure << "\n"
                    << describe_polyhedron(seed, options) << "\n"
                    << r.detail;
      continue;
    }
    if (known != known_failures().end())
      std::printf("%s seed %llu is in known_failures (%s) but now meshes validly: remove it\n", family.c_str(),
                  static_cast<unsigned long long>(seed), known->second.c_str());
    // The improvement stage is monotone: never above the construction's worst.
    EXPECT_LE(r.aspect, r.constructed_aspect) << family << " seed " << seed;
    // Theorem 7: aspect ratio <= C / alpha for every tetrahedron.
    EXPECT_LE(r.aspect_alpha(), kAspectAlphaC)
        << family << " seed " << seed << ": max aspect " << r.aspect << " at alpha " << r.alpha << " rad\n"
        << describe_polyhedron(seed, options);
  }
  print_summary(title.c_str(), records);
}

std::vector<std::uint64_t> seed_range(std::uint64_t first, std::uint64_t count) {
  std::vector<std::uint64_t> seeds;
  for (std::uint64_t s = first; s < first + count; ++s) seeds.push_back(s);
  return seeds;
}

std::string shard_title(const char* family, int shard, int per_shard) {
  const int first = shard * per_shard;
  return std::string(family) + " shard " + std::to_string(shard) + " (seeds " + std::to_string(first) + ".." +
         std::to_string(first + per_shard - 1) + ")";
}

class RandomPolyhedraBounded : public ::testing::TestWithParam<int> {};

TEST_P(RandomPolyhedraBounded, MeshValidWithAspectBelowCOverAlpha) {
  const int shard = GetParam();
  run_seeds(seed_range(static_cast<std::uint64_t>(shard) * kBoundedSeedsPerShard, kBoundedSeedsPerShard), "bounded",
            bounded_feature_polyhedron_options(), shard_title("bounded", shard, kBoundedSeedsPerShard));
}

INSTANTIATE_TEST_SUITE_P(DISABLED_Shards, RandomPolyhedraBounded, ::testing::Range(0, kBoundedShards));

class RandomPolyhedraHarsh : public ::testing::TestWithParam<int> {};

TEST_P(RandomPolyhedraHarsh, MeshValidWithAspectBelowCOverAlpha) {
  const int shard = GetParam();
  run_seeds(seed_range(static_cast<std::uint64_t>(shard) * kHarshSeedsPerShard, kHarshSeedsPerShard), "harsh",
            test::harsh_polyhedron_options(), shard_title("harsh", shard, kHarshSeedsPerShard));
}

INSTANTIATE_TEST_SUITE_P(DISABLED_Shards, RandomPolyhedraHarsh, ::testing::Range(0, kHarshShards));

class RandomPolyhedraSuiteFamily : public ::testing::TestWithParam<int> {};

TEST_P(RandomPolyhedraSuiteFamily, MeshValidWithAspectBelowCOverAlpha) {
  const int shard = GetParam();
  run_seeds(seed_range(static_cast<std::uint64_t>(shard) * kSuiteFamilySeedsPerShard, kSuiteFamilySeedsPerShard),
            "suite", suite_polyhedron_options(), shard_title("suite", shard, kSuiteFamilySeedsPerShard));
}

INSTANTIATE_TEST_SUITE_P(DISABLED_Shards, RandomPolyhedraSuiteFamily, ::testing::Range(0, kSuiteFamilyShards));

class RandomPolyhedraEveryRun : public ::testing::TestWithParam<int> {};

TEST_P(RandomPolyhedraEveryRun, MeshValidWithAspectBelowCOverAlpha) {
  const int shard = GetParam();
  run_seeds(seed_range(static_cast<std::uint64_t>(shard) * kEveryRunSeedsPerShard, kEveryRunSeedsPerShard),
            "every-run", every_run_polyhedron_options(),
            shard_title("every-run", shard, kEveryRunSeedsPerShard));
}

INSTANTIATE_TEST_SUITE_P(Shards, RandomPolyhedraEveryRun, ::testing::Range(0, kEveryRunShards));

// The every-run family keeps every feature of the random families: counted over
// its 200 seeds from the generator's own record (cheap: no meshing), each
// feature must occur on at least kMinSeedsPerFeature seeds, so a change of
// the options that drops one fails here.
TEST(RandomPolyhedraEveryRun, SeedsCoverEveryFeature) {
  constexpr int kMinSeedsPerFeature = 5;
  int nonconvex = 0, notched = 0, holed = 0, cavities = 0, box_cavities = 0, prism_cavities = 0, spiked = 0,
      frustums = 0;
  const PolyhedronOptions options = every_run_polyhedron_options();
  for (std::uint64_t seed = 0; seed < static_cast<std::uint64_t>(kEveryRunShards * kEveryRunSeedsPerShard); ++seed) {
    const RandomPolyhedron r = random_polyhedron_detail(seed, options);
    const std::vector<Vec2>& outer = r.base.loops[0];
    bool reflex = false;
    for (std::size_t i = 0; i < outer.size(); ++i)
      reflex |= orient2d(outer[(i + outer.size() - 1) % outer.size()], outer[i], outer[(i + 1) % outer.size()]) ==
                Sign::Negative;
    nonconvex += reflex;
    notched += r.base.notches > 0;
    holed += r.base.loops.size() > 1;
    cavities += !r.cavities.empty();
    for (const Cavity& c : r.cavities) (c.box ? box_cavities : prism_cavities) += 1;
    spiked += r.base.spikes > 0;
    frustums += !r.right_prism();
  }
  std::printf("every-run seeds 0..%d: nonconvex outline %d, outer notch %d, through-hole %d, cavity %d (%d box, %d "
              "prism cavities), spike %d, frustum %d\n",
              kEveryRunShards * kEveryRunSeedsPerShard - 1, nonconvex, notched, holed, cavities, box_cavities,
              prism_cavities, spiked, frustums);
  for (const int n : {nonconvex, notched, holed, cavities, box_cavities, prism_cavities, spiked, frustums})
    EXPECT_GE(n, kMinSeedsPerFeature);
}

TEST(RandomPolyhedraSuite, BoundedSeedsMeshValidWithAspectBelowCOverAlpha) {
  run_seeds(std::vector<std::uint64_t>(kSuiteSeeds.begin(), kSuiteSeeds.end()), "bounded",
            bounded_feature_polyhedron_options(), "suite (bounded seeds 7, 9, 10)");
}

// The list of known failures may only shrink: its size is pinned here, so
// adding a seed is a visible change of this number.
TEST(RandomPolyhedraSuite, KnownFailureListDoesNotGrow) {
  constexpr std::size_t kKnownFailureCount = 0;
  std::printf("known failures listed: %zu\n", known_failures().size());
  EXPECT_LE(known_failures().size(), kKnownFailureCount);
}

}  // namespace
}  // namespace pqmesh::test
