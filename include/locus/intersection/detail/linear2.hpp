// SPDX-License-Identifier: BSL-1.0
#pragma once
// The one engine behind the six 2D linear pairs (line, ray, segment; row int2.linear). Every
// component becomes {a, b, o, lo, hi}: the direction is b - a exactly (a segment's end points, or
// 0 and a line's direction vector), o is the point of parameter 0, lo bounds t >= 0 (ray,
// segment) and hi bounds t <= 1 (segment, whose parameter 1 is at b). The side of a point p of
// such a component is det[b - a; p - o] = turn2d(a, b, o, p): exact signs decide everything.
// A crossing's parameter is a ratio of two such determinants, each rounded from its exact value
// (core/crossing.hpp: double-double, exact expansions near zero), so tiny angles lose nothing.
// Collinear overlaps are decided by exact lexicographic comparisons, which order collinear points
// along their line. Computation is in double (float input is promoted exactly).
// docs/notes/intersection.md.

#include <locus/config.hpp>
#include <locus/core/crossing.hpp>
#include <locus/core/error_free.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/segment.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>

namespace locus {

/// The result of intersection() between two of Line2, Ray2, Segment2.
template <Real T>
using LinearIntersection2 = Intersection<T, 2, T, T, 2>;

namespace detail::linear2 {

using V = Vec2<double>;
using Result = Intersection<double, 2, double, double, 2>;

/// A linear component: direction b - a (exact), parameter 0 at o, t >= 0 if lo, t <= 1 if hi.
struct Lin {
  V a, b, o;
  bool lo, hi;
};

template <Real T>
[[nodiscard]] constexpr Lin as_lin(const Line2<T>& l) noexcept {
  return {V{}, vec_cast<double>(l.direction), vec_cast<double>(l.origin), false, false};
}
template <Real T>
[[nodiscard]] constexpr Lin as_lin(const Ray2<T>& r) noexcept {
  return {V{}, vec_cast<double>(r.direction), vec_cast<double>(r.origin), true, false};
}
template <Real T>
[[nodiscard]] constexpr Lin as_lin(const Segment2<T>& s) noexcept {
  const V p0 = vec_cast<double>(s.p0);
  return {p0, vec_cast<double>(s.p1), p0, true, true};
}

/// The direction, rounded for a segment (p1 - p0), exact otherwise.
[[nodiscard]] inline V dir(const Lin& l) noexcept { return l.b - l.a; }

/// Exact side of p: sign of det[b - a; p - o].
[[nodiscard]] inline Sign side(const Lin& l, const V& p) noexcept {
  return turn2d(l.a, l.b, l.o, p);
}

[[nodiscard]] inline double side_accurate(const Lin& l, const V& p) noexcept {
  return turn2d_value(l.a, l.b, l.o, p);
}

/// +1 when the direction runs toward lexicographically larger points, -1 otherwise.
[[nodiscard]] inline int lex_dir(const Lin& l) noexcept {
  return -to_int(lexicographic_compare(l.a, l.b));
}

/// Whether p, known to lie on l's line, lies on l (exact).
[[nodiscard]] inline bool in_range(const Lin& l, const V& p) noexcept {
  const int d = lex_dir(l);
  if (l.lo && to_int(lexicographic_compare(l.o, p)) * d > 0) return false;
  if (l.hi && to_int(lexicographic_compare(p, l.b)) * d > 0) return false;
  return true;
}

/// Power-of-two scale bringing max |v| near 1 (exact scaling, so projections are
/// scale-covariant and cannot overflow in the dot products).
[[nodiscard]] inline double pow2_scale(const V& v) noexcept {
  const double m = std::max(std::abs(v.x), std::abs(v.y));
  return m > 0.0 ? std::ldexp(1.0, -std::ilogb(m)) : 1.0;
}

/// The parameter on l of p, a point of l (rounded), clamped to l's parameter range; exact at o
/// and at a segment's p1.
[[nodiscard]] inline double project(const Lin& l, const V& p) noexcept {
  if (p == l.o) return 0.0;
  if (l.hi && p == l.b) return 1.0;
  const double s = pow2_scale(dir(l));
  const V d = s * dir(l);
  double t = 0.0;
  if (l.hi) {
    // From the nearer end point, so that t near 1 keeps its digits.
    const V from0 = s * (p - l.o), from1 = s * (p - l.b);
    t = sqr_length(from0) <= sqr_length(from1) ? dot(from0, d) / dot(d, d)
                                               : 1.0 + dot(from1, d) / dot(d, d);
  } else {
    t = dot(s * (p - l.o), d) / dot(d, d);
  }
  if (l.lo) t = std::max(t, 0.0);
  if (l.hi) t = std::min(t, 1.0);
  return t;
}

[[nodiscard]] inline bool finite(const Lin& l) noexcept { return all_finite(l.a, l.b, l.o); }

/// Parameter of the crossing on l with m (not parallel): t = side(m, l.o) / det[dir l; dir m].
/// For a segment the ratio is s0 / (s0 - s1) with s0, s1 = m's sides of p0 and p1, of opposite
/// signs (or one zero), so the difference cannot cancel; t - 1 = s1 / (s0 - s1) is returned too,
/// and from_end says p1 is the nearer end (X = p1 + (t - 1) d keeps more digits).
struct Param {
  double t, t_minus_1;
  bool from_end;
};
[[nodiscard]] inline Param crossing_param(const Lin& l, const Lin& m) noexcept {
  if (l.hi) {
    const double v0 = side_accurate(m, l.o), v1 = side_accurate(m, l.b);
    const double dd = v0 - v1;
    return {v0 / dd, v1 / dd, std::abs(v1) < std::abs(v0)};
  }
  const double t = side_accurate(m, l.o) / turn2d_value(l.a, l.b, m.a, m.b);
  return {t, t - 1.0, false};
}

[[nodiscard]] inline double clamp_param(const Lin& l, double t) noexcept {
  if (l.lo) t = std::max(t, 0.0);
  if (l.hi) t = std::min(t, 1.0);
  return t;
}

/// One end of a collinear overlap: a point of parameter `param` (0 or 1) on component `owner`.
struct End {
  bool infinite;
  V p;
  int owner;
  double param;
};

template <bool Construct>
[[nodiscard]] inline Result collinear(const Lin& A, const Lin& B) noexcept {
  Result r;
  const int da = lex_dir(A), db = lex_dir(B);
  // Order along A: negative when p comes before q.
  const auto order = [da](const V& p, const V& q) noexcept {
    return to_int(lexicographic_compare(p, q)) * da;
  };
  const End none{true, V{}, -1, 0.0};
  const End lowA = A.lo ? End{false, A.o, 0, 0.0} : none;
  const End upA = A.hi ? End{false, A.b, 0, 1.0} : none;
  const End startB = B.lo ? End{false, B.o, 1, 0.0} : none;
  const End endB = B.hi ? End{false, B.b, 1, 1.0} : none;
  const End& lowB = da == db ? startB : endB;
  const End& upB = da == db ? endB : startB;
  const End low =
      lowA.infinite ? lowB : (lowB.infinite || order(lowA.p, lowB.p) >= 0 ? lowA : lowB);
  const End up = upA.infinite ? upB : (upB.infinite || order(upA.p, upB.p) <= 0 ? upA : upB);
  const auto put = [&](const V& p, int owner, double param) noexcept {
    r.point[r.count] = p;
    r.param_a[r.count] = owner == 0 ? param : project(A, p);
    r.param_b[r.count] = owner == 1 ? param : project(B, p);
    ++r.count;
  };
  if (!low.infinite && !up.infinite) {
    const int c = order(low.p, up.p);
    if (c > 0) return r;
    r.kind = c == 0 ? Kind::point : Kind::segment;
    if constexpr (Construct) {
      put(low.p, low.owner, low.param);
      if (c < 0) put(up.p, up.owner, up.param);
    }
    return r;
  }
  if (low.infinite && up.infinite) {
    r.kind = Kind::line;
    if constexpr (Construct) {
      put(A.o, 0, 0.0);
      put(A.o + dir(A), 0, 1.0);
    }
    return r;
  }
  // One end finite: it is the origin of a ray (a segment would bound both ends), whose
  // direction points into the overlap.
  r.kind = Kind::ray;
  if constexpr (Construct) {
    const End& e = low.infinite ? up : low;
    const Lin& R = e.owner == 0 ? A : B;
    put(e.p, e.owner, 0.0);
    put(R.o + dir(R), e.owner, 1.0);
  }
  return r;
}

/// A degenerate component (zero direction) acts as its point o.
template <bool Construct>
[[nodiscard]] inline Result point_on(const V& p, const Lin& B, bool swap) noexcept {
  Result r;
  if (side(B, p) != Sign::zero || !in_range(B, p)) return r;
  r.kind = Kind::point;
  r.count = 1;
  r.point[0] = p;
  const double pb = Construct ? project(B, p) : 0.0;
  r.param_a[0] = swap ? pb : 0.0;
  r.param_b[0] = swap ? 0.0 : pb;
  return r;
}

/// The binary exponent of the largest |coordinate| when it lies outside [2^-400, 2^400] (where
/// products of coordinates would underflow or overflow), else 0.
[[nodiscard]] inline int range_exponent(const Lin& A, const Lin& B) noexcept {
  const double m = std::max(
      {max_abs(A.a), max_abs(A.b), max_abs(A.o), max_abs(B.a), max_abs(B.b), max_abs(B.o)});
  return m > 0x1p400 || (m > 0.0 && m < 0x1p-400) ? std::ilogb(m) : 0;
}
[[nodiscard]] inline Lin scaled(const Lin& l, int e) noexcept {
  const auto s = [e](const V& v) noexcept { return V{std::ldexp(v.x, e), std::ldexp(v.y, e)}; };
  return {s(l.a), s(l.b), s(l.o), l.lo, l.hi};
}

/// det[d; e] in double with the sum of its products' magnitudes (for the error bounds).
struct Det {
  double v, perm;
};
[[nodiscard]] LOCUS_ALWAYS_INLINE inline Det det_naive(const V& d, const V& e) noexcept {
  const double l = d.x * e.y, r = d.y * e.x;
  return {l - r, std::abs(l) + std::abs(r)};
}
/// Its products neither underflow nor overflow (false on NaN and infinity).
[[nodiscard]] LOCUS_ALWAYS_INLINE inline bool products_in_range(const Det& f) noexcept {
  return f.perm > 0x1p-900 && f.perm < 0x1p1000;
}
/// Its sign is exact: orient2d's stage-A bound, valid when no product underflows or overflows
/// (false on NaN and infinity, so non-finite input never passes).
[[nodiscard]] LOCUS_ALWAYS_INLINE inline bool certain(const Det& f) noexcept {
  return std::abs(f.v) > orient2d_bound_a * f.perm && products_in_range(f);
}
/// det[d; e] with the differences d and e split exactly (two_sum: h + l) and the first-order
/// tails added: error <= u perm + 2u |v| (plus u^2 terms below 0.01 u perm).
struct Split {
  double h, l;
};
struct Split2 {
  Split x, y;
};
[[nodiscard]] LOCUS_ALWAYS_INLINE inline Split2 split_diff(const V& p, const V& q) noexcept {
  Split2 d;
  two_sum(p.x, -q.x, d.x.h, d.x.l);
  two_sum(p.y, -q.y, d.y.h, d.y.l);
  return d;
}
[[nodiscard]] LOCUS_ALWAYS_INLINE inline Det det_tails(const Split2& d, const Split2& e) noexcept {
  const double l = d.x.h * e.y.h, r = d.y.h * e.x.h;
  const double tail = (d.x.h * e.y.l + d.x.l * e.y.h) - (d.y.h * e.x.l + d.y.l * e.x.h);
  return {(l - r) + tail, std::abs(l) + std::abs(r)};
}

/// Whether values f0, f1 of a segment's end point sides, each off by at most u (cp perm + cv |f|),
/// give its crossing parameter t = f0 / (f0 - f1) within 2.99u of the exact one: exactly,
/// t' - t = (f0 d1 - f1 d0) / ((f0' - f1')(f0 - f1)), d the errors. Everything is divided by
/// |f0' - f1'| first, so the choice is the same at every power-of-two scale (the covariance of
/// the results); overflow or underflow fails it. Then the point and the parameters keep the
/// header's bounds (docs/notes/intersection.md, "Fast path").
[[nodiscard]] LOCUS_ALWAYS_INLINE inline bool param_accurate(const Det& f0, const Det& f1,
                                                             double cp, double cv) noexcept {
  constexpr double u = 0x1p-53;
  const double a0 = std::abs(f0.v), a1 = std::abs(f1.v), dd = std::abs(f0.v - f1.v);
  const double inv = 1.0 / dd;
  const double r0 = a0 * inv, r1 = a1 * inv;
  const double e0 = (cp * f0.perm + cv * a0) * inv, e1 = (cp * f1.perm + cv * a1) * inv;
  return r0 * e1 + r1 * e0 + 2.0 * u * e0 * e1 <= 2.99 * (1.0 - u * (e0 + e1)) && dd >= 0x1p-900;
}

/// The tiers of accurate_sides past its cheap test, out of line: they run for a minority of
/// crossings, and inlined they would crowd the fast path's registers.
LOCUS_NOINLINE inline void accurate_sides_slow(const Det& f0, const Det& f1, const V& q0,
                                               const V& q1, const V& p0, const V& p1, double& v0,
                                               double& v1) noexcept {
  // Neither tier below can accept when min(perm) > 3 |f0 - f1| + 2^-40 (perm0 + perm1) (nearly
  // parallel segments): passing needs min(e0, e1) <= 2.99, e >= 1.01 perm / |g0 - g1|, and the
  // values g and f are within 8u (perm0 + perm1) of each other. Then straight to the last tier.
  const bool hopeless =
      std::min(f0.perm, f1.perm) > 3.0 * std::abs(f0.v - f1.v) + 0x1p-40 * (f0.perm + f1.perm);
  if (!hopeless) {
    if (param_accurate(f0, f1, 3.01, 1.01)) return;
    const Split2 d = split_diff(q1, q0);
    const Det g0 = det_tails(d, split_diff(p0, q0)), g1 = det_tails(d, split_diff(p1, q0));
    v0 = g0.v, v1 = g1.v;
    if (param_accurate(g0, g1, 1.01, 2.01)) [[likely]]
      return;
  }
  v0 = detail::turn2d_value_dd(q0, q1, q0, p0);
  v1 = detail::turn2d_value_dd(q0, q1, q0, p1);
}

/// The sides v0, v1 of p0 and p1 on the line q0 q1 (det[q1 - q0; p - q0]) accurate enough for
/// param_accurate, from the naive values f0, f1 (error <= 3u perm + u |f|), else with exact
/// differences, else rounded from their exact values (turn2d_value, the general path's values).
/// Known: v0 and v1 hold those values already (segments_sides computed them for the signs).
template <bool Certified>
LOCUS_ALWAYS_INLINE inline void accurate_sides(const Det& f0, const Det& f1, const V& q0,
                                               const V& q1, const V& p0, const V& p1, double& v0,
                                               double& v1, bool known = false) noexcept {
  if (known) return;
  v0 = f0.v, v1 = f1.v;
  // Cheap sufficient case first: |f| >= 0.62 perm for both (products in range) gives E <= 5.86u
  // |f| and the right signs, hence |t' - t| <= 11.72u |f0| |f1| / (|f0| + |f1|)^2 (1 + O(u)),
  // at most 2.93u.
  // Certified (segments_fast): certain() has checked the range already.
  if (std::abs(f0.v) >= 0.62 * f0.perm && std::abs(f1.v) >= 0.62 * f1.perm &&
      (Certified || (products_in_range(f0) && products_in_range(f1)))) [[likely]]
    return;
  accurate_sides_slow(f0, f1, q0, q1, p0, p1, v0, v1);
}

/// The four end point sides of segments a0 a1 and b0 b1 in double: of A's end points on B
/// (det[b1 - b0; p - b0]) and of B's on A (det[a1 - a0; p - a0]), as the filters compute them.
struct Sides {
  Det a0, a1, b0, b1;
};
[[nodiscard]] LOCUS_ALWAYS_INLINE inline Sides naive_sides(const V& a0, const V& a1, const V& b0,
                                                           const V& b1) noexcept {
  const V da = a1 - a0, db = b1 - b0;
  return {det_naive(db, a0 - b0), det_naive(db, a1 - b0), det_naive(da, b0 - a0),
          det_naive(da, b1 - a0)};
}

/// The crossing of segments that cross properly (every side nonzero; a0, a1 on opposite sides
/// of B and b0, b1 of A), interpolated along A from its nearer end with parameters t = v0 /
/// (v0 - v1) from side values accurate enough for the header's bounds (accurate_sides). Both
/// paths of intersect() construct with it, so the result does not depend on which one decided.
/// Known: the rounded exact values of some sides (segments_sides), used where both of a pair are.
struct Known {
  double a0 = 0, a1 = 0, b0 = 0, b1 = 0;
  bool a = false, b = false;
};
template <bool Certified>
LOCUS_ALWAYS_INLINE inline void proper_crossing(const V& a0, const V& a1, const V& b0, const V& b1,
                                                const Sides& f, Result& r,
                                                const Known& k = Known{}) noexcept {
  double va0 = k.a0, va1 = k.a1, vb0 = k.b0, vb1 = k.b1;
  accurate_sides<Certified>(f.a0, f.a1, b0, b1, a0, a1, va0, va1, k.a);
  accurate_sides<Certified>(f.b0, f.b1, a0, a1, b0, b1, vb0, vb1, k.b);
  // From the nearer end: a0 + t da, or a1 + (t - 1) da with t - 1 = va1 / (va0 - va1).
  const V da = a1 - a0;
  const double dda = va0 - va1, t = std::clamp(va0 / dda, 0.0, 1.0);
  const bool from_end = std::abs(va1) < std::abs(va0);
  const double s = from_end ? std::clamp(va1 / dda, -1.0, 0.0) : t;
  const V base = from_end ? a1 : a0;
  r.kind = Kind::point;
  r.count = 1;
  r.point[0] = base + s * da;
  r.param_a[0] = t;
  r.param_b[0] = std::clamp(vb0 / (vb0 - vb1), 0.0, 1.0);
}

/// Two segments a0 a1 and b0 b1 when the floating-point filters certify all four end point
/// sides (none zero, so a proper crossing or a miss): the decision intersect_in_range would make
/// from the same four filters, without its finiteness and range checks and without the exact
/// stages. Returns false, leaving r alone, when a filter fails (a touch, collinear or degenerate
/// segments, nearly degenerate configurations, non-finite input, products out of range).
template <bool Construct>
[[nodiscard]] LOCUS_ALWAYS_INLINE inline bool segments_fast(const V& a0, const V& a1, const V& b0,
                                                            const V& b1, Result& r) noexcept {
  const Sides f = naive_sides(a0, a1, b0, b1);
  if (!(certain(f.a0) && certain(f.a1) && certain(f.b0) && certain(f.b1))) return false;
  const bool sa0 = f.a0.v > 0, sa1 = f.a1.v > 0, sb0 = f.b0.v > 0, sb1 = f.b1.v > 0;
  // intersect_in_range's rules with every sign nonzero: den = side of a0.
  if (sa0 == sa1 || sb0 == sa0 || sb1 != sa0) return true;  // r stays empty
  if constexpr (Construct) {
    proper_crossing<true>(a0, a1, b0, b1, f, r);
  } else {
    r.kind = Kind::point;
    r.count = 1;
  }
  return true;
}

/// Two finite segments a0 a1 and b0 b1 in range (range_exponent 0) that segments_fast left
/// undecided: each end point side from its filter where certain, else rounded from its exact
/// value (turn2d_value_accurate, whose sign is turn2d()'s), so one evaluation gives both the
/// exact sign and the value the construction needs. Returns false, leaving r alone, when a side
/// is zero or a segment degenerate (a touch, collinear: intersect_in_range decides).
template <bool Construct>
[[nodiscard]] inline bool segments_sides(const V& a0, const V& a1, const V& b0, const V& b1,
                                         Result& r) noexcept {
  if (a0 == a1 || b0 == b1) return false;
  const Sides f = naive_sides(a0, a1, b0, b1);
  const auto value = [](const Det& g, const V& q0, const V& q1, const V& p, bool& exact) noexcept {
    exact = !certain(g);
    return exact ? detail::turn2d_value_accurate(q0, q1, q0, p) : g.v;
  };
  bool xa0, xa1, xb0, xb1;
  Known k;
  k.a0 = value(f.a0, b0, b1, a0, xa0);
  k.a1 = value(f.a1, b0, b1, a1, xa1);
  k.b0 = value(f.b0, a0, a1, b0, xb0);
  k.b1 = value(f.b1, a0, a1, b1, xb1);
  if (k.a0 == 0 || k.a1 == 0 || k.b0 == 0 || k.b1 == 0) return false;
  const bool sa0 = k.a0 > 0, sa1 = k.a1 > 0, sb0 = k.b0 > 0, sb1 = k.b1 > 0;
  // intersect_in_range's rules with every sign nonzero: den = side of a0.
  if (sa0 == sa1 || sb0 == sa0 || sb1 != sa0) return true;  // r stays empty
  if constexpr (Construct) {
    k.a = xa0 && xa1;
    k.b = xb0 && xb1;
    proper_crossing<false>(a0, a1, b0, b1, f, r, k);
  } else {
    r.kind = Kind::point;
    r.count = 1;
  }
  return true;
}

template <bool Construct>
[[nodiscard]] inline Result intersect_in_range(const Lin& A, const Lin& B) noexcept;

template <bool Construct>
[[nodiscard]] inline Result intersect_general(const Lin& A, const Lin& B, bool segments) noexcept;

template <bool Construct>
[[nodiscard]] inline Result intersect(const Lin& A, const Lin& B) noexcept {
  const bool segments = A.hi && B.hi && A.a == A.o && B.a == B.o;
  if (segments) {
    Result r;
    if (segments_fast<Construct>(A.a, A.b, B.a, B.b, r)) [[likely]]
      return r;
  }
  return intersect_general<Construct>(A, B, segments);
}

/// Everything but segments_fast: out of line, so that the fast path keeps a small frame.
template <bool Construct>
[[nodiscard]] LOCUS_NOINLINE inline Result intersect_general(const Lin& A, const Lin& B,
                                                             bool segments) noexcept {
  if (!finite(A) || !finite(B)) return Result{};
  // Far from 1 the input is scaled by a power of two (exact, and every answer is covariant), so
  // no product of coordinates overflows or underflows.
  if (const int e = range_exponent(A, B); e != 0) [[unlikely]] {
    const Lin As = scaled(A, -e), Bs = scaled(B, -e);
    Result r;
    if (!segments || !segments_sides<Construct>(As.a, As.b, Bs.a, Bs.b, r))
      r = intersect_in_range<Construct>(As, Bs);
    for (V& p : r.point) p = V{std::ldexp(p.x, e), std::ldexp(p.y, e)};
    return r;
  }
  if (segments) {
    Result r;
    if (segments_sides<Construct>(A.a, A.b, B.a, B.b, r)) return r;
  }
  return intersect_in_range<Construct>(A, B);
}

template <bool Construct>
[[nodiscard]] inline Result intersect_in_range(const Lin& A, const Lin& B) noexcept {
  Result r;
  const bool pa = A.a == A.b, pb = B.a == B.b;
  if (pa && pb) {
    if (A.o != B.o) return r;
    r.kind = Kind::point;
    r.count = 1;
    r.point[0] = A.o;
    return r;
  }
  if (pa) return point_on<Construct>(A.o, B, false);
  if (pb) return point_on<Construct>(B.o, A, true);

  // Exact decisions. den is the sign of det[dir A; dir B].
  const Sign a0 = side(B, A.o);
  Sign a1 = Sign::zero;
  Sign den;
  if (A.hi) {
    a1 = side(B, A.b);
    if (a0 == a1) {
      if (a0 != Sign::zero) return r;
      return collinear<Construct>(A, B);
    }
    den = a0 != Sign::zero ? a0 : -a1;
  } else {
    den = turn2d(A.a, A.b, B.a, B.b);
    if (den == Sign::zero) {
      if (a0 != Sign::zero) return r;
      return collinear<Construct>(A, B);
    }
    if (A.lo && to_int(a0 * den) < 0) return r;
  }
  const Sign b0 = side(A, B.o);
  Sign b1 = Sign::zero;
  if (B.lo && to_int(b0 * den) > 0) return r;
  if (B.hi) {
    b1 = side(A, B.b);
    if (to_int(b1 * den) < 0) return r;
  }
  r.kind = Kind::point;
  r.count = 1;
  if constexpr (!Construct) return r;

  // The point: an end point exactly when one lies on the other component, else interpolated
  // along A from its nearer end (a segment) or its origin.
  double ta = 0.0, tb = 0.0;
  bool ta_known = false, tb_known = false;
  V x{};
  if (a0 == Sign::zero) {
    x = A.o, ta = 0.0, ta_known = true;
  } else if (A.hi && a1 == Sign::zero) {
    x = A.b, ta = 1.0, ta_known = true;
  } else if (b0 == Sign::zero) {
    x = B.o, tb = 0.0, tb_known = true;
  } else if (B.hi && b1 == Sign::zero) {
    x = B.b, tb = 1.0, tb_known = true;
  }
  if (!ta_known && !tb_known && A.hi && B.hi && A.a == A.o && B.a == B.o) {
    // Two segments crossing properly: the construction of the fast path (segments_fast).
    proper_crossing<false>(A.a, A.b, B.a, B.b, naive_sides(A.a, A.b, B.a, B.b), r);
    return r;
  }
  if (!ta_known) {
    const Param p = crossing_param(A, B);
    ta = clamp_param(A, p.t);
    if (!tb_known) {
      if (p.from_end)
        x = A.b + std::clamp(p.t_minus_1, -1.0, 0.0) * dir(A);
      else
        x = A.o + clamp_param(A, p.t) * dir(A);
    }
  }
  if (!tb_known) tb = clamp_param(B, crossing_param(B, A).t);
  r.point[0] = x;
  r.param_a[0] = ta;
  r.param_b[0] = tb;
  return r;
}

/// intersects(a, b) for any two of Line2, Ray2, Segment2.
template <class A, class B>
[[nodiscard]] inline bool test(const A& a, const B& b) noexcept {
  return intersect<false>(as_lin(a), as_lin(b)).kind != Kind::empty;
}

/// intersection(a, b) for any two of Line2, Ray2, Segment2, in T.
template <Real T, class A, class B>
[[nodiscard]] inline LinearIntersection2<T> find(const A& a, const B& b) noexcept {
  return intersection_cast<T>(intersect<true>(as_lin(a), as_lin(b)));
}

}  // namespace detail::linear2
}  // namespace locus
