// SPDX-License-Identifier: BSL-1.0
#pragma once
// Exact geometric predicates: orient2d, orient3d, incircle, insphere, and small exact helpers
// (orient1d, lexicographic_compare, compare_sqr_distance, turn2d). CAPABILITIES row
// core.predicates; book chapter 13 (figure 13.35: orient2d plus lexicographic_compare).
// Each returns the exact sign of a polynomial in the coordinates: a double filter (Shewchuk 1997,
// stage A; core/detail/predicate_filters.hpp), then adaptive expansion stages
// (src/core/predicates.cpp); float input is promoted to double exactly. Method and the proof of
// the range below: docs/notes/core.md.
// Sign conventions (fixed; the library's combinatorial code relies on them):
//   orient2d(a, b, c)       > 0 iff a, b, c are counter-clockwise: sign of det[b - a; c - a].
//   orient3d(a, b, c, d)    > 0 iff d is on the side of plane abc toward which (b - a) x (c - a)
//                           points: sign of det[b - a; c - a; d - a] (NEGATION of Shewchuk's).
//   incircle(a, b, c, d)    > 0 iff d is strictly inside the circle through a, b, c when
//                           orient2d(a, b, c) > 0 (the sign flips with that orientation).
//   insphere(a, b, c, d, e) > 0 iff e is strictly inside the sphere through a, b, c, d when
//                           orient3d(a, b, c, d) > 0 in OUR convention (NEGATION of Shewchuk's).
//   turn2d(a, b, c, d)      > 0 iff c -> d turns counter-clockwise from a -> b: det[b - a; d - c].
// All are zero exactly on degenerate configurations, flip sign under an odd permutation, and are
// invariant under translation and positive scaling. A NaN or infinite coordinate gives
// Sign::zero (void if the caller is compiled with -ffast-math; FMA contraction is harmless).
// Exactness: every finite float. Double: exact when every nonzero |c| >= 2^-L and
// |c| >= 2^-(L - 32) M (M the largest |coordinate|, no upper limit), L = 480 orient2d (also
// turn2d, compare_sqr_distance), 300 orient3d, 210 incircle, 160 insphere. Outside that range a
// deterministic Sign with no UB or hang, possibly wrong.
// Cost: the filter costs little more than the naive determinant; the fallback runs only near
// degeneracy. No allocation; insphere's fallback uses up to about 140 KB of stack.

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
