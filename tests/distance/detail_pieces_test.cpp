// SPDX-License-Identifier: BSL-1.0
// Direct tests of four implementation headers of the distance queries (namespace locus::detail):
//   distance/detail/planar_pairs.hpp     piece_edge / piece_edge_param / rect_corner_param /
//                                        edge_count / piece_scale / PieceBest. Oracle: the
//                                        primitives' own parametrisations (point_at_barycentric,
//                                        rectangle point_at and corners()), coordinate bounds, a
//                                        brute-force minimum over the offered candidates.
//   distance/detail/tetrahedron.hpp      tet_face_triangle / tet_outside / tet_contains /
//                                        tet_inside_barycentric / tet_from_face. Oracle: exact
//                                        barycentric coordinates in GMP rationals (Cramer's rule)
//                                        and exact orient3d.
//   distance/detail/quadric_lagrange.hpp small_mul / project_onto / quadric_nearest. Oracle: naive
//                                        convolution on integer coefficients (exact), closed-form
//                                        nearest points (sphere, ellipsoid pole, paraboloid vertex
//                                        and ring), dense parametric sampling (Lipschitz bound).
//   distance/detail/rational_span.hpp    bernstein_to_centred / span_point_at / span_roots /
//                                        blossom / span_bezier / NearestTracker. Oracle: integer
//                                        binomial convolution, de Casteljau and Cox-de Boor in
//                                        long double, polynomials built from chosen roots, the
//                                        second-smallest of the offered distances.
#include <locus/core/predicates.hpp>
#include <locus/distance/detail/planar_pairs.hpp>
#include <locus/distance/detail/quadric_lagrange.hpp>
#include <locus/distance/detail/rational_span.hpp>
#include <locus/distance/detail/rescale.hpp>
#include <locus/distance/detail/tetrahedron.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <type_traits>
#include <vector>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
using locus_test::vec_near;

template <class T>
class DetailPiecesTest : public ::testing::Test {};
TYPED_TEST_SUITE(DetailPiecesTest, locus_test::RealTypes);

namespace {

template <class T>
Rectangle<T, 3> random_rectangle(Rng& rng, T S) {
  const Vec3<T> a0 = rng.unit<T, 3>();
  Vec3<T> a1 = cross(a0, rng.unit<T, 3>());
  while (length(a1) < T(0.1)) a1 = cross(a0, rng.unit<T, 3>());
  return {rng.vec<T, 3>(-S, S),
          {a0, normalize(a1)},
          {rng.uniform<T>(T(0), S), rng.uniform<T>(T(0), S)}};
}

// ---- exact tetrahedron oracle ----
using Q3 = std::array<mpq_class, 3>;
template <class T>
Q3 q3(const Vec3<T>& v) {
  return {mpq_class(double(v[0])), mpq_class(double(v[1])), mpq_class(double(v[2]))};
}
mpq_class det3(const Q3& a, const Q3& b, const Q3& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
         a[2] * (b[0] * c[1] - b[1] * c[0]);
}
Q3 qsub(const Q3& a, const Q3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
// Exact barycentric coordinates of p (Cramer): b_i = vol(tet with v_i replaced by p) / vol(tet).
template <class T>
std::array<mpq_class, 4> exact_barycentric(const Tetrahedron3<T>& t, const Vec3<T>& p) {
  std::array<Q3, 4> v{q3(t.v[0]), q3(t.v[1]), q3(t.v[2]), q3(t.v[3])};
  const auto vol = [](const std::array<Q3, 4>& w) {
    return det3(qsub(w[1], w[0]), qsub(w[2], w[0]), qsub(w[3], w[0]));
  };
  const mpq_class D = vol(v);
  std::array<mpq_class, 4> b;
  for (int i = 0; i < 4; ++i) {
    auto w = v;
    w[static_cast<std::size_t>(i)] = q3(p);
    b[static_cast<std::size_t>(i)] = vol(w) / D;
  }
  return b;
}

// ---- long double references ----
long double casteljau(std::vector<long double> b, long double s) {
  const int d = static_cast<int>(b.size()) - 1;
  for (int r = 1; r <= d; ++r)
    for (int j = 0; j <= d - r; ++j)
      b[static_cast<std::size_t>(j)] =
          (1 - s) * b[static_cast<std::size_t>(j)] + s * b[static_cast<std::size_t>(j + 1)];
  return b[0];
}

// Cox-de Boor basis function N_{i,d}(t) (half-open spans), long double.
long double cox_de_boor(const std::vector<double>& kn, int i, int d, long double t) {
  const auto K = [&](int j) { return static_cast<long double>(kn[static_cast<std::size_t>(j)]); };
  if (d == 0) return (K(i) <= t && t < K(i + 1)) ? 1.0L : 0.0L;
  long double r = 0;
  if (K(i + d) > K(i)) r += (t - K(i)) / (K(i + d) - K(i)) * cox_de_boor(kn, i, d - 1, t);
  if (K(i + d + 1) > K(i + 1))
    r += (K(i + d + 1) - t) / (K(i + d + 1) - K(i + 1)) * cox_de_boor(kn, i + 1, d - 1, t);
  return r;
}

}  // namespace

// ------------------------------------------------------------------------------------------------
// planar_pairs.hpp
// ------------------------------------------------------------------------------------------------

TYPED_TEST(DetailPiecesTest, PlanarPairsTriangleEdges) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const T S = 10;
  for (int n = 0; n < 100; ++n) {
    const Triangle3<T> tri{rng.vec<T, 3>(-S, S), rng.vec<T, 3>(-S, S), rng.vec<T, 3>(-S, S)};
    ASSERT_EQ(detail::edge_count(tri), 3);
    const Vec3<T> v[3] = {tri.v0, tri.v1, tri.v2};
    const T scale = detail::piece_scale(tri);
    for (int k = 0; k < 3; ++k) {
      // Documented order: v0 v1, v1 v2, v2 v0.
      const Segment3<T> e = detail::piece_edge(tri, k);
      EXPECT_EQ(e.p0, v[k]);
      EXPECT_EQ(e.p1, v[(k + 1) % 3]);
      // piece_scale bounds every coordinate of the piece (up to rounding of the sum).
      EXPECT_LE(max_abs(v[k]), scale * (T(1) + tol<T>(4)));
      // Endpoints of the parameter are exact barycentric vertices.
      const Vec3<T> b0 = detail::piece_edge_param(tri, k, T(0));
      const Vec3<T> b1 = detail::piece_edge_param(tri, k, T(1));
      for (int j = 0; j < 3; ++j) {
        EXPECT_EQ(b0[j], j == k ? T(1) : T(0));
        EXPECT_EQ(b1[j], j == (k + 1) % 3 ? T(1) : T(0));
      }
      for (int m = 0; m < 5; ++m) {
        const T t = rng.uniform<T>(T(0), T(1));
        const Vec3<T> b = detail::piece_edge_param(tri, k, t);
        EXPECT_EQ(b[(k + 2) % 3], T(0));
        EXPECT_NEAR(double(b[0] + b[1] + b[2]), 1.0, double(tol<T>(2)));
        EXPECT_TRUE(vec_near(point_at_barycentric(tri, b), point_at(e, t), tol<T>(8, scale)));
      }
    }
  }
}

TYPED_TEST(DetailPiecesTest, PlanarPairsRectangleEdges) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 1);
  SCOPED_TRACE(rng.trace());
  const T S = 10;
  for (int n = 0; n < 100; ++n) {
    Rectangle<T, 3> r = random_rectangle<T>(rng, S);
    if (n % 10 == 0) r.extent[n % 20 == 0 ? 0 : 1] = T(-1);  // negative extent reads as 0
    ASSERT_EQ(detail::edge_count(r), 4);
    const T ex = std::max(r.extent[0], T(0)), ey = std::max(r.extent[1], T(0));
    const T sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    const T scale = detail::piece_scale(r);
    EXPECT_EQ(scale, max_abs(r.center) + ex + ey);
    Rectangle<T, 3> clamped = r;
    clamped.extent[0] = ex;
    clamped.extent[1] = ey;
    const auto cs = corners(clamped);
    for (int k = 0; k < 4; ++k) {
      const Vec2<T> c = detail::rect_corner_param(r, k);
      EXPECT_EQ(c[0], sx[k] * ex);
      EXPECT_EQ(c[1], sy[k] * ey);
      const Segment3<T> e = detail::piece_edge(r, k);
      EXPECT_TRUE(vec_near(e.p0, cs[static_cast<std::size_t>(k)], tol<T>(8, scale)));
      EXPECT_TRUE(vec_near(e.p1, cs[static_cast<std::size_t>((k + 1) % 4)], tol<T>(8, scale)));
      EXPECT_LE(max_abs(e.p0), scale * (T(1) + tol<T>(8)));
      EXPECT_EQ(detail::piece_edge_param(r, k, T(0)), c);
      for (int m = 0; m < 5; ++m) {
        const T t = rng.uniform<T>(T(0), T(1));
        const Vec2<T> st = detail::piece_edge_param(r, k, t);
        // Inside the parameter rectangle up to the rounding of lerp (the constant coordinate
        // (1 - t) e + t e can land one ulp beyond e).
        EXPECT_LE(std::abs(st[0]), ex + tol<T>(1, ex));
        EXPECT_LE(std::abs(st[1]), ey + tol<T>(1, ey));
        EXPECT_TRUE(vec_near(point_at(r, st), point_at(e, t), tol<T>(16, scale)));
      }
    }
  }
}

TYPED_TEST(DetailPiecesTest, PlanarPairsPieceBest) {
  using T = TypeParam;
  using D = Distance<T, 3, Vec3<T>, Vec2<T>>;
  Rng rng(locus_test::test_seed() + 2);
  SCOPED_TRACE(rng.trace());
  const auto make = [](T d, const Vec3<T>& c, bool u) {
    D r{};
    r.distance = d;
    r.sqr_distance = d * d;
    r.closest = {c, c};
    r.unique = u;
    return r;
  };
  // Random separated candidates: the minimum wins, uniqueness kept when nobody ties.
  for (int n = 0; n < 50; ++n) {
    detail::PieceBest<T, Vec3<T>, Vec2<T>> acc;
    acc.scale = T(10);
    const int cnt = rng.uniform_int(1, 8);
    T lo = std::numeric_limits<T>::infinity();
    for (int i = 0; i < cnt; ++i) {
      const T d = T(1) + T(i) * T(0.5) + rng.uniform<T>(T(0), T(0.25));
      lo = std::min(lo, d);
      acc.offer(make(d, rng.vec<T, 3>(T(-10), T(10)), true));
    }
    EXPECT_EQ(acc.count, cnt);
    const D r = acc.result();
    EXPECT_EQ(r.distance, lo);
    EXPECT_TRUE(r.unique);
  }
  const Vec3<T> p{1, 2, 3}, q{1, 2, 4};
  {  // a tied non-unique (sliding) candidate makes the answer non-unique
    detail::PieceBest<T, Vec3<T>, Vec2<T>> acc;
    acc.scale = T(10);
    acc.offer(make(T(2), p, true));
    acc.offer(make(T(2), q, false));
    acc.offer(make(T(3), q, true));
    EXPECT_FALSE(acc.result().unique);
  }
  {  // a non-unique candidate clearly farther does not
    detail::PieceBest<T, Vec3<T>, Vec2<T>> acc;
    acc.scale = T(10);
    acc.offer(make(T(3), q, false));
    acc.offer(make(T(2), p, true));
    const D r = acc.result();
    EXPECT_EQ(r.distance, T(2));
    EXPECT_TRUE(r.unique);
  }
  {  // two distinct contacts at distance 0: the pieces meet along a segment
    detail::PieceBest<T, Vec3<T>, Vec2<T>> acc;
    acc.scale = T(10);
    acc.offer(make(T(0), p, true));
    acc.offer(make(T(0), q, true));
    const D r = acc.result();
    EXPECT_EQ(r.distance, T(0));
    EXPECT_FALSE(r.unique);
  }
  {  // the same contact found twice is one contact
    detail::PieceBest<T, Vec3<T>, Vec2<T>> acc;
    acc.scale = T(10);
    acc.offer(make(T(0), p, true));
    acc.offer(make(T(0), p, true));
    acc.offer(make(T(1), q, true));
    EXPECT_TRUE(acc.result().unique);
  }
}

// ------------------------------------------------------------------------------------------------
// tetrahedron.hpp
// ------------------------------------------------------------------------------------------------

TYPED_TEST(DetailPiecesTest, TetrahedronFacesAndSides) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 3);
  SCOPED_TRACE(rng.trace());
  int inside = 0, on_face = 0;
  for (int n = 0; n < 60; ++n) {
    // Small integer coordinates so that many lattice points lie exactly on face planes.
    Tetrahedron3<T> tet{};
    for (auto& v : tet.v)
      for (int c = 0; c < 3; ++c) v[c] = T(rng.uniform_int(-4, 4));
    const int o = orientation(tet);
    if (o == 0) continue;
    for (int i = 0; i < 4; ++i) {
      const Triangle3<T> f = detail::tet_face_triangle(tet, i);
      // The face is made of the three vertices other than i, each once.
      int seen = 0;
      for (const Vec3<T>& fv : {f.v0, f.v1, f.v2})
        for (int j = 0; j < 4; ++j)
          if (fv == tet.v[j]) {
            EXPECT_NE(j, i);
            seen |= 1 << j;
          }
      EXPECT_EQ(seen, 15 & ~(1 << i));
      // Its orient3d normal, times the orientation, points away from the opposite vertex.
      EXPECT_EQ(o * to_int(orient3d(f.v0, f.v1, f.v2, tet.v[i])), -1) << "face " << i;
      EXPECT_EQ(detail::tet_outside(tet, o, i, tet.v[i]), -1);
    }
    for (int m = 0; m < 40; ++m) {
      Vec3<T> p{};
      for (int c = 0; c < 3; ++c) p[c] = T(rng.uniform_int(-10, 10)) / T(2);
      if (m % 4 == 0) p = rng.vec<T, 3>(T(-5), T(5));
      if (m % 8 == 1) p = (tet.v[0] + tet.v[1] + tet.v[2] + tet.v[3]) / T(4);  // exact centroid
      if (m % 8 == 3) p = (tet.v[rng.uniform_int(0, 1)] + tet.v[rng.uniform_int(2, 3)]) / T(2);
      const auto b = exact_barycentric(tet, p);
      bool all_nonneg = true;
      for (int i = 0; i < 4; ++i) {
        const int expect = -sgn(b[static_cast<std::size_t>(i)]);
        EXPECT_EQ(detail::tet_outside(tet, o, i, p), expect) << "face " << i;
        if (expect > 0) all_nonneg = false;
        if (expect == 0) ++on_face;
      }
      EXPECT_EQ(detail::tet_contains(tet, o, p), all_nonneg);
      if (all_nonneg) ++inside;
    }
  }
  EXPECT_GT(inside, 20);
  EXPECT_GT(on_face, 20);
}

TYPED_TEST(DetailPiecesTest, TetrahedronBarycentrics) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 4);
  SCOPED_TRACE(rng.trace());
  const T S = 4;
  int done = 0;
  for (int n = 0; n < 200 && done < 60; ++n) {
    Tetrahedron3<T> tet{
        {rng.vec<T, 3>(-S, S), rng.vec<T, 3>(-S, S), rng.vec<T, 3>(-S, S), rng.vec<T, 3>(-S, S)}};
    const int o = orientation(tet);
    if (std::abs(signed_volume(tet)) < T(0.5)) continue;  // well-conditioned only
    ++done;
    for (int m = 0; m < 10; ++m) {
      // A random inside point from random barycentrics; the oracle is the exact coordinates of
      // the rounded point.
      T w[4], sum = 0;
      for (T& x : w) sum += (x = rng.uniform<T>(T(0.01), T(1)));
      const Vec4<T> b{w[0] / sum, w[1] / sum, w[2] / sum, w[3] / sum};
      const Vec3<T> p = point_at_barycentric(tet, b);
      const auto eb = exact_barycentric(tet, p);
      bool in = true;
      for (const auto& x : eb) in = in && sgn(x) >= 0;
      if (!in) continue;
      const Vec4<T> r = detail::tet_inside_barycentric(tet, o, p);
      EXPECT_NEAR(double(r[0] + r[1] + r[2] + r[3]), 1.0, double(tol<T>(4)));
      for (int i = 0; i < 4; ++i) {
        EXPECT_GE(r[i], T(0));
        EXPECT_NEAR(double(r[i]), eb[static_cast<std::size_t>(i)].get_d(),
                    double(tol<T>(64, T(10))));
      }
      EXPECT_TRUE(vec_near(point_at_barycentric(tet, r), p, tol<T>(64, S)));
    }
    // tet_from_face: a point of face i has the same position as a point of the tetrahedron, with
    // coordinate i exactly zero and the face coordinates carried over exactly.
    for (int i = 0; i < 4; ++i) {
      const Triangle3<T> f = detail::tet_face_triangle(tet, i);
      T w[3], sum = 0;
      for (T& x : w) sum += (x = rng.uniform<T>(T(0), T(1)));
      const Vec3<T> fb{w[0] / sum, w[1] / sum, w[2] / sum};
      const Vec4<T> tb = detail::tet_from_face(i, fb);
      EXPECT_EQ(tb[i], T(0));
      for (int k = 0; k < 3; ++k) EXPECT_EQ(tb[detail::tet_face[i][k]], fb[k]);
      EXPECT_TRUE(
          vec_near(point_at_barycentric(tet, tb), point_at_barycentric(f, fb), tol<T>(8, S)));
    }
  }
  EXPECT_EQ(done, 60);
}

// ------------------------------------------------------------------------------------------------
// quadric_lagrange.hpp (compute type double, as the float and double queries use)
// ------------------------------------------------------------------------------------------------

TEST(DetailPiecesQuadric, SmallMulIsConvolution) {
  Rng rng(locus_test::test_seed() + 5);
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 200; ++n) {
    const int dx = rng.uniform_int(0, 6), dy = rng.uniform_int(0, 6 - dx);
    detail::SmallPoly<double> x, y;
    for (int i = 0; i <= dx; ++i) x.a[i] = std::abs(x.c[i] = rng.uniform_int(-20, 20));
    for (int i = 0; i <= dy; ++i) y.a[i] = std::abs(y.c[i] = rng.uniform_int(-20, 20));
    const auto r = detail::small_mul(x, y);
    for (int k = 0; k < 7; ++k) {
      long long c = 0, a = 0;
      for (int i = 0; i <= k; ++i) {
        c += static_cast<long long>(x.c[i]) * static_cast<long long>(y.c[k - i]);
        a += static_cast<long long>(x.a[i]) * static_cast<long long>(y.a[k - i]);
      }
      EXPECT_EQ(r.c[k], double(c)) << k;
      EXPECT_EQ(r.a[k], double(a)) << k;
    }
  }
}

namespace {
detail::QuadricN<double, 3> diag_quadric(double a0, double a1, double a2, Vec3<double> b,
                                         double c) {
  detail::QuadricN<double, 3> q{};
  q.a.a[0][0] = a0;
  q.a.a[1][1] = a1;
  q.a.a[2][2] = a2;
  q.b = b;
  q.c = c;
  return q;
}
}  // namespace

TEST(DetailPiecesQuadric, ProjectOntoSphere) {
  Rng rng(locus_test::test_seed() + 6);
  SCOPED_TRACE(rng.trace());
  // |x - m|^2 - R^2 with m = (1, -2, 0.5), R = 2: x^T x - 2 m . x + |m|^2 - R^2.
  const Vec3<double> m{1, -2, 0.5};
  const double R = 2;
  const auto q = diag_quadric(1, 1, 1, -2.0 * m, dot(m, m) - R * R);
  for (int n = 0; n < 50; ++n) {
    const Vec3<double> dir = rng.unit<double, 3>();
    const double s = rng.uniform<double>(1.5, 2.6);  // start 25% inside .. 30% outside
    const Vec3<double> x = detail::project_onto(q, m + s * dir);
    // The gradient of a sphere points along the radius: Newton stays on the ray.
    EXPECT_TRUE(vec_near(x, m + R * dir, 1e-12));
  }
}

TEST(DetailPiecesQuadric, NearestKnownPoints) {
  const double sep2 = 1e-12;
  {  // sphere: the radial projection
    Rng rng(locus_test::test_seed() + 7);
    SCOPED_TRACE(rng.trace());
    const Vec3<double> m{0.5, 0.25, -1};
    const double R = 1.5;
    const auto q = diag_quadric(1, 1, 1, -2.0 * m, dot(m, m) - R * R);
    for (int n = 0; n < 20; ++n) {
      const Vec3<double> dir = rng.unit<double, 3>();
      const double s = rng.uniform<double>(0.2, 4);
      const auto tr = detail::quadric_nearest(q, m + s * dir, 3, sep2);
      ASSERT_TRUE(tr.found);
      // The polish compares squared distances, so the position along the surface is resolved
      // to about sqrt(eps) (d2 is stationary there); d2 itself to eps.
      EXPECT_TRUE(vec_near(tr.best_point, m + R * dir, 1e-7));
      EXPECT_NEAR(tr.best_d2, (s - R) * (s - R), 1e-13);
      // Not tied at the tolerance point_quadric.hpp uses for double (64 eps).
      EXPECT_FALSE(tr.tied(64 * std::numeric_limits<double>::epsilon()));
    }
  }
  {  // ellipsoid x^2 + y^2/1.5^2 + z^2/2^2 = 1 seen from (0, 0, 3) on its longest axis: every
     // point has |x| <= 2, so the pole (0, 0, 2) at distance 1 is the unique nearest point.
    const auto q = diag_quadric(1, 1 / 2.25, 0.25, {0, 0, 0}, -1);
    const auto tr = detail::quadric_nearest(q, Vec3<double>{0, 0, 3}, 3, sep2);
    ASSERT_TRUE(tr.found);
    EXPECT_TRUE(vec_near(tr.best_point, Vec3<double>{0, 0, 2}, 1e-9));
    EXPECT_NEAR(tr.best_d2, 1.0, 1e-13);
    EXPECT_FALSE(tr.tied(1e-6));
  }
  {  // paraboloid z = x^2 + y^2 (rank 2) from (0, 0, -1): the vertex, distance 1
    const auto q = diag_quadric(1, 1, 0, {0, 0, -1}, 0);
    const auto tr = detail::quadric_nearest(q, Vec3<double>{0, 0, -1}, 2, sep2);
    ASSERT_TRUE(tr.found);
    EXPECT_TRUE(vec_near(tr.best_point, Vec3<double>{0, 0, 0}, 1e-9));
    EXPECT_NEAR(tr.best_d2, 1.0, 1e-13);
    // From (0, 0, 2): a circle of nearest points; z + (z - 2)^2 is least at z = 3/2, d^2 = 7/4.
    const auto ring = detail::quadric_nearest(q, Vec3<double>{0, 0, 2}, 2, sep2);
    ASSERT_TRUE(ring.found);
    EXPECT_NEAR(ring.best_d2, 1.75, 1e-13);
    EXPECT_NEAR(ring.best_point[2], 1.5, 1e-9);
    EXPECT_TRUE(ring.tied(1e-6));
  }
}

TEST(DetailPiecesQuadric, NearestVsDenseSampling) {
  Rng rng(locus_test::test_seed() + 8);
  SCOPED_TRACE(rng.trace());
  // Ellipsoid with semi-axes (1, 1.5, 2), rotated by an orthonormal frame F: X = F y.
  const Vec3<double> ax{1, 1.5, 2};
  const Vec3<double> f0 = rng.unit<double, 3>();
  const Vec3<double> f1 = normalize(cross(f0, rng.unit<double, 3>()));
  const Vec3<double> f2 = cross(f0, f1);
  const Vec3<double> F[3] = {f0, f1, f2};
  detail::QuadricN<double, 3> q{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double s = 0;
      for (int k = 0; k < 3; ++k) s += F[k][i] * F[k][j] / (ax[k] * ax[k]);
      q.a.a[i][j] = s;
    }
  q.b = {0, 0, 0};
  q.c = -1;
  constexpr int nu = 240, nv = 120;
  std::vector<Vec3<double>> samples;
  samples.reserve(nu * (nv + 1));
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j <= nv; ++j) {
      const double u = 2 * std::numbers::pi * i / nu, v = std::numbers::pi * j / nv;
      const double y[3] = {ax[0] * std::sin(v) * std::cos(u), ax[1] * std::sin(v) * std::sin(u),
                           ax[2] * std::cos(v)};
      samples.push_back(y[0] * f0 + y[1] * f1 + y[2] * f2);
    }
  // Largest gap between neighbouring samples bounds how far the sampled minimum can be above
  // the true minimum (distance is 1-Lipschitz).
  const double gap = 2 * std::numbers::pi * 2.0 / nv;
  for (int n = 0; n < 12; ++n) {
    const Vec3<double> p = rng.vec<double, 3>(-3, 3);
    const auto tr = detail::quadric_nearest(q, p, 3, 1e-12);
    ASSERT_TRUE(tr.found);
    EXPECT_LE(std::abs(q.value(tr.best_point)), 1e-12);
    EXPECT_NEAR(tr.best_d2, sqr_length(tr.best_point - p), 1e-12);
    double best = std::numeric_limits<double>::infinity();
    for (const auto& s : samples) best = std::min(best, sqr_length(s - p));
    const double d = std::sqrt(tr.best_d2), ds = std::sqrt(best);
    EXPECT_LE(d, ds + 1e-12) << "case " << n;  // no sample beats the answer
    EXPECT_LE(ds - d, gap) << "case " << n;
  }
}

// ------------------------------------------------------------------------------------------------
// rational_span.hpp
// ------------------------------------------------------------------------------------------------

TEST(DetailPiecesSpan, BernsteinToCentredExact) {
  for (int d = 0; d <= 12; ++d) {
    std::vector<double> m(static_cast<std::size_t>((d + 1) * (d + 1)));
    detail::bernstein_to_centred(d, m.data());
    for (int i = 0; i <= d; ++i) {
      // binom(d, i) (1 + u)^i (1 - u)^(d - i) by integer convolution.
      std::vector<long long> p{1};
      for (int k = 0; k < d; ++k) {
        std::vector<long long> np(p.size() + 1, 0);
        const long long s = k < i ? 1 : -1;
        for (std::size_t j = 0; j < p.size(); ++j) {
          np[j] += p[j];
          np[j + 1] += s * p[j];
        }
        p = np;
      }
      long long bin = 1;
      for (int k = 0; k < i; ++k) bin = bin * (d - k) / (k + 1);
      for (int j = 0; j <= d; ++j)
        EXPECT_EQ(std::ldexp(m[static_cast<std::size_t>(i * (d + 1) + j)], d),
                  double(bin * p[static_cast<std::size_t>(j)]))
            << "d " << d << " i " << i << " j " << j;
    }
  }
}

TEST(DetailPiecesSpan, CentredPowerAndPointMatchDeCasteljau) {
  Rng rng(locus_test::test_seed() + 9);
  SCOPED_TRACE(rng.trace());
  for (int d = 1; d <= 9; ++d) {
    std::vector<long double> m(static_cast<std::size_t>((d + 1) * (d + 1)));
    detail::bernstein_to_centred(d, m.data());
    for (int n = 0; n < 10; ++n) {
      std::vector<long double> c(static_cast<std::size_t>(d + 1));
      for (auto& x : c) x = rng.uniform<double>(-5, 5);
      std::vector<long double> pw(static_cast<std::size_t>(d + 1), 0);
      for (int i = 0; i <= d; ++i)
        for (int j = 0; j <= d; ++j)
          pw[static_cast<std::size_t>(j)] +=
              c[static_cast<std::size_t>(i)] * m[static_cast<std::size_t>(i * (d + 1) + j)];
      for (int k = 0; k <= 8; ++k) {
        const long double s = k / 8.0L, u = 2 * s - 1;
        long double h = 0;
        for (int j = d; j >= 0; --j) h = h * u + pw[static_cast<std::size_t>(j)];
        EXPECT_NEAR(double(h), double(casteljau(c, s)), 1e-14);
      }
    }
  }
  // span_point_at: homogeneous de Casteljau and projection, vs long double.
  for (int n = 0; n < 40; ++n) {
    const int d = rng.uniform_int(1, 6);
    std::vector<Vec<double, 4>> h(static_cast<std::size_t>(d + 1));
    for (auto& x : h) {
      const double w = rng.uniform<double>(0.5, 2);
      x = detail::homogeneous<double, 3>(rng.vec<double, 3>(-3, 3), w);
    }
    {
      const auto p0 = detail::span_point_at<double, 3>(h.data(), d, 0.0);
      EXPECT_EQ(p0, (detail::span_project<double, 3>(h[0])));
    }
    for (int k = 0; k <= 6; ++k) {
      const double s = k / 6.0;
      const Vec3<double> p = detail::span_point_at<double, 3>(h.data(), d, s);
      std::vector<long double> w(h.size());
      for (std::size_t i = 0; i < h.size(); ++i) w[i] = h[i][3];
      const long double ws = casteljau(w, s);
      for (int c = 0; c < 3; ++c) {
        std::vector<long double> x(h.size());
        for (std::size_t i = 0; i < h.size(); ++i) x[i] = h[i][c];
        EXPECT_NEAR(p[c], double(casteljau(x, s) / ws), 1e-13);
      }
    }
  }
  // A rational quadratic quarter circle: every point at distance 1 from the origin.
  const double w1 = std::sqrt(0.5);
  const Vec<double, 3> qc[3] = {detail::homogeneous<double, 2>({1, 0}, 1.0),
                                detail::homogeneous<double, 2>({1, 1}, w1),
                                detail::homogeneous<double, 2>({0, 1}, 1.0)};
  for (int k = 0; k <= 16; ++k)
    EXPECT_NEAR(length(detail::span_point_at<double, 2>(qc, 2, k / 16.0)), 1.0, 1e-15);
}

namespace {
// sign * prod (u - r_k) with its absolute twin, error bound 8 eps * twin.
detail::BoundedPoly<double> from_roots(const std::vector<double>& roots, double lead) {
  std::vector<double> c{lead}, a{std::abs(lead)};
  for (double r : roots) {
    std::vector<double> nc(c.size() + 1, 0.0), na(a.size() + 1, 0.0);
    for (std::size_t j = 0; j < c.size(); ++j) {
      nc[j + 1] += c[j];
      nc[j] -= r * c[j];
      na[j + 1] += a[j];
      na[j] += std::abs(r) * a[j];
    }
    c = nc;
    a = na;
  }
  detail::BoundedPoly<double> g(static_cast<int>(roots.size()));
  for (std::size_t j = 0; j < c.size(); ++j) {
    g.c[j] = c[j];
    g.err[j] = 8 * std::numeric_limits<double>::epsilon() * a[j];
  }
  return g;
}
}  // namespace

TEST(DetailPiecesSpan, SpanRootsOfChosenRoots) {
  Rng rng(locus_test::test_seed() + 10);
  SCOPED_TRACE(rng.trace());
  const auto check = [](std::vector<double> roots, bool whole, const std::vector<double>& expect,
                        double tolerance) {
    auto g = from_roots(roots, 1.5);
    std::vector<double> out(roots.size() + 1);
    const int cnt = detail::span_roots(g, out.data(), whole);
    ASSERT_EQ(cnt, static_cast<int>(expect.size()));
    std::sort(out.begin(), out.begin() + cnt);
    for (int i = 0; i < cnt; ++i)
      EXPECT_NEAR(out[static_cast<std::size_t>(i)], expect[static_cast<std::size_t>(i)], tolerance);
  };
  // Random simple roots, some outside (-1, 1).
  for (int n = 0; n < 30; ++n) {
    const int d = rng.uniform_int(1, 6);
    std::vector<double> r;
    while (static_cast<int>(r.size()) < d) {
      const double x = rng.uniform<double>(-2, 2);
      bool far = std::abs(std::abs(x) - 1) > 0.05;
      for (double y : r) far = far && std::abs(x - y) > 0.05;
      if (far) r.push_back(x);
    }
    std::vector<double> inside;
    for (double x : r)
      if (x > -1 && x < 1) inside.push_back(x);
    std::sort(inside.begin(), inside.end());
    std::vector<double> all = r;
    std::sort(all.begin(), all.end());
    check(r, false, inside, 1e-10);
    check(r, true, all, 1e-10);
  }
  // A double root is one root (tangency); close roots stay apart.
  check({0.25, 0.25, -0.5}, false, {-0.5, 0.25}, 1e-7);
  check({0.3, 0.3 + 1e-3, -0.7}, false, {-0.7, 0.3, 0.3 + 1e-3}, 1e-8);
  // No real root: u^2 + 1.
  {
    detail::BoundedPoly<double> g(2);
    g.c[0] = g.c[2] = 1;
    g.err[0] = g.err[2] = 1e-16;
    double out[2];
    EXPECT_EQ(detail::span_roots(g, out, true), 0);
  }
  // Identically vanishing within its bound: -1. A noise leading coefficient is dropped.
  {
    detail::BoundedPoly<double> g(3);
    for (int j = 0; j <= 3; ++j) {
      g.c[static_cast<std::size_t>(j)] = 1e-20;
      g.err[static_cast<std::size_t>(j)] = 1e-18;
    }
    double out[3];
    EXPECT_EQ(detail::span_roots(g, out, true), -1);
    auto h = from_roots({0.5}, 2);  // 2u - 1
    detail::BoundedPoly<double> k(2);
    k.c[0] = h.c[0];
    k.c[1] = h.c[1];
    k.err[0] = h.err[0];
    k.err[1] = h.err[1];
    k.c[2] = 1e-20;  // noise
    k.err[2] = 1e-18;
    ASSERT_EQ(detail::span_roots(k, out, true), 1);
    EXPECT_NEAR(out[0], 0.5, 1e-14);
  }
}

TEST(DetailPiecesSpan, BlossomAndSpanBezierVsCoxDeBoor) {
  Rng rng(locus_test::test_seed() + 11);
  SCOPED_TRACE(rng.trace());
  const int d = 3;
  const std::vector<double> kn{0, 0, 0, 0, 0.5, 1.25, 1.5, 3, 3, 3, 3};
  const int n = static_cast<int>(kn.size()) - d - 1;  // 7 control points
  std::vector<Vec2<double>> P(static_cast<std::size_t>(n));
  for (auto& p : P) p = rng.vec<double, 2>(-4, 4);
  const auto get = [&](int i) { return P[static_cast<std::size_t>(i)]; };
  const std::span<const double> ks(kn);
  const auto oracle = [&](long double t) {
    long double x = 0, y = 0;
    for (int i = 0; i < n; ++i) {
      const long double b = cox_de_boor(kn, i, d, t);
      x += b * P[static_cast<std::size_t>(i)][0];
      y += b * P[static_cast<std::size_t>(i)][1];
    }
    return Vec2<double>{double(x), double(y)};
  };
  for (int k = d; k < n; ++k) {
    if (!(kn[static_cast<std::size_t>(k)] < kn[static_cast<std::size_t>(k + 1)])) continue;
    const double a = kn[static_cast<std::size_t>(k)], b = kn[static_cast<std::size_t>(k + 1)];
    for (int m = 0; m < 8; ++m) {
      const double t = a + (b - a) * (m + 0.5) / 8;
      // Diagonal of the blossom: the curve point.
      const double u[3] = {t, t, t};
      EXPECT_TRUE(vec_near(detail::blossom<double, Vec2<double>, double>(ks, d, k, u, get),
                           oracle(t), 1e-12));
      // Symmetric in its arguments.
      const double u1 = rng.uniform<double>(a, b), u2 = rng.uniform<double>(a, b),
                   u3 = rng.uniform<double>(a, b);
      const double ua[3] = {u1, u2, u3}, ub[3] = {u3, u1, u2}, uc[3] = {u2, u3, u1};
      const auto ba = detail::blossom<double, Vec2<double>, double>(ks, d, k, ua, get);
      EXPECT_TRUE(
          vec_near(ba, detail::blossom<double, Vec2<double>, double>(ks, d, k, ub, get), 1e-12));
      EXPECT_TRUE(
          vec_near(ba, detail::blossom<double, Vec2<double>, double>(ks, d, k, uc, get), 1e-12));
    }
    // span_bezier: the Bézier points of the span reproduce the curve under de Casteljau.
    Vec2<double> bz[4];
    detail::span_bezier<double, Vec2<double>, double>(ks, d, k, get, bz);
    for (int m = 0; m <= 8; ++m) {
      const double s = m / 8.0;
      std::vector<long double> x(4), y(4);
      for (int i = 0; i < 4; ++i) {
        x[static_cast<std::size_t>(i)] = bz[i][0];
        y[static_cast<std::size_t>(i)] = bz[i][1];
      }
      const double t = m == 8 ? std::nextafter(b, a) : a + (b - a) * s;
      EXPECT_TRUE(vec_near(Vec2<double>{double(casteljau(x, s)), double(casteljau(y, s))},
                           oracle(t), 1e-11))
          << "span " << k << " s " << s;
    }
  }
}

TEST(DetailPiecesSpan, NearestTrackerSemantics) {
  Rng rng(locus_test::test_seed() + 12);
  SCOPED_TRACE(rng.trace());
  // Distinct points, sep2 = 0: best is the minimum, alt the second smallest, whatever the order.
  for (int n = 0; n < 100; ++n) {
    detail::NearestTracker<double, 3> tr;
    const int cnt = rng.uniform_int(1, 10);
    std::vector<double> d2;
    for (int i = 0; i < cnt; ++i) {
      const double x = rng.uniform<double>(0, 10);
      d2.push_back(x);
      tr.offer(x, double(i), Vec3<double>{double(i), 0, 0});
      if (i == 2)
        tr.offer(std::numeric_limits<double>::quiet_NaN(), 99, Vec3<double>{});  // ignored
    }
    std::vector<double> s = d2;
    std::sort(s.begin(), s.end());
    ASSERT_TRUE(tr.found);
    EXPECT_EQ(tr.best_d2, s[0]);
    const auto at = static_cast<std::size_t>(std::find(d2.begin(), d2.end(), s[0]) - d2.begin());
    EXPECT_EQ(tr.best_t, double(at));
    EXPECT_EQ(tr.best_point[0], double(at));
    EXPECT_EQ(tr.has_alt, cnt > 1);
    if (cnt > 1) {
      EXPECT_EQ(tr.alt_d2, s[1]);
      EXPECT_EQ(tr.tied(0.0), s[1] == s[0]);
      EXPECT_TRUE(tr.tied((s[1] - s[0]) / s[0] * 1.001 + 1e-300));
    } else {
      EXPECT_FALSE(tr.tied(1e300));
    }
  }
  // The same point offered twice (within sep2) is not an alternative.
  detail::NearestTracker<double, 3> tr;
  tr.sep2 = 1e-6;
  tr.offer(2.0, 0.1, Vec3<double>{1, 0, 0});
  tr.offer(2.0, 0.2, Vec3<double>{1, 0, 1e-4});
  EXPECT_FALSE(tr.has_alt);
  EXPECT_FALSE(tr.tied(1.0));
  EXPECT_EQ(tr.best_t, 0.1);  // a tie does not replace the best
  tr.offer(2.0, 0.3, Vec3<double>{-1, 0, 0});
  EXPECT_TRUE(tr.tied(0.0));
  const detail::NearestTracker<double, 3> empty;
  EXPECT_FALSE(empty.found);
}

// detail/rescale.hpp and core's normalising_scale: the range test for each degree against its
// documented bounds (2^+-k, k = (E - 8) / degree), and the scale bringing any positive finite
// magnitude into [1, 2) (within the range of T at its ends), exactly a power of two.
TYPED_TEST(DetailPiecesTest, RescaleRangeAndNormalisingScale) {
  using T = TypeParam;
  constexpr int E = std::numeric_limits<T>::max_exponent;
  const auto check_degree = [](auto degree_tag) {
    constexpr int degree = decltype(degree_tag)::value;
    constexpr int k = (E - 8) / degree;
    using detail::outside_product_range;
    EXPECT_FALSE((outside_product_range<T, degree>(T(1))));
    EXPECT_FALSE((outside_product_range<T, degree>(std::ldexp(T(1), k))));
    EXPECT_FALSE((outside_product_range<T, degree>(std::ldexp(T(1), -k))));
    EXPECT_TRUE((outside_product_range<T, degree>(std::ldexp(T(1), k + 1))));
    EXPECT_TRUE((outside_product_range<T, degree>(std::ldexp(T(1), -k - 1))));
    EXPECT_TRUE((outside_product_range<T, degree>(T(0))));
    // At the edges the product of `degree` such magnitudes is in range with at least 2^7 to spare
    // (degree k <= E - 8, and the largest finite value is just below 2^E).
    T prod = T(128);
    for (int i = 0; i < degree; ++i) prod *= std::ldexp(T(1), k);
    EXPECT_TRUE(std::isfinite(prod));
  };
  check_degree(std::integral_constant<int, 4>{});
  check_degree(std::integral_constant<int, 6>{});
  check_degree(std::integral_constant<int, 8>{});

  Rng rng;
  SCOPED_TRACE(rng.trace());
  constexpr int lo = std::numeric_limits<T>::min_exponent - 1, hi = E - 1;
  for (int i = 0; i < 2000; ++i) {
    const int e = rng.uniform_int(std::numeric_limits<T>::min_exponent - 1, E - 1);
    const T m = std::ldexp(rng.uniform<T>(T(1), T(2)), e);
    if (!(m > T(0)) || !std::isfinite(m)) continue;
    const T f = normalising_scale(m);
    int fe = 0;
    EXPECT_EQ(std::frexp(f, &fe), T(0.5)) << "not a power of two: " << f;  // f = 0.5 2^fe
    EXPECT_TRUE(fe - 1 >= lo && fe - 1 <= hi) << f;
    const T s = m * f;
    if (fe - 1 > lo && fe - 1 < hi) {
      EXPECT_TRUE(s >= T(1) && s < T(2)) << m << " * " << f << " = " << s;
    }
  }
  // The ends of the range: f is clamped to a representable power of two.
  const T big = std::numeric_limits<T>::max(), tiny = std::numeric_limits<T>::denorm_min();
  EXPECT_TRUE(big * normalising_scale(big) >= T(1) && big * normalising_scale(big) < T(4));
  EXPECT_TRUE(std::isfinite(normalising_scale(tiny)) && tiny * normalising_scale(tiny) > T(0));
  EXPECT_EQ(normalising_scale(T(0)), T(1));
  EXPECT_EQ(normalising_scale(std::numeric_limits<T>::infinity()), T(1));
  EXPECT_EQ(normalising_scale(std::numeric_limits<T>::quiet_NaN()), T(1));
}
