// SPDX-License-Identifier: BSL-1.0
#pragma once
// Floating-point expansion arithmetic (private to src/core; row core.predicates).
//
// Written from J. R. Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust
// Geometric Predicates", Discrete & Computational Geometry 18 (1997), sections 2.2-2.8:
// an *expansion* is an unevaluated sum of doubles, stored in increasing order of magnitude,
// whose components are nonoverlapping; its sign is the sign of its last (largest) component.
// Every routine here eliminates zero components, so an expansion of length 0 means 0.
//
// Requirements (the paper's theorems assume them): IEEE binary64 with round-to-nearest-even,
// every operation rounded on its own (no FMA contraction, no x87 extended precision, no
// fast-math reassociation), and no overflow or underflow. Every file including this header must
// be compiled with -ffp-contract=off; predicates.cpp checks __FAST_MATH__.
//
// Output arrays must not alias inputs. Capacities are the caller's duty: grow gives at most
// elen + 1 components, sum elen + flen, scale 2 * elen.

#include <locus/core/error_free.hpp>

#include <cmath>

namespace locus::detail::expansion {

/// Half an ulp of 1: the unit roundoff epsilon of the paper for binary64.
inline constexpr double eps = 0x1p-53;
/// 2^ceil(53/2) + 1, the Veltkamp-Dekker splitting constant (section 2.5).
inline constexpr double splitter = 0x1p27 + 1.0;

/// x + y = a + b exactly, x = fl(a + b); requires |a| >= |b| or a == 0 (Theorem 6).
inline void fast_two_sum(double a, double b, double& x, double& y) noexcept {
  x = a + b;
  const double b_virtual = x - a;
  y = b - b_virtual;
}

/// x + y = a + b exactly, x = fl(a + b), with no precondition (Theorem 7, Knuth): core's.
using locus::two_sum;

/// The roundoff of x = fl(a - b): returns y with x + y = a - b exactly.
inline double two_diff_tail(double a, double b, double x) noexcept {
  const double b_virtual = a - x;
  const double a_virtual = x + b_virtual;
  const double b_round = b_virtual - b;
  const double a_round = a - a_virtual;
  return a_round + b_round;
}

/// hi + lo = a with hi, lo holding at most 26 significant bits each (Theorem 17).
inline void split(double a, double& hi, double& lo) noexcept {
  const double c = splitter * a;
  const double a_big = c - a;
  hi = c - a_big;
  lo = a - hi;
}

/// x + y = a * b exactly, x = fl(a * b), b already split into bhi + blo (Theorem 18).
inline void two_product_presplit(double a, double b, double bhi, double blo, double& x,
                                 double& y) noexcept {
  x = a * b;
  double ahi = 0.0, alo = 0.0;
  split(a, ahi, alo);
  const double err1 = x - ahi * bhi;
  const double err2 = err1 - alo * bhi;
  const double err3 = err2 - ahi * blo;
  y = alo * blo - err3;
}

/// x + y = a * b exactly, x = fl(a * b) (Theorem 18, Dekker; a fused multiply-add where the
/// target has one): core's.
using locus::two_product;

/// h = e + b (Grow-Expansion, Theorem 10), zero components removed. Returns the length.
inline int grow_zeroelim(int elen, const double* e, double b, double* h) noexcept {
  int hlen = 0;
  double q = b;
  for (int i = 0; i < elen; ++i) {
    double hh = 0.0;
    two_sum(q, e[i], q, hh);
    if (hh != 0.0) h[hlen++] = hh;
  }
  if (q != 0.0) h[hlen++] = q;
  return hlen;
}

/// h = e + f (Fast-Expansion-Sum, Theorem 13), zero components removed. Returns the length.
/// The components of e and f are merged by magnitude; the running sum is carried by Two-Sum.
inline int sum_zeroelim(int elen, const double* e, int flen, const double* f, double* h) noexcept {
  int ei = 0, fi = 0;
  auto next = [&]() noexcept {
    if (fi >= flen || (ei < elen && std::abs(e[ei]) <= std::abs(f[fi]))) return e[ei++];
    return f[fi++];
  };
  const int total = elen + flen;
  if (total == 0) return 0;
  if (total == 1) {
    const double g = next();
    if (g == 0.0) return 0;
    h[0] = g;
    return 1;
  }
  int hlen = 0;
  const double g0 = next();
  const double g1 = next();
  double q = 0.0, hh = 0.0;
  fast_two_sum(g1, g0, q, hh);
  if (hh != 0.0) h[hlen++] = hh;
  for (int k = 2; k < total; ++k) {
    two_sum(q, next(), q, hh);
    if (hh != 0.0) h[hlen++] = hh;
  }
  if (q != 0.0) h[hlen++] = q;
  return hlen;
}

/// h = -e (exact). Returns the length.
inline int negate(int elen, const double* e, double* h) noexcept {
  for (int i = 0; i < elen; ++i) h[i] = -e[i];
  return elen;
}

/// h = e * b (Scale-Expansion, Theorem 19), zero components removed. Returns the length.
inline int scale_zeroelim(int elen, const double* e, double b, double* h) noexcept {
  if (elen == 0) return 0;
  double bhi = 0.0, blo = 0.0;
  split(b, bhi, blo);
  int hlen = 0;
  double q = 0.0, hh = 0.0;
  two_product_presplit(e[0], b, bhi, blo, q, hh);
  if (hh != 0.0) h[hlen++] = hh;
  for (int i = 1; i < elen; ++i) {
    double big = 0.0, small = 0.0, sum = 0.0;
    two_product_presplit(e[i], b, bhi, blo, big, small);
    two_sum(q, small, sum, hh);
    if (hh != 0.0) h[hlen++] = hh;
    fast_two_sum(big, sum, q, hh);
    if (hh != 0.0) h[hlen++] = hh;
  }
  if (q != 0.0) h[hlen++] = q;
  return hlen;
}

/// h = a1*b1 - a2*b2 exactly (at most 4 components). Returns the length.
inline int two_products_diff(double a1, double b1, double a2, double b2, double* h) noexcept {
  double p[2], mhi = 0.0, mlo = 0.0, t[3];
  two_product(a1, b1, p[1], p[0]);
  two_product(a2, b2, mhi, mlo);
  // A zero component is harmless to Grow-Expansion, which drops it.
  const int tlen = grow_zeroelim(2, p, -mlo, t);
  return grow_zeroelim(tlen, t, -mhi, h);
}

/// e rewritten with few components (the paper's Compress, section 2.8), in place: a
/// nonadjacent, hence strongly nonoverlapping, expansion of the same value, so that later
/// operations get short inputs. Components are renormalised from the top down, then from the
/// bottom up; each write lands on a slot already read. Returns the new length.
inline int compress(int elen, double* e) noexcept {
  if (elen == 0) return 0;
  int bottom = elen - 1;
  double q = e[elen - 1];
  for (int i = elen - 2; i >= 0; --i) {
    double sum = 0.0, err = 0.0;
    fast_two_sum(q, e[i], sum, err);
    if (err != 0.0) {
      e[bottom--] = sum;
      q = err;
    } else {
      q = sum;
    }
  }
  e[bottom] = q;
  int top = 0;
  for (int i = bottom + 1; i < elen; ++i) {
    double sum = 0.0, err = 0.0;
    fast_two_sum(e[i], q, sum, err);
    if (err != 0.0) e[top++] = err;
    q = sum;
  }
  if (q != 0.0) e[top++] = q;
  return top;
}

/// An approximation of the value of e (the paper's Estimate: the sum of the components).
inline double estimate(int elen, const double* e) noexcept {
  double q = 0.0;
  for (int i = 0; i < elen; ++i) q += e[i];
  return q;
}

/// Sign of the value of e: the sign of its largest component (-1, 0, +1). A NaN component
/// (only reachable outside the documented range) gives 0.
inline int sign(int elen, const double* e) noexcept {
  if (elen == 0) return 0;
  const double top = e[elen - 1];
  return (top > 0.0) - (top < 0.0);
}

}  // namespace locus::detail::expansion
