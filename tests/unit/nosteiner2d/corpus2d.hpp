#pragma once
// Inputs shared by the nosteiner2d tests: the data/2d corpus and polygons
// given as loops of points.
#include <gtest/gtest.h>

#include <exception>
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

}  // namespace pqmesh::test
