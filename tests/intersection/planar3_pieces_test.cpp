// SPDX-License-Identifier: BSL-1.0
// Row int3.linear-polygon: intersection_pieces() of Line3, Ray3 and Segment3 with a filled
// PlanarPolygon3, float and double. Oracle (GMP rationals, brute force): the component's frame
// image (exact on axis-aligned frames; on tilted frames the documented rounded image, to_plane in
// double) is cut at every parameter where its carrier meets an edge (solved in rationals) and at
// its own ends; each cut point and the midpoint of each span between consecutive cuts is
// classified exactly against the closed polygon (crossing number and boundary test in
// rationals), and consecutive included items merge into pieces. A different method from the
// library's (exact ordering of named positions and an even-odd count along the line). Polygons:
// combs, a spiral, a pentagram, collinear and repeated vertices, random integer stars;
// components on integer grids run through vertices, along edges and touch reflex vertices.
// Also: intersection() is the span of the pieces, swapped arguments, crossing components,
// power-of-two scaling, degenerate and non-finite input.

#include <locus/intersection/line_polygon.hpp>
#include <locus/intersection/ray_polygon.hpp>
#include <locus/intersection/segment_polygon.hpp>
#include <locus/primitives/polygon.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <gmpxx.h>

#include "support/typed.hpp"

namespace {

using namespace locus;
using locus_test::Rng;

template <class T>
class IntersectionPlanar3Pieces : public ::testing::Test {};
TYPED_TEST_SUITE(IntersectionPlanar3Pieces, locus_test::RealTypes);

struct Q2 {
  mpq_class x, y;
};
Q2 operator-(const Q2& a, const Q2& b) { return {a.x - b.x, a.y - b.y}; }
mpq_class qcross(const Q2& a, const Q2& b) { return a.x * b.y - a.y * b.x; }
mpq_class qdot(const Q2& a, const Q2& b) { return a.x * b.x + a.y * b.y; }

// Closed polygon membership in rationals: on an edge, or inside by the crossing number.
bool q_in_polygon(const std::vector<Q2>& p, const Q2& x) {
  bool in = false;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
    const Q2& a = p[j];
    const Q2& b = p[i];
    const Q2 e = b - a, w = x - a;
    const bool on = e.x == 0 && e.y == 0
                        ? w.x == 0 && w.y == 0
                        : qcross(e, w) == 0 && qdot(e, w) >= 0 && qdot(e, w) <= qdot(e, e);
    if (on) return true;
    if ((a.y > x.y) != (b.y > x.y)) {
      const mpq_class xi = a.x + (x.y - a.y) * e.x / e.y;
      if (xi > x.x) in = !in;
    }
  }
  return in;
}

struct QPiece {
  mpq_class t0, t1;
  bool segment;
};

// The exact pieces of the 2D component o + t d (t >= 0 if lo, t <= 1 if hi) in the polygon.
std::vector<QPiece> q_pieces(const std::vector<Q2>& poly, const Q2& o, const Q2& d, bool lo,
                             bool hi) {
  std::vector<QPiece> out;
  const auto at = [&](const mpq_class& t) { return Q2{o.x + t * d.x, o.y + t * d.y}; };
  if (d.x == 0 && d.y == 0) {
    if (q_in_polygon(poly, o)) out.push_back({0, 0, false});
    return out;
  }
  std::vector<mpq_class> cuts;
  if (lo) cuts.push_back(0);
  if (hi) cuts.push_back(1);
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Q2& a = poly[i];
    const Q2& b = poly[(i + 1) % poly.size()];
    const Q2 e = b - a, w = a - o;
    const mpq_class den = qcross(d, e);
    if (den != 0) {
      const mpq_class s = qcross(w, d) / den;
      if (s >= 0 && s <= 1) cuts.push_back(qcross(w, e) / den);
    } else if (qcross(w, d) == 0) {
      cuts.push_back(qdot(w, d) / qdot(d, d));
      cuts.push_back(qdot(b - o, d) / qdot(d, d));
    }
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  std::vector<mpq_class> in_domain;
  for (const mpq_class& t : cuts)
    if (!(lo && t < 0) && !(hi && t > 1)) in_domain.push_back(t);
  if (in_domain.empty()) return out;
  // Items: cut k (2k) and the span after it (2k + 1); the spans beyond the domain's unbounded
  // ends hold no piece (checked: outside).
  const std::size_t k = in_domain.size();
  if (!lo) {
    EXPECT_FALSE(q_in_polygon(poly, at(in_domain.front() - 1)));
  }
  if (!hi) {
    EXPECT_FALSE(q_in_polygon(poly, at(in_domain.back() + 1)));
  }
  bool open = false;
  for (std::size_t i = 0; i < k; ++i) {
    const bool point_in = q_in_polygon(poly, at(in_domain[i]));
    const bool span_in = i + 1 < k && q_in_polygon(poly, at((in_domain[i] + in_domain[i + 1]) / 2));
    if (!point_in) {
      EXPECT_FALSE(open);
      continue;
    }
    if (!open) out.push_back({in_domain[i], in_domain[i], false});
    out.back().t1 = in_domain[i];
    out.back().segment = out.back().t0 != out.back().t1;
    open = span_in;
  }
  return out;
}

// An axis-aligned frame (exact frame coordinates): the plane z = c, x = c or y = c.
template <class T>
PlaneFrame3<T> axis_frame(int which, const Vec3<T>& origin) {
  switch (which) {
    case 1:
      return {origin, {0, 1, 0}, {0, 0, 1}, {1, 0, 0}};
    case 2:
      return {origin, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}};
    case 3:
      return {origin, {0, -1, 0}, {1, 0, 0}, {0, 0, 1}};
    default:
      return {origin, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  }
}

template <class T>
Polygon2<T> poly2(std::initializer_list<std::pair<int, int>> v) {
  Polygon2<T> p;
  for (const auto& [x, y] : v) p.vertices.push_back({T(x), T(y)});
  return p;
}

template <class T>
std::vector<Polygon2<T>> named_polygons() {
  return {
      // A comb of three teeth.
      poly2<T>({{0, 0},
                {7, 0},
                {7, 3},
                {6, 3},
                {6, 1},
                {5, 1},
                {5, 3},
                {4, 3},
                {4, 1},
                {3, 1},
                {3, 3},
                {2, 3},
                {2, 1},
                {1, 1},
                {1, 3},
                {0, 3}}),
      // A square spiral of corridors of width 1.
      poly2<T>({{0, 0},
                {5, 0},
                {5, 5},
                {0, 5},
                {0, 2},
                {3, 2},
                {3, 3},
                {1, 3},
                {1, 4},
                {4, 4},
                {4, 1},
                {0, 1}}),
      // A U (reflex vertices at (2, 1), (1, 1)), clockwise.
      poly2<T>({{0, 0}, {0, 3}, {1, 3}, {1, 1}, {2, 1}, {2, 3}, {3, 3}, {3, 0}}),
      // A pentagram (self-crossing: its centre is outside by the even-odd rule).
      poly2<T>({{0, 6}, {3, -4}, {-5, 2}, {5, 2}, {-3, -4}}),
      // Collinear and repeated vertices.
      poly2<T>({{0, 0}, {2, 0}, {2, 0}, {4, 0}, {4, 2}, {2, 2}, {0, 2}}),
      // Two squares touching at a vertex (a pinched polygon).
      poly2<T>({{0, 0}, {2, 0}, {2, 2}, {4, 2}, {4, 4}, {2, 4}, {2, 2}, {0, 2}}),
  };
}

template <class T>
Polygon2<T> random_star(Rng& rng) {
  Polygon2<T> p;
  const int n = rng.uniform_int(5, 12);
  for (int k = 0; k < n; ++k) {
    const double a = 2 * 3.141592653589793 * k / n, r = rng.uniform<double>(1.0, 6.0);
    p.vertices.push_back({T(std::round(3 + r * std::cos(a))), T(std::round(3 + r * std::sin(a)))});
  }
  return p;
}

template <class A>
struct Make;
template <class T>
struct Make<Line3<T>> {
  static Line3<T> from(const Vec3<T>& p, const Vec3<T>& q) { return {p, q - p}; }
  static constexpr bool lo = false, hi = false;
};
template <class T>
struct Make<Ray3<T>> {
  static Ray3<T> from(const Vec3<T>& p, const Vec3<T>& q) { return {p, q - p}; }
  static constexpr bool lo = true, hi = false;
};
template <class T>
struct Make<Segment3<T>> {
  static Segment3<T> from(const Vec3<T>& p, const Vec3<T>& q) { return {p, q}; }
  static constexpr bool lo = true, hi = true;
};
template <class T, class F>
void for_each_linear(F&& f) {
  f.template operator()<Line3<T>>();
  f.template operator()<Ray3<T>>();
  f.template operator()<Segment3<T>>();
}

template <class T>
Vec3<T> origin_of(const Line3<T>& l) {
  return l.origin;
}
template <class T>
Vec3<T> origin_of(const Ray3<T>& l) {
  return l.origin;
}
template <class T>
Vec3<T> origin_of(const Segment3<T>& l) {
  return l.p0;
}
template <class T>
Vec3<double> dir_of(const Line3<T>& l) {
  return vec_cast<double>(l.direction);
}
template <class T>
Vec3<double> dir_of(const Ray3<T>& l) {
  return vec_cast<double>(l.direction);
}

// The component's frame image as the library maps it (the documented rounding): to_plane in
// double of the origin, and of the direction (line, ray) or the end point (segment).
template <class T, class A>
std::pair<Q2, Q2> q_image(const A& a, const PlaneFrame3<T>& f) {
  const PlaneFrame3<double> fd{vec_cast<double>(f.origin), vec_cast<double>(f.u),
                               vec_cast<double>(f.v), vec_cast<double>(f.normal)};
  const Vec2<double> o = to_plane(fd, vec_cast<double>(origin_of(a)));
  Vec2<double> d;
  if constexpr (std::is_same_v<A, Segment3<T>>) {
    const Vec2<double> q = to_plane(fd, vec_cast<double>(a.p1));
    return {Q2{o.x, o.y}, Q2{mpq_class(q.x) - o.x, mpq_class(q.y) - o.y}};
  } else {
    const PlaneFrame3<double> f0{{0, 0, 0}, fd.u, fd.v, fd.normal};
    d = to_plane(f0, dir_of(a));
    return {Q2{o.x, o.y}, Q2{d.x, d.y}};
  }
}

// Compares intersection_pieces(a, poly) with the oracle on the component's image; returns the
// number of pieces.
template <class T, class A>
int check_pieces(const A& a, const PlanarPolygon3<T>& poly, const std::string& what) {
  SCOPED_TRACE(what);
  std::vector<Q2> qp;
  for (const Vec2<T>& v : poly.polygon.vertices) qp.push_back({double(v.x), double(v.y)});
  const auto [o2, d2] = q_image<T>(a, poly.frame);
  const std::vector<QPiece> want = q_pieces(qp, o2, d2, Make<A>::lo, Make<A>::hi);
  const LinearPlanarPieces<T> got = intersection_pieces(a, poly);
  EXPECT_EQ(got.status, Status::ok);
  EXPECT_EQ(got.pieces.size(), want.size());
  if (got.pieces.size() != want.size()) return 0;
  const double eps = double(std::numeric_limits<T>::epsilon());
  const double scale = std::max({1.0, std::abs(o2.x.get_d()), std::abs(o2.y.get_d())});
  const double dlen = std::hypot(d2.x.get_d(), d2.y.get_d());
  for (std::size_t i = 0; i < want.size(); ++i) {
    const auto& g = got.pieces[i];
    EXPECT_EQ(g.kind, want[i].segment ? Kind::segment : Kind::point) << i;
    EXPECT_EQ(g.count, want[i].segment ? 2 : 1) << i;
    const mpq_class ts[2] = {want[i].t0, want[i].t1};
    for (std::size_t k = 0; k < static_cast<std::size_t>(g.count); ++k) {
      const double t = ts[k].get_d();
      EXPECT_NEAR(double(g.param_a[k]), t, 32 * eps * (std::abs(t) + scale / dlen)) << i;
      const Q2 st{o2.x + ts[k] * d2.x, o2.y + ts[k] * d2.y};
      const double m = std::max(
          {scale, std::abs(st.x.get_d()), std::abs(st.y.get_d()), double(max_abs(g.point[k]))});
      EXPECT_NEAR(double(g.param_b[k].x), st.x.get_d(), 32 * eps * m) << i;
      EXPECT_NEAR(double(g.param_b[k].y), st.y.get_d(), 32 * eps * m) << i;
      // The 3D point is the component's point at param_a, and lies at param_b in the frame.
      EXPECT_TRUE(locus_test::vec_near(point_at(a, g.param_a[k]), g.point[k], T(32 * eps * m)));
      EXPECT_TRUE(locus_test::vec_near(point_at(poly, g.param_b[k]), g.point[k], T(64 * eps * m)));
    }
    if (i > 0) {
      const auto& prev = got.pieces[i - 1];
      EXPECT_LE(prev.param_a[static_cast<std::size_t>(prev.count - 1)], g.param_a[0]) << i;
    }
  }
  // intersection(): the span from the first piece to the last, its kind exact.
  const auto r = intersection(a, poly);
  if (want.empty()) {
    EXPECT_EQ(r.kind, Kind::empty);
  } else {
    const bool seg = want.size() > 1 || want[0].segment;
    EXPECT_EQ(r.kind, seg ? Kind::segment : Kind::point);
    const double t0 = want.front().t0.get_d(), t1 = want.back().t1.get_d();
    EXPECT_NEAR(double(r.param_a[0]), t0, 32 * eps * (std::abs(t0) + scale / dlen));
    if (seg) {
      EXPECT_NEAR(double(r.param_a[1]), t1, 32 * eps * (std::abs(t1) + scale / dlen));
    }
  }
  // Swapped arguments: the same pieces, parameters exchanged.
  const auto s = intersection_pieces(poly, a);
  EXPECT_EQ(s.pieces.size(), got.pieces.size());
  for (std::size_t i = 0; i < std::min(s.pieces.size(), got.pieces.size()); ++i) {
    EXPECT_EQ(s.pieces[i].param_a, got.pieces[i].param_b);
    EXPECT_EQ(s.pieces[i].param_b, got.pieces[i].param_a);
  }
  return static_cast<int>(want.size());
}

// Axis-aligned frames: the frame image is exact, so every decision is compared without margin:
// components on the integer grid through vertices, along edges, touching reflex vertices.
TYPED_TEST(IntersectionPlanar3Pieces, ExactFramesAgainstOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  std::vector<Polygon2<T>> polys = named_polygons<T>();
  for (int k = 0; k < 3; ++k) polys.push_back(random_star<T>(rng));
  int pieces = 0, multi = 0, points = 0, cases = 0;
  for (std::size_t pi = 0; pi < polys.size(); ++pi) {
    const Vec3<T> origin{T(rng.uniform_int(-4, 4)) / 2, T(rng.uniform_int(-4, 4)) / 4,
                         T(rng.uniform_int(-4, 4))};
    const PlanarPolygon3<T> poly{axis_frame<T>(static_cast<int>(pi % 4), origin), polys[pi]};
    for_each_linear<T>([&]<class A>() {
      for (int i = 0; i < 10; ++i) {
        const auto g = [&] {
          const Vec2<T> st{T(rng.uniform_int(-2, 16)) / 2, T(rng.uniform_int(-2, 14)) / 2};
          return point_at(poly, st);
        };
        const Vec3<T> p = g();
        Vec3<T> q = g();
        if (i % 5 == 0) q = p;  // a zero direction acts as its point
        const A a = Make<A>::from(p, q);
        const int n = check_pieces<T>(
            a, poly, "polygon " + std::to_string(pi) + " case " + std::to_string(i));
        ++cases;
        pieces += n;
        multi += n > 1;
        const auto r = intersection_pieces(a, poly);
        for (const auto& c : r.pieces) points += c.kind == Kind::point;
        if (::testing::Test::HasFailure()) return;
      }
    });
  }
  EXPECT_GT(pieces, cases / 2);
  EXPECT_GT(multi, cases / 10);  // several pieces: the gaps of non-convex polygons
  EXPECT_GT(points, 20);         // touching points (vertices met from outside)
}

// Tilted planes: the normal (1, 2, 2) / 3 (and (2, 3, 6) / 7) rounded, u and v the other rows of
// the rational orthogonal matrix; points a (2, 1, -2) + b (2, -2, 1) lie exactly in the plane,
// and their rounded frame image passes within an ulp of vertices: the oracle runs on that image.
TYPED_TEST(IntersectionPlanar3Pieces, TiltedFramesAgainstOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  struct Rot {
    int n[3], u[3], v[3], den;
  };
  constexpr Rot rots[] = {{{1, 2, 2}, {2, 1, -2}, {2, -2, 1}, 3},
                          {{2, 3, 6}, {6, 2, -3}, {3, -6, 2}, 7}};
  int pieces = 0, cases = 0;
  for (const Rot& rot : rots) {
    const T inv = T(1) / T(rot.den);
    const auto vec = [&](const int* c, T s) {
      return Vec3<T>{T(c[0]) * s, T(c[1]) * s, T(c[2]) * s};
    };
    const Vec3<T> origin{T(rng.uniform_int(-8, 8)) / 4, T(rng.uniform_int(-8, 8)) / 4,
                         T(rng.uniform_int(-8, 8)) / 4};
    // The normal (2, 3, 6) / 8 is exact, so the points above lie exactly in the plane; u and v
    // are rounded (their rounding is part of the documented frame image).
    const PlaneFrame3<T> f{origin, vec(rot.u, inv), vec(rot.v, inv), vec(rot.n, T(0.125))};
    std::vector<Polygon2<T>> polys = named_polygons<T>();
    polys.push_back(random_star<T>(rng));
    for (Polygon2<T>& p : polys)
      for (Vec2<T>& v : p.vertices) v = v * T(rot.den);  // grid points map near vertices
    for (std::size_t pi = 0; pi < polys.size(); ++pi) {
      const PlanarPolygon3<T> poly{f, polys[pi]};
      for_each_linear<T>([&]<class A>() {
        for (int i = 0; i < 5; ++i) {
          const auto g = [&] {
            const T s = T(rng.uniform_int(-1, 8)), t = T(rng.uniform_int(-1, 7));
            return origin + vec(rot.u, s) + vec(rot.v, t);
          };
          const Vec3<T> p = g(), q = g();  // in order (not as arguments)
          const A a = Make<A>::from(p, q);
          pieces += check_pieces<T>(a, poly, "tilted " + std::to_string(pi));
          ++cases;
          if (::testing::Test::HasFailure()) return;
        }
      });
    }
  }
  EXPECT_GT(pieces, cases / 3);
}

// Worked cases: the comb crossed through its teeth, along its base and touching the tips.
TYPED_TEST(IntersectionPlanar3Pieces, CombFigures) {
  using T = TypeParam;
  const PlanarPolygon3<T> comb{axis_frame<T>(0, {0, 0, 2}), named_polygons<T>()[0]};
  // Through the four teeth at height 2: [0, 1], [2, 3], [4, 5], [6, 7] of x in [-1, 15].
  const Segment3<T> across{{-1, 2, 2}, {15, 2, 2}};
  const auto r = intersection_pieces(across, comb);
  ASSERT_EQ(r.pieces.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(r.pieces[i].kind, Kind::segment);
    EXPECT_EQ(r.pieces[i].point[0], (Vec3<T>{T(2 * i), 2, 2}));
    EXPECT_EQ(r.pieces[i].point[1], (Vec3<T>{T(2 * i + 1), 2, 2}));
    EXPECT_EQ(r.pieces[i].param_b[0], (Vec2<T>{T(2 * i), 2}));
  }
  // Along the tips' line y = 3: the tips' top edges, which are boundary.
  const auto tips = intersection_pieces(Line3<T>{{0, 3, 2}, {1, 0, 0}}, comb);
  ASSERT_EQ(tips.pieces.size(), 4u);
  EXPECT_EQ(tips.pieces[3].param_a[0], T(6));
  EXPECT_EQ(tips.pieces[3].param_a[1], T(7));
  // Along y = 1 (through the notches' floors): one piece, the whole width.
  const auto floor = intersection_pieces(Ray3<T>{{-3, 1, 2}, {2, 0, 0}}, comb);
  ASSERT_EQ(floor.pieces.size(), 1u);
  EXPECT_EQ(floor.pieces[0].param_a[0], T(1.5));
  EXPECT_EQ(floor.pieces[0].param_a[1], T(5));
  // The diagonal x + y = 3: the first tooth from its corner (0, 3) to (1, 2), the gap of the
  // notch, then the base from the notch's corner (2, 1) to (3, 0).
  const auto diag = intersection_pieces(Line3<T>{{0, 3, 2}, {1, -1, 0}}, comb);
  ASSERT_EQ(diag.pieces.size(), 2u);
  EXPECT_EQ(diag.pieces[0].param_b[0], (Vec2<T>{0, 3}));
  EXPECT_EQ(diag.pieces[0].param_b[1], (Vec2<T>{1, 2}));
  EXPECT_EQ(diag.pieces[1].param_b[0], (Vec2<T>{2, 1}));
  EXPECT_EQ(diag.pieces[1].param_b[1], (Vec2<T>{3, 0}));
  // The U: the line y = 1 runs along the notch's floor (reflex vertices (1, 1), (2, 1)), a
  // boundary segment joining both arms: one piece.
  const PlanarPolygon3<T> u{axis_frame<T>(0, {0, 0, 0}), named_polygons<T>()[2]};
  const auto fl = intersection_pieces(Line3<T>{{0, 1, 0}, {1, 0, 0}}, u);
  ASSERT_EQ(fl.pieces.size(), 1u);
  EXPECT_EQ(fl.pieces[0].param_a[0], T(0));
  EXPECT_EQ(fl.pieces[0].param_a[1], T(3));
  // Touching the pentagram's outer vertex (0, 6) from above: a single point.
  const PlanarPolygon3<T> star{axis_frame<T>(0, {0, 0, 0}), named_polygons<T>()[3]};
  const auto top = intersection_pieces(Line3<T>{{-1, 6, 0}, {1, 0, 0}}, star);
  ASSERT_EQ(top.pieces.size(), 1u);
  EXPECT_EQ(top.pieces[0].kind, Kind::point);
  EXPECT_EQ(top.pieces[0].point[0], (Vec3<T>{0, 6, 0}));
  // Through the pinch of two squares meeting at (2, 2): two segments joined at the pinch are
  // one piece; crossing the pinch diagonally the other way only touches it.
  const PlanarPolygon3<T> pinch{axis_frame<T>(0, {0, 0, 0}), named_polygons<T>()[5]};
  const auto through = intersection_pieces(Segment3<T>{{1, 1, 0}, {3, 3, 0}}, pinch);
  ASSERT_EQ(through.pieces.size(), 1u);
  EXPECT_EQ(through.pieces[0].kind, Kind::segment);
  const auto touch = intersection_pieces(Segment3<T>{{1, 3, 0}, {3, 1, 0}}, pinch);
  ASSERT_EQ(touch.pieces.size(), 1u);
  EXPECT_EQ(touch.pieces[0].kind, Kind::point);
  EXPECT_EQ(touch.pieces[0].param_a[0], T(0.5));
}

// Components not in the plane: the crossing point or nothing, as intersection().
TYPED_TEST(IntersectionPlanar3Pieces, CrossingComponentsAsIntersection) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const PlanarPolygon3<T> comb{axis_frame<T>(0, {0, 0, 1}), named_polygons<T>()[0]};
  int hits = 0;
  for_each_linear<T>([&]<class A>() {
    for (int i = 0; i < 100; ++i) {
      const auto g = [&](int z) {
        return Vec3<T>{T(rng.uniform_int(-2, 16)) / 2, T(rng.uniform_int(-2, 8)) / 2, T(z)};
      };
      const int z0 = rng.uniform_int(-1, 1), z1 = rng.uniform_int(2, 3);
      const Vec3<T> p0 = g(z0), p1 = g(z1);  // in order (not as arguments)
      const A a = Make<A>::from(p0, p1);
      const auto r = intersection(a, comb);
      const auto p = intersection_pieces(a, comb);
      EXPECT_EQ(p.status, Status::ok);
      ASSERT_EQ(p.pieces.size(), r.kind == Kind::empty ? 0u : 1u);
      if (r.kind == Kind::empty) continue;
      ++hits;
      EXPECT_EQ(p.pieces[0].kind, Kind::point);
      EXPECT_EQ(p.pieces[0].point[0], r.point[0]);
      EXPECT_EQ(p.pieces[0].param_a[0], r.param_a[0]);
      EXPECT_EQ(p.pieces[0].param_b[0], r.param_b[0]);
    }
  });
  EXPECT_GT(hits, 50);
}

// Scaling every input by 2^k scales points and frame coordinates by 2^k and keeps the
// parameters: the pieces are the same.
TYPED_TEST(IntersectionPlanar3Pieces, PowerOfTwoScaling) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const int big = std::is_same_v<T, float> ? 40 : 400;
  for (const int e : {-big, -7, 5, big}) {
    const T s = std::ldexp(T(1), e);
    const PlanarPolygon3<T> spiral{axis_frame<T>(2, {1, 2, 3}), named_polygons<T>()[1]};
    PlanarPolygon3<T> scaled = spiral;
    scaled.frame.origin = scaled.frame.origin * s;
    for (Vec2<T>& v : scaled.polygon.vertices) v = v * s;
    for_each_linear<T>([&]<class A>() {
      for (int i = 0; i < 20; ++i) {
        const auto g = [&] {
          return point_at(spiral,
                          Vec2<T>{T(rng.uniform_int(-2, 12)) / 2, T(rng.uniform_int(-2, 12)) / 2});
        };
        const Vec3<T> p = g(), q = g();
        const A a = Make<A>::from(p, q);
        const A b = Make<A>::from(p * s, q * s);
        const auto ra = intersection_pieces(a, spiral);
        const auto rb = intersection_pieces(b, scaled);
        ASSERT_EQ(ra.pieces.size(), rb.pieces.size()) << e << " " << i;
        for (std::size_t k = 0; k < ra.pieces.size(); ++k) {
          EXPECT_EQ(ra.pieces[k].kind, rb.pieces[k].kind);
          EXPECT_EQ(ra.pieces[k].param_a, rb.pieces[k].param_a) << e << " " << i;
          for (std::size_t j = 0; j < 2; ++j) {
            EXPECT_EQ(ra.pieces[k].param_b[j] * s, rb.pieces[k].param_b[j]) << e << " " << i;
            EXPECT_EQ(ra.pieces[k].point[j] * s, rb.pieces[k].point[j]) << e << " " << i;
          }
        }
      }
    });
  }
}

TYPED_TEST(IntersectionPlanar3Pieces, DegenerateAndNonFinite) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const PlaneFrame3<T> f = axis_frame<T>(0, {0, 0, 0});
  const PlanarPolygon3<T> sq{f, poly2<T>({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})};
  const Segment3<T> in_plane{{-2, 0, 0}, {2, 0, 0}};
  EXPECT_EQ(intersection_pieces(in_plane, sq).pieces.size(), 1u);
  // Empty polygon, non-finite data, zero normal.
  EXPECT_EQ(intersection_pieces(in_plane, PlanarPolygon3<T>{f, {}}).status, Status::empty_input);
  PlanarPolygon3<T> bad = sq;
  bad.polygon.vertices[2].y = nan;
  EXPECT_EQ(intersection_pieces(in_plane, bad).status, Status::non_finite_input);
  EXPECT_TRUE(intersection_pieces(in_plane, bad).pieces.empty());
  bad = sq;
  bad.frame.u.x = inf;
  EXPECT_EQ(intersection_pieces(in_plane, bad).status, Status::non_finite_input);
  EXPECT_EQ(intersection_pieces(Segment3<T>{{0, 0, nan}, {1, 0, 0}}, sq).status,
            Status::non_finite_input);
  EXPECT_EQ(intersection_pieces(Line3<T>{{0, 0, 0}, {inf, 0, 0}}, sq).status,
            Status::non_finite_input);
  bad = sq;
  bad.frame.normal = {0, 0, 0};
  EXPECT_EQ(intersection_pieces(in_plane, bad).status, Status::degenerate_input);
  // Zero direction and zero-length segment: the point.
  const auto z = intersection_pieces(Ray3<T>{{0.5, 0.5, 0}, {0, 0, 0}}, sq);
  ASSERT_EQ(z.pieces.size(), 1u);
  EXPECT_EQ(z.pieces[0].kind, Kind::point);
  EXPECT_EQ(intersection_pieces(Segment3<T>{{3, 0, 0}, {3, 0, 0}}, sq).pieces.size(), 0u);
  // Degenerate polygons: a single vertex, a segment (two vertices), collinear vertices.
  const PlanarPolygon3<T> dot{f, poly2<T>({{1, 1}})};
  const auto d = intersection_pieces(Line3<T>{{0, 0, 0}, {1, 1, 0}}, dot);
  ASSERT_EQ(d.pieces.size(), 1u);
  EXPECT_EQ(d.pieces[0].kind, Kind::point);
  EXPECT_EQ(d.pieces[0].param_a[0], T(1));
  const PlanarPolygon3<T> seg{f, poly2<T>({{0, 0}, {2, 0}})};
  const auto along = intersection_pieces(Line3<T>{{-1, 0, 0}, {1, 0, 0}}, seg);
  ASSERT_EQ(along.pieces.size(), 1u);
  EXPECT_EQ(along.pieces[0].kind, Kind::segment);
  EXPECT_EQ(along.pieces[0].param_a[0], T(1));
  EXPECT_EQ(along.pieces[0].param_a[1], T(3));
  const auto across = intersection_pieces(Line3<T>{{1, -1, 0}, {0, 1, 0}}, seg);
  ASSERT_EQ(across.pieces.size(), 1u);
  EXPECT_EQ(across.pieces[0].kind, Kind::point);
  const PlanarPolygon3<T> flat{f, poly2<T>({{0, 0}, {1, 1}, {3, 3}})};
  const auto diag = intersection_pieces(Segment3<T>{{-1, -1, 0}, {2, 2, 0}}, flat);
  ASSERT_EQ(diag.pieces.size(), 1u);
  EXPECT_EQ(diag.pieces[0].param_b[0], (Vec2<T>{0, 0}));
  EXPECT_EQ(diag.pieces[0].param_b[1], (Vec2<T>{2, 2}));
}

}  // namespace
