// SPDX-License-Identifier: BSL-1.0
#pragma once
// Exact side-of-ball tests for the smallest enclosing ball (rows cg.minball, cg.balls; private
// to locus::detail).
//
// A ball in Welzl's algorithm is the smallest ball having its 1..D+1 support points on the
// boundary. Whether a point p is strictly outside it is a polynomial sign in the coordinates:
//   2 supports a, b (diametral ball):     sign((p - a) . (p - b))                   degree 2
//   3 supports in 2D (circumcircle):      -incircle(a, b, c, p) * orient2d(a, b, c)
//   3 supports in 3D (diametral sphere of the circumcircle of abc, centre in the plane abc):
//       with u = b - a, v = c - a, q = p - a, w = u x v, X = |u|^2 (v x w) + |v|^2 (w x u):
//       sign(|w|^2 |q|^2 - q . X)  (= 2 |w|^2 (|p - o|^2 - r^2) / 2, o = a + X / (2 |w|^2))  degree
//       6
//   4 supports in 3D (circumsphere):      -insphere(a, b, c, d, p) * orient3d(a, b, c, d)
// The degree-2 and degree-6 signs use a floating-point filter (the value and an a-priori error
// bound c eps * permanent, c = 8 and 64, well above the gamma_k of the at most 12 sequential
// roundings) and fall back to exact big-integer arithmetic (src/bounding/ball_predicates.cpp)
// when the filter cannot decide or the permanent is so small that underflow could break the
// bound. The big-integer path is exact for every finite double, so the decisions are exact
// for all finite float and double input. Non-finite input gives Sign::zero.

#include <locus/core/predicates.hpp>
#include <locus/core/vec.hpp>

#include <cmath>

namespace locus::detail {

/// Exact sign of (p - a) . (p - b) for n = 2 or 3 coordinates (big-integer arithmetic).
[[nodiscard]] Sign diametral_side_exact(const double* p, const double* a, const double* b,
                                        int n) noexcept;
/// Exact sign of (b - a) . (d - c) for n = 2 or 3 coordinates (big-integer arithmetic).
[[nodiscard]] Sign dot_differences_exact(const double* a, const double* b, const double* c,
                                         const double* d, int n) noexcept;
/// Exact sign of |w|^2 |q|^2 - q . X (see the header comment), 3D.
[[nodiscard]] Sign circumcircle_sphere_side_exact(const double* a, const double* b, const double* c,
                                                  const double* p) noexcept;

// Below this permanent the filter's relative bound may fail through underflow.
inline constexpr double ball_filter_min_permanent = 0x1p-900;

/// Sign of (p - a) . (p - b): positive iff p is strictly outside the ball with diameter ab.
template <int N>
[[nodiscard]] inline Sign diametral_side(const Vec<double, N>& p, const Vec<double, N>& a,
                                         const Vec<double, N>& b) noexcept {
  double value = 0.0, permanent = 0.0;
  for (int i = 0; i < N; ++i) {
    const double da = p[i] - a[i], db = p[i] - b[i];
    value += da * db;
    permanent += std::abs(da * db);
  }
  const double bound = 8.0 * predicate_eps * permanent;
  if (std::abs(value) > bound && permanent > ball_filter_min_permanent && bound < 1e300) [[likely]]
    return value > 0.0 ? Sign::positive : Sign::negative;
  return diametral_side_exact(&p[0], &a[0], &b[0], N);
}

/// Exact sign of (b - a) . (d - c) (the calipers of bounding/min_rect2.hpp).
template <int N>
[[nodiscard]] inline Sign dot_differences(const Vec<double, N>& a, const Vec<double, N>& b,
                                          const Vec<double, N>& c,
                                          const Vec<double, N>& d) noexcept {
  double value = 0.0, permanent = 0.0;
  for (int i = 0; i < N; ++i) {
    const double u = b[i] - a[i], v = d[i] - c[i];
    value += u * v;
    permanent += std::abs(u * v);
  }
  const double bound = 8.0 * predicate_eps * permanent;
  if (std::abs(value) > bound && permanent > ball_filter_min_permanent && bound < 1e300) [[likely]]
    return value > 0.0 ? Sign::positive : Sign::negative;
  return dot_differences_exact(&a[0], &b[0], &c[0], &d[0], N);
}

/// Positive iff p is strictly outside the smallest sphere through a, b, c (3D, abc not
/// collinear); zero on it.
[[nodiscard]] inline Sign circumcircle_sphere_side(const Vec3<double>& a, const Vec3<double>& b,
                                                   const Vec3<double>& c,
                                                   const Vec3<double>& p) noexcept {
  const Vec3<double> u = b - a, v = c - a, q = p - a;
  const Vec3<double> au = cwise_abs(u), av = cwise_abs(v), aq = cwise_abs(q);
  const Vec3<double> w = cross(u, v);
  const Vec3<double> pw{au.y * av.z + au.z * av.y, au.z * av.x + au.x * av.z,
                        au.x * av.y + au.y * av.x};
  const double uu = sqr_length(u), vv = sqr_length(v), qq = sqr_length(q);
  const Vec3<double> vw = cross(v, w), wu = cross(w, u);
  const Vec3<double> pvw{av.y * pw.z + av.z * pw.y, av.z * pw.x + av.x * pw.z,
                         av.x * pw.y + av.y * pw.x};
  const Vec3<double> pwu{pw.y * au.z + pw.z * au.y, pw.z * au.x + pw.x * au.z,
                         pw.x * au.y + pw.y * au.x};
  const Vec3<double> x = uu * vw + vv * wu;
  const Vec3<double> px = uu * pvw + vv * pwu;
  const double value = sqr_length(w) * qq - dot(q, x);
  const double permanent = sqr_length(pw) * qq + dot(aq, px);
  const double bound = 64.0 * predicate_eps * permanent;
  if (std::abs(value) > bound && permanent > ball_filter_min_permanent && bound < 1e300) [[likely]]
    return value > 0.0 ? Sign::positive : Sign::negative;
  return circumcircle_sphere_side_exact(&a.x, &b.x, &c.x, &p.x);
}

}  // namespace locus::detail
