// SPDX-License-Identifier: BSL-1.0
#pragma once
// Symmetric eigendecomposition A = V diag(values) V^T (row num.decomp; book appendix A.3).
//
//   eigen_symmetric(Mat2<T>)  closed form, no iteration
//   eigen_symmetric(Mat3<T>)  closed-form eigenvalues of the shifted, scaled matrix, then
//                             eigenvectors by cross products and a 2x2 problem on the
//                             complement (robust for repeated and clustered eigenvalues)
//   eigen_symmetric(MatX<T>)  cyclic Jacobi rotations, any N, at most `max_sweeps` sweeps
//
// Output: eigenvalues in ascending order; V's columns are the matching unit eigenvectors and V is
// a rotation (det +1) for the 2x2 and 3x3 forms. Accuracy: |A - V diag V^T| and |V^T V - I| are
// within a small multiple of eps * |A| and eps (checked against Eigen in the tests).
// Float input is computed in double (compute_t) and rounded at the end.
//
// Bad input: a matrix with NaN/Inf gives Status::non_finite_input (values NaN, V = I); a matrix
// that is not symmetric within `symmetry_tolerance * max|a_ij|` gives Status::invalid_input
// (the result is still computed from the upper triangle). Jacobi that does not converge within
// its sweep budget returns Status::limit_exceeded with its current (usable) estimate.
// Cost: 2x2 and 3x3 are branch-light straight-line code; Jacobi is O(N^3) per sweep.

#include <locus/core/mat.hpp>
#include <locus/core/status.hpp>
#include <locus/numeric/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

namespace locus {

template <class T, int N>
struct SymmetricEigen {
  Status status = Status::empty_input;
  Vec<T, N> values{};      ///< ascending
  Mat<T, N, N> vectors{};  ///< column i is the unit eigenvector of values[i]
};

template <Real T>
struct SymmetricEigenX {
  Status status = Status::empty_input;
  std::vector<T> values;  ///< ascending
  MatX<T> vectors;        ///< column i is the unit eigenvector of values[i]
  int sweeps = 0;         ///< Jacobi sweeps used
};

/// Options of the symmetric eigensolvers.
template <Real T>
struct SymmetricEigenOptions {
  /// |a_ij - a_ji| above this times max|a| makes the input "not symmetric" (invalid_input).
  T symmetry_tolerance = T(64) * eps_v<T>;
  int max_sweeps = 64;  ///< Jacobi budget (NxN only); 3x3 and 2x2 never iterate
};

namespace detail {

template <class T, int N>
Status check_symmetric(const Mat<T, N, N>& a, T tol) noexcept {
  if (!is_finite(a)) return Status::non_finite_input;
  T m = T(0);
  for (int r = 0; r < N; ++r)
    for (int c = 0; c < N; ++c) m = std::max(m, std::abs(a(r, c)));
  for (int r = 0; r < N; ++r)
    for (int c = r + 1; c < N; ++c)
      if (std::abs(a(r, c) - a(c, r)) > tol * m) return Status::invalid_input;
  return Status::ok;
}

// Eigen-pairs of [[a, b], [b, c]] with values ascending; the vector of the larger value is
// (cs, sn), of the smaller (sn, -cs), so [v0 v1] is a rotation. No cancellation: the larger
// root's vector is built from d + r or r - d, whichever adds same-signed terms.
// Precondition: entries scaled to magnitude <= ~1e3 (callers scale), so plain sqrt of sums of
// squares cannot overflow or underflow harmfully; std::hypot would cost several times more.
template <class C>
void eigen2(C a, C b, C c, C& lo, C& hi, C& cs, C& sn) noexcept {
  const C m = (a + c) / C(2), d = (a - c) / C(2);
  const C r = std::sqrt(d * d + b * b);
  lo = m - r;
  hi = m + r;
  // When both eigenvalues have the same sign, the one nearer zero cancels in m -+ r; the product
  // lo * hi = det(A) = a c - b^2 gives it to relative accuracy when b^2 << a c (thin ellipses).
  const C det = a * c - b * b;
  if (m > r && hi != C(0)) {
    lo = det / hi;
  } else if (-m > r && lo != C(0)) {
    hi = det / lo;
  }
  if (r == C(0)) {  // multiple of the identity: any basis works
    cs = C(1);
    sn = C(0);
    return;
  }
  C x, y;
  if (d >= C(0)) {
    x = d + r;
    y = b;
  } else {
    x = b;
    y = r - d;
  }
  const C len = std::sqrt(x * x + y * y);
  cs = x / len;
  sn = y / len;
}

template <class C>
Vec3<C> any_unit_perpendicular(const Vec3<C>& v) noexcept {
  // Zero the smallest component of v and swap the other two: never a near-zero result.
  const C ax = std::abs(v.x), ay = std::abs(v.y), az = std::abs(v.z);
  Vec3<C> p = (ax <= ay && ax <= az) ? Vec3<C>{C(0), v.z, -v.y}
              : (ay <= az)           ? Vec3<C>{v.z, C(0), -v.x}
                                     : Vec3<C>{v.y, -v.x, C(0)};
  return p / length(p);
}

}  // namespace detail

/// Eigendecomposition of a symmetric 2x2 matrix (closed form).
template <Real T>
[[nodiscard]] SymmetricEigen<T, 2> eigen_symmetric(
    const Mat2<T>& a, const SymmetricEigenOptions<T>& opt = {}) noexcept {
  using C = compute_t<T>;
  SymmetricEigen<T, 2> out;
  out.status = Status::ok;
  out.status = detail::check_symmetric(a, opt.symmetry_tolerance);
  if (out.status == Status::non_finite_input) {
    out.values = splat<T, 2>(std::numeric_limits<T>::quiet_NaN());
    out.vectors = Mat2<T>::identity();
    return out;
  }
  if (a(0, 1) == T(0)) {  // diagonal: exact, no rounding at all
    if (a(0, 0) <= a(1, 1)) {
      out.values = {a(0, 0), a(1, 1)};
      out.vectors = Mat2<T>::identity();
    } else {
      out.values = {a(1, 1), a(0, 0)};
      out.vectors = Mat2<T>::from_cols(Vec2<T>{T(0), T(1)}, Vec2<T>{T(-1), T(0)});
    }
    return out;
  }
  const C scale =
      std::max(std::abs(C(a(0, 0))), std::max(std::abs(C(a(0, 1))), std::abs(C(a(1, 1)))));
  if (scale == C(0)) {
    out.values = Vec2<T>{};
    out.vectors = Mat2<T>::identity();
    return out;
  }
  C lo, hi, cs, sn;
  detail::eigen2(C(a(0, 0)) / scale, C(a(0, 1)) / scale, C(a(1, 1)) / scale, lo, hi, cs, sn);
  out.values = {T(lo * scale), T(hi * scale)};
  out.vectors = Mat2<T>::from_cols(Vec2<T>{T(sn), T(-cs)}, Vec2<T>{T(cs), T(sn)});
  return out;
}

/// Eigendecomposition of a symmetric 3x3 matrix (closed form, robust; see the top comment).
template <Real T>
[[nodiscard]] SymmetricEigen<T, 3> eigen_symmetric(
    const Mat3<T>& a_in, const SymmetricEigenOptions<T>& opt = {}) noexcept {
  using C = compute_t<T>;
  SymmetricEigen<T, 3> out;
  out.status = Status::ok;
  out.status = detail::check_symmetric(a_in, opt.symmetry_tolerance);
  if (out.status == Status::non_finite_input) {
    out.values = splat<T, 3>(std::numeric_limits<T>::quiet_NaN());
    out.vectors = Mat3<T>::identity();
    return out;
  }
  // Symmetrise from the upper triangle and scale to max |a_ij| = 1 (no overflow in squares).
  Mat3<C> a{};
  C scale = C(0);
  for (int r = 0; r < 3; ++r)
    for (int c = r; c < 3; ++c) scale = std::max(scale, std::abs(C(a_in(r, c))));
  if (scale == C(0)) {
    out.values = Vec3<T>{};
    out.vectors = Mat3<T>::identity();
    return out;
  }
  for (int r = 0; r < 3; ++r)
    for (int c = r; c < 3; ++c) a(r, c) = a(c, r) = C(a_in(r, c)) / scale;

  Vec3<C> values{};
  Mat3<C> vectors = Mat3<C>::identity();
  const C off = a(0, 1) * a(0, 1) + a(0, 2) * a(0, 2) + a(1, 2) * a(1, 2);
  if (off == C(0)) {
    values = {a(0, 0), a(1, 1), a(2, 2)};
  } else {
    // Shift by the mean eigenvalue q and scale by p so that B = (A - qI)/p has eigenvalues
    // 2cos(phi + 2k pi/3) with cos(3 phi) = det(B)/2.
    const C q = trace(a) / C(3);
    Mat3<C> b = a;
    for (int i = 0; i < 3; ++i) b(i, i) -= q;
    const C p =
        std::sqrt((b(0, 0) * b(0, 0) + b(1, 1) * b(1, 1) + b(2, 2) * b(2, 2) + C(2) * off) / C(6));
    const C half_det = determinant(b * (C(1) / p)) / C(2);
    const C phi = std::acos(clamp(half_det, C(-1), C(1))) / C(3);
    // For det(B) >= 0 the largest eigenvalue is the isolated one, otherwise the smallest; the
    // isolated eigenvalue is at least sqrt(3) p from the other two, so A - lambda I has rank 2
    // and its eigenvector is a well-conditioned cross product of two rows.
    const bool largest_isolated = half_det >= C(0);
    const C beta =
        largest_isolated ? C(2) * std::cos(phi) : C(2) * std::cos(phi + C(2) * pi_v<C> / C(3));
    Mat3<C> m = b;
    for (int i = 0; i < 3; ++i) m(i, i) -= p * beta;
    const Vec3<C> r0 = row(m, 0), r1 = row(m, 1), r2 = row(m, 2);
    const Vec3<C> c01 = cross(r0, r1), c02 = cross(r0, r2), c12 = cross(r1, r2);
    const C n01 = sqr_length(c01), n02 = sqr_length(c02), n12 = sqr_length(c12);
    Vec3<C> v = n01 >= n02 && n01 >= n12 ? c01 : (n02 >= n12 ? c02 : c12);
    const C vmax = std::max(n01, std::max(n02, n12));
    v = vmax > C(0) ? v / std::sqrt(vmax) : Vec3<C>{C(1), C(0), C(0)};
    v = v / length(v);  // one more pass: sqrt(vmax) was a rounded norm
    // The other two eigenpairs: the 2x2 problem A restricted to the plane perpendicular to v.
    const Vec3<C> u = detail::any_unit_perpendicular(v);
    const Vec3<C> w = cross(v, u);
    const Vec3<C> au = a * u, aw = a * w;
    C lo, hi, cs, sn;
    detail::eigen2(dot(u, au), (dot(u, aw) + dot(w, au)) / C(2), dot(w, aw), lo, hi, cs, sn);
    const Vec3<C> v_hi = u * cs + w * sn, v_lo = u * sn - w * cs;
    const C lambda = dot(v, a * v);  // Rayleigh quotient: accurate to eps |A|
    if (largest_isolated) {
      values = {lo, hi, lambda};
      vectors = Mat3<C>::from_cols(v_lo, v_hi, v);
    } else {
      values = {lambda, lo, hi};
      vectors = Mat3<C>::from_cols(v, v_lo, v_hi);
    }
  }
  // Ascending order (the pieces above are ordered except for rounding ties) and det +1.
  int idx[3] = {0, 1, 2};
  std::sort(idx, idx + 3, [&](int i, int j) { return values[i] < values[j]; });
  Mat3<C> sorted{};
  for (int k = 0; k < 3; ++k) {
    out.values[k] = T(values[idx[k]] * scale);
    set_col(sorted, k, col(vectors, idx[k]));
  }
  if (determinant(sorted) < C(0)) set_col(sorted, 2, -col(sorted, 2));
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out.vectors(r, c) = T(sorted(r, c));
  return out;
}

/// Eigendecomposition of a symmetric N x N matrix by cyclic Jacobi rotations.
template <Real T>
[[nodiscard]] SymmetricEigenX<T> eigen_symmetric(const MatX<T>& a_in,
                                                 const SymmetricEigenOptions<T>& opt = {}) {
  using C = compute_t<T>;
  SymmetricEigenX<T> out;
  out.status = Status::ok;
  const int n = a_in.rows;
  if (a_in.rows != a_in.cols) {
    out.status = Status::invalid_input;
    return out;
  }
  out.vectors = MatX<T>::identity(n);
  out.values.assign(static_cast<std::size_t>(n), T(0));
  if (n == 0) {
    out.status = Status::empty_input;
    return out;
  }
  if (!is_finite(a_in)) {
    out.status = Status::non_finite_input;
    std::fill(out.values.begin(), out.values.end(), std::numeric_limits<T>::quiet_NaN());
    return out;
  }
  C scale = C(0);
  for (T x : a_in.data) scale = std::max(scale, std::abs(C(x)));
  for (int r = 0; r < n; ++r)
    for (int c = r + 1; c < n; ++c)
      if (std::abs(C(a_in(r, c)) - C(a_in(c, r))) > C(opt.symmetry_tolerance) * scale)
        out.status = Status::invalid_input;
  if (scale == C(0)) return out;

  MatX<C> a(n, n);
  for (int r = 0; r < n; ++r)
    for (int c = r; c < n; ++c) a(r, c) = a(c, r) = C(a_in(r, c)) / scale;
  MatX<C> v = MatX<C>::identity(n);
  auto off_norm = [&] {
    C s = C(0);
    for (int r = 0; r < n; ++r)
      for (int c = r + 1; c < n; ++c) s += a(r, c) * a(r, c);
    return s;
  };
  C total = C(0);
  for (C x : a.data) total += x * x;
  const C target = sqr(eps_v<C>) * total;  // stop when the off-diagonal part is negligible
  bool converged = false;
  int sweep = 0;
  for (; sweep < opt.max_sweeps; ++sweep) {
    if (off_norm() <= target) {
      converged = true;
      break;
    }
    for (int p = 0; p < n - 1; ++p)
      for (int q = p + 1; q < n; ++q) {
        const C apq = a(p, q);
        if (apq == C(0)) continue;
        // Rotation angle from tan(2 theta) = 2 apq / (aqq - app), the smaller root for t.
        const C theta = (a(q, q) - a(p, p)) / (C(2) * apq);
        const C t =
            (theta >= C(0) ? C(1) : C(-1)) / (std::abs(theta) + std::sqrt(theta * theta + C(1)));
        const C c = C(1) / std::sqrt(t * t + C(1)), s = t * c;
        for (int k = 0; k < n; ++k) {  // A <- A J (columns p, q)
          const C akp = a(k, p), akq = a(k, q);
          a(k, p) = c * akp - s * akq;
          a(k, q) = s * akp + c * akq;
        }
        for (int k = 0; k < n; ++k) {  // A <- J^T A (rows p, q)
          const C apk = a(p, k), aqk = a(q, k);
          a(p, k) = c * apk - s * aqk;
          a(q, k) = s * apk + c * aqk;
        }
        a(p, q) = a(q, p) = C(0);
        for (int k = 0; k < n; ++k) {
          const C vkp = v(k, p), vkq = v(k, q);
          v(k, p) = c * vkp - s * vkq;
          v(k, q) = s * vkp + c * vkq;
        }
      }
  }
  if (!converged && off_norm() <= target) converged = true;
  out.sweeps = sweep;
  if (!converged && out.status == Status::ok) out.status = Status::limit_exceeded;
  std::vector<int> idx(static_cast<std::size_t>(n));
  std::iota(idx.begin(), idx.end(), 0);
  std::stable_sort(idx.begin(), idx.end(), [&](int i, int j) { return a(i, i) < a(j, j); });
  for (int k = 0; k < n; ++k) {
    const int s = idx[std::size_t(k)];
    out.values[std::size_t(k)] = T(a(s, s) * scale);
    for (int r = 0; r < n; ++r) out.vectors(r, k) = T(v(r, s));
  }
  return out;
}

}  // namespace locus
