// SPDX-License-Identifier: BSL-1.0
#pragma once
// Exact GMP oracle for two triangles in 3D that shares nothing with the predicates: the common
// points are the solutions of sum l_i A_i = sum m_j B_j, sum l = sum m = 1, l, m >= 0, a bounded
// polytope in (l, m); it is non-empty iff it has a basic solution (a linearly independent
// column subset with a non-negative solution, found by rational Gauss elimination), and a
// linear objective is largest at one of them. Used by tests/intersection (feasibility) and
// tests/mesh (how far the common set reaches beyond shared vertices).

#include <gmpxx.h>

#include <locus/primitives/triangle.hpp>

#include <array>
#include <optional>
#include <utility>
#include <vector>

namespace locus_test {

// Reduced row echelon form of m on its first `cols` columns (row operations act on whole
// rows); returns the rank.
inline int rref(std::vector<std::vector<mpq_class>>& m, int cols) {
  const int rows = static_cast<int>(m.size());
  int r = 0;
  for (int c = 0; c < cols && r < rows; ++c) {
    const auto uc = static_cast<std::size_t>(c);
    int piv = -1;
    for (int i = r; i < rows; ++i) {
      if (sgn(m[static_cast<std::size_t>(i)][uc]) != 0) {
        piv = i;
        break;
      }
    }
    if (piv < 0) continue;
    std::swap(m[static_cast<std::size_t>(piv)], m[static_cast<std::size_t>(r)]);
    auto& pr = m[static_cast<std::size_t>(r)];
    const mpq_class p = pr[uc];
    for (auto& x : pr) x /= p;
    for (int i = 0; i < rows; ++i) {
      if (i == r) continue;
      auto& row = m[static_cast<std::size_t>(i)];
      const mpq_class f = row[uc];
      if (sgn(f) == 0) continue;
      for (std::size_t j = 0; j < row.size(); ++j) row[j] -= f * pr[j];
    }
    ++r;
  }
  return r;
}

/// The largest value of w . (l0 l1 l2 m0 m1 m2) over the common points of a and b, or nothing
/// when they do not meet.
template <class T>
std::optional<mpq_class> max_over_common_points(const locus::Triangle3<T>& a,
                                                const locus::Triangle3<T>& b,
                                                const std::array<mpq_class, 6>& w) {
  mpq_class A[5][6];
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) {
      A[k][i] = mpq_class(static_cast<double>(a[i][k]));
      A[k][3 + i] = -mpq_class(static_cast<double>(b[i][k]));
    }
    A[3][i] = 1;
    A[3][3 + i] = 0;
    A[4][i] = 0;
    A[4][3 + i] = 1;
  }
  const mpq_class rhs[5] = {0, 0, 0, 1, 1};
  std::optional<mpq_class> best;
  for (int mask = 1; mask < 64; ++mask) {
    std::vector<int> cols;
    for (int c = 0; c < 6; ++c) {
      if (mask & (1 << c)) cols.push_back(c);
    }
    const int k = static_cast<int>(cols.size());
    if (k > 5) continue;
    const auto uk = static_cast<std::size_t>(k);
    std::vector<std::vector<mpq_class>> m(5, std::vector<mpq_class>(uk + 1));
    for (int r = 0; r < 5; ++r) {
      for (std::size_t j = 0; j < uk; ++j) m[static_cast<std::size_t>(r)][j] = A[r][cols[j]];
      m[static_cast<std::size_t>(r)][uk] = rhs[r];
    }
    // Columns are reduced in order, so the columns of A_S hold rank(A_S) pivots and the right-
    // hand side one more when the system is inconsistent.
    if ((mask & 7) == 0 || (mask & 56) == 0) continue;  // sum l = sum m = 1 needs both kinds
    const int rank = rref(m, k);
    if (rank != k) continue;  // dependent columns
    bool consistent = true;
    for (std::size_t r = uk; r < 5; ++r) {
      if (sgn(m[r][uk]) != 0) consistent = false;
    }
    if (!consistent) continue;
    bool nonneg = true;
    mpq_class value = 0;
    for (std::size_t j = 0; j < uk; ++j) {
      if (sgn(m[j][uk]) < 0) nonneg = false;
      value += w[static_cast<std::size_t>(cols[j])] * m[j][uk];
    }
    if (nonneg && (!best || value > *best)) best = value;
  }
  return best;
}

/// Whether closed triangles a and b share a point (exact).
template <class T>
bool triangles_meet_exact(const locus::Triangle3<T>& a, const locus::Triangle3<T>& b) {
  return max_over_common_points(a, b, {0, 0, 0, 0, 0, 0}).has_value();
}

}  // namespace locus_test
