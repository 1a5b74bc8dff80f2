// Hand cases for quad2d::components (components of P ∩ C, thesis §4.1.6 in
// 2D). Expected values are read off the drawings described in each comment.
// Vertex ids are in the order the points are listed; segment k of a loop with
// first vertex o joins o + k and o + k + 1 (so its id is o + k).
#include <gtest/gtest.h>

#include <vector>

#include "pqmesh/domain.hpp"
#include "quad2d/components2d.hpp"

namespace pqmesh::quad2d {
namespace {

void add_loop(Pslg2& g, const std::vector<Vec2>& pts) {
  const int o = static_cast<int>(g.vertices.size()), n = static_cast<int>(pts.size());
  g.vertices.insert(g.vertices.end(), pts.begin(), pts.end());
  for (int k = 0; k < n; ++k) g.segments.push_back({o + k, o + (k + 1) % n});
}

Domain2 polygon(const std::vector<std::vector<Vec2>>& loops) {
  Pslg2 g;
  for (const auto& l : loops) add_loop(g, l);
  return make_domain(g);
}

Square sq(double x, double y, double s) { return {{x, y}, s}; }

using V = std::vector<int>;

// Comb: base [0,10]x[0,1], five teeth [2i, 2i+1] x [1,5], i = 0..4.
// Vertices: 0 (0,0), 1 (10,0), 2 (10,1), 3 (9,1), 4 (9,5), 5 (8,5), 6 (8,1),
// 7 (7,1), 8 (7,5), 9 (6,5), 10 (6,1), 11 (5,1), 12 (5,5), 13 (4,5), 14 (4,1),
// 15 (3,1), 16 (3,5), 17 (2,5), 18 (2,1), 19 (1,1), 20 (1,5), 21 (0,5).
Domain2 comb() {
  return polygon({{{0, 0}, {10, 0}, {10, 1}, {9, 1}, {9, 5}, {8, 5}, {8, 1}, {7, 1}, {7, 5}, {6, 5}, {6, 1},
                   {5, 1}, {5, 5}, {4, 5}, {4, 1}, {3, 1}, {3, 5}, {2, 5}, {2, 1}, {1, 1}, {1, 5}, {0, 5}}});
}

const ComponentFaces* with_vertex(const SquareComponents& r, int v) {
  const ComponentFaces* found = nullptr;
  for (const auto& c : r.components)
    for (int x : c.vertices)
      if (x == v) {
        EXPECT_EQ(found, nullptr) << "vertex " << v << " in two components";
        found = &c;
      }
  return found;
}

TEST(Components2d, SquareInsideAndOutside) {
  const Domain2 d = polygon({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}});
  const auto in = components(d, sq(1, 1, 1));
  ASSERT_EQ(in.components.size(), 1u);
  EXPECT_TRUE(in.components[0].whole_square);
  EXPECT_TRUE(in.components[0].vertices.empty());
  EXPECT_TRUE(in.components[0].edges.empty());
  ASSERT_EQ(in.components[0].boundary_arcs.size(), 1u);
  EXPECT_EQ(in.components[0].boundary_arcs[0].t0, 0.0);
  EXPECT_EQ(in.components[0].boundary_arcs[0].t1, 4.0);
  EXPECT_EQ(locate_component(d, in, {1.5, 1.5}), 0);
  EXPECT_TRUE(components(d, sq(5, 5, 1)).components.empty());
  EXPECT_TRUE(components(d, sq(-3, 1, 2)).components.empty());
  // The whole polygon inside C: one component with every face, no arc.
  const auto all = components(d, sq(-1, -1, 8));
  ASSERT_EQ(all.components.size(), 1u);
  EXPECT_FALSE(all.components[0].whole_square);
  EXPECT_EQ(all.components[0].vertices, (V{0, 1, 2, 3}));
  EXPECT_EQ(all.components[0].edges, (V{0, 1, 2, 3}));
  EXPECT_TRUE(all.components[0].boundary_arcs.empty());
}

TEST(Components2d, CombTeeth) {
  const Domain2 d = comb();
  // C = [0,10] x [2,12] cuts the five teeth above y = 2: five components,
  // each with the two top vertices of its tooth and three edges. Tooth 0's
  // left side lies on C's left side (inside after the outward shift).
  const auto r = components(d, sq(0, 2, 10));
  ASSERT_EQ(r.components.size(), 5u);
  const ComponentFaces* t0 = with_vertex(r, 20);
  ASSERT_NE(t0, nullptr);
  EXPECT_EQ(t0->vertices, (V{20, 21}));
  EXPECT_EQ(t0->edges, (V{19, 20, 21}));
  ASSERT_EQ(t0->boundary_arcs.size(), 1u);  // bottom side, x in [0, 1]
  EXPECT_EQ(t0->boundary_arcs[0].t0, 0.0);
  EXPECT_EQ(t0->boundary_arcs[0].t1, 1.0);
  EXPECT_EQ(t0->boundary_arcs[0].exit_segment, 21);
  EXPECT_EQ(t0->boundary_arcs[0].entry_segment, 19);
  const ComponentFaces* t4 = with_vertex(r, 4);
  ASSERT_NE(t4, nullptr);
  EXPECT_EQ(t4->vertices, (V{4, 5}));
  EXPECT_EQ(t4->edges, (V{3, 4, 5}));
  // Each sample point in a tooth lands in the component holding its vertices.
  for (int i = 0; i < 5; ++i) {
    const int comp = locate_component(d, r, {2.0 * i + 0.5, 3});
    ASSERT_GE(comp, 0);
    const ComponentFaces* c = with_vertex(r, 20 - 4 * i);
    EXPECT_EQ(&r.components[static_cast<std::size_t>(comp)], c) << i;
  }
  // C = [0.5,8.5] x [2,10]: half of tooth 0, teeth 1-3, half of tooth 4.
  const auto h = components(d, sq(0.5, 2, 8));
  ASSERT_EQ(h.components.size(), 5u);
  const ComponentFaces* half0 = with_vertex(h, 20);
  ASSERT_NE(half0, nullptr);
  EXPECT_EQ(half0->vertices, (V{20}));
  EXPECT_EQ(half0->edges, (V{19, 20}));
  // Arc from where the top edge (1,5)->(0,5) leaves through the left side
  // (t = 3*8 + (10 - 5) = 29) counter-clockwise through the lo corner to
  // where edge (1,1)->(1,5) enters through the bottom (t = 1 - 0.5).
  ASSERT_EQ(half0->boundary_arcs.size(), 1u);
  EXPECT_EQ(half0->boundary_arcs[0].t0, 29.0);
  EXPECT_EQ(half0->boundary_arcs[0].t1, 0.5);
  EXPECT_TRUE(half0->boundary_arcs[0].wraps);
  EXPECT_FALSE(t0->boundary_arcs[0].wraps);
  // C = [0,10] x [0.5, 10.5]: the base joins everything.
  EXPECT_EQ(components(d, sq(0, 0.5, 10)).components.size(), 1u);
  // C = [0,10] x [1,11]: the base's top edges lie on the bottom side: joined.
  EXPECT_EQ(components(d, sq(0, 1, 10)).components.size(), 1u);
}

// U shape: base [0,10]x[0,2], prongs [0,4]x[2,10] and [6,10]x[2,10], a hole
// in each prong. Vertices 0 (0,0) 1 (10,0) 2 (10,10) 3 (6,10) 4 (6,2) 5 (4,2)
// 6 (4,10) 7 (0,10); left hole 8-11, right holes 12-15 and 16-19.
Domain2 u_with_holes() {
  return polygon({{{0, 0}, {10, 0}, {10, 10}, {6, 10}, {6, 2}, {4, 2}, {4, 10}, {0, 10}},
                  {{2.5, 5}, {2.5, 6}, {3.5, 6}, {3.5, 5}},
                  {{6.5, 5}, {6.5, 7}, {7.5, 7}, {7.5, 5}},
                  {{8, 4.5}, {8, 7.5}, {9, 7.5}, {9, 4.5}}});
}

TEST(Components2d, HolesAttachToTheirComponent) {
  const Domain2 d = u_with_holes();
  // C = [2,10] x [4,12]: left prong piece and right prong (edge x = 10 on
  // C's right side). The left hole's ray hits the left prong's edge x = 4;
  // hole 12-15's ray hits hole 16-19 (recursion), whose ray hits x = 10.
  const auto r = components(d, sq(2, 4, 8));
  ASSERT_EQ(r.components.size(), 2u);
  const ComponentFaces* left = with_vertex(r, 6);
  const ComponentFaces* right = with_vertex(r, 2);
  ASSERT_NE(left, nullptr);
  ASSERT_NE(right, nullptr);
  EXPECT_EQ(left->vertices, (V{6, 8, 9, 10, 11}));  // vertex 7 (0,10) is left of C
  EXPECT_EQ(right->vertices, (V{2, 3, 12, 13, 14, 15, 16, 17, 18, 19}));
  // C = [2,9.5] x [4,11.5]: the ray of hole 16-19 leaves through the right
  // side of C (x = 9.5, y = 7.5) below the entry of segment 2 at y = 10.
  const auto s = components(d, sq(2, 4, 7.5));
  ASSERT_EQ(s.components.size(), 2u);
  const ComponentFaces* right2 = with_vertex(s, 16);
  ASSERT_NE(right2, nullptr);
  EXPECT_EQ(right2->vertices, (V{3, 12, 13, 14, 15, 16, 17, 18, 19}));
  EXPECT_EQ(with_vertex(s, 8)->vertices, (V{6, 8, 9, 10, 11}));
  EXPECT_EQ(&s.components[static_cast<std::size_t>(locate_component(d, s, {9.25, 6}))], right2);
  EXPECT_EQ(&s.components[static_cast<std::size_t>(locate_component(d, s, {3, 4.5}))], with_vertex(s, 8));
  // A square holding the right holes whole, not meeting the outer loop.
  const auto w = components(d, sq(6.25, 4.25, 3.5));
  ASSERT_EQ(w.components.size(), 1u);
  EXPECT_TRUE(w.components[0].whole_square);
  EXPECT_EQ(w.components[0].vertices, (V{12, 13, 14, 15, 16, 17, 18, 19}));
  // Inside a hole: nothing.
  EXPECT_TRUE(components(d, sq(8.25, 5, 0.5)).components.empty());
}

TEST(Components2d, Notch) {
  // Square [0,10]^2 with a notch [4,6] x [4,10] cut from the top.
  // Vertices 0 (0,0) 1 (10,0) 2 (10,10) 3 (6,10) 4 (6,4) 5 (4,4) 6 (4,10) 7 (0,10).
  const Domain2 d = polygon({{{0, 0}, {10, 0}, {10, 10}, {6, 10}, {6, 4}, {4, 4}, {4, 10}, {0, 10}}});
  EXPECT_EQ(components(d, sq(2, 6, 6)).components.size(), 2u);  // above the notch floor: two sides
  const auto u = components(d, sq(2, 2, 6));                     // the notch floor joins them
  ASSERT_EQ(u.components.size(), 1u);
  EXPECT_EQ(u.components[0].vertices, (V{4, 5}));
  EXPECT_EQ(u.components[0].edges, (V{3, 4, 5}));
  // One arc: from the exit of segment 5 on the top side at x = 4
  // (t = 12 + 4) counter-clockwise through the lo corner to the entry of
  // segment 3 at x = 6 (t = 12 + 2).
  ASSERT_EQ(u.components[0].boundary_arcs.size(), 1u);
  EXPECT_EQ(u.components[0].boundary_arcs[0].t0, 16.0);
  EXPECT_EQ(u.components[0].boundary_arcs[0].t1, 14.0);
  EXPECT_TRUE(u.components[0].boundary_arcs[0].wraps);
  // The notch floor (y = 4) on C's bottom side: inside after the shift, so
  // both sides are joined along it.
  EXPECT_EQ(components(d, sq(2, 4, 6)).components.size(), 1u);
  // C = [2,8] x [4.5,10.5]: floor below C, two components.
  EXPECT_EQ(components(d, sq(2, 4.5, 6)).components.size(), 2u);
}

TEST(Components2d, VertexOnSideAndCorner) {
  // Triangle 0 (0,0), 1 (10,0), 2 (5,5).
  const Domain2 d = polygon({{{0, 0}, {10, 0}, {5, 5}}});
  // Apex on the bottom side of C = [3,7] x [5,9], P below: an infinitesimal
  // component holding the apex and its two edges; its single arc has zero
  // length in the construction.
  const auto r = components(d, sq(3, 5, 4));
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_EQ(r.components[0].vertices, (V{2}));
  EXPECT_EQ(r.components[0].edges, (V{1, 2}));
  ASSERT_EQ(r.components[0].boundary_arcs.size(), 1u);
  EXPECT_EQ(r.components[0].boundary_arcs[0].t0, 2.0);
  EXPECT_EQ(r.components[0].boundary_arcs[0].t1, 2.0);
  EXPECT_EQ(r.components[0].boundary_arcs[0].exit_segment, 2);
  EXPECT_EQ(r.components[0].boundary_arcs[0].entry_segment, 1);
  EXPECT_FALSE(r.components[0].boundary_arcs[0].wraps);
  // Apex on the top side, P inside: one ordinary component.
  const auto t = components(d, sq(3, 1, 4));
  ASSERT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.components[0].vertices, (V{2}));
  // Apex on a corner (lo corner of [5,9]^2 and hi corner of [1,5]^2).
  const auto c1 = components(d, sq(5, 5, 4));
  ASSERT_EQ(c1.components.size(), 1u);
  EXPECT_EQ(c1.components[0].vertices, (V{2}));
  const auto c2 = components(d, sq(1, 1, 4));
  ASSERT_EQ(c2.components.size(), 1u);
  EXPECT_EQ(c2.components[0].vertices, (V{2}));
  // Square touching the triangle only at the apex from the upper left.
  EXPECT_EQ(components(d, sq(1, 5, 4)).components.size(), 1u);
}

TEST(Components2d, HoleVertexPokesThroughSide) {
  // [0,4]^2 (vertices 0-3, segments 0-3) with the triangular hole
  // 4 (2,3.5), 5 (3,2.5), 6 (1,2.5) (segments 4-6). The hole's vertex 5 lies
  // on the left side of C = [3,3.5] x [2.25,2.75], the hole outside C: after
  // the shift the hole pokes into C by an infinitesimal notch. One
  // component; its one arc runs from the exit of segment 5 (5 -> 6) all the
  // way around to the entry of segment 4 (4 -> 5); both ends construct to
  // t = 3 * 0.5 + (2.75 - 2.5) = 1.75, and only `wraps` says it is almost
  // the whole boundary.
  const Domain2 d = polygon({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{2, 3.5}, {3, 2.5}, {1, 2.5}}});
  const auto r = components(d, sq(3, 2.25, 0.5));
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_EQ(r.components[0].vertices, (V{5}));
  EXPECT_EQ(r.components[0].edges, (V{4, 5}));
  ASSERT_EQ(r.components[0].boundary_arcs.size(), 1u);
  const BoundaryArc& arc = r.components[0].boundary_arcs[0];
  EXPECT_EQ(arc.t0, 1.75);
  EXPECT_EQ(arc.t1, 1.75);
  EXPECT_TRUE(arc.wraps);
  EXPECT_EQ(arc.exit_segment, 5);
  EXPECT_EQ(arc.entry_segment, 4);
  // The mirror image: hole vertex on the right side of C = [2.5,3] x [2.25,2.75]
  // from inside C. The hole is cut off at x = 3; still one component.
  const auto m = components(d, sq(2.5, 2.25, 0.5));
  ASSERT_EQ(m.components.size(), 1u);
  EXPECT_EQ(m.components[0].vertices, (V{5}));
}

TEST(Components2d, EdgeAlongSide) {
  // Square P = [0,4]^2: vertices 0 (0,0) 1 (4,0) 2 (4,4) 3 (0,4); segment 1 is x = 4.
  const Domain2 d = polygon({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}});
  // C = [4,8] x [1,3] touches P along segment 1 from outside: one
  // infinitesimal component holding a piece of segment 1, no vertex.
  const auto r = components(d, sq(4, 1, 2));
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_TRUE(r.components[0].vertices.empty());
  EXPECT_EQ(r.components[0].edges, (V{1}));
  // C = [4,8] x [0,4]: the whole segment 1 with both vertices.
  const auto w = components(d, sq(4, 0, 4));
  ASSERT_EQ(w.components.size(), 1u);
  EXPECT_EQ(w.components[0].vertices, (V{1, 2}));
  EXPECT_EQ(w.components[0].edges, (V{0, 1, 2}));
  // C = [2,4] x [1,3] from inside: segment 1 lies on C's right side.
  const auto in = components(d, sq(2, 1, 2));
  ASSERT_EQ(in.components.size(), 1u);
  EXPECT_FALSE(in.components[0].whole_square);
  EXPECT_EQ(in.components[0].edges, (V{1}));
  // C = [0,4]^2 equals P: the outer loop lies inside C.
  const auto eq = components(d, sq(0, 0, 4));
  ASSERT_EQ(eq.components.size(), 1u);
  EXPECT_EQ(eq.components[0].vertices, (V{0, 1, 2, 3}));
}

TEST(Components2d, ReflexVertex) {
  // L shape 0 (0,0) 1 (10,0) 2 (10,5) 3 (5,5) 4 (5,10) 5 (0,10); reflex vertex 3.
  const Domain2 d = polygon({{{0, 0}, {10, 0}, {10, 5}, {5, 5}, {5, 10}, {0, 10}}});
  const auto r = components(d, sq(4, 4, 4));
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_EQ(r.components[0].vertices, (V{3}));
  EXPECT_EQ(r.components[0].edges, (V{2, 3}));
  EXPECT_EQ(r.components[0].boundary_arcs.size(), 1u);
  EXPECT_TRUE(components(d, sq(6, 6, 3)).components.empty());  // in the missing quadrant
  // Thin slit [4.875, 5.125] x [3, 10] cut from [0,10]^2: a square around its
  // bottom (reflex) end is one component, a square above it two.
  const Domain2 s = polygon({{{0, 0}, {10, 0}, {10, 10}, {5.125, 10}, {5.125, 3}, {4.875, 3}, {4.875, 10}, {0, 10}}});
  EXPECT_EQ(components(s, sq(3, 2, 4)).components.size(), 1u);
  EXPECT_EQ(components(s, sq(3, 4, 4)).components.size(), 2u);
}

TEST(Components2d, ExtendedBoxComponent) {
  const Domain2 d = comb();
  // b = [0.125,0.875] x [3,3.75] inside tooth 0 (whole square, no faces);
  // ex(b) = [-1.375,2.375] x [1.5,5.25] meets teeth 0 and 1 separately.
  const Square b = sq(0.125, 3, 0.75);
  const Square ex = extended(b);
  EXPECT_EQ(ex.lo.x, -1.375);
  EXPECT_EQ(ex.lo.y, 1.5);
  EXPECT_EQ(ex.side, 3.75);
  const auto rb = components(d, b);
  const auto rex = components(d, ex);
  ASSERT_EQ(rb.components.size(), 1u);
  EXPECT_TRUE(rb.components[0].whole_square);
  ASSERT_EQ(rex.components.size(), 2u);
  const int c = containing_component(d, rex, rb, rb.components[0]);
  ASSERT_GE(c, 0);
  EXPECT_EQ(rex.components[static_cast<std::size_t>(c)].vertices, (V{20, 21}));
  // b = [0.5,1.5] x [4.5,5.5] centred on vertex 20 (1,5): decided by the
  // vertex; ex(b) = [-1.5,3.5] x [2.5,7.5] again splits teeth 0 and 1.
  const Square b2 = sq(0.5, 4.5, 1);
  const auto rb2 = components(d, b2);
  const auto rex2 = components(d, extended(b2));
  ASSERT_EQ(rb2.components.size(), 1u);
  ASSERT_EQ(rex2.components.size(), 2u);
  const int c2 = containing_component(d, rex2, rb2, rb2.components[0]);
  ASSERT_GE(c2, 0);
  EXPECT_EQ(rex2.components[static_cast<std::size_t>(c2)].vertices, (V{20, 21}));
  // b = [2.5,3.5] x [2,3]: pieces of tooth 1's right edge (segment 15), no vertex.
  const Square b3 = sq(2.5, 2, 1);
  const auto rb3 = components(d, b3);
  const auto rex3 = components(d, extended(b3));  // [0.5,5.5] x [-1,4]: the base joins all
  ASSERT_EQ(rb3.components.size(), 1u);
  EXPECT_EQ(rb3.components[0].edges, (V{15}));
  ASSERT_EQ(rex3.components.size(), 1u);
  EXPECT_EQ(containing_component(d, rex3, rb3, rb3.components[0]), 0);
}

TEST(Components2d, CandidateOverloadAgrees) {
  const Domain2 d = comb();
  const Square parent = sq(0, 0, 8);
  const auto cand = edges_meeting(d, parent);
  const auto parent_result = components(d, parent);
  for (const Square child : {sq(0, 0, 4), sq(4, 0, 4), sq(0, 4, 4), sq(4, 4, 4)}) {
    const auto a = components(d, child);
    const auto b = components(d, child, cand);
    const auto c = components(d, child, cand, &parent_result);
    ASSERT_EQ(a.components.size(), b.components.size());
    ASSERT_EQ(a.components.size(), c.components.size());
    for (std::size_t i = 0; i < a.components.size(); ++i) {
      EXPECT_EQ(a.components[i].vertices, b.components[i].vertices);
      EXPECT_EQ(a.components[i].edges, b.components[i].edges);
      EXPECT_EQ(a.components[i].edges, c.components[i].edges);
    }
  }
  // Children with no ∂P: decided through the container. In a tooth: inside;
  // in a slot between teeth (x in [1,2], y in [2,4]): outside.
  const auto tooth = components(d, sq(0.25, 2, 0.5), edges_meeting(d, sq(0, 2, 1)), &parent_result);
  ASSERT_EQ(tooth.components.size(), 1u);
  EXPECT_TRUE(tooth.components[0].whole_square);
  EXPECT_TRUE(components(d, sq(1.25, 2, 0.5), edges_meeting(d, sq(1, 2, 1)), &parent_result).components.empty());
  // locate_component says -1 for points outside P.
  EXPECT_EQ(locate_component(d, parent_result, {1.5, 3}), -1);
  EXPECT_GE(locate_component(d, parent_result, {0.5, 3}), 0);
  // [0,4] x [4,8] holds the tops of teeth 0 and 1 (y = 5), and touches
  // tooth 2 along its left side x = 4 (an infinitesimal component).
  EXPECT_EQ(components(d, sq(0, 4, 4), cand).components.size(), 3u);
}

}  // namespace
}  // namespace pqmesh::quad2d
