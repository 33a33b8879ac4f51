// SPDX-License-Identifier: BSL-1.0
#pragma once
// The generic distance-query harness used by every tests/distance/*_test.cpp.
//
// check_pairs<T, N, A, B>(gen, opt) draws opt.cases pairs (a, b) from gen(rng) and checks, for
// r = distance(a, b):
//   1. r.distance >= 0 and finite, r.sqr_distance == r.distance^2 up to rounding;
//   2. both parameters lie in their domain and point_at(a, r.param_a) ~ r.closest[0] (same for b);
//   3. |r.closest[0] - r.closest[1]| ~ r.distance;
//   4. distance(b, a) swaps the closest points and parameters (when unique) and has the same
//      distance;
//   5. an INDEPENDENT oracle (best of opt.samples random parameter pairs, then a compass search in
//      the joint parameter space along a rotating basis, using nothing but the primitives'
//      parametrisations): the returned squared distance is never more than the oracle's + k eps
//      scale^2, and (when opt.check_agreement) agrees with it to opt.agree (relative to scale)
//      unless the minimiser lies outside the oracle's window on an unbounded object;
//   6. a random rigid motion (rotation + translation; translation only for axis-aligned boxes)
//      applied to both objects leaves the squared distance unchanged to k eps scale^2;
//   7. where the pair has sqr_distance(a, b): it equals r.sqr_distance exactly, in both argument
//      orders (the lean query shares the full query's computation);
//   8. scaling both objects about the origin by 2^k scales the squared distance by 2^(2k), to the
//      tolerance of check 6: double k = +-140, float +-20 (products of four coordinates still in
//      range), and double +-400, float +-50 (squares in range, but products of four, such as
//      |da x db|^2 or a c, overflow or underflow). The input scales exactly, so a difference is
//      the query's: an absolute tolerance hidden in it, or an intermediate that leaves the
//      exponent range without a rescaled fallback (Side<P>::scaled).
// Side<P> describes how the harness sees a primitive: its parameter map from [0, 1]^k (the
// oracle's search space), point_at, the parameter-domain test, and the rigid motion.

#include <locus/core/mat.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/aligned_box.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/oriented_box.hpp>
#include <locus/primitives/plane.hpp>
#include <locus/primitives/polyline.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/rectangle.hpp>
#include <locus/primitives/segment.hpp>
#include <locus/primitives/sphere.hpp>
#include <locus/primitives/triangle.hpp>

#include "support/typed.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace locus_test::dist {

using locus::Vec;

template <class P>
struct Side;

// ---- points --------------------------------------------------------------------------------
template <class T, int N>
struct Side<Vec<T, N>> {
  using Param = locus::NoParam;
  static constexpr int k = 0;
  static constexpr bool rotatable = true;
  static Vec<T, N> map(const Vec<T, N>& p, const T*, T) { return p; }
  static Vec<T, N> at(const Vec<T, N>& p, Param) { return p; }
  static bool param_ok(const Vec<T, N>&, Param, T) { return true; }
  static bool in_window(const Vec<T, N>&, Param, T) { return true; }
  static Vec<T, N> moved(const Vec<T, N>& p, const locus::Mat<T, N, N>& r, const Vec<T, N>& t) {
    return r * p + t;
  }
  /// The object scaled by f about the origin (a power of two: exact).
  static Vec<T, N> scaled(const Vec<T, N>& p, T f) { return f * p; }
};

// ---- linear components --------------------------------------------------------------------
template <class T, int N>
struct Side<locus::Line<T, N>> {
  using P = locus::Line<T, N>;
  using Param = T;
  static constexpr int k = 1;
  static constexpr bool rotatable = true;
  static Vec<T, N> map(const P& l, const T* u, T w) { return point_at(l, -w + T(2) * w * u[0]); }
  static Vec<T, N> at(const P& l, T t) { return point_at(l, t); }
  static bool param_ok(const P&, T t, T) { return locus::is_finite(t); }
  static bool in_window(const P&, T t, T w) { return std::abs(t) <= T(0.9) * w; }
  static P moved(const P& l, const locus::Mat<T, N, N>& r, const Vec<T, N>& t) {
    return {r * l.origin + t, r * l.direction};
  }
  /// The object scaled by f about the origin (a power of two: exact).
  static P scaled(const P& l, T f) { return {f * l.origin, f * l.direction}; }
};

template <class T, int N>
struct Side<locus::Ray<T, N>> {
  using P = locus::Ray<T, N>;
  using Param = T;
  static constexpr int k = 1;
  static constexpr bool rotatable = true;
  static Vec<T, N> map(const P& l, const T* u, T w) { return point_at(l, w * u[0]); }
  static Vec<T, N> at(const P& l, T t) { return point_at(l, t); }
  static bool param_ok(const P&, T t, T) { return t >= T(0) && locus::is_finite(t); }
  static bool in_window(const P&, T t, T w) { return t <= T(0.9) * w; }
  static P moved(const P& l, const locus::Mat<T, N, N>& r, const Vec<T, N>& t) {
    return {r * l.origin + t, r * l.direction};
  }
  /// The object scaled by f about the origin (a power of two: exact).
  static P scaled(const P& l, T f) { return {f * l.origin, f * l.direction}; }
};

template <class T, int N>
struct Side<locus::Segment<T, N>> {
  using P = locus::Segment<T, N>;
  using Param = T;
  static constexpr int k = 1;
  static constexpr bool rotatable = true;
  static Vec<T, N> map(const P& s, const T* u, T) { return point_at(s, u[0]); }
  static Vec<T, N> at(const P& s, T t) { return point_at(s, t); }
  static bool param_ok(const P&, T t, T) { return t >= T(0) && t <= T(1); }
  static bool in_window(const P&, T, T) { return true; }
  static P moved(const P& s, const locus::Mat<T, N, N>& r, const Vec<T, N>& t) {
    return {r * s.p0 + t, r * s.p1 + t};
  }
  /// The object scaled by f about the origin (a power of two: exact).
  static P scaled(const P& s, T f) { return {f * s.p0, f * s.p1}; }
};

template <class T, int N>
struct Side<locus::Polyline<T, N>> {
  using P = locus::Polyline<T, N>;
  using Param = T;
  static constexpr int k = 1;
  static constexpr bool rotatable = true;
  static Vec<T, N> map(const P& p, const T* u, T) {
    return point_at(p, u[0] * static_cast<T>(segment_count(p)));
  }
  static Vec<T, N> at(const P& p, T t) { return point_at(p, t); }
  static bool param_ok(const P& p, T t, T) {
    return t >= T(0) && t <= static_cast<T>(segment_count(p));
  }
  static bool in_window(const P&, T, T) { return true; }
  static P moved(const P& p, const locus::Mat<T, N, N>& r, const Vec<T, N>& t) {
    P q = p;
    for (auto& v : q.vertices) v = r * v + t;
    return q;
  }
  /// The object scaled by f about the origin (a power of two: exact).
  static P scaled(const P& p, T f) {
    P q = p;
    for (auto& v : q.vertices) v = f * v;
    return q;
  }
};

// ---- areas and solids ---------------------------------------------------------------------
template <class T, int N>
struct Side<locus::Triangle<T, N>> {
  using P = locus::Triangle<T, N>;
  using Param = locus::Vec3<T>;  // barycentric (u, v, w)
  static constexpr int k = 2;
  static constexpr bool rotatable = true;
  static Vec<T, N> map(const P& tri, const T* u, T) {
    T s = u[0], t = u[1];
    if (s + t > T(1)) s = T(1) - s, t = T(1) - t;  // fold the unit square onto the triangle
    return point_at(tri, locus::Vec2<T>{s, t});
  }
  static Vec<T, N> at(const P& tri, const Param& b) { return point_at_barycentric(tri, b); }
  static bool param_ok(const P&, const Param& b, T tol) {
    return b.x >= -tol && b.y >= -tol && b.z >= -tol && std::abs(b.x + b.y + b.z - T(1)) <= tol;
  }
  static bool in_window(const P&, const Param&, T) { return true; }
  static P moved(const P& tri, const locus::Mat<T, N, N>& r, const Vec<T, N>& t) {
    return {r * tri.v0 + t, r * tri.v1 + t, r * tri.v2 + t};
  }
  /// The object scaled by f about the origin (a power of two: exact).
  static P scaled(const P& tri, T f) { return {f * tri.v0, f * tri.v1, f * tri.v2}; }
};

template <class T, int N>
struct Side<locus::Rectangle<T, N>> {
  using P = locus::Rectangle<T, N>;
  using Param = locus::Vec2<T>;
  static constexpr int k = 2;
  static constexpr bool rotatable = true;
  static Vec<T, N> map(const P& r, const T* u, T) {
    return point_at(
        r, locus::Vec2<T>{(T(2) * u[0] - T(1)) * r.extent[0], (T(2) * u[1] - T(1)) * r.extent[1]});
  }
  static Vec<T, N> at(const P& r, const Param& st) { return point_at(r, st); }
  static bool param_ok(const P& r, const Param& st, T tol) {
    return std::abs(st.x) <= r.extent[0] + tol && std::abs(st.y) <= r.extent[1] + tol;
  }
  static bool in_window(const P&, const Param&, T) { return true; }
  static P moved(const P& x, const locus::Mat<T, N, N>& r, const Vec<T, N>& t) {
    return {r * x.center + t, {r * x.axis[0], r * x.axis[1]}, {x.extent[0], x.extent[1]}};
  }
  /// The object scaled by f about the origin (a power of two: exact).
  static P scaled(const P& x, T f) {
    return {f * x.center, {x.axis[0], x.axis[1]}, {f * x.extent[0], f * x.extent[1]}};
  }
};

template <class T, int N>
struct Side<locus::AlignedBox<T, N>> {
  using P = locus::AlignedBox<T, N>;
  using Param = Vec<T, N>;  // in [0, 1]^N
  static constexpr int k = N;
  static constexpr bool rotatable = false;
  static Vec<T, N> map(const P& b, const T* u, T) {
    Vec<T, N> p{};
    for (int i = 0; i < N; ++i) p[i] = u[i];
    return point_at(b, p);
  }
  static Vec<T, N> at(const P& b, const Param& p) { return point_at(b, p); }
  static bool param_ok(const P&, const Param& p, T) {
    for (int i = 0; i < N; ++i)
      if (!(p[i] >= T(0) && p[i] <= T(1))) return false;
    return true;
  }
  static bool in_window(const P&, const Param&, T) { return true; }
  static P moved(const P& b, const locus::Mat<T, N, N>&, const Vec<T, N>& t) {
    return {b.min + t, b.max + t};
  }
  /// The object scaled by f about the origin (a power of two: exact).
  static P scaled(const P& b, T f) { return {f * b.min, f * b.max}; }
};

template <class T, int N>
struct Side<locus::OrientedBox<T, N>> {
  using P = locus::OrientedBox<T, N>;
  using Param = Vec<T, N>;  // in [-1, 1]^N
  static constexpr int k = N;
  static constexpr bool rotatable = true;
  static Vec<T, N> map(const P& b, const T* u, T) {
    Vec<T, N> s{};
    for (int i = 0; i < N; ++i) s[i] = T(2) * u[i] - T(1);
    return point_at(b, s);
  }
  static Vec<T, N> at(const P& b, const Param& s) { return point_at(b, s); }
  static bool param_ok(const P&, const Param& s, T) {
    for (int i = 0; i < N; ++i)
      if (!(s[i] >= T(-1) && s[i] <= T(1))) return false;
    return true;
  }
  static bool in_window(const P&, const Param&, T) { return true; }
  static P moved(const P& b, const locus::Mat<T, N, N>& r, const Vec<T, N>& t) {
    P o = b;
    o.center = r * b.center + t;
    for (int i = 0; i < N; ++i) o.axis[i] = r * b.axis[i];
    return o;
  }
  /// The object scaled by f about the origin (a power of two: exact).
  static P scaled(const P& b, T f) {
    P o = b;
    o.center = f * b.center;
    o.extent = f * b.extent;
    return o;
  }
};

// ---- planes, circles, disks, spheres ------------------------------------------------------
template <class T>
struct Side<locus::Plane3<T>> {
  using P = locus::Plane3<T>;
  using Param = locus::Vec2<T>;  // coordinates in plane_frame(plane)
  static constexpr int k = 2;
  static constexpr bool rotatable = true;
  static Vec<T, 3> map(const P& pl, const T* u, T w) {
    return point_at(*plane_frame(pl), Param{-w + T(2) * w * u[0], -w + T(2) * w * u[1]});
  }
  static Vec<T, 3> at(const P& pl, const Param& st) { return point_at(*plane_frame(pl), st); }
  static bool param_ok(const P&, const Param& st, T) { return locus::is_finite(st); }
  static bool in_window(const P&, const Param& st, T w) {
    return std::abs(st.x) <= T(0.9) * w && std::abs(st.y) <= T(0.9) * w;
  }
  static P moved(const P& pl, const locus::Mat<T, 3, 3>& r, const Vec<T, 3>& t) {
    const Vec<T, 3> n = r * pl.normal;
    return {n, pl.constant + locus::dot(n, t)};
  }
  /// The object scaled by f about the origin (a power of two: exact).
  static P scaled(const P& pl, T f) { return {pl.normal, f * pl.constant}; }
};

template <class T>
struct Side<locus::Circle2<T>> {
  using P = locus::Circle2<T>;
  using Param = T;  // angle
  static constexpr int k = 1;
  static constexpr unsigned periodic = 1u;  // u[0] wraps around
  static constexpr bool rotatable = true;
  static Vec<T, 2> map(const P& c, const T* u, T) {
    return point_at(c, T(6.283185307179586) * u[0]);
  }
  static Vec<T, 2> at(const P& c, T a) { return point_at(c, a); }
  static bool param_ok(const P&, T a, T) { return locus::is_finite(a); }
  static bool in_window(const P&, T, T) { return true; }
  static P moved(const P& c, const locus::Mat<T, 2, 2>& r, const Vec<T, 2>& t) {
    return {r * c.center + t, c.radius};
  }
  /// The object scaled by f about the origin (a power of two: exact).
  static P scaled(const P& c, T f) { return {f * c.center, f * c.radius}; }
};

template <class T>
struct Side<locus::Circle3<T>> {
  using P = locus::Circle3<T>;
  using Param = T;  // angle
  static constexpr int k = 1;
  static constexpr unsigned periodic = 1u;
  static constexpr bool rotatable = true;
  static Vec<T, 3> map(const P& c, const T* u, T) {
    return point_at(c, T(6.283185307179586) * u[0]);
  }
  static Vec<T, 3> at(const P& c, T a) { return point_at(c, a); }
  static bool param_ok(const P&, T a, T) { return locus::is_finite(a); }
  static bool in_window(const P&, T, T) { return true; }
  static P moved(const P& c, const locus::Mat<T, 3, 3>& r, const Vec<T, 3>& t) {
    return {r * c.center + t, r * c.normal, c.radius};
  }
  /// The object scaled by f about the origin (a power of two: exact).
  static P scaled(const P& c, T f) { return {f * c.center, c.normal, f * c.radius}; }
};

template <class T>
struct Side<locus::Disk3<T>> {
  using P = locus::Disk3<T>;
  using Param = locus::Vec2<T>;  // (s, t) in the disk's plane axes
  static constexpr int k = 2;
  static constexpr unsigned periodic = 0u;
  static constexpr bool rotatable = true;
  // Cartesian (s, t) over the square around the disk, pulled radially onto the disk outside it:
  // polar (radius, angle) parameters are singular at the centre, where the compass search stalls
  // (a line crossing the disk 0.15 from its centre was reported at its distance to the centre).
  static Vec<T, 3> map(const P& d, const T* u, T) {
    T s = d.radius * (T(2) * u[0] - T(1)), t = d.radius * (T(2) * u[1] - T(1));
    const T rho = std::sqrt(s * s + t * t);
    if (rho > d.radius) s *= d.radius / rho, t *= d.radius / rho;
    return point_at(d, Param{s, t});
  }
  static Vec<T, 3> at(const P& d, const Param& st) { return point_at(d, st); }
  static bool param_ok(const P& d, const Param& st, T tol) {
    return locus::length(st) <= d.radius + tol;
  }
  static bool in_window(const P&, const Param&, T) { return true; }
  static P moved(const P& d, const locus::Mat<T, 3, 3>& r, const Vec<T, 3>& t) {
    return {r * d.center + t, r * d.normal, d.radius};
  }
  /// The object scaled by f about the origin (a power of two: exact).
  static P scaled(const P& d, T f) { return {f * d.center, d.normal, f * d.radius}; }
};

template <class T>
struct Side<locus::Sphere<T, 3>> {
  using P = locus::Sphere<T, 3>;
  using Param = locus::Vec2<T>;  // (theta, phi)
  static constexpr int k = 2;
  static constexpr unsigned periodic = 3u;  // theta wraps; phi beyond [0, pi] reflects
  static constexpr bool rotatable = true;
  static Vec<T, 3> map(const P& s, const T* u, T) {
    return point_at(s, Param{T(6.283185307179586) * u[0], T(3.141592653589793) * u[1]});
  }
  static Vec<T, 3> at(const P& s, const Param& tp) { return point_at(s, tp); }
  static bool param_ok(const P&, const Param& tp, T tol) {
    return locus::is_finite(tp) && tp.y >= -tol && tp.y <= T(3.141592653589793) + tol;
  }
  static bool in_window(const P&, const Param&, T) { return true; }
  static P moved(const P& s, const locus::Mat<T, 3, 3>& r, const Vec<T, 3>& t) {
    return {r * s.center + t, s.radius};
  }
  /// The object scaled by f about the origin (a power of two: exact).
  static P scaled(const P& s, T f) { return {f * s.center, f * s.radius}; }
};

// ---- helpers ------------------------------------------------------------------------------

/// A random rotation: Gram-Schmidt on random vectors (det +1).
template <class T, int N>
locus::Mat<T, N, N> random_rotation(Rng& rng) {
  locus::Mat<T, N, N> m{};
  if constexpr (N == 2) {
    const T a = rng.uniform<T>(T(0), T(6.283185307179586));
    m = locus::Mat<T, 2, 2>::from_cols(Vec<T, 2>{std::cos(a), std::sin(a)},
                                       Vec<T, 2>{-std::sin(a), std::cos(a)});
  } else {
    static_assert(N == 3, "random_rotation: 2D or 3D");
    const auto x = rng.unit<T, 3>();
    auto y = rng.unit<T, 3>();
    y = locus::normalize(y - locus::dot(x, y) * x);
    if (y == Vec<T, 3>{}) y = locus::normalize(locus::cross(x, Vec<T, 3>{T(0), T(0), T(1)}));
    const auto z = locus::cross(x, y);
    m = locus::Mat<T, 3, 3>::from_cols(x, y, z);
  }
  return m;
}

template <class T>
struct Options {
  int cases = 200;    ///< random pairs per call
  int samples = 256;  ///< oracle: random starting samples
  T scale = T(10);    ///< coordinate scale of the generated input (tolerances scale with it)
  T window = T(200);  ///< oracle: parameter window on unbounded objects
  T k_eps = T(64);    ///< tolerance k * eps * scale^2 on squared distances
  T agree = T(-1);    ///< oracle agreement on distances, relative to scale (<0: default)
  /// false: skip the oracle-agreement check: for non-convex objects, and where a tighter exact
  /// oracle replaces it (the linear pairs, whose narrow valleys defeat the compass search).
  bool check_agreement = true;
  bool check_swap = true;  ///< distance(b, a) exists and is checked
};

namespace detail {

/// The scalars of a trivially copyable primitive, for failure messages.
template <class T, class P>
std::string dump(const P& p) {
  std::string out;
  if constexpr (std::is_trivially_copyable_v<P> && sizeof(P) % sizeof(T) == 0) {
    T v[sizeof(P) / sizeof(T)];
    std::memcpy(v, &p, sizeof(P));
    char buf[40];
    for (const T x : v) {
      std::snprintf(buf, sizeof buf, "%.17g ", static_cast<double>(x));
      out += buf;
    }
  }
  return out;
}

/// Bit i set: coordinate i of the side's parameter box is periodic (not clamped).
template <class S>
constexpr unsigned periodic_mask() {
  if constexpr (requires { S::periodic; })
    return S::periodic;
  else
    return 0u;
}

// The squared distance of the two (rounded) points at the joint parameters u, accumulated in long
// double, and the larger magnitude of the two points. The sample points are rounded, so they lie
// off their objects by ~eps * magnitude; far-away samples (long windows on lines) can then come
// out below the true minimum by ~2 eps * magnitude * distance, which check_pairs allows for.
template <class T>
struct OracleValue {
  T sqr;
  T mag;
};
template <class A, class B, class T, int N>
OracleValue<T> joint_sqr(const A& a, const B& b, const T* u, T w) {
  const auto p = Side<A>::map(a, u, w);
  const auto q = Side<B>::map(b, u + Side<A>::k, w);
  long double s = 0;
  for (int i = 0; i < N; ++i) {
    const long double d = static_cast<long double>(p[i]) - static_cast<long double>(q[i]);
    s += d * d;
  }
  return {static_cast<T>(s), std::max(locus::max_abs(p), locus::max_abs(q))};
}

/// The oracle: best of `samples` random joint parameters, then a compass search along the axes
/// and all pairwise diagonals of an orthonormal basis, with halving steps. The basis starts as
/// the coordinate axes and rotates (Rosenbrock's method) whenever the step halves after the
/// search has moved: its first vector becomes the displacement since the last rotation, the
/// others the old basis orthonormalised against it. A fixed basis cannot follow a narrow valley
/// across its directions (a needle triangle, 22 long and 1e-3 wide, whose distance depends almost
/// only on s + t / 2: the axis-and-diagonal compass ran out of its budget 1.6e-4 above the minimum
/// from about half of random starts, LOCUS_TEST_SEED=27 PointTriangleTest.Harness2D case 35);
/// the rotated basis steps along it. When the step falls below hmin in a rotated basis, the
/// search restarts once more in the coordinate axes from step 1e-2, so that minima on the faces
/// of the parameter box (clamped coordinates) are approached along the faces (a restart from
/// 1e-5 left 20% of starts 1.4e-3 high at LOCUS_TEST_SEED=38 PointTriangleTest.Harness2D
/// case 62, a minimum at a vertex). The step size follows full moves only: a trial point is
/// clamped to the box, and a clamped move that kept less than half of its step still counts as
/// an improvement but not as a reason to keep the step. Otherwise a direction that points mostly
/// out of the box creeps along its small in-box component forever: on a flat box (a zero extent
/// makes one parameter flat, and the first rotation took the basis along it), with the other
/// parameters at 0 or 1, every pass at h = 1/4 found such a move 4e-8 long and the search spent
/// its whole budget 2.4e-3 above the minimum (LOCUS_TEST_SEED=3 PointBoxTest.Harness3D case 23,
/// oriented box; LOCUS_TEST_SEED=34 case 62, aligned box). Fully deterministic; draws nothing
/// from rng beyond the starting samples.
template <class A, class B, class T, int N>
OracleValue<T> oracle_sqr(const A& a, const B& b, Rng& rng, int samples, T w) {
  constexpr int K = Side<A>::k + Side<B>::k;
  if constexpr (K == 0) {
    return joint_sqr<A, B, T, N>(a, b, nullptr, w);
  } else {
    using P = std::array<T, K>;
    constexpr auto sz = [](int i) { return static_cast<std::size_t>(i); };
    P best{}, cur{};
    OracleValue<T> fbest{std::numeric_limits<T>::infinity(), T(0)};
    for (int i = 0; i < samples; ++i) {
      for (auto& x : cur) x = rng.uniform<T>(T(0), T(1));
      const auto f = joint_sqr<A, B, T, N>(a, b, cur.data(), w);
      if (f.sqr < fbest.sqr) fbest = f, best = cur;
    }
    constexpr unsigned periodic =
        periodic_mask<Side<A>>() | (periodic_mask<Side<B>>() << Side<A>::k);
    std::array<P, K> basis{};
    std::vector<P> dirs;
    // Directions: +-b_i and +-b_i +- b_j of the current basis.
    const auto make_dirs = [&] {
      dirs.clear();
      for (int i = 0; i < K; ++i) {
        dirs.push_back(basis[sz(i)]);
        for (int j = i + 1; j < K; ++j) {
          for (T sj : {T(1), T(-1)}) {
            P e{};
            for (int m = 0; m < K; ++m) e[sz(m)] = basis[sz(i)][sz(m)] + sj * basis[sz(j)][sz(m)];
            dirs.push_back(e);
          }
        }
      }
    };
    const auto reset_basis = [&] {
      for (int i = 0; i < K; ++i) {
        basis[sz(i)] = P{};
        basis[sz(i)][sz(i)] = T(1);
      }
      make_dirs();
    };
    // Rotate: Gram-Schmidt on (d, b_0, ..., b_{K-1}), keeping the first K independent vectors.
    // Unit vectors throughout, so the threshold on what is left of a vector is absolute.
    const auto rotate = [&](const P& d, T len_d) {
      std::array<P, K> nb{};
      int n = 0;
      for (int c = -1; c < K && n < K; ++c) {
        P v = c < 0 ? d : basis[sz(c)];
        if (c < 0)
          for (auto& x : v) x /= len_d;
        for (int pass = 0; pass < 2; ++pass) {  // twice: orthogonal to rounding
          for (int i = 0; i < n; ++i) {
            T dot = 0;
            for (int m = 0; m < K; ++m) dot += v[sz(m)] * nb[sz(i)][sz(m)];
            for (int m = 0; m < K; ++m) v[sz(m)] -= dot * nb[sz(i)][sz(m)];
          }
        }
        T len = 0;
        for (int m = 0; m < K; ++m) len += v[sz(m)] * v[sz(m)];
        len = std::sqrt(len);
        if (!(len > T(1e-3))) continue;  // (nearly) in the span of the vectors kept
        for (int m = 0; m < K; ++m) v[sz(m)] /= len;
        nb[sz(n++)] = v;
      }
      if (n < K) return;  // keep the old basis
      basis = nb;
      make_dirs();
    };
    reset_basis();
    bool rotated = false, restarted = false;
    P anchor = best;  // the position at the last rotation
    const T hmin = std::is_same_v<T, float> ? T(1e-7) : T(1e-13);
    int moves_at_h = 0, budget = 3000;
    for (T h = T(0.25); budget > 0; --budget) {
      if (!(h > hmin)) {
        // Converged in a rotated basis: one more pass in the axes (faces of the box).
        if (!rotated || restarted) break;
        restarted = true, rotated = false;
        reset_basis();
        anchor = best;
        h = T(1e-2);
        moves_at_h = 0;
      }
      bool moved = false;  // a move that kept at least half of its step (see above)
      for (const auto& d : dirs) {
        T step = 0;  // squared length of the unclamped step
        for (int i = 0; i < K; ++i) step += h * d[sz(i)] * h * d[sz(i)];
        for (T sg : {T(1), T(-1)}) {
          P c = best;
          for (int i = 0; i < K; ++i) {
            c[sz(i)] += sg * h * d[sz(i)];
            if (!((periodic >> i) & 1u)) c[sz(i)] = std::clamp(c[sz(i)], T(0), T(1));
          }
          const auto f = joint_sqr<A, B, T, N>(a, b, c.data(), w);
          if (f.sqr < fbest.sqr) {
            T kept = 0;
            for (int i = 0; i < K; ++i) kept += (c[sz(i)] - best[sz(i)]) * (c[sz(i)] - best[sz(i)]);
            if (T(4) * kept >= step) moved = true;
            fbest = f, best = c;
          }
        }
      }
      // Long flat valleys (nearly parallel lines) would take ~1/h moves: expand the step while
      // it keeps improving, halve it otherwise.
      if (!moved) {
        h *= T(0.5);
        moves_at_h = 0;
        P d{};
        T len = 0;
        for (int i = 0; i < K; ++i)
          d[sz(i)] = best[sz(i)] - anchor[sz(i)], len += d[sz(i)] * d[sz(i)];
        if (K > 1 && !restarted && len > T(0)) {
          rotate(d, std::sqrt(len));
          rotated = true;
          anchor = best;
        }
      } else if (++moves_at_h >= 4 && h < T(0.25)) {
        h *= T(2);
        moves_at_h = 0;
      }
    }
    return fbest;
  }
}

}  // namespace detail

/// Check 8's exponents (see the header comment).
template <class T>
constexpr std::array<int, 4> scale_exponents() {
  if constexpr (std::is_same_v<T, float>)
    return {-50, -20, 20, 50};
  else
    return {-400, -140, 140, 400};
}

/// The generic checks 1-8 of the header comment on opt.cases pairs from gen(rng).
template <class T, int N, class A, class B, class Gen>
void check_pairs(Gen&& gen, const Options<T>& opt = {}) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  SCOPED_TRACE(__PRETTY_FUNCTION__);
  using SA = Side<A>;
  using SB = Side<B>;
  const T eps = locus::eps_v<T>;
  for (int n = 0; n < opt.cases; ++n) {
    SCOPED_TRACE("case " + std::to_string(n));
    const std::pair<A, B> ab = gen(rng);
    const A& a = ab.first;
    const B& b = ab.second;
    SCOPED_TRACE("a = " + detail::dump<T>(a) + "\nb = " + detail::dump<T>(b));
    const auto r = distance(a, b);
    // The scale of the coordinates involved (tolerances are relative to it).
    const T s = std::max({opt.scale, locus::max_abs(r.closest[0]), locus::max_abs(r.closest[1])});
    const T sq_tol = opt.k_eps * eps * s * s;
    const T lin_tol = opt.k_eps * eps * s;

    // 1. sane distance
    ASSERT_TRUE(locus::is_finite(r.distance) && r.distance >= T(0)) << r.distance;
    EXPECT_NEAR(r.sqr_distance, r.distance * r.distance, T(8) * eps * r.sqr_distance);
    // 2. closest points lie on their objects
    EXPECT_TRUE(SA::param_ok(a, r.param_a, T(16) * eps * s));
    EXPECT_TRUE(SB::param_ok(b, r.param_b, T(16) * eps * s));
    EXPECT_TRUE(vec_near(SA::at(a, r.param_a), r.closest[0], lin_tol));
    EXPECT_TRUE(vec_near(SB::at(b, r.param_b), r.closest[1], lin_tol));
    // 3. the distance is the distance between the closest points
    EXPECT_NEAR(locus::length(r.closest[0] - r.closest[1]), r.distance, T(4) * eps * s);
    // 4. swapping the arguments swaps the results
    if (opt.check_swap) {
      const auto q = distance(b, a);
      EXPECT_NEAR(q.sqr_distance, r.sqr_distance, sq_tol);
      EXPECT_EQ(q.unique, r.unique);
      if (r.unique) {
        EXPECT_TRUE(vec_near(q.closest[0], r.closest[1], std::sqrt(sq_tol)));
        EXPECT_TRUE(vec_near(q.closest[1], r.closest[0], std::sqrt(sq_tol)));
      }
    }
    // 5. the oracle
    const auto ov = detail::oracle_sqr<A, B, T, N>(a, b, rng, opt.samples, opt.window);
    const T o = ov.sqr;
    // The oracle's own error: its points are off their objects by ~eps * their magnitude.
    const T o_err = T(4) * eps * ov.mag * (T(2) * std::sqrt(o) + T(4) * eps * ov.mag);
    EXPECT_LE(r.sqr_distance, o + sq_tol + o_err) << "oracle found a closer pair";
    if (opt.check_agreement && SA::in_window(a, r.param_a, opt.window) &&
        SB::in_window(b, r.param_b, opt.window)) {
      const T agree = opt.agree > T(0) ? opt.agree : (std::is_same_v<T, float> ? T(2e-3) : T(1e-5));
      EXPECT_NEAR(std::sqrt(o), r.distance, agree * s) << "oracle did not converge to the answer";
    }
    // 7. the squared-distance-only query (found by argument-dependent lookup: a qualified
    // locus::sqr_distance is a hard error in translation units that include no header declaring
    // one)
    if constexpr (requires { sqr_distance(a, b); }) {
      EXPECT_EQ(sqr_distance(a, b), r.sqr_distance);
      EXPECT_EQ(sqr_distance(b, a), r.sqr_distance);
    }
    // 6. rigid motions leave the distance unchanged
    {
      const auto rot = (SA::rotatable && SB::rotatable) ? random_rotation<T, N>(rng)
                                                        : locus::Mat<T, N, N>::identity();
      const auto t = rng.vec<T, N>(-opt.scale, opt.scale);
      const auto m = distance(SA::moved(a, rot, t), SB::moved(b, rot, t));
      EXPECT_NEAR(m.sqr_distance, r.sqr_distance, T(4) * sq_tol);
    }
    // 8. scaling both objects by a power of two scales the squared distance by its square
    for (const int k : scale_exponents<T>()) {
      SCOPED_TRACE("scaled by 2^" + std::to_string(k));
      const T f = std::ldexp(T(1), k);
      const auto m = distance(SA::scaled(a, f), SB::scaled(b, f));
      EXPECT_NEAR(std::ldexp(m.sqr_distance, -2 * k), r.sqr_distance, T(4) * sq_tol);
    }
  }
}

/// Non-finite input: every pair gives the documented NaN result (distance NaN, unique false).
template <class R>
::testing::AssertionResult is_nan_result(const R& r) {
  if (!std::isnan(r.distance) || !std::isnan(r.sqr_distance) || r.unique)
    return ::testing::AssertionFailure() << "expected the non-finite result, got distance "
                                         << r.distance << " unique " << r.unique;
  return ::testing::AssertionSuccess();
}

}  // namespace locus_test::dist
