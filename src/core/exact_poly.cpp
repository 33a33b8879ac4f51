// SPDX-License-Identifier: BSL-1.0
// Exact sign of a sum of products of up to eight doubles (include/locus/core/exact_poly.hpp) on
// the engine shared with exact_sum.cpp (exact_terms.hpp: a filter, then core's big integer).

#include <locus/config.hpp>
#include <locus/core/exact_poly.hpp>

#include "exact_terms.hpp"

namespace locus {

int exact_sign_of_terms(std::span<const ExactTerm> terms) noexcept {
  for (const ExactTerm& t : terms)
    LOCUS_ASSERT(t.count >= 0 && t.count <= 8 && t.pow2 >= 0 && t.pow2 <= 64,
                 "exact_sign_of_terms: count in [0, 8], pow2 in [0, 64]");
  return detail::exact_terms::sign<8>(terms);
}

}  // namespace locus
