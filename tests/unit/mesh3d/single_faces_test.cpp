// single_faces (src/mesh3d/single_faces.cpp) files each tetrahedron's faces
// under their smallest vertex and, for distinct ids, reads the faces off ONE
// sort of the tetrahedron's ids instead of sorting each face. Checked against
// the definition (a face is single when its sorted vertex triple occurs once
// among all 4 n faces; codes 4 t + i in increasing order) on random
// tetrahedron lists: dense ids (many shared faces, faces on three or more
// tetrahedra), a grid of Kuhn tetrahedra (a conforming mesh: shared faces in
// pairs), and lists with repeated ids inside a tetrahedron.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <random>
#include <vector>

#include "mesh3d/single_faces.hpp"

namespace pqmesh::mesh3d {
namespace {

std::vector<std::int64_t> reference_single_faces(const std::vector<std::array<int, 4>>& tets) {
  std::map<std::array<int, 3>, int> count;
  auto key = [](std::array<int, 3> f) {
    std::sort(f.begin(), f.end());
    return f;
  };
  for (const auto& k : tets)
    for (int i = 0; i < 4; ++i) ++count[key(outward_face(k, i))];
  std::vector<std::int64_t> out;
  for (std::size_t t = 0; t < tets.size(); ++t)
    for (int i = 0; i < 4; ++i)
      if (count[key(outward_face(tets[t], i))] == 1) out.push_back(static_cast<std::int64_t>(4 * t) + i);
  return out;
}

TEST(SingleFaces, RandomDenseListsMatchTheDefinition) {
  std::mt19937_64 rng(41);
  for (int round = 0; round < 300; ++round) {
    const int nv = 5 + round % 20;
    std::uniform_int_distribution<int> id(0, nv - 1);
    std::vector<std::array<int, 4>> tets(static_cast<std::size_t>(1 + round % 40));
    for (auto& k : tets)
      do {
        k = {id(rng), id(rng), id(rng), id(rng)};
      } while (k[0] == k[1] || k[0] == k[2] || k[0] == k[3] || k[1] == k[2] || k[1] == k[3] || k[2] == k[3]);
    EXPECT_EQ(single_faces(tets, nv), reference_single_faces(tets));
  }
}

TEST(SingleFaces, RepeatedIdsMatchTheDefinition) {
  std::mt19937_64 rng(43);
  for (int round = 0; round < 300; ++round) {
    const int nv = 3 + round % 10;
    std::uniform_int_distribution<int> id(0, nv - 1);
    std::vector<std::array<int, 4>> tets(static_cast<std::size_t>(1 + round % 30));
    for (auto& k : tets) k = {id(rng), id(rng), id(rng), id(rng)};
    EXPECT_EQ(single_faces(tets, nv), reference_single_faces(tets));
  }
}

// The six Kuhn tetrahedra of every cube of an n^3 grid (vertex order
// shuffled per tetrahedron): single faces are exactly the grid's boundary
// triangles, 12 n^2 of them.
TEST(SingleFaces, KuhnGridMatchesTheDefinition) {
  std::mt19937_64 rng(47);
  const int n = 4, m = n + 1;
  auto vid = [&](int x, int y, int z) { return (z * m + y) * m + x; };
  static constexpr int kPaths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  std::vector<std::array<int, 4>> tets;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        for (const auto& path : kPaths) {
          int c[3] = {x, y, z};
          std::array<int, 4> k{};
          k[0] = vid(c[0], c[1], c[2]);
          for (int j = 0; j < 3; ++j) {
            ++c[path[j]];
            k[static_cast<std::size_t>(j + 1)] = vid(c[0], c[1], c[2]);
          }
          std::shuffle(k.begin(), k.end(), rng);
          tets.push_back(k);
        }
  const auto got = single_faces(tets, m * m * m);
  EXPECT_EQ(got, reference_single_faces(tets));
  EXPECT_EQ(got.size(), static_cast<std::size_t>(12 * n * n));
}

}  // namespace
}  // namespace pqmesh::mesh3d
