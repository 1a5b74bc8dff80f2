// Foundation benchmark: the costs every mesher run will pay around the mesher
// itself — validating a large input surface, checking a large tetrahedral
// mesh, computing its quality report and writing it as binary .vtu. Prints
// time, throughput and peak memory; asserts nothing (tests do that).
//   usage: pqmesh_bench_foundation [SPHERE_BANDS=160] [CUBE_CELLS=55] [OUT_DIR=/tmp]
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>

#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/mesh_io.hpp"
#include "pqmesh/quality.hpp"

namespace {

using namespace pqmesh;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

double peak_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

// A closed UV sphere with `bands` latitude bands and 2*bands longitudes:
// 4 * bands * (bands - 1) triangles, outward.
Plc3 uv_sphere(int bands) {
  Plc3 plc;
  const int lon = 2 * bands;
  plc.vertices.push_back({0, 0, 1});
  for (int i = 1; i < bands; ++i) {
    const double theta = std::numbers::pi * i / bands;
    for (int j = 0; j < lon; ++j) {
      const double phi = 2 * std::numbers::pi * j / lon;
      plc.vertices.push_back({std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)});
    }
  }
  plc.vertices.push_back({0, 0, -1});
  const int south = static_cast<int>(plc.vertices.size()) - 1;
  auto ring = [lon](int i, int j) { return 1 + (i - 1) * lon + (j % lon); };
  auto tri = [&plc](int a, int b, int c) { plc.facets.push_back({{{a, b, c}}, 0}); };
  for (int j = 0; j < lon; ++j) tri(0, ring(1, j), ring(1, j + 1));
  for (int i = 1; i + 1 < bands; ++i)
    for (int j = 0; j < lon; ++j) {
      tri(ring(i, j), ring(i + 1, j), ring(i + 1, j + 1));
      tri(ring(i, j), ring(i + 1, j + 1), ring(i, j + 1));
    }
  for (int j = 0; j < lon; ++j) tri(south, ring(bands - 1, j + 1), ring(bands - 1, j));
  return plc;
}

// The unit cube as a domain, and its n^3 cells each split into the 6 Kuhn
// tetrahedra (positively oriented), all coordinates dyadic when n is a power of 2.
Domain3 unit_cube() {
  Plc3 plc;
  for (int k = 0; k < 8; ++k) plc.vertices.push_back({double(k & 1), double((k >> 1) & 1), double((k >> 2) & 1)});
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) plc.facets.push_back({{{f[0], f[1], f[2], f[3]}}, 1});
  return make_domain(std::move(plc));
}

TetMesh3 kuhn_grid(int n) {
  TetMesh3 mesh;
  const double h = 1.0 / n;
  auto id = [n](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) mesh.vertices.push_back({i * h, j * h, k * h});
  // Paths from corner 0 to corner 7 of a cell, one per axis order; vertex
  // order chosen so that det(b - a, c - a, d - a) > 0.
  const int paths[6][4] = {{0, 1, 3, 7}, {0, 1, 7, 5}, {0, 2, 7, 3}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 7, 6}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& p : paths) {
          std::array<int, 4> t{};
          for (int c = 0; c < 4; ++c) t[c] = id(i + (p[c] & 1), j + ((p[c] >> 1) & 1), k + ((p[c] >> 2) & 1));
          mesh.tetrahedra.push_back(t);
        }
  return mesh;
}

}  // namespace

int main(int argc, char** argv) {
  const int bands = argc > 1 ? std::atoi(argv[1]) : 160;
  const int cells = argc > 2 ? std::atoi(argv[2]) : 55;
  const std::string out_dir = argc > 3 ? argv[3] : "/tmp";

  Plc3 sphere = uv_sphere(bands);
  const std::size_t triangles = sphere.facets.size();
  auto t0 = Clock::now();
  const Domain3 domain = make_domain(std::move(sphere));
  const double validate = seconds_since(t0);
  std::printf("validate  %9zu triangles  %7.3f s  %10.0f triangles/s  volume %.6f\n", triangles, validate,
              triangles / validate, domain.volume);

  const Domain3 cube = unit_cube();
  const TetMesh3 mesh = kuhn_grid(cells);
  const double tets = static_cast<double>(mesh.tetrahedra.size());
  t0 = Clock::now();
  const CheckReport report = check_mesh(mesh, cube);
  const double check = seconds_since(t0);
  std::printf("check     %9.0f tetrahedra %7.3f s  %10.0f tets/s       %s\n", tets, check, tets / check,
              report.valid() ? "valid" : "INVALID");

  t0 = Clock::now();
  const QualityReport quality = quality_report(mesh);
  const double qual = seconds_since(t0);
  std::printf("quality   %9.0f tetrahedra %7.3f s  %10.0f tets/s       max aspect %.4f\n", tets, qual, tets / qual,
              quality.aspect_ratio.max);

  const std::string path = out_dir + "/pqmesh_bench_foundation.vtu";
  t0 = Clock::now();
  write_mesh(mesh, path);
  const double write = seconds_since(t0);
  std::printf("write vtu %9.0f tetrahedra %7.3f s  %10.0f tets/s       %s\n", tets, write, tets / write, path.c_str());
  std::remove(path.c_str());

  std::printf("peak memory %.1f MiB\n", peak_mib());
  return report.valid() ? 0 : 1;
}
