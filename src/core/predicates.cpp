// SPDX-License-Identifier: BSL-1.0
// Adaptive exact fallbacks of the geometric predicates (row core.predicates).
//
// Written from J. R. Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust
// Geometric Predicates" (1997), section 6. The inline filter in predicates.hpp is stage A; when
// it cannot decide, the functions here run
//   stage B: the determinant of the *rounded* coordinate differences, computed exactly in
//            expansion arithmetic. If every difference was exact (its roundoff tail is zero,
//            the usual case for nearly degenerate input) this is the exact determinant and its
//            sign is returned at once; otherwise its estimate is accepted when it beats the
//            paper's stage-B error bound;
//   stage C: (orient2d, orient3d, incircle) the estimate corrected by the first-order terms in
//            the difference tails, accepted when it beats the stage-C bound;
//   exact:   the determinant expanded in the raw coordinates (no differences at all), computed
//            exactly; its sign is the answer.
// Every stage is exact or backed by an error bound, so the answer is the exact sign within the
// range documented in predicates.hpp. The error bounds are the paper's, computed as constexpr
// from eps = 2^-53: nothing is initialised at run time.
//
// This file must be compiled with -ffp-contract=off (CMake sets it): the expansion theorems need
// each operation rounded on its own.

#if defined(__FAST_MATH__)
#error "locus: src/core/predicates.cpp must not be compiled with -ffast-math (exact arithmetic)"
#endif

#include <cfloat>
// Expansion arithmetic needs every double operation rounded to double: no x87 extended precision.
#if defined(FLT_EVAL_METHOD) && FLT_EVAL_METHOD != 0
#error "locus: exact predicates need FLT_EVAL_METHOD == 0 (e.g. SSE2 arithmetic, not x87)"
#endif
// Belt and braces for builds that miss CMake's -ffp-contract=off: clang honours the standard
// pragma (GCC ignores it, and gets the flag).
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif

#include <locus/config.hpp>
#include <locus/core/predicates.hpp>

#include "expansion.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace locus::detail {
namespace {

namespace ex = expansion;

constexpr double eps = ex::eps;
constexpr double result_bound = (3.0 + 8.0 * eps) * eps;
constexpr double orient2d_bound_b = (2.0 + 12.0 * eps) * eps;
constexpr double orient2d_bound_c = (9.0 + 64.0 * eps) * eps * eps;
constexpr double orient3d_bound_b = (3.0 + 28.0 * eps) * eps;
constexpr double orient3d_bound_c = (26.0 + 288.0 * eps) * eps * eps;
constexpr double incircle_bound_b = (4.0 + 48.0 * eps) * eps;
constexpr double incircle_bound_c = (44.0 + 576.0 * eps) * eps * eps;
constexpr double insphere_bound_b = (5.0 + 72.0 * eps) * eps;

static_assert(ex::eps == predicate_eps, "one unit roundoff for filter and fallback");

// An expansion with a compile-time capacity, so every buffer size is checked by the types: a
// sum of capacities M and K needs M + K, a scale by a double 2 M.
template <int N>
struct Exp {
  int len = 0;
  double v[N];
};

template <int M, int K>
Exp<M + K> operator+(const Exp<M>& e, const Exp<K>& f) noexcept {
  Exp<M + K> h;
  h.len = ex::sum_zeroelim(e.len, e.v, f.len, f.v, h.v);
  return h;
}

template <int M>
Exp<M> operator-(const Exp<M>& e) noexcept {
  Exp<M> h;
  h.len = ex::negate(e.len, e.v, h.v);
  return h;
}

template <int M, int K>
Exp<M + K> operator-(const Exp<M>& e, const Exp<K>& f) noexcept {
  return e + (-f);
}

template <int M>
Exp<2 * M> operator*(const Exp<M>& e, double b) noexcept {
  Exp<2 * M> h;
  h.len = ex::scale_zeroelim(e.len, e.v, b, h.v);
  return h;
}

/// a1 * b1 - a2 * b2, exactly.
Exp<4> cross(double a1, double b1, double a2, double b2) noexcept {
  Exp<4> h;
  h.len = ex::two_products_diff(a1, b1, a2, b2, h.v);
  return h;
}

/// Rewrites e with few components, to keep later products short.
template <int N>
void compress(Exp<N>& e) noexcept {
  e.len = ex::compress(e.len, e.v);
}

template <int N>
Sign sign(const Exp<N>& e) noexcept {
  return static_cast<Sign>(ex::sign(e.len, e.v));
}

template <int N>
double estimate(const Exp<N>& e) noexcept {
  return ex::estimate(e.len, e.v);
}

/// Decides with `det` if it beats the error bound; zero means "undecided".
Sign decide(double det, double bound) noexcept {
  if (det > bound) return Sign::positive;
  if (-det > bound) return Sign::negative;
  return Sign::zero;
}

// The exactness range (predicates.hpp): true when some coordinate's magnitude exceeds 2^H or
// every coordinate is below 2^-32; the adaptive stages then run on the input scaled into the
// range (rescaled). Independent comparisons combined with | and & (no chain of maxima, no
// short-circuit branches), so that the common, in-range case costs the stages almost nothing
// (about 2 ns on orient2d's fallback, measured).
template <int H, class... P>
bool outside_exact_range(const P&... p) noexcept {
  constexpr double hi = [] {
    double h = 1.0;
    for (int i = 0; i < H; ++i) h *= 2.0;
    return h;
  }();
  bool huge = false, tiny = true;
  const auto visit = [&](const auto& v) {
    for (int k = 0; k < static_cast<int>(sizeof(v) / sizeof(double)); ++k) {
      const double a = std::abs(v[k]);
      huge |= a > hi;
      tiny &= a < 0x1p-32;
    }
  };
  (visit(p), ...);
  return huge | tiny;
}

// adaptive(p...) on the points scaled by the power of two that brings their largest coordinate
// magnitude into [1, 2) (normalising_scale): the sign is invariant under the scaling, which
// rounds nothing while the coordinates stay normal, and the scaled points lie in the exact range,
// so this does not recurse again. Every coordinate zero: a zero determinant. Out of line and cold,
// so that the common path carries only the range test.
template <class... P>
[[gnu::cold]] LOCUS_NOINLINE Sign rescaled(Sign (*adaptive)(const P&...), const P&... p) noexcept {
  const double f = normalising_scale(std::max({max_abs(p)...}));
  return f == 1.0 ? Sign::zero : adaptive((f * p)...);
}

bool finite(const Vec2<double>& p) noexcept { return std::isfinite(p.x) && std::isfinite(p.y); }
bool finite(const Vec3<double>& p) noexcept {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// ---- Raw-coordinate exact determinants -------------------------------------------------------

/// m(p, q) = px qy - qx py, the 2x2 minor of the x, y columns.
template <class P>
Exp<4> minor2(const P& p, const P& q) noexcept {
  return cross(p.x, q.y, q.x, p.y);
}

/// det[p; q; r] of 3x3 raw coordinates, from the minors m(q,r), m(p,r), m(p,q).
Exp<24> minor3(const Vec3<double>& p, const Vec3<double>& q, const Vec3<double>& r,
               const Exp<4>& mqr, const Exp<4>& mpr, const Exp<4>& mpq) noexcept {
  Exp<24> m = (mqr * p.z - mpr * q.z) + mpq * r.z;
  compress(m);
  return m;
}

/// det of rows (p, 1), (q, 1), (r, 1) in 2D: m(q,r) - m(p,r) + m(p,q) = orient2d(p, q, r).
Exp<12> minor3_affine(const Exp<4>& mqr, const Exp<4>& mpr, const Exp<4>& mpq) noexcept {
  return (mqr - mpr) + mpq;
}

/// e * (sum of the K coordinates of p squared), exactly. The lift is formed first as a short
/// expansion (at most 2K components, compressed), then e is scaled by each of its components:
/// cheaper than scaling e twice per coordinate. Capacity 2N per component, 4KN in all.
template <int K, int N>
LOCUS_NOINLINE void lift_times(const double (&p)[K], const Exp<N>& e,
                               Exp<4 * K * N>& out) noexcept {
  Exp<2 * K> lift;
  for (int k = 0; k < K; ++k) {
    double sq[2];
    ex::two_product(p[k], p[k], sq[1], sq[0]);
    Exp<2 * K> next;
    next.len = ex::sum_zeroelim(lift.len, lift.v, 2, sq, next.v);
    lift = next;
  }
  lift.len = ex::compress(lift.len, lift.v);
  // Ping-pong between out and tmp, starting so that the last sum lands in out.
  Exp<4 * K * N> tmp;
  Exp<4 * K * N>* buf[2] = {&out, &tmp};
  int dst = lift.len % 2 == 1 ? 0 : 1;
  out.len = 0;
  tmp.len = 0;
  for (int k = 0; k < lift.len; ++k) {
    const Exp<2 * N> part = e * lift.v[k];
    const Exp<4 * K* N>& src = *buf[1 - dst];
    buf[dst]->len = ex::sum_zeroelim(src.len, src.v, part.len, part.v, buf[dst]->v);
    dst = 1 - dst;
  }
}

/// (x^2 + y^2) * e, exactly.
template <int N>
Exp<8 * N> lift2_times(const Vec2<double>& p, const Exp<N>& e) noexcept {
  const double c[2] = {p.x, p.y};
  Exp<8 * N> r;
  lift_times<2>(c, e, r);
  return r;
}
/// (x^2 + y^2 + z^2) * e, exactly.
template <int N>
Exp<12 * N> lift3_times(const Vec3<double>& p, const Exp<N>& e) noexcept {
  const double c[3] = {p.x, p.y, p.z};
  Exp<12 * N> r;
  lift_times<3>(c, e, r);
  return r;
}

// Out of line: its large buffers must not enlarge the frame of the common path.
LOCUS_NOINLINE Sign orient2d_exact(const Vec2<double>& a, const Vec2<double>& b,
                                   const Vec2<double>& c) noexcept {
  return sign(minor3_affine(minor2(b, c), minor2(a, c), minor2(a, b)));
}

/// Shewchuk's orient3d, det[a - d; b - d; c - d] = D(abc) - D(abd) + D(acd) - D(bcd).
// Out of line: its large buffers must not enlarge the frame of the common path.
LOCUS_NOINLINE Sign orient3d_exact_shewchuk(const Vec3<double>& a, const Vec3<double>& b,
                                            const Vec3<double>& c, const Vec3<double>& d) noexcept {
  const Exp<4> ab = minor2(a, b), ac = minor2(a, c), ad = minor2(a, d);
  const Exp<4> bc = minor2(b, c), bd = minor2(b, d), cd = minor2(c, d);
  const Exp<24> abc = minor3(a, b, c, bc, ac, ab);
  const Exp<24> abd = minor3(a, b, d, bd, ad, ab);
  const Exp<24> acd = minor3(a, c, d, cd, ad, ac);
  const Exp<24> bcd = minor3(b, c, d, cd, bd, bc);
  return sign((abc - abd) + (acd - bcd));
}

/// det of rows (x, y, x^2 + y^2, 1) for a, b, c, d, expanded along the lift column:
/// lift_a E(bcd) - lift_b E(acd) + lift_c E(abd) - lift_d E(abc). Equals Shewchuk's incircle.
// Out of line: its large buffers must not enlarge the frame of the common path.
LOCUS_NOINLINE Sign incircle_exact(const Vec2<double>& a, const Vec2<double>& b,
                                   const Vec2<double>& c, const Vec2<double>& d) noexcept {
  const Exp<4> ab = minor2(a, b), ac = minor2(a, c), ad = minor2(a, d);
  const Exp<4> bc = minor2(b, c), bd = minor2(b, d), cd = minor2(c, d);
  const Exp<12> bcd = minor3_affine(cd, bd, bc);
  const Exp<12> acd = minor3_affine(cd, ad, ac);
  const Exp<12> abd = minor3_affine(bd, ad, ab);
  const Exp<12> abc = minor3_affine(bc, ac, ab);
  return sign((lift2_times(a, bcd) - lift2_times(b, acd)) +
              (lift2_times(c, abd) - lift2_times(d, abc)));
}

/// det of rows (x, y, z, |p|^2, 1) for a..e, expanded along the lift column:
///   -lift_a F(bcde) + lift_b F(acde) - lift_c F(abde) + lift_d F(abce) - lift_e F(abcd)
/// with F(pqrs) = D(pqr) - D(pqs) + D(prs) - D(qrs). Equals Shewchuk's insphere.
// Out of line: its large buffers must not enlarge the frame of the common path.
LOCUS_NOINLINE Sign insphere_exact_shewchuk(const Vec3<double>& a, const Vec3<double>& b,
                                            const Vec3<double>& c, const Vec3<double>& d,
                                            const Vec3<double>& e) noexcept {
  const Vec3<double>* p[5] = {&a, &b, &c, &d, &e};
  Exp<4> m[5][5];
  for (int i = 0; i < 5; ++i)
    for (int j = i + 1; j < 5; ++j) m[i][j] = minor2(*p[i], *p[j]);
  // The ten 3x3 minors D(ijk), i < j < k.
  Exp<24> dm[10];
  int id[5][5][5] = {};
  int count = 0;
  for (int i = 0; i < 5; ++i)
    for (int j = i + 1; j < 5; ++j)
      for (int k = j + 1; k < 5; ++k) {
        id[i][j][k] = count;
        dm[count++] = minor3(*p[i], *p[j], *p[k], m[j][k], m[i][k], m[i][j]);
      }
  auto D = [&](int i, int j, int k) noexcept -> const Exp<24>& { return dm[id[i][j][k]]; };
  // F of the four points other than `skip`, in increasing order q < r < s < t.
  auto four = [&](int skip) noexcept {
    int q[4], n = 0;
    for (int i = 0; i < 5; ++i)
      if (i != skip) q[n++] = i;
    Exp<96> f =
        (D(q[0], q[1], q[2]) - D(q[0], q[1], q[3])) + (D(q[0], q[2], q[3]) - D(q[1], q[2], q[3]));
    compress(f);
    return f;
  };
  // Two ping-pong accumulators; the sum of five terms of 1152 components needs 5760.
  static constexpr int cap = 5 * 1152;
  Exp<cap> acc[2];
  int cur = 0;
  for (int i = 0; i < 5; ++i) {
    const Exp<1152> term = lift3_times(*p[i], four(i));
    // Sign (-1)^(i+1): the cofactor sign of row i+1, column 4.
    double* out = acc[1 - cur].v;
    if (i % 2 == 0) {
      Exp<1152> neg = -term;
      acc[1 - cur].len = ex::sum_zeroelim(acc[cur].len, acc[cur].v, neg.len, neg.v, out);
    } else {
      acc[1 - cur].len = ex::sum_zeroelim(acc[cur].len, acc[cur].v, term.len, term.v, out);
    }
    cur = 1 - cur;
  }
  return sign(acc[cur]);
}

}  // namespace

// ---- orient2d ---------------------------------------------------------------------------------

Sign orient2d_adaptive(const Vec2<double>& a, const Vec2<double>& b,
                       const Vec2<double>& c) noexcept {
  if (!finite(a) || !finite(b) || !finite(c)) return Sign::zero;
  if (outside_exact_range<500>(a, b, c)) [[unlikely]]
    return rescaled(orient2d_adaptive, a, b, c);
  const double acx = a.x - c.x, bcx = b.x - c.x;
  const double acy = a.y - c.y, bcy = b.y - c.y;
  // Stage B.
  const Exp<4> B = cross(acx, bcy, acy, bcx);
  const double acxt = ex::two_diff_tail(a.x, c.x, acx), bcxt = ex::two_diff_tail(b.x, c.x, bcx);
  const double acyt = ex::two_diff_tail(a.y, c.y, acy), bcyt = ex::two_diff_tail(b.y, c.y, bcy);
  if (acxt == 0.0 && bcxt == 0.0 && acyt == 0.0 && bcyt == 0.0) return sign(B);
  const double detsum = std::abs(acx * bcy) + std::abs(acy * bcx);
  double det = estimate(B);
  if (const Sign s = decide(det, orient2d_bound_b * detsum); s != Sign::zero) return s;
  // Stage C.
  const double bound = orient2d_bound_c * detsum + result_bound * std::abs(det);
  det += (acx * bcyt + bcy * acxt) - (acy * bcxt + bcx * acyt);
  if (const Sign s = decide(det, bound); s != Sign::zero) return s;
  return orient2d_exact(a, b, c);
}

// ---- turn2d -----------------------------------------------------------------------------------

// (bx - ax)(dy - cy) - (by - ay)(dx - cx) = m(b, d) - m(b, c) - m(a, d) + m(a, c) with the minors
// m(p, q) = px qy - py qx of the raw coordinates: no rounded difference anywhere. Reached only
// when the filter fails (nearly parallel directions), so no intermediate stages.
Sign turn2d_exact(const Vec2<double>& a, const Vec2<double>& b, const Vec2<double>& c,
                  const Vec2<double>& d) noexcept {
  if (!finite(a) || !finite(b) || !finite(c) || !finite(d)) return Sign::zero;
  if (outside_exact_range<500>(a, b, c, d)) [[unlikely]]
    return rescaled(turn2d_exact, a, b, c, d);
  return sign((minor2(b, d) - minor2(b, c)) + (minor2(a, c) - minor2(a, d)));
}

// ---- orient3d (computed in Shewchuk's sign, returned in ours) ---------------------------------

Sign orient3d_adaptive(const Vec3<double>& a, const Vec3<double>& b, const Vec3<double>& c,
                       const Vec3<double>& d) noexcept {
  if (!finite(a) || !finite(b) || !finite(c) || !finite(d)) return Sign::zero;
  if (outside_exact_range<330>(a, b, c, d)) [[unlikely]]
    return rescaled(orient3d_adaptive, a, b, c, d);
  const double adx = a.x - d.x, bdx = b.x - d.x, cdx = c.x - d.x;
  const double ady = a.y - d.y, bdy = b.y - d.y, cdy = c.y - d.y;
  const double adz = a.z - d.z, bdz = b.z - d.z, cdz = c.z - d.z;
  // Stage B.
  const Exp<4> bc = cross(bdx, cdy, cdx, bdy);
  const Exp<4> ca = cross(cdx, ady, adx, cdy);
  const Exp<4> ab = cross(adx, bdy, bdx, ady);
  const Exp<24> B = (bc * adz + ca * bdz) + ab * cdz;
  const double adxt = ex::two_diff_tail(a.x, d.x, adx), bdxt = ex::two_diff_tail(b.x, d.x, bdx),
               cdxt = ex::two_diff_tail(c.x, d.x, cdx);
  const double adyt = ex::two_diff_tail(a.y, d.y, ady), bdyt = ex::two_diff_tail(b.y, d.y, bdy),
               cdyt = ex::two_diff_tail(c.y, d.y, cdy);
  const double adzt = ex::two_diff_tail(a.z, d.z, adz), bdzt = ex::two_diff_tail(b.z, d.z, bdz),
               cdzt = ex::two_diff_tail(c.z, d.z, cdz);
  if (adxt == 0.0 && bdxt == 0.0 && cdxt == 0.0 && adyt == 0.0 && bdyt == 0.0 && cdyt == 0.0 &&
      adzt == 0.0 && bdzt == 0.0 && cdzt == 0.0)
    return -sign(B);
  const double permanent = (std::abs(bdx * cdy) + std::abs(cdx * bdy)) * std::abs(adz) +
                           (std::abs(cdx * ady) + std::abs(adx * cdy)) * std::abs(bdz) +
                           (std::abs(adx * bdy) + std::abs(bdx * ady)) * std::abs(cdz);
  double det = estimate(B);
  if (const Sign s = decide(det, orient3d_bound_b * permanent); s != Sign::zero) return -s;
  // Stage C: first-order terms in the tails.
  const double bound = orient3d_bound_c * permanent + result_bound * std::abs(det);
  det += (adz * ((bdx * cdyt + cdy * bdxt) - (bdy * cdxt + cdx * bdyt)) +
          adzt * (bdx * cdy - bdy * cdx)) +
         (bdz * ((cdx * adyt + ady * cdxt) - (cdy * adxt + adx * cdyt)) +
          bdzt * (cdx * ady - cdy * adx)) +
         (cdz * ((adx * bdyt + bdy * adxt) - (ady * bdxt + bdx * adyt)) +
          cdzt * (adx * bdy - ady * bdx));
  if (const Sign s = decide(det, bound); s != Sign::zero) return -s;
  return -orient3d_exact_shewchuk(a, b, c, d);
}

// ---- incircle ---------------------------------------------------------------------------------

Sign incircle_adaptive(const Vec2<double>& a, const Vec2<double>& b, const Vec2<double>& c,
                       const Vec2<double>& d) noexcept {
  if (!finite(a) || !finite(b) || !finite(c) || !finite(d)) return Sign::zero;
  if (outside_exact_range<245>(a, b, c, d)) [[unlikely]]
    return rescaled(incircle_adaptive, a, b, c, d);
  const double adx = a.x - d.x, bdx = b.x - d.x, cdx = c.x - d.x;
  const double ady = a.y - d.y, bdy = b.y - d.y, cdy = c.y - d.y;
  // Stage B.
  const Exp<4> bc = cross(bdx, cdy, cdx, bdy);
  const Exp<4> ca = cross(cdx, ady, adx, cdy);
  const Exp<4> ab = cross(adx, bdy, bdx, ady);
  const Exp<96> B =
      (lift2_times({adx, ady}, bc) + lift2_times({bdx, bdy}, ca)) + lift2_times({cdx, cdy}, ab);
  const double adxt = ex::two_diff_tail(a.x, d.x, adx), bdxt = ex::two_diff_tail(b.x, d.x, bdx),
               cdxt = ex::two_diff_tail(c.x, d.x, cdx);
  const double adyt = ex::two_diff_tail(a.y, d.y, ady), bdyt = ex::two_diff_tail(b.y, d.y, bdy),
               cdyt = ex::two_diff_tail(c.y, d.y, cdy);
  if (adxt == 0.0 && bdxt == 0.0 && cdxt == 0.0 && adyt == 0.0 && bdyt == 0.0 && cdyt == 0.0)
    return sign(B);
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  const double permanent = (std::abs(bdx * cdy) + std::abs(cdx * bdy)) * alift +
                           (std::abs(cdx * ady) + std::abs(adx * cdy)) * blift +
                           (std::abs(adx * bdy) + std::abs(bdx * ady)) * clift;
  double det = estimate(B);
  if (const Sign s = decide(det, incircle_bound_b * permanent); s != Sign::zero) return s;
  // Stage C: first-order terms in the tails (d lift = 2 (dx dxt + dy dyt)).
  const double bound = incircle_bound_c * permanent + result_bound * std::abs(det);
  det += ((adx * adx + ady * ady) * ((bdx * cdyt + cdy * bdxt) - (bdy * cdxt + cdx * bdyt)) +
          2.0 * (adx * adxt + ady * adyt) * (bdx * cdy - bdy * cdx)) +
         ((bdx * bdx + bdy * bdy) * ((cdx * adyt + ady * cdxt) - (cdy * adxt + adx * cdyt)) +
          2.0 * (bdx * bdxt + bdy * bdyt) * (cdx * ady - cdy * adx)) +
         ((cdx * cdx + cdy * cdy) * ((adx * bdyt + bdy * adxt) - (ady * bdxt + bdx * adyt)) +
          2.0 * (cdx * cdxt + cdy * cdyt) * (adx * bdy - ady * bdx));
  if (const Sign s = decide(det, bound); s != Sign::zero) return s;
  return incircle_exact(a, b, c, d);
}

// ---- insphere (computed in Shewchuk's sign, returned in ours) ---------------------------------

namespace {

// Stages B and C; nullopt when they cannot decide. Separate from the exact stage so the two
// large frames are never on the stack together.
LOCUS_NOINLINE std::optional<Sign> insphere_stages_bc(const Vec3<double>& a, const Vec3<double>& b,
                                                      const Vec3<double>& c, const Vec3<double>& d,
                                                      const Vec3<double>& e) noexcept {
  const Vec3<double> ae{a.x - e.x, a.y - e.y, a.z - e.z};
  const Vec3<double> be{b.x - e.x, b.y - e.y, b.z - e.z};
  const Vec3<double> ce{c.x - e.x, c.y - e.y, c.z - e.z};
  const Vec3<double> de{d.x - e.x, d.y - e.y, d.z - e.z};
  const Vec3<double>* raw[4] = {&a, &b, &c, &d};
  const Vec3<double>* diff[4] = {&ae, &be, &ce, &de};
  Vec3<double> tail[4]{};
  bool exact_differences = true;
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) {
      tail[i][k] = ex::two_diff_tail((*raw[i])[k], e[k], (*diff[i])[k]);
      exact_differences = exact_differences && tail[i][k] == 0.0;
    }
  // Stage B: the 4x4 determinant of rows (p - e, |p - e|^2) on the rounded differences,
  // expanded along the lift column: -alift D(bcd) + blift D(acd) - clift D(abd) + dlift D(abc)
  // with D(pqr) = det[p; q; r].
  const Exp<4> ab = minor2(ae, be), ac = minor2(ae, ce), ad = minor2(ae, de);
  const Exp<4> bc = minor2(be, ce), bd = minor2(be, de), cd = minor2(ce, de);
  const Exp<24> abc = minor3(ae, be, ce, bc, ac, ab);
  const Exp<24> abd = minor3(ae, be, de, bd, ad, ab);
  const Exp<24> acd = minor3(ae, ce, de, cd, ad, ac);
  const Exp<24> bcd = minor3(be, ce, de, cd, bd, bc);
  const Exp<1152> B =
      (lift3_times(de, abc) - lift3_times(ce, abd)) + (lift3_times(be, acd) - lift3_times(ae, bcd));
  if (exact_differences) return -sign(B);
  const double permanent = insphere_permanent(insphere_terms(a, b, c, d, e));
  if (const Sign s = decide(estimate(B), insphere_bound_b * permanent); s != Sign::zero) return -s;
  // Stage C. The paper gives no stage C for insphere that we reuse; this one follows its idea
  // with a running error bound. With exact differences P = u + t (u rounded, |t| <= eps |u|),
  //   det(P) = B + C1 + R,  C1 = sum_p s_p (dL_p D_p + L_p dD_p)  (first order in t),
  // where L_p = u.u, dL_p = 2 u.t, D_p is the triple product of the other three rows and dD_p
  // its first-order change. Every monomial of det has degree 5, so the rest R of order >= 2 is
  // at most ((1+eps)^5 - 1 - 5 eps) <= 10.01 eps^2 times the permanent (12 eps^2 allows for the
  // permanent's own rounding). In fl(C1) every monomial carries at most 16 rounding factors
  // (a product adds the counts of its operands plus one, a sum the larger count plus one), so by
  // Higham's bound |fl(C1) - C1| <= gamma_16 |C1|abs, where |C1|abs is the same expression on
  // absolute values (20 eps covers gamma_16 / (1 - gamma_16) and the rounding of the bound
  // itself). B + fl(C1) is summed exactly and compared exactly with the bound.
  {
    auto dot = [](const Vec3<double>& x, const Vec3<double>& y) noexcept {
      return x.x * y.x + x.y * y.y + x.z * y.z;
    };
    auto cross3 = [](const Vec3<double>& x, const Vec3<double>& y) noexcept {
      return Vec3<double>{x.y * y.z - x.z * y.y, x.z * y.x - x.x * y.z, x.x * y.y - x.y * y.x};
    };
    auto cross_abs = [](const Vec3<double>& x, const Vec3<double>& y) noexcept {
      return Vec3<double>{std::abs(x.y * y.z) + std::abs(x.z * y.y),
                          std::abs(x.z * y.x) + std::abs(x.x * y.z),
                          std::abs(x.x * y.y) + std::abs(x.y * y.x)};
    };
    auto vabs = [](const Vec3<double>& x) noexcept {
      return Vec3<double>{std::abs(x.x), std::abs(x.y), std::abs(x.z)};
    };
    const Vec3<double> u[4] = {ae, be, ce, de};
    double c1 = 0.0, c1_abs = 0.0;
    for (int p = 0; p < 4; ++p) {
      // The other three rows in increasing order: D_p = det[q; r; w] = q . (r x w).
      int o[3], n = 0;
      for (int i = 0; i < 4; ++i)
        if (i != p) o[n++] = i;
      const Vec3<double>& q = u[o[0]];
      const Vec3<double>& r = u[o[1]];
      const Vec3<double>& w = u[o[2]];
      const Vec3<double>& tq = tail[o[0]];
      const Vec3<double>& tr = tail[o[1]];
      const Vec3<double>& tw = tail[o[2]];
      const double D = dot(q, cross3(r, w));
      const double D_abs = dot(vabs(q), cross_abs(r, w));
      const double dD = (dot(tq, cross3(r, w)) + dot(q, cross3(tr, w))) + dot(q, cross3(r, tw));
      const double dD_abs = (dot(vabs(tq), cross_abs(r, w)) + dot(vabs(q), cross_abs(tr, w))) +
                            dot(vabs(q), cross_abs(r, tw));
      const double L = dot(u[p], u[p]);
      const double dL = 2.0 * dot(u[p], tail[p]);
      const double dL_abs = 2.0 * dot(vabs(u[p]), vabs(tail[p]));
      const double term = dL * D + L * dD;
      const double term_abs = dL_abs * D_abs + L * dD_abs;
      // Cofactor signs of the lift column: -, +, -, + for a, b, c, d.
      c1 += (p % 2 == 0) ? -term : term;
      c1_abs += term_abs;
    }
    const double bound = 12.0 * eps * eps * permanent + 20.0 * eps * c1_abs;
    Exp<1153> S;
    S.len = ex::grow_zeroelim(B.len, B.v, c1, S.v);
    Exp<1154> T;
    T.len = ex::grow_zeroelim(S.len, S.v, -bound, T.v);
    if (sign(T) == Sign::positive) return Sign::negative;  // det > bound: Shewchuk's sign +
    T.len = ex::grow_zeroelim(S.len, S.v, bound, T.v);
    if (sign(T) == Sign::negative) return Sign::positive;
  }
  return std::nullopt;
}

}  // namespace

Sign insphere_adaptive(const Vec3<double>& a, const Vec3<double>& b, const Vec3<double>& c,
                       const Vec3<double>& d, const Vec3<double>& e) noexcept {
  if (!finite(a) || !finite(b) || !finite(c) || !finite(d) || !finite(e)) return Sign::zero;
  if (outside_exact_range<195>(a, b, c, d, e)) [[unlikely]]
    return rescaled(insphere_adaptive, a, b, c, d, e);
  if (const std::optional<Sign> s = insphere_stages_bc(a, b, c, d, e)) return *s;
  return -insphere_exact_shewchuk(a, b, c, d, e);
}

// ---- squared-distance comparison --------------------------------------------------------------

Sign compare_sqr_distance_exact(const double* p, const double* q, const double* r, int n) noexcept {
  // sum_i q_i^2 - r_i^2 - 2 p_i q_i + 2 p_i r_i, every product exact (doubling is exact).
  Exp<24> acc;
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(p[i]) || !std::isfinite(q[i]) || !std::isfinite(r[i])) return Sign::zero;
  }
  if (n == 2 || n == 3) {
    Vec3<double> pv{}, qv{}, rv{};
    for (int i = 0; i < n; ++i) pv[i] = p[i], qv[i] = q[i], rv[i] = r[i];
    if (outside_exact_range<500>(pv, qv, rv)) [[unlikely]]
      return rescaled(
          +[](const Vec3<double>& x, const Vec3<double>& y, const Vec3<double>& z) {
            return compare_sqr_distance_exact(&x[0], &y[0], &z[0], 3);
          },
          pv, qv, rv);
  }
  for (int i = 0; i < n && i < 3; ++i) {
    const Exp<4> sq = cross(q[i], q[i], r[i], r[i]);
    const Exp<4> cr = cross(p[i], 2.0 * r[i], p[i], 2.0 * q[i]);
    const Exp<8> term = sq + cr;
    Exp<24> next;
    next.len = ex::sum_zeroelim(acc.len, acc.v, term.len, term.v, next.v);
    acc = next;
  }
  return sign(acc);
}

}  // namespace locus::detail
