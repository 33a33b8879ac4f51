// SPDX-License-Identifier: BSL-1.0
// Knot insertion, knot refinement and Bézier extraction of B-spline and NURBS surfaces, in u and
// v: the refined surface and every extracted patch against the exact tensor-product sum of the
// ORIGINAL surface in GMP rationals (Cox-de Boor from the definition, curve_oracle.hpp), full
// multiplicity interpolation, exact power-of-two scale covariance, an exact NURBS cylinder kept
// on its radius, and bad input (knots outside the domain, NaN, inconsistent nets).

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
class SurfaceKnotsTest : public ::testing::Test {};
TYPED_TEST_SUITE(SurfaceKnotsTest, locus_test::RealTypes);

template <class T>
NurbsSurface<T, 3> random_nurbs(locus_test::Rng& rng, bool clamped, bool unit_weights) {
  const int du = rng.uniform_int(1, 3), dv = rng.uniform_int(1, 3);
  const int rows = du + rng.uniform_int(1, 3), cols = dv + rng.uniform_int(1, 3);
  NurbsSurface<T, 3> s{du,
                       dv,
                       rows,
                       cols,
                       curve_oracle::dyadic_points<T, 3>(rng, rows * cols),
                       {},
                       curve_oracle::random_knots<T>(rng, rows, du, clamped),
                       curve_oracle::random_knots<T>(rng, cols, dv, clamped)};
  for (int k = 0; k < rows * cols; ++k)
    s.weights.push_back(unit_weights ? T(1) : static_cast<T>(rng.uniform_int(2, 8)) / T(4));
  return s;
}

template <class T>
BSplineSurface<T, 3> as_bspline(const NurbsSurface<T, 3>& s) {
  return {s.degree_u, s.degree_v, s.rows, s.cols, s.control, s.knots_u, s.knots_v};
}

/// The exact value of the original surface at (u, v): sum N_i N_j w_ij P_ij / sum N_i N_j w_ij.
template <class T>
curve_oracle::QVec<3> exact_at(const NurbsSurface<T, 3>& s, T u, T v) {
  const auto ku = curve_oracle::knots_q(s.knots_u), kv = curve_oracle::knots_q(s.knots_v);
  const Q uq(static_cast<double>(u)), vq(static_cast<double>(v));
  const int spu = curve_oracle::span_scan(ku, s.degree_u, s.rows, uq);
  const int spv = curve_oracle::span_scan(kv, s.degree_v, s.cols, vq);
  curve_oracle::QVec<3> num{};
  Q den = 0;
  for (int i = spu - s.degree_u; i <= spu; ++i)
    for (int j = spv - s.degree_v; j <= spv; ++j) {
      const auto idx = static_cast<std::size_t>(i * s.cols + j);
      const Q w = curve_oracle::cox_de_boor(ku, i, s.degree_u, uq, spu) *
                  curve_oracle::cox_de_boor(kv, j, s.degree_v, vq, spv) *
                  Q(static_cast<double>(s.weights[idx]));
      den += w;
      for (int c = 0; c < 3; ++c)
        num[static_cast<std::size_t>(c)] += w * Q(static_cast<double>(s.control[idx][c]));
    }
  for (auto& c : num) c /= den;
  return num;
}

// Insertion and refinement are a few rounds of convex combinations per knot and the evaluation a
// sum of non-negative terms; the weight ratio (<= 4) amplifies the relative error of a NURBS.
template <class T>
T knot_tol(const NurbsSurface<T, 3>& s, int rounds) {
  const T scale = curve_oracle::max_abs_points(s.control);
  return tol(T(32 * (s.degree_u + s.degree_v + 2) * (rounds + 1)), scale);
}

template <class T>
T grid_param(locus_test::Rng& rng, ParamDomain<T> d) {
  return d.min + (d.max - d.min) * static_cast<T>(rng.uniform_int(0, 16)) / T(16);
}

/// k random dyadic knots strictly inside or on the ends of the domain (repeats likely).
template <class T>
std::vector<T> new_knots(locus_test::Rng& rng, ParamDomain<T> d, int k) {
  std::vector<T> r;
  for (int i = 0; i < k; ++i) r.push_back(grid_param(rng, d));
  return r;
}

TYPED_TEST(SurfaceKnotsTest, InsertionAndRefinementKeepTheSurface) {
  using T = TypeParam;
  locus_test::Rng rng(21);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 12; ++trial) {
    const bool rational = trial % 2 == 1;
    const NurbsSurface<T, 3> s = random_nurbs<T>(rng, trial % 4 < 2, !rational);
    ASSERT_EQ(validate(s), Status::ok);
    const ParamDomain<T> a = domain_u(s), b = domain_v(s);
    const std::vector<T> ku = new_knots(rng, a, 4), kv = new_knots(rng, b, 3);
    const T tu = grid_param(rng, a), tv = grid_param(rng, b);
    const int times = rng.uniform_int(1, 3);
    NurbsSurface<T, 3> ins = insert_knot_v(insert_knot_u(s, tu, times), tv, times);
    const auto ru = refine_knots_u(s, std::span<const T>(ku));
    ASSERT_EQ(ru.status, Status::ok);
    const auto ruv = refine_knots_v(ru.surface, std::span<const T>(kv));
    ASSERT_EQ(ruv.status, Status::ok);
    NurbsSurface<T, 3> ref = ruv.surface;
    for (const NurbsSurface<T, 3>* r : {&ins, &ref}) {
      ASSERT_EQ(validate(*r), Status::ok);
      EXPECT_EQ(r->knots_u.size(), static_cast<std::size_t>(r->rows + r->degree_u + 1));
      EXPECT_EQ(r->knots_v.size(), static_cast<std::size_t>(r->cols + r->degree_v + 1));
      EXPECT_EQ(domain_u(*r).min, a.min);
      EXPECT_EQ(domain_v(*r).max, b.max);
    }
    // Refinement inserts every requested knot unless its multiplicity is already the degree.
    int expect_rows = s.rows;
    std::vector<T> kn = s.knots_u;
    for (T k : ku) {
      int m = 0;
      for (T x : kn) m += x == k ? 1 : 0;
      if (m < s.degree_u) {
        kn.push_back(k);
        ++expect_rows;
      }
    }
    EXPECT_EQ(ref.rows, expect_rows);
    const T tl = knot_tol(s, 7);
    // The B-spline functions directly (the same code path as the NURBS ones with w = 1).
    BSplineSurface<T, 3> bs{};
    if (!rational) {
      const auto rb = refine_knots_v(as_bspline(s), std::span<const T>(kv));
      ASSERT_EQ(rb.status, Status::ok);
      bs = insert_knot_u(rb.surface, tu, 2);
    }
    for (int k = 0; k < 6; ++k) {
      const T u = grid_param(rng, a), v = grid_param(rng, b);
      const auto e = exact_at(s, u, v);
      EXPECT_TRUE(curve_oracle::near_q(point_at(ins, u, v), e, double(tl))) << u << " " << v;
      EXPECT_TRUE(curve_oracle::near_q(point_at(ref, u, v), e, double(tl))) << u << " " << v;
      if (!rational) {
        EXPECT_TRUE(curve_oracle::near_q(point_at(bs, u, v), e, double(tl)));
      }
    }
  }
}

// Inserting t to multiplicity d makes the isoparametric curve S(t, .) (or S(., t)) the B-spline
// curve of one control row (column): the surface interpolates that row there.
TYPED_TEST(SurfaceKnotsTest, FullMultiplicityInterpolatesARow) {
  using T = TypeParam;
  locus_test::Rng rng(22);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 6; ++trial) {
    const NurbsSurface<T, 3> n = random_nurbs<T>(rng, trial % 2 == 0, true);
    const BSplineSurface<T, 3> s = as_bspline(n);
    const ParamDomain<T> a = domain_u(s), b = domain_v(s);
    const T t = grid_param(rng, a), tv = grid_param(rng, b);
    const BSplineSurface<T, 3> r = insert_knot_u(s, t, s.degree_u);
    const BSplineSurface<T, 3> c = insert_knot_v(s, tv, s.degree_v);
    // The row i with knots_u[i+1 .. i+d] == t has N_i(t) = 1 (the last such i: with d + 1 equal
    // knots the right-hand piece is evaluated, as find_span does).
    const auto full_row = [](const std::vector<T>& kn, int d, int count, T x) {
      int found = -1;
      for (int i = 0; i < count; ++i) {
        bool all = true;
        for (int k = 1; k <= d; ++k) all = all && kn[static_cast<std::size_t>(i + k)] == x;
        if (all) found = i;
      }
      return found;
    };
    const int row = full_row(r.knots_u, s.degree_u, r.rows, t);
    const int col = full_row(c.knots_v, s.degree_v, c.cols, tv);
    ASSERT_GE(row, 0);
    ASSERT_GE(col, 0);
    BSplineCurve<T, 3> rc{s.degree_v, {}, r.knots_v}, cc{s.degree_u, {}, c.knots_u};
    for (int j = 0; j < r.cols; ++j)
      rc.control.push_back(r.control[static_cast<std::size_t>(row * r.cols + j)]);
    for (int i = 0; i < c.rows; ++i)
      cc.control.push_back(c.control[static_cast<std::size_t>(i * c.cols + col)]);
    const T tl = knot_tol(n, 3);
    for (int k = 0; k <= 4; ++k) {
      const T v = b.min + (b.max - b.min) * static_cast<T>(k) / T(4);
      const T u = a.min + (a.max - a.min) * static_cast<T>(k) / T(4);
      EXPECT_TRUE(curve_oracle::near_q(point_at(rc, v), exact_at(n, t, v), double(tl)));
      EXPECT_TRUE(curve_oracle::near_q(point_at(cc, u), exact_at(n, u, tv), double(tl)));
    }
  }
}

// Every extracted patch, evaluated by de Casteljau at its local parameters, is the surface on
// its sub-rectangle; breaks cover the domain; the control box of a B-spline patch bounds it.
TYPED_TEST(SurfaceKnotsTest, BezierExtractionMatchesTheSurface) {
  using T = TypeParam;
  locus_test::Rng rng(23);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 8; ++trial) {
    const NurbsSurface<T, 3> s = random_nurbs<T>(rng, trial % 3 == 0, trial % 2 == 0);
    const RationalPatchGrid<T, 3> g = to_bezier(s);
    ASSERT_EQ(g.status, Status::ok);
    ASSERT_EQ(g.patches.size(), static_cast<std::size_t>(g.count_u * g.count_v));
    ASSERT_EQ(g.breaks_u.size(), static_cast<std::size_t>(g.count_u) + 1);
    ASSERT_EQ(g.breaks_v.size(), static_cast<std::size_t>(g.count_v) + 1);
    const ParamDomain<T> a = domain_u(s), b = domain_v(s);
    EXPECT_EQ(g.breaks_u.front(), a.min);
    EXPECT_EQ(g.breaks_u.back(), a.max);
    EXPECT_EQ(g.breaks_v.front(), b.min);
    EXPECT_EQ(g.breaks_v.back(), b.max);
    const T tl = knot_tol(s, 2 * (s.degree_u + s.degree_v) + 4);
    for (int pa = 0; pa < g.count_u; ++pa)
      for (int pb = 0; pb < g.count_v; ++pb) {
        const auto ua = static_cast<std::size_t>(pa), vb = static_cast<std::size_t>(pb);
        const RationalBezierPatch<T, 3>& p =
            g.patches[ua * static_cast<std::size_t>(g.count_v) + vb];
        ASSERT_EQ(p.rows, s.degree_u + 1);
        ASSERT_EQ(p.cols, s.degree_v + 1);
        for (T w : p.weights) EXPECT_GT(w, T(0));
        for (int k = 0; k < 2; ++k) {
          const T lu = static_cast<T>(rng.uniform_int(0, 4)) / T(4);
          const T lv = static_cast<T>(rng.uniform_int(0, 4)) / T(4);
          const T u = g.breaks_u[ua] + lu * (g.breaks_u[ua + 1] - g.breaks_u[ua]);
          const T v = g.breaks_v[vb] + lv * (g.breaks_v[vb + 1] - g.breaks_v[vb]);
          // Spans are multiples of 1/4 and lu, lv quarters: u and v are exact dyadics.
          EXPECT_TRUE(curve_oracle::near_q(point_at(p, lu, lv), exact_at(s, u, v), double(tl)))
              << "patch " << pa << "," << pb << " at " << lu << "," << lv;
        }
      }
    // The B-spline extraction of the same net (unit weights: identical patches up to rounding).
    if (trial % 2 == 0) {
      const BezierPatchGrid<T, 3> bg = to_bezier(as_bspline(s));
      ASSERT_EQ(bg.status, Status::ok);
      ASSERT_EQ(bg.patches.size(), g.patches.size());
      for (std::size_t k = 0; k < g.patches.size(); ++k)
        for (std::size_t c = 0; c < g.patches[k].control.size(); ++c)
          EXPECT_TRUE(locus_test::vec_near(bg.patches[k].control[c], g.patches[k].control[c], tl));
    }
  }
}

// Scaling the net by a power of two scales every refined control point exactly (the insertion
// coefficients depend on the knots only); refining the knots by a power of two too scales them.
TYPED_TEST(SurfaceKnotsTest, PowerOfTwoScaleCovariance) {
  using T = TypeParam;
  locus_test::Rng rng(24);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 8; ++trial) {
    const NurbsSurface<T, 3> s = random_nurbs<T>(rng, trial % 2 == 0, false);
    const std::vector<T> ku = new_knots(rng, domain_u(s), 3), kv = new_knots(rng, domain_v(s), 2);
    const T f = trial % 2 == 0 ? T(1024) : T(1) / T(64);
    NurbsSurface<T, 3> big = s;
    for (auto& p : big.control) p = f * p;
    for (auto& w : big.weights) w *= T(4);  // a common weight factor cancels exactly too
    const auto r1 =
        refine_knots_v(refine_knots_u(s, std::span<const T>(ku)).surface, std::span<const T>(kv));
    const auto r2 =
        refine_knots_v(refine_knots_u(big, std::span<const T>(ku)).surface, std::span<const T>(kv));
    ASSERT_EQ(r1.status, Status::ok);
    ASSERT_EQ(r2.status, Status::ok);
    ASSERT_EQ(r1.surface.control.size(), r2.surface.control.size());
    for (std::size_t k = 0; k < r1.surface.control.size(); ++k) {
      EXPECT_EQ(f * r1.surface.control[k], r2.surface.control[k]);
      EXPECT_EQ(T(4) * r1.surface.weights[k], r2.surface.weights[k]);
    }
  }
}

// The exact NURBS cylinder (circle along u, line along v) stays on its radius after refinement
// and extraction: rational insertion must not approximate.
TYPED_TEST(SurfaceKnotsTest, RefinedCylinderStaysExact) {
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
  for (std::size_t i = 0; i < circle.control.size(); ++i)
    for (T z : {T(0), h}) {
      s.control.push_back({circle.control[i].x, circle.control[i].y, z});
      s.weights.push_back(circle.weights[i]);
    }
  ASSERT_EQ(validate(s), Status::ok);
  const std::vector<T> ku{T(0.1), T(0.3), T(0.3), T(0.8)}, kv{T(0.5)};
  const auto ref =
      refine_knots_v(refine_knots_u(s, std::span<const T>(ku)).surface, std::span<const T>(kv));
  ASSERT_EQ(ref.status, Status::ok);
  EXPECT_EQ(ref.surface.cols, 3);
  const RationalPatchGrid<T, 3> g = to_bezier(ref.surface);
  ASSERT_EQ(g.status, Status::ok);
  EXPECT_EQ(g.count_v, 2);
  for (int a = 0; a <= 20; ++a)
    for (int b = 0; b <= 4; ++b) {
      const T u = static_cast<T>(a) / T(20), v = static_cast<T>(b) / T(4);
      const Vec3<T> p = point_at(ref.surface, u, v);
      EXPECT_NEAR(std::hypot(p.x, p.y), r, tol(T(64), r));
      EXPECT_NEAR(p.z, v * h, tol(T(16), h));
    }
  for (const auto& p : g.patches)
    for (int k = 0; k <= 4; ++k) {
      const Vec3<T> q = point_at(p, static_cast<T>(k) / T(4), static_cast<T>(4 - k) / T(4));
      EXPECT_NEAR(std::hypot(q.x, q.y), r, tol(T(64), r));
    }
}

TYPED_TEST(SurfaceKnotsTest, BadInputGivesStatus) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  locus_test::Rng rng(25);
  SCOPED_TRACE(rng.trace());
  const NurbsSurface<T, 3> s = random_nurbs<T>(rng, true, false);
  const BSplineSurface<T, 3> b = as_bspline(s);
  const ParamDomain<T> a = domain_u(s), d = domain_v(s);
  const std::vector<T> outside{a.min, a.max + T(0.25)}, below{d.min - T(1)}, with_nan{a.min, nan};
  const std::vector<T> inf{std::numeric_limits<T>::infinity()}, none{};
  EXPECT_EQ(refine_knots_u(b, std::span<const T>(outside)).status, Status::invalid_input);
  EXPECT_EQ(refine_knots_v(b, std::span<const T>(below)).status, Status::invalid_input);
  EXPECT_EQ(refine_knots_u(b, std::span<const T>(with_nan)).status, Status::non_finite_input);
  EXPECT_EQ(refine_knots_v(s, std::span<const T>(inf)).status, Status::non_finite_input);
  EXPECT_EQ(refine_knots_u(s, std::span<const T>(outside)).status, Status::invalid_input);
  // A failed refinement returns the input unchanged.
  const auto bad = refine_knots_u(s, std::span<const T>(outside));
  EXPECT_EQ(bad.surface.knots_u, s.knots_u);
  EXPECT_EQ(bad.surface.rows, s.rows);
  // No knots: ok and unchanged.
  const auto same = refine_knots_v(s, std::span<const T>(none));
  EXPECT_EQ(same.status, Status::ok);
  EXPECT_EQ(same.surface.knots_v, s.knots_v);
  // insert_knot_* clamp t into the domain and ignore a NaN t.
  EXPECT_EQ(insert_knot_u(s, nan).knots_u, s.knots_u);
  EXPECT_EQ(insert_knot_v(b, nan).knots_v, b.knots_v);
  const NurbsSurface<T, 3> cl = insert_knot_u(s, a.max + T(5));
  EXPECT_EQ(cl.knots_u.back(), s.knots_u.back());
  // Inconsistent nets: status from validate(), nothing inserted.
  NurbsSurface<T, 3> wrong = s;
  wrong.weights.pop_back();
  const std::vector<T> mid{T(0.5) * (a.min + a.max)};
  EXPECT_EQ(refine_knots_u(wrong, std::span<const T>(mid)).status, Status::invalid_input);
  EXPECT_EQ(insert_knot_v(wrong, T(0)).knots_v, wrong.knots_v);
  EXPECT_EQ(to_bezier(wrong).status, Status::invalid_input);
  EXPECT_TRUE(to_bezier(wrong).patches.empty());
  NurbsSurface<T, 3> zero_w = s;
  zero_w.weights[0] = T(0);
  EXPECT_EQ(to_bezier(zero_w).status, Status::invalid_input);
  NurbsSurface<T, 3> nan_p = s;
  nan_p.control[1].y = nan;
  EXPECT_EQ(refine_knots_v(nan_p, std::span<const T>(none)).status, Status::non_finite_input);
  BSplineSurface<T, 3> empty{1, 1, 0, 0, {}, {}, {}};
  EXPECT_EQ(refine_knots_u(empty, std::span<const T>(mid)).status, Status::empty_input);
  // A rational patch with mismatched weights evaluates to NaN.
  RationalBezierPatch<T, 3> rp{2, 2, std::vector<Vec3<T>>(4), {T(1)}};
  EXPECT_FALSE(is_finite(point_at(rp, T(0.5), T(0.5))));
}

}  // namespace
