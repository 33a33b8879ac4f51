// SPDX-License-Identifier: BSL-1.0
#pragma once
// Exact signs for linear components against planes and triangle edges in 3D (row
// core.predicates; used by rows int3.linear-plane, int3.linear-triangle, int3.planes and
// int3.boxes; book sections 11.1-11.2). A plane given by a normal and a constant is rounded
// data: these decide on the data AS GIVEN, never on a normalised copy.
//   side_of_plane(n, c, p)   = sign of dot(n, p) - c (the plane { X : dot(n, X) = c }).
//   sign_of_dot(u, v)        = sign of dot(u, v) (a direction against a normal: parallel is 0).
//   line_edge_side(o, d, a, b) = sign of det[d; a - o; b - o]: the side of the directed line
//                              o + t d on which the edge a -> b passes (Pluecker's permuted
//                              inner product of the two lines). For a line through two points
//                              p, q the same sign is orient3d(p, q, a, b) (core/predicates.hpp).
// Every function returns Sign::zero on a NaN or infinite coordinate (callers test finiteness).
// Method: a double floating-point filter (products of floats are exact in double) with a
// forward error bound; undecided cases (and products near underflow or overflow) go to
// exact_sign_of_sum (core/exact_sum.hpp), which is exact for every finite double;
// line_edge_side first tries orient3d's expansion stage (exact when a - o and b - o round to
// nothing, as for most float input), ten times cheaper than the big integer. Derivations of
// the bounds: docs/notes/intersection.md ("3D"). Also
//   plane_value(n, c, p)     = dot(n, p) - c evaluated accurately (compensated dot product,
//                              Ogita-Rump-Oishi Dot2: as if in twice the working precision,
//                              then rounded; float input is evaluated in double), for parameters
//                              of crossings; its sign agrees with side_of_plane whenever it is
//                              nonzero and the cancellation is above 2^-100 of the terms.
// Cost: the filters are a few dozen flops; the exact fallback a microsecond; no allocation.

#include <locus/core/error_free.hpp>
#include <locus/core/exact_sum.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>

#include <algorithm>
#include <cmath>
#include <span>

namespace locus {

namespace detail::plane_side {

inline bool finite3(const Vec3<double>& v) noexcept {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Accepts a filtered value when its error bound decides the sign; magnitudes near underflow
// or overflow (or a non-finite rounded value) fall through to the exact sum.
inline int filter(double v, double bound, double mag) noexcept {
  if (mag > 0x1p-960 && mag < 0x1p1000 && std::abs(v) > bound) return v > 0 ? 1 : -1;
  return 2;
}

}  // namespace detail::plane_side

/// Exact sign of dot(n, p) - c.
template <Real T>
[[nodiscard]] inline Sign side_of_plane(const Vec3<T>& n_, T c_, const Vec3<T>& p_) noexcept {
  namespace ps = detail::plane_side;
  const Vec3<double> n = vec_cast<double>(n_), p = vec_cast<double>(p_);
  const double c = double(c_);
  if (!ps::finite3(n) || !ps::finite3(p) || !std::isfinite(c)) return Sign::zero;
  const double t0 = n.x * p.x, t1 = n.y * p.y, t2 = n.z * p.z;
  const double v = ((t0 + t1) + t2) - c;
  const double mag = std::abs(t0) + std::abs(t1) + std::abs(t2) + std::abs(c);
  // Three products and three additions, each rounding by at most 2^-53 relative to a partial
  // sum bounded by mag: |error| <= 6 * 2^-53 mag (< 7e-16 mag).
  int s = ps::filter(v, 7e-16 * mag, mag);
  if (s == 2) {
    const ExactMonomial m[4] = {{1, 0, 2, {n.x, p.x, 0, 0}},
                                {1, 0, 2, {n.y, p.y, 0, 0}},
                                {1, 0, 2, {n.z, p.z, 0, 0}},
                                {-1, 0, 1, {c, 0, 0, 0}}};
    s = exact_sign_of_sum(m);
  }
  return static_cast<Sign>(s);
}

/// Exact sign of dot(u, v).
template <Real T>
[[nodiscard]] inline Sign sign_of_dot(const Vec3<T>& u_, const Vec3<T>& v_) noexcept {
  namespace ps = detail::plane_side;
  const Vec3<double> u = vec_cast<double>(u_), v = vec_cast<double>(v_);
  if (!ps::finite3(u) || !ps::finite3(v)) return Sign::zero;
  const double t0 = u.x * v.x, t1 = u.y * v.y, t2 = u.z * v.z;
  const double s_ = (t0 + t1) + t2;
  const double mag = std::abs(t0) + std::abs(t1) + std::abs(t2);
  int s = ps::filter(s_, 6e-16 * mag, mag);  // 5 roundings
  if (s == 2) {
    const ExactMonomial m[3] = {
        {1, 0, 2, {u.x, v.x, 0, 0}}, {1, 0, 2, {u.y, v.y, 0, 0}}, {1, 0, 2, {u.z, v.z, 0, 0}}};
    s = exact_sign_of_sum(m);
  }
  return static_cast<Sign>(s);
}

namespace detail::plane_side {

/// Appends the six monomials of sign * dot(d, cross(x, y)).
inline void add_triple(ExactMonomial* m, int& n, const Vec3<double>& d, const Vec3<double>& x,
                       const Vec3<double>& y, int sign) noexcept {
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    m[n++] = {sign, 0, 3, {d[k], x[i], y[j], 0}};
    m[n++] = {-sign, 0, 3, {d[k], x[j], y[i], 0}};
  }
}

/// Whether ea = a - o and eb = b - o were computed exactly and d, ea, eb lie in the range where
/// orient3d is exact (core/predicates.hpp: every nonzero |c| >= 2^-300 and >= 2^-268 of the
/// largest one); then det[d; ea; eb] is the exact line_edge_side determinant.
[[nodiscard]] inline bool edge_differences_exact(const Vec3<double>& o, const Vec3<double>& d,
                                                 const Vec3<double>& a, const Vec3<double>& b,
                                                 const Vec3<double>& ea,
                                                 const Vec3<double>& eb) noexcept {
  double m = 0.0;
  for (int k = 0; k < 3; ++k) {
    if (!difference_is_exact(a[k], o[k]) || !difference_is_exact(b[k], o[k])) return false;
    m = std::max({m, std::abs(d[k]), std::abs(ea[k]), std::abs(eb[k])});
  }
  const double floor = std::max(0x1p-300, 0x1p-268 * m);
  for (int k = 0; k < 3; ++k)
    for (const double c : {d[k], ea[k], eb[k]})
      if (c != 0.0 && std::abs(c) < floor) return false;
  return true;
}

/// Exact fallback of line_edge_side: det[d; a - o; b - o] = d.(a x b) + d.(b x o) + d.(o x a).
[[nodiscard]] inline int line_edge_exact(const Vec3<double>& o, const Vec3<double>& d,
                                         const Vec3<double>& a, const Vec3<double>& b) noexcept {
  ExactMonomial m[18];
  int n = 0;
  add_triple(m, n, d, a, b, 1);
  add_triple(m, n, d, b, o, 1);
  add_triple(m, n, d, o, a, 1);
  return exact_sign_of_sum(std::span<const ExactMonomial>(m, 18));
}

}  // namespace detail::plane_side

/// Exact sign of det[d; a - o; b - o] (see the header comment).
template <Real T>
[[nodiscard]] inline Sign line_edge_side(const Vec3<T>& o_, const Vec3<T>& d_, const Vec3<T>& a_,
                                         const Vec3<T>& b_) noexcept {
  namespace ps = detail::plane_side;
  const Vec3<double> o = vec_cast<double>(o_), d = vec_cast<double>(d_), a = vec_cast<double>(a_),
                     b = vec_cast<double>(b_);
  const Vec3<double> ea = a - o, eb = b - o;
  const double m0 = ea.y * eb.z - ea.z * eb.y, m1 = ea.z * eb.x - ea.x * eb.z,
               m2 = ea.x * eb.y - ea.y * eb.x;
  const double v = d.x * m0 + d.y * m1 + d.z * m2;
  const double perm = std::abs(d.x) * (std::abs(ea.y * eb.z) + std::abs(ea.z * eb.y)) +
                      std::abs(d.y) * (std::abs(ea.z * eb.x) + std::abs(ea.x * eb.z)) +
                      std::abs(d.z) * (std::abs(ea.x * eb.y) + std::abs(ea.y * eb.x));
  // Shewchuk's orient3d stage-A bound (7 + 56 u) u perm, u = 2^-53: it covers three rounded
  // differences; here d is exact, so fewer roundings occur.
  if (std::isfinite(v)) {
    const int s = ps::filter(v, 7.772e-16 * perm, perm);
    if (s != 2) return static_cast<Sign>(s);
  }
  if (!ps::finite3(o) || !ps::finite3(d) || !ps::finite3(a) || !ps::finite3(b)) return Sign::zero;
  if (ps::edge_differences_exact(o, d, a, b, ea, eb)) {
    // det[d; ea; eb] = orient3d(0, d, ea, eb): differences from the origin are exact, so its
    // adaptive stage B is the exact determinant (a few expansion products, no big integers).
    return detail::orient3d_adaptive(Vec3<double>{}, d, ea, eb);
  }
  return static_cast<Sign>(ps::line_edge_exact(o, d, a, b));
}

/// dot(n, p) - c accurately (Dot2; see the header comment), in double.
template <Real T>
[[nodiscard]] inline double plane_value(const Vec3<T>& n_, T c_, const Vec3<T>& p_) noexcept {
  const Vec3<double> n = vec_cast<double>(n_), p = vec_cast<double>(p_);
  double s = -double(c_), err = 0.0;
  for (int k = 0; k < 3; ++k) {
    double prod, pe, sum, se;
    two_product(n[k], p[k], prod, pe);
    two_sum(s, prod, sum, se);
    s = sum;
    err += pe + se;
  }
  return s + err;
}

/// dot(u, v) accurately (Dot2), in double.
template <Real T>
[[nodiscard]] inline double dot_accurate(const Vec3<T>& u_, const Vec3<T>& v_) noexcept {
  return plane_value(u_, T(0), v_);
}

}  // namespace locus
