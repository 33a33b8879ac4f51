// SPDX-License-Identifier: BSL-1.0
// Tests for distance/line_quadratic_curve.hpp and distance/line_curve.hpp (row dist2.linear-curve:
// line / ray / segment to a general conic and to Bézier, B-spline and NURBS curves; book section
// 6.4, figure 6.23).
//
// Oracle: an independent long-double minimisation over the CURVE's parameter: the curve is
// parametrised by the test itself (conics from their coefficients: centre, eigenframe and
// cos/sin, cosh/sinh or the parabola's graph; line pairs from the linear factors they were
// built from; curves by a long-double de Boor on the homogeneous control points), sampled
// densely, and every discrete local minimum of the EXACT clamped point-to-linear distance is
// refined by golden section. Both the returned distance and its realisability (closest points
// on the objects, |closest[0] - closest[1]| = distance) are checked.
#include <locus/distance/detail/pair_candidates.hpp>
#include <locus/distance/line_curve.hpp>
#include <locus/distance/line_ellipse.hpp>
#include <locus/distance/line_quadratic_curve.hpp>

#include "distance/harness.hpp"
#include "distance/linear_oracle.hpp"
#include "distance/side_curved.hpp"
#include "support/sanitizer.hpp"
#include "support/typed.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

using namespace locus;
using locus_test::Rng;
namespace dist = locus_test::dist;

template <class T>
class LinearCurveTest : public ::testing::Test {};
TYPED_TEST_SUITE(LinearCurveTest, locus_test::RealTypes);

namespace {

#if LOCUS_TEST_SANITIZED
constexpr int kCaseScale = 6;
#else
constexpr int kCaseScale = 1;
#endif

using locus_test::linear_oracle::golden_section_min;
using locus_test::linear_oracle::LD;
using locus_test::linear_oracle::LinLD;
using locus_test::linear_oracle::min_over_samples;
using locus_test::linear_oracle::near_ld;
using locus_test::linear_oracle::sqr_to_linear;
using locus_test::linear_oracle::to_ld;

/// A parametrised piece X(u), u in [lo, hi], sampled once at n + 1 points so that several
/// linear components can be measured against it.
template <int N>
struct Sampled {
  std::function<Vec<LD, N>(LD)> at;
  LD lo, hi;
  std::vector<Vec<LD, N>> pts;
  Sampled(std::function<Vec<LD, N>(LD)> f, LD l, LD h, int n) : at(std::move(f)), lo(l), hi(h) {
    for (int i = 0; i <= n; ++i) pts.push_back(at(lo + (hi - lo) * LD(i) / LD(n)));
  }
  /// min over u of sqr(dist(X(u), q)) for q -> dist2(q) (the exact distance to the other object).
  template <class D2>
  LD min_sqr(D2&& dist2) const {
    std::vector<LD> val(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) val[i] = dist2(pts[i]);
    return min_over_samples(
        val, [&](LD u) { return dist2(at(u)); }, lo, hi);
  }
};

// ---- conics ---------------------------------------------------------------------------------

using V2 = Vec2<LD>;

/// A piece of a conic: X(u) for u in [lo, hi] (sampled lazily by the oracle). `meets` (empty for
/// an ellipse, which is sampled whole) gives the parameters u, in or beyond [lo, hi], where the
/// unbounded curve X(u) meets the infinite line through o with direction d: a line nearly parallel
/// to an asymptote, the axis of a parabola or a line of a pair crosses it arbitrarily far out,
/// beyond any sampled reach (a ray meeting a hyperbola at 4188 with the reach 800, seed 30).
struct Piece {
  std::function<V2(LD)> at;
  LD lo, hi;
  std::function<std::vector<LD>(const V2& o, const V2& d)> meets = {};
};

/// The real roots of a2 x^2 + a1 x + a0 (the cancellation-free pair; a linear or constant
/// polynomial gives its root or none).
std::vector<LD> real_roots(LD a2, LD a1, LD a0) {
  if (a2 == 0) return a1 != 0 ? std::vector<LD>{-a0 / a1} : std::vector<LD>{};
  const LD disc = a1 * a1 - 4 * a2 * a0;
  if (disc < 0) return {};
  const LD qq = -(a1 + std::copysign(std::sqrt(disc), a1)) / 2;
  if (qq == 0) return {LD(0)};
  return {qq / a2, a0 / qq};
}

/// A conic with its expected class and the oracle's parametrisation.
template <class T>
struct TestConic {
  QuadraticCurve2<T> q;
  ConicKind kind;
  std::vector<Piece> pieces;
  std::vector<std::pair<V2, LD>> lines = {};  // a line pair's factors l . X + c = 0
};

struct Coeffs {
  LD a, b, c, d, e, f;
};
template <class T>
Coeffs coeffs(const QuadraticCurve2<T>& q) {
  return {LD(q.a), LD(q.b), LD(q.c), LD(q.d), LD(q.e), LD(q.f)};
}

/// Ellipse or hyperbola pieces from the coefficients (centre, eigenframe, value at the centre).
std::vector<Piece> central_pieces(const Coeffs& k, LD reach) {
  const LD hb = k.b / 2, det = k.a * k.c - hb * hb;
  const V2 ctr{(-k.d * k.c + k.e * hb) / (2 * det), (-k.e * k.a + k.d * hb) / (2 * det)};
  const LD val = k.f + (k.d * ctr.x + k.e * ctr.y) / 2;
  const LD th = std::atan2(k.b, k.a - k.c) / 2;
  const V2 u{std::cos(th), std::sin(th)}, w{-std::sin(th), std::cos(th)};
  const LD l1 = k.a * u.x * u.x + k.b * u.x * u.y + k.c * u.y * u.y;
  const LD l2 = k.a * w.x * w.x + k.b * w.x * w.y + k.c * w.y * w.y;
  const LD pi2 = 2 * std::acos(LD(-1));
  if (det > 0) {
    const LD r1 = std::sqrt(-val / l1), r2 = std::sqrt(-val / l2);
    return {{[=](LD p) { return ctr + (r1 * std::cos(p)) * u + (r2 * std::sin(p)) * w; }, 0, pi2}};
  }
  // Hyperbola: the axis along which -val / l > 0 is the transverse one.
  V2 tu = u, tw = w;
  LD lt = l1, lc = l2;
  if (!(-val / l1 > 0)) tu = w, tw = u, lt = l2, lc = l1;
  const LD r1 = std::sqrt(-val / lt), r2 = std::sqrt(val / lc);
  const LD tmax = std::asinh(reach / std::min(r1, r2));
  std::vector<Piece> out;
  for (const LD sgn : {LD(1), LD(-1)}) {
    // nn . (X(p) - o) = A cosh p + B sinh p + K = 0 with nn normal to d is, in z = e^p > 0,
    // (A + B) z^2 + 2 K z + (A - B) = 0.
    const auto meets = [=](const V2& o, const V2& d) {
      const V2 nn{-d.y, d.x};
      const LD A = sgn * r1 * dot(nn, tu), B = r2 * dot(nn, tw), K = dot(nn, ctr - o);
      std::vector<LD> ps;
      for (const LD z : real_roots(A + B, 2 * K, A - B))
        if (z > 0) ps.push_back(std::log(z));
      return ps;
    };
    out.push_back(
        {[=](LD p) { return ctr + (sgn * r1 * std::cosh(p)) * tu + (r2 * std::sinh(p)) * tw; },
         -tmax, tmax, meets});
  }
  return out;
}

/// Parabola piece from the coefficients: lambda s^2 + beta s + gamma r + f = 0 in the frame of the
/// rank-one A.
std::vector<Piece> parabola_pieces(const Coeffs& k, LD reach) {
  const LD hb = k.b / 2;
  V2 n = (k.a * k.a + hb * hb >= hb * hb + k.c * k.c) ? V2{k.a, hb} : V2{hb, k.c};
  n = n / std::sqrt(sqr_length(n));
  const V2 m{-n.y, n.x};
  const LD lam = k.a + k.c, beta = k.d * n.x + k.e * n.y, gamma = k.d * m.x + k.e * m.y;
  const LD smax =
      std::sqrt(reach * std::fabs(gamma) / std::fabs(lam)) + std::fabs(beta / lam) + reach;
  // nn . (X(s) - o) = 0 times gamma: -(nn . m) lam s^2 + (gamma nn . n - beta nn . m) s
  // - (nn . m) f - gamma nn . o = 0.
  const auto meets = [=](const V2& o, const V2& d) {
    const V2 nn{-d.y, d.x};
    const LD nm = dot(nn, m);
    return real_roots(-nm * lam, gamma * dot(nn, n) - beta * nm, -nm * k.f - gamma * dot(nn, o));
  };
  return {{[=](LD s) { return s * n - ((lam * s * s + beta * s + k.f) / gamma) * m; }, -smax, smax,
           meets}};
}

/// The line l . X + c = 0 as a piece.
Piece line_piece(V2 l, LD c, LD reach) {
  const V2 x0 = (-c / sqr_length(l)) * l;
  const V2 dir = V2{-l.y, l.x} / std::sqrt(sqr_length(l));
  const auto meets = [=](const V2& o, const V2& d) {
    const V2 nn{-d.y, d.x};
    const LD den = dot(nn, dir);
    return den != 0 ? std::vector<LD>{dot(nn, o - x0) / den} : std::vector<LD>{};
  };
  return {[=](LD r) { return x0 + r * dir; }, -reach, reach, meets};
}

template <class T>
TestConic<T> make_central(Rng& rng, T s, bool ellipse) {
  const T phi = rng.uniform<T>(T(0), T(6.283185307179586));
  const T cs = std::cos(phi), sn = std::sin(phi);
  const T l1 = rng.uniform<T>(T(0.05), T(2));
  const T l2 = ellipse ? rng.uniform<T>(T(0.05), T(2)) : -rng.uniform<T>(T(0.05), T(2));
  const T k = ellipse ? -rng.uniform<T>(T(0.5), T(8))
                      : (rng.uniform_int(0, 1) ? T(1) : T(-1)) * rng.uniform<T>(T(0.3), T(8));
  const Vec2<T> c = rng.vec<T, 2>(-s, s);
  // (X - c)^T R diag(l1, l2) R^T (X - c) + k = 0, expanded (rounded in T).
  const T a = l1 * cs * cs + l2 * sn * sn, b = T(2) * (l1 - l2) * cs * sn,
          cc = l1 * sn * sn + l2 * cs * cs;
  const QuadraticCurve2<T> q{a,
                             b,
                             cc,
                             -(T(2) * a * c.x + b * c.y),
                             -(T(2) * cc * c.y + b * c.x),
                             a * c.x * c.x + b * c.x * c.y + cc * c.y * c.y + k};
  return {q, ellipse ? ConicKind::ellipse : ConicKind::hyperbola,
          central_pieces(coeffs(q), LD(100) * LD(s))};
}

template <class T>
TestConic<T> make_parabola(Rng& rng, T s) {
  int p = 0, r = 0;
  while (p == 0 && r == 0) p = rng.uniform_int(-3, 3), r = rng.uniform_int(-3, 3);
  const T lam =
      std::array<T, 4>{T(1), T(2), T(0.5), T(-1)}[static_cast<std::size_t>(rng.uniform_int(0, 3))];
  // A = lam n n^T with n = (p, r): exact in T, so b^2 = 4ac exactly.
  const QuadraticCurve2<T> q{lam * T(p * p),        T(2) * lam * T(p * r),
                             lam * T(r * r),        rng.uniform<T>(-s, s),
                             rng.uniform<T>(-s, s), rng.uniform<T>(-s, s) * s};
  return {q, ConicKind::parabola, parabola_pieces(coeffs(q), LD(100) * LD(s))};
}

/// (l0 . X + c0)(l1 . X + c1) = 0 with small integers (exact coefficients); kind decides the
/// relation of the factors.
template <class T>
TestConic<T> make_lines(Rng& rng, ConicKind kind, T s) {
  const auto rnd_l = [&] {
    V2 l{};
    while (l.x == 0 && l.y == 0) l = {LD(rng.uniform_int(-4, 4)), LD(rng.uniform_int(-4, 4))};
    return l;
  };
  const V2 l0 = rnd_l();
  const LD c0 = rng.uniform_int(-12, 12);
  V2 l1 = rnd_l();
  LD c1 = rng.uniform_int(-12, 12);
  if (kind == ConicKind::parallel_lines || kind == ConicKind::double_line) {
    const LD f = rng.uniform_int(0, 1) ? 1 : 2;
    l1 = f * l0;
    c1 = kind == ConicKind::double_line ? f * c0 : f * c0 + LD(rng.uniform_int(1, 9));
  } else {
    while (l0.x * l1.y - l0.y * l1.x == 0) l1 = rnd_l();
  }
  const QuadraticCurve2<T> q{T(l0.x * l1.x),           T(l0.x * l1.y + l0.y * l1.x), T(l0.y * l1.y),
                             T(l0.x * c1 + l1.x * c0), T(l0.y * c1 + l1.y * c0),     T(c0 * c1)};
  const LD reach = LD(1000) * LD(s);
  return {q, kind, {line_piece(l0, c0, reach), line_piece(l1, c1, reach)}, {{l0, c0}, {l1, c1}}};
}

template <class T>
TestConic<T> random_conic(Rng& rng, int cls, T s) {
  switch (cls) {
    case 0:
      return make_central(rng, s, true);
    case 1:
      return make_central(rng, s, false);
    case 2:
      return make_parabola(rng, s);
    case 3:
      return make_lines<T>(rng, ConicKind::intersecting_lines, s);
    case 4:
      return make_lines<T>(rng, ConicKind::parallel_lines, s);
    default:
      return make_lines<T>(rng, ConicKind::double_line, s);
  }
}

/// The pieces sampled once (n samples each), for the oracle.
std::vector<Sampled<2>> sample(const std::vector<Piece>& pieces, int n) {
  std::vector<Sampled<2>> out;
  for (const Piece& p : pieces) out.emplace_back(p.at, p.lo, p.hi, n);
  return out;
}

/// The distance from the linear component to the sampled pieces; with the pieces themselves, their
/// points on the component's line (wherever they are) are candidates too.
LD oracle(const LinLD<2>& l, const std::vector<Sampled<2>>& sampled,
          const std::vector<Piece>& pieces = {}) {
  LD best = std::numeric_limits<LD>::infinity();
  for (const auto& p : sampled)
    best = std::min(best, p.min_sqr([&](const V2& x) { return sqr_to_linear<2>(x, l); }));
  for (const Piece& p : pieces)
    if (p.meets)
      for (const LD u : p.meets(l.o, l.d))
        if (std::isfinite(u)) best = std::min(best, sqr_to_linear<2>(p.at(u), l));
  return std::sqrt(best);
}

/// |Q(x)| / |grad Q(x)|: the first-order distance of x from the conic.
template <class T>
LD off_conic(const QuadraticCurve2<T>& q, const Vec2<T>& x) {
  const Coeffs k = coeffs(q);
  const LD X = x.x, Y = x.y;
  const LD val = k.a * X * X + k.b * X * Y + k.c * Y * Y + k.d * X + k.e * Y + k.f;
  const LD gx = 2 * k.a * X + k.b * Y + k.d, gy = k.b * X + 2 * k.c * Y + k.e;
  const LD g = std::sqrt(gx * gx + gy * gy);
  return g > 0 ? std::fabs(val) / g : std::fabs(val);
}

/// Bound on the distance from the curve of a point x where compute precision C evaluates Q to
/// zero: Q(x) with its six terms (products of up to three factors) is rounded by at most about
/// 8 eps_C sum|terms|, and |Q| / |grad Q| converts that to a distance. Far out on a nearly
/// degenerate conic it is far above eps |x| (a parabola with linear term 0.0116 across its axis,
/// |grad Q| = 0.013 at its vertex 2500 out where sum|terms| = 7e7: 6e-7 in double, seed 34).
template <class T>
LD conic_rounding(const QuadraticCurve2<T>& q, const Vec2<T>& x) {
  if (!is_finite(x)) return 0;
  const Coeffs k = coeffs(q);
  const LD X = x.x, Y = x.y;
  const LD terms = std::fabs(k.a * X * X) + std::fabs(k.b * X * Y) + std::fabs(k.c * Y * Y) +
                   std::fabs(k.d * X) + std::fabs(k.e * Y) + std::fabs(k.f);
  const LD gx = 2 * k.a * X + k.b * Y + k.d, gy = k.b * X + 2 * k.c * Y + k.e;
  const LD g = std::sqrt(gx * gx + gy * gy);
  const LD e = LD(8) * LD(eps_v<compute_t<T>>) * terms;
  return g > 0 ? e / g : std::numeric_limits<LD>::infinity();
}

/// Exact distance from x to the nearest line of a pair.
LD on_lines(const std::vector<std::pair<V2, LD>>& lines, const V2& x) {
  LD best = std::numeric_limits<LD>::infinity();
  for (const auto& [l, c] : lines)
    best = std::min(best, std::fabs(dot(l, x) + c) / std::sqrt(sqr_length(l)));
  return best;
}

template <class T>
T dist_tol(T s) {
  return (std::is_same_v<T, float> ? T(2e-5) : T(1e-10)) * s;
}

// ---- curves ---------------------------------------------------------------------------------

/// A curve as the oracle sees it: homogeneous control points, degree, knots (Bézier: clamped).
template <int N>
struct CurveLD {
  int deg;
  std::vector<Vec<LD, N>> p;
  std::vector<LD> w, k;

  Vec<LD, N> at(LD t) const {
    const int n = static_cast<int>(p.size());
    t = std::clamp(t, k[static_cast<std::size_t>(deg)], k[static_cast<std::size_t>(n)]);
    int s = deg;
    while (s + 1 < n && !(t < k[static_cast<std::size_t>(s + 1)])) ++s;
    std::array<Vec<LD, N>, 16> a{};
    std::array<LD, 16> ww{};
    for (int j = 0; j <= deg; ++j) {
      const auto i = static_cast<std::size_t>(s - deg + j);
      ww[static_cast<std::size_t>(j)] = w[i];
      a[static_cast<std::size_t>(j)] = w[i] * p[i];
    }
    for (int r = 1; r <= deg; ++r)
      for (int j = deg; j >= r; --j) {
        const int i = s - deg + j;
        const LD lo = k[static_cast<std::size_t>(i)],
                 hi = k[static_cast<std::size_t>(i + deg + 1 - r)];
        const LD al = hi > lo ? (t - lo) / (hi - lo) : LD(0);
        const auto uj = static_cast<std::size_t>(j);
        a[uj] = (1 - al) * a[uj - 1] + al * a[uj];
        ww[uj] = (1 - al) * ww[uj - 1] + al * ww[uj];
      }
    return a[static_cast<std::size_t>(deg)] / ww[static_cast<std::size_t>(deg)];
  }
  LD lo() const { return k[static_cast<std::size_t>(deg)]; }
  LD hi() const { return k[p.size()]; }
};

template <class T, int N>
CurveLD<N> to_ld(const BezierCurve<T, N>& c) {
  CurveLD<N> o;
  o.deg = static_cast<int>(c.control.size()) - 1;
  for (const auto& q : c.control) o.p.push_back(vec_cast<LD>(q)), o.w.push_back(1);
  for (int i = 0; i <= o.deg; ++i) o.k.push_back(0);
  for (int i = 0; i <= o.deg; ++i) o.k.push_back(1);
  return o;
}
template <class T, int N>
CurveLD<N> to_ld(const BSplineCurve<T, N>& c) {
  CurveLD<N> o{c.degree, {}, {}, {}};
  for (const auto& q : c.control) o.p.push_back(vec_cast<LD>(q)), o.w.push_back(1);
  for (const T x : c.knots) o.k.push_back(x);
  return o;
}
template <class T, int N>
CurveLD<N> to_ld(const NurbsCurve<T, N>& c) {
  CurveLD<N> o{c.degree, {}, {}, {}};
  for (const auto& q : c.control) o.p.push_back(vec_cast<LD>(q));
  for (const T x : c.weights) o.w.push_back(x);
  for (const T x : c.knots) o.k.push_back(x);
  return o;
}

template <int N>
Sampled<N> sample(const CurveLD<N>& c, int n) {
  // The same number of samples in every knot span: a span can be short in parameter and long on
  // the curve (a degree-1 NURBS edge over [0.0800, 0.0818] at seed 26), which samples uniform in
  // the parameter would step over. u in [0, spans] maps linearly onto span floor(u).
  std::vector<LD> b;
  for (const LD x : c.k)
    if (x >= c.lo() && x <= c.hi() && (b.empty() || x > b.back())) b.push_back(x);
  const int spans = static_cast<int>(b.size()) - 1;
  return Sampled<N>(
      [c, b, spans](LD u) {
        const int i = std::clamp(static_cast<int>(std::floor(u)), 0, spans - 1);
        const auto ui = static_cast<std::size_t>(i);
        return c.at(b[ui] + (u - LD(i)) * (b[ui + 1] - b[ui]));
      },
      LD(0), LD(spans), n);
}

template <int N>
LD curve_oracle(const LinLD<N>& l, const Sampled<N>& c) {
  return std::sqrt(c.min_sqr([&](const Vec<LD, N>& x) { return sqr_to_linear<N>(x, l); }));
}

template <class T, int N>
BezierCurve<T, N> random_bezier(Rng& rng, T s) {
  BezierCurve<T, N> c;
  const int n = rng.uniform_int(2, 6);
  for (int i = 0; i < n; ++i) c.control.push_back(rng.vec<T, N>(-s, s));
  return c;
}

/// Clamped knots on [0, 2] with an occasional double interior knot (a possible corner).
template <class T>
std::vector<T> random_clamped_knots(Rng& rng, int n, int d) {
  std::vector<T> k(static_cast<std::size_t>(d + 1), T(0));
  std::vector<T> inner;
  for (int i = 0; i < n - d - 1; ++i) inner.push_back(rng.uniform<T>(T(0.05), T(1.95)));
  std::sort(inner.begin(), inner.end());
  if (inner.size() >= 2 && d >= 2 && rng.uniform_int(0, 3) == 0) inner[1] = inner[0];
  for (const T x : inner) k.push_back(x);
  for (int i = 0; i <= d; ++i) k.push_back(T(2));
  return k;
}

template <class T, int N>
BSplineCurve<T, N> random_bspline(Rng& rng, T s) {
  const int d = rng.uniform_int(1, 4), n = d + 1 + rng.uniform_int(0, 4);
  BSplineCurve<T, N> c{d, {}, random_clamped_knots<T>(rng, n, d)};
  for (int i = 0; i < n; ++i) c.control.push_back(rng.vec<T, N>(-s, s));
  return c;
}

template <class T, int N>
NurbsCurve<T, N> random_nurbs(Rng& rng, T s) {
  const int d = rng.uniform_int(1, 3), n = d + 1 + rng.uniform_int(0, 3);
  NurbsCurve<T, N> c{d, {}, {}, random_clamped_knots<T>(rng, n, d)};
  for (int i = 0; i < n; ++i) {
    c.control.push_back(rng.vec<T, N>(-s, s));
    c.weights.push_back(rng.uniform<T>(T(0.3), T(3)));
  }
  return c;
}

struct ErrStats {
  LD max_rel = 0;
  int cases = 0;
  std::string worst;
  void add(LD err, LD scale, const std::string& what = {}) {
    if (err / scale > max_rel) max_rel = err / scale, worst = what;
    ++cases;
  }
};

/// Checks one linear-curve result against the oracle and for realisability.
template <class T, int N, class Lin, class Curve>
void check_curve_case(const Lin& lin, const Curve& c, const Sampled<N>& sc, T s, ErrStats& st) {
  const auto r = distance(lin, c);
  const LinLD<N> ll = to_ld(lin);
  const CurveLD<N> cl = to_ld(c);
  const LD want = curve_oracle<N>(ll, sc);
  const LD tol = dist_tol<T>(s);
  // The parameters are returned in T, so the pair is realised at a representable curve parameter:
  // between neighbouring T values of param_b the curve point jumps by `step_b` (|C'| ulp, 2.1e-3 in
  // float for a 10.7-long degree-1 edge over a 3e-4-long knot span, seed 32), and the best
  // representable pair can be up to step_b / 2 farther apart than the continuous minimum (first
  // order: a crossing or minimum between two representable parameters), plus |d| ulp(param_a) / 2
  // for the linear point. That covers only the rounding: the library must have found the minimum,
  // so the continuous distance over param_b's T-neighbourhood matches the oracle to tol.
  const T pb = r.param_b, inf_t = std::numeric_limits<T>::infinity();
  const LD lo_b = std::max(LD(std::nextafter(pb, -inf_t)), cl.lo());
  const LD hi_b = std::min(LD(std::nextafter(pb, inf_t)), cl.hi());
  const auto to_lin = [&](LD u) { return sqr_to_linear<N>(cl.at(u), ll); };
  const LD step_b = std::max(std::sqrt(sqr_length(cl.at(hi_b) - cl.at(LD(pb)))),
                             std::sqrt(sqr_length(cl.at(LD(pb)) - cl.at(lo_b))));
  const LD step_a = std::sqrt(sqr_length(ll.d)) *
                    LD(std::nextafter(std::fabs(r.param_a), inf_t) - std::fabs(r.param_a));
  const LD local = std::sqrt(std::min(
      {to_lin(lo_b), to_lin(LD(pb)), to_lin(hi_b), golden_section_min(to_lin, lo_b, hi_b, 60)}));
  EXPECT_TRUE(near_ld(local, want, tol)) << "continuous distance around param_b";
  EXPECT_TRUE(near_ld(LD(r.distance), want, tol + (step_b + step_a) / 2));
  st.add(std::fabs(LD(r.distance) - want), LD(s));
  // Realisable: closest[0] = point_at(lin, param_a), closest[1] on the curve at param_b.
  EXPECT_TRUE(locus_test::vec_near(r.closest[0], point_at(lin, r.param_a), T(0)));
  EXPECT_LE(std::sqrt(sqr_length(vec_cast<LD>(r.closest[1]) - cl.at(LD(r.param_b)))), tol);
  EXPECT_NEAR(length(r.closest[0] - r.closest[1]), r.distance, T(8) * eps_v<T> * s);
  const auto sw = distance(c, lin);
  EXPECT_EQ(sw.distance, r.distance);
  EXPECT_EQ(sw.closest[0], r.closest[1]);
  EXPECT_EQ(sw.param_a, r.param_b);
}

}  // namespace

// ---- conics ---------------------------------------------------------------------------------

TYPED_TEST(LinearCurveTest, ConicAgainstOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const T S = 8;
  ErrStats st;
  int skipped = 0, total = 0;
  for (int i = 0; i < 96 / kCaseScale; ++i) {
    const int cls = i % 6;
    const TestConic<T> tc = random_conic<T>(rng, cls, S);
    ++total;
    if (classify_conic(tc.q) != tc.kind) {
      ++skipped;  // rounding of the expansion changed the class (rare: k near 0)
      continue;
    }
    Vec2<T> o = rng.vec<T, 2>(-S, S);
    const Vec2<T> d = rng.unit<T, 2>() * rng.uniform<T>(T(0.3), T(6));
    if (i % 4 == 1) {
      // Through a point of the curve: distance 0.
      const Piece& p = tc.pieces[static_cast<std::size_t>(
          rng.uniform_int(0, static_cast<int>(tc.pieces.size()) - 1))];
      const LD u = p.lo + (p.hi - p.lo) * LD(rng.uniform<T>(T(0.45), T(0.55)));
      o = vec_cast<T>(p.at(u)) - rng.uniform<T>(T(0.1), T(0.9)) * d;
    }
    SCOPED_TRACE("case " + std::to_string(i) + " " + std::string(to_string(tc.kind)));
    const Line<T, 2> line{o, d};
    const Ray<T, 2> ray{o, d};
    const Segment<T, 2> seg{o, o + d};
    const auto rl = distance(line, tc.q);
    const auto rr = distance(ray, tc.q);
    const auto rs = distance(seg, tc.q);
    // Far-away closest points (a line meeting a hyperbola's branch or a line pair far out) carry
    // the rounding of their coordinates: a few ulps of their magnitude on top.
    LD big = 0;
    for (const auto* r : {&rl, &rr, &rs})
      big = std::max({big, LD(max_abs(r->closest[0])), LD(max_abs(r->closest[1]))});
    const LD tol = dist_tol<T>(S) + LD(8) * LD(eps_v<T>) * big;
    const std::vector<Sampled<2>> pieces = sample(tc.pieces, 6000);
    const LD wl = oracle(to_ld(line), pieces, tc.pieces);
    const LD wr = oracle(to_ld(ray), pieces, tc.pieces);
    const LD ws = oracle(to_ld(seg), pieces, tc.pieces);
    const bool lines = tc.kind != ConicKind::ellipse && tc.kind != ConicKind::hyperbola &&
                       tc.kind != ConicKind::parabola;
    // A conic point is only located to conic_rounding() by compute precision (the line pairs are
    // factored into lines by the library and are not).
    const auto tol_of = [&](const auto& r) {
      return lines ? tol : tol + conic_rounding(tc.q, r.closest[1]);
    };
    EXPECT_TRUE(near_ld(LD(rl.distance), wl, tol_of(rl)));
    EXPECT_TRUE(near_ld(LD(rr.distance), wr, tol_of(rr)));
    EXPECT_TRUE(near_ld(LD(rs.distance), ws, tol_of(rs)));
    const auto what = [&](const auto& r) {
      return std::string(to_string(tc.kind)) + ", closest points up to " +
             std::to_string(std::max(max_abs(r.closest[0]), max_abs(r.closest[1])));
    };
    st.add(std::fabs(LD(rl.distance) - wl), LD(S), "line, " + what(rl));
    st.add(std::fabs(LD(rr.distance) - wr), LD(S), "ray, " + what(rr));
    st.add(std::fabs(LD(rs.distance) - ws), LD(S), "segment, " + what(rs));
    if (i % 4 == 1) {
      EXPECT_LE(rs.distance, T(tol));
    }
    for (const auto* r : {&rl, &rr, &rs}) {
      ASSERT_TRUE(is_finite(r->closest[1]));
      // On the curve: first-order |Q| / |grad Q| (the gradient vanishes on a double line, so line
      // pairs are measured against their lines directly, unbounded: a point on a line pair can
      // be far beyond the sampled reach, 1.7e5 out at seed 33).
      EXPECT_LE(
          lines ? on_lines(tc.lines, vec_cast<LD>(r->closest[1])) : off_conic(tc.q, r->closest[1]),
          tol_of(*r));
      EXPECT_NEAR(length(r->closest[0] - r->closest[1]), r->distance, T(8) * eps_v<T> * S);
    }
    EXPECT_TRUE(locus_test::vec_near(rs.closest[0], point_at(seg, rs.param_a), T(0)));
    EXPECT_GE(rs.param_a, T(0));
    EXPECT_LE(rs.param_a, T(1));
    EXPECT_GE(rr.param_a, T(0));
    const auto sw = distance(tc.q, ray);
    EXPECT_EQ(sw.distance, rr.distance);
    EXPECT_EQ(sw.closest[0], rr.closest[1]);
    EXPECT_EQ(sw.param_b, rr.param_a);
  }
  EXPECT_LE(skipped * 20, total);
  std::printf("[ conic  ] %s: %d cases, max |distance - oracle| / scale = %.3g (%s)\n",
              std::is_same_v<T, float> ? "float" : "double", st.cases,
              static_cast<double>(st.max_rel), st.worst.c_str());
}

// Figure 6.23 with a conic: a segment missing an ellipse; the connecting segment is perpendicular
// to the segment and normal to the curve (parallel to grad Q).
TYPED_TEST(LinearCurveTest, Figure6_23Conic) {
  using T = TypeParam;
  // (x - 1)^2 / 16 + (y + 1)^2 / 4 = 1  ->  x^2 + 4 y^2 - 2x + 8y - 11 = 0.
  const QuadraticCurve2<T> q{1, 0, 4, -2, 8, -11};
  const Segment<T, 2> seg{{T(-6), T(6)}, {T(6), T(2)}};
  const auto r = distance(seg, q);
  ASSERT_TRUE(r.param_a > T(0) && r.param_a < T(1));
  const Vec2<T> conn = r.closest[0] - r.closest[1];
  const Vec2<T> dir = seg.p1 - seg.p0;
  const Vec2<T> x = r.closest[1];
  const Vec2<T> grad{T(2) * x.x - T(2), T(8) * x.y + T(8)};
  const T tol = std::is_same_v<T, float> ? T(1e-4) : T(1e-10);
  EXPECT_NEAR(dot(conn, dir) / (length(conn) * length(dir)), T(0), tol);
  EXPECT_NEAR(perp_dot(conn, grad) / (length(conn) * length(grad)), T(0), tol);
  EXPECT_TRUE(near_ld(LD(r.distance),
                      oracle(to_ld(seg), sample(central_pieces(coeffs(q), 100), 20000)),
                      dist_tol<T>(T(8))));
  // The same ellipse as Ellipse2 through line_ellipse.hpp gives the same distance.
  const Ellipse2<T> e{{T(1), T(-1)}, {{1, 0}, {0, 1}}, {T(4), T(2)}};
  EXPECT_NEAR(distance(seg, e).distance, r.distance, T(64) * eps_v<T> * T(8));
}

TYPED_TEST(LinearCurveTest, ConicSpecialCases) {
  using T = TypeParam;
  const T e = T(64) * eps_v<T> * T(10);
  // Parabola y = x^2: a line parallel to the axis crosses it once, at distance 0, unique.
  const QuadraticCurve2<T> par{1, 0, 0, 0, -1, 0};
  const auto vert = distance(Line<T, 2>{{T(2), T(-3)}, {0, T(2)}}, par);
  EXPECT_NEAR(vert.distance, T(0), e);
  EXPECT_TRUE(locus_test::vec_near(vert.closest[1], Vec2<T>{T(2), T(4)}, e));
  EXPECT_TRUE(vert.unique);
  // A line below the parabola with slope 2: tangent point x = 1 (slope 2x), distance from
  // y = 2x - 3 to (1, 1): |2 - 1 - 3| / sqrt(5).
  const auto below = distance(Line<T, 2>{{T(0), T(-3)}, {T(1), T(2)}}, par);
  EXPECT_NEAR(below.distance, T(2) / std::sqrt(T(5)), e);
  EXPECT_TRUE(locus_test::vec_near(below.closest[1], Vec2<T>{T(1), T(1)}, T(16) * e));
  // Crossing twice: distance 0, finitely many pairs -> unique.
  const auto twice = distance(Line<T, 2>{{T(-5), T(1)}, {T(1), 0}}, par);
  EXPECT_NEAR(twice.distance, T(0), e);
  EXPECT_TRUE(twice.unique);
  // Parallel lines y^2 = 1 and a horizontal segment above: distance 2, infinitely many pairs.
  const QuadraticCurve2<T> pl{0, 0, 1, 0, 0, -1};
  const auto above = distance(Segment<T, 2>{{T(-1), T(3)}, {T(4), T(3)}}, pl);
  EXPECT_NEAR(above.distance, T(2), e);
  EXPECT_FALSE(above.unique);
  EXPECT_NEAR(above.closest[1].y, T(1), e);
  // A slanted segment between them: the nearer end.
  const auto slant = distance(Segment<T, 2>{{T(0), T(0.5)}, {T(3), T(-0.25)}}, pl);
  EXPECT_NEAR(slant.distance, T(0.5), e);
  EXPECT_EQ(slant.param_a, T(0));
  EXPECT_TRUE(slant.unique);
  // Double line (x - y)^2 = 0 and a ray starting off it, pointing away.
  const QuadraticCurve2<T> dl{1, -2, 1, 0, 0, 0};
  const auto ray_dl = distance(Ray<T, 2>{{T(2), T(0)}, {T(1), T(-1)}}, dl);
  EXPECT_NEAR(ray_dl.distance, std::sqrt(T(2)), e);
  EXPECT_EQ(ray_dl.param_a, T(0));
  // Intersecting lines xy = 0 and a segment in the first quadrant: nearest end to an axis.
  const QuadraticCurve2<T> il{0, 1, 0, 0, 0, 0};
  const auto quad = distance(Segment<T, 2>{{T(1), T(3)}, {T(4), T(2)}}, il);
  EXPECT_NEAR(quad.distance, T(1), e);
  EXPECT_TRUE(locus_test::vec_near(quad.closest[1], Vec2<T>{0, T(3)}, e));
  // A single line (a = b = c = 0): 2x - 4 = 0, a crossing ray.
  const auto lin1 =
      distance(Ray<T, 2>{{T(0), T(1)}, {T(1), T(1)}}, QuadraticCurve2<T>{0, 0, 0, 2, 0, -4});
  EXPECT_NEAR(lin1.distance, T(0), e);
  EXPECT_NEAR(lin1.param_a, T(2), e);
  // A point conic (x - 1)^2 + (y - 2)^2 = 0.
  const auto pt =
      distance(Line<T, 2>{{T(0), T(0)}, {T(1), 0}}, QuadraticCurve2<T>{1, 0, 1, -2, -4, 5});
  EXPECT_NEAR(pt.distance, T(2), e);
  EXPECT_TRUE(locus_test::vec_near(pt.closest[1], Vec2<T>{1, 2}, e));
  // Hyperbola xy = 1: the line on its asymptote y = 0 approaches it without reaching it.
  const QuadraticCurve2<T> hyp{0, 1, 0, 0, 0, -1};
  const auto asym = distance(Line<T, 2>{{T(-1), T(0)}, {T(2), 0}}, hyp);
  EXPECT_EQ(asym.distance, T(0));
  EXPECT_FALSE(asym.unique);
  EXPECT_TRUE(std::isinf(asym.param_a));
  EXPECT_TRUE(std::isnan(asym.closest[0].x) && std::isnan(asym.closest[1].x));
  // x^2 - y^2 = 1 and the ray y = x + 1, x >= 0, parallel to the asymptote y = x on the side the
  // right branch approaches from: the infimum 1/sqrt(2) is not attained.
  const QuadraticCurve2<T> hyp2{1, 0, -1, 0, 0, -1};
  const auto near_asym = distance(Ray<T, 2>{{T(0), T(1)}, {T(1), T(1)}}, hyp2);
  EXPECT_NEAR(near_asym.distance, T(1) / std::sqrt(T(2)), e);
  EXPECT_FALSE(near_asym.unique);
  EXPECT_TRUE(std::isinf(near_asym.param_a));
  // The same ray reversed (pointing down-left) is closest at its origin... it crosses the left
  // branch? y = x + 1 meets x^2 - y^2 = 1 at x = -1: yes, distance 0.
  const auto back = distance(Ray<T, 2>{{T(0), T(1)}, {T(-1), T(-1)}}, hyp2);
  EXPECT_NEAR(back.distance, T(0), e);
  EXPECT_NEAR(back.param_a, T(1), e);
  // The line parallel to the asymptote crosses a branch once: distance 0.
  EXPECT_NEAR(distance(Line<T, 2>{{T(0), T(1)}, {T(1), T(1)}}, hyp2).distance, T(0), e);
  // A segment along the asymptote: attained at its end nearest the approach (x = 5 end).
  const auto sg = distance(Segment<T, 2>{{T(1), T(1)}, {T(5), T(5)}}, hyp2);
  EXPECT_TRUE(std::isfinite(sg.distance));
  EXPECT_EQ(sg.param_a, T(1));
  EXPECT_NEAR(sg.distance,
              T(oracle(to_ld(Segment<T, 2>{{T(1), T(1)}, {T(5), T(5)}}),
                       sample(central_pieces(coeffs(hyp2), 1000), 20000))),
              T(16) * e);
  // The circle x^2 + y^2 = 4: a zero-length segment at the centre is equidistant from the whole
  // circle (the point-conic query), a segment from the centre is closest at its far end.
  const QuadraticCurve2<T> circ{1, 0, 1, 0, 0, -4};
  const auto centre = distance(Segment<T, 2>{{0, 0}, {0, 0}}, circ);
  EXPECT_NEAR(centre.distance, T(2), e);
  EXPECT_FALSE(centre.unique);
  const auto inside = distance(Segment<T, 2>{{0, 0}, {0, T(0.5)}}, circ);
  EXPECT_NEAR(inside.distance, T(1.5), e);
  EXPECT_EQ(inside.param_a, T(1));
  EXPECT_TRUE(inside.unique);
  // Zero-length segment: the point query.
  const Vec2<T> p{T(3), T(-1)};
  const auto zp = distance(Segment<T, 2>{p, p}, par);
  EXPECT_EQ(zp.distance, distance(p, par).distance);
  EXPECT_EQ(zp.param_a, T(0));
  // The empty conic x^2 + y^2 + 1 = 0 and imaginary parallel lines y^2 + 1 = 0: +infinity.
  for (const QuadraticCurve2<T>& empty :
       {QuadraticCurve2<T>{1, 0, 1, 0, 0, 1}, QuadraticCurve2<T>{0, 0, 1, 0, 0, 1}}) {
    const auto em = distance(Line<T, 2>{{0, 0}, {1, 0}}, empty);
    EXPECT_TRUE(std::isinf(em.distance));
    EXPECT_FALSE(em.unique);
    EXPECT_TRUE(std::isnan(em.closest[1].x));
  }
  // The plane (all zero): distance 0 everywhere.
  const auto pl0 = distance(Ray<T, 2>{{T(1), T(2)}, {1, 0}}, QuadraticCurve2<T>{0, 0, 0, 0, 0, 0});
  EXPECT_EQ(pl0.distance, T(0));
  EXPECT_FALSE(pl0.unique);
}

TYPED_TEST(LinearCurveTest, ConicNonFinite) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const QuadraticCurve2<T> q{1, 0, 1, 0, 0, -1};
  EXPECT_TRUE(dist::is_nan_result(distance(Line<T, 2>{{nan, 0}, {1, 0}}, q)));
  EXPECT_TRUE(dist::is_nan_result(distance(Ray<T, 2>{{0, 0}, {inf, 0}}, q)));
  EXPECT_TRUE(dist::is_nan_result(distance(Segment<T, 2>{{0, 0}, {0, nan}}, q)));
  EXPECT_TRUE(dist::is_nan_result(
      distance(Line<T, 2>{{0, 5}, {1, 0}}, QuadraticCurve2<T>{1, 0, 1, 0, nan, -1})));
  EXPECT_TRUE(dist::is_nan_result(
      distance(QuadraticCurve2<T>{inf, 0, 1, 0, 0, -1}, Segment<T, 2>{{0, 0}, {1, 0}})));
}

// ---- polynomial curves ----------------------------------------------------------------------

TYPED_TEST(LinearCurveTest, CurvesAgainstOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const T S = 8;
  ErrStats st2, st3;
  for (int i = 0; i < 60 / kCaseScale; ++i) {
    SCOPED_TRACE("case " + std::to_string(i));
    const auto lin2 = [&](auto&& check) {
      Vec2<T> o = rng.vec<T, 2>(-S, S);
      const Vec2<T> d = rng.unit<T, 2>() * rng.uniform<T>(T(0.3), T(8));
      check(Line<T, 2>{o, d});
      check(Ray<T, 2>{o, d});
      check(Segment<T, 2>{o, o + d});
    };
    const auto lin3 = [&](auto&& check) {
      const Vec3<T> o = rng.vec<T, 3>(-S, S);
      const Vec3<T> d = rng.unit<T, 3>() * rng.uniform<T>(T(0.3), T(8));
      check(Line<T, 3>{o, d});
      check(Ray<T, 3>{o, d});
      check(Segment<T, 3>{o, o + d});
    };
    switch (i % 3) {
      case 0: {
        const auto c2 = random_bezier<T, 2>(rng, S);
        const Sampled<2> sc2 = sample(to_ld(c2), 3000);
        lin2([&](const auto& l) { check_curve_case<T, 2>(l, c2, sc2, S, st2); });
        const auto c3 = random_bezier<T, 3>(rng, S);
        const Sampled<3> sc3 = sample(to_ld(c3), 3000);
        lin3([&](const auto& l) { check_curve_case<T, 3>(l, c3, sc3, S, st3); });
        break;
      }
      case 1: {
        const auto c2 = random_bspline<T, 2>(rng, S);
        const Sampled<2> sc2 = sample(to_ld(c2), 3000);
        lin2([&](const auto& l) { check_curve_case<T, 2>(l, c2, sc2, S, st2); });
        const auto c3 = random_bspline<T, 3>(rng, S);
        const Sampled<3> sc3 = sample(to_ld(c3), 3000);
        lin3([&](const auto& l) { check_curve_case<T, 3>(l, c3, sc3, S, st3); });
        break;
      }
      default: {
        const auto c2 = random_nurbs<T, 2>(rng, S);
        const Sampled<2> sc2 = sample(to_ld(c2), 3000);
        lin2([&](const auto& l) { check_curve_case<T, 2>(l, c2, sc2, S, st2); });
        const auto c3 = random_nurbs<T, 3>(rng, S);
        const Sampled<3> sc3 = sample(to_ld(c3), 3000);
        lin3([&](const auto& l) { check_curve_case<T, 3>(l, c3, sc3, S, st3); });
        break;
      }
    }
  }
  std::printf(
      "[ curves ] %s: 2D %d cases, 3D %d cases, max |distance - oracle| / scale = %.3g, %.3g\n",
      std::is_same_v<T, float> ? "float" : "double", st2.cases, st3.cases,
      static_cast<double>(st2.max_rel), static_cast<double>(st3.max_rel));
}

TYPED_TEST(LinearCurveTest, CurvesIntersecting) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const T S = 8;
  for (int i = 0; i < 60 / kCaseScale; ++i) {
    SCOPED_TRACE("case " + std::to_string(i));
    const auto c = random_nurbs<T, 2>(rng, S);
    const auto dom = domain(c);
    const T s0 = dom.min + rng.uniform<T>(T(0.1), T(0.9)) * (dom.max - dom.min);
    const Vec2<T> x = point_at(c, s0);
    const Vec2<T> d = rng.unit<T, 2>() * rng.uniform<T>(T(0.5), T(4));
    const Segment<T, 2> seg{x - T(0.4) * d, x + T(0.6) * d};
    const auto r = distance(seg, c);
    EXPECT_LE(r.distance, dist_tol<T>(S));
    const auto rl = distance(Line<T, 2>{x, d}, c);
    EXPECT_LE(rl.distance, dist_tol<T>(S));
  }
}

// Figure 6.23: a segment and a cubic Bézier curve whose closest points are interior to both: the
// connecting segment is perpendicular to the segment and to the curve's tangent.
TYPED_TEST(LinearCurveTest, Figure6_23Curve) {
  using T = TypeParam;
  const BezierCurve<T, 2> c{{{T(0), T(0)}, {T(1), T(3)}, {T(3), T(3)}, {T(4), T(0)}}};
  const Segment<T, 2> seg{{T(-1), T(5)}, {T(5), T(4)}};
  const auto r = distance(seg, c);
  ASSERT_TRUE(r.param_a > T(0) && r.param_a < T(1));
  ASSERT_TRUE(r.param_b > T(0) && r.param_b < T(1));
  const CurveLD<2> cl = to_ld(c);
  const LD h = 1e-6L, sb = LD(r.param_b);
  const Vec2<LD> tangent = (cl.at(sb + h) - cl.at(sb - h)) / (2 * h);
  const Vec2<LD> conn = vec_cast<LD>(r.closest[0]) - vec_cast<LD>(r.closest[1]);
  const Vec2<LD> dir = vec_cast<LD>(seg.p1 - seg.p0);
  const LD tol = std::is_same_v<T, float> ? 1e-4L : 1e-8L;
  EXPECT_NEAR(static_cast<double>(dot(conn, dir) / std::sqrt(sqr_length(conn) * sqr_length(dir))),
              0.0, static_cast<double>(tol));
  EXPECT_NEAR(
      static_cast<double>(dot(conn, tangent) / std::sqrt(sqr_length(conn) * sqr_length(tangent))),
      0.0, static_cast<double>(tol));
  EXPECT_TRUE(
      near_ld(LD(r.distance), curve_oracle<2>(to_ld(seg), sample(cl, 3000)), dist_tol<T>(T(8))));
  EXPECT_TRUE(r.unique);
}

TYPED_TEST(LinearCurveTest, CurveSpecialCases) {
  using T = TypeParam;
  const T e = T(64) * eps_v<T> * T(10);
  // A straight Bézier span parallel to the line: constant distance, infinitely many pairs.
  const BezierCurve<T, 2> flat{{{T(0), T(1)}, {T(1), T(1)}, {T(3), T(1)}}};
  const auto par = distance(Line<T, 2>{{T(-2), T(3)}, {T(1), 0}}, flat);
  EXPECT_NEAR(par.distance, T(2), e);
  EXPECT_FALSE(par.unique);
  // ... a segment overlapping it in projection: still infinitely many; beyond its end: unique.
  EXPECT_FALSE(distance(Segment<T, 2>{{T(2), T(3)}, {T(7), T(3)}}, flat).unique);
  const auto beyond = distance(Segment<T, 2>{{T(4), T(3)}, {T(7), T(3)}}, flat);
  EXPECT_NEAR(beyond.distance, std::sqrt(T(5)), e);
  EXPECT_TRUE(beyond.unique);
  EXPECT_EQ(beyond.param_a, T(0));
  EXPECT_EQ(beyond.param_b, T(1));
  // A curve lying on the line: distance 0 everywhere on it.
  const auto on = distance(Line<T, 2>{{T(-2), T(1)}, {T(3), 0}}, flat);
  EXPECT_NEAR(on.distance, T(0), e);
  EXPECT_FALSE(on.unique);
  // An arch symmetric about x = 0 above a horizontal line: two equally close ends (finitely many
  // pairs: unique); a line crossing it twice: distance 0, unique.
  const BezierCurve<T, 2> arch{{{T(-1), T(0)}, {T(0), T(2)}, {T(1), T(0)}}};
  const auto two = distance(Line<T, 2>{{T(0), T(-1)}, {T(1), 0}}, arch);
  EXPECT_NEAR(two.distance, T(1), e);
  EXPECT_TRUE(two.unique);
  const auto cross2 = distance(Line<T, 2>{{T(0), T(0.5)}, {T(1), 0}}, arch);
  EXPECT_NEAR(cross2.distance, T(0), e);
  EXPECT_TRUE(cross2.unique);
  // Tangent line at the apex (y = 1): distance 0 at s = 1/2 (a double root).
  const auto tan = distance(Ray<T, 2>{{T(-3), T(1)}, {T(1), 0}}, arch);
  EXPECT_NEAR(tan.distance, T(0), e);
  EXPECT_NEAR(tan.param_b, T(0.5), std::sqrt(e));
  // 3D: a NURBS quarter circle of radius 2 around the z axis at height 1; the z axis as a line is
  // equidistant from every point of it.
  const T w = std::sqrt(T(0.5));
  const NurbsCurve<T, 3> arc{2,
                             {{T(2), T(0), T(1)}, {T(2), T(2), T(1)}, {T(0), T(2), T(1)}},
                             {T(1), w, T(1)},
                             {T(0), T(0), T(0), T(1), T(1), T(1)}};
  const auto axis = distance(Line<T, 3>{{T(0), T(0), T(-4)}, {T(0), T(0), T(2)}}, arc);
  EXPECT_NEAR(axis.distance, T(2), T(16) * e);
  EXPECT_FALSE(axis.unique);
  EXPECT_NEAR(axis.closest[0].z, T(1), T(16) * e);
  // A segment of the axis below the arc: its top end, still every arc point.
  const auto low = distance(Segment<T, 3>{{T(0), T(0), T(-4)}, {T(0), T(0), T(-1)}}, arc);
  EXPECT_NEAR(low.distance, std::sqrt(T(8)), T(16) * e);
  EXPECT_FALSE(low.unique);
  EXPECT_EQ(low.param_a, T(1));
  // A 3D line through a point of the arc: distance 0.
  const Vec3<T> on_arc = point_at(arc, T(0.3));
  const auto hit =
      distance(Line<T, 3>{on_arc - Vec3<T>{T(1), T(2), T(3)}, {T(1), T(2), T(3)}}, arc);
  EXPECT_NEAR(hit.distance, T(0), T(16) * e);
  // Degree 0 B-spline: piecewise constant, the nearest control point.
  const BSplineCurve<T, 2> steps{0, {{T(0), T(5)}, {T(3), T(1)}}, {T(0), T(1), T(2)}};
  EXPECT_NEAR(distance(Line<T, 2>{{T(0), T(0)}, {T(1), 0}}, steps).distance, T(1), e);
  // Zero-length segment: the point query.
  const Vec2<T> p{T(0.3), T(4)};
  const auto zp = distance(Segment<T, 2>{p, p}, arch);
  const auto pc = distance(p, arch);
  EXPECT_EQ(zp.distance, pc.distance);
  EXPECT_EQ(zp.param_b, pc.param_b);
  EXPECT_EQ(zp.param_a, T(0));
}

// LOCUS_TEST_SEED=32, CurvesAgainstOracle case 31: a line crossing a degree-1 B-spline edge 10.7
// long over the knot span [0.79900, 0.79930]. Adjacent float parameters there are 2.1e-3 apart on
// the curve, so in float the crossing is not representable; the result must be the best
// representable curve parameter paired with its projection (the linear parameter of the
// unrounded crossing was returned before: 9.7e-4 apart instead of 8.9e-4).
TYPED_TEST(LinearCurveTest, ShortKnotSpanCrossing) {
  using T = TypeParam;
  const BSplineCurve<T, 2> c{1,
                             {{T(-0x1.3087e6p+0), T(0x1.74283p-2)},
                              {T(-0x1.c9148p+2), T(-0x1.94fa2p+2)},
                              {T(0x1.c36b64p+1), T(-0x1.c708acp+2)},
                              {T(0x1.64423ep-1), T(0x1.a567fap+2)}},
                             {T(0), T(0), T(0x1.9916bap-1), T(0x1.993ecp-1), T(2), T(2)}};
  const Line<T, 2> line{{T(0x1.bf1322p+1), T(-0x1.e5d4bap+2)},
                        {T(-0x1.11eb68p+1), T(0x1.7f9042p+2)}};
  const auto r = distance(line, c);
  const CurveLD<2> cl = to_ld(c);
  const LinLD<2> ll = to_ld(line);
  // The exact distance to the line of the curve points at the T parameters around param_b.
  LD best = std::numeric_limits<LD>::infinity();
  T u = r.param_b;
  for (int k = 0; k < 8; ++k) u = std::nextafter(u, T(0));
  for (int k = 0; k < 17; ++k, u = std::nextafter(u, T(2)))
    best = std::min(best, std::sqrt(sqr_to_linear<2>(cl.at(LD(u)), ll)));
  EXPECT_LE(LD(r.distance), best + LD(8) * LD(eps_v<T>) * 8);
  EXPECT_LE(r.distance, (std::is_same_v<T, float> ? T(9e-4) : T(1e-12)));
  EXPECT_GT(r.param_b, T(0x1.9916bap-1));
  EXPECT_LT(r.param_b, T(0x1.993ecp-1));
  EXPECT_NEAR(length(r.closest[0] - r.closest[1]), r.distance, T(8) * eps_v<T> * T(8));
  EXPECT_TRUE(locus_test::vec_near(r.closest[1], point_at(c, r.param_b), T(0)));
}

TYPED_TEST(LinearCurveTest, CurveHarness) {
  using T = TypeParam;
  const T S = 10;
  dist::Options<T> opt;
  opt.cases = 40 / kCaseScale;
  opt.check_agreement = false;  // curves are not convex: the oracle above checks agreement
  dist::check_pairs<T, 2, Segment<T, 2>, BezierCurve<T, 2>>(
      [&](Rng& rng) {
        return std::pair{Segment<T, 2>{rng.vec<T, 2>(-S, S), rng.vec<T, 2>(-S, S)},
                         random_bezier<T, 2>(rng, S)};
      },
      opt);
  dist::check_pairs<T, 3, Ray<T, 3>, NurbsCurve<T, 3>>(
      [&](Rng& rng) {
        return std::pair{Ray<T, 3>{rng.vec<T, 3>(-S, S), rng.unit<T, 3>()},
                         random_nurbs<T, 3>(rng, S)};
      },
      opt);
}

TYPED_TEST(LinearCurveTest, CurveNonFinite) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const BezierCurve<T, 2> c{{{T(0), T(0)}, {T(1), T(1)}}};
  EXPECT_TRUE(dist::is_nan_result(distance(Line<T, 2>{{nan, 0}, {1, 0}}, c)));
  EXPECT_TRUE(dist::is_nan_result(distance(Ray<T, 2>{{0, 0}, {inf, 0}}, c)));
  EXPECT_TRUE(dist::is_nan_result(distance(Segment<T, 2>{{0, 0}, {1, 0}}, BezierCurve<T, 2>{})));
  EXPECT_TRUE(dist::is_nan_result(
      distance(Segment<T, 2>{{0, 0}, {1, 0}}, BezierCurve<T, 2>{{{T(0), nan}, {T(1), T(1)}}})));
  const BSplineCurve<T, 3> bad{2, {{0, 0, 0}, {1, 1, 1}}, {0, 0, 0, 1, 1}};  // degree >= n
  EXPECT_TRUE(dist::is_nan_result(distance(Line<T, 3>{{0, 0, 0}, {1, 0, 0}}, bad)));
  const NurbsCurve<T, 2> negw{1, {{0, 0}, {1, 1}}, {T(1), T(-1)}, {0, 0, 1, 1}};
  EXPECT_TRUE(dist::is_nan_result(distance(negw, Ray<T, 2>{{0, 0}, {1, 0}})));
}

// detail/pair_candidates.hpp on its own, against a brute-force scan of the offered pairs: the
// best is the FIRST pair of smallest score, NaN scores are never taken, a runner-up is always
// distinct from the best (points more than sqrt(sep2) apart) and scores no better, and tied()
// compares distances with the absolute tolerance.
TEST(PairCandidates, BestIsTheFirstSmallestAndTheRunnerUpIsDistinct) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  using PC = detail::PairCandidates<double, 2, int, int>;
  for (int trial = 0; trial < 500; ++trial) {
    PC pc;
    pc.sep2 = 0.25;
    struct Offer {
      double d2;
      Vec2d xa, xb;
    };
    std::vector<Offer> offers;
    const int n = 1 + trial % 9;
    for (int k = 0; k < n; ++k) {
      // Scores on a coarse lattice (ties are common), points on a coarse lattice (coincident
      // pairs are common), now and then a NaN score.
      const double d2 = rng.uniform_int(0, 9) == 0 ? std::numeric_limits<double>::quiet_NaN()
                                                   : double(rng.uniform_int(0, 4));
      const Vec2d xa{double(rng.uniform_int(0, 2)), 0.0}, xb{double(rng.uniform_int(0, 2)), 1.0};
      offers.push_back({d2, xa, xb});
      pc.offer(d2, k, k, xa, xb);
    }
    int first_best = -1;
    for (int k = 0; k < n; ++k)
      if (!std::isnan(offers[std::size_t(k)].d2) &&
          (first_best < 0 || offers[std::size_t(k)].d2 < offers[std::size_t(first_best)].d2))
        first_best = k;
    ASSERT_EQ(pc.found, first_best >= 0) << trial;
    if (first_best < 0) continue;
    EXPECT_EQ(pc.best.pa, first_best) << trial;
    EXPECT_EQ(pc.best.d2, offers[std::size_t(first_best)].d2) << trial;
    if (pc.has_alt) {
      EXPECT_TRUE(pc.distinct(pc.alt, pc.best)) << trial;
      EXPECT_GE(pc.alt.d2, pc.best.d2) << trial;
      EXPECT_EQ(pc.tied(0.0), pc.alt.d2 == pc.best.d2) << trial;
    } else {
      EXPECT_FALSE(pc.tied(1e300)) << trial;
    }
  }
}
