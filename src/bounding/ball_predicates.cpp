// SPDX-License-Identifier: BSL-1.0
// Exact fallbacks of the side-of-ball tests (include/locus/bounding/detail/ball_predicates.hpp).
//
// Every finite double is an integer times 2^e with e >= -1074 (core's low_exponent); shifting
// all inputs of one test by their smallest exponent makes them integers, and the test polynomial
// is then evaluated exactly on core's fixed-capacity big integer (src/core/big_int.hpp). The
// capacity covers degree 6 in values spanning the whole double range: inputs below 2^2150,
// differences below 2^2151, a degree-6 product of them plus its carries below 2^12920, and one
// product's operands below 405 limbs. These paths run only when the floating-point filter
// cannot decide, so they favour simplicity over speed.

#include <locus/bounding/detail/ball_predicates.hpp>

#include "../core/big_int.hpp"

#include <cmath>

namespace locus::detail {
namespace {

using Big = BigInt<420>;  // 13440 bits

int common_exponent(const double* v, int n) noexcept {
  int emin = 0;
  bool any = false;
  for (int i = 0; i < n; ++i) {
    if (v[i] == 0.0) continue;
    const int e = low_exponent(v[i]);
    if (!any || e < emin) emin = e;
    any = true;
  }
  return emin;
}

bool all_finite(const double* v, int n) noexcept {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

Sign sign_of(const Big& a) noexcept {
  const int s = a.sign();
  return s == 0 ? Sign::zero : (s < 0 ? Sign::negative : Sign::positive);
}

}  // namespace

Sign diametral_side_exact(const double* p, const double* a, const double* b, int n) noexcept {
  double all[9];
  for (int i = 0; i < n; ++i) {
    all[i] = p[i];
    all[n + i] = a[i];
    all[2 * n + i] = b[i];
  }
  if (!all_finite(all, 3 * n)) return Sign::zero;
  const int shift = -common_exponent(all, 3 * n);
  Big sum;
  for (int i = 0; i < n; ++i) {
    const Big pi = Big::from_double(p[i], shift);
    sum += (pi - Big::from_double(a[i], shift)) * (pi - Big::from_double(b[i], shift));
  }
  return sign_of(sum);
}

Sign dot_differences_exact(const double* a, const double* b, const double* c, const double* d,
                           int n) noexcept {
  double all[12];
  for (int i = 0; i < n; ++i) {
    all[i] = a[i];
    all[n + i] = b[i];
    all[2 * n + i] = c[i];
    all[3 * n + i] = d[i];
  }
  if (!all_finite(all, 4 * n)) return Sign::zero;
  const int shift = -common_exponent(all, 4 * n);
  Big sum;
  for (int i = 0; i < n; ++i)
    sum += (Big::from_double(b[i], shift) - Big::from_double(a[i], shift)) *
           (Big::from_double(d[i], shift) - Big::from_double(c[i], shift));
  return sign_of(sum);
}

Sign circumcircle_sphere_side_exact(const double* a, const double* b, const double* c,
                                    const double* p) noexcept {
  double all[12];
  for (int i = 0; i < 3; ++i) {
    all[i] = a[i];
    all[3 + i] = b[i];
    all[6 + i] = c[i];
    all[9 + i] = p[i];
  }
  if (!all_finite(all, 12)) return Sign::zero;
  const int shift = -common_exponent(all, 12);
  using V = Big[3];
  V u, v, q;
  for (int i = 0; i < 3; ++i) {
    const Big ai = Big::from_double(a[i], shift);
    u[i] = Big::from_double(b[i], shift) - ai;
    v[i] = Big::from_double(c[i], shift) - ai;
    q[i] = Big::from_double(p[i], shift) - ai;
  }
  const auto cross = [](const V& x, const V& y, V& out) noexcept {
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      out[i] = x[j] * y[k] - x[k] * y[j];
    }
  };
  const auto dot = [](const V& x, const V& y) noexcept {
    return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
  };
  V w, vxw, wxu, x;
  cross(u, v, w);
  cross(v, w, vxw);
  cross(w, u, wxu);
  const Big uu = dot(u, u), vv = dot(v, v);
  for (int i = 0; i < 3; ++i) x[i] = uu * vxw[i] + vv * wxu[i];  // X
  return sign_of(dot(w, w) * dot(q, q) - dot(q, x));             // |w|^2 |q|^2 - q . X
}

}  // namespace locus::detail
