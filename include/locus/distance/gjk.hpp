// SPDX-License-Identifier: BSL-1.0
#pragma once
// GJK distance and EPA penetration depth between convex shapes given by support mappings (any
// shape of distance/support.hpp, or a user type with support()); rows dist2.gjk and dist3.gjk;
// book section 6.10 (figures 6.24-6.29).
//
// gjk_distance(a, b, options) -> GjkDistance<T, N>:
//   status       Status::ok; non_finite_input (a NaN/infinite support point or margin: every
//                number NaN); limit_exceeded (options.max_iterations ran out: the fields hold
//                the best answer so far, an upper bound on the distance).
//   contact      separated (distance > contact tolerance), touching (|signed distance| <=
//                tolerance: the boundaries meet), intersecting (the interiors overlap by more
//                than the tolerance).
//   distance, sqr_distance  >= 0; 0 unless separated-or-touching at positive distance.
//   closest[0] on a, closest[1] on b, |closest[1] - closest[0]| = distance; when the shapes
//                intersect both are (up to rounding) one common point.
//   normal       unit vector from a towards b ((closest[1] - closest[0]) / distance when
//                separated); when intersecting, the direction of the last search (the zero
//                vector if none is known: call penetration() for a meaningful one).
//   iterations   support queries of the main loop; simplex the final simplex (points on a and
//                b with barycentric weights; its Minkowski points are a[i] - b[i]).
// penetration(a, b, options) -> Penetration<T, N>: GJK, then (when the shapes are not clearly
// separated) EPA on the final simplex.
//   depth        > 0 penetration depth: translating b by depth * normal makes the shapes touch
//                (the shortest such translation); < 0 when separated, -depth is the distance.
//   normal       unit, from a towards b; closest[0] on a, closest[1] on b with
//                closest[0] - closest[1] = depth * normal (the deepest points).
//   status       ok; non_finite_input; limit_exceeded (budget or EPA capacity exhausted: the
//                best bounds so far, depth is a lower bound); degenerate_input: the Minkowski
//                difference a - b is flat (no interior: coplanar flat shapes, segments, ...), so
//                the depth is 0 plus the margins and the normal is a normal of its flat hull.
//   contact      as for gjk_distance, decided from depth and the contact tolerance.
//
// Method (GJK, figures 6.25-6.28): V_0 is a point of the Minkowski difference A - B; at step k
// W_k = s_A(-V_k) - s_B(V_k) is the support point of A - B farthest along -V_k, and V_{k+1} is
// the point of conv(S_k + {W_k}) nearest to the origin, S_{k+1} the smallest subset containing
// it (figure 6.29). The nearest point of a simplex is found by the signed-volumes subalgorithm
// (Montanari, Petrinic and Barbieri, "Improving the GJK algorithm for faster and more reliable
// distance queries between convex objects", ACM TOG 2017): barycentric coordinates from signed
// areas/volumes in the best-conditioned coordinate projection, recursing only into faces that
// the origin lies beyond and that contain W_k (V_{k+1} beats V_k, the nearest point of the
// faces without W_k); in full dimension the signs are EXACT (orient2d / orient3d of
// core/predicates.hpp), so "the origin is inside" is never a rounding accident. Termination
// (van den Bergen 1999): |V|^2 - V.W <= relative_tolerance |V|^2 (the distance is then known to
// that relative accuracy), or W repeats a simplex point (exact for polytopes), or |V| stops
// decreasing (the rounding floor), or the origin is enclosed. Round parts (ball radii, capsule
// radii, margins) are removed first and added back (support.hpp), so spheres and capsules are
// exact after one or two steps.
// EPA (van den Bergen, "Proximity queries and penetration depth computation on 3D game
// objects", GDC 2001): the GJK simplex containing the origin is raised to full dimension with
// support points along +-n for n orthogonal to it (if one of them lies in the plane through the
// origin, the origin is on the boundary: touching, depth 0); the polytope is then expanded at
// the face nearest to the origin until the support point along its normal is no farther than
// the face (relative_tolerance) or repeats a vertex. Faces are kept convex with exact orient3d /
// orient2d visibility tests; capacity is fixed (epa_max_vertices), so nothing is allocated.
//
// Tolerances: relative_tolerance (default 64 eps(T)) bounds the relative error of the
// distance/depth; contact_tolerance (absolute; default 64 eps(T) times the largest support
// coordinate seen) separates touching from separated/intersecting. Accuracy: distances between
// polytopes agree with the exact minimum over feature pairs to a few ulps of the coordinate
// scale (tests/distance/gjk_test.cpp; bench/distance/gjk_bench.cpp compares with libccd/FCL).
//
// Float shapes are computed in double internally (compute_t). Cost: a handful of support calls
// (each O(1), or O(n) for ConvexPoints) and O(N^3) per step; EPA O(h + log F) per added vertex
// (h faces replaced, a lazy min-heap of faces). Measured (bench/distance/gjk_bench.cpp, two
// random 32-vertex polyhedra, CPU time on a loaded shared machine, medians of 3-5 repetitions
// over four runs): distance 1.6-1.8x the speed of FCL's GJKSolver_libccd and 3-3.2x
// GJKSolver_indep; error <= 1e-15 on generic, near-contact (gap 1e-9 .. 1e-6) and face-face
// (nearly parallel faces) pairs, where FCL's solvers are off by up to 2e-8 (face-face) and 4e-3
// (near contact). Penetration: 1.7-1.9x faster than libccd's GJK + EPA and exact where libccd
// and FCL are off by 0.2 .. 2 on unit shapes; slower than MPR (libccd, FCL's libccd solver),
// which is not a penetration depth.
// Nothing allocates unless options.trace is set; EPA uses about 60 KB of stack.

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
  T contact_tolerance = T(-1);  ///< < 0: 64 eps(T) times the largest support coordinate
  int max_iterations = 128;     ///< GJK support queries; EPA gets as many again
  Vec<T, N> initial_direction{};  ///< V_0 = support along this (zero: the first axis)
  GjkTrace<T, N>* trace = nullptr;  ///< if set, cleared and filled with the GJK steps
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
