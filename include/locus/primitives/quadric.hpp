// SPDX-License-Identifier: BSL-1.0
#pragma once
// General quadric surfaces: classification and standard form; row prim3.quadric; book section
// 9.4, figures 9.18 (three nonzero eigenvalues), 9.19 (two), 9.20 (one).
// Quadric3<T> {a, b, c} is the surface { X : X^T A X + dot(b, X) + c = 0 }, A symmetric (only
// its upper triangle is read). signed_value(q, X) evaluates the left-hand side. Only real points
// count (x^2 + y^2 + z^2 + 1 = 0 is empty). The classes by rank of A, and the method (inertia
// of A and of the extended 4x4 matrix): docs/notes/primitives.md.
// quadric_type(q): EXACT for all finite float or double coefficients (signs of principal-minor
// sums by core/exact_sum.hpp); `exact` is always true. Cost: 7 exact sums, microseconds, no
// allocation.
// quadric_type(q, rel_tol): for coefficients with rounding error (a cone transformed in floating
// point is exactly a hyperboloid): after scaling by 1 / max|coefficient|, standard-form terms of
// magnitude <= rel_tol count as zero (rescale coordinates first when A, b and c differ greatly in
// magnitude; a typical rel_tol is 1e3 * eps).
// standard_form(q): QuadricStandardForm {rotation R (right-handed, columns = new axes), center P,
// diagonal d, linear e, constant k} with q(P + R y) = d0 y0^2 + d1 y1^2 + d2 y2^2 + dot(e, y) + k;
// nonzero d first (positive before negative, then decreasing |d|); e = (0, 0, e2), e2 > 0 only
// for paraboloids, the parabolic cylinder and the rank-0 plane (then k = 0); k = 0 exactly for
// cones, points, lines and intersecting/double planes. The ranks agree with quadric_type(q); the
// numbers are rounded, computed in compute_t<T>. to_quadric(form) converts back.
// to_quadric(sphere / ellipsoid / cylinder / cone) keeps "negative inside" (infinite cylinder and
// double cone: the height range is dropped); classify it with the rel_tol overload.
// Non-finite coefficients: status non_finite_input, type QuadricType::invalid.

#include <locus/config.hpp>
#include <locus/core/mat.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/cone.hpp>
#include <locus/primitives/cylinder.hpp>
#include <locus/primitives/ellipsoid.hpp>
#include <locus/primitives/plane.hpp>
#include <locus/primitives/sphere.hpp>

#include <cmath>
#include <cstdint>
#include <string_view>

namespace locus {

/// The quadric surface X^T a X + dot(b, X) + c = 0 (a symmetric; upper triangle read).
template <Real T>
struct Quadric3 {
  Mat3<T> a;
  Vec3<T> b;
  T c;
};

using Quadric3f = Quadric3<float>;
using Quadric3d = Quadric3<double>;

/// The affine type of a real quadric surface (its set of real points).
enum class QuadricType : std::uint8_t {
  ellipsoid,
  hyperboloid_one_sheet,
  hyperboloid_two_sheets,
  elliptic_cone,
  elliptic_paraboloid,
  hyperbolic_paraboloid,
  elliptic_cylinder,
  hyperbolic_cylinder,
  parabolic_cylinder,
  intersecting_planes,
  parallel_planes,
  plane,         ///< a single plane (rank A = 0, or a double plane of rank A = 1)
  line,          ///< a single line (degenerate elliptic cylinder)
  point,         ///< a single point (degenerate ellipsoid / cone)
  empty,         ///< no real points
  entire_space,  ///< every point (all coefficients zero)
  invalid,       ///< non-finite coefficients
};

/// A short snake_case name of a quadric type.
[[nodiscard]] constexpr std::string_view to_string(QuadricType t) noexcept {
  switch (t) {
    case QuadricType::ellipsoid:
      return "ellipsoid";
    case QuadricType::hyperboloid_one_sheet:
      return "hyperboloid_one_sheet";
    case QuadricType::hyperboloid_two_sheets:
      return "hyperboloid_two_sheets";
    case QuadricType::elliptic_cone:
      return "elliptic_cone";
    case QuadricType::elliptic_paraboloid:
      return "elliptic_paraboloid";
    case QuadricType::hyperbolic_paraboloid:
      return "hyperbolic_paraboloid";
    case QuadricType::elliptic_cylinder:
      return "elliptic_cylinder";
    case QuadricType::hyperbolic_cylinder:
      return "hyperbolic_cylinder";
    case QuadricType::parabolic_cylinder:
      return "parabolic_cylinder";
    case QuadricType::intersecting_planes:
      return "intersecting_planes";
    case QuadricType::parallel_planes:
      return "parallel_planes";
    case QuadricType::plane:
      return "plane";
    case QuadricType::line:
      return "line";
    case QuadricType::point:
      return "point";
    case QuadricType::empty:
      return "empty";
    case QuadricType::entire_space:
      return "entire_space";
    case QuadricType::invalid:
      return "invalid";
  }
  return "unknown";
}

/// Classification result: the type and the inertia it was decided from.
struct QuadricClass {
  Status status;     ///< ok, or non_finite_input
  QuadricType type;  ///< invalid when status != ok
  int rank_a;        ///< rank of A
  int positive_a;    ///< number of positive eigenvalues of A
  int negative_a;    ///< number of negative eigenvalues of A
  int rank_m;        ///< rank of the extended 4x4 matrix M
  int positive_m;    ///< positive eigenvalues of M
  int negative_m;    ///< negative eigenvalues of M
  bool exact;        ///< true when the inertia was computed without any rounding
};

/// q(P + R y) = sum d_i y_i^2 + dot(e, y) + k (see the header comment).
template <Real T>
struct QuadricStandardForm {
  Status status;
  QuadricType type;
  Mat3<T> rotation;  ///< right-handed; column i is the i-th new axis
  Vec3<T> center;    ///< P
  Vec3<T> diagonal;  ///< d
  Vec3<T> linear;    ///< e = (0, 0, e2)
  T constant;        ///< k
};

/// X^T A X + dot(b, X) + c.
template <Real T>
[[nodiscard]] constexpr T signed_value(const Quadric3<T>& q, const Vec3<T>& x) noexcept {
  T s = q.c + dot(q.b, x);
  for (int i = 0; i < 3; ++i) {
    s += q.a.a[i][i] * x[i] * x[i];
    for (int j = i + 1; j < 3; ++j) s += T(2) * q.a.a[i][j] * x[i] * x[j];
  }
  return s;
}

namespace detail {

/// The affine type from the ranks and inertia of A and M (header comment).
[[nodiscard]] constexpr QuadricType quadric_type_of_inertia(int ra, int pa, int na, int rm, int pm,
                                                            int nm) noexcept {
  const bool a_definite = (pa == ra || na == ra);
  const bool m_definite = (pm == rm || nm == rm);
  switch (ra) {
    case 3:
      if (rm == 3) return a_definite ? QuadricType::point : QuadricType::elliptic_cone;
      if (a_definite) return m_definite ? QuadricType::empty : QuadricType::ellipsoid;
      return (pm == 2 && nm == 2) ? QuadricType::hyperboloid_one_sheet
                                  : QuadricType::hyperboloid_two_sheets;
    case 2:
      if (rm == 4)
        return a_definite ? QuadricType::elliptic_paraboloid : QuadricType::hyperbolic_paraboloid;
      if (rm == 3) {
        if (!a_definite) return QuadricType::hyperbolic_cylinder;
        return m_definite ? QuadricType::empty : QuadricType::elliptic_cylinder;
      }
      return a_definite ? QuadricType::line : QuadricType::intersecting_planes;
    case 1:
      if (rm == 3) return QuadricType::parabolic_cylinder;
      if (rm == 2) return m_definite ? QuadricType::empty : QuadricType::parallel_planes;
      return QuadricType::plane;
    default:
      if (rm == 2) return QuadricType::plane;
      if (rm == 1) return QuadricType::empty;
      return QuadricType::entire_space;
  }
}

template <Real T>
[[nodiscard]] constexpr bool quadric_is_finite(const Quadric3<T>& q) noexcept {
  return is_finite(q.a) && is_finite(q.b) && is_finite(q.c);
}

}  // namespace detail

/// Exact classification of the quadric with the given coefficients (header comment); compiled
/// in src/primitives/quadric.cpp for float and double.
template <Real T>
[[nodiscard]] QuadricClass quadric_type(const Quadric3<T>& q) noexcept;
extern template QuadricClass quadric_type<float>(const Quadric3<float>&) noexcept;
extern template QuadricClass quadric_type<double>(const Quadric3<double>&) noexcept;

namespace detail {

/// Standard form given the decisions: rank of A, whether a linear term survives in the null
/// space of A, whether the constant is zero. (Inputs in compute type C, already scaled.)
template <class T, class C>
[[nodiscard]] inline QuadricStandardForm<T> quadric_standard_form(const Mat3<C>& a,
                                                                  const Vec3<C>& b, C c, int rank,
                                                                  bool has_linear,
                                                                  bool zero_constant) noexcept {
  const auto eig = eigen_symmetric(a);
  // Order: the `rank` largest |lambda| are the nonzero ones; positives first, then |d| descending.
  int idx[3] = {0, 1, 2};
  for (int i = 1; i < 3; ++i)
    for (int j = i; j > 0 && std::fabs(eig.values[idx[j]]) > std::fabs(eig.values[idx[j - 1]]);
         --j) {
      const int t = idx[j];
      idx[j] = idx[j - 1];
      idx[j - 1] = t;
    }
  for (int i = 1; i < rank; ++i)
    for (int j = i; j > 0 && eig.values[idx[j]] > C(0) && !(eig.values[idx[j - 1]] > C(0)); --j) {
      const int t = idx[j];
      idx[j] = idx[j - 1];
      idx[j - 1] = t;
    }
  Vec3<C> axis[3], d{};
  for (int i = 0; i < 3; ++i) {
    axis[i] = col(eig.vectors, idx[i]);
    d[i] = i < rank ? eig.values[idx[i]] : C(0);
  }
  Vec3<C> center{}, lin{};
  C k = c;
  for (int i = 0; i < rank; ++i) {
    const C bi = dot(axis[i], b);
    center += (-bi / (C(2) * d[i])) * axis[i];
    k -= bi * bi / (C(4) * d[i]);
  }
  if (has_linear && rank < 3) {
    // The part of b in the null space of A, as a world vector.
    Vec3<C> g{};
    for (int i = rank; i < 3; ++i) g += dot(axis[i], b) * axis[i];
    const auto gl = normalize_with_length(g);
    if (gl.length > C(0)) {
      const Vec3<C> w = gl.dir;
      axis[2] = w;
      if (rank == 1) {
        axis[1] = cross(w, axis[0]);
      } else if (rank == 0) {
        const auto pb = perpendicular_basis(w);
        axis[0] = pb.u;
        axis[1] = pb.v;
      }
      center += (-k / gl.length) * w;
      lin.z = gl.length;
      k = C(0);
    }
  }
  if (zero_constant) k = C(0);
  Mat3<C> rot = Mat3<C>::from_cols(axis[0], axis[1], axis[2]);
  if (determinant(rot) < C(0))
    for (int r = 0; r < 3; ++r) rot.a[r][0] = -rot.a[r][0];
  QuadricStandardForm<T> f{Status::ok, QuadricType::invalid, {}, {}, {}, {}, static_cast<T>(k)};
  for (int r = 0; r < 3; ++r)
    for (int cc = 0; cc < 3; ++cc) f.rotation.a[r][cc] = static_cast<T>(rot.a[r][cc]);
  f.center = vec_cast<T>(center);
  f.diagonal = vec_cast<T>(d);
  f.linear = vec_cast<T>(lin);
  return f;
}

template <class C, class T>
inline void quadric_to_compute(const Quadric3<T>& q, Mat3<C>& a, Vec3<C>& b, C& c) noexcept {
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) a.a[i][j] = a.a[j][i] = static_cast<C>(q.a.a[i][j]);
  b = vec_cast<C>(q.b);
  c = static_cast<C>(q.c);
}

}  // namespace detail

/// Standard form with the ranks of the exact classification (so its type is
/// quadric_type(q).type).
template <Real T>
[[nodiscard]] inline QuadricStandardForm<T> standard_form(const Quadric3<T>& q) noexcept {
  using C = compute_t<T>;
  const QuadricClass cls = quadric_type(q);
  if (cls.status != Status::ok)
    return {cls.status, QuadricType::invalid, Mat3<T>::identity(), {}, {}, {}, T(0)};
  Mat3<C> a{};
  Vec3<C> b{};
  C c{};
  detail::quadric_to_compute(q, a, b, c);
  auto f = detail::quadric_standard_form<T>(a, b, c, cls.rank_a, cls.rank_m == cls.rank_a + 2,
                                            cls.rank_m == cls.rank_a);
  f.type = cls.type;
  return f;
}

/// Standard form with tolerance decisions: after scaling by 1 / max|coefficient|, eigenvalues,
/// the null-space linear term and the constant with magnitude <= rel_tol count as zero. The
/// returned numbers are in the ORIGINAL scale.
template <Real T>
[[nodiscard]] inline QuadricStandardForm<T> standard_form(const Quadric3<T>& q,
                                                          T rel_tol) noexcept {
  using C = compute_t<T>;
  if (!detail::quadric_is_finite(q))
    return {Status::non_finite_input, QuadricType::invalid, Mat3<T>::identity(), {}, {}, {}, T(0)};
  Mat3<C> a{};
  Vec3<C> b{};
  C c{};
  detail::quadric_to_compute(q, a, b, c);
  C big = std::fabs(c);
  for (int i = 0; i < 3; ++i) {
    big = std::fmax(big, std::fabs(b[i]));
    for (int j = 0; j < 3; ++j) big = std::fmax(big, std::fabs(a.a[i][j]));
  }
  const C tol = static_cast<C>(rel_tol);
  const C s = big > C(0) ? C(1) / big : C(1);
  const Mat3<C> as = a * s;
  const Vec3<C> bs = b * s;
  const C cs = c * s;
  const auto eig = eigen_symmetric(as);
  int rank = 0, pos = 0, neg = 0;
  for (int i = 0; i < 3; ++i)
    if (std::fabs(eig.values[i]) > tol) {
      ++rank;
      (eig.values[i] > C(0) ? pos : neg) += 1;
    }
  // Probe the decisions on the scaled problem, then rebuild in the original scale.
  const auto probe = detail::quadric_standard_form<T, C>(as, bs, cs, rank, true, false);
  const bool has_linear = rank < 3 && static_cast<C>(probe.linear.z) > tol;
  const auto probe2 = detail::quadric_standard_form<T, C>(as, bs, cs, rank, false, false);
  const C k = static_cast<C>(probe2.constant);
  const bool zero_constant = !has_linear && std::fabs(k) <= tol;
  auto f = detail::quadric_standard_form<T, C>(a, b, c, rank, has_linear, zero_constant);
  int rm = rank, pm = pos, nm = neg;
  if (has_linear) {
    rm += 2;
    ++pm;
    ++nm;
  } else if (!zero_constant) {
    ++rm;
    (k > C(0) ? pm : nm) += 1;
  }
  f.type = detail::quadric_type_of_inertia(rank, pos, neg, rm, pm, nm);
  return f;
}

/// Tolerance-based classification (see standard_form(q, rel_tol)); exact = false.
template <Real T>
[[nodiscard]] inline QuadricClass quadric_type(const Quadric3<T>& q, T rel_tol) noexcept {
  const auto f = standard_form(q, rel_tol);
  QuadricClass r{f.status, f.type, 0, 0, 0, 0, 0, 0, false};
  if (f.status != Status::ok) return r;
  for (int i = 0; i < 3; ++i)
    if (f.diagonal[i] != T(0)) {
      ++r.rank_a;
      (f.diagonal[i] > T(0) ? r.positive_a : r.negative_a) += 1;
    }
  r.rank_m = r.rank_a;
  r.positive_m = r.positive_a;
  r.negative_m = r.negative_a;
  if (f.linear.z != T(0)) {
    r.rank_m += 2;
    ++r.positive_m;
    ++r.negative_m;
  } else if (f.constant != T(0)) {
    ++r.rank_m;
    (f.constant > T(0) ? r.positive_m : r.negative_m) += 1;
  }
  return r;
}

/// The quadric of a standard form: A = R diag(d) R^T, b = R e - 2 A P,
/// c = P^T A P - dot(R e, P) + k (rounded).
template <Real T>
[[nodiscard]] constexpr Quadric3<T> to_quadric(const QuadricStandardForm<T>& f) noexcept {
  const Mat3<T>& r = f.rotation;
  const Mat3<T> a = r * Mat3<T>::diagonal(f.diagonal) * transpose(r);
  const Vec3<T> re = r * f.linear;
  const Vec3<T> ap = a * f.center;
  return {a, re - T(2) * ap, dot(f.center, ap) - dot(re, f.center) + f.constant};
}

namespace detail {
/// x^T A x + b.x + c for A symmetric, re-centred at p: A, -2 A p, p^T A p + c.
template <Real T>
[[nodiscard]] constexpr Quadric3<T> quadric_about(const Mat3<T>& a, const Vec3<T>& p,
                                                  T c) noexcept {
  const Vec3<T> ap = a * p;
  return {a, T(-2) * ap, dot(p, ap) + c};
}
}  // namespace detail

/// |X - C|^2 - r^2 in general form.
template <Real T>
[[nodiscard]] constexpr Quadric3<T> to_quadric(const Sphere3<T>& s) noexcept {
  return detail::quadric_about(Mat3<T>::identity(), s.center, -s.radius * s.radius);
}

/// (X - C)^T M (X - C) - 1 in general form (M = implicit_matrix(e)).
template <Real T>
[[nodiscard]] constexpr Quadric3<T> to_quadric(const Ellipsoid3<T>& e) noexcept {
  return detail::quadric_about(implicit_matrix(e), e.center, T(-1));
}

/// |X - C|^2 - dot(D, X - C)^2 - r^2 (the infinite cylinder) in general form.
template <Real T>
[[nodiscard]] constexpr Quadric3<T> to_quadric(const Cylinder3<T>& c) noexcept {
  const Mat3<T> a = Mat3<T>::identity() - outer(c.axis.direction, c.axis.direction);
  return detail::quadric_about(a, c.axis.origin, -c.radius * c.radius);
}

/// cos^2(a) |X - V|^2 - dot(D, X - V)^2 (the infinite double cone) in general form.
template <Real T>
[[nodiscard]] inline Quadric3<T> to_quadric(const Cone3<T>& c) noexcept {
  const Mat3<T> a = Mat3<T>::identity() * sqr(std::cos(c.angle)) - outer(c.axis, c.axis);
  return detail::quadric_about(a, c.vertex, T(0));
}

}  // namespace locus
