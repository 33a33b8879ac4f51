// SPDX-License-Identifier: BSL-1.0
#pragma once
// Subdivision of parametric curves (row num.subdivide; book appendix A, numerical methods for
// curves; the four schemes of Eberly's "subdivision of curves"). Methods, accuracy and caveats:
// docs/notes/numeric.md.
// A curve is any callable `Vec<T, N> curve(T t)`; its derivative, where asked for, any callable
// `Vec<T, N> dcurve(T t)`. Every scheme works on the ORIENTED parameter interval from t0 to t1
// (t1 < t0 is allowed: the parameters then decrease) and returns CurveSamples: the parameters
// params[0] = t0, ..., params.back() = t1 (exactly) and points[i] = curve(params[i]).
//   subdivide_uniform(c, t0, t1, n)        n parameters equally spaced in t.
//   arc_length(c[, dc], t0, t1)            the length: adaptive 5-point Gauss-Legendre of |c'|.
//   subdivide_arc_length(c[, dc], t0, t1, n)  n points equally spaced in ARC LENGTH.
//   subdivide_midpoint(c, t0, t1, tol)     halves a piece while the curve midpoint is farther
//                                          than tol from the chord midpoint.
//   subdivide_variation(c, t0, t1, tol)    halves a piece while the RMS distance between piece
//                                          and chord, sqrt(V / (b - a)), exceeds tol.
// Without a derivative c' is differenced (lengths accurate to about eps_T^(2/3) relative).
// Bad input (nothing loops unboundedly, nothing returns NaN as valid): n < 2 or tol < 0 / NaN:
// invalid_input; non-finite t0, t1 or curve values: non_finite_input (empty output, length NaN);
// a zero-length curve: ordinary results, but subdivide_arc_length returns the uniform sampling
// with degenerate_input. Budgets (max_depth, max_points, max_evaluations, max_iterations, or a
// piece too short to halve): limit_exceeded with the valid coarser result reached.
// Caveats: a kink of |c'| near a quadrature interval's end can exceed the tolerance (split the
// interval there); the midpoint test accepts a piece whose midpoint lies on the chord (raise
// min_depth). Computed in compute_t<T>; the curve is evaluated at parameters of type T.
// Cost: uniform n evaluations; arc length 10 per quadrature leaf (3x without a derivative) plus
// about 6 per Newton step per point; midpoint 1 and variation 5 per piece examined.

#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>

#include <algorithm>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace locus {

/// Parameters and points sampled along a curve, with the outcome of the scheme.
template <class T, int N>
struct CurveSamples {
  Status status = Status::empty_input;
  std::vector<T> params;          ///< from t0 to t1 (monotone), both ends included exactly
  std::vector<Vec<T, N>> points;  ///< points[i] = curve(params[i])
};

/// Length of a curve, with the outcome of the quadrature.
template <Real T>
struct ArcLength {
  Status status = Status::empty_input;
  T length = T(0);
  int evaluations = 0;  ///< derivative evaluations used
};

/// Options of arc_length and subdivide_arc_length.
template <Real T>
struct ArcLengthOptions {
  /// Target absolute error of a length, relative to the curve's total length.
  T relative_tolerance = T(64) * eps_v<T>;
  int max_depth = 40;             ///< halvings of one quadrature interval
  int max_evaluations = 1 << 20;  ///< derivative evaluations of the quadrature
  int max_iterations = 100;       ///< Newton/bisection steps per inverted arc length
};

/// Options of subdivide_midpoint and subdivide_variation.
struct SubdivisionOptions {
  int min_depth = 0;         ///< always halve this many levels (guards against fooled tests)
  int max_depth = 24;        ///< never halve a piece more often than this
  int max_points = 1 << 16;  ///< total points of the result
};

namespace detail::subdivide {

template <class V>
struct VecTraits;
template <class T, int N>
struct VecTraits<Vec<T, N>> {
  static constexpr int dim = N;
  using scalar = T;
};

template <class F, class T>
concept CurveFunction = std::invocable<F&, T> &&
    std::is_same_v<typename VecTraits<std::remove_cvref_t<std::invoke_result_t<F&, T>>>::scalar, T>;

template <class F, class T>
inline constexpr int curve_dim = VecTraits<std::remove_cvref_t<std::invoke_result_t<F&, T>>>::dim;

// 5-point Gauss-Legendre on [-1, 1]: nodes +-(1/3) sqrt(5 -+ 2 sqrt(10/7)), 0.
inline constexpr long double gl_x1 = 0.538469310105683091036314420700208805L;
inline constexpr long double gl_x2 = 0.906179845938663992797626878299392965L;
inline constexpr long double gl_w0 = 128.0L / 225.0L;
inline constexpr long double gl_w1 = 0.478628670499366468041291514835638192L;
inline constexpr long double gl_w2 = 0.236926885056189087514264040719917363L;

template <class C>
struct Gauss5 {
  C x[5];  // nodes on [0, 1], ascending, x[2] = 1/2
  C w[5];  // weights on [0, 1] (sum 1)
};
template <class C>
constexpr Gauss5<C> gauss5() noexcept {
  const C a = C(gl_x2) / C(2), b = C(gl_x1) / C(2);
  return {{C(0.5) - a, C(0.5) - b, C(0.5), C(0.5) + b, C(0.5) + a},
          {C(gl_w2) / C(2), C(gl_w1) / C(2), C(gl_w0) / C(2), C(gl_w1) / C(2), C(gl_w2) / C(2)}};
}

template <class T, int N, class C = compute_t<T>>
C length_c(const Vec<T, N>& v) noexcept {
  C s = C(0);
  for (int i = 0; i < N; ++i) s += C(v[i]) * C(v[i]);
  return std::sqrt(s);
}

// The parameter at fraction u of the oriented interval, ends exact.
template <class T, class C = compute_t<T>>
T param_at(T t0, T t1, C u) noexcept {
  if (u <= C(0)) return t0;
  if (u >= C(1)) return t1;
  return static_cast<T>(C(t0) + (C(t1) - C(t0)) * u);
}

// |dc/dt| at t, from the user's derivative.
template <class T, class DF>
struct ExactSpeed {
  DF& dcurve;
  compute_t<T> operator()(T t) const { return length_c(dcurve(t)); }
};

// |dc/dt| at t from the quadratic through three samples near t, inside [lo, hi].
template <class T, class F>
struct FiniteDifferenceSpeed {
  F& curve;
  T lo, hi;
  compute_t<T> operator()(T t) const {
    using C = compute_t<T>;
    const C width = C(hi) - C(lo);
    if (width == C(0)) return C(0);
    const C h = std::cbrt(C(eps_v<T>)) * width;
    const C s = std::clamp(C(t) - h, C(lo), C(hi) - C(2) * h);
    const T a = static_cast<T>(s), b = static_cast<T>(s + h), c = static_cast<T>(s + C(2) * h);
    const C ca = C(a), cb = C(b), cc = C(c), x = C(t);
    if (!(ca < cb && cb < cc)) return std::numeric_limits<C>::quiet_NaN();
    const auto fa = curve(a), fb = curve(b), fc = curve(c);
    const C wa = (C(2) * x - cb - cc) / ((ca - cb) * (ca - cc));
    const C wc = (C(2) * x - ca - cb) / ((cc - ca) * (cc - cb));
    C sum = C(0);
    for (int i = 0; i < curve_dim<F, T>; ++i) {
      // The weights sum to zero, so differences from the middle sample are used: a constant
      // curve then has speed exactly 0.
      const C d = wa * (C(fa[i]) - C(fb[i])) + wc * (C(fc[i]) - C(fb[i]));
      sum += d * d;
    }
    return std::sqrt(sum);
  }
};

// Finite differences carry errors of about eps_T^(2/3): asking the quadrature for more would
// only chase that noise down to the depth budget.
template <Real T>
ArcLengthOptions<T> fd_options(ArcLengthOptions<T> opt) noexcept {
  const T floor = T(4) * std::cbrt(eps_v<T> * eps_v<T>);
  if (opt.relative_tolerance >= T(0) && opt.relative_tolerance < floor)
    opt.relative_tolerance = floor;
  return opt;
}

// One leaf of the length table: u-interval and its length.
template <class C>
struct Leaf {
  C ua, ub, length;
};

template <Real T>
struct LengthTable {
  using C = compute_t<T>;
  Status status = Status::empty_input;
  std::vector<Leaf<C>> leaves;  // ordered from u = 0 to u = 1
  C total = C(0);
  int evaluations = 0;
};

// Integral of speed over [ua, ub] (fractions of the oriented interval t0 -> t1) by Gauss5.
template <class T, class Speed, class C = compute_t<T>>
C gauss_length(Speed& speed, T t0, T t1, C ua, C ub, int& evals, bool& finite) {
  constexpr Gauss5<C> g = gauss5<C>();
  const C width = ub - ua, scale = std::abs(C(t1) - C(t0));
  C sum = C(0);
  for (int i = 0; i < 5; ++i) {
    const C v = speed(param_at(t0, t1, ua + width * g.x[i]));
    if (!locus::is_finite(v)) finite = false;
    sum += g.w[i] * v;
  }
  evals += 5;
  return sum * width * scale;
}

template <class T, class Speed>
LengthTable<T> length_table(Speed& speed, T t0, T t1, const ArcLengthOptions<T>& opt) {
  using C = compute_t<T>;
  LengthTable<T> tab;
  tab.status = Status::ok;
  struct Item {
    C ua, ub, whole;
    int depth;
  };
  constexpr int initial = 8;  // a first uniform split, so one Gauss rule never sees the whole
  bool finite = true;
  std::vector<Item> stack;
  C rough = C(0);
  Item first[initial];
  for (int i = 0; i < initial; ++i) {
    const C ua = C(i) / C(initial), ub = C(i + 1) / C(initial);
    first[i] = {ua, ub, gauss_length(speed, t0, t1, ua, ub, tab.evaluations, finite), 0};
    rough += first[i].whole;
  }
  if (!finite) {
    tab.status = Status::non_finite_input;
    return tab;
  }
  const C abs_tol = C(opt.relative_tolerance) * rough;
  for (int i = initial - 1; i >= 0; --i) stack.push_back(first[i]);
  bool limit = false;
  while (!stack.empty()) {
    const Item it = stack.back();
    stack.pop_back();
    if (tab.evaluations >= opt.max_evaluations) {
      // Out of budget: the whole-interval estimate stands.
      limit = true;
      tab.leaves.push_back({it.ua, it.ub, it.whole});
      tab.total += it.whole;
      continue;
    }
    const C um = (it.ua + it.ub) / C(2);
    const C left = gauss_length(speed, t0, t1, it.ua, um, tab.evaluations, finite);
    const C right = gauss_length(speed, t0, t1, um, it.ub, tab.evaluations, finite);
    if (!finite) {
      tab.status = Status::non_finite_input;
      tab.leaves.clear();
      return tab;
    }
    const C both = left + right;
    const C err = std::abs(both - it.whole);
    // The round-off floor keeps a tolerance below the noise of the sums from recursing forever.
    const bool good =
        err <= abs_tol * (it.ub - it.ua) || err <= C(32) * std::numeric_limits<C>::epsilon() * both;
    const bool stop = it.depth >= opt.max_depth || !(it.ua < um && um < it.ub);
    if (good || stop) {
      if (!good) limit = true;
      tab.leaves.push_back({it.ua, um, left});
      tab.leaves.push_back({um, it.ub, right});
      tab.total += both;
    } else {
      stack.push_back({um, it.ub, right, it.depth + 1});
      stack.push_back({it.ua, um, left, it.depth + 1});
    }
  }
  if (limit) tab.status = Status::limit_exceeded;
  return tab;
}

template <class T, int N, class F>
bool push_point(CurveSamples<T, N>& out, F& curve, T t) {
  const Vec<T, N> p = curve(t);
  out.params.push_back(t);
  out.points.push_back(p);
  return is_finite(p);
}

template <class T, int N>
void fail(CurveSamples<T, N>& out, Status s) {
  out.status = s;
  out.params.clear();
  out.points.clear();
}

template <class T, int N, class F>
CurveSamples<T, N> uniform(F& curve, T t0, T t1, int count, Status status) {
  using C = compute_t<T>;
  CurveSamples<T, N> out;
  out.status = Status::ok;
  out.status = status;
  out.params.reserve(static_cast<std::size_t>(count));
  out.points.reserve(static_cast<std::size_t>(count));
  bool finite = true;
  for (int i = 0; i < count; ++i) {
    const T t = i == count - 1 ? t1 : param_at(t0, t1, C(i) / C(count - 1));
    finite = push_point(out, curve, t) && finite;
  }
  if (!finite) fail(out, Status::non_finite_input);
  return out;
}

template <class T, int N, class F, class Speed>
CurveSamples<T, N> arc_length_samples(F& curve, Speed& speed, T t0, T t1, int count,
                                      const ArcLengthOptions<T>& opt) {
  using C = compute_t<T>;
  CurveSamples<T, N> out;
  out.status = Status::ok;
  if (count < 2 || !(opt.relative_tolerance >= T(0))) {
    out.status = Status::invalid_input;
    return out;
  }
  if (!locus::is_finite(t0) || !locus::is_finite(t1)) {
    out.status = Status::non_finite_input;
    return out;
  }
  LengthTable<T> tab = length_table(speed, t0, t1, opt);
  if (tab.status == Status::non_finite_input) {
    out.status = Status::non_finite_input;
    return out;
  }
  if (!(tab.total > C(0))) return uniform<T, N>(curve, t0, t1, count, Status::degenerate_input);
  bool limit = tab.status == Status::limit_exceeded;
  const C abs_tol = std::max(C(opt.relative_tolerance) * tab.total,
                             C(4) * std::numeric_limits<C>::epsilon() * tab.total);
  // Cumulative lengths at the leaves' starts.
  std::vector<C> start(tab.leaves.size() + 1, C(0));
  for (std::size_t k = 0; k < tab.leaves.size(); ++k)
    start[k + 1] = start[k] + tab.leaves[k].length;
  const C total = start.back();
  out.params.reserve(static_cast<std::size_t>(count));
  out.points.reserve(static_cast<std::size_t>(count));
  bool finite = push_point(out, curve, t0);
  int evals = 0;
  std::size_t k = 0;
  for (int i = 1; i < count - 1; ++i) {
    const C target = total * C(i) / C(count - 1);
    while (k + 1 < tab.leaves.size() && (start[k + 1] < target || tab.leaves[k].length <= C(0)))
      ++k;
    const Leaf<C>& leaf = tab.leaves[k];
    const C rem = target - start[k];
    // s_leaf(u) = leaf.length * G(ua, u) / G(ua, ub): the leaf's own Gauss rule rescaled so the
    // local arc length meets the table exactly at both ends, hence monotone and consistent.
    bool fin = true;
    const C whole = gauss_length(speed, t0, t1, leaf.ua, leaf.ub, evals, fin);
    C u;
    if (!(whole > C(0)) || !(leaf.length > C(0))) {
      u = leaf.ua;
    } else {
      const C ratio = leaf.length / whole;
      C lo = leaf.ua, hi = leaf.ub;
      u = leaf.ua + (leaf.ub - leaf.ua) * std::clamp(rem / leaf.length, C(0), C(1));
      bool done = false;
      for (int it = 0; it < opt.max_iterations && fin; ++it) {
        const C g = ratio * gauss_length(speed, t0, t1, leaf.ua, u, evals, fin) - rem;
        if (std::abs(g) <= abs_tol / C(8)) {
          done = true;
          break;
        }
        if (g < C(0))
          lo = u;
        else
          hi = u;
        const C dg = ratio * speed(param_at(t0, t1, u)) * std::abs(C(t1) - C(t0));
        C next = dg > C(0) ? u - g / dg : (lo + hi) / C(2);
        if (!(next > lo && next < hi)) next = (lo + hi) / C(2);
        if (next == u || !(lo < next && next < hi)) {
          done = true;  // the bracket is as narrow as the compute type allows
          break;
        }
        u = next;
      }
      if (!done && fin) limit = true;
    }
    if (!fin) {
      fail(out, Status::non_finite_input);
      return out;
    }
    finite = push_point(out, curve, param_at(t0, t1, u)) && finite;
  }
  finite = push_point(out, curve, t1) && finite;
  if (!finite)
    fail(out, Status::non_finite_input);
  else if (limit)
    out.status = Status::limit_exceeded;
  return out;
}

// Breadth-first adaptive refinement; accept(ta, pa, tb, pb, tm, pm) decides a piece given its
// midpoint sample (evaluated once and reused as the new point when the piece is split).
template <class T, int N, class F, class Accept>
CurveSamples<T, N> adaptive(F& curve, T t0, T t1, T tol, const SubdivisionOptions& opt,
                            Accept&& accept) {
  using C = compute_t<T>;
  CurveSamples<T, N> out;
  out.status = Status::ok;
  if (!(tol >= T(0)) || opt.max_points < 2 || opt.min_depth < 0 || opt.max_depth < 0) {
    out.status = Status::invalid_input;
    return out;
  }
  if (!locus::is_finite(t0) || !locus::is_finite(t1)) {
    out.status = Status::non_finite_input;
    return out;
  }
  struct Node {
    T t;
    Vec<T, N> p;
    bool done;  // the piece from this node to the next is final
  };
  std::vector<Node> cur{{t0, curve(t0), false}, {t1, curve(t1), true}}, next;
  if (!is_finite(cur[0].p) || !is_finite(cur[1].p)) {
    out.status = Status::non_finite_input;
    return out;
  }
  bool limit = false;
  int points = 2;
  for (int depth = 0;; ++depth) {
    bool any_open = false;
    next.clear();
    for (std::size_t i = 0; i + 1 < cur.size(); ++i) {
      Node a = cur[i];
      const Node& b = cur[i + 1];
      if (a.done) {
        next.push_back(a);
        continue;
      }
      const T tm = static_cast<T>((C(a.t) + C(b.t)) / C(2));
      const Vec<T, N> pm = curve(tm);
      if (!is_finite(pm)) {
        out.status = Status::non_finite_input;
        return out;
      }
      const int r = depth >= opt.min_depth ? accept(a.t, a.p, b.t, b.p, tm, pm) : 0;
      if (r < 0) {
        out.status = Status::non_finite_input;
        return out;
      }
      if (r > 0) {
        a.done = true;
        next.push_back(a);
      } else if (depth >= opt.max_depth || points >= opt.max_points || tm == a.t || tm == b.t) {
        a.done = true;
        next.push_back(a);
        limit = true;
      } else {
        next.push_back(a);
        next.push_back({tm, pm, false});
        ++points;
        any_open = true;
      }
    }
    next.push_back(cur.back());
    std::swap(cur, next);
    if (!any_open) break;
  }
  out.status = limit ? Status::limit_exceeded : Status::ok;
  out.params.reserve(cur.size());
  out.points.reserve(cur.size());
  for (const Node& nd : cur) {
    out.params.push_back(nd.t);
    out.points.push_back(nd.p);
  }
  return out;
}

}  // namespace detail::subdivide

/// `count` parameters equally spaced from t0 to t1 and the curve's points there.
template <Real T, class F>
requires detail::subdivide::CurveFunction<F, T>
[[nodiscard]] CurveSamples<T, detail::subdivide::curve_dim<F, T>> subdivide_uniform(
    F&& curve, T t0, std::type_identity_t<T> t1, int count) {
  constexpr int N = detail::subdivide::curve_dim<F, T>;
  if (count < 2) return {Status::invalid_input, {}, {}};
  if (!locus::is_finite(t0) || !locus::is_finite(t1)) return {Status::non_finite_input, {}, {}};
  return detail::subdivide::uniform<T, N>(curve, t0, t1, count, Status::ok);
}

/// Arc length of the curve from t0 to t1 given its derivative dcurve.
template <Real T, class F, class DF>
requires detail::subdivide::CurveFunction<F, T> && detail::subdivide::CurveFunction<DF, T>
[[nodiscard]] ArcLength<T> arc_length(F&& curve, DF&& dcurve, T t0, std::type_identity_t<T> t1,
                                      const ArcLengthOptions<T>& opt = {}) {
  (void)curve;
  if (!locus::is_finite(t0) || !locus::is_finite(t1))
    return {Status::non_finite_input, std::numeric_limits<T>::quiet_NaN(), 0};
  if (!(opt.relative_tolerance >= T(0))) return {Status::invalid_input, T(0), 0};
  detail::subdivide::ExactSpeed<T, std::remove_reference_t<DF>> speed{dcurve};
  const auto tab = detail::subdivide::length_table(speed, t0, t1, opt);
  if (tab.status == Status::non_finite_input)
    return {tab.status, std::numeric_limits<T>::quiet_NaN(), tab.evaluations};
  return {tab.status, static_cast<T>(tab.total), tab.evaluations};
}

/// Arc length of the curve from t0 to t1, the derivative approximated by finite differences
/// (accurate to about eps_T^(2/3) relative; see the header comment).
template <Real T, class F>
requires detail::subdivide::CurveFunction<F, T>
[[nodiscard]] ArcLength<T> arc_length(F&& curve, T t0, std::type_identity_t<T> t1,
                                      const ArcLengthOptions<T>& opt = {}) {
  if (!locus::is_finite(t0) || !locus::is_finite(t1))
    return {Status::non_finite_input, std::numeric_limits<T>::quiet_NaN(), 0};
  if (!(opt.relative_tolerance >= T(0))) return {Status::invalid_input, T(0), 0};
  detail::subdivide::FiniteDifferenceSpeed<T, std::remove_reference_t<F>> speed{
      curve, std::min(t0, t1), std::max(t0, t1)};
  const auto tab =
      detail::subdivide::length_table(speed, t0, t1, detail::subdivide::fd_options(opt));
  if (tab.status == Status::non_finite_input)
    return {tab.status, std::numeric_limits<T>::quiet_NaN(), tab.evaluations * 3};
  return {tab.status, static_cast<T>(tab.total), tab.evaluations * 3};
}

/// `count` points equally spaced in arc length from t0 to t1, given the derivative dcurve.
template <Real T, class F, class DF>
requires detail::subdivide::CurveFunction<F, T> && detail::subdivide::CurveFunction<DF, T>
[[nodiscard]] CurveSamples<T, detail::subdivide::curve_dim<F, T>> subdivide_arc_length(
    F&& curve, DF&& dcurve, T t0, std::type_identity_t<T> t1, int count,
    const ArcLengthOptions<T>& opt = {}) {
  constexpr int N = detail::subdivide::curve_dim<F, T>;
  detail::subdivide::ExactSpeed<T, std::remove_reference_t<DF>> speed{dcurve};
  return detail::subdivide::arc_length_samples<T, N>(curve, speed, t0, t1, count, opt);
}

/// `count` points equally spaced in arc length from t0 to t1, the derivative approximated by
/// finite differences (spacing accurate to about eps_T^(2/3) of the length).
template <Real T, class F>
requires detail::subdivide::CurveFunction<F, T>
[[nodiscard]] CurveSamples<T, detail::subdivide::curve_dim<F, T>> subdivide_arc_length(
    F&& curve, T t0, std::type_identity_t<T> t1, int count, const ArcLengthOptions<T>& opt = {}) {
  constexpr int N = detail::subdivide::curve_dim<F, T>;
  detail::subdivide::FiniteDifferenceSpeed<T, std::remove_reference_t<F>> speed{
      curve, locus::is_finite(t0) && locus::is_finite(t1) ? std::min(t0, t1) : t0,
      locus::is_finite(t0) && locus::is_finite(t1) ? std::max(t0, t1) : t1};
  return detail::subdivide::arc_length_samples<T, N>(curve, speed, t0, t1, count,
                                                     detail::subdivide::fd_options(opt));
}

/// Adaptive subdivision: halve every piece whose curve midpoint is farther than `tolerance`
/// from its chord midpoint.
template <Real T, class F>
requires detail::subdivide::CurveFunction<F, T>
[[nodiscard]] CurveSamples<T, detail::subdivide::curve_dim<F, T>> subdivide_midpoint(
    F&& curve, T t0, std::type_identity_t<T> t1, std::type_identity_t<T> tolerance,
    const SubdivisionOptions& opt = {}) {
  using C = compute_t<T>;
  constexpr int N = detail::subdivide::curve_dim<F, T>;
  const C tol2 = C(tolerance) * C(tolerance);
  return detail::subdivide::adaptive<T, N>(
      curve, t0, t1, tolerance, opt,
      [&](T, const Vec<T, N>& pa, T, const Vec<T, N>& pb, T, const Vec<T, N>& pm) -> int {
        C d2 = C(0);
        for (int i = 0; i < N; ++i) d2 += sqr(C(pm[i]) - (C(pa[i]) + C(pb[i])) / C(2));
        return d2 <= tol2 ? 1 : 0;
      });
}

/// Adaptive subdivision: halve every piece whose RMS distance from its chord (the book's
/// variation, normalised by the parameter length) exceeds `tolerance`.
template <Real T, class F>
requires detail::subdivide::CurveFunction<F, T>
[[nodiscard]] CurveSamples<T, detail::subdivide::curve_dim<F, T>> subdivide_variation(
    F&& curve, T t0, std::type_identity_t<T> t1, std::type_identity_t<T> tolerance,
    const SubdivisionOptions& opt = {}) {
  using C = compute_t<T>;
  constexpr int N = detail::subdivide::curve_dim<F, T>;
  constexpr detail::subdivide::Gauss5<C> g = detail::subdivide::gauss5<C>();
  const C tol2 = C(tolerance) * C(tolerance);
  return detail::subdivide::adaptive<T, N>(
      curve, t0, t1, tolerance, opt,
      [&](T ta, const Vec<T, N>& pa, T tb, const Vec<T, N>& pb, T tm, const Vec<T, N>& pm) -> int {
        const C width = C(tb) - C(ta);
        C mean2 = C(0);
        for (int k = 0; k < 5; ++k) {
          T t = tm;
          if (k != 2) t = static_cast<T>(C(ta) + width * g.x[k]);
          const Vec<T, N> p = k == 2 ? pm : curve(t);
          if (!is_finite(p)) return -1;
          // The chord at the node's actual (rounded) parameter.
          const C u = width != C(0) ? (C(t) - C(ta)) / width : C(0.5);
          C d2 = C(0);
          for (int i = 0; i < N; ++i) d2 += sqr(C(p[i]) - (C(pa[i]) + u * (C(pb[i]) - C(pa[i]))));
          mean2 += g.w[k] * d2;
        }
        return mean2 <= tol2 ? 1 : 0;
      });
}

}  // namespace locus
