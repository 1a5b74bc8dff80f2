// United vertex boxes (thesis §4.5.2), coned from the P vertex.
#include <string>
#include <unordered_map>

#include "pqmesh/errors.hpp"
#include "tet3d/boxes/box_assembler.hpp"

namespace pqmesh::tet3d {

// The united box B of P vertex `vertex` (2x2x2 leaves of `leaf`'s size,
// extending below the leaf along the axes of `block`), coned from the vertex.
void BoxAssembler::vertex_box(std::int32_t leaf, int vertex, std::uint8_t block) {
  const BoxKey<3>& key = tree_.key(leaf);
  const std::int64_t fs = key.fine_side();
  const GridPoint lo = united_lo(key, block);
  const Vec3 p = domain_.plc.vertices.at(static_cast<std::size_t>(vertex));
  {
    GridPoint hi = lo;
    for (int a = 0; a < 3; ++a) hi.f[static_cast<std::size_t>(a)] += 2 * fs;
    const Vec3 L = grid_coordinates(tree_, lo), H = grid_coordinates(tree_, hi);
    if (!(L.x < p.x && p.x < H.x && L.y < p.y && p.y < H.y && L.z < p.z && p.z < H.z))
      throw InternalError("tet3d: vertex " + std::to_string(vertex) + " is not inside its united box (leaf " +
                          std::to_string(leaf) + ")");
  }
  const BoxFaces faces = squares_.faces_of(BoxKind::Vertex, vertex);
  std::vector<FaceSquare> squares;
  for (int axis = 0; axis < 3; ++axis)
    for (const bool upper : {false, true}) united_face_squares(key, block, axis, upper, corners_, squares);
  const std::vector<Sign> hints = vertex_box_hints(squares, faces);
  std::vector<Tri> tris;
  for (std::size_t i = 0; i < squares.size(); ++i) {
    const std::size_t first = tris.size();
    squares_.triangulate(squares[i], faces, tris, hints[i]);
    if (!squares[i].upper)
      for (std::size_t k = first; k < tris.size(); ++k) std::swap(tris[k][1], tris[k][2]);
  }
  const VertexKey vk{VertexKind::PVertex, {}, {}, vertex};
  const int v = book_.id(vk, [&] { return p; });
  for (const Tri& t : tris) cone(leaf, t, v);
  ++out_.stats.vertex;
}

// For the squares of a united box that meet no face of v's cone: inside or
// outside P, from a ring point shared with a square that meets a face,
// whose local model (square_cases.hpp local_status) is exact there; then
// propagated over the box surface through shared ring points (a square
// meeting no face lies wholly inside or outside, so all its ring points
// share its status). Zero where nothing is known (the dispatcher then
// falls back to locate()).
std::vector<Sign> BoxAssembler::vertex_box_hints(const std::vector<FaceSquare>& squares, const BoxFaces& faces) {
  std::vector<SquareDispatcher::Incidence> inc;
  std::vector<std::vector<GridPoint>> rings;
  std::unordered_map<GridPoint, Sign, GridPointHash> status;
  for (const FaceSquare& s : squares) {
    inc.push_back(squares_.incidences(s, faces));
    rings.push_back(square_ring(s, corners_));
  }
  for (std::size_t i = 0; i < squares.size(); ++i) {
    const SquareDispatcher::Incidence& m = inc[i];
    if (m.none() || !m.vertices.empty() || m.edges.size() > 1 || m.facets.size() > 2) continue;
    if (m.facets.size() == 2 && squares_.edge_of_facets(m.facets[0], m.facets[1]) < 0) continue;
    for (const GridPoint& p : rings[i]) {
      const Sign st = squares_.local_status(m, grid_coordinates(tree_, p));
      if (st != Sign::Zero) status.emplace(p, st);
    }
  }
  std::vector<Sign> hint(squares.size(), Sign::Zero);
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = 0; i < squares.size(); ++i) {
      if (!inc[i].none() || hint[i] != Sign::Zero) continue;
      for (const GridPoint& p : rings[i]) {
        const auto it = status.find(p);
        if (it == status.end()) continue;
        hint[i] = it->second;
        break;
      }
      if (hint[i] == Sign::Zero) continue;
      changed = true;
      for (const GridPoint& p : rings[i]) status.emplace(p, hint[i]);
    }
  }
  return hint;
}

}  // namespace pqmesh::tet3d
