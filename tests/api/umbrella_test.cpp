// SPDX-License-Identifier: BSL-1.0
// The umbrella headers: <locus/locus.hpp> and one per area compile together in one unit (no
// clash between areas, e.g. two structs of one name) and give the areas' entry points.
#include <locus/boolean.hpp>
#include <locus/bounding.hpp>
#include <locus/bsp.hpp>
#include <locus/construct.hpp>
#include <locus/containment.hpp>
#include <locus/core.hpp>
#include <locus/curves.hpp>
#include <locus/delaunay.hpp>
#include <locus/distance.hpp>
#include <locus/fit.hpp>
#include <locus/hull.hpp>
#include <locus/intersection.hpp>
#include <locus/io.hpp>
#include <locus/locus.hpp>
#include <locus/measure.hpp>
#include <locus/mesh.hpp>
#include <locus/numeric.hpp>
#include <locus/primitives.hpp>
#include <locus/spatial.hpp>
#include <locus/triangulate.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace {

TEST(Umbrella, EveryAreaIsReachableThroughItsUmbrella) {
  using namespace locus;
  const std::vector<Vec2d> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.25}};
  EXPECT_EQ(orient2d(square[0], square[1], square[2]), Sign::positive);  // core
  EXPECT_EQ(convex_hull(square).status, Status::ok);                     // hull
  EXPECT_EQ(delaunay(square).status, Status::ok);                        // delaunay
  const auto circle = min_circle(square);                                // bounding
  EXPECT_EQ(circle.status, Status::ok);
  EXPECT_NEAR(circle.circle.radius, 0.7071067811865476, 1e-15);
  const Segment<double, 2> seg{{0, 2}, {1, 2}};
  EXPECT_DOUBLE_EQ(distance(Vec2d{0, 0}, seg).distance, 2.0);  // distance, primitives
  EXPECT_EQ(intersection(seg, Segment<double, 2>{{0.5, 0}, {0.5, 3}}).point[0],
            (Vec2d{0.5, 2}));                                         // intersection
  const auto roots = real_roots(Polynomial<double>{-2.0, 0.0, 1.0});  // numeric
  ASSERT_EQ(roots.roots.size(), 2u);
  EXPECT_DOUBLE_EQ(roots.roots[1].value * roots.roots[1].value, 2.0);
  const std::vector<Vec2d> quad(square.begin(), square.begin() + 4);
  const std::array<std::uint32_t, 1> ring_ends{4};
  const PolygonTriangulation tri = triangulate_ear_clipping(quad, ring_ends);  // triangulate
  EXPECT_EQ(tri.status, Status::ok);
  EXPECT_EQ(tri.triangles.size(), 2u);
  PolygonMesh<double> mesh;  // mesh
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const std::array<std::uint32_t, 4> face{0, 1, 2, 3};
  add_face(mesh, std::span<const std::uint32_t>(face));
  EXPECT_EQ(fan_triangles(mesh).size(), 2u);
  // boolean: two unit squares overlapping in a 1 x 1/2 strip unite into one 1 x 3/2 rectangle.
  const Polygon2<double> lower{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  const Polygon2<double> upper{{{0, 0.5}, {1, 0.5}, {1, 1.5}, {0, 1.5}}};
  const auto united = boolean_union(lower, upper);
  EXPECT_EQ(united.status, Status::ok);
  ASSERT_EQ(united.polygons.size(), 1u);
  EXPECT_TRUE(united.polygons[0].holes.empty());
  EXPECT_EQ(united.polygons[0].outer.vertices.size(), 4u);
}

}  // namespace
