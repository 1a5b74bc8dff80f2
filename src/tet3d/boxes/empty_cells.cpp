#include "tet3d/boxes/empty_cells.hpp"

namespace pqmesh::tet3d {

EmptyCells::EmptyCells(const OctTree& tree, std::span<const BoxJob> jobs) {
  for (const BoxJob& j : jobs) {
    if (j.kind != BoxKind::Empty) continue;
    const BoxKey<3>& key = tree.key(j.leaf);
    if (index_.insert(key_centre(key)).second) levels_.push_back(key.level);
  }
}

}  // namespace pqmesh::tet3d
