// SPDX-License-Identifier: BSL-1.0
#pragma once
// Internal machinery shared by the point-linear and linear-linear distance headers (rows
// dist2.pt-linear, dist3.pt-linear, dist2.linear-linear, dist3.linear-linear; book sections
// 6.1, 6.3, 10.2, 10.8). The method and its error analysis: docs/notes/distance.md.
//
// A linear component is seen as LinearView {origin, end, dir, bounded_lo, bounded_hi}: the points
// origin + t dir with t >= 0 when bounded_lo and t <= 1 when bounded_hi (a segment has both and
// is evaluated as lerp(origin, end, t) so that its endpoints are exact; a ray has bounded_lo; a
// line neither).
//
// linear_linear minimises |A(s) - B(t)|^2 over the parameter domain: the interior minimiser when
// the directions are well separated, else every realisable candidate (interior point, finite
// edges, an origin's projection) with the smallest winning, so the answer is continuous through
// (near-)parallel configurations. In 2D whether the components meet is decided exactly
// (core's turn2d) and a crossing gets distance exactly 0 (meet_2d; segment_pair_fast may answer
// crossing segments first, with a distance of a few eps * scale).
// Error: the squared distance is within a few eps * scale^2 of the true one, scale the magnitude
// of the closest points. Inputs whose squared directions leave the normal range are solved on
// copies scaled by a power of two (detail/rescale.hpp), so the answer does not depend on units.
// Same-type pairs are solved in a canonical (lexicographic) argument order, so distance(b, a) is
// bit for bit the swap of distance(a, b).
// unique = false when the directions are parallel within sin^2(angle) <= (8 eps)^2 and the
// parameter ranges overlap in more than one point (parallel_unique; also 2D components that
// nearly parallel meet at one exact crossing).

#include <locus/core/error_free.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/branchless.hpp>
#include <locus/distance/detail/rescale.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/segment.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>

namespace locus::detail {

template <class T, int N>
struct LinearView {
  Vec<T, N> origin;
  Vec<T, N> end;  // origin + dir for a segment (exact endpoint); unused otherwise
  Vec<T, N> dir;
  bool bounded_lo;
  bool bounded_hi;

  [[nodiscard]] LOCUS_ALWAYS_INLINE constexpr Vec<T, N> at(T t) const noexcept {
    return bounded_hi ? lerp(origin, end, t) : origin + t * dir;
  }
  [[nodiscard]] LOCUS_ALWAYS_INLINE constexpr T clamp_param(T t) const noexcept {
    if (bounded_lo && t < T(0)) t = T(0);
    if (bounded_hi && t > T(1)) t = T(1);
    return t;
  }
};

template <class T, int N>
[[nodiscard]] LOCUS_ALWAYS_INLINE constexpr LinearView<T, N> view(const Line<T, N>& l) noexcept {
  return {l.origin, l.origin, l.direction, false, false};
}
template <class T, int N>
[[nodiscard]] LOCUS_ALWAYS_INLINE constexpr LinearView<T, N> view(const Ray<T, N>& r) noexcept {
  return {r.origin, r.origin, r.direction, true, false};
}
template <class T, int N>
[[nodiscard]] LOCUS_ALWAYS_INLINE constexpr LinearView<T, N> view(const Segment<T, N>& s) noexcept {
  return {s.p0, s.p1, s.p1 - s.p0, true, true};
}

template <class T, int N>
[[nodiscard]] constexpr bool finite_input(const Line<T, N>& l) noexcept {
  return all_finite(l.origin, l.direction);
}
template <class T, int N>
[[nodiscard]] constexpr bool finite_input(const Ray<T, N>& r) noexcept {
  return all_finite(r.origin, r.direction);
}
template <class T, int N>
[[nodiscard]] constexpr bool finite_input(const Segment<T, N>& s) noexcept {
  return all_finite(s.p0, s.p1);
}

/// closest_param when |dir|^2 underflows or overflows, or the parameter overflows: scale by the
/// largest component first. The offset is scaled by the same factor when that stays finite, so a
/// subnormal direction does not round the products to the subnormal grid. An infinite parameter
/// is clamped by a bounded end (a point far beyond the end of a short segment); 0 when the domain
/// leaves it infinite or it is NaN. (Kept out of closest_param so that its common path inlines.)
template <class T, int N>
[[nodiscard]] T closest_param_rescaled(const LinearView<T, N>& l, const Vec<T, N>& p) noexcept {
  const T m = max_abs(l.dir);
  if (!(m > T(0))) return T(0);
  const Vec<T, N> u = l.dir / m;
  const Vec<T, N> w = p - l.origin;
  const Vec<T, N> ws = w / m;
  const T t = is_finite(ws) ? dot(ws, u) / sqr_length(u) : dot(w, u) / (sqr_length(u) * m);
  const T c = l.clamp_param(t);
  return is_finite(c) ? c : T(0);
}

/// Parameter of the point of `l` closest to p (exact clamp to the domain). A zero direction
/// (or one whose square underflows to zero after scaling) gives 0: the component acts as its
/// origin. A parameter that overflows (p very far along a very short direction) is clamped by a
/// bounded end; where the domain leaves it infinite (a ray or line) or it is NaN, 0.
template <class T, int N>
[[nodiscard]] LOCUS_ALWAYS_INLINE inline T closest_param(const LinearView<T, N>& l,
                                                         const Vec<T, N>& p) noexcept {
  const T a = sqr_length(l.dir);
  if (a >= std::numeric_limits<T>::min() && a <= std::numeric_limits<T>::max()) {
    const T t = dot(p - l.origin, l.dir) / a;
    if (is_finite(t)) return l.clamp_param(t);
  }
  return closest_param_rescaled(l, p);
}

/// |a x b|^2 in any dimension: the sum over coordinate planes of the squared 2x2 minors.
template <class T, int N>
[[nodiscard]] constexpr T sqr_cross_norm(const Vec<T, N>& a, const Vec<T, N>& b) noexcept {
  T s = T(0);
  for (int i = 0; i < N; ++i)
    for (int j = i + 1; j < N; ++j) s += sqr(a[i] * b[j] - a[j] * b[i]);
  return s;
}

template <Real T>
struct LinLinParams {
  T s;
  T t;
  bool unique;
  /// 2D only: the components meet (decided exactly); A.at(s) and B.at(t) are the crossing point
  /// to rounding, and the distance is exactly 0.
  bool meet = false;
};

/// The unconstrained minimiser (s, t) of |A(s) - B(t)|^2 from accurately rounded 2x2 minors:
/// D = |u x v|^2, s = (v x r) . (u x v) / D, t = (u x r) . (u x v) / D with u, v the
/// directions and r = A.origin - B.origin (Lagrange's identity turns Cramer's numerators
/// b e - c d and a e - b d into these; computed from dot products they cancel as badly as D does
/// for nearly parallel directions). Each minor is accurate to a few eps, so the answer has the
/// conditioning of the problem: s is off by ~eps |r| / (|u| sin angle) ALONG the valley of R
/// (r itself is rounded), which raises R by only ~(eps |r|)^2. In 2D s = (v x r) / (u x v)
/// directly. NaN or infinite when the directions are exactly parallel (D = 0) or the minimiser is
/// beyond the range.
template <class T, int N>
[[nodiscard]] inline std::array<T, 2> accurate_minimiser(const LinearView<T, N>& A,
                                                         const LinearView<T, N>& B) noexcept {
  const Vec<T, N> r = A.origin - B.origin, u = A.dir, v = B.dir;
  if constexpr (N == 2) {
    const T den = diff_of_products(u[0], v[1], u[1], v[0]);
    return {diff_of_products(v[0], r[1], v[1], r[0]) / den,
            diff_of_products(u[0], r[1], u[1], r[0]) / den};
  } else {
    T D = T(0), sn = T(0), tn = T(0);
    for (int i = 0; i < N; ++i) {
      for (int j = i + 1; j < N; ++j) {
        const T m = diff_of_products(u[i], v[j], u[j], v[i]);
        D += m * m;
        sn += diff_of_products(v[i], r[j], v[j], r[i]) * m;
        tn += diff_of_products(u[i], r[j], u[j], r[i]) * m;
      }
    }
    return {sn / D, tn / D};
  }
}

/// Exact sign (-1, 0, 1) of (p1 - p0) x (q1 - q0): core's turn2d predicate.
[[nodiscard]] inline int cross_sign(const Vec2<double>& p0, const Vec2<double>& p1,
                                    const Vec2<double>& q0, const Vec2<double>& q1) noexcept {
  return to_int(turn2d(p0, p1, q0, q1));
}

/// 2D: whether the components meet, decided exactly, and if so the meeting point (see
/// LinLinParams). The components' directions as point pairs: a segment's end - origin (its true
/// direction, not the rounded dir), a ray's or line's dir - 0. With u, v the directions and
/// r = A.origin - B.origin, the lines cross at s = (v x r) / (u x v), t = (u x r) / (u x v)
/// unless u x v = 0, and s - 1 = v x (A.end - B.origin) / (u x v),
/// t - 1 = u x (A.origin - B.end) / (u x v): five exact signs decide every constraint. A
/// parameter whose sign is exactly zero is exact (0 or 1: the meeting point is that end point,
/// and the other parameter is its projection); otherwise one comes from accurate_minimiser and
/// the other by projection (see below). meet = false when the lines are parallel, the components
/// miss each other, or the crossing lies beyond the floating-point range. unique is left to the
/// caller.
template <Real T>
[[nodiscard]] inline LinLinParams<T> meet_2d(const LinearView<T, 2>& A,
                                             const LinearView<T, 2>& B) noexcept {
  const auto dbl = [](const Vec2<T>& p) { return Vec2<double>{double(p[0]), double(p[1])}; };
  const Vec2<double> zero{0.0, 0.0};
  const Vec2<double> ao = dbl(A.origin), bo = dbl(B.origin);
  const Vec2<double> a0 = A.bounded_hi ? ao : zero, a1 = A.bounded_hi ? dbl(A.end) : dbl(A.dir);
  const Vec2<double> b0 = B.bounded_hi ? bo : zero, b1 = B.bounded_hi ? dbl(B.end) : dbl(B.dir);
  LinLinParams<T> no{T(0), T(0), true};
  const int sg = cross_sign(a0, a1, b0, b1);
  if (sg == 0) return no;
  const int s_lo = sg * cross_sign(b0, b1, bo, ao);  // sign of s
  if (A.bounded_lo && s_lo < 0) return no;
  const int s_hi = A.bounded_hi ? sg * cross_sign(b0, b1, bo, dbl(A.end)) : -1;  // of s - 1
  if (s_hi > 0) return no;
  const int t_lo = sg * cross_sign(a0, a1, bo, ao);  // sign of t
  if (B.bounded_lo && t_lo < 0) return no;
  const int t_hi = B.bounded_hi ? sg * cross_sign(a0, a1, dbl(B.end), ao) : -1;  // of t - 1
  if (t_hi > 0) return no;
  if (s_lo == 0 || s_hi == 0) {  // A's end point lies on B
    const T s = s_lo == 0 ? T(0) : T(1);
    return {s, closest_param(B, s_lo == 0 ? A.origin : A.end), true, true};
  }
  if (t_lo == 0 || t_hi == 0) {  // B's end point lies on A
    const T t = t_lo == 0 ? T(0) : T(1);
    return {closest_param(A, t_lo == 0 ? B.origin : B.end), t, true, true};
  }
  // The crossing's parameter on one component (a segment if there is one: its clamp bounds the
  // damage), then the other by projection and the first again by projection, so that the pair is
  // consistent even where the crossing itself is ill-conditioned: nearly collinear components
  // (there the rounded direction of a segment may even give u x v the wrong sign, but every point
  // of the overlap is within rounding of the other component).
  const std::array<T, 2> st = accurate_minimiser(A, B);
  if (A.bounded_hi || !B.bounded_hi) {
    if (!is_finite(st[0]) && !A.bounded_hi) return no;  // beyond the range
    const T t = closest_param(B, A.at(is_finite(st[0]) ? A.clamp_param(st[0]) : T(0.5)));
    return {closest_param(A, B.at(t)), t, true, true};
  }
  const T s = closest_param(A, B.at(is_finite(st[1]) ? B.clamp_param(st[1]) : T(0.5)));
  return {s, closest_param(B, A.at(s)), true, true};
}

/// Length of the intersection of [lo0, hi0] and [lo1, hi1] is positive.
template <Real T>
[[nodiscard]] constexpr bool overlaps(T lo0, T hi0, T lo1, T hi1) noexcept {
  const T lo = lo0 < lo1 ? lo1 : lo0;
  const T hi = hi0 < hi1 ? hi0 : hi1;
  return lo < hi;
}

/// The unique flag of linear_linear (see the header): false when the directions are parallel
/// within sin^2(angle) <= (8 eps)^2 (D <= 64 eps^2 a c) and B's parameter range, projected onto
/// A's line as s(t) = (t b - d) / a, overlaps A's range in an interval.
template <class T, int N>
[[nodiscard]] inline bool parallel_unique(const LinearView<T, N>& A, const LinearView<T, N>& B, T a,
                                          T b, T d, T D, T ac) noexcept {
  if (!(D <= T(64) * sqr(eps_v<T>) * ac)) return true;
  constexpr T inf = std::numeric_limits<T>::infinity();
  const T s0 = -d / a;
  T lo1, hi1;
  if (B.bounded_hi) {
    const T s1 = (b - d) / a;
    lo1 = s0 < s1 ? s0 : s1;
    hi1 = s0 < s1 ? s1 : s0;
  } else if (B.bounded_lo) {
    lo1 = b > T(0) ? s0 : -inf;
    hi1 = b > T(0) ? inf : s0;
  } else {
    lo1 = -inf;
    hi1 = inf;
  }
  return !overlaps(A.bounded_lo ? T(0) : -inf, A.bounded_hi ? T(1) : inf, lo1, hi1);
}

/// The view of the component scaled by f about the origin (a segment's direction recomputed
/// from its scaled end points, so that one that overflowed becomes finite).
template <class T, int N>
[[nodiscard]] inline LinearView<T, N> scaled_view(const LinearView<T, N>& l, T f) noexcept {
  const Vec<T, N> o = f * l.origin, e = f * l.end;
  return {o, e, l.bounded_hi ? e - o : f * l.dir, l.bounded_lo, l.bounded_hi};
}

/// linear_linear for components whose squared directions and their product are in range (the
/// caller rescales the others).
template <class T, int N>
[[nodiscard]] inline LinLinParams<T> linear_linear_solve(const LinearView<T, N>& A,
                                                         const LinearView<T, N>& B) noexcept {
  const T a = sqr_length(A.dir), c = sqr_length(B.dir);
  const bool a_point = !(max_abs(A.dir) > T(0)), b_point = !(max_abs(B.dir) > T(0));
  if (a_point && b_point) return {T(0), T(0), true};
  if (a_point) return {T(0), closest_param(B, A.origin), true};
  if (b_point) return {closest_param(A, B.origin), T(0), true};

  const Vec<T, N> r = A.origin - B.origin;
  const T b = dot(A.dir, B.dir), d = dot(A.dir, r), e = dot(B.dir, r);
  const T D = sqr_cross_norm(A.dir, B.dir);  // = a c - b^2 without cancellation
  const T ac = a * c;

  // In the plane the components either meet (distance 0) or have their minimum on an edge of the
  // domain; whether they meet is decided exactly.
  constexpr bool exact_2d = N == 2 && (std::is_same_v<T, float> || std::is_same_v<T, double>);
  if constexpr (exact_2d) {
    LinLinParams<T> m = meet_2d(A, B);
    if (m.meet) {
      m.unique = parallel_unique(A, B, a, b, d, D, ac);
      return m;
    }
  }

  bool have_interior = false;
  T si = T(0), ti = T(0);
  if (D > T(0)) {
    // Cramer's rule is accurate ALONG the valley of R but not across it (s - t cancels for
    // nearly parallel directions): re-derive t by projecting A(s) onto B, then s by projecting
    // B(t) onto A. Each projection is an exact 1D minimiser, so the pair is the minimiser to
    // rounding whenever s was close to it along the valley.
    const T s0 = (b * e - c * d) / D, t0 = (a * e - b * d) / D;
    if (is_finite(s0) && is_finite(t0)) {
      const bool inside = A.clamp_param(s0) == s0 && B.clamp_param(t0) == t0;
      // Well separated directions (angle above ~14 degrees): Cramer's rule is accurate to a few
      // ulps and needs no refinement.
      if (inside && T(16) * D >= ac) return {s0, t0, true};
      if (!inside && D > T(64) * eps_v<T> * ac) {
        // Strictly convex and well conditioned: the constrained minimum lies on an edge whose
        // constraint the unconstrained minimiser violates (otherwise moving towards it would
        // be feasible and decrease R), so only those (at most two) edges are candidates.
        T best = std::numeric_limits<T>::infinity();
        T bs = T(0), bt = T(0);
        const auto edge = [&](T s, T t) {
          const T q = sqr_length(A.at(s) - B.at(t));
          if (q < best) best = q, bs = s, bt = t;
        };
        if (A.bounded_lo && s0 < T(0)) edge(T(0), closest_param(B, A.origin));
        if (A.bounded_hi && s0 > T(1)) edge(T(1), closest_param(B, A.end));
        if (B.bounded_lo && t0 < T(0)) edge(closest_param(A, B.origin), T(0));
        if (B.bounded_hi && t0 > T(1)) edge(closest_param(A, B.end), T(1));
        return {bs, bt, true};
      }
      ti = closest_param(B, A.at(A.clamp_param(s0)));
      si = closest_param(A, B.at(ti));
      have_interior = true;
      if (inside && D > T(64) * eps_v<T> * ac) return {si, ti, true};
    }
  }

  // Nearly parallel (or exactly parallel, or Cramer's rule failed).
  if (!exact_2d && !(A.bounded_hi && B.bounded_hi)) {
    // An unbounded component: the minimiser may lie far away (s ~ |r| / sin angle), where the
    // edges cannot stand in for it; Cramer's rule above is then useless (its numerators cancel
    // like D), so the interior candidate is recomputed from accurate minors. (Two segments keep
    // the candidate above: their parameters are clamped to [0, 1], so a wrong s along the valley
    // costs at most sin^2(angle) |dir|^2 <= 64 eps |dir|^2, and the batch kernels reproduce that
    // arithmetic bit for bit. In 2D components that miss each other have their minimum on an
    // edge.)
    const std::array<T, 2> st = accurate_minimiser(A, B);
    if (is_finite(st[0]) && is_finite(st[1])) {
      ti = closest_param(B, A.at(A.clamp_param(st[0])));
      si = closest_param(A, B.at(ti));
      have_interior = true;
    }
  }

  T best = std::numeric_limits<T>::infinity();
  T bs = T(0), bt = T(0);
  bool found = false;
  const auto consider = [&](T s, T t) {
    const T q = sqr_length(A.at(s) - B.at(t));
    if (!found || q < best) {
      best = q;
      bs = s;
      bt = t;
      found = true;
    }
  };
  if (have_interior) consider(si, ti);
  if (A.bounded_lo) consider(T(0), closest_param(B, A.origin));
  if (A.bounded_hi) consider(T(1), closest_param(B, A.end));
  if (B.bounded_lo) consider(closest_param(A, B.origin), T(0));
  if (B.bounded_hi) consider(closest_param(A, B.end), T(1));
  if (!A.bounded_lo && !B.bounded_lo) consider(T(0), closest_param(B, A.origin));

  return {bs, bt, parallel_unique(A, B, a, b, d, D, ac)};
}

/// linear_linear_solve on the components scaled by the power of two that brings their largest
/// coordinate into [1, 2) (out of line: rare input).
template <class T, int N>
LOCUS_COLD LinLinParams<T> linear_linear_rescaled(const LinearView<T, N>& A,
                                                  const LinearView<T, N>& B) noexcept {
  const T m = std::max({max_abs(A.origin), max_abs(A.end), max_abs(A.dir), max_abs(B.origin),
                        max_abs(B.end), max_abs(B.dir)});
  const T f = normalising_scale(m);
  return linear_linear_solve(scaled_view(A, f), scaled_view(B, f));
}

/// Parameters (s on A, t on B) of a closest pair of two linear components; see the header. When
/// a squared direction or their product leaves the normal range (coordinates beyond ~1e77 or
/// below ~1e-77 in double), the solver runs on the components scaled by a power of two
/// (rescale.hpp): the parameters are scale-free. The batch kernels hand exactly those pairs to
/// this code (their range test is the same), so their lanes keep the unscaled solver's bits.
template <class T, int N>
[[nodiscard]] inline LinLinParams<T> linear_linear(const LinearView<T, N>& A,
                                                   const LinearView<T, N>& B) noexcept {
  constexpr T lo = std::numeric_limits<T>::min(), hi = std::numeric_limits<T>::max();
  const T a = sqr_length(A.dir), c = sqr_length(B.dir), ac = a * c;
  if (!(a >= lo && a <= hi && c >= lo && c <= hi && ac >= lo && ac <= hi)) [[unlikely]]
    return linear_linear_rescaled(A, B);
  return linear_linear_solve(A, B);
}

/// What a point-linear query finds; distance() and sqr_distance() both read it. finite is false
/// (and sqr NaN) exactly when some input coordinate is NaN or infinite.
template <class T, int N>
struct PointLinearCore {
  T t;                ///< parameter of the closest point
  Vec<T, N> closest;  ///< point_at(l, t)
  T sqr;              ///< sqr_length(closest - p)
  bool finite;
};

template <class T, int N, class L>
[[nodiscard]] inline PointLinearCore<T, N> point_linear_core(const Vec<T, N>& p,
                                                             const L& l) noexcept {
  if (!(all_finite(p) && finite_input(l))) {
    constexpr T nan = std::numeric_limits<T>::quiet_NaN();
    return {nan, splat<T, N>(nan), nan, false};
  }
  const T t = closest_param(view(l), p);
  const Vec<T, N> x = point_at(l, t);
  return {t, x, sqr_length(x - p), true};
}

/// distance(p, l) for a point and a line, ray or segment.
template <class T, int N, class L>
[[nodiscard]] inline Distance<T, N, NoParam, T> point_linear(const Vec<T, N>& p,
                                                             const L& l) noexcept {
  const PointLinearCore<T, N> r = point_linear_core(p, l);
  if (!r.finite) return non_finite_distance<T, N, NoParam, T>();
  return make_distance(p, r.closest, NoParam{}, r.t, true);
}

/// Lexicographic order of the views' defining points (origin, then end or direction).
template <class T, int N>
[[nodiscard]] constexpr bool lex_less(const Vec<T, N>& a, const Vec<T, N>& b) noexcept {
  for (int i = 0; i < N; ++i)
    if (a[i] != b[i]) return a[i] < b[i];
  return false;
}
template <class L>
[[nodiscard]] constexpr bool lex_less(const L& a, const L& b) noexcept {
  const auto va = view(a), vb = view(b);
  if (!(va.origin == vb.origin)) return lex_less(va.origin, vb.origin);
  return lex_less(va.bounded_hi ? va.end : va.dir, vb.bounded_hi ? vb.end : vb.dir);
}

/// What a linear-linear query finds; distance() and sqr_distance() both read it. finite is false
/// (and everything NaN) exactly when some input coordinate is NaN or infinite.
template <class T, int N>
struct LinearPairCore {
  T s, t;                            ///< parameters on the first and the second component
  std::array<Vec<T, N>, 2> closest;  ///< point_at(first, s), point_at(second, t)
  T sqr;                             ///< sqr_length(closest[0] - closest[1]); 0 when 2D ones meet
  bool unique;
  bool finite;
};

/// The fast path for two segments: finite input, squares in range, and directions that are not
/// nearly parallel (|dA x dB|^2 > 64 eps |dA|^2 |dB|^2), unless the unconstrained minimiser lies
/// in the domain at an angle below ~14 degrees (that case needs linear_linear's refinement).
/// Returns false when it does not apply. The minimum of the convex R(s, t) is the unconstrained
/// minimiser (Cramer's rule) when it lies in [0, 1]^2. Otherwise (KKT) it lies on an edge of the
/// domain whose constraint the minimiser violates: the one edge when it violates one; at a corner
/// region (two violated) the edge along which moving away from the corner descends (both cannot
/// descend when |dA x dB| > 0, as in point_triangle.hpp; when neither does, or rounding says both,
/// the corner itself). So every case is ONE exact clamped 1D projection, chosen by branches: on
/// mixed input they cost less than computing both divisions and selecting (1.2x per query,
/// measured); the batch kernels compute both and select, with the same bits. Each operation is
/// mirrored exactly under swapping the arguments ((a, b, c, d, e) ->
/// (c, b, a, -e, -d) and the two Cramer numerators trade places without rounding differences),
/// so the result is bit for bit the swap without a canonical argument order.
template <class T, int N>
[[nodiscard]] LOCUS_ALWAYS_INLINE inline bool segment_pair_fast(
    const Segment<T, N>& x, const Segment<T, N>& y, LinearPairCore<T, N>& out) noexcept {
  const Vec<T, N> da = x.p1 - x.p0, db = y.p1 - y.p0, r = x.p0 - y.p0;
  const T a = dot(da, da), b = dot(da, db), c = dot(db, db), d = dot(da, r), e = dot(db, r);
  const T D = sqr_cross_norm(da, db), ac = a * c;
  const T sn = b * e - c * d, tn = a * e - b * d;  // D * (s, t) of the unconstrained minimiser
  const bool sl = (sn < T(0)), sh = (sn > D), tl = (tn < T(0)), th = (tn > D);
  const bool s_out = sl | sh, t_out = tl | th;
  constexpr T lo = std::numeric_limits<T>::min(), hi = std::numeric_limits<T>::max();
  // da, db are finite when a, c are; then d, e are finite exactly when r (x.p0, y.p0) is.
  if (!(a >= lo && c >= lo && ac <= hi && (d - d) + (e - e) == T(0) && D > T(64) * eps_v<T> * ac &&
        (s_out | t_out | (T(16) * D >= ac)))) [[unlikely]]
    return false;
  const T zero = a - a, one = zero + T(1);  // computed bounds: the clamps become max/min
  T s, t;
  if (!(s_out | t_out)) {
    s = clamp_minmax(sn / D, zero, one);
    t = clamp_minmax(tn / D, zero, one);
  } else {
    const T sc = sh ? T(1) : T(0), tc = th ? T(1) : T(0);  // the violated bounds
    // Derivatives of R / 2 along s and t at (sc, tc), and whether moving into the domain along
    // each descends.
    const T gs = (a * sc - b * tc) + d, gt = (c * tc - b * sc) - e;
    const bool ds = (sl & (gs < T(0))) | (sh & (gs > T(0)));
    const bool dt = (tl & (gt < T(0))) | (th & (gt > T(0)));
    if (s_out & ((!t_out) | (dt & (!ds)))) {  // s = sc, t projected
      s = sc;
      t = clamp_minmax((b * sc + e) / c, zero, one);
    } else if (t_out & ((!s_out) | (ds & (!dt)))) {  // t = tc, s projected
      s = clamp_minmax((b * tc - d) / a, zero, one);
      t = tc;
    } else {  // the corner
      s = sc;
      t = tc;
    }
  }
  const Vec<T, N> pa = lerp(x.p0, x.p1, s), pb = lerp(y.p0, y.p1, t);
  out = {s, t, {pa, pb}, sqr_length(pa - pb), true, true};
  return true;
}

/// Two segments outside segment_pair_fast: linear_linear in the canonical argument order. Out of
/// line, so that segment_pair stays small enough to inline; flattened, so that linear_linear's
/// branches on the kinds of its components fold away.
template <class T, int N>
[[nodiscard]] LOCUS_FLATTEN LinearPairCore<T, N> segment_pair_general(
    const Segment<T, N>& x, const Segment<T, N>& y) noexcept {
  if (!(finite_input(x) && finite_input(y))) {
    constexpr T nan = std::numeric_limits<T>::quiet_NaN();
    return {nan, nan, {splat<T, N>(nan), splat<T, N>(nan)}, nan, false, false};
  }
  // Same types: solve in a canonical order so that the swapped query gives the same bits (the
  // candidates' rounding would otherwise depend on the order).
  const bool swap = lex_less(y, x);
  const Segment<T, N>& u = swap ? y : x;
  const Segment<T, N>& v = swap ? x : y;
  const LinLinParams<T> st = linear_linear(view(u), view(v));
  const Vec<T, N> pu = point_at(u, st.s), pv = point_at(v, st.t);
  const T sqr = st.meet ? T(0) : sqr_length(pu - pv);  // meeting (2D): exactly 0
  if (swap) return {st.t, st.s, {pv, pu}, sqr, st.unique, true};
  return {st.s, st.t, {pu, pv}, sqr, st.unique, true};
}

/// Two segments: the fast path, else segment_pair_general. Always inlined: a caller that reads only
/// the squared distance (sqr_distance) then drops the rest of the fast path's result instead of
/// receiving it through memory (per query 1.1x-1.2x, bench/distance segment_segment/sqr_distance).
template <class T, int N>
[[nodiscard]] LOCUS_ALWAYS_INLINE inline LinearPairCore<T, N> segment_pair(
    const Segment<T, N>& x, const Segment<T, N>& y) noexcept {
  LinearPairCore<T, N> out{};
  if (segment_pair_fast(x, y, out)) [[likely]]
    return out;
  return segment_pair_general(x, y);
}

/// distance(a, b) for two linear components.
template <class T, int N, class LA, class LB>
[[nodiscard]] inline Distance<T, N, T, T> linear_linear_distance(const LA& a,
                                                                 const LB& b) noexcept {
  if constexpr (std::is_same_v<LA, Segment<T, N>> && std::is_same_v<LB, Segment<T, N>>) {
    const LinearPairCore<T, N> r = segment_pair(a, b);
    if (!r.finite) return non_finite_distance<T, N, T, T>();
    // sqr = 0 with distinct points: 2D segments meeting (segment_pair).
    if (r.sqr == T(0)) return {T(0), T(0), r.closest, r.s, r.t, r.unique};
    // r.sqr is make_distance's sum of squares, already computed.
    constexpr T lo = std::numeric_limits<T>::min(), hi = std::numeric_limits<T>::max();
    const T len = r.sqr > lo && r.sqr < hi ? std::sqrt(r.sqr) : length(r.closest[0] - r.closest[1]);
    return {len, r.sqr, r.closest, r.s, r.t, r.unique};
  }
  if (!finite_input(a) || !finite_input(b)) return non_finite_distance<T, N, T, T>();
  if constexpr (std::is_same_v<LA, LB>) {
    // Same types: solve in a canonical order so that distance(b, a) is bit for bit the swap of
    // distance(a, b) (the candidates' rounding would otherwise depend on the order).
    if (lex_less(b, a)) return swapped(linear_linear_distance<T, N>(b, a));
  }
  const LinLinParams<T> st = linear_linear(view(a), view(b));
  if (st.meet) {  // 2D, meeting: distance exactly 0 (the points are the crossing to rounding)
    return {T(0), T(0), {point_at(a, st.s), point_at(b, st.t)}, st.s, st.t, st.unique};
  }
  return make_distance(point_at(a, st.s), point_at(b, st.t), st.s, st.t, st.unique);
}

}  // namespace locus::detail
