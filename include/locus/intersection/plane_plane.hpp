// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of two planes and of three planes in 3D: intersects() and intersection(); row
// int3.planes, book sections 11.4-11.5 (figures 11.23, 11.24 and the table of configurations of
// three planes). Three planes live here too: one place for "planes meeting planes".
// Plane3 {normal, constant} is { X : dot(normal, X) = constant }, taken as given (rounded data,
// not normalised). Result (PlanesIntersection<T> = Intersection<T, 3, NoParam, NoParam, 3>):
//   two planes: line (count 2: a point p and p + u, u = n0 x n1), empty (parallel, distinct)
//   or plane (coincident; count 3: three points of it, the third off the line of the first two);
//   three planes: point (count 1), line (count 2), plane (count 3) or empty.
// Exact decisions by ranks of the data as given: rank of the normals (parallel: every component
// of n0 x n1 is exactly 0 (turn2d); three normals independent: the exact sign of det[n0; n1;
// n2] (orient3d)) and of the augmented rows (n, constant) (consistent: every 2x2 or 3x3 minor
// with the constants is exactly 0, by exact_sum / orient3d). The book's table of three planes
// falls out: rank 3: a point; rank 2 consistent: a line (three planes of a pencil, or two
// coincident and one crossing); rank 1 consistent: all coincident (a plane); inconsistent:
// empty (parallel distinct planes, or three lines of a prism).
// Constructed points: the line point p = (c0 (n1 x u) + c1 (u x n0)) / |u|^2 and the point of
// three planes by Cramer's rule, evaluated in double after a power-of-two rescaling of each
// plane (float input in double); their residuals |dot(n_i, p) - c_i| are a few eps of
// |n_i| |p| + |c_i| divided by the sine of the angle between the planes.
// Degenerate: a plane with a zero normal has no points (empty); NaN/Inf input gives empty.
// Cost: a few exact-sign filters and about 60 flops; no allocation.

#include <locus/core/exact_sum.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/result.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/plane.hpp>

#include <cmath>
#include <cstddef>

namespace locus {

/// The result of intersection() of two or three planes (see the header comment).
template <Real T>
using PlanesIntersection = Intersection<T, 3, NoParam, NoParam, 3>;

namespace detail::planes {

using V = Vec3<double>;
/// A plane as given (n, c: the exact decisions) and rescaled by a power of two so that its
/// largest normal component is in [1/2, 1) (sn, sc: the constructions; products stay in range).
struct P {
  V n;
  double c;
  V sn;
  double sc;
};

template <Real T>
[[nodiscard]] inline P as_plane(const Plane3<T>& p) noexcept {
  const V n = vec_cast<double>(p.normal);
  const double c = double(p.constant);
  int e = 0;
  (void)std::frexp(max_abs(n), &e);
  return {n, c, std::ldexp(1.0, -e) * n, std::ldexp(c, -e)};
}
[[nodiscard]] inline bool valid(const P& p) noexcept {
  return is_finite(p.n) && std::isfinite(p.c) && !(p.n == V{});
}

/// n0 x n1 == 0 exactly (turn2d on each coordinate pair: det[n0.ij; n1.ij]).
[[nodiscard]] inline bool parallel(const V& a, const V& b) noexcept {
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    if (turn2d(Vec2<double>{}, Vec2<double>{a[i], a[j]}, Vec2<double>{},
               Vec2<double>{b[i], b[j]}) != Sign::zero)
      return false;
  }
  return true;
}
/// For parallel normals: the constants are consistent (c0 n1 == c1 n0 exactly).
[[nodiscard]] inline bool same_plane(const P& a, const P& b) noexcept {
  for (int k = 0; k < 3; ++k) {
    const ExactMonomial m[2] = {{1, 0, 2, {a.c, b.n[k], 0, 0}}, {-1, 0, 2, {b.c, a.n[k], 0, 0}}};
    if (exact_sign_of_sum(m) != 0) return false;
  }
  return true;
}

using R = Intersection<double, 3, NoParam, NoParam, 3>;

[[nodiscard]] inline R plane_of(const P& a) noexcept {
  R r;
  r.kind = Kind::plane;
  r.count = 3;
  const double nn = dot(a.sn, a.sn);
  const V p = (a.sc / nn) * a.sn;
  int k = 0;  // the axis of the smallest normal component: e_k x n is not small
  for (int i = 1; i < 3; ++i)
    if (std::abs(a.sn[i]) < std::abs(a.sn[k])) k = i;
  V e{};
  e[k] = 1.0;
  const V u = cross(e, a.sn), v = cross(a.sn, u);
  const double su = 1.0 / std::sqrt(dot(u, u)), sv = 1.0 / std::sqrt(dot(v, v));
  r.point = {p, p + su * u, p + sv * v};
  return r;
}

[[nodiscard]] inline R line_of(const P& a, const P& b) noexcept {
  R r;
  r.kind = Kind::line;
  r.count = 2;
  const V u = cross(a.sn, b.sn);
  const V p = (a.sc * cross(b.sn, u) + b.sc * cross(u, a.sn)) / dot(u, u);
  r.point[0] = p;
  r.point[1] = p + u / std::sqrt(dot(u, u));
  return r;
}

[[nodiscard]] inline R two(const P& a, const P& b) noexcept {
  if (!valid(a) || !valid(b)) return {};
  if (!parallel(a.n, b.n)) return line_of(a, b);
  return same_plane(a, b) ? plane_of(a) : R{};
}

[[nodiscard]] inline R three(const P& a, const P& b, const P& c) noexcept {
  if (!valid(a) || !valid(b) || !valid(c)) return {};
  const Sign det = orient3d(V{}, a.n, b.n, c.n);
  if (det != Sign::zero) {
    R r;
    r.kind = Kind::point;
    r.count = 1;
    const V bc = cross(b.sn, c.sn), ca = cross(c.sn, a.sn), ab = cross(a.sn, b.sn);
    r.point[0] = (a.sc * bc + b.sc * ca + c.sc * ab) / dot(a.sn, bc);
    return r;
  }
  const P* pl[3] = {&a, &b, &c};
  // Rank 2: some pair of normals is independent; consistent iff the three 3x3 minors with the
  // constants vanish (rows (n_i, n_j, c) of the three planes, orient3d about the origin).
  for (int s = 0; s < 3; ++s) {
    const P& x = *pl[s];
    const P& y = *pl[(s + 1) % 3];
    if (parallel(x.n, y.n)) continue;
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      const V r0{a.n[i], a.n[j], a.c}, r1{b.n[i], b.n[j], b.c}, r2{c.n[i], c.n[j], c.c};
      if (orient3d(V{}, r0, r1, r2) != Sign::zero) return {};
    }
    return line_of(x, y);
  }
  // Rank 1: all normals parallel; consistent iff every pair is the same plane.
  if (same_plane(a, b) && same_plane(a, c)) return plane_of(a);
  return {};
}

}  // namespace detail::planes

/// Whether two planes meet (exact: not parallel, or coincident).
template <Real T>
[[nodiscard]] inline bool intersects(const Plane3<T>& a, const Plane3<T>& b) noexcept {
  namespace d = detail::planes;
  const d::P p = d::as_plane(a), q = d::as_plane(b);
  if (!d::valid(p) || !d::valid(q)) return false;
  return !d::parallel(p.n, q.n) || d::same_plane(p, q);
}

/// The common set of two planes: line, plane or empty (see the header comment).
template <Real T>
[[nodiscard]] inline PlanesIntersection<T> intersection(const Plane3<T>& a,
                                                        const Plane3<T>& b) noexcept {
  namespace d = detail::planes;
  return intersection_cast<T>(d::two(d::as_plane(a), d::as_plane(b)));
}

/// Whether three planes have a common point (exact).
template <Real T>
[[nodiscard]] inline bool intersects(const Plane3<T>& a, const Plane3<T>& b,
                                     const Plane3<T>& c) noexcept {
  namespace d = detail::planes;
  return d::three(d::as_plane(a), d::as_plane(b), d::as_plane(c)).kind != Kind::empty;
}

/// The common set of three planes: point, line, plane or empty (see the header comment).
template <Real T>
[[nodiscard]] inline PlanesIntersection<T> intersection(const Plane3<T>& a, const Plane3<T>& b,
                                                        const Plane3<T>& c) noexcept {
  namespace d = detail::planes;
  return intersection_cast<T>(d::three(d::as_plane(a), d::as_plane(b), d::as_plane(c)));
}

}  // namespace locus
