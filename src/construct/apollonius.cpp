// SPDX-License-Identifier: BSL-1.0
// Apollonius' problem (include/locus/construct/apollonius.hpp). In the coordinates Y = X - c0,
// rho = r + s0 r0 a solution is a vector Z = (Y, rho) with B(Z, Z) = 0 and B(Z, v_i) = k_i / 2,
// B the Lorentz form x x' + y y' - rho rho', v_i = (c_i - c0, -e_i), e_i = s_i r_i - s0 r0,
// k_i = B(v_i, v_i). Derivation and the exact counting rule: docs/notes/construct.md.
#include <locus/construct/apollonius.hpp>

#include "../core/big_int.hpp"
#include "exact.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <utility>

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

/// How many points the three circles share (0, 1 or 2), exactly; 0 for concentric circles 0
/// and 1 and 2 (those go to the rank-deficient branch). In Y = X - c0 with D_i = c_i - c0 and
/// b_i = |D_i|^2 - r_i^2 + r0^2, a common point solves 2 D_i . Y = b_i and |Y|^2 = r0^2. Every
/// value is an integer times 2^e_min on core's big integer: coordinates below 2^2099 at that
/// scale, so the degree-6 expressions fit 13440 bits.
int common_points(const V (&c)[3], const double (&r)[3]) noexcept {
  using Big = detail::BigInt<420>;
  int e = INT_MAX;
  for (int i = 0; i < 3; ++i) {
    for (const double x : {c[i].x, c[i].y, r[i]}) {
      if (x != 0.0) e = std::min(e, detail::low_exponent(x));
    }
  }
  if (e == INT_MAX) return 0;  // three point circles at the origin: concentric
  const auto big = [e](double x) { return Big::from_double(x, -e); };
  const Big x0 = big(c[0].x), y0 = big(c[0].y), r0 = big(r[0]);
  Big dx[2], dy[2], b[2];
  for (int i = 0; i < 2; ++i) {
    dx[i] = big(c[i + 1].x) - x0;
    dy[i] = big(c[i + 1].y) - y0;
    const Big ri = big(r[i + 1]);
    b[i] = dx[i] * dx[i] + dy[i] * dy[i] - ri * ri + r0 * r0;
  }
  const Big det = dx[0] * dy[1] - dy[0] * dx[1];
  if (!det.is_zero()) {
    // Y = (b0 dy1 - b1 dy0, dx0 b1 - dx1 b0) / (2 det) must lie on |Y| = r0.
    const Big px = b[0] * dy[1] - b[1] * dy[0], py = dx[0] * b[1] - dx[1] * b[0];
    const Big rhs = Big(4) * det * det * r0 * r0;
    return px * px + py * py == rhs ? 1 : 0;
  }
  // Collinear centres: use a nonzero D_k; the other equation must be the same line
  // (D_j = lambda D_k and b_j = lambda b_k), and the line 2 D_k . Y = b_k meets |Y| = r0 in
  // 2, 1 or 0 points as 4 r0^2 |D_k|^2 - b_k^2 is positive, zero or negative.
  const int k = !(dx[0].is_zero() && dy[0].is_zero()) ? 0 : 1, j = 1 - k;
  const Big dd = dx[k] * dx[k] + dy[k] * dy[k];
  if (dd.is_zero()) return 0;
  if (b[j] * dd != b[k] * (dx[j] * dx[k] + dy[j] * dy[k])) return 0;
  const int s = (Big(4) * r0 * r0 * dd - b[k] * b[k]).sign();
  return s > 0 ? 2 : (s == 0 ? 1 : 0);
}

/// When the circles share z points, (P, 0) solves every pattern's equations, so each pattern
/// has those z roots: keep them once, from the first pattern, with radius exactly 0 and signs
/// +1; drop them from the later patterns. Within a pattern they are its z roots of least
/// |radius| (exactly 0 before rounding).
template <Real T>
void merge_radius_zero_roots(Solutions<ApolloniusCircle<T>, 8>& circles,
                             const int (&pattern_begin)[5], int npat, const V (&c)[3],
                             const double (&r)[3]) noexcept {
  const int z = common_points(c, r);
  if (z == 0) return;
  Solutions<ApolloniusCircle<T>, 8> kept;
  kept.status = circles.status;
  kept.infinite = circles.infinite;
  const auto radius_of = [&](int i) {
    return circles.item[static_cast<std::size_t>(i)].circle.radius;
  };
  for (int p = 0; p < npat; ++p) {
    const int b = pattern_begin[p], n = pattern_begin[p + 1] - b;
    int order[8];
    for (int i = 0; i < n; ++i) order[i] = b + i;
    for (int i = 1; i < n; ++i) {  // insertion sort by radius (n <= 8)
      for (int k = i; k > 0 && radius_of(order[k]) < radius_of(order[k - 1]); --k) {
        std::swap(order[k], order[k - 1]);
      }
    }
    for (int i = 0; i < n; ++i) {
      ApolloniusCircle<T> x = circles.item[static_cast<std::size_t>(order[i])];
      if (i < z) {
        if (p > 0) continue;
        x.circle.radius = T(0);
        x.s = {1, 1, 1};
      }
      kept.push(x);
    }
  }
  circles = kept;
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
  int pattern_begin[5] = {0, 0, 0, 0, 0};  // each pattern's first circle in out.circles
  for (int pat = 0; pat < npat; ++pat) {
    pattern_begin[pat] = out.circles.count;
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
  pattern_begin[npat] = out.circles.count;
  if (!out.circles.infinite) merge_radius_zero_roots(out.circles, pattern_begin, npat, C, R);
  return out;
}

template ApolloniusSolutions<float> apollonius<float>(const Circle2<float>&, const Circle2<float>&,
                                                      const Circle2<float>&) noexcept;
template ApolloniusSolutions<double> apollonius<double>(const Circle2<double>&,
                                                        const Circle2<double>&,
                                                        const Circle2<double>&) noexcept;

}  // namespace locus
