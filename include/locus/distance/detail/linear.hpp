// SPDX-License-Identifier: BSL-1.0
#pragma once
// Internal machinery shared by the point-linear and linear-linear distance headers (rows
// dist2.pt-linear, dist3.pt-linear, dist2.linear-linear, dist3.linear-linear; book sections
// 6.1, 6.3, 10.2, 10.8).
//
// A linear component is seen as LinearView {origin, end, dir, bounded_lo, bounded_hi}: the points
// origin + t dir with t >= 0 when bounded_lo and t <= 1 when bounded_hi (a segment has both and
// is evaluated as lerp(origin, end, t) so that its endpoints are exact; a ray has bounded_lo; a
// line neither).
//
// Linear-linear method (written for this library; the approach follows the analysis in Eberly,
// "Robust Computation of Distance Between Line Segments"): R(s, t) = |A(s) - B(t)|^2 is a convex
// quadratic over the parameter domain I_A x I_B. Its minimum is either the unconstrained
// minimiser (if it lies in the domain) or lies on an edge s = 0, s = 1, t = 0 or t = 1 of the
// domain, where the problem is a point-linear query with an exact clamp. The unconstrained
// minimiser comes from Cramer's rule; below an angle of ~14 degrees its s - t is inaccurate
// (cancellation), so t is re-derived by projecting A(s) onto B and then s by projecting B(t)
// onto A. When the directions are well separated (|dA x dB|^2 > 64 eps |dA|^2 |dB|^2) and the
// minimiser lies in the domain it is returned; when it lies outside, only the (one or two) edges
// whose constraints it violates can hold the minimum (KKT), and the nearer of those wins. In the
// nearly parallel regime every candidate (the refined interior point, each finite edge, and for
// two lines the projection of A's origin) is evaluated and the smallest squared distance wins.
// Every candidate is a realisable pair of points, so the answer is never below the true distance by
// more than rounding and is a minimum of continuous functions of the input, hence continuous as the
// input moves through (near-)parallel configurations; this is what the textbook "if det < epsilon
// then parallel" code gets wrong. |dA x dB|^2 is evaluated as a sum of squared 2x2 minors
// (Lagrange's identity), not as a c - b^2, so it does not cancel. Error: the squared distance is
// within a few eps * (scale)^2 of the true one, scale being the magnitude of the closest points
// (tested against exact rationals). When two unbounded components are parallel to within ~eps the
// problem itself is ill-posed (the closest points may be arbitrarily far away, and every answer
// between the parallel distance and the exact one is exact for input perturbed by an ulp); the
// answer is then one of those.
//
// Same-type pairs are solved in a canonical (lexicographic) argument order, so distance(b, a) is
// bit for bit the swap of distance(a, b).
// unique = false when the directions are parallel within sin^2(angle) <= (8 eps)^2 (the closest
// pair is numerically undetermined) and the parameter ranges overlap in more than one point.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/branchless.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/segment.hpp>

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

template <class T>
struct LinLinParams {
  T s;
  T t;
  bool unique;
};

/// Length of the intersection of [lo0, hi0] and [lo1, hi1] is positive.
template <class T>
[[nodiscard]] constexpr bool overlaps(T lo0, T hi0, T lo1, T hi1) noexcept {
  const T lo = lo0 < lo1 ? lo1 : lo0;
  const T hi = hi0 < hi1 ? hi0 : hi1;
  return lo < hi;
}

/// Parameters (s on A, t on B) of a closest pair of two linear components; see the header.
template <class T, int N>
[[nodiscard]] inline LinLinParams<T> linear_linear(const LinearView<T, N>& A,
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

  bool unique = true;
  if (D <= T(64) * sqr(eps_v<T>) * ac) {
    // Parallel: project B's parameter range onto A's line, s(t) = (t b - d) / a, and see
    // whether it overlaps A's range in an interval.
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
    unique = !overlaps(A.bounded_lo ? T(0) : -inf, A.bounded_hi ? T(1) : inf, lo1, hi1);
  }
  return {bs, bt, unique};
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
  T sqr;                             ///< sqr_length(closest[0] - closest[1])
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
/// the corner itself). So every case is ONE exact clamped 1D projection, chosen with selects: the
/// region is unpredictable on mixed input, and a mispredicted branch costs more than the whole
/// query. Each operation is mirrored exactly under swapping the arguments ((a, b, c, d, e) ->
/// (c, b, a, -e, -d) and the two Cramer numerators trade places without rounding differences),
/// so the result is bit for bit the swap without a canonical argument order.
template <class T, int N>
[[nodiscard]] inline bool segment_pair_fast(const Segment<T, N>& x, const Segment<T, N>& y,
                                            LinearPairCore<T, N>& out) noexcept {
  const Vec<T, N> da = x.p1 - x.p0, db = y.p1 - y.p0, r = x.p0 - y.p0;
  const T a = dot(da, da), b = dot(da, db), c = dot(db, db), d = dot(da, r), e = dot(db, r);
  const T D = sqr_cross_norm(da, db), ac = a * c;
  const T sn = b * e - c * d, tn = a * e - b * d;  // D * (s, t) of the unconstrained minimiser
  const bool sl = (sn < T(0)), sh = (sn > D), tl = (tn < T(0)), th = (tn > D);
  const bool s_out = sl | sh, t_out = tl | th;
  constexpr T lo = std::numeric_limits<T>::min(), hi = std::numeric_limits<T>::max();
  // da, db are finite when a, c are; then d, e are finite exactly when r (x.p0, y.p0) is.
  if (!(a >= lo && c >= lo && ac <= hi && (d - d) + (e - e) == T(0) && D > T(64) * eps_v<T> * ac &&
        (s_out | t_out | (T(16) * D >= ac))))
    return false;
  const T sc = select(sh, T(1), T(0)), tc = select(th, T(1), T(0));  // the violated bounds
  // Derivatives of R / 2 along s and t at (sc, tc), and whether moving into the domain along
  // each descends.
  const T gs = (a * sc - b * tc) + d, gt = (c * tc - b * sc) - e;
  const bool ds = (sl & (gs < T(0))) | (sh & (gs > T(0)));
  const bool dt = (tl & (gt < T(0))) | (th & (gt > T(0)));
  const bool move_t = s_out & ((!t_out) | (dt & (!ds)));  // s = sc, t projected
  const bool move_s = t_out & ((!s_out) | (ds & (!dt)));  // t = tc, s projected
  const bool pin_s = s_out & (!move_s), pin_t = t_out & (!move_t);
  const T qs = select(move_s, b * tc - d, sn) / select(move_s, a, D);  // in [0, 1] if inside
  const T qt = select(move_t, b * sc + e, tn) / select(move_t, c, D);
  const T zero = a - a, one = zero + T(1);  // computed bounds: the clamps become max/min
  const T s = select(pin_s, sc, clamp_minmax(qs, zero, one));
  const T t = select(pin_t, tc, clamp_minmax(qt, zero, one));
  const Vec<T, N> pa = lerp(x.p0, x.p1, s), pb = lerp(y.p0, y.p1, t);
  out = {s, t, {pa, pb}, sqr_length(pa - pb), true, true};
  return true;
}

/// Two segments: the fast path, else linear_linear in the canonical argument order.
template <class T, int N>
[[nodiscard]] inline LinearPairCore<T, N> segment_pair(const Segment<T, N>& x,
                                                       const Segment<T, N>& y) noexcept {
  LinearPairCore<T, N> out{};
  if (segment_pair_fast(x, y, out)) return out;
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
  const T sqr = sqr_length(pu - pv);
  if (swap) return {st.t, st.s, {pv, pu}, sqr, st.unique, true};
  return {st.s, st.t, {pu, pv}, sqr, st.unique, true};
}

/// distance(a, b) for two linear components.
template <class T, int N, class LA, class LB>
[[nodiscard]] inline Distance<T, N, T, T> linear_linear_distance(const LA& a,
                                                                 const LB& b) noexcept {
  if constexpr (std::is_same_v<LA, Segment<T, N>> && std::is_same_v<LB, Segment<T, N>>) {
    const LinearPairCore<T, N> r = segment_pair(a, b);
    if (!r.finite) return non_finite_distance<T, N, T, T>();
    return make_distance(r.closest[0], r.closest[1], r.s, r.t, r.unique);
  }
  if (!finite_input(a) || !finite_input(b)) return non_finite_distance<T, N, T, T>();
  if constexpr (std::is_same_v<LA, LB>) {
    // Same types: solve in a canonical order so that distance(b, a) is bit for bit the swap of
    // distance(a, b) (the candidates' rounding would otherwise depend on the order).
    if (lex_less(b, a)) return swapped(linear_linear_distance<T, N>(b, a));
  }
  const LinLinParams<T> st = linear_linear(view(a), view(b));
  return make_distance(point_at(a, st.s), point_at(b, st.t), st.s, st.t, st.unique);
}

}  // namespace locus::detail
