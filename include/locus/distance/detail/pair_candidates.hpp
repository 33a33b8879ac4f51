// SPDX-License-Identifier: BSL-1.0
#pragma once
// Internal machinery of the distance queries that solve by candidates (line_ellipse.hpp,
// line_quadratic_curve.hpp, line_curve.hpp; row dist2.linear-curve, book section 6.4): every
// candidate is a REALISABLE pair of points, one on each object, scored by its squared distance,
// and the smallest wins. Because each candidate is a genuine pair, the minimum is never below
// the true distance by more than the rounding of the pair, and as long as the candidate set
// contains a global minimiser it is the distance.
//
// PairCandidates keeps the best pair and the best pair DISTINCT from it (its points differ by
// more than sqrt(sep2)): the queries use the runner-up to recognise ties. NaN scores are
// ignored; on equal scores the first offered wins (so the result does not depend on rounding
// noise in a later, equivalent candidate).

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>

#include <cmath>
#include <limits>

namespace locus::detail {

template <class C, int N, class PA, class PB>
struct PairCandidates {
  struct Pair {
    C d2 = std::numeric_limits<C>::infinity();
    PA pa{};
    PB pb{};
    Vec<C, N> xa{}, xb{};
    bool unique = true;
  };
  bool found = false;
  Pair best{};
  bool has_alt = false;
  Pair alt{};
  C sep2 = C(0);  ///< squared separation below which two pairs are "the same pair"

  [[nodiscard]] bool distinct(const Pair& p, const Pair& q) const noexcept {
    return sqr_length(p.xa - q.xa) + sqr_length(p.xb - q.xb) > sep2;
  }

  /// Offers the pair (xa on the first object at parameter pa, xb on the second at pb) whose
  /// squared distance is d2; `unique` is the flag the pair would be reported with.
  void offer(C d2, PA pa, PB pb, const Vec<C, N>& xa, const Vec<C, N>& xb,
             bool unique = true) noexcept {
    if (!(d2 == d2)) return;
    const Pair p{d2, pa, pb, xa, xb, unique};
    if (!found || d2 < best.d2) {
      if (found && distinct(p, best)) {
        has_alt = true;
        alt = best;
      }
      found = true;
      best = p;
    } else if ((!has_alt || d2 < alt.d2) && distinct(p, best)) {
      has_alt = true;
      alt = p;
    }
  }

  /// True when a distinct pair is within dist_tol of the best DISTANCE (an absolute tolerance,
  /// so that ties at distance zero are seen too).
  [[nodiscard]] bool tied(C dist_tol) const noexcept {
    return has_alt && std::sqrt(alt.d2) - std::sqrt(best.d2) <= dist_tol;
  }
};

}  // namespace locus::detail
