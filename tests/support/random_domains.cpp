// Seeded random domains (see random_domains.hpp for the contract).
//
// Construction outline.
//  2D: an outer star-shaped loop (random polar angles and radii about the
//      origin, optional spikes: a far vertex between two close near ones,
//      which makes a corner of 1..20 degrees), holes drawn as small star
//      loops and kept only when the exact checks pass, some of them then
//      translated towards their nearest neighbour until the gap is tiny
//      ("near-touching"), again kept only when exact checks pass.
//  3D: the 2D domain extruded (right prism or frustum, see RandomPolyhedron),
//      plus cavities whose footprint is checked like a hole.
// Every rejection redraws from the same stream, so outputs stay a function of
// the seed. Randomness reaches coordinates only through Rng below and
// unit_direction() (no libm), so the outputs are the same on every platform
// with IEEE doubles.
#include "support/random_domains.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <stdexcept>
#include <sstream>
#include <utility>

#include "predicates/predicates.hpp"

namespace pqmesh::test {

namespace {

using Loop = std::vector<Vec2>;

// ---------------------------------------------------------------------------
// Random numbers with a fixed mapping from the generator's 64-bit outputs.

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(mix(seed)) {}
  // Uniform on [0, 1): the top 53 bits of one output.
  double unit() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
  // Uniform integer in [lo, hi] (modulo bias below 2^-50, irrelevant here).
  int integer(int lo, int hi) {
    const auto span = static_cast<std::uint64_t>(hi - lo) + 1;
    return lo + static_cast<int>(engine_() % span);
  }
  bool chance(double p) { return unit() < p; }
  template <class T>
  void shuffle(std::vector<T>& v) {  // Fisher-Yates with our own integer()
    for (int i = static_cast<int>(v.size()) - 1; i > 0; --i) std::swap(v[i], v[integer(0, i)]);
  }

 private:
  // splitmix64 finaliser, so that nearby seeds give unrelated streams.
  static std::uint64_t mix(std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  std::mt19937_64 engine_;
};

constexpr double kPi = 3.14159265358979323846;

// (cos, sin) of 2 pi * turns using + - * / only: reduction to [0, pi/4] by the
// quadrant and octant symmetries, then Taylor series to degree 17 (truncation
// below 1e-17 there).
Vec2 unit_direction(double turns) {
  turns -= std::floor(turns);
  const double q = turns * 4;
  const int quadrant = std::min(3, static_cast<int>(q));
  double x = (q - quadrant) * (kPi / 2);  // in [0, pi/2)
  const bool swap = x > kPi / 4;
  if (swap) x = kPi / 2 - x;
  const double x2 = x * x;
  double s = 0, c = 0, term_s = x, term_c = 1;
  for (int k = 0; k < 9; ++k) {
    s += term_s;
    c += term_c;
    term_s *= -x2 / static_cast<double>((2 * k + 2) * (2 * k + 3));
    term_c *= -x2 / static_cast<double>((2 * k + 1) * (2 * k + 2));
  }
  if (swap) std::swap(s, c);
  switch (quadrant) {
    case 0: return {c, s};
    case 1: return {-s, c};
    case 2: return {-c, -s};
    default: return {s, -c};
  }
}

double snap(double v, int bits) { return std::ldexp(std::round(std::ldexp(v, bits)), -bits); }
Vec2 snap(Vec2 p, int bits) { return {snap(p.x, bits), snap(p.y, bits)}; }

// ---------------------------------------------------------------------------
// Exact checks (orient2d; no tolerances).

bool in_box(Vec2 a, Vec2 b, Vec2 p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

// Closed segments ab and cd share a point.
bool segments_meet(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const Sign d1 = orient2d(a, b, c), d2 = orient2d(a, b, d), d3 = orient2d(c, d, a), d4 = orient2d(c, d, b);
  if (d1 * d2 == Sign::Negative && d3 * d4 == Sign::Negative) return true;
  return (d1 == Sign::Zero && in_box(a, b, c)) || (d2 == Sign::Zero && in_box(a, b, d)) ||
         (d3 == Sign::Zero && in_box(c, d, a)) || (d4 == Sign::Zero && in_box(c, d, b));
}

// A simple closed polygonal curve: no zero-length side, consecutive sides do
// not fold back onto each other, other sides do not meet at all.
bool loop_simple(const Loop& L) {
  const std::size_t n = L.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = L[i], b = L[(i + 1) % n], c = L[(i + 2) % n];
    if (a == b) return false;
    if (orient2d(a, b, c) == Sign::Zero && dot_sign(b, a, c) == Sign::Positive) return false;
  }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent across the closing side
      if (segments_meet(L[i], L[(i + 1) % n], L[j], L[(j + 1) % n])) return false;
    }
  return true;
}

bool loops_disjoint(const Loop& A, const Loop& B) {
  for (std::size_t i = 0; i < A.size(); ++i)
    for (std::size_t j = 0; j < B.size(); ++j)
      if (segments_meet(A[i], A[(i + 1) % A.size()], B[j], B[(j + 1) % B.size()])) return false;
  return true;
}

// Crossing parity of the ray towards +x (half-open rule on the sides' y
// ranges). PRECONDITION: p is not on L.
bool inside_loop(Vec2 p, const Loop& L) {
  bool in = false;
  for (std::size_t i = 0; i < L.size(); ++i) {
    const Vec2 a = L[i], b = L[(i + 1) % L.size()];
    if (a.y <= p.y && p.y < b.y && orient2d(a, b, p) == Sign::Positive) in = !in;
    if (b.y <= p.y && p.y < a.y && orient2d(a, b, p) == Sign::Negative) in = !in;
  }
  return in;
}

// Orientation of a simple loop: the turn at its lowest (then leftmost) vertex,
// which is a strictly convex corner.
Sign loop_turn(const Loop& L) {
  std::size_t k = 0;
  for (std::size_t i = 1; i < L.size(); ++i)
    if (L[i].y < L[k].y || (L[i].y == L[k].y && L[i].x < L[k].x)) k = i;
  const std::size_t n = L.size();
  return orient2d(L[(k + n - 1) % n], L[k], L[(k + 1) % n]);
}

// c sees every side of L from strictly inside (kernel point of a star loop).
bool strict_kernel_point(Vec2 c, const Loop& L) {
  for (std::size_t i = 0; i < L.size(); ++i)
    if (orient2d(c, L[i], L[(i + 1) % L.size()]) != Sign::Positive) return false;
  return true;
}

// Candidate C (simple) fits as a hole or cavity footprint: disjoint from the
// outer loop and every obstacle, strictly inside the outer loop, not inside an
// obstacle and containing none. (Disjoint loops are nested or apart; one
// vertex decides which.)
bool fits(const Loop& C, const Loop& outer, const std::vector<Loop>& obstacles) {
  if (!loop_simple(C) || !loops_disjoint(C, outer) || !inside_loop(C[0], outer)) return false;
  for (const Loop& O : obstacles)
    if (!loops_disjoint(C, O) || inside_loop(C[0], O) || inside_loop(O[0], C)) return false;
  return true;
}

// ---------------------------------------------------------------------------
// Shapes.

double closest_pair(const Loop& A, const std::vector<const Loop*>& B, Vec2& from, Vec2& to);

// The distance (double arithmetic: a sampling criterion, not a validity
// check) from C to the outer loop and every obstacle is at least `clearance`.
bool clear_of(const Loop& C, const Loop& outer, const std::vector<Loop>& obstacles, double clearance) {
  if (clearance <= 0) return true;
  std::vector<const Loop*> others{&outer};
  for (const Loop& O : obstacles) others.push_back(&O);
  Vec2 from, to;
  return closest_pair(C, others, from, to) >= clearance;
}

// Star loop about `centre`: m polar angles with random gaps (each at most
// about 0.45 turn, so the centre is in the kernel), radii in [rmin, rmax].
Loop star_loop(Rng& rng, Vec2 centre, int m, double rmin, double rmax, std::vector<double>* angles_out = nullptr,
               std::vector<double>* radii_out = nullptr) {
  std::vector<double> gaps(m);
  double total = 0;
  for (double& g : gaps) total += g = rng.uniform(0.3, 1.0);
  double t = rng.unit();
  std::vector<double> angles(m), radii(m);
  for (int i = 0; i < m; ++i) {
    angles[i] = t;
    radii[i] = rng.uniform(rmin, rmax);
    t += gaps[i] / total;
  }
  Loop L(m);
  for (int i = 0; i < m; ++i) L[i] = centre + radii[i] * unit_direction(angles[i]);
  if (angles_out) *angles_out = angles;
  if (radii_out) *radii_out = radii;
  return L;
}

// Rebuild a star loop from polar data.
Loop from_polar(Vec2 centre, const std::vector<double>& angles, const std::vector<double>& radii) {
  Loop L(angles.size());
  for (std::size_t i = 0; i < angles.size(); ++i) L[i] = centre + radii[i] * unit_direction(angles[i]);
  return L;
}

// Insert a spike into polar data: in the angular gap after a random vertex,
// the vertices (phi - d, a), (phi, b), (phi + d, a). Outward (a spike): a is
// near the centre, b far, and the corner at the far vertex has half-angle
// atan(a sin d / (b - a cos d)). Inward (a notch, for holes): a is on the rim,
// b deep inside, and the corner outside the loop at the deep vertex has
// half-angle atan(a sin d / (a cos d - b)). Both are solved for d with
// sin d ~ d, cos d ~ 1, tan x ~ x: a corner of the drawn size within a few
// percent, which is all a test corpus needs. Returns false (data unchanged)
// when the gap is too narrow.
bool insert_spike(Rng& rng, std::vector<double>& angles, std::vector<double>& radii, std::vector<char>& locked,
                  double base_radius, double min_deg, double max_deg, bool inward) {
  const int m = static_cast<int>(angles.size());
  const int i = rng.integer(0, m - 1);
  const double lo = angles[i];
  const double gap = (i + 1 < m ? angles[i + 1] : angles[0] + 1.0) - lo;
  const double u = rng.unit();
  const double tip_deg = min_deg + (max_deg - min_deg) * u * u * u;  // biased towards the small end
  const double half = tip_deg * kPi / 360;
  const double a = inward ? base_radius * rng.uniform(0.8, 1.0) : base_radius * rng.uniform(0.3, 0.6);
  const double b = inward ? base_radius * rng.uniform(0.15, 0.5) : base_radius * rng.uniform(0.95, 1.15);
  const double d = half * std::abs(b - a) / a / (2 * kPi);  // in turns
  if (!(d > 0) || 2.2 * d > 0.9 * gap || d > 0.05) return false;
  const double phi = lo + gap * rng.uniform(0.35, 0.65);
  angles.insert(angles.begin() + i + 1, {phi - d, phi, phi + d});
  radii.insert(radii.begin() + i + 1, {a, b, a});
  locked.insert(locked.begin() + i + 1, {1, 1, 1});
  return true;
}

// Closest pair (double constructions) between the vertices of A and the sides
// of the loops in B, and the vertices of B and the sides of A. Returns the
// distance and the pair (from on A, to on B).
double closest_pair(const Loop& A, const std::vector<const Loop*>& B, Vec2& from, Vec2& to) {
  double best = HUGE_VAL;
  auto closest_on = [](Vec2 p, Vec2 a, Vec2 b) {
    const Vec2 ab = b - a;
    const double len2 = dot(ab, ab);
    double t = len2 > 0 ? dot(p - a, ab) / len2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    return a + t * ab;
  };
  auto consider = [&](Vec2 p, Vec2 q, bool p_on_a) {
    const double d = norm(q - p);
    if (d < best) {
      best = d;
      from = p_on_a ? p : q;
      to = p_on_a ? q : p;
    }
  };
  for (const Loop* L : B)
    for (std::size_t j = 0; j < L->size(); ++j) {
      const Vec2 c = (*L)[j], d = (*L)[(j + 1) % L->size()];
      for (std::size_t i = 0; i < A.size(); ++i) {
        const Vec2 a = A[i], b = A[(i + 1) % A.size()];
        consider(a, closest_on(a, c, d), true);
        consider(c, closest_on(c, a, b), false);
      }
    }
  return best;
}

Loop translated(const Loop& L, Vec2 t) {
  Loop out(L);
  for (Vec2& p : out) p = p + t;
  return out;
}

// Move C towards its nearest neighbour so the gap becomes about `gap`; the
// move is snapped to the grid and kept only if the exact checks pass (halving
// it up to 6 times otherwise). Returns the translation applied (0 if none).
Vec2 push_near(Loop& C, const Loop& outer, const std::vector<Loop>& obstacles, double gap, int bits) {
  std::vector<const Loop*> others{&outer};
  for (const Loop& O : obstacles) others.push_back(&O);
  Vec2 from, to;
  const double dist = closest_pair(C, others, from, to);
  if (!(dist > gap)) return {};
  Vec2 move = ((dist - gap) / dist) * (to - from);
  for (int attempt = 0; attempt < 7; ++attempt, move = 0.5 * move) {
    const Vec2 t = snap(move, bits);
    if (t == Vec2{}) break;
    Loop moved = translated(C, t);
    if (fits(moved, outer, obstacles)) {
      C = std::move(moved);
      return t;
    }
  }
  return {};
}

// The 2D domain in unscaled coordinates (outer radius <= 1.15, grid 2^-bits).
PolygonWithHoles make_polygon(Rng& rng, const PolygonOptions& o) {
  const int bits = o.grid_bits;
  PolygonWithHoles out;
  // Outer loop.
  Loop outer;
  for (int attempt = 0;; ++attempt) {
    const int n = rng.integer(std::max(3, o.min_vertices), std::max(o.min_vertices, o.max_vertices));
    std::vector<double> angles, radii;
    star_loop(rng, {}, n, 0.35, 1.0, &angles, &radii);
    // Occasional deep notches make the loop strongly nonconvex.
    int notches = 0;
    for (double& r : radii)
      if (rng.chance(o.notch_probability)) {
        r *= 0.3;
        ++notches;
      }
    int spikes = 0;
    std::vector<char> locked(angles.size(), 0);  // spike vertices keep their fine position
    if (rng.chance(o.spike_probability)) {
      const int want = rng.integer(1, std::max(1, o.max_spikes));
      for (int s = 0; s < want; ++s)
        spikes += insert_spike(rng, angles, radii, locked, 1.0, o.min_spike_degrees, o.max_spike_degrees, false);
    }
    Loop L = from_polar({}, angles, radii);
    for (Vec2& p : L) p = snap(p, bits);
    // Coarse snapping moves a vertex by up to 1/16: never a spike vertex or a
    // neighbour of one (that could sharpen the spike far below the requested
    // minimum angle).
    int snapped = 0;
    Loop coarse = L;
    const std::size_t n_all = L.size();
    for (std::size_t i = 0; i < n_all; ++i) {
      const bool near_spike = locked[i] || locked[(i + 1) % n_all] || locked[(i + n_all - 1) % n_all];
      if (rng.chance(o.snap_probability) && !near_spike) {
        const Vec2 q = snap(coarse[i], 3);
        snapped += !(q == coarse[i]);
        coarse[i] = q;
      }
    }
    if (snapped > 0 && loop_simple(coarse) && loop_turn(coarse) == Sign::Positive) {
      outer = std::move(coarse);
      out.snapped = snapped;
      out.spikes = spikes;
      out.notches = notches;
      break;
    }
    if (loop_simple(L) && loop_turn(L) == Sign::Positive) {
      outer = std::move(L);
      out.spikes = spikes;
      out.notches = notches;
      break;
    }
    if (attempt > 1000) throw std::logic_error("random_polygon: no valid outer loop");  // never observed
  }

  // Holes.
  std::vector<Loop> holes;
  std::vector<Vec2> centres;
  const int want_holes = rng.integer(0, std::max(0, o.max_holes));
  for (int h = 0, attempts = 0; h < want_holes && attempts < 60 * want_holes; ++attempts) {
    const Vec2 c = snap(Vec2{rng.uniform(-0.8, 0.8), rng.uniform(-0.8, 0.8)}, bits);
    const double rho = rng.uniform(o.min_hole_radius, o.max_hole_radius);
    const int m = rng.integer(std::max(3, o.min_hole_vertices), std::max(o.min_hole_vertices, o.max_hole_vertices));
    std::vector<double> angles, radii;
    star_loop(rng, c, m, 0.45 * rho, rho, &angles, &radii);
    // A notch: a thin wedge of the domain poking into the hole (a sharp
    // convex corner of the domain at the hole's deep vertex).
    std::vector<char> locked(angles.size(), 0);
    if (m >= 4 && rng.chance(0.5 * o.spike_probability)) {
      // The notch's draws are made even when hole_notches is off, so that
      // option changes no other draw of the stream.
      std::vector<double> notched_angles = angles, notched_radii = radii;
      std::vector<char> notched_locked = locked;
      if (insert_spike(rng, notched_angles, notched_radii, notched_locked, rho, o.min_spike_degrees,
                       o.max_spike_degrees, true) &&
          o.hole_notches) {
        angles = std::move(notched_angles);
        radii = std::move(notched_radii);
        locked = std::move(notched_locked);
      }
    }
    Loop C = from_polar(c, angles, radii);
    for (Vec2& p : C) p = snap(p, bits);
    if (!strict_kernel_point(c, C) || !fits(C, outer, holes) || !clear_of(C, outer, holes, o.min_clearance)) continue;
    Vec2 centre = c;
    if (rng.chance(o.near_touch_probability)) {
      const double gap = o.min_gap * (1 + 29 * rng.unit() * rng.unit());
      const Vec2 t = push_near(C, outer, holes, gap, bits);
      if (!(t == Vec2{})) {
        centre = centre + t;
        ++out.near_touching;
      }
    }
    holes.push_back(std::move(C));
    centres.push_back(centre);
    ++h;
  }

  out.loops.push_back(std::move(outer));
  for (std::size_t h = 0; h < holes.size(); ++h) {
    std::reverse(holes[h].begin(), holes[h].end());  // clockwise
    out.loops.push_back(std::move(holes[h]));
    out.hole_points.push_back(centres[h]);
  }
  return out;
}

struct Similarity {
  int exponent = 0;
  Vec2 offset;
  Vec2 apply(Vec2 p) const { return Vec2{std::ldexp(p.x, exponent), std::ldexp(p.y, exponent)} + offset; }
  double length(double v) const { return std::ldexp(v, exponent); }
};

Similarity draw_similarity(Rng& rng, bool enabled) {
  Similarity s;
  if (!enabled) return s;
  s.exponent = rng.integer(-3, 3);
  s.offset = {0.25 * rng.integer(-16, 16), 0.25 * rng.integer(-16, 16)};
  return s;
}

void apply(PolygonWithHoles& p, const Similarity& s) {
  for (Loop& L : p.loops)
    for (Vec2& v : L) v = s.apply(v);
  for (Vec2& v : p.hole_points) v = s.apply(v);
}

PolygonWithHoles polygon_from_rng(Rng& rng, const PolygonOptions& o) {
  PolygonWithHoles p = make_polygon(rng, o);
  apply(p, draw_similarity(rng, o.random_scale));
  return p;
}

constexpr std::uint64_t kPslgStream = 0x2d2d2d2d00000002ULL;
constexpr std::uint64_t kPlcStream = 0x3d3d3d3d00000003ULL;

}  // namespace

// ---------------------------------------------------------------------------

PolygonWithHoles random_polygon_loops(std::uint64_t seed, const PolygonOptions& options) {
  Rng rng(seed ^ kPslgStream);
  return polygon_from_rng(rng, options);
}

Pslg2 to_pslg(const PolygonWithHoles& polygon, std::uint64_t seed, bool shuffle_ids) {
  Rng rng(seed ^ 0x5151515151515151ULL);
  Pslg2 out;
  std::vector<Vec2> pts;
  std::vector<int> marker;
  std::vector<std::array<int, 2>> segs;
  std::vector<int> seg_marker;
  for (std::size_t l = 0; l < polygon.loops.size(); ++l) {
    const int first = static_cast<int>(pts.size()), n = static_cast<int>(polygon.loops[l].size());
    for (int i = 0; i < n; ++i) {
      pts.push_back(polygon.loops[l][i]);
      marker.push_back(l == 0 ? 1 : 1 + static_cast<int>(l));
      segs.push_back({first + i, first + (i + 1) % n});
      seg_marker.push_back(l == 0 ? 1 : 1 + static_cast<int>(l));
    }
  }
  std::vector<int> perm(pts.size());
  for (std::size_t i = 0; i < perm.size(); ++i) perm[i] = static_cast<int>(i);
  std::vector<int> seg_order(segs.size());
  for (std::size_t i = 0; i < seg_order.size(); ++i) seg_order[i] = static_cast<int>(i);
  if (shuffle_ids) {
    rng.shuffle(perm);  // old id i becomes perm[i]
    rng.shuffle(seg_order);
  }
  out.vertices.resize(pts.size());
  out.vertex_markers.resize(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    out.vertices[perm[i]] = pts[i];
    out.vertex_markers[perm[i]] = marker[i];
  }
  for (int s : seg_order) {
    std::array<int, 2> e{perm[segs[s][0]], perm[segs[s][1]]};
    if (shuffle_ids && rng.chance(0.5)) std::swap(e[0], e[1]);
    out.segments.push_back(e);
    out.segment_markers.push_back(seg_marker[s]);
  }
  out.holes = polygon.hole_points;
  return out;
}

Pslg2 random_polygon_with_holes(std::uint64_t seed, const PolygonOptions& options) {
  return to_pslg(random_polygon_loops(seed, options), seed, options.shuffle_ids);
}

RandomPolyhedron random_polyhedron_detail(std::uint64_t seed, const PolyhedronOptions& o) {
  Rng rng(seed ^ kPlcStream);
  const int bits = o.polygon.grid_bits;
  // Build in unscaled coordinates, scale everything (x, y, z) at the end.
  PolygonWithHoles base = make_polygon(rng, o.polygon);
  RandomPolyhedron R;

  // Height: a dyadic value in [1/16, 2]; small heights with a wide frustum
  // give sharp dihedral angles at the top edges.
  R.height = snap(rng.chance(o.thin_probability) ? rng.uniform(0.0625, 0.25) : rng.uniform(o.min_height, o.max_height), 6);
  if (rng.chance(o.frustum_probability)) {
    static constexpr double kScales[] = {0.25, 0.375, 0.5, 0.625, 0.75, 0.875, 1.25, 1.5, 2.0};
    const double scale = kScales[rng.integer(0, 8)];
    R.centre = snap(Vec2{rng.uniform(-0.25, 0.25), rng.uniform(-0.25, 0.25)}, 8);
    if (o.min_top_scale <= scale && scale <= o.max_top_scale) R.top_scale = scale;
    else R.centre = Vec2{};  // a right prism, as if no frustum had been drawn
  }
  if (!R.right_prism()) {
    // Keep the walls at least ~2 degrees from horizontal (tan 2 deg ~ 0.035):
    // a vertex at distance r from the centre moves by |s - 1| r horizontally
    // over the height, so h >= 0.035 |s - 1| r_max. Flatter walls would give
    // dihedral angles far below the polygon's own minimum of ~1 degree.
    double r_max = 0;
    for (const Loop& L : base.loops)
      for (Vec2 p : L) r_max = std::max(r_max, norm(p - R.centre));
    const double min_h = 0.035 * std::abs(R.top_scale - 1) * r_max;
    if (R.height < min_h) R.height = std::ldexp(std::ceil(std::ldexp(min_h, 6)), -6);
  }
  const double h = R.height, s = R.top_scale;
  const Vec2 c = R.centre;

  // Cavities. The 2D obstacle for a cavity is its footprint (right prism) or,
  // for a frustum, a box B in base coordinates containing every point
  // c + (x - c) / lambda(z) for x in the footprint and z in [z0, z1]: each
  // coordinate is monotone in x and in lambda, so the extremes are at the
  // footprint's corners and the two end heights; B is widened by two grid
  // steps to absorb the rounding of these constructions. B strictly inside
  // the base polygon makes the cavity strictly inside every section. Cavities
  // are also kept apart from each other in 2D, so no two shells touch.
  std::vector<Loop> cavity_obstacles;
  if (rng.chance(o.cavity_probability)) {
    const int want = rng.integer(1, 2);
    for (int k = 0, attempts = 0; k < want && attempts < 80; ++attempts) {
      Cavity cav;
      double z0 = snap(h * rng.uniform(0.1, 0.55), bits),
             z1 = snap(z0 + h * rng.uniform(o.min_cavity_height, o.max_cavity_height), bits);
      const bool near = rng.chance(o.near_touch_probability);
      const double zgap = std::max(std::ldexp(1.0, -bits), snap(h * o.polygon.min_gap * (1 + 9 * rng.unit()), bits));
      if (near && rng.chance(0.5)) z0 = zgap;
      else if (near) z1 = h - zgap;
      if (!(0 < z0 && z0 < z1 && z1 < h)) continue;
      // Floor and roof at least min_cavity_wall * h thick (always true for 0).
      if (z0 < o.min_cavity_wall * h || z1 > (1 - o.min_cavity_wall) * h) continue;
      cav.z0 = z0;
      cav.z1 = z1;
      const Vec2 fc = snap(Vec2{rng.uniform(-0.7, 0.7), rng.uniform(-0.7, 0.7)}, bits);
      const bool polygonal = R.right_prism() && rng.chance(o.polygon_cavity_probability);
      if (polygonal) {
        cav.footprint = star_loop(rng, fc, rng.integer(3, 7), 1.5 * o.min_cavity_half_width, o.max_cavity_half_width);
        for (Vec2& p : cav.footprint) p = snap(p, bits);
        if (!strict_kernel_point(fc, cav.footprint)) continue;
      } else {
        const double hx = snap(rng.uniform(o.min_cavity_half_width, o.max_cavity_half_width), bits),
                     hy = snap(rng.uniform(o.min_cavity_half_width, o.max_cavity_half_width), bits);
        cav.footprint = {fc + Vec2{-hx, -hy}, fc + Vec2{hx, -hy}, fc + Vec2{hx, hy}, fc + Vec2{-hx, hy}};
        cav.box = true;
      }
      cav.inner_point = fc;
      std::vector<Loop> obs(base.loops.begin() + 1, base.loops.end());
      obs.insert(obs.end(), cavity_obstacles.begin(), cavity_obstacles.end());
      Loop check = cav.footprint;
      if (!R.right_prism()) {
        double xlo = HUGE_VAL, xhi = -HUGE_VAL, ylo = HUGE_VAL, yhi = -HUGE_VAL;
        for (double z : {z0, z1}) {
          const double lambda = 1 + (s - 1) * z / h;
          for (Vec2 p : cav.footprint) {
            const Vec2 q = c + (1 / lambda) * (p - c);
            xlo = std::min(xlo, q.x), xhi = std::max(xhi, q.x), ylo = std::min(ylo, q.y), yhi = std::max(yhi, q.y);
          }
        }
        const double step = std::ldexp(1.0, -bits);
        xlo = snap(xlo, bits) - 2 * step, ylo = snap(ylo, bits) - 2 * step;
        xhi = snap(xhi, bits) + 2 * step, yhi = snap(yhi, bits) + 2 * step;
        check = {{xlo, ylo}, {xhi, ylo}, {xhi, yhi}, {xlo, yhi}};
      }
      if (!fits(check, base.loops[0], obs) || !clear_of(check, base.loops[0], obs, o.polygon.min_clearance)) continue;
      if (R.right_prism() && near && rng.chance(0.5)) {
        const Vec2 t = push_near(check, base.loops[0], obs, o.polygon.min_gap * (1 + 9 * rng.unit()), bits);
        cav.footprint = translated(cav.footprint, t);
        cav.inner_point = cav.inner_point + t;
      }
      cavity_obstacles.push_back(check);
      R.cavities.push_back(std::move(cav));
      ++k;
    }
  }

  // Scale: x, y, z by 2^e, x and y shifted by a dyadic offset (z keeps 0 as the base).
  const Similarity sim = draw_similarity(rng, o.polygon.random_scale);
  apply(base, sim);
  R.height = sim.length(h);
  R.centre = sim.apply(c);
  for (Cavity& cav : R.cavities) {
    for (Vec2& p : cav.footprint) p = sim.apply(p);
    cav.inner_point = sim.apply(cav.inner_point);
    cav.z0 = sim.length(cav.z0);
    cav.z1 = sim.length(cav.z1);
  }
  R.base = std::move(base);

  // Assemble the PLC in structured order, then shuffle.
  Plc3 plc;
  auto add_vertex = [&](Vec3 p) {
    plc.vertices.push_back(p);
    return static_cast<int>(plc.vertices.size()) - 1;
  };
  auto add_prism = [&](const std::vector<Loop>& loops, double zb, double zt, double scale, Vec2 centre,
                       int marker_base) {
    Facet3 bottom, top;
    bottom.marker = marker_base;
    top.marker = marker_base + 1;
    for (std::size_t l = 0; l < loops.size(); ++l) {
      const Loop& L = loops[l];
      const int n = static_cast<int>(L.size());
      std::vector<int> b(n), t(n);
      for (int i = 0; i < n; ++i) {
        b[i] = add_vertex({L[i].x, L[i].y, zb});
        const Vec2 q = scale == 1 ? L[i] : centre + scale * (L[i] - centre);
        t[i] = add_vertex({q.x, q.y, zt});
      }
      bottom.loops.push_back(b);
      top.loops.push_back(t);
      for (int i = 0; i < n; ++i) {
        const int j = (i + 1) % n;
        const int marker = marker_base + 2 + static_cast<int>(l);
        const auto& V = plc.vertices;
        if (orient3d(V[b[i]], V[b[j]], V[t[j]], V[t[i]]) == Sign::Zero) {
          plc.facets.push_back(Facet3{{{b[i], b[j], t[j], t[i]}}, marker});
        } else {  // never observed: the homothety is computed exactly
          ++R.split_quads;
          plc.facets.push_back(Facet3{{{b[i], b[j], t[j]}}, marker});
          plc.facets.push_back(Facet3{{{b[i], t[j], t[i]}}, marker});
        }
      }
    }
    plc.facets.push_back(std::move(bottom));
    plc.facets.push_back(std::move(top));
  };
  add_prism(R.base.loops, 0, R.height, s, R.centre, 1);
  int cavity_marker = 100;
  for (const Cavity& cav : R.cavities) {
    add_prism({cav.footprint}, cav.z0, cav.z1, 1, {}, cavity_marker);
    cavity_marker += 10;
    // A TetGen hole point in the cavity (its footprint's kernel point).
    plc.holes.push_back({cav.inner_point.x, cav.inner_point.y, 0.5 * (cav.z0 + cav.z1)});
  }

  if (o.shuffle_ids) {
    Rng srng(seed ^ 0x7777777777777777ULL);
    std::vector<int> perm(plc.vertices.size());
    for (std::size_t i = 0; i < perm.size(); ++i) perm[i] = static_cast<int>(i);
    srng.shuffle(perm);
    std::vector<Vec3> V(plc.vertices.size());
    for (std::size_t i = 0; i < perm.size(); ++i) V[perm[i]] = plc.vertices[i];
    plc.vertices = std::move(V);
    for (Facet3& f : plc.facets) {
      const bool flip = srng.chance(0.5);
      for (auto& loop : f.loops) {
        for (int& v : loop) v = perm[v];
        std::rotate(loop.begin(), loop.begin() + srng.integer(0, static_cast<int>(loop.size()) - 1), loop.end());
        if (flip) std::reverse(loop.begin(), loop.end());
      }
    }
    srng.shuffle(plc.facets);
  }
  R.plc = std::move(plc);
  return R;
}

PolyhedronOptions bounded_feature_polyhedron_options() {
  PolyhedronOptions o;
  o.polygon.min_vertices = 4;
  o.polygon.max_vertices = 7;
  o.polygon.max_holes = 1;
  o.polygon.min_hole_vertices = 3;
  o.polygon.max_hole_vertices = 5;
  o.polygon.min_hole_radius = 0.15;
  o.polygon.max_hole_radius = 0.3;
  o.polygon.min_spike_degrees = 12;
  o.polygon.max_spike_degrees = 30;
  o.polygon.min_gap = 1.0 / 16;
  o.polygon.min_clearance = 1.0 / 16;
  o.thin_probability = 0;
  o.min_height = 0.75;
  o.max_height = 1.5;
  o.min_top_scale = 0.5;
  o.max_top_scale = 1.5;
  o.cavity_probability = 0.4;
  o.min_cavity_half_width = 0.1;
  o.max_cavity_half_width = 0.2;
  o.min_cavity_height = 0.25;
  o.max_cavity_height = 0.4;
  return o;
}

PolyhedronOptions suite_polyhedron_options() {
  PolyhedronOptions o;
  o.polygon.min_vertices = 4;
  o.polygon.max_vertices = 6;
  o.polygon.max_holes = 1;
  o.polygon.min_hole_vertices = 3;
  o.polygon.max_hole_vertices = 5;
  o.polygon.min_hole_radius = 0.12;
  o.polygon.max_hole_radius = 0.2;
  o.polygon.spike_probability = 0.25;
  o.polygon.max_spikes = 1;
  o.polygon.min_spike_degrees = 20;
  o.polygon.max_spike_degrees = 30;
  o.polygon.min_gap = 3.0 / 16;
  o.polygon.min_clearance = 3.0 / 16;
  o.frustum_probability = 0.5;
  o.thin_probability = 0;
  o.min_height = 1.0;
  o.max_height = 1.25;
  o.min_top_scale = 0.75;
  o.max_top_scale = 1.25;
  o.cavity_probability = 0.6;
  o.min_cavity_half_width = 0.08;
  o.max_cavity_half_width = 0.15;
  o.min_cavity_height = 0.2;
  o.max_cavity_height = 0.35;
  o.min_cavity_wall = 0.25;
  return o;
}

PolyhedronOptions every_run_polyhedron_options() {
  PolyhedronOptions o = suite_polyhedron_options();
  o.polygon.max_vertices = 5;
  o.polygon.notch_probability = 0.08;
  o.polygon.spike_probability = 0.125;
  o.polygon.min_hole_vertices = 4;
  o.polygon.max_hole_vertices = 5;
  o.polygon.min_hole_radius = 0.25;
  o.polygon.max_hole_radius = 0.35;
  o.polygon.hole_notches = false;
  o.polygon.min_gap = 0.25;
  o.polygon.min_clearance = 0.25;
  o.polygon.near_touch_probability = 0;
  o.near_touch_probability = 0;
  o.min_height = 0.75;
  o.max_height = 1.0;
  o.cavity_probability = 0.5;
  o.min_cavity_half_width = 0.1;
  o.max_cavity_half_width = 0.15;
  return o;
}

PolyhedronOptions harsh_polyhedron_options() {
  PolyhedronOptions o;
  o.polygon.max_vertices = 10;
  o.polygon.max_holes = 2;
  o.polygon.max_hole_vertices = 6;
  o.polygon.min_spike_degrees = 5;
  o.polygon.min_gap = 1e-2;
  return o;
}

Plc3 random_polyhedron(std::uint64_t seed, const PolyhedronOptions& options) {
  return random_polyhedron_detail(seed, options).plc;
}

std::string describe_polygon(std::uint64_t seed, const PolygonOptions& options) {
  const PolygonWithHoles p = random_polygon_loops(seed, options);
  std::ostringstream s;
  s << "seed " << seed << ": polygon, outer " << p.loops[0].size() << " vertices, " << p.loops.size() - 1
    << " holes, " << p.spikes << " spikes, " << p.near_touching << " near-touching, " << p.snapped << " snapped";
  return s.str();
}

std::string describe_polyhedron(std::uint64_t seed, const PolyhedronOptions& options) {
  const RandomPolyhedron r = random_polyhedron_detail(seed, options);
  std::ostringstream s;
  s.precision(17);
  s << "seed " << seed << ": " << (r.right_prism() ? "right prism" : "frustum (top scale ") ;
  if (!r.right_prism()) s << r.top_scale << ")";
  s << ", height " << r.height << ", base outer " << r.base.loops[0].size() << " vertices, "
    << r.base.loops.size() - 1 << " through-holes, " << r.base.spikes << " spikes, " << r.base.notches
    << " notches, " << r.cavities.size()
    << " cavities, " << r.plc.vertices.size() << " vertices, " << r.plc.facets.size() << " facets";
  return s.str();
}

double shoelace(const std::vector<Vec2>& loop) {
  double twice = 0;
  for (std::size_t i = 1; i + 1 < loop.size(); ++i) twice += cross(loop[i] - loop[0], loop[i + 1] - loop[0]);
  return twice / 2;
}

double smallest_corner_angle(const std::vector<std::vector<Vec2>>& loops) {
  double best = HUGE_VAL;
  for (const std::vector<Vec2>& L : loops)
    for (std::size_t i = 0; i < L.size(); ++i) {
      const Vec2 v = L[i], prev = L[(i + L.size() - 1) % L.size()], next = L[(i + 1) % L.size()];
      double t = std::atan2(cross(next - v, prev - v), dot(next - v, prev - v));
      if (t < 0) t += 2 * std::numbers::pi;
      best = std::min(best, t);
    }
  return best;
}

std::array<PolygonOptions, 3> hard_polygon_options() {
  PolygonOptions holes;
  holes.max_holes = 12;
  holes.max_vertices = 60;
  holes.near_touch_probability = 0.8;
  holes.min_gap = 1e-5;
  PolygonOptions spikes;
  spikes.spike_probability = 0.9;
  spikes.min_spike_degrees = 0.5;
  spikes.snap_probability = 0.6;
  PolygonOptions coarse;
  coarse.grid_bits = 8;
  coarse.snap_probability = 0.9;
  return {holes, spikes, coarse};
}

}  // namespace pqmesh::test
