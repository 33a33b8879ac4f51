// SPDX-License-Identifier: BSL-1.0
#pragma once
// Tensor-product B-spline surfaces; row prim3.surfaces; book section 9.4 (B-spline surfaces),
// figure 9.26 (a uniform bicubic B-spline surface).
//
// BSplineSurface<T, N> {degree_u, degree_v, rows, cols, control, knots_u, knots_v}: control net
// P_ij, i = 0..rows-1 along u, j = 0..cols-1 along v, row-major control[i * cols + j];
// knots_u has rows + degree_u + 1 values, knots_v cols + degree_v + 1, and
//   S(u, v) = sum_ij N_{i,du}(u) N_{j,dv}(v) P_ij  on [u_du, u_rows] x [v_dv, v_cols]
// with the basis, span and knot conventions of bspline.hpp (the last span closed).
//
// partials() returns {point, du, dv, duv} from the non-zero basis functions and their first
// derivatives in each direction (O((du+1)(dv+1)) terms). normal_at() (N = 3) is
// normalize(du x dv) with the collapsed-edge fallback of bezier_surface.hpp (the limit normal
// from the interior; the zero vector when none exists). insert_knot_u/v (Boehm) and
// refine_knots_u/v run the curve insertion of bspline.hpp on every column / row; to_bezier()
// splits the surface into a grid of Bézier patches (section 9.4 and 5.5 knot insertion).
//
// Bad input: validate() returns invalid_input for rows * cols != control.size() and the knot
// codes of validate_knots() for each direction, non_finite_input for NaN/Inf control points.
// Evaluation checks only sizes (O(1)): a structurally invalid surface evaluates to NaN; bad knot
// values give meaningless but safe results (no crash, no division by zero). Parameters are
// clamped to the domain; NaN parameters give NaN points (and a zero normal). bounding_box() is the
// control-net box, which contains the surface (convex-hull property). Cost: O(du^2 + dv^2 + du dv)
// per evaluation plus two O(log n) span searches; no allocation for degrees < 16.

#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/curves/bezier_surface.hpp>
#include <locus/curves/bspline.hpp>
#include <locus/primitives/aligned_box.hpp>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <span>
#include <utility>
#include <vector>

namespace locus {

/// A tensor-product B-spline surface: control[i * cols + j], i along u, j along v.
template <class T, int N>
struct BSplineSurface {
  int degree_u;
  int degree_v;
  int rows;
  int cols;
  std::vector<Vec<T, N>> control;
  std::vector<T> knots_u;
  std::vector<T> knots_v;
};

namespace detail {

template <class S>
[[nodiscard]] bool tensor_shape_ok(const S& s) noexcept {
  return s.rows >= 1 && s.cols >= 1 &&
         bspline_shape_ok(s.degree_u, static_cast<std::size_t>(s.rows), s.knots_u.size()) &&
         bspline_shape_ok(s.degree_v, static_cast<std::size_t>(s.cols), s.knots_v.size()) &&
         s.control.size() == static_cast<std::size_t>(s.rows) * static_cast<std::size_t>(s.cols);
}

template <class S>
[[nodiscard]] Status validate_tensor_knots(const S& s) noexcept {
  if (s.rows < 1 || s.cols < 1) return Status::empty_input;
  if (s.control.size() != static_cast<std::size_t>(s.rows) * static_cast<std::size_t>(s.cols))
    return Status::invalid_input;
  using T = typename decltype(s.knots_u)::value_type;
  Status st = validate_knots(std::span<const T>(s.knots_u), s.degree_u, s.rows);
  if (st != Status::ok) return st;
  st = validate_knots(std::span<const T>(s.knots_v), s.degree_v, s.cols);
  if (st != Status::ok) return st;
  for (const auto& p : s.control)
    if (!is_finite(p)) return Status::non_finite_input;
  return Status::ok;
}

/// The non-zero basis values and derivatives in one direction at t (clamped into the domain).
template <Real T>
struct BasisAt {
  int span;
  T t;
  CurveScratch<T> val;
  CurveScratch<T> der;
  BasisAt(std::span<const T> knots, int d, int n, T param)
      : span(0),
        t(param),
        val(static_cast<std::size_t>(d) + 1),
        der(static_cast<std::size_t>(d) + 1) {
    t = curve_clamp(t, knots[static_cast<std::size_t>(d)], knots[static_cast<std::size_t>(n)]);
    if (t != t) return;
    span = find_span(knots, d, n, t);
    basis_and_derivative(knots, d, span, t, val.data(), der.data());
  }
};

/// out = {sum N N P, sum N' N P, sum N N' P, sum N' N' P} over the non-zero terms; get(i, j)
/// returns the (possibly homogeneous) control value of P_ij.
template <class T, class V, class Get>
void tensor_partials(std::span<const T> ku, int du, int nu, std::span<const T> kv, int dv, int nv,
                     T u, T v, const Get& get, V out[4]) noexcept {
  BasisAt<T> bu(ku, du, nu, u);
  BasisAt<T> bv(kv, dv, nv, v);
  out[0] = out[1] = out[2] = out[3] = V{};
  for (int a = 0; a <= du; ++a) {
    const auto ua = static_cast<std::size_t>(a);
    V row{}, drow{};
    for (int b = 0; b <= dv; ++b) {
      const auto ub = static_cast<std::size_t>(b);
      const V p = get(bu.span - du + a, bv.span - dv + b);
      row += bv.val[ub] * p;
      drow += bv.der[ub] * p;
    }
    out[0] += bu.val[ua] * row;
    out[1] += bu.der[ua] * row;
    out[2] += bu.val[ua] * drow;
    out[3] += bu.der[ua] * drow;
  }
}

}  // namespace detail

/// ok, or the first problem (see the header comment).
template <class T, int N>
[[nodiscard]] Status validate(const BSplineSurface<T, N>& s) noexcept {
  return detail::validate_tensor_knots(s);
}

/// The domain along u, [u_du, u_rows] (NaN bounds for an inconsistent shape).
template <class T, int N>
[[nodiscard]] ParamDomain<T> domain_u(const BSplineSurface<T, N>& s) noexcept {
  if (!detail::tensor_shape_ok(s))
    return {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::quiet_NaN()};
  return {s.knots_u[static_cast<std::size_t>(s.degree_u)],
          s.knots_u[static_cast<std::size_t>(s.rows)]};
}

/// The domain along v, [v_dv, v_cols] (NaN bounds for an inconsistent shape).
template <class T, int N>
[[nodiscard]] ParamDomain<T> domain_v(const BSplineSurface<T, N>& s) noexcept {
  if (!detail::tensor_shape_ok(s))
    return {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::quiet_NaN()};
  return {s.knots_v[static_cast<std::size_t>(s.degree_v)],
          s.knots_v[static_cast<std::size_t>(s.cols)]};
}

/// S(u, v), du, dv, duv; (u, v) clamped to the domain; NaN for a bad shape or NaN parameters.
template <class T, int N>
[[nodiscard]] SurfaceDerivatives<T, N> partials(const BSplineSurface<T, N>& s, T u, T v) noexcept {
  const Vec<T, N> nan = detail::curve_nan<T, N>();
  if (!detail::tensor_shape_ok(s) || u != u || v != v) return {nan, nan, nan, nan};
  Vec<T, N> out[4];
  const auto cols = static_cast<std::size_t>(s.cols);
  detail::tensor_partials<T, Vec<T, N>>(
      std::span<const T>(s.knots_u), s.degree_u, s.rows, std::span<const T>(s.knots_v), s.degree_v,
      s.cols, u, v,
      [&s, cols](int i, int j) {
        return s.control[static_cast<std::size_t>(i) * cols + static_cast<std::size_t>(j)];
      },
      out);
  return {out[0], out[1], out[2], out[3]};
}

/// S(u, v); (u, v) clamped to the domain.
template <class T, int N>
[[nodiscard]] Vec<T, N> point_at(const BSplineSurface<T, N>& s, T u, T v) noexcept {
  return partials(s, u, v).point;
}

/// The unit normal normalize(du x dv) with the collapsed-edge fallback (bezier_surface.hpp).
template <Real T>
[[nodiscard]] Vec3<T> normal_at(const BSplineSurface<T, 3>& s, T u, T v) noexcept {
  const SurfaceDerivatives<T, 3> d = partials(s, u, v);
  if (!is_finite(d.point)) return Vec3<T>{};
  const ParamDomain<T> a = domain_u(s), b = domain_v(s);
  return detail::surface_normal(d, !(u > T(0.5) * (a.min + a.max)),
                                !(v > T(0.5) * (b.min + b.max)));
}

/// The control-net box; it contains the surface.
template <class T, int N>
[[nodiscard]] AlignedBox<T, N> bounding_box(const BSplineSurface<T, N>& s) noexcept {
  return bounding_box(s.control.data(), s.control.size());
}

namespace detail {

/// Maps every column (the control points P_0j .. P_{rows-1}j with knots_u) through the curve
/// function f and reassembles the net; f must return the same knots for every column.
template <class T, int N, class F>
[[nodiscard]] BSplineSurface<T, N> map_columns(const BSplineSurface<T, N>& s, const F& f) {
  const auto rows = static_cast<std::size_t>(s.rows), cols = static_cast<std::size_t>(s.cols);
  BSplineSurface<T, N> r = s;
  BSplineCurve<T, N> col{s.degree_u, std::vector<Vec<T, N>>(rows), s.knots_u};
  for (std::size_t j = 0; j < cols; ++j) {
    for (std::size_t i = 0; i < rows; ++i) col.control[i] = s.control[i * cols + j];
    const BSplineCurve<T, N> c = f(col);
    if (j == 0) {
      r.rows = static_cast<int>(c.control.size());
      r.knots_u = c.knots;
      r.control.assign(c.control.size() * cols, Vec<T, N>{});
    }
    for (std::size_t i = 0; i < c.control.size(); ++i) r.control[i * cols + j] = c.control[i];
  }
  return r;
}

/// The same for every row (P_i0 .. P_i{cols-1} with knots_v).
template <class T, int N, class F>
[[nodiscard]] BSplineSurface<T, N> map_rows(const BSplineSurface<T, N>& s, const F& f) {
  const auto rows = static_cast<std::size_t>(s.rows), cols = static_cast<std::size_t>(s.cols);
  BSplineSurface<T, N> r = s;
  BSplineCurve<T, N> row{s.degree_v, std::vector<Vec<T, N>>(cols), s.knots_v};
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t j = 0; j < cols; ++j) row.control[j] = s.control[i * cols + j];
    const BSplineCurve<T, N> c = f(row);
    if (i == 0) {
      r.cols = static_cast<int>(c.control.size());
      r.knots_v = c.knots;
      r.control.assign(rows * c.control.size(), Vec<T, N>{});
    }
    for (std::size_t j = 0; j < c.control.size(); ++j)
      r.control[i * c.control.size() + j] = c.control[j];
  }
  return r;
}

/// ok when every knot is finite and inside [lo, hi]; non_finite_input / invalid_input otherwise.
template <class T>
[[nodiscard]] Status check_new_knots(std::span<const T> knots, T lo, T hi) noexcept {
  for (T k : knots)
    if (!is_finite(k)) return Status::non_finite_input;
  for (T k : knots)
    if (!(k >= lo && k <= hi)) return Status::invalid_input;
  return Status::ok;
}

/// Inserts the (sorted) knots one by one into the curve (Boehm, bspline.hpp).
template <class T, int N>
[[nodiscard]] BSplineCurve<T, N> refine_curve(const BSplineCurve<T, N>& c,
                                              const std::vector<T>& sorted) {
  BSplineCurve<T, N> r = c;
  for (T k : sorted) r = insert_knot(r, k);
  return r;
}

template <class T>
[[nodiscard]] std::vector<T> sorted_knots(std::span<const T> knots) {
  std::vector<T> k(knots.begin(), knots.end());
  std::sort(k.begin(), k.end());
  return k;
}

}  // namespace detail

/// Inserts the knot t (clamped to the u domain) `times` times along u by inserting it into every
/// column (insert_knot of bspline.hpp); the surface is unchanged. An inconsistent shape is
/// returned unchanged.
template <class T, int N>
[[nodiscard]] BSplineSurface<T, N> insert_knot_u(const BSplineSurface<T, N>& s, T t,
                                                 int times = 1) {
  if (!detail::tensor_shape_ok(s)) return s;
  return detail::map_columns(
      s, [t, times](const BSplineCurve<T, N>& c) { return insert_knot(c, t, times); });
}

/// Inserts the knot t (clamped to the v domain) `times` times along v (every row).
template <class T, int N>
[[nodiscard]] BSplineSurface<T, N> insert_knot_v(const BSplineSurface<T, N>& s, T t,
                                                 int times = 1) {
  if (!detail::tensor_shape_ok(s)) return s;
  return detail::map_rows(
      s, [t, times](const BSplineCurve<T, N>& c) { return insert_knot(c, t, times); });
}

/// A refined surface (refine_knots_u/v): status ok and the refined surface, or the problem and
/// the input surface unchanged.
template <class S>
struct SurfaceRefinement {
  Status status = Status::empty_input;
  S surface;
};

/// Knot refinement along u: inserts every value of `knots` (any order, repeats allowed) once;
/// the surface is unchanged. status: validate(s), else non_finite_input for a NaN/Inf knot,
/// invalid_input for a knot outside the u domain (nothing is inserted then). A knot whose
/// multiplicity has reached degree_u is skipped (the surface already interpolates there).
template <class T, int N>
[[nodiscard]] SurfaceRefinement<BSplineSurface<T, N>> refine_knots_u(const BSplineSurface<T, N>& s,
                                                                     std::span<const T> knots) {
  SurfaceRefinement<BSplineSurface<T, N>> r{validate(s), s};
  if (r.status != Status::ok) return r;
  const ParamDomain<T> d = domain_u(s);
  r.status = detail::check_new_knots(knots, d.min, d.max);
  if (r.status != Status::ok || knots.empty()) return r;
  const std::vector<T> k = detail::sorted_knots(knots);
  r.surface = detail::map_columns(
      s, [&k](const BSplineCurve<T, N>& c) { return detail::refine_curve(c, k); });
  return r;
}

/// Knot refinement along v (see refine_knots_u).
template <class T, int N>
[[nodiscard]] SurfaceRefinement<BSplineSurface<T, N>> refine_knots_v(const BSplineSurface<T, N>& s,
                                                                     std::span<const T> knots) {
  SurfaceRefinement<BSplineSurface<T, N>> r{validate(s), s};
  if (r.status != Status::ok) return r;
  const ParamDomain<T> d = domain_v(s);
  r.status = detail::check_new_knots(knots, d.min, d.max);
  if (r.status != Status::ok || knots.empty()) return r;
  const std::vector<T> k = detail::sorted_knots(knots);
  r.surface =
      detail::map_rows(s, [&k](const BSplineCurve<T, N>& c) { return detail::refine_curve(c, k); });
  return r;
}

/// A surface as a grid of Bézier patches: patch (a, b) covers [breaks_u[a], breaks_u[a+1]] x
/// [breaks_v[b], breaks_v[b+1]] and is stored at patches[a * count_v + b].
template <class T, int N>
struct BezierPatchGrid {
  Status status = Status::empty_input;
  int count_u;
  int count_v;
  std::vector<BezierPatch<T, N>> patches;
  std::vector<T> breaks_u;
  std::vector<T> breaks_v;
};

/// Splits the surface into Bézier patches (see the header comment); status is validate(s), the
/// grid is empty unless ok.
template <class T, int N>
[[nodiscard]] BezierPatchGrid<T, N> to_bezier(const BSplineSurface<T, N>& s) {
  BezierPatchGrid<T, N> g{validate(s), 0, 0, {}, {}, {}};
  if (g.status != Status::ok) return g;
  BSplineSurface<T, N> r = s;
  const ParamDomain<T> du = domain_u(s), dv = domain_v(s);
  std::vector<T> distinct;
  for (T k : s.knots_u)
    if (k >= du.min && k <= du.max && (distinct.empty() || distinct.back() != k))
      distinct.push_back(k);
  for (T k : distinct) r = insert_knot_u(r, k, r.degree_u);
  distinct.clear();
  for (T k : s.knots_v)
    if (k >= dv.min && k <= dv.max && (distinct.empty() || distinct.back() != k))
      distinct.push_back(k);
  for (T k : distinct) r = insert_knot_v(r, k, r.degree_v);
  // Non-empty spans in each direction.
  const auto spans = [](const std::vector<T>& kn, int d, int n, std::vector<int>& out,
                        std::vector<T>& breaks) {
    for (int k = d; k < n; ++k) {
      const auto uk = static_cast<std::size_t>(k);
      if (!(kn[uk] < kn[uk + 1])) continue;
      if (breaks.empty()) breaks.push_back(kn[uk]);
      breaks.push_back(kn[uk + 1]);
      out.push_back(k);
    }
  };
  std::vector<int> su, sv;
  spans(r.knots_u, r.degree_u, r.rows, su, g.breaks_u);
  spans(r.knots_v, r.degree_v, r.cols, sv, g.breaks_v);
  g.count_u = static_cast<int>(su.size());
  g.count_v = static_cast<int>(sv.size());
  const auto cols = static_cast<std::size_t>(r.cols);
  for (int ku : su)
    for (int kv : sv) {
      BezierPatch<T, N> p{r.degree_u + 1, r.degree_v + 1, {}};
      for (int i = ku - r.degree_u; i <= ku; ++i)
        for (int j = kv - r.degree_v; j <= kv; ++j)
          p.control.push_back(
              r.control[static_cast<std::size_t>(i) * cols + static_cast<std::size_t>(j)]);
      g.patches.push_back(std::move(p));
    }
  return g;
}

}  // namespace locus
