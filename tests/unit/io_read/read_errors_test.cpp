// Every ParseError code triggered by a small malformed file, with the line
// and ids the message must name (lines counted by hand in each string; ids
// in the file's own numbering).
#include <gtest/gtest.h>

#include "io_read_helpers.hpp"
#include "pqmesh/read_domain.hpp"

namespace pqmesh {
namespace {

using test::ExpectedError;
using test::expect_parse_error;
using test::write_temp;

void expect_pslg_error(const std::string& name, const std::string& content, const ExpectedError& want) {
  const std::string path = write_temp(name, content);
  expect_parse_error([&] { read_pslg(path); }, want, path);
}

void expect_plc_error(const std::string& name, const std::string& content, const ExpectedError& want) {
  const std::string path = write_temp(name, content);
  expect_parse_error([&] { read_plc(path); }, want, path);
}

TEST(ReadErrors, Unreadable) {
  const std::string missing = "/nonexistent/dir/shape.poly";
  expect_parse_error([&] { read_pslg(missing); }, {ErrorCode::Unreadable, 0, {}}, missing);
  const std::string missing_stl = "/nonexistent/dir/shape.stl";
  expect_parse_error([&] { read_plc(missing_stl); }, {ErrorCode::Unreadable, 0, {}}, missing_stl);
  // A .poly whose vertices should come from a .node file that does not exist.
  const std::string poly = write_temp("lonely.poly", "0 2 0 0\n0 0\n");
  const std::string node = poly.substr(0, poly.size() - 5) + ".node";
  expect_parse_error([&] { read_pslg(poly); }, {ErrorCode::Unreadable, 0, {}}, node);
}

TEST(ReadErrors, Truncated) {
  // Announces 4 vertices, lists 3; the file's last line is 4.
  expect_pslg_error("trunc.poly", "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n", {ErrorCode::Truncated, 4, {}});
  // Segment section missing entirely.
  expect_pslg_error("noseg.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 1 1\n\n", {ErrorCode::Truncated, 5, {}});
  // OFF announcing 2 faces with only 1.
  expect_plc_error("trunc.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", {ErrorCode::Truncated, 6, {}});
  // ASCII STL ending inside a facet.
  expect_plc_error("trunc.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n", {ErrorCode::Truncated, 4, {}});
  // TetGen facet announcing 2 polygons, listing 1.
  expect_plc_error("trunc.poly", "3 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n1 0\n2\n3 1 2 3\n",
                   {ErrorCode::Truncated, 7, {}});
}

TEST(ReadErrors, Syntax) {
  expect_pslg_error("syntax.poly", "# header\n3 2 0 0\n1 0 0\n2 1 zero\n3 1 1\n", {ErrorCode::Syntax, 4, {2}});
  expect_plc_error("syntax.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertx 0 0 0\n", {ErrorCode::Syntax, 4, {}});
  expect_plc_error("syntax.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 two 3\n", {ErrorCode::Syntax, 4, {1}});
}

TEST(ReadErrors, WrongCount) {
  // Boundary marker count 2 in a header preceded by two comment lines.
  expect_pslg_error("markers.poly", "# a\n# b\n3 2 0 2\n1 0 0\n2 1 0\n3 1 1\n", {ErrorCode::WrongCount, 3, {}});
  // Negative segment count.
  expect_pslg_error("negseg.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 1 1\n-1 0\n", {ErrorCode::WrongCount, 5, {}});
  // Vertex ids out of sequence: 1, 2, 4.
  expect_pslg_error("seq.poly", "3 2 0 0\n1 0 0\n2 1 0\n4 1 1\n3 0\n", {ErrorCode::WrongCount, 4, {4}});
  // OFF face 1 announcing 4 corners but listing 3.
  expect_plc_error("short.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n4 0 1 2\n", {ErrorCode::WrongCount, 7, {1}});
  // Medit in dimension 2.
  expect_plc_error("dim.mesh", "MeshVersionFormatted 1\nDimension\n2\n", {ErrorCode::WrongCount, 3, {}});
}

TEST(ReadErrors, IndexOutOfRange) {
  // Segment 3 refers to vertex 9 of 3.
  expect_pslg_error("index.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 1 1\n3 0\n1 1 2\n2 2 3\n3 3 9\n",
                    {ErrorCode::IndexOutOfRange, 8, {3, 9}});
  // 0-based OFF: face 0 refers to vertex 3 of 0..2.
  expect_plc_error("index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", {ErrorCode::IndexOutOfRange, 6, {0, 3}});
  // OBJ relative id -4 with 3 vertices read resolves to 0: face 1.
  expect_plc_error("index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", {ErrorCode::IndexOutOfRange, 4, {1, 0}});
  // TetGen facet 2 (1-based) refers to vertex 7.
  expect_plc_error("index.poly", "3 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n2 0\n1\n3 1 2 3\n1\n3 1 7 3\n",
                   {ErrorCode::IndexOutOfRange, 9, {2, 7}});
  // Medit triangle 1 refers to vertex 4 of 3.
  expect_plc_error("index.mesh",
                   "MeshVersionFormatted 1\nDimension 3\nVertices\n3\n0 0 0 0\n1 0 0 0\n0 1 0 0\nTriangles\n1\n1 2 4 0\nEnd\n",
                   {ErrorCode::IndexOutOfRange, 10, {1, 4}});
}

TEST(ReadErrors, NonFinite) {
  expect_pslg_error("nan.poly", "3 2 0 0\n1 0 0\n2 nan 0\n3 1 1\n", {ErrorCode::NonFinite, 3, {2}});
  expect_plc_error("inf.off", "OFF\n3 1 0\n0 0 0\n1 0 inf\n0 1 0\n3 0 1 2\n", {ErrorCode::NonFinite, 4, {1}});
  expect_plc_error("huge.obj", "v 0 0 0\nv 1e999 0 0\n", {ErrorCode::NonFinite, 2, {2}});
  expect_plc_error("nan.mesh", "MeshVersionFormatted 1\nDimension 3\nVertices\n2\n0 0 0 0\n1 -inf 0 0\n",
                   {ErrorCode::NonFinite, 6, {2}});
  expect_plc_error("nan.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 NaN\n",
                   {ErrorCode::NonFinite, 5, {0}});
}

TEST(ReadErrors, Unsupported) {
  expect_plc_error("four.off", "4OFF\n1 0 0\n0 0 0 0\n", {ErrorCode::Unsupported, 1, {}});
  expect_plc_error("kw.mesh", "MeshVersionFormatted 1\nDimension 3\nSomethingElse\n1\n", {ErrorCode::Unsupported, 3, {}});
}

}  // namespace
}  // namespace pqmesh
