// SPDX-License-Identifier: BSL-1.0
#pragma once
// Exact geometric predicates: orient2d, orient3d, incircle, insphere, and small exact helpers
// (orient1d, lexicographic_compare, compare_sqr_distance, turn2d). CAPABILITIES row
// core.predicates.
//
// Each predicate returns the *exact* sign of a polynomial in the input coordinates. A fast
// inline filter (core/detail/predicate_filters.hpp, shared with the algorithms) evaluates the
// determinant in double and accepts its sign when it exceeds a static error bound times the
// permanent (the same determinant with absolute values), as in J. R. Shewchuk, "Adaptive
// Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates" (1997), stage A.
// Otherwise, after an exact lattice shortcut for grid input (orient3d, incircle, insphere), it
// calls detail::*_adaptive (src/core/predicates.cpp,
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

#include <locus/config.hpp>
#include <locus/core/detail/predicate_filters.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>

#include <cmath>
#include <cstdint>
#include <optional>
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

namespace detail {

// The slow paths, called only when the filter cannot decide (cold: kept out of hot loops). They
// take double arguments, return the exact sign in OUR conventions, and return Sign::zero for
// non-finite input.
[[nodiscard]] LOCUS_COLD Sign orient2d_adaptive(const Vec2<double>& a, const Vec2<double>& b,
                                                const Vec2<double>& c) noexcept;
[[nodiscard]] LOCUS_COLD Sign orient3d_adaptive(const Vec3<double>& a, const Vec3<double>& b,
                                                const Vec3<double>& c,
                                                const Vec3<double>& d) noexcept;
[[nodiscard]] LOCUS_COLD Sign incircle_adaptive(const Vec2<double>& a, const Vec2<double>& b,
                                                const Vec2<double>& c,
                                                const Vec2<double>& d) noexcept;
[[nodiscard]] LOCUS_COLD Sign insphere_adaptive(const Vec3<double>& a, const Vec3<double>& b,
                                                const Vec3<double>& c, const Vec3<double>& d,
                                                const Vec3<double>& e) noexcept;
/// Exact sign of det[b - a; d - c] (turn2d), expanded into the four 2x2 minors of the points.
[[nodiscard]] LOCUS_COLD Sign turn2d_exact(const Vec2<double>& a, const Vec2<double>& b,
                                           const Vec2<double>& c, const Vec2<double>& d) noexcept;
/// Exact sign of |q - p|^2 - |r - p|^2 for n = 2 or 3 coordinates per point.
[[nodiscard]] LOCUS_COLD Sign compare_sqr_distance_exact(const double* p, const double* q,
                                                         const double* r, int n) noexcept;

// After a failed filter: the lattice shortcut (exactly degenerate grids decide in a few ns
// instead of the adaptive stages' 0.1-3 us), then the adaptive stages. Cold and out of line.
[[nodiscard]] LOCUS_COLD inline Sign orient3d_slow(const Vec3<double>& a, const Vec3<double>& b,
                                                   const Vec3<double>& c,
                                                   const Vec3<double>& d) noexcept {
  if (const std::optional<Sign> s = orient3d_lattice(a, b, c, d)) return *s;
  return orient3d_adaptive(a, b, c, d);
}
[[nodiscard]] LOCUS_COLD inline Sign incircle_slow(const Vec2<double>& a, const Vec2<double>& b,
                                                   const Vec2<double>& c,
                                                   const Vec2<double>& d) noexcept {
  if (const std::optional<Sign> s = incircle_lattice(a, b, c, d)) return *s;
  return incircle_adaptive(a, b, c, d);
}
[[nodiscard]] LOCUS_COLD inline Sign insphere_slow(const Vec3<double>& a, const Vec3<double>& b,
                                                   const Vec3<double>& c, const Vec3<double>& d,
                                                   const Vec3<double>& e) noexcept {
  if (const std::optional<InsphereTerms> t = insphere_lattice(a, b, c, d, e))
    return -sign_of(t->det);
  return insphere_adaptive(a, b, c, d, e);
}

// The filtered predicates: stage A (core/detail/predicate_filters.hpp), else the slow path.
[[nodiscard]] inline Sign orient2d_filtered(const Vec2<double>& a, const Vec2<double>& b,
                                            const Vec2<double>& c) noexcept {
#if LOCUS_PREDICATES_SSE2
  static_assert(sizeof(Vec2<double>) == 2 * sizeof(double), "Vec2 must be two packed doubles");
  const __m128d ac = _mm_sub_pd(_mm_loadu_pd(&a.x), _mm_loadu_pd(&c.x));  // (acx, acy)
  const __m128d bc = _mm_sub_pd(_mm_loadu_pd(&b.x), _mm_loadu_pd(&c.x));  // (bcx, bcy)
  const __m128d products = _mm_mul_pd(ac, _mm_shuffle_pd(bc, bc, 1));     // (acx bcy, acy bcx)
  const __m128d high = _mm_unpackhi_pd(products, products);
  const StageA<double> f = det2_stage_a(_mm_cvtsd_f64(products), _mm_cvtsd_f64(high));
#else
  const StageA<double> f = orient2d_stage_a(a, b, c);
#endif
  if (certain(f)) [[likely]]
    return nonzero_sign(f.det);
  return orient2d_adaptive(a, b, c);
}

[[nodiscard]] inline Sign orient3d_filtered(const Vec3<double>& a, const Vec3<double>& b,
                                            const Vec3<double>& c, const Vec3<double>& d) noexcept {
  const StageA<double> f = orient3d_stage_a(a, b, c, d);
  if (certain(f)) [[likely]]
    return nonzero_sign(f.det);
  return orient3d_slow(a, b, c, d);
}

[[nodiscard]] inline Sign incircle_filtered(const Vec2<double>& a, const Vec2<double>& b,
                                            const Vec2<double>& c, const Vec2<double>& d) noexcept {
  const StageA<double> f = incircle_stage_a(a, b, c, d);
  if (certain(f)) [[likely]]
    return nonzero_sign(f.det);
  return incircle_slow(a, b, c, d);
}

[[nodiscard]] inline Sign insphere_filtered(const Vec3<double>& a, const Vec3<double>& b,
                                            const Vec3<double>& c, const Vec3<double>& d,
                                            const Vec3<double>& e) noexcept {
  const StageA<double> f = insphere_stage_a(a, b, c, d, e);
  if (certain(f)) [[likely]]
    return nonzero_sign(f.det);
  return insphere_slow(a, b, c, d, e);
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
  return detail::orient2d_stage_a(detail::to_double(a), detail::to_double(b), detail::to_double(c))
      .det;
}

/// The orient3d determinant in double (rounded, our convention): six times the signed volume
/// of the tetrahedron abcd.
template <Real T>
[[nodiscard]] inline double orient3d_value(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c,
                                           const Vec3<T>& d) noexcept {
  return detail::orient3d_stage_a(detail::to_double(a), detail::to_double(b), detail::to_double(c),
                                  detail::to_double(d))
      .det;
}

/// The incircle determinant in double (rounded, same sign convention).
template <Real T>
[[nodiscard]] inline double incircle_value(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& c,
                                           const Vec2<T>& d) noexcept {
  return detail::incircle_stage_a(detail::to_double(a), detail::to_double(b), detail::to_double(c),
                                  detail::to_double(d))
      .det;
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
  const detail::StageA<double> f =
      detail::det2_stage_a((double(b.x) - double(a.x)) * (double(d.y) - double(c.y)),
                           (double(b.y) - double(a.y)) * (double(d.x) - double(c.x)));
  if (detail::certain(f)) [[likely]]
    return detail::nonzero_sign(f.det);
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
