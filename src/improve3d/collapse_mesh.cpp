#include "improve3d/collapse_mesh.hpp"

#include <algorithm>
#include <cstddef>
#include <utility>

namespace pqmesh::improve3d::detail {

namespace {

// Replaces u by v in element.
template <std::size_t K>
void repoint(std::array<int, K>& element, int u, int v) {
  for (int& x : element)
    if (x == u) x = v;
}

// The entries i of v with alive(i), in order, with room for a sixteenth more.
template <class T, class Alive>
std::vector<T> kept(const std::vector<T>& v, Alive alive, std::size_t live) {
  std::vector<T> out;
  out.reserve(live + live / 16 + 16);
  for (std::size_t i = 0; i < v.size(); ++i)
    if (alive(i)) out.push_back(v[i]);
  return out;
}

// Room for one more element, growing by a quarter (a flip appends a few
// tetrahedra to arrays of millions; doubling them would double the peak).
template <class T>
void room_for_one(std::vector<T>& v) {
  if (v.size() == v.capacity()) v.reserve(v.capacity() + v.capacity() / 4 + 16);
}

template <class T>
std::vector<T> moved_or_zeros(std::vector<T>& values, std::size_t n) {
  return values.size() == n ? std::move(values) : std::vector<T>(n, T{});
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
      faces_(mesh.faces),
      face_markers_(or_zeros(mesh.face_markers, mesh.faces.size())),
      face_facets_(face_facets.begin(), face_facets.end()),
      has_vertex_markers_(!mesh.vertex_markers.empty()),
      has_tet_markers_(!mesh.tetrahedron_markers.empty()),
      has_face_markers_(!mesh.face_markers.empty()),
      live_tets_(static_cast<std::int64_t>(mesh.tetrahedra.size())),
      live_vertices_(static_cast<std::int64_t>(mesh.vertices.size())),
      star_time_(mesh.vertices.size(), 1) {
  derive(memo);
}

CollapseMesh::CollapseMesh(TetMesh3&& mesh, std::vector<int>&& face_facets, TetrahedronQualityMemo& memo)
    : has_vertex_markers_(!mesh.vertex_markers.empty()),
      has_tet_markers_(!mesh.tetrahedron_markers.empty()),
      has_face_markers_(!mesh.face_markers.empty()),
      live_tets_(static_cast<std::int64_t>(mesh.tetrahedra.size())),
      live_vertices_(static_cast<std::int64_t>(mesh.vertices.size())) {
  const std::size_t n = mesh.vertices.size();
  points_ = std::move(mesh.vertices);
  vertex_markers_ = moved_or_zeros(mesh.vertex_markers, n);
  vertex_alive_.assign(n, 1);
  tets_ = std::move(mesh.tetrahedra);
  if (mesh.tetrahedron_markers.size() == tets_.size()) tet_markers_ = std::move(mesh.tetrahedron_markers);  // else one region 0
  faces_ = std::move(mesh.faces);
  face_markers_ = moved_or_zeros(mesh.face_markers, faces_.size());
  face_facets_ = std::move(face_facets);
  star_time_.assign(n, 1);
  mesh = TetMesh3{};
  face_facets = {};
  derive(memo);
}

void CollapseMesh::derive(TetrahedronQualityMemo& memo) {
  tets_of_vertex_.build(tets_, points_.size());
  faces_of_vertex_.build(faces_, points_.size());
  one_region_ = std::all_of(tet_markers_.begin(), tet_markers_.end(), [&](int m) { return m == tet_markers_.front(); });
  if (one_region_) {
    region_marker_ = tet_markers_.empty() ? 0 : tet_markers_.front();
    tet_markers_ = {};
  }
  aspect_.resize(tets_.size());
  dihedral_.resize(tets_.size());
  for (std::size_t t = 0; t < tets_.size(); ++t) {
    const auto& k = tets_[t];
    const TetQuality q = memo(point(k[0]), point(k[1]), point(k[2]), point(k[3]));
    aspect_[t] = q.aspect_ratio;
    dihedral_[t] = q.min_dihedral_deg;
  }
}

void CollapseMesh::tets_of(int v, std::vector<int>& out) {
  tets_of_vertex_.gather(v, tet_alive(), out);
}

void CollapseMesh::faces_of(int v, std::vector<int>& out) {
  faces_of_vertex_.gather(v, face_alive(), out);
}

void CollapseMesh::apply(const Collapse& c) {
  tick();
  for (const int t : c.dying_tets) stamp(tets_[static_cast<std::size_t>(t)]);
  for (const int t : c.moving_tets) stamp(tets_[static_cast<std::size_t>(t)]);
  for (const int f : c.dying_faces) stamp(faces_[static_cast<std::size_t>(f)]);
  for (const int f : c.moving_faces) stamp(faces_[static_cast<std::size_t>(f)]);
  for (const int t : c.dying_tets) tets_[static_cast<std::size_t>(t)][0] = -1;
  for (const int f : c.dying_faces) faces_[static_cast<std::size_t>(f)][0] = -1;
  for (std::size_t i = 0; i < c.moving_tets.size(); ++i) {
    const int t = c.moving_tets[i];
    repoint(tets_[static_cast<std::size_t>(t)], c.u, c.v);
    aspect_[static_cast<std::size_t>(t)] = c.new_aspect[i];
    dihedral_[static_cast<std::size_t>(t)] = c.new_dihedral[i];
  }
  for (const int f : c.moving_faces) repoint(faces_[static_cast<std::size_t>(f)], c.u, c.v);
  tets_of_vertex_.append(c.v, c.moving_tets, tet_alive());
  faces_of_vertex_.append(c.v, c.moving_faces, face_alive());
  tets_of_vertex_.clear(c.u);
  faces_of_vertex_.clear(c.u);
  vertex_alive_[static_cast<std::size_t>(c.u)] = 0;
  live_tets_ -= static_cast<std::int64_t>(c.dying_tets.size());
  --live_vertices_;
}

std::int64_t CollapseMesh::live_faces() const {
  return std::count_if(faces_.begin(), faces_.end(), [](const std::array<int, 3>& k) { return k[0] >= 0; });
}

double CollapseMesh::worst_aspect() const {
  double worst = 0;
  for (std::size_t t = 0; t < tets_.size(); ++t)
    if (tets_[t][0] >= 0) worst = std::max(worst, aspect_[t]);
  return worst;
}

double CollapseMesh::min_dihedral() const {
  double least = 180;
  for (std::size_t t = 0; t < tets_.size(); ++t)
    if (tets_[t][0] >= 0) least = std::min(least, dihedral_[t]);
  return least;
}

void CollapseMesh::move_vertex(int v, Vec3 p, std::span<const int> tets, std::span<const double> aspect,
                               std::span<const double> dihedral) {
  points_[static_cast<std::size_t>(v)] = p;
  tick();
  star_time_[static_cast<std::size_t>(v)] = time_;
  for (const int t : tets) stamp(tets_[static_cast<std::size_t>(t)]);
  for (std::size_t i = 0; i < tets.size(); ++i) {
    aspect_[static_cast<std::size_t>(tets[i])] = aspect[i];
    dihedral_[static_cast<std::size_t>(tets[i])] = dihedral[i];
  }
}

// One array at a time beside the others (peak memory): the pool first, in
// place, then the per-tetrahedron arrays, tets_ (which tells the live ones) last.
void CollapseMesh::compact_tets() {
  std::size_t n = 0;
  {
    std::vector<int> new_id(tets_.size(), -1);
    for (std::size_t t = 0; t < tets_.size(); ++t)
      if (tets_[t][0] >= 0) new_id[t] = static_cast<int>(n++);
    tets_of_vertex_.renumber(new_id);
  }
  const auto alive = [&](std::size_t t) { return tets_[t][0] >= 0; };
  if (!one_region_) tet_markers_ = kept(tet_markers_, alive, n);
  aspect_ = kept(aspect_, alive, n);
  dihedral_ = kept(dihedral_, alive, n);
  tets_ = kept(tets_, alive, n);
}

int CollapseMesh::add_tet(const std::array<int, 4>& k, int marker, double aspect, double dihedral) {
  if (one_region_ && marker != region_marker_) {
    tet_markers_.assign(tets_.size(), region_marker_);
    one_region_ = false;
  }
  if (!one_region_) room_for_one(tet_markers_);
  room_for_one(tets_);
  room_for_one(aspect_);
  room_for_one(dihedral_);
  const int t = static_cast<int>(tets_.size());
  tets_.push_back(k);
  if (!one_region_) tet_markers_.push_back(marker);
  aspect_.push_back(aspect);
  dihedral_.push_back(dihedral);
  for (const int x : k) tets_of_vertex_.append(x, std::span<const int>(&t, 1), tet_alive());
  tick();
  stamp(k);
  ++live_tets_;
  return t;
}

void CollapseMesh::remove_tet(int t) {
  tick();
  stamp(tets_[static_cast<std::size_t>(t)]);
  tets_[static_cast<std::size_t>(t)][0] = -1;  // dropped from the vertex segments when next walked
  --live_tets_;
}

int CollapseMesh::add_face(const std::array<int, 3>& k, int marker, int facet) {
  const int f = static_cast<int>(faces_.size());
  faces_.push_back(k);
  face_markers_.push_back(marker);
  face_facets_.push_back(facet);
  for (const int x : k) faces_of_vertex_.append(x, std::span<const int>(&f, 1), face_alive());
  tick();
  stamp(k);
  return f;
}

void CollapseMesh::remove_face(int f) {
  tick();
  stamp(faces_[static_cast<std::size_t>(f)]);
  faces_[static_cast<std::size_t>(f)][0] = -1;  // dropped from the vertex segments when next walked
}

void CollapseMesh::write_back(TetMesh3& mesh, std::vector<int>& face_facets) && {
  tets_of_vertex_ = {};
  faces_of_vertex_ = {};
  aspect_ = {};
  dihedral_ = {};
  star_time_ = {};
  std::vector<int> new_id(points_.size(), -1);
  mesh.vertices.clear();
  mesh.vertex_markers.clear();
  mesh.vertices.reserve(static_cast<std::size_t>(live_vertices_));
  for (std::size_t v = 0; v < points_.size(); ++v) {
    if (vertex_alive_[v] == 0) continue;
    new_id[v] = static_cast<int>(mesh.vertices.size());
    mesh.vertices.push_back(points_[v]);
    if (has_vertex_markers_) mesh.vertex_markers.push_back(vertex_markers_[v]);
  }
  points_ = {};
  vertex_markers_ = {};
  vertex_alive_ = {};
  const auto renumbered = [&](int x) { return new_id[static_cast<std::size_t>(x)]; };
  mesh.tetrahedra.clear();
  mesh.tetrahedron_markers.clear();
  mesh.tetrahedra.reserve(static_cast<std::size_t>(live_tets_));
  if (has_tet_markers_) mesh.tetrahedron_markers.reserve(static_cast<std::size_t>(live_tets_));
  for (std::size_t t = 0; t < tets_.size(); ++t) {
    const auto& k = tets_[t];
    if (k[0] < 0) continue;
    mesh.tetrahedra.push_back({renumbered(k[0]), renumbered(k[1]), renumbered(k[2]), renumbered(k[3])});
    if (has_tet_markers_) mesh.tetrahedron_markers.push_back(tet_marker(static_cast<int>(t)));
  }
  tets_ = {};
  tet_markers_ = {};
  mesh.faces.clear();
  mesh.face_markers.clear();
  face_facets.clear();
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    const auto& k = faces_[f];
    if (k[0] < 0) continue;
    mesh.faces.push_back({renumbered(k[0]), renumbered(k[1]), renumbered(k[2])});
    if (has_face_markers_) mesh.face_markers.push_back(face_markers_[f]);
    face_facets.push_back(face_facets_[f]);
  }
}

}  // namespace pqmesh::improve3d::detail
