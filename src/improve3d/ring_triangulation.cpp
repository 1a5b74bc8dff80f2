#include "improve3d/ring_triangulation.hpp"

#include <algorithm>
#include <limits>

namespace pqmesh::improve3d::detail {

namespace {

constexpr double kForbidden = -std::numeric_limits<double>::infinity();

struct Table {
  double best[kMaxRingVertices][kMaxRingVertices];
  int apex[kMaxRingVertices][kMaxRingVertices];
};

void collect(const Table& table, int i, int j, std::vector<std::array<int, 3>>& triangles) {
  if (j - i < 2) return;
  const int k = table.apex[i][j];
  collect(table, i, k, triangles);
  triangles.push_back({i, k, j});
  collect(table, k, j, triangles);
}

}  // namespace

double best_ring_triangulation(const RingScores& scores, std::vector<std::array<int, 3>>& triangles) {
  const int m = scores.size();
  Table table;
  for (int i = 0; i + 1 < m; ++i) table.best[i][i + 1] = std::numeric_limits<double>::infinity();
  for (int span = 2; span < m; ++span)
    for (int i = 0; i + span < m; ++i) {
      const int j = i + span;
      table.best[i][j] = kForbidden;
      table.apex[i][j] = -1;
      for (int k = i + 1; k < j; ++k) {
        const double value = std::min({table.best[i][k], table.best[k][j], scores.at(i, k, j)});
        if (value > table.best[i][j]) {
          table.best[i][j] = value;
          table.apex[i][j] = k;
        }
      }
    }
  triangles.clear();
  if (table.best[0][m - 1] == kForbidden) return kForbidden;
  collect(table, 0, m - 1, triangles);
  return table.best[0][m - 1];
}

}  // namespace pqmesh::improve3d::detail
