// SPDX-License-Identifier: BSL-1.0
// Linear components against spheres, ellipsoids, general quadrics, cylinders, cones and capsules
// (include/locus/intersection/detail/quadric3.hpp); row int3.linear-quadric, book section 11.3.
// Derivations: docs/notes/intersection3.md, "Linear components and quadrics".

#include <locus/config.hpp>
#include <locus/core/exact_poly.hpp>
#include <locus/intersection/detail/quadric3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>

namespace locus::detail::quadric3 {
namespace {

using P = ExactPoly;
constexpr double inf = std::numeric_limits<double>::infinity();

bool finite(const V& v) noexcept { return linear3::finite(v); }
bool finite(double x) noexcept { return std::isfinite(x); }
std::size_t z(int i) noexcept { return static_cast<std::size_t>(i); }
bool valid_lin(const Lin& l) noexcept {
  return finite(l.o) && finite(l.d) && (!l.hi || finite(l.q));
}
bool zero_dir(const Lin& l) noexcept { return l.hi ? l.o == l.q : l.d == V{}; }

// ---------------------------------------------------------------------------------------------
// Exact signs. A quadric is a symmetric bilinear form H on homogeneous points (x, w): Q(X) =
// H((X, 1), (X, 1)). On a line (P, D) = ((o, 1), (d, 0)): q(t) = H(P,P) + 2 t H(P,D) + t^2 H(D,D);
// on a segment the binary form in (1 - t, t) over (P0, P1) = ((p0, 1), (p1, 1)), whose
// discriminant H01^2 - H00 H11 has the sign of the one in t (the substitution has determinant 1)
// and whose slopes are q'(0) ~ H01 - H00, q'(1) ~ H11 - H01: no rounded direction p1 - p0.

/// A homogeneous point: w = 1 a point, w = 0 a direction.
struct HP {
  V p;
  int w;
};

/// A coordinate of x - w c as an exact polynomial.
P rel(const HP& x, const V& c, int i) noexcept {
  return x.w != 0 ? P::diff(x.p[i], c[i]) : P::var(x.p[i]);
}

/// sign(x^2 - y z), beyond ExactPoly's capacity: the products go into one term list.
int sign_sq_minus(const P& x, const P& y, const P& zz) noexcept {
  constexpr int cap = 720;
  if (!x.valid() || !y.valid() || !zz.valid()) return 0;
  const int n = x.size() * x.size() + y.size() * zz.size();
  LOCUS_ASSERT(n <= cap, "exact discriminant: term list too long");
  if (n > cap) return 0;
  std::array<ExactTerm, cap> t;
  int k = 0;
  const auto mul = [&](const ExactTerm& a, const ExactTerm& b, int s) {
    ExactTerm& r = t[z(k++)];
    r.sign = s * a.sign * b.sign;
    r.pow2 = a.pow2 + b.pow2;
    r.count = a.count + b.count;
    for (int i = 0; i < a.count; ++i) r.f[i] = a.f[i];
    for (int i = 0; i < b.count; ++i) r.f[a.count + i] = b.f[i];
  };
  for (const ExactTerm& a : x.terms())
    for (const ExactTerm& b : x.terms()) mul(a, b, 1);
  for (const ExactTerm& a : y.terms())
    for (const ExactTerm& b : zz.terms()) mul(a, b, -1);
  return exact_sign_of_terms(std::span<const ExactTerm>(t.data(), z(k)));
}

/// Signs of q on the component: leading coefficient, value and slope at t = 0 (and t = 1 for a
/// segment), discriminant.
struct Signs {
  int a = 0, c0 = 0, b0 = 0, c1 = 0, b1 = 0, disc = 0;
};

template <class H>
Signs signs_of(const Lin& l, const H& h, bool with_disc = true) noexcept {
  Signs s;
  if (l.hi) {
    const HP p0{l.o, 1}, p1{l.q, 1};
    const P h00 = h(p0, p0), h01 = h(p0, p1), h11 = h(p1, p1);
    s.c0 = h00.sign();
    s.c1 = h11.sign();
    s.b0 = (h01 - h00).sign();
    s.b1 = (h11 - h01).sign();
    s.a = (h00 + h11 - h01.times_pow2(1)).sign();
    if (with_disc) s.disc = sign_sq_minus(h01, h00, h11);
  } else {
    const HP p{l.o, 1}, d{l.d, 0};
    const P hpp = h(p, p), hpd = h(p, d), hdd = h(d, d);
    s.c0 = hpp.sign();
    s.b0 = hpd.sign();
    s.a = hdd.sign();
    if (with_disc) s.disc = sign_sq_minus(hpd, hpp, hdd);
  }
  return s;
}

/// H of the sphere |X - c|^2 - r^2.
struct SphereH {
  const SphereD& s;
  P operator()(const HP& x, const HP& y) const noexcept {
    P r = rel(x, s.c, 0) * rel(y, s.c, 0) + rel(x, s.c, 1) * rel(y, s.c, 1) +
          rel(x, s.c, 2) * rel(y, s.c, 2);
    if (x.w != 0 && y.w != 0) r -= P::var(s.r) * P::var(s.r);
    return r;
  }
};

/// 2 H of the general quadric X^T A X + b.X + c.
struct QuadricH {
  const QuadricD& q;
  P operator()(const HP& x, const HP& y) const noexcept {
    P r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        r += (P::var(q.a[std::min(i, j)][std::max(i, j)]) * P::var(x.p[i]) * P::var(y.p[j]))
                 .times_pow2(1);
    for (int i = 0; i < 3; ++i) {
      if (y.w != 0) r += P::var(q.b[i]) * P::var(x.p[i]);
      if (x.w != 0) r += P::var(q.b[i]) * P::var(y.p[i]);
    }
    if (x.w != 0 && y.w != 0) r += P::var(q.c).times_pow2(1);
    return r;
  }
};

/// a x v for exact polynomial coordinates of v.
struct P3 {
  P x, y, z;
};

/// H of the infinite cylinder |a x (X - c)|^2 - r^2 |a|^2 (a need not be unit).
struct CylinderH {
  const V& c;
  const V& a;
  double r;
  [[nodiscard]] P cross_comp(const HP& x, int i) const noexcept {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    return P::var(a[j]) * rel(x, c, k) - P::var(a[k]) * rel(x, c, j);
  }
  P operator()(const HP& x, const HP& y) const noexcept {
    P s;
    for (int i = 0; i < 3; ++i) s += cross_comp(x, i) * cross_comp(y, i);
    if (x.w != 0 && y.w != 0) {
      const P rr = P::var(r) * P::var(r);
      s -= rr * (P::var(a.x) * P::var(a.x) + P::var(a.y) * P::var(a.y) + P::var(a.z) * P::var(a.z));
    }
    return s;
  }
};

/// Cylinder discriminant: sign(r^2 |a x d|^2 - [a, d, w]^2), w = o - c (see the notes).
int cylinder_disc(const Lin& l, const V& c, const V& a, double r) noexcept {
  const auto cr = [](const V& u, const V& v, int i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    return P::var(u[j]) * P::var(v[k]) - P::var(u[k]) * P::var(v[j]);
  };
  P trip, axd2;
  for (int i = 0; i < 3; ++i) {
    // d x w: line (d x o - d x c); segment (p1 x p0 - p1 x c + p0 x c).
    const P dxw =
        l.hi ? cr(l.q, l.o, i) - cr(l.q, c, i) + cr(l.o, c, i) : cr(l.d, l.o, i) - cr(l.d, c, i);
    trip += P::var(a[i]) * dxw;
    const P axd = l.hi ? cr(a, l.q, i) - cr(a, l.o, i) : cr(a, l.d, i);
    axd2 += axd * axd;
  }
  return -sign_sq_minus(trip, P::var(r) * P::var(r), axd2);
}

// ---------------------------------------------------------------------------------------------
// Rounded roots of q on the whole line, t1 <= t2 (t1 == t2 when tangent).

struct Roots {
  double t1, t2;
};

/// |w + t d|^2 = r^2 given cross = |d x w| accurately enough.
Roots circle_roots(const V& w, const V& d, double r, bool tangent) noexcept {
  const double a = dot(d, d), len = std::sqrt(a);
  const double tm = -dot(d, w) / a;
  if (tangent) return {tm, tm};
  const double dist = length(cross(d, w)) / len;
  const double half = std::sqrt(std::max((r - dist) * (r + dist), 0.0)) / len;
  return {tm - half, tm + half};
}

Roots quadratic_roots(double qa, double qb, double qc, bool tangent) noexcept {
  if (tangent) return {-qb / (2.0 * qa), -qb / (2.0 * qa)};
  const double disc = std::max(qb * qb - 4.0 * qa * qc, 0.0);
  const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
  if (q == 0.0) return {-qb / (2.0 * qa), -qb / (2.0 * qa)};
  double t1 = q / qa, t2 = qc / q;
  if (t1 > t2) std::swap(t1, t2);
  return {t1, t2};
}

struct QCoef {
  double a, b, c;
};
QCoef quadric_coef(const QuadricD& k, const V& o, const V& d) noexcept {
  V ad{}, ao{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double aij = k.a[std::min(i, j)][std::max(i, j)];
      ad[i] += aij * d[j];
      ao[i] += aij * o[j];
    }
  return {dot(d, ad), 2.0 * dot(o, ad) + dot(k.b, d), dot(o, ao) + dot(k.b, o) + k.c};
}

Roots quadric_roots(const QuadricD& k, const Lin& l, bool tangent) noexcept {
  const QCoef q = quadric_coef(k, l.o, l.d);
  return quadratic_roots(q.a, q.b, q.c, tangent);
}

Roots cylinder_roots(const V& c, const V& a, double r, const Lin& l, bool tangent) noexcept {
  const V u = normalize(a);
  const V w = l.o - c;
  const V dp = l.d - dot(l.d, u) * u, wp = w - dot(w, u) * u;
  return circle_roots(wp, dp, r, tangent);
}

// ---------------------------------------------------------------------------------------------
// The roots of q inside the component's domain, decided by the exact signs.

struct Picked {
  int n = 0;
  double t[2]{};
  int mult[2]{};
  bool whole = false;  ///< the component lies on the surface
};

template <class F>
Picked pick(const Lin& l, const Signs& s, const F& roots) noexcept {
  Picked p;
  const auto put = [&](double t, int m) {
    if (l.lo) t = std::max(t, 0.0);
    if (l.hi) t = std::min(t, 1.0);
    p.t[p.n] = t;
    p.mult[p.n++] = m;
  };
  if (s.a == 0) {
    if (s.b0 == 0) {
      p.whole = s.c0 == 0;
      return p;
    }
    if (l.lo && s.b0 * s.c0 > 0) return p;
    if (l.hi && s.b0 * s.c1 < 0) return p;
    // q linear: the root of B t + C from the rounded coefficients (roots() gives it as t1).
    put(s.c0 == 0 ? 0.0 : (l.hi && s.c1 == 0) ? 1.0 : roots(false).t1, 1);
    return p;
  }
  const int p0 = s.a * s.c0, v0 = s.a * s.b0, p1 = s.a * s.c1, v1 = s.a * s.b1;
  if (s.disc < 0) return p;
  if (s.disc == 0) {
    if (l.lo && v0 > 0) return p;
    if (l.hi && v1 < 0) return p;
    put(p0 == 0 ? 0.0 : (l.hi && p1 == 0) ? 1.0 : roots(true).t1, 2);
    return p;
  }
  // Root t1 >= 0 iff q(0) is on the far side of it: A q(0) >= 0 and the vertex ahead (A q'(0) <
  // 0); t2 >= 0 iff 0 lies between the roots or before both. Mirrored at t = 1.
  const bool in1 = (!l.lo || (p0 >= 0 && v0 < 0)) && (!l.hi || (p1 <= 0 || v1 > 0));
  const bool in2 = (!l.lo || (p0 <= 0 || v0 < 0)) && (!l.hi || (p1 >= 0 && v1 > 0));
  if (!in1 && !in2) return p;
  Roots r = roots(false);
  if (p0 == 0) (v0 < 0 ? r.t1 : r.t2) = 0.0;
  if (l.hi && p1 == 0) (v1 < 0 ? r.t1 : r.t2) = 1.0;
  if (in1) put(r.t1, 1);
  if (in2) put(std::max(r.t2, in1 ? p.t[0] : r.t2), 1);
  return p;
}

/// The point of parameter t: exact at t = 0 and (segment) t = 1.
V point_of(const Lin& l, double t) noexcept {
  if (t == 0.0) return l.o;
  if (l.hi && t == 1.0) return l.q;
  if (l.hi && t > 0.5) return l.q + (t - 1.0) * l.d;
  return l.o + t * l.d;
}

void finish(R& r) noexcept {
  if (r.kind == Kind::empty || r.kind == Kind::point || r.kind == Kind::points)
    r.kind = r.count == 0 ? Kind::empty : r.count == 1 ? Kind::point : Kind::points;
}

/// The whole component on the surface: two of its points.
void whole(R& r, const Lin& l) noexcept {
  r.kind = l.hi ? Kind::segment : l.lo ? Kind::ray : Kind::line;
  r.count = 2;
  r.point[0] = l.o;
  r.point[1] = l.hi ? l.q : l.o + l.d;
  r.param_a[0] = 0.0;
  r.param_a[1] = 1.0;
}

/// Fills r from picked parameters; info(X) gives (param_b, normal).
template <class Info>
R emit(const Lin& l, const Picked& p, const Info& info) noexcept {
  R r;
  if (p.whole) {
    whole(r, l);
    for (int i = 0; i < 2; ++i) {
      const auto [pb, nv] = info(r.point[z(i)]);
      r.param_b[z(i)] = pb;
      r.normal[z(i)] = nv;
    }
    return r;
  }
  for (int i = 0; i < p.n; ++i) {
    const auto k = z(r.count++);
    r.point[k] = point_of(l, p.t[i]);
    r.param_a[k] = p.t[i];
    const auto [pb, nv] = info(r.point[k]);
    r.param_b[k] = pb;
    r.normal[k] = nv;
    r.multiplicity[k] = p.mult[i];
  }
  finish(r);
  return r;
}

struct Info {
  Vec2<double> param;
  V normal;
};

/// A zero direction: the point, if it lies on the surface (sign of the value exact).
template <class InfoF>
R point_case(const Lin& l, int value_sign, const InfoF& info) noexcept {
  Picked p;
  if (value_sign == 0) {
    p.n = 1;
    p.t[0] = 0.0;
    p.mult[0] = 1;
  }
  return emit(l, p, info);
}

Vec2<double> angle_height(const V& x, const V& c, const V& axis) noexcept {
  const auto b = perpendicular_basis(axis);
  const V w = x - c;
  return {std::atan2(dot(b.v, w), dot(b.u, w)), dot(axis, w)};
}

bool valid(const SphereD& s) noexcept { return finite(s.c) && finite(s.r) && s.r >= 0.0; }
bool valid(const QuadricD& q) noexcept {
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j)
      if (!finite(q.a[i][j])) return false;
  return finite(q.b) && finite(q.c);
}
bool valid(const CylinderD& c) noexcept {
  return finite(c.c) && finite(c.a) && c.a != V{} && finite(c.r) && c.r >= 0.0 && c.h >= 0.0;
}

// ---------------------------------------------------------------------------------------------
// Intervals of a line inside a solid (finite cylinders, cones, capsules).

enum Src : int { lateral = 0, cap_lo = 1, cap_hi = 2, sphere0 = 3, sphere1 = 4 };

struct Iv {
  double s, e;
  int ss, se;  ///< what bounds each end (Src)
};

/// Intersection of two intervals (empty when s > e).
Iv meet(const Iv& a, const Iv& b) noexcept {
  Iv r = a;
  if (b.s > r.s) {
    r.s = b.s;
    r.ss = b.ss;
  }
  if (b.e < r.e) {
    r.e = b.e;
    r.se = b.se;
  }
  return r;
}

/// The t-interval where lo <= h0 + t hd <= hi (bounds may be infinite).
bool slab(double h0, double hd, double lo, double hi, Iv& out) noexcept {
  if (hd == 0.0) {
    out = {-inf, inf, cap_lo, cap_hi};
    return lo <= h0 && h0 <= hi;
  }
  double a = (lo - h0) / hd, b = (hi - h0) / hd;
  int sa = cap_lo, sb = cap_hi;
  if (a > b) {
    std::swap(a, b);
    std::swap(sa, sb);
  }
  if (std::isnan(a)) a = -inf;
  if (std::isnan(b)) b = inf;
  out = {a, b, sa, sb};
  return true;
}

/// Pieces of the line where q <= 0 (at most two), from exact signs and rounded roots.
template <class F, class G>
int nonpositive_pieces(const Signs& s, const G& linear_root, const F& roots, Iv out[2]) noexcept {
  if (s.a == 0) {
    if (s.b0 == 0) {
      if (s.c0 > 0) return 0;
      out[0] = {-inf, inf, lateral, lateral};
      return 1;
    }
    const double t = linear_root();
    out[0] = s.b0 > 0 ? Iv{-inf, t, lateral, lateral} : Iv{t, inf, lateral, lateral};
    return 1;
  }
  if (s.a > 0) {
    if (s.disc < 0) return 0;
    const Roots r = roots(s.disc == 0);
    out[0] = {r.t1, r.t2, lateral, lateral};
    return 1;
  }
  if (s.disc <= 0) {
    out[0] = {-inf, inf, lateral, lateral};
    return 1;
  }
  const Roots r = roots(false);
  out[0] = {-inf, r.t1, lateral, lateral};
  out[1] = {r.t2, inf, lateral, lateral};
  return 2;
}

/// Emits the finite interval ends inside the component's domain.
template <class InfoF>
R emit_intervals(const Lin& l, Iv* iv, int n, const InfoF& info) noexcept {
  std::sort(iv, iv + n, [](const Iv& a, const Iv& b) { return a.s < b.s; });
  // Merge touching pieces (the two nappes of a cone meet at the vertex).
  int m = 0;
  for (int i = 0; i < n; ++i) {
    if (m > 0 && iv[i].s <= iv[m - 1].e) {
      if (iv[i].e > iv[m - 1].e) {
        iv[m - 1].e = iv[i].e;
        iv[m - 1].se = iv[i].se;
      }
    } else {
      iv[m++] = iv[i];
    }
  }
  R r;
  const auto in = [&](double t) {
    return std::isfinite(t) && (!l.lo || t >= 0.0) && (!l.hi || t <= 1.0);
  };
  const auto put = [&](double t, int src, int mult) {
    if (!in(t) || r.count >= 4) return;
    const auto k = z(r.count++);
    r.point[k] = point_of(l, t);
    r.param_a[k] = t;
    const Info f = info(r.point[k], src);
    r.param_b[k] = f.param;
    r.normal[k] = f.normal;
    r.multiplicity[k] = mult;
  };
  for (int i = 0; i < m; ++i) {
    if (iv[i].s == iv[i].e) {
      put(iv[i].s, iv[i].ss, 2);
    } else {
      put(iv[i].s, iv[i].ss, 1);
      put(iv[i].e, iv[i].se, 1);
    }
  }
  finish(r);
  return r;
}

/// The line's interval inside the infinite solid cylinder (exact count), or false.
bool cylinder_piece(const Lin& l, const V& c, const V& a, double r, Iv& out) noexcept {
  const CylinderH h{c, a, r};
  Signs s = signs_of(l, h, false);
  s.disc = cylinder_disc(l, c, a, r);
  Iv pieces[2];
  const int n = nonpositive_pieces(
      s, [] { return 0.0; }, [&](bool tangent) { return cylinder_roots(c, a, r, l, tangent); },
      pieces);
  if (n == 0) return false;
  out = pieces[0];
  return true;
}

/// The line's interval inside a solid ball (exact count), or false.
bool sphere_piece(const Lin& l, const V& c, double r, int src, Iv& out) noexcept {
  const SphereD sd{c, r};
  const Signs s = signs_of(l, SphereH{sd});
  if (s.disc < 0) return false;
  const Roots rt = circle_roots(l.o - c, l.d, r, s.disc == 0);
  out = {rt.t1, rt.t2, src, src};
  return true;
}

}  // namespace

// ---------------------------------------------------------------------------------------------

R hits(const Lin& l, const SphereD& s) noexcept {
  if (!valid_lin(l) || !valid(s)) return {};
  const auto info = [&](const V& x) {
    const V w = x - s.c;
    const Vec2<double> tp{std::atan2(w.y, w.x), std::atan2(std::hypot(w.x, w.y), w.z)};
    return Info{tp, normalize(w)};
  };
  const SphereH h{s};
  if (zero_dir(l)) return point_case(l, h(HP{l.o, 1}, HP{l.o, 1}).sign(), info);
  const Signs sg = signs_of(l, h);
  return emit(l, pick(l, sg, [&](bool t) { return circle_roots(l.o - s.c, l.d, s.r, t); }), info);
}

R hits(const Lin& l, const QuadricD& q) noexcept {
  if (!valid_lin(l) || !valid(q)) return {};
  const auto info = [&](const V& x) {
    V g{};
    for (int i = 0; i < 3; ++i) {
      g[i] = q.b[i];
      for (int j = 0; j < 3; ++j) g[i] += 2.0 * q.a[std::min(i, j)][std::max(i, j)] * x[j];
    }
    return Info{{0.0, 0.0}, normalize(g)};
  };
  const QuadricH h{q};
  if (zero_dir(l)) return point_case(l, h(HP{l.o, 1}, HP{l.o, 1}).sign(), info);
  const Signs sg = signs_of(l, h);
  return emit(l,
              pick(l, sg,
                   [&](bool t) {
                     if (sg.a == 0) {
                       const QCoef c = quadric_coef(q, l.o, l.d);
                       return Roots{-c.c / c.b, -c.c / c.b};
                     }
                     return quadric_roots(q, l, t);
                   }),
              info);
}

R hits(const Lin& l, const EllipsoidD& e) noexcept {
  if (!valid_lin(l) || !finite(e.c) || !finite(e.e) || !(e.e.x > 0.0 && e.e.y > 0.0 && e.e.z > 0.0))
    return {};
  for (const V& u : e.u)
    if (!finite(u) || u == V{}) return {};
  // The implicit quadric about the centre (rounded once) and the component moved by -c.
  QuadricD q{};
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) q.a[i][j] += e.u[k][i] * e.u[k][j] / (e.e[k] * e.e[k]);
  q.c = -1.0;
  Lin m = l;
  m.o = l.o - e.c;
  m.q = l.q - e.c;
  R r = hits(m, q);
  for (int i = 0; i < r.count; ++i) {
    const auto k = z(i);
    if (r.kind == Kind::point || r.kind == Kind::points) {
      // The point on the original component (exact at its ends).
      r.point[k] = (r.param_a[k] == 0.0) ? l.o : point_of(l, r.param_a[k]);
    } else {
      r.point[k] = r.point[k] + e.c;
    }
    const V w = r.point[k] - e.c;
    const V s{dot(e.u[0], w) / e.e.x, dot(e.u[1], w) / e.e.y, dot(e.u[2], w) / e.e.z};
    r.param_b[k] = {std::atan2(s.y, s.x), std::atan2(std::hypot(s.x, s.y), s.z)};
  }
  return r;
}

R hits(const Lin& l, const CylinderD& c) noexcept {
  if (!valid_lin(l) || !valid(c)) return {};
  const auto side_info = [&](const V& x) {
    const V w = x - c.c;
    const V u = normalize(c.a);
    return Info{angle_height(x, c.c, u), normalize(w - dot(w, u) * u)};
  };
  if (std::isinf(c.h)) {
    const CylinderH h{c.c, c.a, c.r};
    const auto info = [&](const V& x) {
      const Info f = side_info(x);
      return std::pair{f.param, f.normal};
    };
    if (zero_dir(l)) return point_case(l, h(HP{l.o, 1}, HP{l.o, 1}).sign(), info);
    Signs sg = signs_of(l, h, false);
    sg.disc = cylinder_disc(l, c.c, c.a, c.r);
    return emit(l, pick(l, sg, [&](bool t) { return cylinder_roots(c.c, c.a, c.r, l, t); }), info);
  }
  // Finite: the lateral interval (exact count) clipped by the slab of the caps (rounded).
  const V u = normalize(c.a);
  const auto info = [&](const V& x, int src) {
    if (src == lateral) return side_info(x);
    return Info{angle_height(x, c.c, u), src == cap_lo ? -u : u};
  };
  if (zero_dir(l)) {
    // A point: on the surface when on the closed solid and on the side or a cap plane.
    const int side = CylinderH{c.c, c.a, c.r}(HP{l.o, 1}, HP{l.o, 1}).sign();
    const double hh = dot(u, l.o - c.c);
    if (side > 0 || std::fabs(hh) > 0.5 * c.h || (side < 0 && std::fabs(hh) < 0.5 * c.h)) return {};
    Iv one[1] = {{0.0, 0.0, side == 0 ? lateral : (hh < 0.0 ? cap_lo : cap_hi), lateral}};
    R r = emit_intervals(l, one, 1, info);
    r.multiplicity[0] = 1;
    return r;
  }
  Iv iv[1];
  int n = 0;
  Iv side{}, sl{};
  if (cylinder_piece(l, c.c, c.a, c.r, side) &&
      slab(dot(u, l.o - c.c), dot(u, l.d), -0.5 * c.h, 0.5 * c.h, sl)) {
    const Iv x = meet(side, sl);
    if (x.s <= x.e) iv[n++] = x;
  }
  return emit_intervals(l, iv, n, info);
}

R hits(const Lin& l, const ConeD& c) noexcept {
  if (!valid_lin(l) || !finite(c.v) || !finite(c.a) || c.a == V{} || !(c.angle > 0.0) ||
      !(c.angle < 0.5 * 3.14159265358979323846) || !(c.hmin <= c.hmax) || std::isnan(c.hmin))
    return {};
  const V u = normalize(c.a);
  const double cc = std::cos(c.angle);
  // The implicit quadric cos^2 |w|^2 - (u.w)^2 about the vertex (rounded once) and the
  // component moved by -v.
  QuadricD q{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) q.a[i][j] = (i == j ? cc * cc : 0.0) - u[i] * u[j];
  Lin m = l;
  m.o = l.o - c.v;
  m.q = l.q - c.v;
  const auto info = [&](const V& x, int src) {
    const V w = x - c.v;
    const Vec2<double> th = angle_height(x, c.v, u);
    if (src == cap_lo || src == cap_hi) {
      // The cap at min_height faces -u when it is above the vertex, else the nappe's outside.
      const double hcap = src == cap_lo ? c.hmin : c.hmax;
      const bool down = src == cap_lo ? hcap >= 0.0 : hcap < 0.0;
      (void)hcap;
      return Info{th, down ? -u : u};
    }
    const double h = dot(u, w);
    const V radial = w - h * u;
    // grad (cos^2 |w|^2 - (u.w)^2) = 2 (cos^2 w - h u): outward from the solid.
    const V g = cc * cc * w - h * u;
    return Info{th, radial == V{} ? V{} : normalize(g)};
  };
  Iv pieces[2];
  int np = 0;
  Signs sg{};
  if (zero_dir(l)) {
    const int v = QuadricH{q}(HP{m.o, 1}, HP{m.o, 1}).sign();
    if (v <= 0) pieces[np++] = {-inf, inf, lateral, lateral};
  } else {
    sg = signs_of(m, QuadricH{q});
    const auto lin_root = [&] {
      const QCoef k = quadric_coef(q, m.o, m.d);
      return -k.c / k.b;
    };
    np = nonpositive_pieces(
        sg, lin_root, [&](bool t) { return quadric_roots(q, m, t); }, pieces);
  }
  Iv iv[4];
  int n = 0;
  const double h0 = dot(u, m.o), hd = zero_dir(l) ? 0.0 : dot(u, m.d);
  const double nappe[2][2] = {{std::max(c.hmin, 0.0), c.hmax}, {c.hmin, std::min(c.hmax, 0.0)}};
  for (int k = 0; k < 2; ++k) {
    if (nappe[k][0] > nappe[k][1]) continue;
    Iv sl;
    if (!slab(h0, hd, nappe[k][0], nappe[k][1], sl)) continue;
    // Slab ends at h = 0 are the vertex, not a cap.
    if (nappe[k][0] == 0.0) (hd > 0 ? sl.ss : sl.se) = lateral;
    if (nappe[k][1] == 0.0) (hd > 0 ? sl.se : sl.ss) = lateral;
    for (int i = 0; i < np; ++i) {
      const Iv x = meet(pieces[i], sl);
      if (x.s <= x.e && n < 4) iv[n++] = x;
    }
  }
  if (zero_dir(l)) {
    R r;
    const bool on_side = QuadricH{q}(HP{m.o, 1}, HP{m.o, 1}).sign() == 0;
    const bool on_cap = h0 == c.hmin || h0 == c.hmax;
    if (n > 0 && (on_side || on_cap)) {
      Iv one[1] = {{0.0, 0.0, on_side ? lateral : (h0 == c.hmin ? cap_lo : cap_hi), lateral}};
      r = emit_intervals(l, one, 1, info);
      r.multiplicity[0] = 1;
    }
    return r;
  }
  return emit_intervals(l, iv, n, info);
}

R hits(const Lin& l, const CapsuleD& c) noexcept {
  if (!valid_lin(l) || !finite(c.p0) || !finite(c.p1) || !finite(c.r) || !(c.r >= 0.0)) return {};
  const V a = c.p1 - c.p0;
  const auto info = [&](const V& x, int src) {
    if (src == sphere0 || src == sphere1) {
      const V ctr = src == sphere0 ? c.p0 : c.p1;
      const double s = a == V{} ? 0.0 : dot(x - c.p0, a) / dot(a, a);
      const auto b = perpendicular_basis(a == V{} ? V{0, 0, 1} : a);
      const V w = x - ctr;
      return Info{{std::atan2(dot(b.v, w), dot(b.u, w)), s}, normalize(w)};
    }
    const double s = dot(x - c.p0, a) / dot(a, a);
    const V foot = c.p0 + s * a;
    const auto b = perpendicular_basis(a);
    const V w = x - foot;
    return Info{{std::atan2(dot(b.v, w), dot(b.u, w)), s}, normalize(w)};
  };
  if (zero_dir(l)) {
    // A point: on the surface iff its distance to the segment is r (decided in floating point).
    R r;
    const V w = l.o - c.p0;
    const double s = a == V{} ? 0.0 : std::clamp(dot(w, a) / dot(a, a), 0.0, 1.0);
    const V foot = c.p0 + s * a;
    if (sqr_length(l.o - foot) == c.r * c.r) {
      Iv one[1] = {{0.0, 0.0, s == 0.0 ? sphere0 : s == 1.0 ? sphere1 : lateral, lateral}};
      r = emit_intervals(l, one, 1, info);
      r.multiplicity[0] = 1;
    }
    return r;
  }
  Iv parts[3];
  int n = 0;
  Iv x{};
  if (sphere_piece(l, c.p0, c.r, sphere0, x)) parts[n++] = x;
  if (a != V{} && sphere_piece(l, c.p1, c.r, sphere1, x)) parts[n++] = x;
  Iv side{}, sl{};
  if (a != V{} && cylinder_piece(l, c.p0, a, c.r, side) &&
      slab(dot(a, l.o - c.p0), dot(a, l.d), 0.0, dot(a, a), sl)) {
    const Iv y = meet(side, sl);
    if (y.s <= y.e) parts[n++] = {y.s, y.e, lateral, lateral};
  }
  if (n == 0) return {};
  // The capsule is convex: the pieces cover one interval.
  Iv all = parts[0];
  for (int i = 1; i < n; ++i) {
    if (parts[i].s < all.s) {
      all.s = parts[i].s;
      all.ss = parts[i].ss;
    }
    if (parts[i].e > all.e) {
      all.e = parts[i].e;
      all.se = parts[i].se;
    }
  }
  return emit_intervals(l, &all, 1, info);
}

}  // namespace locus::detail::quadric3
