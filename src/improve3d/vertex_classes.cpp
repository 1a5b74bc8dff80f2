#include "improve3d/vertex_classes.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>

namespace pqmesh::improve3d::detail {

namespace {

using Bits = std::array<std::uint64_t, 3>;

Bits bits_of(Vec3 p) {
  return {std::bit_cast<std::uint64_t>(p.x), std::bit_cast<std::uint64_t>(p.y), std::bit_cast<std::uint64_t>(p.z)};
}

// Sorted bit patterns of the input vertices: equality of patterns is
// equality of coordinates bit for bit (-0 and +0 differ, as rule 1 asks).
std::vector<Bits> input_keys(const Domain3& domain) {
  std::vector<Bits> keys;
  keys.reserve(domain.plc.vertices.size());
  for (const Vec3& p : domain.plc.vertices) keys.push_back(bits_of(p));
  std::sort(keys.begin(), keys.end());
  return keys;
}

// (vertex, facet) pairs of every boundary triangle corner, sorted and unique.
std::vector<std::uint64_t> vertex_facet_pairs(const TetMesh3& mesh, std::span<const int> face_facets) {
  std::vector<std::uint64_t> pairs;
  pairs.reserve(mesh.faces.size() * 3);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    for (const int v : mesh.faces[f])
      pairs.push_back(static_cast<std::uint64_t>(static_cast<std::uint32_t>(v)) << 32 |
                      static_cast<std::uint32_t>(face_facets[f]));
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

}  // namespace

bool VertexClasses::facets_within(int u, int v) const {
  const std::span<const int> a = facets_of(u), b = facets_of(v);
  return std::includes(b.begin(), b.end(), a.begin(), a.end());
}

bool VertexClasses::same_facets(int u, int v) const {
  const std::span<const int> a = facets_of(u), b = facets_of(v);
  return std::equal(a.begin(), a.end(), b.begin(), b.end());
}

VertexClasses classify_vertices(const Domain3& domain, const TetMesh3& mesh, std::span<const int> face_facets) {
  const std::size_t n = mesh.vertices.size();
  VertexClasses c;
  c.begin.assign(n + 1, 0);
  const std::vector<std::uint64_t> pairs = vertex_facet_pairs(mesh, face_facets);
  c.facets.reserve(pairs.size());
  for (const std::uint64_t p : pairs) {
    ++c.begin[(p >> 32) + 1];
    c.facets.push_back(static_cast<int>(p & 0xffffffffu));
  }
  for (std::size_t v = 0; v < n; ++v) c.begin[v + 1] += c.begin[v];
  const std::vector<Bits> keys = input_keys(domain);
  c.kind.resize(n);
  for (std::size_t v = 0; v < n; ++v) {
    const int count = c.begin[v + 1] - c.begin[v];
    if (std::binary_search(keys.begin(), keys.end(), bits_of(mesh.vertices[v])))
      c.kind[v] = VertexClass::Input;
    else
      c.kind[v] = count == 0 ? VertexClass::Interior : (count == 1 ? VertexClass::Facet : VertexClass::Edge);
  }
  return c;
}

}  // namespace pqmesh::improve3d::detail
