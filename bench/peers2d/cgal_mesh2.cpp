// cgal_mesh2: the CGAL Mesh_2 peer of the 2D benchmark (bench/run_2d.sh).
//
//   cgal_mesh2 INPUT.poly [SIZE [ANGLE]]
//
// Reads a Triangle .poly (vertices, segments, holes; attributes, markers and
// a trailing regions section are skipped), builds a constrained Delaunay
// triangulation of the segments, and refines it with Delaunay_mesh_size_criteria_2
// using shape bound B = sin^2(ANGLE) (the smallest angle's sine squared is
// at least B; ANGLE in degrees, default 20.7: B = 0.125, CGAL's usual bound) and SIZE as the bound on the longest triangle edge (0 or
// absent: no size bound). Hole points are the seeds of regions not to mesh;
// the region reachable from the outside without crossing a segment is
// never meshed. Prints one line:
//
//   triangles N vertices V seconds T min_angle DEG
//
// where N counts in-domain faces, T is the wall time of triangulating plus
// refining (reading the file excluded), DEG is the smallest angle of the
// in-domain faces, computed in double precision from the vertex coordinates.
// Exit status 2 on a usage or parse error.
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Delaunay_mesh_vertex_base_2<Kernel>;
using FaceBase = CGAL::Delaunay_mesh_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
using Point = Kernel::Point_2;

struct Poly {
  std::vector<Point> vertices;
  std::vector<std::pair<std::size_t, std::size_t>> segments;  // 0-based vertex indices
  std::vector<Point> holes;
};

// Splits the file into the numbers of its non-comment lines; one vector per line.
std::vector<std::vector<double>> read_number_lines(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::vector<std::vector<double>> lines;
  std::string line;
  while (std::getline(in, line)) {
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    std::vector<double> numbers;
    double x = 0;
    while (words >> x) numbers.push_back(x);
    if (!words.eof()) throw std::runtime_error(path + ": not a number in line '" + line + "'");
    if (!numbers.empty()) lines.push_back(std::move(numbers));
  }
  return lines;
}

// Triangle's .poly layout: "n 2 attrs markers", n vertex lines "id x y ...",
// "m markers", m segment lines "id a b [marker]", "h", h hole lines "id x y".
// Vertex ids start at 0 or 1, as the first vertex line says.
Poly read_poly(const std::string& path) {
  const auto lines = read_number_lines(path);
  std::size_t at = 0;
  auto next = [&](std::size_t min_count) -> const std::vector<double>& {
    if (at >= lines.size()) throw std::runtime_error(path + ": file ends early");
    if (lines[at].size() < min_count) throw std::runtime_error(path + ": short line");
    return lines[at++];
  };
  Poly poly;
  const auto& header = next(1);
  const auto n = static_cast<std::size_t>(header[0]);
  if (header.size() > 1 && header[1] != 2) throw std::runtime_error(path + ": not a 2D .poly");
  if (n == 0) throw std::runtime_error(path + ": vertices in a separate .node file are not supported");
  double first_id = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& v = next(3);
    if (i == 0) first_id = v[0];
    poly.vertices.emplace_back(v[1], v[2]);
  }
  const auto m = static_cast<std::size_t>(next(1)[0]);
  for (std::size_t i = 0; i < m; ++i) {
    const auto& s = next(3);
    const double a = s[1] - first_id, b = s[2] - first_id;
    if (a < 0 || b < 0 || a >= static_cast<double>(n) || b >= static_cast<double>(n))
      throw std::runtime_error(path + ": segment endpoint out of range");
    poly.segments.emplace_back(static_cast<std::size_t>(a), static_cast<std::size_t>(b));
  }
  if (at < lines.size()) {
    const auto h = static_cast<std::size_t>(next(1)[0]);
    for (std::size_t i = 0; i < h; ++i) {
      const auto& p = next(3);
      poly.holes.emplace_back(p[1], p[2]);
    }
  }
  return poly;  // a regions section, if any, is ignored
}

// Smallest angle (degrees) of triangle abc, from its squared edge lengths by the law of cosines.
double min_angle_degrees(const Point& a, const Point& b, const Point& c) {
  const double la = CGAL::to_double(CGAL::squared_distance(b, c));
  const double lb = CGAL::to_double(CGAL::squared_distance(c, a));
  const double lc = CGAL::to_double(CGAL::squared_distance(a, b));
  // The smallest angle is opposite the shortest edge.
  double opp = la, s1 = lb, s2 = lc;
  if (lb < opp) { opp = lb; s1 = la; s2 = lc; }
  if (lc < opp) { opp = lc; s1 = la; s2 = lb; }
  const double cosine = std::clamp((s1 + s2 - opp) / (2 * std::sqrt(s1 * s2)), -1.0, 1.0);
  constexpr double kPi = 3.141592653589793238462643383279502884;
  return std::acos(cosine) * 180.0 / kPi;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 4) {
    std::cerr << "usage: cgal_mesh2 INPUT.poly [SIZE [ANGLE]]\n";
    return 2;
  }
  Poly poly;
  double size = 0, shape_bound = 0.125;
  try {
    poly = read_poly(argv[1]);
    if (argc >= 3) size = std::stod(argv[2]);
    if (argc == 4) shape_bound = std::pow(std::sin(std::stod(argv[3]) * 3.14159265358979323846 / 180), 2);
  } catch (const std::exception& e) {
    std::cerr << "cgal_mesh2: " << e.what() << '\n';
    return 2;
  }

  const auto start = std::chrono::steady_clock::now();
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handles;
  handles.reserve(poly.vertices.size());
  for (const auto& p : poly.vertices) handles.push_back(cdt.insert(p));
  for (const auto& [a, b] : poly.segments) cdt.insert_constraint(handles[a], handles[b]);
  // mark = false: the seeds (hole points) name the components that are NOT meshed.
  CGAL::refine_Delaunay_mesh_2(cdt, poly.holes.begin(), poly.holes.end(), Criteria(shape_bound, size), false);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::size_t triangles = 0;
  double min_angle = 180;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    ++triangles;
    min_angle = std::min(min_angle, min_angle_degrees(f->vertex(0)->point(), f->vertex(1)->point(),
                                                      f->vertex(2)->point()));
  }
  std::printf("triangles %zu vertices %zu seconds %.6f min_angle %.4f\n", triangles,
              static_cast<std::size_t>(cdt.number_of_vertices()), seconds, min_angle);
  return 0;
}
