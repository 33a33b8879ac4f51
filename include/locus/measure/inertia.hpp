// SPDX-License-Identifier: BSL-1.0
#pragma once
// Mass properties (mass, volume, centroid, inertia tensor) of a solid bounded by a closed
// triangle mesh, and of a 2D polygon; row cg.measure; book appendix C (centroids) and D. Eberly,
// "Polyhedral Mass Properties (Revisited)" (2002), in the equivalent tetrahedral form of the
// divergence theorem (the integrals: docs/notes/measure.md).
//
// Solid: (vertices, triangles) spans, triangle {i, j, k} with normal (vj - vi) x (vk - vi)
// pointing OUT (for an inward mesh all integrals flip sign together: the centroid is the same
// and the reported volume, mass and inertia are those of the solid). With density rho:
// mass = rho V, the centroid, and the inertia tensor about the centroid
// I = rho (trace(S_c) Id - S_c), S_c the second moment about the centroid, i.e.
// I_xx = rho int (y^2 + z^2), I_xy = -rho int x y (the standard, positive-definite tensor).
// Accumulated in compute_t<T> (double for float), relative to the centre of the bounding box.
//
// 2D: mass_properties(polygon) gives area (signed area's absolute value), centroid and the
// second-moment tensor about the centroid [int x^2, int xy; int xy, int y^2] (x, y relative to
// the centroid) and the polar moment int (x^2 + y^2), by the shoelace-style edge sums.
// Helpers: inertia_about(I, mass, centroid, q) moves the tensor to another point (parallel
// axis theorem); rotate_inertia(I, R) = R I R^T is the tensor of the rotated solid.
//
// Status: empty_input (no triangle / fewer than 3 vertices), invalid_input (an index out of
// range: nothing is computed), non_finite_input (a non-finite coordinate or density),
// degenerate_input (zero volume or area: mass 0, centroid = vertex average, inertia 0); ok
// otherwise. Closedness is not checked (containment/point_in_polyhedron.hpp is_closed_mesh); an
// open mesh gives values that depend on the reference point. Cost O(n), no allocation.

#include <locus/core/mat.hpp>
#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/polygon.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

namespace locus {

/// Mass properties of a solid: mass = density * volume, inertia about the centroid.
template <Real T>
struct MassProperties3 {
  Status status = Status::empty_input;
  T volume{};
  T mass{};
  Vec3<T> centroid{};
  Mat3<T> inertia{};
};

/// Area properties of a polygon: second moments about the centroid, polar = trace.
template <Real T>
struct MassProperties2 {
  Status status = Status::empty_input;
  T area{};
  T mass{};
  Vec2<T> centroid{};
  Mat2<T>
      second_moment{};  ///< [int x^2, int xy; int xy, int y^2] about the centroid, times density
  T polar_moment{};     ///< int (x^2 + y^2) about the centroid, times density
};

/// Mass properties of the solid bounded by a closed triangle mesh with outward normals.
template <Real T>
[[nodiscard]] inline MassProperties3<T> mass_properties(
    std::span<const Vec3<T>> v, std::span<const std::array<std::uint32_t, 3>> tris,
    T density = T(1)) noexcept {
  using C = compute_t<T>;
  MassProperties3<T> out{Status::ok, T(0), T(0), Vec3<T>{}, Mat3<T>{}};
  if (tris.empty() || v.size() < 3) {
    out.status = Status::empty_input;
    return out;
  }
  bool any_bad = false;
  Vec3<C> lo = vec_cast<C>(v[0]), hi = lo, mean{};
  for (const Vec3<T>& x : v) {
    if (!is_finite(x)) any_bad = true;
    const Vec3<C> xc = vec_cast<C>(x);
    mean += xc;
    for (int k = 0; k < 3; ++k) {
      lo[k] = xc[k] < lo[k] ? xc[k] : lo[k];
      hi[k] = xc[k] > hi[k] ? xc[k] : hi[k];
    }
  }
  if (any_bad || !is_finite(density)) {
    out.status = Status::non_finite_input;
    return out;
  }
  for (const auto& t : tris)
    if (t[0] >= v.size() || t[1] >= v.size() || t[2] >= v.size()) {
      out.status = Status::invalid_input;
      return out;
    }
  const Vec3<C> r = C(0.5) * lo + C(0.5) * hi;
  C vol6 = C(0);  // 6 V
  Vec3<C> m1{};   // 24 M1
  Mat3<C> s{};    // 120 S
  for (const auto& t : tris) {
    const Vec3<C> a = vec_cast<C>(v[t[0]]) - r, b = vec_cast<C>(v[t[1]]) - r,
                  c = vec_cast<C>(v[t[2]]) - r;
    const C d = dot(a, cross(b, c));
    const Vec3<C> sum = a + b + c;
    vol6 += d;
    m1 += d * sum;
    s = s + d * (outer(a, a) + outer(b, b) + outer(c, c) + outer(sum, sum));
  }
  const C volume = vol6 / C(6);
  if (!(volume != C(0)) || !is_finite(volume)) {
    out.status = is_finite(volume) ? Status::degenerate_input : Status::non_finite_input;
    out.centroid = vec_cast<T>(mean / static_cast<C>(v.size()));
    return out;
  }
  const Vec3<C> dcen = m1 / (C(4) * vol6);  // M1 / V = (sum d s / 24) / (sum d / 6)
  Mat3<C> sc = (C(1) / C(120)) * s - volume * outer(dcen, dcen);
  // An inward mesh flips every integral; report the solid's (positive) values.
  C sign = C(1);
  if (volume < C(0)) {
    sign = C(-1);
    sc = C(-1) * sc;
  }
  const C rho = static_cast<C>(density);
  const Mat3<C> inertia = rho * (trace(sc) * Mat3<C>::identity() - sc);
  out.volume = static_cast<T>(sign * volume);
  out.mass = static_cast<T>(rho * sign * volume);
  out.centroid = vec_cast<T>(r + dcen);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out.inertia(i, j) = static_cast<T>(inertia(i, j));
  return out;
}

/// The same for any point range (core/point_range.hpp).
template <PointRange3 R>
[[nodiscard]] inline MassProperties3<range_scalar_t<R>> mass_properties(
    const R& v, std::span<const std::array<std::uint32_t, 3>> tris,
    range_scalar_t<R> density = range_scalar_t<R>(1)) noexcept {
  return mass_properties(point_span(v), tris, density);
}

/// Area, centroid and second moments of a polygon (either orientation) with density rho.
template <Real T>
[[nodiscard]] inline MassProperties2<T> mass_properties(const Polygon2<T>& poly,
                                                        T density = T(1)) noexcept {
  using C = compute_t<T>;
  MassProperties2<T> out{Status::ok, T(0), T(0), Vec2<T>{}, Mat2<T>{}, T(0)};
  const auto& p = poly.vertices;
  if (p.size() < 3) {
    out.status = Status::empty_input;
    return out;
  }
  if (!detail::all_finite(std::span<const Vec2<T>>(p)) || !is_finite(density)) {
    out.status = Status::non_finite_input;
    return out;
  }
  const Vec2<C> o = vec_cast<C>(p[0]);
  C a2 = C(0), xx = C(0), yy = C(0), xy = C(0);
  Vec2<C> m{};
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2<C> u = vec_cast<C>(p[i]) - o, w = vec_cast<C>(p[(i + 1) % p.size()]) - o;
    const C c = u.x * w.y - w.x * u.y;  // twice the signed area of (0, u, w)
    a2 += c;
    m += c * (u + w);
    xx += c * (u.x * u.x + u.x * w.x + w.x * w.x);
    yy += c * (u.y * u.y + u.y * w.y + w.y * w.y);
    xy += c * (C(2) * u.x * u.y + u.x * w.y + w.x * u.y + C(2) * w.x * w.y);
  }
  const C area = a2 / C(2);
  if (!(area != C(0))) {
    out.status = Status::degenerate_input;
    out.centroid = polygon_centroid(std::span<const Vec2<T>>(p));
    return out;
  }
  const Vec2<C> d = m / (C(3) * a2);
  // Integrals relative to p[0], then moved to the centroid (parallel axis).
  C ixx = xx / C(12) - area * d.x * d.x, iyy = yy / C(12) - area * d.y * d.y;
  C ixy = xy / C(24) - area * d.x * d.y;
  C sign = C(1);
  if (area < C(0)) sign = C(-1);
  const C rho = static_cast<C>(density) * sign;
  ixx *= rho;
  iyy *= rho;
  ixy *= rho;
  out.area = static_cast<T>(sign * area);
  out.mass = static_cast<T>(rho * area);
  out.centroid = vec_cast<T>(o + d);
  out.second_moment(0, 0) = static_cast<T>(ixx);
  out.second_moment(1, 1) = static_cast<T>(iyy);
  out.second_moment(0, 1) = out.second_moment(1, 0) = static_cast<T>(ixy);
  out.polar_moment = static_cast<T>(ixx + iyy);
  return out;
}

/// Parallel-axis theorem: the inertia tensor about point q of a body with the given mass,
/// centroid and inertia about the centroid.
template <Real T>
[[nodiscard]] constexpr Mat3<T> inertia_about(const Mat3<T>& inertia_at_centroid, T mass,
                                              const Vec3<T>& centroid, const Vec3<T>& q) noexcept {
  const Vec3<T> d = centroid - q;
  return inertia_at_centroid + mass * (dot(d, d) * Mat3<T>::identity() - outer(d, d));
}

/// The inertia tensor of the body rotated by R (orthogonal): R I R^T.
template <Real T>
[[nodiscard]] constexpr Mat3<T> rotate_inertia(const Mat3<T>& inertia, const Mat3<T>& r) noexcept {
  return r * inertia * transpose(r);
}

}  // namespace locus
