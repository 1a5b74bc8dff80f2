// Explicit instantiations: the quadtree and the octree compile as part of pqmesh_tree
// (the template itself is header-only, tree/tree.hpp).
#include "tree/tree.hpp"

namespace pqmesh {

template class Tree<2>;
template class Tree<3>;
template RootCube<2> choose_root_cube<2>(const std::array<double, 2>&, const std::array<double, 2>&, double);
template RootCube<3> choose_root_cube<3>(const std::array<double, 3>&, const std::array<double, 3>&, double);

}  // namespace pqmesh
