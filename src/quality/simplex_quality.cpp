// Shape measures of one triangle or tetrahedron (thesis ch. 3;
// docs/algorithm/quality.md "Quality measures").
//
// Everything here is a construction in double except the few yes/no questions
// whose answer changes WHICH formula applies (is the simplex degenerate, is a
// triangle angle obtuse, does an edge's diametral ball hold a vertex): those go
// through the exact predicates. The single exception is documented at
// face_ball_contains(): a measurement tolerance, never a meshing decision.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "predicates/predicates.hpp"
#include "pqmesh/quality.hpp"
#include "quality/tetrahedron_aspect_within.hpp"
#include "quality/tetrahedron_min_dihedral.hpp"
#include "quality/tetrahedron_shape.hpp"

namespace pqmesh {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kDeg = 180.0 / std::numbers::pi;

constexpr double sq(double v) { return v * v; }
constexpr double norm2(Vec3 v) { return dot(v, v); }

// The unsigned value |v| carrying the exact sign s (Zero -> exactly 0). Used so
// that the sign of a reported area/volume always agrees with the exact orient
// predicate, even when the double determinant rounds the other way.
double with_sign(double v, Sign s) {
  switch (s) {
    case Sign::Positive: return std::abs(v);
    case Sign::Negative: return -std::abs(v);
    case Sign::Zero: break;
  }
  return 0.0;
}

// ---- triangles ----

// `circum` is the circumradius, passed in so that a caller holding it does not
// recompute it and so that R_enc <= R holds exactly in floating point.
double tri_enclosing_radius(Vec2 a, Vec2 b, Vec2 c, double circum) {
  // The smallest enclosing circle of a triangle with a right or obtuse angle is
  // the diametral circle of the edge opposite that angle (the longest edge);
  // otherwise it is the circumcircle. The angle test is exact (dot_sign).
  if (dot_sign(a, b, c) != Sign::Positive) return 0.5 * norm(c - b);
  if (dot_sign(b, c, a) != Sign::Positive) return 0.5 * norm(a - c);
  if (dot_sign(c, a, b) != Sign::Positive) return 0.5 * norm(b - a);
  return circum;
}

// Which of N angles atan2(y_i, x_i) can be the smallest or the largest
// computed value, judged by keys that order the angles: `separated(k_i, k_j)`
// must prove that the EXACT angle i is below the exact angle j by a gap far
// above the few-ulp error of atan2 and of the keys, so that the computed
// angles are strictly ordered the same way. lo is the first smallest key, hi
// the last largest (the next index when all keys are equal); both are always
// needed. Any other angle whose key is separated from both (above lo's, below
// hi's) lies strictly between two needed angles and is neither extreme, so
// the min / max over the needed angles are the same doubles as over all N
// (the quality fields evaluate this for every element of a mesh; atan2 is
// their costliest call). A key that is NaN separates nothing: that angle is
// needed (and a NaN first key makes every angle needed).
template <int N>
struct ExtremeCandidates {
  int lo = 0, hi = 0;
  std::array<bool, N> needed{};
};

template <int N, class Separated>
ExtremeCandidates<N> extreme_candidates(const std::array<double, N>& key, Separated separated) {
  ExtremeCandidates<N> c;
  for (int i = 1; i < N; ++i) {
    if (key[i] < key[c.lo]) c.lo = i;
    if (key[i] >= key[c.hi]) c.hi = i;
  }
  if (c.lo == c.hi) c.hi = (c.lo + 1) % N;  // all keys equal (or a NaN first): none separated below
  for (int i = 0; i < N; ++i)
    c.needed[i] = i == c.lo || i == c.hi || !(separated(key[c.lo], key[i]) && separated(key[i], key[c.hi]));
  return c;
}

// The smallest and largest of the three angles angle_between(b - a, c - a),
// angle_between(c - b, a - b), angle_between(a - c, b - c), as the same
// doubles std::min / std::max of all three would give, with fewer atan2 calls:
//   * two angles whose atan2 arguments are the same doubles have the same
//     value (a right isosceles half-square: its two 45 degree angles);
//   * keys: the three squared edge lengths (opposite_a = |bc|^2, ...); two of
//     them differing by a factor of at least 1 + 2^-20 order the exact
//     opposite angles (law of sines) with relative gaps far above the few-ulp
//     error of the computed ones (extreme_candidates), so the angle opposite
//     the middle edge is skipped when it is separated from both others.
//     (A measurement, not a decision: should rounding ever reorder such
//     angles, the reported extreme moves by that rounding only.)
struct MinMax {
  double min, max;
};

MinMax min_max_angle(Vec2 a, Vec2 b, Vec2 c, double opposite_a, double opposite_b, double opposite_c) {
  const Vec2 u[3] = {b - a, c - b, a - c}, w[3] = {c - a, a - b, b - c};
  double y[3], x[3];
  for (int i = 0; i < 3; ++i) {
    y[i] = std::abs(cross(u[i], w[i]));  // angle_between's atan2 arguments
    x[i] = dot(u[i], w[i]);
  }
  constexpr double kGap = 1 + 0x1p-20;
  const auto pick = extreme_candidates<3>({opposite_a, opposite_b, opposite_c},
                                          [](double below, double above) { return below * kGap <= above; });
  const int lo = pick.lo, hi = pick.hi, mid = 3 - lo - hi;
  double value[3] = {0, 0, 0};
  bool known[3] = {false, false, false};
  const auto angle = [&](int i) {
    if (known[i]) return value[i];
    for (int j = 0; j < 3; ++j)
      if (known[j] && y[j] == y[i] && x[j] == x[i]) {
        known[i] = true;
        return value[i] = value[j];
      }
    known[i] = true;
    return value[i] = std::atan2(y[i], x[i]);
  };
  const double v_lo = angle(lo), v_hi = angle(hi);
  if (!pick.needed[mid]) return {std::min(v_lo, v_hi), std::max(v_lo, v_hi)};
  const double v_mid = angle(mid);
  return {std::min({v_lo, v_mid, v_hi}), std::max({v_lo, v_mid, v_hi})};
}

// ---- tetrahedra ----

// face_ball_contains and its measurement slack: tetrahedron_shape.hpp.

// What the face-ball filter (tet_enclosing_radius) needs of a tetrahedron with a finite
// circumsphere, computed as tetrahedron_quality / circumradius compute them:
// u = b - a, v = c - a, w = d - a, the face area vectors n (opposite a, b, c,
// d: cross(d - b, c - b), cross(v, w), cross(w, u), cross(u, v)), det =
// u . n[1], and the circumcentre relative to a, x = (0.5 / det) (|u|^2 n[1] +
// |v|^2 n[2] + |w|^2 n[3]).
struct CircumFrame {
  std::array<Vec3, 4> n;
  Vec3 u, x;
  double det;
};

CircumFrame circum_frame(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  CircumFrame f{};
  f.u = b - a;
  const Vec3 v = c - a, w = d - a;
  f.n = {cross(d - b, c - b), cross(v, w), cross(w, f.u), cross(f.u, v)};
  f.det = dot(f.u, f.n[1]);
  f.x = (0.5 / f.det) * (norm2(f.u) * f.n[1] + norm2(v) * f.n[2] + norm2(w) * f.n[3]);
  return f;
}

// Face-ball filter: true when the candidate ball of face l (its circumcircle's
// ball) provably FAILS face_ball_contains(centre, r2, p[l]) as computed below,
// so the face needs no construction. Geometry: for a tetrahedron with
// circumcentre C, the face-l ball has centre C_l (C projected onto the face
// plane) and r_l^2 = R^2 - h^2, h the signed distance of C from the plane
// towards p[l]; |p[l] - C_l|^2 - r_l^2 = 2 h H = 2 lambda_l H^2 (H the height
// of p[l] over the face, lambda_l = h / H the barycentric coordinate of C).
// The computed test differs from the exact one by the slack (< 2^-33 R^2) plus
// rounding: a face centre off by delta moves |p - C_l|^2 - r_l^2 by
// 2 delta . (p[l] - o); delta is a few ulps of L^3 / |n_l| (L the longest
// edge), the other roundings a few ulps of (L + R)^2 and of the coordinates'
// magnitude M times L. With the conditions below (face not thin: |n_l|^2 >=
// 2^-12 L^4; tetrahedron not flat: det^2 >= 2^-20 L^6, which keeps R below
// 2^11 L and the computed lambda within 2^-30 of the exact one; M <= 2^12 L;
// L^2 in [2^-280, 2^280]: no underflow or overflow) all of that is below
// 2^-32 (L + R)^2, and the filter asks lambda_l >= 2^-20 and lambda_l H^2 >=
// 2^-28 (L + R)^2 (computed): a factor of 8 or more above it. So a skipped
// face would have been rejected, and the result is the same double.
// The per-tetrahedron terms are computed once (make_face_filter); lambda_l
// is n_l . (C - q) times the rounded 1 / det (a few ulps more, covered by the
// margin), q any vertex of face l (a for l > 0, b for l = 0).
struct FaceFilter {
  const CircumFrame* frame = nullptr;  // null: no filter
  double inv_det = 0, det2 = 0, thin = 0, bound = 0;  // 1/det, det^2, 2^-12 L^4, 2^-28 (L + R)^2
  bool skip(int l) const {
    const Vec3& n = frame->n[static_cast<std::size_t>(l)];
    const double n2 = norm2(n);
    if (n2 < thin) return false;
    const double lambda = dot(n, l == 0 ? frame->x - frame->u : frame->x) * inv_det;
    return lambda >= 0x1p-20 && lambda * det2 >= bound * n2;
  }
};

FaceFilter make_face_filter(const std::array<Vec3, 4>& p, double circum_r, const CircumFrame* frame, double longest2) {
  FaceFilter f;
  if (frame == nullptr || !std::isfinite(circum_r) || !(longest2 >= 0x1p-280 && longest2 <= 0x1p280)) return f;
  double m = 0;  // largest coordinate magnitude
  for (const Vec3& q : p) m = std::max({m, std::abs(q.x), std::abs(q.y), std::abs(q.z)});
  const double det2 = frame->det * frame->det, l3 = longest2 * std::sqrt(longest2);
  if (!(m * m <= 0x1p24 * longest2) || !(det2 >= 0x1p-20 * l3 * l3)) return f;
  const double span = std::sqrt(longest2) + circum_r;
  return {frame, 1.0 / frame->det, det2, 0x1p-12 * longest2 * longest2, 0x1p-28 * span * span};
}

// Smallest enclosing ball of four points (any position, also coplanar or
// coincident). The minimal enclosing ball is the smallest ball through a
// support set of 2, 3 or 4 of the points with its centre in their hull, so it is
// one of: the diametral ball of one of the 6 edges, the circumcircle ball of one
// of the 4 faces (centre in the face plane), or the circumsphere. Every
// candidate that contains all four points is an enclosing ball, hence at least
// as large as the minimal one; the minimal one is a candidate and contains all
// four. So the answer is the smallest candidate that contains all four points.
//
// Only a LONGEST edge can be the answer's diametral edge: if the closed
// diametral ball of edge e holds all four points, every edge has length at
// most |e| (two points of a ball of diameter |e|). So an edge that is provably
// shorter than another needs no (exact) test: it would fail it. "Provably":
// the computed squared lengths c = fl(|d|^2) (d = fl(q - p)) are within a
// relative 5 ulps of the exact ones plus an absolute 2^-1072 of underflow;
// c_e (1 + 2^-40) < c_max with 2^-960 <= c_max <= DBL_MAX (finite) leaves a
// gap of ~2^-40 c_max far above both, so |e| < |longest| exactly. Edges not so
// separated (ties: the grid tetrahedra's equal diagonals, a NaN) take the
// exact test as before. The tested edges' radii are the same doubles
// (0.5 sqrt(c) = 0.5 norm(d)), so the result is bit for bit the same.
// `frame` (null when the circumsphere is not finite) enables FaceFilter.
// The search is split in three parts (tetrahedron_shape reuses the first two
// without the filter): the edge stage, the face balls' construction from
// difference vectors, and tet_enclosing_radius's containment tests.
struct EdgeStage {
  double best;      // min(circum_r, radii of the edges whose diametral ball holds all four)
  double longest2;  // the largest computed squared edge length
};

EdgeStage enclosing_edge_stage(const std::array<Vec3, 4>& p, double circum_r) {
  double best = circum_r;  // +infinity for a flat tetrahedron
  static constexpr int kEdges[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                       {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  std::array<double, 6> length2{};
  double longest2 = 0.0;
  for (int i = 0; i < 6; ++i) {
    length2[i] = norm2(p[kEdges[i][1]] - p[kEdges[i][0]]);
    if (length2[i] > longest2) longest2 = length2[i];
  }
  constexpr double kLengthGap = 1 + 0x1p-40;
  const bool separable = longest2 >= 0x1p-960 && longest2 <= std::numeric_limits<double>::max();
  for (int i = 0; i < 6; ++i) {
    if (separable && length2[i] * kLengthGap < longest2) continue;  // provably shorter: fails
    const auto& e = kEdges[i];
    // Vertex k lies in the closed diametral ball of edge ij iff the angle ikj is
    // right or obtuse: exact.
    if (dot_sign(p[e[2]], p[e[0]], p[e[1]]) != Sign::Positive &&
        dot_sign(p[e[3]], p[e[0]], p[e[1]]) != Sign::Positive) {
      best = std::min(best, 0.5 * std::sqrt(length2[i]));
    }
  }
  return {best, longest2};
}

// The circumcircle ball of the face opposite p[l], relative to the face's first
// vertex o = p[(l + 1) % 4]: centre o + x, squared radius r2. Not `valid` for a
// collinear face (no circumcircle; the edges cover it). x and r2 are computed
// from the face's two difference vectors only.
struct FaceBall {
  Vec3 x;
  double r2;
  bool valid;
};

FaceBall face_ball(const std::array<Vec3, 4>& p, int l) {
  const Vec3 o = p[(l + 1) % 4];
  const Vec3 u = p[(l + 2) % 4] - o;
  const Vec3 v = p[(l + 3) % 4] - o;
  const Vec3 w = cross(u, v);
  const double w2 = norm2(w);
  if (w2 == 0.0) return {{}, 0.0, false};
  // Circumcentre of the face relative to o: x with x.u = |u|^2/2, x.v = |v|^2/2, x.w = 0.
  const Vec3 x = (1.0 / (2.0 * w2)) * cross(norm2(u) * v - norm2(v) * u, w);
  return {x, norm2(x), true};
}

double tet_enclosing_radius(const std::array<Vec3, 4>& p, double circum_r, const CircumFrame* frame) {
  const EdgeStage edges = enclosing_edge_stage(p, circum_r);
  double best = edges.best;
  const FaceFilter filter = make_face_filter(p, circum_r, frame, edges.longest2);
  for (int l = 0; l < 4; ++l) {  // face opposite vertex l
    if (filter.frame != nullptr && filter.skip(l)) continue;
    const FaceBall ball = face_ball(p, l);
    if (!ball.valid) continue;
    const double radius = std::sqrt(ball.r2);
    if (radius < best && face_ball_contains(p[(l + 1) % 4] + ball.x, ball.r2, p[l])) best = radius;
  }
  return best;
}

}  // namespace

// ---------------------------------------------------------------------------

double signed_area(Vec2 a, Vec2 b, Vec2 c) {
  return with_sign(0.5 * cross(b - a, c - a), orient2d(a, b, c));
}

double signed_volume(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  return with_sign(dot(cross(b - a, c - a), d - a) / 6.0, orient3d(a, b, c, d));
}

double inradius(Vec2 a, Vec2 b, Vec2 c) {
  const double s = 0.5 * (norm(b - a) + norm(c - b) + norm(a - c));
  const double area = std::abs(signed_area(a, b, c));
  return area == 0.0 ? 0.0 : area / s;
}

double inradius(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  // r = 3V / S: the tetrahedron is the union of four cones from the incentre
  // over the faces, each of height r.
  const double faces = 0.5 * (norm(cross(d - b, c - b)) + norm(cross(c - a, d - a)) +
                              norm(cross(d - a, b - a)) + norm(cross(b - a, c - a)));
  const double vol = std::abs(signed_volume(a, b, c, d));
  return vol == 0.0 ? 0.0 : 3.0 * vol / faces;
}

double circumradius(Vec2 a, Vec2 b, Vec2 c) {
  // R = (product of the edge lengths) / (4 A).
  const double area = std::abs(signed_area(a, b, c));
  if (area == 0.0) return kInf;
  return norm(b - a) * norm(c - b) * norm(a - c) / (4.0 * area);
}

double circumradius(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  if (orient3d(a, b, c, d) == Sign::Zero) return kInf;
  const Vec3 u = b - a, v = c - a, w = d - a;
  const double det = dot(u, cross(v, w));
  if (det == 0.0) return kInf;
  // Centre x relative to a solves x.u = |u|^2/2, x.v = |v|^2/2, x.w = |w|^2/2.
  const Vec3 x = (0.5 / det) * (norm2(u) * cross(v, w) + norm2(v) * cross(w, u) + norm2(w) * cross(u, v));
  return norm(x);
}

double enclosing_radius(Vec2 a, Vec2 b, Vec2 c) { return tri_enclosing_radius(a, b, c, circumradius(a, b, c)); }

double enclosing_radius(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const double circum = circumradius(a, b, c, d);
  if (!std::isfinite(circum)) return tet_enclosing_radius({a, b, c, d}, circum, nullptr);
  const CircumFrame frame = circum_frame(a, b, c, d);
  return tet_enclosing_radius({a, b, c, d}, circum, &frame);
}

TriQuality triangle_quality(Vec2 a, Vec2 b, Vec2 c) {
  TriQuality q{};
  const Vec2 ab = b - a, bc = c - b, ca = a - c;
  const double lab = norm(ab), lbc = norm(bc), lca = norm(ca);
  const Sign orientation = orient2d(a, b, c);
  q.area = with_sign(0.5 * cross(ab, c - a), orientation);
  if (orientation == Sign::Zero) {
    // Degenerate (collinear or coincident): its angles are 0, 0, 180.
    q.min_angle_deg = 0.0;
    q.max_angle_deg = 180.0;
    q.aspect_ratio = q.sphere_ratio = q.radius_edge = kInf;
    return q;
  }
  const MinMax angles = min_max_angle(a, b, c, lbc * lbc, lca * lca, lab * lab);
  q.min_angle_deg = angles.min * kDeg;
  q.max_angle_deg = angles.max * kDeg;
  const double area = std::abs(q.area);
  // A nonzero exact orientation means at least two distinct points, so s > 0
  // and R > 0; a double area that underflowed to 0 yields +infinity, not NaN.
  const double r = area / (0.5 * (lab + lbc + lca));
  const double circum = lab * lbc * lca / (4.0 * area);
  q.aspect_ratio = tri_enclosing_radius(a, b, c, circum) / r;
  q.sphere_ratio = circum / r;
  q.radius_edge = circum / std::min({lab, lbc, lca});
  return q;
}

namespace {

// Everything tetrahedron_quality computes except the minimal enclosing ball:
// the quality with aspect_ratio left 0 (final when `flat`: the exact
// orientation is Zero), the inradius r and the circumradius with its frame
// (`has_frame` when det != 0).
struct TetCore {
  TetQuality q;
  bool flat;
  double r, circum;
  CircumFrame frame;
  bool has_frame;
};

// The face area vectors of tetrahedron abcd and the keys that order the six
// angles between them, shared by tet_core and tetrahedron_min_dihedral so both
// evaluate the same doubles. u = b - a, v = c - a, w = d - a; n holds the area
// vectors of the faces opposite a, b, c, d: each is the gradient of 6 x volume
// with respect to that vertex, so for a positive tetrahedron all four point
// INTO the tetrahedron (towards the opposite vertex), and for an inverted one
// all four point out. Either way the dihedral angle at the edge shared by faces
// k and l is pi - angle(N_k, N_l).
// Dihedral angle i at the edge of faces k < l (kDihedralPair[i]) is
// pi - angle_between(n[k], n[l]) = pi - atan2(y_i, x_i), y_i = |n_k x n_l|,
// x_i = n_k . n_l. Keys for extreme_candidates: -cos of the exact angle
// between the (double) normals, -x_i / (|n_k| |n_l|), increasing on [0, pi]
// and changing by at most the change of the angle (its derivative is
// sin <= 1). Keys kCosGap = 2^-20 apart thus order the exact angles with a gap
// of nearly 2^-20, far above the error of the keys (a dot product, a square
// root and three roundings: a few ulps of 1) and of the computed angles
// (y_i and x_i are within a few ulps of |n_k| |n_l| of the exact sine and
// cosine terms, so atan2(y_i, x_i) is within a few ulps of pi of the exact
// angle) -- as long as |n_k|^2 and |n_l|^2 lie in [2^-500, 2^500], so that
// nothing underflows or overflows; otherwise the key is NaN and the angle
// computed. pi - phi rounds monotonically. So the dihedral angles that `pick`
// skips lie strictly between computed ones, and y_i (a cross product and a
// square root) is computed only for the angles a caller evaluates
// (dihedral_angle).
constexpr int kDihedralPair[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
constexpr double kCosGap = 0x1p-20;

struct FaceVectors {
  Vec3 u, v, w;
  std::array<Vec3, 4> n;
  std::array<double, 4> n2, nn;  // |n_k|^2, |n_k|
};

struct DihedralKeys : FaceVectors {
  std::array<double, 6> xs, key;  // x_i and the key of angle i
  ExtremeCandidates<6> pick;
};

// `inline` (here and below): with the hint GCC inlines these into their
// callers; out of line, the struct returned through memory costs
// tetrahedron_min_dihedral about 10% more instructions.
inline FaceVectors face_vectors(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  FaceVectors s;
  s.u = b - a;
  s.v = c - a;
  s.w = d - a;
  s.n = {cross(d - b, c - b), cross(s.v, s.w), cross(s.w, s.u), cross(s.u, s.v)};
  for (int k = 0; k < 4; ++k) {
    s.n2[k] = norm2(s.n[k]);
    s.nn[k] = std::sqrt(s.n2[k]);  // == norm(n[k])
  }
  return s;
}

inline DihedralKeys dihedral_keys(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  DihedralKeys s;
  static_cast<FaceVectors&>(s) = face_vectors(a, b, c, d);
  std::array<double, 4> inv{};
  std::array<bool, 4> in_range{};
  for (int k = 0; k < 4; ++k) {
    in_range[k] = s.n2[k] >= 0x1p-500 && s.n2[k] <= 0x1p500;
    inv[k] = 1.0 / s.nn[k];
  }
  for (int i = 0; i < 6; ++i) {
    const int k = kDihedralPair[i][0], l = kDihedralPair[i][1];
    s.xs[i] = dot(s.n[k], s.n[l]);
    s.key[i] = in_range[k] && in_range[l] ? -(s.xs[i] * inv[k]) * inv[l] : std::numeric_limits<double>::quiet_NaN();
  }
  s.pick = extreme_candidates<6>(s.key, [](double below, double above) { return below + kCosGap <= above; });
  return s;
}

// Dihedral angle i of the tetrahedron, in radians: pi - atan2(y_i, x_i).
double dihedral_angle(const DihedralKeys& s, int i) {
  // y_i, x_i: angle_between's atan2 arguments
  const double ys = norm(cross(s.n[kDihedralPair[i][0]], s.n[kDihedralPair[i][1]]));
  // atan2(y, +-0) is pi/2 rounded for every y > 0 (C Annex F): the right
  // dihedral angles of the grid tetrahedra skip the call.
  const double phi = s.xs[i] == 0 && ys > 0 ? std::numbers::pi / 2 : std::atan2(ys, s.xs[i]);
  return std::numbers::pi - phi;
}

// The signed volume, the inradius r = 3 |V| / (half the sum of the face
// areas) and the circumradius with its frame (`has_frame` when det != 0,
// else circum = infinity) of a tetrahedron of the given nonzero or zero
// orientation, from its face vectors: the doubles tetrahedron_quality reports
// and divides by.
struct TetRadii {
  double volume, r, circum;
  CircumFrame frame;
  bool has_frame;
};

inline TetRadii tet_radii(const FaceVectors& s, Sign orientation) {
  const std::array<Vec3, 4>& n = s.n;
  const double det = dot(s.u, n[1]);
  TetRadii t{with_sign(det / 6.0, orientation), 0.0, kInf, {n, s.u, {}, det}, det != 0.0};
  const double faces = 0.5 * (s.nn[0] + s.nn[1] + s.nn[2] + s.nn[3]);
  t.r = 3.0 * std::abs(t.volume) / faces;
  if (t.has_frame) {  // the same doubles circum_frame(a, b, c, d) gives
    t.frame.x = (0.5 / det) * (norm2(s.u) * n[1] + norm2(s.v) * n[2] + norm2(s.w) * n[3]);
    t.circum = norm(t.frame.x);
  }
  return t;
}

TetCore tet_core(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  TetQuality q{};
  const Sign orientation = orient3d(a, b, c, d);
  const DihedralKeys s = dihedral_keys(a, b, c, d);
  const Vec3 &u = s.u, &v = s.v, &w = s.w;
  const TetRadii radii = tet_radii(s, orientation);
  q.volume = radii.volume;
  if (orientation == Sign::Zero) {
    q.min_dihedral_deg = 0.0;
    q.max_dihedral_deg = 180.0;
    q.aspect_ratio = q.sphere_ratio = q.radius_edge = kInf;
    return {q, true, 0.0, kInf, {}, false};
  }
  // The folds over the angles `pick` needs give the same doubles as folding all six.
  double min_dihedral = kInf, max_dihedral = 0.0;
  for (int i = 0; i < 6; ++i) {
    if (!s.pick.needed[i]) continue;
    const double theta = dihedral_angle(s, i);
    min_dihedral = std::min(min_dihedral, theta);
    max_dihedral = std::max(max_dihedral, theta);
  }
  q.min_dihedral_deg = min_dihedral * kDeg;
  q.max_dihedral_deg = max_dihedral * kDeg;

  const double shortest2 = std::min({norm2(u), norm2(v), norm2(w), norm2(c - b), norm2(d - b), norm2(d - c)});
  q.sphere_ratio = radii.circum / radii.r;
  q.radius_edge = radii.circum / std::sqrt(shortest2);
  return {q, false, radii.r, radii.circum, radii.frame, radii.has_frame};
}

}  // namespace

double tetrahedron_min_dihedral(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  return tetrahedron_min_dihedral(a, b, c, d, orient3d(a, b, c, d));
}

double tetrahedron_min_dihedral(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Sign orientation) {
  if (orientation == Sign::Zero) return 0.0;
  // tet_core's normals and keys (dihedral_keys). The smallest dihedral angle
  // is pi minus the largest angle phi between normals; the keys increase with
  // phi, so (as in extreme_candidates) only the last largest key hi and the
  // keys not separated from it can give the largest computed phi: every other
  // angle's computed phi is strictly below hi's, and pi - phi rounds
  // monotonically.
  const DihedralKeys s = dihedral_keys(a, b, c, d);
  const int hi = s.pick.hi;
  double min_dihedral = kInf;
  for (int i = 0; i < 6; ++i) {
    if (!s.pick.needed[i] || (i != hi && s.key[i] + kCosGap <= s.key[hi])) continue;
    min_dihedral = std::min(min_dihedral, dihedral_angle(s, i));
  }
  return min_dihedral * kDeg;
}

bool tetrahedron_aspect_within(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Sign orientation, double limit) {
  if (orientation == Sign::Zero) return kInf <= limit;  // tetrahedron_quality's flat aspect ratio
  const TetRadii radii = tet_radii(face_vectors(a, b, c, d), orientation);
  // The enclosing radius tet_enclosing_radius computes is never above the
  // circumradius it starts from (a min fold), so the aspect ratio is never
  // above the sphere ratio circum / r (the same double tet_core reports).
  if (radii.circum / radii.r <= limit) return true;
  const double enclosing = tet_enclosing_radius({a, b, c, d}, radii.circum, radii.has_frame ? &radii.frame : nullptr);
  return enclosing / radii.r <= limit;
}

TetQuality tetrahedron_quality(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const TetCore core = tet_core(a, b, c, d);
  TetQuality q = core.q;
  if (core.flat) return q;
  // The circumsphere is one of the candidates, with the very same double value,
  // so aspect_ratio <= sphere_ratio holds exactly in floating point too.
  q.aspect_ratio = tet_enclosing_radius({a, b, c, d}, core.circum, core.has_frame ? &core.frame : nullptr) / core.r;
  return q;
}

TetShape tetrahedron_shape(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const TetCore core = tet_core(a, b, c, d);
  TetShape s;
  s.quality = core.q;
  s.flat = core.flat;
  if (core.flat) return s;
  s.r = core.r;
  const std::array<Vec3, 4> p = {a, b, c, d};
  s.best_edges = enclosing_edge_stage(p, core.circum).best;
  for (int l = 0; l < 4; ++l) {
    const FaceBall ball = face_ball(p, l);
    if (!ball.valid) continue;
    const double radius = std::sqrt(ball.r2);
    // best never exceeds best_edges: a ball not below it never wins (nor a NaN).
    if (!(radius < s.best_edges)) continue;
    s.balls[static_cast<std::size_t>(s.ball_count++)] = {ball.x, ball.r2, radius, (l + 1) % 4, l};
  }
  return s;
}

}  // namespace pqmesh
