// SPDX-License-Identifier: BSL-1.0
#pragma once
// Polylines (polygonal chains) in N dimensions and monotone chains; row prim2.polyline; book
// section 5.4, figures 5.8 (a polyline) and 5.11 (strictly monotone and monotone chains).
// Polyline<T, N> {vertices, closed}: an open polyline has the n - 1 segments (v[i], v[i+1]); a
// closed one also (v[n-1], v[0]) (a polygon's boundary). Every algorithm also takes the vertices
// as std::span<const Vec<T, N>> plus `closed` (from a std::vector, name the types:
// polyline_length<double, 2>(vec, closed)).
// Parametrisations:
//   vertex parameter: point_at(poly, t) for t in [0, segment_count]: segment i = floor(t) at
//     local parameter t - i, so t = i is vertex i (exactly) and t = segment_count is the end
//     (v[0] again when closed); t outside the range is clamped.
//   arc length: point_at_arc_length(poly, s) for s in [0, length(poly)], clamped; O(n) per
//     call, or O(log n) with a table from cumulative_lengths().
// Monotone chains (fig 5.11): is_monotone_chain(v, d, strict) is true when the projections
// dot(v[i], d) are all non-decreasing or all non-increasing along the open chain (strict: all
// strictly increasing or all strictly decreasing, so every line perpendicular to d meets the
// chain at most once). The comparisons are EXACT (exact sign of dot(v[i+1] - v[i], d), see
// core/exact_sum.hpp), so axis directions and integer data are decided correctly.
// Degenerate input: an empty polyline has length 0 and point_at returns the zero vector; a
// single vertex is returned for every parameter; zero-length segments are skipped by arc-length
// walking. A chain with fewer than two vertices is (strictly) monotone; a zero or non-finite
// direction, or non-finite vertices, make is_monotone_chain false. Cost O(n), no allocation
// except cumulative_lengths (which returns a vector).

#include <locus/config.hpp>
#include <locus/core/exact_sum.hpp>
#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/segment.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

namespace locus {

/// An open or closed polygonal chain through `vertices`.
template <class T, int N>
struct Polyline {
  std::vector<Vec<T, N>> vertices;
  bool closed = false;
};

template <Real T>
using Polyline2 = Polyline<T, 2>;
template <Real T>
using Polyline3 = Polyline<T, 3>;
using Polyline2f = Polyline2<float>;
using Polyline2d = Polyline2<double>;
using Polyline3f = Polyline3<float>;
using Polyline3d = Polyline3<double>;

/// Number of segments: n - 1 open (0 for n < 2), n closed (0 for n < 2).
[[nodiscard]] constexpr std::size_t segment_count(std::size_t n, bool closed) noexcept {
  if (n < 2) return 0;
  return closed ? n : n - 1;
}

template <class T, int N>
[[nodiscard]] constexpr std::size_t segment_count(const Polyline<T, N>& p) noexcept {
  return segment_count(p.vertices.size(), p.closed);
}

/// Segment i: (v[i], v[(i + 1) mod n]); i < segment_count.
template <class T, int N>
[[nodiscard]] constexpr Segment<T, N> edge(std::span<const Vec<T, N>> v, std::size_t i) noexcept {
  LOCUS_ASSERT(i < v.size(), "polyline edge index out of range");
  return {v[i], v[i + 1 == v.size() ? 0 : i + 1]};
}

template <class T, int N>
[[nodiscard]] constexpr Segment<T, N> edge(const Polyline<T, N>& p, std::size_t i) noexcept {
  return edge(std::span<const Vec<T, N>>(p.vertices), i);
}

/// Total length of the segments.
template <class T, int N>
[[nodiscard]] inline T polyline_length(std::span<const Vec<T, N>> v, bool closed) noexcept {
  const std::size_t m = segment_count(v.size(), closed);
  T sum = T(0);
  for (std::size_t i = 0; i < m; ++i) sum += length(edge(v, i));
  return sum;
}

template <class T, int N>
[[nodiscard]] inline T length(const Polyline<T, N>& p) noexcept {
  return polyline_length(std::span<const Vec<T, N>>(p.vertices), p.closed);
}

/// Vertex parametrisation: segment floor(t) at local parameter t - floor(t); t clamped to
/// [0, segment_count]. Integer t gives the vertex exactly.
template <class T, int N>
[[nodiscard]] inline Vec<T, N> polyline_point_at(std::span<const Vec<T, N>> v, bool closed,
                                                 T t) noexcept {
  if (v.empty()) return Vec<T, N>{};
  const std::size_t m = segment_count(v.size(), closed);
  if (m == 0 || !(t > T(0))) return v[0];  // also NaN -> the first vertex
  if (!(t < static_cast<T>(m))) return closed ? v[0] : v[m];
  std::size_t i = static_cast<std::size_t>(t);
  if (i >= m) i = m - 1;
  return point_at(edge(v, i), t - static_cast<T>(i));
}

template <class T, int N>
[[nodiscard]] inline Vec<T, N> point_at(const Polyline<T, N>& p, T t) noexcept {
  return polyline_point_at(std::span<const Vec<T, N>>(p.vertices), p.closed, t);
}

/// Cumulative arc lengths: out[0] = 0, out[i + 1] = out[i] + |segment i|; size segment_count+1
/// (empty for an empty input).
template <class T, int N>
[[nodiscard]] inline std::vector<T> cumulative_lengths(std::span<const Vec<T, N>> v, bool closed) {
  std::vector<T> out;
  if (v.empty()) return out;
  const std::size_t m = segment_count(v.size(), closed);
  out.reserve(m + 1);
  out.push_back(T(0));
  for (std::size_t i = 0; i < m; ++i) out.push_back(out.back() + length(edge(v, i)));
  return out;
}

/// Arc-length parametrisation with a table from cumulative_lengths (O(log n)); s clamped to
/// [0, total length].
template <class T, int N>
[[nodiscard]] inline Vec<T, N> polyline_point_at_arc_length(std::span<const Vec<T, N>> v,
                                                            bool closed, std::span<const T> cum,
                                                            T s) noexcept {
  if (v.empty()) return Vec<T, N>{};
  const std::size_t m = segment_count(v.size(), closed);
  LOCUS_ASSERT(cum.size() == m + 1, "cumulative length table does not match the polyline");
  if (m == 0 || !(s > T(0))) return v[0];
  if (!(s < cum[m])) return closed ? v[0] : v[m];
  // The first segment whose end is beyond s; zero-length segments are never selected.
  const auto it = std::upper_bound(cum.begin() + 1, cum.end(), s);
  const std::size_t i = static_cast<std::size_t>(it - cum.begin()) - 1;
  const T len = cum[i + 1] - cum[i];
  const T local = len > T(0) ? clamp((s - cum[i]) / len, T(0), T(1)) : T(0);
  return point_at(edge(v, i), local);
}

/// Arc-length parametrisation without a table (O(n)); s clamped to [0, total length].
template <class T, int N>
[[nodiscard]] inline Vec<T, N> point_at_arc_length(const Polyline<T, N>& p, T s) noexcept {
  const std::span<const Vec<T, N>> v(p.vertices);
  if (v.empty()) return Vec<T, N>{};
  const std::size_t m = segment_count(p);
  if (m == 0 || !(s > T(0))) return v[0];
  T acc = T(0);
  for (std::size_t i = 0; i < m; ++i) {
    const T len = length(edge(v, i));
    if (s < acc + len) return point_at(edge(v, i), clamp((s - acc) / len, T(0), T(1)));
    acc += len;
  }
  return p.closed ? v[0] : v[m];
}

/// Exact monotonicity of the open chain v[0..n) with respect to direction d (fig 5.11):
/// non-decreasing or non-increasing projections (strict = strictly).
template <Real T>
[[nodiscard]] inline bool is_monotone_chain(std::span<const Vec2<T>> v, const Vec2<T>& d,
                                            bool strict = false) noexcept {
  if (!is_finite(d) || d == Vec2<T>{}) return false;
  for (const Vec2<T>& p : v)
    if (!is_finite(p)) return false;
  int dir = 0;  // +1 increasing, -1 decreasing, 0 not yet known
  for (std::size_t i = 1; i < v.size(); ++i) {
    const int s = detail::sign_dot_diff(v[i - 1].x, v[i - 1].y, v[i].x, v[i].y, d.x, d.y);
    if (s == 0) {
      if (strict) return false;
      continue;
    }
    if (dir == 0)
      dir = s;
    else if (s != dir)
      return false;
  }
  return true;
}

// The same for any point range (core/point_range.hpp).
template <PointRange R>
[[nodiscard]] constexpr Segment<range_scalar_t<R>, range_dimension_v<R>> edge(
    const R& v, std::size_t i) noexcept {
  return edge(point_span(v), i);
}
template <PointRange R>
[[nodiscard]] inline range_scalar_t<R> polyline_length(const R& v, bool closed) noexcept {
  return polyline_length(point_span(v), closed);
}
template <PointRange R>
[[nodiscard]] inline range_point_t<R> polyline_point_at(const R& v, bool closed,
                                                        range_scalar_t<R> t) noexcept {
  return polyline_point_at(point_span(v), closed, t);
}
template <PointRange R>
[[nodiscard]] inline std::vector<range_scalar_t<R>> cumulative_lengths(const R& v, bool closed) {
  return cumulative_lengths(point_span(v), closed);
}
template <PointRange R>
[[nodiscard]] inline range_point_t<R> polyline_point_at_arc_length(
    const R& v, bool closed, std::span<const range_scalar_t<R>> cum, range_scalar_t<R> s) noexcept {
  return polyline_point_at_arc_length(point_span(v), closed, cum, s);
}
template <PointRange2 R>
[[nodiscard]] inline bool is_monotone_chain(const R& v, const range_point_t<R>& d,
                                            bool strict = false) noexcept {
  return is_monotone_chain(point_span(v), d, strict);
}

}  // namespace locus
