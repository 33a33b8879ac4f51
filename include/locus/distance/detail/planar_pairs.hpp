// SPDX-License-Identifier: BSL-1.0
#pragma once
// Internal machinery of the triangle-triangle, triangle-rectangle and rectangle-rectangle
// distance headers (row dist3.misc): two solid convex planar pieces in 3D.
//
// Method: two disjoint compact convex planar pieces have a closest pair with one point on an
// edge of one of them (if both points were relative-interior points, the two pieces would be
// parallel there and the pair could slide to an edge), and two pieces that meet do so along an
// edge of one of them (an extreme point of their convex intersection lies on the relative
// boundary of one piece). So the answer is the nearest of the edge-piece queries: every edge of
// the first against the second piece and every edge of the second against the first (segment-
// triangle and segment-rectangle, detail/linear_planar.hpp). Segment-triangle decides contact
// exactly, so a triangle pair that meets has distance exactly 0 (except ill-conditioned
// contacts, see segment_triangle.hpp) whenever one of the two triangles is not degenerate.
//
// unique: false when the pieces meet in more than one point (two contacts found by different
// edge queries differ by more than 64 eps * scale: transversal triangles meet along a segment),
// or when an edge query tied with the winner (within 64 eps * scale) reports a sliding pair (an
// edge parallel to the other piece's plane at the minimum, e.g. stacked parallel pieces, or
// parallel nearest edges). Same-type pairs are solved in a
// canonical (lexicographic) argument order, so distance(b, a) is bit for bit the swap of
// distance(a, b).

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/linear.hpp>
#include <locus/distance/detail/linear_planar.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/rectangle.hpp>
#include <locus/primitives/segment.hpp>
#include <locus/primitives/triangle.hpp>

#include <array>

namespace locus::detail {

/// The nearest of several candidate results, with the contact bookkeeping for uniqueness.
template <class T, class PA, class PB>
struct PieceBest {
  Distance<T, 3, PA, PB> best{};
  bool found = false;
  Vec3<T> contact{};
  bool have_contact = false;
  bool spread = false;  // two distinct contacts at distance ~0
  T scale = T(0);

  // Every candidate's distance and uniqueness (at most eight edge queries).
  T dist[8] = {};
  bool uniq[8] = {};
  int count = 0;

  void offer(const Distance<T, 3, PA, PB>& r) noexcept {
    if (!found || r.sqr_distance < best.sqr_distance) {
      best = r;
      found = true;
    }
    dist[count] = r.distance;
    uniq[count++] = r.unique;
    if (r.distance <= T(64) * eps_v<T> * scale) {
      if (!have_contact) {
        contact = r.closest[1];
        have_contact = true;
      } else if (max_abs(r.closest[1] - contact) > T(64) * eps_v<T> * scale) {
        spread = true;
      }
    }
  }
  [[nodiscard]] Distance<T, 3, PA, PB> result() const noexcept {
    Distance<T, 3, PA, PB> r = best;
    const T tol = T(64) * eps_v<T> * scale;
    if (spread && r.distance <= tol) r.unique = false;
    // A query tied with the winner that can slide makes the whole answer non-unique (the winner
    // may be an isolated pair of the same continuum, e.g. another edge's endpoint on it).
    for (int i = 0; i < count; ++i)
      if (!uniq[i] && dist[i] <= r.distance + tol) r.unique = false;
    return r;
  }
};

template <Real T>
[[nodiscard]] constexpr bool finite_input(const Triangle3<T>& t) noexcept {
  return is_finite(t.v0) && is_finite(t.v1) && is_finite(t.v2);
}
template <Real T>
[[nodiscard]] constexpr bool finite_input(const Rectangle<T, 3>& r) noexcept {
  return is_finite(r.center) && is_finite(r.axis[0]) && is_finite(r.axis[1]) &&
         is_finite(r.extent[0]) && is_finite(r.extent[1]);
}

template <Real T>
[[nodiscard]] constexpr T piece_scale(const Triangle3<T>& t) noexcept {
  return max_abs(t.v0) + max_abs(t.v1 - t.v0) + max_abs(t.v2 - t.v0);
}
template <Real T>
[[nodiscard]] constexpr T piece_scale(const Rectangle<T, 3>& r) noexcept {
  return max_abs(r.center) + (r.extent[0] > T(0) ? r.extent[0] : T(0)) +
         (r.extent[1] > T(0) ? r.extent[1] : T(0));
}

/// Edge k of a piece as a segment, and the piece's parameter of the point at t on it.
/// Triangle: edges v0 v1, v1 v2, v2 v0, barycentric parameter.
template <Real T>
[[nodiscard]] constexpr Segment3<T> piece_edge(const Triangle3<T>& t, int k) noexcept {
  return k == 0 ? Segment3<T>{t.v0, t.v1}
                : (k == 1 ? Segment3<T>{t.v1, t.v2} : Segment3<T>{t.v2, t.v0});
}
template <Real T>
[[nodiscard]] constexpr Vec3<T> piece_edge_param(const Triangle3<T>&, int k, T t) noexcept {
  Vec3<T> b{};
  b[k] = T(1) - t;
  b[(k + 1) % 3] = t;
  return b;
}
/// Rectangle: edges between consecutive corners (-,-), (+,-), (+,+), (-,+) (rectangle.hpp's
/// corners()), symmetric (s, t) parameter.
template <Real T>
[[nodiscard]] constexpr Vec2<T> rect_corner_param(const Rectangle<T, 3>& r, int k) noexcept {
  const T ex = r.extent[0] > T(0) ? r.extent[0] : T(0);
  const T ey = r.extent[1] > T(0) ? r.extent[1] : T(0);
  return {(k == 1 || k == 2) ? ex : -ex, k >= 2 ? ey : -ey};
}
template <Real T>
[[nodiscard]] constexpr Segment3<T> piece_edge(const Rectangle<T, 3>& r, int k) noexcept {
  return {point_at(r, rect_corner_param(r, k)), point_at(r, rect_corner_param(r, (k + 1) % 4))};
}
template <Real T>
[[nodiscard]] constexpr Vec2<T> piece_edge_param(const Rectangle<T, 3>& r, int k, T t) noexcept {
  return lerp(rect_corner_param(r, k), rect_corner_param(r, (k + 1) % 4), t);
}

template <Real T>
[[nodiscard]] constexpr int edge_count(const Triangle3<T>&) noexcept {
  return 3;
}
template <Real T>
[[nodiscard]] constexpr int edge_count(const Rectangle<T, 3>&) noexcept {
  return 4;
}

template <Real T>
[[nodiscard]] inline auto segment_piece_distance(const Segment3<T>& s,
                                                 const Triangle3<T>& t) noexcept {
  return linear_triangle_distance<T>(s, t);
}
template <Real T>
[[nodiscard]] inline auto segment_piece_distance(const Segment3<T>& s,
                                                 const Rectangle<T, 3>& r) noexcept {
  return linear_rectangle_distance<T>(s, r);
}

/// distance(a, b) for two solid planar pieces (triangles or rectangles in 3D).
template <class T, class A, class B>
[[nodiscard]] inline auto piece_piece_distance(const A& a, const B& b) noexcept {
  using PA = decltype(piece_edge_param(a, 0, T(0)));
  using PB = decltype(piece_edge_param(b, 0, T(0)));
  if (!finite_input(a) || !finite_input(b)) return non_finite_distance<T, 3, PA, PB>();
  PieceBest<T, PA, PB> acc;
  acc.scale = piece_scale(a) + piece_scale(b);
  for (int k = 0; k < edge_count(a); ++k) {
    const auto r = segment_piece_distance(piece_edge(a, k), b);
    acc.offer({r.distance, r.sqr_distance, r.closest, piece_edge_param(a, k, r.param_a), r.param_b,
               r.unique});
  }
  for (int k = 0; k < edge_count(b); ++k) {
    const auto r = segment_piece_distance(piece_edge(b, k), a);
    acc.offer({r.distance,
               r.sqr_distance,
               {r.closest[1], r.closest[0]},
               r.param_b,
               piece_edge_param(b, k, r.param_a),
               r.unique});
  }
  return acc.result();
}

/// Lexicographic order of the defining scalars (canonical order of same-type pairs).
template <class T, int N>
[[nodiscard]] constexpr int lex_compare(const Vec<T, N>& a, const Vec<T, N>& b) noexcept {
  for (int i = 0; i < N; ++i)
    if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
  return 0;
}
template <Real T>
[[nodiscard]] constexpr bool piece_less(const Triangle3<T>& a, const Triangle3<T>& b) noexcept {
  for (int k = 0; k < 3; ++k)
    if (const int c = lex_compare(a[k], b[k])) return c < 0;
  return false;
}
template <Real T>
[[nodiscard]] constexpr bool piece_less(const Rectangle<T, 3>& a,
                                        const Rectangle<T, 3>& b) noexcept {
  if (const int c = lex_compare(a.center, b.center)) return c < 0;
  if (const int c = lex_compare(a.axis[0], b.axis[0])) return c < 0;
  if (const int c = lex_compare(a.axis[1], b.axis[1])) return c < 0;
  if (a.extent[0] != b.extent[0]) return a.extent[0] < b.extent[0];
  return a.extent[1] < b.extent[1];
}

/// Same-type pairs in canonical order.
template <class T, class P>
[[nodiscard]] inline auto same_piece_distance(const P& a, const P& b) noexcept {
  if (piece_less(b, a)) return swapped(piece_piece_distance<T>(b, a));
  return piece_piece_distance<T>(a, b);
}

}  // namespace locus::detail
