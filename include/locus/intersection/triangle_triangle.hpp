// SPDX-License-Identifier: BSL-1.0
#pragma once
// Two triangles in 3D: intersects() (the book's test) and intersection() (find); book section
// 11.5.4, figures 11.27, 11.28; row int3.plane-triangle. Used by mesh/mesh_checks.hpp.
// Triangles are closed sets: touching at a vertex, along an edge or in a shared plane counts.
// intersects: every decision exact, no tolerance (Guigue-Devillers' order): each triangle's
// vertex signs against the other's plane (stage-A filter sharing the plane's minors; undecided:
// a shared vertex means true, else exact), rejection when strictly one side; then the overlap of
// the two intervals on the common line (2 exact signs; docs/notes/intersection3.md). Coplanar or
// degenerate: six exact segment-triangle tests (docs/notes/mesh.md). Invariant under swapping,
// reordering vertices and power-of-two scaling. Cost: 3-8 filtered signs; + an adaptive one per
// vertex exactly in the other's plane (T-junction); coplanar <= ~40 signs.
// intersection -> TriangleTriangleIntersection<T> (param_a, param_b: (s, t) of point_at(tri, st)
// on each triangle): empty, point, segment (ordered along cross(normal a, normal b)) or, when
// coplanar with a common area, polygon (<= 6 vertices in the order of a's vertices, i.e.
// counter-clockwise about a's normal). Its kind is decided exactly and agrees with intersects.
// Not coplanar: each triangle meets the other's plane in an interval of the common line; the
// end points are compared along it by exact orient3d signs (Guigue-Devillers' observation;
// docs/notes/intersection3.md), so point vs segment is exact. Coplanar: in the coordinate plane
// where a projects non-degenerately, a positive-area test by exact separating edges, then
// Sutherland-Hodgman clipping of a by b's edges on symbolic vertices (input vertex or edge-line
// crossing) classified by exact orient2d / turn2d signs; zero area gives the point or segment
// between the extreme common input vertices. Constructed points (in double, rounded once to T): an
// input vertex exactly when it is one; a crossing of edge p -> q with the other plane at
// t = f(p) / (f(p) - f(q)), f the rounded orient3d (or orient2d when coplanar) values, so
// |point - X| <= 2^-49 L^3 / |n| / sin(angle) + eps |X| (L the largest edge-vertex distance
// involved, n the other triangle's normal (b - a) x (c - a), angle between edge and plane, eps of
// T). Parameters: exact at vertices, interpolated along edges, else projected (rounded, clamped to
// the domain). Degenerate triangles act as the segment between their extreme vertices
// (segment_triangle.hpp; two degenerate ones: 2D segment intersection in an injective coordinate
// plane). Non-finite input: false / empty. Cost of find: ~20 exact signs plus a few divisions.

#include <locus/config.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/intersection/plane_triangle.hpp>
#include <locus/intersection/result.hpp>
#include <locus/intersection/segment_segment.hpp>
#include <locus/intersection/segment_triangle.hpp>
#include <locus/primitives/triangle.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace locus {

namespace detail::tri3 {

template <Real T>
[[nodiscard]] inline Vec2<T> drop(const Vec3<T>& p, int axis) noexcept {
  // Keep a right-handed pair: dropping x gives (y, z), y gives (z, x), z gives (x, y).
  return axis == 0 ? Vec2<T>{p.y, p.z} : (axis == 1 ? Vec2<T>{p.z, p.x} : Vec2<T>{p.x, p.y});
}

/// An axis whose dropping keeps the triangle a, b, c non-degenerate, or -1 if it is degenerate.
template <Real T>
[[nodiscard]] inline int projection_axis(const Vec3<T>& a, const Vec3<T>& b,
                                         const Vec3<T>& c) noexcept {
  for (int k = 2; k >= 0; --k) {
    if (orient2d(drop(a, k), drop(b, k), drop(c, k)) != Sign::zero) return k;
  }
  return -1;
}

template <Real T>
[[nodiscard]] inline bool on_segment2(const Vec2<T>& p, const Vec2<T>& a,
                                      const Vec2<T>& b) noexcept {
  // p is collinear with a, b (checked by the caller): inside the bounding box.
  return std::fmin(a.x, b.x) <= p.x && p.x <= std::fmax(a.x, b.x) && std::fmin(a.y, b.y) <= p.y &&
         p.y <= std::fmax(a.y, b.y);
}

/// Closed segments ab and cd in the plane share a point (exact).
template <Real T>
[[nodiscard]] inline bool segments2(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& c,
                                    const Vec2<T>& d) noexcept {
  const Sign s1 = orient2d(a, b, c), s2 = orient2d(a, b, d);
  const Sign s3 = orient2d(c, d, a), s4 = orient2d(c, d, b);
  if (to_int(s1) * to_int(s2) < 0 && to_int(s3) * to_int(s4) < 0) return true;
  if (s1 == Sign::zero && on_segment2(c, a, b)) return true;
  if (s2 == Sign::zero && on_segment2(d, a, b)) return true;
  if (s3 == Sign::zero && on_segment2(a, c, d)) return true;
  if (s4 == Sign::zero && on_segment2(b, c, d)) return true;
  return false;
}

/// p in the closed non-degenerate triangle abc of the plane (exact).
template <Real T>
[[nodiscard]] inline bool in_triangle2(const Vec2<T>& p, const Vec2<T>& a, const Vec2<T>& b,
                                       const Vec2<T>& c) noexcept {
  const int s = to_int(orient2d(a, b, c));
  return to_int(orient2d(a, b, p)) * s >= 0 && to_int(orient2d(b, c, p)) * s >= 0 &&
         to_int(orient2d(c, a, p)) * s >= 0;
}

/// Closed segments ab and cd in 3D share a point (exact; zero-length segments are points).
template <Real T>
[[nodiscard]] inline bool segments3(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c,
                                    const Vec3<T>& d) noexcept {
  if (orient3d(a, b, c, d) != Sign::zero) return false;
  // Coplanar: find a coordinate plane injective on the affine hull of the four points.
  int axis = projection_axis(a, b, c);
  if (axis < 0) axis = projection_axis(a, b, d);
  if (axis < 0) axis = projection_axis(a, c, d);
  if (axis < 0) axis = projection_axis(b, c, d);
  if (axis < 0) {
    // All four collinear (or coincident): any axis along which two distinct points differ is
    // kept; dropping another one is injective on their line.
    const Vec3<T> pts[4] = {a, b, c, d};
    axis = 2;
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) {
        for (int k = 0; k < 3; ++k) {
          if (pts[i][k] != pts[j][k]) axis = (k + 1) % 3;
        }
      }
    }
  }
  return segments2(drop(a, axis), drop(b, axis), drop(c, axis), drop(d, axis));
}

/// Closed segment ab and closed triangle pqr share a point (exact, any degeneracy).
template <Real T>
[[nodiscard]] inline bool segment_triangle(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& p,
                                           const Vec3<T>& q, const Vec3<T>& r) noexcept {
  const int axis = projection_axis(p, q, r);
  if (axis < 0) {
    return segments3(a, b, p, q) || segments3(a, b, q, r) || segments3(a, b, r, p);
  }
  const int sa = to_int(orient3d(p, q, r, a)), sb = to_int(orient3d(p, q, r, b));
  if (sa * sb > 0) return false;
  if (sa == 0 && sb == 0) {
    const Vec2<T> a2 = drop(a, axis), b2 = drop(b, axis), p2 = drop(p, axis);
    const Vec2<T> q2 = drop(q, axis), r2 = drop(r, axis);
    return in_triangle2(a2, p2, q2, r2) || in_triangle2(b2, p2, q2, r2) ||
           segments2(a2, b2, p2, q2) || segments2(a2, b2, q2, r2) || segments2(a2, b2, r2, p2);
  }
  // The segment meets the plane in one point; it lies in the triangle iff the line ab passes
  // no edge on the outside: the three signed volumes are not strictly mixed.
  const int s1 = to_int(orient3d(a, b, p, q)), s2 = to_int(orient3d(a, b, q, r));
  const int s3 = to_int(orient3d(a, b, r, p));
  return !((s1 > 0 || s2 > 0 || s3 > 0) && (s1 < 0 || s2 < 0 || s3 < 0));
}

template <Real T>
[[nodiscard]] inline bool finite(const Triangle3<T>& t) noexcept {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(t[i].x) || !std::isfinite(t[i].y) || !std::isfinite(t[i].z)) return false;
  }
  return true;
}

/// All three vertices of u strictly on one side of the plane of t (t non-degenerate or not:
/// orient3d of a degenerate t is zero, which never rejects).
template <Real T>
[[nodiscard]] inline bool separated_by_plane(const Triangle3<T>& t,
                                             const Triangle3<T>& u) noexcept {
  const int s0 = to_int(orient3d(t.v0, t.v1, t.v2, u.v0));
  const int s1 = to_int(orient3d(t.v0, t.v1, t.v2, u.v1));
  const int s2 = to_int(orient3d(t.v0, t.v1, t.v2, u.v2));
  return (s0 > 0 && s1 > 0 && s2 > 0) || (s0 < 0 && s1 < 0 && s2 < 0);
}

/// The general test for every configuration (coplanar and degenerate triangles included): a
/// plane rejection, then six exact segment-triangle tests. Out of line: intersects() calls it
/// only when a triangle lies in the other's plane (or is degenerate).
template <Real T>
[[nodiscard]] LOCUS_NOINLINE bool intersects_general(const Triangle3<T>& a,
                                                     const Triangle3<T>& b) noexcept {
  if (!finite(a) || !finite(b)) return false;
  if (separated_by_plane(a, b) || separated_by_plane(b, a)) return false;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (segment_triangle(a[i], a[j], b.v0, b.v1, b.v2)) return true;
    if (segment_triangle(b[i], b[j], a.v0, a.v1, a.v2)) return true;
  }
  return false;
}

using V3 = Vec3<double>;
using V2 = Vec2<double>;

/// The plane of the triangle (o, o + u, o + v) prepared for the signs orient3d(o, o + u, o + v, p)
/// of several points p: the 2x2 minors of u, v (the rounded normal u x v) and their permanents
/// are computed once. For p the filter evaluates det3_stage_a on the transposed rows
/// (u.x, v.x, w.x), (u.y, v.y, w.y), (u.z, v.z, w.z), w = p - o, operation for operation (so
/// the same value and the same stage-A bound, valid for any rows of rounded differences), with
/// these minors shared: 3 subtractions and about 12 other flops per point, not a full orient3d.
struct PlaneFilter {
  V3 origin, normal, permanent;
};

[[nodiscard]] LOCUS_ALWAYS_INLINE inline PlaneFilter plane_filter(const V3& o, const V3& p,
                                                                  const V3& q) noexcept {
  const V3 u = p - o, v = q - o;
  const double yz = u.y * v.z, zy = u.z * v.y;
  const double zx = u.z * v.x, xz = u.x * v.z;
  const double xy = u.x * v.y, yx = u.y * v.x;
  return {o,
          {yz - zy, zx - xz, xy - yx},
          {std::abs(yz) + std::abs(zy), std::abs(zx) + std::abs(xz), std::abs(xy) + std::abs(yx)}};
}

/// The exact sign of orient3d(o, p, q, x) (-1, 0, +1) when the filter decides it, else 2. An
/// exact zero never passes (its rounded value cannot exceed its error bound), nor does
/// non-finite input (the bound is then infinite or NaN, the comparison strict).
[[nodiscard]] LOCUS_ALWAYS_INLINE inline int filtered_side(const PlaneFilter& f,
                                                           const V3& x) noexcept {
  const V3 w = x - f.origin;
  const double det = w.x * f.normal.x + w.y * f.normal.y + w.z * f.normal.z;
  const double permanent =
      f.permanent.x * std::abs(w.x) + f.permanent.y * std::abs(w.y) + f.permanent.z * std::abs(w.z);
  const double bound = orient3d_bound_a * permanent;
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return 2;
}

/// Whether a vertex of a equals (exactly) a vertex of b.
[[nodiscard]] inline bool share_vertex(const V3 a[3], const V3 b[3]) noexcept {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (a[i] == b[j]) return true;
    }
  }
  return false;
}

[[nodiscard]] inline bool finite3(const V3 v[3]) noexcept {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(v[i].x) || !std::isfinite(v[i].y) || !std::isfinite(v[i].z)) return false;
  }
  return true;
}

/// The slow path of the plane signs s of b's vertices relative to a's plane (some undecided,
/// value 2): 1 = the triangles share a vertex (they meet), -1 = non-finite input (false), 0 = the
/// signs are now exact.
[[nodiscard]] LOCUS_NOINLINE inline int resolve_sides(const V3 a[3], const V3 b[3],
                                                      int s[3]) noexcept {
  if (!finite3(a) || !finite3(b)) return -1;
  if (share_vertex(a, b)) return 1;
  for (int j = 0; j < 3; ++j) {
    // The filter has failed: straight to the adaptive stages (exact), without a second stage A
    // or the lattice test (it applies only where stage B is exact already; a T-junction off
    // any small lattice pays for it failing).
    if (s[j] == 2) s[j] = to_int(detail::orient3d_adaptive(a[0], a[1], a[2], b[j]));
  }
  return 0;
}

/// An end point of one triangle's interval on the common line: the crossing of its edge line
/// p -> q with the other plane; e = sign(side(q) - side(p)) relative to that plane.
struct End {
  int p, q, e;
};

struct Interval {
  End lo{}, hi{};
  bool point = false;
};

/// The interval of a triangle with side signs s (relative to the other plane) along
/// D = cross(n_a, n_b); flip = +1 for a, -1 for b (whose own direction is -D).
[[nodiscard]] inline Interval interval(const int s[3], int flip) noexcept {
  Interval iv;
  const int a = plane_tri::lone_vertex(s);
  if (a < 0) {
    const int z = plane_tri::touching_vertex(s), w = (z + 1) % 3;
    iv.lo = iv.hi = End{z, w, s[w]};
    iv.point = true;
    return iv;
  }
  // Along the triangle's own cross(n_self, n_other), dot(., X_c - X_b) has the sign -s[a].
  const End eb{a, (a + 1) % 3, -s[a]}, ec{a, (a + 2) % 3, -s[a]};
  const bool b_first = -s[a] * flip > 0;
  iv.lo = b_first ? eb : ec;
  iv.hi = b_first ? ec : eb;
  return iv;
}

/// A coordinate plane in which the non-degenerate triangle t projects non-degenerately, and the
/// orientation there (nonzero).
struct Projection {
  int axis = -1, orientation = 0;
};

[[nodiscard]] inline Projection projection_of(const V3 t[3]) noexcept {
  for (int k = 2; k >= 0; --k) {
    if (const int o = to_int(orient2d(drop(t[0], k), drop(t[1], k), drop(t[2], k)))) return {k, o};
  }
  return {};
}

/// orient3d(p, q, r, s) for p, q, r in the plane of the non-degenerate triangle t (projection
/// pt) and s on side s_side of it (nonzero): (q - p) x (r - p) = lambda n_t, so the sign is
/// sign(lambda) s_side, and lambda has the sign of its projection's orient2d times t's. The same
/// exact sign as orient3d, from an orient2d whose exact zero (r on the line pq: a T-junction) is
/// far cheaper to certify than orient3d's.
[[nodiscard]] inline int orient3d_in_plane(const V3 t[3], Projection& pt, const V3& p, const V3& q,
                                           const V3& r, int s_side) noexcept {
  if (pt.axis < 0) pt = projection_of(t);
  const int k = pt.axis;
  return to_int(orient2d(drop(p, k), drop(q, k), drop(r, k))) * pt.orientation * s_side;
}

/// sign(dot(D, Y - X)) for X an end of a, Y an end of b (exact): orient3d(a_p, a_q, b_p, b_q)
/// times the ends' e. When one of the four points lies in the other triangle's plane (a sign
/// zero; at most one per end, since every end has a vertex off the plane) it is evaluated by
/// orient3d_in_plane (the permutation (a_p, a_q, b_p, b_q) -> (b_p, b_q, a_p, a_q) is even).
[[nodiscard]] inline int compare(const V3 a[3], const int sa[3], Projection& pa, const End& x,
                                 const V3 b[3], const int sb[3], Projection& pb,
                                 const End& y) noexcept {
  int o;
  if (sb[y.p] == 0) {
    o = orient3d_in_plane(a, pa, a[x.p], a[x.q], b[y.p], sb[y.q]);
  } else if (sb[y.q] == 0) {
    o = -orient3d_in_plane(a, pa, a[x.p], a[x.q], b[y.q], sb[y.p]);
  } else if (sa[x.p] == 0) {
    o = orient3d_in_plane(b, pb, b[y.p], b[y.q], a[x.p], sa[x.q]);
  } else if (sa[x.q] == 0) {
    o = -orient3d_in_plane(b, pb, b[y.p], b[y.q], a[x.q], sa[x.p]);
  } else {
    o = to_int(orient3d(a[x.p], a[x.q], b[y.p], b[y.q]));
  }
  return o * x.e * y.e;
}

/// Neither triangle in the other's plane, neither degenerate, each touching or crossing the
/// other's plane (sa: a's sides relative to b's plane, sb: b's relative to a's): the intervals
/// [lo_a, hi_a], [lo_b, hi_b] of the common line meet iff lo_a <= hi_b and lo_b <= hi_a.
[[nodiscard]] inline bool intervals_meet(const V3 a[3], const int sa[3], const V3 b[3],
                                         const int sb[3]) noexcept {
  const Interval ia = interval(sa, 1), ib = interval(sb, -1);
  Projection pa, pb;
  return compare(a, sa, pa, ia.lo, b, sb, pb, ib.hi) >= 0 &&
         compare(a, sa, pa, ia.hi, b, sb, pb, ib.lo) <= 0;
}

/// Some sign left undecided by the filter (value 2).
[[nodiscard]] LOCUS_ALWAYS_INLINE inline bool undecided(const int s[3]) noexcept {
  return (s[0] == 2) | (s[1] == 2) | (s[2] == 2);
}

/// All three signs nonzero and equal (strictly on one side).
[[nodiscard]] LOCUS_ALWAYS_INLINE inline bool one_side(const int s[3]) noexcept {
  return s[0] == s[1] && s[1] == s[2] && s[0] != 0;
}

}  // namespace detail::tri3

/// Whether two closed triangles in 3D share a point (exact; see the header comment).
template <Real T>
[[nodiscard]] inline bool intersects(const Triangle3<T>& ta, const Triangle3<T>& tb) noexcept {
  namespace d = detail::tri3;
  const d::V3 a[3] = {vec_cast<double>(ta.v0), vec_cast<double>(ta.v1), vec_cast<double>(ta.v2)};
  const d::V3 b[3] = {vec_cast<double>(tb.v0), vec_cast<double>(tb.v1), vec_cast<double>(tb.v2)};
  // b's vertices against a's plane (Guigue-Devillers' order: reject as early as possible).
  const d::PlaneFilter fa = d::plane_filter(a[0], a[1], a[2]);
  int sb[3] = {d::filtered_side(fa, b[0]), d::filtered_side(fa, b[1]), d::filtered_side(fa, b[2])};
  if (d::undecided(sb)) [[unlikely]] {
    if (const int r = d::resolve_sides(a, b, sb)) return r > 0;
  }
  if (d::one_side(sb)) return false;
  const d::PlaneFilter fb = d::plane_filter(b[0], b[1], b[2]);
  int sa[3] = {d::filtered_side(fb, a[0]), d::filtered_side(fb, a[1]), d::filtered_side(fb, a[2])};
  if (d::undecided(sa)) [[unlikely]] {
    if (const int r = d::resolve_sides(b, a, sa)) return r > 0;
  }
  if (d::one_side(sa)) return false;
  // A triangle in the other's plane: coplanar, or degenerate (orient3d is then zero for all).
  if ((sa[0] == 0 && sa[1] == 0 && sa[2] == 0) || (sb[0] == 0 && sb[1] == 0 && sb[2] == 0)) {
    return d::intersects_general(ta, tb);
  }
  return d::intervals_meet(a, sa, b, sb);
}

/// The result of intersection(Triangle3, Triangle3): (s, t) on each triangle; up to 6 points.
template <Real T>
using TriangleTriangleIntersection = Intersection<T, 3, Vec2<T>, Vec2<T>, 6>;

namespace detail::tri3 {

using FindResult = Intersection<double, 3, V2, V2, 6>;

/// (s, t) of a common point x of the closed non-degenerate triangle v, rounded and clamped to
/// the domain s, t >= 0, s + t <= 1: x is rounded, so its projection can fall a few ulps outside
/// (s + t - 1 up to ~30 eps seen on points of an edge).
[[nodiscard]] inline V2 st_of(const V3 v[3], const V3& x) noexcept {
  const V3 e1 = v[1] - v[0], e2 = v[2] - v[0], w = x - v[0];
  const V3 n = cross(e1, e2);
  const double nn = dot(n, n);
  if (!(nn > 0.0)) return {0.0, 0.0};
  double s = std::max(dot(cross(w, e2), n) / nn, 0.0);
  double t = std::max(dot(cross(e1, w), n) / nn, 0.0);
  if (s + t > 1.0) {
    s /= s + t;
    t = 1.0 - s;
  }
  return {s, t};
}

/// sign(dot(D, Y - X)) for X an end of a, Y an end of b (exact).
template <Real T>
[[nodiscard]] inline int compare(const Triangle3<T>& a, const End& x, const Triangle3<T>& b,
                                 const End& y) noexcept {
  return to_int(orient3d(a[x.p], a[x.q], b[y.p], b[y.q])) * x.e * y.e;
}

/// The point of an end (vertex exactly when it is one), with its (s, t) on its own triangle.
inline void construct(const V3 v[3], const int s[3], const double f[3], const End& x, V3& point,
                      V2& st) noexcept {
  double t;
  if (s[x.p] == 0) {
    t = 0.0;
  } else if (s[x.q] == 0) {
    t = 1.0;
  } else {
    t = std::clamp(f[x.p] / (f[x.p] - f[x.q]), 0.0, 1.0);
  }
  point = t == 0.0 ? v[x.p] : (t == 1.0 ? v[x.q] : v[x.p] + t * (v[x.q] - v[x.p]));
  st = (1.0 - t) * plane_tri::vertex_st(x.p) + t * plane_tri::vertex_st(x.q);
}

template <Real T>
[[nodiscard]] inline FindResult find_crossing(const Triangle3<T>& ta, const Triangle3<T>& tb,
                                              const int sa[3], const int sb[3]) noexcept {
  FindResult r;
  const V3 a[3] = {vec_cast<double>(ta.v0), vec_cast<double>(ta.v1), vec_cast<double>(ta.v2)};
  const V3 b[3] = {vec_cast<double>(tb.v0), vec_cast<double>(tb.v1), vec_cast<double>(tb.v2)};
  const Interval ia = interval(sa, 1), ib = interval(sb, -1);
  // lo = max(lo_a, lo_b), hi = min(hi_a, hi_b); owner 0 = a, 1 = b.
  const int lo_owner = compare(ta, ia.lo, tb, ib.lo) >= 0 ? 1 : 0;
  const int hi_owner = compare(ta, ia.hi, tb, ib.hi) >= 0 ? 0 : 1;
  int len;
  if (lo_owner == hi_owner) {
    len = (lo_owner == 0 ? ia.point : ib.point) ? 0 : 1;
  } else if (lo_owner == 0) {
    len = compare(ta, ia.lo, tb, ib.hi);
  } else {
    len = -compare(ta, ia.hi, tb, ib.lo);
  }
  if (len < 0) return r;
  double fa[3], fb[3];
  for (int i = 0; i < 3; ++i) {
    fa[i] = orient3d_value(tb.v0, tb.v1, tb.v2, ta[i]);
    fb[i] = orient3d_value(ta.v0, ta.v1, ta.v2, tb[i]);
  }
  const auto emit = [&](int owner, const End& x) {
    const auto i = static_cast<std::size_t>(r.count++);
    if (owner == 0) {
      construct(a, sa, fa, x, r.point[i], r.param_a[i]);
      r.param_b[i] = st_of(b, r.point[i]);
    } else {
      construct(b, sb, fb, x, r.point[i], r.param_b[i]);
      r.param_a[i] = st_of(a, r.point[i]);
    }
  };
  const End& lo = lo_owner == 0 ? ia.lo : ib.lo;
  const End& hi = hi_owner == 0 ? ia.hi : ib.hi;
  if (len == 0) {
    r.kind = Kind::point;
    // Prefer the end that is an input vertex (then the point is exact).
    const int* sl = lo_owner == 0 ? sa : sb;
    const bool lo_exact = sl[lo.p] == 0 || sl[lo.q] == 0;
    if (lo_exact) {
      emit(lo_owner, lo);
    } else {
      emit(hi_owner, hi);
    }
    return r;
  }
  r.kind = Kind::segment;
  emit(lo_owner, lo);
  emit(hi_owner, hi);
  return r;
}

// ---- coplanar: symbolic Sutherland-Hodgman in a coordinate plane.

/// A vertex of the clipped polygon: a's vertex i (type 0), b's vertex i (type 1), or the
/// crossing of a's edge i (a_i -> a_(i+1)) with b's edge line j (type 2).
struct SymVertex {
  int type, i, j;
};

struct Coplanar {
  V2 a[3], b[3];
  int ob;  // orientation sign of b in the projection

  // Side of v relative to b's edge line j, positive towards b's interior (exact).
  [[nodiscard]] int side(const SymVertex& v, int j) const noexcept {
    const int j1 = (j + 1) % 3;
    if (v.type == 0) return to_int(orient2d(b[j], b[j1], a[v.i])) * ob;
    if (v.type == 1) return v.i == j || v.i == j1 ? 0 : 1;
    if (v.j == j) return 0;
    // Lines v.j and j of b share a vertex u; w is v.j's other vertex (opposite to line j, so on
    // b's inner side). The crossing is u + lambda (w - u): its side is sign(lambda), lambda =
    // g(u) / (g(u) - g(w)), g = orient2d(a_i, a_(i+1), .).
    const int m = v.j, m1 = (m + 1) % 3;
    const int u = (m1 == j) ? m1 : m, w = u == m ? m1 : m;
    const V2 &p = a[v.i], &q = a[(v.i + 1) % 3];
    return to_int(orient2d(p, q, b[u])) * to_int(turn2d(p, q, b[w], b[u]));
  }
};

template <Real T>
[[nodiscard]] inline FindResult find_coplanar(const Triangle3<T>& ta, const Triangle3<T>& tb,
                                              int axis) noexcept {
  FindResult r;
  const V3 a[3] = {vec_cast<double>(ta.v0), vec_cast<double>(ta.v1), vec_cast<double>(ta.v2)};
  const V3 b[3] = {vec_cast<double>(tb.v0), vec_cast<double>(tb.v1), vec_cast<double>(tb.v2)};
  Coplanar c{};
  for (int i = 0; i < 3; ++i) {
    c.a[i] = drop(a[i], axis);
    c.b[i] = drop(b[i], axis);
  }
  const int oa = to_int(orient2d(c.a[0], c.a[1], c.a[2]));
  c.ob = to_int(orient2d(c.b[0], c.b[1], c.b[2]));
  // Interiors disjoint iff an edge line of one has the other on its closed outer side.
  bool disjoint = false;
  for (int i = 0; i < 3 && !disjoint; ++i) {
    const int i1 = (i + 1) % 3;
    bool out_b = true, out_a = true;
    for (int j = 0; j < 3; ++j) {
      out_b = out_b && to_int(orient2d(c.a[i], c.a[i1], c.b[j])) * oa <= 0;
      out_a = out_a && to_int(orient2d(c.b[i], c.b[i1], c.a[j])) * c.ob <= 0;
    }
    disjoint = out_a || out_b;
  }
  if (disjoint) {
    // Zero area: the common set is the hull of the input vertices lying in the other triangle
    // (collinear), i.e. the segment between the lexicographic extremes.
    int lo = -1, hi = -1;
    V3 pts[6];
    int owner[6], idx[6], n = 0;
    for (int i = 0; i < 3; ++i) {
      if (in_triangle2(c.a[i], c.b[0], c.b[1], c.b[2])) pts[n] = a[i], owner[n] = 0, idx[n++] = i;
      if (in_triangle2(c.b[i], c.a[0], c.a[1], c.a[2])) pts[n] = b[i], owner[n] = 1, idx[n++] = i;
    }
    for (int k = 0; k < n; ++k) {
      if (lo < 0 || lexicographic_compare(pts[k], pts[lo]) == Sign::negative) lo = k;
      if (hi < 0 || lexicographic_compare(pts[hi], pts[k]) == Sign::negative) hi = k;
    }
    if (n == 0) return r;
    const auto emit = [&](int k) {
      const auto i = static_cast<std::size_t>(r.count++);
      r.point[i] = pts[k];
      if (owner[k] == 0) {
        r.param_a[i] = plane_tri::vertex_st(idx[k]);
        r.param_b[i] = st_of(b, pts[k]);
      } else {
        r.param_b[i] = plane_tri::vertex_st(idx[k]);
        r.param_a[i] = st_of(a, pts[k]);
      }
    };
    emit(lo);
    if (pts[lo] == pts[hi]) {
      r.kind = Kind::point;
    } else {
      r.kind = Kind::segment;
      emit(hi);
    }
    return r;
  }
  // Positive area: clip a (in its own vertex order) by b's three edge half-planes. An edge of
  // the polygon lies on a's edge i (label i) or on b's edge line j (label 3 + j).
  SymVertex poly[12], next[12];
  int label[12], next_label[12];
  int n = 3;
  for (int i = 0; i < 3; ++i) poly[i] = {0, i, 0}, label[i] = i;
  for (int j = 0; j < 3; ++j) {
    int m = 0;
    for (int k = 0; k < n; ++k) {
      const SymVertex &p = poly[k], &q = poly[(k + 1) % n];
      const int sp = c.side(p, j), sq = c.side(q, j);
      if (sp >= 0 && m < 12) {
        next[m] = p;
        next_label[m++] = (sp == 0 && sq < 0) ? 3 + j : label[k];
      }
      if (sp * sq < 0 && m < 12) {
        SymVertex x;
        if (label[k] < 3) {
          x = {2, label[k], j};
        } else {
          const int e = label[k] - 3;  // b's lines e and j meet at b's shared vertex
          x = {1, (e + 1) % 3 == j ? j : e, 0};
        }
        next[m] = x;
        next_label[m++] = sp > 0 ? 3 + j : label[k];
      }
    }
    n = m;
    std::copy(next, next + m, poly);
    std::copy(next_label, next_label + m, label);
  }
  LOCUS_ASSERT(n >= 3 && n <= 6, "coplanar triangle clipping: unexpected vertex count");
  n = std::min(n, 6);
  r.kind = n >= 3 ? Kind::polygon : Kind::empty;
  for (int k = 0; k < n; ++k) {
    const SymVertex& v = poly[k];
    const auto i = static_cast<std::size_t>(r.count++);
    if (v.type == 0) {
      r.point[i] = a[v.i];
      r.param_a[i] = plane_tri::vertex_st(v.i);
      r.param_b[i] = st_of(b, a[v.i]);
    } else if (v.type == 1) {
      r.point[i] = b[v.i];
      r.param_b[i] = plane_tri::vertex_st(v.i);
      r.param_a[i] = st_of(a, b[v.i]);
    } else {
      const int i0 = v.i, i1 = (v.i + 1) % 3, j0 = v.j, j1 = (v.j + 1) % 3;
      const double g0 = orient2d_value(c.b[j0], c.b[j1], c.a[i0]);
      const double g1 = orient2d_value(c.b[j0], c.b[j1], c.a[i1]);
      const double t = g0 == g1 ? 0.5 : std::clamp(g0 / (g0 - g1), 0.0, 1.0);
      r.point[i] = a[i0] + t * (a[i1] - a[i0]);
      r.param_a[i] = (1.0 - t) * plane_tri::vertex_st(i0) + t * plane_tri::vertex_st(i1);
      r.param_b[i] = st_of(b, r.point[i]);
    }
  }
  return r;
}

/// A degenerate triangle's segment: its lexicographically extreme vertices.
template <Real T>
[[nodiscard]] inline std::array<int, 2> extreme_vertices(const Triangle3<T>& t) noexcept {
  const V3 v[3] = {vec_cast<double>(t.v0), vec_cast<double>(t.v1), vec_cast<double>(t.v2)};
  return plane_tri::extremes(v);
}

/// a degenerate, b not: a's segment against b, parameters mapped to a's (s, t).
template <Real T>
[[nodiscard]] inline FindResult find_degenerate(const Triangle3<T>& ta,
                                                const Triangle3<T>& tb) noexcept {
  FindResult r;
  const std::array<int, 2> e = extreme_vertices(ta);
  const Segment3<double> sa{vec_cast<double>(ta[e[0]]), vec_cast<double>(ta[e[1]])};
  const Triangle3<double> db{vec_cast<double>(tb.v0), vec_cast<double>(tb.v1),
                             vec_cast<double>(tb.v2)};
  const LinearTriangleIntersection<double> k = intersection(sa, db);
  r.kind = k.kind;
  r.count = k.count;
  for (std::size_t i = 0; i < static_cast<std::size_t>(k.count); ++i) {
    const double t = k.param_a[i];
    r.point[i] = k.point[i];
    r.param_a[i] = (1.0 - t) * plane_tri::vertex_st(e[0]) + t * plane_tri::vertex_st(e[1]);
    r.param_b[i] = k.param_b[i];
  }
  return r;
}

/// Both degenerate: 2D segment intersection in a coordinate plane injective on both segments.
template <Real T>
[[nodiscard]] inline FindResult find_two_degenerate(const Triangle3<T>& ta,
                                                    const Triangle3<T>& tb) noexcept {
  FindResult r;
  const std::array<int, 2> ea = extreme_vertices(ta), eb = extreme_vertices(tb);
  const V3 p = vec_cast<double>(ta[ea[0]]), q = vec_cast<double>(ta[ea[1]]);
  const V3 u = vec_cast<double>(tb[eb[0]]), w = vec_cast<double>(tb[eb[1]]);
  if (!segments3(p, q, u, w)) return r;
  // The same injective projection as segments3 (coplanar now).
  int axis = projection_axis(p, q, u);
  if (axis < 0) axis = projection_axis(p, q, w);
  if (axis < 0) axis = projection_axis(p, u, w);
  if (axis < 0) axis = projection_axis(q, u, w);
  if (axis < 0) {
    const V3 pts[4] = {p, q, u, w};
    axis = 2;
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) {
        for (int k = 0; k < 3; ++k) {
          if (pts[i][k] != pts[j][k]) axis = (k + 1) % 3;
        }
      }
    }
  }
  const LinearIntersection2<double> k =
      intersection(Segment2<double>{drop(p, axis), drop(q, axis)},
                   Segment2<double>{drop(u, axis), drop(w, axis)});
  r.kind = k.kind;
  r.count = k.count;
  for (std::size_t i = 0; i < static_cast<std::size_t>(k.count); ++i) {
    const double s = k.param_a[i], t = k.param_b[i];
    r.point[i] = s == 0.0 ? p : (s == 1.0 ? q : p + s * (q - p));
    r.param_a[i] = (1.0 - s) * plane_tri::vertex_st(ea[0]) + s * plane_tri::vertex_st(ea[1]);
    r.param_b[i] = (1.0 - t) * plane_tri::vertex_st(eb[0]) + t * plane_tri::vertex_st(eb[1]);
  }
  return r;
}

template <Real T>
[[nodiscard]] inline FindResult find(const Triangle3<T>& a, const Triangle3<T>& b) noexcept {
  if (!intersects(a, b)) return FindResult{};
  const int axis_a = projection_axis(a.v0, a.v1, a.v2), axis_b = projection_axis(b.v0, b.v1, b.v2);
  if (axis_a < 0 && axis_b < 0) return find_two_degenerate(a, b);
  if (axis_a < 0) return find_degenerate(a, b);
  if (axis_b < 0) return swapped(find_degenerate(b, a));
  int sa[3], sb[3];
  for (int i = 0; i < 3; ++i) {
    sa[i] = to_int(orient3d(b.v0, b.v1, b.v2, a[i]));
    sb[i] = to_int(orient3d(a.v0, a.v1, a.v2, b[i]));
  }
  if (sa[0] == 0 && sa[1] == 0 && sa[2] == 0) return find_coplanar(a, b, axis_a);
  return find_crossing(a, b, sa, sb);
}

}  // namespace detail::tri3

/// The common set of two closed triangles in 3D (see the header comment).
template <Real T>
[[nodiscard]] inline TriangleTriangleIntersection<T> intersection(const Triangle3<T>& a,
                                                                  const Triangle3<T>& b) noexcept {
  return intersection_cast<T>(detail::tri3::find(a, b));
}

}  // namespace locus
