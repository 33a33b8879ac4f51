// SPDX-License-Identifier: BSL-1.0
// Level sets and critical points (numeric/calculus.hpp; row num.calculus), compiled once for
// float and double (the routines on a user's callable stay inline templates: measured faster).
// Methods: docs/notes/numeric.md.

#include <locus/numeric/calculus.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace locus {

namespace detail::calculus {

template <Real T>
struct GridIndex {
  int nx, ny;
  std::size_t horizontal_count() const noexcept {
    return static_cast<std::size_t>(nx - 1) * static_cast<std::size_t>(ny);
  }
  // Edge (i, j)-(i+1, j).
  std::size_t h(int i, int j) const noexcept {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(nx - 1) +
           static_cast<std::size_t>(i);
  }
  // Edge (i, j)-(i, j+1).
  std::size_t v(int i, int j) const noexcept {
    return horizontal_count() + static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) +
           static_cast<std::size_t>(i);
  }
  std::size_t edge_count() const noexcept {
    return horizontal_count() + static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny - 1);
  }
};

}  // namespace detail::calculus

template <Real T>
LevelSet<T> level_set(const ScalarGrid<T>& grid, std::type_identity_t<T> level,
                      const LevelSetOptions& opt) {
  using C = compute_t<T>;
  LevelSet<T> out;
  out.status = Status::ok;
  const int nx = grid.nx, ny = grid.ny;
  if (nx < 2 || ny < 2) {
    out.status = Status::empty_input;
    return out;
  }
  if (grid.values.size() != static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny)) {
    out.status = Status::invalid_input;
    return out;
  }
  if (!locus::is_finite(level) || !is_finite(grid.origin) || !is_finite(grid.spacing)) {
    out.status = Status::non_finite_input;
    return out;
  }
  if (!(grid.spacing.x > T(0)) || !(grid.spacing.y > T(0))) {
    out.status = Status::invalid_input;
    return out;
  }
  const detail::calculus::GridIndex<T> idx{nx, ny};
  const std::size_t edges = idx.edge_count();
  std::vector<std::int64_t> next(edges, -1);
  std::vector<unsigned char> has_in(edges, 0);
  bool any_nonfinite = false;
  for (const T& v : grid.values) any_nonfinite = any_nonfinite || !locus::is_finite(v);
  const auto above = [&](T f) { return f >= level; };
  // Halves keep differences of huge samples finite; halving is exact above the subnormals.
  const C half_level = C(level) / C(2);

  for (int j = 0; j + 1 < ny; ++j) {
    for (int i = 0; i + 1 < nx; ++i) {
      const T f[4] = {grid.at(i, j), grid.at(i + 1, j), grid.at(i + 1, j + 1), grid.at(i, j + 1)};
      if (!locus::is_finite(f[0]) || !locus::is_finite(f[1]) || !locus::is_finite(f[2]) ||
          !locus::is_finite(f[3]))
        continue;  // a hole: no segments
      const bool b[4] = {above(f[0]), above(f[1]), above(f[2]), above(f[3])};
      const std::size_t e[4] = {idx.h(i, j), idx.v(i + 1, j), idx.h(i, j + 1), idx.v(i, j)};
      // Edge k runs from corner k to corner k+1 (counter-clockwise around the cell). A "down"
      // edge goes from above to below, an "up" edge from below to above; with the above
      // region on the left, every segment runs from a down edge to an up edge.
      int down[2], nd = 0;
      for (int k = 0; k < 4; ++k)
        if (b[k] && !b[(k + 1) & 3]) down[nd++] = k;
      const auto link = [&](int from, int to) {
        next[e[from]] = static_cast<std::int64_t>(e[to]);
        has_in[e[to]] = 1;
      };
      if (nd == 1) {
        for (int k = 0; k < 4; ++k)
          if (!b[k] && b[(k + 1) & 3]) link(down[0], k);
      } else if (nd == 2) {
        C g[4];
        C m = C(0);
        for (int k = 0; k < 4; ++k) {
          g[k] = C(f[k]) / C(2) - half_level;
          m = std::max(m, std::abs(g[k]));
        }
        bool centre_above;
        if (opt.saddle == SaddleRule::center_average) {
          centre_above = (g[0] + g[1] + g[2] + g[3]) >= C(0);
        } else {
          for (C& x : g) x /= m;  // m > 0: the corners differ in class
          // The saddle value's denominator g0 + g2 - g1 - g3 has the sign of "corner 0 above".
          const C num = g[0] * g[2] - g[1] * g[3];
          centre_above = (b[0] ? num : -num) >= C(0);
        }
        for (int q = 0; q < 2; ++q)
          link(down[q], centre_above ? (down[q] + 1) & 3 : (down[q] + 3) & 3);
      }
    }
  }

  // The contour vertex on edge id (one computation per edge, from its lower-index end).
  const auto vertex = [&](std::size_t id) -> Vec2<T> {
    int i0, j0, i1, j1;
    if (id < idx.horizontal_count()) {
      j0 = j1 = static_cast<int>(id / static_cast<std::size_t>(nx - 1));
      i0 = static_cast<int>(id % static_cast<std::size_t>(nx - 1));
      i1 = i0 + 1;
    } else {
      const std::size_t r = id - idx.horizontal_count();
      j0 = static_cast<int>(r / static_cast<std::size_t>(nx));
      i0 = i1 = static_cast<int>(r % static_cast<std::size_t>(nx));
      j1 = j0 + 1;
    }
    const C fa = C(grid.at(i0, j0)) / C(2), fb = C(grid.at(i1, j1)) / C(2);
    C t = (half_level - fa) / (fb - fa);
    if (!(t >= C(0))) t = C(0);
    if (t > C(1)) t = C(1);
    const Vec2<T> pa = grid.position(i0, j0), pb = grid.position(i1, j1);
    if (t == C(0)) return pa;
    if (t == C(1)) return pb;
    return {static_cast<T>(C(pa.x) + t * (C(pb.x) - C(pa.x))),
            static_cast<T>(C(pa.y) + t * (C(pb.y) - C(pa.y)))};
  };
  std::vector<unsigned char> used(edges, 0);
  const auto push = [](std::vector<Vec2<T>>& pts, const Vec2<T>& p) {
    if (pts.empty() || !(pts.back() == p)) pts.push_back(p);
  };
  // Open polylines first (they start at an edge with no incoming segment), then loops. Each
  // edge is visited once, so the walks together take at most `edges` steps.
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t s = 0; s < edges; ++s) {
      if (used[s] || next[s] < 0 || (pass == 0 && has_in[s])) continue;
      Contour<T> c;
      c.closed = pass == 1;
      std::int64_t cur = static_cast<std::int64_t>(s);
      while (cur >= 0 && !used[static_cast<std::size_t>(cur)]) {
        used[static_cast<std::size_t>(cur)] = 1;
        push(c.points, vertex(static_cast<std::size_t>(cur)));
        cur = next[static_cast<std::size_t>(cur)];
      }
      if (c.closed)
        while (c.points.size() > 1 && c.points.back() == c.points.front()) c.points.pop_back();
      out.contours.push_back(std::move(c));
    }
  }
  if (any_nonfinite) out.status = Status::non_finite_input;
  return out;
}

template <Real T>
CriticalPoints2<T> critical_points_2d(const ScalarGrid<T>& grid,
                                      const CriticalPointOptions<T>& opt) {
  using C = compute_t<T>;
  CriticalPoints2<T> out;
  out.status = Status::ok;
  const int nx = grid.nx, ny = grid.ny;
  if (nx < 3 || ny < 3) {
    out.status = Status::empty_input;
    return out;
  }
  if (grid.values.size() != static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny)) {
    out.status = Status::invalid_input;
    return out;
  }
  if (!is_finite(grid.origin) || !is_finite(grid.spacing)) {
    out.status = Status::non_finite_input;
    return out;
  }
  if (!(grid.spacing.x > T(0)) || !(grid.spacing.y > T(0))) {
    out.status = Status::invalid_input;
    return out;
  }
  const C hx = C(grid.spacing.x), hy = C(grid.spacing.y);
  struct Model {
    int i, j;
    Vec2<C> g, d;
    C fxx, fxy, fyy, f0;
  };
  std::vector<Model> cand;
  C hscale = C(0);
  bool nonfinite = false;
  for (int j = 1; j + 1 < ny; ++j) {
    for (int i = 1; i + 1 < nx; ++i) {
      C s[3][3];
      bool fin = true;
      for (int b = -1; b <= 1; ++b)
        for (int a = -1; a <= 1; ++a) {
          s[b + 1][a + 1] = C(grid.at(i + a, j + b));
          fin = fin && locus::is_finite(s[b + 1][a + 1]);
        }
      if (!fin) {
        nonfinite = true;
        continue;
      }
      Model m{i, j, {}, {}, C(0), C(0), C(0), s[1][1]};
      m.g = {(s[1][2] - s[1][0]) / (C(2) * hx), (s[2][1] - s[0][1]) / (C(2) * hy)};
      m.fxx = (s[1][2] - C(2) * s[1][1] + s[1][0]) / (hx * hx);
      m.fyy = (s[2][1] - C(2) * s[1][1] + s[0][1]) / (hy * hy);
      m.fxy = (s[2][2] - s[0][2] - s[2][0] + s[0][0]) / (C(4) * hx * hy);
      hscale = std::max({hscale, std::abs(m.fxx), std::abs(m.fyy), std::abs(m.fxy)});
      const C det = m.fxx * m.fyy - m.fxy * m.fxy;
      const C mag = std::max({std::abs(m.fxx * m.fyy), m.fxy * m.fxy});
      if (!(std::abs(det) > C(64) * std::numeric_limits<C>::epsilon() * mag)) continue;
      m.d = {-(m.fyy * m.g.x - m.fxy * m.g.y) / det, -(-m.fxy * m.g.x + m.fxx * m.g.y) / det};
      if (!(m.d.x > -hx / C(2) && m.d.x <= hx / C(2) && m.d.y > -hy / C(2) && m.d.y <= hy / C(2)))
        continue;
      cand.push_back(m);
      if (static_cast<int>(cand.size()) > opt.max_points) break;
    }
  }
  if (static_cast<int>(cand.size()) > opt.max_points) {
    cand.resize(static_cast<std::size_t>(opt.max_points));
    out.status = Status::limit_exceeded;
  }
  const T tau = static_cast<T>(C(opt.degenerate_tolerance) * hscale);
  for (const Model& m : cand) {
    const Vec2<T> p = grid.position(m.i, m.j);
    const Vec2<T> x{static_cast<T>(C(p.x) + m.d.x), static_cast<T>(C(p.y) + m.d.y)};
    const C value = m.f0 + dot(m.g, m.d) / C(2);  // f0 + g.d + d^T H d / 2 with H d = -g
    const auto cls = classify_critical_point(
        Mat2<T>::from_rows(Vec2<T>{static_cast<T>(m.fxx), static_cast<T>(m.fxy)},
                           Vec2<T>{static_cast<T>(m.fxy), static_cast<T>(m.fyy)}),
        tau);
    out.points.push_back({x, static_cast<T>(value), cls.kind, cls.eigenvalues});
  }
  std::sort(out.points.begin(), out.points.end(), [](const auto& a, const auto& b) {
    return a.point.x < b.point.x || (a.point.x == b.point.x && a.point.y < b.point.y);
  });
  if (nonfinite && out.status == Status::ok) out.status = Status::non_finite_input;
  return out;
}

template <Real T>
CriticalPoints1<T> critical_points(const Polynomial<T>& p, T a, std::type_identity_t<T> b) {
  CriticalPoints1<T> r;
  r.status = Status::ok;
  if (!locus::is_finite(a) || !locus::is_finite(b) || !is_finite(p)) {
    r.status = Status::non_finite_input;
    r.min_value = r.max_value = std::numeric_limits<T>::quiet_NaN();
    return r;
  }
  if (a > b) {
    r.status = Status::invalid_input;
    r.min_value = r.max_value = std::numeric_limits<T>::quiet_NaN();
    return r;
  }
  const Polynomial<T> dp = derivative(p);
  if (dp.degree() < 0) {
    r.status = Status::degenerate_input;
  } else {
    // Near mode: p' is rounded data (and a turning point of p' within noise of zero is a
    // degenerate critical point of p for every purpose here); it also keeps this fast.
    const auto roots = real_roots(dp, a, b, near_roots());
    if (roots.status == Status::limit_exceeded) r.status = Status::limit_exceeded;
    for (const auto& rt : roots.roots) {
      CriticalPoint1<T> c{rt.value, p(rt.value), CriticalKind::inflection, rt.multiplicity};
      if (rt.multiplicity % 2 == 1) {
        Polynomial<T> q = dp;
        for (int k = 0; k < rt.multiplicity; ++k) q = derivative(q);
        // The first non-vanishing derivative of p' decides the direction of its sign change.
        c.kind = q(rt.value) > T(0) ? CriticalKind::minimum : CriticalKind::maximum;
      }
      r.points.push_back(c);
    }
  }
  detail::calculus::absolute_extrema(
      r, [&](T x) { return p(x); }, a, b);
  return r;
}

#define LOCUS_CALCULUS_INSTANTIATE(T)                                                \
  template LevelSet<T> level_set<T>(const ScalarGrid<T>&, std::type_identity_t<T>,   \
                                    const LevelSetOptions&);                         \
  template CriticalPoints2<T> critical_points_2d<T>(const ScalarGrid<T>&,            \
                                                    const CriticalPointOptions<T>&); \
  template CriticalPoints1<T> critical_points<T>(const Polynomial<T>&, T, std::type_identity_t<T>);
LOCUS_CALCULUS_INSTANTIATE(float)
LOCUS_CALCULUS_INSTANTIATE(double)
#undef LOCUS_CALCULUS_INSTANTIATE

}  // namespace locus
