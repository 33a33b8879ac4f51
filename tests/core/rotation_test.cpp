// SPDX-License-Identifier: BSL-1.0
// Tests for core/rotation.hpp (row core.rotation: matrix / axis-angle / quaternion / Euler
// conversions, gimbal lock, nearest rotation (figure A.1), interpolation).
#include <locus/core/rotation.hpp>

#include "support/typed.hpp"

#include <cmath>
#include <limits>
#include <vector>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;

template <class T>
class RotationTest : public ::testing::Test {};
TYPED_TEST_SUITE(RotationTest, locus_test::RealTypes);

static_assert(std::is_aggregate_v<AxisAngle<double>> && std::is_aggregate_v<EulerAngles<float>>);

namespace {

using L = long double;

constexpr EulerOrder kOrders[] = {EulerOrder::xyz, EulerOrder::xzy, EulerOrder::yxz,
                                  EulerOrder::yzx, EulerOrder::zxy, EulerOrder::zyx};
const char* order_name(EulerOrder o) {
  switch (o) {
    case EulerOrder::xyz:
      return "xyz";
    case EulerOrder::xzy:
      return "xzy";
    case EulerOrder::yxz:
      return "yxz";
    case EulerOrder::yzx:
      return "yzx";
    case EulerOrder::zxy:
      return "zxy";
    case EulerOrder::zyx:
      return "zyx";
  }
  return "?";
}

// Independent oracles in long double, written from the textbook matrices.
Mat3<L> rx(L t) {
  return {{{1, 0, 0}, {0, std::cos(t), -std::sin(t)}, {0, std::sin(t), std::cos(t)}}};
}
Mat3<L> ry(L t) {
  return {{{std::cos(t), 0, std::sin(t)}, {0, 1, 0}, {-std::sin(t), 0, std::cos(t)}}};
}
Mat3<L> rz(L t) {
  return {{{std::cos(t), -std::sin(t), 0}, {std::sin(t), std::cos(t), 0}, {0, 0, 1}}};
}
Mat3<L> axis_mat(char c, L t) { return c == 'x' ? rx(t) : (c == 'y' ? ry(t) : rz(t)); }

template <class T>
Mat3<L> euler_oracle(EulerOrder o, const Vec3<T>& a) {
  const char* n = order_name(o);
  return axis_mat(n[0], L(a[0])) * axis_mat(n[1], L(a[1])) * axis_mat(n[2], L(a[2]));
}

// Rodrigues: R = cos t I + sin t [u]x + (1 - cos t) u u^T.
template <class T>
Mat3<L> rodrigues(const Vec3<T>& u0, T t) {
  const Vec3<L> u = normalize(vec_cast<L>(u0));
  const L c = std::cos(L(t)), s = std::sin(L(t));
  return Mat3<L>::identity() * c + skew(u) * s + outer(u, u) * (L(1) - c);
}

template <class T, class U>
L max_diff(const Mat3<T>& a, const Mat3<U>& b) {
  L m = 0;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m = std::fmax(m, std::fabs(L(a.a[r][c]) - L(b.a[r][c])));
  return m;
}

template <class T>
L orthonormality_error(const Mat3<T>& m) {
  Mat3<L> ml{};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) ml.a[r][c] = m.a[r][c];
  return max_diff(transpose(ml) * ml, Mat3<L>::identity());
}

// Quaternions q and -q are the same rotation.
template <class T>
L quat_diff_mod_sign(const Quat<T>& a, const Quat<T>& b) {
  L dp = 0, dm = 0;
  const T av[4] = {a.w, a.x, a.y, a.z}, bv[4] = {b.w, b.x, b.y, b.z};
  for (int i = 0; i < 4; ++i) {
    dp = std::fmax(dp, std::fabs(L(av[i]) - L(bv[i])));
    dm = std::fmax(dm, std::fabs(L(av[i]) + L(bv[i])));
  }
  return std::fmin(dp, dm);
}

template <class T>
Quat<T> random_unit(Rng& rng) {
  const Vec4<T> v = rng.unit<T, 4>();
  return {v.x, v.y, v.z, v.w};
}

// Quaternion from axis-angle straight from the definition (independent of to_quat).
template <class T>
Quat<T> quat_def(const Vec3<T>& u, T t) {
  const T s = std::sin(t / T(2));
  return {std::cos(t / T(2)), s * u.x, s * u.y, s * u.z};
}

// Checks all conversions of one rotation q (unit) against each other and the oracles.
template <class T>
void check_all_representations(const Quat<T>& q) {
  // Axis-angle of q straight from the definition, in long double.
  const L vl = std::sqrt(L(q.x) * q.x + L(q.y) * q.y + L(q.z) * q.z);
  const L ang = L(2) * std::atan2(vl, std::fabs(L(q.w)));
  const Mat3<T> m = to_matrix(q);
  if (vl > 0) {
    const Vec3<T> u{T(q.x / vl), T(q.y / vl), T(q.z / vl)};
    EXPECT_LE(max_diff(m, rodrigues(u, T(q.w < 0 ? -ang : ang))), tol<T>(16));
  }
  EXPECT_LE(orthonormality_error(m), tol<T>(16));
  // Rotating a vector by the quaternion and by its matrix agree.
  const Vec3<T> v{T(1), T(-2), T(0.5)};
  EXPECT_TRUE(locus_test::vec_near(rotate(q, v), m * v, tol<T>(32)));
  // matrix -> quaternion -> matrix, quaternion -> matrix -> quaternion.
  const Quat<T> q2 = to_quat(m);
  EXPECT_LE(quat_diff_mod_sign(q2, q), tol<T>(16));
  EXPECT_GE(q2.w, T(0));
  // axis-angle both ways.
  const AxisAngle<T> aa = to_axis_angle(q);
  EXPECT_GE(aa.angle, T(0));
  EXPECT_LE(aa.angle, pi_v<T>);
  EXPECT_NEAR(double(aa.angle), double(ang), double(tol<T>(16)));
  EXPECT_LE(max_diff(to_matrix(aa), m), tol<T>(16));
  EXPECT_LE(max_diff(rodrigues(aa.axis, aa.angle), m), tol<T>(16));
  EXPECT_LE(quat_diff_mod_sign(to_quat(aa), q), tol<T>(16));
  const AxisAngle<T> aam = to_axis_angle(m);
  EXPECT_NEAR(double(aam.angle), double(ang), double(tol<T>(32)));
  EXPECT_LE(max_diff(to_matrix(aam), m), tol<T>(32));
  // Euler angles, all orders, from the matrix and from the quaternion.
  for (EulerOrder o : kOrders) {
    SCOPED_TRACE(order_name(o));
    const EulerAngles<T> e = to_euler(m, o);
    EXPECT_EQ(e.order, o);
    EXPECT_LE(max_diff(euler_oracle(o, e.angles), m), tol<T>(32));
    EXPECT_LE(max_diff(to_matrix(e), m), tol<T>(32));
    EXPECT_LE(quat_diff_mod_sign(to_quat(e), q), tol<T>(32));
    EXPECT_LE(std::fabs(e.angles[1]), pi_v<T> / T(2) * (T(1) + eps_v<T>));
    EXPECT_LE(std::fabs(e.angles[0]), pi_v<T> * (T(1) + eps_v<T>));
    EXPECT_LE(std::fabs(e.angles[2]), pi_v<T> * (T(1) + eps_v<T>));
    if (!e.unique) {
      EXPECT_EQ(e.angles[2], T(0));
    }
    const EulerAngles<T> eq = to_euler(q, o);
    EXPECT_LE(max_diff(to_matrix(eq), m), tol<T>(32));
  }
}

}  // namespace

TYPED_TEST(RotationTest, RandomRotationsRoundTripThroughEveryRepresentation) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 10000; ++n) check_all_representations(random_unit<T>(rng));
}

TYPED_TEST(RotationTest, AdversarialAnglesRoundTrip) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const T pi = pi_v<T>;
  const T angles[] = {T(0),
                      std::numeric_limits<T>::denorm_min(),
                      T(1e-30),
                      T(1e-10),
                      eps_v<T>,
                      std::sqrt(eps_v<T>),
                      T(1e-3),
                      pi / T(2),
                      pi - T(1e-3),
                      pi - std::sqrt(eps_v<T>),
                      pi - T(8) * eps_v<T>,
                      pi,
                      -pi,
                      T(2) * pi};
  std::vector<Vec3<T>> axes = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0},
                               {1, 1, 0}, {1, 1, 1}, {0, -1, 1}};
  for (int k = 0; k < 20; ++k) axes.push_back(rng.unit<T, 3>());
  for (const Vec3<T>& ax : axes)
    for (const T t : angles) {
      SCOPED_TRACE(::testing::Message() << "angle " << double(t));
      const Vec3<T> u = normalize(ax);
      check_all_representations(quat_def(u, t));
      // Matrix built independently (Rodrigues in long double, rounded once).
      const Mat3<L> rl = rodrigues(u, t);
      Mat3<T> r{};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r.a[i][j] = T(rl.a[i][j]);
      const AxisAngle<T> aa = to_axis_angle(r);
      // Near 0 the angle has full relative accuracy; near pi absolute accuracy ~ eps. The
      // reference angle is that of the rounded t, reduced by libm's sin/cos (a long double pi
      // is itself 1e-19 off, too coarse for angles near 2 pi).
      const L tl = std::atan2(std::sin(L(t)), std::cos(L(t)));
      const L tw = std::fabs(tl);
      if (tw < 1e-3L) {
        EXPECT_NEAR(double(aa.angle), double(tw),
                    double(tol<T>(8, T(tw))) + double(std::numeric_limits<T>::min()));
      } else {
        EXPECT_NEAR(double(aa.angle), double(tw), double(tol<T>(16)));
      }
      if (tw > 1e-3L) {
        // Axis is +-u (the sign flips at pi, where both are the same rotation).
        const T d = dot(aa.axis, u);
        EXPECT_NEAR(std::fabs(d), T(1), tol<T>(64));
        if (tw < L(pi) - 1e-3L) {
          EXPECT_GT(L(d) * tl, L(0));
        }
      }
      EXPECT_LE(max_diff(to_matrix(to_quat(r)), r), tol<T>(16));
    }
}

TYPED_TEST(RotationTest, EulerAnglesAreRecoveredAwayFromGimbalLock) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const T pi = pi_v<T>;
  for (EulerOrder o : kOrders) {
    SCOPED_TRACE(order_name(o));
    for (int n = 0; n < 1000; ++n) {
      const Vec3<T> a{rng.uniform<T>(-pi * T(0.999), pi * T(0.999)),
                      rng.uniform<T>(-pi / 2 * T(0.99), pi / 2 * T(0.99)),
                      rng.uniform<T>(-pi * T(0.999), pi * T(0.999))};
      const EulerAngles<T> e{o, a};
      EXPECT_LE(max_diff(to_matrix(e), euler_oracle(o, a)), tol<T>(16));
      const EulerAngles<T> back = to_euler(to_matrix(e), o);
      EXPECT_TRUE(back.unique);
      // cos(a1) >= sin(0.005 pi) ~ 0.0157 amplifies entry rounding into a0, a2 by <= 64.
      EXPECT_TRUE(locus_test::vec_near(back.angles, a, tol<T>(64 * 16)));
      // The quaternion of the angles is the product of the axis quaternions.
      EXPECT_LE(max_diff(to_matrix(to_quat(e)), euler_oracle(o, a)), tol<T>(16));
    }
  }
}

// The documented reading of order ABC: intrinsic rotations about the moving body axes, A first
// (by a0), then the rotated B axis (by a1), then the twice-rotated C axis (by a2).
TYPED_TEST(RotationTest, EulerOrderIsIntrinsicAboutMovingAxes) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (EulerOrder o : kOrders) {
    SCOPED_TRACE(order_name(o));
    const char* name = order_name(o);
    auto axis = [](char c) { return Vec3<T>{T(c == 'x'), T(c == 'y'), T(c == 'z')}; };
    for (int n = 0; n < 200; ++n) {
      const Vec3<T> a = rng.vec<T, 3>(-3, 3);
      const Mat3<L> r1 = rodrigues(axis(name[0]), a[0]);
      const Vec3<L> b1 = r1 * vec_cast<L>(axis(name[1]));
      const Mat3<L> r2 = rodrigues(Vec3<T>{T(b1.x), T(b1.y), T(b1.z)}, a[1]) * r1;
      const Vec3<L> c2 = r2 * vec_cast<L>(axis(name[2]));
      const Mat3<L> r3 = rodrigues(Vec3<T>{T(c2.x), T(c2.y), T(c2.z)}, a[2]) * r2;
      // The moving axes are rounded to T once before use: error ~ eps per step.
      EXPECT_LE(max_diff(to_matrix(EulerAngles<T>{o, a}), r3), tol<T>(32));
    }
  }
}

TYPED_TEST(RotationTest, GimbalLockIsReportedAndTheCanonicalSolutionReproducesTheMatrix) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const T half_pi = pi_v<T> / T(2);
  for (EulerOrder o : kOrders) {
    SCOPED_TRACE(order_name(o));
    for (int n = 0; n < 500; ++n) {
      const T a0 = rng.uniform<T>(-3, 3), a2 = rng.uniform<T>(-3, 3);
      for (const T sign : {T(1), T(-1)}) {
        // Exactly +-90 degrees (as representable): locked, third angle 0, a1 = +-pi/2.
        const Vec3<T> a{a0, sign * half_pi, a2};
        const Mat3<T> m = to_matrix(EulerAngles<T>{o, a});
        const EulerAngles<T> e = to_euler(m, o);
        EXPECT_FALSE(e.unique);
        EXPECT_EQ(e.angles[2], T(0));
        EXPECT_NEAR(e.angles[1], sign * half_pi, tol<T>(32));
        EXPECT_LE(max_diff(euler_oracle(o, e.angles), m), tol<T>(32));
        EXPECT_LE(max_diff(to_matrix(e), m), tol<T>(32));
        // The same lock reached through a quaternion (rounding in different entries).
        const Quat<T> q = to_quat(EulerAngles<T>{o, a});
        const EulerAngles<T> eq = to_euler(q, o);
        EXPECT_FALSE(eq.unique);
        EXPECT_LE(max_diff(to_matrix(eq), to_matrix(q)), tol<T>(64));
        // Nearly +-90 degrees: unique (cos a1 well above the tolerance) and still exact to
        // rounding in the matrix, although a0 and a2 separately are ill-conditioned.
        for (const T delta : {T(1e-2), T(1e-4), T(64) * default_lock_tolerance<T>}) {
          const Vec3<T> b{a0, sign * (half_pi - delta), a2};
          const Mat3<T> mb = to_matrix(EulerAngles<T>{o, b});
          const EulerAngles<T> eb = to_euler(mb, o);
          EXPECT_TRUE(eb.unique) << "delta " << double(delta);
          EXPECT_LE(max_diff(euler_oracle(o, eb.angles), mb), tol<T>(32))
              << "delta " << double(delta);
        }
        // Just inside the lock tolerance: reported locked, reproduces to ~tolerance.
        const Vec3<T> c{a0, sign * (half_pi - default_lock_tolerance<T> / T(4)), a2};
        const Mat3<T> mc = to_matrix(EulerAngles<T>{o, c});
        const EulerAngles<T> ec = to_euler(mc, o);
        EXPECT_FALSE(ec.unique);
        EXPECT_LE(max_diff(euler_oracle(o, ec.angles), mc), tol<T>(32));
      }
    }
  }
}

TYPED_TEST(RotationTest, DegenerateInputGivesIdentity) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const Mat3<T> id = Mat3<T>::identity();
  EXPECT_EQ(to_quat(AxisAngle<T>{{0, 0, 0}, T(1)}), Quat<T>::identity());
  EXPECT_EQ(to_matrix(AxisAngle<T>{{0, 0, 0}, T(1)}), id);
  EXPECT_EQ(to_matrix(AxisAngle<T>{{nan, 0, 1}, T(1)}), id);
  EXPECT_EQ(to_matrix(AxisAngle<T>{{0, 0, 1}, inf}), id);
  EXPECT_EQ(to_quat(AxisAngle<T>{{0, 0, 1}, nan}), Quat<T>::identity());
  EXPECT_EQ(to_matrix(Quat<T>{0, 0, 0, 0}), id);
  EXPECT_EQ(to_matrix(Quat<T>{nan, 0, 0, 0}), id);
  EXPECT_EQ(to_quat(Mat3<T>{}), Quat<T>::identity());
  Mat3<T> bad = id;
  bad.a[1][2] = nan;
  EXPECT_EQ(to_quat(bad), Quat<T>::identity());
  const AxisAngle<T> aa = to_axis_angle(bad);
  EXPECT_EQ(aa.angle, T(0));
  EXPECT_EQ(aa.axis, (Vec3<T>{1, 0, 0}));
  const EulerAngles<T> e = to_euler(bad, EulerOrder::zyx);
  EXPECT_FALSE(e.unique);
  EXPECT_EQ(e.angles, (Vec3<T>{0, 0, 0}));
  EXPECT_EQ(to_matrix(EulerAngles<T>{EulerOrder::xyz, {nan, 0, 0}}), id);
  // A non-unit axis is normalised; a scaled quaternion gives the same matrix.
  EXPECT_LE(max_diff(to_matrix(AxisAngle<T>{{0, 0, 5}, T(1)}), rz(1)), tol<T>(8));
  const Quat<T> q = normalize(Quat<T>{1, 2, 3, 4});
  EXPECT_LE(max_diff(to_matrix(q * T(1e3)), to_matrix(q)), tol<T>(16));
  // Identity rotations.
  EXPECT_EQ(to_quat(id), Quat<T>::identity());
  EXPECT_EQ(to_axis_angle(id).angle, T(0));
  for (EulerOrder o : kOrders) EXPECT_EQ(to_euler(id, o).angles, (Vec3<T>{0, 0, 0}));
}

TYPED_TEST(RotationTest, NearestRotationIsThePolarFactorFigureA1) {
  using T = TypeParam;
  // Figure A.1: a nonuniform scale (x, y) -> (2x, y) followed by a rotation by pi/4. The polar
  // decomposition M = R S separates them again: R = Rz(pi/4), S = diag(2, 1, 1).
  const Mat3<L> rl = rz(L(pi_v<double>) / 4);
  Mat3<T> m{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m.a[i][j] = T(rl.a[i][j] * (j == 0 ? 2 : 1));
  const RotationFix<T> f = nearest_rotation(m);
  ASSERT_EQ(f.status, Status::ok);
  EXPECT_LE(max_diff(f.rotation, rl), tol<T>(8));
  const Mat3<T> s = transpose(f.rotation) * m;
  EXPECT_LE(max_diff(s, Mat3<T>::diagonal({2, 1, 1})), tol<T>(16));
  // The unit circle maps to an ellipse that no rotation alone produces: the stretch stays in S.
  EXPECT_GT(orthonormality_error(m), L(1));
}

TYPED_TEST(RotationTest, NearestRotationOfDriftedMatrices) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 2000; ++n) {
    const Mat3<T> r = to_matrix(random_unit<T>(rng));
    Mat3<T> m = r;
    const T noise = n % 2 ? T(1e-3) : T(0.2);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m.a[i][j] += rng.uniform<T>(-noise, noise);
    if (!(determinant(m) > T(0.1))) continue;
    const RotationFix<T> f = nearest_rotation(m);
    ASSERT_EQ(f.status, Status::ok);
    EXPECT_LE(f.iterations, 12);
    EXPECT_LE(orthonormality_error(f.rotation), tol<T>(8));
    EXPECT_GT(determinant(f.rotation), T(0));
    // Characterisation of the polar factor: R^T M is symmetric positive definite.
    const Mat3<T> s = transpose(f.rotation) * m;
    EXPECT_LE(max_diff(s, transpose(s)), tol<T>(32, T(3)));
    EXPECT_GT(s.a[0][0], T(0));
    EXPECT_GT(s.a[0][0] * s.a[1][1] - s.a[0][1] * s.a[1][0], T(0));
    EXPECT_GT(determinant(s), T(0));
    // Nearest: no farther from m than the rotation m was drifted from, nor than Gram-Schmidt.
    auto fro = [&](const Mat3<T>& x) {
      L acc = 0;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) acc += std::pow(L(x.a[i][j]) - L(m.a[i][j]), 2);
      return std::sqrt(acc);
    };
    EXPECT_LE(fro(f.rotation), fro(r) + tol<T>(16));
    const RotationFix<T> g = orthonormalize_rotation(m);
    ASSERT_EQ(g.status, Status::ok);
    EXPECT_LE(fro(f.rotation), fro(g.rotation) + tol<T>(16));
    // Gram-Schmidt: orthonormal, right-handed, first column along m's first column.
    EXPECT_LE(orthonormality_error(g.rotation), tol<T>(16));
    EXPECT_NEAR(determinant(g.rotation), T(1), tol<T>(16));
    EXPECT_NEAR(dot(col(g.rotation, 0), normalize(col(m, 0))), T(1), tol<T>(8));
  }
}

TYPED_TEST(RotationTest, RepairRejectsReflectionsSingularAndNonFinite) {
  using T = TypeParam;
  const Mat3<T> refl = Mat3<T>::diagonal({1, 1, -1});
  EXPECT_EQ(nearest_rotation(refl).status, Status::degenerate_input);
  EXPECT_EQ(nearest_rotation(refl).rotation, Mat3<T>::identity());
  EXPECT_EQ(nearest_rotation(Mat3<T>{}).status, Status::degenerate_input);
  const Mat3<T> rank2 = Mat3<T>::from_rows(Vec3<T>{1, 2, 3}, Vec3<T>{2, 4, 6}, Vec3<T>{0, 1, 1});
  EXPECT_EQ(nearest_rotation(rank2).status, Status::degenerate_input);
  Mat3<T> nan_m = Mat3<T>::identity();
  nan_m.a[0][0] = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(nearest_rotation(nan_m).status, Status::non_finite_input);
  EXPECT_EQ(orthonormalize_rotation(nan_m).status, Status::non_finite_input);
  EXPECT_EQ(orthonormalize_rotation(rank2).status, Status::degenerate_input);
  EXPECT_EQ(orthonormalize_rotation(refl).status, Status::degenerate_input);
  // Columns 0 and 1 dependent, column 2 not: still no rotation from Gram-Schmidt.
  EXPECT_EQ(orthonormalize_rotation(transpose(rank2)).status, Status::degenerate_input);
  EXPECT_EQ(orthonormalize_rotation(Mat3<T>{}).status, Status::degenerate_input);
  // Huge and tiny scales: the polar factor does not depend on a positive scale.
  const Mat3<T> r = to_matrix(normalize(Quat<T>{1, -2, 3, 0.5}));
  for (const T s : {T(1e-30), T(1e30)}) {
    const RotationFix<T> f = nearest_rotation(r * s);
    ASSERT_EQ(f.status, Status::ok);
    EXPECT_LE(max_diff(f.rotation, r), tol<T>(16));
    const RotationFix<T> g = orthonormalize_rotation(r * s);
    ASSERT_EQ(g.status, Status::ok);
    EXPECT_LE(max_diff(g.rotation, r), tol<T>(16));
  }
}

TYPED_TEST(RotationTest, MatrixSlerpAndAngleBetween) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 1000; ++n) {
    const Quat<T> qa = random_unit<T>(rng);
    const Vec3<T> u = rng.unit<T, 3>();
    const T angle = rng.uniform<T>(T(0.01), T(3.1));
    const Mat3<T> a = to_matrix(qa);
    const Mat3<L> step = rodrigues(u, angle);
    Mat3<L> al{};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) al.a[i][j] = a.a[i][j];
    const Mat3<L> bl = step * al;
    Mat3<T> b{};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) b.a[i][j] = T(bl.a[i][j]);
    EXPECT_LE(max_diff(slerp(a, b, T(0)), a), tol<T>(16));
    EXPECT_LE(max_diff(slerp(a, b, T(1)), b), tol<T>(16));
    const T t = rng.uniform<T>(0, 1);
    EXPECT_LE(max_diff(slerp(a, b, t), rodrigues(u, t * angle) * al), tol<T>(32));
    EXPECT_NEAR(angle_between(qa, to_quat(b)), angle, tol<T>(32));
    EXPECT_NEAR(angle_between(qa, -to_quat(b)), angle, tol<T>(32));
  }
  const Quat<T> q = normalize(Quat<T>{1, 2, 3, 4});
  EXPECT_EQ(angle_between(q, q), T(0));
}
