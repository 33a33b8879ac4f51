// SPDX-License-Identifier: BSL-1.0
// The 2D curve intersection engine (include/locus/intersection/detail/conic2.hpp); rows
// int2.linear-quadratic and int2.quadratic, book sections 7.2-7.5. Derivations:
// docs/notes/intersection.md, "Linear components and conics" and "Conic pairs".

#include <locus/core/crossing.hpp>
#include <locus/core/exact_poly.hpp>
#include <locus/intersection/detail/ball_relation.hpp>
#include <locus/intersection/detail/conic2.hpp>
#include <locus/numeric/roots.hpp>

#include "../core/big_int.hpp"
#include "../numeric/integer_poly.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <limits>
#include <new>
#include <span>
#include <vector>

namespace locus::detail::conic2 {
namespace {

using P = ExactPoly;
constexpr double pi = 3.14159265358979323846;
constexpr double two_pi = 2.0 * pi;
constexpr double u = 0x1p-53;

bool finite(const V& v) noexcept { return std::isfinite(v.x) && std::isfinite(v.y); }
bool finite(double x) noexcept { return std::isfinite(x); }

std::size_t z(int i) noexcept { return static_cast<std::size_t>(i); }

// ---------------------------------------------------------------------------------------------
// Exact signs of q(t) = Q(o + t d) = A t^2 + B t + C (each up to a positive factor).

bool valid_conic(const Conic& k) noexcept {
  switch (k.form) {
    case Form::circle:
      return finite(k.c) && finite(k.r) && k.r >= 0.0;
    case Form::ellipse:
      return finite(k.c) && finite(k.u0) && finite(k.u1) && finite(k.e0) && finite(k.e1) &&
             k.e0 > 0.0 && k.e1 > 0.0 &&
             (P::var(k.u0.x) * P::var(k.u1.y) - P::var(k.u0.y) * P::var(k.u1.x)).sign() != 0;
    case Form::general:
      for (double c : k.q)
        if (!finite(c)) return false;
      return true;
  }
  return false;
}

/// A rounded value with an absolute error bound (running error analysis), the floating-point
/// filter of the exact signs below: same operations as ExactPoly, sign() 2 when undecided.
struct Fd {
  double v = 0.0, e = 0.0;
  static Fd var(double x) noexcept { return {x, 0.0}; }
  static Fd diff(double x, double y) noexcept {
    const double d = x - y;
    return {d, u * std::abs(d)};
  }
  [[nodiscard]] Fd times_pow2(int k) const noexcept { return {std::ldexp(v, k), std::ldexp(e, k)}; }
  friend Fd operator+(const Fd& a, const Fd& b) noexcept {
    const double s = a.v + b.v;
    return {s, a.e + b.e + u * std::abs(s)};
  }
  friend Fd operator-(const Fd& a, const Fd& b) noexcept {
    const double s = a.v - b.v;
    return {s, a.e + b.e + u * std::abs(s)};
  }
  friend Fd operator*(const Fd& a, const Fd& b) noexcept {
    const double p = a.v * b.v;
    // Underflow makes a product's rounding absolute: at most 2^-1075.
    const double tiny = (a.v != 0.0 && b.v != 0.0) ? 0x1p-1074 : 0.0;
    return {p, std::abs(a.v) * b.e + std::abs(b.v) * a.e + a.e * b.e + u * std::abs(p) + tiny};
  }
  [[nodiscard]] int sign() const noexcept {
    if (!std::isfinite(v) || !std::isfinite(e)) return 2;
    // The bound itself is rounded (a few dozen operations deep): 2^-40 covers it.
    const double bound = e * (1.0 + 0x1p-40);
    if (v > bound) return 1;
    if (-v > bound) return -1;
    return v == 0.0 && e == 0.0 ? 0 : 2;
  }
};

/// The direction of l as exact polynomials (a segment's p1 - p0 is a difference, never rounded).
template <class N>
struct DirP {
  N x, y;
};
template <class N>
DirP<N> dir_poly(const Lin& l) noexcept {
  if (l.hi) return {N::diff(l.p1.x, l.o.x), N::diff(l.p1.y, l.o.y)};
  return {N::var(l.d.x), N::var(l.d.y)};
}

/// Sign of Q at p (circle: |p - c|^2 - r^2; ellipse: e0^2 e1^2 times evaluate(); general: Q).
template <class N>
int value_sign_t(const Conic& k, const V& p) noexcept {
  switch (k.form) {
    case Form::circle: {
      const N wx = N::diff(p.x, k.c.x), wy = N::diff(p.y, k.c.y);
      return (wx * wx + wy * wy - N::var(k.r) * N::var(k.r)).sign();
    }
    case Form::ellipse: {
      const N wx = N::diff(p.x, k.c.x), wy = N::diff(p.y, k.c.y);
      const N a0 = N::var(k.u0.x) * wx + N::var(k.u0.y) * wy;
      const N a1 = N::var(k.u1.x) * wx + N::var(k.u1.y) * wy;
      const N e0 = N::var(k.e0), e1 = N::var(k.e1);
      return (e1 * e1 * a0 * a0 + e0 * e0 * a1 * a1 - e0 * e0 * e1 * e1).sign();
    }
    case Form::general: {
      const N x = N::var(p.x), y = N::var(p.y);
      const N a = N::var(k.q[0]), b = N::var(k.q[1]), c = N::var(k.q[2]);
      return (a * x * x + b * x * y + c * y * y + N::var(k.q[3]) * x + N::var(k.q[4]) * y +
              N::var(k.q[5]))
          .sign();
    }
  }
  return 0;
}

/// Signs of A and of B with the origin at p (the derivative q'(t) at the parameter of p, up to
/// a positive factor), and of the discriminant with the origin at o.
struct Signs {
  int a, b0, c0, disc, b1, c1;
};

template <class N>
int slope_sign_t(const Conic& k, const V& p, const DirP<N>& d) noexcept {
  switch (k.form) {
    case Form::circle: {
      const N wx = N::diff(p.x, k.c.x), wy = N::diff(p.y, k.c.y);
      return (d.x * wx + d.y * wy).sign();
    }
    case Form::ellipse: {
      const N wx = N::diff(p.x, k.c.x), wy = N::diff(p.y, k.c.y);
      const N a0 = N::var(k.u0.x) * wx + N::var(k.u0.y) * wy;
      const N a1 = N::var(k.u1.x) * wx + N::var(k.u1.y) * wy;
      const N b0 = N::var(k.u0.x) * d.x + N::var(k.u0.y) * d.y;
      const N b1 = N::var(k.u1.x) * d.x + N::var(k.u1.y) * d.y;
      const N e0 = N::var(k.e0), e1 = N::var(k.e1);
      return (e1 * e1 * a0 * b0 + e0 * e0 * a1 * b1).sign();
    }
    case Form::general: {
      const N x = N::var(p.x), y = N::var(p.y);
      const N a = N::var(k.q[0]), b = N::var(k.q[1]), c = N::var(k.q[2]);
      // grad Q . d = (2 a x + b y + d) dx + (b x + 2 c y + e) dy
      return ((a * x * d.x).times_pow2(1) + b * (y * d.x + x * d.y) + (c * y * d.y).times_pow2(1) +
              N::var(k.q[3]) * d.x + N::var(k.q[4]) * d.y)
          .sign();
    }
  }
  return 0;
}

template <class N>
Signs signs_t(const Conic& k, const Lin& l) noexcept {
  const DirP<N> d = dir_poly<N>(l);
  Signs s{};
  s.c0 = value_sign_t<N>(k, l.o);
  s.b0 = slope_sign_t<N>(k, l.o, d);
  if (l.hi) {
    s.c1 = value_sign_t<N>(k, l.p1);
    s.b1 = slope_sign_t<N>(k, l.p1, d);
  }
  switch (k.form) {
    case Form::circle: {
      // B^2 - 4 A C = 4 (r^2 |d|^2 - (d x w)^2).
      const N wx = N::diff(l.o.x, k.c.x), wy = N::diff(l.o.y, k.c.y);
      const N r = N::var(k.r);
      const N dd = d.x * d.x + d.y * d.y;
      const N cr = d.x * wy - d.y * wx;
      s.a = dd.sign();
      s.disc = (r * r * dd - cr * cr).sign();
      break;
    }
    case Form::ellipse: {
      // B^2 - 4 A C = 4 e0^2 e1^2 (e1^2 beta0^2 + e0^2 beta1^2 - K^2),
      // K = alpha0 beta1 - alpha1 beta0 = (u0 x u1)(w x d) (Binet-Cauchy).
      const N wx = N::diff(l.o.x, k.c.x), wy = N::diff(l.o.y, k.c.y);
      const N b0 = N::var(k.u0.x) * d.x + N::var(k.u0.y) * d.y;
      const N b1 = N::var(k.u1.x) * d.x + N::var(k.u1.y) * d.y;
      const N e0 = N::var(k.e0), e1 = N::var(k.e1);
      const N aa = e1 * e1 * b0 * b0 + e0 * e0 * b1 * b1;
      const N kk = (N::var(k.u0.x) * N::var(k.u1.y) - N::var(k.u0.y) * N::var(k.u1.x)) *
                   (wx * d.y - wy * d.x);
      s.a = aa.sign();
      s.disc = (aa - kk * kk).sign();
      break;
    }
    case Form::general: {
      const N ox = N::var(l.o.x), oy = N::var(l.o.y);
      const N a = N::var(k.q[0]), b = N::var(k.q[1]), c = N::var(k.q[2]);
      const N qa = a * d.x * d.x + b * d.x * d.y + c * d.y * d.y;
      const N qb = (a * ox * d.x).times_pow2(1) + b * (ox * d.y + oy * d.x) +
                   (c * oy * d.y).times_pow2(1) + N::var(k.q[3]) * d.x + N::var(k.q[4]) * d.y;
      const N qc = a * ox * ox + b * ox * oy + c * oy * oy + N::var(k.q[3]) * ox +
                   N::var(k.q[4]) * oy + N::var(k.q[5]);
      s.a = qa.sign();
      s.disc = (qb * qb - (qa * qc).times_pow2(2)).sign();
      break;
    }
  }
  return s;
}

/// Sign of Q at p: filtered, exact when the filter cannot decide.
int value_sign(const Conic& k, const V& p) noexcept {
  const int s = value_sign_t<Fd>(k, p);
  return s != 2 ? s : value_sign_t<P>(k, p);
}

/// The signs of a linear component against a conic: filtered, exact when undecided.
Signs signs(const Conic& k, const Lin& l) noexcept {
  const Signs f = signs_t<Fd>(k, l);
  if (f.a != 2 && f.b0 != 2 && f.c0 != 2 && f.disc != 2 && f.b1 != 2 && f.c1 != 2) return f;
  return signs_t<P>(k, l);
}

// ---------------------------------------------------------------------------------------------
// Rounded roots of q, in a frame where they are accurate.

/// The two roots (t1 <= t2) of q, or the double root (t1 == t2) when tangent.
struct Roots {
  double t1, t2;
};

double pow2_inv(double m) noexcept {
  return m > 0.0 && std::isfinite(m) ? std::ldexp(1.0, -std::ilogb(m)) : 1.0;
}

/// Roots of |Y(tau)|^2 = rr^2 for Y(tau) = w + tau D, given cross = D x w accurately.
Roots unit_roots(const V& w, const V& dd, double cross, double rr, bool tangent) noexcept {
  const double a = dot(dd, dd), len = std::sqrt(a);
  const double tm = -dot(dd, w) / a;
  if (tangent) return {tm, tm};
  const double dist = std::abs(cross) / len;
  const double h2 = (rr - dist) * (rr + dist);
  const double half = std::sqrt(std::max(h2, 0.0)) / len;
  return {tm - half, tm + half};
}

Roots numeric_roots(const Conic& k, const Lin& l, bool tangent) noexcept {
  switch (k.form) {
    case Form::circle: {
      double m = std::max({max_abs(l.o), max_abs(k.c), std::abs(k.r)});
      if (l.hi) m = std::max(m, max_abs(l.p1));
      const double s = pow2_inv(m), sd = pow2_inv(max_abs(l.d));
      const V w = s * (l.o - k.c), dd = sd * l.d;
      // d x w rounded from its exact value: det[d; o - c].
      const double cross =
          (l.hi ? turn2d_value(l.o, l.p1, k.c, l.o) : turn2d_value(V{}, l.d, k.c, l.o)) * s * sd;
      const Roots r = unit_roots(w, dd, cross, s * k.r, tangent);
      // Y = s o + tau D with D = sd d: t = tau sd / s.
      return {r.t1 * sd / s, r.t2 * sd / s};
    }
    case Form::ellipse: {
      const double n0 = length(k.u0), n1 = length(k.u1);
      const V v0 = k.u0 / n0, v1 = k.u1 / n1;
      const V wo = l.o - k.c;
      const V w{dot(v0, wo) / k.e0, dot(v1, wo) / k.e1};
      const double sd = pow2_inv(max_abs(l.d));
      const V dd{dot(v0, sd * l.d) / k.e0, dot(v1, sd * l.d) / k.e1};
      const Roots r = unit_roots(w, dd, perp_dot(dd, w), 1.0, tangent);
      return {r.t1 * sd, r.t2 * sd};
    }
    case Form::general: {
      const double a = k.q[0], b = k.q[1], c = k.q[2], d = k.q[3], e = k.q[4], f = k.q[5];
      const V o = l.o, dv = l.d;
      const double qa = a * dv.x * dv.x + b * dv.x * dv.y + c * dv.y * dv.y;
      const double qb = 2.0 * a * o.x * dv.x + b * (o.x * dv.y + o.y * dv.x) +
                        2.0 * c * o.y * dv.y + d * dv.x + e * dv.y;
      const double qc = a * o.x * o.x + b * o.x * o.y + c * o.y * o.y + d * o.x + e * o.y + f;
      if (tangent) return {-qb / (2.0 * qa), -qb / (2.0 * qa)};
      const double disc = std::max(qb * qb - 4.0 * qa * qc, 0.0);
      const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
      if (q == 0.0) return {-qb / (2.0 * qa), -qb / (2.0 * qa)};
      double t1 = q / qa, t2 = qc / q;
      if (t1 > t2) std::swap(t1, t2);
      return {t1, t2};
    }
  }
  return {0.0, 0.0};
}

/// The root of the linear q(t) = B t + C.
double linear_root(const Conic& k, const Lin& l) noexcept {
  const double a = k.q[0], b = k.q[1], c = k.q[2], d = k.q[3], e = k.q[4], f = k.q[5];
  const V o = l.o, dv = l.d;
  const double qb = 2.0 * a * o.x * dv.x + b * (o.x * dv.y + o.y * dv.x) + 2.0 * c * o.y * dv.y +
                    d * dv.x + e * dv.y;
  const double qc = a * o.x * o.x + b * o.x * o.y + c * o.y * o.y + d * o.x + e * o.y + f;
  return -qc / qb;
}

/// The angle of p on the conic (0 for a general conic).
double curve_param(const Conic& k, const V& p) noexcept {
  switch (k.form) {
    case Form::circle:
      return std::atan2(p.y - k.c.y, p.x - k.c.x);
    case Form::ellipse: {
      const V w = p - k.c;
      return std::atan2(dot(k.u1, w) / (length(k.u1) * k.e1), dot(k.u0, w) / (length(k.u0) * k.e0));
    }
    case Form::general:
      return 0.0;
  }
  return 0.0;
}

/// The point of parameter t, and t clamped to the domain; exact at t = 0 and (segment) t = 1.
V point_of(const Lin& l, double& t) noexcept {
  if (l.lo) t = std::max(t, 0.0);
  if (l.hi) t = std::min(t, 1.0);
  if (t == 0.0) return l.o;
  if (l.hi && t == 1.0) return l.p1;
  if (l.hi && t > 0.5) return l.p1 + (t - 1.0) * l.d;
  return l.o + t * l.d;
}

void push(R2& r, const Lin& l, const Conic& k, double t, int mult) noexcept {
  const V p = point_of(l, t);
  const auto i = z(r.count++);
  r.point[i] = p;
  r.param_a[i] = t;
  r.param_b[i] = curve_param(k, p);
  r.multiplicity[i] = mult;
}

void finish(R2& r) noexcept {
  r.kind = r.count == 0 ? Kind::empty : r.count == 1 ? Kind::point : Kind::points;
}

bool zero_dir(const Lin& l) noexcept { return l.hi ? l.o == l.p1 : l.d == V{}; }

double normalise_angle(double a) noexcept {
  // Into (-pi, pi].
  double r = std::remainder(a, two_pi);
  if (r <= -pi) r += two_pi;
  return r;
}

/// The arc offset of angle in [0, 2 pi), and whether it lies on the arc.
bool on_arc(const ArcD& a, double angle, double& param) noexcept {
  double off = std::fmod(angle - a.start, two_pi);
  if (off < 0.0) off += two_pi;
  if (off >= two_pi) off = 0.0;
  if (a.sweep >= two_pi) {
    param = a.start + off;
    return true;
  }
  if (off <= a.sweep) {
    param = a.start + off;
    return true;
  }
  // Just below a full turn: the start itself, reached from below.
  if (two_pi - off <= 4.0 * u * two_pi) {
    param = a.start;
    return true;
  }
  return false;
}

bool valid_arc(const ArcD& a) noexcept {
  return finite(a.c) && finite(a.r) && a.r >= 0.0 && finite(a.start) && finite(a.sweep) &&
         a.sweep >= 0.0;
}

}  // namespace

// ---------------------------------------------------------------------------------------------

R2 linear_conic(const Lin& l, const Conic& k) noexcept {
  R2 r;
  if (!(finite(l.o) && finite(l.d) && (!l.hi || finite(l.p1)) && valid_conic(k))) return r;
  if (zero_dir(l)) {
    if (value_sign(k, l.o) == 0) push(r, l, k, 0.0, 1);
    finish(r);
    return r;
  }
  const Signs s = signs(k, l);
  if (s.a == 0) {
    // Only a general conic: q is linear (the line is parallel to an asymptotic direction).
    if (s.b0 == 0) {
      if (s.c0 != 0) return r;
      // The whole component lies on the conic.
      r.kind = l.hi ? Kind::segment : l.lo ? Kind::ray : Kind::line;
      r.count = 2;
      r.point[0] = l.o;
      r.point[1] = l.hi ? l.p1 : l.o + l.d;
      r.param_a = {0.0, 1.0};
      return r;
    }
    if (l.lo && s.b0 * s.c0 > 0) return r;
    if (l.hi && s.b0 * s.c1 < 0) return r;
    const double t = s.c0 == 0 ? 0.0 : (l.hi && s.c1 == 0) ? 1.0 : linear_root(k, l);
    push(r, l, k, t, 1);
    finish(r);
    return r;
  }
  const int p0 = s.a * s.c0, v0 = s.a * s.b0, p1 = s.a * s.c1, v1 = s.a * s.b1;
  if (s.disc < 0) return r;
  if (s.disc == 0) {
    if (l.lo && v0 > 0) return r;
    if (l.hi && v1 < 0) return r;
    double t = 0.0;
    if (p0 == 0)
      t = 0.0;
    else if (l.hi && p1 == 0)
      t = 1.0;
    else
      t = numeric_roots(k, l, true).t1;
    push(r, l, k, t, 2);
    finish(r);
    return r;
  }
  const bool in1 = (!l.lo || (p0 >= 0 && v0 < 0)) && (!l.hi || (p1 <= 0 || v1 > 0));
  const bool in2 = (!l.lo || (p0 <= 0 || v0 < 0)) && (!l.hi || (p1 >= 0 && v1 > 0));
  if (!in1 && !in2) return r;
  const Roots nr = numeric_roots(k, l, false);
  // Roots known exactly: an end point on the conic.
  double t1 = nr.t1, t2 = nr.t2;
  if (p0 == 0) (v0 < 0 ? t1 : t2) = 0.0;
  if (l.hi && p1 == 0) (v1 < 0 ? t1 : t2) = 1.0;
  if (in1) push(r, l, k, t1, 1);
  if (in2) push(r, l, k, std::max(t2, in1 ? t1 : t2), 1);
  finish(r);
  return r;
}

R2 linear_arc(const Lin& l, const ArcD& a) noexcept {
  R2 out;
  if (!valid_arc(a)) return out;
  Conic k;
  k.form = Form::circle;
  k.c = a.c;
  k.r = a.r;
  const R2 r = linear_conic(l, k);
  for (int i = 0; i < r.count; ++i) {
    double param = 0.0;
    if (!on_arc(a, r.param_b[z(i)], param)) continue;
    const auto j = z(out.count++);
    out.point[j] = r.point[z(i)];
    out.param_a[j] = r.param_a[z(i)];
    out.param_b[j] = param;
    out.multiplicity[j] = r.multiplicity[z(i)];
  }
  finish(out);
  return out;
}

// ---------------------------------------------------------------------------------------------
// Circle pairs: S_out = |c1 - c0|^2 - (r0 + r1)^2 and S_in = |c1 - c0|^2 - (r0 - r1)^2 decide.

namespace {
struct CircleSigns {
  int out, in;
  bool same_centre;
};
CircleSigns circle_signs(V c0, double r0, V c1, double r1) noexcept {
  const P dx = P::diff(c1.x, c0.x), dy = P::diff(c1.y, c0.y);
  const P d2 = dx * dx + dy * dy;
  const P a = P::var(r0), b = P::var(r1);
  const P sq = a * a + b * b, cross = (a * b).times_pow2(1);
  return {(d2 - sq - cross).sign(), (d2 - sq + cross).sign(), c0 == c1};
}
bool valid_circle(V c, double r) noexcept { return finite(c) && finite(r) && r >= 0.0; }
}  // namespace

R4 circle_circle(V c0, double r0, V c1, double r1) noexcept {
  R4 r;
  if (!valid_circle(c0, r0) || !valid_circle(c1, r1)) return r;
  const CircleSigns s = circle_signs(c0, r0, c1, r1);
  if (s.same_centre) {
    if (r0 != r1) return r;
    if (r0 > 0.0) {
      r.kind = Kind::coincident;
      return r;
    }
    r.kind = Kind::point;
    r.count = 1;
    r.point[0] = c0;
    r.multiplicity[0] = 2;
    return r;
  }
  if (s.out > 0 || s.in < 0) return r;
  const double m = std::max({max_abs(c0), max_abs(c1), r0, r1});
  const double sc = pow2_inv(m);
  const V del = sc * (c1 - c0);
  const double dist = length(del);
  const V uv = del / dist;
  const auto put = [&](const V& p, int mult) {
    const auto i = z(r.count++);
    r.point[i] = p;
    r.param_a[i] = std::atan2(p.y - c0.y, p.x - c0.x);
    r.param_b[i] = std::atan2(p.y - c1.y, p.x - c1.x);
    r.multiplicity[i] = mult;
  };
  if (s.out == 0 || s.in == 0) {
    // Tangent: on the ray from c0 through c1 (outside, or inside with r0 > r1), else opposite.
    const bool toward = s.out == 0 || r0 > r1;
    V p = c0 + (toward ? r0 : -r0) * uv;
    if (r0 == 0.0) p = c0;
    if (r1 == 0.0) p = c1;
    put(p, 2);
    r.kind = Kind::point;
    return r;
  }
  const double a0 = sc * r0, a1 = sc * r1;
  const double along = 0.5 * (dist + (a0 - a1) * (a0 + a1) / dist);
  const double h = std::sqrt(std::max((a0 - along) * (a0 + along), 0.0));
  const V foot = along * uv, side = h * perp(uv);
  put(c0 + (foot - side) / sc, 1);
  put(c0 + (foot + side) / sc, 1);
  r.kind = Kind::points;
  return r;
}

RegionRelation circle_relation(V c0, double r0, V c1, double r1) noexcept {
  if (!valid_circle(c0, r0) || !valid_circle(c1, r1)) return RegionRelation::undecided;
  if (c0 == c1 && r0 == r1) return RegionRelation::equal;
  const CircleSigns s = circle_signs(c0, r0, c1, r1);
  return ball_relation(s.out, s.in, r0 > r1);
}

namespace {
/// The angular overlap of two arcs of one circle: pieces [lo, hi] as offsets from a's start.
int arc_overlap(const ArcD& a, double b_start, double b_sweep, double lo[2],
                double hi[2]) noexcept {
  double delta = std::fmod(b_start - a.start, two_pi);
  if (delta < 0.0) delta += two_pi;
  int n = 0;
  for (double shift : {0.0, -two_pi}) {
    const double s = std::max(delta + shift, 0.0), e = std::min(delta + shift + b_sweep, a.sweep);
    if (s <= e) {
      lo[n] = s;
      hi[n] = e;
      ++n;
    }
  }
  return n;
}

void arc_pieces(R6& r, const ArcD& a, double b_start, double b_sweep, bool a_first) noexcept {
  double lo[2], hi[2];
  const int n = arc_overlap(a, b_start, b_sweep, lo, hi);
  bool any_arc = false;
  for (int i = 0; i < n; ++i) any_arc = any_arc || hi[i] > lo[i];
  for (int i = 0; i < n; ++i) {
    const double ts[3] = {lo[i], 0.5 * (lo[i] + hi[i]), hi[i]};
    const int m = any_arc ? 3 : 1;
    for (int j = 0; j < m; ++j) {
      const double ang = a.start + ts[j];
      const V p = a.c + a.r * V{std::cos(ang), std::sin(ang)};
      double pb = 0.0;
      ArcD b{a.c, a.r, b_start, b_sweep};
      if (!on_arc(b, ang, pb)) pb = b_start;
      const auto k = z(r.count++);
      r.point[k] = p;
      r.param_a[k] = a_first ? ang : pb;
      r.param_b[k] = a_first ? pb : ang;
      r.multiplicity[k] = any_arc ? 0 : 1;
    }
  }
  r.kind = any_arc        ? Kind::arc
           : r.count == 0 ? Kind::empty
           : r.count == 1 ? Kind::point
                          : Kind::points;
}

}  // namespace

R6 circle_arc(V c0, double r0, const ArcD& a) noexcept {
  R6 out;
  if (!valid_arc(a)) return out;
  const R4 cc = circle_circle(c0, r0, a.c, a.r);
  if (cc.kind == Kind::coincident) {
    if (a.sweep >= two_pi) {
      out.kind = Kind::coincident;
      return out;
    }
    // The whole arc: its pieces as seen from the arc, parameters swapped onto the circle.
    arc_pieces(out, a, a.start, a.sweep, true);
    for (int i = 0; i < out.count; ++i) out.param_a[z(i)] = normalise_angle(out.param_a[z(i)]);
    return out;
  }
  for (int i = 0; i < cc.count; ++i) {
    double param = 0.0;
    if (!on_arc(a, cc.param_b[z(i)], param)) continue;
    const auto j = z(out.count++);
    out.point[j] = cc.point[z(i)];
    out.param_a[j] = cc.param_a[z(i)];
    out.param_b[j] = param;
    out.multiplicity[j] = cc.multiplicity[z(i)];
  }
  out.kind = out.count == 0 ? Kind::empty : out.count == 1 ? Kind::point : Kind::points;
  if (cc.kind == Kind::point && cc.count == 1 && out.count == 1) out.kind = Kind::point;
  return out;
}

R6 arc_arc(const ArcD& a, const ArcD& b) noexcept {
  R6 out;
  if (!valid_arc(a) || !valid_arc(b)) return out;
  const R4 cc = circle_circle(a.c, a.r, b.c, b.r);
  if (cc.kind == Kind::coincident) {
    if (a.sweep >= two_pi && b.sweep >= two_pi) {
      out.kind = Kind::coincident;
      return out;
    }
    // Both arcs below a full turn: their angular overlap. A full arc covers the other one.
    const bool a_full = a.sweep >= two_pi, b_full = b.sweep >= two_pi;
    if (a_full) {
      arc_pieces(out, b, b.start, b.sweep, true);
      for (int i = 0; i < out.count; ++i) {
        double pa = 0.0, pb = out.param_b[z(i)];
        static_cast<void>(on_arc(a, out.param_a[z(i)], pa));
        out.param_a[z(i)] = pa;
        out.param_b[z(i)] = pb;
      }
    } else if (b_full) {
      arc_pieces(out, a, a.start, a.sweep, true);
      for (int i = 0; i < out.count; ++i) {
        double pb = 0.0;
        static_cast<void>(on_arc(b, out.param_a[z(i)], pb));
        out.param_b[z(i)] = pb;
      }
    } else {
      arc_pieces(out, a, b.start, b.sweep, true);
    }
    return out;
  }
  for (int i = 0; i < cc.count; ++i) {
    double pa = 0.0, pb = 0.0;
    if (!on_arc(a, cc.param_a[z(i)], pa) || !on_arc(b, cc.param_b[z(i)], pb)) continue;
    const auto j = z(out.count++);
    out.point[j] = cc.point[z(i)];
    out.param_a[j] = pa;
    out.param_b[j] = pb;
    out.multiplicity[j] = cc.multiplicity[z(i)];
  }
  out.kind = out.count == 0 ? Kind::empty : out.count == 1 ? Kind::point : Kind::points;
  return out;
}

// ---------------------------------------------------------------------------------------------
// Conic pairs: the first conic (an ellipse or circle) is mapped onto the unit circle; the
// second, written in that frame, is restricted to the circle by the half-angle substitution
// x = (1 - s^2) / (1 + s^2), y = 2 s / (1 + s^2): a quartic in s whose real roots are the common
// points one to one, their multiplicities the contact orders.

namespace {

/// Coefficients a, b, c, d, e, f with magnitude bounds (sums of |terms|) of each.
struct Quad {
  double c[6];
  double mag[6];
};

/// The second conic in the frame X = centre + x E0 + y E1 of the first.
Quad in_frame(const Conic& k, const V& centre, const V& e0v, const V& e1v) noexcept {
  Quad q{};
  if (k.form == Form::general) {
    const double a = k.q[0], b = k.q[1], c = k.q[2], d = k.q[3], e = k.q[4], f = k.q[5];
    // M = [[a, b/2], [b/2, c]], L = (d, e).
    const auto form = [&](const V& x, const V& y, double& mag) {
      mag = std::abs(a * x.x * y.x) + std::abs(0.5 * b * (x.x * y.y + x.y * y.x)) +
            std::abs(c * x.y * y.y);
      return a * x.x * y.x + 0.5 * b * (x.x * y.y + x.y * y.x) + c * x.y * y.y;
    };
    q.c[0] = form(e0v, e0v, q.mag[0]);
    q.c[1] = 2.0 * form(e0v, e1v, q.mag[1]);
    q.mag[1] *= 2.0;
    q.c[2] = form(e1v, e1v, q.mag[2]);
    const V g{2.0 * a * centre.x + b * centre.y + d, b * centre.x + 2.0 * c * centre.y + e};
    const V gm{std::abs(2.0 * a * centre.x) + std::abs(b * centre.y) + std::abs(d),
               std::abs(b * centre.x) + std::abs(2.0 * c * centre.y) + std::abs(e)};
    q.c[3] = dot(g, e0v);
    q.mag[3] = gm.x * std::abs(e0v.x) + gm.y * std::abs(e0v.y);
    q.c[4] = dot(g, e1v);
    q.mag[4] = gm.x * std::abs(e1v.x) + gm.y * std::abs(e1v.y);
    const double x = centre.x, y = centre.y;
    q.c[5] = a * x * x + b * x * y + c * y * y + d * x + e * y + f;
    q.mag[5] = std::abs(a * x * x) + std::abs(b * x * y) + std::abs(c * y * y) + std::abs(d * x) +
               std::abs(e * y) + std::abs(f);
    return q;
  }
  // Circle or ellipse: sum_i (k_i + m_i x + n_i y)^2 - 1 with unit axes v_i, extents g_i.
  V v[2];
  double g[2];
  if (k.form == Form::circle) {
    v[0] = {1.0, 0.0};
    v[1] = {0.0, 1.0};
    g[0] = g[1] = k.r;
  } else {
    v[0] = k.u0 / length(k.u0);
    v[1] = k.u1 / length(k.u1);
    g[0] = k.e0;
    g[1] = k.e1;
  }
  q.c[5] = -1.0;
  q.mag[5] = 1.0;
  const V w = centre - k.c;
  for (int i = 0; i < 2; ++i) {
    const double ki = dot(v[i], w) / g[i], mi = dot(v[i], e0v) / g[i], ni = dot(v[i], e1v) / g[i];
    const double terms[6] = {mi * mi,       2.0 * mi * ni, ni * ni,
                             2.0 * ki * mi, 2.0 * ki * ni, ki * ki};
    for (int j = 0; j < 6; ++j) {
      q.c[j] += terms[j];
      q.mag[j] += std::abs(terms[j]);
    }
  }
  return q;
}

/// The conic rotated: coefficients in coordinates (x', y') with (x, y) = R(phi) (x', y').
Quad rotated(const Quad& q, double cs, double sn) noexcept {
  const double a = q.c[0], b = q.c[1], c = q.c[2], d = q.c[3], e = q.c[4];
  Quad r{};
  // x = cs x' - sn y', y = sn x' + cs y'.
  r.c[0] = a * cs * cs + b * cs * sn + c * sn * sn;
  r.c[1] = -2.0 * a * cs * sn + b * (cs * cs - sn * sn) + 2.0 * c * sn * cs;
  r.c[2] = a * sn * sn - b * sn * cs + c * cs * cs;
  r.c[3] = d * cs + e * sn;
  r.c[4] = -d * sn + e * cs;
  r.c[5] = q.c[5];
  const double ma = q.mag[0], mb = q.mag[1], mc = q.mag[2];
  const double quad = ma + mb + mc, lin = q.mag[3] + q.mag[4];
  r.mag[0] = r.mag[1] = r.mag[2] = 2.0 * quad;
  r.mag[3] = r.mag[4] = lin;
  r.mag[5] = q.mag[5];
  return r;
}

double value_at(const Quad& q, double x, double y) noexcept {
  return q.c[0] * x * x + q.c[1] * x * y + q.c[2] * y * y + q.c[3] * x + q.c[4] * y + q.c[5];
}

/// A frame: an ellipse or circle of positive extents.
struct Frame {
  V c, e0v, e1v;
};
bool frame_of(const Conic& k, Frame& f) noexcept {
  if (k.form == Form::circle) {
    if (!(k.r > 0.0)) return false;
    f = {k.c, {k.r, 0.0}, {0.0, k.r}};
    return true;
  }
  if (k.form == Form::ellipse) {
    f = {k.c, (k.e0 / length(k.u0)) * k.u0, (k.e1 / length(k.u1)) * k.u1};
    return true;
  }
  return false;
}

bool same(const Conic& a, const Conic& b) noexcept {
  if (a.form != b.form) return false;
  switch (a.form) {
    case Form::circle:
      return a.c == b.c && a.r == b.r;
    case Form::ellipse:
      return a.c == b.c && a.u0 == b.u0 && a.u1 == b.u1 && a.e0 == b.e0 && a.e1 == b.e1;
    case Form::general:
      for (int i = 0; i < 6; ++i)
        if (a.q[i] != b.q[i]) return false;
      return true;
  }
  return false;
}

R4 frame_conic(const Conic& a, const Frame& fr, const Conic& b) noexcept {
  R4 r;
  Quad q = in_frame(b, fr.c, fr.e0v, fr.e1v);
  // Normalise the coefficients' scale (a power of two: exact).
  double m = 0.0;
  for (double x : q.mag) m = std::max(m, x);
  if (!(m > 0.0) || !std::isfinite(m)) return r;
  const double s = pow2_inv(m);
  for (int i = 0; i < 6; ++i) {
    q.c[i] *= s;
    q.mag[i] *= s;
  }
  // The excluded point of the parametrisation (s = infinity) is (-1, 0) rotated by phi: take
  // the phi of the eight candidates where the second conic is farthest from zero.
  double best = -1.0, bc = 1.0, bs = 0.0;
  for (int i = 0; i < 8; ++i) {
    const double ang = i * (pi / 4.0);
    const double cs = (i % 4 == 2) ? 0.0 : std::cos(ang), sn = (i % 4 == 0) ? 0.0 : std::sin(ang);
    const double v = std::abs(value_at(q, -cs, -sn));
    if (v > best) {
      best = v;
      bc = cs;
      bs = sn;
    }
  }
  const Quad p = rotated(q, bc, bs);
  const double A = p.c[0], B = p.c[1], C = p.c[2], D = p.c[3], E = p.c[4], F = p.c[5];
  const std::array<double, 5> k = {A + D + F, 2.0 * (B + E), -2.0 * A + 4.0 * C + 2.0 * F,
                                   2.0 * (E - B), A - D + F};
  // Rounding bound of each coefficient: the rotated coefficients carry about 16 u of their
  // magnitudes (frame map, rotation); the combinations add a few u more.
  const double mq = p.mag[0] + p.mag[1] + p.mag[2], ml = p.mag[3] + p.mag[4], mf = p.mag[5];
  const double tot = 64.0 * u * (4.0 * mq + 2.0 * ml + 2.0 * mf);
  const std::array<double, 5> err = {tot, tot, tot, tot, tot};
  bool all_small = true;
  for (int i = 0; i < 5; ++i) all_small = all_small && std::abs(k[z(i)]) <= err[z(i)];
  if (all_small) {
    r.kind = Kind::coincident;
    return r;
  }
  RootOptions opt = near_roots();
  opt.coefficient_error = std::span<const double>(err.data(), err.size());
  const RootsResult<double> roots = solve_quartic(k[0], k[1], k[2], k[3], k[4], opt);
  if (roots.status != Status::ok) return r;
  for (int i = 0; i < roots.count && r.count < 4; ++i) {
    const double sv = roots.roots[z(i)].value;
    // The angle on the unit circle: phi + 2 atan(s).
    const double th = std::atan2(bs, bc) + 2.0 * std::atan(sv);
    const double x = std::cos(th), y = std::sin(th);
    const V pt = fr.c + x * fr.e0v + y * fr.e1v;
    const auto j = z(r.count++);
    r.point[j] = pt;
    r.param_a[j] = normalise_angle(th);
    r.param_b[j] = curve_param(b, pt);
    r.multiplicity[j] = roots.roots[z(i)].multiplicity;
  }
  (void)a;
  // Order by the parameter on the first conic.
  for (int i = 1; i < r.count; ++i)
    for (int j = i; j > 0 && r.param_a[z(j)] < r.param_a[z(j - 1)]; --j) {
      std::swap(r.point[z(j)], r.point[z(j - 1)]);
      std::swap(r.param_a[z(j)], r.param_a[z(j - 1)]);
      std::swap(r.param_b[z(j)], r.param_b[z(j - 1)]);
      std::swap(r.multiplicity[z(j)], r.multiplicity[z(j - 1)]);
    }
  r.kind = r.count == 0 ? Kind::empty : r.count == 1 ? Kind::point : Kind::points;
  return r;
}

}  // namespace

namespace {

/// Two general conics (neither an ellipse): the resultant in y, R(x) of degree <= 4, after a
/// rotation making both y^2 coefficients large; each real root x gives y from the first conic
/// (the root of its quadratic in y where the second is nearer zero).
R4 general_pair(const Conic& ka, const Conic& kb) noexcept {
  R4 r;
  if (ka.form != Form::general || kb.form != Form::general) return r;
  // Proportional coefficients (exact): the same curve.
  bool proportional = true;
  for (int i = 0; i < 6 && proportional; ++i)
    for (int j = i + 1; j < 6 && proportional; ++j)
      proportional =
          (P::var(ka.q[i]) * P::var(kb.q[j]) - P::var(ka.q[j]) * P::var(kb.q[i])).sign() == 0;
  if (proportional) {
    r.kind = Kind::coincident;
    return r;
  }
  const auto normalised = [](const Conic& k) {
    Quad q{};
    double m = 0.0;
    for (int i = 0; i < 6; ++i) m = std::max(m, std::abs(k.q[i]));
    const double s = pow2_inv(m);
    for (int i = 0; i < 6; ++i) {
      q.c[i] = s * k.q[i];
      q.mag[i] = std::abs(q.c[i]);
    }
    return q;
  };
  const Quad qa0 = normalised(ka), qb0 = normalised(kb);
  double best = -1.0, bc = 1.0, bs = 0.0;
  // Angles offset from multiples of pi/8 so that axis-symmetric figures (common points
  // sharing an abscissa) are not aligned with the elimination direction.
  for (int i = 0; i < 8; ++i) {
    const double ang = 0.3927 * 0.61803398875 + i * (pi / 8.0);
    const double cs = std::cos(ang), sn = std::sin(ang);
    const double v =
        std::min(std::abs(rotated(qa0, cs, sn).c[2]), std::abs(rotated(qb0, cs, sn).c[2]));
    if (v > best) {
      best = v;
      bc = cs;
      bs = sn;
    }
  }
  const Quad qa = rotated(qa0, bc, bs), qb = rotated(qb0, bc, bs);
  // Polynomials in x of degree <= 4 as fixed arrays (low to high): no allocation.
  using Pd = std::array<double, 5>;
  const auto mul = [](const Pd& x, const Pd& y) {
    Pd o{};
    for (int i = 0; i < 5; ++i)
      for (int j = 0; i + j < 5; ++j) o[z(i + j)] += x[z(i)] * y[z(j)];
    return o;
  };
  const auto add = [](const Pd& x, const Pd& y, double sy) {
    Pd o{};
    for (int i = 0; i < 5; ++i) o[z(i)] = x[z(i)] + sy * y[z(i)];
    return o;
  };
  const auto parts = [](const Quad& q, bool absolute, Pd& a2, Pd& a1, Pd& a0) {
    const auto f = [absolute](double x) { return absolute ? std::abs(x) : x; };
    a2 = {f(q.c[2]), 0, 0, 0, 0};
    a1 = {f(q.c[4]), f(q.c[1]), 0, 0, 0};
    a0 = {f(q.c[5]), f(q.c[3]), f(q.c[0]), 0, 0};
  };
  Pd a2, a1, a0, b2, b1, b0;
  parts(qa, false, a2, a1, a0);
  parts(qb, false, b2, b1, b0);
  const Pd s1 = add(mul(a2, b0), mul(a0, b2), -1.0);
  const Pd res =
      add(mul(s1, s1),
          mul(add(mul(a2, b1), mul(a1, b2), -1.0), add(mul(a1, b0), mul(a0, b1), -1.0)), -1.0);
  Pd m2, m1, m0, n2, n1, n0;
  parts(qa, true, m2, m1, m0);
  parts(qb, true, n2, n1, n0);
  const Pd t1 = add(mul(m2, n0), mul(m0, n2), 1.0);
  const Pd mag =
      add(mul(t1, t1), mul(add(mul(m2, n1), mul(m1, n2), 1.0), add(mul(m1, n0), mul(m0, n1), 1.0)),
          1.0);
  std::array<double, 5> k{}, err{};
  double tot = 0.0;
  for (std::size_t i = 0; i < 5; ++i) tot += mag[i];
  for (std::size_t i = 0; i < 5; ++i) {
    k[i] = res[i];
    err[i] = 64.0 * u * tot;
  }
  bool all_small = true;
  for (std::size_t i = 0; i < 5; ++i) all_small = all_small && std::abs(k[i]) <= err[i];
  if (all_small) {
    // A shared component (e.g. a common line of two line pairs): see the pair header.
    r.kind = Kind::coincident;
    return r;
  }
  // Trailing coefficients within their bound are the resultant's genuine degree drop.
  int deg = 4;
  while (deg > 0 && std::abs(k[z(deg)]) <= err[z(deg)]) --deg;
  RootOptions opt = near_roots();
  opt.coefficient_error = std::span<const double>(err.data(), static_cast<std::size_t>(deg) + 1);
  RootsResult<double> roots;
  if (deg == 4)
    roots = solve_quartic(k[0], k[1], k[2], k[3], k[4], opt);
  else if (deg == 3)
    roots = solve_cubic(k[0], k[1], k[2], k[3], opt);
  else if (deg == 2)
    roots = solve_quadratic(k[0], k[1], k[2], opt);
  else if (deg == 1)
    roots = solve_linear(k[0], k[1], opt);
  if (roots.status != Status::ok) return r;
  const auto qval = [](const Quad& q, double x, double y) { return value_at(q, x, y); };
  for (int i = 0; i < roots.count && r.count < 4; ++i) {
    const double x = roots.roots[z(i)].value;
    // y from the first conic's quadratic c y^2 + (b x + e) y + (a x^2 + d x + f) = 0.
    const double c2 = qa.c[2], c1 = qa.c[1] * x + qa.c[4],
                 c0 = qa.c[0] * x * x + qa.c[3] * x + qa.c[5];
    double ys[2];
    int ny = 0;
    if (c2 != 0.0) {
      const double disc = std::max(c1 * c1 - 4.0 * c2 * c0, 0.0);
      const double qq = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
      if (qq != 0.0) {
        ys[ny++] = qq / c2;
        ys[ny++] = c0 / qq;
      } else {
        ys[ny++] = -c1 / (2.0 * c2);
      }
    } else if (c1 != 0.0) {
      ys[ny++] = -c0 / c1;
    }
    if (ny == 0) continue;
    double y = ys[0];
    if (ny == 2 && std::abs(qval(qb, x, ys[1])) < std::abs(qval(qb, x, ys[0]))) y = ys[1];
    const V p{bc * x - bs * y, bs * x + bc * y};
    const auto j = z(r.count++);
    r.point[j] = p;
    r.multiplicity[j] = roots.roots[z(i)].multiplicity;
  }
  r.kind = r.count == 0 ? Kind::empty : r.count == 1 ? Kind::point : Kind::points;
  return r;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Exact conic pairs (docs/notes/intersection.md, "Conic pairs: exact combinatorics").

namespace {

using Z = DynBigInt;
using roots::ZPoly;

/// The implicit coefficients a, b, c, d, e, f of a conic as integers: the curve exactly as
/// stored (an ellipse as sum_i (u_i . (X - C))^2 / e_i^2 = 1 with u_i as given), times a power
/// of two.
struct ZConic {
  std::array<Z, 6> q;
};

/// A shift s with x 2^s an integer for every x (s >= 0).
int common_shift(std::initializer_list<double> xs) noexcept {
  int s = 0;
  for (const double x : xs) {
    if (x == 0.0) continue;
    const DoubleParts p = decompose(x);
    s = std::max(s, -(p.exponent + std::countr_zero(p.mantissa)));
  }
  return s;
}

Z zd(double x, int s) { return Z::from_double(x, s); }
Z pow2(int bits) { return Z(1) << static_cast<std::size_t>(bits); }

ZConic exact_conic(const Conic& k) {
  ZConic z;
  switch (k.form) {
    case Form::general: {
      const int s = common_shift({k.q[0], k.q[1], k.q[2], k.q[3], k.q[4], k.q[5]});
      for (std::size_t i = 0; i < 6; ++i) z.q[i] = zd(k.q[i], s);
      break;
    }
    case Form::circle: {
      // (x^2 + y^2 - 2 cx x - 2 cy y + cx^2 + cy^2 - r^2) 2^(2s).
      const int s = common_shift({k.c.x, k.c.y, k.r});
      const Z cx = zd(k.c.x, s), cy = zd(k.c.y, s), r = zd(k.r, s);
      z.q = {pow2(2 * s),
             Z(0),
             pow2(2 * s),
             -(cx << (static_cast<std::size_t>(s) + 1)),
             -(cy << (static_cast<std::size_t>(s) + 1)),
             cx * cx + cy * cy - r * r};
      break;
    }
    case Form::ellipse: {
      // sum_i e_(1-i)^2 (u_i . X - u_i . C)^2 - e0^2 e1^2, times 2^(6s); term degrees in the
      // doubles: 4 (quadratic part), 5 (linear), 6 and 4 (constant).
      const int s = common_shift({k.c.x, k.c.y, k.u0.x, k.u0.y, k.u1.x, k.u1.y, k.e0, k.e1});
      const auto us = static_cast<std::size_t>(s);
      const Z ux[2] = {zd(k.u0.x, s), zd(k.u1.x, s)}, uy[2] = {zd(k.u0.y, s), zd(k.u1.y, s)};
      const Z cx = zd(k.c.x, s), cy = zd(k.c.y, s);
      const Z w[2] = {zd(k.e1, s) * zd(k.e1, s), zd(k.e0, s) * zd(k.e0, s)};
      Z a(0), b(0), c(0), d(0), e(0), f(0);
      for (int i = 0; i < 2; ++i) {
        const auto j = static_cast<std::size_t>(i);
        const Z p = ux[j] * cx + uy[j] * cy;
        a += w[j] * ux[j] * ux[j];
        b += w[j] * ux[j] * uy[j];
        c += w[j] * uy[j] * uy[j];
        d -= w[j] * ux[j] * p;
        e -= w[j] * uy[j] * p;
        f += w[j] * p * p;
      }
      f -= (w[0] * w[1]) << (2 * us);
      z.q = {a << (2 * us), b << (2 * us + 1), c << (2 * us), d << (us + 1), e << (us + 1), f};
      break;
    }
  }
  return z;
}

/// A conic as a polynomial in y over Z[x'] after the shear x' = x + k y:
/// y2 y^2 + y1(x') y + y0(x'); deg the degree in y (2, or 1 for a line, 0 for a constant).
struct InY {
  ZPoly y2, y1, y0;
  int deg;
};

ZPoly zp(std::initializer_list<Z> c) {
  ZPoly p(c);
  roots::trim(p);
  return p;
}

InY sheared(const ZConic& z, const Z& k) {
  const Z &a = z.q[0], &b = z.q[1], &c = z.q[2], &d = z.q[3], &e = z.q[4], &f = z.q[5];
  // x = x' - k y.
  InY r;
  r.y2 = zp({a * k * k - b * k + c});
  r.y1 = zp({e - d * k, b - (a * k << 1)});
  r.y0 = zp({f, d, a});
  r.deg = !r.y2.empty() ? 2 : !r.y1.empty() ? 1 : 0;
  return r;
}

using roots::add;
using roots::mul;
using roots::sub;

/// The resultant in y of two polynomials of degree 1 or 2 in y (Sylvester, up to sign).
ZPoly resultant_y(const InY& p, const InY& q) {
  if (p.deg == 2 && q.deg == 2) {
    const ZPoly s = sub(mul(p.y2, q.y0), mul(p.y0, q.y2));
    return sub(mul(s, s),
               mul(sub(mul(p.y2, q.y1), mul(p.y1, q.y2)), sub(mul(p.y1, q.y0), mul(p.y0, q.y1))));
  }
  if (p.deg == 1 && q.deg == 1) return sub(mul(p.y1, q.y0), mul(p.y0, q.y1));
  const InY& l = p.deg == 1 ? p : q;
  const InY& m = p.deg == 1 ? q : p;
  // m2 l0^2 - m1 l0 l1 + m0 l1^2.
  return add(sub(mul(m.y2, mul(l.y0, l.y0)), mul(m.y1, mul(l.y0, l.y1))),
             mul(m.y0, mul(l.y1, l.y1)));
}

/// A rounded n / d (d != 0), a few ulps, for integers of any size.
double ratio(const Z& n, const Z& d) {
  if (n.is_zero()) return 0.0;
  const auto bn = static_cast<long>(n.bit_length()), bd = static_cast<long>(d.bit_length());
  const long sn = std::max(0L, bn - 900), sd = std::max(0L, bd - 900);
  const double x = (n >> static_cast<std::size_t>(sn)).to_double();
  const double y = (d >> static_cast<std::size_t>(sd)).to_double();
  return std::ldexp(x / y, static_cast<int>(std::clamp(sn - sd, -4000L, 4000L)));
}

/// The conic's coefficients rounded to double and scaled by one power of two (for residuals).
std::array<double, 6> rounded(const ZConic& z) {
  std::size_t bits = 0;
  for (const Z& c : z.q) bits = std::max(bits, c.bit_length());
  const std::size_t sh = bits > 900 ? bits - 900 : 0;
  std::array<double, 6> r{};
  for (std::size_t i = 0; i < 6; ++i) r[i] = (z.q[i] >> sh).to_double();
  return r;
}

double eval(const std::array<double, 6>& q, double x, double y, double& mag) noexcept {
  const double t[6] = {q[0] * x * x, q[1] * x * y, q[2] * y * y, q[3] * x, q[4] * y, q[5]};
  mag = 0.0;
  double v = 0.0;
  for (const double ti : t) {
    v += ti;
    mag += std::abs(ti);
  }
  return v;
}

/// The y of the common point above the (rounded) abscissa x' = x + k y: a root of one
/// conic's quadratic in y, the candidate with the smaller relative residual on both.
V point_above(const std::array<double, 6>& qa, const std::array<double, 6>& qb, double k,
              double xs) noexcept {
  double best = std::numeric_limits<double>::infinity();
  V out{xs, 0.0};
  const auto score = [&](double y) {
    const double x = xs - k * y;
    double ma = 0.0, mb = 0.0;
    const double va = eval(qa, x, y, ma), vb = eval(qb, x, y, mb);
    const double sc = (ma > 0.0 ? std::abs(va) / ma : std::abs(va)) +
                      (mb > 0.0 ? std::abs(vb) / mb : std::abs(vb));
    if (sc < best) {
      best = sc;
      out = {x, y};
    }
  };
  for (const auto* q : {&qa, &qb}) {
    const double a = (*q)[0], b = (*q)[1], c = (*q)[2], d = (*q)[3], e = (*q)[4], f = (*q)[5];
    const double y2 = a * k * k - b * k + c, y1 = (b - 2.0 * a * k) * xs + (e - d * k),
                 y0 = (a * xs + d) * xs + f;
    if (y2 != 0.0) {
      const double disc = std::max(y1 * y1 - 4.0 * y2 * y0, 0.0);
      const double qq = -0.5 * (y1 + std::copysign(std::sqrt(disc), y1));
      if (qq != 0.0) {
        score(qq / y2);
        score(y0 / qq);
      } else {
        score(-y1 / (2.0 * y2));
      }
    } else if (y1 != 0.0) {
      score(-y0 / y1);
    }
  }
  return out;
}

/// Newton steps on both conics from p (a transversal point): kept while the residual drops.
V polish(const std::array<double, 6>& qa, const std::array<double, 6>& qb, V p) noexcept {
  const auto res = [&](const V& x) {
    double ma = 0.0, mb = 0.0;
    const double va = eval(qa, x.x, x.y, ma), vb = eval(qb, x.x, x.y, mb);
    return (ma > 0.0 ? std::abs(va) / ma : 0.0) + (mb > 0.0 ? std::abs(vb) / mb : 0.0);
  };
  double r = res(p);
  for (int it = 0; it < 3 && r > 0.0; ++it) {
    double ma = 0.0, mb = 0.0;
    const double va = eval(qa, p.x, p.y, ma), vb = eval(qb, p.x, p.y, mb);
    const V ga{2.0 * qa[0] * p.x + qa[1] * p.y + qa[3], qa[1] * p.x + 2.0 * qa[2] * p.y + qa[4]};
    const V gb{2.0 * qb[0] * p.x + qb[1] * p.y + qb[3], qb[1] * p.x + 2.0 * qb[2] * p.y + qb[4]};
    const double det = ga.x * gb.y - ga.y * gb.x;
    // Nearly parallel normals (a near-tangency): Newton would amplify the residual's rounding.
    if (!(std::abs(det) > 0x1p-6 * length(ga) * length(gb)) || !std::isfinite(det)) break;
    const V q{p.x - (va * gb.y - vb * ga.y) / det, p.y - (ga.x * vb - gb.x * va) / det};
    const double rq = res(q);
    if (!(rq < r) || !finite(q)) break;
    p = q;
    r = rq;
  }
  return p;
}

/// A line gx x + gy y + g0 = 0 with integer coefficients.
struct ZLine {
  Z x, y, c;
};

/// The common line of two conics with an identically vanishing resultant (not proportional),
/// in the sheared coordinates (x', y); false when the structure is not the expected one.
bool common_line(const InY& p, const InY& q, ZLine& g) {
  if (p.deg == 1 || q.deg == 1) {
    const InY& l = p.deg == 1 ? p : q;
    const auto at = [](const ZPoly& v, std::size_t i) { return i < v.size() ? v[i] : Z(0); };
    g = {at(l.y0, 1), at(l.y1, 0), at(l.y0, 0)};
    return l.y1.size() == 1 && l.y0.size() <= 2;
  }
  // S = q2 p - p2 q = L1(x') y + L0(x') = h(x') G.
  const ZPoly l1 = sub(mul(q.y2, p.y1), mul(p.y2, q.y1));
  const ZPoly l0 = sub(mul(q.y2, p.y0), mul(p.y2, q.y0));
  const auto at = [](const ZPoly& v, std::size_t i) { return i < v.size() ? v[i] : Z(0); };
  if (l1.size() == 1) {
    if (l0.size() > 2) return false;
    g = {at(l0, 1), l1[0], at(l0, 0)};
    return true;
  }
  if (l1.size() != 2) return false;
  const Z &al = l1[1], &be = l1[0];
  g = {al * at(l0, 2), al * al, al * at(l0, 1) - at(l0, 2) * be};
  return true;
}

/// The conic divided by the line g (gy != 0), times gy: a line in (x', y).
ZLine cofactor(const InY& p, const ZLine& g) {
  const auto at = [](const ZPoly& v, std::size_t i) { return i < v.size() ? v[i] : Z(0); };
  const Z& a2 = p.y2[0];
  return {g.y * at(p.y1, 1) - a2 * g.x, a2 * g.y, g.y * at(p.y1, 0) - a2 * g.c};
}

void make_primitive(ZLine& l) {
  ZPoly v{l.x, l.y, l.c};
  roots::make_primitive(v);  // trims: pad back
  v.resize(3, Z(0));
  l = {v[0], v[1], v[2]};
}

/// The exact sign of the integer polynomial p at the double x: with x = m 2^e (e < 0),
/// sum p_i m^i 2^(-e (n - i)) by Horner's rule.
int exact_sign_at(const ZPoly& p, double x) {
  if (p.empty()) return 0;
  const DoubleParts d = decompose(x);
  Z m = Z::from_double(x == 0.0 ? 0.0 : std::copysign(double(d.mantissa), x));
  std::size_t step = 0;
  if (d.exponent >= 0)
    m = m << static_cast<std::size_t>(d.exponent);
  else
    step = static_cast<std::size_t>(-d.exponent);
  Z acc = p.back();
  for (std::size_t i = p.size() - 1; i-- > 0;)
    acc = acc * m + (p[i] << (step * (p.size() - 1 - i)));
  return acc.sign();
}

/// The cheap certified path: when the rounded coefficients decide (with rigorous running error
/// bounds, Fd) that res is square-free and how many real roots it has, and the near-mode roots are
/// bracketed by sign changes, the roots (all simple) bisected to adjacent doubles (signs filtered,
/// exact when undecided); false when undecided.
/// The core of the filter on coefficients c[0..n] (rigorous error bounds, leading one certified
/// non-zero); res, when given, is the exact polynomial for signs the filter cannot tell (else
/// bisection stops there, and roots must be bracketed within 2^-42 of their scale).
bool filtered_core(const std::array<Fd, 5>& c, int n, const ZPoly* res, double width,
                   std::vector<double>& out);

bool filtered_roots(const ZPoly& res, std::vector<double>& out) {
  out.clear();
  const int n = roots::degree(res);
  if (n < 1 || n > 4) return n == 0;
  std::size_t bits = 0;
  for (const Z& c : res) bits = std::max(bits, c.bit_length());
  const std::size_t sh = bits > 1000 ? bits - 1000 : 0;
  const int scale = -static_cast<int>(bits - sh);
  std::array<Fd, 5> c{};
  for (std::size_t i = 0; i < res.size(); ++i) {
    const double x = std::ldexp((res[i] >> sh).to_double(), scale);
    // Rounding to double, truncation by the shift (below one unit), underflow.
    c[i] = {x, u * std::abs(x) + (sh > 0 ? std::ldexp(1.0, scale) : 0.0) + 0x1p-1070};
  }
  return filtered_core(c, n, &res, 0x1p-42, out);
}

bool filtered_core(const std::array<Fd, 5>& c, int n, const ZPoly* res, double width,
                   std::vector<double>& out) {
  out.clear();
  std::array<double, 5> v{};
  for (std::size_t i = 0; i < 5; ++i) v[i] = c[i].v;
  int count = 0;
  if (n == 1) {
    count = 1;
  } else if (n == 2) {
    const int d = (c[1] * c[1] - (c[2] * c[0]).times_pow2(2)).sign();
    if (d == 2 || d == 0) return false;
    count = d > 0 ? 2 : 0;
  } else if (n == 3) {
    const Fd &a = c[3], &b = c[2], &cc = c[1], &d = c[0];
    const Fd k18{18.0, 0.0}, k4{4.0, 0.0}, k27{27.0, 0.0};
    const int s = (k18 * a * b * cc * d - k4 * b * b * b * d + b * b * cc * cc -
                   k4 * a * cc * cc * cc - k27 * a * a * d * d)
                      .sign();
    if (s == 2 || s == 0) return false;
    count = s > 0 ? 3 : 1;
  } else {
    const Fd &a = c[4], &b = c[3], &cc = c[2], &d = c[1], &e = c[0];
    const auto k = [](double x) { return Fd{x, 0.0}; };
    const Fd disc = k(256) * a * a * a * e * e * e - k(192) * a * a * b * d * e * e -
                    k(128) * a * a * cc * cc * e * e + k(144) * a * a * cc * d * d * e -
                    k(27) * a * a * d * d * d * d + k(144) * a * b * b * cc * e * e -
                    k(6) * a * b * b * d * d * e - k(80) * a * b * cc * cc * d * e +
                    k(18) * a * b * cc * d * d * d + k(16) * a * cc * cc * cc * cc * e -
                    k(4) * a * cc * cc * cc * d * d - k(27) * b * b * b * b * e * e +
                    k(18) * b * b * b * cc * d * e - k(4) * b * b * b * d * d * d -
                    k(4) * b * b * cc * cc * cc * e + b * b * cc * cc * d * d;
    const int s = disc.sign();
    if (s == 2 || s == 0) return false;
    if (s < 0) {
      count = 2;
    } else {
      const int p = (k(8) * a * cc - k(3) * b * b).sign();
      const int q = (k(64) * a * a * a * e - k(16) * a * a * cc * cc + k(16) * a * b * b * cc -
                     k(16) * a * a * b * d - k(3) * b * b * b * b)
                        .sign();
      if (p == 2 || q == 2) return false;
      count = (p < 0 && q < 0) ? 4 : 0;
    }
  }
  if (count == 0) return true;
  RootsResult<double> rr;
  if (n == 1) rr = solve_linear(v[0], v[1]);
  if (n == 2) rr = solve_quadratic(v[0], v[1], v[2]);
  if (n == 3) rr = solve_cubic(v[0], v[1], v[2], v[3]);
  if (n == 4) rr = solve_quartic(v[0], v[1], v[2], v[3], v[4]);
  if (rr.status != Status::ok || rr.count != count) return false;
  // The sign of res at x: filtered, exact when the filter cannot tell.
  const auto sign_at = [&](double x) {
    Fd acc = c[z(n)];
    const Fd xv = Fd::var(x);
    for (int i = n - 1; i >= 0; --i) acc = acc * xv + c[z(i)];
    const int fs = acc.sign();
    return fs != 2 || res == nullptr ? fs : exact_sign_at(*res, x);
  };
  double m = 0.0;
  for (int i = 0; i < rr.count; ++i) m = std::max(m, std::abs(rr.roots[z(i)].value));
  double prev_hi = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < rr.count; ++i) {
    if (rr.roots[z(i)].multiplicity != 1) return false;
    const double r = rr.roots[z(i)].value;
    const double mag = std::max({std::abs(r), 0x1p-10 * m, 0x1p-1000});
    double lo = 0.0, hi = 0.0;
    int slo = 2, shi = 2;
    for (const double rel : {0x1p-50, 0x1p-44, 0x1p-38, 0x1p-30, 0x1p-20}) {
      lo = r - rel * mag;
      hi = r + rel * mag;
      slo = sign_at(lo);
      shi = sign_at(hi);
      if (slo != 2 && shi != 2 && slo * shi < 0) break;
    }
    if (slo == 2 || shi == 2 || slo * shi >= 0 || !(lo > prev_hi)) return false;
    // Bisect down to adjacent doubles (every sign decided, exactly when needed).
    for (int it = 0; it < 2100; ++it) {
      const double mid = lo + 0.5 * (hi - lo);
      if (!(mid > lo && mid < hi)) break;
      const int sm = sign_at(mid);
      if (sm == 2) break;
      if (sm == 0) {
        lo = hi = mid;
        break;
      }
      (sm == slo ? lo : hi) = mid;
    }
    if (hi - lo > width * mag) return false;
    prev_hi = hi;
    out.push_back(0.5 * (lo + hi));
  }
  return true;
}

enum class ExactOutcome : std::uint8_t { done, fallback };

void order_points(R4& r, const Conic& a, const Conic& b) noexcept {
  const bool by_a = a.form != Form::general, by_b = !by_a && b.form != Form::general;
  // Entries before `first` describe a line and stay in place.
  const int first = r.kind == Kind::line ? 2 : 0;
  const auto less = [&](int i, int j) {
    if (by_a) return r.param_a[z(i)] < r.param_a[z(j)];
    if (by_b) return r.param_b[z(i)] < r.param_b[z(j)];
    const V p = r.point[z(i)], q = r.point[z(j)];
    return p.x < q.x || (p.x == q.x && p.y < q.y);
  };
  for (int i = first + 1; i < r.count; ++i)
    for (int j = i; j > first && less(j, j - 1); --j) {
      std::swap(r.point[z(j)], r.point[z(j - 1)]);
      std::swap(r.param_a[z(j)], r.param_a[z(j - 1)]);
      std::swap(r.param_b[z(j)], r.param_b[z(j - 1)]);
      std::swap(r.multiplicity[z(j)], r.multiplicity[z(j - 1)]);
    }
}

/// Two conics with an identically vanishing resultant (not proportional): their common line, and
/// the isolated common point of the other components when there is one.
ExactOutcome shared_component(const Conic& ka, const Conic& kb, const InY& pa, const InY& pb,
                              const Z& k, R4& r) {
  // A shared component (not the whole curves: they are not proportional).
  ZLine g;
  if (!common_line(pa, pb, g) || g.y.is_zero()) return ExactOutcome::fallback;
  // The isolated common point of the other components, when not on the line.
  r.kind = Kind::line;
  r.count = 2;
  // Back to (x, y): x' = x + k y.
  ZLine l{g.x, g.x * k + g.y, g.c};
  make_primitive(l);
  const Z n2 = l.x * l.x + l.y * l.y;
  const V p0{ratio(-(l.c * l.x), n2), ratio(-(l.c * l.y), n2)};
  const double dx = l.x.to_double(), dy = l.y.to_double();
  const double big = std::max(std::abs(dx), std::abs(dy));
  const V dir = V{-dy / big, dx / big};
  const double step = std::max(1.0, max_abs(p0));
  r.point[0] = p0;
  r.point[1] = p0 + step * dir;
  for (int i = 0; i < 2; ++i) {
    r.param_a[z(i)] = curve_param(ka, r.point[z(i)]);
    r.param_b[z(i)] = curve_param(kb, r.point[z(i)]);
    r.multiplicity[z(i)] = 0;
  }
  if (pa.deg == 2 && pb.deg == 2) {
    const ZLine la = cofactor(pa, g), lb = cofactor(pb, g);
    const Z det = la.x * lb.y - lb.x * la.y;
    if (!det.is_zero()) {
      const Z nx = la.y * lb.c - lb.y * la.c, ny = la.c * lb.x - lb.c * la.x;
      if (!(g.x * nx + g.y * ny + g.c * det).is_zero()) {
        const Z x = nx - k * ny;
        const V p{ratio(x, det), ratio(ny, det)};
        r.point[2] = p;
        r.param_a[2] = curve_param(ka, p);
        r.param_b[2] = curve_param(kb, p);
        r.multiplicity[2] = 1;
        r.count = 3;
      }
    }
  }
  return ExactOutcome::done;
}

/// The implicit coefficients in Fd (rounded, with error bounds), unscaled.
std::array<Fd, 6> fd_conic(const Conic& k) noexcept {
  const auto neg = [](const Fd& x) { return Fd{0.0, 0.0} - x; };
  std::array<Fd, 6> q{};
  switch (k.form) {
    case Form::general:
      for (std::size_t i = 0; i < 6; ++i) q[i] = Fd::var(k.q[i]);
      break;
    case Form::circle: {
      const Fd cx = Fd::var(k.c.x), cy = Fd::var(k.c.y), r = Fd::var(k.r);
      q = {Fd{1.0, 0.0},          Fd{},
           Fd{1.0, 0.0},          neg(cx.times_pow2(1)),
           neg(cy.times_pow2(1)), cx * cx + cy * cy - r * r};
      break;
    }
    case Form::ellipse: {
      const Fd ux[2] = {Fd::var(k.u0.x), Fd::var(k.u1.x)},
               uy[2] = {Fd::var(k.u0.y), Fd::var(k.u1.y)};
      const Fd cx = Fd::var(k.c.x), cy = Fd::var(k.c.y);
      const Fd w[2] = {Fd::var(k.e1) * Fd::var(k.e1), Fd::var(k.e0) * Fd::var(k.e0)};
      for (std::size_t j = 0; j < 2; ++j) {
        const Fd p = ux[j] * cx + uy[j] * cy;
        q[0] = q[0] + w[j] * ux[j] * ux[j];
        q[1] = q[1] + (w[j] * ux[j] * uy[j]).times_pow2(1);
        q[2] = q[2] + w[j] * uy[j] * uy[j];
        q[3] = q[3] - (w[j] * ux[j] * p).times_pow2(1);
        q[4] = q[4] - (w[j] * uy[j] * p).times_pow2(1);
        q[5] = q[5] + w[j] * p * p;
      }
      q[5] = q[5] - w[0] * w[1];
      break;
    }
  }
  return q;
}

/// The fast path: the resultant for k = 0 (leading coefficients in y certified non-zero) in Fd,
/// its coefficients enclosing the exact ones, decided by the filter without big integers; false
/// when anything is undecided (then the exact path).
bool fast_pair(const Conic& ka, const Conic& kb, R4& r) {
  const std::array<Fd, 6> a = fd_conic(ka), b = fd_conic(kb);
  if (a[2].sign() == 2 || a[2].sign() == 0 || b[2].sign() == 2 || b[2].sign() == 0) return false;
  using FP = std::array<Fd, 5>;
  const auto mul = [](const FP& x, int dx, const FP& y, int dy) {
    FP o{};
    for (int i = 0; i <= dx; ++i)
      for (int j = 0; j <= dy; ++j) o[z(i + j)] = o[z(i + j)] + x[z(i)] * y[z(j)];
    return o;
  };
  const auto sub = [](const FP& x, const FP& y) {
    FP o{};
    for (std::size_t i = 0; i < 5; ++i) o[i] = x[i] - y[i];
    return o;
  };
  const FP a2{a[2]}, a1{a[4], a[1]}, a0{a[5], a[3], a[0]};
  const FP b2{b[2]}, b1{b[4], b[1]}, b0{b[5], b[3], b[0]};
  const FP s = sub(mul(a2, 0, b0, 2), mul(a0, 2, b2, 0));
  const FP res = sub(mul(s, 2, s, 2), mul(sub(mul(a2, 0, b1, 1), mul(a1, 1, b2, 0)), 1,
                                          sub(mul(a1, 1, b0, 2), mul(a0, 2, b1, 1)), 3));
  double m = 0.0;
  for (const Fd& c : res) m = std::max(m, std::abs(c.v) + c.e);
  if (!(m > 0.0) || !std::isfinite(m)) return false;
  const int sc = -std::ilogb(m);
  FP c{};
  for (std::size_t i = 0; i < 5; ++i) c[i] = res[i].times_pow2(sc);
  int n = 4;
  while (n >= 0 && c[z(n)].sign() == 0) --n;
  if (n < 0 || c[z(n)].sign() == 2) return false;
  std::vector<double> xs;
  // Brackets within 2^-28, then Newton steps (required to apply: well-separated normals).
  if (!filtered_core(c, n, nullptr, 0x1p-28, xs)) return false;
  const std::array<double, 6> qa = {a[0].v, a[1].v, a[2].v, a[3].v, a[4].v, a[5].v};
  const std::array<double, 6> qb = {b[0].v, b[1].v, b[2].v, b[3].v, b[4].v, b[5].v};
  R4 out;
  for (const double x : xs) {
    if (out.count == 4) break;
    const V p = polish(qa, qb, point_above(qa, qb, 0.0, x));
    // The projection (vertical) must be transversal to a curve at the point.
    double cond = 0.0;
    for (const auto* q : {&qa, &qb}) {
      const V g{2.0 * (*q)[0] * p.x + (*q)[1] * p.y + (*q)[3],
                (*q)[1] * p.x + 2.0 * (*q)[2] * p.y + (*q)[4]};
      const double gl = length(g);
      if (gl > 0.0) cond = std::max(cond, std::abs(g.y) / gl);
    }
    if (!(cond >= 0x1p-6) || !finite(p)) return false;
    const V ga{2.0 * qa[0] * p.x + qa[1] * p.y + qa[3], qa[1] * p.x + 2.0 * qa[2] * p.y + qa[4]};
    const V gb{2.0 * qb[0] * p.x + qb[1] * p.y + qb[3], qb[1] * p.x + 2.0 * qb[2] * p.y + qb[4]};
    if (!(std::abs(ga.x * gb.y - ga.y * gb.x) > 0x1p-6 * length(ga) * length(gb))) return false;
    const auto j = z(out.count++);
    out.point[j] = p;
    out.param_a[j] = curve_param(ka, p);
    out.param_b[j] = curve_param(kb, p);
    out.multiplicity[j] = 1;
  }
  out.kind = out.count == 0 ? Kind::empty : out.count == 1 ? Kind::point : Kind::points;
  order_points(out, ka, kb);
  r = out;
  return true;
}

ExactOutcome exact_pair(const Conic& ka, const Conic& kb, R4& r) {
  const ZConic za = exact_conic(ka), zb = exact_conic(kb);
  // Proportional coefficients (exact): the same curve.
  bool proportional = true;
  for (std::size_t i = 0; i < 6 && proportional; ++i)
    for (std::size_t j = i + 1; j < 6 && proportional; ++j)
      proportional = za.q[i] * zb.q[j] == za.q[j] * zb.q[i];
  if (proportional) {
    r.kind = Kind::coincident;
    return ExactOutcome::done;
  }
  // A constant "conic": f = 0 (never: it is proportional to everything) or f != 0 (empty set).
  for (const ZConic* zc : {&za, &zb})
    if (zc->q[0].is_zero() && zc->q[1].is_zero() && zc->q[2].is_zero() && zc->q[3].is_zero() &&
        zc->q[4].is_zero())
      return ExactOutcome::done;
  // The shear: a k (of 12 candidates) whose resultant has the most distinct roots: then no two
  // common points share x' (at most 10 candidates are bad: 6 directions joining two of at most
  // four common points, 2 + 2 asymptotic directions), and a square-free resultant is good at
  // once. Among good shears, the first whose points are well conditioned (the projection
  // direction transversal to a curve at every point) gives the coordinates.
  static constexpr int candidates[12] = {0, 1, -1, 2, -2, 3, -3, 4, -4, 5, -5, 6};
  const bool quad_a = !(za.q[0].is_zero() && za.q[1].is_zero() && za.q[2].is_zero());
  const bool quad_b = !(zb.q[0].is_zero() && zb.q[1].is_zero() && zb.q[2].is_zero());
  const std::array<double, 6> qa = rounded(za), qb = rounded(zb);
  struct Cand {
    int k;
    ZPoly res;
    int distinct;
    bool square_free;
  };
  std::vector<Cand> cands;
  int max_distinct = -1;
  bool have_fallback = false;
  R4 fallback;
  // Points of a good shear from its real roots; false when ill conditioned.
  const auto build = [&](int kc, const std::vector<double>& xs, const std::vector<int>& mult,
                         R4& out) {
    out = R4{};
    bool good = true;
    const double k = kc, dn = std::sqrt(1.0 + k * k);
    for (std::size_t i = 0; i < xs.size() && out.count < 4; ++i) {
      V p = point_above(qa, qb, k, xs[i]);
      if (mult[i] == 1) p = polish(qa, qb, p);
      double cond = 0.0;
      for (const auto* q : {&qa, &qb}) {
        const V g{2.0 * (*q)[0] * p.x + (*q)[1] * p.y + (*q)[3],
                  (*q)[1] * p.x + 2.0 * (*q)[2] * p.y + (*q)[4]};
        const double gl = length(g);
        if (gl > 0.0) cond = std::max(cond, std::abs(g.y - k * g.x) / (gl * dn));
      }
      good = good && cond >= 0x1p-6;
      const auto j = z(out.count++);
      out.point[j] = p;
      out.param_a[j] = curve_param(ka, p);
      out.param_b[j] = curve_param(kb, p);
      out.multiplicity[j] = mult[i];
    }
    out.kind = out.count == 0 ? Kind::empty : out.count == 1 ? Kind::point : Kind::points;
    order_points(out, ka, kb);
    return good;
  };
  // The exact real roots of a good shear's resultant, then its points.
  const auto exact_points = [&](const Cand& c, R4& out, bool& ok) {
    std::vector<Root<double>> found;
    const double inf = std::numeric_limits<double>::infinity();
    ok = roots::exact_real_roots_of_integers<double>(c.res, -inf, inf, RootOptions{}, found) ==
         Status::ok;
    std::vector<double> xs;
    std::vector<int> mult;
    for (const Root<double>& rt : found) {
      xs.push_back(rt.value);
      mult.push_back(rt.multiplicity);
    }
    return ok && build(c.k, xs, mult, out);
  };
  const auto consider = [&](const R4& got, bool good) {
    if (good) {
      r = got;
      return true;
    }
    if (!have_fallback) {
      fallback = got;
      have_fallback = true;
    }
    return false;
  };
  for (const int kc : candidates) {
    const Z k(kc);
    const InY pa = sheared(za, k), pb = sheared(zb, k);
    // Leading coefficients in y must be non-zero constants (no common point at infinity in the
    // projection direction; the degree in y is the conic's degree).
    if (pa.deg != (quad_a ? 2 : 1) || pb.deg != (quad_b ? 2 : 1)) continue;
    if (pa.deg == 1 && pa.y1.size() != 1) continue;
    if (pb.deg == 1 && pb.y1.size() != 1) continue;
    ZPoly res = resultant_y(pa, pb);
    if (res.empty()) return shared_component(ka, kb, pa, pb, k, r);
    bool filtered = false;
    if (cands.empty()) {
      // The first admissible shear: the cheap certified path when it decides.
      std::vector<double> simple;
      if ((filtered = filtered_roots(res, simple))) {
        R4 got;
        const bool good = build(kc, simple, std::vector<int>(simple.size(), 1), got);
        if (consider(got, good)) return ExactOutcome::done;
      }
    }
    const ZPoly g = roots::gcd(res, roots::derivative(res));
    const int distinct = roots::degree(res) - roots::degree(g);
    max_distinct = std::max(max_distinct, distinct);
    cands.push_back({kc, std::move(res), distinct, roots::degree(g) <= 0});
    if (cands.back().square_free && !filtered) {
      R4 got;
      bool ok = false;
      const bool good = exact_points(cands.back(), got, ok);
      if (!ok) return ExactOutcome::fallback;
      if (consider(got, good)) return ExactOutcome::done;
    }
  }
  if (max_distinct < 0) return ExactOutcome::fallback;
  for (const Cand& c : cands) {
    if (c.distinct != max_distinct || c.square_free) continue;  // bad, or already tried
    R4 got;
    bool ok = false;
    const bool good = exact_points(c, got, ok);
    if (!ok) return ExactOutcome::fallback;
    if (consider(got, good)) return ExactOutcome::done;
  }
  if (!have_fallback) return ExactOutcome::fallback;
  r = fallback;
  return ExactOutcome::done;
}

}  // namespace

R4 conic_conic(const Conic& a, const Conic& b) noexcept {
  R4 r;
  if (!valid_conic(a) || !valid_conic(b)) return r;
  if (same(a, b)) {
    r.kind = Kind::coincident;
    return r;
  }
  // A point circle: the point, when it lies on the other conic (exact).
  for (int side = 0; side < 2; ++side) {
    const Conic& p = side == 0 ? a : b;
    const Conic& o = side == 0 ? b : a;
    if (p.form == Form::circle && p.r == 0.0) {
      if (value_sign(o, p.c) != 0) return r;
      r.kind = Kind::point;
      r.count = 1;
      r.point[0] = p.c;
      r.param_a[0] = side == 0 ? 0.0 : curve_param(o, p.c);
      r.param_b[0] = side == 0 ? curve_param(o, p.c) : 0.0;
      r.multiplicity[0] = 2;
      return r;
    }
  }
  // The exact decision; the rounded quartic only when the exact engine gives up (memory, or
  // roots closer than its bisection budget: not reached by double input). The pair is taken in
  // a canonical order so that swapping the arguments gives bit-identical points.
  try {
    const auto key = [](const Conic& k) {
      return std::array<double, 16>{double(k.form), k.c.x,  k.c.y,  k.r,   k.u0.x, k.u0.y,
                                    k.u1.x,         k.u1.y, k.e0,   k.e1,  k.q[0], k.q[1],
                                    k.q[2],         k.q[3], k.q[4], k.q[5]};
    };
    const bool flip = key(b) < key(a);
    const Conic& p = flip ? b : a;
    const Conic& q = flip ? a : b;
    R4 e;
    if (fast_pair(p, q, e) || exact_pair(p, q, e) == ExactOutcome::done) {
      if (!flip) return e;
      R4 s = swapped(e);
      order_points(s, a, b);
      return s;
    }
  } catch (const std::bad_alloc&) {
  }
  Frame f;
  if (frame_of(a, f)) return frame_conic(a, f, b);
  if (frame_of(b, f)) {
    const R4 s = frame_conic(b, f, a);
    return swapped(s);
  }
  return general_pair(a, b);
}

RegionRelation ellipse_relation(const Conic& a, const Conic& b) noexcept {
  Frame fa, fb;
  if (!valid_conic(a) || !valid_conic(b) || !frame_of(a, fa) || !frame_of(b, fb))
    return RegionRelation::undecided;
  if (same(a, b)) return RegionRelation::equal;
  const R4 r = conic_conic(a, b);
  if (r.kind == Kind::coincident) return RegionRelation::equal;
  bool touching = false;
  for (int i = 0; i < r.count; ++i) {
    if (r.multiplicity[z(i)] % 2 == 1) return RegionRelation::overlapping;
    touching = true;
  }
  // No crossing: the regions are nested or have disjoint interiors. A centre strictly inside
  // the other region means nested, and then the larger area contains (both exact).
  const bool b_centre_in_a = value_sign(a, b.c) < 0, a_centre_in_b = value_sign(b, a.c) < 0;
  if (!b_centre_in_a && !a_centre_in_b)
    return touching ? RegionRelation::touching : RegionRelation::separated;
  // Area pi e0 e1 / |u0 x u1| (the implicit ellipse as stored); a circle: pi r^2.
  const auto area_parts = [](const Conic& k, P& num, P& den) {
    if (k.form == Form::circle) {
      num = P::var(k.r) * P::var(k.r);
      den = P::var(1.0);
    } else {
      num = P::var(k.e0) * P::var(k.e1);
      den = P::var(k.u0.x) * P::var(k.u1.y) - P::var(k.u0.y) * P::var(k.u1.x);
      if (den.sign() < 0) den = P::var(0.0) - den;
    }
  };
  P na, da, nb, db;
  area_parts(a, na, da);
  area_parts(b, nb, db);
  const int cmp = (na * db - nb * da).sign();
  if (cmp > 0)
    return touching ? RegionRelation::a_contains_b_touching : RegionRelation::a_contains_b;
  if (cmp < 0)
    return touching ? RegionRelation::b_contains_a_touching : RegionRelation::b_contains_a;
  return RegionRelation::equal;
}

}  // namespace locus::detail::conic2
