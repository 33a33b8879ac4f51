// SPDX-License-Identifier: BSL-1.0
#pragma once
// Exact sign of a polynomial in double inputs, built term by term: the predicate behind the
// conic decisions of the intersection area (rows int2.linear-quadratic, int2.quadratic: the sign
// of a discriminant, of a conic's value at a point; book sections 7.2-7.5). Row core.predicates.
//
// ExactPoly is a sum of at most ExactPoly::capacity monomials sign 2^pow2 f_0 ... f_(count-1)
// with count <= 8 factors (exact_sum.hpp stops at 4): enough for the degree-8 discriminant of a
// segment against an ellipse. Build it from variables (ExactPoly::var(x) is the exact double x;
// differences such as p.x - c.x are sums of two variables, never rounded), then add, subtract,
// multiply and scale by powers of two; every operation is exact. sign(p) is the exact sign
// (-1, 0, +1) of the polynomial's value: a floating-point filter with an a-priori error bound
// first, then, when it cannot decide, the exact integer sum on core's big integer
// (src/core/big_int.hpp, src/core/exact_poly.cpp), valid for every finite double factor.
// Overflowing the capacity, more than 8 factors in a product or pow2 beyond 64 marks the
// polynomial invalid (valid() false; sign() then returns 0): callers size their expressions so
// this never happens, and tests assert it. A non-finite factor also gives sign 0 (callers test
// finiteness first). Cost: building is a few hundred nanoseconds per hundred terms; the exact
// path a few to a hundred microseconds (it grows with the exponent spread); no allocation
// (an ExactPoly is about 26 kB: keep a few on the stack, not in arrays).

#include <locus/core/scalar.hpp>

#include <array>
#include <span>

namespace locus {

/// sign * 2^pow2 * f[0] * ... * f[count - 1] (count <= 8, 0 <= pow2 <= 64).
struct ExactTerm {
  int sign;
  int pow2;
  int count;
  double f[8];
};

/// Exact sign of the sum of the terms (compiled in src/core/exact_poly.cpp); 0 when a factor is
/// not finite.
[[nodiscard]] int exact_sign_of_terms(std::span<const ExactTerm> terms) noexcept;

/// A polynomial in doubles as an exact sum of monomials (see the header comment).
class ExactPoly {
 public:
  static constexpr int capacity = 320;

  ExactPoly() noexcept {}  // the terms stay uninitialised: only the first size() are read
  /// Copies only the live terms (an ExactPoly is large; most are short).
  ExactPoly(const ExactPoly& o) noexcept : n_(o.n_), ok_(o.ok_) {
    for (int i = 0; i < n_; ++i)
      t_[static_cast<std::size_t>(i)] = o.t_[static_cast<std::size_t>(i)];
  }
  ExactPoly& operator=(const ExactPoly& o) noexcept {
    n_ = o.n_;
    ok_ = o.ok_;
    for (int i = 0; i < n_; ++i)
      t_[static_cast<std::size_t>(i)] = o.t_[static_cast<std::size_t>(i)];
    return *this;
  }
  /// The exact value x (the zero polynomial when x == 0).
  [[nodiscard]] static ExactPoly var(double x) noexcept {
    ExactPoly p;
    if (x != 0.0) p.push({1, 0, 1, {x}});
    return p;
  }
  /// The constant sign * 2^pow2 (sign in {-1, 0, 1}).
  [[nodiscard]] static ExactPoly constant(int sign, int pow2 = 0) noexcept {
    ExactPoly p;
    if (sign != 0) p.push({sign, pow2, 0, {}});
    return p;
  }
  /// x - y exactly.
  [[nodiscard]] static ExactPoly diff(double x, double y) noexcept { return var(x) - var(y); }

  [[nodiscard]] bool valid() const noexcept { return ok_; }
  [[nodiscard]] int size() const noexcept { return n_; }
  [[nodiscard]] std::span<const ExactTerm> terms() const noexcept {
    return {t_.data(), static_cast<std::size_t>(n_)};
  }

  ExactPoly& operator+=(const ExactPoly& o) noexcept {
    ok_ = ok_ && o.ok_;
    for (int i = 0; i < o.n_; ++i) push(o.t_[static_cast<std::size_t>(i)]);
    return *this;
  }
  ExactPoly& operator-=(const ExactPoly& o) noexcept {
    ok_ = ok_ && o.ok_;
    for (int i = 0; i < o.n_; ++i) {
      ExactTerm t = o.t_[static_cast<std::size_t>(i)];
      t.sign = -t.sign;
      push(t);
    }
    return *this;
  }
  /// Multiplies by 2^k (k >= 0).
  [[nodiscard]] ExactPoly times_pow2(int k) const noexcept {
    ExactPoly r = *this;
    for (int i = 0; i < r.n_; ++i) {
      ExactTerm& t = r.t_[static_cast<std::size_t>(i)];
      t.pow2 += k;
      if (t.pow2 > 64 || t.pow2 < 0) r.ok_ = false;
    }
    return r;
  }
  [[nodiscard]] friend ExactPoly operator+(ExactPoly a, const ExactPoly& b) noexcept {
    a += b;
    return a;
  }
  [[nodiscard]] friend ExactPoly operator-(ExactPoly a, const ExactPoly& b) noexcept {
    a -= b;
    return a;
  }
  [[nodiscard]] friend ExactPoly operator-(ExactPoly a) noexcept {
    for (int i = 0; i < a.n_; ++i) a.t_[static_cast<std::size_t>(i)].sign *= -1;
    return a;
  }
  [[nodiscard]] friend ExactPoly operator*(const ExactPoly& a, const ExactPoly& b) noexcept {
    ExactPoly r;
    r.ok_ = a.ok_ && b.ok_;
    for (int i = 0; i < a.n_; ++i)
      for (int j = 0; j < b.n_; ++j) {
        const ExactTerm& x = a.t_[static_cast<std::size_t>(i)];
        const ExactTerm& y = b.t_[static_cast<std::size_t>(j)];
        if (x.count + y.count > 8 || x.pow2 + y.pow2 > 64) {
          r.ok_ = false;
          return r;
        }
        ExactTerm t{x.sign * y.sign, x.pow2 + y.pow2, x.count + y.count, {}};
        for (int k = 0; k < x.count; ++k) t.f[k] = x.f[k];
        for (int k = 0; k < y.count; ++k) t.f[x.count + k] = y.f[k];
        r.push(t);
      }
    return r;
  }

  /// Exact sign of the value; 0 when the polynomial is invalid (see the header comment).
  [[nodiscard]] int sign() const noexcept { return ok_ ? exact_sign_of_terms(terms()) : 0; }

 private:
  void push(const ExactTerm& t) noexcept {
    if (n_ >= capacity) {
      ok_ = false;
      return;
    }
    t_[static_cast<std::size_t>(n_++)] = t;
  }
  std::array<ExactTerm, capacity> t_;
  int n_ = 0;
  bool ok_ = true;
};

}  // namespace locus
