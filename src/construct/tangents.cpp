// SPDX-License-Identifier: BSL-1.0
// Lines tangent to circles (include/locus/construct/tangent_lines.hpp): counts from exact signs
// of squared distances against squared radii (exact.hpp), lines computed in double.
#include <locus/construct/tangent_lines.hpp>

#include "exact.hpp"

#include <cmath>

namespace locus {

namespace {
using namespace detail::construct;
using V = Vec2<double>;

template <Real T>
Status circle_status(const Circle2<T>& c) noexcept {
  if (!is_finite(c.center) || !is_finite(c.radius)) return Status::non_finite_input;
  return c.radius > T(0) ? Status::ok : Status::degenerate_input;
}

template <Real T>
Line2<T> line_from(const V& origin, const V& unit_dir) noexcept {
  return {from_d<T>(origin), from_d<T>(unit_dir)};
}
}  // namespace

template <Real T>
Solutions<Line2<T>, 1> tangent_line_at(const Circle2<T>& c, const Vec2<T>& p) noexcept {
  Solutions<Line2<T>, 1> s;
  s.status = circle_status(c);
  if (s.status == Status::ok && !is_finite(p)) s.status = Status::non_finite_input;
  if (s.status != Status::ok || p == c.center) return s;
  const V cc = to_d(c.center), u = normalize(to_d(p) - cc);
  s.push(line_from<T>(cc + double(c.radius) * u, perp(u)));
  return s;
}

template <Real T>
Solutions<Line2<T>, 2> tangent_lines(const Vec2<T>& p, const Circle2<T>& c) noexcept {
  Solutions<Line2<T>, 2> s;
  s.status = circle_status(c);
  if (s.status == Status::ok && !is_finite(p)) s.status = Status::non_finite_input;
  if (s.status != Status::ok) return s;
  const V pd = to_d(p), cc = to_d(c.center);
  const double r = double(c.radius);
  const int side = (sqr_dist(pd, cc) - sqr(var(r))).sign();
  if (side < 0) return s;
  const Normalized<double, 2> nv = normalize_with_length(pd - cc);
  const V w = nv.dir;
  if (side == 0) {
    s.push(line_from<T>(pd, perp(w)));
    return s;
  }
  // Tangent points c + a w -+ b perp(w), a = r^2 / L, b = r sqrt(L^2 - r^2) / L.
  const double L = nv.length;
  const double a = r * (r / L);
  const double b = r * std::sqrt(std::max(0.0, (L - r) * (L + r))) / L;
  for (double sg : {-1.0, 1.0}) {
    const V t = cc + a * w + (sg * b) * perp(w);
    s.push(line_from<T>(t, normalize(pd - t)));
  }
  return s;
}

template <Real T>
Solutions<Line2<T>, 4> tangent_lines(const Circle2<T>& c0, const Circle2<T>& c1) noexcept {
  Solutions<Line2<T>, 4> s;
  s.status = circle_status(c0);
  if (s.status == Status::ok) s.status = circle_status(c1);
  if (s.status != Status::ok) return s;
  const V a = to_d(c0.center), b = to_d(c1.center);
  const double r0 = double(c0.radius), r1 = double(c1.radius);
  const P e = sqr_dist(a, b);
  if (e.sign() == 0) {  // concentric
    s.infinite = r0 == r1;
    return s;
  }
  const int outer = (e - sqr(var(r1) - var(r0))).sign();
  const int inner = (e - sqr(var(r0) + var(r1))).sign();
  const Normalized<double, 2> nd = normalize_with_length(b - a);
  const double L = nd.length;
  const V w = nd.dir;
  // Unit normals n with n . (c1 - c0) = delta: n = (delta / L) w + -(sqrt(L^2 - delta^2) / L)
  // perp(w); the line touches c0 at c0 - r0 n and c1 at c1 - s r1 n (s = +1 outer, -1 inner).
  const auto emit = [&](int sign, double delta) {
    if (sign < 0) return;
    const double al = delta / L;
    const double be = sign == 0 ? 0.0 : std::sqrt(std::max(0.0, (L - delta) * (L + delta))) / L;
    for (double sg : {1.0, -1.0}) {
      const V n = al * w + (sg * be) * perp(w);
      s.push(line_from<T>(a - r0 * n, perp(n)));
      if (sign == 0) break;
    }
  };
  emit(outer, r1 - r0);
  emit(inner, -(r0 + r1));
  return s;
}

#define LOCUS_INSTANTIATE(T)                                                                      \
  template Solutions<Line2<T>, 1> tangent_line_at<T>(const Circle2<T>&, const Vec2<T>&) noexcept; \
  template Solutions<Line2<T>, 2> tangent_lines<T>(const Vec2<T>&, const Circle2<T>&) noexcept;   \
  template Solutions<Line2<T>, 4> tangent_lines<T>(const Circle2<T>&, const Circle2<T>&) noexcept;
LOCUS_INSTANTIATE(float)
LOCUS_INSTANTIATE(double)
#undef LOCUS_INSTANTIATE

}  // namespace locus
