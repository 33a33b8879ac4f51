// SPDX-License-Identifier: BSL-1.0
#pragma once
// Support mappings of convex shapes: the input of GJK and EPA (distance/gjk.hpp); rows dist2.gjk
// and dist3.gjk; book section 6.10 (figure 6.25's support point).
//
// support(shape, d) returns a point X of the (solid) shape maximising dot(X, d). Any convex
// shape with such a function can be given to gjk_distance() and penetration(): the concept
// SupportMapped<S> asks for support(s, d) (found by argument-dependent lookup) and for
// SupportSpace<S> (member aliases `scalar_type` and `static constexpr int dimension`, or a
// specialisation of locus::SupportSpace).
//
// Shapes provided (T = float or double, N = 2 or 3 where it applies): Vec<T, N> (a point),
// Segment<T, N>, Triangle<T, N> (filled), ConvexPoints<T, N> (the hull of a span of points;
// interior points and duplicates cost only time), Sphere<T, N>, Circle2<T> (disk),
// AlignedBox<T, N>, OrientedBox<T, N>, Capsule<T, N>, Cylinder3<T> (finite), Cone3<T> (finite,
// also truncated; a double cone maps its convex hull), and Transformed<S>: any of these under
// x -> rotation * x + translation (rotation orthonormal, not checked), grown by `margin` >= 0.
// Ties (a face or an edge facing d) are broken deterministically. For d = 0 the result is some
// point of the shape.
//
// Margins: balls, capsules and Transformed margins are "core + ball of radius r"; GJK and EPA run
// on the cores and add the radii afterwards (exact, finitely many steps; van den Bergen, JGT
// 1999, section 5). detail::core_support / core_margin implement that split; support() itself
// always maps the whole shape.
// Degenerate input: zero radius, extent or length are fine (lower-dimensional shapes). An empty
// ConvexPoints, an infinite cylinder or cone, and NaN/Inf coordinates make support() return
// non-finite coordinates (GJK: Status::non_finite_input). Cost: O(1), O(n) for ConvexPoints.

#include <locus/core/mat.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/aligned_box.hpp>
#include <locus/primitives/capsule.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/cone.hpp>
#include <locus/primitives/cylinder.hpp>
#include <locus/primitives/oriented_box.hpp>
#include <locus/primitives/segment.hpp>
#include <locus/primitives/sphere.hpp>
#include <locus/primitives/triangle.hpp>

#include <cmath>
#include <concepts>
#include <cstddef>
#include <limits>
#include <span>

namespace locus {

/// The convex hull of a set of points, given by the points (not owned).
template <class T, int N>
struct ConvexPoints {
  std::span<const Vec<T, N>> points;
};

/// A shape under the rigid motion x -> rotation * x + translation, grown by margin >= 0.
template <class Shape, class T, int N>
struct Transformed {
  Shape shape;
  Mat<T, N, N> rotation = Mat<T, N, N>::identity();
  Vec<T, N> translation{};
  T margin = T(0);
};

/// Scalar type and dimension of a support-mapped shape (specialised below for locus shapes).
template <class S>
struct SupportSpace {
  using scalar = typename S::scalar_type;
  static constexpr int dimension = S::dimension;
};
template <class T, int N>
struct SupportSpace<Vec<T, N>> {
  using scalar = T;
  static constexpr int dimension = N;
};
template <class T, int N>
struct SupportSpace<Segment<T, N>> : SupportSpace<Vec<T, N>> {};
template <class T, int N>
struct SupportSpace<Triangle<T, N>> : SupportSpace<Vec<T, N>> {};
template <class T, int N>
struct SupportSpace<ConvexPoints<T, N>> : SupportSpace<Vec<T, N>> {};
template <class T, int N>
struct SupportSpace<Sphere<T, N>> : SupportSpace<Vec<T, N>> {};
template <Real T>
struct SupportSpace<Circle2<T>> : SupportSpace<Vec<T, 2>> {};
template <class T, int N>
struct SupportSpace<AlignedBox<T, N>> : SupportSpace<Vec<T, N>> {};
template <class T, int N>
struct SupportSpace<OrientedBox<T, N>> : SupportSpace<Vec<T, N>> {};
template <class T, int N>
struct SupportSpace<Capsule<T, N>> : SupportSpace<Vec<T, N>> {};
template <Real T>
struct SupportSpace<Cylinder3<T>> : SupportSpace<Vec<T, 3>> {};
template <Real T>
struct SupportSpace<Cone3<T>> : SupportSpace<Vec<T, 3>> {};
template <class S, class T, int N>
struct SupportSpace<Transformed<S, T, N>> : SupportSpace<Vec<T, N>> {};

template <class S>
using support_scalar_t = typename SupportSpace<S>::scalar;
template <class S>
inline constexpr int support_dimension_v = SupportSpace<S>::dimension;

namespace detail {

/// d / |d| scaled by r; the zero vector for d = 0 (any point of the ball is then a support).
template <class T, int N>
[[nodiscard]] inline Vec<T, N> ball_support(const Vec<T, N>& d, T r) noexcept {
  const T len = length(d);
  if (!(len > T(0))) return Vec<T, N>{};
  return (r / len) * d;
}

/// The point of the disk {|x| <= r, x perpendicular to unit axis} farthest along d: r times
/// the unit component of d orthogonal to the axis. When d is parallel to the axis up to
/// rounding, that component is noise (not even orthogonal to the axis), so the disk's center
/// (also a support point then) is returned.
template <Real T>
[[nodiscard]] inline Vec3<T> disk_support(const Vec3<T>& axis, const Vec3<T>& d, T r) noexcept {
  Vec3<T> radial = d - dot(d, axis) * axis;
  radial -= dot(radial, axis) * axis;  // second pass: orthogonal to the axis to rounding
  if (!(max_abs(radial) > T(16) * eps_v<T> * max_abs(d))) return Vec3<T>{};
  return ball_support(radial, r);
}

}  // namespace detail

/// A point is its own support point.
template <Real T, int N>
[[nodiscard]] constexpr Vec<T, N> support(const Vec<T, N>& p, const Vec<T, N>&) noexcept {
  return p;
}

/// The endpoint farther along d (p0 on a tie).
template <Real T, int N>
[[nodiscard]] constexpr Vec<T, N> support(const Segment<T, N>& s, const Vec<T, N>& d) noexcept {
  return dot(s.p1 - s.p0, d) > T(0) ? s.p1 : s.p0;
}

/// The vertex farthest along d (lowest index on a tie).
template <Real T, int N>
[[nodiscard]] constexpr Vec<T, N> support(const Triangle<T, N>& t, const Vec<T, N>& d) noexcept {
  const T h0 = dot(t.v0, d), h1 = dot(t.v1, d), h2 = dot(t.v2, d);
  if (h0 >= h1 && h0 >= h2) return t.v0;
  return h1 >= h2 ? t.v1 : t.v2;
}

/// The point farthest along d (lowest index on a tie); all NaN for an empty set or when a
/// point makes dot(point, d) non-finite (a NaN or infinite coordinate is never skipped).
template <Real T, int N>
[[nodiscard]] inline Vec<T, N> support(const ConvexPoints<T, N>& c, const Vec<T, N>& d) noexcept {
  constexpr T inf = std::numeric_limits<T>::infinity();
  if (c.points.empty()) return splat<T, N>(std::numeric_limits<T>::quiet_NaN());
  std::size_t best = 0;
  T hbest = dot(c.points[0], d);
  // The sum of the dot products is finite exactly when every one is, unless it overflows; only
  // then are the points checked one by one (a test per point costs GJK's inner loop ~5%).
  T sum = hbest;
  for (std::size_t i = 1; i < c.points.size(); ++i) {
    const T h = dot(c.points[i], d);
    sum += h;
    if (h > hbest) {
      hbest = h;
      best = i;
    }
  }
  if (!(std::fabs(sum) < inf))
    for (const auto& q : c.points)
      if (!(std::fabs(dot(q, d)) < inf)) return splat<T, N>(std::numeric_limits<T>::quiet_NaN());
  return c.points[best];
}

/// center + radius d / |d| (the center for d = 0).
template <Real T, int N>
[[nodiscard]] inline Vec<T, N> support(const Sphere<T, N>& s, const Vec<T, N>& d) noexcept {
  return s.center + detail::ball_support(d, s.radius);
}

/// center + radius d / |d| (the center for d = 0).
template <Real T>
[[nodiscard]] inline Vec2<T> support(const Circle2<T>& c, const Vec2<T>& d) noexcept {
  return c.center + detail::ball_support(d, c.radius);
}

/// The corner farthest along d (min where d[i] <= 0).
template <Real T, int N>
[[nodiscard]] constexpr Vec<T, N> support(const AlignedBox<T, N>& b, const Vec<T, N>& d) noexcept {
  Vec<T, N> p{};
  for (int i = 0; i < N; ++i) p[i] = d[i] > T(0) ? b.max[i] : b.min[i];
  return p;
}

/// The corner farthest along d (the -extent side where dot(d, axis) <= 0).
template <Real T, int N>
[[nodiscard]] constexpr Vec<T, N> support(const OrientedBox<T, N>& b, const Vec<T, N>& d) noexcept {
  Vec<T, N> p = b.center;
  for (int i = 0; i < N; ++i)
    p += (dot(b.axis[i], d) > T(0) ? b.extent[i] : -b.extent[i]) * b.axis[i];
  return p;
}

/// Support of the segment plus radius d / |d|.
template <Real T, int N>
[[nodiscard]] inline Vec<T, N> support(const Capsule<T, N>& c, const Vec<T, N>& d) noexcept {
  return support(c.segment, d) + detail::ball_support(d, c.radius);
}

/// The rim point of the cap facing d; an infinite height gives non-finite coordinates.
template <Real T>
[[nodiscard]] inline Vec3<T> support(const Cylinder3<T>& c, const Vec3<T>& d) noexcept {
  const Vec3<T>& axis = c.axis.direction;
  const T half = T(0.5) * c.height;
  return c.axis.origin + (dot(axis, d) > T(0) ? half : -half) * axis +
         detail::disk_support(axis, d, c.radius);
}

/// The farthest of the rims at min_height and max_height (and the apex when a double cone
/// contains it); an infinite height gives non-finite coordinates.
template <Real T>
[[nodiscard]] inline Vec3<T> support(const Cone3<T>& c, const Vec3<T>& d) noexcept {
  const T slope = std::tan(c.angle);
  const Vec3<T> radial = detail::disk_support(c.axis, d, T(1));
  const auto rim = [&](T h) { return c.vertex + h * c.axis + (std::fabs(h) * slope) * radial; };
  Vec3<T> best = rim(c.max_height);
  const Vec3<T> low = rim(c.min_height);
  if (dot(low - best, d) > T(0)) best = low;
  if (c.min_height < T(0) && c.max_height > T(0) && dot(c.vertex - best, d) > T(0)) best = c.vertex;
  return best;
}

/// rotation * support(shape, rotation^T d) + translation + margin d / |d|.
template <class S, Real T, int N>
[[nodiscard]] inline Vec<T, N> support(const Transformed<S, T, N>& t, const Vec<T, N>& d) noexcept {
  return t.rotation * support(t.shape, transpose(t.rotation) * d) + t.translation +
         detail::ball_support(d, t.margin);
}

/// A shape GJK can take: support(s, d) and SupportSpace<S>.
template <class S>
concept SupportMapped = requires(const S& s,
                                 const Vec<support_scalar_t<S>, support_dimension_v<S>>& d) {
  { support(s, d) } -> std::convertible_to<Vec<support_scalar_t<S>, support_dimension_v<S>>>;
};

namespace detail {

// The core/margin split (see the header comment): support(s, d) = core_support(s, d) +
// core_margin(s) d / |d|. Shapes without a round part are their own core.
template <class S, class T, int N>
[[nodiscard]] inline Vec<T, N> core_support(const S& s, const Vec<T, N>& d) noexcept {
  return support(s, d);
}
template <class S>
[[nodiscard]] constexpr support_scalar_t<S> core_margin(const S&) noexcept {
  return support_scalar_t<S>(0);
}

template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> core_support(const Sphere<T, N>& s, const Vec<T, N>&) noexcept {
  return s.center;
}
template <class T, int N>
[[nodiscard]] constexpr T core_margin(const Sphere<T, N>& s) noexcept {
  return s.radius;
}
template <Real T>
[[nodiscard]] constexpr Vec2<T> core_support(const Circle2<T>& c, const Vec2<T>&) noexcept {
  return c.center;
}
template <Real T>
[[nodiscard]] constexpr T core_margin(const Circle2<T>& c) noexcept {
  return c.radius;
}
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> core_support(const Capsule<T, N>& c,
                                               const Vec<T, N>& d) noexcept {
  return support(c.segment, d);
}
template <class T, int N>
[[nodiscard]] constexpr T core_margin(const Capsule<T, N>& c) noexcept {
  return c.radius;
}
template <class S, class T, int N>
[[nodiscard]] inline Vec<T, N> core_support(const Transformed<S, T, N>& t,
                                            const Vec<T, N>& d) noexcept {
  return t.rotation * core_support(t.shape, transpose(t.rotation) * d) + t.translation;
}
template <class S, class T, int N>
[[nodiscard]] constexpr T core_margin(const Transformed<S, T, N>& t) noexcept {
  return t.margin + core_margin(t.shape);
}

}  // namespace detail
}  // namespace locus
