// SPDX-License-Identifier: BSL-1.0
#pragma once
// draw(svg, primitive, style): thin conveniences that draw locus primitives with an SvgWriter
// (io/svg.hpp; no CAPABILITIES row, used by the gallery and the command-line tool).
//
// 2D primitives are drawn exactly where SVG has the element (segments, lines and rays clipped to
// the view, circles, rotated ellipses, circular arcs, polygons and polygons with holes as one
// even-odd path); an elliptical arc is sampled
// (64 pieces per full turn, at least 8). 3D primitives are drawn through the writer's camera as
// wireframes: segments, triangles, polylines, boxes (12 edges), tetrahedra (6 edges) and
// circles (sampled, 64 pieces).
//
// Conventions: each primitive's own parametrisation (see its header): Line/Ray origin +
// t direction, Arc2 counter-clockwise from start by sweep, Ellipse2 center + extent[i] axis[i].
// Degenerate input is passed to the writer, which skips what cannot be drawn (a zero direction,
// a non-finite coordinate, a negative radius); a negative arc sweep draws nothing.
// Cost: O(size of the primitive); the writer stores a copy.

#include <locus/core/vec.hpp>
#include <locus/io/svg.hpp>
#include <locus/primitives/aligned_box.hpp>
#include <locus/primitives/arc.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/ellipse.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/oriented_box.hpp>
#include <locus/primitives/polygon.hpp>
#include <locus/primitives/polyline.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/rectangle.hpp>
#include <locus/primitives/segment.hpp>
#include <locus/primitives/tetrahedron.hpp>
#include <locus/primitives/triangle.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace locus {

namespace detail {
// The 12 edges of a box whose 8 corners are indexed by bits (x, y, z).
template <Real T>
void svg_box_edges(SvgWriter& w, const std::array<Vec3<T>, 8>& c, const SvgStyle& s) {
  for (std::size_t i = 0; i < 8; ++i)
    for (std::size_t bit : {std::size_t{1}, std::size_t{2}, std::size_t{4}})
      if (!(i & bit)) w.segment(c[i], c[i | bit], s);
}
template <Real T>
int svg_arc_pieces(T sweep) {
  const double n = std::ceil(64.0 * std::abs(static_cast<double>(sweep)) / (2.0 * pi_v<double>));
  return n < 8.0 ? 8 : (n > 4096.0 ? 4096 : static_cast<int>(n));
}
}  // namespace detail

/// A segment (2D, or 3D through the camera).
template <Real T, int N>
void draw(SvgWriter& w, const Segment<T, N>& s, const SvgStyle& style = {}) {
  w.segment(s.p0, s.p1, style);
}
/// A 2D line, clipped to the view.
template <Real T>
void draw(SvgWriter& w, const Line2<T>& l, const SvgStyle& style = {}) {
  w.line(l.origin, l.direction, style);
}
/// A 2D ray, clipped to the view.
template <Real T>
void draw(SvgWriter& w, const Ray<T, 2>& r, const SvgStyle& style = {}) {
  w.ray(r.origin, r.direction, style);
}
/// A triangle outline (filled when style.fill is set).
template <Real T, int N>
void draw(SvgWriter& w, const Triangle<T, N>& t, const SvgStyle& style = {}) {
  const std::array<Vec<T, N>, 3> v{t.v0, t.v1, t.v2};
  w.polyline(v, style, true);
}
/// A rectangle (symmetric or corner form).
template <Real T, int N>
void draw(SvgWriter& w, const Rectangle<T, N>& r, const SvgStyle& style = {}) {
  w.polyline(corners(r), style, true);
}
template <Real T, int N>
void draw(SvgWriter& w, const CornerRectangle<T, N>& r, const SvgStyle& style = {}) {
  w.polyline(corners(r), style, true);
}
/// A polyline, open or closed as it says.
template <Real T, int N>
void draw(SvgWriter& w, const Polyline<T, N>& p, const SvgStyle& style = {}) {
  w.polyline(p.vertices, style, p.closed);
}
/// A polygon (filled with the even-odd rule when style.fill is set).
template <Real T>
void draw(SvgWriter& w, const Polygon2<T>& p, const SvgStyle& style = {}) {
  w.polygon(p.vertices, style);
}
/// A polygon with holes: one even-odd path, so the holes stay empty.
template <Real T>
void draw(SvgWriter& w, const PolygonWithHoles2<T>& p, const SvgStyle& style = {}) {
  std::vector<std::vector<Vec2<T>>> holes;
  for (const Polygon2<T>& h : p.holes) holes.push_back(h.vertices);
  w.polygon(p.outer.vertices, holes, style);
}
/// A 2D circle.
template <Real T>
void draw(SvgWriter& w, const Circle2<T>& c, const SvgStyle& style = {}) {
  w.circle(c.center, c.radius, style);
}
/// A circular arc, counter-clockwise from start by sweep.
template <Real T>
void draw(SvgWriter& w, const Arc2<T>& a, const SvgStyle& style = {}) {
  if (!(a.sweep > T(0))) return;
  w.arc(a.circle.center, a.circle.radius, a.start, a.start + a.sweep, style);
}
/// A 2D ellipse.
template <Real T>
void draw(SvgWriter& w, const Ellipse2<T>& e, const SvgStyle& style = {}) {
  w.ellipse(e.center, e.axis[0], e.extent[0], e.extent[1], style);
}
/// An elliptical arc, sampled with locus::point_at.
template <Real T>
void draw(SvgWriter& w, const EllipseArc2<T>& a, const SvgStyle& style = {}) {
  if (!(a.sweep > T(0)) || !is_finite(a.start) || !is_finite(a.sweep)) return;
  const int n = detail::svg_arc_pieces(a.sweep);
  std::vector<Vec2<T>> pts;
  pts.reserve(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i)
    pts.push_back(point_at(a, a.start + a.sweep * (static_cast<T>(i) / static_cast<T>(n))));
  w.polyline(pts, style);
}
/// A 3D circle through the camera, sampled with locus::point_at.
template <Real T>
void draw(SvgWriter& w, const Circle3<T>& c, const SvgStyle& style = {}) {
  std::vector<Vec3<T>> pts;
  for (int i = 0; i < 64; ++i)
    pts.push_back(point_at(c, T(2) * pi_v<T> * static_cast<T>(i) / T(64)));
  w.polyline(pts, style, true);
}
/// An axis-aligned rectangle (2D) or the 12 edges of a box (3D).
template <Real T>
void draw(SvgWriter& w, const AlignedBox<T, 2>& b, const SvgStyle& style = {}) {
  const auto c = corners(b);
  const std::array<Vec2<T>, 4> ring{c[0], c[1], c[3], c[2]};
  w.polyline(ring, style, true);
}
template <Real T>
void draw(SvgWriter& w, const AlignedBox<T, 3>& b, const SvgStyle& style = {}) {
  detail::svg_box_edges(w, corners(b), style);
}
/// An oriented rectangle (2D) or the 12 edges of an oriented box (3D).
template <Real T>
void draw(SvgWriter& w, const OrientedBox<T, 2>& b, const SvgStyle& style = {}) {
  const auto c = corners(b);
  const std::array<Vec2<T>, 4> ring{c[0], c[1], c[3], c[2]};
  w.polyline(ring, style, true);
}
template <Real T>
void draw(SvgWriter& w, const OrientedBox<T, 3>& b, const SvgStyle& style = {}) {
  detail::svg_box_edges(w, corners(b), style);
}
/// The six edges of a tetrahedron.
template <Real T>
void draw(SvgWriter& w, const Tetrahedron3<T>& t, const SvgStyle& style = {}) {
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) w.segment(t.v[i], t.v[j], style);
}

}  // namespace locus
