// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a point and a solid tetrahedron; row dist3.pt-polyhedron (tetrahedron part);
// book section 10.3.4 (figure 10.20).
//
// distance(p, tet) returns Distance<T, 3, NoParam, Vec4<T>>: closest[1] = the point of the solid
// tetrahedron nearest to p (p itself when p is inside or on the boundary: distance exactly 0),
// param_b = its barycentric coordinates b (sum 1, all >= 0; closest[1] ~
// point_at_barycentric(tet, b), exact at the vertices). distance(tet, p) is the swapped result.
// Either vertex orientation is accepted.
//
// Method: the inside test is exact (orient3d of core/predicates.hpp against the four faces with
// outward normals). Outside, the nearest point lies on a face whose plane p is strictly outside
// of (at the nearest point q, p - q is a non-negative combination of the outward normals of the
// faces through q), so only those faces (one to three) are queried with point_triangle.hpp and
// the nearest wins; the face's barycentric coordinates are spread onto the tetrahedron's. Inside,
// b comes from the four sub-volumes (rounded, clamped to >= 0 and normalised).
//
// Degenerate input: a flat tetrahedron (coplanar vertices, orientation 0) has no interior; its
// solid is the union of its four faces, all of which are queried (collinear or coincident
// vertices make them segments or points). NaN or infinite coordinates give
// non_finite_distance() (result.hpp). unique is always true (convex). Cost: O(1): at most four
// orient3d and four point-triangle queries; no allocation.

#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/point_triangle.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/tetrahedron.hpp>
#include <locus/primitives/triangle.hpp>

#include <limits>

namespace locus {

/// Distance from p to the solid tetrahedron; param_b is barycentric (4 coordinates).
template <Real T>
[[nodiscard]] inline Distance<T, 3, NoParam, Vec4<T>> distance(
    const Vec3<T>& p, const Tetrahedron3<T>& tet) noexcept {
  if (!is_finite(p) || !is_finite(tet.v[0]) || !is_finite(tet.v[1]) || !is_finite(tet.v[2]) ||
      !is_finite(tet.v[3]))
    return non_finite_distance<T, 3, NoParam, Vec4<T>>();
  // Faces opposite vertex i with outward normals, for either orientation.
  static constexpr int pos[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  static constexpr int neg[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};
  const int o = to_int(orient3d(tet.v[0], tet.v[1], tet.v[2], tet.v[3]));
  const auto& face = o < 0 ? neg : pos;
  T best = std::numeric_limits<T>::infinity();
  Vec3<T> q = p;
  Vec4<T> bary{};
  bool outside = o == 0;
  for (int i = 0; i < 4; ++i) {
    const Vec3<T>&a = tet.v[face[i][0]], &b = tet.v[face[i][1]], &c = tet.v[face[i][2]];
    if (o != 0 && orient3d(a, b, c, p) != Sign::positive) continue;
    outside = true;
    const auto r = distance(p, Triangle3<T>{a, b, c});
    if (r.sqr_distance < best) {
      best = r.sqr_distance;
      q = r.closest[1];
      bary = Vec4<T>{};
      for (int k = 0; k < 3; ++k) bary[face[i][k]] = r.param_b[k];
    }
  }
  if (!outside) {
    // Sub-volumes det[v_j - p, v_k - p, v_l - p] for the faces, relative to the whole.
    T w[4], sum = T(0);
    for (int i = 0; i < 4; ++i) {
      const Vec3<T> a = tet.v[face[i][0]] - p, b = tet.v[face[i][1]] - p, c = tet.v[face[i][2]] - p;
      w[i] = dot(a, cross(b, c));
      w[i] = w[i] > T(0) ? w[i] : T(0);
      sum += w[i];
    }
    for (int i = 0; i < 4; ++i) bary[i] = sum > T(0) ? w[i] / sum : T(0.25);
    return detail::make_distance(p, p, NoParam{}, bary, true);
  }
  return detail::make_distance(p, q, NoParam{}, bary, true);
}

/// The swapped query: closest[0] and param_a belong to the tetrahedron.
template <Real T>
[[nodiscard]] inline Distance<T, 3, Vec4<T>, NoParam> distance(const Tetrahedron3<T>& tet,
                                                               const Vec3<T>& p) noexcept {
  return swapped(distance(p, tet));
}

}  // namespace locus
