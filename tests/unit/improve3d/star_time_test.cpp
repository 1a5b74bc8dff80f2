// CollapseMesh star times (src/improve3d/collapse_mesh.hpp "Star times") on a
// hand-built mesh where the changed stars are known, and Adjacency's segments
// (src/improve3d/adjacency.hpp) through many moves and packs.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "improve3d/adjacency.hpp"
#include "improve3d/collapse_mesh.hpp"
#include "quality/tetrahedron_quality_memo.hpp"
#include "two_and_one_mesh.hpp"

namespace pqmesh::improve3d::detail {
namespace {

using test::two_and_one;

// The vertices whose star time is after `t`.
std::vector<int> newer_than(const CollapseMesh& mesh, std::uint64_t t) {
  std::vector<int> out;
  for (int v = 0; v < mesh.vertex_count(); ++v)
    if (mesh.star_time(v) > t) out.push_back(v);
  return out;
}

TEST(StarTime, MoveStampsTheVerticesOfTheStarOnly) {
  TetrahedronQualityMemo memo;
  CollapseMesh mesh(two_and_one(), {}, memo);
  const std::uint64_t t0 = mesh.time();
  EXPECT_TRUE(newer_than(mesh, t0).empty());
  const std::vector<int> star = {0};  // the star of 3: tetrahedron 0
  mesh.move_vertex(3, {0.1, 0.1, 0.9}, star, std::vector<double>{2.0}, std::vector<double>{40.0});
  EXPECT_GT(mesh.time(), t0);
  EXPECT_EQ(newer_than(mesh, t0), (std::vector<int>{0, 1, 2, 3}));
}

TEST(StarTime, AddAndRemoveStampTheirVertices) {
  TetrahedronQualityMemo memo;
  CollapseMesh mesh(two_and_one(), {}, memo);
  const std::uint64_t t0 = mesh.time();
  mesh.remove_tet(2);
  EXPECT_EQ(newer_than(mesh, t0), (std::vector<int>{5, 6, 7, 8}));
  const std::uint64_t t1 = mesh.time();
  mesh.add_tet({5, 6, 7, 8}, 0, 1.5, 60.0);
  EXPECT_EQ(newer_than(mesh, t1), (std::vector<int>{5, 6, 7, 8}));
  const std::uint64_t t2 = mesh.time();
  mesh.add_face({0, 1, 3}, 0, 0);
  EXPECT_EQ(newer_than(mesh, t2), (std::vector<int>{0, 1, 3}));
}

// Collapsing 4 onto 0:
// tetrahedron 1 (0 2 1 4) holds 0 and 4, so it dies; the far tetrahedron's vertices keep their time.
TEST(StarTime, CollapseStampsDyingAndMovingTetrahedra) {
  TetrahedronQualityMemo memo;
  CollapseMesh mesh(two_and_one(), {}, memo);
  const std::uint64_t t0 = mesh.time();
  const std::vector<int> dying = {1};
  mesh.apply({4, 0, dying, {}, {}, {}, {}, {}});
  EXPECT_EQ(newer_than(mesh, t0), (std::vector<int>{0, 1, 2, 4}));
}

// Segments that grow past their room move to the pool's end and force packs;
// every segment keeps its content and order.
TEST(AdjacencyPack, SegmentsSurviveManyPacks) {
  constexpr int kVertices = 50;
  std::vector<std::array<int, 2>> elements;
  for (int v = 0; v + 1 < kVertices; ++v) elements.push_back({v, v + 1});
  Adjacency adjacency;
  adjacency.build(elements, kVertices);
  std::vector<std::vector<int>> expected(kVertices);
  for (int e = 0; e < static_cast<int>(elements.size()); ++e)
    for (const int v : elements[static_cast<std::size_t>(e)]) expected[static_cast<std::size_t>(v)].push_back(e);
  int next = static_cast<int>(elements.size());
  for (int round = 0; round < 40; ++round)
    for (int v = round % 3; v < kVertices; v += 3) {
      const std::vector<int> more = {next, next + 1, next + 2};
      next += 3;
      adjacency.append(v, more, [](int) { return true; });
      for (const int e : more) expected[static_cast<std::size_t>(v)].push_back(e);
    }
  for (int v = 0; v < kVertices; ++v) {
    std::vector<int> got;
    adjacency.gather(v, [](int) { return true; }, got);
    EXPECT_EQ(got, expected[static_cast<std::size_t>(v)]) << "vertex " << v;
  }
}

// As above with vertices that start empty (as most vertices' boundary
// triangle segments do) and segments emptied by gather: empty segments share
// their place in the pool with others, before or after them in vertex order.
TEST(AdjacencyPack, EmptySegmentsSurviveManyPacks) {
  constexpr int kVertices = 40;
  std::vector<std::array<int, 1>> elements;
  for (int v = 0; v < kVertices / 2; ++v) elements.push_back({v});  // the upper half empty, at the pool end
  Adjacency adjacency;
  adjacency.build(elements, kVertices);
  std::vector<std::vector<int>> expected(kVertices);
  for (int e = 0; e < static_cast<int>(elements.size()); ++e)
    expected[static_cast<std::size_t>(elements[static_cast<std::size_t>(e)][0])].push_back(e);
  int next = static_cast<int>(elements.size());
  std::vector<int> got;
  for (int round = 0; round < 60; ++round) {
    const int v = (round * 7) % kVertices;
    const std::vector<int> more = {next, next + 1};
    next += 2;
    adjacency.append(v, more, [](int) { return true; });
    for (const int e : more) expected[static_cast<std::size_t>(v)].push_back(e);
    if (round % 5 == 4) {  // empty a segment: every element dead
      const int w = (round * 3) % kVertices;
      got.clear();
      adjacency.gather(w, [](int) { return false; }, got);
      expected[static_cast<std::size_t>(w)].clear();
    }
  }
  for (int v = 0; v < kVertices; ++v) {
    got.clear();
    adjacency.gather(v, [](int) { return true; }, got);
    EXPECT_EQ(got, expected[static_cast<std::size_t>(v)]) << "vertex " << v;
  }
}

// Elements die while their vertices' segments are never gathered (as the
// far vertices of a coarsened region): the packs drop them, so the pool stays
// within a small multiple of the live elements, and every segment keeps its
// live elements in order.
TEST(AdjacencyPack, PacksDropDeadElements) {
  constexpr int kVertices = 30, kPerVertex = 4, kRounds = 400;
  std::vector<std::array<int, 1>> elements;
  for (int v = 0; v < kVertices; ++v)
    for (int i = 0; i < kPerVertex; ++i) elements.push_back({v});
  std::vector<char> dead(elements.size(), 0);
  const auto alive = [&](int e) { return dead[static_cast<std::size_t>(e)] == 0; };
  Adjacency adjacency;
  adjacency.build(elements, kVertices);
  std::vector<std::vector<int>> live(kVertices);
  for (int e = 0; e < static_cast<int>(elements.size()); ++e)
    live[static_cast<std::size_t>(elements[static_cast<std::size_t>(e)][0])].push_back(e);
  for (int round = 0; round < kRounds; ++round) {
    const int v = (round * 7) % kVertices;
    auto& mine = live[static_cast<std::size_t>(v)];
    dead[static_cast<std::size_t>(mine.front())] = 1;  // the oldest element of v dies, a new one comes
    mine.erase(mine.begin());
    const int fresh = static_cast<int>(dead.size());
    dead.push_back(0);
    adjacency.append(v, std::vector<int>{fresh}, alive);
    mine.push_back(fresh);
  }
  // The live elements stay kVertices * kPerVertex; kRounds appends without a drop would need more.
  EXPECT_LT(adjacency.pool_capacity(), static_cast<std::size_t>(4 * kVertices * kPerVertex));
  for (int v = 0; v < kVertices; ++v) {
    std::vector<int> got;
    adjacency.gather(v, alive, got);
    EXPECT_EQ(got, live[static_cast<std::size_t>(v)]) << "vertex " << v;
  }
}

}  // namespace
}  // namespace pqmesh::improve3d::detail
