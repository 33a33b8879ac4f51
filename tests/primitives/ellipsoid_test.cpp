// SPDX-License-Identifier: BSL-1.0
// Tests for primitives/ellipsoid.hpp (row prim3.solids: ellipsoid; the Jacobi eigen-solver).
#include <locus/primitives/ellipsoid.hpp>

#include "support/typed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
using locus_test::vec_near;

template <class T>
class EllipsoidTest : public ::testing::Test {};
TYPED_TEST_SUITE(EllipsoidTest, locus_test::RealTypes);

static_assert(std::is_aggregate_v<Ellipsoid3d> && std::is_trivially_copyable_v<Ellipsoid3f>);

namespace {
template <class T>
Mat3<T> random_rotation(Rng& rng) {
  const auto q = rng.unit<double, 4>();
  const double w = q.x, x = q.y, y = q.z, z = q.w;
  const Mat3<double> m{{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                        {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                        {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
  Mat3<T> r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.a[i][j] = static_cast<T>(m.a[i][j]);
  return r;
}

template <class T>
Ellipsoid3<T> random_ellipsoid(Rng& rng) {
  const Mat3<T> r = random_rotation<T>(rng);
  return {rng.vec<T, 3>(-5, 5),
          {col(r, 0), col(r, 1), col(r, 2)},
          {rng.uniform<T>(T(0.5), 3), rng.uniform<T>(T(0.5), 3), rng.uniform<T>(T(0.5), 3)}};
}

// Max-norm of V diag(l) V^T - M and of V^T V - I.
double eig_residual(const SymmetricEigen<double, 3>& e, const Mat3<double>& m) {
  const Mat3<double> rec = e.vectors * Mat3<double>::diagonal(e.values) * transpose(e.vectors);
  const Mat3<double> orth = transpose(e.vectors) * e.vectors - Mat3<double>::identity();
  double r = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      r = std::max({r, std::fabs(rec.a[i][j] - m.a[i][j]), std::fabs(orth.a[i][j])});
  return r;
}

// (1/3) * flux of X - p through a parametrised surface patch (quadrature over [u0,u1]x[v0,v1],
// central differences of point_at); its area in *area: the divergence theorem as a second,
// independent volume algorithm. When `outward_ref` is given, each normal is flipped to point away
// from outward_ref(u, v) (for open lateral surfaces); otherwise the parametrisation's orientation
// is used.
template <class F, class G>
double flux_volume(F&& pt, G&& outward_ref, double u0, double u1, double v0, double v1,
                   const Vec3<double>& p, int nu, int nv, double* area = nullptr) {
  // Midpoint rule in u (the periodic angle: spectrally accurate), two-point Gauss-Legendre on
  // each of the nv cells in v (exact for cubics).
  const double hu = (u1 - u0) / nu, hv = (v1 - v0) / nv, e = 1e-6, g = hv / (2 * std::sqrt(3.0));
  double s = 0, a = 0;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j)
      for (const double off : {-g, g}) {
        const double u = u0 + (i + 0.5) * hu, v = v0 + (j + 0.5) * hv + off;
        const Vec3<double> x = pt(u, v);
        Vec3<double> nn =
            cross((pt(u + e, v) - pt(u - e, v)) / (2 * e), (pt(u, v + e) - pt(u, v - e)) / (2 * e));
        const Vec3<double> ref = outward_ref(u, v);
        if (!(ref == x) && dot(nn, x - ref) < 0) nn = -nn;
        s += dot(x - p, nn) * hu * hv / 2;
        a += length(nn) * hu * hv / 2;
      }
  if (area) *area = a;
  return s / 3;
}
}  // namespace

TEST(EllipsoidEigenSymmetric, RandomMatricesDecomposeWithSmallResidual) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 2000; ++trial) {
    Mat3<double> m{};
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j) m.a[i][j] = m.a[j][i] = rng.uniform<double>(-10, 10);
    const auto e = eigen_symmetric(m);
    ASSERT_EQ(e.status, Status::ok);
    EXPECT_LE(eig_residual(e, m), 64 * eps_v<double> * 30);
    EXPECT_LE(e.values[0], e.values[1]);
    EXPECT_LE(e.values[1], e.values[2]);
    EXPECT_NEAR(determinant(e.vectors), 1.0, 1e-13);
    // Independent invariants: trace and determinant.
    EXPECT_NEAR(e.values[0] + e.values[1] + e.values[2], trace(m), 1e-12 * 30);
    EXPECT_NEAR(e.values[0] * e.values[1] * e.values[2], determinant(m), 1e-11 * 1000);
  }
}

TEST(EllipsoidEigenSymmetric, RepeatedZeroExtremeAndNonFinite) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 200; ++trial) {
    // Repeated eigenvalues (1, 1, 2) and (0, 0, 3) in a random frame.
    const Mat3<double> r = random_rotation<double>(rng);
    for (const Vec3<double> d :
         {Vec3<double>{1, 1, 2}, Vec3<double>{0, 0, 3}, Vec3<double>{-2, 5, 5}}) {
      const Mat3<double> m = r * Mat3<double>::diagonal(d) * transpose(r);
      const auto e = eigen_symmetric(m);
      ASSERT_EQ(e.status, Status::ok);
      EXPECT_LE(eig_residual(e, m), 1e-13);
      Vec3<double> s = d;
      std::sort(&s.x, &s.x + 3);
      EXPECT_TRUE(vec_near(e.values, s, 1e-13));
    }
  }
  // Scaling by huge and tiny powers leaves the decomposition intact (no overflow / underflow).
  const Mat3<double> base{{{2, 1, 0}, {1, 2, 1}, {0, 1, 2}}};
  for (const double s : {1e300, 1e-300, 1e-310}) {
    const auto e = eigen_symmetric(base * s);
    ASSERT_EQ(e.status, Status::ok);
    EXPECT_NEAR(e.values[0] / s, 2 - std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(e.values[2] / s, 2 + std::sqrt(2.0), 1e-12);
  }
  const auto z = eigen_symmetric(Mat3<double>{});
  EXPECT_EQ(z.status, Status::ok);
  EXPECT_EQ(z.values, (Vec3<double>{}));
  EXPECT_EQ(z.vectors, Mat3<double>::identity());
  Mat3<double> bad = base;
  bad.a[0][1] = std::numeric_limits<double>::quiet_NaN();
  const auto b = eigen_symmetric(bad);
  EXPECT_EQ(b.status, Status::non_finite_input);
  EXPECT_TRUE(std::isnan(b.values[0]));
}

TYPED_TEST(EllipsoidTest, PointAtSatisfiesBothImplicitForms) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 500; ++trial) {
    const auto e = random_ellipsoid<T>(rng);
    const Mat3<T> m = implicit_matrix(e);
    for (int k = 0; k < 5; ++k) {
      const Vec2<T> tp{rng.uniform<T>(0, 2 * pi_v<T>), rng.uniform<T>(0, pi_v<T>)};
      const Vec3<T> p = point_at(e, tp);
      // Extents in [0.5, 3]: the relative conditioning is at most (3 / 0.5)^2 = 36.
      EXPECT_NEAR(signed_value(e, p), T(0), tol<T>(64, 36));
      const Vec3<T> d = p - e.center;
      EXPECT_NEAR(dot(d, m * d), T(1), tol<T>(128, 36));
    }
  }
}

TYPED_TEST(EllipsoidTest, ImplicitRoundTrip) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 500; ++trial) {
    const auto e = random_ellipsoid<T>(rng);
    const auto back = ellipsoid_from_implicit(e.center, implicit_matrix(e));
    ASSERT_TRUE(back.has_value());
    // Same matrix (hence same surface), extents sorted decreasingly, right-handed axes.
    const Mat3<T> m0 = implicit_matrix(e), m1 = implicit_matrix(*back);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(m1.a[i][j], m0.a[i][j], tol<T>(256, 4));
    EXPECT_GE(back->extent[0], back->extent[1]);
    EXPECT_GE(back->extent[1], back->extent[2]);
    EXPECT_NEAR(dot(cross(back->axis[0], back->axis[1]), back->axis[2]), T(1), tol<T>(16));
    EXPECT_NEAR(volume(*back), volume(e), tol<T>(256, volume(e)));
  }
  // Not positive definite, or not finite.
  EXPECT_FALSE(ellipsoid_from_implicit(Vec3<T>{}, Mat3<T>::diagonal({1, 1, 0})).has_value());
  EXPECT_FALSE(ellipsoid_from_implicit(Vec3<T>{}, Mat3<T>::diagonal({1, -1, 1})).has_value());
  EXPECT_FALSE(ellipsoid_from_implicit(
                   Vec3<T>{}, Mat3<T>::diagonal({1, std::numeric_limits<T>::infinity(), 1}))
                   .has_value());
  EXPECT_FALSE(ellipsoid_from_implicit(Vec3<T>{std::numeric_limits<T>::quiet_NaN(), 0, 0},
                                       Mat3<T>::identity())
                   .has_value());
  const auto unit = ellipsoid_from_implicit(Vec3<T>{}, Mat3<T>::diagonal({4, 1, T(0.25)}));
  ASSERT_TRUE(unit.has_value());
  EXPECT_TRUE(vec_near(unit->extent, Vec3<T>{2, 1, T(0.5)}, tol<T>(8, 2)));
}

TYPED_TEST(EllipsoidTest, VolumeMatchesMonteCarloAndBoxIsTight) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const auto e = random_ellipsoid<T>(rng);
  const auto box = bounding_box(e);
  // Tight box: sampled surface points stay inside, and the extreme samples come close to it.
  Vec3<T> lo = splat<T, 3>(T(1e30)), hi = splat<T, 3>(T(-1e30));
  for (int i = 0; i < 400; ++i)
    for (int j = 0; j <= 200; ++j) {
      const Vec3<T> p = point_at(e, Vec2<T>{T(i) * pi_v<T> / 200, T(j) * pi_v<T> / 200});
      lo = cwise_min(lo, p);
      hi = cwise_max(hi, p);
    }
  for (int k = 0; k < 3; ++k) {
    EXPECT_LE(box.min[k], lo[k] + tol<T>(64, 10));
    EXPECT_GE(box.max[k], hi[k] - tol<T>(64, 10));
    // Grid spacing pi/200: the sampled extreme is within (1 - cos(pi/200)) * 3 * 2 of the max.
    EXPECT_LE(lo[k] - box.min[k], T(1e-3));
    EXPECT_LE(box.max[k] - hi[k], T(1e-3));
  }
  const int n = 20000;
  int hits = 0;
  for (int k = 0; k < n; ++k) {
    Vec3<T> p{};
    for (int i = 0; i < 3; ++i) p[i] = rng.uniform<T>(box.min[i], box.max[i]);
    hits += signed_value(e, p) <= T(0);
  }
  const double frac = double(hits) / n, expect = double(volume(e)) / double(volume(box));
  EXPECT_NEAR(frac, expect, 5 * std::sqrt(expect * (1 - expect) / n));  // 5 binomial sigma
}

TYPED_TEST(EllipsoidTest, Degenerate) {
  using T = TypeParam;
  const Ellipsoid3<T> flat{{0, 0, 0}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {1, 2, 0}};
  EXPECT_EQ(volume(flat), T(0));
  const Ellipsoid3<T> bad{{0, 0, 0}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {1, -2, 1}};
  EXPECT_TRUE(std::isnan(volume(bad)));
  // A sphere as an ellipsoid.
  const Ellipsoid3<T> s{{1, 1, 1}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {2, 2, 2}};
  EXPECT_NEAR(volume(s), T(32) / T(3) * pi_v<T>, tol<T>(8, 40));
  EXPECT_TRUE(vec_near(point_at(s, Vec2<T>{0, 0}), Vec3<T>{1, 1, 3}, tol<T>(8, 3)));
}

TYPED_TEST(EllipsoidTest, VolumeByDivergenceTheorem) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const auto e = random_ellipsoid<T>(rng);
  Ellipsoid3<double> ed{
      vec_cast<double>(e.center),
      {vec_cast<double>(e.axis[0]), vec_cast<double>(e.axis[1]), vec_cast<double>(e.axis[2])},
      vec_cast<double>(e.extent)};
  const auto pt = [&](double a, double b) { return point_at(ed, Vec2<double>{a, b}); };
  const auto ref = [&](double, double) { return ed.center; };
  const double v =
      flux_volume(pt, ref, 0, 2 * pi_v<double>, 0, pi_v<double>, Vec3<double>{1, 1, 1}, 64, 32);
  EXPECT_NEAR(double(volume(e)), v, 1e-6 * v + double(tol<T>(64)) * v);
}
