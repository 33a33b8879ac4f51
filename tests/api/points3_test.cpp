// SPDX-License-Identifier: BSL-1.0
// The API rule for bulk 3D input (docs/notes/api.md): every algorithm and bulk query taking
// points accepts std::vector, std::array, C arrays, std::span (const or not, any extent) and a
// flat coordinate array through point_span<3>(xyz, n), in float and double, without spelling the
// scalar type; and every form gives the same result. A new algorithm is added here: if it breaks
// the rule this file stops compiling.
#include "forms.hpp"

#include <locus/bounding/min_box3.hpp>
#include <locus/bounding/min_sphere.hpp>
#include <locus/containment/point_in_polyhedron.hpp>
#include <locus/delaunay/delaunay3.hpp>
#include <locus/distance/batch.hpp>
#include <locus/distance/point_mesh.hpp>
#include <locus/distance/point_polyhedron.hpp>
#include <locus/distance/point_polyline.hpp>
#include <locus/fit/gaussian_fit.hpp>
#include <locus/fit/line_fit.hpp>
#include <locus/fit/plane_fit.hpp>
#include <locus/fit/quadratic_fit.hpp>
#include <locus/fit/sphere_fit.hpp>
#include <locus/hull/hull3.hpp>
#include <locus/io/svg.hpp>
#include <locus/measure/area_volume.hpp>
#include <locus/measure/inertia.hpp>
#include <locus/primitives/aligned_box.hpp>
#include <locus/primitives/planar_polygon.hpp>
#include <locus/primitives/plane.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace locus::api_test {
namespace {

constexpr std::size_t kCloud = 40;  // generic points
constexpr std::size_t kRing = 10;   // a planar convex polygon, tilted

template <class T>
std::vector<Vec3<T>> cloud() {
  Lcg g(0x3d5eedu);
  std::vector<Vec3<T>> v;
  for (std::size_t i = 0; i < kCloud; ++i)
    v.push_back({static_cast<T>(g.next()), static_cast<T>(g.next()), static_cast<T>(g.next())});
  return v;
}

template <class T>
std::vector<Vec3<T>> ring() {
  std::vector<Vec3<T>> v;
  for (std::size_t i = 0; i < kRing; ++i) {
    const double a = 6.283185307179586 * static_cast<double>(i) / static_cast<double>(kRing);
    const double x = 2.0 * std::cos(a), y = std::sin(a);
    v.push_back({static_cast<T>(x), static_cast<T>(y), static_cast<T>(0.5 * x - 0.25 * y + 1.0)});
  }
  return v;
}

template <class T>
class PointRange3Test : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(PointRange3Test, Scalars);

TYPED_TEST(PointRange3Test, HullsAndTriangulations) {
  using T = TypeParam;
  Forms<T, 3, kCloud> pts(cloud<T>());
  const Vec3<T> q{T(0.125), T(-0.0625), T(0.25)};

  expect_same(pts, "convex_hull", [](const auto& p) {
    const Hull3Result r = convex_hull(p);
    return digest(r.status, r.dimension, r.triangles, r.adjacency, r.vertices);
  });
  expect_same(pts, "ConvexHull3::compute", [](const auto& p) {
    ConvexHull3<T> h;
    const Hull3Result r = h.compute(p);
    return digest(r.status, r.dimension, r.triangles);
  });
  expect_same(pts, "delaunay", [](const auto& p) {
    const Delaunay3Result r = delaunay(p);
    return digest(r.status, r.dimension, r.tetrahedra, r.adjacency, r.hull);
  });
  expect_same(pts, "locate and nearest_vertex", [&](const auto& p) {
    const Delaunay3Result dt = delaunay(p);
    const Locate3Result r = locate(dt, p, q);
    const NearestVertex3Result n = nearest_vertex(dt, p, q);
    return digest(r.status, r.location, r.tetrahedron, r.face, n.status, n.vertex);
  });
}

TYPED_TEST(PointRange3Test, BoundingAndFitting) {
  using T = TypeParam;
  Forms<T, 3, kCloud> pts(cloud<T>());
  Forms<T, 3, kRing> poly(ring<T>());

  expect_same(pts, "min_sphere", [](const auto& p) {
    const auto r = min_sphere(p);
    return digest(r.status, r.sphere.center, r.sphere.radius, r.support);
  });
  expect_same(pts, "min_box", [](const auto& p) {
    const auto r = min_box(p);
    return digest(r.status, r.box.center, r.box.axis, r.box.extent, r.volume);
  });
  expect_same(pts, "bounding_box", [](const auto& p) {
    const auto b = bounding_box(p);
    return digest(b.min, b.max);
  });
  expect_same(pts, "fit_line", [](const auto& p) {
    const auto r = fit_line(p);
    return digest(r.status, r.line.origin, r.line.direction, r.rms);
  });
  expect_same(pts, "fit_plane", [](const auto& p) {
    const auto r = fit_plane(p);
    return digest(r.status, r.plane.normal, r.plane.constant, r.rms);
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
  expect_same(pts, "fit_quadric", [](const auto& p) {
    const auto r = fit_quadric(p);
    return digest(r.status, r.quadric.a, r.quadric.b, r.quadric.c, r.rms);
  });
  expect_same(pts, "fit_sphere", [](const auto& p) {
    const auto r = fit_sphere(p);
    return digest(r.status, r.sphere.center, r.sphere.radius, r.rms, r.iterations);
  });
  expect_same(pts, "fit_sphere_algebraic", [](const auto& p) {
    const auto r = fit_sphere_algebraic(p);
    return digest(r.status, r.sphere.center, r.sphere.radius, r.rms);
  });
  expect_same(poly, "newell and planar polygons", [](const auto& p) {
    const auto plane = best_fit_plane_newell(p);
    const auto pp = planar_polygon(p);
    Digest d = digest(newell_normal(p), plane.has_value(), pp.has_value());
    if (plane) put(d, digest(plane->normal, plane->constant));
    if (pp) put(d, digest(pp->frame.origin, pp->frame.normal, pp->polygon.vertices));
    return d;
  });
}

TYPED_TEST(PointRange3Test, MeshesMeasuresContainmentAndDistance) {
  using T = TypeParam;
  Forms<T, 3, kCloud> pts(cloud<T>());
  Forms<T, 3, kRing> poly(ring<T>());
  const Hull3Result hull = convex_hull(pts.vec);
  ASSERT_EQ(hull.status, Status::ok);
  const std::vector<std::array<std::uint32_t, 3>>& tris = hull.triangles;
  const Vec3<T> q{T(0.125), T(-0.0625), T(0.25)};
  const Vec3<T> far{T(3), T(-2), T(1)};

  expect_same(poly, "planar polygon measures", [](const auto& p) {
    return digest(polygon_vector_area(p), polygon_area(p), polygon_centroid(p));
  });
  expect_same(pts, "mesh measures", [&](const auto& p) {
    const auto m = mass_properties(p, tris);
    return digest(mesh_signed_volume(p, tris), mesh_volume(p, tris), mesh_surface_area(p, tris),
                  m.status, m.volume, m.centroid, m.inertia);
  });
  expect_same(pts, "mesh containment", [&](const auto& p) {
    return digest(classify(q, p, tris), classify(far, p, tris), contains(p, tris, q),
                  classify_convex(q, p, tris), classify_convex(far, p, tris));
  });
  expect_same(pts, "mesh distance", [&](const auto& p) {
    const MeshDistanceTree tree(p, tris);
    const auto a = tree.nearest(far);
    const auto b = distance_to_mesh(far, p, tris);
    const auto c = distance_to_convex_polyhedron(far, p, tris);
    return digest(tree.status(), a.sqr_distance, a.closest, a.param_b.triangle, b.sqr_distance,
                  b.closest, c.sqr_distance, c.closest);
  });
  expect_same(poly, "distance to a polyline", [&](const auto& p) {
    const auto r = distance_to_polyline(far, p, true);
    return digest(r.sqr_distance, r.closest, r.param_b);
  });
  expect_same(pts, "batch distances", [&](const auto& p) {
    const Triangle3<T> t{{T(0), T(0), T(0)}, {T(1), T(0), T(0.5)}, {T(0), T(1), T(-0.5)}};
    std::vector<T> out(kCloud);
    sqr_distances(p, t, out);
    return digest(out);
  });
  expect_same(poly, "svg", [](const auto& p) {
    SvgWriter svg;
    svg.polyline(p);
    return digest(svg.to_string());
  });
}

// The comparisons above are between real answers, not between failures.
TYPED_TEST(PointRange3Test, TheComparedResultsAreAnswers) {
  using T = TypeParam;
  const std::vector<Vec3<T>> p = cloud<T>(), r = ring<T>();
  const Hull3Result hull = convex_hull(p);
  EXPECT_EQ(hull.dimension, 3);
  EXPECT_EQ(delaunay(p).dimension, 3);
  EXPECT_EQ(min_sphere(p).status, Status::ok);
  EXPECT_EQ(min_box(p).status, Status::ok);
  EXPECT_EQ(fit_plane(p).status, Status::ok);
  EXPECT_EQ(fit_sphere(p).status, Status::ok);
  EXPECT_EQ(fit_quadric(p).status, Status::ok);
  EXPECT_TRUE(planar_polygon(r).has_value());
  EXPECT_GT(mesh_volume(p, hull.triangles), T(0));
  EXPECT_EQ(MeshDistanceTree(p, hull.triangles).status(), Status::ok);
}

}  // namespace
}  // namespace locus::api_test
