#pragma once
// The executable's operator new (large_page_new.cpp) gives blocks of at least a
// threshold size 2 MiB-aligned memory marked MADV_HUGEPAGE; 4 MiB unless set here.
// Where memory comes from only: sizes, contents and output are unchanged.
#include <cstddef>

namespace pqmesh::cli {

// Call once, before the work whose blocks it should govern (no effect on platforms
// and builds without the large-page operator new).
void set_large_page_threshold(std::size_t bytes);

}  // namespace pqmesh::cli
