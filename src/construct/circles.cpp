// SPDX-License-Identifier: BSL-1.0
// Circles of chapter 8: through three points, tangent to three lines, of a given radius
// (include/locus/construct/circle_through.hpp, circles_of_radius.hpp). The counts come from
// exact signs (exact.hpp); the centres are computed in double and rounded.
#include <locus/construct/circle_through.hpp>
#include <locus/construct/circles_of_radius.hpp>
#include <locus/core/error_free.hpp>
#include <locus/core/predicates.hpp>

#include "exact.hpp"

#include <cmath>

namespace locus {

namespace {
using namespace detail::construct;
using V = Vec2<double>;

template <Real T>
bool finite(const Vec2<T>& p) noexcept {
  return is_finite(p);
}
template <Real T>
bool finite(const Line2<T>& l) noexcept {
  return is_finite(l.origin) && is_finite(l.direction);
}
template <Real T>
bool finite(const Circle2<T>& c) noexcept {
  return is_finite(c.center) && is_finite(c.radius);
}
template <Real T>
bool finite(T x) noexcept {
  return is_finite(x);
}
template <class... A>
bool all_finite(const A&... a) noexcept {
  return (finite(a) && ...);
}

template <Real T>
Circle2<T> circle_from(const V& x, double r) noexcept {
  return {from_d<T>(x), static_cast<T>(r)};
}

/// Unit normal perp(d / |d|) of a line.
V unit_normal(const V& d) noexcept { return perp(normalize(d)); }

}  // namespace

// ---- circle through three points (8.1) -------------------------------------------------------

template <Real T>
Solutions<Circle2<T>, 1> circle_through(const Vec2<T>& p0, const Vec2<T>& p1,
                                        const Vec2<T>& p2) noexcept {
  Solutions<Circle2<T>, 1> s;
  if (!all_finite(p0, p1, p2)) {
    s.status = Status::non_finite_input;
    return s;
  }
  if (orient2d(p0, p1, p2) == Sign::zero) return s;
  const V a = to_d(p0), b = to_d(p1) - a, c = to_d(p2) - a;
  const double bb = dot(b, b), cc = dot(c, c);
  const double det = 2.0 * diff_of_products(b.x, c.y, b.y, c.x);
  const V u{diff_of_products(c.y, bb, b.y, cc) / det, diff_of_products(b.x, cc, c.x, bb) / det};
  s.push(circle_from<T>(a + u, length(u)));
  return s;
}

// ---- circles tangent to three lines (8.2) ----------------------------------------------------

template <Real T>
Solutions<Circle2<T>, 4> circles_tangent_to(const Line2<T>& l0, const Line2<T>& l1,
                                            const Line2<T>& l2) noexcept {
  Solutions<Circle2<T>, 4> s;
  if (!all_finite(l0, l1, l2)) {
    s.status = Status::non_finite_input;
    return s;
  }
  const V o[3] = {to_d(l0.origin), to_d(l1.origin), to_d(l2.origin)};
  const V d[3] = {to_d(l0.direction), to_d(l1.direction), to_d(l2.direction)};
  for (const V& di : d)
    if (di == V{}) {
      s.status = Status::degenerate_input;
      return s;
    }
  // w[i] = sign of perp_dot(d_j, d_k) (i, j, k cyclic); 0 when lines j, k are parallel.
  int w[3];
  for (int i = 0; i < 3; ++i) {
    const V& dj = d[(i + 1) % 3];
    const V& dk = d[(i + 2) % 3];
    w[i] = (var(dj.x) * var(dk.y) - var(dj.y) * var(dk.x)).sign();
  }
  const int parallel_pairs = (w[0] == 0) + (w[1] == 0) + (w[2] == 0);
  if (parallel_pairs == 3) {
    // All parallel: no circle touches three distinct parallels; two coincident ones leave the
    // circles between them and the third (infinitely many), three coincident any circle on them.
    for (int j = 0; j < 3; ++j)
      if (cross_at(d[j], o[(j + 1) % 3], o[j]).sign() == 0) s.infinite = true;
    return s;
  }
  if (parallel_pairs == 1) {
    // Lines j, k parallel (w[i] == 0): coincident when o_k lies on line j.
    const int i = w[0] == 0 ? 0 : (w[1] == 0 ? 1 : 2);
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    if (cross_at(d[j], o[k], o[j]).sign() == 0) {
      s.infinite = true;
      return s;
    }
  } else {
    // No two parallel: concurrent lines leave only the point (radius 0). Concurrency: the
    // implicit coefficients (-d.y, d.x, perp_dot(d, o)) of the three lines are dependent.
    P det3 = P::constant(0);
    for (int i = 0; i < 3; ++i) {
      const V& dj = d[(i + 1) % 3];
      const V& dk = d[(i + 2) % 3];
      const P minor = var(dj.x) * var(dk.y) - var(dj.y) * var(dk.x);
      const P ci = var(d[i].x) * var(o[i].y) - var(d[i].y) * var(o[i].x);
      det3 += ci * minor;
    }
    if (det3.sign() == 0) return s;
  }
  // Patterns e = (+,+,+), (-,+,+), (+,-,+), (+,+,-). The system n_i . X - e_i r = n_i . o_i is
  // singular exactly when sum_i e_i w_i |d_i| / (|d_0||d_1||d_2|) = 0; with a parallel pair
  // (j, k) (w_i = 0, d_k = lambda d_j) that is e_k = e_j sign(lambda); otherwise it is never
  // singular (a triangle has its four circles).
  const V n[3] = {unit_normal(d[0]), unit_normal(d[1]), unit_normal(d[2])};
  for (int pat = 0; pat < 4; ++pat) {
    int e[3] = {1, 1, 1};
    if (pat > 0) e[pat - 1] = -1;
    if (parallel_pairs == 1) {
      const int i = w[0] == 0 ? 0 : (w[1] == 0 ? 1 : 2);
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      const int lambda = (var(d[j].x) * var(d[k].x) + var(d[j].y) * var(d[k].y)).sign();
      if (e[k] == e[j] * lambda) continue;
    }
    // Solve n_i . (X - o_0) - e_i r = n_i . (o_i - o_0) by Cramer's rule (translated to o_0 so
    // the right-hand sides are small differences).
    const double m[3][3] = {{n[0].x, n[0].y, -double(e[0])},
                            {n[1].x, n[1].y, -double(e[1])},
                            {n[2].x, n[2].y, -double(e[2])}};
    const double b[3] = {0.0, dot(n[1], o[1] - o[0]), dot(n[2], o[2] - o[0])};
    const auto det_with = [&](int col) {
      double a[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) a[i][j] = j == col ? b[i] : m[i][j];
      return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
             a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
             a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    };
    const double D = det_with(-1);
    const V x = o[0] + V{det_with(0) / D, det_with(1) / D};
    const double r = det_with(2) / D;
    s.push(circle_from<T>(x, std::abs(r)));
  }
  return s;
}

template <Real T>
Solutions<Circle2<T>, 1> incircle(const Triangle2<T>& t) noexcept {
  Solutions<Circle2<T>, 1> s;
  const auto all = circles_tangent_to<T>(Line2<T>{t.v0, t.v1 - t.v0}, Line2<T>{t.v1, t.v2 - t.v1},
                                         Line2<T>{t.v2, t.v0 - t.v2});
  s.status = all.status;
  if (all.count == 4) s.push(all.item[0]);
  return s;
}

template <Real T>
Solutions<Circle2<T>, 3> excircles(const Triangle2<T>& t) noexcept {
  Solutions<Circle2<T>, 3> s;
  const auto all = circles_tangent_to<T>(Line2<T>{t.v0, t.v1 - t.v0}, Line2<T>{t.v1, t.v2 - t.v1},
                                         Line2<T>{t.v2, t.v0 - t.v2});
  s.status = all.status;
  if (all.count != 4) return s;
  // Beyond edge v1v2 (line 1) is opposite v0, beyond v2v0 (line 2) opposite v1, v0v1 opposite v2.
  s.push(all.item[2]);
  s.push(all.item[3]);
  s.push(all.item[1]);
  return s;
}

// ---- circles of a given radius (8.6-8.11) ----------------------------------------------------

namespace {

/// Shared front end: status of r (must be positive and finite).
template <Real T>
Status radius_status(T r) noexcept {
  if (!is_finite(r)) return Status::non_finite_input;
  return r > T(0) ? Status::ok : Status::degenerate_input;
}

/// A circle locus of the centres: centre and radius (exact and rounded).
struct CircleLocus {
  V c;
  P rho;
  double rho_d;
};

/// The loci of centres at the right distance from a given circle: outside (R + r), and inside
/// (|R - r|) when R != r. Returns how many.
int circle_loci(const V& c, double R, double r, CircleLocus* out) noexcept {
  out[0] = {c, var(R) + var(r), R + r};
  if (R == r) return 1;
  if (R > r)
    out[1] = {c, var(R) - var(r), R - r};
  else
    out[1] = {c, var(r) - var(R), r - R};
  return 2;
}

template <Real T, int N>
bool push_meet(Solutions<Circle2<T>, N>& s, const V& a, const CircleLocus& la, const V& b,
               const CircleLocus& lb, double r) noexcept {
  const Meet m = circles_meet(a, la.rho, b, lb.rho);
  if (m == Meet::same) return false;
  if (m == Meet::none) return true;
  V pts[2];
  const int k = circle_circle_points(a, la.rho_d, b, lb.rho_d, m, pts);
  for (int i = 0; i < k; ++i) s.push(circle_from<T>(pts[i], r));
  return true;
}

}  // namespace

template <Real T>
Solutions<Circle2<T>, 2> circles_of_radius(const Vec2<T>& p, const Vec2<T>& q, T r) noexcept {
  Solutions<Circle2<T>, 2> s;
  if (!all_finite(p, q)) s.status = Status::non_finite_input;
  if (s.status == Status::ok) s.status = radius_status(r);
  if (s.status != Status::ok) return s;
  const CircleLocus a{to_d(p), var(double(r)), double(r)}, b{to_d(q), var(double(r)), double(r)};
  if (!push_meet(s, a.c, a, b.c, b, double(r))) s.infinite = true;
  return s;
}

template <Real T>
Solutions<Circle2<T>, 2> circles_of_radius(const Vec2<T>& p, const Line2<T>& l, T r) noexcept {
  Solutions<Circle2<T>, 2> s;
  if (!all_finite(p, l)) s.status = Status::non_finite_input;
  if (s.status == Status::ok) s.status = radius_status(r);
  if (s.status == Status::ok && l.direction == Vec2<T>{}) s.status = Status::degenerate_input;
  if (s.status != Status::ok) return s;
  const V pd = to_d(p), o = to_d(l.origin), d = to_d(l.direction);
  const double rd = double(r);
  const V u = normalize(d), n = perp(u);
  const int side = cross_at(d, pd, o).sign();
  const V foot = o + dot(u, pd - o) * u;
  if (side == 0) {  // p on the line: the two mirrored circles (8.13)
    s.push(circle_from<T>(foot - rd * n, rd));
    s.push(circle_from<T>(foot + rd * n, rd));
    return s;
  }
  // The centre is on p's side at distance r from the line and r from p.
  const P sr = side > 0 ? var(rd) : -var(rd);
  const Meet m = offset_line_meets_circle(o, d, sr, pd, var(rd));
  if (m == Meet::none) return s;
  V pts[2];
  const int k = line_circle_points(foot + (side * rd) * n, u, pd, rd, m, pts);
  for (int i = 0; i < k; ++i) s.push(circle_from<T>(pts[i], rd));
  return s;
}

template <Real T>
Solutions<Circle2<T>, 4> circles_of_radius(const Line2<T>& l0, const Line2<T>& l1, T r) noexcept {
  Solutions<Circle2<T>, 4> s;
  if (!all_finite(l0, l1)) s.status = Status::non_finite_input;
  if (s.status == Status::ok) s.status = radius_status(r);
  if (s.status == Status::ok && (l0.direction == Vec2<T>{} || l1.direction == Vec2<T>{}))
    s.status = Status::degenerate_input;
  if (s.status != Status::ok) return s;
  const V o0 = to_d(l0.origin), d0 = to_d(l0.direction), o1 = to_d(l1.origin),
          d1 = to_d(l1.direction);
  const double rd = double(r);
  if ((var(d0.x) * var(d1.y) - var(d0.y) * var(d1.x)).sign() == 0) {
    // Parallel: the strip between them has width |perp_dot(d0, o1 - o0)| / |d0|; infinitely
    // many circles when it is exactly 2r, or 0 (coincident lines), none otherwise.
    const P x = cross_at(d0, o1, o0);
    const P q = sqr(var(d0.x)) + sqr(var(d0.y));
    if (x.sign() == 0 || (sqr(x) - P::constant(1, 2) * sqr(var(rd)) * q).sign() == 0)
      s.infinite = true;
    return s;
  }
  // X = P + (e0 u1 - e1 u0) r / sin(theta), P the crossing, sin(theta) = perp_dot(u0, u1).
  const V u0 = normalize(d0), u1 = normalize(d1);
  const double sn = perp_dot(u0, u1);
  const V w = o1 - o0;
  const double t0 = perp_dot(w, u1) / sn;
  const V cross_pt = o0 + t0 * u0;
  for (int e0 : {1, -1})
    for (int e1 : {1, -1}) {
      const V x = cross_pt + (rd / sn) * (double(e0) * u1 - double(e1) * u0);
      s.push(circle_from<T>(x, rd));
    }
  return s;
}

template <Real T>
Solutions<Circle2<T>, 4> circles_of_radius(const Vec2<T>& p, const Circle2<T>& c, T r) noexcept {
  Solutions<Circle2<T>, 4> s;
  if (!all_finite(p, c)) s.status = Status::non_finite_input;
  if (s.status == Status::ok) s.status = radius_status(r);
  if (s.status == Status::ok && !(c.radius > T(0))) s.status = Status::degenerate_input;
  if (s.status != Status::ok) return s;
  const double rd = double(r);
  const CircleLocus lp{to_d(p), var(rd), rd};
  CircleLocus lc[2];
  const int nl = circle_loci(to_d(c.center), double(c.radius), rd, lc);
  for (int i = 0; i < nl; ++i)
    if (!push_meet(s, lc[i].c, lc[i], lp.c, lp, rd)) s.infinite = true;
  return s;
}

template <Real T>
Solutions<Circle2<T>, 8> circles_of_radius(const Line2<T>& l, const Circle2<T>& c, T r) noexcept {
  Solutions<Circle2<T>, 8> s;
  if (!all_finite(l, c)) s.status = Status::non_finite_input;
  if (s.status == Status::ok) s.status = radius_status(r);
  if (s.status == Status::ok && (!(c.radius > T(0)) || l.direction == Vec2<T>{}))
    s.status = Status::degenerate_input;
  if (s.status != Status::ok) return s;
  const double rd = double(r);
  const V o = to_d(l.origin), d = to_d(l.direction), u = normalize(d), n = perp(u);
  CircleLocus lc[2];
  const int nl = circle_loci(to_d(c.center), double(c.radius), rd, lc);
  for (int i = 0; i < nl; ++i)
    for (int side : {1, -1}) {
      const P sr = side > 0 ? var(rd) : -var(rd);
      const Meet m = offset_line_meets_circle(o, d, sr, lc[i].c, lc[i].rho);
      if (m == Meet::none) continue;
      V pts[2];
      const int k = line_circle_points(o + (side * rd) * n, u, lc[i].c, lc[i].rho_d, m, pts);
      for (int j = 0; j < k; ++j) s.push(circle_from<T>(pts[j], rd));
    }
  return s;
}

template <Real T>
Solutions<Circle2<T>, 8> circles_of_radius(const Circle2<T>& c0, const Circle2<T>& c1,
                                           T r) noexcept {
  Solutions<Circle2<T>, 8> s;
  if (!all_finite(c0, c1)) s.status = Status::non_finite_input;
  if (s.status == Status::ok) s.status = radius_status(r);
  if (s.status == Status::ok && (!(c0.radius > T(0)) || !(c1.radius > T(0))))
    s.status = Status::degenerate_input;
  if (s.status != Status::ok) return s;
  const double rd = double(r);
  CircleLocus a[2], b[2];
  const int na = circle_loci(to_d(c0.center), double(c0.radius), rd, a);
  const int nb = circle_loci(to_d(c1.center), double(c1.radius), rd, b);
  for (int i = 0; i < na; ++i)
    for (int j = 0; j < nb; ++j)
      if (!push_meet(s, a[i].c, a[i], b[j].c, b[j], rd)) s.infinite = true;
  return s;
}

#define LOCUS_INSTANTIATE(T)                                                                   \
  template Solutions<Circle2<T>, 1> circle_through<T>(const Vec2<T>&, const Vec2<T>&,          \
                                                      const Vec2<T>&) noexcept;                \
  template Solutions<Circle2<T>, 4> circles_tangent_to<T>(const Line2<T>&, const Line2<T>&,    \
                                                          const Line2<T>&) noexcept;           \
  template Solutions<Circle2<T>, 1> incircle<T>(const Triangle2<T>&) noexcept;                 \
  template Solutions<Circle2<T>, 3> excircles<T>(const Triangle2<T>&) noexcept;                \
  template Solutions<Circle2<T>, 2> circles_of_radius<T>(const Vec2<T>&, const Vec2<T>&,       \
                                                         T) noexcept;                          \
  template Solutions<Circle2<T>, 2> circles_of_radius<T>(const Vec2<T>&, const Line2<T>&,      \
                                                         T) noexcept;                          \
  template Solutions<Circle2<T>, 4> circles_of_radius<T>(const Line2<T>&, const Line2<T>&,     \
                                                         T) noexcept;                          \
  template Solutions<Circle2<T>, 4> circles_of_radius<T>(const Vec2<T>&, const Circle2<T>&,    \
                                                         T) noexcept;                          \
  template Solutions<Circle2<T>, 8> circles_of_radius<T>(const Line2<T>&, const Circle2<T>&,   \
                                                         T) noexcept;                          \
  template Solutions<Circle2<T>, 8> circles_of_radius<T>(const Circle2<T>&, const Circle2<T>&, \
                                                         T) noexcept;
LOCUS_INSTANTIATE(float)
LOCUS_INSTANTIATE(double)
#undef LOCUS_INSTANTIATE

}  // namespace locus
