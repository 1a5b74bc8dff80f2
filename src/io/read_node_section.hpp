#pragma once
// The node (vertex) list shared by Triangle .poly/.node and TetGen
// .poly/.smesh/.node files, plus the hole and region lists at their ends.
//
// Node header: "<n> <dim> <#attributes> <#boundary markers (0|1)>"; node lines
// "<id> <coords...> [attributes] [marker]". The first id (0 or 1) fixes the
// file's numbering; later ids must follow consecutively. A count of 0 in a
// .poly/.smesh means the nodes live in the .node file with the same base name.
#include <string>
#include <vector>

#include "io/read_text_tokens.hpp"
#include "pqmesh/plc.hpp"

namespace pqmesh::detail {

struct NodeSection {
  int dim = 0;
  std::vector<double> coords;  // dim values per node
  std::vector<int> markers;    // one per node when the header announces markers, else empty
  std::vector<int> lines;      // line of each node (in `path`)
  int first_id = 0;
  std::string path;            // file the nodes came from (the .poly or its .node)
  int count() const { return dim > 0 ? static_cast<int>(coords.size()) / dim : 0; }
};

// `header` is the node header record already read from `src`.
NodeSection read_node_section(TextSource& src, const TextRecord& header, int expected_dim);

// Reads a required count record; `what` names the section in messages.
long long read_count(TextSource& src, TextRecord& record, const std::string& what);

// A non-negative count from token `i` of `record`, or a WrongCount/Syntax error.
long long count_token(const TextSource& src, const TextRecord& record, std::size_t i, const std::string& what);
// An integer token, or a Syntax error naming `what`.
long long int_token(const TextSource& src, const TextRecord& record, std::size_t i, const std::string& what);
// A finite double token; Syntax error if it does not parse, NonFinite (naming
// `what_id`, the entity's id) when it is NaN or infinite.
double coord_token(const TextSource& src, const TextRecord& record, std::size_t i, const std::string& what,
                   long long what_id);

// Converts a vertex id written in the file to a 0-based index; throws
// IndexOutOfRange naming the element (`element_kind` `element_id`) and the bad id.
int vertex_index(const TextSource& src, long long file_id, int first_id, int vertex_count, int line,
                 const std::string& element_kind, long long element_id);

// Optional trailing sections: holes "<h>" + "<id> <coords>", regions "<r>" +
// "<id> <coords> <attribute> <max size>". Missing sections mean none.
void read_holes(TextSource& src, int dim, std::vector<double>& holes);
void read_regions(TextSource& src, int dim, std::vector<double>& regions);  // dim + 2 values per region

}  // namespace pqmesh::detail
