// SPDX-License-Identifier: BSL-1.0
#pragma once
// The floating-point filters of the exact predicates (core/predicates.hpp), defined once for the
// predicates themselves and for the algorithms that run them in their own loops (Delaunay 2D and
// 3D, the SIMD lanes of the batched distances):
//   - the stage-A error bounds of J. R. Shewchuk (1997), section 6, for an IEEE type T with
//     unit roundoff u = epsilon / 2: *_bound_a_v<T>;
//   - the determinants and their bounds as StageA {det, bound} in core's sign conventions: the
//     sign of det is exact when |det| > bound. det3_stage_a is generic over the arithmetic (a
//     double, or a GCC vector of lanes with an abs of its own);
//   - a semi-static insphere bound (a cheaper permanent from per-axis maxima);
//   - lattice shortcuts: when the coordinate differences are exact and small integer multiples
//     of one power of two, the double evaluation is exact, so is its sign, zero included.
// Validity: the relative bounds hold when no product underflows (core/predicates.hpp states the
// range); non-finite input never passes (the bound is then inf or NaN, the comparisons strict)
// and is never on a lattice. Derivations: docs/notes/core.md, "Filters and spatial sort".

#include <locus/config.hpp>
#include <locus/core/error_free.hpp>
#include <locus/core/vec.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <type_traits>

namespace locus {

/// The sign of a predicate's determinant.
enum class Sign : std::int8_t { negative = -1, zero = 0, positive = 1 };

/// The sign of x; NaN gives zero.
template <Real T>
[[nodiscard]] constexpr Sign sign_of(T x) noexcept {
  return static_cast<Sign>(static_cast<int>(x > T(0)) - static_cast<int>(x < T(0)));
}

namespace detail {

// ---- Stage-A error bounds -----------------------------------------------------------------------

template <Real T>
inline constexpr T unit_roundoff_v = std::numeric_limits<T>::epsilon() / T(2);
template <Real T>
inline constexpr T orient2d_bound_a_v = (T(3) + T(16) * unit_roundoff_v<T>)*unit_roundoff_v<T>;
template <Real T>
inline constexpr T orient3d_bound_a_v = (T(7) + T(56) * unit_roundoff_v<T>)*unit_roundoff_v<T>;
template <Real T>
inline constexpr T incircle_bound_a_v = (T(10) + T(96) * unit_roundoff_v<T>)*unit_roundoff_v<T>;
template <Real T>
inline constexpr T insphere_bound_a_v = (T(16) + T(224) * unit_roundoff_v<T>)*unit_roundoff_v<T>;
// The float constants are exact (no rounding down of a bound).
static_assert(double(orient3d_bound_a_v<float>) == (7.0 + 56.0 * 0x1p-24) * 0x1p-24);
static_assert(double(incircle_bound_a_v<float>) == (10.0 + 96.0 * 0x1p-24) * 0x1p-24);

inline constexpr double predicate_eps = unit_roundoff_v<double>;
inline constexpr double orient2d_bound_a = orient2d_bound_a_v<double>;
inline constexpr double orient3d_bound_a = orient3d_bound_a_v<double>;
inline constexpr double incircle_bound_a = incircle_bound_a_v<double>;
inline constexpr double insphere_bound_a = insphere_bound_a_v<double>;
// |sum_i (q_i - p_i)^2 - (r_i - p_i)^2| in up to 3 dimensions: each square carries 3 roundings,
// each difference of squares 1, the sum N-1 <= 2; 8 eps leaves room for second-order terms.
inline constexpr double sqr_distance_bound_a = (8.0 + 64.0 * predicate_eps) * predicate_eps;
// The semi-static insphere bound (insphere_stage_a_semi_static): the stage-A constant with room
// for the few roundings by which its cheaper permanent may fall below the exact one.
inline constexpr double insphere_semi_static_bound = insphere_bound_a * (1.0 + 0x1p-40);

/// A rounded determinant in core's sign convention and its stage-A error bound.
template <class S>
struct StageA {
  S det, bound;
};

/// True when the sign of f.det is the exact sign (strict: a NaN or infinite bound never passes).
[[nodiscard]] LOCUS_ALWAYS_INLINE inline bool certain(const StageA<double>& f) noexcept {
  return std::abs(f.det) > f.bound;
}

/// The sign of a nonzero, non-NaN x, branch-free (a data-dependent branch on random input
/// costs more than the whole filter): one compare and 2 b - 1.
[[nodiscard]] LOCUS_ALWAYS_INLINE inline Sign nonzero_sign(double x) noexcept {
  return static_cast<Sign>(2 * static_cast<int>(x > 0.0) - 1);
}

template <class T, int N>
[[nodiscard]] constexpr Vec<double, N> to_double(const Vec<T, N>& v) noexcept {
  Vec<double, N> r{};
  for (int i = 0; i < N; ++i) r[i] = static_cast<double>(v[i]);
  return r;
}

// ---- Determinants with their bounds -------------------------------------------------------------

/// left - right for the two products of a 2x2 determinant of rounded differences. The paper's
/// bound is c (|left| + |right|); when the two share a sign that equals c |left + right|
/// (rounding is symmetric), and when they differ det cannot change sign and any bound >= 0
/// decides correctly: one absolute value fewer.
[[nodiscard]] LOCUS_ALWAYS_INLINE inline StageA<double> det2_stage_a(double left,
                                                                     double right) noexcept {
  return {left - right, orient2d_bound_a * std::abs(left + right)};
}

/// det[a - c; b - c] = orient2d(a, b, c).
[[nodiscard]] LOCUS_ALWAYS_INLINE inline StageA<double> orient2d_stage_a(
    const Vec2<double>& a, const Vec2<double>& b, const Vec2<double>& c) noexcept {
  const double acx = a.x - c.x, bcx = b.x - c.x;
  const double acy = a.y - c.y, bcy = b.y - c.y;
  return det2_stage_a(acx * bcy, acy * bcx);
}

/// det[p; q; r] of three rows of rounded differences (members x, y, z of any arithmetic type S:
/// double, or a vector of lanes), expanded along the z column as Shewchuk's orient3d, with its
/// stage-A bound for the unit roundoff of T (abs: |.| on S).
template <class T, class R, class Abs>
[[nodiscard]] LOCUS_ALWAYS_INLINE inline auto det3_stage_a(const R& p, const R& q, const R& r,
                                                           Abs abs) noexcept {
  const auto qxry = q.x * r.y, rxqy = r.x * q.y;
  const auto rxpy = r.x * p.y, pxry = p.x * r.y;
  const auto pxqy = p.x * q.y, qxpy = q.x * p.y;
  const auto det = p.z * (qxry - rxqy) + q.z * (rxpy - pxry) + r.z * (pxqy - qxpy);
  const auto permanent = (abs(qxry) + abs(rxqy)) * abs(p.z) + (abs(rxpy) + abs(pxry)) * abs(q.z) +
                         (abs(pxqy) + abs(qxpy)) * abs(r.z);
  return StageA<std::remove_cvref_t<decltype(det)>>{det, orient3d_bound_a_v<T> * permanent};
}

/// orient3d(a, b, c, d) (core's sign: det[b - a; c - a; d - a]), from Shewchuk's
/// det[a - d; b - d; c - d], its negation.
[[nodiscard]] LOCUS_ALWAYS_INLINE inline StageA<double> orient3d_stage_a(
    const Vec3<double>& a, const Vec3<double>& b, const Vec3<double>& c,
    const Vec3<double>& d) noexcept {
  const StageA<double> s =
      det3_stage_a<double>(a - d, b - d, c - d, [](double x) noexcept { return std::abs(x); });
  return {-s.det, s.bound};
}

/// incircle(a, b, c, d) (Shewchuk's, the same sign as core's).
[[nodiscard]] LOCUS_ALWAYS_INLINE inline StageA<double> incircle_stage_a(
    const Vec2<double>& a, const Vec2<double>& b, const Vec2<double>& c,
    const Vec2<double>& d) noexcept {
  const double adx = a.x - d.x, bdx = b.x - d.x, cdx = c.x - d.x;
  const double ady = a.y - d.y, bdy = b.y - d.y, cdy = c.y - d.y;
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  const double det =
      alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
  const double permanent = (std::abs(bdxcdy) + std::abs(cdxbdy)) * alift +
                           (std::abs(cdxady) + std::abs(adxcdy)) * blift +
                           (std::abs(adxbdy) + std::abs(bdxady)) * clift;
  return {det, incircle_bound_a * permanent};
}

/// The pieces of Shewchuk's insphere, det[p - e, |p - e|^2] over p = a, b, c, d (the negation of
/// core's): the differences p - e, the 3x3 minors {bcd, cda, dab, abc} of the other three rows,
/// the lifts |p - e|^2 and det. Algorithms reuse the minors (symbolic perturbation).
struct InsphereTerms {
  Vec3<double> diff[4];
  double minor[4];
  double lift[4];
  double det;
};
[[nodiscard]] LOCUS_ALWAYS_INLINE inline InsphereTerms insphere_terms(
    const Vec3<double>& a, const Vec3<double>& b, const Vec3<double>& c, const Vec3<double>& d,
    const Vec3<double>& e) noexcept {
  const double aex = a.x - e.x, bex = b.x - e.x, cex = c.x - e.x, dex = d.x - e.x;
  const double aey = a.y - e.y, bey = b.y - e.y, cey = c.y - e.y, dey = d.y - e.y;
  const double aez = a.z - e.z, bez = b.z - e.z, cez = c.z - e.z, dez = d.z - e.z;
  const double ab = aex * bey - bex * aey, bc = bex * cey - cex * bey;
  const double cd = cex * dey - dex * cey, da = dex * aey - aex * dey;
  const double ac = aex * cey - cex * aey, bd = bex * dey - dex * bey;
  const double abc = aez * bc - bez * ac + cez * ab;
  const double bcd = bez * cd - cez * bd + dez * bc;
  const double cda = cez * da + dez * ac + aez * cd;
  const double dab = dez * ab + aez * bd + bez * da;
  const double alift = aex * aex + aey * aey + aez * aez;
  const double blift = bex * bex + bey * bey + bez * bez;
  const double clift = cex * cex + cey * cey + cez * cez;
  const double dlift = dex * dex + dey * dey + dez * dez;
  const double det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
  return {{{aex, aey, aez}, {bex, bey, bez}, {cex, cey, cez}, {dex, dey, dez}},
          {bcd, cda, dab, abc},
          {alift, blift, clift, dlift},
          det};
}

/// The permanent of insphere_terms' determinant (the stage-A bound is insphere_bound_a times it).
[[nodiscard]] LOCUS_ALWAYS_INLINE inline double insphere_permanent(
    const InsphereTerms& t) noexcept {
  const Vec3<double>&a = t.diff[0], &b = t.diff[1], &c = t.diff[2], &d = t.diff[3];
  const auto pair = [](const Vec3<double>& p, const Vec3<double>& q) noexcept {
    return std::abs(p.x * q.y) + std::abs(q.x * p.y);
  };
  const double azp = std::abs(a.z), bzp = std::abs(b.z), czp = std::abs(c.z), dzp = std::abs(d.z);
  const double ab_p = pair(a, b), bc_p = pair(b, c), cd_p = pair(c, d);
  const double da_p = pair(d, a), ac_p = pair(a, c), bd_p = pair(b, d);
  return (cd_p * bzp + bd_p * czp + bc_p * dzp) * t.lift[0] +
         (da_p * czp + ac_p * dzp + cd_p * azp) * t.lift[1] +
         (ab_p * dzp + bd_p * azp + da_p * bzp) * t.lift[2] +
         (bc_p * azp + ac_p * bzp + ab_p * czp) * t.lift[3];
}

/// insphere(a, b, c, d, e) in core's sign.
[[nodiscard]] LOCUS_ALWAYS_INLINE inline StageA<double> insphere_stage_a(
    const Vec3<double>& a, const Vec3<double>& b, const Vec3<double>& c, const Vec3<double>& d,
    const Vec3<double>& e) noexcept {
  const InsphereTerms t = insphere_terms(a, b, c, d, e);
  return {-t.det, insphere_bound_a * insphere_permanent(t)};
}

/// insphere in core's sign with a semi-static bound: the permanent replaced by the larger
/// 6 mx my mz (sum of the lifts), mx, my, mz the largest |differences| per axis. Cheaper, and
/// as tight when the five points have similar spreads (an insertion order by space).
[[nodiscard]] LOCUS_ALWAYS_INLINE inline StageA<double> insphere_stage_a_semi_static(
    const InsphereTerms& t) noexcept {
  const auto max4 = [&](int k) noexcept {
    return std::max(std::max(std::abs(t.diff[0][k]), std::abs(t.diff[1][k])),
                    std::max(std::abs(t.diff[2][k]), std::abs(t.diff[3][k])));
  };
  const double m = 6.0 * ((max4(0) * max4(1)) * max4(2));
  return {-t.det,
          insphere_semi_static_bound * (m * ((t.lift[0] + t.lift[1]) + (t.lift[2] + t.lift[3])))};
}

// ---- Lattice shortcuts --------------------------------------------------------------------------

/// x - y rounds to nothing (its TwoSum error is zero; false for a non-finite difference).
[[nodiscard]] inline bool difference_is_exact(double x, double y) noexcept {
  double s, e;
  two_sum(x, -y, s, e);
  return e == 0.0;
}

/// u is an integer, for |u| < 2^52 (adding 2^52 rounds to an integer; no libm call).
[[nodiscard]] inline bool is_small_integer(double u) noexcept {
  const double a = std::abs(u);
  return (a + 0x1p52) - 0x1p52 == a;
}

/// The exponent ex with 2^(ex-1) <= m < 2^ex (frexp's) for a normal m > 0, without a libm call;
/// 0 for subnormal m (which the lattice ranges reject).
[[nodiscard]] inline int binary_exponent(double m) noexcept {
  const int biased = static_cast<int>((std::bit_cast<std::uint64_t>(m) >> 52) & 0x7FFu);
  return biased == 0 ? 0 : biased - 1022;
}

/// 2^k for -1022 <= k <= 1023.
[[nodiscard]] inline double power_of_two(int k) noexcept {
  return std::bit_cast<double>(static_cast<std::uint64_t>(k + 1023) << 52);
}

/// A lattice of degree-n determinants: differences that are integer multiples of q = 2^(ex-bits)
/// below 2^bits q in magnitude (ex the binary exponent of the largest one) keep every product
/// and sum of the double evaluation an integer multiple of q^k below 2^53 q^k, hence exact, for
/// lo < ex < hi (q^n does not underflow, 2^53 q^n does not overflow).
struct Lattice {
  int bits, lo, hi;
};
inline constexpr Lattice incircle_lattice_v{12, -250, 250};
inline constexpr Lattice orient3d_lattice_v{16, -300, 300};
inline constexpr Lattice insphere_lattice_v{9, -200, 190};

/// The n coordinates (x, y[, z]) of the rows p[i] - o are exact and on lattice L.
template <int N>
[[nodiscard]] inline bool differences_on_lattice(const Vec<double, N>* const* p, int n,
                                                 const Vec<double, N>& o, Lattice L) noexcept {
  double m = 0.0;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < N; ++k) {
      if (!difference_is_exact((*p[i])[k], o[k])) return false;
      m = std::max(m, std::abs((*p[i])[k] - o[k]));
    }
  if (!(m > 0.0) || !std::isfinite(m)) return false;
  const int ex = binary_exponent(m);  // m < 2^ex
  if (!(ex > L.lo && ex < L.hi)) return false;
  const double inv_q = power_of_two(L.bits - ex);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < N; ++k)
      if (!is_small_integer(((*p[i])[k] - o[k]) * inv_q)) return false;
  return true;
}

/// The exact incircle sign (zero included) when a, b, c, d are on incircle_lattice_v around d.
[[nodiscard]] inline std::optional<Sign> incircle_lattice(const Vec2<double>& a,
                                                          const Vec2<double>& b,
                                                          const Vec2<double>& c,
                                                          const Vec2<double>& d) noexcept {
  const Vec2<double>* const p[3] = {&a, &b, &c};
  if (!differences_on_lattice<2>(p, 3, d, incircle_lattice_v)) return std::nullopt;
  return sign_of(incircle_stage_a(a, b, c, d).det);
}

/// The exact orient3d sign (zero included) when a, b, c, d are on orient3d_lattice_v around d.
[[nodiscard]] inline std::optional<Sign> orient3d_lattice(const Vec3<double>& a,
                                                          const Vec3<double>& b,
                                                          const Vec3<double>& c,
                                                          const Vec3<double>& d) noexcept {
  const Vec3<double>* const p[3] = {&a, &b, &c};
  if (!differences_on_lattice<3>(p, 3, d, orient3d_lattice_v)) return std::nullopt;
  return sign_of(orient3d_stage_a(a, b, c, d).det);
}

/// insphere_terms, every field exact, when a, b, c, d, e are on insphere_lattice_v around e.
[[nodiscard]] inline std::optional<InsphereTerms> insphere_lattice(const Vec3<double>& a,
                                                                   const Vec3<double>& b,
                                                                   const Vec3<double>& c,
                                                                   const Vec3<double>& d,
                                                                   const Vec3<double>& e) noexcept {
  const Vec3<double>* const p[4] = {&a, &b, &c, &d};
  if (!differences_on_lattice<3>(p, 4, e, insphere_lattice_v)) return std::nullopt;
  return insphere_terms(a, b, c, d, e);
}

/// Every point a coordinate k q (|k| < 2^52), q = 2^(ex - 9) from the largest extent 2^(ex-1) <=
/// m < 2^ex, every extent below 2^9 q: any differences of these points are exact and on
/// insphere_lattice_v (so also on orient3d's), and insphere_terms and orient3d_stage_a evaluate
/// exactly. O(n); false for an empty or non-finite set.
template <Real T>
[[nodiscard]] bool points_on_insphere_lattice(std::span<const Vec3<T>> points) noexcept {
  if (points.empty()) return false;
  Vec3<double> lo = to_double(points[0]), hi = lo;
  for (const auto& p : points)
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], double(p[i]));
      hi[i] = std::max(hi[i], double(p[i]));
    }
  const double m = std::max(std::max(hi.x - lo.x, hi.y - lo.y), hi.z - lo.z);
  if (!(m > 0.0) || !std::isfinite(m)) return false;
  constexpr Lattice L = insphere_lattice_v;
  const int ex = binary_exponent(m);
  if (!(ex > L.lo && ex < L.hi)) return false;
  const double inv_q = power_of_two(L.bits - ex);
  for (int i = 0; i < 3; ++i) {
    const double klo = lo[i] * inv_q, khi = hi[i] * inv_q;
    if (!is_small_integer(klo) || !is_small_integer(khi) || !(khi - klo < 0x1p9)) return false;
  }
  const double q = power_of_two(ex - L.bits);
  for (const auto& p : points)
    for (int i = 0; i < 3; ++i) {
      const double k = double(p[i]) * inv_q;
      if (!is_small_integer(k) || k * q != double(p[i])) return false;  // (no underflow)
    }
  return true;
}

}  // namespace detail
}  // namespace locus
