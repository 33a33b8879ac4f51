// SPDX-License-Identifier: BSL-1.0
#pragma once
// Tetrahedra; row prim3.solids; book section 9.3 (polyhedra; the tetrahedron of figures 9.11
// and 9.17, and the point-tetrahedron distance of figure 10.20).
//
// Tetrahedron3<T> {v[4]}. Orientation: orientation(tet) is the EXACT sign of
// orient3d(v0, v1, v2, v3) (core/predicates.hpp): positive when v3 lies on the side of the plane
// v0 v1 v2 that (v1 - v0) x (v2 - v0) points to. signed_volume() = det[v1 - v0, v2 - v0,
// v3 - v0] / 6 is computed in floating point (rounded) but its sign is forced to agree with
// orientation(): when the rounded magnitude is 0 and the exact sign is not, the smallest
// subnormal of that sign is returned, so sign(signed_volume) == orientation always.
//
// Faces: face(tet, i) is the triangle opposite vertex i, ordered so that its normal
// (Triangle's normal(), (b - a) x (c - a)) points OUT of the tetrahedron. For a positively
// oriented tetrahedron the faces are (v1 v2 v3), (v0 v3 v2), (v0 v1 v3), (v0 v2 v1); for a
// negatively oriented one each is reversed. A flat tetrahedron (orientation 0) gets the
// positive table; its "outward" normals are then meaningless.
//
// Parametrisations (as Triangle's): point_at(tet, (s, t, u)) = v0 + s (v1 - v0) + t (v2 - v0) +
// u (v3 - v0), the solid being s, t, u >= 0, s + t + u <= 1; point_at_barycentric(tet, b) =
// sum b_i v_i with sum b_i = 1 (exact at the vertices).
//
// Degenerate input: coplanar or coincident vertices give orientation 0, volume 0 (exactly: the
// sign fix forces 0 as well) and is_degenerate() true. Non-finite coordinates: orient3d reports
// Sign::zero for them, so orientation() is 0, signed_volume() 0 and is_degenerate() true.
// Cost O(1); orient3d is adaptive (exact fallback only near zero); no allocation.

#include <locus/config.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/aligned_box.hpp>
#include <locus/primitives/triangle.hpp>

#include <cmath>
#include <limits>

namespace locus {

/// The tetrahedron with vertices v[0..3].
template <Real T>
struct Tetrahedron3 {
  Vec3<T> v[4];
};

using Tetrahedron3f = Tetrahedron3<float>;
using Tetrahedron3d = Tetrahedron3<double>;

/// Exact sign of orient3d(v0, v1, v2, v3): +1, 0 or -1.
template <Real T>
[[nodiscard]] inline int orientation(const Tetrahedron3<T>& t) noexcept {
  return static_cast<int>(orient3d(t.v[0], t.v[1], t.v[2], t.v[3]));
}

/// True when the vertices are (exactly) coplanar.
template <Real T>
[[nodiscard]] inline bool is_degenerate(const Tetrahedron3<T>& t) noexcept {
  return orientation(t) == 0;
}

/// det[v1 - v0, v2 - v0, v3 - v0] / 6, rounded, with the exact sign of orientation().
template <Real T>
[[nodiscard]] inline T signed_volume(const Tetrahedron3<T>& t) noexcept {
  const int s = orientation(t);
  if (s == 0) return T(0);
  const T vol = dot(cross(t.v[1] - t.v[0], t.v[2] - t.v[0]), t.v[3] - t.v[0]) / T(6);
  if (vol != vol) return vol;  // NaN input: nothing to fix
  const T mag = std::fabs(vol) > T(0) ? std::fabs(vol) : std::numeric_limits<T>::denorm_min();
  return s > 0 ? mag : -mag;
}

/// |signed_volume|.
template <Real T>
[[nodiscard]] inline T volume(const Tetrahedron3<T>& t) noexcept {
  return std::fabs(signed_volume(t));
}

/// The face opposite vertex i, ordered so that its normal points outward.
template <Real T>
[[nodiscard]] inline Triangle3<T> face(const Tetrahedron3<T>& t, int i) noexcept {
  LOCUS_ASSERT(i >= 0 && i < 4, "Tetrahedron face index out of range");
  static constexpr int table[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  const int* f = table[i];
  if (orientation(t) < 0) return {t.v[f[0]], t.v[f[2]], t.v[f[1]]};
  return {t.v[f[0]], t.v[f[1]], t.v[f[2]]};
}

/// Outward normal of face i, (b - a) x (c - a) of face(t, i): length twice the face area.
template <Real T>
[[nodiscard]] inline Vec3<T> face_normal(const Tetrahedron3<T>& t, int i) noexcept {
  const Triangle3<T> f = face(t, i);
  return cross(f.v1 - f.v0, f.v2 - f.v0);
}

/// Sum of the four face areas.
template <Real T>
[[nodiscard]] inline T surface_area(const Tetrahedron3<T>& t) noexcept {
  T s = T(0);
  for (int i = 0; i < 4; ++i) {
    const Triangle3<T> f{t.v[(i + 1) % 4], t.v[(i + 2) % 4], t.v[(i + 3) % 4]};
    s += T(0.5) * length(cross(f.v1 - f.v0, f.v2 - f.v0));
  }
  return s;
}

/// (v0 + v1 + v2 + v3) / 4, summed as quarters so that it cannot overflow.
template <Real T>
[[nodiscard]] constexpr Vec3<T> centroid(const Tetrahedron3<T>& t) noexcept {
  return T(0.25) * t.v[0] + T(0.25) * t.v[1] + T(0.25) * t.v[2] + T(0.25) * t.v[3];
}

/// v0 + s (v1 - v0) + t (v2 - v0) + u (v3 - v0) with stu = (s, t, u).
template <Real T>
[[nodiscard]] constexpr Vec3<T> point_at(const Tetrahedron3<T>& t, const Vec3<T>& stu) noexcept {
  return t.v[0] + stu.x * (t.v[1] - t.v[0]) + stu.y * (t.v[2] - t.v[0]) + stu.z * (t.v[3] - t.v[0]);
}

/// sum b_i v_i (barycentric; exact at the vertices).
template <Real T>
[[nodiscard]] constexpr Vec3<T> point_at_barycentric(const Tetrahedron3<T>& t,
                                                     const Vec4<T>& b) noexcept {
  return b.x * t.v[0] + b.y * t.v[1] + b.z * t.v[2] + b.w * t.v[3];
}

/// The box of the four vertices.
template <Real T>
[[nodiscard]] constexpr AlignedBox3<T> bounding_box(const Tetrahedron3<T>& t) noexcept {
  AlignedBox3<T> b{t.v[0], t.v[0]};
  for (int i = 1; i < 4; ++i) b = expand(b, t.v[i]);
  return b;
}

}  // namespace locus
