// SPDX-License-Identifier: BSL-1.0
// Tests of io/svg_primitives.hpp: each primitive's own parametrisation reaches the document
// correctly. Checked against independent facts about the shape (areas by the shoelace formula,
// arc end points from cos/sin, points of an elliptical arc on the implicit ellipse, projected
// circle radius), never against the writer's own output for the same call.

#include <locus/io/svg_primitives.hpp>

#include "io/svg_xml.hpp"
#include "support/typed.hpp"

#include <cmath>
#include <vector>

namespace {

using namespace svg_test;
using locus::SvgStyle;
using locus::SvgWriter;
using locus::Vec2;
using locus::Vec3;
using locus::Vec3d;
using locus_test::Rng;

template <class T>
class SvgPrimitives : public ::testing::Test {};
TYPED_TEST_SUITE(SvgPrimitives, locus_test::RealTypes);

// Shoelace area of a pixel ring mapped back to the world (signed: counter-clockwise > 0).
double world_area(const Model& md, const std::vector<Vec2d>& px) {
  double a = 0;
  for (std::size_t i = 0; i < px.size(); ++i) {
    const Vec2d p = md.world(px[i]), q = md.world(px[(i + 1) % px.size()]);
    a += p.x * q.y - p.y * q.x;
  }
  return a / 2;
}

TYPED_TEST(SvgPrimitives, BoxesAndRectanglesAreRingsWithTheRightArea) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const Vec2d lo{-10, -10}, hi{10, 10};
  locus::SvgOptions o;
  o.background = "none";
  const Model md(lo, hi, o);
  for (int rep = 0; rep < 30; ++rep) {
    const Vec2<T> c = rng.vec<T, 2>(T(-3), T(3));
    const Vec2<T> u = rng.unit<T, 2>();
    const Vec2<T> e{static_cast<T>(rng.uniform(0.5, 4.0)), static_cast<T>(rng.uniform(0.5, 4.0))};
    SvgWriter w(o);
    w.set_view(lo, hi);
    const locus::AlignedBox<T, 2> ab{c - e, c + e};
    const locus::OrientedBox<T, 2> ob{c, {u, locus::perp(u)}, e};
    const locus::Rectangle<T, 2> rect{c, {u, locus::perp(u)}, {e.x, e.y}};
    const locus::CornerRectangle<T, 2> cr{c, e.x * u, e.y * locus::perp(u)};
    draw(w, ab);
    draw(w, ob);
    draw(w, rect);
    draw(w, cr);
    const Node root = parse_or_fail(w.to_string());
    const auto polys = elements(root, "polygon");
    ASSERT_EQ(polys.size(), 4u);
    // A bow-tie (wrong corner order) would have area 0.
    const double box_area = 4.0 * static_cast<double>(e.x) * static_cast<double>(e.y);
    const double tol = 1e-3 / md.s * 40;  // printed rounding times the perimeter scale
    EXPECT_NEAR(std::abs(world_area(md, point_list(polys[0]->at("points")))), box_area, tol);
    EXPECT_NEAR(std::abs(world_area(md, point_list(polys[1]->at("points")))), box_area, tol);
    EXPECT_NEAR(std::abs(world_area(md, point_list(polys[2]->at("points")))), box_area, tol);
    EXPECT_NEAR(std::abs(world_area(md, point_list(polys[3]->at("points")))), box_area / 4, tol);
  }
}

TYPED_TEST(SvgPrimitives, ArcsEndWhereTheirAnglesSay) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const Vec2d lo{-10, -10}, hi{10, 10};
  locus::SvgOptions o;
  o.background = "none";
  const Model md(lo, hi, o);
  for (int rep = 0; rep < 30; ++rep) {
    const locus::Circle2<T> circ{rng.vec<T, 2>(T(-2), T(2)), static_cast<T>(rng.uniform(1.0, 5.0))};
    const T start = static_cast<T>(rng.uniform(-4.0, 4.0));
    const T sweep = static_cast<T>(rng.uniform(0.2, 6.0));
    SvgWriter w(o);
    w.set_view(lo, hi);
    draw(w, locus::Arc2<T>{circ, start, sweep});
    draw(w, locus::Arc2<T>{circ, start, T(-1)});  // negative sweep: nothing
    const Node root = parse_or_fail(w.to_string());
    const auto paths = elements(root, "path");
    ASSERT_EQ(paths.size(), 1u);
    const auto cmds = parse_path(paths[0]->at("d"));
    ASSERT_EQ(cmds.size(), 2u);
    const double cx = static_cast<double>(circ.center.x), cy = static_cast<double>(circ.center.y);
    const double r = static_cast<double>(circ.radius), a0 = static_cast<double>(start);
    const double a1 = a0 + static_cast<double>(sweep);
    const Vec2d p0 = md.px({cx + r * std::cos(a0), cy + r * std::sin(a0)});
    const Vec2d p1 = md.px({cx + r * std::cos(a1), cy + r * std::sin(a1)});
    const double tol = kPx + 1e-4 * md.s * r;  // float angles: a few ulps of the angle sum
    EXPECT_NEAR(cmds[0].v.at(0), p0.x, tol);
    EXPECT_NEAR(cmds[0].v.at(1), p0.y, tol);
    EXPECT_NEAR(cmds[1].v.at(5), p1.x, tol);
    EXPECT_NEAR(cmds[1].v.at(6), p1.y, tol);
    EXPECT_EQ(cmds[1].v.at(3), static_cast<double>(sweep) > kPi ? 1.0 : 0.0);  // large-arc flag
  }
}

TYPED_TEST(SvgPrimitives, EllipticalArcSamplesLieOnTheEllipse) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const Vec2d lo{-10, -10}, hi{10, 10};
  locus::SvgOptions o;
  o.background = "none";
  const Model md(lo, hi, o);
  for (int rep = 0; rep < 20; ++rep) {
    const Vec2<T> u = rng.unit<T, 2>();
    const locus::Ellipse2<T> e{
        rng.vec<T, 2>(T(-2), T(2)),
        {u, locus::perp(u)},
        {static_cast<T>(rng.uniform(1.0, 5.0)), static_cast<T>(rng.uniform(1.0, 5.0))}};
    const T start = static_cast<T>(rng.uniform(-3.0, 3.0)),
            sweep = static_cast<T>(rng.uniform(0.3, 6.2));
    SvgWriter w(o);
    w.set_view(lo, hi);
    draw(w, locus::EllipseArc2<T>{e, start, sweep});
    const Node root = parse_or_fail(w.to_string());
    const auto pl = elements(root, "polyline");
    ASSERT_EQ(pl.size(), 1u);
    const auto pts = point_list(pl[0]->at("points"));
    ASSERT_GE(pts.size(), 9u);
    const Vec2d c = locus::vec_cast<double>(e.center), ud = locus::vec_cast<double>(u);
    const double e0 = static_cast<double>(e.extent[0]), e1 = static_cast<double>(e.extent[1]);
    for (const Vec2d& q : pts) {
      const Vec2d d = md.world(q) - c;
      const double s = locus::dot(d, ud) / e0, t = locus::perp_dot(ud, d) / e1;
      EXPECT_NEAR(s * s + t * t, 1.0, 2e-3);  // printed rounding (1e-3 px) over radii >= 24 px
    }
    // First and last samples are the arc's ends.
    const double a0 = static_cast<double>(start), a1 = a0 + static_cast<double>(sweep);
    const Vec2d s0 = c + e0 * std::cos(a0) * ud + e1 * std::sin(a0) * locus::perp(ud);
    const Vec2d s1 = c + e0 * std::cos(a1) * ud + e1 * std::sin(a1) * locus::perp(ud);
    EXPECT_NEAR(md.world(pts.front()).x, s0.x, 1e-3);
    EXPECT_NEAR(md.world(pts.front()).y, s0.y, 1e-3);
    EXPECT_NEAR(md.world(pts.back()).x, s1.x, 1e-3);
    EXPECT_NEAR(md.world(pts.back()).y, s1.y, 1e-3);
  }
}

TYPED_TEST(SvgPrimitives, PolygonsWithHolesKeepTheirRings) {
  using T = TypeParam;
  const Vec2d lo{-10, -10}, hi{10, 10};
  locus::SvgOptions o;
  o.background = "none";
  const Model md(lo, hi, o);
  SvgWriter w(o);
  w.set_view(lo, hi);
  const locus::Polygon2<T> outer{{{-4, -4}, {4, -4}, {4, 4}, {-4, 4}}};
  const locus::Polygon2<T> hole{{{-1, -1}, {-1, 2}, {2, 2}, {2, -1}}};
  draw(w, locus::PolygonWithHoles2<T>{outer, {hole}}, SvgStyle{});
  draw(w, outer);
  const Node root = parse_or_fail(w.to_string());
  const auto paths = elements(root, "path");
  ASSERT_EQ(paths.size(), 2u);
  EXPECT_EQ(paths[0]->at("fill-rule"), "evenodd");
  // Ring areas by the shoelace formula: 64 and 9 (the hole is clockwise).
  std::vector<std::vector<Vec2d>> rings;
  for (const PathCmd& cmd : parse_path(paths[0]->at("d"))) {
    if (cmd.op == 'M') rings.emplace_back();
    if (cmd.op == 'M' || cmd.op == 'L') rings.back().push_back({cmd.v.at(0), cmd.v.at(1)});
  }
  ASSERT_EQ(rings.size(), 2u);
  EXPECT_NEAR(world_area(md, rings[0]), 64.0, 1e-3);
  EXPECT_NEAR(world_area(md, rings[1]), -9.0, 1e-3);
}

TYPED_TEST(SvgPrimitives, ThreeDimensionalWireframes) {
  using T = TypeParam;
  locus::SvgOptions o;
  o.background = "none";
  SvgWriter w(o);
  locus::SvgCamera cam;  // orthographic, looking down -z: the image is the (x, y) shadow
  cam.eye = {0, 0, 10};
  w.set_camera(cam);
  const Vec2d lo{-5, -5}, hi{5, 5};
  w.set_view(lo, hi);
  const Model md(lo, hi, o);
  draw(w, locus::AlignedBox<T, 3>{{-1, -1, -1}, {1, 2, 3}});
  draw(w, locus::Tetrahedron3<T>{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}});
  const locus::Circle3<T> circ{{T(0.5), T(-0.5), T(1)}, {0, 0, 1}, T(2)};
  draw(w, circ);
  draw(w, locus::Segment<T, 3>{{0, 0, 0}, {1, 1, 1}});
  const Node root = parse_or_fail(w.to_string());
  EXPECT_EQ(elements(root, "line").size(), 12u + 6u + 1u);
  const auto ring = elements(root, "polygon");
  ASSERT_EQ(ring.size(), 1u);
  const auto pts = point_list(ring[0]->at("points"));
  EXPECT_EQ(pts.size(), 64u);
  for (const Vec2d& q : pts) {
    const Vec2d p = md.world(q);
    EXPECT_NEAR(std::hypot(p.x - 0.5, p.y + 0.5), 2.0, 1e-3);
  }
}

TYPED_TEST(SvgPrimitives, LinesRaysTrianglesPolylinesCircles) {
  using T = TypeParam;
  SvgWriter w;
  w.set_view(Vec2d{-5, -5}, Vec2d{5, 5});
  draw(w, locus::Line<T, 2>{{0, 0}, {1, 1}});
  draw(w, locus::Ray<T, 2>{{0, 0}, {1, 0}});
  draw(w, locus::Segment<T, 2>{{0, 0}, {1, 3}});
  draw(w, locus::Triangle<T, 2>{{0, 0}, {1, 0}, {0, 1}});
  draw(w, locus::Polyline<T, 2>{{{0, 0}, {1, 1}, {2, 0}}, false});
  draw(w, locus::Polyline<T, 2>{{{0, 0}, {1, 1}, {2, 0}}, true});
  draw(w, locus::Circle2<T>{{0, 0}, T(2)});
  draw(w, locus::Ellipse2<T>{{0, 0}, {Vec2<T>{1, 0}, Vec2<T>{0, 1}}, {T(2), T(1)}});
  const Node root = parse_or_fail(w.to_string());
  EXPECT_EQ(elements(root, "line").size(), 3u);
  EXPECT_EQ(elements(root, "polygon").size(), 2u);
  EXPECT_EQ(elements(root, "polyline").size(), 1u);
  EXPECT_EQ(elements(root, "circle").size(), 1u);
  EXPECT_EQ(elements(root, "ellipse").size(), 1u);
}

}  // namespace
