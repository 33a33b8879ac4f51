// SPDX-License-Identifier: BSL-1.0
// Tests for core/basis.hpp (row core.basis; figures 3.13, 3.14, 3.16, 3.17).
#include <locus/core/basis.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <array>
#include <cmath>
#include <limits>
#include <tuple>
#include <vector>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;

template <class T>
class BasisTest : public ::testing::Test {};
TYPED_TEST_SUITE(BasisTest, locus_test::RealTypes);

namespace {

// Determinant of the columns a, b, c (written out here, independent of products.hpp).
template <class T>
T triple_det(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  return a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) +
         a.z * (b.x * c.y - b.y * c.x);
}

// Exact solve of a small dense rational system by Gauss-Jordan (the matrix must be regular).
std::vector<mpq_class> exact_solve(std::vector<std::vector<mpq_class>> m,
                                   std::vector<mpq_class> r) {
  const std::size_t n = r.size();
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t p = c;
    while (m[p][c] == 0) ++p;
    std::swap(m[p], m[c]);
    std::swap(r[p], r[c]);
    for (std::size_t i = 0; i < n; ++i) {
      if (i == c || m[i][c] == 0) continue;
      const mpq_class f = m[i][c] / m[c][c];
      for (std::size_t j = c; j < n; ++j) m[i][j] -= f * m[c][j];
      r[i] -= f * r[c];
    }
  }
  for (std::size_t i = 0; i < n; ++i) r[i] /= m[i][i];
  return r;
}

// Exact orthogonal projection of v onto span(s) (s independent): normal equations in rationals.
template <class T, int N, std::size_t K>
std::array<mpq_class, N> exact_projection(const Vec<T, N>& v, const std::array<Vec<T, N>, K>& s) {
  std::vector<std::vector<mpq_class>> g(K, std::vector<mpq_class>(K));
  std::vector<mpq_class> r(K);
  for (std::size_t i = 0; i < K; ++i) {
    for (std::size_t j = 0; j < K; ++j)
      for (int k = 0; k < N; ++k) g[i][j] += mpq_class(s[i][k]) * mpq_class(s[j][k]);
    for (int k = 0; k < N; ++k) r[i] += mpq_class(s[i][k]) * mpq_class(v[k]);
  }
  const auto c = exact_solve(g, r);
  std::array<mpq_class, N> p{};
  for (std::size_t i = 0; i < K; ++i)
    for (int k = 0; k < N; ++k) p[static_cast<std::size_t>(k)] += c[i] * mpq_class(s[i][k]);
  return p;
}

template <class T, int N, std::size_t K>
::testing::AssertionResult orthonormal(const std::array<Vec<T, N>, K>& q, int count, T t) {
  for (int i = 0; i < count; ++i)
    for (int j = i; j < count; ++j) {
      const T e = dot(q[static_cast<std::size_t>(i)], q[static_cast<std::size_t>(j)]) -
                  (i == j ? T(1) : T(0));
      if (!(std::abs(e) <= t))
        return ::testing::AssertionFailure() << "q" << i << ".q" << j << " off by " << e;
    }
  return ::testing::AssertionSuccess();
}

// Residual of v after removing its components along the orthonormal q[0..count), by a direct
// sum (not the library's routine).
template <class T, int N, std::size_t K>
T residual(const Vec<T, N>& v, const std::array<Vec<T, N>, K>& q, int count) {
  Vec<T, N> p{};
  for (int j = 0; j < count; ++j)
    p += q[static_cast<std::size_t>(j)] * dot(q[static_cast<std::size_t>(j)], v);
  return length(v - p);
}

// Sine of the angle between a and b, in double (|b - a| carries the information when b is
// nearly a, so the rejection is computed from d = b - a).
template <class T, int N>
double sine_between(const Vec<T, N>& a, const Vec<T, N>& b) {
  double aa = 0, ad = 0, bb = 0;
  Vec<double, N> d{};
  for (int k = 0; k < N; ++k) {
    d[k] = double(b[k]) - double(a[k]);
    aa += double(a[k]) * double(a[k]);
    ad += double(a[k]) * d[k];
    bb += double(b[k]) * double(b[k]);
  }
  double rr = 0;  // |d - (a.d / a.a) a|^2 = squared distance of b from the line of a
  for (int k = 0; k < N; ++k) {
    const double r = d[k] - ad / aa * double(a[k]);
    rr += r * r;
  }
  return std::sqrt(rr / bb);
}

template <class T, int N, std::size_t K>
void check_gram_schmidt(Rng& rng, bool ill_conditioned) {
  for (int n = 0; n < 200; ++n) {
    std::array<Vec<T, N>, K> v{};
    for (auto& x : v) x = rng.vec<T, N>(-3, 3);
    // Nearly dependent input: classical Gram-Schmidt loses orthogonality here. The perturbation
    // is redrawn while the sine of the angle between v[0] and v[1] is below 1e-4: a perturbation
    // nearly parallel to v[0] can make that sine as small as the documented independence
    // tolerance (64 eps = 7.6e-6 for float; seed 14 drew 5.1e-6, where rank 2 is the right
    // answer), and the tolerances below assume a residual of at least 1e-4 relative.
    if (ill_conditioned) {
      do {
        v[1] = v[0] + rng.vec<T, N>(T(-1e-3), T(1e-3));
      } while (sine_between(v[0], v[1]) < 1e-4);
    }
    const auto g = gram_schmidt(v);
    const int expected = static_cast<int>(K) < N ? static_cast<int>(K) : N;
    ASSERT_EQ(g.rank, expected);
    EXPECT_EQ(g.status, g.rank == static_cast<int>(K) ? Status::ok : Status::degenerate_input);
    EXPECT_TRUE(orthonormal(g.basis, g.rank, tol<T>(4 * N)));
    // Same span: every input is in the span of the output, every output in the span of the
    // input (the second check with the exact projection onto the independent inputs).
    for (const auto& x : v) EXPECT_LE(residual(x, g.basis, g.rank), tol<T>(16 * N, length(x)));
    if (static_cast<int>(K) <= N) {
      for (int j = 0; j < g.rank; ++j) {
        const auto& q = g.basis[static_cast<std::size_t>(j)];
        const auto p = exact_projection(q, v);
        for (int k = 0; k < N; ++k)
          EXPECT_NEAR(double(q[k]), p[static_cast<std::size_t>(k)].get_d(),
                      // v[1] - v[0] ~ 1e-3 |v|: the residual that becomes q[1] carries
                      // rounding errors ~ eps |v|, i.e. ~1e3 eps relative to its length.
                      double(ill_conditioned ? tol<T>(64, T(2e3)) : tol<T>(64)));
      }
    }
    // Order is kept: basis[0] points along v[0].
    EXPECT_NEAR(dot(g.basis[0], normalize(v[0])), T(1), tol<T>(4));
    for (int j = g.rank; j < static_cast<int>(K); ++j)
      EXPECT_EQ(g.basis[static_cast<std::size_t>(j)], (Vec<T, N>{}));
  }
}

}  // namespace

TYPED_TEST(BasisTest, GramSchmidtIsOrthonormalAndSpansTheInput) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  check_gram_schmidt<T, 3, 3>(rng, false);
  check_gram_schmidt<T, 3, 2>(rng, false);
  check_gram_schmidt<T, 2, 2>(rng, false);
  check_gram_schmidt<T, 6, 4>(rng, false);
  check_gram_schmidt<T, 2, 3>(rng, false);  // three vectors in the plane: rank 2
  check_gram_schmidt<T, 3, 3>(rng, true);
  check_gram_schmidt<T, 5, 3>(rng, true);
}

TYPED_TEST(BasisTest, GramSchmidtOfThreeAndTwoVectorsAndHandedness) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 1000; ++n) {
    const auto a = rng.vec<T, 3>(-1, 1), b = rng.vec<T, 3>(-1, 1), c = rng.vec<T, 3>(-1, 1);
    const auto g = gram_schmidt(a, b, c);
    if (g.rank < 3) continue;
    // Figure 3.16: orthonormalisation keeps the orientation of the triple.
    EXPECT_EQ(is_right_handed(g.basis[0], g.basis[1], g.basis[2]), is_right_handed(a, b, c));
    const auto g2 = gram_schmidt(a, b);
    EXPECT_EQ(g2.basis[0], g.basis[0]);
    EXPECT_EQ(g2.basis[1], g.basis[1]);
    EXPECT_GT(dot(g2.basis[1], b), T(0));
  }
}

TYPED_TEST(BasisTest, GramSchmidtReportsDependentZeroAndNonFiniteInput) {
  using T = TypeParam;
  const Vec3<T> a{1, 2, 3}, b{-2, 0, 5};
  const Vec3<T> c = a * T(2) - b * T(3);  // exact in both types: integers
  const auto g = gram_schmidt(a, b, c);
  EXPECT_EQ(g.status, Status::degenerate_input);
  EXPECT_EQ(g.rank, 2);
  EXPECT_EQ(g.basis[2], (Vec3<T>{}));
  EXPECT_TRUE(orthonormal(g.basis, 2, tol<T>(8)));
  // Dependent vector first: it is skipped and the later ones are used.
  const auto z = gram_schmidt(Vec3<T>{}, a, a * T(-4));
  EXPECT_EQ(z.rank, 1);
  EXPECT_NEAR(dot(z.basis[0], normalize(a)), T(1), tol<T>(4));
  const auto nn = gram_schmidt(a, Vec3<T>{std::numeric_limits<T>::quiet_NaN(), 0, 0});
  EXPECT_EQ(nn.status, Status::non_finite_input);
  EXPECT_EQ(nn.rank, 0);
  EXPECT_EQ(gram_schmidt(a, Vec3<T>{std::numeric_limits<T>::infinity(), 0, 0}).status,
            Status::non_finite_input);
  // Tiny and huge vectors are normalised first: no underflow/overflow in the residuals.
  const T tiny = std::numeric_limits<T>::denorm_min() * T(16);
  const T huge = std::numeric_limits<T>::max() / T(2);
  const auto th = gram_schmidt(Vec3<T>{tiny, tiny, 0}, Vec3<T>{huge, 0, 0});
  EXPECT_EQ(th.rank, 2);
  EXPECT_TRUE(orthonormal(th.basis, 2, tol<T>(8)));
}

TYPED_TEST(BasisTest, LinearIndependenceWithNamedTolerance) {
  using T = TypeParam;
  const Vec3<T> x{1, 0, 0}, y{0, 1, 0};
  EXPECT_TRUE(linearly_independent(x, y));
  EXPECT_FALSE(linearly_independent(x, x * T(-3)));
  EXPECT_FALSE(linearly_independent(x, Vec3<T>{}));
  EXPECT_FALSE(linearly_independent(x, y, x + y));
  EXPECT_TRUE(linearly_independent(x, y, Vec3<T>{1, 1, 1}));
  // Nearly parallel: independent at the default (rounding-level) tolerance, dependent with a
  // user tolerance larger than the sine of the angle (1e-3).
  const Vec3<T> b{1, T(1e-3), 0};
  EXPECT_TRUE(linearly_independent(x, b));
  EXPECT_FALSE(linearly_independent(x, b, T(1e-2)));
  EXPECT_TRUE(linearly_independent(x, b, T(1e-4)));
  // Symmetric for two vectors.
  EXPECT_EQ(linearly_independent(b, x, T(1e-2)), linearly_independent(x, b, T(1e-2)));
  // Four vectors in 3D are always dependent; NaN is never independent.
  EXPECT_FALSE(linearly_independent(std::array<Vec3<T>, 4>{x, y, Vec3<T>{0, 0, 1}, b}));
  EXPECT_FALSE(linearly_independent(x, Vec3<T>{0, std::numeric_limits<T>::quiet_NaN(), 0}));
  // Exactly dependent integer sets at random: always detected.
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 1000; ++n) {
    Vec<T, 4> p{}, q{};
    for (int i = 0; i < 4; ++i) {
      p[i] = T(rng.uniform_int(-50, 50));
      q[i] = T(rng.uniform_int(-50, 50));
    }
    const Vec<T, 4> r = p * T(rng.uniform_int(-5, 5)) + q * T(rng.uniform_int(-5, 5));
    EXPECT_FALSE(linearly_independent(p, q, r));
  }
}

// Figure 3.16: the right-hand rule.
TYPED_TEST(BasisTest, Fig3_16RightHandedness) {
  using T = TypeParam;
  const Vec3<T> x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  EXPECT_TRUE(is_right_handed(x, y, z));
  EXPECT_TRUE(is_right_handed(y, z, x));
  EXPECT_FALSE(is_right_handed(y, x, z));
  EXPECT_FALSE(is_right_handed(x, y, -z));
  EXPECT_FALSE(is_right_handed(x, y, x));  // degenerate: not right-handed
  // det = (1 + e)^2 - (1 + 2e) = e^2 > 0 exactly, while the rounded determinant is 0.
  const T e = eps_v<T>;
  const Vec3<T> b{0, T(1) + e, T(1) + T(2) * e}, c{0, T(1), T(1) + e};
  EXPECT_TRUE(is_right_handed(x, b, c));
  EXPECT_FALSE(is_right_handed(x, c, b));
  EXPECT_TRUE(is_right_handed(Vec2<T>{T(1) + e, T(1) + T(2) * e}, Vec2<T>{T(1), T(1) + e}));
  EXPECT_FALSE(is_right_handed(x, y, Vec3<T>{0, 0, std::numeric_limits<T>::quiet_NaN()}));
  EXPECT_TRUE(is_right_handed(Vec2<T>{1, 0}, Vec2<T>{0, 1}));
  EXPECT_FALSE(is_right_handed(Vec2<T>{0, 1}, Vec2<T>{1, 0}));
  EXPECT_TRUE(is_orthonormal(std::array<Vec3<T>, 3>{x, y, z}));
  EXPECT_FALSE(is_orthonormal(std::array<Vec3<T>, 3>{x, y, z * T(1.001)}));
  EXPECT_FALSE(is_orthonormal(std::array<Vec3<T>, 2>{x, normalize(Vec3<T>{1, 1, 0})}));
  EXPECT_FALSE(is_orthonormal(
      std::array<Vec2<T>, 2>{Vec2<T>{1, 0}, Vec2<T>{0, std::numeric_limits<T>::quiet_NaN()}}));
}

template <class T>
void check_completion(const Vec3<T>& d) {
  const auto b = complete_basis(d);
  ASSERT_EQ(b.status, Status::ok);
  EXPECT_TRUE(orthonormal(b.axis, 3, tol<T>(8)));
  EXPECT_NEAR(triple_det(b.axis[0], b.axis[1], b.axis[2]), T(1), tol<T>(8));
  EXPECT_TRUE(locus_test::vec_near(b.axis[0], normalize(d), tol<T>(2)));
  EXPECT_TRUE(is_finite(b.axis[1]) && is_finite(b.axis[2]));
}

// 10^4 random unit vectors plus the hard directions of Frisvad's original method.
TYPED_TEST(BasisTest, CompleteBasisFromOneVectorIsOrthonormalAndRightHanded) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 10000; ++n) check_completion(rng.unit<T, 3>());
  for (int n = 0; n < 2000; ++n) {
    // Near the poles (z close to -1 and +1) and near the axes.
    const T e = T(std::pow(10.0, -rng.uniform<double>(2, 30)));
    check_completion(Vec3<T>{e * rng.uniform<T>(-1, 1), e * rng.uniform<T>(-1, 1), T(-1)});
    check_completion(Vec3<T>{e * rng.uniform<T>(-1, 1), e * rng.uniform<T>(-1, 1), T(1)});
    check_completion(Vec3<T>{T(1), e, T(0)});
  }
  const T tiny = T(1e-20);
  for (const Vec3<T>& d :
       {Vec3<T>{1, tiny, 0}, Vec3<T>{0, 0, -1}, Vec3<T>{0, 0, 1}, Vec3<T>{-1, 0, 0},
        Vec3<T>{0, -1, 0}, Vec3<T>{tiny, 0, -1}, Vec3<T>{-tiny, tiny, -1}, Vec3<T>{0, 0, -T(0.5)},
        Vec3<T>{1, 0, -T(0)}, Vec3<T>{T(3e-30), T(-4e-30), T(1e-31)}, Vec3<T>{T(1e30), 0, T(1e30)}})
    check_completion(d);
  const auto z = complete_basis(Vec3<T>{});
  EXPECT_EQ(z.status, Status::degenerate_input);
  EXPECT_EQ(z.axis[0], (Vec3<T>{1, 0, 0}));
  EXPECT_TRUE(orthonormal(z.axis, 3, T(0)));
  const auto nn = complete_basis(Vec3<T>{0, std::numeric_limits<T>::quiet_NaN(), 1});
  EXPECT_EQ(nn.status, Status::non_finite_input);
  EXPECT_TRUE(orthonormal(nn.axis, 3, T(0)));
}

TYPED_TEST(BasisTest, CompleteBasisIn2DAndFromTwoVectors) {
  using T = TypeParam;
  const auto b2 = complete_basis(Vec2<T>{3, 4});
  EXPECT_EQ(b2.status, Status::ok);
  EXPECT_TRUE(locus_test::vec_near(b2.axis[0], Vec2<T>{T(0.6), T(0.8)}, tol<T>(2)));
  EXPECT_EQ(b2.axis[1], perp(b2.axis[0]));
  EXPECT_EQ(complete_basis(Vec2<T>{}).status, Status::degenerate_input);
  EXPECT_EQ(complete_basis(Vec2<T>{std::numeric_limits<T>::infinity(), 0}).status,
            Status::non_finite_input);
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 2000; ++n) {
    const auto a = rng.vec<T, 3>(-2, 2), b = rng.vec<T, 3>(-2, 2);
    const auto f = complete_basis(a, b);
    ASSERT_EQ(f.status, Status::ok);
    EXPECT_TRUE(orthonormal(f.axis, 3, tol<T>(8)));
    EXPECT_NEAR(triple_det(f.axis[0], f.axis[1], f.axis[2]), T(1), tol<T>(8));
    EXPECT_NEAR(dot(f.axis[0], normalize(a)), T(1), tol<T>(4));
    EXPECT_GT(dot(f.axis[1], b), T(0));                           // towards b
    EXPECT_NEAR(dot(f.axis[2], b), T(0), tol<T>(16, length(b)));  // in the plane of a, b
  }
  // Dependent input: still an orthonormal right-handed basis, along the first non-zero input.
  const auto dep = complete_basis(Vec3<T>{}, Vec3<T>{0, 0, 2});
  EXPECT_EQ(dep.status, Status::degenerate_input);
  EXPECT_EQ(dep.axis[0], (Vec3<T>{0, 0, 1}));
  EXPECT_TRUE(orthonormal(dep.axis, 3, tol<T>(8)));
  EXPECT_NEAR(triple_det(dep.axis[0], dep.axis[1], dep.axis[2]), T(1), tol<T>(8));
  const auto par = complete_basis(Vec3<T>{1, 1, 0}, Vec3<T>{-2, -2, 0});
  EXPECT_EQ(par.status, Status::degenerate_input);
  EXPECT_TRUE(orthonormal(par.axis, 3, tol<T>(8)));
  EXPECT_EQ(
      complete_basis(Vec3<T>{1, 0, 0}, Vec3<T>{std::numeric_limits<T>::quiet_NaN(), 0, 0}).status,
      Status::non_finite_input);
}

// Figure 3.13: the span of two vectors in 3D is a plane; projection onto it.
TYPED_TEST(BasisTest, Fig3_13ProjectionOntoASpanMatchesExactNormalEquations) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 1000; ++n) {
    const std::array<Vec3<T>, 2> s{rng.vec<T, 3>(-2, 2), rng.vec<T, 3>(-2, 2)};
    if (length(cross(s[0], s[1])) < T(0.1) * length(s[0]) * length(s[1])) continue;
    const auto v = rng.vec<T, 3>(-3, 3);
    const auto p = project_onto_span(v, s);
    const auto e = exact_projection(v, s);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(double(p[k]), e[static_cast<std::size_t>(k)].get_d(),
                  double(tol<T>(64, length(v))));
    const auto r = reject_from_span(v, s);
    EXPECT_NEAR(dot(r, s[0]), T(0), tol<T>(32, length(v) * length(s[0])));
    EXPECT_NEAR(dot(r, s[1]), T(0), tol<T>(32, length(v) * length(s[1])));
    EXPECT_TRUE(in_span(s[0] * T(2) - s[1] * T(0.5), s));
    EXPECT_FALSE(in_span(cross(s[0], s[1]), s));
  }
  // 5D, three spanning vectors.
  for (int n = 0; n < 300; ++n) {
    const std::array<Vec<T, 5>, 3> s{rng.vec<T, 5>(-2, 2), rng.vec<T, 5>(-2, 2),
                                     rng.vec<T, 5>(-2, 2)};
    const auto v = rng.vec<T, 5>(-3, 3);
    const auto p = project_onto_span(v, s);
    const auto e = exact_projection(v, s);
    for (int k = 0; k < 5; ++k)
      EXPECT_NEAR(double(p[k]), e[static_cast<std::size_t>(k)].get_d(),
                  double(tol<T>(256, length(v))));
  }
  // A dependent spanning set spans a line; a zero set spans {0}; NaN propagates.
  const std::array<Vec3<T>, 2> line{Vec3<T>{1, 1, 0}, Vec3<T>{2, 2, 0}};
  EXPECT_TRUE(locus_test::vec_near(project_onto_span(Vec3<T>{1, 0, 5}, line),
                                   Vec3<T>{T(0.5), T(0.5), 0}, tol<T>(8)));
  EXPECT_EQ(project_onto_span(Vec3<T>{1, 2, 3}, std::array<Vec3<T>, 1>{}), (Vec3<T>{}));
  EXPECT_TRUE(in_span(Vec3<T>{}, std::array<Vec3<T>, 1>{}));
  EXPECT_FALSE(is_finite(project_onto_span(
      Vec3<T>{1, 2, 3},
      std::array<Vec3<T>, 1>{Vec3<T>{std::numeric_limits<T>::quiet_NaN(), 0, 0}})));
  EXPECT_FALSE(in_span(Vec3<T>{std::numeric_limits<T>::quiet_NaN(), 0, 0}, line));
}

// Figures 3.14 and 3.17: a vector as a linear combination of two different bases.
TYPED_TEST(BasisTest, Fig3_14And3_17CoordinatesInABasisMatchExactSolve) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 1000; ++n) {
    std::array<Vec3<T>, 3> b1{}, b2{};
    for (auto& x : b1) x = rng.vec<T, 3>(-2, 2);
    for (auto& x : b2) x = rng.vec<T, 3>(-2, 2);
    const T d1 = std::abs(triple_det(b1[0], b1[1], b1[2]));
    const T d2 = std::abs(triple_det(b2[0], b2[1], b2[2]));
    if (d1 < T(0.2) || d2 < T(0.2)) continue;  // the conditioning is the solvers' topic
    const auto v = rng.vec<T, 3>(-3, 3);
    const auto c1 = basis_coordinates(v, b1), c2 = basis_coordinates(v, b2);
    ASSERT_TRUE(c1 && c2);
    for (const auto& [b, c, d] : {std::tuple{b1, *c1, d1}, std::tuple{b2, *c2, d2}}) {
      std::vector<std::vector<mpq_class>> m(3, std::vector<mpq_class>(3));
      std::vector<mpq_class> r(3);
      for (int i = 0; i < 3; ++i) {
        r[static_cast<std::size_t>(i)] = v[i];
        for (int j = 0; j < 3; ++j)
          m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
              b[static_cast<std::size_t>(j)][i];
      }
      const auto e = exact_solve(m, r);
      // Error bound ~ eps * |v| * |B| * |B^-1|; |B^-1| <= |B|^2 / |det B| (adjugate bound).
      const T scale = T(3) * T(12) * T(12) / d;
      for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(double(c[i]), e[static_cast<std::size_t>(i)].get_d(),
                    double(tol<T>(64, scale)));
      // Reconstruction: the same v from both bases.
      const Vec3<T> back = b[0] * c[0] + b[1] * c[1] + b[2] * c[2];
      EXPECT_TRUE(locus_test::vec_near(back, v, tol<T>(64, scale)));
    }
  }
  // Two vectors spanning a plane in 3D: exact coordinates for v in the plane.
  const std::array<Vec3<T>, 2> plane{Vec3<T>{1, 0, 1}, Vec3<T>{0, 2, 1}};
  const auto c = basis_coordinates(Vec3<T>{3, -4, 1}, plane);  // = 3 p0 - 2 p1
  ASSERT_TRUE(c);
  EXPECT_NEAR((*c)[0], T(3), tol<T>(16));
  EXPECT_NEAR((*c)[1], T(-2), tol<T>(16));
  // Dependent basis and non-finite input.
  EXPECT_FALSE(basis_coordinates(
      Vec3<T>{1, 2, 3},
      std::array<Vec3<T>, 3>{Vec3<T>{1, 0, 0}, Vec3<T>{0, 1, 0}, Vec3<T>{1, 1, 0}}));
  EXPECT_FALSE(basis_coordinates(Vec3<T>{1, 2, std::numeric_limits<T>::quiet_NaN()}, plane));
  // Tiny basis vectors: coordinates are large but exact in scale.
  const T s = T(1e-20);
  const auto ct =
      basis_coordinates(Vec2<T>{1, 1}, std::array<Vec2<T>, 2>{Vec2<T>{s, 0}, Vec2<T>{0, s}});
  ASSERT_TRUE(ct);
  EXPECT_NEAR((*ct)[0], T(1) / s, tol<T>(8, T(1) / s));
}
