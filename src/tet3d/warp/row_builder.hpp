#pragma once
// RowBuilder: rows of small sets of values by id, kept in order of first
// insertion, built one insertion at a time and then packed into row starts
// and values (the warp candidates' neighbour and box-edge rows,
// warp_candidates.hpp).
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace pqmesh::tet3d {

// Rows (sets kept in order of first insertion) of values by id, built one
// insertion at a time: N values inline per id, the rest of a longer row in a
// map (rare: plate_holes has no neighbour row above 6 and 1% of box-edge
// rows above 6). Repeats are found by a linear scan of the row.
template <class V, std::size_t N>
class RowBuilder {
 public:
  void add_id() { rows_.emplace_back(); }
  void add(std::int32_t id, const V& v) {
    Row& r = rows_[static_cast<std::size_t>(id)];
    V* const end = r.v.data() + r.n;
    if (std::find(r.v.data(), end, v) != end) return;
    if (r.n < N) {
      r.v[r.n++] = v;
      return;
    }
    std::vector<V>& more = overflow_[id];
    if (std::find(more.begin(), more.end(), v) == more.end()) more.push_back(v);
  }
  // Rows of ids 0 .. n - 1 (ids never added: empty) as row starts (n + 1)
  // and values; the builder is empty afterwards.
  void finish(std::size_t n, std::vector<std::uint32_t>& start, std::vector<V>& values) {
    start.assign(n + 1, 0);
    std::size_t total = 0;
    for (std::size_t i = 0; i < rows_.size(); ++i) total += rows_[i].n;
    for (const auto& [id, more] : overflow_) total += more.size();
    values.clear();
    values.reserve(total);
    for (std::size_t i = 0; i < n; ++i) {
      if (i < rows_.size()) {
        const Row& r = rows_[i];
        values.insert(values.end(), r.v.begin(), r.v.begin() + r.n);
        if (r.n == N)
          if (const auto it = overflow_.find(static_cast<std::int32_t>(i)); it != overflow_.end())
            values.insert(values.end(), it->second.begin(), it->second.end());
      }
      start[i + 1] = static_cast<std::uint32_t>(values.size());
    }
    std::vector<Row>().swap(rows_);
    overflow_.clear();
  }

 private:
  struct Row {
    std::array<V, N> v{};
    std::uint8_t n = 0;
  };
  std::vector<Row> rows_;
  std::unordered_map<std::int32_t, std::vector<V>> overflow_;
};

}  // namespace pqmesh::tet3d
