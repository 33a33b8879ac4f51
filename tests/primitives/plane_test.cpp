// SPDX-License-Identifier: BSL-1.0
// Tests for primitives/plane.hpp (row prim3.planar: planes, frames in a plane, 2D objects in 3D,
// Newell normals).
#include <locus/primitives/circle.hpp>
#include <locus/primitives/plane.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
using locus_test::vec_near;

template <class T>
class PlaneTest : public ::testing::Test {};
TYPED_TEST_SUITE(PlaneTest, locus_test::RealTypes);

static_assert(std::is_aggregate_v<Plane3d> && std::is_trivially_copyable_v<Plane3f>);
static_assert(std::is_aggregate_v<PlaneFrame3<float>>);

namespace {
mpq_class q(double x) { return mpq_class(x); }

template <class T>
Vec3<T> int_vec(Rng& rng, int lim) {
  return {T(rng.uniform_int(-lim, lim)), T(rng.uniform_int(-lim, lim)),
          T(rng.uniform_int(-lim, lim))};
}
}  // namespace

TYPED_TEST(PlaneTest, Figure9_1PointNormalForm) {
  using T = TypeParam;
  // Fig 9.1: the plane through P with normal n is { X : n . (X - P) = 0 }.
  const Vec3<T> p{1, 2, 3}, n{0, 0, 2};
  const auto pl = plane_from_point_normal(p, n);
  EXPECT_EQ(pl.constant, T(6));
  EXPECT_EQ(signed_value(pl, p), T(0));
  EXPECT_EQ(signed_value(pl, Vec3<T>{5, -7, 3}), T(0));
  EXPECT_EQ(signed_value(pl, Vec3<T>{0, 0, 4}), T(2));  // |n| times the distance 1
  EXPECT_EQ(signed_distance(pl, Vec3<T>{0, 0, 4}), T(1));
  EXPECT_EQ(signed_distance(pl, Vec3<T>{0, 0, 0}), T(-3));
  // Fig 9.2: a x + b y + c z + d = 0 has unit-normal distance -d / |n| from the origin.
  const auto u = normalized(pl);
  EXPECT_EQ(u.normal, (Vec3<T>{0, 0, 1}));
  EXPECT_EQ(u.constant, T(3));
  EXPECT_EQ(closest_to_origin(pl), (Vec3<T>{0, 0, 3}));
}

TYPED_TEST(PlaneTest, ThroughIntegerPointsIsExact) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  // Coordinates small enough that the cross product and dot products are exact in T.
  const int lim = std::is_same_v<T, float> ? 64 : 4096;
  int made = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const auto a = int_vec<T>(rng, lim), b = int_vec<T>(rng, lim), c = int_vec<T>(rng, lim);
    const auto pl = plane_through(a, b, c);
    // Exact cross product with GMP decides collinearity independently.
    const mpq_class ux = q(b.x) - q(a.x), uy = q(b.y) - q(a.y), uz = q(b.z) - q(a.z);
    const mpq_class vx = q(c.x) - q(a.x), vy = q(c.y) - q(a.y), vz = q(c.z) - q(a.z);
    const mpq_class nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    const bool collinear = nx == 0 && ny == 0 && nz == 0;
    ASSERT_EQ(pl.has_value(), !collinear);
    if (!pl) continue;
    ++made;
    EXPECT_TRUE(q(pl->normal.x) == nx && q(pl->normal.y) == ny && q(pl->normal.z) == nz);
    for (const auto& p : {a, b, c}) {
      const mpq_class v = q(pl->normal.x) * q(p.x) + q(pl->normal.y) * q(p.y) +
                          q(pl->normal.z) * q(p.z) - q(pl->constant);
      EXPECT_EQ(v, 0);
    }
  }
  EXPECT_GT(made, 1900);
}

TYPED_TEST(PlaneTest, CollinearAndCoincidentGiveNullopt) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 500; ++trial) {
    const auto a = int_vec<T>(rng, 50), d = int_vec<T>(rng, 20);
    const T s = T(rng.uniform_int(-5, 5)), t = T(rng.uniform_int(-5, 5));
    EXPECT_FALSE(plane_through(a, Vec3<T>(a + s * d), Vec3<T>(a + t * d)).has_value());
    EXPECT_FALSE(plane_through(a, a, Vec3<T>(a + d)).has_value());
  }
  // Nearly collinear but not collinear: the exact test keeps it.
  const T e = std::numeric_limits<T>::epsilon();
  EXPECT_TRUE(
      plane_through(Vec3<T>{0, 0, 0}, Vec3<T>{1, 1, 1}, Vec3<T>{2, 2, 2 + 4 * e}).has_value());
  // Non-finite points and a zero normal from underflow.
  const T nan = std::numeric_limits<T>::quiet_NaN();
  EXPECT_FALSE(plane_through(Vec3<T>{nan, 0, 0}, Vec3<T>{1, 0, 0}, Vec3<T>{0, 1, 0}).has_value());
  const T tiny = std::numeric_limits<T>::denorm_min();
  EXPECT_FALSE(
      plane_through(Vec3<T>{0, 0, 0}, Vec3<T>{tiny, 0, 0}, Vec3<T>{0, tiny, 0}).has_value());
}

TYPED_TEST(PlaneTest, SignedDistanceAndProjectionAgainstExactOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 1000; ++trial) {
    const Plane3<T> pl{rng.vec<T, 3>(-4, 4), rng.uniform<T>(-10, 10)};
    if (length(pl.normal) < T(0.1)) continue;
    const auto x = rng.vec<T, 3>(-10, 10);
    const mpq_class v = q(pl.normal.x) * q(x.x) + q(pl.normal.y) * q(x.y) +
                        q(pl.normal.z) * q(x.z) - q(pl.constant);
    const double nl =
        std::sqrt(mpq_class(q(pl.normal.x) * q(pl.normal.x) + q(pl.normal.y) * q(pl.normal.y) +
                            q(pl.normal.z) * q(pl.normal.z))
                      .get_d());
    const double dist = v.get_d() / nl;
    // Terms up to |n||x| + |c| ~ 80 / |n| >= 0.1: a few dozen eps of that scale.
    const T scale = (length(pl.normal) * length(x) + std::fabs(pl.constant)) / length(pl.normal);
    EXPECT_NEAR(double(signed_distance(pl, x)), dist, double(tol<T>(16, scale)));
    EXPECT_NEAR(double(signed_value(pl, x)), v.get_d(),
                double(tol<T>(8, scale * length(pl.normal))));
    const auto p = project(pl, x);
    EXPECT_NEAR(signed_distance(pl, p), T(0), tol<T>(32, scale));
    // x - p is parallel to the normal, of length |dist|.
    EXPECT_NEAR(length(cross(x - p, normalize(pl.normal))), T(0), tol<T>(32, scale));
    EXPECT_NEAR(double(length(x - p)), std::fabs(dist), double(tol<T>(32, scale)));
    // normalized() keeps the signed distances.
    const auto u = normalized(pl);
    EXPECT_NEAR(length(u.normal), T(1), tol<T>(4));
    EXPECT_NEAR(double(signed_value(u, x)), dist, double(tol<T>(16, scale)));
  }
}

TYPED_TEST(PlaneTest, DegeneratePlane) {
  using T = TypeParam;
  const Plane3<T> z{{0, 0, 0}, 1};
  EXPECT_TRUE(is_degenerate(z));
  EXPECT_TRUE(is_degenerate(Plane3<T>{{0, std::numeric_limits<T>::infinity(), 0}, 1}));
  EXPECT_FALSE(is_degenerate(Plane3<T>{{0, 1, 0}, 1}));
  EXPECT_EQ(normalized(z).normal, (Vec3<T>{}));
  EXPECT_EQ(normalized(z).constant, T(0));
  EXPECT_TRUE(std::isnan(signed_distance(z, Vec3<T>{1, 2, 3})));
  EXPECT_EQ(project(z, Vec3<T>{1, 2, 3}), (Vec3<T>{1, 2, 3}));
  EXPECT_FALSE(plane_frame(z).has_value());
  EXPECT_FALSE(plane_frame(Vec3<T>{}, Vec3<T>{}).has_value());
  EXPECT_EQ(perpendicular_basis(Vec3<T>{}).u, (Vec3<T>{}));
}

TYPED_TEST(PlaneTest, Figure9_3FrameIsOrthonormalAndRoundTrips) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 1000; ++trial) {
    Vec3<T> n = rng.unit<T, 3>();
    if (trial < 4) n = Vec3<T>{0, 0, trial % 2 ? T(-1) : T(1)};  // the branch of the basis formula
    const Plane3<T> pl{n * rng.uniform<T>(T(0.5), 3), rng.uniform<T>(-5, 5)};
    const auto f = plane_frame(pl);
    ASSERT_TRUE(f.has_value());
    EXPECT_NEAR(length(f->u), T(1), tol<T>(8));
    EXPECT_NEAR(length(f->v), T(1), tol<T>(8));
    EXPECT_NEAR(dot(f->u, f->v), T(0), tol<T>(8));
    EXPECT_TRUE(vec_near(cross(f->u, f->v), f->normal, tol<T>(16)));
    EXPECT_TRUE(vec_near(f->normal, normalize(pl.normal), tol<T>(4)));
    EXPECT_NEAR(signed_distance(pl, f->origin), T(0), tol<T>(16, 5));
    // Plane coordinates round-trip; other points map to their projection.
    const Vec2<T> st = rng.vec<T, 2>(-10, 10);
    const auto x = to_world(*f, st);
    EXPECT_EQ(point_at(*f, st), x);
    EXPECT_NEAR(signed_distance(pl, x), T(0), tol<T>(64, 15));
    EXPECT_TRUE(vec_near(to_plane(*f, x), st, tol<T>(64, 15)));
    const auto y = rng.vec<T, 3>(-10, 10);
    EXPECT_TRUE(vec_near(to_world(*f, to_plane(*f, y)), project(pl, y), tol<T>(64, 20)));
    // The same axes as a Circle3 with this normal (one convention library-wide).
    const auto ca = in_plane_axes(Circle3<T>{f->origin, pl.normal, T(1)});
    EXPECT_TRUE(vec_near(ca.u, f->u, tol<T>(4)));
    EXPECT_TRUE(vec_near(ca.v, f->v, tol<T>(4)));
    // The plane of the frame is the same plane.
    const auto back = plane_of(*f);
    EXPECT_NEAR(signed_distance(back, y), signed_distance(pl, y), tol<T>(64, 20));
  }
}

TYPED_TEST(PlaneTest, Section9_2_3CircleEmbeddedInPlane) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 100; ++trial) {
    const auto f = plane_frame(rng.vec<T, 3>(-5, 5), rng.unit<T, 3>());
    ASSERT_TRUE(f.has_value());
    const Vec2<T> c2 = rng.vec<T, 2>(-3, 3);
    const T r = rng.uniform<T>(T(0.5), 2);
    const Vec3<T> c3 = to_world(*f, c2);
    for (int k = 0; k < 16; ++k) {
      const T a = T(k) * pi_v<T> / T(8);
      const Vec3<T> p = to_world(*f, Vec2<T>{c2.x + r * std::cos(a), c2.y + r * std::sin(a)});
      EXPECT_NEAR(length(p - c3), r, tol<T>(64, 10));
      EXPECT_NEAR(dot(p - f->origin, f->normal), T(0), tol<T>(64, 10));
    }
  }
}

TYPED_TEST(PlaneTest, NewellNormalIsTwiceAreaTimesNormal) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 200; ++trial) {
    const auto f = plane_frame(rng.vec<T, 3>(-5, 5), rng.unit<T, 3>());
    ASSERT_TRUE(f.has_value());
    // A star-shaped (hence simple) polygon, counter-clockwise in plane coordinates.
    const int n = rng.uniform_int(3, 12);
    std::vector<Vec2<T>> p2;
    std::vector<Vec3<T>> p3;
    for (int k = 0; k < n; ++k) {
      const T a = (T(k) + rng.uniform<T>(T(0.1), T(0.9))) * 2 * pi_v<T> / T(n);
      const T r = rng.uniform<T>(T(0.5), 2);
      p2.push_back({r * std::cos(a), r * std::sin(a)});
      p3.push_back(to_world(*f, p2.back()));
    }
    T area2 = 0;  // shoelace, twice the area
    for (int k = 0; k < n; ++k) area2 += perp_dot(p2[std::size_t(k)], p2[std::size_t((k + 1) % n)]);
    const auto nn = newell_normal(std::span<const Vec3<T>>(p3));
    EXPECT_EQ(newell_normal(p3.data(), p3.size()), nn);
    EXPECT_TRUE(vec_near(nn, area2 * f->normal, tol<T>(256, 10)));
    const auto bp = best_fit_plane_newell(std::span<const Vec3<T>>(p3));
    ASSERT_TRUE(bp.has_value());
    for (const auto& p : p3) EXPECT_NEAR(signed_distance(*bp, p), T(0), tol<T>(256, 10));
    // Reversing the order flips the normal.
    std::vector<Vec3<T>> rev(p3.rbegin(), p3.rend());
    EXPECT_TRUE(vec_near(newell_normal(std::span<const Vec3<T>>(rev)), -nn, tol<T>(256, 10)));
  }
  std::vector<Vec3<T>> two{{0, 0, 0}, {1, 0, 0}};
  EXPECT_EQ(newell_normal(std::span<const Vec3<T>>(two)), (Vec3<T>{}));
  std::vector<Vec3<T>> line{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
  EXPECT_FALSE(best_fit_plane_newell(std::span<const Vec3<T>>(line)).has_value());
}

TYPED_TEST(PlaneTest, ThroughIsTranslationAndRotationCovariant) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 500; ++trial) {
    // Integer points and offsets: every quantity below is exact, so the checks are equalities.
    const auto a = int_vec<T>(rng, 30), b = int_vec<T>(rng, 30), c = int_vec<T>(rng, 30);
    const auto off = int_vec<T>(rng, 100);
    const auto p = plane_through(a, b, c);
    const auto q = plane_through(Vec3<T>(a + off), Vec3<T>(b + off), Vec3<T>(c + off));
    ASSERT_EQ(p.has_value(), q.has_value());
    if (!p) continue;
    EXPECT_EQ(q->normal, p->normal);
    EXPECT_EQ(q->constant, p->constant + dot(p->normal, off));
    // A cyclic vertex order keeps the plane, a swap flips the normal.
    const auto r = plane_through(b, c, a), s = plane_through(b, a, c);
    EXPECT_EQ(r->normal, p->normal);
    EXPECT_EQ(s->normal, -p->normal);
    // The coordinate permutation (x, y, z) -> (y, z, x) is a rotation: the normal permutes too.
    const auto rot = [](const Vec3<T>& v) { return Vec3<T>{v.y, v.z, v.x}; };
    const auto pr = plane_through(rot(a), rot(b), rot(c));
    EXPECT_EQ(pr->normal, rot(p->normal));
    EXPECT_EQ(pr->constant, p->constant);
  }
}
