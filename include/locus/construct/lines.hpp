// SPDX-License-Identifier: BSL-1.0
#pragma once
// The line constructions of book section 8.12 (figures 8.30-8.34); row cons2.lines.
//
// normal_line(l, p): the line through p perpendicular to l (8.30); origin p, direction
// perp(unit direction of l).
// perpendicular_bisector(p, q): the points equidistant from p and q (8.31); origin the midpoint,
// direction perp((q - p) / |q - p|), so p lies on its right. p == q: count 0, degenerate_input.
// parallel_lines(l, d): the lines parallel to l at distance d >= 0 (8.32): origin
// l.origin - d n then + d n (n = perp of the unit direction, pointing left); d = 0 gives l once.
// parallel_lines_vertical(l, d) / parallel_lines_horizontal(l, d): the lines through
// l.origin -+ (0, d) / -+ (d, 0) (8.33: offset along the y / x axis instead of the normal); a
// vertical line offset vertically (horizontal offset horizontally) is l itself: count 1.
// tangent_lines_normal_to(c, l): the two tangents of c perpendicular to l (8.34), touching at
// c.center - r u then c.center + r u (u the unit direction of l); origins at the tangent points.
//
// Every returned line has a unit direction (Solutions, construct/solutions.hpp). Which case
// applies (p == q, a zero offset, an axis-parallel line) is decided by exact comparisons of the
// input values. Bad input: a non-finite value gives non_finite_input, a zero direction, a
// negative distance or a radius <= 0 degenerate_input (count 0). Accuracy: origins within
// 4 eps_T (|o| + d) and directions within 4 eps_T of the exact ones (one normalisation, one
// multiply-add per coordinate). Cost O(1), inline, no allocation.

#include <locus/construct/solutions.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/line.hpp>

namespace locus {

namespace detail::construct {
/// The unit direction of l, or a status when l is unusable.
template <Real T>
[[nodiscard]] inline Status unit_direction(const Line2<T>& l, Vec2<T>& u) noexcept {
  if (!is_finite(l.origin) || !is_finite(l.direction)) return Status::non_finite_input;
  if (l.direction == Vec2<T>{}) return Status::degenerate_input;
  u = normalize(l.direction);
  return Status::ok;
}
}  // namespace detail::construct

/// The line through p perpendicular to l (figure 8.30).
template <Real T>
[[nodiscard]] inline Solutions<Line2<T>, 1> normal_line(const Line2<T>& l,
                                                        const Vec2<T>& p) noexcept {
  Solutions<Line2<T>, 1> s;
  Vec2<T> u{};
  s.status = detail::construct::unit_direction(l, u);
  if (s.status == Status::ok && !is_finite(p)) s.status = Status::non_finite_input;
  if (s.status == Status::ok) s.push({p, perp(u)});
  return s;
}

/// The perpendicular bisector of p and q (figure 8.31).
template <Real T>
[[nodiscard]] inline Solutions<Line2<T>, 1> perpendicular_bisector(const Vec2<T>& p,
                                                                   const Vec2<T>& q) noexcept {
  Solutions<Line2<T>, 1> s;
  if (!is_finite(p) || !is_finite(q)) {
    s.status = Status::non_finite_input;
  } else if (p == q) {
    s.status = Status::degenerate_input;
  } else {
    const Vec2<T> mid{p.x / 2 + q.x / 2, p.y / 2 + q.y / 2};  // no overflow near the range end
    s.push({mid, perp(normalize(q - p))});
  }
  return s;
}

namespace detail::construct {
template <Real T>
[[nodiscard]] inline Solutions<Line2<T>, 2> offset_pair(const Line2<T>& l, T d,
                                                        Vec2<T> dir_of_offset, bool same) noexcept {
  Solutions<Line2<T>, 2> s;
  Vec2<T> u{};
  s.status = unit_direction(l, u);
  if (s.status == Status::ok && !is_finite(d)) s.status = Status::non_finite_input;
  if (s.status == Status::ok && d < T(0)) s.status = Status::degenerate_input;
  if (s.status != Status::ok) return s;
  if (d == T(0) || same) {
    s.push({l.origin, u});
    return s;
  }
  s.push({l.origin - d * dir_of_offset, u});
  s.push({l.origin + d * dir_of_offset, u});
  return s;
}
}  // namespace detail::construct

/// The lines parallel to l at distance d (figure 8.32).
template <Real T>
[[nodiscard]] inline Solutions<Line2<T>, 2> parallel_lines(const Line2<T>& l, T d) noexcept {
  return detail::construct::offset_pair(l, d, perp(normalize(l.direction)), false);
}
/// The lines l shifted by -d and +d along the y axis (figure 8.33).
template <Real T>
[[nodiscard]] inline Solutions<Line2<T>, 2> parallel_lines_vertical(const Line2<T>& l,
                                                                    T d) noexcept {
  return detail::construct::offset_pair(l, d, Vec2<T>{T(0), T(1)}, l.direction.x == T(0));
}
/// The lines l shifted by -d and +d along the x axis (figure 8.33).
template <Real T>
[[nodiscard]] inline Solutions<Line2<T>, 2> parallel_lines_horizontal(const Line2<T>& l,
                                                                      T d) noexcept {
  return detail::construct::offset_pair(l, d, Vec2<T>{T(1), T(0)}, l.direction.y == T(0));
}

/// The two tangents of c perpendicular to l (figure 8.34).
template <Real T>
[[nodiscard]] inline Solutions<Line2<T>, 2> tangent_lines_normal_to(const Circle2<T>& c,
                                                                    const Line2<T>& l) noexcept {
  Solutions<Line2<T>, 2> s;
  Vec2<T> u{};
  s.status = detail::construct::unit_direction(l, u);
  if (s.status == Status::ok && (!is_finite(c.center) || !is_finite(c.radius)))
    s.status = Status::non_finite_input;
  if (s.status == Status::ok && !(c.radius > T(0))) s.status = Status::degenerate_input;
  if (s.status != Status::ok) return s;
  s.push({c.center - c.radius * u, perp(u)});
  s.push({c.center + c.radius * u, perp(u)});
  return s;
}

}  // namespace locus
