// SPDX-License-Identifier: BSL-1.0
// Bézier rectangle and triangle patches: evaluation and partials against exact Bernstein sums
// (GMP), tensor product against curve-of-curves, normals, subdivision, control boxes, the
// collapsed-edge normal and bad input.

#include <locus/curves/bezier_surface.hpp>

#include "curve_oracle.hpp"
#include "support/typed.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace {

using namespace locus;
using curve_oracle::Q;
using curve_oracle::QVec;
using locus_test::tol;

template <class T>
class BezierSurfaceTest : public ::testing::Test {};
TYPED_TEST_SUITE(BezierSurfaceTest, locus_test::RealTypes);

// Two nested de Casteljau passes: below 4 (m + n + 2) eps * scale per derivative scale.
template <class T>
T patch_tol(int m, int n, T scale) {
  return tol(T(4 * (m + n + 2)), scale);
}

template <class T>
BezierPatch<T, 3> random_patch(locus_test::Rng& rng, int rows, int cols) {
  return {rows, cols, curve_oracle::dyadic_points<T, 3>(rng, rows * cols)};
}

/// Exact {S, S_u, S_v, S_uv} of a rectangle patch: rows in v first, then in u.
template <class T>
std::array<QVec<3>, 4> exact_patch(const BezierPatch<T, 3>& p, const Q& u, const Q& v) {
  const auto qp = curve_oracle::to_q(p.control);
  std::vector<QVec<3>> r, d;
  for (int i = 0; i < p.rows; ++i) {
    std::vector<QVec<3>> row(qp.begin() + i * p.cols, qp.begin() + (i + 1) * p.cols);
    r.push_back(curve_oracle::bezier_derivative<3>(row, 0, v));
    d.push_back(curve_oracle::bezier_derivative<3>(row, 1, v));
  }
  return {curve_oracle::bezier_derivative<3>(r, 0, u), curve_oracle::bezier_derivative<3>(r, 1, u),
          curve_oracle::bezier_derivative<3>(d, 0, u), curve_oracle::bezier_derivative<3>(d, 1, u)};
}

// Figure 9.24: a bicubic patch over a height field. Corners are exact; the boundary curves are the
// Bézier curves of the boundary rows and columns; interior points match the exact sum.
TYPED_TEST(BezierSurfaceTest, Figure9_24_BicubicPatch) {
  using T = TypeParam;
  BezierPatch<T, 3> p{4, 4, {}};
  const int h[4][4] = {{0, 1, 1, 0}, {1, 3, 2, 1}, {1, 2, 4, 1}, {0, 1, 1, 0}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      p.control.push_back({static_cast<T>(i), static_cast<T>(j), static_cast<T>(h[i][j])});
  EXPECT_EQ(degree_u(p), 3);
  EXPECT_EQ(degree_v(p), 3);
  EXPECT_EQ(point_at(p, T(0), T(0)), p.control[0]);
  EXPECT_EQ(point_at(p, T(0), T(1)), p.control[3]);
  EXPECT_EQ(point_at(p, T(1), T(0)), p.control[12]);
  EXPECT_EQ(point_at(p, T(1), T(1)), p.control[15]);
  const BezierCurve3<T> edge{{p.control[0], p.control[1], p.control[2], p.control[3]}};
  for (int j = 0; j <= 8; ++j) {
    const T t = static_cast<T>(j) / T(8);
    EXPECT_TRUE(
        locus_test::vec_near(point_at(p, T(0), t), point_at(edge, t), patch_tol(3, 3, T(4))));
    for (int k = 0; k <= 8; ++k) {
      const T s = static_cast<T>(k) / T(8);
      const auto e = exact_patch(p, Q(k, 8), Q(j, 8));
      EXPECT_TRUE(curve_oracle::near_q(point_at(p, s, t), e[0], double(patch_tol(3, 3, T(4)))));
      // Normal: unit, perpendicular to both partials, on the side of du x dv.
      const SurfaceDerivatives<T, 3> d = partials(p, s, t);
      const Vec3<T> nrm = normal_at(p, s, t);
      EXPECT_NEAR(length(nrm), T(1), tol(T(8)));
      EXPECT_NEAR(dot(nrm, d.du), T(0), tol(T(64), length(d.du)));
      EXPECT_NEAR(dot(nrm, d.dv), T(0), tol(T(64), length(d.dv)));
      EXPECT_GT(dot(nrm, cross(d.du, d.dv)), T(0));
    }
  }
}

TYPED_TEST(BezierSurfaceTest, PartialsMatchExactTensorBernstein) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 25; ++trial) {
    const int rows = rng.uniform_int(1, 5), cols = rng.uniform_int(1, 5);
    const BezierPatch<T, 3> p = random_patch<T>(rng, rows, cols);
    const T scale = curve_oracle::max_abs_points(p.control);
    const T ds = scale * T(2 * (rows + cols));  // |S_u|, |S_v| <= 2 degree max|P|
    for (int k = 0; k < 12; ++k) {
      const int a = rng.uniform_int(0, 32), b = rng.uniform_int(0, 32);
      const T u = static_cast<T>(a) / T(32), v = static_cast<T>(b) / T(32);
      const auto e = exact_patch(p, Q(a, 32), Q(b, 32));
      const SurfaceDerivatives<T, 3> d = partials(p, u, v);
      const double t0 = double(patch_tol(rows, cols, scale)),
                   t1 = double(patch_tol(rows, cols, ds));
      ASSERT_TRUE(curve_oracle::near_q(d.point, e[0], t0)) << rows << "x" << cols;
      ASSERT_TRUE(curve_oracle::near_q(d.du, e[1], t1));
      ASSERT_TRUE(curve_oracle::near_q(d.dv, e[2], t1));
      ASSERT_TRUE(
          curve_oracle::near_q(d.duv, e[3], double(patch_tol(rows, cols, ds * ds / scale))));
      EXPECT_EQ(point_at(p, u, v), d.point);
    }
  }
}

// Curve of curves in the other order (columns in u first, then the v curve) as a second,
// independent evaluation path.
TYPED_TEST(BezierSurfaceTest, TensorProductEqualsCurveOfCurves) {
  using T = TypeParam;
  locus_test::Rng rng(3);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 20; ++trial) {
    const int rows = rng.uniform_int(1, 6), cols = rng.uniform_int(1, 6);
    BezierPatch<T, 3> p{rows, cols, {}};
    for (int i = 0; i < rows * cols; ++i) p.control.push_back(rng.vec<T, 3>(T(-4), T(4)));
    for (int k = 0; k < 10; ++k) {
      const T u = rng.uniform(T(0), T(1)), v = rng.uniform(T(0), T(1));
      BezierCurve3<T> across;
      for (int j = 0; j < cols; ++j) {
        BezierCurve3<T> col;
        for (int i = 0; i < rows; ++i)
          col.control.push_back(p.control[static_cast<std::size_t>(i * cols + j)]);
        across.control.push_back(point_at(col, u));
      }
      EXPECT_TRUE(locus_test::vec_near(point_at(p, u, v), point_at(across, v),
                                       patch_tol(rows, cols, T(8))));
    }
  }
}

TYPED_TEST(BezierSurfaceTest, SubdivisionReproducesThePatch) {
  using T = TypeParam;
  locus_test::Rng rng(5);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 15; ++trial) {
    const int rows = rng.uniform_int(1, 5), cols = rng.uniform_int(1, 5);
    const BezierPatch<T, 3> p = random_patch<T>(rng, rows, cols);
    const T scale = curve_oracle::max_abs_points(p.control);
    const int cut = rng.uniform_int(1, 15);
    const T t = static_cast<T>(cut) / T(16);
    const Q tq(cut, 16);
    const PatchSplit<T, 3> su = subdivide_u(p, t), sv = subdivide_v(p, t);
    for (int a = 0; a <= 4; ++a)
      for (int b = 0; b <= 4; ++b) {
        const T x = static_cast<T>(a) / T(4), y = static_cast<T>(b) / T(4);
        const Q xq(a, 4), yq(b, 4);
        const double tl = double(patch_tol(2 * rows, 2 * cols, scale));
        EXPECT_TRUE(
            curve_oracle::near_q(point_at(su.first, x, y), exact_patch(p, tq * xq, yq)[0], tl));
        EXPECT_TRUE(curve_oracle::near_q(point_at(su.second, x, y),
                                         exact_patch(p, tq + (Q(1) - tq) * xq, yq)[0], tl));
        EXPECT_TRUE(
            curve_oracle::near_q(point_at(sv.first, x, y), exact_patch(p, xq, tq * yq)[0], tl));
        EXPECT_TRUE(curve_oracle::near_q(point_at(sv.second, x, y),
                                         exact_patch(p, xq, tq + (Q(1) - tq) * yq)[0], tl));
      }
    // The halves' control boxes lie inside the parent's (hierarchy refinement).
    const AlignedBox3<T> pb = inflate(bounding_box(p), patch_tol(rows, cols, scale));
    for (const auto* half : {&su.first, &su.second, &sv.first, &sv.second}) {
      const AlignedBox3<T> hb = bounding_box(*half);
      for (int k = 0; k < 3; ++k) {
        EXPECT_GE(hb.min[k], pb.min[k]);
        EXPECT_LE(hb.max[k], pb.max[k]);
      }
    }
  }
}

TYPED_TEST(BezierSurfaceTest, ConvexHullOfTheControlNet) {
  using T = TypeParam;
  locus_test::Rng rng(7);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 15; ++trial) {
    const int rows = rng.uniform_int(1, 5), cols = rng.uniform_int(1, 5);
    BezierPatch<T, 3> p{rows, cols, {}};
    for (int i = 0; i < rows * cols; ++i) p.control.push_back(rng.vec<T, 3>(T(-4), T(4)));
    const AlignedBox3<T> box = inflate(bounding_box(p), patch_tol(rows, cols, T(4)));
    for (int k = 0; k < 30; ++k) {
      const Vec3<T> q = point_at(p, rng.uniform(T(0), T(1)), rng.uniform(T(0), T(1)));
      for (int c = 0; c < 3; ++c) {
        EXPECT_GE(q[c], box.min[c]);
        EXPECT_LE(q[c], box.max[c]);
      }
    }
  }
}

// A patch whose u = 0 edge collapses to an apex (a dome): du x dv vanishes there; the normal is
// the limit from the interior.
TYPED_TEST(BezierSurfaceTest, CollapsedEdgeNormalIsTheInteriorLimit) {
  using T = TypeParam;
  BezierPatch<T, 3> p{3, 3, {}};
  const Vec3<T> apex{T(0), T(0), T(2)};
  for (int j = 0; j < 3; ++j) p.control.push_back(apex);
  for (int i = 1; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const T a = static_cast<T>(j) * T(0.6);
      const T r = static_cast<T>(i);
      p.control.push_back(
          {r * std::cos(a), r * std::sin(a), T(2) - static_cast<T>(i * i) * T(0.5)});
    }
  for (int j = 0; j <= 8; ++j) {
    const T v = static_cast<T>(j) / T(8);
    const SurfaceDerivatives<T, 3> d = partials(p, T(0), v);
    EXPECT_EQ(d.dv, (Vec3<T>{}));  // the collapsed edge: exactly zero
    const Vec3<T> n0 = normal_at(p, T(0), v);
    EXPECT_TRUE(is_finite(n0));
    EXPECT_NEAR(length(n0), T(1), tol(T(8)));
    // Close to the normal just inside (the surface is smooth there; O(delta) difference).
    const Vec3<T> n1 = normal_at(p, T(1e-3), v);
    EXPECT_GT(dot(n0, n1), T(0.99));
    EXPECT_NEAR(dot(n0, d.du), T(0), tol(T(64), length(d.du)));
  }
  // The same with the collapse at u = 1 (rows reversed): the sign still follows the interior.
  BezierPatch<T, 3> q{3, 3, {}};
  for (int i = 2; i >= 0; --i)
    for (int j = 0; j < 3; ++j) q.control.push_back(p.control[static_cast<std::size_t>(i * 3 + j)]);
  for (int j = 0; j <= 8; ++j) {
    const T v = static_cast<T>(j) / T(8);
    EXPECT_GT(dot(normal_at(q, T(1), v), normal_at(q, T(1) - T(1e-3), v)), T(0.99));
  }
  // A flat patch collapsed at v = 0: the normal is exactly +-z, matching the interior.
  BezierPatch<T, 3> f{
      2, 2, {{T(0), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(0)}, {T(1), T(1), T(0)}}};
  const Vec3<T> nf = normal_at(f, T(0.5), T(0));
  EXPECT_EQ(std::abs(nf.z), T(1));
  EXPECT_GT(nf.z * normal_at(f, T(0.5), T(0.5)).z, T(0));
  // Everything collapsed to one point: no normal (zero vector), never NaN.
  const BezierPatch<T, 3> pt{2, 3, std::vector<Vec3<T>>(6, Vec3<T>{T(1), T(2), T(3)})};
  EXPECT_EQ(normal_at(pt, T(0.3), T(0.6)), (Vec3<T>{}));
  // (1 - t) a + t a rounds: equal points are reproduced to a few ulps, not exactly.
  EXPECT_TRUE(locus_test::vec_near(point_at(pt, T(0.3), T(0.6)), Vec3<T>{T(1), T(2), T(3)},
                                   tol(T(8), T(3))));
}

TYPED_TEST(BezierSurfaceTest, BadInputAndClamping) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const std::vector<Vec3<T>> four{
      {T(0), T(0), T(0)}, {T(0), T(1), T(0)}, {T(1), T(0), T(0)}, {T(1), T(1), T(1)}};
  EXPECT_FALSE(is_finite(point_at(BezierPatch<T, 3>{2, 3, four}, T(0.5), T(0.5))));
  EXPECT_FALSE(is_finite(point_at(BezierPatch<T, 3>{0, 0, {}}, T(0.5), T(0.5))));
  EXPECT_FALSE(is_finite(partials(BezierPatch<T, 3>{-2, -2, four}, T(0.5), T(0.5)).du));
  EXPECT_FALSE(is_finite(BezierPatch<T, 3>{2, 3, four}));
  EXPECT_EQ(normal_at(BezierPatch<T, 3>{2, 3, four}, T(0.5), T(0.5)), (Vec3<T>{}));
  const BezierPatch<T, 3> p{2, 2, four};
  EXPECT_TRUE(is_finite(p));
  EXPECT_EQ(point_at(p, T(-1), T(2)), four[1]);
  EXPECT_EQ(point_at(p, T(5), T(-5)), four[2]);
  EXPECT_FALSE(is_finite(point_at(p, nan, T(0.5))));
  EXPECT_EQ(normal_at(p, nan, T(0.5)), (Vec3<T>{}));
  BezierPatch<T, 3> bad = p;
  bad.control[3].z = nan;
  EXPECT_FALSE(is_finite(bad));
  EXPECT_FALSE(is_finite(point_at(bad, T(0.5), T(0.5))));
  // A 1 x 1 net: the constant patch with zero partials.
  const BezierPatch<T, 3> one{1, 1, {{T(3), T(1), T(2)}}};
  const SurfaceDerivatives<T, 3> d = partials(one, T(0.4), T(0.7));
  EXPECT_EQ(d.point, one.control[0]);
  EXPECT_EQ(d.du, (Vec3<T>{}));
  EXPECT_EQ(d.dv, (Vec3<T>{}));
  // Subdividing a bad shape returns it unchanged.
  EXPECT_EQ(subdivide_u(BezierPatch<T, 3>{2, 3, four}, T(0.5)).first.control.size(), 4u);
}

// ---- triangle patches ----

/// Exact S, S_u, S_v, S_uv of a triangle patch from the monomial form (w = 1 - u - v).
template <class T>
std::array<QVec<3>, 4> exact_triangle(const BezierTriangle<T, 3>& p, const Q& u, const Q& v) {
  const int n = p.degree;
  const Q w = Q(1) - u - v;
  const auto pw = [](const Q& x, int e) { return e < 0 ? Q(0) : curve_oracle::qpow(x, e); };
  std::array<QVec<3>, 4> r{};
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i + j <= n; ++i) {
      const int k = n - i - j;
      const Q c = curve_oracle::binom(n, i) * curve_oracle::binom(n - i, j);
      const Q f = pw(u, i) * pw(v, j) * pw(w, k);
      const Q fu = i * pw(u, i - 1) * pw(v, j) * pw(w, k) - k * pw(u, i) * pw(v, j) * pw(w, k - 1);
      const Q fv = j * pw(u, i) * pw(v, j - 1) * pw(w, k) - k * pw(u, i) * pw(v, j) * pw(w, k - 1);
      const Q fuv = i * j * pw(u, i - 1) * pw(v, j - 1) * pw(w, k) -
                    i * k * pw(u, i - 1) * pw(v, j) * pw(w, k - 1) -
                    k * j * pw(u, i) * pw(v, j - 1) * pw(w, k - 1) +
                    k * (k - 1) * pw(u, i) * pw(v, j) * pw(w, k - 2);
      const auto& cp = p.control[static_cast<std::size_t>(triangle_index(n, i, j))];
      for (std::size_t a = 0; a < 3; ++a) {
        const Q x(static_cast<double>(cp[static_cast<int>(a)]));
        r[0][a] += c * f * x;
        r[1][a] += c * fu * x;
        r[2][a] += c * fv * x;
        r[3][a] += c * fuv * x;
      }
    }
  return r;
}

// Figure 9.25: a cubic triangular patch. Corners P300, P030, P003 are interpolated exactly, the
// whole patch matches the exact barycentric Bernstein sum.
TYPED_TEST(BezierSurfaceTest, Figure9_25_CubicTrianglePatch) {
  using T = TypeParam;
  const int n = 3;
  BezierTriangle<T, 3> p{n,
                         std::vector<Vec3<T>>(static_cast<std::size_t>(triangle_control_count(n)))};
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i + j <= n; ++i) {
      const int k = n - i - j;
      // Corner positions on an equilateral-ish layout, bumped up in the middle.
      p.control[static_cast<std::size_t>(triangle_index(n, i, j))] = {
          static_cast<T>(2 * i + j), static_cast<T>(2 * j), static_cast<T>(i * j * k)};
    }
  EXPECT_EQ(point_at(p, T(1), T(0)), p.control[static_cast<std::size_t>(triangle_index(n, 3, 0))]);
  EXPECT_EQ(point_at(p, T(0), T(1)), p.control[static_cast<std::size_t>(triangle_index(n, 0, 3))]);
  EXPECT_EQ(point_at(p, T(0), T(0)), p.control[static_cast<std::size_t>(triangle_index(n, 0, 0))]);
  for (int a = 0; a <= 8; ++a)
    for (int b = 0; a + b <= 8; ++b) {
      const T u = static_cast<T>(a) / T(8), v = static_cast<T>(b) / T(8);
      const auto e = exact_triangle(p, Q(a, 8), Q(b, 8));
      const SurfaceDerivatives<T, 3> d = partials(p, u, v);
      EXPECT_TRUE(curve_oracle::near_q(point_at(p, u, v), e[0], double(tol(T(16 * n), T(6)))));
      EXPECT_TRUE(curve_oracle::near_q(d.point, e[0], double(tol(T(16 * n), T(6)))));
      EXPECT_TRUE(curve_oracle::near_q(d.du, e[1], double(tol(T(16 * n), T(36)))));
      EXPECT_TRUE(curve_oracle::near_q(d.dv, e[2], double(tol(T(16 * n), T(36)))));
      EXPECT_TRUE(curve_oracle::near_q(d.duv, e[3], double(tol(T(16 * n), T(216)))));
      const Vec3<T> nrm = normal_at(p, u, v);
      EXPECT_NEAR(length(nrm), T(1), tol(T(8)));
      EXPECT_NEAR(dot(nrm, d.du), T(0), tol(T(64), length(d.du)));
      EXPECT_NEAR(dot(nrm, d.dv), T(0), tol(T(64), length(d.dv)));
    }
}

TYPED_TEST(BezierSurfaceTest, TrianglePatchMatchesExactSum) {
  using T = TypeParam;
  locus_test::Rng rng(9);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 20; ++trial) {
    const int n = rng.uniform_int(0, 6);
    const BezierTriangle<T, 3> p{n,
                                 curve_oracle::dyadic_points<T, 3>(rng, triangle_control_count(n))};
    EXPECT_TRUE(is_finite(p));
    const T scale = curve_oracle::max_abs_points(p.control);
    const T ds = scale * T(4 * n + 1);
    for (int k = 0; k < 10; ++k) {
      const int a = rng.uniform_int(0, 32), b = rng.uniform_int(0, 32 - a);
      const T u = static_cast<T>(a) / T(32), v = static_cast<T>(b) / T(32);
      const auto e = exact_triangle(p, Q(a, 32), Q(b, 32));
      const SurfaceDerivatives<T, 3> d = partials(p, u, v);
      ASSERT_TRUE(curve_oracle::near_q(d.point, e[0], double(tol(T(8 * (n + 1)), scale))));
      ASSERT_TRUE(curve_oracle::near_q(d.du, e[1], double(tol(T(8 * (n + 1)), ds))));
      ASSERT_TRUE(curve_oracle::near_q(d.dv, e[2], double(tol(T(8 * (n + 1)), ds))));
      ASSERT_TRUE(curve_oracle::near_q(d.duv, e[3], double(tol(T(8 * (n + 1)), ds * ds / scale))));
    }
  }
}

TYPED_TEST(BezierSurfaceTest, DegreeOneTriangleIsTheFlatTriangle) {
  using T = TypeParam;
  locus_test::Rng rng(11);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 20; ++trial) {
    const Vec3<T> p100 = rng.vec<T, 3>(T(-3), T(3)), p010 = rng.vec<T, 3>(T(-3), T(3)),
                  p001 = rng.vec<T, 3>(T(-3), T(3));
    // Storage: idx(0,0) = P001, idx(1,0) = P100, idx(0,1) = P010.
    const BezierTriangle<T, 3> tri{1, {p001, p100, p010}};
    const Vec3<T> flat_n = normalize(cross(p100 - p001, p010 - p001));
    for (int k = 0; k < 10; ++k) {
      const T u = rng.uniform(T(0), T(1)), v = rng.uniform(T(0), T(1) - u);
      const Vec3<T> want = u * p100 + v * p010 + (T(1) - u - v) * p001;
      EXPECT_TRUE(locus_test::vec_near(point_at(tri, u, v), want, tol(T(16), T(3))));
      const SurfaceDerivatives<T, 3> d = partials(tri, u, v);
      EXPECT_EQ(d.du, p100 - p001);
      EXPECT_EQ(d.dv, p010 - p001);
      EXPECT_EQ(d.duv, (Vec3<T>{}));
      EXPECT_TRUE(locus_test::vec_near(normal_at(tri, u, v), flat_n, tol(T(16))));
    }
    const AlignedBox3<T> box = bounding_box(tri);
    EXPECT_EQ(box.min, cwise_min(cwise_min(p100, p010), p001));
    EXPECT_EQ(box.max, cwise_max(cwise_max(p100, p010), p001));
  }
}

TYPED_TEST(BezierSurfaceTest, TriangleSubdivisionReproducesThePatch) {
  using T = TypeParam;
  locus_test::Rng rng(13);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 15; ++trial) {
    const int n = rng.uniform_int(0, 5);
    const BezierTriangle<T, 3> p{n,
                                 curve_oracle::dyadic_points<T, 3>(rng, triangle_control_count(n))};
    const T scale = curve_oracle::max_abs_points(p.control);
    // A dyadic split point inside the triangle (on an edge for some trials).
    const int su = rng.uniform_int(0, 8), sv = rng.uniform_int(0, 8 - su);
    const T u = static_cast<T>(su) / T(8), v = static_cast<T>(sv) / T(8);
    const Q uq(su, 8), vq(sv, 8);
    const std::array<BezierTriangle<T, 3>, 3> parts = subdivide(p, u, v);
    for (int a = 0; a <= 4; ++a)
      for (int b = 0; a + b <= 4; ++b) {
        const Q aq(a, 4), bq(b, 4), cq = Q(1) - aq - bq;
        const T at = static_cast<T>(a) / T(4), bt = static_cast<T>(b) / T(4);
        // Parent barycentrics of local (a, b, c) in each sub-patch (corners in the header).
        const std::array<std::pair<Q, Q>, 3> parent{
            {{aq * uq, aq * vq + bq}, {aq + bq * uq, bq * vq}, {aq + cq * uq, bq + cq * vq}}};
        for (int k = 0; k < 3; ++k) {
          const auto e = exact_triangle(p, parent[static_cast<std::size_t>(k)].first,
                                        parent[static_cast<std::size_t>(k)].second);
          // Two de Casteljau passes (the split, then the evaluation).
          EXPECT_TRUE(curve_oracle::near_q(point_at(parts[static_cast<std::size_t>(k)], at, bt),
                                           e[0], double(tol(T(16 * (n + 1)), scale))))
              << "part " << k << " n " << n;
        }
      }
  }
}

TYPED_TEST(BezierSurfaceTest, TriangleBadInputAndClamping) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const BezierTriangle<T, 3> tri{1, {{T(0), T(0), T(0)}, {T(1), T(0), T(0)}, {T(0), T(1), T(0)}}};
  // Outside the triangle: clamped to u, v >= 0, then scaled onto u + v = 1.
  EXPECT_EQ(point_at(tri, T(-1), T(0.5)), point_at(tri, T(0), T(0.5)));
  EXPECT_TRUE(
      locus_test::vec_near(point_at(tri, T(2), T(2)), point_at(tri, T(0.5), T(0.5)), tol(T(4))));
  EXPECT_FALSE(is_finite(point_at(tri, nan, T(0.2))));
  // Wrong control count, negative degree: NaN.
  EXPECT_FALSE(is_finite(point_at(BezierTriangle<T, 3>{2, tri.control}, T(0.2), T(0.2))));
  EXPECT_FALSE(is_finite(partials(BezierTriangle<T, 3>{-1, {}}, T(0.2), T(0.2)).du));
  EXPECT_FALSE(is_finite(BezierTriangle<T, 3>{2, tri.control}));
  // Degree 0: constant.
  const BezierTriangle<T, 3> c0{0, {{T(1), T(2), T(3)}}};
  EXPECT_EQ(point_at(c0, T(0.2), T(0.3)), c0.control[0]);
  EXPECT_EQ(partials(c0, T(0.2), T(0.3)).du, (Vec3<T>{}));
  EXPECT_EQ(normal_at(c0, T(0.2), T(0.3)), (Vec3<T>{}));
  // Collinear corners: a degenerate (flat, zero-area) patch has no normal: zero vector.
  const BezierTriangle<T, 3> line{1, {{T(0), T(0), T(0)}, {T(1), T(1), T(1)}, {T(2), T(2), T(2)}}};
  EXPECT_EQ(normal_at(line, T(0.2), T(0.3)), (Vec3<T>{}));
  // NaN control point: propagates.
  BezierTriangle<T, 3> bad = tri;
  bad.control[1].y = nan;
  EXPECT_FALSE(is_finite(bad));
  EXPECT_FALSE(is_finite(point_at(bad, T(0.3), T(0.3))));
}

}  // namespace
