// SPDX-License-Identifier: BSL-1.0
#pragma once
// A planar polygon in 3D against a plane and against a triangle; row int3.plane-mesh, book
// section 11.5.6 (figures 11.30, 11.31). The polygon is its vertices in order (a closed chain,
// first vertex not repeated, convex or not, planar: not checked), filled by the even-odd rule.
// intersection(polygon, Plane3) -> PolygonPlaneIntersection<T>: coplanar (every vertex exactly in
// the plane: the whole polygon) or the pieces of the common line inside the closed polygon, as
// segments ordered along cross(plane normal, polygon normal) (Newell's normal); a zero-length
// piece is a touching point. intersection(polygon, Triangle3) -> PolygonTriangleIntersection<T>:
// the same pieces clipped to the triangle, or, when the polygon lies in the triangle's plane
// (exact orient3d), the polygon clipped by the triangle's edge half-planes (Sutherland-Hodgman).
// Exact: the side of every input vertex (side_of_plane, orient3d), so which edges cross and which
// vertices lie in the plane. Pieces: the crossings of the boundary with the plane are taken under
// both symbolic rules "a vertex in the plane counts as positive" and "... as negative" (each
// gives an even number of crossings, paired along the line), and the union of the two sets of
// intervals is the closed common set (docs/notes/intersection3.md). Rounded: the crossing points
// (as plane_triangle.hpp) and their ORDER along the line (keys dot(direction, point) in double),
// so pieces closer than the rounding may merge or split; clipping against the triangle compares
// the same keys; coplanar clipping decides original vertices exactly and constructed ones on
// rounded values. A non-convex polygon clipped coplanarly keeps Sutherland-Hodgman's
// zero-width bridges between its parts.
// Status: ok; empty_input (fewer than 3 vertices); non_finite_input; degenerate_input (zero
// plane normal, a degenerate triangle, or a polygon whose Newell normal is zero).
// Cost: O(n log n) for n vertices; allocates the result vectors.

#include <locus/core/plane_side.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/intersection/plane_triangle.hpp>
#include <locus/intersection/triangle_triangle.hpp>
#include <locus/primitives/plane.hpp>
#include <locus/primitives/segment.hpp>
#include <locus/primitives/triangle.hpp>

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>
#include <vector>

namespace locus {

/// The common set of a planar polygon and a plane (see the header comment).
template <Real T>
struct PolygonPlaneIntersection {
  Status status = Status::empty_input;
  bool coplanar = false;              ///< the whole polygon lies in the plane
  std::vector<Segment3<T>> segments;  ///< pieces along the common line, in order
};

/// The common set of a planar polygon and a triangle (see the header comment).
template <Real T>
struct PolygonTriangleIntersection {
  Status status = Status::empty_input;
  bool coplanar = false;              ///< polygon in the triangle's plane: see `polygon`
  std::vector<Segment3<T>> segments;  ///< not coplanar: pieces along the common line, in order
  std::vector<Vec3<T>> polygon;       ///< coplanar: the clipped polygon (empty if none)
};

namespace detail::plane_poly {

using V = Vec3<double>;

/// Pieces of the line { side = 0 } inside the polygon; side(i) exact, value(i) rounded, for
/// vertex i; dir orders the line. Each piece is (key, point) pairs.
struct Piece {
  double k0, k1;
  V p0, p1;
};

template <class Side, class Value>
[[nodiscard]] std::vector<Piece> pieces(std::span<const V> v, const Side& side, const Value& value,
                                        const V& dir) {
  const std::size_t n = v.size();
  std::vector<Piece> out;
  for (const int zero_as : {1, -1}) {
    std::vector<std::pair<double, V>> cross;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t j = (i + 1) % n;
      const int si = side(i), sj = side(j);
      const int ri = si == 0 ? zero_as : si, rj = sj == 0 ? zero_as : sj;
      if (ri == rj) continue;
      V x;
      if (si == 0) {
        x = v[i];
      } else if (sj == 0) {
        x = v[j];
      } else {
        const double fi = value(i), fj = value(j);
        const double t = std::clamp(fi / (fi - fj), 0.0, 1.0);
        x = v[i] + t * (v[j] - v[i]);
      }
      cross.push_back({dot(dir, x), x});
    }
    std::sort(cross.begin(), cross.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t k = 0; k + 1 < cross.size(); k += 2) {
      out.push_back({cross[k].first, cross[k + 1].first, cross[k].second, cross[k + 1].second});
    }
  }
  // Union of the two families: sort by start and merge overlapping or touching pieces.
  std::sort(out.begin(), out.end(), [](const Piece& a, const Piece& b) { return a.k0 < b.k0; });
  std::vector<Piece> merged;
  for (const Piece& p : out) {
    if (!merged.empty() && p.k0 <= merged.back().k1) {
      if (p.k1 > merged.back().k1) merged.back().k1 = p.k1, merged.back().p1 = p.p1;
    } else {
      merged.push_back(p);
    }
  }
  return merged;
}

template <Real T>
[[nodiscard]] inline bool finite_all(std::span<const Vec3<T>> v) noexcept {
  return std::all_of(v.begin(), v.end(), [](const Vec3<T>& p) { return is_finite(p); });
}

/// Newell's normal in double.
template <Real T>
[[nodiscard]] inline V newell(std::span<const Vec3<T>> v) noexcept {
  V n{};
  for (std::size_t i = 0; i < v.size(); ++i) {
    const V a = vec_cast<double>(v[i]), b = vec_cast<double>(v[(i + 1) % v.size()]);
    n += V{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
  }
  return n;
}

}  // namespace detail::plane_poly

/// The pieces of a plane inside a planar polygon, or the whole polygon (see the header comment).
template <Real T>
[[nodiscard]] PolygonPlaneIntersection<T> intersection(std::span<const Vec3<T>> polygon,
                                                       const Plane3<T>& plane) {
  namespace pp = detail::plane_poly;
  PolygonPlaneIntersection<T> r;
  if (polygon.size() < 3) return r;
  if (!pp::finite_all(polygon) || !is_finite(plane.normal) || !std::isfinite(plane.constant)) {
    r.status = Status::non_finite_input;
    return r;
  }
  const pp::V nn = pp::newell(polygon);
  if (plane.normal == Vec3<T>{} || nn == pp::V{}) {
    r.status = Status::degenerate_input;
    return r;
  }
  r.status = Status::ok;
  std::vector<pp::V> v(polygon.size());
  std::vector<int> s(polygon.size());
  bool all_zero = true;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    v[i] = vec_cast<double>(polygon[i]);
    s[i] = to_int(side_of_plane(plane.normal, plane.constant, polygon[i]));
    all_zero = all_zero && s[i] == 0;
  }
  if (all_zero) {
    r.coplanar = true;
    return r;
  }
  const pp::V n = vec_cast<double>(plane.normal);
  const auto side = [&](std::size_t i) { return s[i]; };
  const auto value = [&](std::size_t i) {
    return plane_value(plane.normal, plane.constant, polygon[i]);
  };
  for (const pp::Piece& p : pp::pieces(std::span<const pp::V>(v), side, value, cross(n, nn))) {
    r.segments.push_back({vec_cast<T>(p.p0), vec_cast<T>(p.p1)});
  }
  return r;
}

/// Swapped arguments.
template <Real T>
[[nodiscard]] PolygonPlaneIntersection<T> intersection(const Plane3<T>& plane,
                                                       std::span<const Vec3<T>> polygon) {
  return intersection(polygon, plane);
}

/// A planar polygon against a closed triangle (see the header comment).
template <Real T>
[[nodiscard]] PolygonTriangleIntersection<T> intersection(std::span<const Vec3<T>> polygon,
                                                          const Triangle3<T>& tri) {
  namespace pp = detail::plane_poly;
  PolygonTriangleIntersection<T> r;
  if (polygon.size() < 3) return r;
  if (!pp::finite_all(polygon) || !is_finite(tri.v0) || !is_finite(tri.v1) || !is_finite(tri.v2)) {
    r.status = Status::non_finite_input;
    return r;
  }
  const pp::V nn = pp::newell(polygon);
  const int axis = detail::tri3::projection_axis(tri.v0, tri.v1, tri.v2);
  if (axis < 0 || nn == pp::V{}) {
    r.status = Status::degenerate_input;
    return r;
  }
  r.status = Status::ok;
  std::vector<pp::V> v(polygon.size());
  std::vector<int> s(polygon.size());
  bool all_zero = true;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    v[i] = vec_cast<double>(polygon[i]);
    s[i] = to_int(orient3d(tri.v0, tri.v1, tri.v2, polygon[i]));
    all_zero = all_zero && s[i] == 0;
  }
  const pp::V t0 = vec_cast<double>(tri.v0), t1 = vec_cast<double>(tri.v1),
              t2 = vec_cast<double>(tri.v2);
  if (all_zero) {
    // Sutherland-Hodgman in the coordinate plane dropping `axis`; orient2d on input vertices.
    r.coplanar = true;
    const auto drop = [axis](const pp::V& p) {
      return axis == 0 ? Vec2<double>{p.y, p.z}
                       : (axis == 1 ? Vec2<double>{p.z, p.x} : Vec2<double>{p.x, p.y});
    };
    const pp::V tv[3] = {t0, t1, t2};
    const int o = to_int(orient2d(drop(t0), drop(t1), drop(t2)));
    std::vector<pp::V> poly = v, next;
    for (int j = 0; j < 3 && !poly.empty(); ++j) {
      const Vec2<double> a = drop(tv[j]), b = drop(tv[(j + 1) % 3]);
      next.clear();
      for (std::size_t k = 0; k < poly.size(); ++k) {
        const pp::V &p = poly[k], &q = poly[(k + 1) % poly.size()];
        const int sp = to_int(orient2d(a, b, drop(p))) * o,
                  sq = to_int(orient2d(a, b, drop(q))) * o;
        if (sp >= 0) next.push_back(p);
        if (sp * sq < 0) {
          const double fp = orient2d_value(a, b, drop(p)), fq = orient2d_value(a, b, drop(q));
          const double t = std::clamp(fp / (fp - fq), 0.0, 1.0);
          next.push_back(p + t * (q - p));
        }
      }
      std::swap(poly, next);
    }
    for (const pp::V& p : poly) r.polygon.push_back(vec_cast<T>(p));
    return r;
  }
  // Not coplanar: the polygon's pieces in the triangle's plane, cut to the triangle's own
  // segment in the polygon's (Newell) plane, both ordered by the same keys.
  const pp::V nt = cross(t1 - t0, t2 - t0), dir = cross(nt, nn);
  const auto side = [&](std::size_t i) { return s[i]; };
  const auto value = [&](std::size_t i) { return orient3d_value(t0, t1, t2, v[i]); };
  const std::vector<pp::Piece> ps = pp::pieces(std::span<const pp::V>(v), side, value, dir);
  const pp::V centre = v[0];
  const auto cut = intersection(Triangle3<double>{t0, t1, t2}, Plane3<double>{nn, dot(nn, centre)});
  if (cut.kind == Kind::empty || cut.kind == Kind::polygon) return r;
  pp::V c0 = cut.point[0], c1 = cut.kind == Kind::segment ? cut.point[1] : cut.point[0];
  double k0 = dot(dir, c0), k1 = dot(dir, c1);
  if (k1 < k0) std::swap(k0, k1), std::swap(c0, c1);
  for (const pp::Piece& p : ps) {
    if (p.k1 < k0 || p.k0 > k1) continue;
    const pp::V a = p.k0 >= k0 ? p.p0 : c0, b = p.k1 <= k1 ? p.p1 : c1;
    r.segments.push_back({vec_cast<T>(a), vec_cast<T>(b)});
  }
  return r;
}

/// Swapped arguments.
template <Real T>
[[nodiscard]] PolygonTriangleIntersection<T> intersection(const Triangle3<T>& tri,
                                                          std::span<const Vec3<T>> polygon) {
  return intersection(polygon, tri);
}

}  // namespace locus
