// The spoke floor (spoke_floor.hpp): a practical deviation from the thesis's
// smallest spirals, documented in docs/algorithm/nosteiner2d.md "Welding and
// the polygon Q".
//
// Why the floored part stays empty: a floored spoke has length
// kSpokeFloorFraction * delta_P(V) < delta_P(V); a wedge triangle between two
// floored spokes has apex <= pi/2 < pi, so it lies in the disk of radius
// delta_P(V) around V and in V's interior sector, where only the two sides at
// V reach. The triangle between the last spoke on the spiral and the first
// floored one is not covered by this argument; the assembly's exact check
// (check_mesh, `verify`) is what guarantees validity, and the tests run it.
#include "nosteiner2d/spoke_floor.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace pqmesh::detail {

int floor_spokes(VertexWedge& w, double log_floor) {
  auto& sp = w.spokes;
  const int n = static_cast<int>(sp.size());
  std::vector<char> raised(std::size_t(n), 0);
  int count = 0;
  for (int i = 0; i < n; ++i)
    if (sp[std::size_t(i)].log_rho < log_floor) {
      sp[std::size_t(i)].log_rho = log_floor;
      raised[std::size_t(i)] = 1;
      ++count;
    }
  if (count == 0) return 0;
  std::vector<WedgeSpoke> out;
  bool respaced = false;
  for (int i = 0; i < n;) {
    if (!raised[std::size_t(i)]) {
      out.push_back(sp[std::size_t(i)]);
      ++i;
      continue;
    }
    int j = i;
    while (j + 1 < n && raised[std::size_t(j + 1)]) ++j;
    // Run i..j on the floor circle: keep its ends, re-space the inside.
    const double a = sp[std::size_t(i)].phi, b = sp[std::size_t(j)].phi;
    // k <= j - i: the new step (b - a) / k is at least the mean, hence at least
    // the smallest, of the old steps in the run, and at most max(pi/3, the
    // largest old step) <= pi/2 (Theorem 16's bound holds for every old step).
    const int k = std::max(1, std::min(j - i, static_cast<int>(std::ceil((b - a) / (std::numbers::pi / 3)))));
    if (j > i && k != j - i) respaced = true;
    out.push_back(sp[std::size_t(i)]);
    if (j > i) {
      for (int s = 1; s < k; ++s) out.push_back({a + (b - a) * s / k, log_floor, {}});
      out.push_back(sp[std::size_t(j)]);
    }
    i = j + 1;
  }
  if (respaced) w.thirds_first = -1;
  sp = std::move(out);
  return count;
}

}  // namespace pqmesh::detail
