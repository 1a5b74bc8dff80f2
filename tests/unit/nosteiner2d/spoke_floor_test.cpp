// The spoke floor (src/nosteiner2d/spoke_floor.hpp,
// docs/algorithm/nosteiner2d.md "Spoke floor"): a hand case derived below, and
// on the corpus and the random polygons, applied to every welded vertex wedge
// with the floor polygon_q uses (kSpokeFloorFraction delta_P(V)): every spoke
// reaches the floor, the first and last angles are kept, steps stay in (0,
// pi/2], and the wedge's min angle does not decrease.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>

#include "nosteiner2d/spoke_floor.hpp"
#include "pqmesh/domain.hpp"
#include "nosteiner2d/stages.hpp"
#include "pqmesh/read_domain.hpp"
#include "support/paths.hpp"
#include "support/random_domains.hpp"
#include "corpus2d.hpp"

namespace pqmesh {
namespace {

constexpr double kPi = std::numbers::pi;

// Smallest angle of the triangle (V, p, q) from polar data: sides 1 and
// a = rho_q / rho_p around the apex angle delta (law of cosines/sines).
double polar_min_angle(const WedgeSpoke& p, const WedgeSpoke& q) {
  const double delta = q.phi - p.phi;
  const double a = std::exp(q.log_rho - p.log_rho);
  const double at_p = std::atan2(a * std::sin(delta), 1 - a * std::cos(delta));
  return std::min({delta, at_p, kPi - delta - at_p});
}

double wedge_min_angle(const VertexWedge& w) {
  double m = kPi;
  for (std::size_t k = 1; k < w.spokes.size(); ++k) m = std::min(m, polar_min_angle(w.spokes[k - 1], w.spokes[k]));
  return m;
}

// 21 spokes at phi = i/10 with ln rho = -i (ratio 1/e per step); floor -5.5.
// Spokes 6..20 (ln rho -6..-20) are below it: 15 raised. Their run spans
// phi 0.6..2.0 = 1.4 rad; ceil(1.4 / (pi/3)) = 2 <= 14 old steps, so the run
// becomes 0.6, 1.3, 2.0: 6 + 3 = 9 spokes.
TEST(SpokeFloor, HandSpiral) {
  VertexWedge w;
  w.thirds_first = 10;
  for (int i = 0; i <= 20; ++i) w.spokes.push_back({i / 10.0, -double(i), {}});
  const double before = wedge_min_angle(w);
  EXPECT_EQ(detail::floor_spokes(w, -5.5), 15);
  ASSERT_EQ(w.spokes.size(), 9u);
  for (int i = 0; i <= 5; ++i) {
    EXPECT_EQ(w.spokes[std::size_t(i)].phi, i / 10.0);
    EXPECT_EQ(w.spokes[std::size_t(i)].log_rho, -double(i));
  }
  EXPECT_EQ(w.spokes[6].phi, 0.6);
  EXPECT_NEAR(w.spokes[7].phi, 1.3, 1e-15);
  EXPECT_EQ(w.spokes[8].phi, 2.0);
  for (std::size_t i = 6; i < 9; ++i) EXPECT_EQ(w.spokes[i].log_rho, -5.5);
  EXPECT_EQ(w.thirds_first, -1);
  // Old worst: apex 0.1 with ratio 1/e; new worst: the same triangle shape
  // before the floor (spokes 4-5), the floor triangles are isosceles with apex 0.7.
  EXPECT_GE(wedge_min_angle(w), before);
  // Nothing below the floor: no change at all.
  const VertexWedge copy = w;
  EXPECT_EQ(detail::floor_spokes(w, -100), 0);
  ASSERT_EQ(w.spokes.size(), copy.spokes.size());
  EXPECT_EQ(w.thirds_first, -1);
}

// A single spoke below the floor is raised but no spoke is added or removed.
TEST(SpokeFloor, SingleSpokeRaised) {
  VertexWedge w;
  w.thirds_first = 1;
  w.spokes = {{0, 0, {}}, {0.5, -1, {}}, {1.0, -3, {}}, {1.5, -1, {}}, {2.0, 0, {}}};
  EXPECT_EQ(detail::floor_spokes(w, -2), 1);
  ASSERT_EQ(w.spokes.size(), 5u);
  EXPECT_EQ(w.spokes[2].log_rho, -2);
  EXPECT_EQ(w.spokes[2].phi, 1.0);
  EXPECT_EQ(w.thirds_first, 1);
}

struct Stats {
  int wedges = 0, floored = 0, raised = 0;
  double min_gain = 1e300;  // new min angle / old, over floored wedges
};

void check_domain(const Domain2& d, Stats& st) {
  const SteinerFreeBound b = steiner_free_bound(d, {.sides_at_far_end = true});
  std::vector<std::vector<Vec2>> loops;
  for (const auto& loop : d.loops) {
    loops.emplace_back();
    for (int v : loop) loops.back().push_back(d.pslg.vertices[std::size_t(v)]);
  }
  const PolygonDelta delta = polygon_delta(loops);
  std::size_t i = 0;
  for (std::size_t l = 0; l < d.loops.size(); ++l)
    for (std::size_t k = 0; k < d.loops[l].size(); ++k, i += 2) {
      VertexWedge w = vertex_wedge(d, b.spirals[i], b.spirals[i + 1]);
      const double before = wedge_min_angle(w), first = w.spokes.front().phi, last = w.spokes.back().phi;
      const double log_floor = std::log(detail::kSpokeFloorFraction * delta.vertex[l][k]);
      ASSERT_LT(log_floor, std::log(delta.vertex[l][k]));
      const int raised = detail::floor_spokes(w, log_floor);
      ++st.wedges;
      EXPECT_EQ(w.spokes.front().phi, first);
      EXPECT_EQ(w.spokes.back().phi, last);
      for (std::size_t s = 0; s < w.spokes.size(); ++s) {
        EXPECT_GE(w.spokes[s].log_rho, log_floor);
        if (s > 0) {
          EXPECT_GT(w.spokes[s].phi, w.spokes[s - 1].phi);
          EXPECT_LE(w.spokes[s].phi - w.spokes[s - 1].phi, kPi / 2 * (1 + 1e-12));
        }
      }
      if (raised > 0) {
        ++st.floored;
        st.raised += raised;
        const double after = wedge_min_angle(w);
        EXPECT_GE(after, before * (1 - 1e-9));
        st.min_gain = std::min(st.min_gain, after / before);
      }
    }
}

TEST(SpokeFloor, CorpusAndRandomPolygons) {
  Stats st;
  for (const char* name : test::kCorpus2d)
    check_domain(test::corpus_domain(name), st);
  for (std::uint64_t seed = 1; seed <= 300; ++seed) check_domain(make_domain(test::random_polygon_with_holes(seed)), st);
  std::cout << "[spoke floor] " << st.wedges << " wedges, " << st.floored << " floored (" << st.raised
            << " spokes raised), min(new / old wedge min angle) " << st.min_gain << "\n";
  EXPECT_GT(st.floored, 0);  // the random polygons do reach the floor (the point of it)
}

}  // namespace
}  // namespace pqmesh
