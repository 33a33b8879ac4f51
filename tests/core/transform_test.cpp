// SPDX-License-Identifier: BSL-1.0
// Tests for core/transform.hpp (rows core.xform, core.normals; figures 3.19-3.22, 4.9-4.25,
// 4.32-4.34). Oracles independent of the implementation: exact GMP rationals for the maps whose
// images are rational in the inputs (mirror, directional scaling, shear by a factor), geometric
// invariants (lengths, angles measured by atan2, fixed sets, determinants), and a second
// construction (rotation about an axis as basis change * rotation about z * basis change back).
#include <locus/core/transform.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
using locus_test::vec_near;

template <class T>
class TransformTest : public ::testing::Test {};
TYPED_TEST_SUITE(TransformTest, locus_test::RealTypes);

static_assert(std::is_aggregate_v<Affine3d> && std::is_trivially_copyable_v<Affine3f>);
static_assert(sizeof(Affine2f) == 6 * sizeof(float) && sizeof(Affine3d) == 12 * sizeof(double));
static_assert(apply_point(translation(Vec3d{1, 2, 3}), Vec3d{1, 1, 1}) == Vec3d{2, 3, 4});
static_assert(apply_vector(translation(Vec3d{1, 2, 3}), Vec3d{1, 1, 1}) == Vec3d{1, 1, 1});
static_assert(to_matrix(Affine2d::identity()) == Mat3d::identity());

namespace {

// ---- helpers --------------------------------------------------------------------------------

template <class T, int N>
T frobenius(const Mat<T, N, N>& m) {
  T s = 0;
  for (int r = 0; r < N; ++r)
    for (int c = 0; c < N; ++c) s += m.a[r][c] * m.a[r][c];
  return std::sqrt(s);
}

// |entries of a - identity| within lin_tol (linear part) and trans_tol (translation).
template <class T, int N>
::testing::AssertionResult is_identity(const Affine<T, N>& a, T lin_tol, T trans_tol) {
  for (int r = 0; r < N; ++r) {
    for (int c = 0; c < N; ++c) {
      const T want = r == c ? T(1) : T(0);
      if (!(std::abs(a.linear.a[r][c] - want) <= lin_tol))
        return ::testing::AssertionFailure()
               << "linear(" << r << "," << c << ") = " << a.linear.a[r][c] << ", tol " << lin_tol;
    }
    if (!(std::abs(a.translation[r]) <= trans_tol))
      return ::testing::AssertionFailure()
             << "translation[" << r << "] = " << a.translation[r] << ", tol " << trans_tol;
  }
  return ::testing::AssertionSuccess();
}

template <class T, int N>
::testing::AssertionResult affine_near(const Affine<T, N>& a, const Affine<T, N>& b, T lin_tol,
                                       T trans_tol) {
  for (int r = 0; r < N; ++r) {
    for (int c = 0; c < N; ++c)
      if (!(std::abs(a.linear.a[r][c] - b.linear.a[r][c]) <= lin_tol))
        return ::testing::AssertionFailure()
               << "linear(" << r << "," << c << "): " << a.linear.a[r][c] << " vs "
               << b.linear.a[r][c];
    if (!(std::abs(a.translation[r] - b.translation[r]) <= trans_tol))
      return ::testing::AssertionFailure()
             << "translation[" << r << "]: " << a.translation[r] << " vs " << b.translation[r];
  }
  return ::testing::AssertionSuccess();
}

template <class T, int N>
bool all_nan(const Affine<T, N>& a) {
  for (int r = 0; r < N; ++r) {
    for (int c = 0; c < N; ++c)
      if (!std::isnan(a.linear.a[r][c])) return false;
    if (!std::isnan(a.translation[r])) return false;
  }
  return true;
}

// M * M^{-1} = I for the generic inverse and for the closed-form inverse `closed`. Rounding: an
// inverse carries a forward error of about cond * eps relative to its size (cond = |L| |L^-1|,
// Frobenius), so each linear entry of the product is off by a few eps * cond and each
// translation entry by eps * cond times the sizes of the translations that are combined.
template <class T, int N>
void expect_inverts(const Affine<T, N>& a, const Affine<T, N>& closed) {
  const T cond = frobenius(a.linear) * frobenius(closed.linear);
  const T tsize = frobenius(a.linear) * length(closed.translation) +
                  frobenius(closed.linear) * length(a.translation) + T(1);
  const T lt = tol<T>(32, cond), tt = tol<T>(64, cond * tsize);
  EXPECT_TRUE(is_identity(compose(a, closed), lt, tt));
  EXPECT_TRUE(is_identity(compose(closed, a), lt, tt));
  const auto inv = inverse(a);
  ASSERT_TRUE(inv.has_value());
  EXPECT_TRUE(is_identity(compose(a, *inv), lt, tt));
  EXPECT_TRUE(is_identity(compose(*inv, a), lt, tt));
  // The homogeneous matrices invert too.
  const auto m = to_matrix(a) * to_matrix(closed);
  for (int r = 0; r <= N; ++r)
    for (int c = 0; c <= N; ++c) EXPECT_NEAR(m.a[r][c], r == c ? T(1) : T(0), c == N ? tt : lt);
}

template <int N>
using QVec = std::array<mpq_class, N>;

template <class T, int N>
QVec<N> q(const Vec<T, N>& v) {
  QVec<N> r;
  for (int i = 0; i < N; ++i) r[size_t(i)] = mpq_class(double(v[i]));
  return r;
}
template <int N>
mpq_class qdot(const QVec<N>& a, const QVec<N>& b) {
  mpq_class s = 0;
  for (size_t i = 0; i < size_t(N); ++i) s += a[i] * b[i];
  return s;
}
template <class T, int N>
::testing::AssertionResult near_exact(const Vec<T, N>& v, const std::type_identity_t<QVec<N>>& e,
                                      T abs_tol) {
  for (int i = 0; i < N; ++i) {
    const double d = e[size_t(i)].get_d();
    if (!(std::abs(double(v[i]) - d) <= double(abs_tol)))
      return ::testing::AssertionFailure()
             << "component " << i << ": " << v[i] << " vs exact " << d << ", tol " << abs_tol;
  }
  return ::testing::AssertionSuccess();
}

// A right-handed orthonormal basis (e0, e1, u) with u = axis/|axis|, built independently of the
// library: Gram-Schmidt against the coordinate axis least aligned with u.
template <class T>
Mat3<T> basis_with_last(const Vec3<T>& axis) {
  const Vec3<T> u = normalize(axis);
  Vec3<T> seed{1, 0, 0};
  if (std::abs(u.y) < std::abs(u.x) && std::abs(u.y) <= std::abs(u.z)) seed = {0, 1, 0};
  if (std::abs(u.z) < std::abs(u.x) && std::abs(u.z) < std::abs(u.y)) seed = {0, 0, 1};
  const Vec3<T> e0 = normalize(Vec3<T>(seed - u * dot(u, seed)));
  const Vec3<T> e1 = cross(u, e0);
  return Mat3<T>::from_cols(e0, e1, u);
}

template <class T>
T signed_angle(const Vec3<T>& v, const Vec3<T>& w, const Vec3<T>& axis) {
  return std::atan2(dot(cross(v, w), axis), dot(v, w));
}

// A random map mixing nonuniform scalings and shears along random directions and a rotation.
template <class T>
Affine3<T> random_deformation(Rng& rng) {
  Affine3<T> a = Affine3<T>::identity();
  for (int k = 0; k < 3; ++k) {
    const Vec3<T> c = rng.vec<T, 3>(-3, 3);
    a = scaling_along(c, rng.unit<T, 3>(), rng.uniform<T>(T(0.2), T(5))) * a;
    a = shear_by_factor(c, rng.unit<T, 3>(), rng.unit<T, 3>(), rng.uniform<T>(-2, 2)) * a;
  }
  return rotation(rng.vec<T, 3>(-3, 3), rng.unit<T, 3>(), rng.uniform<T>(-3, 3)) * a;
}

}  // namespace

// ---- conversion, composition, inverse -----------------------------------------------------

TYPED_TEST(TransformTest, HomogeneousMatrixRoundTripsAndActsLikeTheAffineMap) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 200; ++k) {
    Affine3<T> a{}, b{};
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) {
        a.linear.a[r][c] = T(rng.uniform_int(-9, 9));
        b.linear.a[r][c] = T(rng.uniform_int(-9, 9));
      }
      a.translation[r] = T(rng.uniform_int(-9, 9));
      b.translation[r] = T(rng.uniform_int(-9, 9));
    }
    const auto m = to_matrix(a);
    const auto back = to_affine(m);
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(back->linear, a.linear);
    EXPECT_EQ(back->translation, a.translation);
    // Small integers: every product below is exact, so equality is the right check.
    const Vec3<T> p{T(rng.uniform_int(-9, 9)), T(rng.uniform_int(-9, 9)),
                    T(rng.uniform_int(-9, 9))};
    const Vec4<T> hp = m * Vec4<T>{p.x, p.y, p.z, T(1)}, hv = m * Vec4<T>{p.x, p.y, p.z, T(0)};
    EXPECT_EQ((Vec3<T>{hp.x, hp.y, hp.z}), apply_point(a, p));
    EXPECT_EQ(hp.w, T(1));
    EXPECT_EQ((Vec3<T>{hv.x, hv.y, hv.z}), apply_vector(a, p));
    EXPECT_EQ(to_matrix(compose(a, b)), to_matrix(a) * to_matrix(b));
    EXPECT_EQ(apply_point(a * b, p), apply_point(a, apply_point(b, p)));
    // A homogeneous matrix scaled by w != 0 denotes the same map.
    const auto scaled = to_affine(Mat4<T>(m * T(4)));
    ASSERT_TRUE(scaled.has_value());
    EXPECT_EQ(scaled->linear, a.linear);
  }
  Mat4<T> projective = Mat4<T>::identity();
  projective.a[3][2] = T(1);
  EXPECT_FALSE(to_affine(projective).has_value());
  Mat3<T> zero_w = Mat3<T>::identity();
  zero_w.a[2][2] = T(0);
  EXPECT_FALSE(to_affine(zero_w).has_value());
  Mat3<T> nan_m = Mat3<T>::identity();
  nan_m.a[2][0] = std::numeric_limits<T>::quiet_NaN();
  EXPECT_FALSE(to_affine(nan_m).has_value());
}

TYPED_TEST(TransformTest, GenericInverseInvertsAndComposesInReverseOrder) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 500; ++k) {
    const Affine3<T> a = random_deformation<T>(rng), b = random_deformation<T>(rng);
    const auto ia = inverse(a), ib = inverse(b), iab = inverse(compose(a, b));
    ASSERT_TRUE(ia && ib && iab);
    const T cond = frobenius(a.linear) * frobenius(ia->linear);
    const T cond_ab =
        frobenius(a.linear) * frobenius(b.linear) * frobenius(ia->linear) * frobenius(ib->linear);
    EXPECT_TRUE(is_identity(compose(a, *ia), tol<T>(16, cond), tol<T>(64, cond * T(30))));
    // (ab)^-1 = b^-1 a^-1. Forward error of an inverse: cond * eps relative to its size.
    const Affine3<T> ab = compose(a, b);
    const T inv_size = frobenius(iab->linear);
    const T t_size = inv_size * length(ab.translation) + length(iab->translation) + T(1);
    EXPECT_TRUE(affine_near(*iab, compose(*ib, *ia), tol<T>(64, cond_ab * inv_size),
                            tol<T>(256, cond_ab * t_size)));
  }
  // Singular and non-finite linear parts are reported.
  EXPECT_FALSE(inverse(scaling(Vec3<T>{1, 2, 3}, T(0))).has_value());
  // Rounded singular maps too: I - u u^T with u = (1, 1, 0)/sqrt(2) has a rounding-level
  // determinant, not an exact 0.
  const auto flat = scaling_along(Vec3<T>{1, 2, 3}, Vec3<T>{1, 1, 0}, T(0));
  EXPECT_LE(std::abs(determinant(flat)), tol<T>(8));
  EXPECT_FALSE(inverse(flat).has_value());
  EXPECT_FALSE(inverse_transpose(flat).has_value());
  // The criterion is relative (1 / condition number), so uniformly tiny or huge maps invert; the
  // determinant of such a map would underflow or overflow, the scaled computation does not.
  const T tiny = std::numeric_limits<T>::min() * T(1024);
  const T huge = std::numeric_limits<T>::max() / T(8);
  for (const T s : {tiny, huge}) {
    const auto inv = inverse(scaling(Vec3<T>{}, s));
    ASSERT_TRUE(inv.has_value());
    EXPECT_EQ(apply_vector(*inv, Vec3<T>{s, -s, T(2) * s}), (Vec3<T>{T(1), T(-1), T(2)}));
  }
  // Scale ratios beyond 1 / (32 eps) are numerically singular.
  EXPECT_TRUE(inverse(scaling_axes(Vec3<T>{}, Vec3<T>{T(1), T(1), T(1) / T(16)})).has_value());
  EXPECT_FALSE(inverse(scaling_axes(Vec3<T>{}, Vec3<T>{T(1), T(1), T(8) * eps_v<T>})).has_value());
  EXPECT_TRUE(
      inverse(scaling_axes(Vec3<T>{}, Vec3<T>{T(1), T(1), T(8) * eps_v<T>}), T(0)).has_value());
  // A nearly dependent pair of rows below the threshold is reported; with tolerance 0 only an
  // exact zero determinant is.
  Affine2<T> nearly = Affine2<T>::identity();
  nearly.linear = Mat2<T>::from_rows(Vec2<T>{1, 1}, Vec2<T>{1, T(1) + T(4) * eps_v<T>});
  EXPECT_FALSE(inverse(nearly).has_value());
  EXPECT_TRUE(inverse(nearly, T(0)).has_value());
  EXPECT_FALSE(inverse(scaling_axes(Vec2<T>{1, 2}, Vec2<T>{3, 0})).has_value());
  Affine2<T> nan_t = Affine2<T>::identity();
  nan_t.translation.x = std::numeric_limits<T>::quiet_NaN();
  EXPECT_FALSE(inverse(nan_t).has_value());
  Affine2<T> inf_l = Affine2<T>::identity();
  inf_l.linear.a[0][1] = std::numeric_limits<T>::infinity();
  EXPECT_FALSE(inverse(inf_l).has_value());
}

// ---- translation ----------------------------------------------------------------------------

TYPED_TEST(TransformTest, TranslationMovesPointsNotVectorsFigure4_9) {
  using T = TypeParam;
  const auto a = translation(Vec2<T>{3, -1});
  EXPECT_EQ(apply_point(a, Vec2<T>{1, 1}), (Vec2<T>{4, 0}));
  EXPECT_EQ(apply_vector(a, Vec2<T>{1, 1}), (Vec2<T>{1, 1}));
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 200; ++k) {
    const auto t = rng.vec<T, 3>(-10, 10);
    const auto p = rng.vec<T, 3>(-10, 10), r = rng.vec<T, 3>(-10, 10);
    const auto m = translation(t);
    // Differences of points are unchanged (a translation is a rigid motion).
    EXPECT_TRUE(
        vec_near(Vec3<T>(apply_point(m, p) - apply_point(m, r)), Vec3<T>(p - r), tol<T>(4, T(40))));
    expect_inverts(m, translation(Vec3<T>(-t)));
    EXPECT_EQ(determinant(m), T(1));
  }
}

TYPED_TEST(TransformTest, TranslationAndScalingOfAFrameFigures4_10_4_14) {
  using T = TypeParam;
  // A frame (origin o, axes u, v) maps by its points and vectors: a translation moves the origin
  // and keeps the axes; a uniform scaling about a point scales the axes and the origin's offset.
  const Vec2<T> o{1, 2}, u{T(0.6), T(0.8)}, v{T(-0.8), T(0.6)};
  const auto t = translation(Vec2<T>{3, -1});
  EXPECT_EQ(apply_point(t, o), (Vec2<T>{4, 1}));
  EXPECT_EQ(apply_vector(t, u), u);
  EXPECT_EQ(apply_vector(t, v), v);
  const auto s = scaling(Vec2<T>{1, 1}, T(2));
  EXPECT_EQ(apply_point(s, o), (Vec2<T>{1, 3}));
  EXPECT_EQ(apply_vector(s, u), Vec2<T>(u * T(2)));
  // A point with local coordinates (a, b) keeps them in the transformed frame.
  const T a = T(1.5), b = T(-0.5);
  const Vec2<T> p = o + u * a + v * b;
  EXPECT_TRUE(vec_near(apply_point(s, p),
                       Vec2<T>(apply_point(s, o) + apply_vector(s, u) * a + apply_vector(s, v) * b),
                       tol<T>(8, T(4))));
}

// ---- rotations ------------------------------------------------------------------------------

TYPED_TEST(TransformTest, Rotation2DIsCounterClockwiseFigures3_21) {
  using T = TypeParam;
  const T half_pi = pi_v<T> / 2;
  EXPECT_TRUE(vec_near(apply_point(rotation_2d(half_pi), Vec2<T>{1, 0}), Vec2<T>{0, 1}, tol<T>(2)));
  // About a center: (2, 1) around (1, 1) by 90 degrees lands at (1, 2).
  EXPECT_TRUE(vec_near(apply_point(rotation(Vec2<T>{1, 1}, half_pi), Vec2<T>{2, 1}), Vec2<T>{1, 2},
                       tol<T>(4)));
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 500; ++k) {
    const auto c = rng.vec<T, 2>(-10, 10), p = rng.vec<T, 2>(-10, 10);
    const T angle = rng.uniform<T>(T(-3.1), T(3.1));
    const auto a = rotation(c, angle);
    EXPECT_TRUE(vec_near(apply_point(a, c), c, tol<T>(16, T(10))));  // fixes the center
    const Vec2<T> v = p - c, w = apply_point(a, p) - c;
    EXPECT_NEAR(length(w), length(v), tol<T>(16, T(30)));
    if (length(v) > T(0.5)) {  // the measured angle is well-conditioned away from the center
      EXPECT_NEAR(std::atan2(perp_dot(v, w), dot(v, w)), angle, tol<T>(64));
    }
    EXPECT_NEAR(determinant(a), T(1), tol<T>(4));
    expect_inverts(a, rotation(c, -angle));
  }
}

TYPED_TEST(TransformTest, RotationsAboutCoordinateAxesFigure4_11) {
  using T = TypeParam;
  const T h = pi_v<T> / 2, e = tol<T>(2);
  // Counter-clockwise seen from the positive axis: x -> y about z, y -> z about x, z -> x about y.
  EXPECT_TRUE(vec_near(apply_point(rotation_about_z(h), Vec3<T>{1, 0, 0}), Vec3<T>{0, 1, 0}, e));
  EXPECT_TRUE(vec_near(apply_point(rotation_about_x(h), Vec3<T>{0, 1, 0}), Vec3<T>{0, 0, 1}, e));
  EXPECT_TRUE(vec_near(apply_point(rotation_about_y(h), Vec3<T>{0, 0, 1}), Vec3<T>{1, 0, 0}, e));
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 300; ++k) {
    const T angle = rng.uniform<T>(-3, 3);
    const Affine3<T> simple[3] = {rotation_about_x(angle), rotation_about_y(angle),
                                  rotation_about_z(angle)};
    for (int i = 0; i < 3; ++i) {
      const auto axis = unit_vec<T, 3>(i);
      // Agrees with the general axis-angle construction about the same axis.
      EXPECT_TRUE(affine_near(simple[i], rotation(Vec3<T>{}, axis, angle), tol<T>(4), tol<T>(4)));
      EXPECT_EQ(apply_point(simple[i], axis), axis);  // exactly: the axis row/column is exact
      const auto v = unit_vec<T, 3>((i + 1) % 3);
      EXPECT_NEAR(signed_angle(v, apply_vector(simple[i], v), axis), angle, tol<T>(16));
      EXPECT_NEAR(determinant(simple[i]), T(1), tol<T>(4));
    }
  }
}

TYPED_TEST(TransformTest, RotationAboutArbitraryAxisThroughPointFigures4_12_4_13) {
  using T = TypeParam;
  // Figure cases computed by hand: about the vertical line through (1, 1, 0) by 90 degrees,
  // (2, 1, 5) -> (1, 2, 5); about (1, 1, 1) by 120 degrees the coordinate axes cycle x -> y -> z.
  const auto a = rotation(Vec3<T>{1, 1, 0}, Vec3<T>{0, 0, 7}, pi_v<T> / 2);
  EXPECT_TRUE(vec_near(apply_point(a, Vec3<T>{2, 1, 5}), Vec3<T>{1, 2, 5}, tol<T>(8)));
  const auto b = rotation(Vec3<T>{}, Vec3<T>{1, 1, 1}, T(2) * pi_v<T> / 3);
  EXPECT_TRUE(vec_near(apply_point(b, Vec3<T>{1, 0, 0}), Vec3<T>{0, 1, 0}, tol<T>(8)));
  EXPECT_TRUE(vec_near(apply_point(b, Vec3<T>{0, 0, 1}), Vec3<T>{1, 0, 0}, tol<T>(8)));

  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 500; ++k) {
    const auto q0 = rng.vec<T, 3>(-10, 10);
    const auto axis = rng.vec<T, 3>(-2, 2);
    if (length(axis) < T(0.1)) continue;
    const T angle = rng.uniform<T>(T(-3.1), T(3.1));
    const auto r = rotation(q0, axis, angle);
    const auto u = normalize(axis);
    // Fixes the axis points.
    for (T s : {T(-3), T(0), T(2.5)})
      EXPECT_TRUE(
          vec_near(apply_point(r, Vec3<T>(q0 + u * s)), Vec3<T>(q0 + u * s), tol<T>(32, T(20))));
    // Orthogonal linear part with det +1: preserves lengths and angles, no reflection.
    const auto rtr = transpose(r.linear) * r.linear;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(rtr.a[i][j], i == j ? T(1) : T(0), tol<T>(16));
    EXPECT_NEAR(determinant(r), T(1), tol<T>(16));
    // A vector perpendicular to the axis turns by exactly the angle, counter-clockwise about u.
    const auto v = normalize(cross(u, rng.unit<T, 3>()));
    if (length(v) > T(0.5)) {
      EXPECT_NEAR(signed_angle(v, apply_vector(r, v), u), angle, tol<T>(32));
    }
    // Second construction: move the axis to the z axis, rotate about z, move back.
    const Mat3<T> bas = basis_with_last(axis);
    const Affine3<T> to_axis{transpose(bas), Vec3<T>{}}, from_axis{bas, Vec3<T>{}};
    const auto second =
        translation(q0) * from_axis * rotation_about_z(angle) * to_axis * translation(Vec3<T>(-q0));
    EXPECT_TRUE(affine_near(r, second, tol<T>(16), tol<T>(64, T(20))));
    // The axis direction's sign and length: -axis reverses the sense, 3*axis does not.
    EXPECT_TRUE(
        affine_near(rotation(q0, Vec3<T>(axis * T(3)), angle), r, tol<T>(8), tol<T>(32, T(20))));
    EXPECT_TRUE(affine_near(rotation(q0, Vec3<T>(-axis), -angle), r, tol<T>(8), tol<T>(32, T(20))));
    expect_inverts(r, rotation(q0, axis, -angle));
    // Rotations about one axis compose by adding angles.
    const T angle2 = rng.uniform<T>(-1, 1);
    EXPECT_TRUE(affine_near(compose(rotation(q0, axis, angle2), r),
                            rotation(q0, axis, angle + angle2), tol<T>(32), tol<T>(64, T(20))));
  }
}

TYPED_TEST(TransformTest, DegenerateRotationAxesAndAngles) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  // A zero axis specifies no rotation: the identity (documented).
  const auto id = rotation(Vec3<T>{1, 2, 3}, Vec3<T>{}, T(1));
  EXPECT_EQ(id.linear, Mat3<T>::identity());
  EXPECT_EQ(id.translation, (Vec3<T>{}));
  // Non-finite axes give an all-NaN map, which has no inverse.
  EXPECT_TRUE(all_nan(rotation(Vec3<T>{}, Vec3<T>{nan, 0, 1}, T(1))));
  EXPECT_TRUE(all_nan(rotation(Vec3<T>{}, Vec3<T>{inf, 0, 0}, T(1))));
  EXPECT_FALSE(inverse(rotation(Vec3<T>{}, Vec3<T>{nan, 0, 1}, T(1))).has_value());
  // NaN/Inf angles propagate and are caught by inverse().
  EXPECT_FALSE(is_finite(rotation_2d(nan).linear));
  EXPECT_FALSE(is_finite(rotation(Vec3<T>{}, Vec3<T>{0, 0, 1}, inf).linear));
  EXPECT_FALSE(inverse(rotation_about_y(nan)).has_value());
  // A tiny (subnormal-scale) axis still has a direction.
  const T tiny = std::numeric_limits<T>::denorm_min() * T(8);
  const auto r = rotation(Vec3<T>{}, Vec3<T>{0, 0, tiny}, pi_v<T> / 2);
  EXPECT_TRUE(vec_near(apply_point(r, Vec3<T>{1, 0, 0}), Vec3<T>{0, 1, 0}, tol<T>(2)));
}

// ---- scaling --------------------------------------------------------------------------------

TYPED_TEST(TransformTest, UniformScalingAboutPointFigures3_19_4_15) {
  using T = TypeParam;
  // Figure 3.19: "scale by two" doubles every vector.
  EXPECT_EQ(apply_vector(scaling(Vec2<T>{}, T(2)), Vec2<T>{3, -1}), (Vec2<T>{6, -2}));
  EXPECT_EQ(apply_point(scaling(Vec2<T>{1, 1}, T(2)), Vec2<T>{2, 3}), (Vec2<T>{3, 5}));
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 300; ++k) {
    const auto c = rng.vec<T, 3>(-10, 10), p = rng.vec<T, 3>(-10, 10), r = rng.vec<T, 3>(-10, 10);
    T s = rng.uniform<T>(T(0.1), T(4));
    if (k % 2) s = -s;
    const auto a = scaling(c, s);
    EXPECT_TRUE(vec_near(apply_point(a, c), c, tol<T>(16, T(10) * std::abs(s))));
    EXPECT_NEAR(length(Vec3<T>(apply_point(a, p) - apply_point(a, r))),
                std::abs(s) * length(Vec3<T>(p - r)), tol<T>(32, T(40) * std::abs(s)));
    EXPECT_NEAR(determinant(a), s * s * s, tol<T>(8, std::abs(s * s * s)));
    expect_inverts(a, scaling(c, T(1) / s));
  }
}

TYPED_TEST(TransformTest, NonuniformScalingAlongDirectionFigures3_20_4_16) {
  using T = TypeParam;
  // Figure 3.20: nonuniform scale along the coordinate axes.
  EXPECT_EQ(apply_vector(scaling_axes(Vec2<T>{}, Vec2<T>{2, T(0.5)}), Vec2<T>{1, 4}),
            (Vec2<T>{2, 2}));
  EXPECT_EQ(apply_point(scaling_axes(Vec3<T>{1, 1, 1}, Vec3<T>{2, 3, 4}), Vec3<T>{2, 2, 2}),
            (Vec3<T>{3, 4, 5}));
  // Along the diagonal of the plane: (1, 1) doubles, (1, -1) is unchanged.
  const auto d = scaling_along(Vec2<T>{}, Vec2<T>{1, 1}, T(2));
  EXPECT_TRUE(vec_near(apply_vector(d, Vec2<T>{1, 1}), Vec2<T>{2, 2}, tol<T>(4)));
  EXPECT_TRUE(vec_near(apply_vector(d, Vec2<T>{1, -1}), Vec2<T>{1, -1}, tol<T>(4)));

  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 400; ++k) {
    const auto c = rng.vec<T, 3>(-10, 10), p = rng.vec<T, 3>(-10, 10);
    const auto dir = rng.vec<T, 3>(-2, 2);
    if (length(dir) < T(0.1)) continue;
    const T s = rng.uniform<T>(T(-3), T(3));
    const auto a = scaling_along(c, dir, s);
    // Exact oracle: p' = p + (s - 1) ((p - c) . d / (d . d)) d in rationals.
    const auto qc = q(c), qp = q(p), qd = q(dir);
    QVec<3> qpc, want;
    for (size_t i = 0; i < 3; ++i) qpc[i] = qp[i] - qc[i];
    const mpq_class f = (mpq_class(double(s)) - 1) * qdot<3>(qpc, qd) / qdot<3>(qd, qd);
    for (size_t i = 0; i < 3; ++i) want[i] = qp[i] + f * qd[i];
    EXPECT_TRUE(
        near_exact(apply_point(a, p), want, tol<T>(32, T(40) * std::max(T(1), std::abs(s)))));
    EXPECT_NEAR(determinant(a), s, tol<T>(16, T(4)));
    if (std::abs(s) > T(0.1)) expect_inverts(a, scaling_along(c, dir, T(1) / s));
  }
  // Zero direction: identity; non-finite direction: NaN; zero factor: singular.
  const auto id = scaling_along(Vec3<T>{1, 2, 3}, Vec3<T>{}, T(5));
  EXPECT_EQ(id.linear, Mat3<T>::identity());
  EXPECT_EQ(id.translation, (Vec3<T>{}));
  EXPECT_TRUE(
      all_nan(scaling_along(Vec2<T>{}, Vec2<T>{std::numeric_limits<T>::quiet_NaN(), 1}, T(2))));
  EXPECT_FALSE(inverse(scaling_along(Vec3<T>{1, 2, 3}, Vec3<T>{1, 1, 0}, T(0))).has_value());
}

TYPED_TEST(TransformTest, ScalingAlongArbitraryDirectionSets) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 400; ++k) {
    const auto c = rng.vec<T, 3>(-10, 10);
    Mat3<T> dirs{};
    if (k % 2 == 0) {
      // An orthonormal frame that is not axis-aligned: the columns of a random rotation.
      dirs = rotation(Vec3<T>{}, rng.unit<T, 3>(), rng.uniform<T>(-3, 3)).linear;
    } else {
      for (int r = 0; r < 3; ++r)
        for (int col = 0; col < 3; ++col) dirs.a[r][col] = rng.uniform<T>(-1, 1);
      if (std::abs(determinant(dirs)) < T(0.1)) continue;  // keep the eigenbasis well-conditioned
    }
    const Vec3<T> f{rng.uniform<T>(T(0.2), 3), rng.uniform<T>(-3, T(-0.2)),
                    rng.uniform<T>(T(0.2), 3)};
    const auto a = scaling_along(c, dirs, f);
    ASSERT_TRUE(a.has_value());
    const auto dinv = inverse(dirs);
    ASSERT_TRUE(dinv.has_value());
    const T cond = frobenius(dirs) * frobenius(*dinv);
    // Each direction is an eigenvector with its factor; the center is fixed.
    for (int i = 0; i < 3; ++i) {
      const auto di = col(dirs, i);
      EXPECT_TRUE(vec_near(apply_vector(*a, di), Vec3<T>(di * f[i]), tol<T>(32, T(3) * cond)));
    }
    EXPECT_TRUE(vec_near(apply_point(*a, c), c, tol<T>(64, T(30) * cond)));
    EXPECT_NEAR(determinant(*a), f.x * f.y * f.z, tol<T>(64, T(27) * cond));
    const auto closed = scaling_along(c, dirs, Vec3<T>{T(1) / f.x, T(1) / f.y, T(1) / f.z});
    ASSERT_TRUE(closed.has_value());
    expect_inverts(*a, *closed);
  }
  // Dependent directions have no eigenbasis: std::nullopt.
  const auto dep = Mat3<T>::from_cols(Vec3<T>{1, 0, 0}, Vec3<T>{2, 0, 0}, Vec3<T>{0, 0, 1});
  EXPECT_FALSE(scaling_along(Vec3<T>{}, dep, Vec3<T>{1, 2, 3}).has_value());
  // 2D: an orthonormal pair rotated by 30 degrees.
  const T cs = std::cos(pi_v<T> / 6), sn = std::sin(pi_v<T> / 6);
  const auto d2 = Mat2<T>::from_cols(Vec2<T>{cs, sn}, Vec2<T>{-sn, cs});
  const auto a2 = scaling_along(Vec2<T>{1, 1}, d2, Vec2<T>{3, T(0.5)});
  ASSERT_TRUE(a2.has_value());
  EXPECT_TRUE(vec_near(apply_vector(*a2, Vec2<T>{cs, sn}), Vec2<T>{3 * cs, 3 * sn}, tol<T>(16)));
  EXPECT_TRUE(vec_near(apply_point(*a2, Vec2<T>{1, 1}), Vec2<T>{1, 1}, tol<T>(16)));
}

// ---- reflections ----------------------------------------------------------------------------

TYPED_TEST(TransformTest, ReflectionInLineAndPlaneFigures4_17_to_4_22) {
  using T = TypeParam;
  // Figure 4.18: simple reflection in the x axis of the plane.
  EXPECT_EQ(apply_point(reflection(Vec2<T>{}, Vec2<T>{0, 1}), Vec2<T>{3, 2}), (Vec2<T>{3, -2}));
  // Figure 4.21: mirror in the line y = x + 1 (through (0, 1), normal (1, -1)): (2, 0) -> (-1, 3).
  EXPECT_TRUE(vec_near(apply_point(reflection(Vec2<T>{0, 1}, Vec2<T>{1, -1}), Vec2<T>{2, 0}),
                       Vec2<T>{-1, 3}, tol<T>(8)));
  // Figure 4.22: mirror in the plane z = 2.
  EXPECT_TRUE(
      vec_near(apply_point(reflection(Vec3<T>{5, 5, 2}, Vec3<T>{0, 0, 3}), Vec3<T>{1, 2, 3}),
               Vec3<T>{1, 2, 1}, tol<T>(8, T(5))));

  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 500; ++k) {
    const auto q0 = rng.vec<T, 3>(-10, 10), p = rng.vec<T, 3>(-10, 10);
    const auto nrm = rng.vec<T, 3>(-2, 2);
    if (length(nrm) < T(0.1)) continue;
    const auto m = reflection(q0, nrm);
    // Exact oracle: p' = p - 2 ((p - q) . n / (n . n)) n.
    const auto qq = q(q0), qp = q(p), qn = q(nrm);
    QVec<3> qpq, want;
    for (size_t i = 0; i < 3; ++i) qpq[i] = qp[i] - qq[i];
    const mpq_class f = 2 * qdot<3>(qpq, qn) / qdot<3>(qn, qn);
    for (size_t i = 0; i < 3; ++i) want[i] = qp[i] - f * qn[i];
    EXPECT_TRUE(near_exact(apply_point(m, p), want, tol<T>(32, T(40))));
    // Fixes the plane, negates the normal, det -1, an involution.
    const auto n = normalize(nrm);
    const auto in_plane = q0 + normalize(cross(n, rng.unit<T, 3>())) * T(3);
    EXPECT_TRUE(vec_near(apply_point(m, in_plane), in_plane, tol<T>(32, T(15))));
    EXPECT_TRUE(vec_near(apply_vector(m, n), Vec3<T>(-n), tol<T>(8)));
    EXPECT_NEAR(determinant(m), T(-1), tol<T>(16));
    expect_inverts(m, m);
    // 2D mirror in a line through a point.
    const auto q2 = rng.vec<T, 2>(-10, 10), n2 = rng.unit<T, 2>();
    const auto m2 = reflection(q2, n2);
    EXPECT_TRUE(vec_near(apply_point(m2, Vec2<T>(q2 + perp(n2) * T(2))),
                         Vec2<T>(q2 + perp(n2) * T(2)), tol<T>(32, T(12))));
    EXPECT_TRUE(vec_near(apply_vector(m2, n2), Vec2<T>(-n2), tol<T>(8)));
    EXPECT_NEAR(determinant(m2), T(-1), tol<T>(8));
    expect_inverts(m2, m2);
  }
  // Zero normal: identity (documented); non-finite normal: all-NaN map.
  const auto id = reflection(Vec3<T>{1, 2, 3}, Vec3<T>{});
  EXPECT_EQ(id.linear, Mat3<T>::identity());
  EXPECT_EQ(id.translation, (Vec3<T>{}));
  EXPECT_TRUE(all_nan(reflection(Vec2<T>{}, Vec2<T>{0, std::numeric_limits<T>::infinity()})));
}

TYPED_TEST(TransformTest, ReflectionAboutLineAndThroughPointFigure4_19_4_20) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 300; ++k) {
    // 2D: reflection about a line is the mirror whose normal is perpendicular to the line.
    const auto q2 = rng.vec<T, 2>(-10, 10), d2 = rng.vec<T, 2>(-2, 2);
    if (length(d2) < T(0.1)) continue;
    EXPECT_TRUE(affine_near(reflection_about_line(q2, d2), reflection(q2, perp(d2)), tol<T>(8),
                            tol<T>(32, T(10))));
    // 3D: the half-turn about the line: rotation by pi, det +1, fixes the line.
    const auto q3 = rng.vec<T, 3>(-10, 10), d3 = rng.vec<T, 3>(-2, 2);
    if (length(d3) < T(0.1)) continue;
    const auto h = reflection_about_line(q3, d3);
    EXPECT_TRUE(affine_near(h, rotation(q3, d3, pi_v<T>), tol<T>(8), tol<T>(32, T(10))));
    EXPECT_NEAR(determinant(h), T(1), tol<T>(8));
    const auto on_line = q3 + d3 * T(1.5);
    EXPECT_TRUE(vec_near(apply_point(h, on_line), on_line, tol<T>(32, T(15))));
    // The foot of every point is the midpoint of the point and its image.
    const auto p = rng.vec<T, 3>(-10, 10);
    const auto u = normalize(d3);
    const auto foot = q3 + u * dot(u, Vec3<T>(p - q3));
    EXPECT_TRUE(vec_near(Vec3<T>((apply_point(h, p) + p) * T(0.5)), foot, tol<T>(32, T(20))));
    expect_inverts(h, h);
    // Point reflection: the center is the midpoint of every point and its image.
    const auto pr = reflection_through_point(q3);
    EXPECT_TRUE(vec_near(Vec3<T>((apply_point(pr, p) + p) * T(0.5)), q3, tol<T>(8, T(10))));
    EXPECT_EQ(determinant(pr), T(-1));
    expect_inverts(pr, pr);
  }
  const auto id = reflection_about_line(Vec3<T>{1, 2, 3}, Vec3<T>{});
  EXPECT_EQ(id.linear, Mat3<T>::identity());
  EXPECT_TRUE(all_nan(
      reflection_about_line(Vec3<T>{}, Vec3<T>{std::numeric_limits<T>::quiet_NaN(), 0, 0})));
}

// ---- shear ----------------------------------------------------------------------------------

TYPED_TEST(TransformTest, ShearFigures3_22_4_23_4_24) {
  using T = TypeParam;
  const T angle = pi_v<T> / 6, k = std::tan(angle);
  // Figures 3.22, 4.23: the 2D shear fixing the x axis, (x, y) -> (x + tan(a) y, y).
  const auto s2 = shear(Vec2<T>{}, Vec2<T>{1, 0}, angle);
  EXPECT_TRUE(vec_near(apply_point(s2, Vec2<T>{1, 2}), Vec2<T>{1 + 2 * k, 2}, tol<T>(8)));
  EXPECT_TRUE(vec_near(apply_point(s2, Vec2<T>{5, 0}), Vec2<T>{5, 0}, tol<T>(8)));
  // Figure 4.24: a shear of 3D space fixing the xy plane along x: (x, y, z) -> (x + tan(a) z, y,
  // z).
  const auto s3 = shear(Vec3<T>{}, Vec3<T>{0, 0, 1}, Vec3<T>{1, 0, 0}, angle);
  EXPECT_TRUE(vec_near(apply_point(s3, Vec3<T>{1, 2, 3}), Vec3<T>{1 + 3 * k, 2, 3}, tol<T>(8)));
  // The direction is projected into the plane: (1, 0, 5) acts like (1, 0, 0).
  EXPECT_TRUE(affine_near(shear(Vec3<T>{}, Vec3<T>{0, 0, 1}, Vec3<T>{1, 0, 5}, angle), s3,
                          tol<T>(4), tol<T>(4)));
}

TYPED_TEST(TransformTest, GeneralShearSpecificationFigure4_25) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int kk = 0; kk < 500; ++kk) {
    const auto q0 = rng.vec<T, 3>(-10, 10), p = rng.vec<T, 3>(-10, 10);
    const auto n = rng.unit<T, 3>();
    const auto w = normalize(cross(n, rng.unit<T, 3>()));  // a direction in the plane
    if (length(w) < T(0.5)) continue;
    const T angle = rng.uniform<T>(T(-1.2), T(1.2));
    const auto s = shear(q0, n, w, angle);
    // det 1: volumes are preserved.
    EXPECT_NEAR(determinant(s), T(1), tol<T>(64, T(1) + sqr(std::tan(angle))));
    // Fixes the shear plane.
    const auto in_plane = q0 + normalize(cross(n, rng.unit<T, 3>())) * T(4);
    EXPECT_TRUE(vec_near(apply_point(s, in_plane), in_plane, tol<T>(64, T(20))));
    // Moves every point along w by tan(angle) times its signed distance to the plane.
    const Vec3<T> disp = apply_point(s, p) - p;
    const T dist = dot(n, Vec3<T>(p - q0));
    EXPECT_TRUE(vec_near(disp, Vec3<T>(w * (std::tan(angle) * dist)),
                         tol<T>(64, T(30) * (T(1) + std::abs(std::tan(angle))))));
    // The image of the normal line through q0 makes the angle `angle` with n, towards +w.
    const Vec3<T> img = apply_vector(s, n);
    EXPECT_NEAR(std::atan2(dot(img, w), dot(img, n)), angle, tol<T>(32));
    expect_inverts(s, shear(q0, n, w, -angle));
    // A non-orthogonal direction acts through its component in the plane.
    const auto tilted = shear(q0, Vec3<T>(n * T(3)), Vec3<T>(w * T(2) + n * T(5)), angle);
    EXPECT_TRUE(affine_near(tilted, s, tol<T>(32), tol<T>(64, T(20))));
    // Exact oracle with unnormalised inputs that are orthogonal by construction: normal along a
    // coordinate axis, direction in the coordinate plane.
    const int ax = kk % 3;
    const auto nax = unit_vec<T, 3>(ax) * T(2);
    Vec3<T> dir = rng.vec<T, 3>(-2, 2);
    dir[ax] = T(0);
    if (length(dir) < T(0.1)) continue;
    const T fac = rng.uniform<T>(-2, 2);
    const auto sf = shear_by_factor(q0, nax, dir, fac);
    // p' = p + fac ((p - q)_ax) dir / |dir|, |dir| irrational: compare in double.
    const double dl =
        std::sqrt(double(dir.x) * dir.x + double(dir.y) * dir.y + double(dir.z) * dir.z);
    const double dd = double(fac) * (double(p[ax]) - double(q0[ax])) / dl;
    const Vec3<double> want{p.x + dd * dir.x, p.y + dd * dir.y, p.z + dd * dir.z};
    EXPECT_TRUE(vec_near(vec_cast<double>(apply_point(sf, p)), want, double(tol<T>(64, T(60)))));
  }
  // Degenerate: zero normal, direction parallel to the normal -> identity; NaN -> NaN map.
  const auto id1 = shear(Vec3<T>{1, 2, 3}, Vec3<T>{}, Vec3<T>{1, 0, 0}, T(0.5));
  const auto id2 = shear(Vec3<T>{1, 2, 3}, Vec3<T>{0, 0, 2}, Vec3<T>{0, 0, 1}, T(0.5));
  const auto id3 = shear(Vec2<T>{1, 2}, Vec2<T>{}, T(0.5));
  EXPECT_EQ(id1.linear, Mat3<T>::identity());
  EXPECT_EQ(id2.linear, Mat3<T>::identity());
  EXPECT_EQ(id3.linear, Mat2<T>::identity());
  EXPECT_TRUE(all_nan(shear(Vec3<T>{}, Vec3<T>{0, 0, 1},
                            Vec3<T>{std::numeric_limits<T>::quiet_NaN(), 0, 0}, T(0.5))));
  EXPECT_FALSE(
      inverse(shear(Vec2<T>{}, Vec2<T>{1, 0}, std::numeric_limits<T>::quiet_NaN())).has_value());
}

// ---- normals --------------------------------------------------------------------------------

TYPED_TEST(TransformTest, NormalOfPlaneUnderNonuniformScaleFigures4_32_4_33) {
  using T = TypeParam;
  // The plane x + y = k has normal (1, 1, 0) and tangents (1, -1, 0), (0, 0, 1). Scaling x by 2
  // maps it to x/2 + y = k, whose normal is (1, 2, 0); transforming the normal like a vector
  // gives (2, 1, 0), which is not perpendicular to the scaled plane (figure 4.33).
  const auto a = scaling_axes(Vec3<T>{}, Vec3<T>{2, 1, 1});
  const Vec3<T> n{1, 1, 0}, t0{1, -1, 0}, t1{0, 0, 1};
  const auto wrong = apply_vector(a, n);
  EXPECT_NE(dot(wrong, apply_vector(a, t0)), T(0));
  const auto right = apply_normal(a, n);
  EXPECT_EQ(cross(right, Vec3<T>{1, 2, 0}), (Vec3<T>{}));
  EXPECT_GT(dot(right, Vec3<T>{1, 2, 0}), T(0));
  EXPECT_EQ(dot(right, apply_vector(a, t0)), T(0));
  EXPECT_EQ(dot(right, apply_vector(a, t1)), T(0));
  // Points of the transformed plane satisfy right . x = const.
  const T k = 3;
  const Vec3<T> p0{k, 0, 0}, p1{0, k, 5};
  EXPECT_EQ(dot(right, apply_point(a, p0)), dot(right, apply_point(a, p1)));
  // Figure 4.34: the normal from the transformed tangents points the same way here (det > 0).
  EXPECT_EQ(cross(normal_from_tangents(a, t0, t1), right), (Vec3<T>{}));
  EXPECT_EQ(normal_from_tangents(t0, t1), cross(t0, t1));
}

TYPED_TEST(TransformTest, NormalsStayPerpendicularUnderRandomScalingsAndShears) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 500; ++k) {
    auto a = random_deformation<T>(rng);
    if (k % 3 == 0) a = reflection(rng.vec<T, 3>(-3, 3), rng.unit<T, 3>()) * a;
    const auto t0 = rng.vec<T, 3>(-1, 1), t1 = rng.vec<T, 3>(-1, 1);
    const auto n = cross(t0, t1);
    const auto nn = apply_normal(a, n);
    const auto lt0 = apply_vector(a, t0), lt1 = apply_vector(a, t1);
    const auto nm = normal_matrix(a);
    // Rounding of cof(L) n and of L t: relative to the product of the magnitudes involved.
    const T scale0 = frobenius(nm) * length(n) * frobenius(a.linear) * length(t0);
    const T scale1 = frobenius(nm) * length(n) * frobenius(a.linear) * length(t1);
    EXPECT_NEAR(dot(nn, lt0), T(0), tol<T>(32, scale0));
    EXPECT_NEAR(dot(nn, lt1), T(0), tol<T>(32, scale1));
    // Same direction as the book's inverse transpose: |det| L^{-T} n.
    const auto it = inverse_transpose(a);
    ASSERT_TRUE(it.has_value());
    const T det = determinant(a);
    const Vec3<T> book = *it * n * std::abs(det);
    // The inverse carries a forward error of cond * eps relative to its size.
    const T cond = frobenius(a.linear) * frobenius(*it);
    EXPECT_TRUE(vec_near(nn, book, tol<T>(64, cond * frobenius(nm) * length(n))));
    // The tangent-based normal is the cofactor image: equal for det > 0, opposite for det < 0.
    const auto from_t = normal_from_tangents(a, t0, t1);
    EXPECT_TRUE(vec_near(from_t, Vec3<T>(det < 0 ? -nn : nn),
                         tol<T>(64, frobenius(a.linear) * frobenius(a.linear) * T(4))));
    // 2D: the normal of a curve stays perpendicular to the transformed tangent.
    const Affine2<T> b =
        shear_by_factor(rng.vec<T, 2>(-3, 3), rng.unit<T, 2>(), rng.unit<T, 2>(),
                        rng.uniform<T>(-2, 2)) *
        scaling_along(rng.vec<T, 2>(-3, 3), rng.unit<T, 2>(), rng.uniform<T>(T(0.2), 5));
    const auto t2 = rng.vec<T, 2>(-1, 1);
    const auto n2 = apply_normal(b, normal_from_tangent(t2));
    EXPECT_NEAR(dot(n2, apply_vector(b, t2)), T(0),
                tol<T>(32, frobenius(b.linear) * frobenius(b.linear) * T(2)));
    EXPECT_TRUE(vec_near(normal_from_tangent(b, t2), n2,
                         tol<T>(32, frobenius(b.linear) * T(2))));  // det > 0 here
  }
}

TYPED_TEST(TransformTest, NormalsUnderSingularAndReflectingMaps) {
  using T = TypeParam;
  // Flattening onto the xy plane (singular): the plane z = 0 keeps its normal, a plane x = c
  // collapses to a line and its normal becomes zero; the inverse transpose does not exist.
  const auto flat = scaling_axes(Vec3<T>{}, Vec3<T>{1, 1, 0});
  EXPECT_FALSE(inverse_transpose(flat).has_value());
  EXPECT_EQ(apply_normal(flat, Vec3<T>{0, 0, 1}), (Vec3<T>{0, 0, 1}));
  EXPECT_EQ(apply_normal(flat, Vec3<T>{1, 0, 0}), (Vec3<T>{}));
  // A tilted plane under the flattening: its normal is still perpendicular to the images of its
  // tangents (which span the xy plane), exactly, by the cofactor identity cof(L)^T L = det L I.
  const Vec3<T> t0{1, 0, 1}, t1{0, 1, 2};
  const auto nn = apply_normal(flat, cross(t0, t1));
  EXPECT_EQ(dot(nn, apply_vector(flat, t0)), T(0));
  EXPECT_EQ(dot(nn, apply_vector(flat, t1)), T(0));
  EXPECT_NE(nn, (Vec3<T>{}));
  // A mirror keeps an outward normal outward; the tangent-based normal flips with orientation.
  const auto m = reflection(Vec3<T>{}, Vec3<T>{0, 0, 1});
  EXPECT_EQ(apply_normal(m, Vec3<T>{0, 0, 1}), (Vec3<T>{0, 0, -1}));  // top of a sphere -> bottom
  EXPECT_EQ(normal_from_tangents(m, Vec3<T>{1, 0, 0}, Vec3<T>{0, 1, 0}), (Vec3<T>{0, 0, 1}));
  // Cofactor matrix identity on a random matrix: cof(M)^T M = det(M) I.
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 100; ++k) {
    Mat3<T> x{};
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) x.a[r][c] = T(rng.uniform_int(-5, 5));
    const auto p = transpose(cofactor_matrix(x)) * x;
    EXPECT_EQ(p, Mat3<T>::identity() * determinant(x));  // small integers: exact
  }
}

// ---- compositions ---------------------------------------------------------------------------

TYPED_TEST(TransformTest, CompositionsOfFactories) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 300; ++k) {
    const auto c = rng.vec<T, 3>(-10, 10);
    const T s1 = rng.uniform<T>(T(0.2), 3), s2 = rng.uniform<T>(T(0.2), 3);
    // Scalings about one center multiply their factors.
    EXPECT_TRUE(affine_near(scaling(c, s1) * scaling(c, s2), scaling(c, s1 * s2), tol<T>(8, T(9)),
                            tol<T>(32, T(90))));
    // Two mirrors in parallel planes compose to a translation by twice their distance.
    const auto n = rng.unit<T, 3>();
    const T d = rng.uniform<T>(-3, 3);
    const auto two = reflection(Vec3<T>(c + n * d), n) * reflection(c, n);
    EXPECT_TRUE(
        affine_near(two, translation(Vec3<T>(n * (T(2) * d))), tol<T>(16), tol<T>(64, T(15))));
    // Two mirrors in planes through a common line compose to a rotation about it by twice the
    // angle between them.
    const auto axis = rng.unit<T, 3>();
    const auto n1 = normalize(cross(axis, rng.unit<T, 3>()));
    if (length(n1) < T(0.5)) continue;
    const T half = rng.uniform<T>(-1, 1);
    const auto n2 = apply_vector(rotation(Vec3<T>{}, axis, half), n1);
    EXPECT_TRUE(affine_near(reflection(c, n2) * reflection(c, n1), rotation(c, axis, T(2) * half),
                            tol<T>(32), tol<T>(128, T(10))));
    // Conjugation: rotation about a translated axis.
    const auto t = rng.vec<T, 3>(-5, 5);
    const T ang = rng.uniform<T>(-3, 3);
    EXPECT_TRUE(affine_near(translation(t) * rotation(c, axis, ang) * translation(Vec3<T>(-t)),
                            rotation(Vec3<T>(c + t), axis, ang), tol<T>(8), tol<T>(64, T(20))));
  }
}
