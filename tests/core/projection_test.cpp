// SPDX-License-Identifier: BSL-1.0
// Tests for core/projection.hpp (row core.projection; figures 4.26-4.31). Oracles: exact GMP
// rationals for the three plane projections (their images are rational in the unnormalised
// inputs), geometric invariants (image on the plane, displacement parallel to the normal /
// direction / through the eye), idempotence, and invariance of the cross-ratio.
#include <locus/core/projection.hpp>

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
class ProjectionTest : public ::testing::Test {};
TYPED_TEST_SUITE(ProjectionTest, locus_test::RealTypes);

static_assert(cross_ratio(0.0, 1.0, 2.0, 3.0).value() == 4.0 / 3.0);
static_assert(!cross_ratio(0.0, 1.0, 1.0, 3.0).has_value());
static_assert(dehomogenize(Vec3d{2, 4, 2}).value() == Vec2d{1, 2});

namespace {

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
template <int N>
QVec<N> qsub(const QVec<N>& a, const QVec<N>& b) {
  QVec<N> r;
  for (size_t i = 0; i < size_t(N); ++i) r[i] = a[i] - b[i];
  return r;
}
// a + f b
template <int N>
QVec<N> qaxpy(const QVec<N>& a, const mpq_class& f, const QVec<N>& b) {
  QVec<N> r;
  for (size_t i = 0; i < size_t(N); ++i) r[i] = a[i] + f * b[i];
  return r;
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

template <class T, int N>
Vec<T, N> apply(const Mat<T, N + 1, N + 1>& m, const Vec<T, N>& p) {
  const auto r = apply_projective(m, p);
  EXPECT_TRUE(r.has_value());
  return r.value_or(Vec<T, N>{});
}

template <class T, int M>
T max_entry(const Mat<T, M, M>& m) {
  T s = 0;
  for (int r = 0; r < M; ++r)
    for (int c = 0; c < M; ++c) s = std::max(s, std::abs(m.a[r][c]));
  return s;
}

// The component of v orthogonal to the unit vector u.
template <class T, int N>
Vec<T, N> reject(const Vec<T, N>& v, const Vec<T, N>& u) {
  return v - u * dot(u, v);
}

}  // namespace

// ---- orthographic ---------------------------------------------------------------------------

TYPED_TEST(ProjectionTest, OrthographicProjectionFigure4_26) {
  using T = TypeParam;
  // Onto the plane z = 1 (any normal length, either sign): drops the z coordinate to 1.
  const auto m = orthographic_projection(Vec3<T>{7, -3, 1}, Vec3<T>{0, 0, -4});
  ASSERT_TRUE(m.has_value());
  EXPECT_EQ(apply(*m, Vec3<T>{2, 3, 9}), (Vec3<T>{2, 3, 1}));
  EXPECT_EQ(m->a[3][0], T(0));  // affine: last row 0 0 0 1
  EXPECT_EQ(m->a[3][3], T(1));

  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 500; ++k) {
    const auto q0 = rng.vec<T, 3>(-10, 10), p = rng.vec<T, 3>(-10, 10);
    const auto nrm = rng.vec<T, 3>(-2, 2);
    if (length(nrm) < T(0.1)) continue;
    const auto pm = orthographic_projection(q0, nrm);
    ASSERT_TRUE(pm.has_value());
    const auto img = apply(*pm, p);
    const auto n = normalize(nrm);
    // On the plane; the displacement is parallel to the normal.
    EXPECT_NEAR(dot(n, Vec3<T>(img - q0)), T(0), tol<T>(32, T(40)));
    EXPECT_TRUE(vec_near(reject(Vec3<T>(p - img), n), Vec3<T>{}, tol<T>(32, T(40))));
    // Exact oracle: p - ((p - q) . n / (n . n)) n.
    const auto qn = q(nrm), qp = q(p);
    const auto want = qaxpy<3>(qp, -qdot<3>(qsub<3>(qp, q(q0)), qn) / qdot<3>(qn, qn), qn);
    EXPECT_TRUE(near_exact(img, want, tol<T>(32, T(40))));
    // Idempotent: projecting twice is projecting once.
    const auto twice = *pm * *pm;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        EXPECT_NEAR(twice.a[r][c], pm->a[r][c], tol<T>(16, r < 3 && c == 3 ? T(30) : T(2)));
    // Rank 3: the normal direction is annihilated, so there is no inverse.
    EXPECT_NEAR(determinant(*pm), T(0), tol<T>(16, T(30)));
    // 2D: projection onto a line.
    const auto q2 = rng.vec<T, 2>(-10, 10), n2 = rng.unit<T, 2>(), p2 = rng.vec<T, 2>(-10, 10);
    const auto m2 = orthographic_projection(q2, n2);
    ASSERT_TRUE(m2.has_value());
    const auto i2 = apply(*m2, p2);
    EXPECT_NEAR(dot(n2, Vec2<T>(i2 - q2)), T(0), tol<T>(32, T(40)));
    EXPECT_NEAR(perp_dot(Vec2<T>(p2 - i2), n2), T(0), tol<T>(32, T(40)));
  }
  const T nan = std::numeric_limits<T>::quiet_NaN();
  EXPECT_FALSE(orthographic_projection(Vec3<T>{}, Vec3<T>{}).has_value());
  EXPECT_FALSE(orthographic_projection(Vec3<T>{}, Vec3<T>{0, nan, 1}).has_value());
  EXPECT_FALSE(orthographic_projection(Vec2<T>{nan, 0}, Vec2<T>{0, 1}).has_value());
}

// ---- oblique --------------------------------------------------------------------------------

TYPED_TEST(ProjectionTest, ObliqueProjectionFigures4_27_4_28) {
  using T = TypeParam;
  // Onto z = 0 along (1, 0, 1): (x, y, z) -> (x - z, y, 0) (the edge-on view of figure 4.28).
  const auto m = oblique_projection(Vec3<T>{}, Vec3<T>{0, 0, 1}, Vec3<T>{1, 0, 1});
  ASSERT_TRUE(m.has_value());
  EXPECT_TRUE(vec_near(apply(*m, Vec3<T>{5, 2, 3}), Vec3<T>{2, 2, 0}, tol<T>(8, T(5))));

  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 500; ++k) {
    const auto q0 = rng.vec<T, 3>(-10, 10), p = rng.vec<T, 3>(-10, 10);
    const auto nrm = rng.vec<T, 3>(-2, 2), dir = rng.vec<T, 3>(-2, 2);
    if (length(nrm) < T(0.1) || length(dir) < T(0.1)) continue;
    const auto n = normalize(nrm), d = normalize(dir);
    const T cosang = std::abs(dot(n, d));
    if (cosang < T(0.05)) continue;  // grazing directions: conditioning 1/cos, tested below
    const auto pm = oblique_projection(q0, nrm, dir);
    ASSERT_TRUE(pm.has_value());
    const auto img = apply(*pm, p);
    const T scale = T(40) / cosang;
    EXPECT_NEAR(dot(n, Vec3<T>(img - q0)), T(0), tol<T>(64, scale));
    EXPECT_TRUE(vec_near(reject(Vec3<T>(p - img), d), Vec3<T>{}, tol<T>(64, scale)));
    // Exact oracle: p - ((p - q) . n / (d . n)) d.
    const auto qn = q(nrm), qd = q(dir), qp = q(p);
    const auto want = qaxpy<3>(qp, -qdot<3>(qsub<3>(qp, q(q0)), qn) / qdot<3>(qd, qn), qd);
    EXPECT_TRUE(near_exact(img, want, tol<T>(64, scale)));
    // Points of the plane are fixed; the map is idempotent.
    const auto on = q0 + normalize(cross(n, rng.unit<T, 3>())) * T(3);
    EXPECT_TRUE(vec_near(apply(*pm, on), on, tol<T>(64, scale)));
    const auto twice = *pm * *pm;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        EXPECT_NEAR(twice.a[r][c], pm->a[r][c], tol<T>(64, scale * max_entry(*pm) / T(10)));
    // Along the normal it is the orthographic projection.
    const auto ortho = orthographic_projection(q0, nrm), along_n = oblique_projection(q0, nrm, nrm);
    ASSERT_TRUE(ortho && along_n);
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) EXPECT_NEAR(along_n->a[r][c], ortho->a[r][c], tol<T>(16, T(30)));
  }
  // A direction parallel to the plane (or zero) has no projection; a nearly parallel one is
  // finite and still lands on the plane.
  EXPECT_FALSE(oblique_projection(Vec3<T>{}, Vec3<T>{0, 0, 1}, Vec3<T>{1, 2, 0}).has_value());
  EXPECT_FALSE(oblique_projection(Vec3<T>{}, Vec3<T>{0, 0, 1}, Vec3<T>{}).has_value());
  EXPECT_FALSE(oblique_projection(Vec3<T>{}, Vec3<T>{}, Vec3<T>{0, 0, 1}).has_value());
  EXPECT_FALSE(
      oblique_projection(Vec2<T>{}, Vec2<T>{0, 1}, Vec2<T>{std::numeric_limits<T>::infinity(), 1})
          .has_value());
  const T small = T(1) / T(1024);
  const auto near_par = oblique_projection(Vec3<T>{}, Vec3<T>{0, 0, 1}, Vec3<T>{1, 0, small});
  ASSERT_TRUE(near_par.has_value());
  const auto img = apply(*near_par, Vec3<T>{0, 0, 1});
  EXPECT_NEAR(img.x, -T(1) / small, tol<T>(8, T(1) / small));
  EXPECT_NEAR(img.z, T(0), tol<T>(8, T(1) / small));
}

// ---- perspective ----------------------------------------------------------------------------

TYPED_TEST(ProjectionTest, PerspectiveProjectionFigure4_29) {
  using T = TypeParam;
  // Eye at the origin, plane z = -1: (x, y, z) -> (-x/z, -y/z, -1).
  const auto m = perspective_projection(Vec3<T>{}, Vec3<T>{0, 0, -1}, Vec3<T>{0, 0, 1});
  ASSERT_TRUE(m.has_value());
  EXPECT_TRUE(vec_near(apply(*m, Vec3<T>{2, 4, -4}), Vec3<T>{T(0.5), 1, -1}, tol<T>(4)));
  // The eye plane z = 0 maps to infinity.
  EXPECT_FALSE(apply_projective(*m, Vec3<T>{1, 2, 0}).has_value());

  Rng rng;
  SCOPED_TRACE(rng.trace());
  int checked = 0;
  for (int k = 0; k < 600; ++k) {
    const auto eye = rng.vec<T, 3>(-10, 10), q0 = rng.vec<T, 3>(-10, 10);
    const auto p = rng.vec<T, 3>(-10, 10), nrm = rng.vec<T, 3>(-2, 2);
    if (length(nrm) < T(0.1)) continue;
    const auto n = normalize(nrm);
    const T h = dot(n, Vec3<T>(q0 - eye));  // eye height over the plane
    const T hp = dot(n, Vec3<T>(p - eye));  // point height over the eye plane
    if (std::abs(h) < T(0.5) || std::abs(hp) < T(0.5)) continue;
    const auto pm = perspective_projection(eye, q0, nrm);
    ASSERT_TRUE(pm.has_value());
    const auto img = apply(*pm, p);
    // The image is at distance up to |h / hp| * |p - eye| from the eye; errors scale with it.
    const T scale = (T(1) + std::abs(h / hp)) * T(60);
    EXPECT_NEAR(dot(n, Vec3<T>(img - q0)), T(0), tol<T>(64, scale));
    // Collinear with the eye.
    const auto pe = normalize(Vec3<T>(p - eye));
    EXPECT_TRUE(vec_near(reject(Vec3<T>(img - eye), pe), Vec3<T>{}, tol<T>(64, scale)));
    // Exact oracle: eye + ((q - eye) . n / ((p - eye) . n)) (p - eye).
    const auto qn = q(nrm), qe = q(eye), qpe = qsub<3>(q(p), qe);
    const auto want = qaxpy<3>(qe, qdot<3>(qsub<3>(q(q0), qe), qn) / qdot<3>(qpe, qn), qpe);
    EXPECT_TRUE(near_exact(img, want, tol<T>(64, scale)));
    // Plane points are fixed, and the eye is the kernel: m (eye, 1) = 0.
    const auto on = q0 + normalize(cross(n, rng.unit<T, 3>())) * T(3);
    EXPECT_TRUE(vec_near(apply(*pm, on), on, tol<T>(64, T(60))));
    const Vec4<T> ke = *pm * Vec4<T>{eye.x, eye.y, eye.z, T(1)};
    EXPECT_TRUE(vec_near(ke, Vec4<T>{}, tol<T>(64, max_entry(*pm) * T(30))));
    ++checked;
  }
  EXPECT_GT(checked, 200);
  // The eye on the plane gives no projection; non-finite input neither.
  EXPECT_FALSE(
      perspective_projection(Vec3<T>{1, 2, 0}, Vec3<T>{5, 5, 0}, Vec3<T>{0, 0, 1}).has_value());
  EXPECT_FALSE(perspective_projection(Vec3<T>{}, Vec3<T>{0, 0, 1}, Vec3<T>{}).has_value());
  EXPECT_FALSE(perspective_projection(Vec2<T>{std::numeric_limits<T>::quiet_NaN(), 0},
                                      Vec2<T>{0, 1}, Vec2<T>{0, 1})
                   .has_value());
  // 2D: projection from an eye onto a line; x = 2 seen from the origin.
  const auto m2 = perspective_projection(Vec2<T>{}, Vec2<T>{2, 0}, Vec2<T>{1, 0});
  ASSERT_TRUE(m2.has_value());
  EXPECT_TRUE(vec_near(apply(*m2, Vec2<T>{4, 3}), Vec2<T>{2, T(1.5)}, tol<T>(4)));
  EXPECT_TRUE(
      vec_near(apply(*m2, Vec2<T>{-1, 3}), Vec2<T>{2, -6}, tol<T>(16)));  // behind: through the eye
}

// ---- cross-ratio ----------------------------------------------------------------------------

TYPED_TEST(ProjectionTest, CrossRatioFigure4_30) {
  using T = TypeParam;
  // Positions 0, 1, 2, 3: ((2 - 0)(3 - 1)) / ((2 - 1)(3 - 0)) = 4/3.
  const auto r =
      cross_ratio(Vec3<T>{1, 1, 1}, Vec3<T>{2, 3, 4}, Vec3<T>{3, 5, 7}, Vec3<T>{4, 7, 10});
  ASSERT_TRUE(r.has_value());
  EXPECT_NEAR(*r, T(4) / T(3), tol<T>(8));
  // Harmonic division: positions -1, 1, 1/3, 3 give ((1/3 + 1)(3 - 1)) / ((1/3 - 1)(3 + 1)) = -1.
  EXPECT_NEAR(*cross_ratio(T(-1), T(1), T(1) / T(3), T(3)), T(-1), tol<T>(8));

  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 300; ++k) {
    const T a = rng.uniform<T>(-5, 5), b = rng.uniform<T>(-5, 5), c = rng.uniform<T>(-5, 5),
            d = rng.uniform<T>(-5, 5);
    const auto x = cross_ratio(a, b, c, d);
    if (std::abs(c - b) < T(0.1) || std::abs(d - a) < T(0.1)) continue;
    ASSERT_TRUE(x.has_value());
    // Exact rational oracle.
    const mpq_class qa{double(a)}, qb{double(b)}, qc{double(c)}, qd{double(d)};
    const double exact = mpq_class((qc - qa) * (qd - qb) / ((qc - qb) * (qd - qa))).get_d();
    EXPECT_NEAR(double(*x), exact, double(tol<T>(16, T(1) + std::abs(T(exact))) * T(100)));
    // Symmetries: (A, B; C, D) = (B, A; D, C) = (C, D; A, B), and swapping C, D inverts it.
    EXPECT_NEAR(*cross_ratio(b, a, d, c), *x, tol<T>(64, T(1) + std::abs(*x)) * T(100));
    EXPECT_NEAR(*cross_ratio(c, d, a, b), *x, tol<T>(64, T(1) + std::abs(*x)) * T(100));
    if (std::abs(c - a) > T(0.1) && std::abs(d - b) > T(0.1)) {
      const auto y = cross_ratio(a, b, d, c);
      ASSERT_TRUE(y.has_value());
      EXPECT_NEAR(*x * *y, T(1), tol<T>(64, T(100)));
    }
  }
  // Degenerate: C = B, D = A, all points equal, non-finite input.
  EXPECT_FALSE(cross_ratio(T(0), T(1), T(1), T(2)).has_value());
  EXPECT_FALSE(cross_ratio(T(0), T(1), T(2), T(0)).has_value());
  EXPECT_FALSE(cross_ratio(Vec2<T>{1, 1}, Vec2<T>{1, 1}, Vec2<T>{1, 1}, Vec2<T>{1, 1}).has_value());
  EXPECT_FALSE(cross_ratio(T(0), std::numeric_limits<T>::quiet_NaN(), T(1), T(2)).has_value());
  EXPECT_FALSE(cross_ratio(Vec2<T>{0, 0}, Vec2<T>{1, std::numeric_limits<T>::infinity()},
                           Vec2<T>{2, 0}, Vec2<T>{3, 0})
                   .has_value());
  // Only ratios matter, so the result is the same for a tiny and a huge copy of the line.
  const T s = T(1e-30);
  EXPECT_NEAR(
      *cross_ratio(Vec2<T>{0, 0}, Vec2<T>{s, s}, Vec2<T>{2 * s, 2 * s}, Vec2<T>{3 * s, 3 * s}),
      T(4) / T(3), tol<T>(16));
}

TYPED_TEST(ProjectionTest, PerspectiveProjectionPreservesCrossRatioFigure4_31) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int checked = 0;
  for (int k = 0; k < 400; ++k) {
    // Four points on a random line at well-separated positions.
    std::array<T, 4> t{};
    for (auto& ti : t) ti = rng.uniform<T>(-4, 4);
    std::sort(t.begin(), t.end());
    if (t[1] - t[0] < T(0.5) || t[2] - t[1] < T(0.5) || t[3] - t[2] < T(0.5)) continue;
    std::shuffle(t.begin(), t.end(), rng.engine());
    const auto base = rng.vec<T, 3>(-3, 3), u = rng.unit<T, 3>();
    std::array<Vec3<T>, 4> p;
    for (size_t i = 0; i < 4; ++i) p[i] = base + u * t[i];
    const auto before = cross_ratio(t[0], t[1], t[2], t[3]);
    ASSERT_TRUE(before.has_value());

    const auto eye = rng.vec<T, 3>(-10, 10), q0 = rng.vec<T, 3>(-10, 10), n = rng.unit<T, 3>();
    const auto pm = perspective_projection(eye, q0, n);
    if (!pm) continue;
    // Skip views in which a point is nearly on the eye plane (its image runs off to infinity)
    // or the line passes near the eye (all images collapse to one point): conditioning.
    bool ok = std::abs(dot(n, Vec3<T>(q0 - eye))) > T(1);
    for (const auto& pi : p) ok = ok && std::abs(dot(n, Vec3<T>(pi - eye))) > T(1);
    const auto closest = base + u * dot(u, Vec3<T>(eye - base));
    ok = ok && length(Vec3<T>(closest - eye)) > T(1);
    if (!ok) continue;
    std::array<Vec3<T>, 4> img;
    for (size_t i = 0; i < 4; ++i) img[i] = apply(*pm, p[i]);
    // The images are collinear (on the line where the plane through eye and line meets the
    // target plane) and keep the cross-ratio.
    const auto after = cross_ratio(img[0], img[1], img[2], img[3]);
    ASSERT_TRUE(after.has_value());
    // Conditioning: the images are stretched by up to |h / hp| and their spacing shrinks by the
    // same mechanism; measure it from the images themselves (span over smallest gap).
    T span = 0, gap = std::numeric_limits<T>::max();
    for (size_t i = 0; i < 4; ++i)
      for (size_t j = i + 1; j < 4; ++j) {
        const T dij = length(Vec3<T>(img[i] - img[j]));
        span = std::max(span, dij);
        gap = std::min(gap, dij);
      }
    const T extent =
        std::max({length(img[0]), length(img[1]), length(img[2]), length(img[3]), T(1)});
    const T cond = (extent / gap) * (span / gap);
    EXPECT_NEAR(*after, *before, tol<T>(64, cond * (T(1) + std::abs(*before))))
        << "span " << span << " gap " << gap << " extent " << extent;
    ++checked;
  }
  EXPECT_GT(checked, 50);
  // Figure 4.31: perspective does not preserve simple ratios (it is not affine), only the
  // cross-ratio. Eye at the origin, plane z = -1: B is the midpoint of A and C, but its image
  // (1/2) is not the midpoint of the images 0 and 2/3.
  const auto pz = perspective_projection(Vec3<T>{}, Vec3<T>{0, 0, -1}, Vec3<T>{0, 0, 1});
  ASSERT_TRUE(pz.has_value());
  const auto ia = apply(*pz, Vec3<T>{0, 0, -1}), ib = apply(*pz, Vec3<T>{1, 0, -2}),
             ic = apply(*pz, Vec3<T>{2, 0, -3});
  EXPECT_NEAR(ib.x, T(0.5), tol<T>(4));
  EXPECT_NEAR(ic.x, T(2) / T(3), tol<T>(4));
  EXPECT_GT(std::abs(ib.x - (ia.x + ic.x) / 2), T(0.1));
  // 2D: a pencil of four lines through an eye cuts every line in the same cross-ratio.
  const auto m1 = perspective_projection(Vec2<T>{0, 0}, Vec2<T>{0, 1}, Vec2<T>{0, 1});
  const auto m2 = perspective_projection(Vec2<T>{0, 0}, Vec2<T>{2, 0}, Vec2<T>{1, 1});
  ASSERT_TRUE(m1 && m2);
  const std::array<Vec2<T>, 4> src{{{-2, 3}, {1, 4}, {2, 2}, {5, 3}}};
  std::array<Vec2<T>, 4> a1, a2;
  for (size_t i = 0; i < 4; ++i) {
    a1[i] = apply(*m1, src[i]);
    a2[i] = apply(*m2, src[i]);
  }
  const auto r1 = cross_ratio(a1[0], a1[1], a1[2], a1[3]),
             r2 = cross_ratio(a2[0], a2[1], a2[2], a2[3]);
  ASSERT_TRUE(r1 && r2);
  // Exact value from the slopes x/y on the line y = 1: -2/3, 1/4, 1, 5/3.
  const T want = ((T(1) - T(-2) / T(3)) * (T(5) / T(3) - T(1) / T(4))) /
                 ((T(1) - T(1) / T(4)) * (T(5) / T(3) - T(-2) / T(3)));
  EXPECT_NEAR(*r1, want, tol<T>(32, T(4)));
  EXPECT_NEAR(*r2, want, tol<T>(64, T(4)));
}

// ---- homogeneous helpers ----------------------------------------------------------------------

TYPED_TEST(ProjectionTest, HomogeneousDivideReportsPointsAtInfinity) {
  using T = TypeParam;
  EXPECT_EQ(dehomogenize(Vec4<T>{2, 4, 6, 2}).value(), (Vec3<T>{1, 2, 3}));
  EXPECT_EQ(dehomogenize(Vec4<T>{2, 4, 6, -2}).value(), (Vec3<T>{-1, -2, -3}));
  EXPECT_FALSE(dehomogenize(Vec4<T>{1, 2, 3, 0}).has_value());
  EXPECT_FALSE(dehomogenize(Vec3<T>{1, std::numeric_limits<T>::quiet_NaN(), 1}).has_value());
  EXPECT_FALSE(dehomogenize(Vec3<T>{1, 1, std::numeric_limits<T>::infinity()}).has_value());
  // Overflow in the divide is a point at infinity too.
  EXPECT_FALSE(dehomogenize(Vec2<T>{std::numeric_limits<T>::max(), std::numeric_limits<T>::min()})
                   .has_value());
  const auto pp = project_point(Mat4<T>::identity(), Vec3<T>{1, 2, 3});
  EXPECT_TRUE(pp.in_front);
  EXPECT_EQ(pp.w, T(1));
  EXPECT_EQ(pp.point, (Vec3<T>{1, 2, 3}));
}

// ---- camera matrices ------------------------------------------------------------------------

TYPED_TEST(ProjectionTest, LookAtBuildsRightHandedViewMatrix) {
  using T = TypeParam;
  // Camera at (0, 0, 5) looking at the origin with +y up is a translation by -5 in z.
  const auto v0 = look_at(Vec3<T>{0, 0, 5}, Vec3<T>{}, Vec3<T>{0, 1, 0});
  ASSERT_TRUE(v0.has_value());
  EXPECT_TRUE(vec_near(apply(*v0, Vec3<T>{1, 2, 3}), Vec3<T>{1, 2, -2}, tol<T>(8)));

  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 300; ++k) {
    const auto eye = rng.vec<T, 3>(-10, 10), target = rng.vec<T, 3>(-10, 10);
    const auto up = rng.unit<T, 3>();
    const auto f = normalize(Vec3<T>(target - eye));
    if (length(Vec3<T>(target - eye)) < T(0.5) || length(cross(f, up)) < T(0.2)) continue;
    const auto v = look_at(eye, target, up);
    ASSERT_TRUE(v.has_value());
    const T dist = length(Vec3<T>(target - eye));
    // Eye to the origin, target onto the -z axis at its distance.
    EXPECT_TRUE(vec_near(apply(*v, eye), Vec3<T>{}, tol<T>(32, T(20))));
    EXPECT_TRUE(vec_near(apply(*v, target), Vec3<T>{0, 0, -dist}, tol<T>(64, T(40))));
    // `up` maps into the upper half of the yz plane.
    const Vec4<T> up_v = *v * Vec4<T>{up.x, up.y, up.z, T(0)};
    EXPECT_NEAR(up_v.x, T(0), tol<T>(16));
    EXPECT_GT(up_v.y, T(0));
    // The linear part is a rotation: orthonormal rows, det +1.
    Mat3<T> r{};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r.a[i][j] = v->a[i][j];
    const auto rrt = r * transpose(r);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(rrt.a[i][j], i == j ? T(1) : T(0), tol<T>(16));
    EXPECT_NEAR(determinant(r), T(1), tol<T>(16));
    // Distances are preserved.
    const auto a = rng.vec<T, 3>(-10, 10), b = rng.vec<T, 3>(-10, 10);
    EXPECT_NEAR(length(Vec3<T>(apply(*v, a) - apply(*v, b))), length(Vec3<T>(a - b)),
                tol<T>(64, T(40)));
  }
  // Degenerate: eye = target, zero up, up parallel to the view direction, NaN.
  EXPECT_FALSE(look_at(Vec3<T>{1, 1, 1}, Vec3<T>{1, 1, 1}, Vec3<T>{0, 1, 0}).has_value());
  EXPECT_FALSE(look_at(Vec3<T>{0, 0, 5}, Vec3<T>{}, Vec3<T>{}).has_value());
  EXPECT_FALSE(look_at(Vec3<T>{0, 0, 5}, Vec3<T>{}, Vec3<T>{0, 0, 3}).has_value());
  EXPECT_FALSE(
      look_at(Vec3<T>{0, 0, 5}, Vec3<T>{}, Vec3<T>{0, std::numeric_limits<T>::quiet_NaN(), 0})
          .has_value());
}

TYPED_TEST(ProjectionTest, PerspectiveAndOrthographicClipMatrices) {
  using T = TypeParam;
  const T l = -2, r = 3, b = -1, t = 2, n = 1, f = 10;
  for (const DepthRange depth : {DepthRange::minus_one_to_one, DepthRange::zero_to_one}) {
    const T zlo = depth == DepthRange::minus_one_to_one ? T(-1) : T(0);
    const auto pm = perspective_frustum(l, r, b, t, n, f, depth);
    const auto om = orthographic_box(l, r, b, t, n, f, depth);
    ASSERT_TRUE(pm && om);
    for (int i = 0; i < 8; ++i) {
      const T sx = (i & 1) ? T(1) : T(-1), sy = (i & 2) ? T(1) : T(-1);
      const bool far_corner = (i & 4) != 0;
      const T x = sx < 0 ? l : r, y = sy < 0 ? b : t;
      const T zc = far_corner ? T(1) : zlo;
      // Frustum corner: the near rectangle scaled by f/n for the far one.
      const T sc = far_corner ? f / n : T(1);
      const auto pp = project_point(*pm, Vec3<T>{x * sc, y * sc, far_corner ? -f : -n});
      EXPECT_TRUE(pp.in_front);
      EXPECT_NEAR(pp.w, far_corner ? f : n, tol<T>(8, f));
      EXPECT_TRUE(vec_near(pp.point, Vec3<T>{sx, sy, zc}, tol<T>(32, T(10))));
      // Box corner.
      const auto op = project_point(*om, Vec3<T>{x, y, far_corner ? -f : -n});
      EXPECT_TRUE(op.in_front);
      EXPECT_EQ(op.w, T(1));
      EXPECT_TRUE(vec_near(op.point, Vec3<T>{sx, sy, zc}, tol<T>(16, T(10))));
    }
    // Depth increases monotonically from near to far.
    T prev = -std::numeric_limits<T>::infinity();
    for (T z = -n; z >= -f; z -= T(0.5)) {
      const auto pp = project_point(*pm, Vec3<T>{0, 0, z});
      ASSERT_TRUE(pp.in_front);
      EXPECT_GT(pp.point.z, prev);
      prev = pp.point.z;
    }
    // Behind the eye (z > 0) and on the eye plane (z = 0): w <= 0, reported.
    const auto behind = project_point(*pm, Vec3<T>{0, 0, 1});
    EXPECT_FALSE(behind.in_front);
    EXPECT_LT(behind.w, T(0));
    EXPECT_EQ(behind.point, (Vec3<T>{}));
    EXPECT_FALSE(project_point(*pm, Vec3<T>{1, 1, 0}).in_front);
    // The symmetric field-of-view form is the matching frustum.
    const T fovy = T(1), aspect = T(1.5);
    const auto fov = perspective_fov(fovy, aspect, n, f, depth);
    const T top = n * std::tan(fovy / 2);
    const auto fr = perspective_frustum(-top * aspect, top * aspect, -top, top, n, f, depth);
    ASSERT_TRUE(fov && fr);
    EXPECT_EQ(*fov, *fr);
    // A point on the top edge of the view cone at any depth maps to y = 1.
    const T z = -T(4);
    const auto edge = project_point(*fov, Vec3<T>{0, -z * std::tan(fovy / 2), z});
    EXPECT_NEAR(edge.point.y, T(1), tol<T>(16));
  }
  // Invalid parameters.
  EXPECT_FALSE(perspective_frustum(T(-1), T(1), T(-1), T(1), T(0), T(10)).has_value());
  EXPECT_FALSE(perspective_frustum(T(-1), T(1), T(-1), T(1), T(2), T(2)).has_value());
  EXPECT_FALSE(perspective_frustum(T(1), T(1), T(-1), T(1), T(1), T(10)).has_value());
  EXPECT_FALSE(
      perspective_frustum(T(-1), T(1), T(-1), T(1), std::numeric_limits<T>::quiet_NaN(), T(10))
          .has_value());
  EXPECT_FALSE(perspective_fov(T(0), T(1), T(1), T(10)).has_value());
  EXPECT_FALSE(perspective_fov(pi_v<T>, T(1), T(1), T(10)).has_value());
  EXPECT_FALSE(perspective_fov(T(1), T(0), T(1), T(10)).has_value());
  EXPECT_FALSE(orthographic_box(T(-1), T(1), T(2), T(2), T(1), T(10)).has_value());
  EXPECT_FALSE(orthographic_box(T(-1), T(1), T(-1), T(1), T(3), T(3)).has_value());
  EXPECT_TRUE(orthographic_box(T(-1), T(1), T(-1), T(1), T(-3), T(3)).has_value());
}
