// Invariants of the 3D octree (thesis §4.1.7, §4.2) over the
// fast corpus models and seeded random polyhedra (tests/support/random_domains:
// right prisms and frustums over random polygons with holes, spikes and box or
// prism cavities; options scaled down below):
//   * every leaf meeting P is empty inside P, a vertex, edge or facet cone, or
//     two facets of an edge outside it (leaf_kind.hpp; never Other);
//   * Lemma 1: every vertex lies at least 1/4 of its united box's side from
//     the box's facets (the thesis asks 1/8 of the box size);
//   * the balance condition between balance-adjacent unprotected leaves;
//   * Theorem 5: h(b) / (alpha h(B)) >= octest::kTheorem5Bound over adjacent pairs
//     (size_ratio.hpp), a bound measured here (see kTheorem5Bound in octree_test_util.hpp).
// The checks live in tests/unit/mv3d/octree_test_util.hpp, shared with
// octree_corpus_test.cpp (which adds the per-phase cone checks on the corpus).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <limits>
#include <string>
#include <utility>

#include "mv3d/octree_builder.hpp"
#include "mv3d/size_ratio.hpp"
#include "pqmesh/alpha.hpp"
#include "pqmesh/domain.hpp"
#include "support/random_domains.hpp"
#include "unit/mv3d/octree_test_util.hpp"

namespace pqmesh::mv3d {
namespace {

// Random polyhedra small enough for an octree in a few seconds: few vertices,
// at most one hole, spikes of 20-45 degrees, fewer cavities, no near-touching
// holes or cavities (their 1e-3 gaps alone need ~10 levels of refinement).
test::PolyhedronOptions small_polyhedra() {
  test::PolyhedronOptions o;
  o.polygon.min_vertices = 4;
  o.polygon.max_vertices = 6;
  o.polygon.max_holes = 1;
  o.polygon.min_hole_vertices = 3;
  o.polygon.max_hole_vertices = 4;
  o.polygon.min_spike_degrees = 20;
  o.polygon.max_spike_degrees = 45;
  o.polygon.near_touch_probability = 0;
  o.near_touch_probability = 0;
  o.cavity_probability = 0.25;
  return o;
}

// The separating splits of thesis §4.1.7 steps 6 and 9 multiply the leaves by
// about 10 (seed 5: 37k -> 412k leaves), so the main test runs a few cheap
// seeds of small_polyhedra(), among them seed 6 (the smallest Theorem 5 ratio
// measured) and seed 7 (a frustum, top scale 1/2, which without step 6 left a
// protected leaf next to edge boxes holding three facets of one vertex without
// the vertex or an edge); the others up to kMoreSeeds run in the disabled test.
constexpr std::uint64_t kFastSeeds[] = {1, 6, 7, 10, 11, 12, 14, 19};
constexpr std::uint64_t kMoreSeeds = 64;

struct Totals {
  double worst = std::numeric_limits<double>::infinity();
  std::string worst_where;
};
Totals& totals() {
  static Totals t;
  return t;
}

void check_octree(const Domain3& d, const std::string& label, OctreeOptions options = {}) {
  OctreeBuilder b(d, std::move(options));
  const auto t0 = std::chrono::steady_clock::now();
  b.build();
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto kinds = octest::expect_leaf_kinds(b, label);
  octest::expect_lemma1(b, label);
  octest::expect_balance(b, label);
  const AlphaResult alpha = compute_alpha(d.plc);
  const SizeRatioReport r = size_ratio(b, alpha.radians);
  EXPECT_GE(r.min_ratio, octest::kTheorem5Bound)
      << label << ": leaves " << r.small << " (side " << r.h_small << ") and " << r.big << " (side " << r.h_big << ")";
  std::printf(
      "%-40s %6d leaves %.2fs | %s | alpha %.2f deg, Theorem 5 min h(b)/(alpha h(B)) %.4f (leaves %d, %d: "
      "%g / %g; plain %.4f)\n",
      label.c_str(), b.tree().leaf_count(), secs, octest::kinds_summary(kinds).c_str(), alpha.degrees(), r.min_ratio,
      r.small, r.big, r.h_small, r.h_big, r.min_plain);
  if (r.min_ratio < totals().worst) {
    totals().worst = r.min_ratio;
    totals().worst_where = label;
  }
}

class OctreeInvariantsCorpus : public ::testing::TestWithParam<const char*> {};

TEST_P(OctreeInvariantsCorpus, LeafKindsLemma1BalanceTheorem5) {
  check_octree(octest::load_corpus(GetParam()), GetParam());
}

std::string param_name(const ::testing::TestParamInfo<const char*>& param) {
  std::string s = param.param;
  for (char& c : s)
    if (c == '.') c = '_';
  return s;
}

INSTANTIATE_TEST_SUITE_P(Corpus, OctreeInvariantsCorpus, ::testing::ValuesIn(octest::kFastCorpus), param_name);

void check_random(std::uint64_t seed) {
  const test::PolyhedronOptions options = small_polyhedra();
  SCOPED_TRACE(test::describe_polyhedron(seed, options));
  check_octree(make_domain(test::random_polyhedron(seed, options)), "seed " + std::to_string(seed));
}

TEST(OctreeInvariantsRandom, LeafKindsLemma1BalanceTheorem5) {
  for (const std::uint64_t seed : kFastSeeds) check_random(seed);
  std::printf("Theorem 5: smallest h(b)/(alpha h(B)) in this process %.4f (%s); asserted bound %.4f\n", totals().worst,
              totals().worst_where.c_str(), octest::kTheorem5Bound);
}

// Harsh seed 9 (random_domains.hpp, harsh_polyhedron_options) on the generic
// grid, as `pqmesh mesh` builds it: the leaves balance-adjacent to an edge
// box of a trihedral vertex cone all have a kind, none Other
// (OctreeBuilder::neighbour_would_be_of_no_kind, docs/algorithm/octree3d.md).
TEST(OctreeInvariantsRandom, HarshSeed9EdgeBoxNeighboursHaveAKind) {
  const std::uint64_t seed = 9;
  const test::PolyhedronOptions options = test::harsh_polyhedron_options();
  SCOPED_TRACE(test::describe_polyhedron(seed, options));
  OctreeOptions generic;
  generic.generic_grid = true;
  check_octree(make_domain(test::random_polyhedron(seed, options)), "harsh seed 9", std::move(generic));
}

// Seed 7 without the separating splits (OctreeOptions::separate): every leaf
// has a kind; the edge rule splits away a protected leaf that would hold
// three facets of a vertex outside it (the case of harsh seed 9 above).
TEST(OctreeInvariantsRandom, Seed7WithoutSeparatingSplitsHasEveryLeafOfAKind) {
  OctreeOptions unseparated;
  unseparated.separate = false;
  check_octree(make_domain(test::random_polyhedron(7, small_polyhedra())), "seed 7 unseparated", std::move(unseparated));
}

TEST(OctreeInvariantsRandom, DISABLED_MoreSeeds) {
  for (std::uint64_t seed = 1; seed <= kMoreSeeds; ++seed)
    if (std::find(std::begin(kFastSeeds), std::end(kFastSeeds), seed) == std::end(kFastSeeds)) check_random(seed);
  std::printf("Theorem 5: smallest h(b)/(alpha h(B)) in this process %.4f (%s); asserted bound %.4f\n", totals().worst,
              totals().worst_where.c_str(), octest::kTheorem5Bound);
}

}  // namespace
}  // namespace pqmesh::mv3d
