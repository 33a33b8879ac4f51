// SPDX-License-Identifier: BSL-1.0
#pragma once
// Exact (GMP) oracles of the int2.linear-quadratic and int2.quadratic tests, independent of the
// library's method. A conic is a function Q(x, y) evaluated in rationals (a circle's |X - c|^2 -
// r^2, an ellipse's e0^2 e1^2 (sum (u_i.(X - c))^2 / e_i^2 - 1), a general conic's polynomial).
// Against a linear component o + t d, q(t) = Q(o + t d) = A t^2 + B t + C is recovered from three
// values (C = Q(o), A + B + C = Q(o + d), A - B + C = Q(o - d)); its roots in the parameter domain
// are counted by comparing (-B +- sqrt(disc)) / (2A) with the domain ends exactly (squaring with
// sign care), not by the library's sign-of-q-and-q' rule. Root values come from mpf (256 bits).

#include <locus/core/vec.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/ellipse.hpp>
#include <locus/primitives/quadratic_curve.hpp>

#include <gmpxx.h>

#include <functional>
#include <vector>

namespace locus_test::conic {

struct Q2 {
  mpq_class x, y;
};
template <class T>
Q2 q(const locus::Vec2<T>& v) {
  return {mpq_class(double(v.x)), mpq_class(double(v.y))};
}
inline mpq_class qd(double x) { return mpq_class(x); }

using QFun = std::function<mpq_class(const Q2&)>;

template <class T>
QFun conic_fun(const locus::Circle2<T>& c) {
  const Q2 cc = q(c.center);
  const mpq_class r = qd(double(c.radius));
  return [=](const Q2& p) {
    const mpq_class dx = p.x - cc.x, dy = p.y - cc.y;
    return mpq_class(dx * dx + dy * dy - r * r);
  };
}
template <class T>
QFun conic_fun(const locus::Ellipse2<T>& e) {
  const Q2 c = q(e.center), u0 = q(e.axis[0]), u1 = q(e.axis[1]);
  const mpq_class e0 = qd(double(e.extent[0])), e1 = qd(double(e.extent[1]));
  return [=](const Q2& p) {
    const mpq_class wx = p.x - c.x, wy = p.y - c.y;
    const mpq_class a0 = u0.x * wx + u0.y * wy, a1 = u1.x * wx + u1.y * wy;
    return mpq_class(e1 * e1 * a0 * a0 + e0 * e0 * a1 * a1 - e0 * e0 * e1 * e1);
  };
}
template <class T>
QFun conic_fun(const locus::QuadraticCurve2<T>& k) {
  const mpq_class a = qd(double(k.a)), b = qd(double(k.b)), c = qd(double(k.c)),
                  d = qd(double(k.d)), e = qd(double(k.e)), f = qd(double(k.f));
  return [=](const Q2& p) {
    return mpq_class(a * p.x * p.x + b * p.x * p.y + c * p.y * p.y + d * p.x + e * p.y + f);
  };
}

/// A linear component o + t d with t >= 0 if lo, t <= 1 if hi.
struct QLin {
  Q2 o, d;
  bool lo, hi;
};

/// The exact answer: count of distinct roots in the domain, whether the component lies on the
/// conic, and (approximately, 256-bit) the roots with their multiplicity.
struct LinAnswer {
  bool whole = false;
  int count = 0;
  double t[2] = {0, 0};
  int mult[2] = {0, 0};
};

/// sign(sqrt(D) * s - x) for D >= 0, s = +1 or -1.
inline int cmp_sqrt(const mpq_class& D, int s, const mpq_class& x) {
  // s sqrt(D) vs x.
  if (s > 0) {
    if (x < 0) return 1;
    return sgn(D - x * x);
  }
  // -sqrt(D) - x = -(sqrt(D) + x)
  if (x > 0) return -1;
  // sqrt(D) + x with x <= 0: sign(D - x^2)
  return -sgn(D - x * x);
}

inline LinAnswer solve_linear_conic(const QFun& Q, const QLin& l) {
  LinAnswer r;
  const Q2 o = l.o, op{l.o.x + l.d.x, l.o.y + l.d.y}, om{l.o.x - l.d.x, l.o.y - l.d.y};
  const mpq_class C = Q(o), qp = Q(op), qm = Q(om);
  const mpq_class A = (qp + qm) / 2 - C, B = (qp - qm) / 2;
  const auto in_domain_rational = [&](const mpq_class& t) {
    return !(l.lo && t < 0) && !(l.hi && t > 1);
  };
  if (A == 0) {
    if (B == 0) {
      r.whole = C == 0;
      return r;
    }
    const mpq_class t = -C / B;
    if (in_domain_rational(t)) {
      r.count = 1;
      r.t[0] = t.get_d();
      r.mult[0] = 1;
    }
    return r;
  }
  const mpq_class D = B * B - 4 * A * C;
  if (D < 0) return r;
  if (D == 0) {
    const mpq_class t = -B / (2 * A);
    if (in_domain_rational(t)) {
      r.count = 1;
      r.t[0] = t.get_d();
      r.mult[0] = 2;
    }
    return r;
  }
  // roots (-B + s sqrt(D)) / (2A); root >= lo  <=>  s sqrt(D) >= 2A lo + B when A > 0.
  const int sa = sgn(A);
  std::vector<std::pair<double, int>> roots;
  for (int s : {-1, 1}) {
    bool ok = true;
    if (l.lo) {
      // (-B + s sqrt D)/(2A) >= 0  <=>  sa (s sqrt D - B) >= 0
      const int c = cmp_sqrt(D, s, B);
      ok = ok && sa * c >= 0;
    }
    if (l.hi) {
      // (-B + s sqrt D)/(2A) <= 1  <=>  sa (s sqrt D - B - 2A) <= 0
      const int c = cmp_sqrt(D, s, B + 2 * A);
      ok = ok && sa * c <= 0;
    }
    if (!ok) continue;
    mpf_class sd(D, 256);
    sd = sqrt(sd);
    mpf_class t(-B, 256);
    t = (t + s * sd) / mpf_class(2 * A, 256);
    roots.push_back({t.get_d(), 1});
  }
  std::sort(roots.begin(), roots.end());
  r.count = static_cast<int>(roots.size());
  for (int i = 0; i < r.count; ++i) {
    r.t[i] = roots[static_cast<std::size_t>(i)].first;
    r.mult[i] = 1;
  }
  return r;
}

}  // namespace locus_test::conic
