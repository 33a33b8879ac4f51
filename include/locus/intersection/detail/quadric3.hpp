// SPDX-License-Identifier: BSL-1.0
#pragma once
// Engine of the 3D linear-component pairs against curved surfaces (rows int3.linear-quadric and
// int3.torus): sphere, ellipsoid, general quadric, cylinder, cone, capsule, torus. Internal:
// include a pair header. Everything is computed in double (float input is promoted exactly) and
// compiled once in src/intersection/quadric3.cpp and torus.cpp. A component is
// detail::linear3::Lin (o + t d, t >= 0 if lo, t <= 1 if hi, a segment keeps p1 exactly).
// Derivations: docs/notes/intersection3.md, "Linear components and quadrics", "Torus".

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/intersection/detail/linear3.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/capsule.hpp>
#include <locus/primitives/cone.hpp>
#include <locus/primitives/cylinder.hpp>
#include <locus/primitives/ellipsoid.hpp>
#include <locus/primitives/quadric.hpp>
#include <locus/primitives/sphere.hpp>
#include <locus/primitives/torus.hpp>

#include <array>

namespace locus {

/// Hits of a linear component on a surface: up to four points (a torus; two for the convex
/// solids, four for a finite double cone), by increasing component parameter, each with the
/// outward unit normal of the surface and its multiplicity (2 at a tangency). When the whole
/// component lies on the surface the kind is line, ray or segment (count 2: two of its points).
template <Real T, class PA, class PB>
struct SurfaceHits3 : Intersection<T, 3, PA, PB, 4> {
  std::array<Vec3<T>, 4> normal{};    ///< outward unit normal at point[i] (zero if undefined)
  std::array<int, 4> multiplicity{};  ///< 1 at a crossing, 2 at a tangency (or more: torus)
};

/// The result of intersection() of a Line3, Ray3 or Segment3 with a curved surface: param_a the
/// component's t, param_b the surface's point_at parameters (see each pair header).
template <Real T>
using LinearSurfaceIntersection3 = SurfaceHits3<T, T, Vec2<T>>;

template <Real T, class PA, class PB>
[[nodiscard]] constexpr SurfaceHits3<T, PB, PA> swapped(const SurfaceHits3<T, PA, PB>& r) noexcept {
  SurfaceHits3<T, PB, PA> s;
  s.kind = r.kind;
  s.count = r.count;
  s.point = r.point;
  s.param_a = r.param_b;
  s.param_b = r.param_a;
  s.normal = r.normal;
  s.multiplicity = r.multiplicity;
  return s;
}

namespace detail::quadric3 {

using V = Vec3<double>;
using Lin = linear3::Lin;
using R = SurfaceHits3<double, double, Vec2<double>>;

struct SphereD {
  V c;
  double r;
};
struct QuadricD {
  double a[3][3];  ///< symmetric (the upper triangle is read)
  V b;
  double c;
};
struct EllipsoidD {
  V c, u[3], e;
};
struct CylinderD {
  V c, a;
  double r, h;  ///< h = +inf: infinite
};
struct ConeD {
  V v, a;
  double angle, hmin, hmax;
};
struct CapsuleD {
  V p0, p1;
  double r;
};
struct TorusD {
  V c, n;
  double big, small;
};

template <Real T>
[[nodiscard]] constexpr SphereD as_d(const Sphere3<T>& s) noexcept {
  return {vec_cast<double>(s.center), double(s.radius)};
}
template <Real T>
[[nodiscard]] constexpr QuadricD as_d(const Quadric3<T>& q) noexcept {
  QuadricD k{};
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) k.a[i][j] = k.a[j][i] = double(q.a.a[i][j]);
  k.b = vec_cast<double>(q.b);
  k.c = double(q.c);
  return k;
}
template <Real T>
[[nodiscard]] constexpr EllipsoidD as_d(const Ellipsoid3<T>& e) noexcept {
  return {vec_cast<double>(e.center),
          {vec_cast<double>(e.axis[0]), vec_cast<double>(e.axis[1]), vec_cast<double>(e.axis[2])},
          vec_cast<double>(e.extent)};
}
template <Real T>
[[nodiscard]] constexpr CylinderD as_d(const Cylinder3<T>& c) noexcept {
  return {vec_cast<double>(c.axis.origin), vec_cast<double>(c.axis.direction), double(c.radius),
          double(c.height)};
}
template <Real T>
[[nodiscard]] constexpr ConeD as_d(const Cone3<T>& c) noexcept {
  return {vec_cast<double>(c.vertex), vec_cast<double>(c.axis), double(c.angle),
          double(c.min_height), double(c.max_height)};
}
template <Real T>
[[nodiscard]] constexpr CapsuleD as_d(const Capsule3<T>& c) noexcept {
  return {vec_cast<double>(c.segment.p0), vec_cast<double>(c.segment.p1), double(c.radius)};
}
template <Real T>
[[nodiscard]] constexpr TorusD as_d(const Torus3<T>& t) noexcept {
  return {vec_cast<double>(t.center), vec_cast<double>(t.normal), double(t.major_radius),
          double(t.minor_radius)};
}

// Compiled in src/intersection/quadric3.cpp and torus.cpp.
[[nodiscard]] R hits(const Lin& l, const SphereD& s) noexcept;
[[nodiscard]] R hits(const Lin& l, const QuadricD& q) noexcept;
[[nodiscard]] R hits(const Lin& l, const EllipsoidD& e) noexcept;
[[nodiscard]] R hits(const Lin& l, const CylinderD& c) noexcept;
[[nodiscard]] R hits(const Lin& l, const ConeD& c) noexcept;
[[nodiscard]] R hits(const Lin& l, const CapsuleD& c) noexcept;
[[nodiscard]] R hits(const Lin& l, const TorusD& t) noexcept;

/// The result in T (rounded once more for float).
template <Real T>
[[nodiscard]] constexpr LinearSurfaceIntersection3<T> cast(const R& r) noexcept {
  LinearSurfaceIntersection3<T> s;
  s.kind = r.kind;
  s.count = r.count;
  for (std::size_t i = 0; i < 4; ++i) {
    s.point[i] = vec_cast<T>(r.point[i]);
    s.param_a[i] = static_cast<T>(r.param_a[i]);
    s.param_b[i] = vec_cast<T>(r.param_b[i]);
    s.normal[i] = vec_cast<T>(r.normal[i]);
    s.multiplicity[i] = r.multiplicity[i];
  }
  return s;
}

/// intersection(component, shape) for any of the shapes above.
template <Real T, class Comp, class Shape>
[[nodiscard]] inline LinearSurfaceIntersection3<T> find(const Comp& a, const Shape& b) noexcept {
  return cast<T>(hits(linear3::as_lin(a), as_d(b)));
}

}  // namespace detail::quadric3
}  // namespace locus
