// SPDX-License-Identifier: BSL-1.0
// Linear components against a torus (include/locus/intersection/detail/quadric3.hpp); row
// int3.torus, book section 11.3.5 (figures 11.74-11.77). Derivation: docs/notes/intersection3.md,
// "Torus".

#include <locus/intersection/detail/quadric3.hpp>
#include <locus/numeric/roots.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace locus::detail::quadric3 {
namespace {

constexpr double eps = 0x1p-52;

double pow2_inv(double m) noexcept {
  return m > 0.0 && std::isfinite(m) ? std::ldexp(1.0, -std::ilogb(m)) : 1.0;
}

/// The torus quartic along w + t d (torus at the origin, unit axis n, radii big, small).
struct Quartic {
  double c[5], err[5];
};

Quartic torus_quartic(const V& w, const V& d, const V& n, double big, double small) noexcept {
  const double e = dot(d, d), f = dot(w, d), ww = dot(w, w);
  const double g = ww + big * big - small * small;
  const double gabs = ww + big * big + small * small;
  const double zn = dot(n, w), dn = dot(n, d);
  const double dperp = sqr_length(cross(d, n)), wperp = sqr_length(cross(w, n));
  const double r2 = 4.0 * big * big;
  Quartic q{};
  q.c[4] = e * e;
  q.c[3] = 4.0 * e * f;
  q.c[2] = 4.0 * f * f + 2.0 * e * g - r2 * dperp;
  q.c[1] = 4.0 * f * g - 2.0 * r2 * (f - zn * dn);
  q.c[0] = g * g - r2 * wperp;
  // Absolute error bounds: a few ulps of the magnitudes of the terms (each is a short sum of
  // products of rounded dot products).
  const double af = std::fabs(f), azd = std::fabs(zn * dn);
  q.err[4] = 4.0 * eps * e * e;
  q.err[3] = 8.0 * eps * 4.0 * e * af;
  q.err[2] = 16.0 * eps * (4.0 * f * f + 2.0 * e * gabs + r2 * e);
  q.err[1] = 16.0 * eps * (4.0 * af * gabs + 2.0 * r2 * (af + azd));
  q.err[0] = 16.0 * eps * (gabs * gabs + r2 * ww);
  return q;
}

/// The torus function at X (scaled frame): (|X|^2 + R^2 - r^2)^2 - 4 R^2 |X x n|^2.
double value(const V& x, const V& n, double big, double small) noexcept {
  const double g = dot(x, x) + big * big - small * small;
  return g * g - 4.0 * big * big * sqr_length(cross(x, n));
}
V gradient(const V& x, const V& n, double big, double small) noexcept {
  const double g = dot(x, x) + big * big - small * small;
  return 4.0 * g * x - 8.0 * big * big * (x - dot(n, x) * n);
}

}  // namespace

R hits(const Lin& l, const TorusD& t) noexcept {
  R r;
  if (!linear3::finite(l.o) || !linear3::finite(l.d) || (l.hi && !linear3::finite(l.q)) ||
      !linear3::finite(t.c) || !linear3::finite(t.n) || t.n == V{} || !std::isfinite(t.big) ||
      !std::isfinite(t.small) || !(t.big >= 0.0) || !(t.small >= 0.0))
    return r;
  const V n = normalize(t.n);
  const double s = pow2_inv(t.big + t.small);
  const double big = s * t.big, small = s * t.small;
  const V w = s * (l.o - t.c);
  const bool zero = l.hi ? l.o == l.q : l.d == V{};
  const auto info = [&](const V& x) {
    const V xs = s * (x - t.c);
    const auto b = perpendicular_basis(n);
    const double h = dot(n, xs);
    const double rho = length(xs - h * n);
    const Vec2<double> uv{std::atan2(dot(b.v, xs), dot(b.u, xs)), std::atan2(h, rho - big)};
    return std::pair{uv, normalize(gradient(xs, n, big, small))};
  };
  const auto put = [&](double tt, int mult) {
    if (r.count >= 4) return;
    const auto k = static_cast<std::size_t>(r.count++);
    r.point[k] = tt == 0.0 ? l.o : (l.hi && tt == 1.0) ? l.q : l.o + tt * l.d;
    r.param_a[k] = tt;
    const auto [uv, nv] = info(r.point[k]);
    r.param_b[k] = uv;
    r.normal[k] = nv;
    r.multiplicity[k] = mult;
  };
  if (zero) {
    if (value(w, n, big, small) == 0.0) put(0.0, 1);
  } else {
    const double k = pow2_inv(length(s * l.d));
    const V d = (s * k) * l.d;  // t = k tau
    const Quartic q = torus_quartic(w, d, n, big, small);
    RootOptions opt = near_roots();
    opt.coefficient_error = std::span<const double>(q.err, 5);
    const RootsResult<double> rr = solve_quartic(q.c[0], q.c[1], q.c[2], q.c[3], q.c[4], opt);
    for (int i = 0; i < rr.count; ++i) {
      double tau = rr.roots[static_cast<std::size_t>(i)].value;
      const int mult = rr.roots[static_cast<std::size_t>(i)].multiplicity;
      if (mult == 1) {
        // Newton on the geometric value (more accurate than the expanded coefficients).
        for (int it = 0; it < 2; ++it) {
          const V x = w + tau * d;
          const double fd = dot(gradient(x, n, big, small), d);
          if (fd == 0.0) break;
          const double next = tau - value(x, n, big, small) / fd;
          if (!std::isfinite(next) ||
              std::fabs(value(w + next * d, n, big, small)) > std::fabs(value(x, n, big, small)))
            break;
          tau = next;
        }
      }
      const double tt = k * tau;
      if (l.lo && tt < 0.0) continue;
      if (l.hi && tt > 1.0) continue;
      put(tt, mult);
    }
  }
  r.kind = r.count == 0 ? Kind::empty : r.count == 1 ? Kind::point : Kind::points;
  return r;
}

}  // namespace locus::detail::quadric3
