#pragma once
// Giving freed heap pages back to the system between the stages of box
// meshing (facet_boxes.cpp, worst_box_freeze.cpp). The candidate stage's
// free blocks (the square scratch and the hash nodes of the table passes are
// small blocks) stay in glibc's heap, and the stage after them allocates its
// tables as fresh mappings, so the freed pages would count twice in the peak
// (plate_holes without the trim: +3.4 MB). glibc only; elsewhere a no-op.
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace pqmesh::tet3d {

inline void release_free_heap() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace pqmesh::tet3d
