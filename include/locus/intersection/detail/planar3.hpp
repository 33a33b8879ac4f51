// SPDX-License-Identifier: BSL-1.0
#pragma once
// Shared engine of a 3D linear component against a planar region given by a frame (origin, u,
// v, normal) and a closed 2D region in frame coordinates: a planar polygon (PlanarPolygon3) or
// a disk (Disk3); row int3.linear-polygon. Internal: include a pair header. The region's plane is
// { X : dot(normal, X - origin) = 0 } as given; sides of it are exact signs. A polygon tests the
// rounded crossing point in frame coordinates; a disk decides its rim exactly on the unrounded
// crossing (core/plane_crossing_ball.hpp). In the plane, the kind of contact (none, point,
// segment) is exact: for a polygon on the rounded frame image of the component (positions along
// it compared exactly, detail/linear_polyline2.hpp), for a disk on the data as given. The pieces
// of a component in a polygon's plane: polygon_pieces2 (src/intersection/planar3_pieces.cpp).

#include <locus/core/plane_crossing_ball.hpp>
#include <locus/core/plane_side.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/intersection/detail/linear2.hpp>
#include <locus/intersection/detail/linear3.hpp>
#include <locus/intersection/detail/linear_polyline2.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/planar_polygon.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <type_traits>
#include <vector>

namespace locus {

/// The result of intersection() of a Line3, Ray3 or Segment3 with a PlanarPolygon3 or a Disk3:
/// param_a on the component, param_b the frame coordinates (s, t) of point_at(region, st).
template <Real T>
using LinearPlanarIntersection = Intersection<T, 3, T, Vec2<T>, 2>;

/// The result of intersection_pieces() of a Line3, Ray3 or Segment3 with a PlanarPolygon3:
/// a status and every piece (a LinearPlanarIntersection of kind point or segment), in order.
template <Real T>
using LinearPlanarPieces = IntersectionPieces<LinearPlanarIntersection<T>>;

namespace detail::planar3 {

using V = Vec3<double>;
using V2 = Vec2<double>;
using linear3::Lin;
using Result = Intersection<double, 3, double, V2, 2>;

struct Frame {
  V o, u, v, n;
};

/// Exact sign of dot(n, x - p0): the six products n_k x_k - n_k p0_k.
[[nodiscard]] inline Sign side(const Frame& f, const V& x) noexcept {
  const V w = x - f.o;
  const double t0 = f.n.x * w.x, t1 = f.n.y * w.y, t2 = f.n.z * w.z;
  const double val = (t0 + t1) + t2, mag = std::abs(t0) + std::abs(t1) + std::abs(t2);
  // Differences, products and two additions: at most 5 roundings of 2^-53 relative to mag.
  if (mag > 0x1p-960 && mag < 0x1p1000 && std::abs(val) > 6e-16 * mag)
    return val > 0 ? Sign::positive : Sign::negative;
  ExactMonomial m[6];
  for (int k = 0; k < 3; ++k) {
    m[2 * k] = {1, 0, 2, {f.n[k], x[k], 0, 0}};
    m[2 * k + 1] = {-1, 0, 2, {f.n[k], f.o[k], 0, 0}};
  }
  return static_cast<Sign>(exact_sign_of_sum(m));
}

[[nodiscard]] inline V2 to_frame(const Frame& f, const V& x) noexcept {
  const V w = x - f.o;
  return {dot(w, f.u), dot(w, f.v)};
}

/// The frame image of a component (rounded): the same parameters on the 2D component.
[[nodiscard]] inline linear2::Lin image(const Frame& f, const Lin& l) noexcept {
  const V2 o2 = to_frame(f, l.o);
  return l.hi ? linear2::Lin{o2, to_frame(f, l.q), o2, true, true}
              : linear2::Lin{V2{}, V2{dot(l.d, f.u), dot(l.d, f.v)}, o2, l.lo, false};
}

/// The component against the region: inside(x, st) tests an input point x of the plane (frame
/// point st, rounded) and crossing_inside(l, st) the crossing of l's carrier with the plane
/// (closed region); coplanar(l2, tmin, tmax) gives the contact of the component lying in the
/// plane (l2: its frame image): 0 none, 1 a point (tmin), 2 a segment (tmin, tmax; the kind is
/// exact even when the rounded ends coincide).
template <bool Construct, class Inside, class CrossingInside, class Coplanar>
[[nodiscard]] inline Result run(const Lin& l, const Frame& f, Inside&& inside,
                                CrossingInside&& crossing_inside, Coplanar&& coplanar) noexcept {
  Result r;
  if (!linear3::finite(l) || !linear3::finite(f.o) || !linear3::finite(f.u) ||
      !linear3::finite(f.v) || !linear3::finite(f.n) || f.n == V{})
    return r;
  // The point x (parameter t) when it lies in the region; exact_point: x is an input point.
  const auto point = [&](const V& x, double t, bool exact_point) {
    const V2 st = to_frame(f, x);
    if (!(exact_point ? inside(x, st) : crossing_inside(l, st))) return r;
    Result p;
    p.kind = Kind::point;
    p.count = 1;
    p.point[0] = x;
    p.param_a[0] = t;
    p.param_b[0] = st;
    return p;
  };
  const Sign s0 = side(f, l.o);
  if (linear3::is_point(l)) return s0 == Sign::zero ? point(l.o, 0.0, true) : r;
  Sign s1 = Sign::zero, sd = Sign::zero;
  if (l.hi) {
    s1 = side(f, l.q);
    sd = s0 == s1 ? Sign::zero : (s1 > s0 ? Sign::positive : Sign::negative);
    if (s0 == s1 && s0 != Sign::zero) return r;
  } else {
    sd = sign_of_dot(f.n, l.d);
  }
  const bool in_plane = l.hi ? (s0 == Sign::zero && s1 == Sign::zero) : (sd == Sign::zero);
  if (in_plane) {
    if (s0 != Sign::zero) return r;  // parallel, off the plane
    // In the plane: the 2D problem in frame coordinates (rounded).
    const linear2::Lin l2 = image(f, l);
    double t0 = 0, t1 = 0;
    const int contact = coplanar(l2, t0, t1);
    if (contact == 0) return r;
    r.kind = contact == 1 ? Kind::point : Kind::segment;
    r.count = contact;
    const double ts[2] = {t0, t1};
    for (int i = 0; i < r.count; ++i) {
      const V x = linear3::at(l, ts[i]);
      r.point[static_cast<std::size_t>(i)] = x;
      r.param_a[static_cast<std::size_t>(i)] = ts[i];
      r.param_b[static_cast<std::size_t>(i)] = to_frame(f, x);
    }
    return r;
  }
  if (s0 == Sign::zero) return point(l.o, 0.0, true);
  if (l.hi && s1 == Sign::zero) return point(l.q, 1.0, true);
  if (l.lo && s0 == sd) return r;  // moving away from the plane
  (void)Construct;
  double t;
  if (l.hi) {
    const double f0 = dot_accurate(f.n, l.o - f.o), f1 = dot_accurate(f.n, l.q - f.o);
    t = std::clamp(f0 / (f0 - f1), 0.0, 1.0);
  } else {
    t = linear3::clamp_param(l, -dot_accurate(f.n, l.o - f.o) / dot_accurate(f.n, l.d));
  }
  return point(linear3::at(l, t), t, false);
}

/// Whether a frame point lies in the closed polygon (exact on the rounded point): on an edge,
/// or inside by the crossing number.
template <Real T>
[[nodiscard]] inline bool in_polygon(std::span<const Vec2<T>> poly, const V2& p) noexcept {
  const std::size_t n = poly.size();
  if (n == 0) return false;
  bool in = false;
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const V2 a = vec_cast<double>(poly[j]), b = vec_cast<double>(poly[i]);
    if (orient2d(a, b, p) == Sign::zero && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
        std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y))
      return true;
    if ((a.y > p.y) != (b.y > p.y)) {
      // The edge crosses the horizontal through p: to the right of p iff orient2d agrees.
      const Sign o = orient2d(a, b, p);
      if ((b.y > a.y) == (o == Sign::positive)) in = !in;
    }
  }
  return in;
}

/// The exponent of the largest |coordinate| of a 2D component and polygon when it lies outside
/// [2^-200, 2^200], else 0: scaled by 2^-e (exact), positions are compared within the exact
/// range of compare_crossing_params (core/crossing.hpp).
template <Real T>
[[nodiscard]] inline int range_exponent(const linear2::Lin& l,
                                        std::span<const Vec2<T>> poly) noexcept {
  double m = std::max({max_abs(l.a), max_abs(l.b), max_abs(l.o)});
  for (const Vec2<T>& p : poly) m = std::max(m, double(max_abs(p)));
  return m > 0x1p200 || (m > 0.0 && m < 0x1p-200) ? std::ilogb(m) : 0;
}
[[nodiscard]] inline V2 scaled(const V2& p, int e) noexcept {
  return {std::ldexp(p.x, e), std::ldexp(p.y, e)};
}

/// A 2D component against the closed polygon: the first and last common points (edge crossings
/// and the component's end points inside), chosen by exact comparisons of their positions
/// along it; 0 none, 1 a single position, 2 two distinct positions (run()'s contact).
template <Real T>
[[nodiscard]] inline int polygon_span(std::span<const Vec2<T>> poly, const linear2::Lin& l,
                                      double& tmin, double& tmax) noexcept {
  namespace lp = linear_polyline2;
  bool any = false;
  lp::Key kmin{}, kmax{};
  // Positions compared on the problem scaled into range (exact, the same order).
  const int e = -range_exponent(l, poly);
  const linear2::Lin ls{scaled(l.a, e), scaled(l.b, e), scaled(l.o, e), l.lo, l.hi};
  const auto compare = [&](const lp::Key& j, const lp::Key& k) {
    return lp::compare(ls, {scaled(j.x0, e), scaled(j.x1, e)}, {scaled(k.x0, e), scaled(k.x1, e)});
  };
  const auto add = [&](const lp::Key& k, double t) {
    if (!any) {
      kmin = kmax = k, tmin = tmax = t, any = true;
    } else if (compare(kmin, k) < 0) {
      kmin = k, tmin = t;
    } else if (compare(kmax, k) > 0) {
      kmax = k, tmax = t;
    }
  };
  if (l.lo && in_polygon(poly, l.o)) add(lp::through(l, l.o), 0.0);
  if (l.hi && in_polygon(poly, l.b)) add(lp::through(l, l.b), 1.0);
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const V2 a = vec_cast<double>(poly[i]), b = vec_cast<double>(poly[(i + 1) % n]);
    const linear2::Result x = linear2::intersect<true>(l, linear2::Lin{a, b, a, true, true});
    // A transversal crossing is named by its edge, other common points are input points.
    const bool transversal =
        x.kind == Kind::point && a != b && turn2d(l.a, l.b, a, b) != Sign::zero;
    for (std::size_t j = 0; j < static_cast<std::size_t>(x.count); ++j)
      add(transversal ? lp::Key{a, b} : lp::through(l, x.point[j]), x.param_a[j]);
  }
  if (!any) return 0;
  if (compare(kmin, kmax) == 0) {
    tmax = tmin;
    return 1;
  }
  tmax = std::max(tmax, tmin);  // exact order; keep the rounded ends ordered too
  return 2;
}

/// A 2D component against the closed disk |x| <= r (frame centred at the disk's centre):
/// the roots of |o + t d|^2 = r^2 clipped to the domain (rounded).
[[nodiscard]] inline bool disk_span(double r, const linear2::Lin& l, double& tmin,
                                    double& tmax) noexcept {
  const V2 d = l.b - l.a;
  const double a = dot(d, d), b = dot(l.o, d), c = dot(l.o, l.o) - r * r;
  const double disc = b * b - a * c;
  if (a == 0 || disc < 0) return false;
  const double s = std::sqrt(disc);
  // Stable roots: q = -(b + sign(b) s); t = q / a and c / q.
  const double q = -(b + std::copysign(s, b));
  double t0 = q / a, t1 = q != 0 ? c / q : t0;
  if (t0 > t1) std::swap(t0, t1);
  if (l.lo) t0 = std::max(t0, 0.0);
  if (l.hi) t1 = std::min(t1, 1.0);
  if (t0 > t1) return false;
  tmin = t0, tmax = t1;
  return true;
}

/// A component lying in the disk's plane against the closed disk: which contact (0 none, 1 one
/// point, 2 a chord) is exact (core/plane_crossing_ball.hpp: the carrier's distance to the
/// centre, where the foot of the centre lies, the end points); a chord's ends are disk_span's
/// (rounded); a chord shorter than their rounding keeps kind 2 with both ends at its rounded
/// ends clamped into order, or at its point nearest the centre when the rounded roots are lost.
[[nodiscard]] inline int disk_in_plane(const Lin& l, const V& c, double r, const linear2::Lin& l2,
                                       double& t0, double& t1) noexcept {
  const int near = l.hi ? segment_line_near_ball(l.o, l.q, c, r) : line_near_ball(l.o, l.d, c, r);
  if (near > 0) return 0;
  // The foot of the centre at or before the start, or at or after the end: the end is the
  // component's nearest point to the centre, and distances grow away from it.
  const bool before =
      l.lo && (l.hi ? dot_of_differences(l.o, c, l.q, l.o) : dot_of_differences(l.o, c, l.d)) >= 0;
  const bool after = l.hi && !before && dot_of_differences(l.q, c, l.q, l.o) <= 0;
  const V a = l.o - c;
  const double dd = dot(l.d, l.d);
  const double nearest =
      before ? 0.0 : (after ? 1.0 : linear3::clamp_param(l, dd > 0 ? -dot(a, l.d) / dd : 0.0));
  t0 = t1 = nearest;
  if (before || after) {
    const int s = point_in_ball(before ? l.o : l.q, c, r);
    if (s > 0) return 0;
    if (s == 0) return 1;  // the end on the rim, the rest farther
  } else if (near == 0) {
    return 1;  // tangent at the foot
  }
  // A chord of positive length: an end strictly inside (distances grow away from it only on
  // one side, and the component has positive length), or the foot strictly inside the range
  // with the carrier crossing the open disk.
  if (disk_span(r, l2, t0, t1)) return 2;
  t0 = t1 = nearest;
  return 2;
}

/// One piece of a 2D component in a closed polygon: count 1 (a point) or 2 (a segment of
/// positive length), the parameters t (rounded, in order) and the frame points st of its ends.
struct Piece2 {
  int count = 1;
  std::array<double, 2> t{};
  std::array<V2, 2> st{};
};

/// Every piece of the finite 2D component l in the closed polygon of finite vertices (even-odd
/// rule, boundary included), in order along l (src/intersection/planar3_pieces.cpp).
[[nodiscard]] std::vector<Piece2> polygon_pieces2(const linear2::Lin& l, std::span<const V2> poly);

template <Real T>
[[nodiscard]] inline Frame frame_of(const PlaneFrame3<T>& f) noexcept {
  return {vec_cast<double>(f.origin), vec_cast<double>(f.u), vec_cast<double>(f.v),
          vec_cast<double>(f.normal)};
}

template <bool Construct, Real T>
[[nodiscard]] inline Result polygon(const Lin& l, const PlanarPolygon3<T>& p) noexcept;

/// intersection_pieces(): a component lying in the plane by polygon_pieces2 on its frame image,
/// any other as intersection() (one point or none).
template <Real T>
[[nodiscard]] LinearPlanarPieces<T> polygon_pieces(const Lin& l, const PlanarPolygon3<T>& p) {
  LinearPlanarPieces<T> out;
  const std::span<const Vec2<T>> v(p.polygon.vertices);
  if (v.empty()) return out;  // empty_input
  out.status = Status::non_finite_input;
  const Frame f = frame_of(p.frame);
  if (!linear3::finite(l) || !linear3::finite(f.o) || !linear3::finite(f.u) ||
      !linear3::finite(f.v) || !linear3::finite(f.n))
    return out;
  for (const Vec2<T>& q : v)
    if (!is_finite(q)) return out;
  out.status = f.n == V{} ? Status::degenerate_input : Status::ok;
  if (out.status != Status::ok) return out;
  const bool in_plane = !linear3::is_point(l) && side(f, l.o) == Sign::zero &&
                        (l.hi ? side(f, l.q) == Sign::zero : sign_of_dot(f.n, l.d) == Sign::zero);
  if (!in_plane) {
    const Result r = polygon<true>(l, p);
    if (r.kind != Kind::empty) out.pieces.push_back(intersection_cast<T>(r));
    return out;
  }
  std::vector<Piece2> pieces;
  if constexpr (std::is_same_v<T, double>) {
    pieces = polygon_pieces2(image(f, l), v);
  } else {
    std::vector<V2> vd(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) vd[i] = vec_cast<double>(v[i]);
    pieces = polygon_pieces2(image(f, l), vd);
  }
  out.pieces.reserve(pieces.size());
  for (const Piece2& q : pieces) {
    LinearPlanarIntersection<T> r;
    r.kind = q.count == 1 ? Kind::point : Kind::segment;
    r.count = q.count;
    for (std::size_t i = 0; i < static_cast<std::size_t>(q.count); ++i) {
      r.point[i] = vec_cast<T>(linear3::at(l, q.t[i]));
      r.param_a[i] = static_cast<T>(q.t[i]);
      r.param_b[i] = vec_cast<T>(q.st[i]);
    }
    out.pieces.push_back(r);
  }
  return out;
}

template <bool Construct, Real T>
[[nodiscard]] inline Result polygon(const Lin& l, const PlanarPolygon3<T>& p) noexcept {
  const Frame f = frame_of(p.frame);
  const std::span<const Vec2<T>> v(p.polygon.vertices);
  for (const Vec2<T>& q : v)
    if (!is_finite(q)) return {};
  const auto in_region = [&](const V2& st) { return in_polygon(v, st); };
  return run<Construct>(
      l, f, [&](const V&, const V2& st) { return in_region(st); },
      [&](const Lin&, const V2& st) { return in_region(st); },
      [&](const linear2::Lin& l2, double& t0, double& t1) { return polygon_span(v, l2, t0, t1); });
}

template <bool Construct, Real T>
[[nodiscard]] inline Result disk(const Lin& l, const Disk3<T>& d) noexcept {
  const CircleAxes<T> ax = in_plane_axes(d);
  const Frame f{vec_cast<double>(d.center), vec_cast<double>(ax.u), vec_cast<double>(ax.v),
                vec_cast<double>(d.normal)};
  const double r = double(d.radius);
  if (!std::isfinite(r) || r < 0 || ax.u == Vec3<T>{}) return {};
  // The rim exactly: |X - center| <= radius for the input point or the unrounded crossing.
  return run<Construct>(
      l, f, [&](const V& x, const V2&) { return point_in_ball(x, f.o, r) <= 0; },
      [&](const Lin& c, const V2&) {
        return (c.hi ? crossing_in_ball_segment(c.o, c.q, f.o, f.n, r)
                     : crossing_in_ball_line(c.o, c.d, f.o, f.n, r)) <= 0;
      },
      [&](const linear2::Lin& l2, double& t0, double& t1) {
        return disk_in_plane(l, f.o, r, l2, t0, t1);
      });
}

}  // namespace detail::planar3
}  // namespace locus
