// SPDX-License-Identifier: BSL-1.0
// Accurate det[b - a; d - c] (include/locus/core/crossing.hpp): the determinant is expanded into
// the minors of the raw coordinates, m(p, q) = p.x q.y - p.y q.x,
//   det[b - a; d - c] = m(b, d) - m(b, c) - m(a, d) + m(a, c),
// each minor exact as an expansion of at most four components (two products and their errors),
// summed exactly, compressed, and rounded once by summing from the smallest component up.
// Must be compiled with -ffp-contract=off (CMake sets it): the expansion theorems need each
// operation rounded on its own.

#if defined(__FAST_MATH__)
#error "locus: src/core/crossing.cpp must not be compiled with -ffast-math (exact arithmetic)"
#endif

#include <locus/core/crossing.hpp>

#include <cmath>

#include "expansion.hpp"

namespace locus::detail {

double turn2d_value_accurate(const Vec2<double>& a, const Vec2<double>& b, const Vec2<double>& c,
                             const Vec2<double>& d) noexcept {
  namespace ex = expansion;
  if (!(std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(b.x) && std::isfinite(b.y) &&
        std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(d.x) && std::isfinite(d.y)))
    return std::nan("");
  double bd[4], bc[4], ad[4], ac[4];
  const int nbd = ex::two_products_diff(b.x, d.y, b.y, d.x, bd);
  const int nbc = ex::two_products_diff(b.y, c.x, b.x, c.y, bc);  // -m(b, c)
  const int nad = ex::two_products_diff(a.y, d.x, a.x, d.y, ad);  // -m(a, d)
  const int nac = ex::two_products_diff(a.x, c.y, a.y, c.x, ac);
  double s1[8], s2[8], s[16];
  const int n1 = ex::sum_zeroelim(nbd, bd, nbc, bc, s1);
  const int n2 = ex::sum_zeroelim(nad, ad, nac, ac, s2);
  int n = ex::sum_zeroelim(n1, s1, n2, s2, s);
  n = ex::compress(n, s);
  return ex::estimate(n, s);
}

}  // namespace locus::detail
