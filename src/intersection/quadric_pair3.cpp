// SPDX-License-Identifier: BSL-1.0
// Sphere-sphere (exact decisions) and ellipsoid-ellipsoid (secular equation) pairs
// (include/locus/intersection/detail/quadric_pair3.hpp); row int3.surface-surface, book section
// 11.8. Derivation: docs/notes/surface_intersection.md, "Quadric pairs".

#include <locus/core/exact_poly.hpp>
#include <locus/intersection/detail/ball_relation.hpp>
#include <locus/intersection/detail/quadric_pair3.hpp>
#include <locus/numeric/eigen_sym.hpp>
#include <locus/primitives/plane.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace locus::detail::quadric_pair3 {
namespace {

using P = ExactPoly;

[[nodiscard]] bool finite(const V& v) noexcept {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
[[nodiscard]] bool valid_sphere(const V& c, double r) noexcept {
  return finite(c) && std::isfinite(r) && r >= 0.0;
}
[[nodiscard]] double pow2_inv(double m) noexcept {
  return m > 0.0 && std::isfinite(m) ? std::ldexp(1.0, -std::ilogb(m)) : 1.0;
}

struct Signs {
  int out;  // sign(|u|^2 - (r0 + r1)^2)
  int in;   // sign(|u|^2 - (r0 - r1)^2)
};
Signs sphere_signs(const V& c0, double r0, const V& c1, double r1) noexcept {
  const P dx = P::diff(c1.x, c0.x), dy = P::diff(c1.y, c0.y), dz = P::diff(c1.z, c0.z);
  const P d2 = dx * dx + dy * dy + dz * dz;
  const P a = P::var(r0), b = P::var(r1);
  const P sq = a * a + b * b, cross = (a * b).times_pow2(1);
  return {(d2 - sq - cross).sign(), (d2 - sq + cross).sign()};
}

}  // namespace

SphereSphereIntersection<double> sphere_sphere(const V& c0, double r0, const V& c1,
                                               double r1) noexcept {
  SphereSphereIntersection<double> r;
  if (!valid_sphere(c0, r0) || !valid_sphere(c1, r1)) return r;
  if (c0 == c1) {
    if (r0 != r1) return r;
    if (r0 > 0.0) {
      r.kind = Kind::coincident;
      return r;
    }
    r.kind = Kind::point;
    r.count = 1;
    r.point[0] = r.center = c0;
    return r;
  }
  const Signs s = sphere_signs(c0, r0, c1, r1);
  if (s.out > 0 || s.in < 0) return r;
  const double m = std::max({max_abs(c0), max_abs(c1), r0, r1});
  const double sc = pow2_inv(m);
  const V del = sc * (c1 - c0);
  const double dist = length(del);
  const V dir = del / dist;
  r.normal = dir;
  if (s.out == 0 || s.in == 0) {
    // Tangent: on the ray from c0 through c1 (outside, or inside with r0 > r1), else opposite.
    const bool toward = s.out == 0 || r0 > r1;
    V p = c0 + (toward ? r0 : -r0) * dir;
    if (r0 == 0.0) p = c0;
    if (r1 == 0.0) p = c1;
    r.kind = Kind::point;
    r.count = 1;
    r.point[0] = r.center = p;
    return r;
  }
  const double a0 = sc * r0, a1 = sc * r1;
  const double along = 0.5 * (dist + (a0 - a1) * (a0 + a1) / dist);
  const double h = std::sqrt(std::max((a0 - along) * (a0 + along), 0.0));
  r.center = c0 + (along / sc) * dir;
  r.radius = h / sc;
  const auto basis = perpendicular_basis(dir);
  r.kind = Kind::circle;
  r.count = 3;
  r.point[0] = r.center + r.radius * basis.u;
  r.point[1] = r.center + r.radius * basis.v;
  r.point[2] = r.center - r.radius * basis.u;
  return r;
}

RegionRelation sphere_relation(const V& c0, double r0, const V& c1, double r1) noexcept {
  if (!valid_sphere(c0, r0) || !valid_sphere(c1, r1)) return RegionRelation::undecided;
  if (c0 == c1 && r0 == r1) return RegionRelation::equal;
  const Signs s = sphere_signs(c0, r0, c1, r1);
  return ball_relation(s.out, s.in, r0 > r1);
}

namespace {

/// The extreme of q(y) = sum lambda_i y_i^2 - 2 g.y + k over |y| = 1: minimum (lowest = true,
/// multiplier mu <= lambda_0) or maximum (mu >= lambda_2). lambda ascending.
double sphere_extreme(const V& lambda, const V& g, double k, bool lowest) noexcept {
  const double gl = length(g);
  const int edge = lowest ? 0 : 2;
  const double le = lambda[edge];
  // phi(mu) = sum g_i^2 / (lambda_i - mu)^2 - 1: monotone on the branch, -1 at distance >= |g|.
  double near = le, far = lowest ? le - gl - 1.0 : le + gl + 1.0;
  const auto phi = [&](double mu) {
    double s = -1.0;
    for (int i = 0; i < 3; ++i) {
      const double den = lambda[i] - mu;
      if (den == 0.0) return g[i] == 0.0 ? s : INFINITY;
      s += g[i] * g[i] / (den * den);
    }
    return s;
  };
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (near + far);
    if (mid == near || mid == far) break;
    (phi(mid) > 0.0 ? near : far) = mid;
  }
  const double mu = far;  // phi(far) <= 0: |y| <= 1 there
  V y{};
  for (int i = 0; i < 3; ++i) {
    const double den = lambda[i] - mu;
    y[i] = den != 0.0 ? g[i] / den : 0.0;
  }
  // The hard case (g_edge = 0, mu = lambda_edge): complete y to unit length along the extreme
  // eigenvector; otherwise only the bisection's last bits are missing: rescale.
  const double yl = length(y);
  if (g[edge] == 0.0 && yl < 1.0) y[edge] = std::sqrt(std::max(0.0, 1.0 - yl * yl));
  const double yl2 = length(y);
  if (yl2 > 0.0) y = y / yl2;
  double q = k;
  for (int i = 0; i < 3; ++i) q += lambda[i] * y[i] * y[i] - 2.0 * g[i] * y[i];
  return q;
}

}  // namespace

RegionRelation ellipsoid_relation_numeric(const V& c0, const V (&a0)[3], const V& e0, const V& c1,
                                          const V (&a1)[3], const V& e1, double rel_tol) noexcept {
  for (const V* v : {&c0, &e0, &c1, &e1, &a0[0], &a0[1], &a0[2], &a1[0], &a1[1], &a1[2]})
    if (!finite(*v)) return RegionRelation::undecided;
  for (int i = 0; i < 3; ++i)
    if (!(e0[i] > 0.0) || !(e1[i] > 0.0) || a0[i] == V{} || a1[i] == V{})
      return RegionRelation::undecided;
  bool same = c0 == c1 && e0 == e1;
  for (int i = 0; i < 3; ++i) same = same && a0[i] == a1[i];
  if (same) return RegionRelation::equal;
  // Frame: scale by a power of two so the first ellipsoid has size O(1).
  const double sc = pow2_inv(std::max({e0.x, e0.y, e0.z}));
  // y -> x = c0 + sum_i a0_i e0_i y_i; b: sum_j (a1_j . (x - c1) / e1_j)^2 - 1.
  // Row j of the map y -> a1_j . (x - c1) / e1_j is  (a1_j . a0_i) e0_i / e1_j  (i = 0..2),
  // with offset a1_j . (c0 - c1) / e1_j (everything scaled by sc cancels in the ratios).
  double row[3][3];
  double off[3];
  for (int j = 0; j < 3; ++j) {
    const V aj = normalize(a1[j]);
    for (int i = 0; i < 3; ++i) row[j][i] = dot(aj, normalize(a0[i])) * (sc * e0[i]) / (sc * e1[j]);
    off[j] = dot(aj, sc * (c0 - c1)) / (sc * e1[j]);
  }
  // Q(y) = |R y + o|^2 - 1 = y^T (R^T R) y + 2 (R^T o).y + |o|^2 - 1.
  Mat3<double> h{};
  V g{};
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) {
      double s = 0.0;
      for (int j = 0; j < 3; ++j) s += row[j][i] * row[j][k];
      h(i, k) = s;
    }
    double s = 0.0;
    for (int j = 0; j < 3; ++j) s += row[j][i] * off[j];
    g[i] = -s;  // Q = y^T H y - 2 g.y + k
  }
  const double k = off[0] * off[0] + off[1] * off[1] + off[2] * off[2] - 1.0;
  const SymmetricEigen<double, 3> eig = eigen_symmetric(h);
  if (eig.status != Status::ok) return RegionRelation::undecided;
  V ge{};
  for (int i = 0; i < 3; ++i) {
    double s = 0.0;
    for (int r = 0; r < 3; ++r) s += eig.vectors(r, i) * g[r];
    ge[i] = s;
  }
  const double qmin = sphere_extreme(eig.values, ge, k, true);
  const double qmax = sphere_extreme(eig.values, ge, k, false);
  const double tau = rel_tol * (std::fabs(eig.values[2]) + 2.0 * length(ge) + std::fabs(k) + 1.0);
  const int smin = qmin > tau ? 1 : qmin < -tau ? -1 : 0;
  const int smax = qmax > tau ? 1 : qmax < -tau ? -1 : 0;
  if (smin == 0 && smax == 0) return RegionRelation::equal;
  if (smin < 0 && smax > 0) return RegionRelation::overlapping;
  if (smax < 0) return RegionRelation::b_contains_a;
  if (smax == 0) return RegionRelation::b_contains_a_touching;
  // min >= 0: is b's center inside a? Center of b in y: H^-1 g (Q's minimiser).
  const Vec3<double> ginv{ge[0] / eig.values[0], ge[1] / eig.values[1], ge[2] / eig.values[2]};
  const bool center_inside = sqr_length(ginv) < 1.0;
  if (smin > 0) return center_inside ? RegionRelation::a_contains_b : RegionRelation::separated;
  return center_inside ? RegionRelation::a_contains_b_touching : RegionRelation::touching;
}

}  // namespace locus::detail::quadric_pair3
