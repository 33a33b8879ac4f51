// SPDX-License-Identifier: BSL-1.0
// Plane sections of the sphere, the infinite cylinder and the infinite double cone
// (include/locus/intersection/detail/plane_quadric3.hpp); row int3.plane-quadric, book section
// 11.5 (figures 11.32-11.52). Derivation: docs/notes/intersection3.md, "Plane sections".

#include <locus/core/exact_poly.hpp>
#include <locus/intersection/detail/plane_quadric3.hpp>

#include <algorithm>
#include <cmath>

namespace locus::detail::plane_quadric3 {
namespace {

using P = ExactPoly;

bool finite(const V& v) noexcept {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// N.X - k exactly (its sign: the side of X).
P plane_value(const V& n, double k, const V& x) noexcept {
  return P::var(n.x) * P::var(x.x) + P::var(n.y) * P::var(x.y) + P::var(n.z) * P::var(x.z) -
         P::var(k);
}
P dotp(const V& a, const V& b) noexcept {
  return P::var(a.x) * P::var(b.x) + P::var(a.y) * P::var(b.y) + P::var(a.z) * P::var(b.z);
}
/// sign((N.X - k)^2 - r^2 |N|^2): + the plane misses the ball of radius r about X.
int distance_sign(const V& n, double k, const V& x, double r) noexcept {
  const P s = plane_value(n, k, x);
  return (s * s - P::var(r) * P::var(r) * dotp(n, n)).sign();
}
/// Whether a x b == 0 exactly.
bool parallel(const V& a, const V& b) noexcept {
  const auto comp = [&](int i) {
    const int j = (i + 1) % 3, l = (i + 2) % 3;
    return (P::var(a[j]) * P::var(b[l]) - P::var(a[l]) * P::var(b[j])).sign();
  };
  return comp(0) == 0 && comp(1) == 0 && comp(2) == 0;
}

/// The plane frame at the foot O of the reference point p: unit normal n, signed distance delta
/// of p (p = O + delta n), u the unit projection of the axis a (any in-plane unit vector when a
/// is along n), v = n x u; an = a.n, au = a.u >= 0.
struct Frame {
  V n, o, u, v;
  double delta, an, au;
};
Frame frame(const V& normal, double k, const V& p, const V& a) noexcept {
  Frame f{};
  const double len = length(normal);
  f.n = normal / len;
  f.delta = (dot(normal, p) - k) / len;
  f.o = p - f.delta * f.n;
  const V ua = a == V{} ? V{} : normalize(a);
  f.an = dot(ua, f.n);
  const V proj = ua - f.an * f.n;
  if (proj == V{} || a == V{} || parallel(a, normal)) {
    f.u = perpendicular_basis(f.n).u;
    f.au = 0.0;
  } else {
    f.u = normalize(proj);
    f.au = dot(ua, f.u);
  }
  f.v = cross(f.n, f.u);
  return f;
}

/// The conic A x^2 + C y^2 + 2 D x + F = 0 in the frame (C > 0), of the given type.
C central(const Frame& f, ConicType type, double a, double c, double d, double fz) noexcept {
  C r;
  r.type = type;
  r.normal = f.n;
  const double x0 = a != 0.0 ? -d / a : 0.0;
  const double f0 = fz - (a != 0.0 ? d * d / a : 0.0);
  r.center = f.o + x0 * f.u;
  if (type == ConicType::circle) {
    const double rad = std::sqrt(std::max(-f0 / c, 0.0));
    r.axis[0] = f.u;
    r.axis[1] = f.v;
    r.extent[0] = r.extent[1] = rad;
    r.focus[0] = r.focus[1] = r.center;
    return r;
  }
  const double ex = -f0 / a, ey = -f0 / c;  // x^2 / ex + y^2 / ey = 1
  if (type == ConicType::ellipse) {
    const double sx = std::sqrt(std::max(ex, 0.0)), sy = std::sqrt(std::max(ey, 0.0));
    const bool xmajor = sx >= sy;
    r.axis[0] = xmajor ? f.u : f.v;
    r.axis[1] = xmajor ? f.v : -f.u;
    r.extent[0] = std::max(sx, sy);
    r.extent[1] = std::min(sx, sy);
    const double fc =
        std::sqrt(std::max((r.extent[0] - r.extent[1]) * (r.extent[0] + r.extent[1]), 0.0));
    r.focus[0] = r.center + fc * r.axis[0];
    r.focus[1] = r.center - fc * r.axis[0];
    return r;
  }
  // Hyperbola: the positive one of ex, ey is the transverse axis.
  const bool xtrans = ex > 0.0;
  r.axis[0] = xtrans ? f.u : f.v;
  r.axis[1] = xtrans ? f.v : -f.u;
  r.extent[0] = std::sqrt(std::fabs(xtrans ? ex : ey));
  r.extent[1] = std::sqrt(std::fabs(xtrans ? ey : ex));
  const double fc = std::hypot(r.extent[0], r.extent[1]);
  r.focus[0] = r.center + fc * r.axis[0];
  r.focus[1] = r.center - fc * r.axis[0];
  return r;
}

}  // namespace

C section(const V& normal, double k, const V& center, double radius) noexcept {
  C r;
  if (!finite(normal) || !std::isfinite(k) || normal == V{} || !finite(center) ||
      !std::isfinite(radius) || !(radius >= 0.0))
    return r;
  const int s = distance_sign(normal, k, center, radius);
  if (s > 0) return r;
  const Frame f = frame(normal, k, center, V{});
  r.normal = f.n;
  r.center = f.o;
  r.axis[0] = f.u;
  r.axis[1] = f.v;
  r.focus[0] = r.focus[1] = f.o;
  if (s == 0) {
    r.type = ConicType::point;
    return r;
  }
  r.type = ConicType::circle;
  const double d = std::fabs(f.delta);
  r.extent[0] = r.extent[1] = std::sqrt(std::max((radius - d) * (radius + d), 0.0));
  return r;
}

C section(const V& normal, double k, const V& center, const V& axis, double radius) noexcept {
  C r;
  if (!finite(normal) || !std::isfinite(k) || normal == V{} || !finite(center) || !finite(axis) ||
      axis == V{} || !std::isfinite(radius) || !(radius >= 0.0))
    return r;
  const Frame f = frame(normal, k, center, axis);
  if (dotp(normal, axis).sign() == 0) {
    // The plane is parallel to the axis: the distance of the axis decides, exactly.
    const int s = distance_sign(normal, k, center, radius);
    if (s > 0) return r;
    r.normal = f.n;
    r.axis[0] = r.axis[1] = f.u;
    const double d = std::fabs(f.delta);
    const double h = std::sqrt(std::max((radius - d) * (radius + d), 0.0));
    r.type = s == 0 ? ConicType::line : ConicType::parallel_lines;
    r.center = s == 0 ? f.o : f.o + h * f.v;
    r.other = s == 0 ? f.o : f.o - h * f.v;
    return r;
  }
  // |w|^2 - (a.w)^2 - r^2 in the frame: an^2 x^2 + y^2 + 2 delta an au x + delta^2 au^2 - r^2.
  const ConicType t = parallel(axis, normal) ? ConicType::circle : ConicType::ellipse;
  return central(f, t, f.an * f.an, 1.0, f.delta * f.an * f.au,
                 f.delta * f.delta * f.au * f.au - radius * radius);
}

C section(const V& normal, double k, const V& vertex, const V& axis, double angle, bool) noexcept {
  C r;
  if (!finite(normal) || !std::isfinite(k) || normal == V{} || !finite(vertex) || !finite(axis) ||
      axis == V{} || !(angle > 0.0) || !(angle < 1.5707963267948966))
    return r;
  // Type: sign((a.N)^2 - sin^2(alpha) |a|^2 |N|^2) (sin rounded once), exact in it.
  const double sn = std::sin(angle), cs = std::cos(angle);
  const P an = dotp(axis, normal);
  const int ts =
      (an * an - P::var(sn) * P::var(sn) * dotp(axis, axis) * dotp(normal, normal)).sign();
  const int side = plane_value(normal, k, vertex).sign();
  const Frame f = frame(normal, k, vertex, axis);
  r.normal = f.n;
  const double c2 = cs * cs;
  // cos^2 |w|^2 - (a.w)^2 in the frame: (c2 - au^2) x^2 + c2 y^2 + 2 delta an au x +
  // delta^2 (c2 - an^2).
  const double a = c2 - f.au * f.au, d = f.delta * f.an * f.au;
  const double fz = f.delta * f.delta * (c2 - f.an * f.an);
  if (side == 0) {
    r.center = vertex;
    if (ts > 0) {
      r.type = ConicType::point;
      r.focus[0] = r.focus[1] = vertex;
      return r;
    }
    if (ts == 0) {
      r.type = ConicType::line;
      r.axis[0] = r.axis[1] = f.u;
      return r;
    }
    // c2 y^2 = -a x^2: slopes +- sqrt(-a / c2).
    const double m = std::sqrt(std::max(-a / c2, 0.0));
    r.type = ConicType::crossing_lines;
    r.axis[0] = normalize(f.u + m * f.v);
    r.axis[1] = normalize(f.u - m * f.v);
    return r;
  }
  if (ts > 0)
    return central(f, parallel(axis, normal) ? ConicType::circle : ConicType::ellipse,
                   std::max(a, 0x1p-1022), c2, d, fz);
  if (ts < 0) return central(f, ConicType::hyperbola, std::min(a, -0x1p-1022), c2, d, fz);
  // Parabola: c2 y^2 + 2 d x + fz = 0 (a = 0): vertex x = -fz / (2 d), opening towards -sign(d).
  r.type = ConicType::parabola;
  const double xv = -fz / (2.0 * d);
  r.center = f.o + xv * f.u;
  r.axis[0] = d > 0.0 ? -f.u : f.u;
  r.axis[1] = cross(f.n, r.axis[0]);
  r.extent[0] = std::fabs(d) / (2.0 * c2);
  r.focus[0] = r.focus[1] = r.center + r.extent[0] * r.axis[0];
  return r;
}

}  // namespace locus::detail::plane_quadric3
