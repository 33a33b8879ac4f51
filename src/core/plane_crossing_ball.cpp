// SPDX-License-Identifier: BSL-1.0
// Exact side of a ball for the crossing of a line with a plane
// (include/locus/core/plane_crossing_ball.hpp): a floating-point filter, then the exact sum of
// monomials on core's engine (exact_sign_of_terms, core/exact_poly.hpp). Stack: under 40 kB.

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

// A short list of monomials and products of two lists, gathered for exact_sign_of_terms: the
// bookkeeping of ExactPoly's product without its 26 kB temporaries (nested expressions of
// ExactPoly here kept about half a megabyte of stack).
template <std::size_t N>
struct Terms {
  std::array<ExactTerm, N> t;
  std::size_t n = 0;
  /// sign * a * b, term by term.
  template <std::size_t A, std::size_t B>
  void add_product(int sign, const Terms<A>& a, const Terms<B>& b) noexcept {
    for (std::size_t i = 0; i < a.n; ++i)
      for (std::size_t j = 0; j < b.n; ++j) {
        const ExactTerm& x = a.t[i];
        const ExactTerm& y = b.t[j];
        LOCUS_ASSERT(n < N && x.count + y.count <= 8 && x.pow2 + y.pow2 <= 64,
                     "plane_crossing_ball: term count");
        ExactTerm r{sign * x.sign * y.sign, x.pow2 + y.pow2, x.count + y.count, {}};
        for (int k = 0; k < x.count; ++k) r.f[k] = x.f[k];
        for (int k = 0; k < y.count; ++k) r.f[x.count + k] = y.f[k];
        t[n++] = r;
      }
  }
  [[nodiscard]] int sign() const noexcept { return exact_sign_of_terms({t.data(), n}); }
};

// One monomial of three or two factors.
template <std::size_t N>
void add3(Terms<N>& out, int sign, double f0, double f1, double f2) noexcept {
  LOCUS_ASSERT(out.n < N, "plane_crossing_ball: term count");
  out.t[out.n++] = {sign, 0, 3, {f0, f1, f2}};
}
template <std::size_t N>
void add2(Terms<N>& out, int sign, int pow2, double f0, double f1) noexcept {
  LOCUS_ASSERT(out.n < N, "plane_crossing_ball: term count");
  out.t[out.n++] = {sign, pow2, 2, {f0, f1}};
}

// The minor a_i b_j - a_j b_i with a = p - c, b = q - c, without rounded differences:
// p_i q_j - p_j q_i + c_i (p_j - q_j) - c_j (p_i - q_i) (six monomials), times the factor m.
template <std::size_t N>
void add_minor(Terms<N>& out, double m, const V& p, const V& q, const V& c, int i, int j) noexcept {
  add3(out, 1, m, p[i], q[j]);
  add3(out, -1, m, p[j], q[i]);
  add3(out, 1, m, c[i], p[j]);
  add3(out, -1, m, c[i], q[j]);
  add3(out, -1, m, c[j], p[i]);
  add3(out, 1, m, c[j], q[i]);
}

// a_i d_j - a_j d_i with a = p - c (four monomials), times the factor m.
template <std::size_t N>
void add_line_cross(Terms<N>& out, double m, const V& p, const V& d, const V& c, int i,
                    int j) noexcept {
  add3(out, 1, m, p[i], d[j]);
  add3(out, -1, m, c[i], d[j]);
  add3(out, -1, m, p[j], d[i]);
  add3(out, 1, m, c[j], d[i]);
}

// r^2 as one monomial.
Terms<1> r_squared(double r) noexcept {
  Terms<1> rr;
  add2(rr, 1, 0, r, r);
  return rr;
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
  // degree 3 each; |W|^2 has 192 and r^2 (n.d)^2 nine.
  Terms<201> sum;
  Terms<3> den;
  for (int k = 0; k < 3; ++k) {
    Terms<8> w;
    // W_k = sum over i != k of n_i (a_k d_i - a_i d_k) = n_i times the cross minor (k, i).
    for (const int i : {other1(k), other2(k)}) add_line_cross(w, n[i], p, d, c, k, i);
    sum.add_product(1, w, w);
    add2(den, 1, 0, n[k], d[k]);
  }
  Terms<3> rden;
  rden.add_product(1, r_squared(r), den);
  sum.add_product(-1, rden, den);
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
  // 36 (more than an ExactPoly holds).
  Terms<3 * 144 + 36> sum;
  Terms<6> den;
  for (int k = 0; k < 3; ++k) {
    Terms<12> w;
    for (const int i : {other1(k), other2(k)}) add_minor(w, n[i], p, q, c, i, k);
    sum.add_product(1, w, w);
    add2(den, 1, 0, n[k], p[k]);
    add2(den, -1, 0, n[k], q[k]);
  }
  Terms<6> rden;
  rden.add_product(1, r_squared(r), den);
  sum.add_product(-1, rden, den);
  return sum.sign();
}

int point_in_ball(const V& x, const V& c, double r) noexcept {
  // sum of x_k^2 - 2 x_k c_k + c_k^2, minus r^2: ten monomials.
  std::array<ExactTerm, 10> t;
  for (int k = 0; k < 3; ++k) {
    t[static_cast<std::size_t>(3 * k)] = {1, 0, 2, {x[k], x[k]}};
    t[static_cast<std::size_t>(3 * k + 1)] = {-1, 1, 2, {x[k], c[k]}};
    t[static_cast<std::size_t>(3 * k + 2)] = {1, 0, 2, {c[k], c[k]}};
  }
  t[9] = {-1, 0, 2, {r, r}};
  return exact_sign_of_terms(t);
}

int line_near_ball(const V& p, const V& d, const V& c, double r) noexcept {
  // (a x d)_k = a_i d_j - a_j d_i with a = p - c: four monomials; 48 + 3 in all.
  Terms<51> sum;
  for (int k = 0; k < 3; ++k) {
    Terms<4> w;
    add_line_cross(w, 1.0, p, d, c, (k + 1) % 3, (k + 2) % 3);
    sum.add_product(1, w, w);
    LOCUS_ASSERT(sum.n < 51, "line_near_ball: term count");
    sum.t[sum.n++] = {-1, 0, 4, {r, r, d[k], d[k]}};
  }
  return sum.sign();
}

int segment_line_near_ball(const V& p, const V& q, const V& c, double r) noexcept {
  // (a x b)_k with a = p - c, b = q - c: the six-monomial minor; 108 + 9 in all.
  Terms<117> sum;
  for (int k = 0; k < 3; ++k) {
    Terms<6> w;
    add_minor(w, 1.0, p, q, c, (k + 1) % 3, (k + 2) % 3);
    sum.add_product(1, w, w);
    // - r^2 (q_k - p_k)^2 = - r^2 q_k^2 + 2 r^2 q_k p_k - r^2 p_k^2.
    LOCUS_ASSERT(sum.n + 3 <= 117, "segment_line_near_ball: term count");
    sum.t[sum.n++] = {-1, 0, 4, {r, r, q[k], q[k]}};
    sum.t[sum.n++] = {1, 1, 4, {r, r, q[k], p[k]}};
    sum.t[sum.n++] = {-1, 0, 4, {r, r, p[k], p[k]}};
  }
  return sum.sign();
}

int dot_of_differences(const V& x, const V& y, const V& v) noexcept {
  std::array<ExactTerm, 6> t;
  for (int k = 0; k < 3; ++k) {
    t[static_cast<std::size_t>(2 * k)] = {1, 0, 2, {x[k], v[k]}};
    t[static_cast<std::size_t>(2 * k + 1)] = {-1, 0, 2, {y[k], v[k]}};
  }
  return exact_sign_of_terms(t);
}

int dot_of_differences(const V& x, const V& y, const V& z, const V& w) noexcept {
  std::array<ExactTerm, 12> t;
  for (int k = 0; k < 3; ++k) {
    t[static_cast<std::size_t>(4 * k)] = {1, 0, 2, {x[k], z[k]}};
    t[static_cast<std::size_t>(4 * k + 1)] = {-1, 0, 2, {x[k], w[k]}};
    t[static_cast<std::size_t>(4 * k + 2)] = {-1, 0, 2, {y[k], z[k]}};
    t[static_cast<std::size_t>(4 * k + 3)] = {1, 0, 2, {y[k], w[k]}};
  }
  return exact_sign_of_terms(t);
}

}  // namespace locus
