// SPDX-License-Identifier: BSL-1.0
// Exact classification of a quadric (include/locus/primitives/quadric.hpp): the signs of the
// sums of principal minors of A and of M = [[A, b/2], [b^T/2, c]], each a sum of signed products
// of coefficients decided by core's exact_sign_of_sum. The entries are those of the congruent
// matrix 2M = [[2A, b], [b^T, 2c]] (same inertia), with each factor 2 carried as a power of two
// of the product rather than applied to a coefficient, so that no entry is ever rounded.

#include <locus/core/exact_sum.hpp>
#include <locus/primitives/quadric.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <span>

namespace locus {
namespace {

struct Entries {
  double v[4][4];  // coefficient
  int p2[4][4];    // its power of two in 2M
};

// Sign of the sum of the k x k principal minors of the leading dim x dim block of 2M: the sum,
// over every k-subset S and every permutation s of S, of sgn(s) prod_{i in S} m[i][s(i)].
int principal_minor_sum_sign(const Entries& m, int dim, int k) noexcept {
  std::array<ExactMonomial, 24> terms;  // at most C(4, 3) * 3! = 4! = 24 products; n are set
  std::size_t n = 0;
  for (unsigned mask = 0; mask < (1u << dim); ++mask) {
    if (std::popcount(mask) != k) continue;
    int rows[4] = {}, perm[4] = {};
    int r = 0;
    for (int i = 0; i < dim; ++i)
      if (mask & (1u << i)) rows[r++] = i;
    std::copy_n(rows, k, perm);
    do {
      int inversions = 0;
      for (int i = 0; i < k; ++i)
        for (int j = i + 1; j < k; ++j) inversions += perm[i] > perm[j];
      ExactMonomial t{inversions % 2 == 0 ? 1 : -1, 0, k, {}};
      for (int i = 0; i < k; ++i) {
        t.f[i] = m.v[rows[i]][perm[i]];
        t.pow2 += m.p2[rows[i]][perm[i]];
      }
      terms[n++] = t;
    } while (std::next_permutation(perm, perm + k));
  }
  return exact_sign_of_sum(std::span<const ExactMonomial>(terms.data(), n));
}

// Rank and numbers of positive and negative eigenvalues from the signs s[0..n] of the
// characteristic coefficients e_k (s[0] = 1): rank = the last nonzero index, positives = the
// sign changes of (-1)^k s[k] (Descartes, exact for a real-rooted polynomial).
void inertia(const int* s, int n, int& rank, int& pos, int& neg) noexcept {
  rank = 0;
  for (int k = 1; k <= n; ++k)
    if (s[k] != 0) rank = k;
  pos = 0;
  int prev = 1;
  for (int k = 1; k <= rank; ++k) {
    if (s[k] == 0) continue;
    const int cur = (k % 2 == 0) ? s[k] : -s[k];
    if (cur != prev) ++pos;
    prev = cur;
  }
  neg = rank - pos;
}

}  // namespace

template <Real T>
QuadricClass quadric_type(const Quadric3<T>& q) noexcept {
  QuadricClass r{Status::ok, QuadricType::invalid, 0, 0, 0, 0, 0, 0, true};
  if (!detail::quadric_is_finite(q)) {
    r.status = Status::non_finite_input;
    r.exact = false;
    return r;
  }
  Entries m{};
  for (int i = 0; i < 3; ++i) {
    for (int j = i; j < 3; ++j) {
      m.v[i][j] = m.v[j][i] = static_cast<double>(q.a.a[i][j]);
      m.p2[i][j] = m.p2[j][i] = 1;
    }
    m.v[i][3] = m.v[3][i] = static_cast<double>(q.b[i]);
  }
  m.v[3][3] = static_cast<double>(q.c);
  m.p2[3][3] = 1;
  int sa[4] = {1, 0, 0, 0}, sm[5] = {1, 0, 0, 0, 0};
  for (int k = 1; k <= 3; ++k) sa[k] = principal_minor_sum_sign(m, 3, k);
  for (int k = 1; k <= 4; ++k) sm[k] = principal_minor_sum_sign(m, 4, k);
  inertia(sa, 3, r.rank_a, r.positive_a, r.negative_a);
  inertia(sm, 4, r.rank_m, r.positive_m, r.negative_m);
  r.type = detail::quadric_type_of_inertia(r.rank_a, r.positive_a, r.negative_a, r.rank_m,
                                           r.positive_m, r.negative_m);
  return r;
}

template QuadricClass quadric_type<float>(const Quadric3<float>&) noexcept;
template QuadricClass quadric_type<double>(const Quadric3<double>&) noexcept;

}  // namespace locus
