// SPDX-License-Identifier: BSL-1.0
#pragma once
// GJK distance and EPA penetration depth between convex shapes given by support mappings (any
// shape of distance/support.hpp, or a user type with support()); rows dist2.gjk, dist3.gjk;
// book section 6.10, figures 6.24-6.29. Method and accuracy: docs/notes/distance.md.
//
// gjk_distance(a, b, options) -> GjkDistance<T, N>:
//   contact      separated, touching (|signed distance| <= contact tolerance) or intersecting.
//   distance, sqr_distance >= 0 (0 when intersecting); closest[0] on a, closest[1] on b,
//                |closest[1] - closest[0]| = distance (one common point when intersecting).
//   normal       unit, from a towards b; when intersecting the last search direction (zero if
//                none is known: call penetration() for a meaningful one).
//   iterations   support queries of the main loop; simplex: the final simplex (points on a and
//                b with barycentric weights; its Minkowski points are a[i] - b[i]).
// penetration(a, b, options) -> Penetration<T, N> (GJK, then EPA unless clearly separated):
//   depth        > 0: translating b by depth * normal makes the shapes touch (shortest such
//                translation); < 0 when separated (-depth is the distance).
//   normal       unit, from a towards b; closest[0] - closest[1] = depth * normal.
// Status: ok; non_finite_input (a NaN/Inf support point or margin: every number NaN);
// limit_exceeded (max_iterations or EPA's epa_max_vertices ran out: the best bounds so far, an
// upper bound on the distance, a lower bound on the depth); degenerate_input (penetration only:
// a - b has no interior, depth 0 plus the margins, normal a normal of its flat hull).
// Tolerances: relative_tolerance (default 64 eps(T)) bounds the relative error of the
// distance/depth; contact_tolerance (absolute; default 64 eps(T) times the largest support
// coordinate seen). Inside/outside decisions use exact orient2d/orient3d (core/predicates.hpp).
// Float shapes are computed in double. Cost: a few support calls and O(N^3) per step; EPA
// O(h + log F) per vertex. Nothing allocates unless options.trace is set (EPA: ~60 KB of stack).

#include <locus/config.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/support.hpp>

#include <array>
#include <concepts>
#include <cstdint>
#include <vector>

namespace locus {

/// How two shapes relate (gjk_distance, penetration).
enum class Contact : std::uint8_t {
  separated,     ///< positive distance (beyond the contact tolerance)
  touching,      ///< the boundaries meet, the interiors do not overlap (within the tolerance)
  intersecting,  ///< the interiors overlap
};

/// A GJK simplex: size points of A - B, each a[i] - b[i] with a[i] on the first shape and b[i]
/// on the second (margins excluded: these are points of the cores), weight[i] its barycentric
/// coordinate of the simplex point nearest to the origin.
template <class T, int N>
struct GjkSimplex {
  int size = 0;
  std::array<Vec<T, N>, N + 1> a{};
  std::array<Vec<T, N>, N + 1> b{};
  std::array<T, N + 1> weight{};
};

/// One GJK iteration (figures 6.25-6.28): v = V_k, w = W_k = the support point of A - B along
/// -V_k, simplex = S_{k+1} (the smallest subset of S_k + {W_k} containing V_{k+1}), v_next =
/// V_{k+1}. The last step of a run that converged has simplex = S_k and v_next = v.
template <class T, int N>
struct GjkStep {
  Vec<T, N> v{};
  Vec<T, N> w{};
  GjkSimplex<T, N> simplex{};
  Vec<T, N> v_next{};
};

/// The steps of one run (cores only: margins are not part of the trace).
template <class T, int N>
struct GjkTrace {
  Vec<T, N> v0{};  ///< V_0, the starting point of A - B
  std::vector<GjkStep<T, N>> steps;
};

/// Options of gjk_distance and penetration.
template <class T, int N>
struct GjkOptions {
  T relative_tolerance = T(64) * eps_v<T>;  ///< stop when the distance is this accurate
  T contact_tolerance = T(-1);              ///< < 0: 64 eps(T) times the largest support coordinate
  int max_iterations = 128;                 ///< GJK support queries; EPA gets as many again
  Vec<T, N> initial_direction{};            ///< V_0 = support along this (zero: the first axis)
  GjkTrace<T, N>* trace = nullptr;          ///< if set, cleared and filled with the GJK steps
};

/// Result of gjk_distance (see the header comment).
template <class T, int N>
struct GjkDistance {
  Status status = Status::empty_input;
  Contact contact = Contact::separated;
  T distance{};
  T sqr_distance{};
  std::array<Vec<T, N>, 2> closest{};
  Vec<T, N> normal{};
  int iterations = 0;
  GjkSimplex<T, N> simplex{};
};

/// Result of penetration (see the header comment).
template <class T, int N>
struct Penetration {
  Status status = Status::empty_input;
  Contact contact = Contact::separated;
  T depth{};
  Vec<T, N> normal{};
  std::array<Vec<T, N>, 2> closest{};
  int iterations = 0;
};

/// Largest number of polytope vertices EPA builds (then: Status::limit_exceeded).
inline constexpr int epa_max_vertices = 128;

namespace detail {

/// A type-erased core support mapping: core(shape, d) plus the round part's radius.
template <class T, int N>
struct SupportMap {
  const void* shape;
  Vec<T, N> (*core)(const void*, const Vec<T, N>&) noexcept;
  T margin;
};

template <class S>
[[nodiscard]] inline SupportMap<support_scalar_t<S>, support_dimension_v<S>> make_support_map(
    const S& s) noexcept {
  using T = support_scalar_t<S>;
  constexpr int n = support_dimension_v<S>;
  return {&s,
          [](const void* p, const Vec<T, n>& d) noexcept -> Vec<T, n> {
            return core_support(*static_cast<const S*>(p), d);
          },
          core_margin(s)};
}

template <Real T, int N>
[[nodiscard]] GjkDistance<T, N> gjk_distance(const SupportMap<T, N>& a, const SupportMap<T, N>& b,
                                             const GjkOptions<T, N>& options) noexcept;
template <Real T, int N>
[[nodiscard]] Penetration<T, N> penetration(const SupportMap<T, N>& a, const SupportMap<T, N>& b,
                                            const GjkOptions<T, N>& options) noexcept;

extern template GjkDistance<float, 2> gjk_distance(const SupportMap<float, 2>&,
                                                   const SupportMap<float, 2>&,
                                                   const GjkOptions<float, 2>&) noexcept;
extern template GjkDistance<float, 3> gjk_distance(const SupportMap<float, 3>&,
                                                   const SupportMap<float, 3>&,
                                                   const GjkOptions<float, 3>&) noexcept;
extern template GjkDistance<double, 2> gjk_distance(const SupportMap<double, 2>&,
                                                    const SupportMap<double, 2>&,
                                                    const GjkOptions<double, 2>&) noexcept;
extern template GjkDistance<double, 3> gjk_distance(const SupportMap<double, 3>&,
                                                    const SupportMap<double, 3>&,
                                                    const GjkOptions<double, 3>&) noexcept;
extern template Penetration<float, 2> penetration(const SupportMap<float, 2>&,
                                                  const SupportMap<float, 2>&,
                                                  const GjkOptions<float, 2>&) noexcept;
extern template Penetration<float, 3> penetration(const SupportMap<float, 3>&,
                                                  const SupportMap<float, 3>&,
                                                  const GjkOptions<float, 3>&) noexcept;
extern template Penetration<double, 2> penetration(const SupportMap<double, 2>&,
                                                   const SupportMap<double, 2>&,
                                                   const GjkOptions<double, 2>&) noexcept;
extern template Penetration<double, 3> penetration(const SupportMap<double, 3>&,
                                                   const SupportMap<double, 3>&,
                                                   const GjkOptions<double, 3>&) noexcept;

}  // namespace detail

/// GJK distance between two convex shapes of the same scalar type and dimension.
template <SupportMapped A, SupportMapped B>
requires std::same_as<support_scalar_t<A>, support_scalar_t<B>> &&
    (support_dimension_v<A> == support_dimension_v<B>)
        [[nodiscard]] inline GjkDistance<support_scalar_t<A>, support_dimension_v<A>> gjk_distance(
            const A& a, const B& b,
            const GjkOptions<support_scalar_t<A>, support_dimension_v<A>>& options = {}) noexcept {
  return detail::gjk_distance(detail::make_support_map(a), detail::make_support_map(b), options);
}

/// Penetration depth (EPA) or, when separated, minus the distance.
template <SupportMapped A, SupportMapped B>
requires std::same_as<support_scalar_t<A>, support_scalar_t<B>> &&
    (support_dimension_v<A> == support_dimension_v<B>)
        [[nodiscard]] inline Penetration<support_scalar_t<A>, support_dimension_v<A>> penetration(
            const A& a, const B& b,
            const GjkOptions<support_scalar_t<A>, support_dimension_v<A>>& options = {}) noexcept {
  return detail::penetration(detail::make_support_map(a), detail::make_support_map(b), options);
}

}  // namespace locus
