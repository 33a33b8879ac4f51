// SPDX-License-Identifier: BSL-1.0
#pragma once
// The result of every distance query, distance(a, b), and the closest_point(p, obj) shorthand;
// the foundation of rows dist2.* and dist3.* (book chapters 6 and 10).
//
// Distance<T, N, ParamA, ParamB> holds
//   distance      >= 0, the Euclidean distance between the two objects;
//   sqr_distance  its square (computed first; distance = sqrt(sqr_distance) up to rounding);
//   closest[0]    a point of the first argument, closest[1] a point of the second, with
//                 |closest[0] - closest[1]| = distance (up to rounding);
//   param_a       the first argument's parameter of closest[0], in the parametrisation of that
//                 primitive's point_at (Segment: t in [0, 1]; Line: t in R; Ray: t >= 0;
//                 Triangle: barycentric (u, v, w); a point: NoParam), and param_b likewise;
//   unique        false when infinitely many closest pairs exist (parallel lines, overlapping
//                 parallel segments, ...); one of them is returned.
// Index 0 always refers to the first argument: distance(b, a) is swapped(distance(a, b)), bit
// for bit. Solid objects (triangles, rectangles, boxes, disks) are filled: inside is distance 0.
//
// Bad input (every pair): any NaN or infinite coordinate, direction or size gives
// non_finite_distance(): distance = sqr_distance = NaN, closest points and parameters NaN,
// unique = false; no query loops or divides by zero. Zero directions and sizes are not errors:
// the object degenerates (a zero-length segment acts as its point). Finite input large enough to
// overflow the squared distance gives inf.
// sqr_distance(a, b) (both orders, where a pair header offers it) returns the same bits as
// distance(a, b).sqr_distance without the points, parameters and root; NaN for non-finite input.
// Many 3D queries at once: sqr_distances() in batch.hpp. Cost: an aggregate of at most 2 N + 8
// scalars; no allocation.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <type_traits>

namespace locus {

/// The (empty) parameter of a point: a point has nothing to parametrise.
struct NoParam {
  friend constexpr bool operator==(NoParam, NoParam) noexcept { return true; }
};

/// A point is its own point_at: point_at(p, NoParam{}) == p (lets generic code treat points as
/// 0-dimensional primitives).
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> point_at(const Vec<T, N>& p, NoParam) noexcept {
  return p;
}

/// The result of distance(a, b); see the header comment for each field.
template <class T, int N, class ParamA, class ParamB>
struct Distance {
  using scalar_type = T;
  using param_a_type = ParamA;
  using param_b_type = ParamB;
  static constexpr int dimension = N;

  T distance{};                        ///< >= 0 (NaN for non-finite input)
  T sqr_distance{};                    ///< distance^2, computed without a square root
  std::array<Vec<T, N>, 2> closest{};  ///< [0] lies on the first argument, [1] on the second
  ParamA param_a{};                    ///< parameter of closest[0] on the first argument
  ParamB param_b{};                    ///< parameter of closest[1] on the second argument
  bool unique = true;                  ///< false: infinitely many closest pairs, one returned
};

/// The same answer for the swapped query distance(b, a).
template <class T, int N, class PA, class PB>
[[nodiscard]] constexpr Distance<T, N, PB, PA> swapped(const Distance<T, N, PA, PB>& d) noexcept {
  return {d.distance, d.sqr_distance, {d.closest[1], d.closest[0]}, d.param_b, d.param_a, d.unique};
}

namespace detail {

template <class P>
[[nodiscard]] constexpr P nan_param() noexcept {
  if constexpr (std::is_floating_point_v<P>) {
    return std::numeric_limits<P>::quiet_NaN();
  } else if constexpr (std::is_same_v<P, NoParam>) {
    return NoParam{};
  } else {
    // Vec<T, M> parameters (barycentric, box coordinates): every component NaN.
    P p{};
    using S = std::remove_cvref_t<decltype(p[0])>;
    constexpr int m = static_cast<int>(sizeof(P) / sizeof(S));
    for (int i = 0; i < m; ++i) p[i] = std::numeric_limits<S>::quiet_NaN();
    return p;
  }
}

/// Builds a result from its two closest points: the distance is measured between them, so
/// |closest[0] - closest[1]| == distance holds to one rounding.
template <class T, int N, class PA, class PB>
[[nodiscard]] inline Distance<T, N, PA, PB> make_distance(const Vec<T, N>& ca, const Vec<T, N>& cb,
                                                          PA pa, PB pb, bool unique) noexcept {
  const Vec<T, N> diff = ca - cb;
  const T sq = sqr_length(diff);
  return {length(diff), sq, {ca, cb}, pa, pb, unique};
}

}  // namespace detail

/// The result for non-finite input: everything NaN, unique = false.
template <class T, int N, class PA, class PB>
[[nodiscard]] constexpr Distance<T, N, PA, PB> non_finite_distance() noexcept {
  constexpr T nan = std::numeric_limits<T>::quiet_NaN();
  return {nan,
          nan,
          {splat<T, N>(nan), splat<T, N>(nan)},
          detail::nan_param<PA>(),
          detail::nan_param<PB>(),
          false};
}

/// The point of `obj` closest to p: distance(p, obj).closest[1]. Works for every object that
/// has a point-object distance query (include its pair header first).
template <class T, int N, class Obj>
[[nodiscard]] inline Vec<T, N> closest_point(const Vec<T, N>& p,
                                             const Obj& obj) noexcept requires requires {
  distance(p, obj);
}
{ return distance(p, obj).closest[1]; }

}  // namespace locus
