// PointBook remembers the ids of recently asked plain grid keys
// (point_book.hpp, recent_): a hit must return the id the full path gives,
// and no first use may be skipped or reordered. Checked against a reference
// numbering (ids in order of first use, warped grid points under their
// Warped key) on random sequences of keys drawn from a small grid (many
// repeats, many slot collisions), mixed with keys of other kinds and with
// Grid keys that carry a facet (not remembered), with and without a warp
// table.
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <tuple>
#include <vector>

#include "tet3d/points/point_book.hpp"
#include "tet3d/warp/warp_table.hpp"

namespace pqmesh::tet3d {
namespace {

using RefKey = std::tuple<int, std::array<std::int64_t, 3>, std::array<std::int64_t, 3>, int>;

void run_sequence(bool with_warps, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> coord(0, 7), kind(0, 9), facet(0, 3);
  auto grid = [&] {
    GridPoint p;
    for (auto& f : p.f) f = std::int64_t{coord(rng)} << 40;
    return p;
  };
  WarpTable warps;
  if (with_warps)
    for (int i = 0; i < 60; ++i) warps.insert(grid(), Warp{facet(rng), Vec3{1.0 * i, 0, 0}});
  PointBook book;
  book.set_warps(with_warps ? &warps : nullptr);
  std::map<RefKey, int> ref;
  std::vector<Vec3> ref_points;
  for (int step = 0; step < 20000; ++step) {
    VertexKey key;
    const int k = kind(rng);
    key.p = grid();
    if (k == 0) {  // another kind
      key.kind = VertexKind::FacetCrossing;
      key.q = grid();
      key.facet = facet(rng);
    } else if (k == 1) {  // a Grid key with a facet: never remembered
      key.facet = facet(rng);
    }
    const Vec3 made{static_cast<double>(step), 1, 2};
    VertexKey resolved = key;
    Vec3 at = made;
    if (with_warps && key.kind == VertexKind::Grid)
      if (const Warp* w = warps.find(key.p)) {
        resolved = {VertexKind::Warped, key.p, {}, w->facet};
        at = w->at;
      }
    const RefKey rk{static_cast<int>(resolved.kind), resolved.p.f, resolved.q.f, resolved.facet};
    const auto [it, fresh] = ref.try_emplace(rk, static_cast<int>(ref.size()));
    if (fresh) ref_points.push_back(at);
    const int got = book.id(key, [&] { return made; });
    ASSERT_EQ(got, it->second) << "step " << step;
    ASSERT_EQ(book.size(), static_cast<int>(ref.size()));
    EXPECT_EQ(book.point(got).x, ref_points[static_cast<std::size_t>(got)].x);
  }
}

TEST(PointBookRecent, IdsMatchFirstUseNumberingWithoutWarps) { run_sequence(false, 3); }
TEST(PointBookRecent, IdsMatchFirstUseNumberingWithWarps) { run_sequence(true, 5); }

}  // namespace
}  // namespace pqmesh::tet3d
