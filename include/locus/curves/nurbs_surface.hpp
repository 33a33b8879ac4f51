// SPDX-License-Identifier: BSL-1.0
#pragma once
// Tensor-product NURBS surfaces; row prim3.surfaces; book section 9.4 (NURBS surfaces),
// (no figure of its own; the rational form of figure 9.26).
//
// NurbsSurface<T, N> {degree_u, degree_v, rows, cols, control, weights, knots_u, knots_v}: a
// BSplineSurface (bspline_surface.hpp) with one weight per control point (same row-major order):
//   S(u, v) = A(u, v) / W(u, v),  A = sum N_i(u) N_j(v) w_ij P_ij,  W = sum N_i(u) N_j(v) w_ij.
// Partials by the quotient rule: S_u = (A_u - W_u S) / W, S_v likewise, and
// S_uv = (A_uv - W_uv S - W_u S_v - W_v S_u) / W. With all weights 1 it is the B-spline surface.
//
// Weights: validate() requires weights.size() == control.size() (invalid_input), finite weights
// (non_finite_input) and every weight > 0 (invalid_input for zero or negative weights: W > 0 and
// the convex-hull property need them). Evaluation computes with any weights; where W(u, v) == 0
// or the quotient is not finite, every field of the result is NaN (never a finite but meaningless
// point), and normal_at() returns the zero vector. weight_at() exposes W. Everything else
// (clamping, NaN parameters, knot checks, normal fallback) is as in bspline_surface.hpp.
// Knot insertion, refinement and to_bezier() work on the homogeneous B-spline surface
// (w P, w) with the code of bspline_surface.hpp and project back; new weights are convex
// combinations of old ones. to_bezier() gives rational patches (RationalBezierPatch).
// Cost: that of the B-spline surface with one more coordinate.

#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/curves/bspline_surface.hpp>
#include <locus/curves/nurbs.hpp>
#include <locus/primitives/aligned_box.hpp>

#include <cstddef>
#include <limits>
#include <span>
#include <utility>
#include <vector>

namespace locus {

/// A tensor-product NURBS surface: control[i * cols + j] with weight weights[i * cols + j].
template <class T, int N>
struct NurbsSurface {
  int degree_u;
  int degree_v;
  int rows;
  int cols;
  std::vector<Vec<T, N>> control;
  std::vector<T> weights;
  std::vector<T> knots_u;
  std::vector<T> knots_v;
};

/// ok, or the first problem (see the header comment and bspline_surface.hpp).
template <class T, int N>
[[nodiscard]] Status validate(const NurbsSurface<T, N>& s) noexcept {
  const Status st = detail::validate_tensor_knots(s);
  if (st != Status::ok) return st;
  if (s.weights.size() != s.control.size()) return Status::invalid_input;
  for (T w : s.weights)
    if (!is_finite(w)) return Status::non_finite_input;
  for (T w : s.weights)
    if (!(w > T(0))) return Status::invalid_input;
  return Status::ok;
}

namespace detail {

template <class T, int N>
[[nodiscard]] bool nurbs_surface_shape_ok(const NurbsSurface<T, N>& s) noexcept {
  return tensor_shape_ok(s) && s.weights.size() == s.control.size();
}

/// The homogeneous sums {A, A_u, A_v, A_uv} with W in the last coordinate.
template <class T, int N>
void nurbs_surface_homogeneous(const NurbsSurface<T, N>& s, T u, T v,
                               Vec<T, N + 1> out[4]) noexcept {
  const auto cols = static_cast<std::size_t>(s.cols);
  tensor_partials<T, Vec<T, N + 1>>(
      std::span<const T>(s.knots_u), s.degree_u, s.rows, std::span<const T>(s.knots_v), s.degree_v,
      s.cols, u, v,
      [&s, cols](int i, int j) {
        const std::size_t k = static_cast<std::size_t>(i) * cols + static_cast<std::size_t>(j);
        Vec<T, N + 1> h{};
        for (int c = 0; c < N; ++c) h[c] = s.weights[k] * s.control[k][c];
        h[N] = s.weights[k];
        return h;
      },
      out);
}

}  // namespace detail

/// W(u, v) (parameters clamped); NaN for a bad shape.
template <class T, int N>
[[nodiscard]] T weight_at(const NurbsSurface<T, N>& s, T u, T v) noexcept {
  if (!detail::nurbs_surface_shape_ok(s) || u != u || v != v)
    return std::numeric_limits<T>::quiet_NaN();
  Vec<T, N + 1> h[4];
  detail::nurbs_surface_homogeneous(s, u, v, h);
  return h[0][N];
}

/// S(u, v), du, dv, duv; all NaN where W == 0, for a bad shape or NaN parameters.
template <class T, int N>
[[nodiscard]] SurfaceDerivatives<T, N> partials(const NurbsSurface<T, N>& s, T u, T v) noexcept {
  const Vec<T, N> nan = detail::curve_nan<T, N>();
  const SurfaceDerivatives<T, N> bad{nan, nan, nan, nan};
  if (!detail::nurbs_surface_shape_ok(s) || u != u || v != v) return bad;
  Vec<T, N + 1> h[4];
  detail::nurbs_surface_homogeneous(s, u, v, h);
  const T w = h[0][N];
  if (!(w != T(0)) || !is_finite(w)) return bad;
  Vec<T, N> a[4];
  for (int k = 0; k < 4; ++k)
    for (int c = 0; c < N; ++c) a[k][c] = h[k][c];
  SurfaceDerivatives<T, N> r;
  r.point = a[0] / w;
  r.du = (a[1] - h[1][N] * r.point) / w;
  r.dv = (a[2] - h[2][N] * r.point) / w;
  r.duv = (a[3] - h[3][N] * r.point - h[1][N] * r.dv - h[2][N] * r.du) / w;
  if (!is_finite(r.point) || !is_finite(r.du) || !is_finite(r.dv) || !is_finite(r.duv)) return bad;
  return r;
}

/// S(u, v); NaN where W == 0.
template <class T, int N>
[[nodiscard]] Vec<T, N> point_at(const NurbsSurface<T, N>& s, T u, T v) noexcept {
  return partials(s, u, v).point;
}

/// The domain along u (NaN bounds for an inconsistent shape).
template <class T, int N>
[[nodiscard]] ParamDomain<T> domain_u(const NurbsSurface<T, N>& s) noexcept {
  if (!detail::nurbs_surface_shape_ok(s))
    return {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::quiet_NaN()};
  return {s.knots_u[static_cast<std::size_t>(s.degree_u)],
          s.knots_u[static_cast<std::size_t>(s.rows)]};
}

/// The domain along v (NaN bounds for an inconsistent shape).
template <class T, int N>
[[nodiscard]] ParamDomain<T> domain_v(const NurbsSurface<T, N>& s) noexcept {
  if (!detail::nurbs_surface_shape_ok(s))
    return {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::quiet_NaN()};
  return {s.knots_v[static_cast<std::size_t>(s.degree_v)],
          s.knots_v[static_cast<std::size_t>(s.cols)]};
}

/// The unit normal normalize(du x dv) with the collapsed-edge fallback; zero where W == 0.
template <Real T>
[[nodiscard]] Vec3<T> normal_at(const NurbsSurface<T, 3>& s, T u, T v) noexcept {
  const SurfaceDerivatives<T, 3> d = partials(s, u, v);
  if (!is_finite(d.point)) return Vec3<T>{};
  const ParamDomain<T> a = domain_u(s), b = domain_v(s);
  return detail::surface_normal(d, !(u > T(0.5) * (a.min + a.max)),
                                !(v > T(0.5) * (b.min + b.max)));
}

/// The control-net box; it contains the surface when every weight is positive.
template <class T, int N>
[[nodiscard]] AlignedBox<T, N> bounding_box(const NurbsSurface<T, N>& s) noexcept {
  return bounding_box(s.control.data(), s.control.size());
}

/// The NURBS surface with the B-spline's net and knots and all weights 1.
template <class T, int N>
[[nodiscard]] NurbsSurface<T, N> to_nurbs(const BSplineSurface<T, N>& s) {
  return {s.degree_u, s.degree_v, s.rows, s.cols, s.control, std::vector<T>(s.control.size(), T(1)),
          s.knots_u,  s.knots_v};
}

/// The homogeneous B-spline surface with control points (w P, w) (N + 1 coordinates).
template <class T, int N>
[[nodiscard]] BSplineSurface<T, N + 1> to_homogeneous(const NurbsSurface<T, N>& s) {
  BSplineSurface<T, N + 1> h{s.degree_u, s.degree_v, s.rows, s.cols, {}, s.knots_u, s.knots_v};
  h.control.reserve(s.control.size());
  for (std::size_t k = 0; k < s.control.size() && k < s.weights.size(); ++k)
    h.control.push_back(detail::nurbs_homogeneous_point(s.control[k], s.weights[k]));
  return h;
}

namespace detail {

/// The NURBS surface of a homogeneous net: P = A / w (NaN where w == 0), weights w.
template <class T, int N>
[[nodiscard]] NurbsSurface<T, N> from_homogeneous(const BSplineSurface<T, N + 1>& h) {
  NurbsSurface<T, N> r{h.degree_u, h.degree_v, h.rows, h.cols, {}, {}, h.knots_u, h.knots_v};
  r.control.reserve(h.control.size());
  r.weights.reserve(h.control.size());
  for (const auto& p : h.control) {
    r.control.push_back(nurbs_project<T, N>(p));
    r.weights.push_back(p[N]);
  }
  return r;
}

}  // namespace detail

/// Inserts t (clamped to the u domain) `times` times along u; the surface is unchanged. An
/// inconsistent shape is returned unchanged.
template <class T, int N>
[[nodiscard]] NurbsSurface<T, N> insert_knot_u(const NurbsSurface<T, N>& s, T t, int times = 1) {
  if (!detail::nurbs_surface_shape_ok(s)) return s;
  return detail::from_homogeneous<T, N>(insert_knot_u(to_homogeneous(s), t, times));
}

/// Inserts t (clamped to the v domain) `times` times along v; the surface is unchanged.
template <class T, int N>
[[nodiscard]] NurbsSurface<T, N> insert_knot_v(const NurbsSurface<T, N>& s, T t, int times = 1) {
  if (!detail::nurbs_surface_shape_ok(s)) return s;
  return detail::from_homogeneous<T, N>(insert_knot_v(to_homogeneous(s), t, times));
}

/// Knot refinement along u; status and rules as refine_knots_u of bspline_surface.hpp, with
/// validate() of the NURBS surface first.
template <class T, int N>
[[nodiscard]] SurfaceRefinement<NurbsSurface<T, N>> refine_knots_u(const NurbsSurface<T, N>& s,
                                                                   std::span<const T> knots) {
  SurfaceRefinement<NurbsSurface<T, N>> r{validate(s), s};
  if (r.status != Status::ok) return r;
  const auto h = refine_knots_u(to_homogeneous(s), knots);
  r.status = h.status;
  if (h.status == Status::ok) r.surface = detail::from_homogeneous<T, N>(h.surface);
  return r;
}

/// Knot refinement along v (see refine_knots_u).
template <class T, int N>
[[nodiscard]] SurfaceRefinement<NurbsSurface<T, N>> refine_knots_v(const NurbsSurface<T, N>& s,
                                                                   std::span<const T> knots) {
  SurfaceRefinement<NurbsSurface<T, N>> r{validate(s), s};
  if (r.status != Status::ok) return r;
  const auto h = refine_knots_v(to_homogeneous(s), knots);
  r.status = h.status;
  if (h.status == Status::ok) r.surface = detail::from_homogeneous<T, N>(h.surface);
  return r;
}

/// A rational tensor-product Bézier patch on [0, 1]^2: control and weights row-major as in
/// BezierPatch, S = sum B_i(u) B_j(v) w_ij P_ij / sum B_i(u) B_j(v) w_ij.
template <class T, int N>
struct RationalBezierPatch {
  int rows;
  int cols;
  std::vector<Vec<T, N>> control;
  std::vector<T> weights;
};

/// S(u, v) of a rational patch ((u, v) clamped to [0, 1]^2): de Casteljau on (w P, w), then the
/// projection; NaN for a bad shape or where the weight sum is 0.
template <class T, int N>
[[nodiscard]] Vec<T, N> point_at(const RationalBezierPatch<T, N>& p, T u, T v) {
  if (p.weights.size() != p.control.size()) return detail::curve_nan<T, N>();
  BezierPatch<T, N + 1> h{p.rows, p.cols, {}};
  h.control.reserve(p.control.size());
  for (std::size_t k = 0; k < p.control.size(); ++k)
    h.control.push_back(detail::nurbs_homogeneous_point(p.control[k], p.weights[k]));
  return detail::nurbs_project<T, N>(point_at(h, u, v));
}

/// A NURBS surface as a grid of rational Bézier patches; layout as BezierPatchGrid.
template <class T, int N>
struct RationalPatchGrid {
  Status status = Status::empty_input;
  int count_u;
  int count_v;
  std::vector<RationalBezierPatch<T, N>> patches;
  std::vector<T> breaks_u;
  std::vector<T> breaks_v;
};

/// Splits the surface into rational Bézier patches (to_bezier of the homogeneous surface);
/// status is validate(s), the grid is empty unless ok.
template <class T, int N>
[[nodiscard]] RationalPatchGrid<T, N> to_bezier(const NurbsSurface<T, N>& s) {
  RationalPatchGrid<T, N> g{validate(s), 0, 0, {}, {}, {}};
  if (g.status != Status::ok) return g;
  BezierPatchGrid<T, N + 1> h = to_bezier(to_homogeneous(s));
  g.status = h.status;
  g.count_u = h.count_u;
  g.count_v = h.count_v;
  g.breaks_u = std::move(h.breaks_u);
  g.breaks_v = std::move(h.breaks_v);
  for (const auto& hp : h.patches) {
    RationalBezierPatch<T, N> p{hp.rows, hp.cols, {}, {}};
    for (const auto& c : hp.control) {
      p.control.push_back(detail::nurbs_project<T, N>(c));
      p.weights.push_back(c[N]);
    }
    g.patches.push_back(std::move(p));
  }
  return g;
}

}  // namespace locus
