// SPDX-License-Identifier: BSL-1.0
#pragma once
// Internal machinery of point_quadratic_curve.hpp (N = 2) and point_quadric.hpp (N = 3): the
// point nearest to p on the quadric Q(X) = X^T A X + B . X + c = 0 by Lagrange's condition.
//
// In the frame X = p + R y (R the eigenvectors of A, eigenvalues l_i) the quadric reads
// sum_i l_i y_i^2 + beta . y + gamma = 0 with beta = R^T (2 A p + B), gamma = Q(p). A critical
// point of |y|^2 on it satisfies y + t (2 L y + beta) = 0, i.e. y_i = -t beta_i / D_i, D_i = 1 + 2
// l_i t, and substituting gives the polynomial (degree 2N)
//   gamma prod_j D_j^2 - sum_i t beta_i^2 (1 + l_i t) prod_{j != i} D_j^2 = 0,
// formed with a coefficient error bound and solved for ALL real roots by numeric/roots.hpp. The
// roots miss exactly the critical points with D_i = 0 (p on a symmetry plane of the quadric:
// beta_i = 0, the textbook failure); those are added directly: t = -1 / (2 l_i), the other
// coordinates from the formula, the free one(s) from the equation (two symmetric candidates).
// The singular point of cones and line/plane pairs (grad Q = 0; pseudo-inverse stationary point)
// is a candidate too. Every candidate is moved onto the quadric by Newton steps along grad Q
// (so each is a true point of the surface, up to rounding), polished by at most 40 safeguarded
// tangent steps (a candidate from an ill-conditioned root slides into its minimum; nearly
// degenerate quadrics such as a rounded cone), and the nearest wins; a distinct
// candidate at the same distance (64 eps relative) makes the answer non-unique.
// Computed in compute_t<T>; cost O(1): one N x N eigen-decomposition, one root solve of degree
// 2N, at most 4N + 2 candidates, each projected and polished (typically a few steps).

#include <locus/core/mat.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/rational_span.hpp>
#include <locus/numeric/eigen_sym.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace locus::detail {

/// A polynomial of degree <= 6 in t with absolute-value twin (for its error bound).
template <class C>
struct SmallPoly {
  C c[7]{};
  C a[7]{};
};

template <class C>
[[nodiscard]] constexpr SmallPoly<C> small_mul(const SmallPoly<C>& x,
                                               const SmallPoly<C>& y) noexcept {
  SmallPoly<C> r;
  for (int i = 0; i < 7; ++i)
    for (int j = 0; i + j < 7; ++j) {
      r.c[i + j] += x.c[i] * y.c[j];
      r.a[i + j] += x.a[i] * y.a[j];
    }
  return r;
}

/// The quadric X^T A X + B . X + c in compute precision (A symmetric).
template <class C, int N>
struct QuadricN {
  Mat<C, N, N> a;
  Vec<C, N> b;
  C c;

  [[nodiscard]] C value(const Vec<C, N>& x) const noexcept { return dot(x, a * x) + dot(b, x) + c; }
  [[nodiscard]] Vec<C, N> gradient(const Vec<C, N>& x) const noexcept { return C(2) * (a * x) + b; }
  /// sum of |terms|, the scale of value()'s rounding error.
  [[nodiscard]] C value_abs(const Vec<C, N>& x) const noexcept {
    C s = std::fabs(c);
    for (int i = 0; i < N; ++i) {
      s += std::fabs(b[i] * x[i]);
      for (int j = 0; j < N; ++j) s += std::fabs(a.a[i][j] * x[i] * x[j]);
    }
    return s;
  }
  /// x lies on the quadric to rounding: |value| <= 256 eps * value_abs (and x is finite).
  [[nodiscard]] bool contains(const Vec<C, N>& x) const noexcept {
    return is_finite(x) &&
           std::fabs(value(x)) <= C(256) * std::numeric_limits<C>::epsilon() * value_abs(x);
  }
};

/// The point p + sum_i y_i axis_i with y_i = -beta_i / (2 l_i) for the `rank` largest |l_i|
/// (0 otherwise): the stationary point of Q nearest to p's frame origin; for a quadric that is an
/// affine subspace counted twice (double line or plane, line, point) it is the projection of p.
template <class C, int N>
[[nodiscard]] inline Vec<C, N> quadric_pseudo_center(const QuadricN<C, N>& q, const Vec<C, N>& p,
                                                     int rank) noexcept {
  const SymmetricEigen<C, N> eg = eigen_symmetric(q.a);
  int order[N];
  for (int i = 0; i < N; ++i) order[i] = i;
  std::sort(order, order + N,
            [&](int x, int y) { return std::fabs(eg.values[x]) > std::fabs(eg.values[y]); });
  const Vec<C, N> g0 = q.gradient(p);
  Vec<C, N> x = p;
  for (int k = 0; k < rank; ++k) {
    const int i = order[k];
    const Vec<C, N> ax = col(eg.vectors, i);
    x += (-dot(ax, g0) / (C(2) * eg.values[i])) * ax;
  }
  return x;
}

/// Newton steps along the gradient onto Q = 0 (at most 6; stops at a zero gradient).
template <class C, int N>
[[nodiscard]] inline Vec<C, N> project_onto(const QuadricN<C, N>& q, Vec<C, N> x) noexcept {
  for (int it = 0; it < 6; ++it) {
    const C v = q.value(x);
    if (v == C(0)) break;
    const Vec<C, N> g = q.gradient(x);
    const C g2 = sqr_length(g);
    if (!(g2 > C(0)) || !is_finite(g2)) break;
    const Vec<C, N> nx = x - (v / g2) * g;
    if (!is_finite(nx)) break;
    if (nx == x) break;
    x = nx;
  }
  return x;
}

/// Nearest point of the quadric to p by the Lagrange polynomial and the special candidates.
/// rank: the number of non-zero eigenvalues of A (from the exact classification).
template <class C, int N>
[[nodiscard]] inline NearestTracker<C, N> quadric_nearest(const QuadricN<C, N>& q,
                                                          const Vec<C, N>& p, int rank,
                                                          C tie_sep2) noexcept {
  NearestTracker<C, N> tr;
  tr.sep2 = tie_sep2;
  const SymmetricEigen<C, N> eg = eigen_symmetric(q.a);
  // Zero out the eigenvalues the classification says are zero (the smallest in magnitude).
  C lam[N];
  int order[N];
  for (int i = 0; i < N; ++i) {
    lam[i] = eg.values[i];
    order[i] = i;
  }
  std::sort(order, order + N, [&](int x, int y) { return std::fabs(lam[x]) > std::fabs(lam[y]); });
  for (int k = rank; k < N; ++k) lam[order[k]] = C(0);
  Vec<C, N> axis[N];
  for (int i = 0; i < N; ++i) axis[i] = col(eg.vectors, i);
  const Vec<C, N> g0 = q.gradient(p);
  C beta[N], beta_abs[N];
  for (int i = 0; i < N; ++i) {
    beta[i] = dot(axis[i], g0);
    C s = C(0);
    for (int k = 0; k < N; ++k) {
      C row = std::fabs(q.b[k]);
      for (int j = 0; j < N; ++j) row += C(2) * std::fabs(q.a.a[k][j] * p[j]);
      s += std::fabs(axis[i][k]) * row;
    }
    beta_abs[i] = s;
  }
  const C gamma = q.value(p), gamma_abs = q.value_abs(p);
  const auto at = [&](const C* y) {
    Vec<C, N> x = p;
    for (int i = 0; i < N; ++i) x += y[i] * axis[i];
    return x;
  };
  // Only points of the surface (to rounding) are candidates: a stationary point off the surface
  // (the centre of a hyperboloid) is not.
  const auto offer = [&](const C* y) {
    Vec<C, N> x = project_onto(q, at(y));
    if (!q.contains(x)) return;
    // Polish: tangent steps towards p, each re-projected, kept only while they get closer. A
    // candidate computed from an ill-conditioned root (nearly degenerate quadrics, clusters)
    // slides into its local minimum.
    C d2 = sqr_length(x - p);
    for (int it = 0; it < 40; ++it) {
      const Vec<C, N> gr = q.gradient(x);
      const C g2 = sqr_length(gr);
      if (!(g2 > C(0))) break;
      const Vec<C, N> r = p - x;
      Vec<C, N> step = r - (dot(r, gr) / g2) * gr;
      bool improved = false;
      for (int h = 0; h < 12 && !improved; ++h, step = C(0.5) * step) {
        const Vec<C, N> nx = project_onto(q, x + step);
        const C nd2 = sqr_length(nx - p);
        if (q.contains(nx) && nd2 < d2) {
          x = nx;
          d2 = nd2;
          improved = true;
        }
      }
      if (!improved) break;
    }
    tr.offer(d2, C(0), x);
  };

  // The Lagrange polynomial.
  SmallPoly<C> d2[N];
  for (int i = 0; i < N; ++i) {
    SmallPoly<C> d;
    d.c[0] = d.a[0] = C(1);
    d.c[1] = C(2) * lam[i];
    d.a[1] = std::fabs(d.c[1]);
    d2[i] = small_mul(d, d);
  }
  SmallPoly<C> g;
  {
    SmallPoly<C> all;
    all.c[0] = all.a[0] = C(1);
    for (int i = 0; i < N; ++i) all = small_mul(all, d2[i]);
    for (int k = 0; k < 7; ++k) {
      g.c[k] = gamma * all.c[k];
      g.a[k] = gamma_abs * all.a[k];
    }
  }
  for (int i = 0; i < N; ++i) {
    SmallPoly<C> term;
    const C b2 = beta[i] * beta[i], b2a = beta_abs[i] * beta_abs[i];
    term.c[1] = b2;
    term.a[1] = b2a;
    term.c[2] = lam[i] * b2;
    term.a[2] = std::fabs(lam[i]) * b2a;
    for (int j = 0; j < N; ++j)
      if (j != i) term = small_mul(term, d2[j]);
    for (int k = 0; k < 7; ++k) {
      g.c[k] -= term.c[k];
      g.a[k] += term.a[k];
    }
  }
  BoundedPoly<C> bp(2 * N);
  const C factor = C(64) * std::numeric_limits<C>::epsilon();
  for (int k = 0; k <= 2 * N; ++k) {
    bp.c[static_cast<std::size_t>(k)] = g.c[k];
    bp.err[static_cast<std::size_t>(k)] = factor * g.a[k];
  }
  C roots[2 * N];
  const int cnt = span_roots(bp, roots, true);
  for (int r = 0; r < cnt; ++r) {
    const C t = roots[r];
    C y[N];
    for (int i = 0; i < N; ++i) {
      const C di = C(1) + C(2) * lam[i] * t;
      y[i] = di != C(0) ? -t * beta[i] / di : C(0);
    }
    offer(y);
  }

  // Critical points with D_i = 0 (p on a symmetry plane): the free coordinates from Q = 0.
  C big = C(0);
  for (int i = 0; i < N; ++i) big = std::fmax(big, std::fabs(lam[i]));
  for (int i = 0; i < N; ++i) {
    if (lam[i] == C(0)) continue;
    const C t = C(-0.5) / lam[i];
    bool free_coord[N];
    C y[N];
    C rest = gamma;
    int first_free = -1;
    for (int j = 0; j < N; ++j) {
      free_coord[j] = std::fabs(lam[j] - lam[i]) <= C(64) * std::numeric_limits<C>::epsilon() * big;
      y[j] = C(0);
      if (free_coord[j]) {
        if (first_free < 0) first_free = j;
        continue;
      }
      const C dj = C(1) + C(2) * lam[j] * t;
      y[j] = dj != C(0) ? -t * beta[j] / dj : C(0);
      rest += lam[j] * y[j] * y[j] + beta[j] * y[j];
    }
    const C r2 = -rest / lam[i];
    if (!(r2 >= C(0))) continue;
    const C r = std::sqrt(r2);
    y[first_free] = r;
    offer(y);
    y[first_free] = -r;
    offer(y);
  }

  // The (pseudo-inverse) stationary point of Q: the apex of cones, the crossing of line pairs.
  {
    C y[N];
    for (int i = 0; i < N; ++i) y[i] = lam[i] != C(0) ? -beta[i] / (C(2) * lam[i]) : C(0);
    offer(y);
  }
  return tr;
}

}  // namespace locus::detail
