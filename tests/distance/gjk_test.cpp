// SPDX-License-Identifier: BSL-1.0
// GJK distance and EPA penetration depth (distance/gjk.hpp, distance/support.hpp); rows
// dist2.gjk, dist3.gjk. Oracles: for polytopes the minimum over all feature pairs (vertex-
// triangle and edge-edge in 3D, vertex-edge in 2D) with locus's point_triangle, point_segment and
// segment_segment queries, and the convex hull of all pairwise vertex differences (the
// Minkowski difference: the origin's distance to it, or the depth as the smallest face-plane
// distance); analytic answers for spheres, boxes, capsules, cylinders; degenerate inputs.

#include <locus/core/rotation.hpp>
#include <locus/distance/gjk.hpp>
#include <locus/distance/point_aligned_box.hpp>
#include <locus/distance/point_oriented_box.hpp>
#include <locus/distance/point_segment.hpp>
#include <locus/distance/point_triangle.hpp>
#include <locus/distance/segment_segment.hpp>
#include <locus/hull/hull2.hpp>
#include <locus/hull/hull3.hpp>

#include "support/sanitizer.hpp"
#include "support/typed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace {

using namespace locus;
using locus_test::Rng;

#if LOCUS_TEST_SANITIZED
constexpr int kScale = 4;  // fewer random cases under the sanitizers
#else
constexpr int kScale = 1;
#endif

// ---- polytopes and brute-force oracles ---------------------------------------------------------

struct Poly3 {
  std::vector<Vec3d> pts;                          // the input points (GJK sees these)
  std::vector<std::array<std::uint32_t, 3>> tris;  // hull triangles (the oracle uses these)
};

Poly3 make_poly3(std::vector<Vec3d> pts) {
  Poly3 p;
  p.pts = std::move(pts);
  const Hull3Result h = convex_hull(p.pts);
  EXPECT_EQ(h.status, Status::ok);
  EXPECT_EQ(h.dimension, 3);
  p.tris = h.triangles;
  return p;
}

Poly3 random_poly3(Rng& rng, int n, const Vec3d& center, double radius) {
  std::vector<Vec3d> pts;
  for (int i = 0; i < n; ++i)
    pts.push_back(center + radius * rng.unit<double, 3>() * rng.uniform(0.3, 1.0));
  return make_poly3(std::move(pts));
}

/// Distance between two separated or touching convex polytopes: minimum over feature pairs.
double brute_distance3(const Poly3& a, const Poly3& b) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& t : b.tris) {
    const Triangle3d tri{b.pts[t[0]], b.pts[t[1]], b.pts[t[2]]};
    for (const auto& p : a.pts) best = std::min(best, distance(p, tri).distance);
  }
  for (const auto& t : a.tris) {
    const Triangle3d tri{a.pts[t[0]], a.pts[t[1]], a.pts[t[2]]};
    for (const auto& p : b.pts) best = std::min(best, distance(p, tri).distance);
  }
  for (const auto& ta : a.tris)
    for (int i = 0; i < 3; ++i) {
      const Segment3d ea{a.pts[ta[i]], a.pts[ta[(i + 1) % 3]]};
      for (const auto& tb : b.tris)
        for (int j = 0; j < 3; ++j) {
          const Segment3d eb{b.pts[tb[j]], b.pts[tb[(j + 1) % 3]]};
          best = std::min(best, distance(ea, eb).distance);
        }
    }
  return best;
}

/// The Minkowski difference hull A - B: signed distance of the origin (positive outside: the
/// distance; negative inside: minus the penetration depth, the smallest face-plane distance).
double minkowski_signed3(const std::vector<Vec3d>& a, const std::vector<Vec3d>& b) {
  std::vector<Vec3d> d;
  for (const auto& p : a)
    for (const auto& q : b) d.push_back(p - q);
  const Hull3Result h = convex_hull(d);
  EXPECT_EQ(h.dimension, 3);
  bool inside = true;
  double out = std::numeric_limits<double>::infinity(), in = out;
  const Vec3d o{};
  for (const auto& t : h.triangles) {
    const Triangle3d tri{d[t[0]], d[t[1]], d[t[2]]};
    if (orient3d(tri.v0, tri.v1, tri.v2, o) > Sign::zero) inside = false;
    out = std::min(out, distance(o, tri).distance);
    const Vec3d n = normalize(normal(tri));
    in = std::min(in, -dot(n, o - tri.v0));
  }
  return inside ? -in : out;
}

struct Poly2 {
  std::vector<Vec2d> pts;
  std::vector<std::uint32_t> ring;  // hull, counter-clockwise
};

Poly2 random_poly2(Rng& rng, int n, const Vec2d& center, double radius) {
  Poly2 p;
  for (int i = 0; i < n; ++i)
    p.pts.push_back(center + radius * rng.unit<double, 2>() * rng.uniform(0.3, 1.0));
  const Hull2Result h = convex_hull(p.pts);
  EXPECT_EQ(h.dimension, 2);
  p.ring = h.indices;
  return p;
}

double brute_distance2(const Poly2& a, const Poly2& b) {
  double best = std::numeric_limits<double>::infinity();
  const auto edges = [](const Poly2& p, std::size_t i) {
    return Segment2d{p.pts[p.ring[i]], p.pts[p.ring[(i + 1) % p.ring.size()]]};
  };
  for (std::size_t i = 0; i < a.ring.size(); ++i)
    for (std::size_t j = 0; j < b.ring.size(); ++j)
      best = std::min(best, distance(edges(a, i), edges(b, j)).distance);
  return best;
}

double minkowski_signed2(const std::vector<Vec2d>& a, const std::vector<Vec2d>& b) {
  std::vector<Vec2d> d;
  for (const auto& p : a)
    for (const auto& q : b) d.push_back(p - q);
  const Hull2Result h = convex_hull(d);
  bool inside = true;
  double out = std::numeric_limits<double>::infinity(), in = out;
  const Vec2d o{};
  for (std::size_t i = 0; i < h.indices.size(); ++i) {
    const Vec2d p = d[h.indices[i]], q = d[h.indices[(i + 1) % h.indices.size()]];
    if (orient2d(p, q, o) < Sign::zero) inside = false;
    out = std::min(out, distance(o, Segment2d{p, q}).distance);
    const Vec2d e = normalize(q - p);
    in = std::min(in, perp_dot(e, o - p));
  }
  return inside ? -in : out;
}

Mat3d random_rotation(Rng& rng) {
  const Vec3d axis = rng.unit<double, 3>();
  return to_matrix(AxisAngle<double>{axis, rng.uniform(0.0, 6.28)});
}

// ---- random polytopes vs brute force ---------------------------------------------------------

TEST(Gjk3, RandomPolytopesMatchFeaturePairMinimum) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  double worst = 0.0;
  int separated = 0, intersecting = 0;
  for (int c = 0; c < 300 / kScale; ++c) {
    const Poly3 a =
        random_poly3(rng, rng.uniform_int(4, 40), rng.vec<double, 3>(-2, 2), rng.uniform(0.2, 2.0));
    const Poly3 b =
        random_poly3(rng, rng.uniform_int(4, 40), rng.vec<double, 3>(-2, 2), rng.uniform(0.2, 2.0));
    const auto r = gjk_distance(ConvexPoints<double, 3>{a.pts}, ConvexPoints<double, 3>{b.pts});
    ASSERT_EQ(r.status, Status::ok);
    const double mink = minkowski_signed3(a.pts, b.pts);
    if (mink > 1e-9) {
      ++separated;
      const double exact = brute_distance3(a, b);
      EXPECT_NEAR(exact, mink, 1e-12);
      EXPECT_EQ(r.contact, Contact::separated);
      worst = std::max(worst, std::fabs(r.distance - exact));
      EXPECT_NEAR(r.distance, exact, 1e-13) << "case " << c;
      EXPECT_NEAR(r.sqr_distance, exact * exact, 1e-12);
      // Witnesses: on the hulls (distance to the hull ~ 0) and |closest[1] - closest[0]| = d.
      EXPECT_NEAR(length(r.closest[1] - r.closest[0]), r.distance, 1e-13);
      EXPECT_NEAR(length(r.normal), 1.0, 1e-14);
      EXPECT_NEAR(dot(r.normal, r.closest[1] - r.closest[0]), r.distance, 1e-13);
      // Swap symmetry.
      const auto s = gjk_distance(ConvexPoints<double, 3>{b.pts}, ConvexPoints<double, 3>{a.pts});
      EXPECT_NEAR(s.distance, r.distance, 1e-13);
    } else if (mink < -1e-9) {
      ++intersecting;
      EXPECT_EQ(r.contact, Contact::intersecting);
      EXPECT_EQ(r.distance, 0.0);
      const auto p = penetration(ConvexPoints<double, 3>{a.pts}, ConvexPoints<double, 3>{b.pts});
      EXPECT_EQ(p.status, Status::ok);
      EXPECT_EQ(p.contact, Contact::intersecting);
      EXPECT_NEAR(p.depth, -mink, 1e-12) << "case " << c;
      EXPECT_NEAR(length(p.normal), 1.0, 1e-14);
      EXPECT_NEAR(dot(p.normal, p.closest[0] - p.closest[1]), p.depth, 1e-12);
      // Translating b by depth * normal (slightly more) separates the shapes.
      std::vector<Vec3d> moved = b.pts;
      for (auto& q : moved) q += (p.depth * (1 + 1e-9) + 1e-12) * p.normal;
      EXPECT_GE(minkowski_signed3(a.pts, moved), -1e-12);
    }
  }
  EXPECT_GT(separated, 20 / kScale);
  EXPECT_GT(intersecting, 20 / kScale);
  RecordProperty("worst_abs_error", std::to_string(worst));
}

/// Rotation taking unit u to unit v.
Mat3d rotation_between(const Vec3d& u, const Vec3d& v) {
  const Vec3d axis = cross(u, v);
  const double s = length(axis), c = dot(u, v);
  if (s < 1e-12) {
    if (c > 0) return Mat3d::identity();
    const Vec3d o = std::fabs(u.x) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
    return to_matrix(AxisAngle<double>{normalize(cross(u, o)), pi_v<double>});
  }
  return to_matrix(AxisAngle<double>{axis / s, std::atan2(s, c)});
}

TEST(Gjk3, NearlyParallelFacesMatchFeaturePairMinimum) {
  // Face-face pairs: the largest hull face of b turned against the largest face of a, tilted by
  // 0 or 1e-12 .. 1e-7 radians, at a gap of 1e-4 .. 1e-1. Every point of the two faces is
  // almost equally close, so the final simplex is nearly flat: where GJK loses accuracy.
  Rng rng(47);
  SCOPED_TRACE(rng.trace());
  const auto largest_face = [](const Poly3& p) {
    double best = -1;
    Vec3d n{}, c{};
    for (const auto& t : p.tris) {
      const Triangle3d tri{p.pts[t[0]], p.pts[t[1]], p.pts[t[2]]};
      if (length(normal(tri)) > best) {
        best = length(normal(tri));
        n = normalize(normal(tri));
        c = (tri.v0 + tri.v1 + tri.v2) / 3.0;
      }
    }
    return std::pair{n, c};
  };
  for (int c = 0; c < 120 / kScale; ++c) {
    const Poly3 a = random_poly3(rng, 24, {0, 0, 0}, 1.0);
    const Poly3 b0 = random_poly3(rng, 24, {0, 0, 0}, 1.0);
    const auto [na, ca] = largest_face(a);
    const auto [nb, cb] = largest_face(b0);
    const double tilt = c % 4 == 0 ? 0.0 : std::pow(10.0, rng.uniform(-12.0, -7.0));
    const double gap = std::pow(10.0, rng.uniform(-4.0, -1.0));
    const Vec3d side = normalize(cross(na, rng.unit<double, 3>()));
    const Mat3d rot = to_matrix(AxisAngle<double>{side, tilt}) *
                      to_matrix(AxisAngle<double>{na, rng.uniform(0.0, 6.28)}) *
                      rotation_between(nb, -na);
    std::vector<Vec3d> moved;
    for (const auto& q : b0.pts) moved.push_back(rot * q + (ca + gap * na - rot * cb));
    const Poly3 b = make_poly3(moved);
    const double exact = brute_distance3(a, b);
    ASSERT_GT(exact, 0.0);
    const auto r = gjk_distance(ConvexPoints<double, 3>{a.pts}, ConvexPoints<double, 3>{b.pts});
    EXPECT_EQ(r.status, Status::ok);
    EXPECT_EQ(r.contact, Contact::separated);
    EXPECT_NEAR(r.distance, exact, 2e-15) << "case " << c << " gap " << gap << " tilt " << tilt;
    EXPECT_NEAR(length(r.closest[1] - r.closest[0]), r.distance, 2e-15);
    EXPECT_NEAR(dot(r.normal, na), 1.0, 1e-6);  // from a towards b: a's outward face normal
  }
}

TEST(Gjk3, NearContactPolytopesMatchFeaturePairMinimum) {
  // Separated pairs moved together along their separating direction to a gap of 1e-9 .. 1e-6:
  // the termination test must not stop early (an absolute tolerance would be 1e-6 off here).
  Rng rng(53);
  SCOPED_TRACE(rng.trace());
  int tested = 0;
  for (int c = 0; c < 120 / kScale; ++c) {
    const Poly3 a = random_poly3(rng, 24, {0, 0, 0}, 1.0);
    const Poly3 b0 = random_poly3(rng, 24, 3.0 * rng.unit<double, 3>(), 1.0);
    const auto r0 = gjk_distance(ConvexPoints<double, 3>{a.pts}, ConvexPoints<double, 3>{b0.pts});
    const double target = std::pow(10.0, rng.uniform(-9.0, -6.0));
    std::vector<Vec3d> moved = b0.pts;
    for (auto& q : moved) q -= (r0.distance - target) * r0.normal;
    const Poly3 b = make_poly3(moved);
    const double exact = brute_distance3(a, b);
    if (!(exact > 0.0)) continue;
    ++tested;
    const auto r = gjk_distance(ConvexPoints<double, 3>{a.pts}, ConvexPoints<double, 3>{b.pts});
    EXPECT_EQ(r.status, Status::ok);
    EXPECT_NEAR(r.distance, exact, 1e-15) << "case " << c << " target " << target;
  }
  EXPECT_GT(tested, 100 / kScale);
}

TEST(Gjk, FlatSimplexInFullDimension) {
  // Collinear segments in 2D and coplanar polygons in 3D: every GJK simplex of full size is
  // flat (orient2d / orient3d = 0), so only its facets can hold the nearest point.
  EXPECT_NEAR(gjk_distance(Segment2d{{0, 0}, {1, 0}}, Segment2d{{2.5, 0}, {4, 0}}).distance, 1.5,
              1e-15);
  const std::vector<Vec2d> tri2{{0, 0}, {1, 0}, {3, 0}};  // a flat "triangle"
  EXPECT_NEAR(gjk_distance(ConvexPoints<double, 2>{tri2}, Vec2d{5, 0}).distance, 2.0, 1e-15);
  EXPECT_EQ(gjk_distance(ConvexPoints<double, 2>{tri2}, Vec2d{2, 0}).contact, Contact::touching);
  Rng rng(59);
  SCOPED_TRACE(rng.trace());
  for (int c = 0; c < 100; ++c) {
    // Two convex polygons in the plane z = 0 (as 3D point sets), compared with the 2D answer.
    std::vector<Vec2d> a2, b2;
    const Vec2d ca = rng.vec<double, 2>(-2, 2), cb = rng.vec<double, 2>(-2, 2);
    for (int i = 0; i < 8; ++i) {
      a2.push_back(ca + rng.uniform(0.3, 1.0) * rng.unit<double, 2>());
      b2.push_back(cb + rng.uniform(0.3, 1.0) * rng.unit<double, 2>());
    }
    std::vector<Vec3d> a3, b3;
    for (const auto& p : a2) a3.push_back({p.x, p.y, 0});
    for (const auto& p : b2) b3.push_back({p.x, p.y, 0});
    const auto r2 = gjk_distance(ConvexPoints<double, 2>{a2}, ConvexPoints<double, 2>{b2});
    const auto r3 = gjk_distance(ConvexPoints<double, 3>{a3}, ConvexPoints<double, 3>{b3});
    const double mink = minkowski_signed2(a2, b2);
    if (mink > 1e-9) {
      EXPECT_NEAR(r2.distance, mink, 1e-14);
      EXPECT_NEAR(r3.distance, mink, 1e-14);
    } else if (mink < -1e-9) {
      EXPECT_EQ(r2.contact, Contact::intersecting);
      EXPECT_NE(r3.contact, Contact::separated);  // flat in 3D: the boundaries touch
    }
  }
}

TEST(Gjk3, SeparatedPolytopesPenetrationIsMinusDistance) {
  Rng rng(7);
  SCOPED_TRACE(rng.trace());
  for (int c = 0; c < 60 / kScale; ++c) {
    const Poly3 a = random_poly3(rng, 20, {0, 0, 0}, 1.0);
    const Poly3 b = random_poly3(rng, 20, 2.5 * rng.unit<double, 3>(), 1.0);
    const double exact = brute_distance3(a, b);
    const auto p = penetration(ConvexPoints<double, 3>{a.pts}, ConvexPoints<double, 3>{b.pts});
    if (exact > 1e-9) {
      EXPECT_EQ(p.contact, Contact::separated);
      EXPECT_NEAR(p.depth, -exact, 1e-13);
    }
  }
}

TEST(Gjk2, RandomPolygonsMatchBruteForce) {
  Rng rng(11);
  SCOPED_TRACE(rng.trace());
  int separated = 0, intersecting = 0;
  for (int c = 0; c < 600 / kScale; ++c) {
    const Poly2 a =
        random_poly2(rng, rng.uniform_int(3, 30), rng.vec<double, 2>(-2, 2), rng.uniform(0.2, 2.0));
    const Poly2 b =
        random_poly2(rng, rng.uniform_int(3, 30), rng.vec<double, 2>(-2, 2), rng.uniform(0.2, 2.0));
    const auto r = gjk_distance(ConvexPoints<double, 2>{a.pts}, ConvexPoints<double, 2>{b.pts});
    ASSERT_EQ(r.status, Status::ok);
    const double mink = minkowski_signed2(a.pts, b.pts);
    if (mink > 1e-9) {
      ++separated;
      const double exact = brute_distance2(a, b);
      EXPECT_NEAR(exact, mink, 1e-12);
      EXPECT_EQ(r.contact, Contact::separated);
      EXPECT_NEAR(r.distance, exact, 1e-13) << "case " << c;
      EXPECT_NEAR(length(r.closest[1] - r.closest[0]), r.distance, 1e-13);
    } else if (mink < -1e-9) {
      ++intersecting;
      EXPECT_EQ(r.contact, Contact::intersecting);
      const auto p = penetration(ConvexPoints<double, 2>{a.pts}, ConvexPoints<double, 2>{b.pts});
      EXPECT_EQ(p.status, Status::ok);
      EXPECT_NEAR(p.depth, -mink, 1e-12) << "case " << c;
      EXPECT_NEAR(dot(p.normal, p.closest[0] - p.closest[1]), p.depth, 1e-12);
    }
  }
  EXPECT_GT(separated, 50 / kScale);
  EXPECT_GT(intersecting, 50 / kScale);
}

// ---- analytic shapes ----------------------------------------------------------------------

template <class T>
class GjkTyped : public ::testing::Test {};
TYPED_TEST_SUITE(GjkTyped, locus_test::RealTypes);

TYPED_TEST(GjkTyped, SpheresAreExact) {
  using T = TypeParam;
  Rng rng(3);
  SCOPED_TRACE(rng.trace());
  for (int c = 0; c < 200; ++c) {
    const Sphere<T, 3> a{rng.vec<T, 3>(-5, 5), rng.uniform<T>(0, 2)};
    const Sphere<T, 3> b{rng.vec<T, 3>(-5, 5), rng.uniform<T>(0, 2)};
    const double gap =
        length(vec_cast<double>(b.center - a.center)) - double(a.radius) - double(b.radius);
    const auto r = gjk_distance(a, b);
    const auto p = penetration(a, b);
    const T tol = locus_test::tol<T>(64, T(10));
    EXPECT_LE(r.iterations, 2);
    if (gap > 0) {
      EXPECT_NEAR(r.distance, T(gap), tol);
      EXPECT_TRUE(locus_test::vec_near(r.closest[0], support(a, r.normal), tol));
      EXPECT_TRUE(locus_test::vec_near(r.closest[1], support(b, -r.normal), tol));
    } else {
      EXPECT_EQ(r.distance, T(0));
      EXPECT_EQ(r.contact, Contact::intersecting);
    }
    EXPECT_NEAR(p.depth, T(-gap), tol);
    EXPECT_NEAR(double(dot(p.normal, normalize(b.center - a.center))), 1.0, 1e-5);
  }
}

TYPED_TEST(GjkTyped, SphereBoxMatchesPointBox) {
  using T = TypeParam;
  Rng rng(5);
  SCOPED_TRACE(rng.trace());
  for (int c = 0; c < 200; ++c) {
    const Vec3<T> lo = rng.vec<T, 3>(-2, 0), hi = lo + rng.vec<T, 3>(T(0.1), 3);
    const AlignedBox<T, 3> box{lo, hi};
    const Sphere<T, 3> s{rng.vec<T, 3>(-4, 4), rng.uniform<T>(T(0.1), 1)};
    const T d = distance(s.center, box).distance;
    const auto r = gjk_distance(box, s);
    const T tol = locus_test::tol<T>(256, T(4));
    if (d - s.radius > tol) {
      EXPECT_EQ(r.contact, Contact::separated);
      EXPECT_NEAR(r.distance, d - s.radius, tol);
    } else if (d - s.radius < -tol) {
      EXPECT_EQ(r.contact, Contact::intersecting);
    }
    // The same box as an OrientedBox under a random rotation, the sphere rotated along.
    const Mat3d rot = random_rotation(rng);
    OrientedBox<T, 3> ob = oriented_box(box);
    ob.center = vec_cast<T>(rot * vec_cast<double>(ob.center));
    for (auto& ax : ob.axis) ax = vec_cast<T>(rot * vec_cast<double>(ax));
    const Sphere<T, 3> s2{vec_cast<T>(rot * vec_cast<double>(s.center)), s.radius};
    const auto r2 = gjk_distance(ob, s2);
    EXPECT_NEAR(r2.distance, r.distance, locus_test::tol<T>(2048, T(4)));
  }
}

TYPED_TEST(GjkTyped, CapsulesMatchSegmentSegment) {
  using T = TypeParam;
  Rng rng(9);
  SCOPED_TRACE(rng.trace());
  for (int c = 0; c < 200; ++c) {
    const Capsule<T, 3> a{{rng.vec<T, 3>(-3, 3), rng.vec<T, 3>(-3, 3)}, rng.uniform<T>(0, T(0.5))};
    const Capsule<T, 3> b{{rng.vec<T, 3>(-3, 3), rng.vec<T, 3>(-3, 3)}, rng.uniform<T>(0, T(0.5))};
    const double core =
        distance(Segment3d{vec_cast<double>(a.segment.p0), vec_cast<double>(a.segment.p1)},
                 Segment3d{vec_cast<double>(b.segment.p0), vec_cast<double>(b.segment.p1)})
            .distance;
    const double gap = core - double(a.radius) - double(b.radius);
    const auto r = gjk_distance(a, b);
    const auto p = penetration(a, b);
    const T tol = locus_test::tol<T>(256, T(6));
    EXPECT_LE(r.iterations, 6);
    if (gap > 0) {
      EXPECT_NEAR(r.distance, T(gap), tol);
    }
    if (core > 1e-6) {
      EXPECT_NEAR(p.depth, T(-gap), tol);
    }
  }
}

TEST(Gjk3, CylinderAgainstPointIsAnalytic) {
  Rng rng(13);
  SCOPED_TRACE(rng.trace());
  for (int c = 0; c < 200; ++c) {
    const Vec3d axis = rng.unit<double, 3>();
    const Cylinder3d cyl{
        {rng.vec<double, 3>(-1, 1), axis}, rng.uniform(0.2, 1.5), rng.uniform(0.2, 3.0)};
    const Vec3d p = rng.vec<double, 3>(-4, 4);
    const Vec3d rel = p - cyl.axis.origin;
    const double h = dot(rel, axis), rad = length(rel - h * axis);
    const double dr = std::max(rad - cyl.radius, 0.0),
                 dh = std::max(std::fabs(h) - 0.5 * cyl.height, 0.0);
    const double exact = std::hypot(dr, dh);
    const auto r = gjk_distance(cyl, p);
    EXPECT_NE(r.status, Status::limit_exceeded);
    if (exact > 1e-6) {
      EXPECT_NEAR(r.distance, exact, 1e-9 * (1 + exact)) << "case " << c;
    } else {
      EXPECT_NE(r.contact, Contact::separated);
    }
  }
}

TEST(Gjk3, ConeAgainstSampledHull) {
  // A finite cone and a point: compare with the hull of 4096 rim samples plus the apex (the
  // sampled hull is inside the cone, so its distance is an upper bound within 1e-3).
  Rng rng(17);
  SCOPED_TRACE(rng.trace());
  const Cone3d cone{{0.5, -0.2, 0.3}, normalize(Vec3d{1, 2, 2}), 0.5, 0.0, 2.0};
  std::vector<Vec3d> samples{cone.vertex};
  const auto basis = perpendicular_basis(cone.axis);
  for (int i = 0; i < 4096; ++i) {
    const double t = 2 * pi_v<double> * i / 4096;
    samples.push_back(cone.vertex + 2.0 * cone.axis +
                      2.0 * std::tan(0.5) * (std::cos(t) * basis.u + std::sin(t) * basis.v));
  }
  for (int c = 0; c < 50; ++c) {
    const Vec3d p = rng.vec<double, 3>(-4, 4);
    const auto r = gjk_distance(cone, p);
    const auto s = gjk_distance(ConvexPoints<double, 3>{samples}, p);
    EXPECT_LE(r.distance, s.distance + 1e-12);
    EXPECT_GE(r.distance, s.distance - 2e-3);
    if (r.contact == Contact::separated) {
      EXPECT_NEAR(dot(r.closest[0] - r.closest[1], r.normal), -r.distance, 1e-12);
    }
  }
}

TEST(Gjk3, TransformedShapeEqualsMovedPoints) {
  Rng rng(19);
  SCOPED_TRACE(rng.trace());
  for (int c = 0; c < 100 / kScale; ++c) {
    const Poly3 a = random_poly3(rng, 24, {0, 0, 0}, 1.0);
    const Poly3 b = random_poly3(rng, 24, {0, 0, 0}, 1.0);
    const Mat3d rot = random_rotation(rng);
    const Vec3d t = rng.vec<double, 3>(-3, 3);
    std::vector<Vec3d> moved;
    for (const auto& p : b.pts) moved.push_back(rot * p + t);
    const Transformed<ConvexPoints<double, 3>, double, 3> tb{ConvexPoints<double, 3>{b.pts}, rot, t,
                                                             0.0};
    const auto r1 = gjk_distance(ConvexPoints<double, 3>{a.pts}, tb);
    const auto r2 = gjk_distance(ConvexPoints<double, 3>{a.pts}, ConvexPoints<double, 3>{moved});
    EXPECT_NEAR(r1.distance, r2.distance, 1e-12);
    // A margin shrinks the distance by exactly the margin.
    const Transformed<ConvexPoints<double, 3>, double, 3> tm{ConvexPoints<double, 3>{b.pts}, rot, t,
                                                             0.1};
    const auto r3 = gjk_distance(ConvexPoints<double, 3>{a.pts}, tm);
    if (r2.distance > 0.1 + 1e-9) {
      EXPECT_NEAR(r3.distance, r2.distance - 0.1, 1e-12);
    }
    // Rigid motion of both: same distance.
    std::vector<Vec3d> ma;
    for (const auto& p : a.pts) ma.push_back(rot * p + t);
    const auto r4 = gjk_distance(ConvexPoints<double, 3>{ma}, ConvexPoints<double, 3>{moved});
    const auto r5 = gjk_distance(ConvexPoints<double, 3>{a.pts}, ConvexPoints<double, 3>{b.pts});
    EXPECT_NEAR(r4.distance, r5.distance, 1e-12);
  }
}

TEST(Gjk3, MixedPrimitivesAgainstPolytopeBruteForce) {
  // Segment, triangle and point shapes are polytopes too: check them against the oracle.
  Rng rng(23);
  SCOPED_TRACE(rng.trace());
  for (int c = 0; c < 200 / kScale; ++c) {
    const Triangle3d tri{rng.vec<double, 3>(-2, 2), rng.vec<double, 3>(-2, 2),
                         rng.vec<double, 3>(-2, 2)};
    const Segment3d seg{rng.vec<double, 3>(-2, 2), rng.vec<double, 3>(-2, 2)};
    const Vec3d p = rng.vec<double, 3>(-2, 2);
    // Triangle-segment: minimum over edge-edge and segment endpoint-triangle pairs, unless the
    // segment pierces the triangle (the Minkowski-difference oracle decides).
    double exact = std::min(distance(seg.p0, tri).distance, distance(seg.p1, tri).distance);
    for (int i = 0; i < 3; ++i)
      exact = std::min(exact, distance(Segment3d{tri[i], tri[(i + 1) % 3]}, seg).distance);
    if (minkowski_signed3({tri.v0, tri.v1, tri.v2}, {seg.p0, seg.p1}) < 0) exact = 0;
    const auto r = gjk_distance(tri, seg);
    if (exact > 1e-9) {
      EXPECT_NEAR(r.distance, exact, 1e-13);
    } else {
      EXPECT_NE(r.contact, Contact::separated);
      // Flat shapes: the Minkowski difference has no interior (segment x triangle spans 3D
      // unless parallel, so only check the status is not an error).
      const auto pen = penetration(tri, seg);
      EXPECT_NE(pen.status, Status::non_finite_input);
    }
    EXPECT_NEAR(gjk_distance(p, tri).distance, distance(p, tri).distance, 1e-13);
    EXPECT_NEAR(gjk_distance(seg, p).distance, distance(p, seg).distance, 1e-13);
  }
}

// ---- contact classification and degenerate input ---------------------------------------------

AlignedBox3d cube(const Vec3d& c, double h) {
  return {c - splat<double, 3>(h), c + splat<double, 3>(h)};
}

TEST(Gjk3, TouchingBoxes) {
  // Face, edge and vertex contact of unit cubes: distance 0, touching, depth 0.
  const AlignedBox3d a = cube({0, 0, 0}, 1);
  for (const Vec3d& off :
       {Vec3d{2, 0, 0}, Vec3d{2, 2, 0}, Vec3d{2, 2, 2}, Vec3d{2, 0.5, 0.3}, Vec3d{0, 0, -2}}) {
    const AlignedBox3d b = cube(off, 1);
    const auto r = gjk_distance(a, b);
    EXPECT_EQ(r.status, Status::ok);
    EXPECT_EQ(r.contact, Contact::touching) << off.x << " " << off.y << " " << off.z;
    EXPECT_EQ(r.distance, 0.0);
    const auto p = penetration(a, b);
    EXPECT_EQ(p.contact, Contact::touching);
    EXPECT_NEAR(p.depth, 0.0, 1e-14);
    EXPECT_NEAR(length(p.normal), 1.0, 1e-12);
    // Apart or overlapping by 1e-6 along every axis on which the cubes touch.
    Vec3d push{};
    for (int i = 0; i < 3; ++i)
      push[i] = std::fabs(off[i]) == 2 ? (off[i] > 0 ? 1e-6 : -1e-6) : 0.0;
    const auto far = gjk_distance(a, cube(off + push, 1));
    EXPECT_EQ(far.contact, Contact::separated);
    EXPECT_NEAR(far.distance, length(push), 1e-15);
    const auto near = penetration(a, cube(off - push, 1));
    EXPECT_EQ(near.contact, Contact::intersecting);
    EXPECT_NEAR(near.depth, 1e-6, 1e-15);
  }
}

TEST(Gjk3, CubesOverlappingAlongZ) {
  // libccd issue 25: cubes of side 2 at z = 0 and z = 1.9 overlap by 0.1 along z.
  const auto p = penetration(cube({0, 0, 0}, 1), cube({0, 0, 1.9}, 1));
  EXPECT_EQ(p.status, Status::ok);
  EXPECT_EQ(p.contact, Contact::intersecting);
  EXPECT_NEAR(p.depth, 0.1, 1e-14);
  EXPECT_NEAR(p.normal.z, 1.0, 1e-14);
  const auto r = gjk_distance(cube({0, 0, 0}, 1), cube({0, 0, 1.9}, 1));
  EXPECT_EQ(r.contact, Contact::intersecting);
}

TEST(Gjk3, CoincidentAndNestedShapes) {
  const AlignedBox3d a{{-1, -2, -3}, {1, 2, 3}};
  const auto same = penetration(a, a);
  EXPECT_EQ(same.contact, Contact::intersecting);
  EXPECT_NEAR(same.depth, 2.0, 1e-14);  // the thinnest direction: x, width 2
  EXPECT_NEAR(std::fabs(same.normal.x), 1.0, 1e-14);
  EXPECT_EQ(gjk_distance(a, a).contact, Contact::intersecting);
  // Nested: a small box inside a big one; depth = distance to exit the big one along the best axis.
  const AlignedBox3d small{{0.2, -0.1, -0.1}, {0.4, 0.1, 0.1}};
  const auto nested = penetration(a, small);
  EXPECT_NEAR(nested.depth, 1.0 - 0.2, 1e-14);
  EXPECT_NEAR(nested.normal.x, 1.0, 1e-14);
  // Identical polytopes (random), and identical spheres.
  Rng rng(29);
  const Poly3 p = random_poly3(rng, 30, {1, 2, 3}, 1.5);
  const auto pp = penetration(ConvexPoints<double, 3>{p.pts}, ConvexPoints<double, 3>{p.pts});
  EXPECT_EQ(pp.contact, Contact::intersecting);
  EXPECT_NEAR(pp.depth, -minkowski_signed3(p.pts, p.pts), 1e-12);
  const Sphere3d s{{1, 1, 1}, 2};
  const auto ss = penetration(s, s);
  EXPECT_NEAR(ss.depth, 4.0, 1e-14);
  EXPECT_NEAR(length(ss.normal), 1.0, 1e-14);
}

TEST(Gjk3, FlatShapes) {
  // Coplanar overlapping triangles: the Minkowski difference is flat.
  const Triangle3d a{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
  const Triangle3d b{{0.5, 0.5, 0}, {3, 0.5, 0}, {0.5, 3, 0}};
  const auto r = gjk_distance(a, b);
  EXPECT_EQ(r.contact, Contact::touching);
  const auto p = penetration(a, b);
  EXPECT_EQ(p.status, Status::degenerate_input);
  EXPECT_EQ(p.contact, Contact::touching);
  EXPECT_EQ(p.depth, 0.0);
  EXPECT_NEAR(std::fabs(p.normal.z), 1.0, 1e-14);
  // Crossing segments in 3D: flat difference (a parallelogram); capsules around them have
  // depth = the radii sum.
  const Segment3d s0{{-1, 0, 0}, {1, 0, 0}}, s1{{0, -1, 0}, {0, 1, 0}};
  const auto ps = penetration(s0, s1);
  EXPECT_EQ(ps.status, Status::degenerate_input);
  EXPECT_NEAR(std::fabs(ps.normal.z), 1.0, 1e-14);
  const auto pc = penetration(Capsule3d{s0, 0.25}, Capsule3d{s1, 0.5});
  EXPECT_EQ(pc.status, Status::ok);
  EXPECT_NEAR(pc.depth, 0.75, 1e-14);
  // Coplanar but separated triangles: an ordinary positive distance.
  const Triangle3d c{{3, 3, 0}, {5, 3, 0}, {3, 5, 0}};
  EXPECT_NEAR(gjk_distance(a, c).distance, std::sqrt(2.0) * 2, 1e-14);
  // Points: equal points touch, distinct points are separated.
  EXPECT_EQ(gjk_distance(Vec3d{1, 2, 3}, Vec3d{1, 2, 3}).contact, Contact::touching);
  EXPECT_NEAR(gjk_distance(Vec3d{1, 2, 3}, Vec3d{1, 2, 4}).distance, 1.0, 1e-15);
}

TEST(Gjk3, DuplicatePointsAndInteriorPoints) {
  Rng rng(31);
  const Poly3 a = random_poly3(rng, 12, {0, 0, 0}, 1);
  const Poly3 b = random_poly3(rng, 12, {3, 0, 0}, 1);
  std::vector<Vec3d> dup;
  for (int k = 0; k < 4; ++k)
    for (const auto& p : a.pts) dup.push_back(p);
  dup.push_back({0, 0, 0});
  const auto r = gjk_distance(ConvexPoints<double, 3>{dup}, ConvexPoints<double, 3>{b.pts});
  EXPECT_NEAR(r.distance, brute_distance3(a, b), 1e-13);
}

TEST(Gjk3, HugeAndTinyScales) {
  Rng rng(37);
  SCOPED_TRACE(rng.trace());
  for (double scale : {1e-80, 1e-20, 1e20, 1e80}) {
    for (int c = 0; c < 20; ++c) {
      Poly3 a = random_poly3(rng, 16, rng.vec<double, 3>(-2, 2), 1.0);
      Poly3 b = random_poly3(rng, 16, rng.vec<double, 3>(-2, 2), 1.0);
      const double mink = minkowski_signed3(a.pts, b.pts);
      for (auto& p : a.pts) p = scale * p;
      for (auto& p : b.pts) p = scale * p;
      const auto r = gjk_distance(ConvexPoints<double, 3>{a.pts}, ConvexPoints<double, 3>{b.pts});
      const auto p = penetration(ConvexPoints<double, 3>{a.pts}, ConvexPoints<double, 3>{b.pts});
      EXPECT_EQ(r.status, Status::ok);
      if (mink > 1e-9) {
        EXPECT_NEAR(r.distance / scale, mink, 1e-12);
        EXPECT_NEAR(-p.depth / scale, mink, 1e-12);
      } else if (mink < -1e-9) {
        EXPECT_EQ(r.contact, Contact::intersecting);
        EXPECT_NEAR(-p.depth / scale, mink, 1e-12);
      }
    }
  }
}

TEST(Gjk3, NonFiniteAndInvalidInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const Sphere3d good{{0, 0, 0}, 1};
  for (const Sphere3d& bad :
       {Sphere3d{{nan, 0, 0}, 1}, Sphere3d{{0, 0, 0}, nan}, Sphere3d{{inf, 0, 0}, 1}}) {
    const auto r = gjk_distance(good, bad);
    EXPECT_EQ(r.status, Status::non_finite_input);
    EXPECT_TRUE(std::isnan(r.distance));
    EXPECT_TRUE(std::isnan(penetration(bad, good).depth));
  }
  const std::vector<Vec3d> pts{{0, 0, 0}, {nan, 1, 1}, {1, 0, 0}};
  EXPECT_EQ(gjk_distance(ConvexPoints<double, 3>{pts}, good).status, Status::non_finite_input);
  EXPECT_EQ(gjk_distance(ConvexPoints<double, 3>{}, good).status, Status::non_finite_input);
  const Cylinder3d infinite{{{0, 0, 0}, {0, 0, 1}}, 1, inf};
  EXPECT_EQ(gjk_distance(infinite, Vec3d{3, 0, 0}).status, Status::non_finite_input);
  EXPECT_EQ(gjk_distance(good, Sphere3d{{3, 0, 0}, -1}).status, Status::invalid_input);
}

TEST(Gjk3, IterationBudget) {
  Rng rng(41);
  const Poly3 a = random_poly3(rng, 60, {0, 0, 0}, 1);
  const Poly3 b = random_poly3(rng, 60, {2.5, 0.3, 0.1}, 1);
  const double exact = brute_distance3(a, b);
  GjkOptions<double, 3> opt;
  opt.max_iterations = 1;
  const auto r = gjk_distance(ConvexPoints<double, 3>{a.pts}, ConvexPoints<double, 3>{b.pts}, opt);
  EXPECT_EQ(r.status, Status::limit_exceeded);
  EXPECT_GE(r.distance, exact - 1e-14);  // an upper bound
  EXPECT_EQ(r.iterations, 1);
  opt.max_iterations = 0;
  EXPECT_EQ(
      gjk_distance(ConvexPoints<double, 3>{a.pts}, ConvexPoints<double, 3>{b.pts}, opt).status,
      Status::limit_exceeded);
  // A curved pair converges within the default budget.
  const Cylinder3d c1{{{0, 0, 0}, normalize(Vec3d{1, 1, 0})}, 1, 2};
  const Cone3d c2{{3, 1, 0.5}, normalize(Vec3d{-1, 0.2, 0.1}), 0.4, 0.2, 1.5};
  const auto rc = gjk_distance(c1, c2);
  EXPECT_EQ(rc.status, Status::ok);
  EXPECT_LT(rc.iterations, 128);
}

TEST(Gjk2, AnalyticAndDegenerate) {
  // Circles and boxes in 2D.
  const Circle2d c0{{0, 0}, 1}, c1{{3, 4}, 2};
  EXPECT_NEAR(gjk_distance(c0, c1).distance, 2.0, 1e-15);
  EXPECT_NEAR(penetration(c0, Circle2d{{1, 0}, 1}).depth, 1.0, 1e-15);
  const AlignedBox2d a{{0, 0}, {2, 1}};
  EXPECT_EQ(gjk_distance(a, AlignedBox2d{{2, 0.5}, {3, 3}}).contact, Contact::touching);
  const auto p = penetration(a, AlignedBox2d{{1.5, 0.25}, {3, 0.75}});
  EXPECT_NEAR(p.depth, 0.5, 1e-15);
  EXPECT_NEAR(p.normal.x, 1.0, 1e-15);
  // Collinear overlapping segments: flat difference.
  const auto ps = penetration(Segment2d{{0, 0}, {2, 0}}, Segment2d{{1, 0}, {3, 0}});
  EXPECT_EQ(ps.status, Status::degenerate_input);
  EXPECT_EQ(ps.depth, 0.0);
  // Crossing segments in 2D: a full-dimensional difference, depth > 0.
  const auto px = penetration(Segment2d{{-1, 0}, {1, 0}}, Segment2d{{0, -1}, {0, 2}});
  EXPECT_EQ(px.status, Status::ok);
  EXPECT_NEAR(px.depth, 1.0, 1e-15);
  const auto bad = gjk_distance(Vec2d{std::numeric_limits<double>::quiet_NaN(), 0}, c0);
  EXPECT_EQ(bad.status, Status::non_finite_input);
}

TEST(Gjk2, FloatPolygons) {
  Rng rng(43);
  SCOPED_TRACE(rng.trace());
  for (int c = 0; c < 200; ++c) {
    const Poly2 a = random_poly2(rng, 12, rng.vec<double, 2>(-2, 2), 1.0);
    const Poly2 b = random_poly2(rng, 12, rng.vec<double, 2>(-2, 2), 1.0);
    std::vector<Vec2f> af, bf;
    for (const auto& p : a.pts) af.push_back(vec_cast<float>(p));
    for (const auto& p : b.pts) bf.push_back(vec_cast<float>(p));
    std::vector<Vec2d> ad, bd;  // the float points, exactly, in double
    for (const auto& p : af) ad.push_back(vec_cast<double>(p));
    for (const auto& p : bf) bd.push_back(vec_cast<double>(p));
    const double mink = minkowski_signed2(ad, bd);
    const auto r = gjk_distance(ConvexPoints<float, 2>{af}, ConvexPoints<float, 2>{bf});
    if (mink > 1e-5) {
      EXPECT_NEAR(double(r.distance), mink, 1e-6);
    }
    if (mink < -1e-5) {
      EXPECT_NEAR(double(penetration(ConvexPoints<float, 2>{af}, ConvexPoints<float, 2>{bf}).depth),
                  -mink, 1e-6);
    }
  }
}

// ---- trace (figures 6.25-6.28) ------------------------------------------------------------------

TEST(Gjk2, TraceRecordsTheIterations) {
  const std::vector<Vec2d> a{{0, 0}, {2, 0}, {1, 1.5}};
  const std::vector<Vec2d> b{{4, 1}, {6, 0}, {5, 3}};
  GjkTrace<double, 2> trace;
  GjkOptions<double, 2> opt;
  opt.trace = &trace;
  const auto r = gjk_distance(ConvexPoints<double, 2>{a}, ConvexPoints<double, 2>{b}, opt);
  ASSERT_FALSE(trace.steps.empty());
  EXPECT_EQ(static_cast<int>(trace.steps.size()), r.iterations);
  double prev = length(trace.v0);
  for (const auto& s : trace.steps) {
    EXPECT_NEAR(length(s.v), prev, 1e-15);  // V_k continues from the previous step
    EXPECT_LE(length(s.v_next), length(s.v) + 1e-15);
    EXPECT_GE(s.simplex.size, 1);
    Vec2d v{};
    for (int i = 0; i < s.simplex.size; ++i)
      v += s.simplex.weight[i] * (s.simplex.a[i] - s.simplex.b[i]);
    EXPECT_NEAR(length(v - s.v_next), 0.0, 1e-14);
    prev = length(s.v_next);
  }
  EXPECT_NEAR(prev, r.distance, 1e-14);
  EXPECT_NEAR(r.distance, minkowski_signed2(a, b), 1e-14);
}

}  // namespace
