// SPDX-License-Identifier: BSL-1.0
// Direct tests of the internal headers distance/detail/linear.hpp, detail/linear_box.hpp,
// detail/linear_polyline.hpp and detail/linear_planar.hpp (namespace locus::detail).
// Oracles:
//  * linear.hpp: view()/at()/clamp_param against their definitions (exact endpoints);
//    closest_param against the exact rational projection (GMP, exact.hpp), including zero,
//    subnormal, underflowing-square and overflowing-square directions; sqr_cross_norm against
//    |cross(a, b)|^2, perp_dot^2 and Lagrange's identity on small integers (exact); overlaps()
//    against sampling half-integer points; linear_linear() against the exact rational minimum
//    (exact.hpp sqr_linear_linear) and, for exactly parallel pairs, the unique flag against the
//    exact overlap of the projected parameter ranges.
//  * linear_box.hpp: linear_box_param against an exact rational minimisation of the piecewise
//    quadratic f(t) (every breakpoint and every piece's vertex, in GMP), including the unique
//    flag (a flat piece of positive length); the oriented-box distance against dense sampling of
//    the segment (point-box distance is a clamp) with a Lipschitz bound.
//  * linear_polyline.hpp: the minimum over the edges of the public line/ray/segment-segment
//    distance functions.
//  * linear_planar.hpp: segment_meets_triangle against an exact rational segment-triangle
//    intersection test (plane crossing + barycentric test; coplanar: endpoint in triangle or an
//    exact zero segment-edge distance), on small-integer input full of coplanar and touching
//    cases; BestCandidate::offer semantics.
#include <locus/distance/detail/linear.hpp>
#include <locus/distance/detail/linear_box.hpp>
#include <locus/distance/detail/linear_planar.hpp>
#include <locus/distance/detail/linear_polyline.hpp>
#include <locus/distance/line_segment.hpp>
#include <locus/distance/point_oriented_box.hpp>
#include <locus/distance/ray_segment.hpp>
#include <locus/distance/segment_segment.hpp>

#include "distance/exact.hpp"
#include "distance/harness.hpp"
#include "support/typed.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
namespace ex = locus_test::exact;

template <class T>
class DetailLinearTest : public ::testing::Test {};
TYPED_TEST_SUITE(DetailLinearTest, locus_test::RealTypes);

namespace {

// The exact component a view stands for (a segment from origin to end: its exact endpoints).
template <class T, int N>
ex::QLinear<static_cast<std::size_t>(N)> q_view(const detail::LinearView<T, N>& v) {
  if (v.bounded_hi) return ex::segment(v.origin, v.end);
  return {ex::to_q(v.origin), ex::to_q(v.dir), v.bounded_lo, v.bounded_hi};
}

// The largest coordinate magnitude of an exact closest pair of A and B (the "scale" of the
// header's error bound), by the same case analysis as exact.hpp's sqr_linear_linear.
template <std::size_t N>
double q_closest_scale(const ex::QLinear<N>& A, const ex::QLinear<N>& B) {
  const auto mag = [](const ex::QVec<N>& x, const ex::QVec<N>& y) {
    double m = 0;
    for (std::size_t i = 0; i < N; ++i)
      m = std::max({m, std::abs(x[i].get_d()), std::abs(y[i].get_d())});
    return m;
  };
  const auto at = [](const ex::QLinear<N>& l, const mpq_class& t) {
    return ex::axpy(l.origin, t, l.dir);
  };
  const mpq_class a = ex::dot(A.dir, A.dir), c = ex::dot(B.dir, B.dir), b = ex::dot(A.dir, B.dir);
  if (a == 0) return mag(A.origin, at(B, ex::closest_param(B, A.origin)));
  if (c == 0) return mag(B.origin, at(A, ex::closest_param(A, B.origin)));
  const ex::QVec<N> r = ex::sub(A.origin, B.origin);
  const mpq_class d = ex::dot(A.dir, r), e = ex::dot(B.dir, r), D = a * c - b * b;
  if (D != 0) {
    const mpq_class s = (b * e - c * d) / D, t = (a * e - b * d) / D;
    if (ex::clamp_param(A, s) == s && ex::clamp_param(B, t) == t) return mag(at(A, s), at(B, t));
  }
  bool have = false;
  mpq_class best;
  double scale = 0;
  const auto take = [&](const ex::QVec<N>& x, const ex::QVec<N>& y) {
    const ex::QVec<N> w = ex::sub(x, y);
    const mpq_class q = ex::dot(w, w);
    if (!have || q < best) best = q, have = true, scale = mag(x, y);
  };
  const auto from_a = [&](const mpq_class& s) {
    const ex::QVec<N> x = at(A, s);
    take(x, at(B, ex::closest_param(B, x)));
  };
  const auto from_b = [&](const mpq_class& t) {
    const ex::QVec<N> y = at(B, t);
    take(at(A, ex::closest_param(A, y)), y);
  };
  if (A.lo) from_a(0);
  if (A.hi) from_a(1);
  if (B.lo) from_b(0);
  if (B.hi) from_b(1);
  if (!have) from_a(0);  // two parallel lines
  return scale;
}

template <class T, int N>
detail::LinearView<T, N> make_view(int kind, const Vec<T, N>& o, const Vec<T, N>& d) {
  if (kind == 0) return detail::view(Line<T, N>{o, d});
  if (kind == 1) return detail::view(Ray<T, N>{o, d});
  return detail::view(Segment<T, N>{o, o + d});
}

template <class T, int N>
ex::QLinear<static_cast<std::size_t>(N)> q_of(const Line<T, N>& l) {
  return ex::line(l.origin, l.direction);
}
template <class T, int N>
ex::QLinear<static_cast<std::size_t>(N)> q_of(const Ray<T, N>& l) {
  return ex::ray(l.origin, l.direction);
}
template <class T, int N>
ex::QLinear<static_cast<std::size_t>(N)> q_of(const Segment<T, N>& s) {
  return ex::segment(s.p0, s.p1);
}

template <class T, int N>
double norm_d(const Vec<T, N>& v) {
  // long double: the squares of subnormal doubles stay representable (x86 extended range).
  long double s = 0;
  for (int i = 0; i < N; ++i) s += static_cast<long double>(v[i]) * static_cast<long double>(v[i]);
  return static_cast<double>(std::sqrt(s));
}

// ---- closest_param ----------------------------------------------------------------------------

// Checks closest_param(l, p) against the exact clamped projection: |t - t_exact| within the
// rounding of dot(p - o, d) / |d|^2 (relative eps in each of N products and the division, plus the
// absolute rounding of subnormal intermediates: for a subnormal direction the rescaled path
// rounds each of the N products of dot(p - o, d / m) and the denominator |d / m|^2 m to a
// multiple of denorm_min, an error of at most (N / 2 + |t| / 2) denorm_min / m in t), and an exact
// clamp when the exact parameter is outside the domain by more than that.
template <class T, int N>
void check_closest_param(const detail::LinearView<T, N>& l, const Vec<T, N>& p) {
  const T t = detail::closest_param(l, p);
  ASSERT_EQ(l.clamp_param(t), t);
  const auto q = q_view(l);
  const mpq_class a = ex::dot(q.dir, q.dir);
  ASSERT_GT(a, 0);
  const mpq_class raw = ex::dot(ex::sub(ex::to_q(p), q.origin), q.dir) / a;
  const double t_raw = raw.get_d(), t_ex = ex::clamp_param(q, raw).get_d();
  const double dn = norm_d(l.dir), m = double(max_abs(l.dir));
  const double err =
      double(tol<T>(T(N + 4))) * (norm_d(Vec<T, N>(p - l.origin)) / dn + std::abs(t_raw)) +
      (double(N) + std::abs(t_raw)) * double(std::numeric_limits<T>::denorm_min()) / m;
  EXPECT_NEAR(double(t), t_ex, err);
  if (l.bounded_lo && t_raw < -err) {
    EXPECT_EQ(t, T(0));
  }
  if (l.bounded_hi && t_raw > 1 + err) {
    EXPECT_EQ(t, T(1));
  }
}

// ---- exact linear-box oracle ------------------------------------------------------------------

template <int N>
struct QBoxMin {
  mpq_class fmin;
  bool unique;
};

template <int N>
mpq_class q_excess_sqr(const std::array<mpq_class, N>& p, const std::array<mpq_class, N>& d,
                       const std::array<mpq_class, N>& lo, const std::array<mpq_class, N>& hi,
                       const mpq_class& t) {
  mpq_class f = 0;
  for (std::size_t i = 0; i < N; ++i) {
    const mpq_class x = p[i] + t * d[i];
    if (x < lo[i]) f += (lo[i] - x) * (lo[i] - x);
    if (x > hi[i]) f += (x - hi[i]) * (x - hi[i]);
  }
  return f;
}

// Exact minimum of f(t) = sum_i excess_i(p + t d)^2 over the domain, and whether the minimisers
// form an interval of positive length (a piece on which every coordinate with d_i != 0 stays in
// its slab). The minimum lies at a breakpoint, a domain end or a piece's quadratic vertex.
template <int N>
QBoxMin<N> q_linear_box(const std::array<mpq_class, N>& p, const std::array<mpq_class, N>& d,
                        const std::array<mpq_class, N>& lo, const std::array<mpq_class, N>& hi,
                        bool blo, bool bhi) {
  std::vector<mpq_class> pts;
  if (blo) pts.emplace_back(0);
  if (bhi) pts.emplace_back(1);
  for (std::size_t i = 0; i < N; ++i) {
    if (d[i] == 0) continue;
    for (const mpq_class& b : {lo[i], hi[i]}) {
      const mpq_class t = (b - p[i]) / d[i];
      if ((!blo || t >= 0) && (!bhi || t <= 1)) pts.push_back(t);
    }
  }
  std::sort(pts.begin(), pts.end());
  if (pts.empty()) pts.emplace_back(0);
  // Pieces: (pts[k-1], pts[k]) plus the unbounded ends.
  std::vector<std::array<mpq_class, 2>> pieces;
  if (!blo) pieces.push_back({pts.front() - 1, pts.front()});
  for (std::size_t k = 1; k < pts.size(); ++k)
    if (pts[k - 1] < pts[k]) pieces.push_back({pts[k - 1], pts[k]});
  if (!bhi) pieces.push_back({pts.back(), pts.back() + 1});
  bool have = false;
  mpq_class best;
  const auto take = [&](const mpq_class& t) {
    const mpq_class f = q_excess_sqr<N>(p, d, lo, hi, t);
    if (!have || f < best) best = f, have = true;
  };
  for (const mpq_class& t : pts) take(t);
  bool unique = true;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const mpq_class mid = (pieces[k][0] + pieces[k][1]) / 2;
    mpq_class A = 0, B = 0;
    for (std::size_t i = 0; i < N; ++i) {
      if (d[i] == 0) continue;
      const mpq_class x = p[i] + mid * d[i];
      if (x < lo[i]) A += d[i] * d[i], B += d[i] * (p[i] - lo[i]);
      if (x > hi[i]) A += d[i] * d[i], B += d[i] * (p[i] - hi[i]);
    }
    if (A == 0) {
      unique = false;  // f constant on a piece of positive length: g = 0 there, the minimum
      continue;
    }
    mpq_class t = -B / A;
    const bool unbounded_lo = !blo && k == 0, unbounded_hi = !bhi && k + 1 == pieces.size();
    if (!unbounded_lo && t < pieces[k][0]) t = pieces[k][0];
    if (!unbounded_hi && t > pieces[k][1]) t = pieces[k][1];
    take(t);
  }
  return {best, unique};
}

template <class T, int N>
std::array<mpq_class, N> qa(const Vec<T, N>& v) {
  std::array<mpq_class, N> r;
  for (int i = 0; i < N; ++i) r[static_cast<std::size_t>(i)] = mpq_class(double(v[i]));
  return r;
}

template <class T, int N>
void run_linear_box(Rng& rng, int cases) {
  int nonunique = 0, flat_axis = 0;
  for (int n = 0; n < cases; ++n) {
    const int kind = rng.uniform_int(0, 2);
    const Vec<T, N> c = rng.vec<T, N>(T(-3), T(3));
    Vec<T, N> e = rng.vec<T, N>(T(0), T(2));
    if (rng.uniform_int(0, 9) == 0) e[rng.uniform_int(0, N - 1)] = T(0);  // flat box
    const Vec<T, N> lo = c - e, hi = c + e;
    Vec<T, N> p = rng.vec<T, N>(T(-8), T(8));
    Vec<T, N> d = rng.unit<T, N>() * rng.uniform<T>(T(0.5), T(10));
    const int sub = rng.uniform_int(0, 9);
    if (sub < 3) {  // one or more zero components: parallel to faces
      d[rng.uniform_int(0, N - 1)] = T(0);
      if (sub == 0) d[rng.uniform_int(0, N - 1)] = T(0);
      ++flat_axis;
    } else if (sub < 5) {  // through the box: p = a box point - s d
      Vec<T, N> q{};
      for (int i = 0; i < N; ++i) q[i] = rng.uniform<T>(lo[i], hi[i]);
      p = q - rng.uniform<T>(T(-0.5), T(1.5)) * d;
    } else if (sub == 5) {
      d = Vec<T, N>{};
    }
    const bool blo = kind >= 1, bhi = kind == 2;
    const detail::LinearBoxParam<T> r = detail::linear_box_param(p, d, lo, hi, blo, bhi);
    SCOPED_TRACE(::testing::Message() << "case " << n << " kind " << kind << " sub " << sub);
    ASSERT_TRUE(std::isfinite(double(r.t)));
    if (blo) {
      EXPECT_GE(r.t, T(0));
    }
    if (bhi) {
      EXPECT_LE(r.t, T(1));
    }
    if (!(max_abs(d) > T(0))) {
      EXPECT_EQ(r.t, T(0));
      EXPECT_TRUE(r.unique);
      continue;
    }
    const QBoxMin<N> o = q_linear_box<N>(qa(p), qa(d), qa(lo), qa(hi), blo, bhi);
    const mpq_class at = q_excess_sqr<N>(qa(p), qa(d), qa(lo), qa(hi), mpq_class(double(r.t)));
    const Vec<T, N> x = p + r.t * d;
    const T scale = std::max({T(8), max_abs(p), max_abs(lo), max_abs(hi), max_abs(x)});
    EXPECT_LE(mpq_class(at - o.fmin).get_d(), double(tol<T>(64, scale * scale)));
    EXPECT_EQ(r.unique, o.unique);
    if (!o.unique) {
      ++nonunique;
      EXPECT_EQ(at, o.fmin);  // the midpoint of a flat piece is an exact minimiser in exact f
    }

    // The aligned-box wrapper: same parameter, the box point is the clamp of l(t).
    if (kind == 2) {
      const Segment<T, N> s{p, p + d};
      const auto w = detail::linear_aligned_box_distance(s, AlignedBox<T, N>{lo, hi});
      const auto q = ex::segment(s.p0, s.p1);
      const QBoxMin<N> os = q_linear_box<N>(q.origin, q.dir, qa(lo), qa(hi), true, true);
      EXPECT_NEAR(double(w.sqr_distance), os.fmin.get_d(), double(tol<T>(64, scale * scale)));
      EXPECT_EQ(w.closest[0], point_at(s, w.param_a));
      for (int i = 0; i < N; ++i) EXPECT_EQ(w.closest[1][i], clamp(w.closest[0][i], lo[i], hi[i]));
    }
  }
  EXPECT_GT(nonunique, cases / 20);
  EXPECT_GT(flat_axis, cases / 10);
}

// ---- exact segment-triangle intersection ------------------------------------------------------

using Q3 = std::array<mpq_class, 3>;

Q3 q_cross(const Q3& a, const Q3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// x coplanar with the non-degenerate triangle (v0, e0, e1): barycentric inside test (Gram).
bool q_in_triangle(const Q3& x, const Q3& v0, const Q3& e0, const Q3& e1) {
  const Q3 w = ex::sub(x, v0);
  const mpq_class a = ex::dot(e0, e0), b = ex::dot(e0, e1), c = ex::dot(e1, e1);
  const mpq_class d0 = ex::dot(e0, w), d1 = ex::dot(e1, w), det = a * c - b * b;
  const mpq_class s = (c * d0 - b * d1) / det, u = (a * d1 - b * d0) / det;
  return s >= 0 && u >= 0 && s + u <= 1;
}

// 1 / 0: the closed segment meets / misses the closed triangle; -1: degenerate triangle.
template <class T>
int q_segment_meets_triangle(const Vec3<T>& p, const Vec3<T>& q, const Triangle3<T>& tri) {
  const Q3 v0 = ex::to_q(tri.v0), e0 = ex::sub(ex::to_q(tri.v1), v0),
           e1 = ex::sub(ex::to_q(tri.v2), v0);
  const Q3 nrm = q_cross(e0, e1);
  if (ex::dot(nrm, nrm) == 0) return -1;
  const Q3 qp = ex::to_q(p), qq = ex::to_q(q);
  const mpq_class sp = ex::dot(nrm, ex::sub(qp, v0)), sq = ex::dot(nrm, ex::sub(qq, v0));
  if ((sp > 0 && sq > 0) || (sp < 0 && sq < 0)) return 0;
  if (sp == 0 && sq == 0) {
    if (q_in_triangle(qp, v0, e0, e1) || q_in_triangle(qq, v0, e0, e1)) return 1;
    const auto seg = ex::segment(p, q);
    const Vec3<T>* v[3] = {&tri.v0, &tri.v1, &tri.v2};
    for (int k = 0; k < 3; ++k)
      if (ex::sqr_linear_linear(seg, ex::segment(*v[k], *v[(k + 1) % 3])) == 0) return 1;
    return 0;
  }
  const mpq_class t = sp / (sp - sq);  // the crossing of the plane, in [0, 1]
  return q_in_triangle(ex::axpy(qp, t, ex::sub(qq, qp)), v0, e0, e1) ? 1 : 0;
}

}  // namespace

// view(), LinearView::at and clamp_param follow their definitions; a segment's ends are exact.
TYPED_TEST(DetailLinearTest, ViewAtClamp) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 200; ++n) {
    const Vec3<T> a = rng.vec<T, 3>(T(-100), T(100)), b = rng.vec<T, 3>(T(-100), T(100));
    const auto lv = detail::view(Line3<T>{a, b});
    const auto rv = detail::view(Ray3<T>{a, b});
    const auto sv = detail::view(Segment3<T>{a, b});
    EXPECT_EQ(lv.origin, a);
    EXPECT_EQ(lv.dir, b);
    EXPECT_FALSE(lv.bounded_lo);
    EXPECT_FALSE(lv.bounded_hi);
    EXPECT_EQ(rv.origin, a);
    EXPECT_EQ(rv.dir, b);
    EXPECT_TRUE(rv.bounded_lo);
    EXPECT_FALSE(rv.bounded_hi);
    EXPECT_EQ(sv.origin, a);
    EXPECT_EQ(sv.end, b);
    EXPECT_EQ(sv.dir, b - a);
    EXPECT_TRUE(sv.bounded_lo);
    EXPECT_TRUE(sv.bounded_hi);
    EXPECT_EQ(sv.at(T(0)), a);
    EXPECT_EQ(sv.at(T(1)), b);  // exact endpoint (lerp), although a + (b - a) may round
    const T t = rng.uniform<T>(T(-3), T(3));
    EXPECT_EQ(lv.at(t), a + t * b);
    EXPECT_EQ(rv.at(t), a + t * b);
    EXPECT_EQ(sv.at(t), lerp(a, b, t));
    EXPECT_EQ(lv.clamp_param(t), t);
    EXPECT_EQ(rv.clamp_param(t), t < T(0) ? T(0) : t);
    EXPECT_EQ(sv.clamp_param(t), t < T(0) ? T(0) : (t > T(1) ? T(1) : t));
  }
  const auto sv = detail::view(Segment2<T>{{T(0), T(0)}, {T(1), T(1)}});
  for (const T t : {T(0), T(1), T(0.5)}) EXPECT_EQ(sv.clamp_param(t), t);
  EXPECT_EQ(sv.clamp_param(-std::numeric_limits<T>::infinity()), T(0));
  EXPECT_EQ(sv.clamp_param(std::numeric_limits<T>::infinity()), T(1));
  EXPECT_EQ(sv.clamp_param(-std::numeric_limits<T>::denorm_min()), T(0));
}

TYPED_TEST(DetailLinearTest, ClosestParamExact) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  constexpr T dmin = std::numeric_limits<T>::denorm_min();
  // Underflowing square (but normal components) and overflowing square: the rescaled path.
  const T tiny = std::is_same_v<T, float> ? T(1e-25) : T(1e-170);
  const T huge = std::is_same_v<T, float> ? T(1e25) : T(1e200);
  for (int n = 0; n < 600; ++n) {
    const int kind = rng.uniform_int(0, 2), regime = n % 5;
    SCOPED_TRACE(::testing::Message() << "case " << n << " kind " << kind << " regime " << regime);
    Vec3<T> o = rng.vec<T, 3>(T(-10), T(10)), d = rng.unit<T, 3>() * rng.uniform<T>(T(0.5), T(4));
    Vec3<T> p = rng.vec<T, 3>(T(-20), T(20));
    if (regime == 1) {  // |d|^2 underflows; o and p at the same tiny scale keep t moderate
      d = d * tiny;
      o = o * tiny;
    } else if (regime == 2) {  // |d|^2 overflows; p, o of the same magnitude
      d = d * huge;
      o = o * huge;
      p = p * huge;
    } else if (regime == 3) {  // subnormal direction and offsets: multiples of denorm_min
      Vec3<T> k{}, j{};
      for (int i = 0; i < 3; ++i) {
        k[i] = T(rng.uniform_int(-40, 40));
        j[i] = T(rng.uniform_int(-200, 200));
      }
      if (k == Vec3<T>{}) k.x = T(1);
      d = k * dmin;
      o = Vec3<T>{};
      p = j * dmin;
    } else if (regime == 4) {  // 2D
      const Vec2<T> o2{o.x, o.y}, d2{d.x, d.y}, p2{p.x, p.y};
      check_closest_param(make_view(kind, o2, d2), p2);
      continue;
    }
    const auto l = make_view(kind, o, d);
    if (regime == 1) {
      // A point at parameter ~[-2, 3] of the line, off it by ~|d|.
      p = o + rng.uniform<T>(T(-2), T(3)) * d + rng.unit<T, 3>() * (tiny * T(2));
    }
    check_closest_param(l, p);
    // Zero direction (either sign of zero): parameter 0.
    const auto z = make_view(kind == 2 ? 0 : kind, o, Vec3<T>{T(0), -T(0), T(0)});
    EXPECT_EQ(detail::closest_param(z, p), T(0));
  }
  // A zero-length segment is its first point.
  const Vec2<T> a{T(1), T(2)};
  EXPECT_EQ(detail::closest_param(detail::view(Segment2<T>{a, a}), Vec2<T>{T(5), T(-3)}), T(0));
}

// A point far beyond the end of a very short segment: the unclamped parameter overflows to
// +-inf and must still be clamped to the nearer end (not reset to 0); a ray keeps its origin only
// when the point lies behind it. A line has no end to clamp to: 0 (documented fallback).
TYPED_TEST(DetailLinearTest, ClosestParamOverflowClamps) {
  using T = TypeParam;
  constexpr T dmin = std::numeric_limits<T>::denorm_min();
  const Vec3<T> x{T(1), T(0), T(0)}, zero{};
  for (const T len : {dmin, T(64) * dmin, std::numeric_limits<T>::min() / T(4)}) {
    SCOPED_TRACE(::testing::Message() << "length " << len);
    const auto seg = detail::view(Segment3<T>{zero, len * x});
    EXPECT_EQ(detail::closest_param(seg, x), T(1));
    EXPECT_EQ(detail::closest_param(seg, -x), T(0));
    EXPECT_EQ(detail::closest_param(seg, T(1e10) * x), T(1));
    const auto ray = detail::view(Ray3<T>{zero, len * x});
    EXPECT_EQ(detail::closest_param(ray, -x), T(0));
    const T tr = detail::closest_param(ray, x);  // +inf unclamped: no finite answer but 0
    EXPECT_TRUE(tr == T(0) || tr >= T(1) / (len * T(2)));
    check_closest_param(seg, Vec3<T>{T(3) * len, len, T(0)});  // moderate t still exact
  }
  if constexpr (std::is_same_v<T, double>) {
    const auto seg = detail::view(Segment3<T>{zero, T(1e-300) * x});
    EXPECT_EQ(detail::closest_param(seg, T(1e10) * x), T(1));
  }
  // Subnormal direction, moderate parameter: no rounding to the subnormal grid (25.01 stays
  // close to 25.01, not 24 or 25).
  const auto sub = detail::view(Line3<T>{zero, T(100) * dmin * x});
  const T t = detail::closest_param(sub, T(2501) * dmin * x);
  EXPECT_NEAR(double(t), 25.01, 25.01 * double(tol<T>(T(8))));
}

TYPED_TEST(DetailLinearTest, SqrCrossNormAndOverlaps) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 500; ++n) {
    // Small integers: every product and sum is exact in float and double.
    Vec<T, 4> a{}, b{};
    for (int i = 0; i < 4; ++i) {
      a[i] = T(rng.uniform_int(-20, 20));
      b[i] = T(rng.uniform_int(-20, 20));
    }
    if (n % 7 == 0) b = a * T(rng.uniform_int(-3, 3));  // parallel: exactly 0
    const Vec3<T> a3{a[0], a[1], a[2]}, b3{b[0], b[1], b[2]};
    const Vec2<T> a2{a[0], a[1]}, b2{b[0], b[1]};
    EXPECT_EQ(detail::sqr_cross_norm(a3, b3), sqr_length(cross(a3, b3)));
    EXPECT_EQ(detail::sqr_cross_norm(b3, a3), sqr_length(cross(a3, b3)));
    EXPECT_EQ(detail::sqr_cross_norm(a2, b2), sqr(perp_dot(a2, b2)));
    // Lagrange's identity in 4D, in 64-bit integers.
    long long aa = 0, bb = 0, ab = 0;
    for (int i = 0; i < 4; ++i) {
      aa += static_cast<long long>(a[i]) * static_cast<long long>(a[i]);
      bb += static_cast<long long>(b[i]) * static_cast<long long>(b[i]);
      ab += static_cast<long long>(a[i]) * static_cast<long long>(b[i]);
    }
    EXPECT_EQ(static_cast<long long>(detail::sqr_cross_norm(a, b)), aa * bb - ab * ab);
    if (n % 7 == 0) {
      EXPECT_EQ(detail::sqr_cross_norm(a, b), T(0));
    }
  }
  // overlaps(): positive-length intersection iff some half-integer lies in both open intervals
  // (integer endpoints; an empty interval lo > hi contains none).
  for (int lo0 = 0; lo0 <= 4; ++lo0)
    for (int hi0 = 0; hi0 <= 4; ++hi0)
      for (int lo1 = 0; lo1 <= 4; ++lo1)
        for (int hi1 = 0; hi1 <= 4; ++hi1) {
          bool both = false;
          for (int k = 0; k < 5; ++k) {
            const double x = k + 0.5;
            both = both || (lo0 < x && x < hi0 && lo1 < x && x < hi1);
          }
          EXPECT_EQ(detail::overlaps(T(lo0), T(hi0), T(lo1), T(hi1)), both)
              << lo0 << " " << hi0 << " " << lo1 << " " << hi1;
        }
  constexpr T inf = std::numeric_limits<T>::infinity();
  EXPECT_TRUE(detail::overlaps(-inf, inf, -inf, inf));
  EXPECT_TRUE(detail::overlaps(-inf, T(0), T(-1), inf));
  EXPECT_FALSE(detail::overlaps(-inf, T(0), T(0), inf));
  EXPECT_FALSE(detail::overlaps(T(0), T(1), T(1), inf));
}

namespace {

template <class T, int N>
void run_linear_linear(Rng& rng, int cases) {
  const T S = 4;
  int parallel_nonunique = 0, parallel_unique = 0;
  for (int n = 0; n < cases; ++n) {
    const int ka = rng.uniform_int(0, 2), kb = rng.uniform_int(0, 2);
    const Vec<T, N> o0 = rng.vec<T, N>(-S, S), o1 = rng.vec<T, N>(-S, S);
    Vec<T, N> d0 = rng.unit<T, N>() * rng.uniform<T>(T(0.5), T(2)) * S;
    Vec<T, N> d1 = rng.unit<T, N>() * rng.uniform<T>(T(0.5), T(2)) * S;
    const int kind = rng.uniform_int(0, 19);
    bool exactly_parallel = false;
    if (kind < 3) {  // nearly parallel: relative perturbation 1e-3 .. 1000 eps
      const T lo = -std::log10(T(1000) * eps_v<T>);
      const T rel = std::pow(T(10), -rng.uniform<T>(T(3), lo));
      d1 = d0 * (rng.uniform_int(0, 1) ? T(1) : T(-0.7)) + rng.unit<T, N>() * (rel * S);
    } else if (kind < 9) {  // exactly parallel by a power of two; collinear half the time
      d1 = d0 * (rng.uniform_int(0, 1) ? T(2) : T(-0.5));
      exactly_parallel = true;
    } else if (kind < 10) {
      (rng.uniform_int(0, 1) ? d0 : d1) = Vec<T, N>{};
    }
    Vec<T, N> b_origin = o1;
    if (exactly_parallel && rng.uniform_int(0, 1)) b_origin = o0 + rng.uniform<T>(T(-2), T(2)) * d0;
    const auto A = make_view(ka, o0, d0);
    const auto B = make_view(kb, b_origin, d1);
    SCOPED_TRACE(::testing::Message() << "case " << n << " kinds " << ka << kb << " kind " << kind);
    const detail::LinLinParams<T> st = detail::linear_linear(A, B);
    ASSERT_TRUE(std::isfinite(double(st.s)) && std::isfinite(double(st.t)));
    EXPECT_EQ(A.clamp_param(st.s), st.s);
    EXPECT_EQ(B.clamp_param(st.t), st.t);
    const Vec<T, N> pa = A.at(st.s), pb = B.at(st.t);
    const auto qA = q_view(A), qB = q_view(B);
    const double exact = ex::sqr_linear_linear(qA, qB).get_d();
    // Within k eps scale^2, scale being the magnitude of the closest points (exact or returned).
    const double scale =
        std::max({8.0, double(max_abs(pa)), double(max_abs(pb)), q_closest_scale(qA, qB)});
    EXPECT_NEAR(double(sqr_length(pa - pb)), exact, 64.0 * double(eps_v<T>) * scale * scale);

    // The unique flag: exactly parallel pairs are non-unique iff B's range projected onto A's
    // line overlaps A's range in an interval (exact rationals); otherwise unique.
    if (exactly_parallel && max_abs(d0) > T(0)) {
      const mpq_class a = ex::dot(qA.dir, qA.dir);
      const ex::QVec<N> r = ex::sub(qB.origin, qA.origin);
      const mpq_class s0 = ex::dot(r, qA.dir) / a, k = ex::dot(qB.dir, qA.dir) / a;
      // B(t) projects to s0 + k t; A's range is [0 or -inf, 1 or inf].
      bool overlap;
      if (!qB.lo) {
        overlap = true;  // B's projection is the whole line
      } else if (!qB.hi) {
        // [s0, inf) if k > 0 else (-inf, s0]: overlaps A's open range in an interval iff A's
        // range extends beyond s0 in that direction.
        overlap = k > 0 ? (!qA.hi || s0 < 1) : (!qA.lo || s0 > 0);
      } else {
        const mpq_class s1 = s0 + k;
        const mpq_class lo = s0 < s1 ? s0 : s1, hi = s0 < s1 ? s1 : s0;
        const mpq_class alo = qA.lo ? mpq_class(0) : lo - 1, ahi = qA.hi ? mpq_class(1) : hi + 1;
        overlap = (lo > alo ? lo : alo) < (hi < ahi ? hi : ahi);
      }
      EXPECT_EQ(st.unique, !overlap);
      (st.unique ? parallel_unique : parallel_nonunique)++;
    } else {
      // Unique whenever a direction is zero, or the exact sin^2 of the angle, D / (a c), is
      // clearly (4x) above the documented (8 eps)^2; closer to it the flag may go either way.
      const mpq_class a = ex::dot(qA.dir, qA.dir), c = ex::dot(qB.dir, qB.dir),
                      b = ex::dot(qA.dir, qB.dir);
      const mpq_class e8 = mpq_class(8.0 * double(eps_v<T>));
      if (a == 0 || c == 0 || a * c - b * b > 4 * e8 * e8 * a * c) {
        EXPECT_TRUE(st.unique);
      }
    }
  }
  EXPECT_GT(parallel_unique, cases / 50);
  EXPECT_GT(parallel_nonunique, cases / 20);
}

}  // namespace

TYPED_TEST(DetailLinearTest, LinearLinearExact) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  run_linear_linear<T, 2>(rng, 400);
  run_linear_linear<T, 3>(rng, 600);
}

TYPED_TEST(DetailLinearTest, LinearBoxParamExact) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  run_linear_box<T, 2>(rng, 300);
  run_linear_box<T, 3>(rng, 400);
}

// linear_oriented_box_distance on a rotated box: a segment sampled densely (each sample's box
// distance is a clamp in the box frame) bounds the true minimum within |d| h / 2 from below.
TYPED_TEST(DetailLinearTest, LinearOrientedBoxSampled) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  constexpr int kSamples = 2000;
  for (int n = 0; n < 60; ++n) {
    const auto R = locus_test::dist::random_rotation<T, 3>(rng);
    OrientedBox<T, 3> box{rng.vec<T, 3>(T(-2), T(2)), {}, rng.vec<T, 3>(T(0), T(2))};
    for (int i = 0; i < 3; ++i) box.axis[i] = col(R, i);
    const Segment3<T> s{rng.vec<T, 3>(T(-6), T(6)), rng.vec<T, 3>(T(-6), T(6))};
    const auto r = detail::linear_oriented_box_distance(s, box);
    double best = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= kSamples; ++k) {
      const T t = T(k) / T(kSamples);
      best = std::min(best, double(distance(point_at(s, t), box).distance));
    }
    const double h = 1.0 / kSamples, len = norm_d(Vec3<T>(s.p1 - s.p0));
    SCOPED_TRACE(::testing::Message() << "case " << n);
    EXPECT_LE(double(r.distance), best + double(tol<T>(64, T(16))));
    EXPECT_GE(double(r.distance), best - 0.5 * h * len - double(tol<T>(64, T(16))));
    EXPECT_EQ(r.closest[0], point_at(s, r.param_a));
  }
  // Non-finite input.
  OrientedBox<T, 3> box{
      {}, {{T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}}, {T(1), T(1), T(1)}};
  const auto bad = detail::linear_oriented_box_distance(
      Line3<T>{{std::numeric_limits<T>::quiet_NaN(), T(0), T(0)}, {T(1), T(0), T(0)}}, box);
  EXPECT_TRUE(std::isnan(double(bad.distance)));
}

// linear_polyline_distance is the minimum over the edges of the public linear-segment distance.
TYPED_TEST(DetailLinearTest, LinearPolylineMinOverEdges) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int multi_edge = 0;
  for (int n = 0; n < 300; ++n) {
    const int kind = rng.uniform_int(0, 2), nv = rng.uniform_int(1, 12);
    const bool closed = rng.uniform_int(0, 1) == 1;
    std::vector<Vec2<T>> v;
    Vec2<T> cur = rng.vec<T, 2>(T(-10), T(10));
    for (int i = 0; i < nv; ++i) {
      v.push_back(cur);
      cur = cur + rng.vec<T, 2>(T(-3), T(3));
    }
    const Vec2<T> o = rng.vec<T, 2>(T(-10), T(10));
    Vec2<T> d = rng.unit<T, 2>() * rng.uniform<T>(T(0.5), T(8));
    if (rng.uniform_int(0, 9) == 0) d = Vec2<T>{};
    const Line2<T> line{o, d};
    const Ray2<T> ray{o, d};
    const Segment2<T> seg{o, o + d};
    const std::span<const Vec2<T>> sv(v);
    const std::size_t m = segment_count(v.size(), closed);
    SCOPED_TRACE(::testing::Message() << "case " << n << " kind " << kind << " nv " << nv);
    const auto check = [&](const auto& l) {
      const auto r = detail::linear_polyline_distance<T, 2>(l, sv, closed);
      if (m == 0) {
        const double q = ex::sqr_point_linear(ex::to_q(v[0]), q_of(l)).get_d();
        const T scale = std::max({T(16), max_abs(r.closest[0]), max_abs(v[0])});
        EXPECT_NEAR(double(r.sqr_distance), q, double(tol<T>(64, scale * scale)));
        EXPECT_EQ(r.closest[1], v[0]);
        EXPECT_EQ(r.param_b, T(0));
        return;
      }
      // The answer is one edge's result (same bits, vertex parameter i + local parameter), and
      // no edge is closer beyond rounding: the rejection tests may drop an edge that ties up to
      // the rounding of mu (e.g. the closest point is a vertex shared by two edges).
      T best = std::numeric_limits<T>::infinity();
      bool is_an_edge = false;
      for (std::size_t i = 0; i < m; ++i) {
        const auto q = distance(l, edge(sv, i));
        best = std::min(best, q.sqr_distance);
        is_an_edge = is_an_edge || (q.sqr_distance == r.sqr_distance &&
                                    r.param_b == static_cast<T>(i) + q.param_b &&
                                    q.closest[0] == r.closest[0] && q.closest[1] == r.closest[1]);
      }
      multi_edge += m > 1;
      EXPECT_TRUE(is_an_edge);
      const T scale = std::max({T(16), max_abs(r.closest[0]), max_abs(r.closest[1])});
      EXPECT_GE(r.sqr_distance, best);
      EXPECT_LE(r.sqr_distance - best, tol<T>(16, scale * scale));
      EXPECT_EQ(r.closest[0], point_at(l, r.param_a));
    };
    if (kind == 0) check(line);
    if (kind == 1) check(ray);
    if (kind == 2) check(seg);
  }
  EXPECT_GT(multi_edge, 100);
  // Empty chain and non-finite vertices: non-finite result.
  const std::vector<Vec2<T>> none;
  const Segment2<T> s{{T(0), T(0)}, {T(1), T(0)}};
  EXPECT_TRUE(std::isnan(double(
      detail::linear_polyline_distance<T, 2>(s, std::span<const Vec2<T>>(none), false).distance)));
  const std::vector<Vec2<T>> bad{{T(0), T(1)}, {std::numeric_limits<T>::infinity(), T(0)}};
  EXPECT_TRUE(std::isnan(double(
      detail::linear_polyline_distance<T, 2>(s, std::span<const Vec2<T>>(bad), false).distance)));
}

// segment_meets_triangle against the exact rational test, on small integers (many coplanar,
// touching and degenerate configurations) and on constructed contacts at vertices and edges.
TYPED_TEST(DetailLinearTest, SegmentMeetsTriangleExact) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int count[3] = {0, 0, 0}, coplanar = 0;
  const auto ivec = [&](int r) {
    return Vec3<T>{T(rng.uniform_int(-r, r)), T(rng.uniform_int(-r, r)), T(rng.uniform_int(-r, r))};
  };
  for (int n = 0; n < 3000; ++n) {
    Triangle3<T> tri{ivec(2), ivec(2), ivec(2)};
    Vec3<T> p = ivec(3), q = ivec(3);
    const int kind = n % 6;
    if (kind == 1) {  // coplanar: the triangle in z = 0 (or x = 0), the segment too
      tri.v0.z = tri.v1.z = tri.v2.z = p.z = q.z = T(rng.uniform_int(-1, 1));
    } else if (kind == 2) {  // an endpoint at a vertex, or the segment through an edge midpoint
      const Vec3<T>* v[3] = {&tri.v0, &tri.v1, &tri.v2};
      const int i = rng.uniform_int(0, 2);
      if (rng.uniform_int(0, 1))
        p = *v[i];
      else
        q = T(2) * (T(0.5) * (*v[i] + *v[(i + 1) % 3])) - p;  // midpoint of p, q on the edge
    } else if (kind == 3) {  // random doubles-of-T in a small range, not integer
      tri = Triangle3<T>{rng.vec<T, 3>(T(-2), T(2)), rng.vec<T, 3>(T(-2), T(2)),
                         rng.vec<T, 3>(T(-2), T(2))};
      p = rng.vec<T, 3>(T(-3), T(3));
      q = rng.vec<T, 3>(T(-3), T(3));
    } else if (kind == 4) {  // degenerate triangle: collinear vertices
      tri.v2 = tri.v0 + T(rng.uniform_int(-2, 2)) * (tri.v1 - tri.v0);
    }
    const int got = detail::segment_meets_triangle(p, q, tri);
    const int want = q_segment_meets_triangle(p, q, tri);
    EXPECT_EQ(got, want) << "case " << n;
    ++count[want + 1];
    if (want >= 0) {
      const Q3 v0 = ex::to_q(tri.v0);
      const Q3 nrm = q_cross(ex::sub(ex::to_q(tri.v1), v0), ex::sub(ex::to_q(tri.v2), v0));
      coplanar += ex::dot(nrm, ex::sub(ex::to_q(p), v0)) == 0 &&
                  ex::dot(nrm, ex::sub(ex::to_q(q), v0)) == 0;
    }
    // Swapping the ends or the vertex order does not change the answer.
    EXPECT_EQ(detail::segment_meets_triangle(q, p, tri), want);
    EXPECT_EQ(detail::segment_meets_triangle(p, q, Triangle3<T>{tri.v0, tri.v2, tri.v1}), want);
  }
  EXPECT_GT(count[0], 100);
  EXPECT_GT(count[1], 300);
  EXPECT_GT(count[2], 300);
  EXPECT_GT(coplanar, 300);
}

TYPED_TEST(DetailLinearTest, BestCandidateOffer) {
  using T = TypeParam;
  using BC = detail::BestCandidate<T, Vec2<T>>;
  constexpr T inf = std::numeric_limits<T>::infinity(), nan = std::numeric_limits<T>::quiet_NaN();
  {
    BC b;
    EXPECT_FALSE(b.found);
    b.offer(inf, T(0.25), Vec2<T>{T(1), T(2)}, false);  // first offer always taken, even inf
    EXPECT_TRUE(b.found);
    EXPECT_EQ(b.sqr, inf);
    EXPECT_EQ(b.t, T(0.25));
    EXPECT_EQ(b.param, (Vec2<T>{T(1), T(2)}));
    EXPECT_FALSE(b.unique);
    b.offer(T(3), T(0.5), Vec2<T>{T(3), T(4)}, true);  // strictly smaller replaces
    EXPECT_EQ(b.sqr, T(3));
    EXPECT_EQ(b.t, T(0.5));
    EXPECT_TRUE(b.unique);
    b.offer(T(3), T(0.75), Vec2<T>{T(5), T(6)}, false);  // a tie keeps the first
    EXPECT_EQ(b.t, T(0.5));
    EXPECT_TRUE(b.unique);
    b.offer(nan, T(0.9), Vec2<T>{}, false);  // NaN never replaces a found candidate
    EXPECT_EQ(b.sqr, T(3));
    EXPECT_EQ(b.t, T(0.5));
    b.offer(T(2), T(0.1), Vec2<T>{T(7), T(8)}, false);
    EXPECT_EQ(b.sqr, T(2));
    EXPECT_EQ(b.param, (Vec2<T>{T(7), T(8)}));
    EXPECT_FALSE(b.unique);
  }
  {
    // A NaN first offer is taken (found), and replaced by the first comparable offer; later
    // offers compete as usual.
    BC b;
    b.offer(nan, T(0.3), Vec2<T>{T(1), T(1)}, true);
    EXPECT_TRUE(b.found);
    EXPECT_TRUE(std::isnan(double(b.sqr)));
    b.offer(nan, T(0.4), Vec2<T>{T(1), T(1)}, true);
    EXPECT_TRUE(std::isnan(double(b.sqr)));
    b.offer(T(5), T(0.6), Vec2<T>{T(2), T(2)}, false);
    EXPECT_EQ(b.sqr, T(5));
    EXPECT_EQ(b.t, T(0.6));
    EXPECT_FALSE(b.unique);
    b.offer(nan, T(0.7), Vec2<T>{T(3), T(3)}, true);
    EXPECT_EQ(b.t, T(0.6));
    b.offer(T(1), T(0.8), Vec2<T>{T(4), T(4)}, true);
    EXPECT_EQ(b.t, T(0.8));
    EXPECT_EQ(b.param, (Vec2<T>{T(4), T(4)}));
  }
}
