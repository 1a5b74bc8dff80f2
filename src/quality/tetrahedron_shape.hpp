#pragma once
// tetrahedron_quality() in two steps, for TetrahedronQualityMemo:
//   tetrahedron_shape(a, b, c, d)   every value that depends on the points only
//                                   through their differences;
//   tetrahedron_quality(shape, {a, b, c, d})  the rest: the face-ball containment
//                                   tests of the minimal enclosing ball, which
//                                   read the absolute coordinates (centre o + x).
// tetrahedron_quality(tetrahedron_shape(a, b, c, d), {a, b, c, d}) is
// tetrahedron_quality(a, b, c, d) bit for bit: the shape holds the same
// doubles (orientation, dihedral angles, inradius, circumradius, the
// edge-ball stage), and the second step runs the same containment test with
// the same centre and radius on every face ball that the one-step function
// could accept. The one-step function skips faces by its face-ball filter,
// but only faces whose test provably fails (simplex_quality.cpp, FaceFilter),
// and it skips balls not smaller than the current best, which never change
// the result; the shape drops balls not smaller than the edge stage's best
// for the same reason (the best only decreases from there).
#include <array>
#include <cstddef>

#include "pqmesh/quality.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh {

// Containment test for the face-circumcircle candidate balls of the minimal
// enclosing ball search. It compares a constructed centre and radius with a
// relative slack of kBallSlack on squared lengths. That is a tolerance, which
// docs/DESIGN_RULES.md "Exact decisions" forbids in decisions; it is acceptable
// HERE because the result is only a measurement: accepting a ball that misses a
// vertex by the slack understates R_enc by at most ~kBallSlack/2 relative, and
// rejecting the true minimal ball because of rounding would overstate it by a
// whole candidate.
inline constexpr double kBallSlack = 1e-10;

inline bool face_ball_contains(Vec3 centre, double radius2, Vec3 p) {
  const Vec3 d = p - centre;
  return dot(d, d) <= radius2 * (1.0 + kBallSlack);
}

struct TetShape {
  struct Ball {
    Vec3 x;             // circumcentre of the face opposite p[face], relative to p[origin]
    double r2 = 0;      // squared radius
    double radius = 0;  // sqrt(r2)
    int origin = 0;     // (face + 1) % 4
    int face = 0;
  };
  TetQuality quality{};  // aspect_ratio: final only when flat
  bool flat = false;     // exact orientation Zero
  double r = 0;          // inradius
  double best_edges = 0;  // min(circumradius, the edge balls holding all four points)
  int ball_count = 0;     // balls[0 .. ball_count): the candidate face balls, in face order
  std::array<Ball, 4> balls{};
};

TetShape tetrahedron_shape(Vec3 a, Vec3 b, Vec3 c, Vec3 d);

// The second step (inline: it runs once per tetrahedron on the memo's hits).
inline TetQuality tetrahedron_quality(const TetShape& s, const std::array<Vec3, 4>& p) {
  TetQuality q = s.quality;
  if (s.flat) return q;
  double best = s.best_edges;
  for (int i = 0; i < s.ball_count; ++i) {
    const TetShape::Ball& ball = s.balls[static_cast<std::size_t>(i)];
    if (ball.radius < best && face_ball_contains(p[static_cast<std::size_t>(ball.origin)] + ball.x, ball.r2,
                                                 p[static_cast<std::size_t>(ball.face)]))
      best = ball.radius;
  }
  q.aspect_ratio = best / s.r;
  return q;
}

}  // namespace pqmesh
