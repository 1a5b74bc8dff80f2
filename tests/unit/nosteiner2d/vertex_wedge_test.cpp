// Welding the two smallest optimal spirals at a vertex (thesis §5.1.1,
// Figs. 5.8-5.10): structural properties the construction must have, on the
// corpus and random polygons, and the measured ratio of the wedge's min angle
// to g(P) (printed; the thesis proves it bounded below by a constant but
// gives none, and the edge rotations of §5.1.1 are not built yet).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>

#include "pqmesh/domain.hpp"
#include "nosteiner2d/stages.hpp"
#include "pqmesh/read_domain.hpp"
#include "support/paths.hpp"
#include "support/random_domains.hpp"
#include "corpus2d.hpp"

namespace pqmesh {
namespace {

struct Stats {
  double min_ratio = 1e300;
  double min_log_rho = 0;   // smallest ln(rho / L(E)) over all spokes
  double max_x_excess = 0;  // largest ln(rho_X' / envelope) after the small-side fix
  int unrepresentable = 0, wedges = 0, fixed = 0, max_spokes = 0;
};

void check_wedges(const Domain2& d, const std::string& what, Stats& st) {
  SCOPED_TRACE(what);
  const SteinerFreeBound b = steiner_free_bound(d);
  for (std::size_t i = 0; i + 1 < b.spirals.size(); i += 2) {
    const EmptySpiral& sn = b.spirals[i];      // (V, V -> next)
    const EmptySpiral& sp = b.spirals[i + 1];  // (V, V -> prev)
    ASSERT_TRUE(sn.ccw && !sp.ccw && sn.vertex == sp.vertex);
    const VertexWedge w = vertex_wedge(d, sn, sp);
    ++st.wedges;
    st.fixed += w.small_side_fixed;
    st.unrepresentable += !w.representable;
    st.max_spokes = std::max(st.max_spokes, static_cast<int>(w.spokes.size()));
    ASSERT_GE(w.spokes.size(), 2u);
    // The wedge covers the corner: from E (phi = 0) to F (phi = alpha), phi increasing.
    EXPECT_EQ(w.spokes.front().phi, 0.0);
    EXPECT_NEAR(w.spokes.back().phi, sn.alpha, 1e-12);
    for (std::size_t k = 1; k < w.spokes.size(); ++k) EXPECT_LT(w.spokes[k - 1].phi, w.spokes[k].phi);
    // First / last spokes: a quarter of the kept edge (§5.1 smallest spiral).
    if (w.kept != VertexWedge::Kept::PrevOnly) {
      EXPECT_NEAR(w.spokes.front().log_rho, std::log(sn.length / 4), 1e-12);
    }
    if (w.kept != VertexWedge::Kept::NextOnly) {
      EXPECT_NEAR(w.spokes.back().log_rho, std::log(sp.length / 4), 1e-12);
    }
    // Every spoke vertex of S' and T' lies inside or on the outer envelope of
    // the two smallest spirals; the two spokes of Fig. 5.10 have X's length.
    auto envelope = [&](double phi) {
      return std::max(std::log(sn.length / 4) + phi * 4 * sn.log_shrink,
                      std::log(sp.length / 4) + (sn.alpha - phi) * 4 * sp.log_shrink);
    };
    if (w.kept == VertexWedge::Kept::Both) {
      // Measured, not asserted: the thesis says the fix keeps the spirals
      // inside S and T, but the moved X' can lie slightly outside the
      // envelope (the line ZX leaves the log spiral S beyond X).
      EXPECT_TRUE(std::isfinite(w.log_rho_x_moved));
      st.max_x_excess = std::max(st.max_x_excess, w.log_rho_x_moved - envelope(w.phi_x_moved));
      ASSERT_GE(w.thirds_first, 1);
      EXPECT_EQ(w.spokes[w.thirds_first].log_rho, w.log_rho_x_moved);
      EXPECT_EQ(w.spokes[w.thirds_first + 1].log_rho, w.log_rho_x_moved);
    }
    for (int k = 0; k < static_cast<int>(w.spokes.size()); ++k) {
      const WedgeSpoke& s = w.spokes[k];
      st.min_log_rho = std::min(st.min_log_rho, s.log_rho - std::log(std::max(sn.length, sp.length)));
      if (w.kept == VertexWedge::Kept::Both && (k == w.thirds_first || k == w.thirds_first + 1)) continue;
      EXPECT_LE(s.log_rho, envelope(s.phi) + 1e-9 * (1 + std::abs(s.log_rho)))
          << "vertex " << w.vertex << " fixed " << w.small_side_fixed << " kept " << static_cast<int>(w.kept) << " phi "
          << s.phi << " phi_x " << w.phi_x;
    }
    // Where both are kept, they meet at X: equal radii there.
    if (w.kept == VertexWedge::Kept::Both) {
      const double ls = std::log(sn.length / 4) + w.phi_x * 4 * sn.log_shrink;
      const double lt = std::log(sp.length / 4) + (sn.alpha - w.phi_x) * 4 * sp.log_shrink;
      EXPECT_NEAR(ls, lt, 1e-9 * (1 + std::abs(ls)));
    }
    EXPECT_GT(w.min_angle, 0.0);
    st.min_ratio = std::min(st.min_ratio, w.min_angle / b.g);
  }
}

void print(const Stats& st, const char* what) {
  std::cout << "[vertex wedges] " << what << ": " << st.wedges << " wedges, min(wedge min angle / g) = " << st.min_ratio
            << ", small-side fixes " << st.fixed << ", max spokes " << st.max_spokes << ", smallest ln(rho/L) "
            << st.min_log_rho << ", unrepresentable " << st.unrepresentable << ", max ln(rho_X'/envelope) "
            << st.max_x_excess << "\n";
}

TEST(VertexWedge, Corpus) {
  Stats st;
  for (const char* name : test::kCorpus2d)
    check_wedges(test::corpus_domain(name), name, st);
  print(st, "data/2d");
}

TEST(VertexWedge, RandomPolygonsWithHoles) {
  Stats st;
  for (std::uint64_t seed = 1; seed <= 300; ++seed)
    check_wedges(make_domain(test::random_polygon_with_holes(seed)), test::describe_polygon(seed), st);
  print(st, "300 random polygons");
}

}  // namespace
}  // namespace pqmesh
