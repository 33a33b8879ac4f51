// SPDX-License-Identifier: BSL-1.0
// Tests for core/barycentric.hpp (row core.affine; figures 3.41, 3.42).
#include <locus/core/barycentric.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;

template <class T>
class BarycentricTest : public ::testing::Test {};
TYPED_TEST_SUITE(BarycentricTest, locus_test::RealTypes);

namespace {

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

// Exact barycentric coordinates of the orthogonal projection of p onto the affine hull of the
// (affinely independent) vertices: normal equations of the edges from v0, in rationals.
template <class T, int N>
std::vector<mpq_class> exact_bary(const Vec<T, N>& p, const std::vector<Vec<T, N>>& v) {
  const std::size_t m = v.size() - 1;
  std::vector<std::vector<mpq_class>> g(m, std::vector<mpq_class>(m));
  std::vector<mpq_class> r(m);
  auto e = [&](std::size_t i, int k) -> mpq_class {
    return mpq_class(v[i + 1][k]) - mpq_class(v[0][k]);
  };
  for (std::size_t i = 0; i < m; ++i) {
    for (std::size_t j = 0; j < m; ++j)
      for (int k = 0; k < N; ++k) g[i][j] += e(i, k) * e(j, k);
    for (int k = 0; k < N; ++k) r[i] += e(i, k) * (mpq_class(p[k]) - mpq_class(v[0][k]));
  }
  const auto c = exact_solve(g, r);
  std::vector<mpq_class> w(m + 1);
  w[0] = 1;
  for (std::size_t i = 0; i < m; ++i) {
    w[i + 1] = c[i];
    w[0] -= c[i];
  }
  return w;
}

// Conditioning scale of a simplex query: (largest distance among p and the vertices)^d over the
// simplex's d-volume measure (|det| of the edge vectors, or sqrt of the Gram determinant).
template <class T, int N>
double condition(const Vec<T, N>& p, const std::vector<Vec<T, N>>& v) {
  double far = 0;
  for (const auto& x : v) {
    far = std::max(far, double(length(x - p)));
    for (const auto& y : v) far = std::max(far, double(length(x - y)));
  }
  const std::size_t m = v.size() - 1;
  std::vector<std::vector<mpq_class>> g(m, std::vector<mpq_class>(m));
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = 0; j < m; ++j)
      for (int k = 0; k < N; ++k)
        g[i][j] += (mpq_class(v[i + 1][k]) - v[0][k]) * (mpq_class(v[j + 1][k]) - v[0][k]);
  // Gram determinant by exact elimination.
  mpq_class det = 1;
  for (std::size_t c = 0; c < m; ++c) {
    std::size_t piv = c;
    while (piv < m && g[piv][c] == 0) ++piv;
    if (piv == m) return std::numeric_limits<double>::infinity();
    std::swap(g[piv], g[c]);
    det *= g[c][c];
    for (std::size_t i = c + 1; i < m; ++i) {
      const mpq_class f = g[i][c] / g[c][c];
      for (std::size_t j = c; j < m; ++j) g[i][j] -= f * g[c][j];
    }
  }
  return std::pow(far, double(m)) / std::sqrt(det.get_d());
}

// First-order error model: rounding the inputs' differences perturbs the sub-volumes by
// ~eps * far^d and the total volume by ~eps * edge^d, so a weight's error is
// ~eps * cond * (1 + |w|) with cond from condition() (the |w| term is the relative error of the
// volume, carried by every weight).
double weight_scale(const std::vector<mpq_class>& e) {
  double m = 0;
  for (const auto& x : e) m = std::max(m, std::abs(x.get_d()));
  return 1 + m;
}

template <class T, std::size_t K>
void expect_weights(const std::array<T, K>& w, const std::vector<mpq_class>& e, double t) {
  t *= weight_scale(e);
  for (std::size_t i = 0; i < K; ++i) EXPECT_NEAR(double(w[i]), e[i].get_d(), t) << "weight " << i;
}

template <class T, std::size_t K>
bool no_nan(const std::array<T, K>& w) {
  for (T x : w)
    if (x != x) return false;
  return true;
}

}  // namespace

// Figure 3.41: affine coordinates (s, t) of p = a + s (b - a) + t (c - a) are the barycentric
// coordinates (1 - s - t, s, t).
TYPED_TEST(BarycentricTest, Fig3_41AffineVersusBarycentricCoordinates) {
  using T = TypeParam;
  const Vec2<T> a{1, 1}, b{5, 2}, c{2, 6};
  const T s = T(0.25), t = T(0.5);
  const Vec2<T> p = a + (b - a) * s + (c - a) * t;
  const auto w = barycentric(p, a, b, c);
  EXPECT_TRUE(w.valid);
  EXPECT_NEAR(w.w[0], T(0.25), tol<T>(16));
  EXPECT_NEAR(w.w[1], s, tol<T>(16));
  EXPECT_NEAR(w.w[2], t, tol<T>(16));
  // Vertices have unit coordinates; the centroid (1/3, 1/3, 1/3).
  const auto wa = barycentric(a, a, b, c);
  EXPECT_EQ(wa.w[0], T(1));
  EXPECT_EQ(wa.w[1], T(0));
  EXPECT_EQ(wa.w[2], T(0));
  const auto wc = barycentric((a + b + c) / T(3), a, b, c);
  for (T x : wc.w) EXPECT_NEAR(x, T(1) / T(3), tol<T>(16));
}

// Figure 3.42: the first simplexes -- segment, triangle, tetrahedron -- and their coordinates.
TYPED_TEST(BarycentricTest, Fig3_42SegmentTriangleTetrahedron) {
  using T = TypeParam;
  const Vec3<T> a{0, 0, 0}, b{4, 0, 0}, c{0, 4, 0}, d{0, 0, 4};
  const auto s = barycentric(Vec3<T>{1, 3, -2}, a, b);  // projected onto the line: t = 1/4
  EXPECT_TRUE(s.valid);
  EXPECT_EQ(s.w[0], T(0.75));
  EXPECT_EQ(s.w[1], T(0.25));
  const auto t = barycentric(Vec3<T>{1, 2, 7}, a, b, c);  // projected onto z = 0
  EXPECT_TRUE(t.valid);
  EXPECT_NEAR(t.w[0], T(0.25), tol<T>(8));
  EXPECT_NEAR(t.w[1], T(0.25), tol<T>(8));
  EXPECT_NEAR(t.w[2], T(0.5), tol<T>(8));
  const auto q = barycentric(Vec3<T>{1, 1, 1}, a, b, c, d);
  EXPECT_TRUE(q.valid);
  for (int i = 1; i < 4; ++i) EXPECT_NEAR(q.w[static_cast<std::size_t>(i)], T(0.25), tol<T>(8));
  EXPECT_NEAR(q.w[0], T(0.25), tol<T>(8));
  // Vertices of the tetrahedron: unit coordinates.
  const std::array<Vec3<T>, 4> v{a, b, c, d};
  for (std::size_t i = 0; i < 4; ++i) {
    const auto w = barycentric(v[i], a, b, c, d);
    for (std::size_t j = 0; j < 4; ++j) EXPECT_NEAR(w.w[j], i == j ? T(1) : T(0), tol<T>(4));
  }
}

TYPED_TEST(BarycentricTest, SegmentMatchesExactProjectedParameter) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 1000; ++n) {
    const auto a = rng.vec<T, 3>(-5, 5), b = rng.vec<T, 3>(-5, 5), p = rng.vec<T, 3>(-5, 5);
    const auto w = barycentric(p, a, b);
    ASSERT_TRUE(w.valid);
    const auto e = exact_bary(p, std::vector<Vec3<T>>{a, b});
    expect_weights(w.w, e, double(tol<T>(8)) * condition(p, std::vector<Vec3<T>>{a, b}));
  }
}

TYPED_TEST(BarycentricTest, Triangle2DMatchesExactRationalSolve) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 1000; ++n) {
    const std::vector<Vec2<T>> v{rng.vec<T, 2>(-5, 5), rng.vec<T, 2>(-5, 5), rng.vec<T, 2>(-5, 5)};
    const auto p = rng.vec<T, 2>(-8, 8);
    const auto w = barycentric(p, v[0], v[1], v[2]);
    const double k = condition(p, v);
    if (k > 1e4) continue;  // near-flat draws: see the degenerate tests
    ASSERT_TRUE(w.valid);
    const auto e = exact_bary(p, v);
    const double ws = weight_scale(e);
    expect_weights(w.w, e, double(tol<T>(16)) * k);
    // Inverse: the weights rebuild p (|w_i| |v_i| sized terms cancel).
    EXPECT_TRUE(locus_test::vec_near(from_barycentric(v[0], v[1], v[2], w.w), p,
                                     T(double(tol<T>(64)) * k * 10 * ws)));
    // Second method: the general simplex routine.
    const auto g = barycentric(p, std::array<Vec2<T>, 3>{v[0], v[1], v[2]});
    ASSERT_TRUE(g.valid);
    for (std::size_t i = 0; i < 3; ++i)
      EXPECT_NEAR(double(g.w[i]), double(w.w[i]), double(tol<T>(64)) * k * ws);
  }
}

TYPED_TEST(BarycentricTest, Triangle3DProjectsOntoThePlane) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 1000; ++n) {
    const std::vector<Vec3<T>> v{rng.vec<T, 3>(-5, 5), rng.vec<T, 3>(-5, 5), rng.vec<T, 3>(-5, 5)};
    const auto p = rng.vec<T, 3>(-8, 8);
    const double k = condition(p, v);
    if (k > 1e4) continue;
    const auto w = barycentric(p, v[0], v[1], v[2]);
    ASSERT_TRUE(w.valid);
    const auto e = exact_bary(p, v);
    expect_weights(w.w, e, double(tol<T>(32)) * k);
    // The rebuilt point is p's projection: p minus it is normal to the plane.
    const auto q = from_barycentric(v[0], v[1], v[2], w.w);
    const auto nrm = normalize(cross(v[1] - v[0], v[2] - v[0]));
    EXPECT_NEAR(double(length(cross(p - q, nrm))), 0.0,
                double(tol<T>(64)) * k * 10 * weight_scale(e));
  }
}

TYPED_TEST(BarycentricTest, TetrahedronMatchesExactRationalSolve) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 1000; ++n) {
    const std::vector<Vec3<T>> v{rng.vec<T, 3>(-5, 5), rng.vec<T, 3>(-5, 5), rng.vec<T, 3>(-5, 5),
                                 rng.vec<T, 3>(-5, 5)};
    const auto p = rng.vec<T, 3>(-8, 8);
    const double k = condition(p, v);
    if (k > 1e4) continue;
    const auto w = barycentric(p, v[0], v[1], v[2], v[3]);
    ASSERT_TRUE(w.valid);
    const auto e = exact_bary(p, v);
    const double ws = weight_scale(e);
    expect_weights(w.w, e, double(tol<T>(32)) * k);
    EXPECT_TRUE(locus_test::vec_near(from_barycentric(v[0], v[1], v[2], v[3], w.w), p,
                                     T(double(tol<T>(64)) * k * 10 * ws)));
    // Permuting the vertices permutes the weights.
    const auto r = barycentric(p, v[2], v[0], v[3], v[1]);
    EXPECT_NEAR(double(r.w[0]), double(w.w[2]), double(tol<T>(64)) * k * ws);
    EXPECT_NEAR(double(r.w[3]), double(w.w[1]), double(tol<T>(64)) * k * ws);
  }
}

template <class T, int N, std::size_t K>
void check_simplex(Rng& rng, int count) {
  for (int n = 0; n < count; ++n) {
    std::array<Vec<T, N>, K> v{};
    for (auto& x : v) x = rng.vec<T, N>(-5, 5);
    const auto p = rng.vec<T, N>(-8, 8);
    const std::vector<Vec<T, N>> vv(v.begin(), v.end());
    const double k = condition(p, vv);
    if (k > 1e4) continue;
    const auto w = barycentric(p, v);
    ASSERT_TRUE(w.valid);
    const auto e = exact_bary(p, vv);
    expect_weights(w.w, e, double(tol<T>(64)) * k);
    // Translation and scaling of everything leave the weights unchanged.
    std::array<Vec<T, N>, K> moved{};
    const Vec<T, N> shift = rng.vec<T, N>(-100, 100);
    for (std::size_t i = 0; i < K; ++i) moved[i] = v[i] * T(4) + shift;
    const auto wm = barycentric(p * T(4) + shift, moved);
    for (std::size_t i = 0; i < K; ++i)
      EXPECT_NEAR(double(wm.w[i]), double(w.w[i]), double(tol<T>(64)) * k * 40 * weight_scale(e));
  }
}

TYPED_TEST(BarycentricTest, GeneralSimplexInNDMatchesExactSolve) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  check_simplex<T, 3, 4>(rng, 300);  // tetrahedron
  check_simplex<T, 5, 3>(rng, 300);  // triangle in 5D (projection onto its plane)
  check_simplex<T, 5, 6>(rng, 300);  // full 5-simplex
  check_simplex<T, 4, 2>(rng, 300);  // segment in 4D
}

TYPED_TEST(BarycentricTest, DegenerateSimplicesGiveValidFalseAndNoNaN) {
  using T = TypeParam;
  // Zero-length segment.
  const auto s = barycentric(Vec2<T>{3, 3}, Vec2<T>{1, 1}, Vec2<T>{1, 1});
  EXPECT_FALSE(s.valid);
  EXPECT_EQ(s.w, (std::array<T, 2>{1, 0}));
  // Exactly collinear triangle: coordinates w.r.t. the longest edge (a, c).
  const auto c = barycentric(Vec2<T>{2, 2}, Vec2<T>{0, 0}, Vec2<T>{1, 1}, Vec2<T>{3, 3});
  EXPECT_FALSE(c.valid);
  EXPECT_NEAR(c.w[0], T(1) / T(3), tol<T>(4));
  EXPECT_EQ(c.w[1], T(0));
  EXPECT_NEAR(c.w[2], T(2) / T(3), tol<T>(4));
  // Same in 3D, and a point off the line.
  const auto c3 =
      barycentric(Vec3<T>{2, 2, 5}, Vec3<T>{0, 0, 0}, Vec3<T>{3, 3, 0}, Vec3<T>{1, 1, 0});
  EXPECT_FALSE(c3.valid);
  EXPECT_NEAR(c3.w[0], T(1) / T(3), tol<T>(4));
  EXPECT_NEAR(c3.w[1], T(2) / T(3), tol<T>(4));
  EXPECT_EQ(c3.w[2], T(0));
  // Flat at rounding level: det = -3 eps against edges of length ~4 -> flat by default; with
  // tol = 0 the exact (huge but finite) coordinates are returned.
  const Vec2<T> a{0, 0}, b{1, T(1) + eps_v<T>}, cc{3, 3};
  EXPECT_FALSE(barycentric(Vec2<T>{1, 0}, a, b, cc).valid);
  const auto raw = barycentric(Vec2<T>{1, 0}, a, b, cc, T(0));
  EXPECT_TRUE(raw.valid);
  EXPECT_TRUE(no_nan(raw.w));
  // All vertices coincide.
  const auto pt = barycentric(Vec2<T>{5, 5}, Vec2<T>{1, 1}, Vec2<T>{1, 1}, Vec2<T>{1, 1});
  EXPECT_FALSE(pt.valid);
  EXPECT_EQ(pt.w, (std::array<T, 3>{1, 0, 0}));
  // Flat tetrahedron (coplanar): coordinates w.r.t. the largest face; rebuild p in the plane.
  const Vec3<T> ta{0, 0, 0}, tb{4, 0, 0}, tc{0, 4, 0}, td{1, 1, 0};
  const auto ft = barycentric(Vec3<T>{1, 2, 0}, ta, tb, tc, td);
  EXPECT_FALSE(ft.valid);
  EXPECT_EQ(ft.w[3], T(0));  // face (a, b, c) is the largest
  EXPECT_TRUE(locus_test::vec_near(from_barycentric(ta, tb, tc, td, ft.w), Vec3<T>{1, 2, 0},
                                   tol<T>(16, T(4))));
  // Collinear tetrahedron: down to a segment.
  const auto lt = barycentric(Vec3<T>{1, 0, 0}, ta, tb, Vec3<T>{2, 0, 0}, Vec3<T>{3, 0, 0});
  EXPECT_FALSE(lt.valid);
  EXPECT_TRUE(
      locus_test::vec_near(from_barycentric(ta, tb, Vec3<T>{2, 0, 0}, Vec3<T>{3, 0, 0}, lt.w),
                           Vec3<T>{1, 0, 0}, tol<T>(16, T(4))));
  // General simplex with a dependent vertex: valid = false, weights still rebuild p.
  const std::array<Vec3<T>, 4> dep{ta, tb, tc, Vec3<T>{2, 2, 0}};
  const auto gd = barycentric(Vec3<T>{1, 1, 0}, dep);
  EXPECT_FALSE(gd.valid);
  EXPECT_TRUE(
      locus_test::vec_near(from_barycentric(dep, gd.w), Vec3<T>{1, 1, 0}, tol<T>(16, T(4))));
}

TYPED_TEST(BarycentricTest, NonFiniteAndOverflowingInput) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const Vec2<T> a{0, 0}, b{1, 0}, c{0, 1};
  const auto n2 = barycentric(Vec2<T>{nan, 0}, a, b, c);
  EXPECT_FALSE(n2.valid);
  EXPECT_EQ(n2.w, (std::array<T, 3>{1, 0, 0}));
  EXPECT_FALSE(barycentric(Vec2<T>{0, 0}, a, Vec2<T>{inf, 0}, c).valid);
  EXPECT_FALSE(barycentric(Vec3<T>{nan, 0, 0}, Vec3<T>{}, Vec3<T>{1, 0, 0}).valid);
  const auto n3 = barycentric(Vec3<T>{0, 0, 0}, Vec3<T>{}, Vec3<T>{1, 0, 0}, Vec3<T>{0, 1, 0},
                              Vec3<T>{0, 0, nan});
  EXPECT_FALSE(n3.valid);
  EXPECT_EQ(n3.w, (std::array<T, 4>{1, 0, 0, 0}));
  EXPECT_FALSE(barycentric(Vec3<T>{nan, 0, 0},
                           std::array<Vec3<T>, 3>{Vec3<T>{}, Vec3<T>{1, 0, 0}, Vec3<T>{0, 1, 0}})
                   .valid);
  // A point far outside a tiny triangle: coordinates overflow -> fallback, never NaN.
  const T huge = std::numeric_limits<T>::max() / T(4);
  const auto far = barycentric(Vec2<T>{huge, huge}, a, Vec2<T>{T(1e-3), 0}, Vec2<T>{0, T(1e-3)});
  EXPECT_TRUE(no_nan(far.w));
  const auto far3 = barycentric(Vec3<T>{huge, -huge, huge}, Vec3<T>{}, Vec3<T>{T(1e-3), 0, 0},
                                Vec3<T>{0, T(1e-3), 0}, Vec3<T>{0, 0, T(1e-3)});
  EXPECT_TRUE(no_nan(far3.w));
  const auto fars = barycentric(Vec2<T>{huge, huge}, Vec2<T>{}, Vec2<T>{T(1e-3), 0});
  EXPECT_TRUE(no_nan(fars.w));
}
