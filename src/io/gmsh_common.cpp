#include "io/gmsh_common.hpp"

#include <cstdint>

namespace pqmesh::detail::gmsh {

std::vector<std::size_t> order_by_entity(const PhysicalGroups& groups, const std::vector<int>& markers,
                                         std::size_t count, std::vector<std::size_t>& block_sizes) {
  block_sizes.assign(groups.markers.size(), 0);
  std::vector<int> entity(count);
  for (std::size_t i = 0; i < count; ++i) {
    entity[i] = groups.entity_of(marker_or_zero(markers, i)) - 1;
    ++block_sizes[entity[i]];
  }
  std::vector<std::size_t> start(groups.markers.size() + 1, 0);
  for (std::size_t g = 0; g < groups.markers.size(); ++g) start[g + 1] = start[g] + block_sizes[g];
  std::vector<std::size_t> order(count);
  for (std::size_t i = 0; i < count; ++i) order[start[entity[i]]++] = i;
  return order;
}

void put_physical_names(BufferedWriter& out, const PhysicalGroups& faces, int face_dim, const PhysicalGroups& cells,
                        int cell_dim) {
  out.put("$PhysicalNames\n").put_int(static_cast<std::int64_t>(faces.markers.size() + cells.markers.size()));
  out.put('\n');
  for (const auto* groups : {&faces, &cells}) {
    const int dim = groups == &faces ? face_dim : cell_dim;
    for (std::size_t g = 0; g < groups->markers.size(); ++g) {
      out.put_int(dim).put(' ').put_int(groups->physical_tags[g]).put(" \"marker ");
      out.put_int(groups->markers[g]).put("\"\n");
    }
  }
  out.put("$EndPhysicalNames\n");
}

void put_data_header(BufferedWriter& out, const char* section, const std::string& name, std::size_t count) {
  out.put('$').put(section).put("\n1\n\"").put(name).put("\"\n1\n0\n3\n0\n1\n");
  out.put_int(static_cast<std::int64_t>(count)).put('\n');
}

}  // namespace pqmesh::detail::gmsh
