#include "tet3d/warp/warp_journal.hpp"

#include <limits>

#include "pqmesh/errors.hpp"

namespace pqmesh::tet3d {

WarpCounts warp_counts(const WarpTable& table) {
  WarpCounts out{};
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = table.*WarpTable::kCounts[k];
  return out;
}

void record_point(std::uint32_t point, const WarpCandidate& c, const WarpCounts& before, std::size_t copies_before,
                  const WarpTable& table, WarpJournal& journal) {
  for (std::size_t k = 0; k < before.size(); ++k) {
    const std::int64_t delta = table.*WarpTable::kCounts[k] - before[k];
    if (delta == 0) continue;
    if (delta > std::numeric_limits<std::int16_t>::max() || delta < std::numeric_limits<std::int16_t>::min())
      throw InternalError("tet3d: a warp count changed by more than a journal row holds");
    journal.counts.push_back({point, static_cast<std::uint16_t>(k), static_cast<std::int16_t>(delta)});
  }
  if (table.copy_count() == copies_before) return;
  std::size_t found = 0;
  for (const int f : c.facets)
    if (const Vec3* at = table.find_copy(c.p, f)) {
      journal.copies.push_back({point, f, *at});
      ++found;
    }
  if (copies_before + found != table.copy_count())
    throw InternalError("tet3d: a Fig. 4.7 copy keyed by a facet outside its point's boxes");
}

void JournalCursor::replay(std::uint32_t point, const WarpCandidate& c, WarpTable& table, WarpJournal& out) {
  while (count_ < j_.counts.size() && j_.counts[count_].point < point) ++count_;
  for (; count_ < j_.counts.size() && j_.counts[count_].point == point; ++count_) {
    const WarpJournal::Count& row = j_.counts[count_];
    table.*WarpTable::kCounts[row.count] += row.delta;
    out.counts.push_back(row);
  }
  while (copy_ < j_.copies.size() && j_.copies[copy_].point < point) ++copy_;
  for (; copy_ < j_.copies.size() && j_.copies[copy_].point == point; ++copy_) {
    const WarpJournal::Copy& row = j_.copies[copy_];
    table.insert_copy(c.p, row.facet, row.at);
    out.copies.push_back(row);
  }
}

bool JournalCursor::same_copies(std::uint32_t point, const WarpJournal& out) {
  while (copy_ < j_.copies.size() && j_.copies[copy_].point < point) ++copy_;
  std::size_t first_new = out.copies.size();
  while (first_new > 0 && out.copies[first_new - 1].point == point) --first_new;
  bool same = true;
  std::size_t k = first_new;
  for (; copy_ < j_.copies.size() && j_.copies[copy_].point == point; ++copy_, ++k) {
    const WarpJournal::Copy& a = j_.copies[copy_];
    same = same && k < out.copies.size() && out.copies[k].facet == a.facet && out.copies[k].at == a.at;
  }
  return same && k == out.copies.size();
}

}  // namespace pqmesh::tet3d
