#pragma once
// The executable's operator new (large_page_new.cpp) gives blocks of at least a
// threshold size 2 MiB-aligned memory marked MADV_HUGEPAGE; 4 MiB unless set here.
// Where memory comes from only: sizes, contents and output are unchanged.
#include <cstddef>

namespace pqmesh::cli {

// Call once, before the work whose blocks it should govern (no effect on platforms
// and builds without the large-page operator new).
void set_large_page_threshold(std::size_t bytes);

// From now on the malloc heap (the small blocks: node lists, GMP limbs, hash
// tables under the threshold) grows in steps of 16 MiB and every part of it
// added later is marked MADV_HUGEPAGE, as glibc's malloc does under the tunable
// glibc.malloc.hugetlb=1. Call once, before the work (no effect where the
// large-page operator new is not built).
void grow_heap_in_huge_pages();

}  // namespace pqmesh::cli
