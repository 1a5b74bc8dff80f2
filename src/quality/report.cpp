// Summaries of element quality: statistics with arg-extremes and fixed-bin
// histograms, accumulated in one streaming pass (no per-element storage).
#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "pqmesh/quality.hpp"
#include "quality/element_access.hpp"

namespace pqmesh {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct StatAccumulator {
  Stat s;
  double sum = 0;
  std::int64_t n = 0;

  void add(double v, std::int64_t index) {
    if (n == 0 || v < s.min) {  // strict: the first element attaining the extreme wins
      s.min = v;
      s.argmin = index;
    }
    if (n == 0 || v > s.max) {
      s.max = v;
      s.argmax = index;
    }
    sum += v;
    ++n;
  }
  Stat finish() const {
    Stat out = s;
    out.mean = n == 0 ? 0.0 : sum / static_cast<double>(n);
    return out;
  }
};

Histogram make_histogram(std::string measure, std::vector<double> edges) {
  Histogram h;
  h.measure = std::move(measure);
  h.counts.assign(edges.size() - 1, 0);
  h.edges = std::move(edges);
  return h;
}

Histogram uniform_histogram(std::string measure, double lo, double hi, double width) {
  std::vector<double> edges;
  const int bins = static_cast<int>((hi - lo) / width + 0.5);
  for (int i = 0; i <= bins; ++i) edges.push_back(lo + width * i);
  return make_histogram(std::move(measure), std::move(edges));
}

Histogram aspect_histogram(double ideal) {
  std::vector<double> edges;
  for (double f : {1.0, 1.1, 1.25, 1.5, 2.0, 3.0, 5.0, 10.0, 100.0}) edges.push_back(ideal * f);
  edges.push_back(kInf);
  return make_histogram("aspect ratio", std::move(edges));
}

// The bin convention of Histogram (see quality.hpp): clamp below to the first
// bin, and put values >= the last edge (or NaN) into the last bin.
void add_to(Histogram& h, double v) {
  const auto it = std::upper_bound(h.edges.begin(), h.edges.end(), v);
  std::ptrdiff_t bin = (it - h.edges.begin()) - 1;
  const auto last = static_cast<std::ptrdiff_t>(h.counts.size()) - 1;
  bin = std::clamp<std::ptrdiff_t>(bin, 0, last);
  ++h.counts[static_cast<std::size_t>(bin)];
}

double min_angle_of(const TriQuality& q) { return q.min_angle_deg; }
double max_angle_of(const TriQuality& q) { return q.max_angle_deg; }
double size_of(const TriQuality& q) { return q.area; }
double min_angle_of(const TetQuality& q) { return q.min_dihedral_deg; }
double max_angle_of(const TetQuality& q) { return q.max_dihedral_deg; }
double size_of(const TetQuality& q) { return q.volume; }

template <class Q>
class ReportBuilder {
 public:
  explicit ReportBuilder(int dimension) {
    report_.dimension = dimension;
    if (dimension == 2) {
      report_.min_angle_hist = uniform_histogram("min angle (deg)", 0, 90, 5);
      report_.max_angle_hist = uniform_histogram("max angle (deg)", 0, 180, 5);
      report_.aspect_hist = aspect_histogram(2.0);
    } else {
      report_.min_angle_hist = uniform_histogram("min dihedral (deg)", 0, 180, 5);
      report_.max_angle_hist = uniform_histogram("max dihedral (deg)", 0, 180, 5);
      report_.aspect_hist = aspect_histogram(3.0);
    }
  }

  void add(const Q& q) {
    const std::int64_t i = report_.elements++;
    min_angle_.add(min_angle_of(q), i);
    max_angle_.add(max_angle_of(q), i);
    aspect_.add(q.aspect_ratio, i);
    sphere_.add(q.sphere_ratio, i);
    radius_edge_.add(q.radius_edge, i);
    const double size = size_of(q);
    size_.add(size, i);
    if (size == 0.0) ++report_.degenerate;  // exact zero: set from the exact predicate
    if (size < 0.0) ++report_.inverted;
    add_to(report_.min_angle_hist, min_angle_of(q));
    add_to(report_.max_angle_hist, max_angle_of(q));
    add_to(report_.aspect_hist, q.aspect_ratio);
  }

  QualityReport finish() {
    report_.min_angle = min_angle_.finish();
    report_.max_angle = max_angle_.finish();
    report_.aspect_ratio = aspect_.finish();
    report_.sphere_ratio = sphere_.finish();
    report_.radius_edge = radius_edge_.finish();
    report_.size = size_.finish();
    report_.total_size = size_.sum;
    return std::move(report_);
  }

 private:
  QualityReport report_;
  StatAccumulator min_angle_, max_angle_, aspect_, sphere_, radius_edge_, size_;
};

}  // namespace

QualityReport quality_report(std::span<const TriQuality> elements) {
  ReportBuilder<TriQuality> b(2);
  for (const TriQuality& q : elements) b.add(q);
  return b.finish();
}

QualityReport quality_report(std::span<const TetQuality> elements) {
  ReportBuilder<TetQuality> b(3);
  for (const TetQuality& q : elements) b.add(q);
  return b.finish();
}

QualityReport quality_report(const TriMesh2& mesh) {
  ReportBuilder<TriQuality> b(2);
  TriangleQualityMemo memo;
  for (std::size_t e = 0; e < mesh.triangles.size(); ++e) b.add(detail::quality_of_element(mesh, e, memo));
  return b.finish();
}

QualityReport quality_report(const TetMesh3& mesh) {
  ReportBuilder<TetQuality> b(3);
  TetrahedronQualityMemo memo;
  for (std::size_t e = 0; e < mesh.tetrahedra.size(); ++e) b.add(detail::quality_of_element(mesh, e, memo));
  return b.finish();
}

}  // namespace pqmesh
