// SPDX-License-Identifier: BSL-1.0
// Tests for primitives/quadric.hpp (row prim3.quadric: classification by eigenvalue signs and
// standard form; figures 9.18, 9.19, 9.20).
#include <locus/primitives/quadric.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
using locus_test::vec_near;

template <class T>
class QuadricTest : public ::testing::Test {};
TYPED_TEST_SUITE(QuadricTest, locus_test::RealTypes);

static_assert(std::is_aggregate_v<Quadric3d> && std::is_trivially_copyable_v<Quadric3f>);

namespace {
using I = std::int64_t;

// A quadric with integer coefficients, x^T A x + b.x + c (A symmetric).
struct IntQuadric {
  I a[3][3];
  I b[3];
  I c;
};

struct Case {
  const char* name;
  QuadricType type;
  IntQuadric q;
};

IntQuadric diag(I d0, I d1, I d2, I b0, I b1, I b2, I c) {
  return {{{d0, 0, 0}, {0, d1, 0}, {0, 0, d2}}, {b0, b1, b2}, c};
}

// One standard-form representative per class (the book's figures 9.18-9.20 and their
// degenerate companions). The linear terms of the paraboloids and of the parabolic cylinder
// deliberately have nonzero components along squared axes too, so completing squares matters.
std::vector<Case> all_cases() {
  using Q = QuadricType;
  return {
      {"ellipsoid", Q::ellipsoid, diag(1, 2, 3, 0, 0, 0, -6)},
      {"hyperboloid_one_sheet", Q::hyperboloid_one_sheet, diag(1, 2, -3, 0, 0, 0, -6)},
      {"hyperboloid_two_sheets", Q::hyperboloid_two_sheets, diag(1, -2, -3, 0, 0, 0, -6)},
      {"elliptic_cone", Q::elliptic_cone, diag(1, 2, -3, 0, 0, 0, 0)},
      {"point", Q::point, diag(1, 2, 3, 2, 0, 0, 1)},  // (x + 1)^2 + 2 y^2 + 3 z^2 = 0
      {"imaginary_ellipsoid", Q::empty, diag(1, 2, 3, 0, 0, 0, 6)},
      {"elliptic_paraboloid", Q::elliptic_paraboloid, diag(1, 2, 0, 2, 0, -4, 5)},
      {"hyperbolic_paraboloid", Q::hyperbolic_paraboloid, diag(1, -2, 0, 0, 4, 3, 1)},
      {"elliptic_cylinder", Q::elliptic_cylinder, diag(1, 2, 0, 0, 0, 0, -4)},
      {"imaginary_cylinder", Q::empty, diag(1, 2, 0, 0, 0, 0, 4)},
      {"hyperbolic_cylinder", Q::hyperbolic_cylinder, diag(1, -2, 0, 0, 0, 0, 4)},
      {"line", Q::line, diag(1, 2, 0, -2, 0, 0, 1)},  // (x - 1)^2 + 2 y^2 = 0
      {"intersecting_planes", Q::intersecting_planes, diag(1, -2, 0, 0, 0, 0, 0)},
      {"parabolic_cylinder", Q::parabolic_cylinder, diag(3, 0, 0, 6, 2, -1, 7)},
      {"parallel_planes", Q::parallel_planes, diag(3, 0, 0, 0, 0, 0, -12)},
      {"imaginary_parallel_planes", Q::empty, diag(3, 0, 0, 0, 0, 0, 12)},
      {"double_plane", Q::plane, diag(3, 0, 0, 6, 0, 0, 3)},  // 3 (x + 1)^2 = 0
      {"plane", Q::plane, diag(0, 0, 0, 1, 2, -2, 5)},
      {"contradiction", Q::empty, diag(0, 0, 0, 0, 0, 0, 3)},
      {"entire_space", Q::entire_space, diag(0, 0, 0, 0, 0, 0, 0)},
  };
}

// Rotation by the integer quaternion (w, x, y, z), scaled by N = w^2 + x^2 + y^2 + z^2 so that
// it is an integer matrix: R = Rn / N is exactly orthogonal.
void int_rotation(Rng& rng, I rn[3][3], I& n) {
  I w, x, y, z;
  do {
    w = rng.uniform_int(-3, 3), x = rng.uniform_int(-3, 3), y = rng.uniform_int(-3, 3),
    z = rng.uniform_int(-3, 3);
    n = w * w + x * x + y * y + z * z;
  } while (n == 0);
  const I m[3][3] = {{w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)},
                     {2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)},
                     {2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) rn[i][j] = m[i][j];
}

// The quadric in the coordinates X = R x - t, multiplied by N^2 (a positive factor, so the
// class is unchanged): every coefficient stays an integer, small enough to be exact in float.
IntQuadric transform(const IntQuadric& q, Rng& rng) {
  I r[3][3], n;
  int_rotation(rng, r, n);
  IntQuadric o{};
  // A' = Rn A Rn^T, b' = N Rn b (the quadric of x = R^T X, times N^2).
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      I s = 0;
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) s += r[i][k] * q.a[k][l] * r[j][l];
      o.a[i][j] = s;
    }
  for (int i = 0; i < 3; ++i) {
    I s = 0;
    for (int k = 0; k < 3; ++k) s += r[i][k] * q.b[k];
    o.b[i] = n * s;
  }
  o.c = n * n * q.c;
  // Translate: X = Y - t gives b'' = b' - 2 A' t, c'' = t^T A' t - b'.t + c'.
  const I t[3] = {rng.uniform_int(-3, 3), rng.uniform_int(-3, 3), rng.uniform_int(-3, 3)};
  IntQuadric p = o;
  for (int i = 0; i < 3; ++i) {
    I s = 0;
    for (int k = 0; k < 3; ++k) s += o.a[i][k] * t[k];
    p.b[i] = o.b[i] - 2 * s;
  }
  I tat = 0, bt = 0;
  for (int i = 0; i < 3; ++i) {
    bt += o.b[i] * t[i];
    for (int k = 0; k < 3; ++k) tat += t[i] * o.a[i][k] * t[k];
  }
  p.c = tat - bt + o.c;
  return p;
}

template <class T>
Quadric3<T> to_real(const IntQuadric& q, I sign = 1) {
  Quadric3<T> r{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      EXPECT_LT(std::abs(q.a[i][j]), I(1) << 24);  // exact in float
      r.a.a[i][j] = static_cast<T>(sign * q.a[i][j]);
    }
    EXPECT_LT(std::abs(q.b[i]), I(1) << 24);
    r.b[i] = static_cast<T>(sign * q.b[i]);
  }
  EXPECT_LT(std::abs(q.c), I(1) << 24);
  r.c = static_cast<T>(sign * q.c);
  return r;
}

template <class T>
T coefficient_scale(const Quadric3<T>& q) {
  T s = std::fabs(q.c);
  for (int i = 0; i < 3; ++i) {
    s = std::fmax(s, std::fabs(q.b[i]));
    for (int j = 0; j < 3; ++j) s = std::fmax(s, std::fabs(q.a.a[i][j]));
  }
  return s;
}
}  // namespace

TYPED_TEST(QuadricTest, Figures9_18To9_20StandardFormsClassify) {
  using T = TypeParam;
  for (const auto& c : all_cases()) {
    SCOPED_TRACE(c.name);
    const auto r = quadric_type(to_real<T>(c.q));
    EXPECT_EQ(r.status, Status::ok);
    EXPECT_TRUE(r.exact);
    EXPECT_EQ(to_string(r.type), to_string(c.type));
  }
  // Fig 9.18 (three nonzero eigenvalues) / 9.19 (two) / 9.20 (one): the rank of A.
  EXPECT_EQ(quadric_type(to_real<T>(diag(1, 2, -3, 0, 0, 0, -6))).rank_a, 3);
  EXPECT_EQ(quadric_type(to_real<T>(diag(1, -2, 0, 0, 4, 3, 1))).rank_a, 2);
  EXPECT_EQ(quadric_type(to_real<T>(diag(3, 0, 0, 6, 2, -1, 7))).rank_a, 1);
}

TYPED_TEST(QuadricTest, ExactClassificationIsInvariantUnderRationalRotationsAndTranslations) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (const auto& c : all_cases()) {
    SCOPED_TRACE(c.name);
    for (int trial = 0; trial < 25; ++trial) {
      const IntQuadric iq = transform(c.q, rng);
      for (const I sign : {I(1), I(-1)}) {  // q = 0 and -q = 0 are the same surface
        const auto r = quadric_type(to_real<T>(iq, sign));
        ASSERT_EQ(r.status, Status::ok);
        EXPECT_TRUE(r.exact);
        ASSERT_EQ(to_string(r.type), to_string(c.type));
        EXPECT_EQ(r.positive_a + r.negative_a, r.rank_a);
        EXPECT_EQ(r.positive_m + r.negative_m, r.rank_m);
      }
    }
  }
}

TYPED_TEST(QuadricTest, StandardFormRoundTripAndDefinition) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (const auto& c : all_cases()) {
    SCOPED_TRACE(c.name);
    for (int trial = 0; trial < 10; ++trial) {
      const Quadric3<T> q = to_real<T>(transform(c.q, rng));
      const auto f = standard_form(q);
      ASSERT_EQ(f.status, Status::ok);
      ASSERT_EQ(to_string(f.type), to_string(c.type));
      // Rotation: orthonormal and right-handed (computed in double, rounded to T).
      const Mat3<T> rtr = transpose(f.rotation) * f.rotation;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(rtr.a[i][j], i == j ? T(1) : T(0), tol<T>(16));
      EXPECT_NEAR(determinant(f.rotation), T(1), tol<T>(16));
      // Shape of the form: nonzero diagonal entries first; linear term only along axis 2.
      const auto cls = quadric_type(q);
      for (int i = 0; i < 3; ++i) EXPECT_EQ(f.diagonal[i] != T(0), i < cls.rank_a);
      EXPECT_EQ(f.linear.x, T(0));
      EXPECT_EQ(f.linear.y, T(0));
      const bool has_linear = cls.rank_m == cls.rank_a + 2;
      EXPECT_EQ(f.linear.z > T(0), has_linear);
      if (has_linear || cls.rank_m == cls.rank_a) {
        EXPECT_EQ(f.constant, T(0));
      }
      // Definition: q(P + R y) = sum d_i y_i^2 + e.y + k for random y. The scale bounds the
      // terms of q at |X| <= |P| + 2: eps-level relative error of each term.
      const T big = coefficient_scale(q);
      const T reach = length(f.center) + T(2);
      const T scale = big * (reach * reach + reach + T(1));
      for (int s = 0; s < 10; ++s) {
        const Vec3<T> y = rng.vec<T, 3>(-1, 1);
        const Vec3<T> x = f.center + f.rotation * y;
        const T lhs = signed_value(q, x);
        const T rhs = f.diagonal.x * y.x * y.x + f.diagonal.y * y.y * y.y +
                      f.diagonal.z * y.z * y.z + dot(f.linear, y) + f.constant;
        EXPECT_NEAR(lhs, rhs, tol<T>(256, scale));
      }
      // Back to the general form.
      const Quadric3<T> back = to_quadric(f);
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(back.a.a[i][j], q.a.a[i][j], tol<T>(256, scale));
        EXPECT_NEAR(back.b[i], q.b[i], tol<T>(256, scale));
      }
      EXPECT_NEAR(back.c, q.c, tol<T>(256, scale));
    }
  }
}

TYPED_TEST(QuadricTest, ToleranceClassificationRecoversRoundedDegenerateClasses) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int exact_differs = 0;
  for (const auto& c : all_cases()) {
    SCOPED_TRACE(c.name);
    for (int trial = 0; trial < 10; ++trial) {
      // Rotate and translate in floating point (irrational rotation: the coefficients carry
      // rounding error, so a cone is typically no longer exactly a cone).
      const auto qv = rng.unit<double, 4>();
      const double w = qv.x, x = qv.y, y = qv.z, z = qv.w;
      const Mat3<double> r{{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                            {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                            {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
      Quadric3<T> q0 = to_real<T>(c.q);
      // Same shape via to_quadric of a hand-made standard-form-like description: X = t + R x.
      QuadricStandardForm<T> f{Status::ok, c.type, {}, rng.vec<T, 3>(-2, 2), {}, {}, T(0)};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) f.rotation.a[i][j] = static_cast<T>(r.a[i][j]);
      f.diagonal = {q0.a.a[0][0], q0.a.a[1][1], q0.a.a[2][2]};
      f.linear = q0.b;
      f.constant = q0.c;
      const Quadric3<T> q = to_quadric(f);
      const T rel_tol = tol<T>(1024);  // a few hundred roundings of the coefficients
      const auto rt = quadric_type(q, rel_tol);
      ASSERT_EQ(rt.status, Status::ok);
      EXPECT_FALSE(rt.exact);
      EXPECT_EQ(to_string(rt.type), to_string(c.type));
      EXPECT_EQ(to_string(standard_form(q, rel_tol).type), to_string(c.type));
      exact_differs += quadric_type(q).type != c.type;
    }
  }
  // The rounded inputs really are perturbed: exact classification sees other classes sometimes.
  EXPECT_GT(exact_differs, 0);
}

TYPED_TEST(QuadricTest, NonFiniteAndExactnessRange) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  Quadric3<T> q = to_real<T>(diag(1, 2, 3, 0, 0, 0, -1));
  q.b.y = nan;
  EXPECT_EQ(quadric_type(q).status, Status::non_finite_input);
  EXPECT_EQ(quadric_type(q).type, QuadricType::invalid);
  EXPECT_EQ(standard_form(q).status, Status::non_finite_input);
  EXPECT_EQ(quadric_type(q, T(1e-3)).status, Status::non_finite_input);
  q.b.y = 0;
  q.a.a[0][0] = inf;
  EXPECT_EQ(quadric_type(q).type, QuadricType::invalid);
  // Tiny but in-range coefficients are classified exactly: x^2 + 2^-100 (y^2 + z^2) - 2^-120 is
  // an ellipsoid, x^2 + 2^-100 y^2 - 2^-100 z^2 + 2^-120 a hyperboloid of two sheets.
  const T t100 = std::ldexp(T(1), -100), t120 = std::ldexp(T(1), -120);
  const Quadric3<T> e{Mat3<T>::diagonal({1, t100, t100}), {}, -t120};
  EXPECT_EQ(quadric_type(e).type, QuadricType::ellipsoid);
  EXPECT_TRUE(quadric_type(e).exact);
  const Quadric3<T> h{Mat3<T>::diagonal({1, t100, -t100}), {}, t120};
  EXPECT_EQ(quadric_type(h).type, QuadricType::hyperboloid_two_sheets);
  EXPECT_TRUE(quadric_type(h).exact);
  if constexpr (std::is_same_v<T, double>) {
    // Far beyond any fixed working precision: products of four coefficients span 2^-1280 to 1,
    // still exact (the classification has no range limit for finite input).
    const Quadric3<T> far{Mat3<T>::diagonal({1, 1e-80, 1}), {}, -1};
    EXPECT_TRUE(quadric_type(far).exact);
    EXPECT_EQ(quadric_type(far).type, QuadricType::ellipsoid);
    const double t = 0x1p-320;  // x^2 + t y^2 - t z^2 + t^3 = 0: two sheets (t^3 subnormal-free)
    const Quadric3<T> two{Mat3<T>::diagonal({1, t, -t}), {}, t * t * t};
    EXPECT_EQ(quadric_type(two).type, QuadricType::hyperboloid_two_sheets);
    const Quadric3<T> one{Mat3<T>::diagonal({1, t, -t}), {}, -t * t * t};
    EXPECT_EQ(quadric_type(one).type, QuadricType::hyperboloid_one_sheet);
  }
}

TYPED_TEST(QuadricTest, SignedValueMatchesDefinition) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 200; ++trial) {
    const Quadric3<T> q = to_real<T>(transform(all_cases()[std::size_t(trial % 20)].q, rng));
    const Vec3<T> x = rng.vec<T, 3>(-2, 2);
    // x^T A x + b.x + c with the full (symmetric) matrix product.
    const double ref = double(dot(x, q.a * x)) + double(dot(q.b, x)) + double(q.c);
    EXPECT_NEAR(double(signed_value(q, x)), ref, double(tol<T>(64, coefficient_scale(q) * 16)));
  }
}

TYPED_TEST(QuadricTest, QuadricSolidsConvertToTheirClass) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const T rel_tol = tol<T>(1024);
  for (int trial = 0; trial < 100; ++trial) {
    const Vec3<T> c = rng.vec<T, 3>(-3, 3), d = rng.unit<T, 3>();
    const Sphere3<T> s{c, rng.uniform<T>(T(0.5), 2)};
    const Cylinder3<T> cy{{c, d}, rng.uniform<T>(T(0.5), 2), T(1)};
    const Cone3<T> co{c, d, rng.uniform<T>(T(0.2), T(1.3)), 0, T(1)};
    Ellipsoid3<T> e{
        c, {}, {rng.uniform<T>(T(0.5), 2), rng.uniform<T>(T(0.5), 2), rng.uniform<T>(T(0.5), 2)}};
    const auto pb = perpendicular_basis(d);
    e.axis[0] = d, e.axis[1] = pb.u, e.axis[2] = pb.v;
    EXPECT_EQ(quadric_type(to_quadric(s), rel_tol).type, QuadricType::ellipsoid);
    EXPECT_EQ(quadric_type(to_quadric(e), rel_tol).type, QuadricType::ellipsoid);
    EXPECT_EQ(quadric_type(to_quadric(cy), rel_tol).type, QuadricType::elliptic_cylinder);
    EXPECT_EQ(quadric_type(to_quadric(co), rel_tol).type, QuadricType::elliptic_cone);
    // The general form evaluates to the solid's own implicit function.
    const Vec3<T> x = rng.vec<T, 3>(-4, 4);
    const T scale = T(100);  // |x - c|^2 <= 7^2 * 3 plus radii: terms of size ~100
    EXPECT_NEAR(signed_value(to_quadric(s), x), signed_value(s, x), tol<T>(64, scale));
    EXPECT_NEAR(signed_value(to_quadric(e), x), signed_value(e, x), tol<T>(64, 4 * scale));
    EXPECT_NEAR(signed_value(to_quadric(cy), x), signed_value(cy, x), tol<T>(64, scale));
    EXPECT_NEAR(signed_value(to_quadric(co), x), signed_value(co, x), tol<T>(64, scale));
  }
  // Exactly representable solids classify exactly.
  EXPECT_EQ(quadric_type(to_quadric(Sphere3<T>{{1, -2, 3}, 2})).type, QuadricType::ellipsoid);
  EXPECT_EQ(quadric_type(to_quadric(Sphere3<T>{{1, -2, 3}, 0})).type, QuadricType::point);
  EXPECT_EQ(quadric_type(to_quadric(Cylinder3<T>{{{1, 2, 3}, {0, 1, 0}}, 3, 1})).type,
            QuadricType::elliptic_cylinder);
  EXPECT_EQ(quadric_type(to_quadric(Cylinder3<T>{{{1, 2, 3}, {0, 1, 0}}, 0, 1})).type,
            QuadricType::line);
}

namespace {
// Inertia (positive, negative) of a symmetric rational matrix by congruence (symmetric Gaussian
// elimination with 1x1 or 2x2 pivots; Sylvester's law of inertia): an algorithm independent of
// the principal-minor signs that quadric_type() uses.
std::pair<int, int> exact_inertia(std::vector<std::vector<mpq_class>> m) {
  int pos = 0, neg = 0;
  while (!m.empty()) {
    const std::size_t n = m.size();
    std::size_t k = n;
    for (std::size_t i = 0; i < n; ++i)
      if (m[i][i] != 0) {
        k = i;
        break;
      }
    std::vector<std::size_t> piv;
    if (k < n) {
      (m[k][k] > 0 ? pos : neg) += 1;
      piv = {k};
    } else {
      std::size_t pi = n, pj = n;
      for (std::size_t i = 0; i < n && pi == n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
          if (m[i][j] != 0) {
            pi = i, pj = j;
            break;
          }
      if (pi == n) break;  // the rest is zero
      ++pos, ++neg;        // [[0, c], [c, 0]] has one positive and one negative eigenvalue
      piv = {pi, pj};
    }
    std::vector<std::size_t> rest;
    for (std::size_t i = 0; i < n; ++i)
      if (std::find(piv.begin(), piv.end(), i) == piv.end()) rest.push_back(i);
    std::vector<std::vector<mpq_class>> r(rest.size(), std::vector<mpq_class>(rest.size()));
    for (std::size_t a = 0; a < rest.size(); ++a)
      for (std::size_t b = 0; b < rest.size(); ++b) {
        const std::size_t i = rest[a], j = rest[b];
        if (piv.size() == 1) {
          r[a][b] = m[i][j] - m[i][k] * m[k][j] / m[k][k];
        } else {
          // Schur complement of the pivot block C = [[0, c], [c, 0]], C^-1 = [[0, 1/c], [1/c, 0]].
          const std::size_t p = piv[0], q = piv[1];
          const mpq_class c = m[p][q];
          r[a][b] = m[i][j] - (m[i][p] * m[q][j] + m[i][q] * m[p][j]) / c;
        }
      }
    m = r;
  }
  return {pos, neg};
}
}  // namespace

// Congruence by D = diag(2^k0, 2^k1, 2^k2, 2^k3) keeps the inertia of A and of M (Sylvester):
// a_ij 2^(ki + kj), b_i 2^(ki + k3), c 2^(2 k3) has the type of the integer quadric, with the
// coefficients spread over most of the exponent range of T (subnormals included for double).
TYPED_TEST(QuadricTest, ExtremeCongruentScalingsKeepTheExactType) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  constexpr bool dbl = std::is_same_v<T, double>;
  const int lo = dbl ? -530 : -45, hi = dbl ? 470 : 40;
  const std::vector<Case> cases = all_cases();
  int tested = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    const Case& c = cases[std::size_t(trial) % cases.size()];
    const IntQuadric iq = trial % 2 ? transform(c.q, rng) : c.q;
    const Quadric3<T> base = to_real<T>(iq);
    const QuadricClass expect = quadric_type(base);
    const int k[4] = {rng.uniform_int(lo, hi), rng.uniform_int(lo, hi), rng.uniform_int(lo, hi),
                      rng.uniform_int(lo, hi)};
    Quadric3<T> q = base;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) q.a.a[i][j] = std::ldexp(base.a.a[i][j], k[i] + k[j]);
      q.b[i] = std::ldexp(base.b[i], k[i] + k[3]);
    }
    q.c = std::ldexp(base.c, 2 * k[3]);
    // The scaling must be exact for the oracle to hold: undo it and compare.
    bool exact = true;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j)
        exact = exact && std::ldexp(q.a.a[i][j], -k[i] - k[j]) == base.a.a[i][j];
      exact = exact && std::ldexp(q.b[i], -k[i] - k[3]) == base.b[i];
    }
    exact = exact && std::ldexp(q.c, -2 * k[3]) == base.c;
    if (!exact) continue;
    const QuadricClass r = quadric_type(q);
    ++tested;
    ASSERT_EQ(expect.type, c.type) << c.name;
    ASSERT_TRUE(r.exact);
    ASSERT_EQ(r.type, c.type) << c.name << " trial " << trial;
    ASSERT_EQ(r.positive_m, expect.positive_m) << c.name << " trial " << trial;
    ASSERT_EQ(r.negative_m, expect.negative_m) << c.name << " trial " << trial;
    ASSERT_EQ(r.positive_a, expect.positive_a) << c.name << " trial " << trial;
  }
  EXPECT_GT(tested, 1000);
}

TYPED_TEST(QuadricTest, RandomIntegerQuadricsMatchRationalCongruenceOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int types_seen[int(QuadricType::invalid) + 1] = {};
  for (int trial = 0; trial < 3000; ++trial) {
    // Small coefficients with many zeros and low-rank products, so degenerate classes are common.
    IntQuadric q{};
    if (trial % 2) {
      for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j)
          q.a[i][j] = q.a[j][i] = rng.uniform_int(0, 2) ? 0 : rng.uniform_int(-3, 3);
    } else {  // A = sum of rank-one terms s u u^T
      const int terms = rng.uniform_int(0, 3);
      for (int t = 0; t < terms; ++t) {
        const I u[3] = {rng.uniform_int(-2, 2), rng.uniform_int(-2, 2), rng.uniform_int(-2, 2)};
        const I sg = rng.uniform_int(0, 1) ? 1 : -1;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) q.a[i][j] += sg * u[i] * u[j];
      }
    }
    for (int i = 0; i < 3; ++i) q.b[i] = rng.uniform_int(0, 1) ? 0 : 2 * rng.uniform_int(-3, 3);
    q.c = rng.uniform_int(0, 1) ? 0 : rng.uniform_int(-9, 9);
    if (trial % 3 == 0) q = transform(q, rng);  // rotated and translated: dense coefficients
    const Quadric3<T> qt = to_real<T>(q);
    std::vector<std::vector<mpq_class>> a(3, std::vector<mpq_class>(3)),
        m(4, std::vector<mpq_class>(4));
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j)
        a[std::size_t(i)][std::size_t(j)] = m[std::size_t(i)][std::size_t(j)] =
            mpq_class(q.a[i][j]);
      m[std::size_t(i)][3] = m[3][std::size_t(i)] = mpq_class(mpq_class(q.b[i]) / 2);
    }
    m[3][3] = mpq_class(q.c);
    const auto [pa, na] = exact_inertia(a);
    const auto [pm, nm] = exact_inertia(m);
    const auto r = quadric_type(qt);
    ASSERT_TRUE(r.exact);
    EXPECT_EQ(r.positive_a, pa);
    EXPECT_EQ(r.negative_a, na);
    EXPECT_EQ(r.positive_m, pm);
    EXPECT_EQ(r.negative_m, nm);
    EXPECT_EQ(r.type, detail::quadric_type_of_inertia(pa + na, pa, na, pm + nm, pm, nm));
    // Spot check of the set itself: a point on the surface found by the standard form is a
    // root of q (up to rounding), for every type with real points.
    const auto f = standard_form(qt);
    if (r.type != QuadricType::empty && r.type != QuadricType::entire_space) {
      const Vec3<T> x = f.center;  // the vertex / center lies on cones, points, lines, planes...
      if (f.constant == T(0)) {
        const T reach = length(x) + 1;
        EXPECT_NEAR(signed_value(qt, x), T(0), tol<T>(256, coefficient_scale(qt) * reach * reach));
      }
    }
    types_seen[int(r.type)] += 1;
  }
  // The random family reaches every type.
  for (int t = 0; t < int(QuadricType::invalid); ++t)
    EXPECT_GT(types_seen[t], 0) << to_string(QuadricType(t));
}
