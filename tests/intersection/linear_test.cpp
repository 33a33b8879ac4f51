// SPDX-License-Identifier: BSL-1.0
// Row int2.linear: intersects() / intersection() for the six pairs of Line2, Ray2, Segment2,
// float and double, against the exact GMP oracle (linear_oracle.hpp). Each case checks: the kind
// equals the exact one; intersects() agrees; a crossing point is within the header's bound
// 6 eps max(|X|, m) of the exact point X, and each parameter within that bound over |direction|;
// overlap end points equal the exact ones (they are input points) with accurate parameters;
// every entry lies on both arguments through its parameters; the swapped overload returns
// swapped(). Inputs: seeded random, tiny crossing angles (down to 1e-15 rad), near-parallel
// offsets, collinear overlaps of every arrangement, integer grids (touching at end points,
// T-junctions, shared end points, zero-length segments, zero directions), NaN/Inf, and
// power-of-two scaling (the answer must scale exactly). Segment pairs at angles down to 1e-30 under
// every compiled version of the accurate side values (FMA or Dekker products, src/core/
// crossing.cpp), and the batched form (segment_segment_batch.hpp) equal to the per-pair one bit
// for bit under every version of its kernel.

#include <locus/intersection/line_line.hpp>
#include <locus/intersection/line_ray.hpp>
#include <locus/intersection/line_segment.hpp>
#include <locus/intersection/ray_ray.hpp>
#include <locus/intersection/ray_segment.hpp>
#include <locus/intersection/result.hpp>
#include <locus/intersection/segment_segment.hpp>
#include <locus/intersection/segment_segment_batch.hpp>

#include <locus/core/detail/batch_isa.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "intersection/linear_oracle.hpp"
#include "support/scale_covariance.hpp"
#include "support/typed.hpp"

namespace {

using namespace locus;
using locus_test::Rng;
namespace ex = locus_test::exact2;

template <class T>
class IntersectionLinear : public ::testing::Test {};
TYPED_TEST_SUITE(IntersectionLinear, locus_test::RealTypes);

// The two points that define a primitive (end points, or origin and origin + direction), and
// its construction from them.
template <class P>
struct Make;
template <class T>
struct Make<Line2<T>> {
  static Line2<T> from(const Vec2<T>& p, const Vec2<T>& q) { return {p, q - p}; }
  static Line2<T> od(const Vec2<T>& o, const Vec2<T>& d) { return {o, d}; }
};
template <class T>
struct Make<Ray2<T>> {
  static Ray2<T> from(const Vec2<T>& p, const Vec2<T>& q) { return {p, q - p}; }
  static Ray2<T> od(const Vec2<T>& o, const Vec2<T>& d) { return {o, d}; }
};
template <class T>
struct Make<Segment2<T>> {
  static Segment2<T> from(const Vec2<T>& p, const Vec2<T>& q) { return {p, q}; }
  static Segment2<T> od(const Vec2<T>& o, const Vec2<T>& d) { return {o, o + d}; }
};

template <class T>
double coord_max(const Line2<T>& l) {
  return double(max_abs(l.origin));
}
template <class T>
double coord_max(const Ray2<T>& r) {
  return double(max_abs(r.origin));
}
template <class T>
double coord_max(const Segment2<T>& s) {
  return double(std::max(max_abs(s.p0), max_abs(s.p1)));
}

// The input points of a primitive: end points, or the origin.
template <class T>
std::vector<Vec2<T>> input_points(const Segment2<T>& s) {
  return {s.p0, s.p1};
}
template <class P>
auto input_points(const P& p) {
  return std::vector{p.origin};
}

template <class P>
std::string describe(const P& p) {
  auto v = [](const auto& x) {
    char b[128];
    std::snprintf(b, sizeof b, "(%.17g, %.17g)", double(x.x), double(x.y));
    return std::string(b);
  };
  if constexpr (requires { p.p0; })
    return "segment " + v(p.p0) + " " + v(p.p1);
  else
    return "origin " + v(p.origin) + " direction " + v(p.direction);
}

const char* name(ex::QKind k) {
  switch (k) {
    case ex::QKind::empty:
      return "empty";
    case ex::QKind::point:
      return "point";
    case ex::QKind::segment:
      return "segment";
    case ex::QKind::ray:
      return "ray";
    case ex::QKind::line:
      return "line";
  }
  return "?";
}

double qmax_abs(const ex::Q2& p) { return std::max(std::abs(p.x.get_d()), std::abs(p.y.get_d())); }

template <class T>
double err(const Vec2<T>& p, const ex::Q2& e) {
  return std::max(std::abs(mpq_class(mpq_class(double(p.x)) - e.x).get_d()),
                  std::abs(mpq_class(mpq_class(double(p.y)) - e.y).get_d()));
}

// Largest error measured, relative to eps max(|X|, m), over a test.
struct Worst {
  double ratio = 0.0;
  void add(double r) { ratio = std::max(ratio, r); }
};

// Checks intersection(a, b) against the oracle; returns false on a failure (already reported).
template <class T, class A, class B>
void check(const A& a, const B& b, Worst* worst = nullptr) {
  SCOPED_TRACE("a = " + describe(a) + ", b = " + describe(b));
  const LinearIntersection2<T> r = intersection(a, b);
  const ex::QLin qa = ex::ql(a), qb = ex::ql(b);
  const ex::QResult e = ex::intersect(qa, qb);
  ASSERT_EQ(to_string(r.kind), std::string(name(e.kind)));
  EXPECT_EQ(intersects(a, b), e.kind != ex::QKind::empty);
  const int expected_count = e.kind == ex::QKind::empty ? 0 : e.kind == ex::QKind::point ? 1 : 2;
  ASSERT_EQ(r.count, expected_count);
  const double eps = double(eps_v<T>);
  const double m = std::max(coord_max(a), coord_max(b));
  const double da = std::max(std::abs(qa.d.x.get_d()), std::abs(qa.d.y.get_d()));
  const double db = std::max(std::abs(qb.d.x.get_d()), std::abs(qb.d.y.get_d()));
  // Entries whose point the oracle knows (the finite ends): bound of the header.
  for (int i = 0; i < (e.kind == ex::QKind::line ? 0 : e.count); ++i) {
    SCOPED_TRACE("entry " + std::to_string(i));
    const double bound = 6.0 * eps * std::max(qmax_abs(e.point[i]), m);
    ASSERT_TRUE(is_finite(r.point[static_cast<std::size_t>(i)]) &&
                std::isfinite(r.param_a[static_cast<std::size_t>(i)]) &&
                std::isfinite(r.param_b[static_cast<std::size_t>(i)]))
        << "a non-finite point or parameter reported";
    const double pe = err(r.point[static_cast<std::size_t>(i)], e.point[i]);
    EXPECT_LE(pe, bound) << "point error " << pe;
    if (e.kind != ex::QKind::point) {
      EXPECT_EQ(pe, 0.0) << "overlap ends are input points";
    }
    for (const auto& in : input_points(a))
      if (ex::q(in) == e.point[i]) {
        EXPECT_EQ(pe, 0.0) << "a touch at an input point is exact";
      }
    for (const auto& in : input_points(b))
      if (ex::q(in) == e.point[i]) {
        EXPECT_EQ(pe, 0.0) << "a touch at an input point is exact";
      }
    const double ta = double(r.param_a[static_cast<std::size_t>(i)]);
    const double tb = double(r.param_b[static_cast<std::size_t>(i)]);
    const double ea = std::abs(mpq_class(mpq_class(ta) - e.ta[i]).get_d()) * da;
    const double eb = std::abs(mpq_class(mpq_class(tb) - e.tb[i]).get_d()) * db;
    EXPECT_LE(ea, bound) << "param_a " << ta << " against " << e.ta[i].get_d();
    EXPECT_LE(eb, bound) << "param_b " << tb << " against " << e.tb[i].get_d();
    if (worst && bound > 0) worst->add(std::max({pe, ea, eb}) / (bound / 6.0));
  }
  // Every entry lies on both arguments through its parameters (ray's second point, line points).
  for (int i = 0; i < r.count; ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    const double scale = std::max(m, double(max_abs(r.point[k])));
    EXPECT_TRUE(locus_test::vec_near(point_at(a, r.param_a[k]), r.point[k], T(8 * eps * scale)));
    EXPECT_TRUE(locus_test::vec_near(point_at(b, r.param_b[k]), r.point[k], T(8 * eps * scale)));
  }
  if (e.kind == ex::QKind::ray) {
    EXPECT_EQ(r.param_a[1] > r.param_a[0] ? 1 : -1, e.ray_dir) << "ray runs the wrong way";
  }
  if (e.kind == ex::QKind::line || e.kind == ex::QKind::ray) {
    EXPECT_NE(r.point[0], r.point[1]);
  }
  if (e.kind == ex::QKind::segment) {
    EXPECT_LT(r.param_a[0], r.param_a[1]);
  }
  if constexpr (!std::is_same_v<A, B>) {
    const LinearIntersection2<T> s = intersection(b, a);
    const LinearIntersection2<T> w = swapped(r);
    EXPECT_EQ(s.kind, w.kind);
    ASSERT_EQ(s.count, w.count);
    for (std::size_t i = 0; i < static_cast<std::size_t>(s.count); ++i) {
      EXPECT_EQ(s.point[i], w.point[i]);
      EXPECT_EQ(s.param_a[i], w.param_a[i]);
      EXPECT_EQ(s.param_b[i], w.param_b[i]);
    }
    EXPECT_EQ(intersects(b, a), intersects(a, b));
  }
}

// Runs f.template operator()<A, B>() for the six canonical pairs.
template <class T, class F>
void for_each_pair(F&& f) {
  f.template operator()<Line2<T>, Line2<T>>();
  f.template operator()<Line2<T>, Ray2<T>>();
  f.template operator()<Line2<T>, Segment2<T>>();
  f.template operator()<Ray2<T>, Ray2<T>>();
  f.template operator()<Ray2<T>, Segment2<T>>();
  f.template operator()<Segment2<T>, Segment2<T>>();
}

template <class P>
std::string type_name() {
  if constexpr (requires(P p) { p.p0; })
    return "segment";
  else if constexpr (std::is_same_v<P, Ray2<float>> || std::is_same_v<P, Ray2<double>>)
    return "ray";
  else
    return "line";
}

TYPED_TEST(IntersectionLinear, RandomAgainstExact) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int crossings = 0;
  for_each_pair<T>([&]<class A, class B>() {
    SCOPED_TRACE(type_name<A>() + "-" + type_name<B>());
    for (int i = 0; i < 1500; ++i) {
      const A a = Make<A>::from(rng.vec<T, 2>(-1, 1), rng.vec<T, 2>(-1, 1));
      const B b = Make<B>::from(rng.vec<T, 2>(-1, 1), rng.vec<T, 2>(-1, 1));
      check<T>(a, b);
      crossings += intersects(a, b) ? 1 : 0;
      if (::testing::Test::HasFatalFailure()) return;
    }
  });
  EXPECT_GT(crossings, 3000);  // the sample exercises both outcomes of every pair
  EXPECT_LT(crossings, 9000 - 300);
}

// Two components through a common point c at a tiny angle: the textbook formula (cross products
// of rounded differences) loses about log10(1 / angle) digits here; the header's bound must hold.
TYPED_TEST(IntersectionLinear, TinyAngleCrossings) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const int max_exp = std::is_same_v<T, float> ? 7 : 15;
  Worst worst;
  int points = 0;
  for_each_pair<T>([&]<class A, class B>() {
    SCOPED_TRACE(type_name<A>() + "-" + type_name<B>());
    for (int i = 0; i < 600; ++i) {
      const double angle = std::pow(10.0, -rng.uniform<double>(2.0, double(max_exp)));
      const Vec2<double> c{rng.uniform<double>(-1, 1), rng.uniform<double>(-1, 1)};
      const double phi = rng.uniform<double>(0, 6.283185307179586);
      const double l0 = rng.uniform<double>(0.1, 1), l1 = rng.uniform<double>(0.1, 1);
      const double s0 = rng.uniform<double>(0.05, 0.95), s1 = rng.uniform<double>(0.05, 0.95);
      const Vec2<double> u{std::cos(phi), std::sin(phi)};
      const Vec2<double> v{std::cos(phi + angle), std::sin(phi + angle)};
      const A a = Make<A>::from(vec_cast<T>(c - s0 * l0 * u), vec_cast<T>(c + (1 - s0) * l0 * u));
      const B b = Make<B>::from(vec_cast<T>(c - s1 * l1 * v), vec_cast<T>(c + (1 - s1) * l1 * v));
      check<T>(a, b, &worst);
      points += intersection(a, b).kind == Kind::point ? 1 : 0;
      if (::testing::Test::HasFatalFailure()) return;
    }
  });
  EXPECT_GT(points, 6 * 600 / 3);
  std::printf("[ measured ] worst error / (eps max(|X|, m)) = %.3g\n", worst.ratio);
}

// Segment pairs that exercise every tier of the crossing's side values (detail/linear2.hpp,
// segments_fast and proper_crossing): end points at mixed magnitudes, and short segments crossing
// a long one close to its end, where one side value is tiny against its products; the header's
// bound must hold whichever tier computed the point.
TYPED_TEST(IntersectionLinear, SegmentCrossingsAtMixedScales) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  Worst worst;
  int points = 0;
  for (int i = 0; i < 600; ++i) {
    const auto pt = [&] {
      return Vec2<T>{T(rng.uniform<double>(-1, 1) * std::exp2(rng.uniform<double>(-5, 0))),
                     T(rng.uniform<double>(-1, 1) * std::exp2(rng.uniform<double>(-5, 0)))};
    };
    const Vec2<T> a0 = pt(), a1 = pt();
    Vec2<T> b0 = pt(), b1 = pt();
    if (i % 2 == 1) {
      const double t = rng.uniform<double>(0.9, 1.0);
      const double len = std::exp2(-rng.uniform<double>(0, std::is_same_v<T, float> ? 20 : 40));
      const Vec2<double> x =
          vec_cast<double>(a0) + t * (vec_cast<double>(a1) - vec_cast<double>(a0));
      const Vec2<double> d{rng.uniform<double>(-1, 1), rng.uniform<double>(-1, 1)};
      b0 = vec_cast<T>(x - rng.uniform<double>(0.1, 1) * len * d);
      b1 = vec_cast<T>(x + rng.uniform<double>(0.1, 1) * len * d);
    }
    const Segment2<T> a{a0, a1}, b{b0, b1};
    check<T>(a, b, &worst);
    points += intersection(a, b).kind == Kind::point ? 1 : 0;
    if (::testing::Test::HasFatalFailure()) return;
  }
  EXPECT_GT(points, 600 / 3);
  std::printf("[ measured ] worst error / (eps max(|X|, m)) = %.3g\n", worst.ratio);
}

// Two segments through a common point at an angle 2^-k, k in [20, 100]: the side values come
// from every tier (filters, exact differences, double-double, triple length, expansions), under
// every compiled version of src/core/crossing.cpp (detail::set_batch_isa picks it).
template <class T>
std::pair<Segment2<T>, Segment2<T>> tiny_angle_pair(Rng& rng, int kmin, int kmax) {
  const double angle = std::ldexp(1.0, -rng.uniform_int(kmin, kmax));
  const Vec2<double> c{rng.uniform<double>(-1, 1), rng.uniform<double>(-1, 1)};
  const double phi = rng.uniform<double>(0, 6.283185307179586);
  const double l0 = rng.uniform<double>(0.1, 1), l1 = rng.uniform<double>(0.1, 1);
  const double s0 = rng.uniform<double>(0.05, 0.95), s1 = rng.uniform<double>(-0.5, 1.5);
  const Vec2<double> u{std::cos(phi), std::sin(phi)};
  const Vec2<double> v{std::cos(phi + angle), std::sin(phi + angle)};
  return {Segment2<T>{vec_cast<T>(c - s0 * l0 * u), vec_cast<T>(c + (1 - s0) * l0 * u)},
          Segment2<T>{vec_cast<T>(c - s1 * l1 * v), vec_cast<T>(c + (1 - s1) * l1 * v)}};
}

TYPED_TEST(IntersectionLinear, TinyAnglesUnderEveryVersion) {
  using T = TypeParam;
  using detail::BatchIsa;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const BatchIsa before = detail::batch_isa();
  Worst worst;
  for (const BatchIsa isa : {BatchIsa::baseline, BatchIsa::avx2, BatchIsa::x86_64_v4}) {
    detail::set_batch_isa(isa);
    for (int i = 0; i < 200; ++i) {
      const auto [a, b] = tiny_angle_pair<T>(rng, 20, 100);
      check<T>(a, b, &worst);
      if (::testing::Test::HasFatalFailure()) break;
    }
  }
  detail::set_batch_isa(before);
  std::printf("[ measured ] worst error / (eps max(|X|, m)) = %.3g\n", worst.ratio);
}

// intersections(a, b, out) equals intersection(a[i], b[i]) bit for bit: generic pairs, tiny
// angles, touching and collinear pairs on a grid, degenerate and non-finite segments, every
// length modulo the lane count, under every version of the kernel.
TYPED_TEST(IntersectionLinear, BatchMatchesPerPair) {
  using T = TypeParam;
  using detail::BatchIsa;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  std::vector<Segment2<T>> a, b;
  const auto add = [&](const Segment2<T>& x, const Segment2<T>& y) {
    a.push_back(x);
    b.push_back(y);
  };
  for (int i = 0; i < 200; ++i)
    add({rng.vec<T, 2>(-1, 1), rng.vec<T, 2>(-1, 1)}, {rng.vec<T, 2>(-1, 1), rng.vec<T, 2>(-1, 1)});
  for (int i = 0; i < 100; ++i) {
    const auto ab = tiny_angle_pair<T>(rng, 10, 70);
    add(ab.first, ab.second);
  }
  const auto grid = [&] { return Vec2<T>{T(rng.uniform_int(-2, 2)), T(rng.uniform_int(-2, 2))}; };
  for (int i = 0; i < 100; ++i) add({grid(), grid()}, {grid(), grid()});
  const T inf = std::numeric_limits<T>::infinity(), nan = std::numeric_limits<T>::quiet_NaN();
  add({{0, 0}, {1, 1}}, {{nan, 0}, {1, 0}});
  add({{0, inf}, {1, 1}}, {{0, 1}, {1, 0}});
  add({{0, 0}, {0, 0}}, {{-1, 0}, {1, 0}});
  add({{0, 0}, {1, 1}}, {{0, 1}, {1, 0}});
  add({{T(1e30), 0}, {T(-1e30), T(1)}}, {{0, T(1e30)}, {0, T(-1e30)}});
  const BatchIsa before = detail::batch_isa();
  const auto same = [](const LinearIntersection2<T>& x, const LinearIntersection2<T>& y) {
    return x.kind == y.kind && x.count == y.count &&
           std::memcmp(&x.point, &y.point, sizeof x.point) == 0 &&
           std::memcmp(&x.param_a, &y.param_a, sizeof x.param_a) == 0 &&
           std::memcmp(&x.param_b, &y.param_b, sizeof x.param_b) == 0;
  };
  int hits = 0;
  for (const BatchIsa isa : {BatchIsa::baseline, BatchIsa::avx2, BatchIsa::x86_64_v4}) {
    detail::set_batch_isa(isa);
    for (const std::size_t n :
         {std::size_t{0}, std::size_t{1}, std::size_t{3}, std::size_t{6}, a.size()}) {
      std::vector<LinearIntersection2<T>> out(n);
      intersections(std::span(a.data(), n), std::span(b.data(), n), std::span(out));
      for (std::size_t i = 0; i < n; ++i) {
        const LinearIntersection2<T> r = intersection(a[i], b[i]);
        EXPECT_TRUE(same(out[i], r)) << "pair " << i << " isa " << int(isa) << " n " << n;
        hits += r.kind != Kind::empty;
      }
    }
  }
  detail::set_batch_isa(before);
  EXPECT_GT(hits, 3 * 100);  // both outcomes are exercised
  EXPECT_LT(hits, 3 * int(a.size()) - 300);
}

// Parallel and nearly parallel components offset by a few ulps or less: the decision is exact.
TYPED_TEST(IntersectionLinear, NearParallelOffsets) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for_each_pair<T>([&]<class A, class B>() {
    SCOPED_TRACE(type_name<A>() + "-" + type_name<B>());
    for (int i = 0; i < 600; ++i) {
      const Vec2<T> p = rng.vec<T, 2>(-1, 1), q = rng.vec<T, 2>(-1, 1);
      const Vec2<T> d = q - p;
      Vec2<T> off{};
      for (int k = 0; k < 2; ++k)
        off[k] = T(rng.uniform_int(-2, 2)) * std::nextafter(std::abs(p[k]), T(4)) * eps_v<T> / 2;
      const T s = T(rng.uniform_int(-3, 3)) / 4, s2 = T(rng.uniform_int(-3, 3)) / 4;
      const A a = Make<A>::from(p, q);
      const B b = i % 2 == 0
                      ? Make<B>::od(p + off + s * d, (rng.uniform_int(0, 1) ? T(1) : T(-1)) * d)
                      : Make<B>::from(p + off + s * d, p + s2 * d);
      check<T>(a, b);
      if (::testing::Test::HasFatalFailure()) return;
    }
  });
}

// Exactly collinear components (points p + k d with small integers k on a coarse grid, exact in
// float): every arrangement of overlaps, touching ends, containment, opposite directions, and
// zero-length segments and zero directions.
TYPED_TEST(IntersectionLinear, CollinearOverlaps) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int kinds[5] = {0, 0, 0, 0, 0};
  for_each_pair<T>([&]<class A, class B>() {
    SCOPED_TRACE(type_name<A>() + "-" + type_name<B>());
    for (int i = 0; i < 800; ++i) {
      const Vec2<T> p{T(rng.uniform_int(-256, 256)) / 64, T(rng.uniform_int(-256, 256)) / 64};
      Vec2<T> d{T(rng.uniform_int(-5, 5)) / 8, T(rng.uniform_int(-5, 5)) / 8};
      if (d == Vec2<T>{}) d.x = T(0.375);
      const auto at = [&](int k) { return p + T(k) * d; };
      const int k0 = rng.uniform_int(-4, 4), k1 = rng.uniform_int(-4, 4);
      const int j0 = rng.uniform_int(-4, 4), j1 = rng.uniform_int(-4, 4);
      const A a = Make<A>::from(at(k0), at(k1));
      const B b = Make<B>::from(at(j0), at(j1));
      check<T>(a, b);
      const ex::QResult e = ex::intersect(ex::ql(a), ex::ql(b));
      ++kinds[static_cast<int>(e.kind)];
      if (::testing::Test::HasFatalFailure()) return;
    }
  });
  for (int k = 0; k < 5; ++k) EXPECT_GT(kinds[k], 20) << "kind " << k << " not exercised";
}

// Small integer grids: many exact degeneracies (touching at end points, T-junctions, shared end
// points, parallel, collinear, zero-length segments, zero directions).
TYPED_TEST(IntersectionLinear, IntegerGridDegeneracies) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int touching = 0;
  for_each_pair<T>([&]<class A, class B>() {
    SCOPED_TRACE(type_name<A>() + "-" + type_name<B>());
    for (int i = 0; i < 2000; ++i) {
      auto g = [&] { return Vec2<T>{T(rng.uniform_int(-2, 2)), T(rng.uniform_int(-2, 2))}; };
      const A a = Make<A>::from(g(), g());
      const B b = Make<B>::from(g(), g());
      check<T>(a, b);
      touching += intersection(a, b).kind == Kind::point ? 1 : 0;
      if (::testing::Test::HasFatalFailure()) return;
    }
  });
  EXPECT_GT(touching, 1000);
}

// NaN or infinite coordinates: kind empty, count 0, intersects false; never a crash or a NaN
// point presented as valid.
TYPED_TEST(IntersectionLinear, NonFiniteInputGivesEmpty) {
  using T = TypeParam;
  const T bad[3] = {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity(),
                    -std::numeric_limits<T>::infinity()};
  for_each_pair<T>([&]<class A, class B>() {
    SCOPED_TRACE(type_name<A>() + "-" + type_name<B>());
    // The same pair crosses when finite.
    const Vec2<T> p0{-1, -1}, p1{1, 1}, q0{-1, 1}, q1{1, -1};
    ASSERT_TRUE(intersects(Make<A>::from(p0, p1), Make<B>::from(q0, q1)));
    for (const T v : bad) {
      for (int which = 0; which < 8; ++which) {
        Vec2<T> pts[4] = {p0, p1, q0, q1};
        pts[which / 2][which % 2] = v;
        const A a = Make<A>::from(pts[0], pts[1]);
        const B b = Make<B>::from(pts[2], pts[3]);
        const LinearIntersection2<T> r = intersection(a, b);
        EXPECT_EQ(r.kind, Kind::empty) << which;
        EXPECT_EQ(r.count, 0);
        EXPECT_FALSE(intersects(a, b));
        EXPECT_EQ(intersection(b, a).kind, Kind::empty);
      }
    }
  });
}

// Scaling the input by 2^k scales every point by 2^k and leaves kinds, counts and parameters
// unchanged, bit for bit (every operation scales exactly; the accurate path too).
TYPED_TEST(IntersectionLinear, PowerOfTwoScaleCovariance) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const int max_exp = std::is_same_v<T, float> ? 7 : 15;
  for_each_pair<T>([&]<class A, class B>() {
    SCOPED_TRACE(type_name<A>() + "-" + type_name<B>());
    for (int i = 0; i < 120; ++i) {
      std::vector<Vec2<T>> pts(4);
      if (i % 3 == 0) {
        for (auto& p : pts) p = rng.vec<T, 2>(-1, 1);
      } else if (i % 3 == 1) {
        const double angle = std::pow(10.0, -rng.uniform<double>(2.0, double(max_exp)));
        const double phi = rng.uniform<double>(0, 6.283185307179586);
        const Vec2<double> c{rng.uniform<double>(-1, 1), rng.uniform<double>(-1, 1)};
        const Vec2<double> u{std::cos(phi), std::sin(phi)},
            v{std::cos(phi + angle), std::sin(phi + angle)};
        pts = {vec_cast<T>(c - 0.4 * u), vec_cast<T>(c + 0.7 * u), vec_cast<T>(c - 0.6 * v),
               vec_cast<T>(c + 0.3 * v)};
      } else {
        const Vec2<T> p{T(rng.uniform_int(-8, 8)) / 8, T(rng.uniform_int(-8, 8)) / 8};
        const Vec2<T> d{T(rng.uniform_int(-3, 3)) / 4, T(rng.uniform_int(1, 3)) / 4};
        for (auto& q : pts) q = p + T(rng.uniform_int(-3, 3)) * d;
      }
      const auto run = [&](int k) {
        const std::vector<Vec2<T>> s = locus_test::scaled(pts, k);
        const A a = Make<A>::from(s[0], s[1]);
        const B b = Make<B>::from(s[2], s[3]);
        const LinearIntersection2<T> r = intersection(a, b);
        std::vector<locus_test::Covariant> out{{"kind", double(static_cast<int>(r.kind)), 0},
                                               {"count", double(r.count), 0},
                                               {"intersects", intersects(a, b) ? 1.0 : 0.0, 0}};
        for (std::size_t j = 0; j < static_cast<std::size_t>(r.count); ++j) {
          locus_test::add(out, "point", r.point[j], 1);
          out.push_back({"param_a", double(r.param_a[j]), 0});
          out.push_back({"param_b", double(r.param_b[j]), 0});
        }
        return out;
      };
      locus_test::expect_scale_covariant(run, locus_test::scale_exponents<T>());
      if (::testing::Test::HasFatalFailure()) return;
    }
  });
}

// The book's configurations (section 7.1): crossing segments, a segment touching another at an
// end point, parallel disjoint, collinear overlapping and collinear disjoint segments; each
// against the oracle, with the expected kind named so a wrong oracle cannot pass silently.
TYPED_TEST(IntersectionLinear, BookConfigurations) {
  using T = TypeParam;
  using S = Segment2<T>;
  const struct {
    S a, b;
    Kind kind;
  } cases[] = {
      {{{0, 0}, {4, 2}}, {{0, 3}, {3, 0}}, Kind::point},    // crossing
      {{{0, 0}, {4, 2}}, {{2, 1}, {2, 5}}, Kind::point},    // T-junction at b.p0
      {{{0, 0}, {4, 2}}, {{4, 2}, {6, 0}}, Kind::point},    // shared end point
      {{{0, 0}, {4, 2}}, {{0, 1}, {4, 3}}, Kind::empty},    // parallel, disjoint
      {{{0, 0}, {4, 2}}, {{2, 1}, {6, 3}}, Kind::segment},  // collinear, overlapping
      {{{0, 0}, {4, 2}}, {{6, 3}, {8, 4}}, Kind::empty},    // collinear, disjoint
      {{{0, 0}, {4, 2}}, {{8, 4}, {4, 2}}, Kind::point},    // collinear, touching end to end
      {{{0, 0}, {4, 2}}, {{3, 0}, {5, 1}}, Kind::empty},    // lines cross outside the segments
  };
  for (const auto& c : cases) {
    check<T>(c.a, c.b);
    EXPECT_EQ(intersection(c.a, c.b).kind, c.kind);
  }
  // The crossing of the first case, (2, 1) at t = 1/2 on a and 2/3 on b, worked by hand.
  const auto r = intersection(cases[0].a, cases[0].b);
  EXPECT_EQ(r.point[0], (Vec2<T>{2, 1}));
  EXPECT_EQ(r.param_a[0], T(0.5));
  EXPECT_NEAR(double(r.param_b[0]), 2.0 / 3.0, double(eps_v<T>));
}

// Coordinates near the ends of the exponent range (2^+-1000 and 2^+-900 for double, 2^+-110 and
// 2^+-100 for float): random and tiny-angle cases still match the oracle within the bound (the
// engine rescales by a power of two where products would overflow or underflow).
TYPED_TEST(IntersectionLinear, FarExponentsMatchTheOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for_each_pair<T>([&]<class A, class B>() {
    SCOPED_TRACE(type_name<A>() + "-" + type_name<B>());
    for (const int k : locus_test::far_scale_exponents<T>()) {
      SCOPED_TRACE("scale 2^" + std::to_string(k));
      for (int i = 0; i < 100; ++i) {
        std::vector<Vec2<T>> pts(4);
        if (i % 2 == 0) {
          for (auto& p : pts) p = rng.vec<T, 2>(-1, 1);
        } else {
          const double angle = std::pow(10.0, -rng.uniform<double>(2.0, 6.0));
          const Vec2<double> c{rng.uniform<double>(-1, 1), rng.uniform<double>(-1, 1)};
          const Vec2<double> u{1.0, 0.0}, v{std::cos(angle), std::sin(angle)};
          pts = {vec_cast<T>(c - 0.4 * u), vec_cast<T>(c + 0.7 * u), vec_cast<T>(c - 0.6 * v),
                 vec_cast<T>(c + 0.3 * v)};
        }
        const std::vector<Vec2<T>> s = locus_test::scaled(pts, k);
        check<T>(Make<A>::from(s[0], s[1]), Make<B>::from(s[2], s[3]));
        if (::testing::Test::HasFatalFailure()) return;
      }
    }
  });
}

}  // namespace
