// SPDX-License-Identifier: BSL-1.0
#pragma once
// Bézier surface patches: rectangular (tensor-product) and triangular; row prim3.surfaces; book
// section 9.4, figures 9.24 (bicubic rectangle patch) and 9.25 (cubic triangle patch). The
// limit normal and the triangle split's pyramid: docs/notes/curves.md.
//
// BezierPatch<T, N> {rows, cols, control}: control net P_ij, i = 0..rows-1 along u, j =
// 0..cols-1 along v, stored row-major control[i * cols + j]; degrees m = rows - 1 in u and
// n = cols - 1 in v; S(u, v) = sum_ij B_i^m(u) B_j^n(v) P_ij on [0, 1]^2; corners exact.
// BezierTriangle<T, N> {degree, control}: P_ijk, i + j + k = n, stored at triangle_index(n, i, j)
// = j (n + 1) - j (j - 1) / 2 + i ((n + 1)(n + 2) / 2 points); with barycentric (u, v,
// w = 1 - u - v), S(u, v) = sum n! / (i! j! k!) u^i v^j w^k P_ijk, so S(1, 0) = P_n00,
// S(0, 1) = P_0n0, S(0, 0) = P_00n. Partials are with respect to u and v (w eliminated).
// partials() returns {point, du, dv, duv}; normal_at() (N = 3) is normalize(du x dv). Where
// du x dv vanishes (64 eps relative) at a collapsed edge the rectangle patch returns the limit
// normal from the interior; when that vanishes too, or for a triangle patch, the zero vector.
// Never NaN for finite input.
// Parameters: clamped to [0, 1]^2 for rectangles; for triangles u, v >= 0 and (u, v) scaled onto
// u + v = 1 when u + v > 1. NaN parameters give NaN points (a zero normal). A control count that
// does not match the shape, or rows/cols < 1 (degree < 0), evaluates to NaN; NaN/Inf control
// points propagate (is_finite() checks). A 1 x 1 net is the constant patch.
// subdivide_u / subdivide_v split a rectangle patch at a parameter (both halves reparametrised
// to [0, 1]); subdivide(triangle, u, v) splits a triangle patch at s = (u, v, w) into three with
// corners (s, e2, e3), (e1, s, e3), (e1, e2, s) (O(n^3); a split point on an edge gives valid
// zero-area patches). bounding_box() is the control-net box (convex-hull property).
// Cost: point_at and partials O(m n (m + n)); triangle evaluation O(n^3). Evaluation allocates
// only for rectangle degrees >= 16 and triangle degrees >= 7 (fixed scratch buffers).

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/curves/bezier.hpp>
#include <locus/primitives/aligned_box.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace locus {

/// A tensor-product Bézier patch: control[i * cols + j], i along u, j along v.
template <class T, int N>
struct BezierPatch {
  int rows;
  int cols;
  std::vector<Vec<T, N>> control;
};

/// A triangular Bézier patch of the given degree; see triangle_index() for the storage order.
template <class T, int N>
struct BezierTriangle {
  int degree;
  std::vector<Vec<T, N>> control;
};

/// A surface point with its first partials and mixed second partial.
template <class T, int N>
struct SurfaceDerivatives {
  Vec<T, N> point;
  Vec<T, N> du;
  Vec<T, N> dv;
  Vec<T, N> duv;
};

/// The storage index of P_ijk (k = n - i - j) in a BezierTriangle of degree n.
[[nodiscard]] constexpr int triangle_index(int n, int i, int j) noexcept {
  return j * (n + 1) - j * (j - 1) / 2 + i;
}

/// The number of control points of a triangle patch of degree n: (n + 1)(n + 2) / 2.
[[nodiscard]] constexpr int triangle_control_count(int n) noexcept { return (n + 1) * (n + 2) / 2; }

namespace detail {

template <class T, int N>
[[nodiscard]] bool patch_shape_ok(const BezierPatch<T, N>& p) noexcept {
  return p.rows >= 1 && p.cols >= 1 &&
         p.control.size() == static_cast<std::size_t>(p.rows) * static_cast<std::size_t>(p.cols);
}

template <class T, int N>
[[nodiscard]] bool triangle_shape_ok(const BezierTriangle<T, N>& p) noexcept {
  return p.degree >= 0 && p.degree < 4096 &&
         p.control.size() == static_cast<std::size_t>(triangle_control_count(p.degree));
}

/// The point and first derivative of the Bézier curve b[0..n] at t (b is overwritten).
template <class T, class V>
void bezier_value_derivative(V* b, int n, T t, V& value, V& deriv) noexcept {
  if (n == 0) {
    value = b[0];
    deriv = V{};
    return;
  }
  const T s = T(1) - t;
  for (int r = 1; r < n; ++r)
    for (int i = 0; i <= n - r; ++i) b[i] = s * b[i] + t * b[i + 1];
  deriv = static_cast<T>(n) * (b[1] - b[0]);
  value = s * b[0] + t * b[1];
}

/// The unit normal from the partials, with the collapsed-edge fallback described above.
/// u_low / v_low say whether the parameter lies in the lower half of its range (the sign of the
/// limit normal depends on which edge collapsed).
template <Real T>
[[nodiscard]] Vec3<T> surface_normal(const SurfaceDerivatives<T, 3>& s, bool u_low,
                                     bool v_low) noexcept {
  const T k = T(64) * eps_v<T>;
  const T lu = sqr_length(s.du), lv = sqr_length(s.dv);
  const Vec3<T> n = cross(s.du, s.dv);
  const T big = lu > lv ? lu : lv;
  if (sqr_length(n) > k * k * big * big) return normalize(n);
  Vec3<T> f{};
  T ref = T(0);
  if (lv <= lu) {
    f = (u_low ? T(1) : T(-1)) * cross(s.du, s.duv);
    ref = lu * sqr_length(s.duv);
  } else {
    f = (v_low ? T(1) : T(-1)) * cross(s.duv, s.dv);
    ref = lv * sqr_length(s.duv);
  }
  if (!(sqr_length(f) > k * k * ref)) return Vec3<T>{};
  return normalize(f);
}

}  // namespace detail

/// Degree along u (rows - 1).
template <class T, int N>
[[nodiscard]] int degree_u(const BezierPatch<T, N>& p) noexcept {
  return p.rows - 1;
}
/// Degree along v (cols - 1).
template <class T, int N>
[[nodiscard]] int degree_v(const BezierPatch<T, N>& p) noexcept {
  return p.cols - 1;
}

/// True when the shape is consistent and every control coordinate is finite.
template <class T, int N>
[[nodiscard]] bool is_finite(const BezierPatch<T, N>& p) noexcept {
  if (!detail::patch_shape_ok(p)) return false;
  for (const auto& c : p.control)
    if (!is_finite(c)) return false;
  return true;
}

/// S(u, v), its partials du, dv and the mixed partial duv; (u, v) clamped to [0, 1]^2.
template <class T, int N>
[[nodiscard]] SurfaceDerivatives<T, N> partials(const BezierPatch<T, N>& p, T u, T v) noexcept {
  const Vec<T, N> nan = detail::curve_nan<T, N>();
  if (!detail::patch_shape_ok(p)) return {nan, nan, nan, nan};
  u = detail::curve_clamp(u, T(0), T(1));
  v = detail::curve_clamp(v, T(0), T(1));
  const auto rows = static_cast<std::size_t>(p.rows), cols = static_cast<std::size_t>(p.cols);
  detail::CurveScratch<Vec<T, N>> work(cols), r(rows), d(rows);
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t j = 0; j < cols; ++j) work[j] = p.control[i * cols + j];
    detail::bezier_value_derivative(work.data(), p.cols - 1, v, r[i], d[i]);
  }
  SurfaceDerivatives<T, N> s;
  detail::bezier_value_derivative(r.data(), p.rows - 1, u, s.point, s.du);
  detail::bezier_value_derivative(d.data(), p.rows - 1, u, s.dv, s.duv);
  return s;
}

/// S(u, v); (u, v) clamped to [0, 1]^2; NaN for a bad shape.
template <class T, int N>
[[nodiscard]] Vec<T, N> point_at(const BezierPatch<T, N>& p, T u, T v) noexcept {
  if (!detail::patch_shape_ok(p)) return detail::curve_nan<T, N>();
  u = detail::curve_clamp(u, T(0), T(1));
  v = detail::curve_clamp(v, T(0), T(1));
  const auto rows = static_cast<std::size_t>(p.rows), cols = static_cast<std::size_t>(p.cols);
  detail::CurveScratch<Vec<T, N>> work(cols), r(rows);
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t j = 0; j < cols; ++j) work[j] = p.control[i * cols + j];
    r[i] = detail::de_casteljau_inplace(work.data(), p.cols - 1, v);
  }
  return detail::de_casteljau_inplace(r.data(), p.rows - 1, u);
}

/// The unit normal normalize(du x dv), with the collapsed-edge fallback (see the header).
template <Real T>
[[nodiscard]] Vec3<T> normal_at(const BezierPatch<T, 3>& p, T u, T v) noexcept {
  const SurfaceDerivatives<T, 3> s = partials(p, u, v);
  return detail::surface_normal(s, !(u > T(0.5)), !(v > T(0.5)));
}

/// The control-net box; it contains the patch.
template <class T, int N>
[[nodiscard]] AlignedBox<T, N> bounding_box(const BezierPatch<T, N>& p) noexcept {
  return bounding_box(p.control.data(), p.control.size());
}

/// Two patches from a split.
template <class T, int N>
struct PatchSplit {
  BezierPatch<T, N> first;   ///< the part with the lower parameter, reparametrised to [0, 1]
  BezierPatch<T, N> second;  ///< the part with the higher parameter
};

/// Splits at u = t (clamped to [0, 1]): first covers u in [0, t], second [t, 1].
template <class T, int N>
[[nodiscard]] PatchSplit<T, N> subdivide_u(const BezierPatch<T, N>& p, T t) {
  if (!detail::patch_shape_ok(p)) return {p, p};
  PatchSplit<T, N> s{{p.rows, p.cols, p.control}, {p.rows, p.cols, p.control}};
  const auto rows = static_cast<std::size_t>(p.rows), cols = static_cast<std::size_t>(p.cols);
  BezierCurve<T, N> col;
  col.control.resize(rows);
  for (std::size_t j = 0; j < cols; ++j) {
    for (std::size_t i = 0; i < rows; ++i) col.control[i] = p.control[i * cols + j];
    const BezierSplit<T, N> h = subdivide(col, t);
    for (std::size_t i = 0; i < rows; ++i) {
      s.first.control[i * cols + j] = h.first.control[i];
      s.second.control[i * cols + j] = h.second.control[i];
    }
  }
  return s;
}

/// Splits at v = t (clamped to [0, 1]): first covers v in [0, t], second [t, 1].
template <class T, int N>
[[nodiscard]] PatchSplit<T, N> subdivide_v(const BezierPatch<T, N>& p, T t) {
  if (!detail::patch_shape_ok(p)) return {p, p};
  PatchSplit<T, N> s{{p.rows, p.cols, p.control}, {p.rows, p.cols, p.control}};
  const auto rows = static_cast<std::size_t>(p.rows), cols = static_cast<std::size_t>(p.cols);
  BezierCurve<T, N> row;
  row.control.resize(cols);
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t j = 0; j < cols; ++j) row.control[j] = p.control[i * cols + j];
    const BezierSplit<T, N> h = subdivide(row, t);
    for (std::size_t j = 0; j < cols; ++j) {
      s.first.control[i * cols + j] = h.first.control[j];
      s.second.control[i * cols + j] = h.second.control[j];
    }
  }
  return s;
}

// ---- triangular patches ----

/// True when the shape is consistent and every control coordinate is finite.
template <class T, int N>
[[nodiscard]] bool is_finite(const BezierTriangle<T, N>& p) noexcept {
  if (!detail::triangle_shape_ok(p)) return false;
  for (const auto& c : p.control)
    if (!is_finite(c)) return false;
  return true;
}

namespace detail {

/// One barycentric de Casteljau level in place: degree m net -> degree m - 1 net.
template <class T, class V>
void triangle_level(V* b, int m, T u, T v, T w) noexcept {
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m - j; ++i)
      b[triangle_index(m - 1, i, j)] = u * b[triangle_index(m, i + 1, j)] +
                                       v * b[triangle_index(m, i, j + 1)] +
                                       w * b[triangle_index(m, i, j)];
}

template <Real T>
void clamp_barycentric(T& u, T& v) noexcept {
  u = u < T(0) ? T(0) : u;
  v = v < T(0) ? T(0) : v;
  const T s = u + v;
  if (s > T(1)) {
    u = u / s;
    v = T(1) - u;
  }
}

}  // namespace detail

/// S(u, v) with barycentric (u, v, 1 - u - v), by barycentric de Casteljau; (u, v) clamped
/// onto the triangle; NaN for a bad shape.
template <class T, int N>
[[nodiscard]] Vec<T, N> point_at(const BezierTriangle<T, N>& p, T u, T v) noexcept {
  if (!detail::triangle_shape_ok(p)) return detail::curve_nan<T, N>();
  detail::clamp_barycentric(u, v);
  const T w = T(1) - u - v;
  detail::CurveScratch<Vec<T, N>, 28> b(p.control.size());
  for (std::size_t i = 0; i < p.control.size(); ++i) b[i] = p.control[i];
  for (int m = p.degree; m >= 1; --m) detail::triangle_level(b.data(), m, u, v, w);
  return b[0];
}

/// S(u, v), dS/du, dS/dv (w = 1 - u - v eliminated) and the mixed partial d2S/dudv.
template <class T, int N>
[[nodiscard]] SurfaceDerivatives<T, N> partials(const BezierTriangle<T, N>& p, T u, T v) noexcept {
  const Vec<T, N> nan = detail::curve_nan<T, N>();
  if (!detail::triangle_shape_ok(p)) return {nan, nan, nan, nan};
  detail::clamp_barycentric(u, v);
  const T w = T(1) - u - v;
  const int n = p.degree;
  detail::CurveScratch<Vec<T, N>, 28> b(p.control.size());
  for (std::size_t i = 0; i < p.control.size(); ++i) b[i] = p.control[i];
  SurfaceDerivatives<T, N> s{};
  if (n == 0) {
    s.point = b[0];
    return s;
  }
  for (int m = n; m >= 3; --m) detail::triangle_level(b.data(), m, u, v, w);
  if (n >= 2) {
    // Level n - 2: a quadratic net; d2/dudv = n (n-1) (b_110 - b_101 - b_011 + b_002).
    const auto q = [&](int i, int j) {
      return b[static_cast<std::size_t>(triangle_index(2, i, j))];
    };
    s.duv = static_cast<T>(n * (n - 1)) * ((q(1, 1) - q(1, 0)) - (q(0, 1) - q(0, 0)));
    detail::triangle_level(b.data(), 2, u, v, w);
  }
  // Level n - 1: b_100 = idx(1,0), b_010 = idx(0,1), b_001 = idx(0,0).
  const Vec<T, N> b100 = b[1], b010 = b[2], b001 = b[0];
  s.du = static_cast<T>(n) * (b100 - b001);
  s.dv = static_cast<T>(n) * (b010 - b001);
  s.point = u * b100 + v * b010 + w * b001;
  return s;
}

/// Splits a triangle patch at the point (u, v) (clamped onto the triangle) into three
/// patches; see the header comment for their corners. A bad shape returns three copies.
template <class T, int N>
[[nodiscard]] std::array<BezierTriangle<T, N>, 3> subdivide(const BezierTriangle<T, N>& p, T u,
                                                            T v) {
  if (!detail::triangle_shape_ok(p)) return {p, p, p};
  detail::clamp_barycentric(u, v);
  const T w = T(1) - u - v;
  const int n = p.degree;
  // levels[r] holds the degree n - r net of de Casteljau level r.
  std::vector<std::vector<Vec<T, N>>> levels(static_cast<std::size_t>(n) + 1);
  levels[0] = p.control;
  for (int r = 1; r <= n; ++r) {
    const int m = n - r + 1;  // degree of the previous level
    const auto& prev = levels[static_cast<std::size_t>(r - 1)];
    auto& cur = levels[static_cast<std::size_t>(r)];
    cur.resize(static_cast<std::size_t>(triangle_control_count(m - 1)));
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m - j; ++i)
        cur[static_cast<std::size_t>(triangle_index(m - 1, i, j))] =
            u * prev[static_cast<std::size_t>(triangle_index(m, i + 1, j))] +
            v * prev[static_cast<std::size_t>(triangle_index(m, i, j + 1))] +
            w * prev[static_cast<std::size_t>(triangle_index(m, i, j))];
  }
  std::array<BezierTriangle<T, N>, 3> out;
  for (auto& t : out) {
    t.degree = n;
    t.control.resize(p.control.size());
  }
  // Level r, index (a, b) with c = n - r - a - b: the blossom of (s^r, e1^a, e2^b, e3^c).
  const auto at = [&](int r, int a, int b) {
    return levels[static_cast<std::size_t>(r)]
                 [static_cast<std::size_t>(triangle_index(n - r, a, b))];
  };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i + j <= n; ++i) {
      const int k = n - i - j;
      const auto idx = static_cast<std::size_t>(triangle_index(n, i, j));
      out[0].control[idx] = at(i, 0, j);  // corners (s, e2, e3): s^i e2^j e3^k
      out[1].control[idx] = at(j, i, 0);  // corners (e1, s, e3): e1^i s^j e3^k
      out[2].control[idx] = at(k, i, j);  // corners (e1, e2, s): e1^i e2^j s^k
    }
  return out;
}

/// normalize(du x dv): the unit normal, the zero vector where du x dv vanishes (64 eps relative).
template <Real T>
[[nodiscard]] Vec3<T> normal_at(const BezierTriangle<T, 3>& p, T u, T v) noexcept {
  const SurfaceDerivatives<T, 3> s = partials(p, u, v);
  const Vec3<T> n = cross(s.du, s.dv);
  const T k = T(64) * eps_v<T>;
  if (!(sqr_length(n) > k * k * sqr_length(s.du) * sqr_length(s.dv))) return Vec3<T>{};
  return normalize(n);
}

/// The control-net box; it contains the patch.
template <class T, int N>
[[nodiscard]] AlignedBox<T, N> bounding_box(const BezierTriangle<T, N>& p) noexcept {
  return bounding_box(p.control.data(), p.control.size());
}

}  // namespace locus
