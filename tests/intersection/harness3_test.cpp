// SPDX-License-Identifier: BSL-1.0
// The generic intersection harness (harness.hpp) on 3D pairs (rows int3.linear-plane,
// int3.linear-triangle, int3.linear-quadric, int3.boxes, int3.planes, int3.plane-triangle,
// int3.surface-surface, int3.linear-polygon): seeded grid inputs leaning to the degenerate (an end
// point or origin in the plane or on the triangle, through a vertex or an edge midpoint, in the
// triangle's plane, tangent to the sphere, the cylinder or a disk's rim, through a disk's rim, on a
// cylinder parallel to its axis, on a box face, through an oriented box's corner or grazing its
// face, spheres tangent outside or inside, coincident, concentric or a point sphere, a triangle
// with a vertex, an edge or all of it in the plane (collinear too), parallel and coincident planes,
// triangles sharing a vertex or an edge or coplanar), with the exact GMP oracle of
// linear3_oracle.hpp and exact classifications of line-sphere and line-(infinite) cylinder (the
// sign of the discriminant), ray/segment-box (slab clipping; oriented boxes with signed-permutation
// axes), sphere-sphere (the signs of |u|^2 - (r0 +- r1)^2), triangle-plane (vertex sides) and
// plane-plane (ranks) written here; ray/segment-cylinder and segment-disk run without an oracle.

#include <locus/intersection/line_cylinder.hpp>
#include <locus/intersection/line_sphere.hpp>
#include <locus/intersection/plane_plane.hpp>
#include <locus/intersection/plane_triangle.hpp>
#include <locus/intersection/ray_aligned_box.hpp>
#include <locus/intersection/ray_cylinder.hpp>
#include <locus/intersection/ray_oriented_box.hpp>
#include <locus/intersection/ray_triangle.hpp>
#include <locus/intersection/segment_cylinder.hpp>
#include <locus/intersection/segment_disk.hpp>
#include <locus/intersection/segment_oriented_box.hpp>
#include <locus/intersection/segment_plane.hpp>
#include <locus/intersection/segment_triangle.hpp>
#include <locus/intersection/sphere_sphere.hpp>
#include <locus/intersection/triangle_triangle.hpp>

#include <gmpxx.h>

#include <optional>
#include <utility>

#include "intersection/harness.hpp"
#include "intersection/linear3_oracle.hpp"
#include "support/typed.hpp"

namespace {

using locus::AlignedBox;
using locus::Kind;
using locus::Line3;
using locus::OrientedBox3;
using locus::Plane3;
using locus::Ray3;
using locus::Segment3;
using locus::Sphere;
using locus::Triangle3;
using locus::Vec3;
using locus_test::Rng;
using locus_test::ix::check_intersection_pairs;
using locus_test::ix::Expected;
using locus_test::ix::grid_vec;
using locus_test::ix::Options;

template <class T>
class IntersectionHarness3 : public ::testing::Test {};
TYPED_TEST_SUITE(IntersectionHarness3, locus_test::RealTypes);

/// The exact oracle's kind and count (points: 1, segment: 2).
std::optional<Expected> expected(const locus_test::exact3::QResult& q) {
  using locus_test::exact3::QKind;
  switch (q.kind) {
    case QKind::empty:
      return Expected{Kind::empty, 0};
    case QKind::point:
      return Expected{Kind::point, 1};
    case QKind::segment:
      return Expected{Kind::segment, 2};
    default:
      return std::nullopt;
  }
}

/// A plane through a grid point q with a grid normal; returns the plane and q.
template <class T>
std::pair<Plane3<T>, Vec3<T>> grid_plane(Rng& rng) {
  Vec3<T> n = grid_vec<T, 3>(rng, -1, 1);
  if (n == Vec3<T>{}) n = {T(1), T(0), T(0)};
  const Vec3<T> q = grid_vec<T, 3>(rng, -1, 1);
  return {{n, locus::dot(n, q)}, q};  // exact: products on the grid 2^-20, sums of 3
}

TYPED_TEST(IntersectionHarness3, SegmentPlane) {
  using T = TypeParam;
  Options opt;
  opt.residual = 16;
  check_intersection_pairs<T>(
      [](Rng& rng) {
        const std::pair<Plane3<T>, Vec3<T>> pq = grid_plane<T>(rng);
        Vec3<T> p0 = grid_vec<T, 3>(rng, -1, 1), p1 = grid_vec<T, 3>(rng, -1, 1);
        const Vec3<T> in_plane = locus::cross(pq.first.normal, grid_vec<T, 3>(rng, -1, 1));
        switch (rng.uniform_int(0, 4)) {
          case 0:
            p0 = pq.second;
            break;  // an end point in the plane
          case 1:   // the whole segment in the plane
            p0 = pq.second;
            p1 = pq.second + in_plane;
            break;
          case 2:
            p1 = p0 + in_plane;
            break;  // parallel
          default:
            break;
        }
        return std::pair{Segment3<T>{p0, p1}, pq.first};
      },
      opt,
      [](const Segment3<T>& s, const Plane3<T>& p) {
        namespace ex = locus_test::exact3;
        return expected(ex::plane(ex::ql(s), ex::q(p.normal), mpq_class(double(p.constant))));
      });
}

/// A grid triangle and a linear component (origin, direction) aimed at it, often degenerately:
/// through a vertex, through an edge midpoint, starting on the triangle, lying in its plane.
template <class T>
std::pair<Triangle3<T>, std::array<Vec3<T>, 2>> triangle_and_component(Rng& rng) {
  const Triangle3<T> t{grid_vec<T, 3>(rng, -1, 1), grid_vec<T, 3>(rng, -1, 1),
                       grid_vec<T, 3>(rng, -1, 1)};
  Vec3<T> o = grid_vec<T, 3>(rng, -2, 2), d = grid_vec<T, 3>(rng, -1, 1);
  const Vec3<T> e1 = t.v1 - t.v0, e2 = t.v2 - t.v0;
  switch (rng.uniform_int(0, 6)) {
    case 0:
      d = t.v0 - o;
      break;  // through a vertex
    case 1:
      d = (t.v1 + t.v2) / T(2) - o;
      break;  // through an edge midpoint
    case 2:
      o = t.v0 + e1 / T(4) + e2 / T(4);
      break;  // starting inside
    case 3:   // in the plane, across
      o = t.v0 - e1 / T(2) + e2 / T(4);
      d = e1;
      break;
    case 4:  // in the plane, along an edge
      o = t.v0 - e1 / T(2);
      d = e1;
      break;
    default:
      break;
  }
  return {t, {o, d}};
}

TYPED_TEST(IntersectionHarness3, RayTriangle) {
  using T = TypeParam;
  Options opt;
  opt.residual = 16;
  check_intersection_pairs<T>(
      [](Rng& rng) {
        const auto tc = triangle_and_component<T>(rng);
        return std::pair{Ray3<T>{tc.second[0], tc.second[1]}, tc.first};
      },
      opt,
      [](const Ray3<T>& r, const Triangle3<T>& t) {
        namespace ex = locus_test::exact3;
        return expected(ex::triangle(ex::ql(r), ex::qt(t)));
      });
}

TYPED_TEST(IntersectionHarness3, SegmentTriangle) {
  using T = TypeParam;
  Options opt;
  opt.residual = 16;
  check_intersection_pairs<T>(
      [](Rng& rng) {
        const auto tc = triangle_and_component<T>(rng);
        // Ends at 1/2 or 2 of the direction: short of the triangle or through it.
        const T k = rng.uniform_int(0, 1) ? T(2) : T(0.5);
        return std::pair{Segment3<T>{tc.second[0], tc.second[0] + k * tc.second[1]}, tc.first};
      },
      opt,
      [](const Segment3<T>& s, const Triangle3<T>& t) {
        namespace ex = locus_test::exact3;
        return expected(ex::triangle(ex::ql(s), ex::qt(t)));
      });
}

TYPED_TEST(IntersectionHarness3, LineSphere) {
  using T = TypeParam;
  Options opt;
  opt.residual = 16;
  // Near tangency a point's position along the line is only sqrt(eps) accurate.
  opt.param = opt.position = std::is_same_v<T, float> ? 2e-3 : 1e-7;
  check_intersection_pairs<T>(
      [](Rng& rng) {
        const Sphere<T, 3> s{grid_vec<T, 3>(rng, -1, 1), T(rng.uniform_int(1, 64)) / T(64)};
        Vec3<T> o = grid_vec<T, 3>(rng, -2, 2), d = grid_vec<T, 3>(rng, -1, 1);
        switch (rng.uniform_int(0, 4)) {
          case 0:  // tangent at the top: horizontal through (cx, cy, cz + r)
            o = s.center + Vec3<T>{T(0), T(0), s.radius};
            d.z = T(0);
            break;
          case 1:
            o = s.center;
            break;  // through the centre
          case 2:
            o = s.center + Vec3<T>{s.radius, T(0), T(0)};
            break;  // through a surface point
          default:
            break;
        }
        if (d == Vec3<T>{}) d = {T(1), T(0), T(0)};
        return std::pair{Line3<T>{o, d}, s};
      },
      opt,
      [](const Line3<T>& l, const Sphere<T, 3>& s) -> std::optional<Expected> {
        namespace ex = locus_test::exact3;
        const ex::Q3 w = ex::q(l.origin) - ex::q(s.center), d = ex::q(l.direction);
        const mpq_class r(double(s.radius));
        const mpq_class a = ex::qdot(d, d), b = ex::qdot(d, w), c = ex::qdot(w, w) - r * r;
        const int disc = sgn(b * b - a * c);
        if (disc < 0) return Expected{Kind::empty, 0};
        return disc == 0 ? Expected{Kind::point, 1} : Expected{Kind::points, 2};
      });
}

TYPED_TEST(IntersectionHarness3, RayAlignedBox) {
  using T = TypeParam;
  Options opt;
  opt.residual = 8;
  check_intersection_pairs<T>(
      [](Rng& rng) {
        const Vec3<T> p = grid_vec<T, 3>(rng, -1, 1), q = grid_vec<T, 3>(rng, -1, 1);
        AlignedBox<T, 3> b;
        for (int i = 0; i < 3; ++i) {
          b.min[i] = std::min(p[i], q[i]);
          b.max[i] = std::max(p[i], q[i]);
        }
        Vec3<T> o = grid_vec<T, 3>(rng, -2, 2), d = grid_vec<T, 3>(rng, -1, 1);
        switch (rng.uniform_int(0, 4)) {
          case 0:
            d = b.max - o;
            break;  // through a corner
          case 1:
            o = (b.min + b.max) / T(2);
            break;  // from the centre
          case 2:   // grazing a face, axis-parallel
            o.z = b.max.z;
            d.z = T(0);
            break;
          case 3:
            o = b.min;
            break;  // from a corner
          default:
            break;
        }
        return std::pair{Ray3<T>{o, d}, b};
      },
      opt,
      [](const Ray3<T>& r, const AlignedBox<T, 3>& b) -> std::optional<Expected> {
        // Slab clipping of t >= 0 in rationals.
        mpq_class lo = 0, hi = 0;
        bool bounded = false;
        for (int k = 0; k < 3; ++k) {
          const mpq_class o(double(r.origin[k])), d(double(r.direction[k]));
          const mpq_class mn(double(b.min[k])), mx(double(b.max[k]));
          if (d == 0) {
            if (o < mn || o > mx) return Expected{Kind::empty, 0};
            continue;
          }
          mpq_class t1 = (mn - o) / d, t2 = (mx - o) / d;
          if (t1 > t2) std::swap(t1, t2);
          if (t1 > lo) lo = t1;
          if (!bounded || t2 < hi) hi = t2;
          bounded = true;
        }
        if (!bounded) return Expected{Kind::point, 1};  // a zero direction inside the box
        if (lo > hi) return Expected{Kind::empty, 0};
        return lo == hi ? Expected{Kind::point, 1} : Expected{Kind::segment, 2};
      });
}

/// A grid box whose axes are a signed permutation of the coordinate axes (exact), or, with
/// `rotated`, turned about z by cos = 3/5, sin = 4/5 rounded (not exactly orthonormal).
template <class T>
OrientedBox3<T> grid_oriented_box(Rng& rng, bool rotated) {
  OrientedBox3<T> b;
  b.center = grid_vec<T, 3>(rng, -1, 1);
  for (int i = 0; i < 3; ++i) b.extent[i] = T(rng.uniform_int(0, 64)) / T(64);
  std::array<int, 3> perm{0, 1, 2};
  for (int i = 2; i > 0; --i)
    std::swap(perm[std::size_t(i)], perm[std::size_t(rng.uniform_int(0, i))]);
  for (int i = 0; i < 3; ++i) {
    b.axis[i] = Vec3<T>{};
    b.axis[i][perm[std::size_t(i)]] = rng.uniform_int(0, 1) ? T(1) : T(-1);
  }
  if (rotated) {
    const T c = T(3) / T(5), s = T(4) / T(5);
    b.axis[0] = {c, s, T(0)};
    b.axis[1] = {-s, c, T(0)};
    b.axis[2] = {T(0), T(0), T(1)};
  }
  return b;
}

/// An origin and a direction aimed at the box, often degenerately: through a corner, from the
/// centre, from a corner, grazing a face (parallel to it, in its plane), through a face centre.
/// A rotated (rounded) box gets only generic draws, through its centre or random: within a few
/// eps of its surface the library's rounded frame change decides (ray_oriented_box.hpp), so a
/// degenerate draw may rightly change kind under the harness's motions.
template <class T>
std::array<Vec3<T>, 2> aimed_at_box(Rng& rng, const OrientedBox3<T>& b, bool rotated) {
  Vec3<T> o = grid_vec<T, 3>(rng, -2, 2), d = grid_vec<T, 3>(rng, -1, 1);
  const Vec3<T> a0 = b.extent[0] * b.axis[0], a1 = b.extent[1] * b.axis[1],
                a2 = b.extent[2] * b.axis[2];
  const int draw = rng.uniform_int(0, 5);
  if (rotated) {
    if (draw < 3) d = b.center - o;
    return {o, d};
  }
  switch (draw) {
    case 0:
      d = b.center + a0 + a1 + a2 - o;
      break;  // through a corner
    case 1:
      o = b.center;
      break;  // from the centre
    case 2:
      o = b.center - a0 - a1 - a2;
      break;  // from a corner
    case 3:   // grazing a face: in the plane of face +axis2, moving parallel to it
      o = b.center + a2 + T(rng.uniform_int(-8, 8)) / T(4) * a0;
      {
        const T k0 = T(rng.uniform_int(-4, 4)), k1 = T(rng.uniform_int(-4, 4));  // sequenced
        d = k0 * b.axis[0] + k1 * b.axis[1];
      }
      break;
    case 4:
      d = b.center + a0 - o;
      break;  // through a face centre
    default:
      break;
  }
  return {o, d};
}

/// Slab clipping of origin + t direction, t >= 0 (and t <= 1 for a segment), against a box
/// whose axes are a signed permutation (so the frame change is exact), in rationals.
template <class T>
std::optional<Expected> exact_obox_slabs(const Vec3<T>& o, const Vec3<T>& d,
                                         const OrientedBox3<T>& b, bool segment) {
  namespace ex = locus_test::exact3;
  for (int k = 0; k < 3; ++k)  // a rounded (rotated) frame: no oracle
    if (ex::qdot(ex::q(b.axis[k]), ex::q(b.axis[k])) != 1) return std::nullopt;
  mpq_class lo = 0, hi = 1;
  bool bounded = segment;  // a segment: t <= 1
  bool moving = false;
  const ex::Q3 w = ex::q(o) - ex::q(b.center), dd = ex::q(d);
  for (int k = 0; k < 3; ++k) {
    const ex::Q3 axis = ex::q(b.axis[k]);
    const mpq_class ok = ex::qdot(w, axis), dk = ex::qdot(dd, axis), e(double(b.extent[k]));
    if (dk == 0) {
      if (ok < -e || ok > e) return Expected{Kind::empty, 0};
      continue;
    }
    moving = true;
    mpq_class t1 = (-e - ok) / dk, t2 = (e - ok) / dk;
    if (t1 > t2) std::swap(t1, t2);
    if (t1 > lo) lo = t1;
    if (!bounded || t2 < hi) hi = t2;
    bounded = true;
  }
  if (!moving) return Expected{Kind::point, 1};  // a zero direction inside the box
  if (lo > hi) return Expected{Kind::empty, 0};
  return lo == hi ? Expected{Kind::point, 1} : Expected{Kind::segment, 2};
}

TYPED_TEST(IntersectionHarness3, RayOrientedBox) {
  using T = TypeParam;
  Options opt;
  opt.cases = 100;
  opt.residual = 16;
  check_intersection_pairs<T>(
      [](Rng& rng) {
        const bool rotated = rng.uniform_int(0, 3) == 0;
        const OrientedBox3<T> b = grid_oriented_box<T>(rng, rotated);
        const std::array<Vec3<T>, 2> od = aimed_at_box<T>(rng, b, rotated);
        return std::pair{Ray3<T>{od[0], od[1]}, b};
      },
      opt,
      [](const Ray3<T>& r, const OrientedBox3<T>& b) {
        return exact_obox_slabs<T>(r.origin, r.direction, b, false);
      });
}

TYPED_TEST(IntersectionHarness3, SegmentOrientedBox) {
  using T = TypeParam;
  Options opt;
  opt.cases = 100;
  opt.residual = 16;
  check_intersection_pairs<T>(
      [](Rng& rng) {
        const bool rotated = rng.uniform_int(0, 3) == 0;
        const OrientedBox3<T> b = grid_oriented_box<T>(rng, rotated);
        const std::array<Vec3<T>, 2> od = aimed_at_box<T>(rng, b, rotated);
        // Ends at 1/2, 1 or 2 of the direction: short of the box, on it, or through it.
        const int k = rng.uniform_int(0, 2);
        const T f = k == 0 ? T(0.5) : T(k);
        return std::pair{Segment3<T>{od[0], od[0] + f * od[1]}, b};
      },
      opt,
      [](const Segment3<T>& s, const OrientedBox3<T>& b) {
        return exact_obox_slabs<T>(s.p0, s.p1 - s.p0, b, true);
      });
}

/// A signed coordinate axis (exact).
template <class T>
Vec3<T> grid_axis(Rng& rng) {
  Vec3<T> e{};
  e[rng.uniform_int(0, 2)] = rng.uniform_int(0, 1) ? T(1) : T(-1);
  return e;
}

TYPED_TEST(IntersectionHarness3, SphereSphere) {
  using T = TypeParam;
  Options opt;
  opt.cases = 100;
  opt.residual = 16;
  opt.exact_swap = false;  // a same-type pair: the circle's normal reverses
  check_intersection_pairs<T>(
      [](Rng& rng) {
        Sphere<T, 3> a{grid_vec<T, 3>(rng, -1, 1), T(rng.uniform_int(1, 64)) / T(64)};
        Sphere<T, 3> b{grid_vec<T, 3>(rng, -1, 1), T(rng.uniform_int(1, 64)) / T(64)};
        switch (rng.uniform_int(0, 8)) {
          case 0:
            b.center = a.center + (a.radius + b.radius) * grid_axis<T>(rng);
            break;  // tangent outside, along an axis
          case 1:
            b.center = a.center + (a.radius - b.radius) * grid_axis<T>(rng);
            break;   // tangent inside (or coincident), along an axis
          case 2: {  // tangent outside along (3, 4, 0) / 5: |u| = 5 j / 64 = r0 + r1
            const int j = rng.uniform_int(1, 8);
            a.radius = T(rng.uniform_int(1, 5 * j - 1)) / T(64);
            b.radius = T(5 * j) / T(64) - a.radius;
            Vec3<T> u{};
            u[rng.uniform_int(0, 2)] = T(3 * j) / T(64);
            u[u.x != T(0) ? 1 : 0] += T(4 * j) / T(64);
            b.center = a.center + u;
            break;
          }
          case 3:
            b = a;
            break;  // coincident
          case 4:
            b.center = a.center;
            break;  // concentric
          case 5:   // a point sphere on a
            b = {a.center + a.radius * grid_axis<T>(rng), T(0)};
            break;
          default:  // near each other: mostly a circle
            b.center = a.center + grid_vec<T, 3>(rng, -0.5, 0.5);
            break;
        }
        return std::pair{a, b};
      },
      opt,
      [](const Sphere<T, 3>& a, const Sphere<T, 3>& b) -> std::optional<Expected> {
        namespace ex = locus_test::exact3;
        const ex::Q3 u = ex::q(b.center) - ex::q(a.center);
        const mpq_class r0(double(a.radius)), r1(double(b.radius)), uu = ex::qdot(u, u);
        const mpq_class outer = uu - (r0 + r1) * (r0 + r1), inner = uu - (r0 - r1) * (r0 - r1);
        if (uu == 0 && r0 == r1 && r0 > 0) return Expected{Kind::coincident, 0};
        if (outer > 0 || inner < 0) return Expected{Kind::empty, 0};
        if (outer == 0 || inner == 0) return Expected{Kind::point, 1};
        return Expected{Kind::circle, 3};
      });
}

/// An infinite cylinder on a signed coordinate axis and a component (origin, direction) aimed at
/// it, often degenerately: tangent, on the surface along the axis, parallel, through the axis.
template <class T>
std::pair<locus::Cylinder3<T>, std::array<Vec3<T>, 2>> cylinder_and_component(Rng& rng) {
  const Vec3<T> axis = grid_axis<T>(rng);
  const locus::Cylinder3<T> c{{grid_vec<T, 3>(rng, -1, 1), axis},
                              T(rng.uniform_int(1, 64)) / T(64),
                              std::numeric_limits<T>::infinity()};
  // A radial direction, perpendicular to the axis: a signed axis other than the cylinder's.
  Vec3<T> radial = grid_axis<T>(rng);
  if (locus::dot(radial, axis) != T(0)) radial = Vec3<T>{axis.z, axis.x, axis.y};
  const Vec3<T> tangent = locus::cross(axis, radial);
  Vec3<T> o = grid_vec<T, 3>(rng, -2, 2), d = grid_vec<T, 3>(rng, -1, 1);
  switch (rng.uniform_int(0, 5)) {
    case 0:  // tangent: through a surface point along the tangent plane
      o = c.axis.origin + c.radius * radial;
      {
        const T k0 = T(rng.uniform_int(1, 4)), k1 = T(rng.uniform_int(-4, 4));  // sequenced
        d = k0 * tangent + k1 * axis;
      }
      break;
    case 1:  // on the surface, along the axis
      o = c.axis.origin + c.radius * radial;
      d = axis;
      break;
    case 2:  // parallel to the axis, inside or outside
      d = T(rng.uniform_int(1, 3)) * axis;
      break;
    case 3:
      o = c.axis.origin;
      break;  // through the axis
    default:
      break;
  }
  if (d == Vec3<T>{}) d = radial;
  return {c, {o, d}};
}

TYPED_TEST(IntersectionHarness3, LineInfiniteCylinder) {
  using T = TypeParam;
  Options opt;
  opt.cases = 100;
  opt.residual = 16;
  // Near tangency a point's position along the line is only sqrt(eps) accurate.
  opt.param = opt.position = std::is_same_v<T, float> ? 2e-3 : 1e-7;
  check_intersection_pairs<T>(
      [](Rng& rng) {
        const auto cc = cylinder_and_component<T>(rng);
        return std::pair{Line3<T>{cc.second[0], cc.second[1]}, cc.first};
      },
      opt,
      [](const Line3<T>& l, const locus::Cylinder3<T>& c) -> std::optional<Expected> {
        // With a unit axis a: the disc r^2 |a x d|^2 - [a, d, o - C]^2 (line_cylinder.hpp).
        namespace ex = locus_test::exact3;
        const ex::Q3 a = ex::q(c.axis.direction), d = ex::q(l.direction);
        const ex::Q3 w = ex::q(l.origin) - ex::q(c.axis.origin);
        const mpq_class r(double(c.radius));
        const ex::Q3 axd = ex::qcross(a, d);
        if (ex::is_zero(axd)) {  // parallel to the axis: on the surface or not
          const ex::Q3 axw = ex::qcross(a, w);
          const int on = sgn(ex::qdot(axw, axw) - r * r);
          return on == 0 ? Expected{Kind::line, 2} : Expected{Kind::empty, 0};
        }
        const mpq_class triple = ex::qdot(axd, w);
        const int disc = sgn(r * r * ex::qdot(axd, axd) - triple * triple);
        if (disc < 0) return Expected{Kind::empty, 0};
        return disc == 0 ? Expected{Kind::point, 1} : Expected{Kind::points, 2};
      });
}

// Rays and segments on the same draws, checked without an oracle (residuals on both objects,
// swap, scaling and motions).
TYPED_TEST(IntersectionHarness3, RayInfiniteCylinder) {
  using T = TypeParam;
  Options opt;
  opt.cases = 100;
  opt.residual = 16;
  opt.param = opt.position = std::is_same_v<T, float> ? 2e-3 : 1e-7;
  check_intersection_pairs<T>(
      [](Rng& rng) {
        const auto cc = cylinder_and_component<T>(rng);
        return std::pair{Ray3<T>{cc.second[0], cc.second[1]}, cc.first};
      },
      opt);
}

TYPED_TEST(IntersectionHarness3, SegmentInfiniteCylinder) {
  using T = TypeParam;
  Options opt;
  opt.cases = 100;
  opt.residual = 16;
  opt.param = opt.position = std::is_same_v<T, float> ? 2e-3 : 1e-7;
  check_intersection_pairs<T>(
      [](Rng& rng) {
        const auto cc = cylinder_and_component<T>(rng);
        const T k = rng.uniform_int(0, 1) ? T(2) : T(0.5);
        return std::pair{Segment3<T>{cc.second[0], cc.second[0] + k * cc.second[1]}, cc.first};
      },
      opt);
}

// A segment and a disk, checked without an oracle: through a rim point, an end point on the
// disk, in the disk's plane (a chord, or tangent to the rim), through the centre, random.
TYPED_TEST(IntersectionHarness3, SegmentDisk) {
  using T = TypeParam;
  Options opt;
  opt.cases = 100;
  opt.residual = 16;
  opt.param = opt.position = std::is_same_v<T, float> ? 2e-3 : 1e-7;  // chords near tangency
  check_intersection_pairs<T>(
      [](Rng& rng) {
        const Vec3<T> axis = grid_axis<T>(rng);
        Vec3<T> radial = grid_axis<T>(rng);
        if (locus::dot(radial, axis) != T(0)) radial = Vec3<T>{axis.z, axis.x, axis.y};
        const Vec3<T> tangent = locus::cross(axis, radial);
        locus::Disk3<T> k{grid_vec<T, 3>(rng, -1, 1), axis, T(rng.uniform_int(1, 64)) / T(64)};
        Vec3<T> p0 = grid_vec<T, 3>(rng, -2, 2), p1 = grid_vec<T, 3>(rng, -2, 2);
        const Vec3<T> w = grid_vec<T, 3>(rng, -0.5, 0.5);
        switch (rng.uniform_int(0, 5)) {
          case 0: {  // crossing at a rim point (the segment's midpoint)
            const Vec3<T> rim = k.center + k.radius * radial;
            p0 = rim + axis / T(2) + w;
            p1 = rim - axis / T(2) - w;
            break;
          }
          case 1:
            p0 = k.center + k.radius / T(2) * radial;
            break;   // an end point on the disk
          case 2: {  // in the plane: a chord, tangent to the rim at j = +-4
            const Vec3<T> off = k.center + T(rng.uniform_int(-5, 5)) / T(4) * k.radius * tangent;
            p0 = off - T(2) * k.radius * radial;
            p1 = off + T(2) * k.radius * radial;
            break;
          }
          case 3:
            p0 = k.center + axis;
            p1 = k.center - axis;
            break;  // through the centre
          default:
            k.normal = grid_vec<T, 3>(rng, -1, 1);
            if (k.normal == Vec3<T>{}) k.normal = axis;
            break;
        }
        return std::pair{Segment3<T>{p0, p1}, k};
      },
      opt);
}

TYPED_TEST(IntersectionHarness3, PlanePlane) {
  using T = TypeParam;
  Options opt;
  opt.residual = 64;  // the line point's residual grows like 1 / sin(angle) (plane_plane.hpp)
  opt.exact_swap = false;
  check_intersection_pairs<T>(
      [](Rng& rng) {
        const Plane3<T> a = grid_plane<T>(rng).first;
        Plane3<T> b = grid_plane<T>(rng).first;
        switch (rng.uniform_int(0, 3)) {
          case 0:
            b = {T(-2) * a.normal, T(-2) * a.constant};
            break;  // coincident
          case 1:
            b = {a.normal, a.constant + T(1) / T(8)};
            break;  // parallel
          default:
            break;
        }
        return std::pair{a, b};
      },
      opt,
      [](const Plane3<T>& a, const Plane3<T>& b) -> std::optional<Expected> {
        namespace ex = locus_test::exact3;
        const ex::Q3 na = ex::q(a.normal), nb = ex::q(b.normal);
        if (!ex::is_zero(ex::qcross(na, nb))) return Expected{Kind::line, 2};
        const mpq_class ca(double(a.constant)), cb(double(b.constant));
        // Parallel: coincident when (na, ca) and (nb, cb) are proportional.
        const bool same = ex::is_zero(
            ex::Q3{na.x * cb - nb.x * ca, na.y * cb - nb.y * ca, na.z * cb - nb.z * ca});
        return same ? Expected{Kind::plane, 3} : Expected{Kind::empty, 0};
      });
}

TYPED_TEST(IntersectionHarness3, TrianglePlane) {
  using T = TypeParam;
  Options opt;
  opt.cases = 100;
  opt.residual = 16;
  check_intersection_pairs<T>(
      [](Rng& rng) {
        const std::pair<Plane3<T>, Vec3<T>> pq = grid_plane<T>(rng);
        const Vec3<T> n = pq.first.normal, q = pq.second;
        // In-plane points q + cross(n, w): coordinates on the grid 2^-20 below 4 (exact).
        const auto in_plane = [&]() { return q + locus::cross(n, grid_vec<T, 3>(rng, -1, 1)); };
        Triangle3<T> t{grid_vec<T, 3>(rng, -1, 1), grid_vec<T, 3>(rng, -1, 1),
                       grid_vec<T, 3>(rng, -1, 1)};
        switch (rng.uniform_int(0, 7)) {
          case 0:
            t.v0 = in_plane();
            break;  // a vertex in the plane
          case 1:   // an edge in the plane
            t.v0 = in_plane();
            t.v1 = in_plane();
            break;
          case 2:  // the whole triangle in the plane
            t = {in_plane(), in_plane(), in_plane()};
            break;
          case 3: {  // in the plane and collinear
            const Vec3<T> a = in_plane(), b = in_plane();
            t = {a, b, T(2) * b - a};
            break;
          }
          case 4: {  // a vertex in the plane, the others on opposite sides
            const Vec3<T> a = in_plane();
            t = {a, a + n + grid_vec<T, 3>(rng, -0.25, 0.25), a - n};
            break;
          }
          case 5: {  // degenerate, collinear across the plane through a vertex on it
            const Vec3<T> a = in_plane();
            t = {a + n, a, a - n};
            break;
          }
          default:
            break;
        }
        return std::pair{t, pq.first};
      },
      opt,
      [](const Triangle3<T>& t, const Plane3<T>& p) -> std::optional<Expected> {
        namespace ex = locus_test::exact3;
        const ex::Q3 n = ex::q(p.normal), v[3] = {ex::q(t.v0), ex::q(t.v1), ex::q(t.v2)};
        const mpq_class c(double(p.constant));
        int pos = 0, neg = 0, zero = 0;
        for (const ex::Q3& x : v) {
          const int side = sgn(ex::qdot(n, x) - c);
          pos += side > 0;
          neg += side < 0;
          zero += side == 0;
        }
        const bool flat = ex::is_zero(ex::qcross(v[1] - v[0], v[2] - v[0]));
        if (flat) {  // the segment between the extreme vertices
          if (zero == 3) {
            const bool one_point = ex::is_zero(v[1] - v[0]) && ex::is_zero(v[2] - v[0]);
            return one_point ? Expected{Kind::point, 1} : Expected{Kind::segment, 2};
          }
          return pos == 3 || neg == 3 ? Expected{Kind::empty, 0} : Expected{Kind::point, 1};
        }
        if (zero == 3) return Expected{Kind::polygon, 3};
        if (pos == 3 || neg == 3) return Expected{Kind::empty, 0};
        if (zero == 1 && (pos == 2 || neg == 2)) return Expected{Kind::point, 1};
        return Expected{Kind::segment, 2};
      });
}

TYPED_TEST(IntersectionHarness3, TriangleTriangle) {
  using T = TypeParam;
  Options opt;
  opt.residual = 64;
  opt.exact_swap = false;
  check_intersection_pairs<T>(
      [](Rng& rng) {
        const Triangle3<T> a{grid_vec<T, 3>(rng, -1, 1), grid_vec<T, 3>(rng, -1, 1),
                             grid_vec<T, 3>(rng, -1, 1)};
        Triangle3<T> b{grid_vec<T, 3>(rng, -1, 1), grid_vec<T, 3>(rng, -1, 1),
                       grid_vec<T, 3>(rng, -1, 1)};
        const Vec3<T> e1 = a.v1 - a.v0, e2 = a.v2 - a.v0;
        switch (rng.uniform_int(0, 4)) {
          case 0:
            b.v0 = a.v0;
            break;  // a shared vertex
          case 1:   // a shared edge
            b.v0 = a.v1;
            b.v1 = a.v0;
            break;
          case 2:  // coplanar, overlapping
            b = {a.v0 + e1 / T(2), a.v0 + e2 / T(2) + e1, a.v0 - e1 / T(4) + e2};
            break;
          case 3:
            b.v0 = a.v0 + e1 / T(4) + e2 / T(4);
            break;  // a vertex inside a
          default:
            break;
        }
        return std::pair{a, b};
      },
      opt);
}

}  // namespace
