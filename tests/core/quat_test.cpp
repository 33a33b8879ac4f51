// SPDX-License-Identifier: BSL-1.0
// Tests for core/quat.hpp (row core.rotation: quaternion algebra, rotation, exp/log, slerp).
#include <locus/core/quat.hpp>

#include "support/typed.hpp"

#include <cmath>
#include <limits>
#include <type_traits>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;

template <class T>
class QuatTest : public ::testing::Test {};
TYPED_TEST_SUITE(QuatTest, locus_test::RealTypes);

static_assert(std::is_aggregate_v<Quatd> && std::is_trivially_copyable_v<Quatf>);
static_assert(sizeof(Quatf) == 4 * sizeof(float));
static_assert(Quatd{1, 2, 3, 4}.w == 1 && Quatd{1, 2, 3, 4}.z == 4, "w first, then x, y, z");

namespace {

using L = long double;

// A random unit quaternion, uniform on S^3 (normalised Gaussian 4-vector).
template <class T>
Quat<T> random_unit(Rng& rng) {
  const Vec4<T> v = rng.unit<T, 4>();
  return {v.x, v.y, v.z, v.w};
}

// Independent: the quaternion of a rotation by t about unit axis u, built from its definition.
template <class T>
Quat<T> from_axis(const Vec3<T>& u, T t) {
  const T s = std::sin(t / T(2));
  return {std::cos(t / T(2)), s * u.x, s * u.y, s * u.z};
}

// Independent oracle: Rodrigues' rotation formula in long double.
template <class T>
Vec3<L> rodrigues(const Vec3<T>& u0, T t, const Vec3<T>& v0) {
  const Vec3<L> u = vec_cast<L>(u0), v = vec_cast<L>(v0);
  const L c = std::cos(L(t)), s = std::sin(L(t));
  return v * c + cross(u, v) * s + u * (dot(u, v) * (L(1) - c));
}

// Rotation angle between two unit quaternions, computed in long double with acos of the
// normalised |dot| guarded by the cross-check through atan2 of the chord lengths.
template <class T>
L rot_angle(const Quat<T>& a, const Quat<T>& b) {
  L d = L(a.w) * b.w + L(a.x) * b.x + L(a.y) * b.y + L(a.z) * b.z;
  const L s = d < 0 ? L(-1) : L(1);
  const L m[4] = {L(a.w) - s * L(b.w), L(a.x) - s * L(b.x), L(a.y) - s * L(b.y),
                  L(a.z) - s * L(b.z)};
  const L p[4] = {L(a.w) + s * L(b.w), L(a.x) + s * L(b.x), L(a.y) + s * L(b.y),
                  L(a.z) + s * L(b.z)};
  L mm = 0, pp = 0;
  for (int i = 0; i < 4; ++i) mm += m[i] * m[i], pp += p[i] * p[i];
  return L(4) * std::atan2(std::sqrt(mm), std::sqrt(pp));
}

template <class T>
T qdiff(const Quat<T>& a, const Quat<T>& b) {
  return std::fmax(std::fmax(std::fabs(a.w - b.w), std::fabs(a.x - b.x)),
                   std::fmax(std::fabs(a.y - b.y), std::fabs(a.z - b.z)));
}

}  // namespace

TYPED_TEST(QuatTest, HamiltonProductTable) {
  using T = TypeParam;
  const Quat<T> one{1, 0, 0, 0}, i{0, 1, 0, 0}, j{0, 0, 1, 0}, k{0, 0, 0, 1};
  EXPECT_EQ(i * j, k);
  EXPECT_EQ(j * k, i);
  EXPECT_EQ(k * i, j);
  EXPECT_EQ(j * i, -k);
  EXPECT_EQ(i * i, -one);
  EXPECT_EQ(j * j, -one);
  EXPECT_EQ(k * k, -one);
  EXPECT_EQ(i * j * k, -one);
  EXPECT_EQ(Quat<T>::identity(), one);
  EXPECT_EQ(conjugate(Quat<T>{1, 2, 3, 4}), (Quat<T>{1, -2, -3, -4}));
  EXPECT_EQ(dot(Quat<T>{1, 2, 3, 4}, Quat<T>{5, 6, 7, 8}), T(70));
}

TYPED_TEST(QuatTest, AlgebraicIdentitiesOnRandomQuaternions) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 2000; ++n) {
    const Vec4<T> va = rng.vec<T, 4>(-2, 2), vb = rng.vec<T, 4>(-2, 2), vc = rng.vec<T, 4>(-2, 2);
    const Quat<T> a{va.x, va.y, va.z, va.w}, b{vb.x, vb.y, vb.z, vb.w}, c{vc.x, vc.y, vc.z, vc.w};
    // Entries up to 2, products of three: terms up to 8, 16 per component.
    EXPECT_LE(qdiff((a * b) * c, a * (b * c)), tol<T>(64, T(8)));
    EXPECT_LE(qdiff(conjugate(a * b), conjugate(b) * conjugate(a)), tol<T>(8, T(4)));
    EXPECT_NEAR(norm(a * b), norm(a) * norm(b), tol<T>(16, norm(a) * norm(b)));
    if (norm(a) > T(0.1)) {
      EXPECT_LE(qdiff(a * inverse(a), Quat<T>::identity()), tol<T>(64, T(20)));
      EXPECT_NEAR(norm(normalize(a)), T(1), tol<T>(4));
    }
  }
}

TYPED_TEST(QuatTest, RotateAgreesWithRodriguesAndSandwichProduct) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 10000; ++n) {
    const Vec3<T> u = rng.unit<T, 3>();
    const T t = rng.uniform<T>(-T(4), T(4));
    const Vec3<T> v = rng.vec<T, 3>(-10, 10);
    const Quat<T> q = from_axis(u, t);
    const Vec3<T> r = rotate(q, v);
    const Vec3<L> ref = rodrigues(u, t, v);
    const T scale = length(v);
    EXPECT_TRUE(locus_test::vec_near(r, vec_cast<T>(ref), tol<T>(16, scale)));
    // q v q* as a Hamilton product of a pure quaternion: a second formula.
    const Quat<T> s = q * Quat<T>{0, v.x, v.y, v.z} * conjugate(q);
    EXPECT_NEAR(s.w, T(0), tol<T>(16, scale));
    EXPECT_TRUE(locus_test::vec_near(r, vector_part(s), tol<T>(32, scale)));
    // Composition: rotating by q1 * q2 = rotating by q2, then q1.
    const Quat<T> q2 = random_unit<T>(rng);
    EXPECT_TRUE(
        locus_test::vec_near(rotate(q * q2, v), rotate(q, rotate(q2, v)), tol<T>(32, scale)));
  }
}

TYPED_TEST(QuatTest, NormalizeAndInverseOfDegenerateQuaternions) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  EXPECT_EQ(normalize(Quat<T>{0, 0, 0, 0}), Quat<T>::identity());
  EXPECT_EQ(normalize(Quat<T>{nan, 1, 0, 0}), Quat<T>::identity());
  EXPECT_EQ(normalize(Quat<T>{inf, 0, 0, 0}), Quat<T>::identity());
  EXPECT_EQ(inverse(Quat<T>{0, 0, 0, 0}), Quat<T>::identity());
  EXPECT_EQ(inverse(Quat<T>{0, nan, 0, 0}), Quat<T>::identity());
  // Huge and tiny (subnormal) quaternions still normalise: the norm is overflow-safe.
  const T big = std::numeric_limits<T>::max() / T(2);
  const Quat<T> nb = normalize(Quat<T>{big, big, 0, 0});
  EXPECT_NEAR(nb.w, std::sqrt(T(0.5)), tol<T>(4));
  EXPECT_NEAR(nb.x, std::sqrt(T(0.5)), tol<T>(4));
  const T tiny = std::numeric_limits<T>::denorm_min();
  EXPECT_EQ(normalize(Quat<T>{0, 0, tiny, 0}), (Quat<T>{0, 0, 1, 0}));
  // inverse of a scaled quaternion: (s q)^-1 = q* / s for unit q.
  const Quat<T> q = normalize(Quat<T>{1, 2, 3, 4});
  EXPECT_LE(qdiff(inverse(q * T(1e-20)), conjugate(q) * T(1e20)), tol<T>(8, T(1e20)));
}

TYPED_TEST(QuatTest, ExpAndLogAreInverse) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 2000; ++n) {
    // log(exp(p)) = p on the principal branch |vector part| < pi.
    const Vec3<T> u = rng.unit<T, 3>();
    const T h = rng.uniform<T>(0, T(3));
    const T w = rng.uniform<T>(-2, 2);
    const Quat<T> p = Quat<T>::from_parts(w, h * u);
    const Quat<T> lp = log(exp(p));
    // d(log)/dq scales errors by up to 1/sin(h) near the branch end; h <= 3 keeps it below 8.
    EXPECT_LE(qdiff(lp, p), tol<T>(256, T(4)));
    // exp(log(q)) = q for any nonzero q.
    const Vec4<T> vq = rng.vec<T, 4>(-3, 3);
    const Quat<T> q{vq.x, vq.y, vq.z, vq.w};
    if (norm(q) < T(0.1)) continue;
    EXPECT_LE(qdiff(exp(log(q)), q), tol<T>(64, norm(q)));
    // A pure quaternion (0, t/2 u) exponentiates to the rotation by t about u.
    EXPECT_LE(qdiff(exp(Quat<T>::from_parts(T(0), (h / T(2)) * u)), from_axis(u, h)), tol<T>(8));
  }
  EXPECT_EQ(log(Quat<T>::identity()), (Quat<T>{0, 0, 0, 0}));
  EXPECT_EQ(exp(Quat<T>{0, 0, 0, 0}), Quat<T>::identity());
  const Quat<T> lz = log(Quat<T>{0, 0, 0, 0});
  EXPECT_TRUE(std::isinf(lz.w) && lz.w < T(0));
  // -1 = exp(pi i) on the chosen branch.
  EXPECT_LE(qdiff(log(Quat<T>{-1, 0, 0, 0}), Quat<T>{0, pi_v<T>, 0, 0}), tol<T>(1));
  // Tiny vector parts keep full relative accuracy (no 0/0, no cancellation).
  const T tiny = T(1e-30);
  const Quat<T> e = exp(Quat<T>{0, tiny, 0, 0});
  EXPECT_EQ(e.w, T(1));
  EXPECT_NEAR(e.x, tiny, tol<T>(2, tiny));
  const Quat<T> lt = log(Quat<T>{1, tiny, 0, 0});
  EXPECT_NEAR(lt.x, tiny, tol<T>(2, tiny));
}

TYPED_TEST(QuatTest, SlerpHasUnitNormConstantSpeedAndExactEndpoints) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const int steps = 16;
  for (int n = 0; n < 500; ++n) {
    const Quat<T> a = random_unit<T>(rng), b = random_unit<T>(rng);
    const L total = rot_angle(a, b);
    if (total < 1e-2L) continue;  // nearly parallel inputs have their own test
    EXPECT_EQ(slerp(a, b, T(0)), a);
    const Quat<T> end = slerp(a, b, T(1));
    EXPECT_TRUE(end == b || end == -b);
    Quat<T> prev = a;
    for (int s = 1; s <= steps; ++s) {
      const T t = T(s) / T(steps);
      const Quat<T> q = slerp(a, b, t);
      EXPECT_NEAR(norm(q), T(1), tol<T>(8));
      // Constant angular velocity: successive samples are total / steps apart, and the sample
      // at t is t * total away from a (angles in the rotation group, up to 2 pi).
      EXPECT_NEAR(double(rot_angle(prev, q)), double(total / steps), double(tol<T>(64)));
      EXPECT_NEAR(double(rot_angle(a, q)), double(total * L(t)), double(tol<T>(64)));
      prev = q;
    }
  }
}

TYPED_TEST(QuatTest, SlerpFollowsTheFixedAxisRotation) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 1000; ++n) {
    const Vec3<T> u = rng.unit<T, 3>();
    const T angle = rng.uniform<T>(T(0.01), T(3.1));
    const Quat<T> a = random_unit<T>(rng);
    const T t = rng.uniform<T>(0, 1);
    // slerp(a, r a, t) = r^t a where r^t is the rotation by t * angle about u.
    const Quat<T> got = slerp(a, from_axis(u, angle) * a, t);
    EXPECT_LE(qdiff(got, from_axis(u, t * angle) * a), tol<T>(32));
    // Shortest path: passing -b gives the same rotations.
    const Quat<T> got_neg = slerp(a, -(from_axis(u, angle) * a), t);
    EXPECT_LE(qdiff(got_neg, got), tol<T>(32));
  }
}

TYPED_TEST(QuatTest, SlerpOfNearlyIdenticalInputsIsFinite) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 1000; ++n) {
    const Quat<T> a = random_unit<T>(rng);
    const T tiny_angles[] = {
        T(0),     std::numeric_limits<T>::denorm_min(), T(1e-30),
        eps_v<T>, std::sqrt(eps_v<T>) / T(2),           std::sqrt(eps_v<T>) * T(2)};
    for (const T ang : tiny_angles) {
      const Vec3<T> u = rng.unit<T, 3>();
      const Quat<T> b = from_axis(u, ang) * a;
      for (const T t : {T(0), T(0.25), T(0.5), T(1)}) {
        const Quat<T> q = slerp(a, b, t);
        ASSERT_TRUE(is_finite(q));
        EXPECT_NEAR(norm(q), T(1), tol<T>(8));
        // Within the tiny angle of both inputs.
        EXPECT_LE(double(rot_angle(q, a)), double(ang) + double(tol<T>(16)));
        const Quat<T> nq = nlerp(a, b, t);
        EXPECT_LE(qdiff(nq, q), tol<T>(16));
      }
      // Antipodal copies are the same rotation: slerp stays at a.
      EXPECT_LE(qdiff(slerp(a, -b, T(0.5)), a), T(ang) + tol<T>(16));
    }
  }
}

TYPED_TEST(QuatTest, NlerpIsUnitWithExactEndpointRotations) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 1000; ++n) {
    const Quat<T> a = random_unit<T>(rng), b = random_unit<T>(rng);
    EXPECT_LE(qdiff(nlerp(a, b, T(0)), a), tol<T>(4));
    const Quat<T> e = nlerp(a, b, T(1));
    EXPECT_LE(std::fmin(qdiff(e, b), qdiff(e, -b)), tol<T>(4));
    const Quat<T> m = nlerp(a, b, T(0.5));
    EXPECT_NEAR(norm(m), T(1), tol<T>(4));
    // The midpoint of nlerp is the midpoint of slerp (symmetry).
    EXPECT_LE(qdiff(m, slerp(a, b, T(0.5))), tol<T>(32));
  }
}
