// Stage 3 of the tetrahedral checker matches faces per smallest vertex with a
// hash table and falls back to a sorted scan when a vertex has a face on the
// same side of two tetrahedra or on three or more (check3d_topology.cpp). Both
// paths are checked against the definition written out plainly: every sorted
// vertex triple with its (tetrahedron, orientation parity) list in a std::map;
// a triple on one tetrahedron is a boundary face; on two with equal parities
// the two overlap; on three or more it is reported with all of them. The
// report must give the same boundary-face count and the same stage-3 messages
// in the same order, on random positive tetrahedron soups (many shared,
// overlapping and triple faces), on Kuhn grids with shuffled vertex orders
// (conforming), on grids with duplicated or extra tetrahedra, and on a fan of
// many tetrahedra around one vertex (a large bucket).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "pqmesh/check.hpp"
#include "pqmesh/mesh.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh {
namespace {

// The outward faces of a positive tetrahedron (the checker's convention).
constexpr int kOutward[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

std::string ids_text(const std::vector<int>& ids) {
  std::string s;
  for (std::size_t i = 0; i < ids.size(); ++i) s += (i ? " " : "") + std::to_string(ids[i]);
  return s;
}

struct Expected {
  std::int64_t boundary_faces = 0;
  std::vector<std::string> messages;
};

Expected reference(const TetMesh3& m) {
  std::map<std::array<int, 3>, std::vector<std::pair<int, int>>> faces;  // triple -> (tet, parity)
  for (std::size_t t = 0; t < m.tetrahedra.size(); ++t)
    for (const auto& row : kOutward) {
      std::array<int, 3> f = {m.tetrahedra[t][row[0]], m.tetrahedra[t][row[1]], m.tetrahedra[t][row[2]]};
      const int inversions = (f[0] > f[1]) + (f[0] > f[2]) + (f[1] > f[2]);
      std::sort(f.begin(), f.end());
      faces[f].push_back({static_cast<int>(t), inversions % 2});
    }
  Expected e;
  for (auto& [f, list] : faces) {
    std::sort(list.begin(), list.end());
    const std::string face = ids_text({f[0], f[1], f[2]});
    if (list.size() == 1) {
      ++e.boundary_faces;
    } else if (list.size() == 2) {
      if (list[0].second == list[1].second)
        e.messages.push_back("tetrahedra " + std::to_string(list[0].first) + " and " + std::to_string(list[1].first) +
                             " lie on the same side of their common face (" + face + "): they overlap");
    } else {
      std::vector<int> tets;
      for (const auto& x : list) tets.push_back(x.first);
      e.messages.push_back("face (" + face + ") is on " + std::to_string(list.size()) + " tetrahedra: " + ids_text(tets));
    }
  }
  return e;
}

// The checker's stage-3 face messages (other NonConforming issues, such as
// hanging vertices, come later and start differently).
std::vector<std::string> face_messages(const CheckReport& r) {
  std::vector<std::string> out;
  for (const auto& issue : r.issues)
    if (issue.kind == CheckKind::NonConforming &&
        (issue.message.rfind("tetrahedra ", 0) == 0 || issue.message.rfind("face (", 0) == 0))
      out.push_back(issue.message);
  return out;
}

void expect_matches_reference(const TetMesh3& m, const std::string& what) {
  CheckOptions options;
  options.max_issues_per_kind = 1000000;
  const CheckReport r = check_mesh_topology(m, options);
  const Expected e = reference(m);
  ASSERT_EQ(r.count(CheckKind::Orientation) + r.count(CheckKind::DegenerateElement), 0) << what;
  EXPECT_EQ(r.boundary_faces, e.boundary_faces) << what;
  EXPECT_EQ(face_messages(r), e.messages) << what;
}

// Positive orientation by swapping the last two ids; false when flat.
bool make_positive(const TetMesh3& m, std::array<int, 4>& q) {
  const Sign s = orient3d(m.vertices[q[0]], m.vertices[q[1]], m.vertices[q[2]], m.vertices[q[3]]);
  if (s == Sign::Zero) return false;
  if (s == Sign::Negative) std::swap(q[2], q[3]);
  return true;
}

// The ids in random order (callers restore the orientation with make_positive).
void shuffle_ids(std::array<int, 4>& q, std::mt19937_64& rng) {
  std::shuffle(q.begin(), q.end(), rng);
}

TEST(CheckFaceMatching, RandomSoupsMatchTheDefinition) {
  std::mt19937_64 rng(1202);
  std::uniform_real_distribution<double> u(0, 1);
  for (int round = 0; round < 300; ++round) {
    TetMesh3 m;
    const int nv = 5 + round % 25;
    for (int i = 0; i < nv; ++i) m.vertices.push_back({u(rng), u(rng), u(rng)});
    std::uniform_int_distribution<int> id(0, nv - 1);
    const int nt = 1 + round % 60;
    while (static_cast<int>(m.tetrahedra.size()) < nt) {
      std::array<int, 4> q = {id(rng), id(rng), id(rng), id(rng)};
      if (q[0] == q[1] || q[0] == q[2] || q[0] == q[3] || q[1] == q[2] || q[1] == q[3] || q[2] == q[3]) continue;
      if (!make_positive(m, q)) continue;
      m.tetrahedra.push_back(q);
    }
    expect_matches_reference(m, "soup " + std::to_string(round));
  }
}

// Kuhn grid of n^3 cubes, vertices numbered in a random order, each
// tetrahedron's ids rotated randomly (orientation fixed afterwards).
TetMesh3 kuhn_grid(int n, std::mt19937_64& rng) {
  TetMesh3 m;
  const int s = n + 1;
  std::vector<int> number(static_cast<std::size_t>(s * s * s));
  for (std::size_t i = 0; i < number.size(); ++i) number[i] = static_cast<int>(i);
  std::shuffle(number.begin(), number.end(), rng);
  m.vertices.resize(number.size());
  for (int z = 0; z < s; ++z)
    for (int y = 0; y < s; ++y)
      for (int x = 0; x < s; ++x)
        m.vertices[number[(z * s + y) * s + x]] = {static_cast<double>(x), static_cast<double>(y), static_cast<double>(z)};
  static constexpr int kPaths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        for (const auto& path : kPaths) {
          int c[3] = {x, y, z};
          std::array<int, 4> q{};
          q[0] = number[(c[2] * s + c[1]) * s + c[0]];
          for (int j = 0; j < 3; ++j) {
            ++c[path[j]];
            q[j + 1] = number[(c[2] * s + c[1]) * s + c[0]];
          }
          shuffle_ids(q, rng);
          EXPECT_TRUE(make_positive(m, q));
          m.tetrahedra.push_back(q);
        }
  return m;
}

TEST(CheckFaceMatching, KuhnGridsAndDefectsMatchTheDefinition) {
  std::mt19937_64 rng(77);
  for (int round = 0; round < 40; ++round) {
    TetMesh3 m = kuhn_grid(1 + round % 5, rng);
    expect_matches_reference(m, "grid " + std::to_string(round));
    EXPECT_EQ(reference(m).messages.size(), 0u);
    // Defects: a duplicated tetrahedron (four faces on the same side twice,
    // or on three tetrahedra), then a tetrahedron spanning other cubes.
    TetMesh3 d = m;
    std::array<int, 4> dup = d.tetrahedra[rng() % d.tetrahedra.size()];
    shuffle_ids(dup, rng);
    EXPECT_TRUE(make_positive(d, dup));
    d.tetrahedra.push_back(dup);
    expect_matches_reference(d, "grid+dup " + std::to_string(round));
    std::uniform_int_distribution<int> id(0, static_cast<int>(d.vertices.size()) - 1);
    for (int extra = 0; extra < 3;) {
      std::array<int, 4> q = {id(rng), id(rng), id(rng), id(rng)};
      if (q[0] == q[1] || q[0] == q[2] || q[0] == q[3] || q[1] == q[2] || q[1] == q[3] || q[2] == q[3]) continue;
      if (!make_positive(d, q)) continue;
      d.tetrahedra.insert(d.tetrahedra.begin() + static_cast<std::ptrdiff_t>(rng() % d.tetrahedra.size()), q);
      ++extra;
    }
    expect_matches_reference(d, "grid+extra " + std::to_string(round));
  }
}

// Vertex 0 at the apex of a fan over a triangulated square grid: hundreds of
// faces filed under vertex 0 (a large hash table), all shared in pairs except
// the outer rim.
TEST(CheckFaceMatching, LargeFanMatchesTheDefinition) {
  std::mt19937_64 rng(5);
  const int n = 20;
  TetMesh3 m;
  m.vertices.push_back({0.5 * n, 0.5 * n, 1});
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) m.vertices.push_back({static_cast<double>(x), static_cast<double>(y), 0});
  auto v = [&](int x, int y) { return 1 + y * (n + 1) + x; };
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      for (const auto& tri : {std::array<int, 3>{v(x, y), v(x + 1, y), v(x + 1, y + 1)},
                              std::array<int, 3>{v(x, y), v(x + 1, y + 1), v(x, y + 1)}}) {
        std::array<int, 4> q = {0, tri[0], tri[1], tri[2]};
        shuffle_ids(q, rng);
        EXPECT_TRUE(make_positive(m, q));
        m.tetrahedra.push_back(q);
      }
  expect_matches_reference(m, "fan");
  TetMesh3 d = m;
  d.tetrahedra.push_back(d.tetrahedra[rng() % d.tetrahedra.size()]);
  expect_matches_reference(d, "fan+dup");
}

}  // namespace
}  // namespace pqmesh
