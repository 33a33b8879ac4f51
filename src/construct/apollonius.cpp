// SPDX-License-Identifier: BSL-1.0
// Apollonius' problem (include/locus/construct/apollonius.hpp). In the coordinates Y = X - c0,
// rho = r + s0 r0 a solution is a vector Z = (Y, rho) with B(Z, Z) = 0 and B(Z, v_i) = k_i / 2,
// B the Lorentz form x x' + y y' - rho rho', v_i = (c_i - c0, -e_i), e_i = s_i r_i - s0 r0,
// k_i = B(v_i, v_i). Derivation and the exact counting rule: docs/notes/construct.md.
#include <locus/construct/apollonius.hpp>

#include "exact.hpp"

#include <cmath>

namespace locus {

namespace {
using namespace detail::construct;
using V = Vec2<double>;

struct V3 {
  double x, y, r;
};
double lorentz(const V3& a, const V3& b) noexcept { return a.x * b.x + a.y * b.y - a.r * b.r; }
V3 cross3(const V3& a, const V3& b) noexcept {
  return {a.y * b.r - a.r * b.y, a.r * b.x - a.x * b.r, a.x * b.y - a.y * b.x};
}
V3 axpy(double s, const V3& a, const V3& b) noexcept {
  return {s * a.x + b.x, s * a.y + b.y, s * a.r + b.r};
}

/// Pushes the circle of Z; a negative radius is the negated pattern's circle, except when every
/// radius is 0 (`self_dual`: the negated pattern is the pattern itself, so the root is a copy).
template <Real T>
void push_circle(ApolloniusSolutions<T>& out, const V& c0, const V3& z, double s0r0,
                 const int (&s)[3], bool self_dual) noexcept {
  double r = z.r - s0r0;
  int sg[3] = {s[0], s[1], s[2]};
  if (r < 0) {
    if (self_dual) return;
    r = -r;
    for (int& x : sg) x = -x;
  }
  const V x = c0 + V{z.x, z.y};
  out.circles.push({{from_d<T>(x), static_cast<T>(r)}, {sg[0], sg[1], sg[2]}});
}

/// The line with unit normal m tangent to c0 on its +m side (the huge circle lies there).
template <Real T>
void push_line(ApolloniusSolutions<T>& out, const V& c0, double r0, V m,
               const int (&s)[3]) noexcept {
  m = normalize(m);
  out.lines.push({{from_d<T>(c0 + r0 * m), from_d<T>(perp(m))}, {s[0], s[1], s[2]}});
}
}  // namespace

template <Real T>
ApolloniusSolutions<T> apollonius(const Circle2<T>& c0, const Circle2<T>& c1,
                                  const Circle2<T>& c2) noexcept {
  ApolloniusSolutions<T> out;
  const Circle2<T>* in[3] = {&c0, &c1, &c2};
  Status st = Status::ok;
  for (const auto* c : in) {
    if (!is_finite(c->center) || !is_finite(c->radius)) st = Status::non_finite_input;
    if (st == Status::ok && c->radius < T(0)) st = Status::degenerate_input;
  }
  out.circles.status = out.lines.status = st;
  if (st != Status::ok) return out;
  const V C[3] = {to_d(c0.center), to_d(c1.center), to_d(c2.center)};
  const double R[3] = {double(c0.radius), double(c1.radius), double(c2.radius)};
  // Sign patterns modulo global negation, zero radii keeping +1: the first circle with a
  // positive radius keeps +1, the others with a positive radius take both signs.
  int free_idx[3], nfree = 0;
  for (int i = 0; i < 3; ++i)
    if (R[i] > 0) free_idx[nfree++] = i;
  const int npat = nfree == 0 ? 1 : 1 << (nfree - 1);
  for (int pat = 0; pat < npat; ++pat) {
    int s[3] = {1, 1, 1};
    for (int f = 1; f < nfree; ++f)
      if (pat & (1 << (f - 1))) s[free_idx[f]] = -1;
    // Exact quantities.
    const P e1 = (s[1] > 0 ? var(R[1]) : -var(R[1])) - var(R[0]);
    const P e2 = (s[2] > 0 ? var(R[2]) : -var(R[2])) - var(R[0]);
    const P dx1 = dif(C[1].x, C[0].x), dy1 = dif(C[1].y, C[0].y);
    const P dx2 = dif(C[2].x, C[0].x), dy2 = dif(C[2].y, C[0].y);
    const P k1 = sqr(dx1) + sqr(dy1) - sqr(e1);
    const P k2 = sqr(dx2) + sqr(dy2) - sqr(e2);
    const P g = dx1 * dx2 + dy1 * dy2 - e1 * e2;
    // Rounded quantities (Y relative to c0).
    const double re1 = double(s[1]) * R[1] - R[0], re2 = double(s[2]) * R[2] - R[0];
    const V D1 = C[1] - C[0], D2 = C[2] - C[0];
    const V3 u1{D1.x, D1.y, re1}, u2{D2.x, D2.y, re2};  // J v_i: B(Z, v_i) = dot(Z, u_i)
    const double hk1 = 0.5 * (dot(D1, D1) - re1 * re1), hk2 = 0.5 * (dot(D2, D2) - re2 * re2);
    const int m12 = (dx1 * dy2 - dy1 * dx2).sign();
    const int m1r = (dx1 * e2 - e1 * dx2).sign();
    const int m2r = (dy1 * e2 - e1 * dy2).sign();
    if (m12 == 0 && m1r == 0 && m2r == 0) {
      // v1, v2 dependent. Consistent (infinitely many circles) when one is zero, they are
      // equal, or k1 = 0; otherwise no circle, and the lines m . (c1 - c0) = -e1, |m| = 1.
      const bool z1 = C[1] == C[0] && e1.sign() == 0;
      const bool z2 = C[2] == C[0] && e2.sign() == 0;
      const bool equal = C[1] == C[2] && (e1 - e2).sign() == 0;
      const int sk1 = k1.sign(), sk2 = k2.sign();
      if (z1 || z2 || equal || sk1 == 0 || sk2 == 0) {
        out.circles.infinite = true;
        continue;
      }
      const bool use1 = !(C[1] == C[0]);
      const V Dd = use1 ? D1 : D2;
      const double ee = use1 ? re1 : re2;
      if ((use1 ? sk1 : sk2) < 0 || Dd == V{}) continue;
      const Normalized<double, 2> nd = normalize_with_length(Dd);
      const double al = -ee / nd.length;
      const double be = std::sqrt(std::max(0.0, (1 - al) * (1 + al)));
      for (double sg : {1.0, -1.0})
        push_line(out, C[0], R[0], al * nd.dir + (sg * be) * perp(nd.dir), s);
      continue;
    }
    // Independent: the solutions lie on Z = Zp + t q, q = u1 x u2 (B-orthogonal to v1, v2).
    const V3 q = cross3(u1, u2);
    const double qq = q.x * q.x + q.y * q.y + q.r * q.r;
    const V3 a1 = cross3(u2, q), a2 = cross3(q, u1);
    const V3 zp{(hk1 * a1.x + hk2 * a2.x) / qq, (hk1 * a1.y + hk2 * a2.y) / qq,
                (hk1 * a1.r + hk2 * a2.r) / qq};
    const double qa = lorentz(q, q), qb = 2.0 * lorentz(zp, q), qc = lorentz(zp, zp);
    const P detg = k1 * k2 - sqr(g);
    if (detg.sign() != 0) {
      const int disc = k1.sign() * k2.sign() * (k1 + k2 - P::constant(1, 1) * g).sign();
      if (disc < 0) continue;
      if (disc == 0) {
        push_circle(out, C[0], axpy(-qb / (2.0 * qa), q, zp), R[0], s, nfree == 0);
        continue;
      }
      const double sq = std::sqrt(std::max(0.0, qb * qb - 4.0 * qa * qc));
      const double big = -0.5 * (qb + (qb >= 0 ? sq : -sq));  // no cancellation
      const double t1 = big / qa, t2 = big != 0.0 ? qc / big : t1;
      push_circle(out, C[0], axpy(t1, q, zp), R[0], s, nfree == 0);
      push_circle(out, C[0], axpy(t2, q, zp), R[0], s, nfree == 0);
      continue;
    }
    // Parallel to the cone: a tangent line (m = q_xy / q_r), and one finite circle unless
    // B(Zp, q) = 0, i.e. k1 (g - k2) = 0; G = 0 gives infinitely many.
    if (k1.sign() == 0 && k2.sign() == 0 && g.sign() == 0) {
      out.circles.infinite = true;
      continue;
    }
    push_line(out, C[0], R[0], V{q.x / q.r, q.y / q.r}, s);
    if (k1.sign() != 0 && (g - k2).sign() != 0)
      push_circle(out, C[0], axpy(-qc / qb, q, zp), R[0], s, nfree == 0);
  }
  return out;
}

template ApolloniusSolutions<float> apollonius<float>(const Circle2<float>&, const Circle2<float>&,
                                                      const Circle2<float>&) noexcept;
template ApolloniusSolutions<double> apollonius<double>(const Circle2<double>&,
                                                        const Circle2<double>&,
                                                        const Circle2<double>&) noexcept;

}  // namespace locus
