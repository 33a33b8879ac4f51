// SPDX-License-Identifier: BSL-1.0
// The 2D curve intersection engine (include/locus/intersection/detail/conic2.hpp); rows
// int2.linear-quadratic and int2.quadratic, book sections 7.2-7.5. Derivations:
// docs/notes/intersection.md, "Linear components and conics" and "Conic pairs".

#include <locus/core/crossing.hpp>
#include <locus/core/exact_poly.hpp>
#include <locus/intersection/detail/ball_relation.hpp>
#include <locus/intersection/detail/conic2.hpp>
#include <locus/numeric/roots.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>

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
  // No crossing: a boundary point of one, away from the tangencies, lies strictly inside the
  // other or not.
  const auto probe = [&](const Frame& f, bool use_b) {
    double best = -1.0, th = 0.0;
    for (int i = 0; i < 8; ++i) {
      const double c = i * (pi / 4.0);
      double near = two_pi;
      for (int j = 0; j < r.count; ++j) {
        const double pj = use_b ? r.param_b[z(j)] : r.param_a[z(j)];
        near = std::min(near, std::abs(normalise_angle(c - pj)));
      }
      if (near > best) {
        best = near;
        th = c;
      }
    }
    return f.c + std::cos(th) * f.e0v + std::sin(th) * f.e1v;
  };
  if (value_sign(a, probe(fb, true)) < 0)
    return touching ? RegionRelation::a_contains_b_touching : RegionRelation::a_contains_b;
  if (value_sign(b, probe(fa, false)) < 0)
    return touching ? RegionRelation::b_contains_a_touching : RegionRelation::b_contains_a;
  return touching ? RegionRelation::touching : RegionRelation::separated;
}

}  // namespace locus::detail::conic2
