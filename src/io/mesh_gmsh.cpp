// Gmsh MSH 4.1 and 2.2, ASCII (reference: the "MSH file format" chapter of
// the Gmsh manual); binary 4.1 is written by mesh_gmsh_binary.cpp with the
// same sections and order. Layout written here:
//   $PhysicalNames  one group per (dimension, marker), named "marker <m>";
//                   physical tags follow PhysicalGroups (mesh_common.hpp).
//   $Entities (4.1) one entity per (dimension, marker): curves (2D) or
//                   surfaces (3D) for boundary items, surfaces (2D) or volumes
//                   (3D) for elements; entity tags 1, 2, ... in marker order;
//                   every bounding box is the mesh's; no bounding entities.
//   $Nodes          all nodes in the first element entity (legal: a node may
//                   be classified on an entity of higher dimension than the
//                   elements that use it); node tag = vertex index + 1.
//   $Elements       element tag = element index + 1, boundary item tag =
//                   number of elements + index + 1; 4.1 groups them in blocks
//                   by entity, so the reader sorts by tag to restore the order.
//   $NodeData       "vertex_marker" when the mesh has vertex markers.
//   Cell fields are not written: an $ElementData over the elements only
//   (not the boundary items) is legal for Gmsh but rejected by meshio.
// Gmsh orders triangle nodes counter-clockwise and tetrahedron nodes with
// positive volume (its reference tetrahedron is (0,0,0), (1,0,0), (0,1,0),
// (0,0,1)), the same as pqmesh, so connectivity is written unchanged.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

#include "io/gmsh_common.hpp"
#include "io/mesh_common.hpp"
#include "io/mesh_input.hpp"
#include "io/mesh_output.hpp"

namespace pqmesh::detail {

namespace {

using namespace gmsh;

template <class M>
void write_body(const M& mesh, BufferedWriter& out, bool v22) {
  using T = MeshTraits<M>;
  constexpr int D = T::dim;
  const auto& cells = T::cells(mesh);
  const auto& faces = T::faces(mesh);
  const std::size_t nv = mesh.vertices.size(), nc = cells.size(), nf = faces.size();
  const PhysicalGroups cell_groups = make_physical_groups(T::cell_markers(mesh), nc);
  const PhysicalGroups face_groups = make_physical_groups(T::face_markers(mesh), nf);
  const int cell_type = D == 2 ? kTriangle : kTetrahedron;
  const int face_type = D == 2 ? kLine : kTriangle;

  out.put(v22 ? "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n" : "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
  put_physical_names(out, face_groups, D - 1, cell_groups, D);

  if (v22) {
    out.put("$Nodes\n").put_int(static_cast<std::int64_t>(nv)).put('\n');
    for (std::size_t i = 0; i < nv; ++i) {
      out.put_int(static_cast<std::int64_t>(i + 1));
      for (int k = 0; k < 3; ++k) out.put(' ').put_double(coord(mesh.vertices[i], k));
      out.put('\n');
    }
    out.put("$EndNodes\n$Elements\n").put_int(static_cast<std::int64_t>(nc + nf)).put('\n');
    std::int64_t tag = 1;
    for (std::size_t c = 0; c < nc; ++c) {
      const int e = cell_groups.entity_of(marker_or_zero(T::cell_markers(mesh), c));
      out.put_int(tag++).put(' ').put_int(cell_type).put(" 2 ").put_int(cell_groups.physical_tags[e - 1]);
      out.put(' ').put_int(e);
      for (int v : cells[c]) out.put(' ').put_int(v + 1);
      out.put('\n');
    }
    for (std::size_t f = 0; f < nf; ++f) {
      const int e = face_groups.entity_of(marker_or_zero(T::face_markers(mesh), f));
      out.put_int(tag++).put(' ').put_int(face_type).put(" 2 ").put_int(face_groups.physical_tags[e - 1]);
      out.put(' ').put_int(e);
      for (int v : faces[f]) out.put(' ').put_int(v + 1);
      out.put('\n');
    }
    out.put("$EndElements\n");
  } else {
    // Bounding box shared by every entity.
    double lo[3], hi[3];
    bounding_box(mesh, lo, hi);
    const EntityCounts counts = entity_counts(D, face_groups, cell_groups, nv);
    out.put("$Entities\n");
    for (int d = 0; d < 4; ++d) out.put_int(static_cast<std::int64_t>(counts.per_dim[d])).put(d < 3 ? ' ' : '\n');
    auto put_entity = [&](std::size_t tag, const PhysicalGroups& groups) {
      out.put_int(static_cast<std::int64_t>(tag));
      for (double v : lo) out.put(' ').put_double(v);
      for (double v : hi) out.put(' ').put_double(v);
      if (tag - 1 < groups.markers.size())
        out.put(" 1 ").put_int(groups.physical_tags[tag - 1]).put(" 0\n");
      else
        out.put(" 0 0\n");
    };
    for (std::size_t g = 1; g <= face_groups.markers.size(); ++g) put_entity(g, face_groups);
    for (std::size_t g = 1; g <= counts.cells; ++g) put_entity(g, cell_groups);
    out.put("$EndEntities\n");

    out.put("$Nodes\n");
    if (nv == 0) {
      out.put("0 0 0 0\n");
    } else {
      out.put("1 ").put_int(static_cast<std::int64_t>(nv)).put(" 1 ").put_int(static_cast<std::int64_t>(nv));
      out.put('\n').put_int(D).put(" 1 0 ").put_int(static_cast<std::int64_t>(nv)).put('\n');
      for (std::size_t i = 0; i < nv; ++i) out.put_int(static_cast<std::int64_t>(i + 1)).put('\n');
      for (std::size_t i = 0; i < nv; ++i) {
        out.put_double(coord(mesh.vertices[i], 0)).put(' ').put_double(coord(mesh.vertices[i], 1)).put(' ');
        out.put_double(coord(mesh.vertices[i], 2)).put('\n');
      }
    }
    out.put("$EndNodes\n$Elements\n");
    std::vector<std::size_t> cell_blocks, face_blocks;
    const auto cell_order = order_by_entity(cell_groups, T::cell_markers(mesh), nc, cell_blocks);
    const auto face_order = order_by_entity(face_groups, T::face_markers(mesh), nf, face_blocks);
    std::size_t num_blocks = 0;
    for (std::size_t s : cell_blocks) num_blocks += s > 0 ? 1 : 0;
    for (std::size_t s : face_blocks) num_blocks += s > 0 ? 1 : 0;
    out.put_int(static_cast<std::int64_t>(num_blocks)).put(' ').put_int(static_cast<std::int64_t>(nc + nf));
    out.put(' ').put_int(nc + nf > 0 ? 1 : 0).put(' ').put_int(static_cast<std::int64_t>(nc + nf)).put('\n');
    auto put_blocks = [&](const auto& items, const std::vector<std::size_t>& order,
                          const std::vector<std::size_t>& blocks, int dim, int type, std::size_t tag_offset) {
      std::size_t pos = 0;
      for (std::size_t g = 0; g < blocks.size(); ++g) {
        if (blocks[g] == 0) continue;
        out.put_int(dim).put(' ').put_int(static_cast<std::int64_t>(g + 1)).put(' ').put_int(type).put(' ');
        out.put_int(static_cast<std::int64_t>(blocks[g])).put('\n');
        for (std::size_t k = 0; k < blocks[g]; ++k, ++pos) {
          const std::size_t i = order[pos];
          out.put_int(static_cast<std::int64_t>(tag_offset + i + 1));
          for (int v : items[i]) out.put(' ').put_int(v + 1);
          out.put('\n');
        }
      }
    };
    put_blocks(cells, cell_order, cell_blocks, D, cell_type, 0);
    put_blocks(faces, face_order, face_blocks, D - 1, face_type, nc);
    out.put("$EndElements\n");
  }

  if (!mesh.vertex_markers.empty()) {
    put_data_header(out, "NodeData", "vertex_marker", nv);
    for (std::size_t i = 0; i < nv; ++i)
      out.put_int(static_cast<std::int64_t>(i + 1)).put(' ').put_int(mesh.vertex_markers[i]).put('\n');
    out.put("$EndNodeData\n");
  }
}

// ---------------------------------------------------------------- reading

// Node tag -> index in order of appearance.
class TagIndex {
 public:
  void add(std::int64_t tag) { tags_.push_back(tag); }
  // Call once after all add(); false when a tag repeats (sets dup to it).
  bool build(std::int64_t& dup) {
    std::int64_t max_tag = 0;
    for (std::int64_t t : tags_) max_tag = std::max(max_tag, t);
    if (max_tag <= static_cast<std::int64_t>(2 * tags_.size() + 1024)) {
      dense_.assign(static_cast<std::size_t>(max_tag) + 1, -1);
      for (std::size_t i = 0; i < tags_.size(); ++i) {
        if (dense_[tags_[i]] >= 0) {
          dup = tags_[i];
          return false;
        }
        dense_[tags_[i]] = static_cast<int>(i);
      }
    } else {
      sparse_.resize(tags_.size());
      for (std::size_t i = 0; i < tags_.size(); ++i) sparse_[i] = {tags_[i], static_cast<int>(i)};
      std::sort(sparse_.begin(), sparse_.end());
      for (std::size_t i = 1; i < sparse_.size(); ++i)
        if (sparse_[i].first == sparse_[i - 1].first) {
          dup = sparse_[i].first;
          return false;
        }
    }
    return true;
  }
  int find(std::int64_t tag) const {
    if (!dense_.empty() || sparse_.empty()) {
      return tag >= 0 && tag < static_cast<std::int64_t>(dense_.size()) ? dense_[tag] : -1;
    }
    const auto it = std::lower_bound(sparse_.begin(), sparse_.end(), std::pair<std::int64_t, int>{tag, -1});
    return it != sparse_.end() && it->first == tag ? it->second : -1;
  }
  std::size_t size() const { return tags_.size(); }

 private:
  std::vector<std::int64_t> tags_;
  std::vector<int> dense_;
  std::vector<std::pair<std::int64_t, int>> sparse_;
};

int nodes_of_type(int type) {
  switch (type) {
    case 1: return 2;
    case 2: return 3;
    case 3: return 4;
    case 4: return 4;
    case 5: return 8;
    case 6: return 6;
    case 7: return 5;
    case 8: return 3;
    case 9: return 6;
    case 10: return 9;
    case 11: return 10;
    case 15: return 1;
    default: return 0;
  }
}

struct PhysicalName {
  int dim;
  int tag;
  std::string name;
};

struct GmshReader {
  // Every number takes at least two bytes (digit and separator): counts are
  // reserved only up to what the file can hold, so an absurd count fails as
  // Truncated when the file runs out instead of allocating.
  std::int64_t max_numbers;
  TextReader in;
  int dim;
  bool v22 = false;
  std::vector<PhysicalName> names;
  // (dim, entity tag) -> first physical tag (0: none), 4.1 only.
  std::vector<std::pair<std::pair<int, int>, int>> entity_physical;
  TagIndex nodes;
  std::vector<double> xyz;
  RawMesh raw;
  std::vector<std::int64_t> cell_tags, face_tags;
  std::vector<std::pair<std::int64_t, int>> vertex_marker_entries;
  bool have_nodes = false, have_elements = false;

  GmshReader(const std::string& path, int d) : GmshReader(path, read_whole_file(path), d) {}
  GmshReader(const std::string& path, std::string text, int d)
      : max_numbers(static_cast<std::int64_t>(text.size() / 2 + 1)), in(path, std::move(text), '\0'), dim(d) {}

  int marker_of_physical(int d, int physical) const {
    if (physical == 0) return 0;
    for (const PhysicalName& n : names) {
      if (n.dim != d || n.tag != physical) continue;
      const std::string prefix = "marker ";
      if (n.name.compare(0, prefix.size(), prefix) == 0) {
        const std::string rest = n.name.substr(prefix.size());
        std::size_t used = 0;
        try {
          const long long m = std::stoll(rest, &used);
          if (used == rest.size() && m >= INT32_MIN && m <= INT32_MAX) return static_cast<int>(m);
        } catch (const std::exception&) {
        }
      }
      break;
    }
    return physical;
  }

  std::string quoted_name() {
    std::string_view rest = in.rest_of_line();
    if (rest.size() < 2 || rest.front() != '"' || rest.back() != '"')
      in.fail(ErrorCode::Syntax, "expected a quoted name, found '" + std::string(rest) + "'");
    return std::string(rest.substr(1, rest.size() - 2));
  }

  void read_format() {
    const std::string_view version = in.token("mesh format version");
    const std::int64_t file_type = in.integer("file type");
    in.integer("data size");
    if (version == "4.1") {
      v22 = false;
    } else if (version == "2.2" || version == "2.1" || version == "2" || version == "2.0") {
      v22 = true;
    } else {
      in.fail(ErrorCode::Unsupported, "MSH version " + std::string(version) + " (only 4.1 and 2.2 are read)");
    }
    if (file_type != 0)
      in.fail(ErrorCode::Unsupported, "binary MSH files are not read (convert with `gmsh FILE -0 -format msh41`)");
    in.expect("$EndMeshFormat");
  }

  void read_physical_names() {
    const std::int64_t n = in.integer_in("number of physical names", 0, INT32_MAX);
    for (std::int64_t i = 0; i < n; ++i) {
      PhysicalName p;
      p.dim = static_cast<int>(in.integer_in("physical dimension", 0, 3));
      p.tag = static_cast<int>(in.integer_in("physical tag", 1, INT32_MAX));
      p.name = quoted_name();
      names.push_back(std::move(p));
    }
    in.expect("$EndPhysicalNames");
  }

  void read_entities() {
    std::int64_t counts[4];
    for (auto& c : counts) c = in.integer_in("number of entities", 0, INT32_MAX);
    for (int d = 0; d < 4; ++d)
      for (std::int64_t i = 0; i < counts[d]; ++i) {
        const int tag = static_cast<int>(in.integer_in("entity tag", 0, INT32_MAX));
        for (int k = 0; k < (d == 0 ? 3 : 6); ++k) in.real("entity bounding box");
        const std::int64_t np = in.integer_in("number of physical tags", 0, INT32_MAX);
        int first = 0;
        for (std::int64_t k = 0; k < np; ++k) {
          const std::int64_t p = in.integer("physical tag");
          if (k == 0) first = static_cast<int>(std::abs(p));
        }
        if (d > 0) {
          const std::int64_t nb = in.integer_in("number of bounding entities", 0, INT32_MAX);
          for (std::int64_t k = 0; k < nb; ++k) in.integer("bounding entity");
        }
        entity_physical.push_back({{d, tag}, first});
      }
    std::sort(entity_physical.begin(), entity_physical.end());
    in.expect("$EndEntities");
  }

  int physical_of_entity(int d, int tag) const {
    const auto it = std::lower_bound(entity_physical.begin(), entity_physical.end(),
                                     std::pair<std::pair<int, int>, int>{{d, tag}, INT32_MIN});
    return it != entity_physical.end() && it->first == std::pair<int, int>{d, tag} ? it->second : 0;
  }

  void add_node(std::int64_t tag) {
    if (tag < 1) in.fail(ErrorCode::WrongCount, "node tag " + std::to_string(tag) + " is not positive", tag);
    nodes.add(tag);
  }

  void read_nodes() {
    if (have_nodes) in.fail(ErrorCode::Syntax, "second $Nodes section");
    have_nodes = true;
    if (v22) {
      const std::int64_t n = in.integer_in("number of nodes", 0, INT32_MAX - 1);
      xyz.reserve(static_cast<std::size_t>(std::min(3 * n, max_numbers)));
      for (std::int64_t i = 0; i < n; ++i) {
        add_node(in.integer("node tag"));
        for (int k = 0; k < 3; ++k) xyz.push_back(in.real("node coordinate"));
      }
    } else {
      const std::int64_t blocks = in.integer_in("number of node blocks", 0, INT32_MAX);
      const std::int64_t n = in.integer_in("number of nodes", 0, INT32_MAX - 1);
      in.integer("minimum node tag");
      in.integer("maximum node tag");
      xyz.reserve(static_cast<std::size_t>(std::min(3 * n, max_numbers)));
      std::int64_t seen = 0;
      for (std::int64_t b = 0; b < blocks; ++b) {
        in.integer("entity dimension");
        in.integer("entity tag");
        if (in.integer("parametric flag") != 0) in.fail(ErrorCode::Unsupported, "parametric nodes");
        const std::int64_t count = in.integer_in("nodes in block", 0, n - seen);
        for (std::int64_t i = 0; i < count; ++i) add_node(in.integer("node tag"));
        for (std::int64_t i = 0; i < 3 * count; ++i) xyz.push_back(in.real("node coordinate"));
        seen += count;
      }
      if (seen != n)
        in.fail(ErrorCode::WrongCount,
                "node blocks hold " + std::to_string(seen) + " nodes, header says " + std::to_string(n));
    }
    std::int64_t dup = 0;
    if (!nodes.build(dup)) in.fail(ErrorCode::WrongCount, "node tag " + std::to_string(dup) + " repeats", dup);
    in.expect("$EndNodes");
  }

  // One element of `type` with element tag `tag` and marker `marker`.
  void read_element(int type, std::int64_t tag, int marker) {
    const int cell_type = dim == 2 ? kTriangle : kTetrahedron;
    const int face_type = dim == 2 ? kLine : kTriangle;
    const int nn = nodes_of_type(type);
    if (nn == 0) in.fail(ErrorCode::Unsupported, "element type " + std::to_string(type), tag);
    const bool is_cell = type == cell_type, is_face = type == face_type;
    const bool ignored = type == kPoint || (dim == 3 && type == kLine);
    if (!is_cell && !is_face && !ignored)
      in.fail(ErrorCode::Unsupported,
              "element " + std::to_string(tag) + " has type " + std::to_string(type) + ", not allowed in a " +
                  (dim == 2 ? "triangle" : "tetrahedral") + " mesh",
              tag);
    std::vector<int>& target = is_cell ? raw.cells : raw.faces;
    for (int k = 0; k < nn; ++k) {
      const std::int64_t node = in.integer("element node");
      const int index = nodes.find(node);
      if (index < 0)
        in.fail(ErrorCode::IndexOutOfRange,
                "element " + std::to_string(tag) + " refers to missing node " + std::to_string(node), node);
      if (!ignored) target.push_back(index);
    }
    if (is_cell) {
      raw.cell_markers.push_back(marker);
      cell_tags.push_back(tag);
    } else if (is_face) {
      raw.face_markers.push_back(marker);
      face_tags.push_back(tag);
    }
  }

  void read_elements() {
    if (!have_nodes) in.fail(ErrorCode::Syntax, "$Elements before $Nodes");
    if (have_elements) in.fail(ErrorCode::Syntax, "second $Elements section");
    have_elements = true;
    // Markers by physical tag, cached: (dim, physical) -> marker.
    std::vector<std::pair<std::pair<int, int>, int>> cache;
    auto marker = [&](int d, int physical) {
      for (const auto& c : cache)
        if (c.first == std::pair<int, int>{d, physical}) return c.second;
      const int m = marker_of_physical(d, physical);
      if (cache.size() < 64) cache.push_back({{d, physical}, m});
      return m;
    };
    if (v22) {
      const std::int64_t n = in.integer_in("number of elements", 0, INT32_MAX);
      for (std::int64_t i = 0; i < n; ++i) {
        const std::int64_t tag = in.integer("element tag");
        const int type = static_cast<int>(in.integer("element type"));
        const std::int64_t ntags = in.integer_in("number of element tags", 0, 64);
        int physical = 0;
        for (std::int64_t k = 0; k < ntags; ++k) {
          const std::int64_t t = in.integer("element tag value");
          if (k == 0) physical = static_cast<int>(std::clamp<std::int64_t>(t, INT32_MIN, INT32_MAX));
        }
        const int d = type == kTetrahedron ? 3 : type == kTriangle ? 2 : type == kLine ? 1 : 0;
        read_element(type, tag, physical > 0 ? marker(d, physical) : 0);
      }
    } else {
      const std::int64_t blocks = in.integer_in("number of element blocks", 0, INT32_MAX);
      const std::int64_t n = in.integer_in("number of elements", 0, INT32_MAX);
      in.integer("minimum element tag");
      in.integer("maximum element tag");
      std::int64_t seen = 0;
      for (std::int64_t b = 0; b < blocks; ++b) {
        const int d = static_cast<int>(in.integer_in("entity dimension", 0, 3));
        const int entity = static_cast<int>(in.integer("entity tag"));
        const int type = static_cast<int>(in.integer("element type"));
        const std::int64_t count = in.integer_in("elements in block", 0, n - seen);
        const int physical = physical_of_entity(d, entity);
        const int m = physical > 0 ? marker(d, physical) : 0;
        for (std::int64_t i = 0; i < count; ++i) read_element(type, in.integer("element tag"), m);
        seen += count;
      }
      if (seen != n)
        in.fail(ErrorCode::WrongCount,
                "element blocks hold " + std::to_string(seen) + " elements, header says " + std::to_string(n));
    }
    in.expect("$EndElements");
  }

  // $NodeData / $ElementData; only a one-component NodeData "vertex_marker" is kept.
  void read_data(bool node_data) {
    const std::int64_t nstrings = in.integer_in("number of string tags", 0, 64);
    std::string name;
    for (std::int64_t i = 0; i < nstrings; ++i) {
      const std::string s = quoted_name();
      if (i == 0) name = s;
    }
    const std::int64_t nreals = in.integer_in("number of real tags", 0, 64);
    for (std::int64_t i = 0; i < nreals; ++i) in.real("real tag");
    const std::int64_t nints = in.integer_in("number of integer tags", 3, 64);
    std::int64_t components = 1, entries = 0;
    for (std::int64_t i = 0; i < nints; ++i) {
      const std::int64_t v = in.integer("integer tag");
      if (i == 1) components = v;
      if (i == 2) entries = v;
    }
    if (components < 1 || components > 9 || entries < 0 || entries > INT32_MAX)
      in.fail(ErrorCode::WrongCount, "bad component or entry count in data section");
    const bool keep = node_data && name == "vertex_marker" && components == 1;
    for (std::int64_t i = 0; i < entries; ++i) {
      const std::int64_t tag = in.integer("data entity tag");
      for (std::int64_t k = 0; k < components; ++k) {
        const double v = in.real("data value");
        if (keep) {
          if (v != static_cast<double>(static_cast<int>(v)))
            in.fail(ErrorCode::Syntax, "vertex_marker value is not an integer", tag);
          vertex_marker_entries.push_back({tag, static_cast<int>(v)});
        }
      }
    }
    in.expect(node_data ? "$EndNodeData" : "$EndElementData");
  }

  void skip_section(std::string_view name) {
    const std::string end = "$End" + std::string(name);
    while (true) {
      if (in.at_end()) in.fail(ErrorCode::Truncated, "file ends inside section $" + std::string(name));
      if (in.token("section") == end) return;
    }
  }

  template <class V>
  static void permute_by_tag(std::vector<std::int64_t>& tags, std::vector<V>& items, int width,
                             std::vector<int>& markers) {
    if (std::is_sorted(tags.begin(), tags.end())) return;
    std::vector<std::size_t> order(tags.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return tags[a] < tags[b]; });
    std::vector<V> new_items(items.size());
    std::vector<int> new_markers(markers.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
      for (int k = 0; k < width; ++k) new_items[i * width + k] = items[order[i] * width + k];
      new_markers[i] = markers[order[i]];
    }
    items.swap(new_items);
    markers.swap(new_markers);
  }

  RawMesh run() {
    if (in.at_end()) in.fail(ErrorCode::Truncated, "empty file");
    in.expect("$MeshFormat");
    read_format();
    while (!in.at_end()) {
      const std::string_view t = in.token("section");
      if (t.size() < 2 || t[0] != '$') in.fail(ErrorCode::Syntax, "expected a section, found '" + std::string(t) + "'");
      const std::string_view name = t.substr(1);
      if (name == "PhysicalNames") {
        read_physical_names();
      } else if (name == "Entities") {
        read_entities();
      } else if (name == "Nodes") {
        read_nodes();
      } else if (name == "Elements") {
        read_elements();
      } else if (name == "NodeData") {
        read_data(true);
      } else if (name == "ElementData") {
        read_data(false);
      } else {
        skip_section(name);
      }
    }
    if (!have_nodes) in.fail(ErrorCode::Truncated, "no $Nodes section");
    if (!have_elements) in.fail(ErrorCode::Truncated, "no $Elements section");
    raw.xyz = std::move(xyz);
    if (!vertex_marker_entries.empty()) {
      raw.vertex_markers.assign(nodes.size(), 0);
      for (const auto& [tag, m] : vertex_marker_entries) {
        const int index = nodes.find(tag);
        if (index < 0) in.fail(ErrorCode::IndexOutOfRange, "vertex_marker for missing node " + std::to_string(tag), tag);
        raw.vertex_markers[index] = m;
      }
    }
    permute_by_tag(cell_tags, raw.cells, dim + 1, raw.cell_markers);
    permute_by_tag(face_tags, raw.faces, dim, raw.face_markers);
    return std::move(raw);
  }
};

}  // namespace

template <class M>
void write_gmsh(const M& mesh, const std::string& path, GmshLayout layout) {
  AtomicFile file(path);
  BufferedWriter out(file.file(), path);
  if (layout == GmshLayout::Binary41)
    gmsh::write_binary41(mesh, out);
  else
    write_body(mesh, out, layout == GmshLayout::Ascii22);
  out.flush();
  file.commit();
}

template void write_gmsh(const TriMesh2&, const std::string&, GmshLayout);
template void write_gmsh(const TetMesh3&, const std::string&, GmshLayout);

RawMesh read_gmsh(const std::string& path, int dim) {
  GmshReader reader(path, dim);
  return reader.run();
}

}  // namespace pqmesh::detail
