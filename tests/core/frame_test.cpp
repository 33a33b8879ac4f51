// SPDX-License-Identifier: BSL-1.0
// Tests for core/frame.hpp (row core.frames; figures 2.1, 3.35-3.40, 4.6-4.8, 4.10).
#include <locus/core/affine.hpp>
#include <locus/core/basis.hpp>
#include <locus/core/frame.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <cmath>
#include <limits>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;

template <class T>
class FrameTest : public ::testing::Test {};
TYPED_TEST_SUITE(FrameTest, locus_test::RealTypes);

static_assert(std::is_aggregate_v<Frame3d> && std::is_trivially_copyable_v<Frame3f>);
static_assert(to_world_point(Frame2d::identity(), Vec2d{3, 4}) == Vec2d{3, 4});

namespace {

template <class T, int N>
Frame<T, N> random_frame(Rng& rng) {
  for (;;) {
    Frame<T, N> f{};
    f.origin = rng.vec<T, N>(-10, 10);
    for (auto& a : f.axis) a = rng.vec<T, N>(-2, 2);
    // Keep the basis reasonably conditioned: conditioning is the linear solvers' subject.
    const auto m = axes_matrix(f);
    T scale = T(1);
    for (const auto& a : f.axis) scale *= length(a);
    if (std::abs(determinant(m)) > T(0.2) * scale) return f;
  }
}

template <class T, int N>
Frame<T, N> random_rigid_frame(Rng& rng) {
  Frame<T, N> f{};
  f.origin = rng.vec<T, N>(-10, 10);
  if constexpr (N == 3) {
    const auto b = complete_basis(rng.unit<T, 3>());
    f.axis = b.axis;
  } else {
    const auto b = complete_basis(rng.unit<T, 2>());
    f.axis = b.axis;
  }
  return f;
}

template <class T, int M>
::testing::AssertionResult mat_near(const Mat<T, M, M>& a, const Mat<T, M, M>& b, T t) {
  for (int r = 0; r < M; ++r)
    for (int c = 0; c < M; ++c)
      if (!(std::abs(a(r, c) - b(r, c)) <= t))
        return ::testing::AssertionFailure()
               << "entry (" << r << "," << c << "): " << a(r, c) << " vs " << b(r, c);
  return ::testing::AssertionSuccess();
}

}  // namespace

// Figure 3.35: the coordinates of a point relative to an arbitrary frame, against an exact
// rational solve of O + sum c_i v_i = P.
TYPED_TEST(FrameTest, Fig3_35LocalCoordinatesMatchExactSolve) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 1000; ++n) {
    const auto f = random_frame<T, 3>(rng);
    const auto p = rng.vec<T, 3>(-10, 10);
    const auto c = to_local_point(f, p);
    // Cramer's rule in rationals.
    auto qdet = [](const std::array<std::array<mpq_class, 3>, 3>& m) -> mpq_class {
      return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
             m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
             m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    std::array<std::array<mpq_class, 3>, 3> a{};
    for (std::size_t r = 0; r < 3; ++r)
      for (std::size_t k = 0; k < 3; ++k) a[r][k] = f.axis[k][static_cast<int>(r)];
    const mpq_class det = qdet(a);
    for (std::size_t k = 0; k < 3; ++k) {
      auto ak = a;
      for (std::size_t r = 0; r < 3; ++r)
        ak[r][k] = mpq_class(p[static_cast<int>(r)]) - mpq_class(f.origin[static_cast<int>(r)]);
      const mpq_class e = qdet(ak) / det;
      // det >= 0.2 |v0||v1||v2|, entries <= 2 sqrt 3, |P - O| <= 35: ~1e3 scale.
      EXPECT_NEAR(double(c[static_cast<int>(k)]), e.get_d(), double(tol<T>(64, T(1000))));
    }
  }
}

// Round trips world -> local -> world and local -> world -> local, general and rigid frames.
template <class T, int N>
void check_round_trips(Rng& rng) {
  for (int n = 0; n < 500; ++n) {
    const auto f = random_frame<T, N>(rng);
    const auto p = rng.vec<T, N>(-10, 10), v = rng.vec<T, N>(-3, 3);
    EXPECT_TRUE(
        locus_test::vec_near(to_world_point(f, to_local_point(f, p)), p, tol<T>(64, T(1000))));
    EXPECT_TRUE(
        locus_test::vec_near(to_local_point(f, to_world_point(f, p)), p, tol<T>(64, T(1000))));
    EXPECT_TRUE(
        locus_test::vec_near(to_world_vector(f, to_local_vector(f, v)), v, tol<T>(64, T(100))));
    const auto r = random_rigid_frame<T, N>(rng);
    ASSERT_TRUE(is_orthonormal(r));
    const auto ri = rigid_inverse(r);
    EXPECT_TRUE(
        locus_test::vec_near(to_world_point(r, to_world_point(ri, p)), p, tol<T>(16, T(20))));
    EXPECT_TRUE(
        locus_test::vec_near(to_world_point(ri, p), to_local_point(r, p), tol<T>(16, T(20))));
    // Rigid frames preserve lengths.
    EXPECT_NEAR(length(to_world_vector(r, v)), length(v), tol<T>(8, T(6)));
  }
}

TYPED_TEST(FrameTest, RoundTripsWorldLocalWorld) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  check_round_trips<T, 2>(rng);
  check_round_trips<T, 3>(rng);
}

// The matrix form equals the function form for points (w = 1) and vectors (w = 0).
template <class T, int N>
void check_matrix_form(Rng& rng) {
  for (int n = 0; n < 500; ++n) {
    const auto f = random_frame<T, N>(rng), g = random_frame<T, N>(rng);
    const auto m = to_matrix(f);
    const auto p = rng.vec<T, N>(-10, 10);
    const auto hp = from_homogeneous(m * to_homogeneous_point(p));
    EXPECT_TRUE(hp.is_point);
    EXPECT_TRUE(locus_test::vec_near(hp.value, to_world_point(f, p), tol<T>(16, T(100))));
    const auto hv = from_homogeneous(m * to_homogeneous_vector(p));
    EXPECT_FALSE(hv.is_point);
    EXPECT_TRUE(locus_test::vec_near(hv.value, to_world_vector(f, p), tol<T>(16, T(100))));
    // Back from the matrix: the same frame, bit for bit.
    const auto back = to_frame(m);
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(back->origin, f.origin);
    for (std::size_t i = 0; i < static_cast<std::size_t>(N); ++i)
      EXPECT_EQ(back->axis[i], f.axis[i]);
    // Composition is the matrix product.
    EXPECT_TRUE(mat_near(to_matrix(compose(f, g)), m * to_matrix(g), tol<T>(32, T(200))));
    // Inverse against the (N+1)x(N+1) matrix inverse (a different code path in mat.hpp).
    const auto fi = inverse(f);
    const auto mi = inverse(m);
    ASSERT_TRUE(fi.has_value() && mi.has_value());
    EXPECT_TRUE(mat_near(to_matrix(*fi), *mi, tol<T>(256, T(100))));
    EXPECT_TRUE(mat_near(to_matrix(compose(f, *fi)), Mat<T, N + 1, N + 1>::identity(),
                         tol<T>(256, T(100))));
  }
}

TYPED_TEST(FrameTest, MatrixFormEqualsFunctionFormAndComposes) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  check_matrix_form<T, 2>(rng);
  check_matrix_form<T, 3>(rng);
  // Rigid inverse equals the general inverse for orthonormal frames.
  for (int n = 0; n < 500; ++n) {
    const auto r = random_rigid_frame<T, 3>(rng);
    EXPECT_TRUE(mat_near(to_matrix(rigid_inverse(r)), to_matrix(*inverse(r)), tol<T>(32, T(20))));
  }
}

// Figures 4.6-4.8 (and 2.1a): the same point and vectors represented in two frames A and B.
TYPED_TEST(FrameTest, Fig4_6To4_8ChangeOfFrame) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 500; ++n) {
    const auto A = random_frame<T, 3>(rng), B = random_frame<T, 3>(rng);
    const auto Binv = inverse(B);
    ASSERT_TRUE(Binv.has_value());
    const auto AtoB = compose(*Binv, A);  // A-coordinates -> B-coordinates
    const auto pA = rng.vec<T, 3>(-5, 5);
    const auto pB = to_world_point(AtoB, pA);
    // Figure 4.6: P in A and P in B name the same world point.
    EXPECT_TRUE(
        locus_test::vec_near(to_world_point(B, pB), to_world_point(A, pA), tol<T>(256, T(1000))));
    EXPECT_TRUE(
        locus_test::vec_near(pB, to_local_point(B, to_world_point(A, pA)), tol<T>(256, T(1000))));
    // Figure 4.7: A's origin represented in B.
    EXPECT_TRUE(
        locus_test::vec_near(AtoB.origin, to_local_point(B, A.origin), tol<T>(256, T(1000))));
    // Figure 4.8: A's basis vectors represented in B.
    for (std::size_t i = 0; i < 3; ++i)
      EXPECT_TRUE(
          locus_test::vec_near(AtoB.axis[i], to_local_vector(B, A.axis[i]), tol<T>(256, T(100))));
  }
}

// Figure 4.10: translating a frame by t translates the points it describes by t.
TYPED_TEST(FrameTest, Fig4_10TranslationOfAFrame) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 500; ++n) {
    auto f = random_frame<T, 3>(rng);
    const auto p = rng.vec<T, 3>(-5, 5), t = rng.vec<T, 3>(-5, 5);
    const auto before = to_world_point(f, p);
    f.origin += t;
    EXPECT_TRUE(locus_test::vec_near(to_world_point(f, p), before + t, tol<T>(16, T(50))));
  }
}

// Figures 3.36-3.39: affine maps preserve ratios, sums, scaling and point + vector.
TYPED_TEST(FrameTest, Fig3_36To3_39AffineMapProperties) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 500; ++n) {
    const auto f = random_frame<T, 3>(rng);
    const auto p = rng.vec<T, 3>(-5, 5), q = rng.vec<T, 3>(-5, 5), u = rng.vec<T, 3>(-5, 5);
    const T t = rng.uniform<T>(-1, 2), s = rng.uniform<T>(-3, 3);
    const T k = tol<T>(64, T(200));
    EXPECT_TRUE(locus_test::vec_near(to_world_point(f, lerp(p, q, t)),
                                     lerp(to_world_point(f, p), to_world_point(f, q), t), k));
    EXPECT_TRUE(locus_test::vec_near(to_world_vector(f, p + u),
                                     to_world_vector(f, p) + to_world_vector(f, u), k));
    EXPECT_TRUE(locus_test::vec_near(to_world_vector(f, u * s), to_world_vector(f, u) * s, k));
    EXPECT_TRUE(locus_test::vec_near(to_world_point(f, p + u),
                                     to_world_point(f, p) + to_world_vector(f, u), k));
  }
}

// Figure 3.40: composing two rotation frames about the origin adds their angles.
TYPED_TEST(FrameTest, Fig3_40CompositionOfRotations) {
  using T = TypeParam;
  auto rot = [](T a) {
    Frame2<T> f{};
    f.axis = {Vec2<T>{std::cos(a), std::sin(a)}, Vec2<T>{-std::sin(a), std::cos(a)}};
    return f;
  };
  const T a = T(0.3), b = T(1.1);
  const auto c = compose(rot(a), rot(b));
  EXPECT_TRUE(mat_near(to_matrix(c), to_matrix(rot(a + b)), tol<T>(8)));
  // And a frame composed with its inverse is the identity frame.
  const auto id = compose(rot(a), rigid_inverse(rot(a)));
  EXPECT_TRUE(mat_near(to_matrix(id), to_matrix(Frame2<T>::identity()), tol<T>(4)));
}

TYPED_TEST(FrameTest, SingularNonFiniteAndProjectiveInput) {
  using T = TypeParam;
  Frame3<T> f = Frame3<T>::identity();
  f.axis[2] = f.axis[0] + f.axis[1];  // singular basis
  EXPECT_FALSE(inverse(f).has_value());
  EXPECT_EQ(to_local_point(f, Vec3<T>{1, 2, 3}), (Vec3<T>{}));
  EXPECT_FALSE(is_orthonormal(f));
  Frame3<T> nf = Frame3<T>::identity();
  nf.origin.x = std::numeric_limits<T>::quiet_NaN();
  EXPECT_FALSE(inverse(nf).has_value());
  nf = Frame3<T>::identity();
  nf.axis[1].y = std::numeric_limits<T>::infinity();
  EXPECT_FALSE(inverse(nf).has_value());
  auto m = to_matrix(Frame3<T>::identity());
  m(3, 0) = T(0.5);  // projective bottom row: not a frame
  EXPECT_FALSE(to_frame(m).has_value());
  m = to_matrix(Frame3<T>::identity());
  m(3, 3) = T(2);
  EXPECT_FALSE(to_frame(m).has_value());
  // NaN frames propagate NaN through to_world_* (IEEE), never crash.
  Frame3<T> nan_origin = Frame3<T>::identity();
  nan_origin.origin.z = std::numeric_limits<T>::quiet_NaN();
  EXPECT_FALSE(is_finite(to_world_point(nan_origin, Vec3<T>{1, 2, 3})));
  EXPECT_TRUE(is_finite(to_world_vector(nan_origin, Vec3<T>{1, 2, 3})));
  EXPECT_FALSE(is_orthonormal(nf));
  // The identity frame.
  const auto id = Frame3<T>::identity();
  EXPECT_TRUE(is_orthonormal(id));
  EXPECT_EQ(to_matrix(id), (Mat4<T>::identity()));
  EXPECT_EQ(to_local_point(id, Vec3<T>{1, 2, 3}), (Vec3<T>{1, 2, 3}));
}
