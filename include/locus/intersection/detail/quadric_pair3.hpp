// SPDX-License-Identifier: BSL-1.0
#pragma once
// Engine of the sphere-sphere and ellipsoid-ellipsoid pairs (row int3.surface-surface, book
// section 11.8 / 11.5 quadric pairs). Internal: include sphere_sphere.hpp or
// ellipsoid_ellipsoid.hpp. Computed in double, compiled once in src/intersection/quadric_pair3.cpp.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/result.hpp>
#include <locus/intersection/result.hpp>

namespace locus {

/// The intersection of two spheres (surfaces): kind empty, point (tangent: point[0], count 1),
/// circle (count 3: three points of it) or coincident (equal spheres, count 0); plus the circle
/// itself: its center, unit normal (from the first center toward the second) and radius (0 for a
/// tangent point, whose position is then center).
template <Real T>
struct SphereSphereIntersection : Intersection<T, 3, NoParam, NoParam, 3> {
  Vec3<T> center{};
  Vec3<T> normal{};
  T radius = T(0);
};

namespace detail::quadric_pair3 {

using V = Vec3<double>;

// Compiled in src/intersection/quadric_pair3.cpp.
[[nodiscard]] SphereSphereIntersection<double> sphere_sphere(const V& c0, double r0, const V& c1,
                                                             double r1) noexcept;
[[nodiscard]] RegionRelation sphere_relation(const V& c0, double r0, const V& c1,
                                             double r1) noexcept;
/// Ellipsoids as center, three axes and extents: the exact relation of the quadrics as stored
/// (src/intersection/ellipsoid_relation.cpp). certificates false skips the cheap exact
/// certificates and always runs the root-structure decision (for the tests: both must agree).
[[nodiscard]] RegionRelation ellipsoid_relation(const V& c0, const V (&a0)[3], const V& e0,
                                                const V& c1, const V (&a1)[3], const V& e1,
                                                bool certificates = true) noexcept;
/// The former floating-point method (secular equation, axes normalized, extremes within
/// rel_tol of zero taken as zero); kept as a second algorithm for the tests.
[[nodiscard]] RegionRelation ellipsoid_relation_numeric(const V& c0, const V (&a0)[3], const V& e0,
                                                        const V& c1, const V (&a1)[3], const V& e1,
                                                        double rel_tol) noexcept;

template <Real T>
[[nodiscard]] SphereSphereIntersection<T> cast(const SphereSphereIntersection<double>& r) noexcept {
  SphereSphereIntersection<T> o;
  o.kind = r.kind;
  o.count = r.count;
  for (std::size_t i = 0; i < 3; ++i) o.point[i] = vec_cast<T>(r.point[i]);
  o.center = vec_cast<T>(r.center);
  o.normal = vec_cast<T>(r.normal);
  o.radius = static_cast<T>(r.radius);
  return o;
}

}  // namespace detail::quadric_pair3
}  // namespace locus
