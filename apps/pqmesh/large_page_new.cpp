// The pqmesh executable's global operator new: every block of 4 MiB or more (1 MiB in
// 2D meshing, large_page_new.hpp)
// (the meshes' vertex and triangle arrays, the triangulation's triangles, the
// checker's tables, the .vtu quality fields, ...) comes from 2 MiB-aligned
// memory marked MADV_HUGEPAGE, as geometry/large_page_allocator.hpp does for
// the library's own big tables. With transparent huge pages in "madvise"
// mode the kernel then backs such a block by 2 MiB pages: one page fault
// instead of 512 when it is first written, and far fewer TLB misses on the
// random accesses of point location, flips and edge matching. This reaches
// the arrays whose types are public (std::vector with the standard
// allocator), which the library cannot give an allocator of its own.
//
// Only where memory comes from changes: sizes, contents and the order of
// everything the program does are those of the default operator new, so the
// output is the same byte for byte. Blocks are released with free() either
// way (aligned_alloc memory is free()d like malloc memory); with the mmap
// threshold set in cmd_mesh.cpp a large block is its own mapping, returned
// to the system when freed. Other platforms, and sanitizer builds (whose
// runtimes check new/delete pairing through their own operator new): the
// default operator new.
//
// The 3D mesher also has the heap of small blocks grow in huge pages
// (grow_heap_in_huge_pages): its octree data, GMP limbs and box lists are
// blocks under the threshold, and they caused most of its page faults.
#include <cstddef>
#include <cstdlib>
#include <new>

#include "large_page_new.hpp"

#if defined(__linux__) && defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)  // (__GLIBC__: headers above)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>

namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;
// Blocks of large_threshold bytes or more get huge pages. The default is the
// threshold of LargePageAllocator. Lower ones (1 or 3 MiB: the per-vertex tables
// of 3.4 MB on the plate of docs/algorithm/quad2d.md "Speed and memory") raised
// the 2D peak by 18 MB while the quadtree's nodes lived in the malloc heap
// (later arrays were served from the freed tree's heap space); since the nodes
// are in slabs of their own (tree/chunked_vector.hpp) the 2D mesher sets 1 MiB
// (cmd_mesh.cpp). Set once, before the work starts.
std::size_t large_threshold = std::size_t{4} << 20;

// The heap (grow_heap_in_huge_pages): malloc extends it by at least
// kHeapStep at a time, and heap_marked_to is the break up to which it is marked
// MADV_HUGEPAGE (0: off). The kernel backs a 2 MiB page of a marked range by a
// huge page if nothing in it was touched before the marking; growth is seen at
// the next operator new, after malloc wrote the block that caused it, so each
// step loses a page or two of its 16. Blocks GMP allocates between two calls of
// operator new only delay the marking. (The executable runs one thread.)
constexpr std::size_t kHeapStep = std::size_t{16} << 20;
std::uintptr_t heap_marked_to = 0;

void mark_heap_growth() {
  const auto brk = reinterpret_cast<std::uintptr_t>(sbrk(0));  // glibc: the cached break, no system call
  if (brk > heap_marked_to) {
    const std::uintptr_t page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
    const std::uintptr_t from = heap_marked_to / page * page;
#if defined(MADV_HUGEPAGE)
    madvise(reinterpret_cast<void*>(from), brk - from, MADV_HUGEPAGE);  // a hint: failure only costs speed
#endif
  }
  heap_marked_to = brk;  // after a trim too, so that the regrown part is marked again
}

void* try_allocate(std::size_t n) {
  if (n < large_threshold) {
    void* p = std::malloc(n == 0 ? 1 : n);
    if (heap_marked_to != 0) mark_heap_growth();
    return p;
  }
  const std::size_t rounded = (n + kHugePage - 1) / kHugePage * kHugePage;
  void* p = std::aligned_alloc(kHugePage, rounded);
#if defined(MADV_HUGEPAGE)
  if (p != nullptr) madvise(p, rounded, MADV_HUGEPAGE);  // a hint: failure only costs speed
#endif
  return p;
}

// [new.delete.single]: on failure call the new-handler until there is none.
void* allocate(std::size_t n) {
  for (;;) {
    if (void* p = try_allocate(n)) return p;
    const std::new_handler handler = std::get_new_handler();
    if (handler == nullptr) throw std::bad_alloc();
    handler();
  }
}

}  // namespace

void pqmesh::cli::set_large_page_threshold(std::size_t bytes) { large_threshold = bytes; }

void pqmesh::cli::grow_heap_in_huge_pages() {
  mallopt(M_TOP_PAD, static_cast<int>(kHeapStep));
  heap_marked_to = reinterpret_cast<std::uintptr_t>(sbrk(0));
}

void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

#else

void pqmesh::cli::set_large_page_threshold(std::size_t /*bytes*/) {}
void pqmesh::cli::grow_heap_in_huge_pages() {}

#endif
