// SPDX-License-Identifier: BSL-1.0
#pragma once
// Point ranges: the one way bulk point input reaches an algorithm (docs/notes/api.md).
//
// PointRange<R> is any contiguous, sized range whose value type is Vec<T, N> with T float or
// double: std::vector, std::array, std::span (const or not, any extent), C arrays. PointRange2
// and PointRange3 fix N. point_span(r) views such a range as std::span<const Vec<T, N>> (no
// copy), and point_span<N>(flat, n) views n points stored as a flat array of interleaved
// coordinates x0, y0, [z0,] x1, ... (Vec<T, N> has the layout of T[N], see core/vec.hpp).
//
// Every algorithm and bulk query declares its span form, std::span<const Vec<T, N>>, and next to
// it one constrained overload taking `const R&` with R a PointRange that forwards to it through
// point_span. So a user's container works without spelling <double>, and a flat array is passed
// as point_span<2>(xy, n).

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>

#include <cstddef>
#include <ranges>
#include <span>
#include <type_traits>

namespace locus {

namespace detail {
template <class V>
struct point_traits {
  static constexpr bool is_point = false;
};
template <Real T, int N>
struct point_traits<Vec<T, N>> {
  static constexpr bool is_point = true;
  static constexpr int dimension = N;
  using scalar = T;
};
}  // namespace detail

/// The point type (a Vec<T, N>) of a range.
template <class R>
using range_point_t = std::remove_cv_t<std::ranges::range_value_t<R>>;

/// A contiguous sized range of Vec<T, N>, T float or double.
template <class R>
concept PointRange = std::ranges::contiguous_range<R> && std::ranges::sized_range<R> &&
    detail::point_traits<range_point_t<R>>::is_point;

/// A PointRange of points of dimension N.
template <class R, int N>
concept PointRangeOf = PointRange<R> && detail::point_traits<range_point_t<R>>::dimension == N;
template <class R>
concept PointRange2 = PointRangeOf<R, 2>;
template <class R>
concept PointRange3 = PointRangeOf<R, 3>;

/// The scalar type T and the dimension N of a PointRange of Vec<T, N>.
template <PointRange R>
using range_scalar_t = typename detail::point_traits<range_point_t<R>>::scalar;
template <PointRange R>
inline constexpr int range_dimension_v = detail::point_traits<range_point_t<R>>::dimension;

/// The points of `r` as a span (a view: `r` must outlive it).
template <PointRange R>
[[nodiscard]] constexpr std::span<const range_point_t<R>> point_span(const R& r) noexcept {
  return {std::ranges::data(r), std::ranges::size(r)};
}

/// n points of dimension N stored as a flat array of N n interleaved coordinates.
template <int N, Real T>
[[nodiscard]] inline std::span<const Vec<T, N>> point_span(const T* flat, std::size_t n) noexcept {
  static_assert(sizeof(Vec<T, N>) == N * sizeof(T) && alignof(Vec<T, N>) == alignof(T) &&
                    std::is_standard_layout_v<Vec<T, N>>,
                "locus: Vec<T, N> must have the layout of T[N]");
  return {reinterpret_cast<const Vec<T, N>*>(flat), n};
}

}  // namespace locus
