// SPDX-License-Identifier: BSL-1.0
// B-spline and NURBS surfaces: tensor-product evaluation and partials against curve-of-curves
// evaluation by de Boor (an independent path), the exact rational sum (GMP), the Bézier patch,
// normals, an exact NURBS cylinder, control boxes, validation and bad input.

#include <locus/curves/bspline_surface.hpp>
#include <locus/curves/nurbs.hpp>
#include <locus/curves/nurbs_surface.hpp>

#include "curve_oracle.hpp"
#include "support/typed.hpp"

#include <cmath>
#include <limits>
#include <span>
#include <vector>

namespace {

using namespace locus;
using curve_oracle::Q;
using locus_test::tol;

template <class T>
class BSplineSurfaceTest : public ::testing::Test {};
TYPED_TEST_SUITE(BSplineSurfaceTest, locus_test::RealTypes);

// Basis sums of non-negative terms (partition of unity) and two de Boor passes on the other
// side: both within 8 (du + dv + 2) eps * scale.
template <class T>
T surf_tol(int du, int dv, T scale) {
  return tol(T(8 * (du + dv + 2)), scale);
}

template <class T>
BSplineSurface<T, 3> random_surface(locus_test::Rng& rng, bool clamped) {
  const int du = rng.uniform_int(0, 3), dv = rng.uniform_int(0, 3);
  const int rows = du + rng.uniform_int(1, 4), cols = dv + rng.uniform_int(1, 4);
  return {du,
          dv,
          rows,
          cols,
          curve_oracle::dyadic_points<T, 3>(rng, rows * cols),
          curve_oracle::random_knots<T>(rng, rows, du, clamped),
          curve_oracle::random_knots<T>(rng, cols, dv, clamped)};
}

/// Curve of curves: each row as a B-spline curve in v (value and v-derivative at v), then those
/// as B-spline curves in u: {S, S_u, S_v, S_uv}, all by de Boor.
template <class T>
std::array<Vec3<T>, 4> curve_of_curves(const BSplineSurface<T, 3>& s, T u, T v) {
  BSplineCurve3<T> pu{s.degree_u, {}, s.knots_u}, du{s.degree_u, {}, s.knots_u};
  for (int i = 0; i < s.rows; ++i) {
    BSplineCurve3<T> row{s.degree_v, {}, s.knots_v};
    for (int j = 0; j < s.cols; ++j)
      row.control.push_back(s.control[static_cast<std::size_t>(i * s.cols + j)]);
    pu.control.push_back(point_at(row, v));
    du.control.push_back(derivative_at(row, v, 1));
  }
  return {point_at(pu, u), derivative_at(pu, u, 1), point_at(du, u), derivative_at(du, u, 1)};
}

// Figure 9.26: a uniform bicubic B-spline surface. At the knot pair (u_{i+3}, v_{j+3}) the
// surface is the (1, 4, 1) x (1, 4, 1) / 36 average of the 3 x 3 control block at (i, j).
TYPED_TEST(BSplineSurfaceTest, Figure9_26_UniformBicubic) {
  using T = TypeParam;
  const int n = 6;
  BSplineSurface<T, 3> s{3, 3, n, n, {}, uniform_knots<T>(n, 3), uniform_knots<T>(n, 3)};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      s.control.push_back(
          {static_cast<T>(i), static_cast<T>(j), static_cast<T>((i * 7 + j * 3) % 5) - T(2)});
  ASSERT_EQ(validate(s), Status::ok);
  const T w[3] = {T(1), T(4), T(1)};
  for (int i = 0; i + 2 < n; ++i)
    for (int j = 0; j + 2 < n; ++j) {
      Vec3<T> want{};
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
          want += (w[a] * w[b] / T(36)) * s.control[static_cast<std::size_t>((i + a) * n + j + b)];
      const T u = s.knots_u[static_cast<std::size_t>(i + 3)];
      const T v = s.knots_v[static_cast<std::size_t>(j + 3)];
      EXPECT_TRUE(locus_test::vec_near(point_at(s, u, v), want, surf_tol(3, 3, T(6))));
      const Vec3<T> nrm = normal_at(s, u, v);
      const SurfaceDerivatives<T, 3> d = partials(s, u, v);
      EXPECT_NEAR(length(nrm), T(1), tol(T(8)));
      EXPECT_NEAR(dot(nrm, d.du), T(0), tol(T(64), length(d.du)));
      EXPECT_NEAR(dot(nrm, d.dv), T(0), tol(T(64), length(d.dv)));
    }
}

TYPED_TEST(BSplineSurfaceTest, TensorProductEqualsCurveOfCurves) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 30; ++trial) {
    const BSplineSurface<T, 3> s = random_surface<T>(rng, trial % 2 == 0);
    ASSERT_EQ(validate(s), Status::ok);
    const T scale = curve_oracle::max_abs_points(s.control);
    // Spans are >= 1/4: each derivative order multiplies the bound by at most 8 d.
    const T su = scale * T(8 * s.degree_u + 1), sv = scale * T(8 * s.degree_v + 1);
    const ParamDomain<T> a = domain_u(s), b = domain_v(s);
    for (int k = 0; k < 12; ++k) {
      const T u = a.min + (a.max - a.min) * static_cast<T>(rng.uniform_int(0, 16)) / T(16);
      const T v = b.min + (b.max - b.min) * static_cast<T>(rng.uniform_int(0, 16)) / T(16);
      const SurfaceDerivatives<T, 3> d = partials(s, u, v);
      const auto e = curve_of_curves(s, u, v);
      const T tl = surf_tol(s.degree_u, s.degree_v, T(1));
      ASSERT_TRUE(locus_test::vec_near(d.point, e[0], tl * scale)) << "u " << u << " v " << v;
      ASSERT_TRUE(locus_test::vec_near(d.du, e[1], tl * su));
      ASSERT_TRUE(locus_test::vec_near(d.dv, e[2], tl * sv));
      ASSERT_TRUE(locus_test::vec_near(d.duv, e[3], tl * su * sv / scale));
    }
  }
}

TYPED_TEST(BSplineSurfaceTest, MatchesExactBasisSum) {
  using T = TypeParam;
  locus_test::Rng rng(3);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 15; ++trial) {
    const BSplineSurface<T, 3> s = random_surface<T>(rng, trial % 2 == 1);
    const auto ku = curve_oracle::knots_q(s.knots_u), kv = curve_oracle::knots_q(s.knots_v);
    const auto qp = curve_oracle::to_q(s.control);
    const T scale = curve_oracle::max_abs_points(s.control);
    const ParamDomain<T> a = domain_u(s), b = domain_v(s);
    for (int k = 0; k < 8; ++k) {
      const T u = a.min + (a.max - a.min) * static_cast<T>(rng.uniform_int(0, 8)) / T(8);
      const T v = b.min + (b.max - b.min) * static_cast<T>(rng.uniform_int(0, 8)) / T(8);
      const Q uq(static_cast<double>(u)), vq(static_cast<double>(v));
      const int spu = curve_oracle::span_scan(ku, s.degree_u, s.rows, uq);
      const int spv = curve_oracle::span_scan(kv, s.degree_v, s.cols, vq);
      curve_oracle::QVec<3> e{};
      for (int i = 0; i < s.rows; ++i)
        for (int j = 0; j < s.cols; ++j) {
          const Q w = curve_oracle::cox_de_boor(ku, i, s.degree_u, uq, spu) *
                      curve_oracle::cox_de_boor(kv, j, s.degree_v, vq, spv);
          for (std::size_t c = 0; c < 3; ++c)
            e[c] += w * qp[static_cast<std::size_t>(i * s.cols + j)][c];
        }
      ASSERT_TRUE(curve_oracle::near_q(point_at(s, u, v), e,
                                       double(surf_tol(s.degree_u, s.degree_v, scale))));
    }
  }
}

TYPED_TEST(BSplineSurfaceTest, SingleClampedPatchEqualsBezierPatch) {
  using T = TypeParam;
  locus_test::Rng rng(5);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 10; ++trial) {
    const int rows = rng.uniform_int(1, 5), cols = rng.uniform_int(1, 5);
    const BezierPatch<T, 3> bz{rows, cols, curve_oracle::dyadic_points<T, 3>(rng, rows * cols)};
    const BSplineSurface<T, 3> s{rows - 1,
                                 cols - 1,
                                 rows,
                                 cols,
                                 bz.control,
                                 open_uniform_knots<T>(rows, rows - 1),
                                 open_uniform_knots<T>(cols, cols - 1)};
    ASSERT_EQ(validate(s), Status::ok);
    const T scale = curve_oracle::max_abs_points(bz.control);
    for (int k = 0; k < 10; ++k) {
      const T u = rng.uniform(T(0), T(1)), v = rng.uniform(T(0), T(1));
      const SurfaceDerivatives<T, 3> a = partials(s, u, v), b = partials(bz, u, v);
      const T tl = surf_tol(rows, cols, scale);
      EXPECT_TRUE(locus_test::vec_near(a.point, b.point, tl));
      EXPECT_TRUE(locus_test::vec_near(a.du, b.du, tl * T(2 * rows)));
      EXPECT_TRUE(locus_test::vec_near(a.dv, b.dv, tl * T(2 * cols)));
      EXPECT_TRUE(locus_test::vec_near(a.duv, b.duv, tl * T(4 * rows * cols)));
      if (rows > 1 && cols > 1) {
        const Vec3<T> na = normal_at(s, u, v), nb = normal_at(bz, u, v);
        // Normals agree unless the patch is nearly singular there.
        if (length(cross(b.du, b.dv)) > T(1e-2) * length(b.du) * length(b.dv)) {
          EXPECT_GT(dot(na, nb), T(1) - T(1e3) * eps_v<T>);
        }
      }
    }
  }
}

TYPED_TEST(BSplineSurfaceTest, ConvexHullAndNormals) {
  using T = TypeParam;
  locus_test::Rng rng(7);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 15; ++trial) {
    const BSplineSurface<T, 3> s = random_surface<T>(rng, trial % 2 == 0);
    const T scale = curve_oracle::max_abs_points(s.control);
    const AlignedBox3<T> box = inflate(bounding_box(s), surf_tol(s.degree_u, s.degree_v, scale));
    const ParamDomain<T> a = domain_u(s), b = domain_v(s);
    for (int k = 0; k < 20; ++k) {
      const T u = rng.uniform(a.min, a.max), v = rng.uniform(b.min, b.max);
      const Vec3<T> p = point_at(s, u, v);
      for (int c = 0; c < 3; ++c) {
        EXPECT_GE(p[c], box.min[c]);
        EXPECT_LE(p[c], box.max[c]);
      }
      const SurfaceDerivatives<T, 3> d = partials(s, u, v);
      const Vec3<T> nrm = normal_at(s, u, v);
      const T area = length(cross(d.du, d.dv));
      if (area > T(1e-3) * length(d.du) * length(d.dv)) {
        EXPECT_NEAR(length(nrm), T(1), tol(T(8)));
        EXPECT_NEAR(dot(nrm, d.du), T(0), tol(T(64), length(d.du)));
        EXPECT_NEAR(dot(nrm, d.dv), T(0), tol(T(64), length(d.dv)));
        EXPECT_GT(dot(nrm, cross(d.du, d.dv)), T(0));
      } else {
        EXPECT_TRUE(is_finite(nrm));  // degenerate: a fallback or the zero vector, never NaN
      }
    }
  }
}

TYPED_TEST(BSplineSurfaceTest, ValidationAndBadInput) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const std::vector<Vec3<T>> net(9, Vec3<T>{T(1), T(1), T(1)});
  const std::vector<T> k3{0, 0, 0, 1, 1, 1};  // degree 2, 3 control points
  const auto v = [&](int du, int dv, int rows, int cols, std::vector<Vec3<T>> c, std::vector<T> ku,
                     std::vector<T> kv) {
    return validate(BSplineSurface<T, 3>{du, dv, rows, cols, c, ku, kv});
  };
  EXPECT_EQ(v(2, 2, 3, 3, net, k3, k3), Status::ok);
  EXPECT_EQ(v(2, 2, 3, 2, net, k3, k3), Status::invalid_input);  // rows * cols != size
  EXPECT_EQ(v(2, 2, 3, 3, net, {0, 0, 0, 1, 1}, k3), Status::invalid_input);
  EXPECT_EQ(v(2, 2, 3, 3, net, k3, {0, 0, 1, 0, 1, 1}), Status::invalid_input);
  EXPECT_EQ(v(2, 2, 3, 3, net, k3, {0, 0, 0, nan, 1, 1}), Status::non_finite_input);
  EXPECT_EQ(v(3, 2, 3, 3, net, {0, 0, 0, 0, 1, 1, 1}, k3), Status::invalid_input);
  EXPECT_EQ(v(2, 2, 0, 0, {}, k3, k3), Status::empty_input);
  std::vector<Vec3<T>> bad = net;
  bad[4].y = nan;
  EXPECT_EQ(v(2, 2, 3, 3, bad, k3, k3), Status::non_finite_input);
  // Structurally invalid: NaN results, zero normal; never an out-of-range read.
  const BSplineSurface<T, 3> wrong{2, 2, 3, 3, net, {0, 0, 1, 1}, k3};
  EXPECT_FALSE(is_finite(point_at(wrong, T(0.5), T(0.5))));
  EXPECT_EQ(normal_at(wrong, T(0.5), T(0.5)), (Vec3<T>{}));
  EXPECT_FALSE(
      is_finite(partials(BSplineSurface<T, 3>{2, 2, 3, 4, net, k3, k3}, T(0.5), T(0.5)).du));
  // Clamping to the domain; NaN parameters.
  BSplineSurface<T, 3> s{2, 2, 3, 3, net, k3, k3};
  for (int i = 0; i < 9; ++i) s.control[static_cast<std::size_t>(i)] = {T(i / 3), T(i % 3), T(i)};
  EXPECT_EQ(point_at(s, T(-1), T(-1)), s.control[0]);
  EXPECT_EQ(point_at(s, T(2), T(2)), s.control[8]);
  EXPECT_FALSE(is_finite(point_at(s, nan, T(0.5))));
  EXPECT_EQ(normal_at(s, T(0.5), nan), (Vec3<T>{}));
}

TYPED_TEST(BSplineSurfaceTest, KnotInsertionAndBezierGridKeepTheSurface) {
  using T = TypeParam;
  locus_test::Rng rng(13);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 12; ++trial) {
    const BSplineSurface<T, 3> s = random_surface<T>(rng, trial % 2 == 0);
    const T scale = curve_oracle::max_abs_points(s.control);
    const ParamDomain<T> a = domain_u(s), b = domain_v(s);
    const T tu = a.min + (a.max - a.min) * static_cast<T>(rng.uniform_int(0, 8)) / T(8);
    const T tv = b.min + (b.max - b.min) * static_cast<T>(rng.uniform_int(0, 8)) / T(8);
    const BSplineSurface<T, 3> r = insert_knot_v(insert_knot_u(s, tu, 2), tv, 1);
    ASSERT_EQ(validate(r), Status::ok);
    EXPECT_EQ(static_cast<std::size_t>(r.rows),
              r.knots_u.size() - static_cast<std::size_t>(r.degree_u) - 1);
    EXPECT_EQ(static_cast<std::size_t>(r.cols),
              r.knots_v.size() - static_cast<std::size_t>(r.degree_v) - 1);
    const BezierPatchGrid<T, 3> g = to_bezier(s);
    ASSERT_EQ(g.status, Status::ok);
    ASSERT_EQ(g.patches.size(), static_cast<std::size_t>(g.count_u * g.count_v));
    ASSERT_EQ(g.breaks_u.size(), static_cast<std::size_t>(g.count_u) + 1);
    ASSERT_EQ(g.breaks_v.size(), static_cast<std::size_t>(g.count_v) + 1);
    EXPECT_EQ(g.breaks_u.front(), a.min);
    EXPECT_EQ(g.breaks_u.back(), a.max);
    // Insertion and conversion add rounds of convex combinations to the control points.
    const T tl = T(4) * surf_tol(s.degree_u, s.degree_v, scale);
    for (int k = 0; k < 12; ++k) {
      const T u = a.min + (a.max - a.min) * static_cast<T>(rng.uniform_int(0, 16)) / T(16);
      const T v = b.min + (b.max - b.min) * static_cast<T>(rng.uniform_int(0, 16)) / T(16);
      const Vec3<T> want = curve_of_curves(s, u, v)[0];
      EXPECT_TRUE(locus_test::vec_near(point_at(r, u, v), want, tl));
      // The patch containing (u, v), evaluated at its local parameters.
      int pa = 0, pb = 0;
      while (pa + 1 < g.count_u && u >= g.breaks_u[static_cast<std::size_t>(pa) + 1]) ++pa;
      while (pb + 1 < g.count_v && v >= g.breaks_v[static_cast<std::size_t>(pb) + 1]) ++pb;
      const auto ua = static_cast<std::size_t>(pa), vb = static_cast<std::size_t>(pb);
      const T lu = (u - g.breaks_u[ua]) / (g.breaks_u[ua + 1] - g.breaks_u[ua]);
      const T lv = (v - g.breaks_v[vb]) / (g.breaks_v[vb + 1] - g.breaks_v[vb]);
      const BezierPatch<T, 3>& patch = g.patches[ua * static_cast<std::size_t>(g.count_v) + vb];
      EXPECT_TRUE(locus_test::vec_near(point_at(patch, lu, lv), want, tl));
      // The patch's control box bounds the surface there (hierarchy refinement).
      const AlignedBox3<T> box = inflate(bounding_box(patch), tl);
      for (int c = 0; c < 3; ++c) {
        EXPECT_GE(want[c], box.min[c]);
        EXPECT_LE(want[c], box.max[c]);
      }
    }
  }
  // Bad shapes: returned unchanged / status.
  const BSplineSurface<T, 3> wrong{1, 1, 2, 2, {}, {0, 0, 1, 1}, {0, 0, 1, 1}};
  EXPECT_EQ(insert_knot_u(wrong, T(0.5)).knots_u.size(), 4u);
  EXPECT_EQ(to_bezier(wrong).status, Status::invalid_input);
}

// ---- NURBS surfaces ----

TYPED_TEST(BSplineSurfaceTest, NurbsWithUnitWeightsEqualsBSpline) {
  using T = TypeParam;
  locus_test::Rng rng(9);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 15; ++trial) {
    const BSplineSurface<T, 3> s = random_surface<T>(rng, trial % 2 == 0);
    const NurbsSurface<T, 3> n = to_nurbs(s);
    ASSERT_EQ(validate(n), Status::ok);
    const T scale = curve_oracle::max_abs_points(s.control);
    const T su = scale * T(8 * s.degree_u + 1), sv = scale * T(8 * s.degree_v + 1);
    const ParamDomain<T> a = domain_u(n), b = domain_v(n);
    for (int k = 0; k < 10; ++k) {
      const T u = rng.uniform(a.min, a.max), v = rng.uniform(b.min, b.max);
      const SurfaceDerivatives<T, 3> x = partials(n, u, v), y = partials(s, u, v);
      // W = 1 up to rounding, so the quotient rule adds a few eps of the derivative scales.
      const T tl = T(4) * surf_tol(s.degree_u, s.degree_v, T(1));
      EXPECT_TRUE(locus_test::vec_near(x.point, y.point, tl * scale));
      EXPECT_TRUE(locus_test::vec_near(x.du, y.du, tl * su));
      EXPECT_TRUE(locus_test::vec_near(x.dv, y.dv, tl * sv));
      EXPECT_TRUE(locus_test::vec_near(x.duv, y.duv, tl * su * sv / scale));
      EXPECT_NEAR(weight_at(n, u, v), T(1), tl);
    }
  }
}

TYPED_TEST(BSplineSurfaceTest, NurbsMatchesExactRationalSumAndFiniteDifferences) {
  using T = TypeParam;
  locus_test::Rng rng(11);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 12; ++trial) {
    const BSplineSurface<T, 3> b = random_surface<T>(rng, trial % 2 == 1);
    NurbsSurface<T, 3> s = to_nurbs(b);
    for (auto& w : s.weights) w = static_cast<T>(rng.uniform_int(2, 8)) / T(4);  // [1/2, 2]
    ASSERT_EQ(validate(s), Status::ok);
    const auto ku = curve_oracle::knots_q(s.knots_u), kv = curve_oracle::knots_q(s.knots_v);
    const auto qp = curve_oracle::to_q(s.control);
    const T scale = curve_oracle::max_abs_points(s.control);
    const ParamDomain<T> a = domain_u(s), bb = domain_v(s);
    for (int k = 0; k < 8; ++k) {
      const T u = a.min + (a.max - a.min) * static_cast<T>(rng.uniform_int(0, 8)) / T(8);
      const T v = bb.min + (bb.max - bb.min) * static_cast<T>(rng.uniform_int(0, 8)) / T(8);
      const Q uq(static_cast<double>(u)), vq(static_cast<double>(v));
      const int spu = curve_oracle::span_scan(ku, s.degree_u, s.rows, uq);
      const int spv = curve_oracle::span_scan(kv, s.degree_v, s.cols, vq);
      curve_oracle::QVec<3> num{};
      Q den = 0;
      for (int i = 0; i < s.rows; ++i)
        for (int j = 0; j < s.cols; ++j) {
          const auto idx = static_cast<std::size_t>(i * s.cols + j);
          const Q w = curve_oracle::cox_de_boor(ku, i, s.degree_u, uq, spu) *
                      curve_oracle::cox_de_boor(kv, j, s.degree_v, vq, spv) *
                      Q(static_cast<double>(s.weights[idx]));
          den += w;
          for (std::size_t c = 0; c < 3; ++c) num[c] += w * qp[idx][c];
        }
      for (auto& c : num) c /= den;
      // The weight ratio (<= 4) amplifies the relative error of the numerator and W.
      ASSERT_TRUE(curve_oracle::near_q(point_at(s, u, v), num,
                                       double(T(8) * surf_tol(s.degree_u, s.degree_v, scale))));
    }
    // Partials against central differences in double, away from knots.
    NurbsSurface<double, 3> sd{s.degree_u, s.degree_v, s.rows, s.cols, {}, {}, {}, {}};
    for (const auto& p : s.control) sd.control.push_back(vec_cast<double>(p));
    for (T w : s.weights) sd.weights.push_back(double(w));
    for (T x : s.knots_u) sd.knots_u.push_back(double(x));
    for (T x : s.knots_v) sd.knots_v.push_back(double(x));
    for (int k = 0; k < 8; ++k) {
      const double u = rng.uniform(double(a.min), double(a.max));
      const double v = rng.uniform(double(bb.min), double(bb.max));
      bool near = false;
      for (double x : sd.knots_u) near = near || std::abs(x - u) < 1e-3;
      for (double x : sd.knots_v) near = near || std::abs(x - v) < 1e-3;
      if (near) continue;
      const double h = 1e-5;
      const SurfaceDerivatives<double, 3> d = partials(sd, u, v);
      const Vec3<double> fu = (point_at(sd, u + h, v) - point_at(sd, u - h, v)) / (2 * h);
      const Vec3<double> fv = (point_at(sd, u, v + h) - point_at(sd, u, v - h)) / (2 * h);
      const Vec3<double> fuv = (partials(sd, u, v + h).du - partials(sd, u, v - h).du) / (2 * h);
      // Truncation h^2/6 |third derivative| with |S^(k)| <= 4 (32 d)^k max|P| (spans >= 1/4,
      // weight ratio <= 4), plus rounding eps / h.
      const double maxp = double(scale) + 1;
      const double ft = h * h * 4 * std::pow(32.0 * 4, 4) * maxp + 1e-9 * maxp;
      EXPECT_TRUE(locus_test::vec_near(d.du, fu, ft));
      EXPECT_TRUE(locus_test::vec_near(d.dv, fv, ft));
      EXPECT_TRUE(locus_test::vec_near(d.duv, fuv, ft * 16));
    }
  }
}

// A cylinder of revolution as an exact NURBS surface: the NURBS circle along u, a line along v.
// Every point is at the radius from the axis, every normal horizontal and radial.
TYPED_TEST(BSplineSurfaceTest, NurbsCylinderIsExact) {
  using T = TypeParam;
  const T r = T(1.5), h = T(3);
  const NurbsCurve2<T> circle = to_nurbs(Circle2<T>{{T(0), T(0)}, r});
  NurbsSurface<T, 3> s{2,
                       1,
                       static_cast<int>(circle.control.size()),
                       2,
                       {},
                       {},
                       circle.knots,
                       {T(0), T(0), T(1), T(1)}};
  for (std::size_t i = 0; i < circle.control.size(); ++i) {
    for (T z : {T(0), h}) {
      s.control.push_back({circle.control[i].x, circle.control[i].y, z});
      s.weights.push_back(circle.weights[i]);
    }
  }
  ASSERT_EQ(validate(s), Status::ok);
  for (int a = 0; a <= 40; ++a)
    for (int b = 0; b <= 4; ++b) {
      const T u = static_cast<T>(a) / T(40), v = static_cast<T>(b) / T(4);
      const Vec3<T> p = point_at(s, u, v);
      EXPECT_NEAR(std::hypot(p.x, p.y), r, tol(T(32), r));
      EXPECT_NEAR(p.z, v * h, tol(T(8), h));
      const Vec3<T> nrm = normal_at(s, u, v);
      EXPECT_NEAR(nrm.z, T(0), tol(T(64)));
      // Radial (outward or inward by orientation; here du runs counter-clockwise, dv up, so
      // du x dv points outward).
      EXPECT_NEAR(nrm.x * p.y - nrm.y * p.x, T(0), tol(T(64), r));
      EXPECT_GT(nrm.x * p.x + nrm.y * p.y, T(0));
    }
  const AlignedBox3<T> box = bounding_box(s);
  EXPECT_EQ(box.min.z, T(0));
  EXPECT_EQ(box.max.z, h);
}

TYPED_TEST(BSplineSurfaceTest, NurbsWeightsAndBadInput) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const std::vector<T> k2{0, 0, 1, 1};  // degree 1, 2 control points
  const std::vector<Vec3<T>> net{
      {T(0), T(0), T(0)}, {T(0), T(1), T(0)}, {T(1), T(0), T(0)}, {T(1), T(1), T(1)}};
  const auto make = [&](std::vector<T> w) {
    return NurbsSurface<T, 3>{1, 1, 2, 2, net, w, k2, k2};
  };
  EXPECT_EQ(validate(make({1, 2, 1, 1})), Status::ok);
  EXPECT_EQ(validate(make({1, 0, 1, 1})), Status::invalid_input);
  EXPECT_EQ(validate(make({1, -1, 1, 1})), Status::invalid_input);
  EXPECT_EQ(validate(make({1, nan, 1, 1})), Status::non_finite_input);
  EXPECT_EQ(validate(make({1, 1, 1})), Status::invalid_input);
  EXPECT_FALSE(is_finite(point_at(make({1, 1, 1}), T(0.5), T(0.5))));  // shape: NaN
  // Mixed signs: W(u, v) = (1 - u)(1 - v) - (1 - u) v + u (1 - v) - u v vanishes on a line;
  // at (0.5, 0.5) W = 0: every field NaN, the normal zero, weight_at reports 0.
  const NurbsSurface<T, 3> m = make({1, -1, 1, -1});
  EXPECT_EQ(weight_at(m, T(0.5), T(0.5)), T(0));
  const SurfaceDerivatives<T, 3> d = partials(m, T(0.5), T(0.5));
  EXPECT_FALSE(is_finite(d.point));
  EXPECT_FALSE(is_finite(d.du));
  EXPECT_FALSE(is_finite(d.dv));
  EXPECT_FALSE(is_finite(d.duv));
  EXPECT_EQ(normal_at(m, T(0.5), T(0.5)), (Vec3<T>{}));
  EXPECT_TRUE(is_finite(point_at(m, T(0.5), T(0.25))));
  // All weights zero: no point anywhere.
  EXPECT_FALSE(is_finite(point_at(make({0, 0, 0, 0}), T(0.3), T(0.7))));
  // NaN parameters; clamping.
  const NurbsSurface<T, 3> ok = make({1, 2, 1, 1});
  EXPECT_FALSE(is_finite(point_at(ok, nan, T(0.5))));
  EXPECT_TRUE(is_finite(weight_at(ok, T(0.5), T(0.5))));
  EXPECT_TRUE(std::isnan(weight_at(ok, nan, T(0.5))));
  EXPECT_EQ(point_at(ok, T(-3), T(4)), net[1]);
}

}  // namespace
