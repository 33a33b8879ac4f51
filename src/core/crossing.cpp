// SPDX-License-Identifier: BSL-1.0
// Accurate det[b - a; d - c] (include/locus/core/crossing.hpp), past the double-double tier of
// turn2d_value_dd, in two stages.
//
// 1. A triple-length evaluation (error at most u |det| (1 + 4u) + 512 u^3 P, u = 2^-53,
//    P = |p| + |q| below): the differences split exactly, b.x - a.x = h1 + l1 and so on (two_sum,
//    |l| <= u |h|), and
//      det = (h1 + l1)(h2 + l2) - (h3 + l3)(h4 + l4)
//          = (p - q) + [pe - qe + c1 + c2 - c3 - c4] + [c1e + c2e - c3e - c4e + l1 l2 - l3 l4]
//    with p + pe = h1 h2, q + qe = h3 h4, c1 + c1e = h1 l2, c2 + c2e = l1 h2, c3 + c3e = h3 l4,
//    c4 + c4e = l3 h4 exactly (two_product), p - q = s + se exactly (two_sum). The first-order
//    bracket, with se (each term at most u P, 4u P in all), is summed by a cascade of two_sums
//    whose six errors (each at most 4u^2 P) join the second-order bracket (at most 28 u^2 P in
//    all: 12 terms summed in floating point, error at most 11u 28u^2 P + the roundings of l1 l2
//    and l3 l4, u^3 P); then s + first-order sum is split exactly once more and rounded with the
//    rest. Accepted when |v| >= 2^-90 P, where 512 u^3 P <= 2^-60 |v|: relative error about 1.01u,
//    and the sign is exact. Needs P in [2^-800, 2^900] and every |h| below 2^990 (no product
//    overflows; underflow adds at most about 2^-1068, below 2^-170 |v|); non-finite input fails.
// 2. Otherwise (|det| tiny against P: nearly collinear to within 2^-90, or zero) the exact
//    expansion: the determinant expanded into the minors of the raw coordinates,
//    m(p, q) = p.x q.y - p.y q.x,
//      det[b - a; d - c] = m(b, d) - m(b, c) - m(a, d) + m(a, c),
//    each minor exact as an expansion of at most four components (two products and their errors),
//    summed exactly, compressed, and rounded once by summing from the smallest component up.
//
// Stage 1 and the double-double tier before it are written once, over the scalar or SIMD lane
// type, in crossing_stages.hpp (the batched segment intersection runs them in lanes).
// They are compiled twice: with fused multiply-adds for processors that have them
// (x86-64-v4, or AVX2 with FMA; chosen at run time by detail::batch_isa() of
// core/detail/batch_isa.hpp, the lane code's selector), where a product's error is one instruction,
// and with Dekker's product elsewhere (builds have no -march). Must be compiled with
// -ffp-contract=off (CMake sets it): the expansion theorems and Dekker's product need each
// operation rounded on its own; the FMA version calls __builtin_fma explicitly.

#if defined(__FAST_MATH__)
#error "locus: src/core/crossing.cpp must not be compiled with -ffast-math (exact arithmetic)"
#endif

#include <locus/config.hpp>
#include <locus/core/crossing.hpp>
#include <locus/core/detail/batch_isa.hpp>

#include <cmath>

#include "crossing_stages.hpp"
#include "expansion.hpp"

namespace locus::detail {
namespace {

double turn2d_value_expansion(const Vec2<double>& a, const Vec2<double>& b, const Vec2<double>& c,
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

/// The double-double tier of turn2d_value_dd (include/locus/core/crossing.hpp, same bound and
/// acceptance), then stage 1, then stage 2 (crossing_stages.hpp holds the first two).
template <bool kFma>
LOCUS_ALWAYS_INLINE inline double accurate(const Vec2<double>& a, const Vec2<double>& b,
                                           const Vec2<double>& c, const Vec2<double>& d) noexcept {
  namespace st = crossing_stages;
  using Ops = st::ScalarOps<kFma>;
  const st::Split<Ops> h = st::split<Ops>(a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y);
  const st::Leading<Ops> lead = st::leading(h);
  const st::Value<Ops> dd = st::double_double(h, lead);
  if (dd.ok) [[likely]]
    return dd.v;
  const st::Value<Ops> tl = st::triple(h, lead, st::cross(h), st::largest_difference(h));
  if (tl.ok) [[likely]]
    return tl.v;
  return turn2d_value_expansion(a, b, c, d);
}

using AccurateFn = double (*)(const Vec2<double>&, const Vec2<double>&, const Vec2<double>&,
                              const Vec2<double>&) noexcept;

double accurate_dekker(const Vec2<double>& a, const Vec2<double>& b, const Vec2<double>& c,
                       const Vec2<double>& d) noexcept {
  return accurate<false>(a, b, c, d);
}

#if defined(__x86_64__) && defined(__has_attribute) && !defined(LOCUS_NO_MULTIVERSION)
#if __has_attribute(target)
#define LOCUS_CROSSING_FMA_VERSION 1
__attribute__((target("avx2,fma"))) double accurate_fma(const Vec2<double>& a,
                                                        const Vec2<double>& b,
                                                        const Vec2<double>& c,
                                                        const Vec2<double>& d) noexcept {
  return accurate<true>(a, b, c, d);
}
#endif
#endif

/// The version for the running processor: with FMA where batch_isa() permits AVX2 or better
/// and the processor has FMA (every x86-64-v3 one does).
AccurateFn pick() noexcept {
#ifdef LOCUS_CROSSING_FMA_VERSION
  static const bool has_fma = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("fma") != 0;
  }();
  if (has_fma && batch_isa() != BatchIsa::baseline) return &accurate_fma;
#endif
  return &accurate_dekker;
}

}  // namespace

double turn2d_value_accurate(const Vec2<double>& a, const Vec2<double>& b, const Vec2<double>& c,
                             const Vec2<double>& d) noexcept {
  return pick()(a, b, c, d);
}

}  // namespace locus::detail
