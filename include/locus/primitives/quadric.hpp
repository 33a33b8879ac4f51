// SPDX-License-Identifier: BSL-1.0
#pragma once
// General quadric surfaces: classification and standard form; row prim3.quadric; book section
// 9.4, figures 9.18 (three nonzero eigenvalues), 9.19 (two), 9.20 (one).
//
// Quadric3<T> {a, b, c} is the surface { X : X^T A X + dot(b, X) + c = 0 }, A symmetric (only
// its upper triangle is read). signed_value(q, X) evaluates the left-hand side.
//
// Classification. The affine type of a real quadric is decided by the inertia (numbers of
// positive and negative eigenvalues) of A and of the 4x4 extended matrix M = [[A, b/2],
// [b^T/2, c]]. As in the book, diagonalising A = R D R^T and completing squares gives one of
//   rank A = 3: ellipsoid, hyperboloid of one / two sheets, elliptic cone, point, empty
//   rank A = 2: elliptic / hyperbolic paraboloid, elliptic / hyperbolic cylinder, line,
//               two intersecting planes, empty
//   rank A = 1: parabolic cylinder, two parallel planes, one (double) plane, empty
//   rank A = 0: plane, empty (0 = c != 0), entire space (0 = 0)
// and in each case the rank and inertia of M tell the alternatives apart (M is congruent to
// diag(D) extended by the block of the remaining linear term and constant). Only real points
// count: an "imaginary ellipsoid" x^2 + y^2 + z^2 + 1 = 0 is empty.
//
// classify(q) is EXACT for the given floating-point coefficients: the inertia comes from the
// signs of the coefficients of the characteristic polynomials of A and M (sums of principal
// minors; Descartes' rule of signs is exact for the real-rooted characteristic polynomial of a
// symmetric matrix), evaluated exactly with floating-point expansion arithmetic (error-free
// two-sum and two-product of core/error_free.hpp, written after Shewchuk's paper; like all
// error-free transformations it is invalid under -ffast-math). The coefficients are first scaled
// by a power of two (sign-preserving, since every invariant is homogeneous). The result is exact whenever every nonzero coefficient has its unit in the last
// place >= 2^-268 times the largest coefficient's scale (about 2^-215 relative magnitude) - always
// for float input; otherwise some product may underflow and `exact` is false (the answer is still
// computed the same way).
//
// classify(q, rel_tol) is the tolerance-based alternative for coefficients that carry rounding
// error (e.g. a cone transformed in floating point is exactly a hyperboloid): after scaling
// every coefficient by 1 / max|coefficient|, eigenvalues, the remaining linear term and the
// constant of the standard form with magnitude <= rel_tol are treated as zero. The threshold is
// relative to the largest coefficient, so rescale coordinates first when A, b and c have very
// different magnitudes. A typical value is 1e3 * eps for data with a few rounding errors.
//
// Standard form: QuadricStandardForm {rotation R (right-handed, columns = new axes), center P,
// diagonal d, linear e, constant k} with
//   q(P + R y) = d0 y0^2 + d1 y1^2 + d2 y2^2 + dot(e, y) + k,
// nonzero d first (positive before negative, then decreasing |d|), zero d last; e = (0, 0, e2)
// with e2 > 0 only for paraboloids, the parabolic cylinder and the plane of rank A = 0 (then
// k = 0: the origin of y lies on the surface's vertex/plane); otherwise e = 0 and k = 0 exactly
// for cones, points, lines and intersecting/double planes. standard_form(q) takes the ranks
// from the exact classification, so the form always agrees with classify(q); its numbers (R, P,
// d, k) are rounded and computed in compute_t<T> (double for float). The eigenvectors come from
// numeric/eigen_sym.hpp's eigen_symmetric. to_quadric(form) converts back.
//
// The quadric solids convert to general form with to_quadric(): sphere |X - C|^2 - r^2,
// ellipsoid (X - C)^T M (X - C) - 1, infinite cylinder |X - C|^2 - dot(D, X - C)^2 - r^2 and
// infinite double cone cos^2(a) |X - V|^2 - dot(D, X - V)^2; signed_value() of the result equals
// signed_value() of the solid (up to rounding), so "negative inside" carries over. The height
// range of a finite cylinder or cone is not part of a quadric. The coefficients are rounded, so
// classify the result with the tolerance overload (a rounded cone is exactly a hyperboloid).
//
// Degenerate input: NaN or infinite coefficients give status non_finite_input and type
// QuadricType::invalid. Cost: classify(q) evaluates 13 exact principal minors (a few thousand
// flops, no allocation; the expansions live on the stack, about 2 KB each).

#include <locus/config.hpp>
#include <locus/core/error_free.hpp>
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
template <class T>
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
template <class T>
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
template <class T>
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
[[nodiscard]] constexpr QuadricType quadric_type(int ra, int pa, int na, int rm, int pm,
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

/// Exact floating-point expansions (nonoverlapping components, increasing magnitude, zeros
/// removed), enough for the 4x4 determinant of single doubles (at most 192 components).
struct Expansion {
  static constexpr int capacity = 256;
  double c[capacity];
  int n = 0;
};

/// e += b exactly (Shewchuk's Grow-Expansion with zero elimination).
inline void grow(Expansion& e, double b) noexcept {
  double q = b;
  int k = 0;
  for (int i = 0; i < e.n; ++i) {
    double h;
    two_sum(q, e.c[i], q, h);
    if (h != 0.0) e.c[k++] = h;
  }
  if (q != 0.0) {
    LOCUS_ASSERT(k < Expansion::capacity, "quadric expansion capacity exceeded");
    e.c[k++] = q;
  }
  e.n = k;
}

/// e += f * s exactly.
inline void add_scaled(Expansion& e, const Expansion& f, double s) noexcept {
  for (int i = 0; i < f.n; ++i) {
    const double p = f.c[i] * s;
    grow(e, product_error(f.c[i], s, p));
    grow(e, p);
  }
}

/// e += a * b exactly.
inline void add_product(Expansion& e, double a, double b) noexcept {
  const double p = a * b;
  grow(e, product_error(a, b, p));
  grow(e, p);
}

[[nodiscard]] inline int sign(const Expansion& e) noexcept {
  return e.n == 0 ? 0 : (e.c[e.n - 1] > 0.0 ? 1 : -1);
}

/// Exact signs of the principal-minor sums of a symmetric 4x4 matrix m (double entries).
struct QuadricInvariants {
  int a[4];  // a[k] = sign of the k-th principal minor sum of the top-left 3x3 block (a[0] = 1)
  int m[5];  // m[k] = the same for the whole 4x4 matrix
};

[[nodiscard]] inline Expansion minor2(const double (&m)[4][4], int r0, int r1, int c0,
                                      int c1) noexcept {
  Expansion e;
  add_product(e, m[r0][c0], m[r1][c1]);
  add_product(e, -m[r0][c1], m[r1][c0]);
  return e;
}

/// out += sgn * det of rows r, columns c (sgn = +-1, so the scaling stays exact).
inline void add_det3(Expansion& out, const double (&m)[4][4], const int (&r)[3], const int (&c)[3],
                     double sgn) noexcept {
  add_scaled(out, minor2(m, r[1], r[2], c[1], c[2]), sgn * m[r[0]][c[0]]);
  add_scaled(out, minor2(m, r[1], r[2], c[0], c[2]), -sgn * m[r[0]][c[1]]);
  add_scaled(out, minor2(m, r[1], r[2], c[0], c[1]), sgn * m[r[0]][c[2]]);
}

[[nodiscard]] inline QuadricInvariants quadric_invariants(const double (&m)[4][4]) noexcept {
  QuadricInvariants inv{{1, 0, 0, 0}, {1, 0, 0, 0, 0}};
  Expansion e1, e2, e3, e4;
  for (int i = 0; i < 3; ++i) grow(e1, m[i][i]);
  inv.a[1] = sign(e1);
  grow(e1, m[3][3]);
  inv.m[1] = sign(e1);
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      const Expansion x = minor2(m, i, j, i, j);
      add_scaled(e2, x, 1.0);
    }
  inv.a[2] = sign(e2);
  for (int i = 0; i < 3; ++i) add_scaled(e2, minor2(m, i, 3, i, 3), 1.0);
  inv.m[2] = sign(e2);
  add_det3(e3, m, {0, 1, 2}, {0, 1, 2}, 1.0);
  inv.a[3] = sign(e3);
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) add_det3(e3, m, {i, j, 3}, {i, j, 3}, 1.0);
  inv.m[3] = sign(e3);
  // det M by cofactors along row 0.
  constexpr int cols[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  for (int j = 0; j < 4; ++j) {
    Expansion d3;
    add_det3(d3, m, {1, 2, 3}, cols[j], 1.0);
    add_scaled(e4, d3, (j % 2 == 0) ? m[0][j] : -m[0][j]);
  }
  inv.m[4] = sign(e4);
  return inv;
}

/// Rank and number of positive eigenvalues from the signs s[0..n] of the characteristic
/// coefficients e_k (s[0] = 1): rank = last nonzero, positives = sign changes of (-1)^k s[k].
inline void inertia(const int* s, int n, int& rank, int& pos, int& neg) noexcept {
  rank = 0;
  for (int k = 1; k <= n; ++k)
    if (s[k] != 0) rank = k;
  pos = 0;
  int prev = 1;
  for (int k = 1; k <= rank; ++k) {
    if (s[k] == 0) continue;
    const int cur = (k % 2 == 0) ? s[k] : -s[k];
    if (cur != prev) ++pos;
    prev = cur;
  }
  neg = rank - pos;
}

template <class T>
[[nodiscard]] constexpr bool quadric_is_finite(const Quadric3<T>& q) noexcept {
  return is_finite(q.a) && is_finite(q.b) && is_finite(q.c);
}

}  // namespace detail

/// Exact classification of the quadric with the given coefficients (header comment).
template <class T>
[[nodiscard]] inline QuadricClass classify(const Quadric3<T>& q) noexcept {
  QuadricClass r{Status::ok, QuadricType::invalid, 0, 0, 0, 0, 0, 0, true};
  if (!detail::quadric_is_finite(q)) {
    r.status = Status::non_finite_input;
    r.exact = false;
    return r;
  }
  double m[4][4];
  for (int i = 0; i < 3; ++i) {
    for (int j = i; j < 3; ++j) m[i][j] = m[j][i] = static_cast<double>(q.a.a[i][j]);
    m[i][3] = m[3][i] = 0.5 * static_cast<double>(q.b[i]);
  }
  m[3][3] = static_cast<double>(q.c);
  double big = 0.0;
  for (const auto& rw : m)
    for (double x : rw) big = std::fmax(big, std::fabs(x));
  if (big > 0.0) {
    int e = 0;
    (void)std::frexp(big, &e);
    for (auto& rw : m)
      for (double& x : rw) {
        x = std::ldexp(x, -e);
        // Exactness: every entry's ulp 2^(ex - 53) >= 2^-268, so products of four stay on the
        // subnormal grid 2^-1074 and no error term is lost.
        if (x != 0.0) {
          int ex = 0;
          (void)std::frexp(x, &ex);
          if (ex - 53 < -268) r.exact = false;
        }
      }
  }
  const auto inv = detail::quadric_invariants(m);
  detail::inertia(inv.a, 3, r.rank_a, r.positive_a, r.negative_a);
  detail::inertia(inv.m, 4, r.rank_m, r.positive_m, r.negative_m);
  r.type = detail::quadric_type(r.rank_a, r.positive_a, r.negative_a, r.rank_m, r.positive_m,
                                r.negative_m);
  return r;
}

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

/// Standard form with the ranks of the exact classification (so its type is classify(q).type).
template <class T>
[[nodiscard]] inline QuadricStandardForm<T> standard_form(const Quadric3<T>& q) noexcept {
  using C = compute_t<T>;
  const QuadricClass cls = classify(q);
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
template <class T>
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
  f.type = detail::quadric_type(rank, pos, neg, rm, pm, nm);
  return f;
}

/// Tolerance-based classification (see standard_form(q, rel_tol)); exact = false.
template <class T>
[[nodiscard]] inline QuadricClass classify(const Quadric3<T>& q, T rel_tol) noexcept {
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
template <class T>
[[nodiscard]] constexpr Quadric3<T> to_quadric(const QuadricStandardForm<T>& f) noexcept {
  const Mat3<T>& r = f.rotation;
  const Mat3<T> a = r * Mat3<T>::diagonal(f.diagonal) * transpose(r);
  const Vec3<T> re = r * f.linear;
  const Vec3<T> ap = a * f.center;
  return {a, re - T(2) * ap, dot(f.center, ap) - dot(re, f.center) + f.constant};
}

namespace detail {
/// x^T A x + b.x + c for A symmetric, re-centred at p: A, -2 A p, p^T A p + c.
template <class T>
[[nodiscard]] constexpr Quadric3<T> quadric_about(const Mat3<T>& a, const Vec3<T>& p,
                                                  T c) noexcept {
  const Vec3<T> ap = a * p;
  return {a, T(-2) * ap, dot(p, ap) + c};
}
}  // namespace detail

/// |X - C|^2 - r^2 in general form.
template <class T>
[[nodiscard]] constexpr Quadric3<T> to_quadric(const Sphere3<T>& s) noexcept {
  return detail::quadric_about(Mat3<T>::identity(), s.center, -s.radius * s.radius);
}

/// (X - C)^T M (X - C) - 1 in general form (M = implicit_matrix(e)).
template <class T>
[[nodiscard]] constexpr Quadric3<T> to_quadric(const Ellipsoid3<T>& e) noexcept {
  return detail::quadric_about(implicit_matrix(e), e.center, T(-1));
}

/// |X - C|^2 - dot(D, X - C)^2 - r^2 (the infinite cylinder) in general form.
template <class T>
[[nodiscard]] constexpr Quadric3<T> to_quadric(const Cylinder3<T>& c) noexcept {
  const Mat3<T> a = Mat3<T>::identity() - outer(c.axis.direction, c.axis.direction);
  return detail::quadric_about(a, c.axis.origin, -c.radius * c.radius);
}

/// cos^2(a) |X - V|^2 - dot(D, X - V)^2 (the infinite double cone) in general form.
template <class T>
[[nodiscard]] inline Quadric3<T> to_quadric(const Cone3<T>& c) noexcept {
  const Mat3<T> a = Mat3<T>::identity() * sqr(std::cos(c.angle)) - outer(c.axis, c.axis);
  return detail::quadric_about(a, c.vertex, T(0));
}

}  // namespace locus
