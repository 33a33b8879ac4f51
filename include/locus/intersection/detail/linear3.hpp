// SPDX-License-Identifier: BSL-1.0
#pragma once
// Shared engine of the 3D linear-component pairs (line, ray, segment against plane and
// triangle; rows int3.linear-plane and int3.linear-triangle). Internal: include a pair header.
// A component is o + t d with t >= 0 if lo and t <= 1 if hi; a segment keeps its exact second
// point q = p1 (d = p1 - p0 is rounded and only used to construct points). Every decision is an
// exact sign (core/plane_side.hpp, core/predicates.hpp); see docs/notes/intersection.md ("3D").

#include <locus/core/plane_side.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/result.hpp>
#include <locus/intersection/detail/linear2.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/plane.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/segment.hpp>
#include <locus/primitives/triangle.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>

namespace locus {

/// The result of intersection() of a Line3, Ray3 or Segment3 with a Plane3: param_a on the
/// component, param_b NoParam (a plane has no point_at).
template <Real T>
using LinearPlaneIntersection = Intersection<T, 3, T, NoParam, 2>;

/// The result of intersection() of a Line3, Ray3 or Segment3 with a Triangle3: param_a on the
/// component, param_b the triangle's (s, t) of point_at(tri, st) = v0 + s (v1 - v0) + t (v2 - v0)
/// (barycentrics (1 - s - t, s, t)).
template <Real T>
using LinearTriangleIntersection = Intersection<T, 3, T, Vec2<T>, 2>;

/// The watertight hit of a linear component on a triangle (watertight_hit(), see
/// ray_triangle.hpp): whether it hits, from which side, where.
template <Real T>
struct TriangleHit {
  bool hit = false;       ///< the component hits the triangle (watertight rule)
  bool front = false;     ///< hit from the side the normal (v1 - v0) x (v2 - v0) points to
  T t = T(0);             ///< parameter on the component
  Vec3<T> barycentric{};  ///< (b0, b1, b2), sum 1, the point is b0 v0 + b1 v1 + b2 v2
  Vec3<T> point{};        ///< the hit point
  [[nodiscard]] constexpr explicit operator bool() const noexcept { return hit; }
};

namespace detail::linear3 {

using V = Vec3<double>;

struct Lin {
  V o, d, q;
  bool lo, hi;
};

template <Real T>
[[nodiscard]] constexpr Lin as_lin(const Line3<T>& l) noexcept {
  return {vec_cast<double>(l.origin), vec_cast<double>(l.direction), V{}, false, false};
}
template <Real T>
[[nodiscard]] constexpr Lin as_lin(const Ray3<T>& r) noexcept {
  return {vec_cast<double>(r.origin), vec_cast<double>(r.direction), V{}, true, false};
}
template <Real T>
[[nodiscard]] constexpr Lin as_lin(const Segment3<T>& s) noexcept {
  const V p0 = vec_cast<double>(s.p0), p1 = vec_cast<double>(s.p1);
  return {p0, p1 - p0, p1, true, true};
}

[[nodiscard]] inline bool finite(const V& v) noexcept {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
[[nodiscard]] inline bool finite(const Lin& l) noexcept {
  return finite(l.o) && finite(l.d) && finite(l.q);
}
/// True when the component is a single point (zero direction, or a zero-length segment).
[[nodiscard]] inline bool is_point(const Lin& l) noexcept { return l.hi ? l.o == l.q : l.d == V{}; }
/// The point at parameter t (a segment interpolates between its exact end points).
[[nodiscard]] inline V at(const Lin& l, double t) noexcept {
  if (l.hi) {
    if (t == 0.0) return l.o;
    if (t == 1.0) return l.q;
    return l.o + t * (l.q - l.o);
  }
  return l.o + t * l.d;
}
/// Parameter of a point x on (or near) the component's line; exact at the end points.
[[nodiscard]] inline double param_of(const Lin& l, const V& x) noexcept {
  if (x == l.o) return 0.0;
  if (l.hi && x == l.q) return 1.0;
  const double dd = dot(l.d, l.d);
  return dd > 0.0 ? dot(x - l.o, l.d) / dd : 0.0;
}
[[nodiscard]] inline double clamp_param(const Lin& l, double t) noexcept {
  if (l.lo && t < 0.0) t = 0.0;
  if (l.hi && t > 1.0) t = 1.0;
  return t;
}

// ---------------------------------------------------------------------------------------------
// Against a plane { X : dot(n, X) = c }.

using PlaneResult = Intersection<double, 3, double, NoParam, 2>;

[[nodiscard]] inline PlaneResult plane_point(const V& p, double t) noexcept {
  PlaneResult r;
  r.kind = Kind::point;
  r.count = 1;
  r.point[0] = p;
  r.param_a[0] = t;
  return r;
}

template <bool Construct>
[[nodiscard]] inline PlaneResult plane(const Lin& l, const V& n, double c) noexcept {
  PlaneResult r;
  if (!finite(l) || !finite(n) || !std::isfinite(c) || n == V{}) return r;
  const Sign s0 = side_of_plane(n, c, l.o);
  if (is_point(l)) return s0 == Sign::zero ? plane_point(l.o, 0.0) : r;
  if (l.hi) {
    const Sign s1 = side_of_plane(n, c, l.q);
    if (s0 == Sign::zero && s1 == Sign::zero) {
      r.kind = Kind::segment;
      r.count = 2;
      r.point = {l.o, l.q};
      r.param_a = {0.0, 1.0};
      return r;
    }
    if (s0 == Sign::zero) return plane_point(l.o, 0.0);
    if (s1 == Sign::zero) return plane_point(l.q, 1.0);
    if (s0 == s1) return r;
    if constexpr (!Construct) return plane_point(V{}, 0.0);
    const double f0 = plane_value(n, c, l.o), f1 = plane_value(n, c, l.q);
    const double t = std::clamp(f0 / (f0 - f1), 0.0, 1.0);
    return plane_point(at(l, t), t);
  }
  const Sign sd = sign_of_dot(n, l.d);
  if (sd == Sign::zero) {
    if (s0 != Sign::zero) return r;
    r.kind = l.lo ? Kind::ray : Kind::line;
    r.count = 2;
    r.point = {l.o, l.o + l.d};
    r.param_a = {0.0, 1.0};
    return r;
  }
  if (s0 == Sign::zero) return plane_point(l.o, 0.0);
  if (l.lo && s0 == sd) return r;
  if constexpr (!Construct) return plane_point(V{}, 0.0);
  const double t = clamp_param(l, -plane_value(n, c, l.o) / dot_accurate(n, l.d));
  return plane_point(at(l, t), t);
}

template <Real T>
[[nodiscard]] inline LinearPlaneIntersection<T> cast_plane(const PlaneResult& r) noexcept {
  LinearPlaneIntersection<T> o;
  o.kind = r.kind;
  o.count = r.count;
  for (std::size_t i = 0; i < static_cast<std::size_t>(r.count); ++i) {
    o.point[i] = vec_cast<T>(r.point[i]);
    o.param_a[i] = static_cast<T>(r.param_a[i]);
  }
  return o;
}

// ---------------------------------------------------------------------------------------------
// Against a triangle.

struct Tri {
  V v[3];
};

template <Real T>
[[nodiscard]] inline Tri as_tri(const Triangle3<T>& t) noexcept {
  return {{vec_cast<double>(t.v0), vec_cast<double>(t.v1), vec_cast<double>(t.v2)}};
}

[[nodiscard]] inline bool finite(const Tri& t) noexcept {
  return finite(t.v[0]) && finite(t.v[1]) && finite(t.v[2]);
}

/// Exact sign of det[d; a - o; b - o] for the component's line (orient3d for a segment).
[[nodiscard]] inline Sign edge_side(const Lin& l, const V& a, const V& b) noexcept {
  if (l.hi) return orient3d(l.o, l.q, a, b);
  return line_edge_side(l.o, l.d, a, b);
}

/// The sign of the edge a -> b under the symbolic translation of the line by
/// eps e_x + eps^2 e_y + eps^3 e_z (docs/notes/intersection.md), given its exact sign
/// edge_side(l, a, b): that sign when nonzero, else the first nonzero component of d x (b - a);
/// zero only when b - a is parallel to d.
[[nodiscard]] inline Sign perturbed_edge_side(const Lin& l, const V& a, const V& b,
                                              Sign exact) noexcept {
  if (exact != Sign::zero) return exact;
  const V p0 = l.hi ? l.o : V{}, p1 = l.hi ? l.q : l.d;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const Sign c = turn2d(Vec2<double>{p0[i], p0[j]}, Vec2<double>{p1[i], p1[j]},
                          Vec2<double>{a[i], a[j]}, Vec2<double>{b[i], b[j]});
    if (c != Sign::zero) return c;
  }
  return Sign::zero;
}

/// Whether the parameter of the crossing with the plane of the triangle lies in the domain,
/// given sigma = sign(dot(d, N)) != 0 (closed: the end points count).
[[nodiscard]] inline bool crossing_in_domain(const Lin& l, const Tri& t, Sign sigma) noexcept {
  if (l.lo) {
    const Sign so = orient3d(t.v[0], t.v[1], t.v[2], l.o);  // sign of dot(N, o - v0)
    if (so == sigma) return false;
  }
  if (l.hi) {
    const Sign sq = orient3d(t.v[0], t.v[1], t.v[2], l.q);
    if (sq == -sigma) return false;
  }
  return true;
}

/// The crossing point, parameter and barycentrics given the signs of the three edge
/// determinants (zero ones force a zero barycentric, so edges and vertices are hit exactly).
struct Crossing {
  V point, bary;
  double t;
};

[[nodiscard]] inline Crossing construct_crossing(const Lin& l, const Tri& tri, const Sign (&s)[3],
                                                 Sign sigma) noexcept {
  // f_i = det[d; v_i - o; v_{i+1} - o] is proportional to the barycentric of v_{i+2}.
  // A power-of-two rescaling (exact) keeps the cubic f_i inside the exponent range.
  const double m = std::max(
      {max_abs(l.o), max_abs(l.d), max_abs(tri.v[0]), max_abs(tri.v[1]), max_abs(tri.v[2])});
  int ex = 0;
  (void)std::frexp(m, &ex);
  const double k = std::ldexp(1.0, -ex);
  const V o = k * l.o, d = k * l.d;
  double f[3];
  for (int i = 0; i < 3; ++i) {
    const V a = k * tri.v[i];
    const V b = k * tri.v[(i + 1) % 3];
    if (s[i] == Sign::zero) {
      f[i] = 0.0;
      continue;
    }
    const V ea = a - o, eb = b - o;
    const double v = dot(d, cross(ea, eb));
    // Rounding cannot flip a decided sign into a wrong barycentric: clamp to the exact sign.
    f[i] = (v > 0.0) == (s[i] == Sign::positive) ? std::abs(v) : 0.0;
    if (f[i] == 0.0) f[i] = 0x1p-1000;  // a nonzero sign keeps a (tiny) positive weight
  }
  const double sum = f[0] + f[1] + f[2];
  Crossing c;
  c.bary = V{f[1] / sum, f[2] / sum, f[0] / sum};
  // A vertex (two zero weights) or an edge point keeps exact zeros; a vertex is returned as is.
  int nonzero = 0, last = 0;
  for (int j = 0; j < 3; ++j)
    if (c.bary[j] != 0.0) ++nonzero, last = j;
  if (nonzero == 1) {
    c.bary = V{};
    c.bary[last] = 1.0;
    c.point = tri.v[last];
  } else {
    c.point = c.bary.x * tri.v[0] + c.bary.y * tri.v[1] + c.bary.z * tri.v[2];
  }
  // The component's own input points are exact when they lie on the triangle (its origin also
  // for a line: the line crosses the plane there).
  if (orient3d(tri.v[0], tri.v[1], tri.v[2], l.o) == Sign::zero) {
    c.point = l.o;
    c.t = 0.0;
  } else if (l.hi && orient3d(tri.v[0], tri.v[1], tri.v[2], l.q) == Sign::zero) {
    c.point = l.q;
    c.t = 1.0;
  } else {
    c.t = clamp_param(l, param_of(l, c.point));
  }
  (void)sigma;
  return c;
}

/// The watertight hit (see ray_triangle.hpp).
/// The three edge determinants f_i = det[d; v_i - o; v_{i+1} - o] by one floating-point filter
/// (the differences v_k - o shared; d = q - o rounded for a segment, which Shewchuk's orient3d
/// bound covers as well): 1 / -1 where the bound decides, 2 where it does not (and on
/// non-finite values).
inline void filtered_edge_signs(const Lin& l, const Tri& tri, int (&out)[3]) noexcept {
  const V d = l.hi ? l.q - l.o : l.d;
  const V a[3] = {tri.v[0] - l.o, tri.v[1] - l.o, tri.v[2] - l.o};
  for (int i = 0; i < 3; ++i) {
    const V& x = a[i];
    const V& y = a[(i + 1) % 3];
    const double p0 = x.y * y.z, q0 = x.z * y.y, p1 = x.z * y.x, q1 = x.x * y.z, p2 = x.x * y.y,
                 q2 = x.y * y.x;
    const double v = d.x * (p0 - q0) + d.y * (p1 - q1) + d.z * (p2 - q2);
    const double perm = std::abs(d.x) * (std::abs(p0) + std::abs(q0)) +
                        std::abs(d.y) * (std::abs(p1) + std::abs(q1)) +
                        std::abs(d.z) * (std::abs(p2) + std::abs(q2));
    out[i] = (perm > 0x1p-960 && perm < 0x1p1000 && std::abs(v) > 7.772e-16 * perm)
                 ? (v > 0 ? 1 : -1)
                 : 2;
  }
}

[[nodiscard]] inline TriangleHit<double> hit(const Lin& l, const Tri& tri) noexcept {
  TriangleHit<double> h;
  // Fast rejection: two decided signs that differ mean a miss. (A decided sign implies finite
  // data: any infinite or NaN coordinate makes its perm infinite or NaN.)
  int f[3];
  filtered_edge_signs(l, tri, f);
  if ((f[0] != 2 && f[1] != 2 && f[0] != f[1]) || (f[1] != 2 && f[2] != 2 && f[1] != f[2]) ||
      (f[0] != 2 && f[2] != 2 && f[0] != f[2]))
    return h;
  if (!finite(l) || !finite(tri) || is_point(l)) return h;
  Sign s[3], exact[3];
  for (int i = 0; i < 3; ++i) {
    exact[i] = f[i] != 2 ? static_cast<Sign>(f[i]) : edge_side(l, tri.v[i], tri.v[(i + 1) % 3]);
    s[i] = perturbed_edge_side(l, tri.v[i], tri.v[(i + 1) % 3], exact[i]);
    if (s[i] == Sign::zero || s[i] != s[0]) return h;
  }
  const Sign sigma = s[0];  // = sign(dot(d, N)) (the unperturbed signs agree or vanish)
  if (!crossing_in_domain(l, tri, sigma)) return h;
  const Crossing c = construct_crossing(l, tri, exact, sigma);
  h.hit = true;
  h.front = sigma == Sign::negative;
  h.t = c.t;
  h.barycentric = c.bary;
  h.point = c.point;
  return h;
}

template <Real T>
[[nodiscard]] inline TriangleHit<T> cast_hit(const TriangleHit<double>& h) noexcept {
  if constexpr (std::is_same_v<T, double>) {
    return h;
  } else {
    return {h.hit, h.front, static_cast<T>(h.t), vec_cast<T>(h.barycentric), vec_cast<T>(h.point)};
  }
}

using TriResult = Intersection<double, 3, double, Vec2<double>, 2>;

/// A projection that keeps the triangle non-degenerate: drops axis k (exact coordinates).
[[nodiscard]] inline Vec2<double> drop(const V& p, int k) noexcept {
  return k == 0 ? Vec2<double>{p.y, p.z}
                : (k == 1 ? Vec2<double>{p.z, p.x} : Vec2<double>{p.x, p.y});
}

/// The axis whose projection keeps the (non-degenerate) triangle non-degenerate, preferring the
/// dominant normal component.
[[nodiscard]] inline int projection_axis(const Tri& t) noexcept {
  const V n = cross(t.v[1] - t.v[0], t.v[2] - t.v[0]);
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int a, int b) { return std::abs(n[a]) > std::abs(n[b]); });
  for (const int k : order)
    if (orient2d(drop(t.v[0], k), drop(t.v[1], k), drop(t.v[2], k)) != Sign::zero) return k;
  return -1;
}

/// Barycentric (s, t) of a point of the triangle's plane, from the projection dropping axis k.
[[nodiscard]] inline Vec2<double> st_of(const Tri& tri, const V& p, int k) noexcept {
  for (int i = 0; i < 3; ++i)
    if (p == tri.v[i])
      return i == 0 ? Vec2<double>{0, 0} : (i == 1 ? Vec2<double>{1, 0} : Vec2<double>{0, 1});
  const Vec2<double> a = drop(tri.v[0], k), b = drop(tri.v[1], k), c = drop(tri.v[2], k),
                     x = drop(p, k);
  const double area = orient2d_value(a, b, c);
  // The point is known to lie in the closed triangle: clamp the rounded coordinates to it.
  double s = std::max(0.0, orient2d_value(a, x, c) / area);
  double t = std::max(0.0, orient2d_value(a, b, x) / area);
  if (s + t > 1.0) s /= s + t, t = 1.0 - s;
  return {s, t};
}

/// Whether the projected point x lies in the closed projected triangle (exact).
[[nodiscard]] inline bool in_triangle2(const Vec2<double> (&t)[3], const Vec2<double>& x) noexcept {
  const Sign o = orient2d(t[0], t[1], t[2]);
  for (int i = 0; i < 3; ++i)
    if (orient2d(t[i], t[(i + 1) % 3], x) == -o) return false;
  return true;
}

/// A component lying in the plane of the triangle: the 2D problem in the projection dropping
/// axis k (parameters along the component are preserved by the projection).
template <bool Construct>
[[nodiscard]] inline TriResult coplanar(const Lin& l, const Tri& tri, int k) noexcept {
  TriResult r;
  const Vec2<double> t2[3] = {drop(tri.v[0], k), drop(tri.v[1], k), drop(tri.v[2], k)};
  // Candidates: crossings with the edges and the component's own end points inside.
  double tmin = 0, tmax = 0;
  V pmin{}, pmax{};
  Vec2<double> stmin{}, stmax{};
  bool any = false;
  const auto add = [&](double t, const V& p, const Vec2<double>& st) {
    if (!any || t < tmin) tmin = t, pmin = p, stmin = st;
    if (!any || t > tmax) tmax = t, pmax = p, stmax = st;
    any = true;
  };
  const linear2::Lin l2 =
      l.hi ? linear2::Lin{drop(l.o, k), drop(l.q, k), drop(l.o, k), true, true}
           : linear2::Lin{Vec2<double>{}, drop(l.d, k), drop(l.o, k), l.lo, false};
  if (l.lo && in_triangle2(t2, drop(l.o, k))) add(0.0, l.o, st_of(tri, l.o, k));
  if (l.hi && in_triangle2(t2, drop(l.q, k))) add(1.0, l.q, st_of(tri, l.q, k));
  for (int i = 0; i < 3; ++i) {
    const linear2::Lin e{t2[i], t2[(i + 1) % 3], t2[i], true, true};
    const linear2::Result x = linear2::intersect<true>(l2, e);
    for (int j = 0; j < x.count; ++j) {
      const double u = x.param_b[static_cast<std::size_t>(j)];
      const V& a = tri.v[i];
      const V& b = tri.v[(i + 1) % 3];
      const V p = u == 0.0 ? a : (u == 1.0 ? b : a + u * (b - a));
      // (s, t) along edge i, with exact zeros off the edge.
      const Vec2<double> st =
          i == 0 ? Vec2<double>{u, 0.0}
                 : (i == 1 ? Vec2<double>{1.0 - u, u} : Vec2<double>{0.0, 1.0 - u});
      add(x.param_a[static_cast<std::size_t>(j)], p, st);
    }
  }
  if (!any) return r;
  if constexpr (Construct) {
    r.point[0] = pmin;
    r.param_a[0] = tmin;
    r.param_b[0] = stmin;
    r.point[1] = pmax;
    r.param_a[1] = tmax;
    r.param_b[1] = stmax;
  }
  r.kind = (pmin == pmax || tmin == tmax) ? Kind::point : Kind::segment;
  r.count = r.kind == Kind::point ? 1 : 2;
  return r;
}

/// The closed-set intersection of a component and a triangle (see line_triangle.hpp).
template <bool Construct>
[[nodiscard]] inline TriResult triangle(const Lin& l, const Tri& tri) noexcept {
  TriResult r;
  if (!finite(l) || !finite(tri)) return r;
  const int k = projection_axis(tri);
  if (k < 0) return r;  // degenerate triangle
  if (is_point(l)) {
    if (orient3d(tri.v[0], tri.v[1], tri.v[2], l.o) != Sign::zero) return r;
    const Vec2<double> t2[3] = {drop(tri.v[0], k), drop(tri.v[1], k), drop(tri.v[2], k)};
    if (!in_triangle2(t2, drop(l.o, k))) return r;
    r.kind = Kind::point;
    r.count = 1;
    r.point[0] = l.o;
    r.param_b[0] = st_of(tri, l.o, k);
    return r;
  }
  Sign s[3];
  for (int i = 0; i < 3; ++i) s[i] = edge_side(l, tri.v[i], tri.v[(i + 1) % 3]);
  if (s[0] == Sign::zero && s[1] == Sign::zero && s[2] == Sign::zero)
    return coplanar<Construct>(l, tri, k);
  Sign sigma = Sign::zero;
  for (const Sign x : s) {
    if (x == Sign::zero) continue;
    if (sigma != Sign::zero && x != sigma) return r;
    sigma = x;
  }
  if (!crossing_in_domain(l, tri, sigma)) return r;
  r.kind = Kind::point;
  r.count = 1;
  if constexpr (Construct) {
    const Crossing c = construct_crossing(l, tri, s, sigma);
    r.point[0] = c.point;
    r.param_a[0] = c.t;
    r.param_b[0] = Vec2<double>{c.bary.y, c.bary.z};
  }
  return r;
}

}  // namespace detail::linear3
}  // namespace locus
