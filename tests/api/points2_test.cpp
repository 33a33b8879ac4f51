// SPDX-License-Identifier: BSL-1.0
// The API rule for bulk 2D input (docs/notes/api.md): every algorithm and bulk query taking
// points accepts std::vector, std::array, C arrays, std::span (const or not, any extent) and a
// flat coordinate array through point_span<2>(xy, n), in float and double, without spelling the
// scalar type; and every form gives the same result. A new algorithm is added here: if it breaks
// the rule this file stops compiling.
#include "forms.hpp"

#include <locus/bounding/min_circle.hpp>
#include <locus/bounding/min_rect2.hpp>
#include <locus/containment/point_in_polygon.hpp>
#include <locus/delaunay/constrained_delaunay2.hpp>
#include <locus/delaunay/delaunay2.hpp>
#include <locus/distance/line_polyline.hpp>
#include <locus/distance/point_convex_polygon.hpp>
#include <locus/distance/point_polyline.hpp>
#include <locus/distance/ray_polyline.hpp>
#include <locus/distance/segment_polyline.hpp>
#include <locus/fit/circle_fit.hpp>
#include <locus/fit/gaussian_fit.hpp>
#include <locus/fit/line_fit.hpp>
#include <locus/fit/plane_fit.hpp>
#include <locus/fit/quadratic_fit.hpp>
#include <locus/fit/sphere_fit.hpp>
#include <locus/hull/hull2.hpp>
#include <locus/intersection/line_polyline.hpp>
#include <locus/intersection/ray_polyline.hpp>
#include <locus/intersection/segment_polyline.hpp>
#include <locus/io/svg.hpp>
#include <locus/primitives/aligned_box.hpp>
#include <locus/primitives/polygon.hpp>
#include <locus/primitives/polyline.hpp>
#include <locus/triangulate/ear_clipping.hpp>
#include <locus/triangulate/monotone.hpp>
#include <locus/triangulate/trapezoid_decomposition.hpp>
#include <locus/triangulate/trapezoid_map.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace locus::api_test {
namespace {

constexpr std::size_t kCloud = 40;  // generic points
constexpr std::size_t kRing = 12;   // a convex polygon (counter-clockwise)

template <class T>
std::vector<Vec2<T>> cloud() {
  Lcg g(0x2d5eedu);
  std::vector<Vec2<T>> v;
  for (std::size_t i = 0; i < kCloud; ++i)
    v.push_back({static_cast<T>(g.next()), static_cast<T>(g.next())});
  return v;
}

template <class T>
std::vector<Vec2<T>> ring() {
  std::vector<Vec2<T>> v;
  for (std::size_t i = 0; i < kRing; ++i) {
    const double a = 6.283185307179586 * static_cast<double>(i) / static_cast<double>(kRing);
    v.push_back({static_cast<T>(2.0 * std::cos(a) + 0.25), static_cast<T>(std::sin(a) - 0.5)});
  }
  return v;
}

template <class T>
class PointRange2Test : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(PointRange2Test, Scalars);

TYPED_TEST(PointRange2Test, HullsAndTriangulations) {
  using T = TypeParam;
  Forms<T, 2, kCloud> pts(cloud<T>());
  Forms<T, 2, kRing> poly(ring<T>());
  const Vec2<T> q{T(0.125), T(-0.0625)};

  expect_same(pts, "convex_hull", [](const auto& p) {
    const Hull2Result r = convex_hull(p);
    return digest(r.status, r.dimension, r.indices);
  });
  expect_same(pts, "ConvexHull2::compute", [](const auto& p) {
    ConvexHull2<T> h;
    const Hull2Result r = h.compute(p);
    return digest(r.status, r.dimension, r.indices);
  });
  expect_same(pts, "delaunay", [](const auto& p) {
    const Delaunay2Result r = delaunay(p);
    return digest(r.status, r.dimension, r.triangles, r.adjacency, r.hull);
  });
  expect_same(pts, "locate", [&](const auto& p) {
    const Delaunay2Result dt = delaunay(p);
    const LocateResult r = locate(dt, p, q);
    return digest(r.status, r.location, r.triangle, r.corner);
  });
  const std::vector<std::array<std::uint32_t, 2>> constraints = {{0, 7}, {3, 11}};
  expect_same(pts, "constrained_delaunay", [&](const auto& p) {
    const ConstrainedDelaunay2Result r = constrained_delaunay(p, constraints);
    return digest(r.status, r.triangles, r.adjacency, r.constrained, r.rejected);
  });
  const std::array<std::uint32_t, 1> ring_ends = {static_cast<std::uint32_t>(kRing)};
  expect_same(poly, "triangulate_polygon", [&](const auto& p) {
    const ConstrainedDelaunay2Result r = triangulate_polygon(p, ring_ends);
    return digest(r.status, r.triangles, r.inside);
  });
  expect_same(poly, "triangulate_ear_clipping", [&](const auto& p) {
    const PolygonTriangulation r = triangulate_ear_clipping(p, ring_ends);
    return digest(r.status, r.triangles);
  });
  expect_same(poly, "triangulate_monotone", [&](const auto& p) {
    const PolygonTriangulation r = triangulate_monotone(p, ring_ends);
    return digest(r.status, r.triangles);
  });
  expect_same(poly, "monotone_decomposition", [&](const auto& p) {
    const MonotoneDecomposition r = monotone_decomposition(p, ring_ends);
    return digest(r.status, r.diagonals);
  });
  expect_same(poly, "trapezoid_decomposition", [&](const auto& p) {
    const TrapezoidDecomposition r = trapezoid_decomposition(p, ring_ends);
    return digest(r.status, static_cast<double>(r.trapezoids.size()));
  });
  std::array<std::array<std::uint32_t, 2>, kRing> ring_segments{};
  for (std::uint32_t i = 0; i < kRing; ++i)
    ring_segments[i] = {i, static_cast<std::uint32_t>((i + 1) % kRing)};
  expect_same(poly, "trapezoid_map", [&](const auto& p) {
    const TrapezoidMap r = trapezoid_map(p, ring_segments);
    return digest(r.status, static_cast<double>(r.trapezoids.size()));
  });
}

TYPED_TEST(PointRange2Test, BoundingAndFitting) {
  using T = TypeParam;
  Forms<T, 2, kCloud> pts(cloud<T>());
  Forms<T, 2, kRing> poly(ring<T>());

  expect_same(pts, "min_circle", [](const auto& p) {
    const auto r = min_circle(p);
    return digest(r.status, r.circle.center, r.circle.radius, r.support);
  });
  expect_same(pts, "min_rect", [](const auto& p) {
    const auto r = min_rect(p);
    return digest(r.status, r.rectangle.center, r.rectangle.axis, r.rectangle.extent, r.area);
  });
  expect_same(pts, "bounding_box", [](const auto& p) {
    const auto b = bounding_box(p);
    return digest(b.min, b.max);
  });
  expect_same(pts, "fit_line", [](const auto& p) {
    const auto r = fit_line(p);
    return digest(r.status, r.line.origin, r.line.direction, r.rms);
  });
  expect_same(pts, "fit_line_vertical", [](const auto& p) {
    const auto r = fit_line_vertical(p);
    return digest(r.status, r.slope, r.intercept, r.rms);
  });
  expect_same(pts, "fit_hyperplane", [](const auto& p) {
    const auto r = fit_hyperplane(p);
    return digest(r.status, r.normal, r.constant, r.rms);
  });
  expect_same(pts, "fit_hyperplane_vertical", [](const auto& p) {
    const auto r = fit_hyperplane_vertical(p);
    return digest(r.status, r.coefficients, r.constant, r.rms);
  });
  expect_same(pts, "fit_gaussian", [](const auto& p) {
    const auto r = fit_gaussian(p);
    return digest(r.status, r.mean, r.covariance, r.box.center, r.box.extent, r.rms);
  });
  expect_same(pts, "fit_quadratic_curve", [](const auto& p) {
    const auto r = fit_quadratic_curve(p);
    const auto& c = r.curve;
    return digest(r.status, c.a, c.b, c.c, c.d, c.e, c.f, r.rms);
  });
  // The circle fits on points near a circle (the cloud has no meaningful circle).
  expect_same(poly, "fit_circle", [](const auto& p) {
    const auto r = fit_circle(p);
    return digest(r.status, r.circle.center, r.circle.radius, r.rms, r.iterations);
  });
  expect_same(poly, "fit_circle_algebraic", [](const auto& p) {
    const auto r = fit_circle_algebraic(p);
    return digest(r.status, r.circle.center, r.circle.radius, r.rms);
  });
  expect_same(poly, "fit_sphere", [](const auto& p) {
    const auto r = fit_sphere(p);
    return digest(r.status, r.sphere.center, r.sphere.radius, r.rms);
  });
  expect_same(poly, "fit_sphere_algebraic", [](const auto& p) {
    const auto r = fit_sphere_algebraic(p);
    return digest(r.status, r.sphere.center, r.sphere.radius, r.rms);
  });
}

TYPED_TEST(PointRange2Test, PolygonsPolylinesAndContainment) {
  using T = TypeParam;
  Forms<T, 2, kRing> poly(ring<T>());
  const Vec2<T> q{T(0.5), T(-0.25)};
  const Vec2<T> d{T(1), T(0.25)};

  expect_same(poly, "polygon measures", [](const auto& p) {
    return digest(polygon_signed_area(p), polygon_area(p), polygon_perimeter(p),
                  polygon_centroid(p), polygon_orientation(p), polygon_is_convex(p),
                  polygon_is_simple(p), polygon_self_intersection(p));
  });
  expect_same(poly, "polygon monotonicity", [&](const auto& p) {
    const MonotoneSplit s = polygon_monotone_split(p, d);
    return digest(s.monotone, s.min_vertex, s.max_vertex, polygon_is_monotone(p, d),
                  is_monotone_chain(p, d));
  });
  expect_same(poly, "polyline", [](const auto& p) {
    const std::vector<T> cum = cumulative_lengths(p, true);
    const Segment<T, 2> e = edge(p, 3);
    return digest(polyline_length(p, false), polyline_point_at(p, true, T(2.5)), cum,
                  polyline_point_at_arc_length(p, true, std::span<const T>(cum), T(1.5)), e.p0,
                  e.p1);
  });
  expect_same(poly, "containment", [&](const auto& p) {
    const PolygonLocator2 locator(p);
    return digest(classify_convex(q, p), contains_convex(p, q), classify_polygon(q, p),
                  winding_number(q, p), locator.status(), locator.classify(q));
  });
  expect_same(poly, "distance to polygon and polylines", [&](const auto& p) {
    const auto a = distance_to_convex_polygon(q, p);
    const auto b = distance_to_polyline(q, p, true);
    const auto c = distance_to_polyline(Segment<T, 2>{q, q + d}, p, false);
    const auto e = distance_to_polyline(Ray<T, 2>{q, d}, p, true);
    const auto f = distance_to_polyline(Line<T, 2>{q, d}, p, true);
    return digest(a.sqr_distance, a.closest, b.sqr_distance, b.closest, b.param_b, c.sqr_distance,
                  c.closest, e.sqr_distance, e.param_a, f.sqr_distance, f.closest);
  });
  expect_same(poly, "intersection with polygon and polylines", [&](const auto& p) {
    std::vector<double> out;
    const auto add = [&out](const PolylineIntersection2<T>& r) {
      out.push_back(double(static_cast<int>(r.status)));
      for (const auto& c : r.crossings)
        out.insert(out.end(), {double(c.count), double(c.edge), double(c.point[0].x),
                               double(c.point[0].y), double(c.param_a[0]), double(c.param_b[0])});
    };
    add(intersection(Line<T, 2>{q, d}, p, true));
    add(intersection(Ray<T, 2>{q, d}, p, false));
    add(intersection(Segment<T, 2>{q, q + d}, p, true));
    return digest(out);
  });
  expect_same(poly, "svg", [](const auto& p) {
    SvgWriter svg;
    svg.polyline(p);
    svg.polygon(p);
    return digest(svg.to_string());
  });
}

// The comparisons above are between real answers, not between failures.
TYPED_TEST(PointRange2Test, TheComparedResultsAreAnswers) {
  using T = TypeParam;
  const std::vector<Vec2<T>> p = cloud<T>(), r = ring<T>();
  EXPECT_EQ(convex_hull(p).dimension, 2);
  EXPECT_EQ(delaunay(p).dimension, 2);
  EXPECT_EQ(min_circle(p).status, Status::ok);
  EXPECT_EQ(min_rect(p).status, Status::ok);
  EXPECT_EQ(fit_line(p).status, Status::ok);
  EXPECT_EQ(fit_gaussian(p).status, Status::ok);
  EXPECT_EQ(fit_circle(r).status, Status::ok);
  EXPECT_EQ(fit_quadratic_curve(p).status, Status::ok);
  const std::array<std::uint32_t, 1> ring_ends = {static_cast<std::uint32_t>(kRing)};
  EXPECT_EQ(triangulate_polygon(r, ring_ends).triangle_count(), kRing - 2);
  EXPECT_GT(polygon_area(r), T(0));
  EXPECT_TRUE(polygon_is_convex(r));
}

}  // namespace
}  // namespace locus::api_test
