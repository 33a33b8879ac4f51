// SPDX-License-Identifier: BSL-1.0
#pragma once
// Engine of the plane sections of the sphere, the cylinder and the cone (row int3.plane-quadric):
// the result type PlaneConic3 and its sampler. Internal: include plane_sphere.hpp,
// plane_cylinder.hpp or plane_cone.hpp. Compiled once in src/intersection/plane_quadric.cpp (in
// double). Derivation: docs/notes/intersection3.md, "Plane sections of quadrics".

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/cone.hpp>
#include <locus/primitives/cylinder.hpp>
#include <locus/primitives/plane.hpp>
#include <locus/primitives/sphere.hpp>

#include <cmath>
#include <cstdint>
#include <string_view>

namespace locus {

/// The kind of a plane section of a quadric surface.
enum class ConicType : std::uint8_t {
  empty,           ///< no common point
  point,           ///< one point (center)
  line,            ///< one line (center + s axis[0]), a tangent plane
  parallel_lines,  ///< two parallel lines through center and other, direction axis[0]
  crossing_lines,  ///< two lines through center with directions axis[0], axis[1]
  circle,          ///< center, radius extent[0] = extent[1], in-plane axes axis[0], axis[1]
  ellipse,         ///< center, semi-axes extent[0] >= extent[1] along axis[0], axis[1]
  parabola,        ///< vertex center, opening along axis[0], focal length extent[0]
  hyperbola,       ///< center, transverse semi-axis extent[0] along axis[0], conjugate extent[1]
};

[[nodiscard]] constexpr std::string_view to_string(ConicType t) noexcept {
  constexpr std::string_view names[] = {"empty",          "point",          "line",
                                        "parallel_lines", "crossing_lines", "circle",
                                        "ellipse",        "parabola",       "hyperbola"};
  return names[static_cast<int>(t)];
}

/// A conic in a plane of 3D (see ConicType for the meaning of each field per type). axis[0],
/// axis[1] are unit, orthogonal for circle, ellipse, parabola and hyperbola; normal is the unit
/// plane normal. focus[0], focus[1]: the foci of an ellipse / hyperbola (on axis[0]); focus[0]
/// of a parabola (center + extent[0] axis[0]); a circle's foci are its center.
template <Real T>
struct PlaneConic3 {
  ConicType type = ConicType::empty;
  Vec3<T> center{};
  Vec3<T> axis[2]{};
  T extent[2]{};
  Vec3<T> focus[2]{};
  Vec3<T> other{};
  Vec3<T> normal{};
};

/// A point of the conic for the parameter s: circle/ellipse center + e0 cos s a0 + e1 sin s a1;
/// hyperbola branch b (0: towards +axis[0], 1: -axis[0]) center +- e0 cosh s a0 + e1 sinh s a1;
/// parabola center + s^2 / (4 e0) a0 + s a1; lines center (or other for branch 1 of parallel
/// lines) + s axis[branch] (crossing lines) / + s axis[0]; a point: center.
template <Real T>
[[nodiscard]] inline Vec3<T> point_at(const PlaneConic3<T>& c, T s, int branch = 0) noexcept {
  switch (c.type) {
    case ConicType::circle:
    case ConicType::ellipse:
      return c.center + (c.extent[0] * std::cos(s)) * c.axis[0] +
             (c.extent[1] * std::sin(s)) * c.axis[1];
    case ConicType::hyperbola:
      return c.center + ((branch == 0 ? T(1) : T(-1)) * c.extent[0] * std::cosh(s)) * c.axis[0] +
             (c.extent[1] * std::sinh(s)) * c.axis[1];
    case ConicType::parabola:
      return c.center + (s * s / (T(4) * c.extent[0])) * c.axis[0] + s * c.axis[1];
    case ConicType::line:
      return c.center + s * c.axis[0];
    case ConicType::parallel_lines:
      return (branch == 0 ? c.center : c.other) + s * c.axis[0];
    case ConicType::crossing_lines:
      return c.center + s * c.axis[branch == 0 ? 0 : 1];
    default:
      return c.center;
  }
}

namespace detail::plane_quadric3 {

using V = Vec3<double>;
using C = PlaneConic3<double>;

// Compiled in src/intersection/plane_quadric.cpp.
[[nodiscard]] C section(const V& normal, double constant, const V& center, double radius) noexcept;
[[nodiscard]] C section(const V& normal, double constant, const V& center, const V& axis,
                        double radius) noexcept;
[[nodiscard]] C section(const V& normal, double constant, const V& vertex, const V& axis,
                        double angle, bool) noexcept;

template <Real T>
[[nodiscard]] constexpr PlaneConic3<T> cast(const C& c) noexcept {
  PlaneConic3<T> r;
  r.type = c.type;
  r.center = vec_cast<T>(c.center);
  r.other = vec_cast<T>(c.other);
  r.normal = vec_cast<T>(c.normal);
  for (int i = 0; i < 2; ++i) {
    r.axis[i] = vec_cast<T>(c.axis[i]);
    r.extent[i] = static_cast<T>(c.extent[i]);
    r.focus[i] = vec_cast<T>(c.focus[i]);
  }
  return r;
}

}  // namespace detail::plane_quadric3
}  // namespace locus
