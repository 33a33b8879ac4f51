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

#include <locus/core/crossing.hpp>
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

template <bool Construct>
[[nodiscard]] inline Result intersect_in_range(const Lin& A, const Lin& B) noexcept;

template <bool Construct>
[[nodiscard]] inline Result intersect(const Lin& A, const Lin& B) noexcept {
  if (!finite(A) || !finite(B)) return Result{};
  // Far from 1 the input is scaled by a power of two (exact, and every answer is covariant), so
  // no product of coordinates overflows or underflows.
  if (const int e = range_exponent(A, B); e != 0) [[unlikely]] {
    Result r = intersect_in_range<Construct>(scaled(A, -e), scaled(B, -e));
    for (V& p : r.point) p = V{std::ldexp(p.x, e), std::ldexp(p.y, e)};
    return r;
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
