#pragma once
// The per-point record of a warp table build (warp.hpp WarpJournal): what
// one ring point added to the table besides its entry, written after the
// point is decided and read back when a rebuild keeps the point's outcome.
#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>

#include "tet3d/warp/warp.hpp"

namespace pqmesh::tet3d {

using WarpCounts = std::array<std::int64_t, std::size(WarpTable::kCounts)>;

WarpCounts warp_counts(const WarpTable& table);

// Appends to `journal` what ring point `point` (candidate c) added to
// `table` since `before` and `copies_before`: its counts and Fig. 4.7
// copies. Throws InternalError if a count changed by more than an int16
// holds or a copy is keyed by a facet outside c's (neither happens: a point
// adds a few counts and copies only for its slot's facets).
void record_point(std::uint32_t point, const WarpCandidate& c, const WarpCounts& before, std::size_t copies_before,
                  const WarpTable& table, WarpJournal& journal);

// A journal read in candidate order: the rows of one point at a time.
class JournalCursor {
 public:
  explicit JournalCursor(const WarpJournal& j) : j_(j) {}
  // Adds point `point`'s counts and copies (candidate c) from the old
  // journal to `table` and appends them to `out`.
  void replay(std::uint32_t point, const WarpCandidate& c, WarpTable& table, WarpJournal& out);
  // Whether the copies `out` recorded for `point` (its last rows) are the
  // old journal's for it; skips the old rows.
  bool same_copies(std::uint32_t point, const WarpJournal& out);

 private:
  const WarpJournal& j_;
  std::size_t count_ = 0, copy_ = 0;
};

}  // namespace pqmesh::tet3d
