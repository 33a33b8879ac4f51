// SPDX-License-Identifier: BSL-1.0
#pragma once
// Univariate polynomials with exact integer coefficients (private to src/): the representation
// under the exact real-root engine of numeric/roots.hpp (RootMode::exact, src/numeric/
// roots_exact.cpp), shared with the callers that build a polynomial exactly and need its real
// roots decided exactly, e.g. a resultant or a characteristic polynomial whose coefficients are
// products of many doubles and so no longer doubles themselves.
//
// ZPoly is a coefficient vector, lowest degree first, on core's DynBigInt (src/core/big_int.hpp).
// Doubles enter exactly by DynBigInt::from_double(x, shift) with a common shift (every double of
// a set times 2^shift is an integer when shift >= -min low_exponent): scaling all inputs by one
// power of two scales each coefficient of a homogeneous expression by a power of two, which
// leaves the roots unchanged. The arithmetic is exact, allocates, and may throw std::bad_alloc.
//
// exact_real_roots_of_integers() is the engine of numeric/roots.hpp's exact mode on such a
// polynomial: the real roots in [lo, hi], each correctly rounded to T with its multiplicity,
// distinct roots never merged (several in one T cell are reported separately with the same
// value), decided by Sturm sequences of the gcd chain. Cost: polynomial in the degree and the
// coefficients' bit length; see docs/notes/numeric.md.

#include <locus/core/status.hpp>
#include <locus/numeric/roots.hpp>

#include "../core/big_int.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace locus::detail::roots {

using ZPoly = std::vector<DynBigInt>;  // low to high; trimmed: the last coefficient is non-zero

inline void trim(ZPoly& p) {
  while (!p.empty() && p.back().is_zero()) p.pop_back();
}
/// -1 for the zero polynomial.
[[nodiscard]] inline int degree(const ZPoly& p) noexcept { return static_cast<int>(p.size()) - 1; }

// Arithmetic as named functions: ZPoly is a std::vector, so operators would not be found by
// argument-dependent lookup outside this namespace.
[[nodiscard]] inline ZPoly add(const ZPoly& a, const ZPoly& b) {
  ZPoly r(a.size() > b.size() ? a : b);
  const ZPoly& s = a.size() > b.size() ? b : a;
  for (std::size_t i = 0; i < s.size(); ++i) r[i] += s[i];
  trim(r);
  return r;
}
[[nodiscard]] inline ZPoly negated(const ZPoly& a) {
  ZPoly r(a);
  for (DynBigInt& c : r) c = -c;
  return r;
}
[[nodiscard]] inline ZPoly sub(const ZPoly& a, const ZPoly& b) { return add(a, negated(b)); }
[[nodiscard]] inline ZPoly mul(const ZPoly& a, const ZPoly& b) {
  if (a.empty() || b.empty()) return {};
  ZPoly r(a.size() + b.size() - 1);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  trim(r);
  return r;
}
[[nodiscard]] inline ZPoly scaled(const ZPoly& a, const DynBigInt& k) {
  if (k.is_zero()) return {};
  ZPoly r(a);
  for (DynBigInt& c : r) c = c * k;
  return r;
}

[[nodiscard]] inline ZPoly derivative(const ZPoly& p) {
  ZPoly d;
  for (std::size_t i = 1; i < p.size(); ++i)
    d.push_back(p[i] * DynBigInt(static_cast<std::int64_t>(i)));
  trim(d);
  return d;
}

/// Divides p by the gcd of its coefficients (a positive number: signs are kept).
inline void make_primitive(ZPoly& p) {
  if (p.empty()) return;
  DynBigInt g = abs(p.back());
  const DynBigInt one(1);
  for (std::size_t i = 0; i + 1 < p.size() && !(g == one); ++i)
    if (!p[i].is_zero()) g = gcd(g, p[i]);
  if (g == one) return;
  for (DynBigInt& c : p)
    if (!c.is_zero()) c = divide_exact(c, g);
}

/// The Sturm sequence p, p', -rem, ... of p (made primitive; p of degree >= 1): the number of
/// distinct real roots in (a, b] is the drop in sign variations from a to b, and the last member
/// is gcd(p, p') up to a constant (its roots are p's multiple roots).
[[nodiscard]] std::vector<ZPoly> sturm_sequence(const ZPoly& p);
/// The greatest common divisor of a and b in Z[x], primitive with a positive leading coefficient
/// (empty when both are zero); by primitive pseudo-remainders.
[[nodiscard]] ZPoly gcd(const ZPoly& a, const ZPoly& b);

/// The real roots of p (any integer polynomial; the zero polynomial has none) in [lo, hi]
/// (either may be infinite), appended to out in increasing order, each correctly rounded to T
/// with its multiplicity. Returns ok, or limit_exceeded when opt's exact budgets are exceeded
/// (degree above max_exact_degree, or roots closer than max_exact_bisections halvings).
template <Real T>
Status exact_real_roots_of_integers(ZPoly p, T lo, T hi, const RootOptions& opt,
                                    std::vector<Root<T>>& out);
extern template Status exact_real_roots_of_integers<float>(ZPoly, float, float, const RootOptions&,
                                                           std::vector<Root<float>>&);
extern template Status exact_real_roots_of_integers<double>(ZPoly, double, double,
                                                            const RootOptions&,
                                                            std::vector<Root<double>>&);

}  // namespace locus::detail::roots
