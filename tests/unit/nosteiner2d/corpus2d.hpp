#pragma once
// Inputs shared by the nosteiner2d tests: the data/2d corpus and polygons
// given as loops of points.
#include <gtest/gtest.h>

#include <cmath>
#include <exception>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/read_domain.hpp"
#include "support/paths.hpp"

namespace pqmesh::test {

// The data/2d inputs (data/2d/<name>.poly) the tests run on.
inline constexpr const char* kCorpus2d[] = {"square",      "l_shape",     "comb",         "spike_1deg",
                                            "spike_5deg",  "spike_10deg", "square_holes", "regions"};

// The domain of data/2d/<name>.poly.
inline Domain2 corpus_domain(const char* name) {
  return make_domain(read_pslg(data_path(std::string("2d/") + name + ".poly")));
}

// Calls f(domain, name) for each corpus input; an input that does not load is a test failure, skipped.
template <class F>
void for_each_corpus_domain(F&& f) {
  for (const char* name : kCorpus2d) {
    const std::string path = data_path(std::string("2d/") + name + ".poly");
    Domain2 d;
    try {
      d = make_domain(read_pslg(path));
    } catch (const std::exception& ex) {
      ADD_FAILURE() << path << ": " << ex.what();
      continue;
    }
    f(d, name);
  }
}

// The PSLG of counter-clockwise loops: each loop's points in order, closed by segments.
inline Pslg2 loops_pslg(const std::vector<std::vector<Vec2>>& loops) {
  Pslg2 p;
  for (const auto& loop : loops) {
    const int base = int(p.vertices.size()), n = int(loop.size());
    for (int i = 0; i < n; ++i) {
      p.vertices.push_back(loop[std::size_t(i)]);
      p.segments.push_back({base + i, base + (i + 1) % n});
    }
  }
  return p;
}

// Loops as a validated domain.
inline Domain2 loops_domain(const std::vector<std::vector<Vec2>>& loops) { return make_domain(loops_pslg(loops)); }

// One counter-clockwise loop as a validated domain.
inline Domain2 polygon(const std::vector<Vec2>& pts) { return loops_domain({pts}); }

// The regular n-gon on the unit circle, vertex i at angle 2 pi i / n (rounded
// cos / sin, as bench/nosteiner_polys.py writes it).
inline Domain2 regular_ngon(int n) {
  std::vector<Vec2> pts;
  for (int i = 0; i < n; ++i)
    pts.push_back({std::cos(2 * std::numbers::pi * i / n), std::sin(2 * std::numbers::pi * i / n)});
  return polygon(pts);
}

struct NamedDomain {
  std::string name;
  Domain2 domain;
};

// Hand-made hard cases (dyadic coordinates unless said otherwise).
inline std::vector<NamedDomain> hard_case_domains() {
  std::vector<NamedDomain> out;
  // Thesis Fig. 1.1: a thin trapezoid whose long edge faces close vertices.
  for (double t : {1.0 / 64, 1.0 / 1024})
    out.push_back({"fig1.1 trapezoid t=" + std::to_string(t), polygon({{0, 0}, {1, 0}, {0.5625, t}, {0.4375, t}})});
  // A reflex vertex very close to the middle of a long edge (the notch).
  for (double y : {1.0 / 128, 1.0 / 4096})
    out.push_back({"reflex notch y=" + std::to_string(y),
                   polygon({{0, 0}, {1, 0}, {1, 1}, {0.625, 1}, {0.484375, y}, {0.375, 1}, {0, 1}})});
  // A comb with narrow slots: 8 teeth of width 1/16, slots 1/512 wide, 1/2 deep.
  {
    std::vector<Vec2> c = {{0, 0}, {1, 0}};
    const double tooth = 1.0 / 16, slot = 1.0 / 512;
    double x = 1;
    c.push_back({1, 1});
    for (int i = 0; i < 8; ++i) {
      x -= tooth;
      if (i == 7) break;
      c.push_back({x, 1});
      c.push_back({x, 0.5});
      x -= slot;
      c.push_back({x, 0.5});
      c.push_back({x, 1});
    }
    c.push_back({x, 1});
    c.push_back({0, 1});
    out.push_back({"comb narrow slots", polygon(c)});
  }
  // Small-angle spikes: a star of 12 spikes with tips at radius 1 and
  // valleys at 1/4 (tip angles ~6 deg), plus one 0.5-degree spike.
  {
    std::vector<Vec2> s;
    for (int i = 0; i < 24; ++i) {
      const double a = std::numbers::pi * i / 12, r = i % 2 == 0 ? 1.0 : 0.25;
      s.push_back({std::ldexp(std::round(std::ldexp(r * std::cos(a), 30)), -30),
                   std::ldexp(std::round(std::ldexp(r * std::sin(a), 30)), -30)});
    }
    out.push_back({"star 12 spikes", polygon(s)});
    const double h = std::tan(0.25 * std::numbers::pi / 180);
    out.push_back({"spike 0.5 deg", polygon({{0, -h}, {1, 0}, {0, h}, {-0.5, 0.5}, {-0.5, -0.5}})});
  }
  // Many holes: an 8 x 8 grid of square holes (64 holes) in the unit square.
  {
    std::vector<std::vector<Vec2>> loops = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j) {
        const double x = (i + 0.25) / 8, y = (j + 0.25) / 8, w = 0.5 / 8;
        loops.push_back({{x, y}, {x, y + w}, {x + w, y + w}, {x + w, y}});
      }
    Pslg2 p = loops_pslg(loops);
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j) p.holes.push_back({(i + 0.5) / 8, (j + 0.5) / 8});
    out.push_back({"64 square holes", make_domain(p)});
  }
  out.push_back({"regular 1000-gon", regular_ngon(1000)});  // rounded cos/sin; make_domain validates it
  return out;
}

}  // namespace pqmesh::test
