// SPDX-License-Identifier: BSL-1.0
#pragma once
// Exact side of a ball for the crossing of a line with a plane (row core.predicates; used by row
// int3.linear-polygon for the rim of a disk, book section 11.3).
//
// The plane is { X : dot(n, X - c) = 0 } and the ball { X : |X - c| <= r }, both as given. The
// crossing X of a line with the plane is never rounded: written as a ratio, the side is the sign
// of a polynomial of degree 6 in the inputs.
//   crossing_in_ball_line(p, d, c, n, r): the line p + t d. With a = p - c, X - c = W / (n.d),
//     W = a (n.d) - d (n.a) = n x (a x d); the result is sign(|W|^2 - r^2 (n.d)^2).
//   crossing_in_ball_segment(p, q, c, n, r): the line through p and q (the segment's carrier,
//     without rounding q - p). With a = p - c, b = q - c, f0 = n.a, f1 = n.b,
//     X - c = (f0 b - f1 a) / (f0 - f1); the result is sign(|f0 b - f1 a|^2 - r^2 (f0 - f1)^2).
//   point_in_ball(x, c, r): sign(|x - c|^2 - r^2).
// For a line that may lie in the plane (the distance from c to the line against r):
//   line_near_ball(p, d, c, r) = sign(|(p - c) x d|^2 - r^2 |d|^2),
//   segment_line_near_ball(p, q, c, r) = sign(|(p - c) x (q - c)|^2 - r^2 |q - p|^2),
//   dot_of_differences(x, y, v) = sign((x - y).v), and (x, y, z, w) = sign((x - y).(z - w))
//   (where the foot of c lies along the line).
// So -1 is strictly inside the ball, 0 on its sphere, +1 outside. When the line is parallel to
// the plane (n.d = 0, f0 = f1) there is no crossing and the result is sign(|W|^2) (>= 0): callers
// decide parallelism first (core/plane_side.hpp, predicates.hpp). Non-finite input gives 0.
// Method: a floating-point evaluation with an a-priori error bound (every nonzero input and
// difference within [2^-120, 2^120]), else the exact sum on core's engine
// (core/exact_poly.hpp's exact_sign_of_terms; about 200 terms for the line, 470 for the
// segment). Float input is promoted exactly. Cost: about 80 flops when the filter decides, tens
// of microseconds otherwise; no allocation (at most about 40 kB of stack).
// Compiled in src/core/plane_crossing_ball.cpp.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>

namespace locus {

/// sign(|X - c|^2 - r^2) for X the crossing of the line p + t d with dot(n, X - c) = 0.
[[nodiscard]] int crossing_in_ball_line(const Vec3<double>& p, const Vec3<double>& d,
                                        const Vec3<double>& c, const Vec3<double>& n,
                                        double r) noexcept;

/// sign(|X - c|^2 - r^2) for X the crossing of the line through p and q with dot(n, X - c) = 0.
[[nodiscard]] int crossing_in_ball_segment(const Vec3<double>& p, const Vec3<double>& q,
                                           const Vec3<double>& c, const Vec3<double>& n,
                                           double r) noexcept;

/// sign(|x - c|^2 - r^2), exact.
[[nodiscard]] int point_in_ball(const Vec3<double>& x, const Vec3<double>& c, double r) noexcept;

/// sign(|(p - c) x d|^2 - r^2 |d|^2): the line p + t d against the ball (exact).
[[nodiscard]] int line_near_ball(const Vec3<double>& p, const Vec3<double>& d,
                                 const Vec3<double>& c, double r) noexcept;

/// sign(|(p - c) x (q - c)|^2 - r^2 |q - p|^2): the line through p and q against the ball.
[[nodiscard]] int segment_line_near_ball(const Vec3<double>& p, const Vec3<double>& q,
                                         const Vec3<double>& c, double r) noexcept;

/// sign((x - y).v), exact.
[[nodiscard]] int dot_of_differences(const Vec3<double>& x, const Vec3<double>& y,
                                     const Vec3<double>& v) noexcept;

/// sign((x - y).(z - w)), exact.
[[nodiscard]] int dot_of_differences(const Vec3<double>& x, const Vec3<double>& y,
                                     const Vec3<double>& z, const Vec3<double>& w) noexcept;

}  // namespace locus
