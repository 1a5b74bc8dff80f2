// The compact warp candidate list (warp_candidates.hpp) against a plain
// construction written here from its definition: one record per point with
// growing vectors, filled use by use (every job's squares in order, ring
// order within a square) with a linear search for repeats, ring points in
// order of first use, then square centres in order of first use. Listed:
// the points that can move (ring points of a job with a facet), with their
// rows, and their ring neighbours (rows empty); the centres of squares with
// a corner that can move. Every field
// of every candidate must agree, in order: the warp's sums follow the rows'
// order, so the same content in another order would change output bytes.
// Models: data/3d files (octrees with and without the separating splits) and
// a block with a reflex slot (rows above RowBuilder's inline capacity come
// from the many small boxes at its edge).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "../plc/domain_fixtures.hpp"
#include "mv3d/octree_builder.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/read_domain.hpp"
#include "support/paths.hpp"
#include "tet3d/squares/box_faces.hpp"
#include "tet3d/boxes/box_jobs.hpp"
#include "tet3d/facet_boxes.hpp"
#include "tet3d/squares/square_cases.hpp"
#include "tet3d/warp/warp_candidates.hpp"

namespace pqmesh::tet3d {
namespace {

struct PlainCandidate {
  GridPoint p;
  std::vector<int> facets;
  std::vector<GridPoint> neighbours;
  std::vector<GridPoint> square_corners;
  std::int32_t level = -1;
  std::vector<std::pair<GridPoint, GridPoint>> box_edges;
};

template <class T>
void add_once(std::vector<T>& row, const T& x) {
  if (std::find(row.begin(), row.end(), x) == row.end()) row.push_back(x);
}

std::vector<PlainCandidate> plain_candidates(const OctTree& tree, const CornerSet& corners, const Domain3& domain,
                                             const std::vector<BoxJob>& jobs) {
  PointBook scratch;
  const SquareDispatcher faces_only(tree, corners, domain, scratch, nullptr);
  std::vector<PlainCandidate> rings, centres;
  std::map<GridPoint, std::size_t> ring_at, centre_at;
  std::set<GridPoint> movable;
  for (const BoxJob& j : jobs) {
    if (job_faces(faces_only, j).facets.empty()) continue;
    std::vector<FaceSquare> squares;
    job_squares(tree, corners, j, squares);
    for (const FaceSquare& s : squares)
      for (const GridPoint& p : square_ring(s, corners)) movable.insert(p);
  }
  const auto can_move = [&](const GridPoint& p) { return movable.count(p) != 0; };
  for (const BoxJob& j : jobs) {
    std::vector<FaceSquare> squares;
    job_squares(tree, corners, j, squares);
    const BoxFaces faces = job_faces(faces_only, j);
    const bool united = j.kind == BoxKind::Vertex;
    const std::int32_t level = tree.level(j.leaf) - (united ? 1 : 0);
    const BoxKey<3>& key = tree.key(j.leaf);
    const GridPoint lo = united ? united_lo(key, j.block) : key_corner(key, 0);
    GridPoint hi = lo;
    for (std::int64_t& x : hi.f) x += (united ? 2 : 1) * key.fine_side();
    for (const FaceSquare& s : squares) {
      const GridPoint c = s.centre();
      std::vector<GridPoint> square_corners;  // counterclockwise in (u, v) from s.lo
      for (const auto& [du, dv] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
        GridPoint q = s.lo;
        q.f[static_cast<std::size_t>(s.u)] += du * s.side;
        q.f[static_cast<std::size_t>(s.v)] += dv * s.side;
        square_corners.push_back(q);
      }
      if (std::any_of(square_corners.begin(), square_corners.end(), can_move)) {
        if (centre_at.emplace(c, centres.size()).second) {
          PlainCandidate pc;
          pc.p = c;
          pc.square_corners = square_corners;
          centres.push_back(pc);
        }
        for (const int f : faces.facets) add_once(centres[centre_at[c]].facets, f);
      }
      const std::vector<GridPoint> ring = square_ring(s, corners);
      const std::size_t n = ring.size();
      for (std::size_t i = 0; i < n; ++i) {
        const GridPoint& p = ring[i];
        if (!can_move(p) && !can_move(ring[(i + 1) % n]) && !can_move(ring[(i + n - 1) % n])) continue;
        if (ring_at.emplace(p, rings.size()).second) {
          PlainCandidate pc;
          pc.p = p;
          rings.push_back(pc);
        }
      }
      for (std::size_t i = 0; i < n; ++i) {
        const GridPoint& p = ring[i];
        if (!can_move(p)) continue;
        PlainCandidate& r = rings[ring_at[p]];
        r.level = std::max(r.level, level);
        for (const int f : faces.facets) add_once(r.facets, f);
        add_once(r.neighbours, ring[(i + 1) % ring.size()]);
        add_once(r.neighbours, ring[(i + ring.size() - 1) % ring.size()]);
        for (std::size_t a = 0; a < 3; ++a) {
          const std::size_t b = (a + 1) % 3, d = (a + 2) % 3;
          const bool on_edge = (p.f[b] == lo.f[b] || p.f[b] == hi.f[b]) && (p.f[d] == lo.f[d] || p.f[d] == hi.f[d]);
          if (!on_edge) continue;
          std::pair<GridPoint, GridPoint> e{p, p};
          e.first.f[a] = lo.f[a];
          e.second.f[a] = hi.f[a];
          add_once(r.box_edges, e);
        }
      }
    }
  }
  rings.insert(rings.end(), centres.begin(), centres.end());
  return rings;
}

struct Sizes {
  std::size_t candidates = 0, longest_neighbours = 0, longest_edges = 0;
};

// Compares both lists field by field; returns the sizes seen.
Sizes compare(const Domain3& d, const mv3d::OctreeOptions& opt, const std::string& what) {
  mv3d::OctreeBuilder b(d, opt);
  b.build();
  const BoxJobs jobs = box_jobs(b);
  const CornerSet corners(b);
  const std::vector<PlainCandidate> want = plain_candidates(b.tree(), corners, d, jobs.jobs);
  const WarpCandidates got = warp_candidates(b.tree(), corners, d, jobs.jobs);
  Sizes sizes;
  sizes.candidates = got.size();
  EXPECT_EQ(got.size(), want.size()) << what;
  if (got.size() != want.size()) return sizes;
  std::size_t centres = 0;
  for (std::size_t i = 0; i < want.size(); ++i) {
    const PlainCandidate& w = want[i];
    const WarpCandidate c = got[i];
    centres += w.square_corners.empty() ? 0 : 1;
    EXPECT_EQ(c.p, w.p) << what << " candidate " << i;
    EXPECT_EQ(c.level, w.level) << what << " candidate " << i;
    EXPECT_EQ(std::vector<int>(c.facets.begin(), c.facets.end()), w.facets) << what << " candidate " << i;
    EXPECT_EQ(std::vector<GridPoint>(c.neighbours.begin(), c.neighbours.end()), w.neighbours)
        << what << " candidate " << i;
    EXPECT_EQ(std::vector<GridPoint>(c.square_corners.begin(), c.square_corners.end()), w.square_corners)
        << what << " candidate " << i;
    std::vector<std::pair<GridPoint, GridPoint>> edges;
    for (const BoxEdgeSpan& e : c.box_edges) edges.push_back(e.ends(c.p));
    EXPECT_EQ(edges, w.box_edges) << what << " candidate " << i;
    if (::testing::Test::HasFailure()) return sizes;  // the first difference only
    sizes.longest_neighbours = std::max(sizes.longest_neighbours, w.neighbours.size());
    sizes.longest_edges = std::max(sizes.longest_edges, w.box_edges.size());
  }
  EXPECT_EQ(got.ring_count(), want.size() - centres) << what;
  std::printf("  %s: %zu candidates (%zu centres), longest rows: %zu neighbours, %zu box edges\n", what.c_str(),
              got.size(), centres, sizes.longest_neighbours, sizes.longest_edges);
  return sizes;
}

TEST(WarpCandidates, SameRowsInSameOrderAsPlainConstructionOnModels) {
  std::size_t longest_edges = 0;
  for (const char* model : {"cube.poly", "l_block.poly", "cube_through_hole.poly", "cube_cavity.poly",
                            "schoenhardt.poly", "star_vertex.poly", "wedge_5deg.poly"}) {
    const Domain3 d = make_domain(read_plc(test::data_path(std::string("3d/") + model)));
    // The separating splits multiply the boxes: on the smaller models only
    // (test time).
    const bool small = std::string(model) != "cube_through_hole.poly" && std::string(model) != "cube_cavity.poly";
    for (const bool separate : {false, true}) {
      if (separate && !small) continue;
      mv3d::OctreeOptions opt;
      opt.separate = separate;
      const Sizes s = compare(d, opt, std::string(model) + (separate ? " separated" : ""));
      EXPECT_GT(s.candidates, 0u) << model;
      longest_edges = std::max(longest_edges, s.longest_edges);
    }
  }
  // Some row exceeded the inline capacity (6), so the overflow path was
  // compared too.
  EXPECT_GT(longest_edges, 6u);
}

TEST(WarpCandidates, SameRowsOnReflexSlotBlock) {
  // A block with a thin V slot from its top (reflex edge at its bottom).
  const Plc3 plc = test::prism_xz(
      {{0.1, 0.1}, {0.9, 0.1}, {0.9, 0.9}, {0.53, 0.9}, {0.5, 0.37}, {0.47, 0.9}, {0.1, 0.9}}, 0.13, 0.83);
  const Sizes s = compare(make_domain(plc), mv3d::OctreeOptions{}, "slotted block");
  EXPECT_GT(s.candidates, 0u);
}

}  // namespace
}  // namespace pqmesh::tet3d
