#pragma once
// Which united vertex boxes (thesis §4.1.3: the 2x2x2 block of the vertex
// leaf's size around the grid corner nearest the vertex) would overlap, on
// the integer grid of tree/key.hpp (exact).
//
// The thesis's extended box (margin 2, 5 times the side) keeps two vertices
// of one component far enough apart that their united boxes are disjoint.
// With margin 1 (OctreeOptions::extended_margin, the lighter octree) two
// vertices may end two leaves apart and their blocks share a leaf, which the
// two vertex jobs would both mesh (an invalid mesh). The octree builder splits
// the leaves of such pairs before centering (octree_builder.cpp,
// separate_united_boxes).
// Cost: O(n log n + k) for n blocks, k pairs whose x extents overlap.
#include <array>
#include <cstdint>
#include <vector>

#include "tree/key.hpp"

namespace pqmesh::mv3d {

struct GridBlock {
  std::array<std::int64_t, 3> lo{}, hi{};
};

// The united block of a vertex in the leaf of key `k`: bit a of `below` set
// when it extends one leaf side below the leaf along axis a (else above).
GridBlock united_grid_block(const BoxKey<3>& k, unsigned below);

// Whether the open box of key k meets the open block.
bool meets_block(const BoxKey<3>& k, const GridBlock& block);

// Indices of the blocks whose open interiors meet another block's (each once,
// ascending).
std::vector<std::size_t> overlapping_blocks(const std::vector<GridBlock>& blocks);

}  // namespace pqmesh::mv3d
