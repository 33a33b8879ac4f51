// SPDX-License-Identifier: BSL-1.0
#pragma once
// Internal machinery of the linear-box distance headers (line/ray/segment to aligned and
// oriented boxes, 2D and 3D); row dist3.linear-obb (and its 2D analogue); book section 10.9.4
// (figures 10.46-10.52). Why this replaces the book's case analysis: docs/notes/distance.md.
//
// In the box's frame (the identity for an aligned box; the box axes for an oriented one) the box
// is the product of slabs [lo_i, hi_i] and the linear component is x(t) = p + t d with t in its
// domain (line: R, ray: [0, inf), segment: [0, 1]). The squared distance from x(t) to the box is
//   f(t) = sum_i e_i(t)^2,  e_i(t) = x_i(t) - clamp(x_i(t), lo_i, hi_i)   (the excess over slab i),
// a convex, C1, piecewise quadratic function of t with breakpoints (lo_i - p_i) / d_i and
// (hi_i - p_i) / d_i. Its derivative g(t) = 2 sum_i d_i e_i(t) is continuous, piecewise linear
// and non-decreasing: the breakpoints inside the domain are sorted, the sign of g evaluated at
// each, and g = 0 solved in closed form on the piece where it changes sign (or the minimum is at
// a domain end). A zero direction component gives no breakpoint (a tiny one gives far or
// infinite ones), so the answer is continuous as a component passes through 0.
//
// Uniqueness: f is constant exactly on a piece where every coordinate with d_i != 0 is inside its
// slab; such a piece of positive length is the set of minimisers (the line passes through the
// box, or runs parallel to a face or edge while its projection meets it); components below
// 8 eps |d| count as zero for this test. Then unique = false and the midpoint of that piece
// (clipped to the domain) is returned. A zero direction (or a zero-length segment) is the point
// p at t = 0. Cost: at most 2 N + 2 breakpoints, an insertion sort, O(N) per breakpoint; no
// allocation.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/linear.hpp>
#include <locus/distance/point_aligned_box.hpp>
#include <locus/distance/point_oriented_box.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/aligned_box.hpp>
#include <locus/primitives/oriented_box.hpp>

#include <cmath>
#include <limits>

namespace locus::detail {

template <Real T>
struct LinearBoxParam {
  T t;
  bool unique;
};

/// Parameter t of a point of x(t) = p + t d, t in [0 if bounded_lo, 1 if bounded_hi], closest to
/// the box prod_i [lo_i, hi_i] (frame coordinates; lo_i <= hi_i; finite input). See the header.
template <class T, int N>
[[nodiscard]] inline LinearBoxParam<T> linear_box_param(const Vec<T, N>& p, const Vec<T, N>& d,
                                                        const Vec<T, N>& lo, const Vec<T, N>& hi,
                                                        bool bounded_lo, bool bounded_hi) noexcept {
  constexpr T inf = std::numeric_limits<T>::infinity();
  if (!(max_abs(d) > T(0))) return {T(0), true};
  const T tlo = bounded_lo ? T(0) : -inf, thi = bounded_hi ? T(1) : inf;

  // Per coordinate: the parameters where x_i enters and leaves its slab (d_i != 0). Quotients
  // that overflow become +-inf, which the interval comparisons below treat correctly (the
  // coordinate then keeps one state over every finite piece).
  T enter[N], leave[N];
  T cuts[2 * N + 2];
  int m = 0;
  if (bounded_lo) cuts[m++] = tlo;
  for (int i = 0; i < N; ++i) {
    enter[i] = -inf;
    leave[i] = inf;
    if (d[i] == T(0)) continue;
    const T ta = (lo[i] - p[i]) / d[i], tb = (hi[i] - p[i]) / d[i];
    enter[i] = ta < tb ? ta : tb;
    leave[i] = ta < tb ? tb : ta;
    if (enter[i] > tlo && enter[i] < thi) cuts[m++] = enter[i];
    if (leave[i] > tlo && leave[i] < thi) cuts[m++] = leave[i];
  }
  if (bounded_hi) cuts[m++] = thi;
  for (int i = 1; i < m; ++i)  // insertion sort: at most 2 N + 2 values
    for (int j = i; j > 0 && cuts[j] < cuts[j - 1]; --j) {
      const T x = cuts[j];
      cuts[j] = cuts[j - 1];
      cuts[j - 1] = x;
    }

  // The linear piece g(t)/2 = A t + B on an open interval (a, b) that contains no breakpoint;
  // returns false when every moving coordinate is inside its slab there (A = 0: f is flat).
  // Components below 8 eps |d|_max (rounding noise of a frame change: a direction that is
  // parallel to a face up to rounding) do not count as moving for this flatness test; their
  // excess changes by less than that fraction of the piece's length, so f is flat to rounding.
  const T tiny = T(8) * eps_v<T> * max_abs(d);
  const auto piece = [&](T a, T b, T& A, T& B) {
    A = T(0);
    B = T(0);
    bool moving_outside = false;
    for (int i = 0; i < N; ++i) {
      if (d[i] == T(0)) continue;  // constant excess: no slope, no breakpoint
      int state = 0;               // -1 below lo, +1 above hi
      if (b <= enter[i])
        state = d[i] > T(0) ? -1 : 1;
      else if (a >= leave[i])
        state = d[i] > T(0) ? 1 : -1;
      if (state == 0) continue;
      if (std::abs(d[i]) > tiny) moving_outside = true;
      A += d[i] * d[i];
      B += d[i] * (p[i] - (state < 0 ? lo[i] : hi[i]));
    }
    return moving_outside;
  };
  const auto slope_at = [&](T t) {  // g(t)/2
    T s = T(0);
    for (int i = 0; i < N; ++i) {
      const T x = p[i] + t * d[i];
      if (x < lo[i])
        s += d[i] * (x - lo[i]);
      else if (x > hi[i])
        s += d[i] * (x - hi[i]);
    }
    return s;
  };

  // Flat piece (the minimisers form an interval): the pieces are (-inf, c0), (c0, c1), ...,
  // (c_{m-1}, inf) restricted to the domain.
  {
    T A, B;
    for (int k = 0; k <= m; ++k) {
      const T a = k == 0 ? (bounded_lo ? inf : -inf) : cuts[k - 1];
      const T b = k == m ? (bounded_hi ? -inf : inf) : cuts[k];
      if (!(a < b)) continue;  // empty piece (outside the domain, or repeated breakpoint)
      if (piece(a, b, A, B)) continue;
      T t;
      if (is_finite(a) && is_finite(b))
        t = a * T(0.5) + b * T(0.5);
      else if (is_finite(a))
        t = a;
      else if (is_finite(b))
        t = b;
      else
        t = T(0);
      return {t, false};
    }
  }

  // The first breakpoint where g >= 0 ends the piece holding the minimum.
  int k = 0;
  while (k < m && slope_at(cuts[k]) < T(0)) ++k;
  if (k == 0 && bounded_lo) return {tlo, true};  // g(tlo) >= 0: minimum at the lower end
  if (k == m && bounded_hi) return {thi, true};  // g < 0 on the whole domain
  const T a = k == 0 ? -inf : cuts[k - 1];
  const T b = k == m ? inf : cuts[k];
  T A, B;
  piece(a, b, A, B);
  T t = A > T(0) ? -B / A : std::numeric_limits<T>::quiet_NaN();
  if (!is_finite(t)) t = is_finite(b) ? b : (is_finite(a) ? a : T(0));
  if (t < a) t = a;
  if (t > b) t = b;
  return {t, true};
}

/// distance(l, box) for a line, ray or segment and an aligned box: the parameter is found in
/// the box's coordinates, and the pair is (l(t), the box point closest to l(t)).
template <class T, int N, class L>
[[nodiscard]] inline Distance<T, N, T, Vec<T, N>> linear_aligned_box_distance(
    const L& l, const AlignedBox<T, N>& box) noexcept {
  if (!finite_input(l) || !is_finite(box.min) || !is_finite(box.max) || is_empty(box))
    return non_finite_distance<T, N, T, Vec<T, N>>();
  const LinearView<T, N> v = view(l);
  const LinearBoxParam<T> s =
      linear_box_param(v.origin, v.dir, box.min, box.max, v.bounded_lo, v.bounded_hi);
  const Vec<T, N> x = point_at(l, s.t);
  const auto q = distance(x, box);
  return make_distance(x, q.closest[1], s.t, q.param_b, s.unique);
}

/// distance(l, box) for a line, ray or segment and an oriented box (a negative extent counts as
/// 0, as in point_oriented_box.hpp).
template <class T, int N, class L>
[[nodiscard]] inline Distance<T, N, T, Vec<T, N>> linear_oriented_box_distance(
    const L& l, const OrientedBox<T, N>& box) noexcept {
  bool finite = finite_input(l) && is_finite(box.center) && is_finite(box.extent);
  for (int i = 0; i < N; ++i) finite = finite && is_finite(box.axis[i]);
  if (!finite) return non_finite_distance<T, N, T, Vec<T, N>>();
  const LinearView<T, N> v = view(l);
  const Vec<T, N> r = v.origin - box.center;
  Vec<T, N> p{}, d{}, e{};
  for (int i = 0; i < N; ++i) {
    p[i] = dot(r, box.axis[i]);
    d[i] = dot(v.dir, box.axis[i]);
    e[i] = box.extent[i] > T(0) ? box.extent[i] : T(0);
  }
  const LinearBoxParam<T> s = linear_box_param(p, d, -e, e, v.bounded_lo, v.bounded_hi);
  const Vec<T, N> x = point_at(l, s.t);
  const auto q = distance(x, box);
  return make_distance(x, q.closest[1], s.t, q.param_b, s.unique);
}

}  // namespace locus::detail
