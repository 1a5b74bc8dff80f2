#include "improve3d/collapse_mesh.hpp"

#include <algorithm>
#include <cstddef>

namespace pqmesh::improve3d::detail {

namespace {

// Threads corner k * e + i of every element e onto the list of its i-th
// vertex. Pushing at the head in decreasing corner order leaves each list in
// increasing element order.
template <std::size_t K>
void link(const std::vector<std::array<int, K>>& elements, std::vector<int>& head, std::vector<int>& next) {
  next.assign(elements.size() * K, -1);
  for (std::size_t c = elements.size() * K; c-- > 0;) {
    const int v = elements[c / K][c % K];
    next[c] = head[static_cast<std::size_t>(v)];
    head[static_cast<std::size_t>(v)] = static_cast<int>(c);
  }
}

// The traversal of CollapseMesh::tets_of / faces_of: appends the live
// elements of the list at *link and unlinks the dead corners.
template <std::size_t K>
void gather(int* link, std::vector<int>& next, const std::vector<std::uint8_t>& alive, std::vector<int>& out) {
  while (*link >= 0) {
    const int c = *link;
    const int e = c / static_cast<int>(K);
    if (alive[static_cast<std::size_t>(e)] == 0) {
      *link = next[static_cast<std::size_t>(c)];
      continue;
    }
    out.push_back(e);
    link = &next[static_cast<std::size_t>(c)];
  }
}

// Replaces u by v in element e and moves that corner to the head of v's list
// (u's list is abandoned with u).
template <std::size_t K>
void repoint(std::array<int, K>& element, int e, int u, int v, std::vector<int>& head, std::vector<int>& next) {
  for (std::size_t i = 0; i < K; ++i)
    if (element[i] == u) {
      element[i] = v;
      const std::size_t c = static_cast<std::size_t>(e) * K + i;
      next[c] = head[static_cast<std::size_t>(v)];
      head[static_cast<std::size_t>(v)] = static_cast<int>(c);
      return;
    }
}

template <class T>
std::vector<T> or_zeros(const std::vector<T>& values, std::size_t n) {
  return values.size() == n ? values : std::vector<T>(n, T{});
}

}  // namespace

CollapseMesh::CollapseMesh(const TetMesh3& mesh, std::span<const int> face_facets, TetrahedronQualityMemo& memo)
    : points_(mesh.vertices),
      vertex_markers_(or_zeros(mesh.vertex_markers, mesh.vertices.size())),
      vertex_alive_(mesh.vertices.size(), 1),
      tets_(mesh.tetrahedra),
      tet_markers_(or_zeros(mesh.tetrahedron_markers, mesh.tetrahedra.size())),
      tet_alive_(mesh.tetrahedra.size(), 1),
      faces_(mesh.faces),
      face_markers_(or_zeros(mesh.face_markers, mesh.faces.size())),
      face_facets_(face_facets.begin(), face_facets.end()),
      face_alive_(mesh.faces.size(), 1),
      has_vertex_markers_(!mesh.vertex_markers.empty()),
      has_tet_markers_(!mesh.tetrahedron_markers.empty()),
      has_face_markers_(!mesh.face_markers.empty()),
      live_tets_(static_cast<std::int64_t>(mesh.tetrahedra.size())),
      live_vertices_(static_cast<std::int64_t>(mesh.vertices.size())) {
  aspect_.resize(tets_.size());
  for (std::size_t t = 0; t < tets_.size(); ++t) {
    const auto& k = tets_[t];
    aspect_[t] = memo(point(k[0]), point(k[1]), point(k[2]), point(k[3])).aspect_ratio;
  }
  link_tets();
  link_faces();
}

void CollapseMesh::link_tets() {
  tet_head_.assign(points_.size(), -1);
  link(tets_, tet_head_, tet_next_);
}

void CollapseMesh::link_faces() {
  face_head_.assign(points_.size(), -1);
  link(faces_, face_head_, face_next_);
}

void CollapseMesh::tets_of(int v, std::vector<int>& out) {
  gather<4>(&tet_head_[static_cast<std::size_t>(v)], tet_next_, tet_alive_, out);
}

void CollapseMesh::faces_of(int v, std::vector<int>& out) {
  gather<3>(&face_head_[static_cast<std::size_t>(v)], face_next_, face_alive_, out);
}

void CollapseMesh::apply(const Collapse& c) {
  for (const int t : c.dying_tets) tet_alive_[static_cast<std::size_t>(t)] = 0;
  for (const int f : c.dying_faces) face_alive_[static_cast<std::size_t>(f)] = 0;
  for (std::size_t i = 0; i < c.moving_tets.size(); ++i) {
    const int t = c.moving_tets[i];
    repoint(tets_[static_cast<std::size_t>(t)], t, c.u, c.v, tet_head_, tet_next_);
    aspect_[static_cast<std::size_t>(t)] = c.new_aspect[i];
  }
  for (const int f : c.moving_faces) repoint(faces_[static_cast<std::size_t>(f)], f, c.u, c.v, face_head_, face_next_);
  vertex_alive_[static_cast<std::size_t>(c.u)] = 0;
  tet_head_[static_cast<std::size_t>(c.u)] = face_head_[static_cast<std::size_t>(c.u)] = -1;
  live_tets_ -= static_cast<std::int64_t>(c.dying_tets.size());
  --live_vertices_;
}

double CollapseMesh::worst_aspect() const {
  double worst = 0;
  for (std::size_t t = 0; t < tets_.size(); ++t)
    if (tet_alive_[t] != 0) worst = std::max(worst, aspect_[t]);
  return worst;
}

void CollapseMesh::write_back(TetMesh3& mesh, std::vector<int>& face_facets) const {
  std::vector<int> new_id(points_.size(), -1);
  mesh.vertices.clear();
  mesh.vertex_markers.clear();
  for (std::size_t v = 0; v < points_.size(); ++v) {
    if (vertex_alive_[v] == 0) continue;
    new_id[v] = static_cast<int>(mesh.vertices.size());
    mesh.vertices.push_back(points_[v]);
    if (has_vertex_markers_) mesh.vertex_markers.push_back(vertex_markers_[v]);
  }
  mesh.tetrahedra.clear();
  mesh.tetrahedron_markers.clear();
  for (std::size_t t = 0; t < tets_.size(); ++t) {
    if (tet_alive_[t] == 0) continue;
    const auto& k = tets_[t];
    mesh.tetrahedra.push_back({new_id[static_cast<std::size_t>(k[0])], new_id[static_cast<std::size_t>(k[1])],
                               new_id[static_cast<std::size_t>(k[2])], new_id[static_cast<std::size_t>(k[3])]});
    if (has_tet_markers_) mesh.tetrahedron_markers.push_back(tet_markers_[t]);
  }
  mesh.faces.clear();
  mesh.face_markers.clear();
  face_facets.clear();
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    if (face_alive_[f] == 0) continue;
    const auto& k = faces_[f];
    mesh.faces.push_back({new_id[static_cast<std::size_t>(k[0])], new_id[static_cast<std::size_t>(k[1])],
                          new_id[static_cast<std::size_t>(k[2])]});
    if (has_face_markers_) mesh.face_markers.push_back(face_markers_[f]);
    face_facets.push_back(face_facets_[f]);
  }
}

}  // namespace pqmesh::improve3d::detail
