// SPDX-License-Identifier: BSL-1.0
#pragma once
// Shared engine of the 3D box pairs (row int3.boxes; book sections 11.12-11.14): slab clipping of
// a linear component against an aligned box with exact comparisons of slab parameters, the
// plane-box side, box-box and box-sphere tests. Internal: include a pair header. Derivations:
// docs/notes/intersection.md ("3D boxes").

#include <locus/core/exact_sum.hpp>
#include <locus/core/plane_side.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/result.hpp>
#include <locus/intersection/detail/linear3.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/aligned_box.hpp>
#include <locus/primitives/oriented_box.hpp>
#include <locus/primitives/sphere.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace locus {

/// The result of intersection() of a Line3, Ray3 or Segment3 with an AlignedBox3 or
/// OrientedBox3: the part inside the box (param_b NoParam).
template <Real T>
using LinearBoxIntersection = Intersection<T, 3, T, NoParam, 2>;

namespace detail::box3 {

using V = Vec3<double>;
using linear3::Lin;
using Result = Intersection<double, 3, double, NoParam, 2>;

/// D_k, the k-th direction component: exact d_k, or q_k - o_k (rounded) for a segment.
[[nodiscard]] inline double dir(const Lin& l, int k) noexcept {
  return l.hi ? l.q[k] - l.o[k] : l.d[k];
}
/// Exact sign of D_k.
[[nodiscard]] inline int dir_sign(const Lin& l, int k) noexcept {
  const double a = l.hi ? l.q[k] : l.d[k], b = l.hi ? l.o[k] : 0.0;
  return a > b ? 1 : (a < b ? -1 : 0);
}

/// A bound on the parameter: t = (v - o_axis) / D_axis (axis >= 0), t = 0 (axis -1) or t = 1
/// (axis -2).
struct Bound {
  int axis;
  double v;
};

/// Exact sign of (a - o_i) D_j - (b - o_j) D_i (D as in dir()).
[[nodiscard]] inline int cross_sign(const Lin& l, int i, double a, int j, double b) noexcept {
  const double ai = a - l.o[i], bj = b - l.o[j];
  const double p = ai * dir(l, j), q = bj * dir(l, i);
  const double mag = std::abs(p) + std::abs(q);
  // Four roundings of relative size 2^-53 before the last subtraction (differences, D's,
  // products), one in it: below 8 * 2^-53 of mag.
  if (mag > 0x1p-960 && mag < 0x1p1000 && std::abs(p - q) > 9e-16 * mag) return p > q ? 1 : -1;
  // (a - o_i)(Q_j - R_j) - (b - o_j)(Q_i - R_i), Q - R = q - o (segment) or d - 0.
  const double qi = l.hi ? l.q[i] : l.d[i], qj = l.hi ? l.q[j] : l.d[j];
  const double ri = l.hi ? l.o[i] : 0.0, rj = l.hi ? l.o[j] : 0.0;
  const ExactMonomial m[8] = {{1, 0, 2, {a, qj, 0, 0}},       {-1, 0, 2, {a, rj, 0, 0}},
                              {-1, 0, 2, {l.o[i], qj, 0, 0}}, {1, 0, 2, {l.o[i], rj, 0, 0}},
                              {-1, 0, 2, {b, qi, 0, 0}},      {1, 0, 2, {b, ri, 0, 0}},
                              {1, 0, 2, {l.o[j], qi, 0, 0}},  {-1, 0, 2, {l.o[j], ri, 0, 0}}};
  return exact_sign_of_sum(m);
}

/// Exact sign of t(x) - t(y).
[[nodiscard]] inline int compare(const Lin& l, const Bound& x, const Bound& y) noexcept {
  if (x.axis < 0 && y.axis < 0) return x.axis == y.axis ? 0 : (x.axis == -2 ? 1 : -1);
  if (x.axis < 0) return -compare(l, y, x);
  const int si = dir_sign(l, x.axis);
  if (y.axis == -1) {  // t = (v - o) / D against 0
    const double v = x.v, o = l.o[x.axis];
    return (v > o ? 1 : (v < o ? -1 : 0)) * si;
  }
  if (y.axis == -2) {  // against 1: (v - o) / (q - o) - 1 has the sign of (v - q) / D
    const double v = x.v, q = l.q[x.axis];
    return (v > q ? 1 : (v < q ? -1 : 0)) * si;
  }
  return cross_sign(l, x.axis, x.v, y.axis, y.v) * si * dir_sign(l, y.axis);
}

[[nodiscard]] inline double value(const Lin& l, const Bound& b) noexcept {
  if (b.axis < 0) return b.axis == -1 ? 0.0 : 1.0;
  return (b.v - l.o[b.axis]) / dir(l, b.axis);
}

/// The point at a bound, on the box: its own coordinate exact, the others clamped into the box.
[[nodiscard]] inline V point_at_bound(const Lin& l, const Bound& b, double t, const V& lo,
                                      const V& hi) noexcept {
  V p = b.axis == -1 ? l.o : (b.axis == -2 ? l.q : linear3::at(l, t));
  for (int k = 0; k < 3; ++k) p[k] = std::clamp(p[k], lo[k], hi[k]);
  if (b.axis >= 0) p[b.axis] = b.v;
  return p;
}

/// Slab clipping against [lo, hi] with exact decisions (see ray_aligned_box.hpp).
template <bool Construct>
[[nodiscard]] inline Result clip(const Lin& l, const V& lo, const V& hi) noexcept {
  Result r;
  if (!linear3::finite(l) || !linear3::finite(lo) || !linear3::finite(hi)) return r;
  for (int k = 0; k < 3; ++k)
    if (!(lo[k] <= hi[k])) return r;
  Bound enter{-3, 0}, leave{-3, 0};  // -3: unbounded
  if (l.lo) enter = {-1, 0};
  if (l.hi) leave = {-2, 0};
  bool moving = false;
  for (int k = 0; k < 3; ++k) {
    const int s = dir_sign(l, k);
    if (s == 0) {
      if (l.o[k] < lo[k] || l.o[k] > hi[k]) return r;
      continue;
    }
    moving = true;
    const Bound e{k, s > 0 ? lo[k] : hi[k]}, x{k, s > 0 ? hi[k] : lo[k]};
    if (enter.axis == -3 || compare(l, e, enter) > 0) enter = e;
    if (leave.axis == -3 || compare(l, x, leave) < 0) leave = x;
  }
  if (!moving) {  // a point inside the box
    r.kind = Kind::point;
    r.count = 1;
    r.point[0] = l.o;
    return r;
  }
  const int c = compare(l, enter, leave);
  if (c > 0) return r;
  r.kind = c == 0 ? Kind::point : Kind::segment;
  r.count = c == 0 ? 1 : 2;
  if constexpr (Construct) {
    const double t0 = value(l, enter), t1 = c == 0 ? t0 : std::max(t0, value(l, leave));
    r.param_a = {t0, t1};
    r.point = {point_at_bound(l, enter, t0, lo, hi), point_at_bound(l, leave, t1, lo, hi)};
    if (c == 0) r.point[0] = point_at_bound(l, enter, t0, lo, hi);
  }
  return r;
}

template <Real T>
[[nodiscard]] inline Result aligned(const Lin& l, const AlignedBox3<T>& b,
                                    bool construct) noexcept {
  return construct ? clip<true>(l, vec_cast<double>(b.min), vec_cast<double>(b.max))
                   : clip<false>(l, vec_cast<double>(b.min), vec_cast<double>(b.max));
}

/// Coordinates of p in the box frame: dot(p - center, axis_k) (rounded).
template <Real T>
[[nodiscard]] inline V to_box(const OrientedBox3<T>& b, const V& p) noexcept {
  const V w = p - vec_cast<double>(b.center);
  return {dot(w, vec_cast<double>(b.axis[0])), dot(w, vec_cast<double>(b.axis[1])),
          dot(w, vec_cast<double>(b.axis[2]))};
}
template <Real T>
[[nodiscard]] inline V dir_to_box(const OrientedBox3<T>& b, const V& d) noexcept {
  return {dot(d, vec_cast<double>(b.axis[0])), dot(d, vec_cast<double>(b.axis[1])),
          dot(d, vec_cast<double>(b.axis[2]))};
}
template <Real T>
[[nodiscard]] inline V from_box(const OrientedBox3<T>& b, const V& s) noexcept {
  return vec_cast<double>(b.center) + s.x * vec_cast<double>(b.axis[0]) +
         s.y * vec_cast<double>(b.axis[1]) + s.z * vec_cast<double>(b.axis[2]);
}

template <Real T>
[[nodiscard]] inline Result oriented(const Lin& l, const OrientedBox3<T>& b,
                                     bool construct) noexcept {
  Result r;
  const V e = vec_cast<double>(b.extent);
  if (!linear3::finite(l) || !linear3::finite(e) || !is_finite(b.center) || !is_finite(b.axis[0]) ||
      !is_finite(b.axis[1]) || !is_finite(b.axis[2]))
    return r;
  Lin m = l;
  m.o = to_box(b, l.o);
  if (l.hi) {
    m.q = to_box(b, l.q);
    m.d = m.q - m.o;
  } else {
    m.d = dir_to_box(b, l.d);
  }
  r = construct ? clip<true>(m, -1.0 * e, e) : clip<false>(m, -1.0 * e, e);
  if (construct)
    for (std::size_t i = 0; i < static_cast<std::size_t>(r.count); ++i) {
      const double t = r.param_a[i];
      r.point[i] = (t == 0.0 && l.lo) ? l.o : ((t == 1.0 && l.hi) ? l.q : from_box(b, r.point[i]));
    }
  return r;
}

}  // namespace detail::box3
}  // namespace locus

namespace locus::detail::box3 {

/// Exact sign of the plane function over an aligned box given by its extreme corners: +1 (the
/// box lies strictly on the positive side), -1 (strictly negative), 0 (they meet).
[[nodiscard]] inline int plane_side_of_corners(const V& n, double c, const V& pmin,
                                               const V& pmax) noexcept {
  if (side_of_plane(n, c, pmin) == Sign::positive) return 1;
  if (side_of_plane(n, c, pmax) == Sign::negative) return -1;
  return 0;
}

/// Exact sign of sum_k (c_k - clamp(c_k, lo_k, hi_k))^2 - r^2 (the squared distance from the
/// centre to the box against the squared radius).
[[nodiscard]] inline int sphere_box_sign(const V& c, double r, const V& lo, const V& hi) noexcept {
  double d2 = 0, mag = r * r;
  ExactMonomial m[10];
  int n = 0;
  for (int k = 0; k < 3; ++k) {
    const double b = c[k] < lo[k] ? lo[k] : (c[k] > hi[k] ? hi[k] : c[k]);
    if (b == c[k]) continue;
    const double diff = c[k] - b;
    d2 += diff * diff;
    m[n++] = {1, 0, 2, {c[k], c[k], 0, 0}};
    m[n++] = {-1, 1, 2, {c[k], b, 0, 0}};
    m[n++] = {1, 0, 2, {b, b, 0, 0}};
  }
  mag += d2;
  m[n++] = {-1, 0, 2, {r, r, 0, 0}};
  const double v = d2 - r * r;
  // Each difference, square and addition rounds once (relative 2^-53): below 8 * 2^-53 mag.
  if (mag > 0x1p-960 && mag < 0x1p1000 && std::abs(v) > 1e-15 * mag) return v > 0 ? 1 : -1;
  return exact_sign_of_sum(std::span<const ExactMonomial>(m, static_cast<std::size_t>(n)));
}

}  // namespace locus::detail::box3
