#include "io/read_node_section.hpp"

#include <algorithm>
#include <cmath>

namespace pqmesh::detail {

long long int_token(const TextSource& src, const TextRecord& record, std::size_t i, const std::string& what) {
  if (i >= record.tokens.size()) src.fail(ErrorCode::Syntax, "missing " + what, record.line);
  long long value = 0;
  if (!parse_int(record.tokens[i], value))
    src.fail(ErrorCode::Syntax, "expected an integer " + what + ", found '" + std::string(record.tokens[i]) + "'",
             record.line);
  return value;
}

long long count_token(const TextSource& src, const TextRecord& record, std::size_t i, const std::string& what) {
  const long long value = int_token(src, record, i, what);
  if (value < 0) src.fail(ErrorCode::WrongCount, "negative " + what + " " + std::to_string(value), record.line);
  if (value > 2'000'000'000) src.fail(ErrorCode::WrongCount, what + " " + std::to_string(value) + " is too large", record.line);
  return value;
}

double coord_token(const TextSource& src, const TextRecord& record, std::size_t i, const std::string& what,
                   long long what_id) {
  if (i >= record.tokens.size())
    src.fail(ErrorCode::Syntax, "missing coordinate of " + what + " " + std::to_string(what_id), record.line, {what_id});
  double value = 0;
  if (!parse_double(record.tokens[i], value))
    src.fail(ErrorCode::Syntax,
             "coordinate '" + std::string(record.tokens[i]) + "' of " + what + " " + std::to_string(what_id) +
                 " is not a number",
             record.line, {what_id});
  if (!std::isfinite(value))
    src.fail(ErrorCode::NonFinite, what + " " + std::to_string(what_id) + " has a non-finite coordinate", record.line,
             {what_id});
  return value;
}

long long read_count(TextSource& src, TextRecord& record, const std::string& what) {
  if (!src.next_record(record)) src.fail_truncated("the " + what);
  return count_token(src, record, 0, what);
}

int vertex_index(const TextSource& src, long long file_id, int first_id, int vertex_count, int line,
                 const std::string& element_kind, long long element_id) {
  const long long index = file_id - first_id;
  if (index < 0 || index >= vertex_count)
    src.fail(ErrorCode::IndexOutOfRange,
             element_kind + " " + std::to_string(element_id) + " refers to vertex " + std::to_string(file_id) +
                 ", which does not exist (vertex ids are " + std::to_string(first_id) + ".." +
                 std::to_string(first_id + vertex_count - 1) + ")",
             line, {element_id, file_id});
  return static_cast<int>(index);
}

namespace {

// Reads `n` node lines after a header whose fields are already decoded.
void read_nodes(TextSource& src, long long n, int dim, long long attributes, long long marker_count, NodeSection& out) {
  out.dim = dim;
  out.path = src.path();
  const auto cap = static_cast<long long>(src.content().size() / 2 + 1);
  out.coords.reserve(static_cast<std::size_t>(std::min(n, cap) * dim));
  out.lines.reserve(static_cast<std::size_t>(std::min(n, cap)));
  if (marker_count > 0) out.markers.reserve(static_cast<std::size_t>(std::min(n, cap)));
  TextRecord record;
  for (long long i = 0; i < n; ++i) {
    if (!src.next_record(record))
      src.fail_truncated("all " + std::to_string(n) + " vertices are listed (found " + std::to_string(i) + ")");
    const long long id = int_token(src, record, 0, "vertex id");
    if (i == 0) {
      if (id != 0 && id != 1)
        src.fail(ErrorCode::WrongCount, "the first vertex id must be 0 or 1, found " + std::to_string(id), record.line,
                 {id});
      out.first_id = static_cast<int>(id);
    } else if (id != out.first_id + i) {
      src.fail(ErrorCode::WrongCount,
               "vertex id " + std::to_string(id) + " out of sequence (expected " + std::to_string(out.first_id + i) +
                   ")",
               record.line, {id});
    }
    for (int d = 0; d < dim; ++d) out.coords.push_back(coord_token(src, record, 1 + static_cast<std::size_t>(d), "vertex", id));
    if (marker_count > 0) {
      const auto at = static_cast<std::size_t>(1 + dim + attributes);
      out.markers.push_back(at < record.tokens.size() ? static_cast<int>(int_token(src, record, at, "vertex marker")) : 0);
    }
    out.lines.push_back(record.line);
  }
}

struct NodeHeader {
  long long n = 0, dim = 0, attributes = 0, markers = 0;
};

NodeHeader decode_header(const TextSource& src, const TextRecord& header, int expected_dim) {
  NodeHeader h;
  h.n = count_token(src, header, 0, "vertex count");
  h.dim = header.tokens.size() > 1 ? int_token(src, header, 1, "dimension") : expected_dim;
  h.attributes = header.tokens.size() > 2 ? count_token(src, header, 2, "attribute count") : 0;
  h.markers = header.tokens.size() > 3 ? int_token(src, header, 3, "boundary marker count") : 0;
  return h;
}

void check_header(const TextSource& src, const NodeHeader& h, int expected_dim, int line) {
  if (h.dim != expected_dim)
    src.fail(ErrorCode::WrongCount,
             "dimension " + std::to_string(h.dim) + " where this format needs " + std::to_string(expected_dim), line);
  if (h.markers != 0 && h.markers != 1)
    src.fail(ErrorCode::WrongCount, "boundary marker count must be 0 or 1, found " + std::to_string(h.markers), line);
}

// An optional list of `what` records: a count line, then the records, each
// starting with its id; calls row(record, id) for each.
template <class Row>
void read_listed(TextSource& src, const std::string& what, Row&& row) {
  TextRecord record;
  if (!src.next_record(record)) return;
  const long long n = count_token(src, record, 0, what + " count");
  for (long long i = 0; i < n; ++i) {
    if (!src.next_record(record)) src.fail_truncated("all " + std::to_string(n) + " " + what + "s are listed");
    row(record, int_token(src, record, 0, what + " id"));
  }
}

}  // namespace

NodeSection read_node_section(TextSource& src, const TextRecord& header, int expected_dim) {
  NodeSection out;
  const NodeHeader h = decode_header(src, header, expected_dim);
  if (h.n > 0) {
    check_header(src, h, expected_dim, header.line);
    read_nodes(src, h.n, expected_dim, h.attributes, h.markers, out);
    return out;
  }
  // Zero nodes here: they come from the companion .node file.
  TextSource node_file(replace_extension(src.path(), ".node"));
  TextRecord node_header;
  if (!node_file.next_record(node_header)) node_file.fail_truncated("the vertex header");
  const NodeHeader nh = decode_header(node_file, node_header, expected_dim);
  check_header(node_file, nh, expected_dim, node_header.line);
  if (nh.n == 0) node_file.fail(ErrorCode::WrongCount, "the .node file lists no vertices", node_header.line);
  read_nodes(node_file, nh.n, expected_dim, nh.attributes, nh.markers, out);
  return out;
}

void read_holes(TextSource& src, int dim, std::vector<double>& holes) {
  read_listed(src, "hole", [&](const TextRecord& record, long long id) {
    for (int d = 0; d < dim; ++d) holes.push_back(coord_token(src, record, 1 + static_cast<std::size_t>(d), "hole", id));
  });
}

void read_regions(TextSource& src, int dim, std::vector<double>& regions) {
  read_listed(src, "region", [&](const TextRecord& record, long long id) {
    for (int d = 0; d < dim; ++d)
      regions.push_back(coord_token(src, record, 1 + static_cast<std::size_t>(d), "region", id));
    const auto at = static_cast<std::size_t>(1 + dim);
    regions.push_back(at < record.tokens.size() ? coord_token(src, record, at, "region", id) : 0.0);
    regions.push_back(at + 1 < record.tokens.size() ? coord_token(src, record, at + 1, "region", id) : -1.0);
  });
}

}  // namespace pqmesh::detail
