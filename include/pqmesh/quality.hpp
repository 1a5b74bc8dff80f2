#pragma once
// Element quality measures of thesis ch. 3 (docs/algorithm/quality.md "Quality
// measures"), per element and as summaries with histograms.
//
//   aspect ratio   = R_enc / r, R_enc the radius of the SMALLEST ENCLOSING ball
//                    of the simplex (ch. 3 "Aspect ratio": not the circumsphere in
//                    general), r the inradius. Equilateral triangle 2, regular
//                    tetrahedron 3; in d dimensions R_enc >= d r always.
//   sphere ratio   = circumradius / inradius (ch. 3 "Sphere ratio"). Since the
//                    circumball encloses the simplex, sphere ratio >= aspect ratio.
//   radius-edge    = circumradius / shortest edge.
//   angles         = triangle angles, or the six dihedral angles of a tetrahedron,
//                    in degrees.
//
// Orientation: sizes (area, volume) are signed with the convention of mesh.hpp
// (positive = counter-clockwise / positive volume); every other measure uses the
// unsigned size, so an inverted element reports its shape and a negative size.
//
// Degenerate elements (exactly zero area/volume, decided by the exact orient
// predicates): aspect ratio, sphere ratio and radius-edge ratio are +infinity,
// the minimum angle is 0 and the maximum 180 degrees. Nothing throws for them.
//
// The measures are constructions in double; they never drive a meshing decision.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "pqmesh/mesh.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh {

struct TriQuality {
  double min_angle_deg;
  double max_angle_deg;
  double aspect_ratio;
  double sphere_ratio;
  double radius_edge;
  double area;  // signed
};

struct TetQuality {
  double min_dihedral_deg;
  double max_dihedral_deg;
  double aspect_ratio;
  double sphere_ratio;
  double radius_edge;
  double volume;  // signed
};

// --- single simplices -------------------------------------------------------

TriQuality triangle_quality(Vec2 a, Vec2 b, Vec2 c);
TetQuality tetrahedron_quality(Vec3 a, Vec3 b, Vec3 c, Vec3 d);

// Signed area (positive when a, b, c are counter-clockwise) and signed volume
// det(b - a, c - a, d - a) / 6.
double signed_area(Vec2 a, Vec2 b, Vec2 c);
double signed_volume(Vec3 a, Vec3 b, Vec3 c, Vec3 d);

// Inradius r = |A| / s (s the half perimeter) in 2D, r = 3 |V| / (sum of the
// face areas) in 3D. Zero for a degenerate simplex.
double inradius(Vec2 a, Vec2 b, Vec2 c);
double inradius(Vec3 a, Vec3 b, Vec3 c, Vec3 d);

// Circumradius; +infinity for a degenerate simplex (exact orient == 0).
double circumradius(Vec2 a, Vec2 b, Vec2 c);
double circumradius(Vec3 a, Vec3 b, Vec3 c, Vec3 d);

// Radius of the smallest enclosing circle / ball. Triangle: half the longest
// edge when some angle is right or obtuse (decided exactly), the circumradius
// otherwise. Tetrahedron: the smallest of the candidate balls (6 edge diametral
// balls, 4 face circumcircle balls, the circumsphere) that contain all four
// points; for a degenerate (flat) tetrahedron only the edge and face candidates
// are used (the circumsphere does not exist).
double enclosing_radius(Vec2 a, Vec2 b, Vec2 c);
double enclosing_radius(Vec3 a, Vec3 b, Vec3 c, Vec3 d);

// --- meshes -----------------------------------------------------------------

// One entry per element, in element order. Throws InvalidInput
// (ErrorCode::IndexOutOfRange, ids = {element, vertex id}) for an element that
// names a vertex that does not exist.
std::vector<TriQuality> element_quality(const TriMesh2& mesh);
std::vector<TetQuality> element_quality(const TetMesh3& mesh);

// --- summaries ----------------------------------------------------------------

// counts[i] counts the values v with edges[i] <= v < edges[i + 1]; values below
// edges.front() go to the first bin and values >= edges.back() (including
// +infinity and the closing edge itself, e.g. exactly 180 degrees) to the last,
// so the counts always add up to the number of elements. NaN never occurs for
// the measures above.
struct Histogram {
  std::string measure;
  std::vector<double> edges;  // counts.size() + 1 increasing values; the last may be +infinity
  std::vector<std::int64_t> counts;
};

// Over all elements; argmin/argmax are the FIRST element attaining the extreme
// (deterministic). The mean is +infinity when some value is +infinity. For an
// empty mesh all values are 0 and argmin = argmax = -1.
struct Stat {
  double min = 0, max = 0, mean = 0;
  std::int64_t argmin = -1, argmax = -1;
};

struct QualityReport {
  int dimension = 0;              // 2 (triangles) or 3 (tetrahedra)
  std::int64_t elements = 0;
  std::int64_t degenerate = 0;    // exactly zero area/volume
  std::int64_t inverted = 0;      // negative area/volume (wrong orientation)
  Stat min_angle;                 // min triangle angle or min dihedral angle, degrees
  Stat max_angle;                 // max triangle angle or max dihedral angle, degrees
  Stat aspect_ratio;
  Stat sphere_ratio;
  Stat radius_edge;
  Stat size;                      // signed area or volume
  double total_size = 0;          // sum of the signed sizes
  // Bins of 5 degrees over [0, 90] for the minimum triangle angle, [0, 180] for
  // the minimum dihedral and for every maximum angle.
  Histogram min_angle_hist;
  Histogram max_angle_hist;
  // Fixed bins relative to the ideal value q = 2 (triangles) or 3 (tetrahedra):
  // edges q x {1, 1.1, 1.25, 1.5, 2, 3, 5, 10, 100, +infinity}.
  Histogram aspect_hist;

  // Compact human-readable report: a table of the statistics and the
  // histograms as ASCII bars (empty outer bins trimmed). Deterministic.
  std::string to_text() const;
};

QualityReport quality_report(const TriMesh2& mesh);
QualityReport quality_report(const TetMesh3& mesh);
QualityReport quality_report(std::span<const TriQuality> elements);
QualityReport quality_report(std::span<const TetQuality> elements);

// A self-contained SVG bar chart of a histogram (for `pqmesh quality --svg`).
std::string histogram_svg(const Histogram& histogram, const std::string& title);

}  // namespace pqmesh
