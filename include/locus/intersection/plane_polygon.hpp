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
// vertices lie in the plane, and the ORDER of every crossing along the common line (ranked by
// core/plane_crossing.hpp on the crossings' exact coordinates in the line's dominant axis).
// Pieces: the crossings of the boundary with the plane are taken under both symbolic rules "a
// vertex in the plane counts as positive" and "... as negative" (each gives an even number of
// crossings, paired along the line), and the union of the two sets of intervals is the closed
// common set (docs/notes/intersection3.md). Against a triangle, the triangle's extent on the
// line is where its edges cross the plane through three vertices of the polygon (v[0], the vertex
// farthest from it, the one farthest from their line): exactly the polygon's plane when the
// polygon is exactly planar; for rounded, not exactly planar input it is one consistent choice.
// Rounded: only the points, each coordinate within one ulp of the exact crossing. Coplanar
// clipping decides original vertices exactly and constructed ones on rounded values; a
// non-convex polygon clipped coplanarly keeps Sutherland-Hodgman's zero-width bridges.
// Status: ok; empty_input (fewer than 3 vertices); non_finite_input; degenerate_input (zero
// plane normal, a degenerate triangle, or a polygon whose Newell normal is zero).
// Cost: O(n log n) for n vertices, each comparison exact on big integers (about a microsecond);
// allocates.

#include <locus/core/plane_crossing.hpp>
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
#include <array>
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

/// A piece of the common line: the exact ranks of its ends along the line and their points.
struct Piece {
  std::size_t r0, r1;
  V p0, p1;
};

/// The coordinate in which the line's direction is largest, and whether it runs backwards.
struct LineAxis {
  int axis;
  bool reversed;
};

[[nodiscard]] inline LineAxis line_axis(const V& dir) noexcept {
  const double ax = std::abs(dir.x), ay = std::abs(dir.y), az = std::abs(dir.z);
  const int axis = ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
  return {axis, dir[axis] < 0.0};
}

/// The crossings of the polygon's boundary with a plane (side(i) exact for vertex i): one
/// per vertex in the plane and one per edge whose ends lie strictly on opposite sides.
struct BoundaryCrossings {
  std::vector<PlaneCrossing3> crossings;
  std::vector<std::size_t> at_vertex;  // index into crossings, for vertices in the plane
  std::vector<std::size_t> at_edge;    // index into crossings, for edges i -> i + 1 that cross
};

template <class Side>
[[nodiscard]] BoundaryCrossings boundary_crossings(std::span<const V> v, const Side& side,
                                                   const ExactPlane3* plane) {
  const std::size_t n = v.size(), none = ~std::size_t{0};
  BoundaryCrossings b;
  b.at_vertex.assign(n, none);
  b.at_edge.assign(n, none);
  for (std::size_t i = 0; i < n; ++i) {
    if (side(i) == 0) {
      b.at_vertex[i] = b.crossings.size();
      b.crossings.push_back({nullptr, v[i], v[i]});
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    if (side(i) * side(j) < 0) {
      b.at_edge[i] = b.crossings.size();
      b.crossings.push_back({plane, v[i], v[j]});
    }
  }
  return b;
}

/// The rank of crossing c along the line (ascending in the line's direction).
[[nodiscard]] inline std::size_t line_rank(const PlaneCrossing3& c, std::size_t max_rank,
                                           const LineAxis& la) noexcept {
  return la.reversed ? max_rank - c.rank : c.rank;
}

/// Pieces of the line { side = 0 } inside the polygon, from its ranked boundary crossings.
template <class Side>
[[nodiscard]] std::vector<Piece> pieces(std::size_t n, const Side& side, const BoundaryCrossings& b,
                                        std::size_t max_rank, const LineAxis& la) {
  std::vector<Piece> out;
  for (const int zero_as : {1, -1}) {
    std::vector<std::pair<std::size_t, V>> cross;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t j = (i + 1) % n;
      const int si = side(i), sj = side(j);
      const int ri = si == 0 ? zero_as : si, rj = sj == 0 ? zero_as : sj;
      if (ri == rj) continue;
      const std::size_t k = si == 0 ? b.at_vertex[i] : (sj == 0 ? b.at_vertex[j] : b.at_edge[i]);
      const PlaneCrossing3& c = b.crossings[k];
      cross.push_back({line_rank(c, max_rank, la), c.point});
    }
    std::sort(cross.begin(), cross.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    for (std::size_t k = 0; k + 1 < cross.size(); k += 2) {
      out.push_back({cross[k].first, cross[k + 1].first, cross[k].second, cross[k + 1].second});
    }
  }
  // Union of the two families: sort by start and merge overlapping or touching pieces.
  std::sort(out.begin(), out.end(), [](const Piece& x, const Piece& y) { return x.r0 < y.r0; });
  std::vector<Piece> merged;
  for (const Piece& p : out) {
    if (!merged.empty() && p.r0 <= merged.back().r1) {
      if (p.r1 > merged.back().r1) merged.back().r1 = p.r1, merged.back().p1 = p.p1;
    } else {
      merged.push_back(p);
    }
  }
  return merged;
}

[[nodiscard]] inline std::size_t max_rank(std::span<const PlaneCrossing3> c) noexcept {
  std::size_t m = 0;
  for (const PlaneCrossing3& x : c) m = std::max(m, x.rank);
  return m;
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

/// Three vertices spanning the polygon's plane: v[0], the vertex farthest from it, and the one
/// farthest from the line through both (in double; the plane is then exact through them).
[[nodiscard]] inline std::array<std::size_t, 3> spanning_vertices(std::span<const V> v) noexcept {
  std::size_t i1 = 0, i2 = 0;
  double best = 0.0;
  for (std::size_t i = 1; i < v.size(); ++i) {
    const double d = sqr_length(v[i] - v[0]);
    if (d > best) best = d, i1 = i;
  }
  best = 0.0;
  for (std::size_t i = 1; i < v.size(); ++i) {
    const double d = sqr_length(cross(v[i1] - v[0], v[i] - v[0]));
    if (d > best) best = d, i2 = i;
  }
  return {0, i1, i2};
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
  const ExactPlane3 exact = ExactPlane3::from_normal(n, static_cast<double>(plane.constant));
  const auto side = [&](std::size_t i) { return s[i]; };
  pp::BoundaryCrossings b = pp::boundary_crossings(std::span<const pp::V>(v), side, &exact);
  const pp::LineAxis la = pp::line_axis(cross(n, nn));
  rank_plane_crossings(b.crossings, la.axis);
  for (const pp::Piece& p : pp::pieces(v.size(), side, b, pp::max_rank(b.crossings), la)) {
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
  // extent in the polygon's plane (the plane through three of its vertices), every crossing of
  // both ranked together along the common line.
  const pp::V nt = cross(t1 - t0, t2 - t0);
  const ExactPlane3 tri_plane = ExactPlane3::from_points(t0, t1, t2);
  const auto side = [&](std::size_t i) { return s[i]; };
  pp::BoundaryCrossings b = pp::boundary_crossings(std::span<const pp::V>(v), side, &tri_plane);
  const std::size_t polygon_crossings = b.crossings.size();
  const std::array<std::size_t, 3> span = pp::spanning_vertices(v);
  const ExactPlane3 poly_plane = ExactPlane3::from_points(v[span[0]], v[span[1]], v[span[2]]);
  const pp::V tv[3] = {t0, t1, t2};
  int ts[3];
  for (int k = 0; k < 3; ++k) {
    ts[k] = to_int(orient3d(v[span[0]], v[span[1]], v[span[2]], tv[k]));
    if (ts[k] == 0) b.crossings.push_back({nullptr, tv[k], tv[k]});
  }
  for (int k = 0; k < 3; ++k) {
    if (ts[k] * ts[(k + 1) % 3] < 0) b.crossings.push_back({&poly_plane, tv[k], tv[(k + 1) % 3]});
  }
  const std::size_t tri_crossings = b.crossings.size() - polygon_crossings;
  // No crossing: the triangle misses the polygon's plane; all three on it: the polygon is not
  // exactly planar (its vertices off the triangle's plane), and the common set is empty.
  if (tri_crossings == 0 || (ts[0] == 0 && ts[1] == 0 && ts[2] == 0)) return r;
  const pp::LineAxis la = pp::line_axis(cross(nt, nn));
  rank_plane_crossings(b.crossings, la.axis);
  const std::size_t top = pp::max_rank(b.crossings);
  const PlaneCrossing3* lo = nullptr;
  const PlaneCrossing3* hi = nullptr;
  for (std::size_t k = polygon_crossings; k < b.crossings.size(); ++k) {
    const PlaneCrossing3& c = b.crossings[k];
    if (lo == nullptr || pp::line_rank(c, top, la) < pp::line_rank(*lo, top, la)) lo = &c;
    if (hi == nullptr || pp::line_rank(c, top, la) > pp::line_rank(*hi, top, la)) hi = &c;
  }
  const std::size_t k0 = pp::line_rank(*lo, top, la), k1 = pp::line_rank(*hi, top, la);
  for (const pp::Piece& p : pp::pieces(v.size(), side, b, top, la)) {
    if (p.r1 < k0 || p.r0 > k1) continue;
    const pp::V a = p.r0 >= k0 ? p.p0 : lo->point, c = p.r1 <= k1 ? p.p1 : hi->point;
    r.segments.push_back({vec_cast<T>(a), vec_cast<T>(c)});
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
