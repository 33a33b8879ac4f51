// SPDX-License-Identifier: BSL-1.0
// Exact side of a ball for the crossing of a line with a plane
// (include/locus/core/plane_crossing_ball.hpp): a floating-point filter, then the exact sum of
// monomials on core's engine (exact_sign_of_terms, core/exact_poly.hpp).

#include <locus/core/exact_poly.hpp>
#include <locus/core/plane_crossing_ball.hpp>

#include <array>
#include <cmath>
#include <cstddef>

namespace locus {
namespace {

using V = Vec3<double>;

// Every nonzero value within [2^-120, 2^120]: then no product of up to six of them under- or
// overflows, and an underflow after a cancellation costs far less than 2^-600 (see filter()).
bool in_filter_range(const V& v) noexcept {
  for (int k = 0; k < 3; ++k) {
    const double x = std::abs(v[k]);
    if (x != 0.0 && !(x >= 0x1p-120 && x <= 0x1p120)) return false;
  }
  return true;
}
bool in_filter_range(double x) noexcept { return in_filter_range(V{x, 0.0, 0.0}); }

// The sign of |w|^2 - r^2 den^2 evaluated in doubles, or 2 when the error bound cannot decide.
// The inputs of the polynomial (the differences a, b, p - q and the raw n, d, r) carry at most
// one rounding each; the evaluation has depth at most 10, so its error is below
// gamma_10 * magnitude (the same expression with absolute values everywhere) < 2^-48 magnitude
// (with room for the rounding of magnitude itself). Inputs in range bound every product by 2^730
// and put each underflow (after a cancellation) far below the absolute 2^-600 added.
int filter(const V& w, const V& wabs, double den, double denabs, double r) noexcept {
  const double rr = r * r;
  const double value = dot(w, w) - rr * (den * den);
  const double magnitude = dot(wabs, wabs) + rr * (denabs * denabs);
  const double bound = 0x1p-48 * magnitude + 0x1p-600;
  if (value > bound) return 1;
  if (-value > bound) return -1;
  return 2;
}

constexpr int other1(int k) noexcept { return k == 0 ? 1 : 0; }
constexpr int other2(int k) noexcept { return k == 2 ? 1 : 2; }

bool finite(const V& v) noexcept {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

int crossing_in_ball_line(const V& p, const V& d, const V& c, const V& n, double r) noexcept {
  if (!finite(p) || !finite(d) || !finite(c) || !finite(n) || !std::isfinite(r)) return 0;
  const V a = p - c;
  if (in_filter_range(a) && in_filter_range(d) && in_filter_range(n) && in_filter_range(r)) {
    V w, wabs;
    for (int k = 0; k < 3; ++k) {
      w[k] = 0.0;
      wabs[k] = 0.0;
      for (const int i : {other1(k), other2(k)}) {
        w[k] += n[i] * (a[k] * d[i] - a[i] * d[k]);
        wabs[k] += std::abs(n[i]) * (std::abs(a[k] * d[i]) + std::abs(a[i] * d[k]));
      }
    }
    const double den = dot(n, d);
    const double denabs = std::abs(n.x * d.x) + std::abs(n.y * d.y) + std::abs(n.z * d.z);
    const int s = filter(w, wabs, den, denabs, r);
    if (s != 2) return s;
  }
  // X - c = W / (n.d) with W_k = sum over i != k of n_i (a_k d_i - a_i d_k): 8 monomials of
  // degree 3 each; |W|^2 has 192 and r^2 (n.d)^2 nine, within ExactPoly's capacity.
  ExactPoly sum;
  ExactPoly den;
  for (int k = 0; k < 3; ++k) {
    ExactPoly w;
    for (const int i : {other1(k), other2(k)}) {
      const ExactPoly minor = ExactPoly::diff(p[k], c[k]) * ExactPoly::var(d[i]) -
                              ExactPoly::diff(p[i], c[i]) * ExactPoly::var(d[k]);
      w += ExactPoly::var(n[i]) * minor;
    }
    sum += w * w;
    den += ExactPoly::var(n[k]) * ExactPoly::var(d[k]);
  }
  const ExactPoly rr = ExactPoly::var(r) * ExactPoly::var(r);
  sum -= rr * (den * den);
  LOCUS_ASSERT(sum.valid(), "crossing_in_ball_line: term count");
  return sum.sign();
}

int crossing_in_ball_segment(const V& p, const V& q, const V& c, const V& n, double r) noexcept {
  if (!finite(p) || !finite(q) || !finite(c) || !finite(n) || !std::isfinite(r)) return 0;
  const V a = p - c, b = q - c, e = p - q;
  if (in_filter_range(a) && in_filter_range(b) && in_filter_range(e) && in_filter_range(n) &&
      in_filter_range(r)) {
    V w, wabs;
    for (int k = 0; k < 3; ++k) {
      w[k] = 0.0;
      wabs[k] = 0.0;
      for (const int i : {other1(k), other2(k)}) {
        w[k] += n[i] * (a[i] * b[k] - b[i] * a[k]);
        wabs[k] += std::abs(n[i]) * (std::abs(a[i] * b[k]) + std::abs(b[i] * a[k]));
      }
    }
    const double den = dot(n, e);
    const double denabs = std::abs(n.x * e.x) + std::abs(n.y * e.y) + std::abs(n.z * e.z);
    const int s = filter(w, wabs, den, denabs, r);
    if (s != 2) return s;
  }
  // W = f0 b - f1 a, W_k = sum over i != k of n_i M_ik with the minor
  // M_ik = a_i b_k - b_i a_k = p_i q_k - q_i p_k + c_i (p_k - q_k) - c_k (p_i - q_i) (six
  // monomials, never a rounded difference); |W|^2 has 3 * 144 monomials and r^2 (n.(p - q))^2
  // 36: more than one ExactPoly holds, so the squares are gathered into one array.
  constexpr std::size_t max_terms = 3 * 144 + 36;
  std::array<ExactTerm, max_terms> terms;
  std::size_t count = 0;
  bool ok = true;
  const auto append = [&](const ExactPoly& poly) {
    ok = ok && poly.valid() && count + static_cast<std::size_t>(poly.size()) <= max_terms;
    if (!ok) return;
    for (const ExactTerm& t : poly.terms()) terms[count++] = t;
  };
  const auto var = [](double x) { return ExactPoly::var(x); };
  ExactPoly den;
  for (int k = 0; k < 3; ++k) {
    ExactPoly w;
    for (const int i : {other1(k), other2(k)}) {
      const ExactPoly minor = var(p[i]) * var(q[k]) - var(q[i]) * var(p[k]) +
                              var(c[i]) * ExactPoly::diff(p[k], q[k]) -
                              var(c[k]) * ExactPoly::diff(p[i], q[i]);
      w += var(n[i]) * minor;
    }
    append(w * w);
    den += var(n[k]) * ExactPoly::diff(p[k], q[k]);
  }
  append(-(var(r) * var(r) * (den * den)));
  LOCUS_ASSERT(ok, "crossing_in_ball_segment: term count");
  if (!ok) return 0;
  return exact_sign_of_terms({terms.data(), count});
}

int point_in_ball(const V& x, const V& c, double r) noexcept {
  ExactPoly sum = -(ExactPoly::var(r) * ExactPoly::var(r));
  for (int k = 0; k < 3; ++k) {
    const ExactPoly a = ExactPoly::diff(x[k], c[k]);
    sum += a * a;
  }
  LOCUS_ASSERT(sum.valid(), "point_in_ball: term count");
  return sum.sign();
}

int line_near_ball(const V& p, const V& d, const V& c, double r) noexcept {
  // (a x d)_k = a_i d_j - a_j d_i with a = p - c: four monomials; 48 + 3 in all.
  ExactPoly sum;
  ExactPoly dd;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const ExactPoly w = ExactPoly::diff(p[i], c[i]) * ExactPoly::var(d[j]) -
                        ExactPoly::diff(p[j], c[j]) * ExactPoly::var(d[i]);
    sum += w * w;
    dd += ExactPoly::var(d[k]) * ExactPoly::var(d[k]);
  }
  sum -= ExactPoly::var(r) * ExactPoly::var(r) * dd;
  LOCUS_ASSERT(sum.valid(), "line_near_ball: term count");
  return sum.sign();
}

int segment_line_near_ball(const V& p, const V& q, const V& c, double r) noexcept {
  // (a x b)_k with a = p - c, b = q - c: p_i q_j - p_j q_i + c_i (p_j - q_j) - c_j (p_i - q_i),
  // six monomials; 108 + 12 in all.
  const auto var = [](double x) { return ExactPoly::var(x); };
  ExactPoly sum;
  ExactPoly len2;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const ExactPoly w = var(p[i]) * var(q[j]) - var(p[j]) * var(q[i]) +
                        var(c[i]) * ExactPoly::diff(p[j], q[j]) -
                        var(c[j]) * ExactPoly::diff(p[i], q[i]);
    sum += w * w;
    const ExactPoly e = ExactPoly::diff(q[k], p[k]);
    len2 += e * e;
  }
  sum -= var(r) * var(r) * len2;
  LOCUS_ASSERT(sum.valid(), "segment_line_near_ball: term count");
  return sum.sign();
}

int dot_of_differences(const V& x, const V& y, const V& v) noexcept {
  ExactPoly sum;
  for (int k = 0; k < 3; ++k) sum += ExactPoly::diff(x[k], y[k]) * ExactPoly::var(v[k]);
  return sum.sign();
}

int dot_of_differences(const V& x, const V& y, const V& z, const V& w) noexcept {
  ExactPoly sum;
  for (int k = 0; k < 3; ++k) sum += ExactPoly::diff(x[k], y[k]) * ExactPoly::diff(z[k], w[k]);
  return sum.sign();
}

}  // namespace locus
