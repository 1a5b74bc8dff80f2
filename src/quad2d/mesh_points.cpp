// Mesh vertices from the finished quadtree; see mesh_points.hpp.
#include "quad2d/mesh_points.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <tuple>

#include "pqmesh/errors.hpp"
#include "predicates/predicates.hpp"
#include "quad2d/radix_sort.hpp"

namespace pqmesh::quad2d {

namespace {

// Leaf corners as integers: every corner is (x0 + ix * unit, y0 + iy * unit)
// exactly, with unit half the smallest leaf side (corners of a leaf of side h
// are multiples of h / 2 from the root's origin, all powers of two) and
// (x0, y0) the lowest corner coordinates; x - x0 is then an exact multiple of
// unit below 2^53 units, so the conversions both ways are exact and integer
// order is coordinate order.
struct CornerGrid {
  double x0 = 0, y0 = 0, unit = 1, inv_unit = 1;
  int xbits = 0, ybits = 0;  // bits of the largest ix and iy
  std::uint64_t ix(double x) const { return static_cast<std::uint64_t>((x - x0) * inv_unit); }
  std::uint64_t iy(double y) const { return static_cast<std::uint64_t>((y - y0) * inv_unit); }
  Vec2 point(std::uint64_t i, std::uint64_t j) const {
    return {x0 + static_cast<double>(i) * unit, y0 + static_cast<double>(j) * unit};
  }
};

// A leaf corner packed in one word, (ix, iy, busy) with busy the lowest bit
// (1: the leaf meets an input edge or lies in a vertex box), when
// xbits + ybits + 1 <= 64 (trees up to about 30 levels below the domain's
// extent); sorting the words sorts by (x, y).
struct NarrowCorners {
  using Key = std::uint64_t;
  const CornerGrid& g;
  Key make(std::uint64_t i, std::uint64_t j, bool busy) const {
    return (((i << g.ybits) | j) << 1) | static_cast<Key>(busy);
  }
  bool same(Key a, Key b) const { return (a >> 1) == (b >> 1); }
  bool busy(Key k) const { return (k & 1u) != 0; }
  Vec2 point(Key k) const {
    const Key c = k >> 1;
    return g.point(c >> g.ybits, c & ((Key{1} << g.ybits) - 1));
  }
  void sort(std::vector<Key>& v) const {
    std::vector<Key> scratch;
    radix_sort(v, g.xbits + g.ybits + 1, [](Key k) { return k; }, scratch);
  }
};

// Deeper trees: ix and (iy, busy) in two words, sorted by (ix, iy, busy).
struct WideCorners {
  struct Key {
    std::uint64_t i, j;  // j = iy << 1 | busy
  };
  const CornerGrid& g;
  Key make(std::uint64_t i, std::uint64_t j, bool busy) const { return {i, (j << 1) | static_cast<std::uint64_t>(busy)}; }
  bool same(Key a, Key b) const { return a.i == b.i && (a.j >> 1) == (b.j >> 1); }
  bool busy(Key k) const { return (k.j & 1u) != 0; }
  Vec2 point(Key k) const { return g.point(k.i, k.j >> 1); }
  void sort(std::vector<Key>& v) const {
    std::vector<Key> scratch;
    radix_sort(v, g.ybits + 1, [](Key k) { return k.j; }, scratch);
    radix_sort(v, g.xbits, [](Key k) { return k.i; }, scratch);
  }
};

struct Tagged {
  Vec2 p;
  int segment = -1;  // the input segment the point lies on, or -1
  int vertex = -1;   // the input vertex it is, or -1
  double scale = 0;  // points on a segment: the smallest box side where it was made
};

struct Crossing {
  Vec2 p;          // on the segment, rounded (within_ulp_of_segment)
  int segment;
  Vec2 c1, c2;     // the corners around p on its box side, c1 below / left of c2
  int owner;       // the vertex whose united box the side belongs to, or -1
  bool vertical;   // the side is vertical (x constant)
  double scale;    // |c2 - c1|
};

struct Snap {
  double x, y;
  int segment;
  friend bool operator<(const Snap& a, const Snap& b) { return std::tie(a.x, a.y, a.segment) < std::tie(b.x, b.y, b.segment); }
};

// Moves a constructed point by single ulps towards the line ab until it is a
// faithful rounding of a point of the segment (within_ulp_of_segment). Only y
// moves when keep_x (the point is on a vertical box side x = const, exact),
// only x when keep_y, else the coordinate whose ulp moves the point furthest
// across the line (|normal component| * ulp). A construction is off by a few
// ulps of the segment's coordinates, which near the origin can be many ulps
// of the point's own: the step budget allows for that.
Vec2 settle_on_segment(Vec2 p, Vec2 a, Vec2 b, bool keep_x, bool keep_y) {
  const double inf = std::numeric_limits<double>::infinity();
  // The exact point lies in the segment's bounding box; a construction may
  // round out of it near an endpoint, where moving towards the line alone
  // would never succeed.
  p.x = std::clamp(p.x, std::min(a.x, b.x), std::max(a.x, b.x));
  p.y = std::clamp(p.y, std::min(a.y, b.y), std::max(a.y, b.y));
  const double nx = a.y - b.y, ny = b.x - a.x;  // left normal of ab
  const auto ulp = [inf](double v) { return std::nextafter(std::fabs(v), inf) - std::fabs(v); };
  const bool move_x = keep_y || (!keep_x && std::fabs(nx) * ulp(p.x) >= std::fabs(ny) * ulp(p.y));
  for (int step = 0; step < (1 << 20); ++step) {
    if (within_ulp_of_segment(p, a, b)) return p;
    const Sign s = orient2d(a, b, p);  // Positive: p is on the left (normal side)
    const double dir = (s == Sign::Positive) ? -1.0 : 1.0;
    if (move_x)
      p.x = std::nextafter(p.x, dir * nx > 0 ? inf : -inf);
    else
      p.y = std::nextafter(p.y, dir * ny > 0 ? inf : -inf);
  }
  throw InternalError("quad2d: cannot round a point onto an input segment");
}

// Squared distance from p to the closed segment ab; t is the parameter of the
// nearest point (clamped to [0, 1]).
double distance2(Vec2 p, Vec2 a, Vec2 b, double& t) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  t = ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2;
  t = std::clamp(t, 0.0, 1.0);
  const double qx = a.x + t * dx - p.x, qy = a.y + t * dy - p.y;
  return qx * qx + qy * qy;
}


constexpr int kDropped = -3;

// The rounded crossing of input segment s with the box-side line {x = at}
// (vertical) or {y = at}, remembered: the two boxes on either side of a box
// side ask for the same crossing, and rounding it onto the segment
// (settle_on_segment) may need exact arithmetic. The construction is a
// function of (s, vertical, at) alone, so a remembered point is the point the
// second box would have made. Flat open addressing (linear probing, load at
// most 1/2); never iterated, so it cannot affect the output order.
class CrossingMemo {
 public:
  // The remembered point for the key, or nullptr.
  const Vec2* find(int s, bool vertical, double at) const {
    if (slots_.empty()) return nullptr;
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(at);
    for (std::size_t i = hash(s, vertical, bits) & mask_;; i = (i + 1) & mask_) {
      const Slot& e = slots_[i];
      if (e.segment < 0) return nullptr;
      if (e.segment == s && e.vertical == vertical && e.at_bits == bits) return &e.p;
    }
  }
  // Room for n points without growing (one allocation: the table's memory
  // goes back to the system as a whole when it is released). Empty table only.
  void reserve(std::size_t n) {
    std::size_t size = 64;
    while (size < 2 * n) size *= 2;
    if (count_ == 0 && size > slots_.size()) {
      slots_.assign(size, Slot{});
      mask_ = size - 1;
      count_ = 0;
    }
  }
  void insert(int s, bool vertical, double at, Vec2 p) {
    if (2 * (count_ + 1) > slots_.size()) grow();
    place({std::bit_cast<std::uint64_t>(at), s, vertical, p});
    ++count_;
  }

 private:
  struct Slot {
    std::uint64_t at_bits = 0;
    int segment = -1;  // -1: empty
    bool vertical = false;
    Vec2 p;
  };
  static std::size_t hash(int s, bool vertical, std::uint64_t bits) {
    std::uint64_t h = bits ^ (static_cast<std::uint64_t>(static_cast<std::uint32_t>(s)) << 1 | (vertical ? 1u : 0u)) *
                                 0x9E3779B97F4A7C15ull;
    h ^= h >> 31;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 29;
    return static_cast<std::size_t>(h);
  }
  void place(const Slot& x) {
    std::size_t i = hash(x.segment, x.vertical, x.at_bits) & mask_;
    while (slots_[i].segment >= 0) i = (i + 1) & mask_;
    slots_[i] = x;
  }
  void grow() {
    std::vector<Slot> old(std::max<std::size_t>(64, 2 * slots_.size()));
    old.swap(slots_);
    mask_ = slots_.size() - 1;
    for (const Slot& x : old)
      if (x.segment >= 0) place(x);
  }
  std::vector<Slot> slots_;
  std::size_t mask_ = 0, count_ = 0;
};

class PointGenerator {
 public:
  PointGenerator(const QuadtreeBuilder& b, QuadMeshStats& stats) : b_(b), d_(b.domain()), stats_(stats) {}

  MeshPoints run() {
    make_grid();
    if (grid_.xbits + grid_.ybits <= kMaxDirectBits)
      direct_corner_phase();
    else if (grid_.xbits + grid_.ybits + 1 <= 64)
      corner_phase(NarrowCorners{grid_});
    else
      corner_phase(WideCorners{grid_});
    place_crossings();
    return assemble();
  }

 private:
  Vec2 vertex(int v) const { return d_.pslg.vertices[static_cast<std::size_t>(v)]; }

  template <class T>
  static void release(std::vector<T>& v) {
    std::vector<T>().swap(v);
  }

  // p is closer to input vertex v than Lemma 1's clearance (a construction
  // compared with a threshold: either outcome is valid,
  // docs/algorithm/quad2d.md "Mesh vertices and warping").
  bool too_close(Vec2 p, int v) const {
    const Vec2 q = vertex(v);
    const double c = b_.vertex_clearance(v);
    return (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y) < c * c;
  }

  // The leaves that meet P and the integer grid of their corners.
  void make_grid() {
    const double inf = std::numeric_limits<double>::infinity();
    double x0 = inf, y0 = inf, x1 = -inf, y1 = -inf, h = inf;
    for (const std::int32_t n : b_.leaves_by_id()) {
      if (!b_.data(n).has_component) continue;
      leaves_.push_back(n);
      const Square s = b_.square(n);
      x0 = std::min(x0, s.lo.x);
      y0 = std::min(y0, s.lo.y);
      x1 = std::max(x1, s.lo.x + s.side);
      y1 = std::max(y1, s.lo.y + s.side);
      h = std::min(h, s.side);
    }
    if (leaves_.empty()) return;
    grid_.x0 = x0;
    grid_.y0 = y0;
    grid_.unit = h / 2;
    grid_.inv_unit = 1 / grid_.unit;  // exact: a power of two
    grid_.xbits = bit_width64(grid_.ix(x1));
    grid_.ybits = bit_width64(grid_.iy(y1));
  }

  // corner_phase without sorting, when the corner grid has at most
  // 2^kMaxDirectBits points: one byte per grid point, (records << 1) | busy,
  // where records counts the (leaf, corner) pairs at the point (saturating at
  // 127, so 4 means exactly 4) and busy is the or of their busy flags, the
  // same facts the sorted runs of corner_phase give. Only the grid lines that
  // hold a leaf corner get a row or column of the table (row_slot_ and
  // col_slot_ number them in increasing order, -1 for the others): a point on
  // any other line is no corner. On the plate of docs/algorithm/quad2d.md
  // "Speed and memory" that is about 1,000 of 8,192 lines each way, a table of
  // ~1 MB instead of 64 MiB of address space of which the used rows and the
  // scans of find_crossings touched ~3,500 pages. The distinct corners are the
  // non-zero bytes: the table itself answers find_crossings' questions
  // (grid_corners_around), and scanning the rows and columns in increasing
  // order places the corners in (x, y) order, as corner_phase does.
  static constexpr int kMaxDirectBits = 26;
  void direct_corner_phase() {
    const std::size_t rows = std::size_t{1} << grid_.xbits, cols = std::size_t{1} << grid_.ybits;
    std::vector<std::int32_t> row_slot(rows, -1), col_slot(cols, -1);
    const auto corner_lines = [&](std::int32_t n, std::uint64_t& i, std::uint64_t& j, std::uint64_t& w) {
      const Square s = b_.square(n);
      i = grid_.ix(s.lo.x);
      j = grid_.iy(s.lo.y);
      w = grid_.ix(s.lo.x + s.side) - i;
    };
    for (const std::int32_t n : leaves_) {
      std::uint64_t i = 0, j = 0, w = 0;
      corner_lines(n, i, j, w);
      row_slot[i] = row_slot[i + w] = col_slot[j] = col_slot[j + w] = 0;
    }
    std::vector<std::uint64_t> used_cols;  // the grid column of each table column
    std::size_t used_rows = 0;
    for (std::int32_t& r : row_slot)
      if (r == 0) r = static_cast<std::int32_t>(used_rows++);
    for (std::size_t j = 0; j < cols; ++j)
      if (col_slot[j] == 0) {
        col_slot[j] = static_cast<std::int32_t>(used_cols.size());
        used_cols.push_back(j);
      }
    const std::size_t width = used_cols.size();
    std::vector<std::uint8_t> cells(used_rows * width, 0);
    const auto cell = [&](std::uint64_t i, std::uint64_t j) -> std::uint8_t& {
      return cells[static_cast<std::size_t>(row_slot[i]) * width + static_cast<std::size_t>(col_slot[j])];
    };
    std::size_t distinct = 0;
    for (const std::int32_t n : leaves_) {
      const NodeData& nd = b_.data(n);
      const std::uint8_t busy = !nd.square_edges.empty() || nd.vertex_owner >= 0 ? 1 : 0;
      std::uint64_t i = 0, j = 0, w = 0;
      corner_lines(n, i, j, w);
      for (int k = 0; k < 4; ++k) {
        std::uint8_t& c = cell(i + static_cast<std::uint64_t>(k & 1) * w, j + static_cast<std::uint64_t>(k >> 1) * w);
        if (c == 0) ++distinct;
        c = static_cast<std::uint8_t>((c >> 1 < 127 ? c + 2 : c) | busy);
      }
    }
    cells_ = cells.data();
    row_slot_ = row_slot.data();
    col_slot_ = col_slot.data();
    width_ = width;
    find_crossings();
    cells_ = nullptr;
    row_slot_ = col_slot_ = nullptr;
    memo_ = CrossingMemo{};
    plain_.reserve(distinct);
    std::vector<int> segs;
    for (std::size_t i = 0; i < rows; ++i) {
      if (row_slot[i] < 0) continue;
      const std::uint8_t* row = &cells[static_cast<std::size_t>(row_slot[i]) * width];
      for (std::size_t t = 0; t < width; ++t) {
        // Most of a row is empty: skip eight empty bytes at once.
        if (t % 8 == 0 && t + 8 <= width) {
          std::uint64_t word;
          std::memcpy(&word, row + t, 8);
          if (word == 0) {
            t += 7;
            continue;
          }
        }
        const std::uint8_t c = row[t];
        if (c == 0) continue;
        // Fast path of place_corners: a corner of four leaves, none busy.
        if (c == (4 << 1))
          plain_.push_back(grid_.point(i, used_cols[t]));
        else
          place_corner(grid_.point(i, used_cols[t]), segs);
      }
    }
    std::sort(snaps_.begin(), snaps_.end());
  }

  // The grid of direct_corner_phase: whether grid point (i, j) is a leaf corner.
  bool is_corner(std::uint64_t i, std::uint64_t j) const {
    const std::int32_t r = row_slot_[i], c = col_slot_[j];
    return r >= 0 && c >= 0 && cells_[static_cast<std::size_t>(r) * width_ + static_cast<std::size_t>(c)] != 0;
  }

  // The leaf corners on the box-side line {x = at} (vertical) or {y = at}
  // nearest to p on either side: c1 the last one with across(c1) <= across(p),
  // c2 the first one with across(c2) > across(p), read off the grid (exact
  // comparisons with exact grid coordinates; the rounded index is only a
  // start). Exactly what sorted_corners_around gives.
  bool grid_corners_around(bool vertical, double at, Vec2 p, Vec2& c1, Vec2& c2) const {
    const std::uint64_t fixed = vertical ? grid_.ix(at) : grid_.iy(at);
    const std::int64_t n = std::int64_t{1} << (vertical ? grid_.ybits : grid_.xbits);
    const double v = vertical ? p.y : p.x, origin = vertical ? grid_.y0 : grid_.x0;
    const auto coord = [&](std::int64_t k) { return origin + static_cast<double>(k) * grid_.unit; };
    const auto corner = [&](std::int64_t k) {
      const auto u = static_cast<std::uint64_t>(k);
      return vertical ? is_corner(fixed, u) : is_corner(u, fixed);
    };
    // k: the last grid line with coord(k) <= v (-1: none).
    const double guess = std::floor((v - origin) * grid_.inv_unit);
    std::int64_t k = guess < 0 ? -1 : guess >= static_cast<double>(n - 1) ? n - 1 : static_cast<std::int64_t>(guess);
    while (k >= 0 && coord(k) > v) --k;
    while (k + 1 < n && coord(k + 1) <= v) ++k;
    std::int64_t lo = k, hi = k + 1;
    while (lo >= 0 && !corner(lo)) --lo;
    if (lo < 0) return false;
    while (hi < n && !corner(hi)) ++hi;
    if (hi >= n) return false;
    const auto point = [&](std::int64_t m) {
      const auto u = static_cast<std::uint64_t>(m);
      return vertical ? grid_.point(fixed, u) : grid_.point(u, fixed);
    };
    c1 = point(lo);
    c2 = point(hi);
    return true;
  }

  // The same from the distinct corners sorted by (x, y) (by_x_) and by (y, x)
  // (by_y_), which corner_phase makes.
  bool sorted_corners_around(bool vertical, double at, Vec2 p, Vec2& c1, Vec2& c2) const {
    const std::vector<Vec2>& line = vertical ? by_x_ : by_y_;
    const auto key_less = [vertical](Vec2 u, Vec2 w) {
      return vertical ? std::tie(u.x, u.y) < std::tie(w.x, w.y) : std::tie(u.y, u.x) < std::tie(w.y, w.x);
    };
    const auto along = [vertical](Vec2 q) { return vertical ? q.x : q.y; };
    auto it = std::upper_bound(line.begin(), line.end(), p, key_less);
    if (it == line.begin() || it == line.end()) return false;
    c2 = *it;
    c1 = *(it - 1);
    return along(c1) == at && along(c2) == at;  // else rounding carried p off the side's range
  }

  // Every leaf corner (once per leaf) sorted by (x, y); the distinct corners
  // by (x, y) and by (y, x) for find_crossings; then the corners are placed.
  template <class Codec>
  void corner_phase(const Codec& codec) {
    std::vector<typename Codec::Key> corners;
    corners.reserve(4 * leaves_.size());
    for (const std::int32_t n : leaves_) {
      const NodeData& nd = b_.data(n);
      const bool busy = !nd.square_edges.empty() || nd.vertex_owner >= 0;
      const Square s = b_.square(n);
      const std::uint64_t i = grid_.ix(s.lo.x), j = grid_.iy(s.lo.y), w = grid_.ix(s.lo.x + s.side) - i;
      for (int k = 0; k < 4; ++k) corners.push_back(codec.make(i + (k & 1) * w, j + (k >> 1) * w, busy));
    }
    codec.sort(corners);
    for (std::size_t i = 0; i < corners.size(); ++i)
      if (i == 0 || !codec.same(corners[i - 1], corners[i])) by_x_.push_back(codec.point(corners[i]));
    by_y_ = by_x_;
    {
      std::vector<Vec2> scratch;
      radix_sort(by_y_, grid_.xbits, [this](Vec2 p) { return grid_.ix(p.x); }, scratch);
      radix_sort(by_y_, grid_.ybits, [this](Vec2 p) { return grid_.iy(p.y); }, scratch);
    }
    find_crossings();
    memo_ = CrossingMemo{};
    release(by_x_);  // peak memory: each table goes as soon as it has served
    release(by_y_);
    place_corners(corners, codec);
  }

  // Corners: warp, keep, or drop (docs/algorithm/quad2d.md "Mesh vertices and
  // warping").
  template <class Codec>
  void place_corners(std::vector<typename Codec::Key>& corners, const Codec& codec) {
    std::vector<int> segs;
    for (std::size_t i = 0; i < corners.size();) {
      std::size_t j = i;
      bool busy = false;
      for (; j < corners.size() && codec.same(corners[i], corners[j]); ++j)
        if (codec.busy(corners[j])) busy = true;
      // Fast path: c is a corner of four leaves (so of no larger leaf's side),
      // none meets an input edge or lies in a vertex box: c is inside P, far
      // from the boundary, and stays as it is.
      if (j - i == 4 && !busy)
        plain_.push_back(codec.point(corners[i]));
      else
        place_corner(codec.point(corners[i]), segs);
      i = j;
    }
    release(corners);
    std::sort(snaps_.begin(), snaps_.end());
  }

  // A corner that is not on the fast path. Points it keeps as they are go to
  // plain_ (in (x, y) order, as the corners come), the others to points_.
  void place_corner(const Vec2 c, std::vector<int>& segs) {
    double h = std::numeric_limits<double>::infinity(), h_max = 0;
    segs.clear();
    std::int32_t edge_leaf = -1;
    // Every leaf whose closed square holds c, also those of which c is a
    // hanging corner (a point of a side, not a corner): their size matters.
    b_.tree().leaves_containing({c.x, c.y}, around_);
    for (const std::int32_t n : around_) {
      const NodeData& nd = b_.data(n);
      if (!nd.has_component) continue;
      const int owner = nd.vertex_owner;
      if (owner >= 0 && too_close(c, owner)) return;  // Lemma 1: keep clear of the vertex
      h = std::min(h, b_.tree().side(n));
      h_max = std::max(h_max, b_.tree().side(n));
      // Every edge meeting the squares (all components, Euclidean): a corner
      // that lies on the far side of a thin exterior slot is ON the edge there.
      for (const LoopEdge e : nd.square_edges)
        segs.push_back(d_.loop_segments[static_cast<std::size_t>(e.loop)][static_cast<std::size_t>(e.index)]);
      if (!nd.square_edges.empty()) edge_leaf = n;
    }
    std::sort(segs.begin(), segs.end());
    segs.erase(std::unique(segs.begin(), segs.end()), segs.end());
    // Warping radius: a quarter of the largest box at c, but at most a third of
    // the smallest (docs/algorithm/quad2d.md "Mesh vertices and warping"). Two
    // corners one grid step h apart are both warped onto an edge only if it
    // makes an angle phi with their side where h cos(phi) < 2r, and their
    // images are h sin(phi) apart: with r <= h/3 that is more than 0.74 h.
    const double r = std::min(h_max / 4, h / 3), r2 = r * r;
    bool warped = false;
    for (const int s : segs) {
      const auto& seg = d_.pslg.segments[static_cast<std::size_t>(s)];
      const Vec2 a = vertex(seg[0]), e = vertex(seg[1]);
      double t = 0;
      if (!(distance2(c, a, e, t) < r2) && !std::binary_search(forced_.begin(), forced_.end(), Snap{c.x, c.y, s}))
        continue;
      warped = true;
      snaps_.push_back({c.x, c.y, s});
      if (t <= 0 || t >= 1) continue;  // nearest point is an input vertex, already a mesh vertex
      Vec2 p = c;
      if (orient2d(a, e, c) != Sign::Zero) p = settle_on_segment({a.x + t * (e.x - a.x), a.y + t * (e.y - a.y)}, a, e, false, false);
      points_.push_back({p, s, -1, h});
      ++stats_.warped;
    }
    if (warped) return;
    if (edge_leaf >= 0) {
      const SquareComponents sc = b_.components_of(edge_leaf);
      if (locate_component(d_, sc, c) < 0) return;  // outside P
    }
    plain_.push_back(c);
  }

  bool snapped(Vec2 c, int segment) const { return std::binary_search(snaps_.begin(), snaps_.end(), Snap{c.x, c.y, segment}); }

  // Crossings of input edges with leaf sides (docs/algorithm/quad2d.md "Mesh
  // vertices and warping"), each with the two corners around it on its side.
  // Warping (thesis §4.3 in 2D): the corner nearer to the crossing is moved
  // onto the edge, and the crossing itself is then not kept (the warped corner
  // stands for it). A crossing exactly in the middle of its side, or whose
  // nearer corner must stay clear of an input vertex (Lemma 1), is kept as a
  // vertex instead.
  void find_crossings() {
    // A segment crosses the boundary of a box at most twice (both convex).
    std::size_t pairs = 0;
    for (const std::int32_t n : leaves_) pairs += b_.data(n).segments.size();
    memo_.reserve(2 * pairs);
    for (const std::int32_t n : leaves_) {
      const NodeData& nd = b_.data(n);
      if (nd.segments.empty()) continue;
      const Square sq = b_.square(n);
      const double x0 = sq.lo.x, y0 = sq.lo.y, x1 = x0 + sq.side, y1 = y0 + sq.side;
      for (const int s : nd.segments) {
        crossing(s, true, x0, y0, y1, nd.vertex_owner);
        crossing(s, true, x1, y0, y1, nd.vertex_owner);
        crossing(s, false, y0, x0, x1, nd.vertex_owner);
        crossing(s, false, y1, x0, x1, nd.vertex_owner);
      }
    }
    for (const Crossing& x : crossings_) {
      const auto across = [&x](Vec2 p) { return x.vertical ? p.y : p.x; };
      const double below = across(x.p) - across(x.c1), above = across(x.c2) - across(x.p);
      if (below < above && !(x.owner >= 0 && too_close(x.c1, x.owner)))
        forced_.push_back({x.c1.x, x.c1.y, x.segment});
      else if (above < below && !(x.owner >= 0 && too_close(x.c2, x.owner)))
        forced_.push_back({x.c2.x, x.c2.y, x.segment});
    }
    std::sort(forced_.begin(), forced_.end());
  }

  void place_crossings() {
    std::sort(crossings_.begin(), crossings_.end(), [](const Crossing& u, const Crossing& w) {
      return std::tie(u.p.x, u.p.y, u.segment) < std::tie(w.p.x, w.p.y, w.segment);
    });
    for (std::size_t i = 0; i < crossings_.size(); ++i) {
      const Crossing& x = crossings_[i];
      if (i > 0 && crossings_[i - 1].p.x == x.p.x && crossings_[i - 1].p.y == x.p.y && crossings_[i - 1].segment == x.segment)
        continue;  // the same side seen from two boxes
      if (snapped(x.c1, x.segment) || snapped(x.c2, x.segment)) continue;
      points_.push_back({x.p, x.segment, -1, x.scale});
      ++stats_.edge_points;
    }
  }

  // Segment s against the box side {x = at, lo <= y <= hi} (vertical) or
  // {y = at, lo <= x <= hi}.
  void crossing(int s, bool vertical, double at, double lo, double hi, int owner) {
    const auto& seg = d_.pslg.segments[static_cast<std::size_t>(s)];
    Vec2 a = vertex(seg[0]), e = vertex(seg[1]);
    const Rect side = vertical ? Rect{{at, lo}, {at, hi}} : Rect{{lo, at}, {hi, at}};
    if (!segment_meets_rect(a, e, side)) return;
    const auto along = [vertical](Vec2 p) { return vertical ? p.x : p.y; };
    const auto across = [vertical](Vec2 p) { return vertical ? p.y : p.x; };
    if (along(a) == at || along(e) == at) return;  // an endpoint on the side (or the edge runs along it)
    if (along(a) > along(e)) std::swap(a, e);         // canonical: the same double from every box
    Vec2 p;
    if (const Vec2* known = memo_.find(s, vertical, at)) {
      p = *known;
    } else {
      const double t = (at - along(a)) / (along(e) - along(a));
      const double v = across(a) + t * (across(e) - across(a));
      p = settle_on_segment(vertical ? Vec2{at, v} : Vec2{v, at}, a, e, vertical, !vertical);
      memo_.insert(s, vertical, at, p);
    }
    if (owner >= 0 && too_close(p, owner)) return;
    // The corners on this line around p.
    Vec2 c1, c2;
    if (!(cells_ != nullptr ? grid_corners_around(vertical, at, p, c1, c2) : sorted_corners_around(vertical, at, p, c1, c2)))
      return;
    if (across(c1) == across(p)) return;  // p is a corner: the corner was warped
    crossings_.push_back({p, s, c1, c2, owner, vertical, across(c2) - across(c1)});
  }

  // The Steiner points along each input segment, in order, keep a gap of at
  // least a quarter of the smaller of their two scales: a point closer than
  // that to the previous kept one (or to the segment's far end) is dropped.
  // Dropping a Steiner point never breaks the mesh (the triangulation
  // connects what is left); it only removes the rare pair that warps of
  // corners of different box sizes bring close together.
  void thin_segments() {
    std::vector<std::vector<std::size_t>> on(d_.pslg.segments.size());
    for (std::size_t i = 0; i < points_.size(); ++i)
      if (points_[i].segment >= 0) on[static_cast<std::size_t>(points_[i].segment)].push_back(i);
    for (std::size_t s = 0; s < on.size(); ++s) {
      if (on[s].empty()) continue;
      const auto& seg = d_.pslg.segments[s];
      const Vec2 a = vertex(seg[0]), e = vertex(seg[1]);
      const auto param = [&](std::size_t i) {
        const Vec2 p = points_[i].p;
        return (p.x - a.x) * (e.x - a.x) + (p.y - a.y) * (e.y - a.y);
      };
      std::sort(on[s].begin(), on[s].end(), [&](std::size_t u, std::size_t w) {
        const double pu = param(u), pw = param(w);
        return pu != pw ? pu < pw : u < w;
      });
      Vec2 last = a;
      double last_scale = std::numeric_limits<double>::infinity();
      for (const std::size_t i : on[s]) {
        const Tagged& t = points_[i];
        const double gap = 0.25 * std::min(t.scale, last_scale);
        const double to_end = std::hypot(e.x - t.p.x, e.y - t.p.y);
        if (std::hypot(t.p.x - last.x, t.p.y - last.y) < gap || to_end < 0.25 * t.scale) {
          points_[i].segment = kDropped;
          continue;
        }
        last = t.p;
        last_scale = t.scale;
      }
    }
    points_.erase(std::remove_if(points_.begin(), points_.end(), [](const Tagged& t) { return t.segment == kDropped; }),
                  points_.end());
  }

  // The points in (x, y) order, merged from plain_ (sorted, distinct, none
  // on a segment or an input vertex) and the sorted points_; at equal
  // coordinates the plain point comes first, as (x, y, -1, -1) sorts first.
  MeshPoints assemble() {
    thin_segments();
    for (std::size_t v = 0; v < d_.pslg.vertices.size(); ++v) points_.push_back({d_.pslg.vertices[v], -1, static_cast<int>(v)});
    std::vector<char> on_loop(d_.pslg.vertices.size(), 0);
    for (const auto& loop : d_.loops)
      for (const int v : loop) on_loop[static_cast<std::size_t>(v)] = 1;
    std::sort(points_.begin(), points_.end(), [](const Tagged& a, const Tagged& c) {
      return std::tie(a.p.x, a.p.y, a.vertex, a.segment) < std::tie(c.p.x, c.p.y, c.vertex, c.segment);
    });
    MeshPoints out;
    out.points.reserve(plain_.size() + points_.size());
    out.input_vertex.reserve(plain_.size() + points_.size());
    out.segment_chain.assign(d_.pslg.segments.size(), {});
    std::vector<int> vertex_point(d_.pslg.vertices.size(), -1);
    const auto same = [](Vec2 u, Vec2 w) { return u.x == w.x && u.y == w.y; };
    const auto less = [](Vec2 u, Vec2 w) { return u.x < w.x || (u.x == w.x && u.y < w.y); };
    std::size_t next_plain = 0, i = 0;  // next in plain_, next in points_
    while (next_plain < plain_.size() || i < points_.size()) {
      const bool take_plain =
          i == points_.size() || (next_plain < plain_.size() && !less(points_[i].p, plain_[next_plain]));
      const Vec2 p = take_plain ? plain_[next_plain] : points_[i].p;
      std::size_t count = 0;
      if (take_plain) {
        ++next_plain;
        ++count;
      }
      std::size_t j = i;
      int vertex_id = -1;
      while (j < points_.size() && same(points_[j].p, p)) {
        vertex_id = std::max(vertex_id, points_[j].vertex);
        ++j;
        ++count;
      }
      if (vertex_id >= 0 && !on_loop[static_cast<std::size_t>(vertex_id)]) vertex_id = -2;  // isolated input vertex
      // Isolated vertices are not meshed (docs/algorithm/quad2d.md "Mesh vertices and warping").
      if (vertex_id == -2 && count == 1) {
        i = j;
        continue;
      }
      const int id = static_cast<int>(out.points.size());
      out.points.push_back(p);
      out.input_vertex.push_back(vertex_id >= 0 ? vertex_id : -1);
      if (vertex_id >= 0) vertex_point[static_cast<std::size_t>(vertex_id)] = id;
      for (std::size_t k = i; k < j; ++k)
        if (points_[k].segment >= 0 && points_[k].vertex < 0) {
          auto& chain = out.segment_chain[static_cast<std::size_t>(points_[k].segment)];
          if (chain.empty() || chain.back() != id) chain.push_back(id);
        }
      i = j;
    }
    release(plain_);
    release(points_);
    for (std::size_t s = 0; s < d_.pslg.segments.size(); ++s) {
      const auto& seg = d_.pslg.segments[s];
      const int pa = vertex_point[static_cast<std::size_t>(seg[0])], pb = vertex_point[static_cast<std::size_t>(seg[1])];
      if (pa < 0 || pb < 0) throw InternalError("quad2d: an input vertex of segment " + std::to_string(s) + " was lost");
      auto& chain = out.segment_chain[s];
      const Vec2 a = out.points[static_cast<std::size_t>(pa)], e = out.points[static_cast<std::size_t>(pb)];
      const auto param = [&](int id) {
        const Vec2 p = out.points[static_cast<std::size_t>(id)];
        return (p.x - a.x) * (e.x - a.x) + (p.y - a.y) * (e.y - a.y);
      };
      std::sort(chain.begin(), chain.end(), [&](int u, int w) { return param(u) < param(w); });
      chain.erase(std::remove(chain.begin(), chain.end(), pa), chain.end());
      chain.erase(std::remove(chain.begin(), chain.end(), pb), chain.end());
      chain.insert(chain.begin(), pa);
      chain.push_back(pb);
    }
    return out;
  }

  const QuadtreeBuilder& b_;
  const Domain2& d_;
  QuadMeshStats& stats_;
  std::vector<std::int32_t> leaves_;
  CornerGrid grid_;
  std::vector<Vec2> by_x_, by_y_;  // corner_phase: distinct corners sorted by (x, y) and by (y, x)
  // direct_corner_phase's table while find_crossings runs (is_corner).
  const std::uint8_t* cells_ = nullptr;
  const std::int32_t* row_slot_ = nullptr;
  const std::int32_t* col_slot_ = nullptr;
  std::size_t width_ = 0;
  std::vector<Snap> snaps_;
  std::vector<Snap> forced_;        // (corner, segment): a crossing forces the corner onto the segment
  std::vector<Crossing> crossings_;
  CrossingMemo memo_;  // find_crossings only
  std::vector<std::int32_t> around_;
  std::vector<Vec2> plain_;     // corners kept where they are, in (x, y) order
  std::vector<Tagged> points_;  // the other points: on segments, input vertices
};

}  // namespace

MeshPoints generate_points(const QuadtreeBuilder& builder, QuadMeshStats& stats) {
  return PointGenerator(builder, stats).run();
}

}  // namespace pqmesh::quad2d
