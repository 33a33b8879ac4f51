// SPDX-License-Identifier: BSL-1.0
#pragma once
// The perimeter, area, volume and surface-area formulas of the book's appendix C that are not
// already functions of a primitive; row formulas. The formulas themselves: docs/notes/measure.md.
//
// Already in primitives (use those): triangle, polygon, rectangle, box, circle, ellipse, sphere,
// ellipsoid, cylinder, cone, frustum of a cone, capsule, torus and tetrahedron measures are in
// their own headers; polygon areas in 3D and polyhedron volumes, centroids and inertia are in
// measure/area_volume.hpp and measure/inertia.hpp.
//
// Here, from scalar measurements (lengths, angles in radians, heights):
//  * triangles from side lengths: area (Heron, in Kahan's cancellation-free ordering), inradius,
//    circumradius;
//  * quadrilaterals from vertices: signed area in 2D, the vector area in 3D (any simple
//    quadrilateral, convex or not), perimeter, area centroid; trapezoid, parallelogram, and
//    Bretschneider's formula from the sides and two opposite angles;
//  * regular n-gon with side s: perimeter, area, inradius, circumradius;
//  * circle pieces (radius r, central angle theta): arc length, chord, sector and segment area
//    (a series for small theta, where the difference cancels), annulus;
//  * sphere pieces (radius r, height h): cap volume, cap / zone area, sector volume, segment
//    between parallel planes;
//  * prisms, pyramids and frusta of pyramids; Platonic solids of edge length a (volume, area).
// Degenerate and bad input: formulas are evaluated as written; negative or NaN measurements give
// NaN or a negative result as the arithmetic does, except where a square root or a division
// could fail: triangle_area_from_sides returns NaN for side lengths violating the triangle
// inequality, inradius/circumradius return 0 / inf for a degenerate triangle as K = 0 gives,
// regular-polygon functions return NaN for n < 3. Cost O(1), constexpr where no sqrt/trig.

#include <locus/core/angle.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/rescale.hpp>
#include <locus/primitives/polygon.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <utility>

namespace locus {

// ---- triangles from side lengths ---------------------------------------------------------------

/// Heron's area from the side lengths, in Kahan's stable form; NaN if they violate the
/// triangle inequality (or are negative / NaN).
namespace detail {
/// The power of two by which lengths up to m are scaled before products of four of them are
/// formed (1 when those stay in range; distance/detail/rescale.hpp): the formulas below run on
/// the scaled lengths and scale their result back exactly, so they are scale-covariant.
template <Real T>
[[nodiscard]] inline T formula_scale(T m) noexcept {
  return outside_product_range<T, 4>(m) ? normalising_scale(m) : T(1);
}
/// Heron's formula on sides sorted a >= b >= c (no scaling).
template <Real T>
[[nodiscard]] inline T heron(T a, T b, T c) noexcept {
  if (a < b) std::swap(a, b);
  if (b < c) std::swap(b, c);
  if (a < b) std::swap(a, b);
  // Sorted, sqrt((a+(b+c)) (c-(a-b)) (c+(a-b)) (a+(b-c))) / 4 loses nothing.
  const T f = (a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c));
  if (!(f >= T(0)) || !(c >= T(0))) return std::numeric_limits<T>::quiet_NaN();
  return T(0.25) * std::sqrt(f);
}
}  // namespace detail

template <Real T>
[[nodiscard]] inline T triangle_area_from_sides(T a, T b, T c) noexcept {
  const T s = detail::formula_scale(std::max({std::abs(a), std::abs(b), std::abs(c)}));
  return detail::heron(s * a, s * b, s * c) / s / s;
}

/// Inradius K / s from the side lengths.
template <Real T>
[[nodiscard]] inline T triangle_inradius(T a, T b, T c) noexcept {
  const T s = detail::formula_scale(std::max({std::abs(a), std::abs(b), std::abs(c)}));
  a *= s, b *= s, c *= s;
  return detail::heron(a, b, c) / (T(0.5) * (a + b + c)) / s;
}

/// Circumradius a b c / (4 K) from the side lengths (inf for a degenerate triangle).
template <Real T>
[[nodiscard]] inline T triangle_circumradius(T a, T b, T c) noexcept {
  const T s = detail::formula_scale(std::max({std::abs(a), std::abs(b), std::abs(c)}));
  a *= s, b *= s, c *= s;
  return a * b * c / (T(4) * detail::heron(a, b, c)) / s;
}

// ---- quadrilaterals ----------------------------------------------------------------------------

/// Signed area of the quadrilateral p0 p1 p2 p3 (half the cross product of its diagonals;
/// positive when counter-clockwise).
template <Real T>
[[nodiscard]] constexpr T quadrilateral_signed_area(const Vec2<T>& p0, const Vec2<T>& p1,
                                                    const Vec2<T>& p2, const Vec2<T>& p3) noexcept {
  return T(0.5) * perp_dot(p2 - p0, p3 - p1);
}

/// Area of a 2D quadrilateral.
template <Real T>
[[nodiscard]] inline T quadrilateral_area(const Vec2<T>& p0, const Vec2<T>& p1, const Vec2<T>& p2,
                                          const Vec2<T>& p3) noexcept {
  return std::abs(quadrilateral_signed_area(p0, p1, p2, p3));
}

/// Area of a planar 3D quadrilateral: |(p2 - p0) x (p3 - p1)| / 2.
template <Real T>
[[nodiscard]] inline T quadrilateral_area(const Vec3<T>& p0, const Vec3<T>& p1, const Vec3<T>& p2,
                                          const Vec3<T>& p3) noexcept {
  return T(0.5) * length(cross(p2 - p0, p3 - p1));
}

/// Perimeter |p1 - p0| + |p2 - p1| + |p3 - p2| + |p0 - p3|.
template <class T, int N>
[[nodiscard]] inline T quadrilateral_perimeter(const Vec<T, N>& p0, const Vec<T, N>& p1,
                                               const Vec<T, N>& p2, const Vec<T, N>& p3) noexcept {
  return length(p1 - p0) + length(p2 - p1) + length(p3 - p2) + length(p0 - p3);
}

/// Area centroid of a 2D quadrilateral (polygon_centroid of its four vertices).
template <Real T>
[[nodiscard]] inline Vec2<T> quadrilateral_centroid(const Vec2<T>& p0, const Vec2<T>& p1,
                                                    const Vec2<T>& p2, const Vec2<T>& p3) noexcept {
  // polygon_centroid forms products of three coordinates: on the vertices relative to p0,
  // scaled by a power of two when those could leave the range.
  const T s =
      detail::formula_scale(std::max({max_abs(p1 - p0), max_abs(p2 - p0), max_abs(p3 - p0)}));
  const Vec2<T> v[4] = {Vec2<T>{}, s * (p1 - p0), s * (p2 - p0), s * (p3 - p0)};
  return p0 + polygon_centroid(std::span<const Vec2<T>>(v, 4)) / s;
}

/// Trapezoid with parallel sides a, b and height h: (a + b) h / 2.
template <Real T>
[[nodiscard]] constexpr T trapezoid_area(T a, T b, T h) noexcept {
  return T(0.5) * (a + b) * h;
}

/// Parallelogram spanned by u and v: |u x v|.
template <Real T>
[[nodiscard]] inline T parallelogram_area(const Vec2<T>& u, const Vec2<T>& v) noexcept {
  return std::abs(perp_dot(u, v));
}
template <Real T>
[[nodiscard]] inline T parallelogram_area(const Vec3<T>& u, const Vec3<T>& v) noexcept {
  return length(cross(u, v));
}

/// Bretschneider: a convex quadrilateral with sides a, b, c, d (in order) and the interior
/// angles alpha (between d and a) and gamma (between b and c):
/// sqrt((s-a)(s-b)(s-c)(s-d) - a b c d cos^2((alpha + gamma) / 2)). NaN for impossible data.
template <Real T>
[[nodiscard]] inline T quadrilateral_area_bretschneider(T a, T b, T c, T d, T alpha,
                                                        T gamma) noexcept {
  // Products of four sides: on the sides scaled by a power of two q, scaled back by 1/q^2.
  const T q = detail::formula_scale(std::max({std::abs(a), std::abs(b), std::abs(c), std::abs(d)}));
  a *= q, b *= q, c *= q, d *= q;
  const T s = T(0.5) * (a + b + c + d);
  const T k = std::cos(T(0.5) * (alpha + gamma));
  const T f = (s - a) * (s - b) * (s - c) * (s - d) - a * b * c * d * k * k;
  if (!(f >= T(0)))
    return f > -eps_v<T> * s * s * s * s ? T(0) : std::numeric_limits<T>::quiet_NaN();
  return std::sqrt(f) / q / q;
}

// ---- regular polygons
// ----------------------------------------------------------------------------

/// Perimeter n s of a regular n-gon with side s.
template <Real T>
[[nodiscard]] inline T regular_polygon_perimeter(int n, T s) noexcept {
  return n < 3 ? std::numeric_limits<T>::quiet_NaN() : static_cast<T>(n) * s;
}

/// Area n s^2 / (4 tan(pi / n)).
template <Real T>
[[nodiscard]] inline T regular_polygon_area(int n, T s) noexcept {
  if (n < 3) return std::numeric_limits<T>::quiet_NaN();
  return static_cast<T>(n) * s * s / (T(4) * std::tan(pi_v<T> / static_cast<T>(n)));
}

/// Inradius (apothem) s / (2 tan(pi / n)).
template <Real T>
[[nodiscard]] inline T regular_polygon_inradius(int n, T s) noexcept {
  if (n < 3) return std::numeric_limits<T>::quiet_NaN();
  return s / (T(2) * std::tan(pi_v<T> / static_cast<T>(n)));
}

/// Circumradius s / (2 sin(pi / n)).
template <Real T>
[[nodiscard]] inline T regular_polygon_circumradius(int n, T s) noexcept {
  if (n < 3) return std::numeric_limits<T>::quiet_NaN();
  return s / (T(2) * std::sin(pi_v<T> / static_cast<T>(n)));
}

// ---- circle pieces
// ---------------------------------------------------------------------------------

// Arc length r theta: arc_length in core/angle.hpp.

/// Chord length 2 r sin(theta / 2).
template <Real T>
[[nodiscard]] inline T chord_length(T r, T theta) noexcept {
  return T(2) * r * std::sin(T(0.5) * theta);
}

/// Sector area r^2 theta / 2.
template <Real T>
[[nodiscard]] constexpr T circular_sector_area(T r, T theta) noexcept {
  return T(0.5) * r * r * theta;
}

/// Segment area (between the chord and the arc) r^2 (theta - sin theta) / 2.
template <Real T>
[[nodiscard]] inline T circular_segment_area(T r, T theta) noexcept {
  // theta - sin theta = theta^3/6 - theta^5/120 + theta^7/5040 - ...: the series avoids the
  // cancellation for small angles (its truncation error is below eps there).
  T d;
  if (std::abs(theta) < T(0.5)) {
    const T t2 = theta * theta;
    d = theta * t2 *
        (T(1) / T(6) -
         t2 * (T(1) / T(120) - t2 * (T(1) / T(5040) - t2 * (T(1) / T(362880) - t2 / T(39916800)))));
  } else {
    d = theta - std::sin(theta);
  }
  return T(0.5) * r * r * d;
}

/// Annulus pi (R^2 - r^2) = pi (R - r)(R + r).
template <Real T>
[[nodiscard]] constexpr T annulus_area(T outer, T inner) noexcept {
  return pi_v<T> * (outer - inner) * (outer + inner);
}

// ---- sphere pieces
// --------------------------------------------------------------------------------

/// Spherical cap of height h on a sphere of radius r: pi h^2 (3 r - h) / 3.
template <Real T>
[[nodiscard]] constexpr T spherical_cap_volume(T r, T h) noexcept {
  return pi_v<T> * h * h * (T(3) * r - h) / T(3);
}

/// Curved area of a cap or zone of height h: 2 pi r h.
template <Real T>
[[nodiscard]] constexpr T spherical_zone_area(T r, T h) noexcept {
  return T(2) * pi_v<T> * r * h;
}

/// Spherical sector (cone to the centre plus the cap of height h): 2 pi r^2 h / 3.
template <Real T>
[[nodiscard]] constexpr T spherical_sector_volume(T r, T h) noexcept {
  return T(2) * pi_v<T> * r * r * h / T(3);
}

/// Spherical segment between parallel planes: base radii a, b, height h:
/// pi h (3 a^2 + 3 b^2 + h^2) / 6.
template <Real T>
[[nodiscard]] constexpr T spherical_segment_volume(T a, T b, T h) noexcept {
  return pi_v<T> * h * (T(3) * a * a + T(3) * b * b + h * h) / T(6);
}

// ---- prisms and pyramids
// -----------------------------------------------------------------------------

/// Prism with base area B and height h: B h.
template <Real T>
[[nodiscard]] constexpr T prism_volume(T base_area, T h) noexcept {
  return base_area * h;
}

/// Pyramid (or cone) with base area B and height h: B h / 3.
template <Real T>
[[nodiscard]] constexpr T pyramid_volume(T base_area, T h) noexcept {
  return base_area * h / T(3);
}

/// Frustum of a pyramid with parallel base areas B1, B2 and height h: h (B1 + B2 + sqrt(B1 B2))
/// / 3.
template <Real T>
[[nodiscard]] inline T pyramid_frustum_volume(T b1, T b2, T h) noexcept {
  // sqrt(B1) sqrt(B2), not sqrt(B1 B2): the product of two areas overflows long before the
  // volume does.
  return h * (b1 + b2 + std::sqrt(b1) * std::sqrt(b2)) / T(3);
}

// ---- Platonic solids
// ---------------------------------------------------------------------------------

/// The five Platonic solids.
enum class PlatonicSolid : unsigned char {
  tetrahedron,
  cube,
  octahedron,
  dodecahedron,
  icosahedron
};

/// Volume of the Platonic solid with edge length a.
template <Real T>
[[nodiscard]] inline T platonic_volume(PlatonicSolid solid, T a) noexcept {
  const T a3 = a * a * a;
  switch (solid) {
    case PlatonicSolid::tetrahedron:
      return a3 / (T(6) * std::sqrt(T(2)));
    case PlatonicSolid::cube:
      return a3;
    case PlatonicSolid::octahedron:
      return std::sqrt(T(2)) / T(3) * a3;
    case PlatonicSolid::dodecahedron:
      return (T(15) + T(7) * std::sqrt(T(5))) / T(4) * a3;
    case PlatonicSolid::icosahedron:
      return T(5) * (T(3) + std::sqrt(T(5))) / T(12) * a3;
  }
  return std::numeric_limits<T>::quiet_NaN();
}

/// Surface area of the Platonic solid with edge length a.
template <Real T>
[[nodiscard]] inline T platonic_surface_area(PlatonicSolid solid, T a) noexcept {
  const T a2 = a * a;
  switch (solid) {
    case PlatonicSolid::tetrahedron:
      return std::sqrt(T(3)) * a2;
    case PlatonicSolid::cube:
      return T(6) * a2;
    case PlatonicSolid::octahedron:
      return T(2) * std::sqrt(T(3)) * a2;
    case PlatonicSolid::dodecahedron:
      return T(3) * std::sqrt(T(25) + T(10) * std::sqrt(T(5))) * a2;
    case PlatonicSolid::icosahedron:
      return T(5) * std::sqrt(T(3)) * a2;
  }
  return std::numeric_limits<T>::quiet_NaN();
}

}  // namespace locus
