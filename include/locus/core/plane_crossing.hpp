// SPDX-License-Identifier: BSL-1.0
#pragma once
// Exact order of the points where segments cross planes, and those points rounded from their
// exact values (row core.predicates; used by int3.plane-mesh's plane-polygon and
// polygon-triangle queries, book section 11.5.6). A crossing is the point of the segment a -> b
// where the plane's value changes sign, x = (f(a) b - f(b) a) / (f(a) - f(b)), or a point given
// outright (a vertex lying in a plane). A plane is either { X : dot(n, X) = c } as given, with
// f(X) = dot(n, X) - c, or the plane through three points, with f(X) = orient3d(p0, p1, p2, X);
// both are decided on the data AS GIVEN, never on a normalised copy, so crossings of different
// planes compare exactly too.
//   rank_plane_crossings(crossings, axis) gives each crossing its rank in the exact order of
//     the crossings' coordinate `axis` (0, 1, 2): equal coordinates get equal ranks, ranks run
//     0, 1, ... without gaps. Ordering points of one line along the coordinate in which the
//     line's direction is largest orders them along the line; for points that are not exactly
//     collinear (rounded data) it is still one exact, consistent order.
//   Each crossing's `point` is written back rounded from its exact value: every coordinate
//     within one unit in the last place of the exact one (faithful rounding).
// Preconditions: finite data; a segment crossing has f(a) and f(b) of strictly opposite exact
// signs (callers decide the sides first, with side_of_plane or orient3d); otherwise the crossing
// is treated as the point a. Method: every coordinate is an integer times a power of two, so
// f(a), f(b) and the numerators and denominators of x are exact integers on core's big integer
// (src/core/big_int.hpp), scaled by one common power of two per call; comparisons cross-multiply.
// Cost: O(n log n) comparisons of integers a few hundred bits long for data of one magnitude
// (longer when the exponents of the data spread); allocates.

#include <locus/core/vec.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace locus {

/// A plane, exactly as given: dot(normal, X) = constant, or through three points.
struct ExactPlane3 {
  bool through_points = false;    ///< true: the plane through p0, p1, p2 (orient3d's sign)
  Vec3<double> normal{};          ///< used when !through_points
  double constant = 0.0;          ///< used when !through_points
  Vec3<double> p0{}, p1{}, p2{};  ///< used when through_points

  [[nodiscard]] static ExactPlane3 from_normal(const Vec3<double>& n, double c) noexcept {
    ExactPlane3 p;
    p.normal = n;
    p.constant = c;
    return p;
  }
  [[nodiscard]] static ExactPlane3 from_points(const Vec3<double>& a, const Vec3<double>& b,
                                               const Vec3<double>& c) noexcept {
    ExactPlane3 p;
    p.through_points = true;
    p.p0 = a;
    p.p1 = b;
    p.p2 = c;
    return p;
  }
};

/// The crossing of segment a -> b with *plane, or the point a itself when plane is null.
struct PlaneCrossing3 {
  const ExactPlane3* plane = nullptr;
  Vec3<double> a{}, b{};
  Vec3<double> point{};  ///< output: the crossing rounded from its exact value
  std::size_t rank = 0;  ///< output: rank of its coordinate `axis` in the exact order
};

/// Ranks (and rounded points) of the crossings along coordinate `axis`; see the header comment.
void rank_plane_crossings(std::span<PlaneCrossing3> crossings, int axis);

}  // namespace locus
