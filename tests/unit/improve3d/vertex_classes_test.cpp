// The vertex classes of rule 1 (src/improve3d/vertex_classes.hpp) on a mesh
// of the unit cube: the 8 corners are input vertices, a vertex on a cube
// edge has two facets (two coordinates in {0, 1}), one inside a face one
// facet, an interior vertex none.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstddef>

#include "improve3d/vertex_classes.hpp"
#include "improve_support.hpp"
#include "pqmesh/read_domain.hpp"
#include "pqmesh/tetmesh.hpp"
#include "support/paths.hpp"

namespace pqmesh {
namespace {

using improve3d::detail::VertexClass;

int coordinates_on_the_boundary(Vec3 p) {
  int n = 0;
  for (const double c : {p.x, p.y, p.z}) n += c == 0 || c == 1;
  return n;
}

TEST(VertexClasses, CubeCornersEdgesFacesInterior) {
  const Domain3 d = make_domain(read_plc(test::data_path("3d/cube.poly")));
  TetMeshOptions mo;
  mo.max_size = 0.25;
  const TetMesh3 mesh = tet_mesh(d, test::construction_only(mo)).mesh;
  const std::vector<int> facets = test::facets_of_faces(d, mesh);
  const auto classes = improve3d::detail::classify_vertices(d, mesh, facets);
  std::array<int, 4> count{};
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const VertexClass c = classes.of(static_cast<int>(v));
    ++count[static_cast<std::size_t>(c)];
    const int on = coordinates_on_the_boundary(mesh.vertices[v]);
    const std::size_t n = classes.facets_of(static_cast<int>(v)).size();
    if (c == VertexClass::Input) {
      EXPECT_EQ(on, 3) << v;
      EXPECT_EQ(n, 3u) << v;
    } else {
      EXPECT_EQ(static_cast<int>(n), on) << v;
      EXPECT_EQ(static_cast<int>(c), std::min(on, 2)) << v;
    }
  }
  EXPECT_EQ(count[static_cast<std::size_t>(VertexClass::Input)], 8);
  EXPECT_GT(count[static_cast<std::size_t>(VertexClass::Edge)], 0);
  EXPECT_GT(count[static_cast<std::size_t>(VertexClass::Facet)], 0);
  EXPECT_GT(count[static_cast<std::size_t>(VertexClass::Interior)], 0);
}

}  // namespace
}  // namespace pqmesh
