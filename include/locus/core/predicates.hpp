// SPDX-License-Identifier: BSL-1.0
#pragma once
// Exact geometric predicates: orient2d, orient3d, incircle, insphere, and small exact helpers
// (orient1d, lexicographic_compare, compare_sqr_distance, turn2d). CAPABILITIES row
// core.predicates.
//
// Each predicate returns the *exact* sign of a polynomial in the input coordinates. A fast
// filter, inline here, evaluates the determinant in double and accepts its sign when it exceeds
// a static error bound times the permanent (the same determinant with absolute values), as in
// J. R. Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric
// Predicates" (1997), stage A. Otherwise it calls detail::*_adaptive (src/core/predicates.cpp,
// built with -ffp-contract=off), which runs the paper's adaptive stages B, C and an exact stage
// in expansion arithmetic. No global initialisation: every error bound is a constexpr computed
// from eps = 2^-53. Float input is promoted to double, which is exact.
//
// Sign conventions (fixed; the library's combinatorial code relies on them):
//   orient2d(a, b, c)       > 0 iff a, b, c are counter-clockwise: sign of det[b - a; c - a].
//   orient3d(a, b, c, d)    > 0 iff d lies on the side of plane abc toward which
//                           (b - a) x (c - a) points: sign of det[b - a; c - a; d - a].
//                           This is the NEGATION of Shewchuk's orient3d (his is det[a-d; b-d;
//                           c-d]).
//   incircle(a, b, c, d)    > 0 iff d is strictly inside the circle through a, b, c when
//                           orient2d(a, b, c) > 0 (Shewchuk's convention); the sign flips with
//                           the orientation of a, b, c.
//   insphere(a, b, c, d, e) > 0 iff e is strictly inside the sphere through a, b, c, d when
//                           orient3d(a, b, c, d) > 0 in OUR convention; the sign flips with the
//                           orientation. This is the NEGATION of Shewchuk's insphere.
//   turn2d(a, b, c, d)      > 0 iff the direction c -> d is counter-clockwise from a -> b (less
//                           than a half turn): sign of det[b - a; d - c]; orient2d(a, b, c) =
//                           turn2d(a, b, a, c). Zero iff the two directions are parallel (or
//                           one is zero).
// All are zero exactly on degenerate configurations (collinear, coplanar, cocircular,
// cospherical), swap sign under an odd permutation of the points, and are invariant under
// translation (orient*, in*) and positive scaling.
//
// Degenerate and bad input: if any coordinate is NaN or infinite the result is Sign::zero
// (the filter can never accept a non-finite determinant or bound, and the fallback checks).
//
// Exactness range. Float input: every finite float is handled exactly (differences and products
// of promoted floats stay far inside double range). Double input: the result is exact whenever
// every nonzero coordinate c satisfies |c| >= 2^-L and |c| >= 2^-(L - 32) M, M the largest
// coordinate magnitude, with no upper limit on M:
//     orient2d   L = 480, H = 500   (about 3e-145; also turn2d, compare_sqr_distance)
//     orient3d   L = 300, H = 330   (about 5e-91)
//     incircle   L = 210, H = 245   (about 6e-64)
//     insphere   L = 160, H = 195   (about 7e-49)
// Why: every stage is exact when every nonzero coordinate lies in [2^-L, 2^H] (a degree-n
// predicate needs n*(L+52) <= 1074, so every difference, product and expansion component is a
// multiple of the smallest subnormal and no rounding is ever absolute; and n*(H+2) + 9 < 1024, so
// no sum of the at most 2^9 monomials overflows, which also keeps every Veltkamp-Dekker split,
// applied to values of degree <= n-1, 2^27 below overflow). Above 2^H the filter cannot accept
// (an overflowing product makes its bound infinite or NaN), and the adaptive stages first scale
// the input by the power of two that brings M into [1, 2) (normalising_scale, core/scalar.hpp),
// which leaves the sign unchanged and rounds nothing while the coordinates stay normal: hence
// the relative lower limit. (They scale small input up too, when M < 2^-32, but the filter may
// already have accepted a wrong sign there: products in the subnormal range carry absolute
// errors its relative bound does not cover. Only when every product underflows to zero does the
// filter decline for certain; exactness below 2^-L is therefore not promised.)
// Outside that range the result is still a deterministic Sign with no UB and no hang, but may be
// wrong. Compiling the *calling* code with -ffast-math (-ffinite-math-only) voids the NaN rule;
// FMA contraction in the caller does not invalidate the filter (a fused operation only drops
// roundings that the error bounds allow for).
//
// Cost: the filter is the naive determinant plus an error bound (a few more flops and one
// well-predicted branch): on random input about 1.15x the naive determinant for orient2d and
// 1.4-1.8x for the others (bench/core/predicates_bench.cpp). The fallback runs only for nearly
// degenerate input: about 10 ns for orient2d, 0.1 us orient3d, 0.5 us incircle, 1.5-3 us
// insphere; of that, the test for input outside the exact range (which is then scaled) takes
// about 2 ns (orient2d's fallback 81.7 -> 70.1 M/s, BM_orient2d_exact_degenerate; within noise for
// the others). No allocation; stack use of the fallbacks is a few KB except insphere (about 40 KB
// in stages B/C, about 140 KB in its rarely reached exact stage).
//
// Book: chapter 13 uses these signs throughout; figure 13.35 (the five relations of a point and a
// segment) is decided exactly by orient2d plus lexicographic_compare (see the tests).

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>

#include <cmath>
#include <cstdint>
#include <type_traits>

// orient2d's filter packs its two products into one SSE2 register where available (always on
// x86-64): the same IEEE operations on the same operands, so bit-identical to the scalar code,
// with fewer instructions on the hot path.
// Define LOCUS_PREDICATES_SSE2 to 0 to force the scalar code.
#if !defined(LOCUS_PREDICATES_SSE2)
#if defined(__SSE2__) || defined(_M_X64) || (defined(_M_IX86_FP) && _M_IX86_FP >= 2)
#define LOCUS_PREDICATES_SSE2 1
#else
#define LOCUS_PREDICATES_SSE2 0
#endif
#endif
#if LOCUS_PREDICATES_SSE2
#include <emmintrin.h>
#endif

namespace locus {

/// The sign of a predicate's determinant.
enum class Sign : std::int8_t { negative = -1, zero = 0, positive = 1 };

/// The opposite sign (a swap of two arguments of a predicate).
[[nodiscard]] constexpr Sign operator-(Sign s) noexcept {
  return static_cast<Sign>(-static_cast<int>(s));
}

/// The sign of a product.
[[nodiscard]] constexpr Sign operator*(Sign a, Sign b) noexcept {
  return static_cast<Sign>(static_cast<int>(a) * static_cast<int>(b));
}

/// -1, 0 or +1.
[[nodiscard]] constexpr int to_int(Sign s) noexcept { return static_cast<int>(s); }

/// The sign of x; NaN gives zero.
template <Real T>
[[nodiscard]] constexpr Sign sign_of(T x) noexcept {
  return static_cast<Sign>(static_cast<int>(x > T(0)) - static_cast<int>(x < T(0)));
}

namespace detail {

// Unit roundoff of binary64 and the stage-A error bounds of the paper (section 6).
inline constexpr double predicate_eps = 0x1p-53;
inline constexpr double orient2d_bound_a = (3.0 + 16.0 * predicate_eps) * predicate_eps;
inline constexpr double orient3d_bound_a = (7.0 + 56.0 * predicate_eps) * predicate_eps;
inline constexpr double incircle_bound_a = (10.0 + 96.0 * predicate_eps) * predicate_eps;
inline constexpr double insphere_bound_a = (16.0 + 224.0 * predicate_eps) * predicate_eps;
// |sum_i (q_i - p_i)^2 - (r_i - p_i)^2| in up to 3 dimensions: each square carries 3 roundings,
// each difference of squares 1, the sum N-1 <= 2; 8 eps leaves room for second-order terms.
inline constexpr double sqr_distance_bound_a = (8.0 + 64.0 * predicate_eps) * predicate_eps;

#if defined(__GNUC__) || defined(__clang__)
#define LOCUS_PREDICATE_COLD [[gnu::cold]]
#else
#define LOCUS_PREDICATE_COLD
#endif

// The slow paths, called only when the filter cannot decide (cold: kept out of hot loops). They
// take double arguments, return the exact sign in OUR conventions, and return Sign::zero for
// non-finite input.
LOCUS_PREDICATE_COLD [[nodiscard]] Sign orient2d_adaptive(const Vec2<double>& a,
                                                          const Vec2<double>& b,
                                                          const Vec2<double>& c) noexcept;
LOCUS_PREDICATE_COLD [[nodiscard]] Sign orient3d_adaptive(const Vec3<double>& a,
                                                          const Vec3<double>& b,
                                                          const Vec3<double>& c,
                                                          const Vec3<double>& d) noexcept;
LOCUS_PREDICATE_COLD [[nodiscard]] Sign incircle_adaptive(const Vec2<double>& a,
                                                          const Vec2<double>& b,
                                                          const Vec2<double>& c,
                                                          const Vec2<double>& d) noexcept;
LOCUS_PREDICATE_COLD [[nodiscard]] Sign insphere_adaptive(const Vec3<double>& a,
                                                          const Vec3<double>& b,
                                                          const Vec3<double>& c,
                                                          const Vec3<double>& d,
                                                          const Vec3<double>& e) noexcept;
/// Exact sign of det[b - a; d - c] (turn2d), expanded into the four 2x2 minors of the points.
LOCUS_PREDICATE_COLD [[nodiscard]] Sign turn2d_exact(const Vec2<double>& a, const Vec2<double>& b,
                                                     const Vec2<double>& c,
                                                     const Vec2<double>& d) noexcept;
/// Exact sign of |q - p|^2 - |r - p|^2 for n = 2 or 3 coordinates per point.
LOCUS_PREDICATE_COLD [[nodiscard]] Sign compare_sqr_distance_exact(const double* p, const double* q,
                                                                   const double* r, int n) noexcept;

template <class T, int N>
[[nodiscard]] constexpr Vec<double, N> to_double(const Vec<T, N>& v) noexcept {
  Vec<double, N> r{};
  for (int i = 0; i < N; ++i) r[i] = static_cast<double>(v[i]);
  return r;
}

/// The sign of a nonzero, non-NaN x, branch-free (a data-dependent branch on random input
/// costs more than the whole filter): one compare and 2 b - 1.
[[nodiscard]] inline Sign nonzero_sign(double x) noexcept {
  return static_cast<Sign>(2 * static_cast<int>(x > 0.0) - 1);
}

// The filters. Strict comparisons: with a non-finite input the bound is +inf or NaN, so no
// determinant can pass and the fallback reports zero.
[[nodiscard]] inline Sign orient2d_filtered(const Vec2<double>& a, const Vec2<double>& b,
                                            const Vec2<double>& c) noexcept {
#if LOCUS_PREDICATES_SSE2
  static_assert(sizeof(Vec2<double>) == 2 * sizeof(double), "Vec2 must be two packed doubles");
  const __m128d ac = _mm_sub_pd(_mm_loadu_pd(&a.x), _mm_loadu_pd(&c.x));  // (acx, acy)
  const __m128d bc = _mm_sub_pd(_mm_loadu_pd(&b.x), _mm_loadu_pd(&c.x));  // (bcx, bcy)
  const __m128d products = _mm_mul_pd(ac, _mm_shuffle_pd(bc, bc, 1));     // (acx bcy, acy bcx)
  const __m128d high = _mm_unpackhi_pd(products, products);
  const double left = _mm_cvtsd_f64(products);
  const double right = _mm_cvtsd_f64(high);
#else
  const double acx = a.x - c.x, bcx = b.x - c.x;
  const double acy = a.y - c.y, bcy = b.y - c.y;
  const double left = acx * bcy;
  const double right = acy * bcx;
#endif
  const double det = left - right;
  // The paper's bound is c (|left| + |right|). When left and right share a sign that equals
  // c |left + right| (rounding is symmetric); when they differ, det cannot change sign and any
  // bound >= 0 decides correctly. One absolute value fewer on the hot path.
  const double bound = orient2d_bound_a * std::abs(left + right);
  if (std::abs(det) > bound) [[likely]]
    return nonzero_sign(det);
  return orient2d_adaptive(a, b, c);
}

// Shewchuk's orient3d, det[a - d; b - d; c - d], and its permanent; our sign is its opposite.
[[nodiscard]] inline Sign orient3d_filtered(const Vec3<double>& a, const Vec3<double>& b,
                                            const Vec3<double>& c, const Vec3<double>& d) noexcept {
  const double adx = a.x - d.x, bdx = b.x - d.x, cdx = c.x - d.x;
  const double ady = a.y - d.y, bdy = b.y - d.y, cdy = c.y - d.y;
  const double adz = a.z - d.z, bdz = b.z - d.z, cdz = c.z - d.z;
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double permanent = (std::abs(bdxcdy) + std::abs(cdxbdy)) * std::abs(adz) +
                           (std::abs(cdxady) + std::abs(adxcdy)) * std::abs(bdz) +
                           (std::abs(adxbdy) + std::abs(bdxady)) * std::abs(cdz);
  const double bound = orient3d_bound_a * permanent;
  if (std::abs(det) > bound) [[likely]]
    return -nonzero_sign(det);
  return orient3d_adaptive(a, b, c, d);
}

// Shewchuk's incircle (the same sign as ours).
[[nodiscard]] inline Sign incircle_filtered(const Vec2<double>& a, const Vec2<double>& b,
                                            const Vec2<double>& c, const Vec2<double>& d) noexcept {
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
  const double bound = incircle_bound_a * permanent;
  if (std::abs(det) > bound) [[likely]]
    return nonzero_sign(det);
  return incircle_adaptive(a, b, c, d);
}

// Shewchuk's insphere, det[p - e, |p - e|^2] over p = a, b, c, d; our sign is its opposite.
struct InsphereTerms {
  double det, permanent;
};
[[nodiscard]] inline InsphereTerms insphere_terms(const Vec3<double>& a, const Vec3<double>& b,
                                                  const Vec3<double>& c, const Vec3<double>& d,
                                                  const Vec3<double>& e) noexcept {
  const double aex = a.x - e.x, bex = b.x - e.x, cex = c.x - e.x, dex = d.x - e.x;
  const double aey = a.y - e.y, bey = b.y - e.y, cey = c.y - e.y, dey = d.y - e.y;
  const double aez = a.z - e.z, bez = b.z - e.z, cez = c.z - e.z, dez = d.z - e.z;
  const double aexbey = aex * bey, bexaey = bex * aey;
  const double bexcey = bex * cey, cexbey = cex * bey;
  const double cexdey = cex * dey, dexcey = dex * cey;
  const double dexaey = dex * aey, aexdey = aex * dey;
  const double aexcey = aex * cey, cexaey = cex * aey;
  const double bexdey = bex * dey, dexbey = dex * bey;
  const double ab = aexbey - bexaey, bc = bexcey - cexbey, cd = cexdey - dexcey;
  const double da = dexaey - aexdey, ac = aexcey - cexaey, bd = bexdey - dexbey;
  const double abc = aez * bc - bez * ac + cez * ab;
  const double bcd = bez * cd - cez * bd + dez * bc;
  const double cda = cez * da + dez * ac + aez * cd;
  const double dab = dez * ab + aez * bd + bez * da;
  const double alift = aex * aex + aey * aey + aez * aez;
  const double blift = bex * bex + bey * bey + bez * bez;
  const double clift = cex * cex + cey * cey + cez * cez;
  const double dlift = dex * dex + dey * dey + dez * dez;
  const double det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
  const double azp = std::abs(aez), bzp = std::abs(bez), czp = std::abs(cez), dzp = std::abs(dez);
  const double ab_p = std::abs(aexbey) + std::abs(bexaey);
  const double bc_p = std::abs(bexcey) + std::abs(cexbey);
  const double cd_p = std::abs(cexdey) + std::abs(dexcey);
  const double da_p = std::abs(dexaey) + std::abs(aexdey);
  const double ac_p = std::abs(aexcey) + std::abs(cexaey);
  const double bd_p = std::abs(bexdey) + std::abs(dexbey);
  const double permanent = (cd_p * bzp + bd_p * czp + bc_p * dzp) * alift +
                           (da_p * czp + ac_p * dzp + cd_p * azp) * blift +
                           (ab_p * dzp + bd_p * azp + da_p * bzp) * clift +
                           (bc_p * azp + ac_p * bzp + ab_p * czp) * dlift;
  return {det, permanent};
}

[[nodiscard]] inline Sign insphere_filtered(const Vec3<double>& a, const Vec3<double>& b,
                                            const Vec3<double>& c, const Vec3<double>& d,
                                            const Vec3<double>& e) noexcept {
  const InsphereTerms t = insphere_terms(a, b, c, d, e);
  const double bound = insphere_bound_a * t.permanent;
  if (std::abs(t.det) > bound) [[likely]]
    return -nonzero_sign(t.det);
  return insphere_adaptive(a, b, c, d, e);
}

}  // namespace detail

/// Exact orientation of the triangle abc: positive iff counter-clockwise (det[b - a; c - a]).
template <Real T>
[[nodiscard]] inline Sign orient2d(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& c) noexcept {
  if constexpr (std::is_same_v<T, double>) {
    return detail::orient2d_filtered(a, b, c);
  } else {
    return detail::orient2d_filtered(detail::to_double(a), detail::to_double(b),
                                     detail::to_double(c));
  }
}

/// Exact side of d relative to plane abc: positive iff d is on the side (b - a) x (c - a)
/// points to (det[b - a; c - a; d - a]; the negation of Shewchuk's orient3d).
template <Real T>
[[nodiscard]] inline Sign orient3d(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c,
                                   const Vec3<T>& d) noexcept {
  if constexpr (std::is_same_v<T, double>) {
    return detail::orient3d_filtered(a, b, c, d);
  } else {
    return detail::orient3d_filtered(detail::to_double(a), detail::to_double(b),
                                     detail::to_double(c), detail::to_double(d));
  }
}

/// Exact in-circle test: positive iff d is strictly inside the circle through a, b, c when
/// a, b, c are counter-clockwise (flips with their orientation; zero when cocircular).
template <Real T>
[[nodiscard]] inline Sign incircle(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& c,
                                   const Vec2<T>& d) noexcept {
  if constexpr (std::is_same_v<T, double>) {
    return detail::incircle_filtered(a, b, c, d);
  } else {
    return detail::incircle_filtered(detail::to_double(a), detail::to_double(b),
                                     detail::to_double(c), detail::to_double(d));
  }
}

/// Exact in-sphere test: positive iff e is strictly inside the sphere through a, b, c, d when
/// orient3d(a, b, c, d) > 0 (flips with that orientation; zero when cospherical).
template <Real T>
[[nodiscard]] inline Sign insphere(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c,
                                   const Vec3<T>& d, const Vec3<T>& e) noexcept {
  if constexpr (std::is_same_v<T, double>) {
    return detail::insphere_filtered(a, b, c, d, e);
  } else {
    return detail::insphere_filtered(detail::to_double(a), detail::to_double(b),
                                     detail::to_double(c), detail::to_double(d),
                                     detail::to_double(e));
  }
}

/// The orient2d determinant evaluated in double (rounded, same sign convention): twice the
/// signed area of abc. Use the sign only through orient2d().
template <Real T>
[[nodiscard]] inline double orient2d_value(const Vec2<T>& a, const Vec2<T>& b,
                                           const Vec2<T>& c) noexcept {
  const double acx = double(a.x) - double(c.x), bcx = double(b.x) - double(c.x);
  const double acy = double(a.y) - double(c.y), bcy = double(b.y) - double(c.y);
  return acx * bcy - acy * bcx;
}

/// The orient3d determinant in double (rounded, our convention): six times the signed volume
/// of the tetrahedron abcd.
template <Real T>
[[nodiscard]] inline double orient3d_value(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c,
                                           const Vec3<T>& d) noexcept {
  const double adx = double(a.x) - double(d.x), bdx = double(b.x) - double(d.x),
               cdx = double(c.x) - double(d.x);
  const double ady = double(a.y) - double(d.y), bdy = double(b.y) - double(d.y),
               cdy = double(c.y) - double(d.y);
  const double adz = double(a.z) - double(d.z), bdz = double(b.z) - double(d.z),
               cdz = double(c.z) - double(d.z);
  return -(adz * (bdx * cdy - cdx * bdy) + bdz * (cdx * ady - adx * cdy) +
           cdz * (adx * bdy - bdx * ady));
}

/// The incircle determinant in double (rounded, same sign convention).
template <Real T>
[[nodiscard]] inline double incircle_value(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& c,
                                           const Vec2<T>& d) noexcept {
  const double adx = double(a.x) - double(d.x), bdx = double(b.x) - double(d.x),
               cdx = double(c.x) - double(d.x);
  const double ady = double(a.y) - double(d.y), bdy = double(b.y) - double(d.y),
               cdy = double(c.y) - double(d.y);
  return (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
         (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
         (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
}

/// The insphere determinant in double (rounded, our convention).
template <Real T>
[[nodiscard]] inline double insphere_value(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c,
                                           const Vec3<T>& d, const Vec3<T>& e) noexcept {
  return -detail::insphere_terms(detail::to_double(a), detail::to_double(b), detail::to_double(c),
                                 detail::to_double(d), detail::to_double(e))
              .det;
}

/// Exact sign of b - a: positive iff a < b. NaN gives zero.
template <Real T>
[[nodiscard]] constexpr Sign orient1d(T a, T b) noexcept {
  return a < b ? Sign::positive : (b < a ? Sign::negative : Sign::zero);
}

/// Three-way lexicographic comparison (x, then y, then z): negative iff p < q, zero iff equal.
/// A NaN coordinate compares equal to everything (it never decides).
template <Real T, int N>
[[nodiscard]] constexpr Sign lexicographic_compare(const Vec<T, N>& p,
                                                   const Vec<T, N>& q) noexcept {
  for (int i = 0; i < N; ++i) {
    if (p[i] < q[i]) return Sign::negative;
    if (q[i] < p[i]) return Sign::positive;
  }
  return Sign::zero;
}

/// Exact sign of det[b - a; d - c] = perp_dot(b - a, d - c): positive iff the direction c -> d is
/// counter-clockwise from a -> b (the turn from one to the other is left, less than a half turn),
/// zero iff they are parallel or one is zero. The two directions need not share a point
/// (orient2d(a, b, c) = turn2d(a, b, a, c)): e.g. whether two segments' lines cross, and on which
/// side, from their end points, without rounding the directions first. Non-finite input gives
/// zero; exact range as orient2d (it has degree 2). The filter is orient2d's: the same two
/// rounded differences per product, so the same stage-A bound.
template <Real T>
[[nodiscard]] inline Sign turn2d(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& c,
                                 const Vec2<T>& d) noexcept {
  const double l = (double(b.x) - double(a.x)) * (double(d.y) - double(c.y));
  const double r = (double(b.y) - double(a.y)) * (double(d.x) - double(c.x));
  const double det = l - r;
  const double bound = detail::orient2d_bound_a * (std::abs(l) + std::abs(r));
  if (std::abs(det) > bound) [[likely]]
    return detail::nonzero_sign(det);
  return detail::turn2d_exact(detail::to_double(a), detail::to_double(b), detail::to_double(c),
                              detail::to_double(d));
}

/// Exact sign of |q - p|^2 - |r - p|^2: positive iff q is farther from p than r is. Non-finite
/// input gives zero; exact range as orient2d (it has degree 2).
template <Real T, int N>
requires(N == 2 || N == 3) [[nodiscard]] inline Sign
    compare_sqr_distance(const Vec<T, N>& p, const Vec<T, N>& q, const Vec<T, N>& r) noexcept {
  double value = 0.0, permanent = 0.0;
  for (int i = 0; i < N; ++i) {
    const double dq = double(q[i]) - double(p[i]);
    const double dr = double(r[i]) - double(p[i]);
    const double q2 = dq * dq, r2 = dr * dr;
    value += q2 - r2;
    permanent += q2 + r2;
  }
  const double bound = detail::sqr_distance_bound_a * permanent;
  if (value > bound) return Sign::positive;
  if (-value > bound) return Sign::negative;
  double pd[N], qd[N], rd[N];
  for (int i = 0; i < N; ++i) {
    pd[i] = double(p[i]);
    qd[i] = double(q[i]);
    rd[i] = double(r[i]);
  }
  return detail::compare_sqr_distance_exact(pd, qd, rd, N);
}

}  // namespace locus
