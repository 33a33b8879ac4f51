// SPDX-License-Identifier: BSL-1.0
// Exact sign of a sum of signed products of up to four doubles (include/locus/core/exact_sum.hpp)
// on the engine shared with exact_poly.cpp (exact_terms.hpp: a filter, then core's big integer).

#include <locus/config.hpp>
#include <locus/core/exact_sum.hpp>

#include "exact_terms.hpp"

namespace locus {

int exact_sign_of_sum(std::span<const ExactMonomial> terms) noexcept {
  for (const ExactMonomial& t : terms)
    LOCUS_ASSERT(t.count >= 0 && t.count <= 4 && t.pow2 >= 0 && t.pow2 <= 64,
                 "exact_sign_of_sum: count in [0, 4], pow2 in [0, 64]");
  return detail::exact_terms::sign<4>(terms);
}

}  // namespace locus
