// SVG picture of a 2D mesh: triangles filled by their smallest angle (six
// 10-degree classes, red = worst, green = best, the legend underneath), input
// edges (TriMesh2::edges) drawn bold on top, y axis flipped so the picture is
// upright, viewBox fitted to the bounding box plus a margin. Coordinates are
// printed with 3 decimals (pixels): a picture, not a round-trip format.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "io/mesh_common.hpp"
#include "io/mesh_output.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kClasses = 6;  // [0,10), [10,20), ..., [50,60] degrees
const std::array<const char*, kClasses> kColours = {"#d7191c", "#f46d43", "#fdae61",
                                                    "#fee08b", "#a6d96a", "#1a9641"};

// Smallest interior angle of triangle abc in degrees (a construction used for
// colouring only; no decision depends on it).
double min_angle_degrees(Vec2 a, Vec2 b, Vec2 c) {
  const double A = angle_between(b - a, c - a);
  const double B = angle_between(c - b, a - b);
  const double C = kPi - A - B;
  return std::min({A, B, C}) * 180.0 / kPi;
}

int angle_class(double degrees) {
  if (!(degrees >= 0)) return 0;  // NaN from a degenerate triangle: worst class
  return std::min(kClasses - 1, static_cast<int>(degrees / 10.0));
}

}  // namespace

void write_svg(const TriMesh2& mesh, const std::string& path, const WriteOptions& options) {
  double lo_x = 0, hi_x = 1, lo_y = 0, hi_y = 1;
  if (!mesh.vertices.empty()) {
    lo_x = hi_x = mesh.vertices[0].x;
    lo_y = hi_y = mesh.vertices[0].y;
    for (const Vec2& p : mesh.vertices) {
      lo_x = std::min(lo_x, p.x);
      hi_x = std::max(hi_x, p.x);
      lo_y = std::min(lo_y, p.y);
      hi_y = std::max(hi_y, p.y);
    }
  }
  const double span = std::max(hi_x - lo_x, hi_y - lo_y);
  const double width = options.svg_width > 0 ? options.svg_width : 800;
  const double scale = span > 0 ? width / span : 1.0;
  const double margin = 10, legend_height = 40;
  const double pic_w = (hi_x - lo_x) * scale, pic_h = (hi_y - lo_y) * scale;
  const double total_w = std::max(pic_w, 6 * 90.0) + 2 * margin;
  const double total_h = pic_h + 2 * margin + legend_height;

  AtomicFile file(path);
  BufferedWriter out(file.file(), path);
  auto put_point = [&](const Vec2& p) {
    out.put_fixed(margin + (p.x - lo_x) * scale, 3).put(',').put_fixed(margin + (hi_y - p.y) * scale, 3);
  };
  out.put("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
  out.put("<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 ").put_fixed(total_w, 3).put(' ');
  out.put_fixed(total_h, 3).put("\" width=\"").put_fixed(total_w, 3).put("\" height=\"").put_fixed(total_h, 3);
  out.put("\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n");

  std::vector<int> cls(mesh.triangles.size());
  std::array<std::size_t, kClasses> count{};
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    cls[t] = angle_class(min_angle_degrees(mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]));
    ++count[cls[t]];
  }
  for (int k = 0; k < kClasses; ++k) {
    if (count[k] == 0) continue;
    out.put("<g fill=\"").put(kColours[k]).put("\" stroke=\"#333333\" stroke-width=\"0.5\" stroke-linejoin=\"round\">\n");
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      if (cls[t] != k) continue;
      out.put("<polygon points=\"");
      for (int i = 0; i < 3; ++i) {
        if (i > 0) out.put(' ');
        put_point(mesh.vertices[mesh.triangles[t][i]]);
      }
      out.put("\"/>\n");
    }
    out.put("</g>\n");
  }
  if (!mesh.edges.empty()) {
    out.put("<g stroke=\"black\" stroke-width=\"2.5\" stroke-linecap=\"round\" fill=\"none\">\n");
    for (const auto& e : mesh.edges) {
      out.put("<polyline points=\"");
      put_point(mesh.vertices[e[0]]);
      out.put(' ');
      put_point(mesh.vertices[e[1]]);
      out.put("\"/>\n");
    }
    out.put("</g>\n");
  }
  // Legend: one swatch per class with its triangle count.
  const double y = pic_h + 2 * margin + 5;
  out.put("<g font-family=\"sans-serif\" font-size=\"11\">\n");
  for (int k = 0; k < kClasses; ++k) {
    const double x = margin + 90.0 * k;
    out.put("<rect x=\"").put_fixed(x, 3).put("\" y=\"").put_fixed(y, 3).put("\" width=\"14\" height=\"14\" fill=\"");
    out.put(kColours[k]).put("\" stroke=\"#333333\"/>\n<text x=\"").put_fixed(x + 18, 3).put("\" y=\"");
    out.put_fixed(y + 11, 3).put("\">").put_int(10 * k).put('-').put_int(10 * k + 10).put("&#176;: ");
    out.put_int(static_cast<std::int64_t>(count[k])).put("</text>\n");
  }
  out.put("<text x=\"").put_fixed(margin, 3).put("\" y=\"").put_fixed(y + 30, 3);
  out.put("\">smallest angle per triangle; bold: input edges</text>\n</g>\n</svg>\n");
  out.flush();
  file.commit();
}

}  // namespace pqmesh::detail
