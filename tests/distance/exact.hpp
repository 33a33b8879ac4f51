// SPDX-License-Identifier: BSL-1.0
#pragma once
// Exact (GMP rational) squared distances between points, lines, rays and segments: the exact
// oracle of the linear distance tests. Floating-point inputs are exact rationals, so these are
// the true squared distances of the given input. Method (independent of the library's code
// path, all in exact arithmetic): minimum of the quadratic over the parameter domain = the
// unconstrained minimiser when it lies in the domain, otherwise the minimum over the domain's
// edges (exact clamped projections); parallel lines: distance from a point of one to the other.

#include <locus/core/vec.hpp>

#include <gmpxx.h>

#include <array>
#include <cstddef>

namespace locus_test::exact {

template <std::size_t N>
using QVec = std::array<mpq_class, N>;

template <class T, int N>
QVec<static_cast<std::size_t>(N)> to_q(const locus::Vec<T, N>& v) {
  QVec<static_cast<std::size_t>(N)> q;
  for (int i = 0; i < N; ++i) q[static_cast<std::size_t>(i)] = mpq_class(static_cast<double>(v[i]));
  return q;
}
template <std::size_t N>
QVec<N> sub(const QVec<N>& a, const QVec<N>& b) {
  QVec<N> r;
  for (std::size_t i = 0; i < N; ++i) r[i] = a[i] - b[i];
  return r;
}
template <std::size_t N>
QVec<N> axpy(const QVec<N>& o, const mpq_class& t, const QVec<N>& d) {
  QVec<N> r;
  for (std::size_t i = 0; i < N; ++i) r[i] = o[i] + t * d[i];
  return r;
}
template <std::size_t N>
mpq_class dot(const QVec<N>& a, const QVec<N>& b) {
  mpq_class s = 0;
  for (std::size_t i = 0; i < N; ++i) s += a[i] * b[i];
  return s;
}

/// origin + t dir, t >= 0 if lo, t <= 1 if hi.
template <std::size_t N>
struct QLinear {
  QVec<N> origin, dir;
  bool lo, hi;
};

template <class T, int N>
QLinear<static_cast<std::size_t>(N)> line(const locus::Vec<T, N>& o, const locus::Vec<T, N>& d) {
  return {to_q(o), to_q(d), false, false};
}
template <class T, int N>
QLinear<static_cast<std::size_t>(N)> ray(const locus::Vec<T, N>& o, const locus::Vec<T, N>& d) {
  return {to_q(o), to_q(d), true, false};
}
template <class T, int N>
QLinear<static_cast<std::size_t>(N)> segment(const locus::Vec<T, N>& p0,
                                             const locus::Vec<T, N>& p1) {
  const auto a = to_q(p0);
  return {a, sub(to_q(p1), a), true, true};
}

template <std::size_t N>
mpq_class clamp_param(const QLinear<N>& l, mpq_class t) {
  if (l.lo && t < 0) t = 0;
  if (l.hi && t > 1) t = 1;
  return t;
}

template <std::size_t N>
mpq_class closest_param(const QLinear<N>& l, const QVec<N>& p) {
  const mpq_class a = dot(l.dir, l.dir);
  if (a == 0) return 0;
  return clamp_param(l, mpq_class(dot(sub(p, l.origin), l.dir) / a));
}

template <std::size_t N>
mpq_class sqr_point_linear(const QVec<N>& p, const QLinear<N>& l) {
  const QVec<N> c = axpy(l.origin, closest_param(l, p), l.dir);
  const QVec<N> d = sub(p, c);
  return dot(d, d);
}

template <std::size_t N>
mpq_class sqr_linear_linear(const QLinear<N>& A, const QLinear<N>& B) {
  const mpq_class a = dot(A.dir, A.dir), c = dot(B.dir, B.dir), b = dot(A.dir, B.dir);
  if (a == 0) return sqr_point_linear(A.origin, B);
  if (c == 0) return sqr_point_linear(B.origin, A);
  const QVec<N> r = sub(A.origin, B.origin);
  const mpq_class d = dot(A.dir, r), e = dot(B.dir, r), D = a * c - b * b;
  const auto R = [&](const mpq_class& s, const mpq_class& t) {
    const QVec<N> w = sub(axpy(A.origin, s, A.dir), axpy(B.origin, t, B.dir));
    return mpq_class(dot(w, w));
  };
  if (D != 0) {
    const mpq_class s = (b * e - c * d) / D, t = (a * e - b * d) / D;
    if (clamp_param(A, s) == s && clamp_param(B, t) == t) return R(s, t);
  }
  bool have = false;
  mpq_class best;
  const auto take = [&](const mpq_class& q) {
    if (!have || q < best) best = q, have = true;
  };
  if (A.lo) take(sqr_point_linear(A.origin, B));
  if (A.hi) take(sqr_point_linear(axpy(A.origin, mpq_class(1), A.dir), B));
  if (B.lo) take(sqr_point_linear(B.origin, A));
  if (B.hi) take(sqr_point_linear(axpy(B.origin, mpq_class(1), B.dir), A));
  if (!have) take(sqr_point_linear(A.origin, B));  // two parallel lines
  return best;
}

}  // namespace locus_test::exact
