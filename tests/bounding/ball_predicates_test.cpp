// SPDX-License-Identifier: BSL-1.0
// The exact fallbacks of bounding/detail/ball_predicates.hpp at the ends of the double range,
// where their big integers are widest: coordinates mixing DBL_MAX-sized, ordinary, tiny and
// subnormal magnitudes in one test (degree 2 and degree 6 polynomials), against GMP rationals.

#include <locus/bounding/detail/ball_predicates.hpp>

#include <gmpxx.h>

#include <cmath>
#include <limits>

#include "support/typed.hpp"

namespace {

using locus::Sign;
using locus_test::Rng;

Sign sign_of(const mpq_class& x) {
  return x > 0 ? Sign::positive : (x < 0 ? Sign::negative : Sign::zero);
}

// A coordinate from one of the magnitude classes, so that most tests span the whole range.
double extreme(Rng& rng) {
  const double m = rng.uniform<double>(0.5, 1.0);
  double v = 0.0;
  switch (rng.uniform_int(0, 5)) {
    case 0:
      v = std::numeric_limits<double>::max() * m;
      break;
    case 1:
      v = std::ldexp(m, rng.uniform_int(900, 1023));
      break;
    case 2:
      v = std::ldexp(m, rng.uniform_int(-40, 40));
      break;
    case 3:
      v = std::numeric_limits<double>::denorm_min() * rng.uniform_int(1, 1 << 20);
      break;
    case 4:
      v = std::ldexp(m, rng.uniform_int(-1074, -900));
      break;
    default:
      v = 0.0;
  }
  return rng.uniform_int(0, 1) == 0 ? v : -v;
}

TEST(BallPredicatesExact, WholeDoubleRangeVsGmp) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 400; ++trial) {
    double a[3], b[3], c[3], p[3];
    mpq_class qa[3], qb[3], qc[3], qp[3];
    for (int i = 0; i < 3; ++i) {
      a[i] = extreme(rng);
      b[i] = extreme(rng);
      c[i] = extreme(rng);
      p[i] = trial % 4 == 0 ? a[i] : extreme(rng);  // p on both balls' boundaries
      qa[i] = a[i];
      qb[i] = b[i];
      qc[i] = c[i];
      qp[i] = p[i];
    }
    for (int n : {2, 3}) {
      mpq_class diam = 0, dots = 0;
      for (int i = 0; i < n; ++i) {
        diam += (qp[i] - qa[i]) * (qp[i] - qb[i]);
        dots += (qb[i] - qa[i]) * (qp[i] - qc[i]);
      }
      ASSERT_EQ(locus::detail::diametral_side_exact(p, a, b, n), sign_of(diam)) << trial;
      ASSERT_EQ(locus::detail::dot_differences_exact(a, b, c, p, n), sign_of(dots)) << trial;
    }
    // |w|^2 |q|^2 - q . X with u = b - a, v = c - a, q = p - a, w = u x v,
    // X = |u|^2 (v x w) + |v|^2 (w x u) (the header's degree-6 polynomial).
    mpq_class u[3], v[3], q[3], w[3], vw[3], wu[3];
    for (int i = 0; i < 3; ++i) {
      u[i] = qb[i] - qa[i];
      v[i] = qc[i] - qa[i];
      q[i] = qp[i] - qa[i];
    }
    auto cross = [](const mpq_class* x, const mpq_class* y, mpq_class* out) {
      for (int i = 0; i < 3; ++i)
        out[i] = x[(i + 1) % 3] * y[(i + 2) % 3] - x[(i + 2) % 3] * y[(i + 1) % 3];
    };
    auto dot = [](const mpq_class* x, const mpq_class* y) -> mpq_class {
      return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
    };
    cross(u, v, w);
    cross(v, w, vw);
    cross(w, u, wu);
    const mpq_class uu = dot(u, u), vv = dot(v, v);
    mpq_class qx = 0;
    for (int i = 0; i < 3; ++i) qx += q[i] * (uu * vw[i] + vv * wu[i]);
    const mpq_class value = dot(w, w) * dot(q, q) - qx;
    ASSERT_EQ(locus::detail::circumcircle_sphere_side_exact(a, b, c, p), sign_of(value)) << trial;
  }
}

}  // namespace
