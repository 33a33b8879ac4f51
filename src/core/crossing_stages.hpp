// SPDX-License-Identifier: BSL-1.0
#pragma once
// Private to the library: the double-double and triple-length stages of det[b - a; d - c]
// (detail::turn2d_value_accurate, include/locus/core/crossing.hpp), written once over the
// arithmetic they run in, for src/core/crossing.cpp (one double: ScalarOps, whose products'
// errors come from a fused multiply-add or from Dekker's product) and for the batched segment
// intersection src/intersection/batch_segment2.cpp (the doubles of one SIMD register:
// LaneOps, Dekker's product, core/lanes.hpp). Both run the same operations in the same order, so
// a lane gets the bits of the scalar stage wherever the two ways of forming a product's error
// agree (both exact). The error bounds and the acceptance tests are derived in crossing.cpp's
// file comment. Every includer must be compiled with -ffp-contract=off (CMake: the expansion
// and batch sources): the error-free transformations need each operation rounded on its own.
//
// An Ops type names the value type S, the mask type M (what a comparison of S gives), and
// abs(x), max(a, b) (a < b ? b : a), both(m1, m2) (and), two_sum(a, b, s, e) and product_error(a,
// b, p).

#include <locus/config.hpp>
#include <locus/core/error_free.hpp>

#include <cmath>
#include <type_traits>

#include "lanes.hpp"

namespace locus::detail::crossing_stages {

/// One double; product errors by __builtin_fma (kFma: only in code compiled for FMA) or by
/// core/error_free.hpp's product_error.
template <bool kFma>
struct ScalarOps {
  using S = double;
  using M = bool;
  LOCUS_ALWAYS_INLINE static S abs(S x) { return std::abs(x); }
  LOCUS_ALWAYS_INLINE static S max(S a, S b) { return a < b ? b : a; }
  LOCUS_ALWAYS_INLINE static M both(M a, M b) { return a && b; }
  LOCUS_ALWAYS_INLINE static void two_sum(S a, S b, S& s, S& e) { locus::two_sum(a, b, s, e); }
  LOCUS_ALWAYS_INLINE static S product_error(S a, S b, S p) {
    if constexpr (kFma)
      return __builtin_fma(a, b, -p);
    else
      return locus::product_error(a, b, p);
  }
};

/// The doubles of one SIMD register (a template so that nothing with vector parameters is
/// compiled unless a kernel uses it).
template <class T = double>
struct LaneOps {
  static_assert(std::is_same_v<T, double>, "the stages are written for double");
  using S = lanes::V<T>;
  using M = lanes::M<T>;
  LOCUS_ALWAYS_INLINE static S abs(S x) { return lanes::abs<T>(x); }
  LOCUS_ALWAYS_INLINE static S max(S a, S b) { return lanes::sel<T>(a < b, b, a); }
  LOCUS_ALWAYS_INLINE static M both(M a, M b) { return a & b; }
  LOCUS_ALWAYS_INLINE static void two_sum(S a, S b, S& s, S& e) { lanes::two_sum<T>(a, b, s, e); }
  LOCUS_ALWAYS_INLINE static S product_error(S a, S b, S p) {
    return lanes::product_error_dekker<T>(a, b, p);
  }
};

/// p + e = a b exactly, p = fl(a b) (core/error_free.hpp's two_product, in Ops).
template <class Ops, class S = typename Ops::S>
LOCUS_ALWAYS_INLINE inline void two_product(S a, S b, S& p, S& e) {
  p = a * b;
  e = Ops::product_error(a, b, p);
}

/// The differences split exactly: b.x - a.x = h1 + l1, d.y - c.y = h2 + l2, b.y - a.y = h3 + l3,
/// d.x - c.x = h4 + l4 (two_sum), so det = (h1 + l1)(h2 + l2) - (h3 + l3)(h4 + l4).
template <class Ops>
struct Split {
  typename Ops::S h1, l1, h2, l2, h3, l3, h4, l4;
};
template <class Ops, class S = typename Ops::S>
LOCUS_ALWAYS_INLINE inline Split<Ops> split(S ax, S ay, S bx, S by, S cx, S cy, S dx, S dy) {
  Split<Ops> d;
  Ops::two_sum(bx, -ax, d.h1, d.l1);
  Ops::two_sum(dy, -cy, d.h2, d.l2);
  Ops::two_sum(by, -ay, d.h3, d.l3);
  Ops::two_sum(dx, -cx, d.h4, d.l4);
  return d;
}

/// The leading products, exact: p + pe = h1 h2, q + qe = h3 h4, s + se = p - q; perm = |p| + |q|.
template <class Ops>
struct Leading {
  typename Ops::S p, pe, q, qe, s, se, perm;
};
template <class Ops>
LOCUS_ALWAYS_INLINE inline Leading<Ops> leading(const Split<Ops>& d) {
  Leading<Ops> r;
  two_product<Ops>(d.h1, d.h2, r.p, r.pe);
  two_product<Ops>(d.h3, d.h4, r.q, r.qe);
  Ops::two_sum(r.p, -r.q, r.s, r.se);
  r.perm = Ops::abs(r.p) + Ops::abs(r.q);
  return r;
}

/// A stage's value, and where it is accepted.
template <class Ops>
struct Value {
  typename Ops::S v;
  typename Ops::M ok;
};

/// The double-double stage (turn2d_value_dd's tier): the leading difference and the first-order
/// tails; accepted when 2^-47 perm <= |v| and the products are in range.
template <class Ops>
LOCUS_ALWAYS_INLINE inline Value<Ops> double_double(const Split<Ops>& d, const Leading<Ops>& f) {
  using S = typename Ops::S;
  const S tail = (f.se + (f.pe - f.qe)) +
                 ((d.h1 * d.l2 + d.l1 * d.h2) - (d.h3 * d.l4 + d.l3 * d.h4)) +
                 (d.l1 * d.l2 - d.l3 * d.l4);
  const S v = f.s + tail;
  const S av = Ops::abs(v);
  return {v, Ops::both(Ops::both(av >= 0x1p-47 * f.perm, f.perm > 0x1p-900), f.perm < 0x1p1000)};
}

/// The cross products of the triple-length stage, exact: c1 + c1e = h1 l2, c2 + c2e = l1 h2,
/// c3 + c3e = h3 l4, c4 + c4e = l3 h4.
template <class Ops>
struct Cross {
  typename Ops::S c1, c1e, c2, c2e, c3, c3e, c4, c4e;
};
template <class Ops>
LOCUS_ALWAYS_INLINE inline Cross<Ops> cross(const Split<Ops>& d) {
  Cross<Ops> r;
  two_product<Ops>(d.h1, d.l2, r.c1, r.c1e);
  two_product<Ops>(d.l1, d.h2, r.c2, r.c2e);
  two_product<Ops>(d.h3, d.l4, r.c3, r.c3e);
  two_product<Ops>(d.l3, d.h4, r.c4, r.c4e);
  return r;
}

/// The largest |h|: below 2^990, no product of the stages overflows.
template <class Ops>
LOCUS_ALWAYS_INLINE inline typename Ops::S largest_difference(const Split<Ops>& d) {
  return Ops::max(Ops::max(Ops::abs(d.h1), Ops::abs(d.h2)),
                  Ops::max(Ops::abs(d.h3), Ops::abs(d.h4)));
}

/// The triple-length stage (crossing.cpp's stage 1): the first-order bracket summed by a cascade
/// of two_sums whose errors join the second-order bracket; accepted when 2^-90 perm <= |v|,
/// perm in [2^-800, 2^900] and hmax = largest_difference(d) below 2^990.
template <class Ops>
LOCUS_ALWAYS_INLINE inline Value<Ops> triple(const Split<Ops>& d, const Leading<Ops>& f,
                                             const Cross<Ops>& c, typename Ops::S hmax) {
  using S = typename Ops::S;
  // First order: se + pe - qe + c1 + c2 - c3 - c4, the cascade's errors kept.
  S g = f.se, e1, e2, e3, e4, e5, e6;
  Ops::two_sum(g, f.pe, g, e1);
  Ops::two_sum(g, -f.qe, g, e2);
  Ops::two_sum(g, c.c1, g, e3);
  Ops::two_sum(g, c.c2, g, e4);
  Ops::two_sum(g, -c.c3, g, e5);
  Ops::two_sum(g, -c.c4, g, e6);
  const S second = ((c.c1e + c.c2e) - (c.c3e + c.c4e)) + (d.l1 * d.l2 - d.l3 * d.l4) +
                   (((e1 + e2) + (e3 + e4)) + (e5 + e6));
  S t, te;
  Ops::two_sum(f.s, g, t, te);
  const S v = t + (te + second);
  const S av = Ops::abs(v);
  return {v, Ops::both(Ops::both(av >= 0x1p-90 * f.perm, f.perm >= 0x1p-800),
                       Ops::both(f.perm <= 0x1p900, hmax < 0x1p990))};
}

}  // namespace locus::detail::crossing_stages
