// SPDX-License-Identifier: BSL-1.0
// Level sets and critical points (numeric/calculus.hpp; row num.calculus), compiled once for
// float and double; the callables arrive as detail::FunctionRef. Methods: docs/notes/numeric.md.

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

namespace detail::calculus {

template <class T, class F>
void absolute_extrema(CriticalPoints1<T>& r, F&& f, T a, T b) {
  const auto consider = [&](T x, T v) {
    if (!locus::is_finite(v)) return;
    if (!locus::is_finite(r.min_value) || v < r.min_value) {
      r.min_x = x;
      r.min_value = v;
    }
    if (!locus::is_finite(r.max_value) || v > r.max_value) {
      r.max_x = x;
      r.max_value = v;
    }
  };
  r.min_value = r.max_value = std::numeric_limits<T>::quiet_NaN();
  r.min_x = r.max_x = a;
  consider(a, f(a));
  for (const auto& p : r.points) consider(p.x, p.value);
  consider(b, f(b));
}

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

namespace detail::calculus {
template <Real T>
CriticalPoints2<T> critical_points_2d_ref(FunctionRef<T(Vec2<T>)> f,
                                          FunctionRef<Vec2<T>(Vec2<T>)> grad,
                                          FunctionRef<Mat2<T>(Vec2<T>)> hess, const Vec2<T>& lo,
                                          const Vec2<T>& hi, const CriticalPointOptions<T>& opt) {
  using C = compute_t<T>;
  CriticalPoints2<T> out;
  out.status = Status::ok;
  if (!is_finite(lo) || !is_finite(hi)) {
    out.status = Status::non_finite_input;
    return out;
  }
  if (!(lo.x < hi.x) || !(lo.y < hi.y) || opt.seeds_x < 1 || opt.seeds_y < 1 ||
      opt.max_iterations < 1 || opt.max_points < 1) {
    out.status = Status::invalid_input;
    return out;
  }
  const C dx = C(hi.x) - C(lo.x), dy = C(hi.y) - C(lo.y);
  const C diag = std::sqrt(dx * dx + dy * dy);
  const C accept_step = std::sqrt(C(eps_v<T>)) * diag;
  const C merge = C(opt.merge_tolerance) * diag;
  struct Found {
    Vec2<T> x;
    C gnorm;
  };
  std::vector<Found> found;
  C hscale = C(0);
  bool any_finite = false, limit = false;
  const auto gnorm_at = [&](const Vec2<T>& x, Vec2<C>& g) -> bool {
    const Vec2<T> gt = grad(x);
    g = {C(gt.x), C(gt.y)};
    return is_finite(g);
  };
  for (int sj = 0; sj < opt.seeds_y; ++sj) {
    for (int si = 0; si < opt.seeds_x; ++si) {
      Vec2<T> x{static_cast<T>(C(lo.x) + dx * (C(si) + C(0.5)) / C(opt.seeds_x)),
                static_cast<T>(C(lo.y) + dy * (C(sj) + C(0.5)) / C(opt.seeds_y))};
      Vec2<C> g;
      if (!gnorm_at(x, g)) continue;
      C last_step = std::numeric_limits<C>::infinity();
      bool ok = true;
      for (int it = 0; it < opt.max_iterations; ++it) {
        const Mat2<T> ht = hess(x);
        if (!is_finite(ht)) {
          ok = false;
          break;
        }
        any_finite = true;
        for (int r = 0; r < 2; ++r)
          for (int c = 0; c < 2; ++c) hscale = std::max(hscale, C(std::abs(ht(r, c))));
        const C off = (C(ht(0, 1)) + C(ht(1, 0))) / C(2);
        const Mat2<C> hc = Mat2<C>::from_rows(Vec2<C>{C(ht(0, 0)), off}, Vec2<C>{off, C(ht(1, 1))});
        const auto eig = eigen_symmetric(hc);
        const C lmax = std::max(std::abs(eig.values[0]), std::abs(eig.values[1]));
        Vec2<C> d{};
        for (int k = 0; k < 2; ++k) {
          const C lk = eig.values[k];
          if (!(std::abs(lk) > C(1e-12) * lmax)) continue;
          const Vec2<C> vk{eig.vectors(0, k), eig.vectors(1, k)};
          d -= (dot(vk, g) / lk) * vk;
        }
        C len = length(d);
        if (!(len > C(0))) {
          last_step = C(0);
          break;
        }
        if (len > diag) {
          d *= diag / len;
          len = diag;
        }
        const C g0 = length(g);
        C alpha = C(1);
        Vec2<T> xn{};
        Vec2<C> gn{};
        bool moved = false;
        for (int bt = 0; bt < 30; ++bt) {
          xn = {static_cast<T>(C(x.x) + alpha * d.x), static_cast<T>(C(x.y) + alpha * d.y)};
          if (!gnorm_at(xn, gn)) {
            alpha /= C(2);
            continue;
          }
          // Close to convergence |g| is rounding noise: take the full Newton step.
          if (length(gn) <= g0 || alpha * len <= accept_step) {
            moved = true;
            break;
          }
          alpha /= C(2);
        }
        if (!moved) break;
        last_step = alpha * len;
        const bool same = xn == x;
        x = xn;
        g = gn;
        if (same ||
            last_step <= C(4) * C(eps_v<T>) * (std::max(std::abs(C(x.x)), std::abs(C(x.y))) + diag))
          break;
      }
      if (!ok || !(last_step <= accept_step)) continue;
      if (C(x.x) < C(lo.x) - merge || C(x.x) > C(hi.x) + merge || C(x.y) < C(lo.y) - merge ||
          C(x.y) > C(hi.y) + merge)
        continue;
      const C gl = length(g);
      bool merged = false;
      for (Found& fd : found) {
        if (std::hypot(C(fd.x.x) - C(x.x), C(fd.x.y) - C(x.y)) <= merge) {
          if (gl < fd.gnorm) fd = {x, gl};
          merged = true;
          break;
        }
      }
      if (!merged) {
        if (static_cast<int>(found.size()) >= opt.max_points)
          limit = true;
        else
          found.push_back({x, gl});
      }
    }
  }
  if (!any_finite) {
    out.status = Status::non_finite_input;
    return out;
  }
  const T tau = static_cast<T>(C(opt.degenerate_tolerance) * hscale);
  for (const Found& fd : found) {
    const auto cls = classify_critical_point(hess(fd.x), tau);
    out.points.push_back({fd.x, f(fd.x), cls.kind, cls.eigenvalues});
  }
  std::sort(out.points.begin(), out.points.end(), [](const auto& a, const auto& b) {
    return a.point.x < b.point.x || (a.point.x == b.point.x && a.point.y < b.point.y);
  });
  if (limit) out.status = Status::limit_exceeded;
  return out;
}
}  // namespace detail::calculus

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

namespace detail::calculus {
template <Real T>
CriticalPoints1<T> critical_points_1d_ref(FunctionRef<T(T)> f, FunctionRef<T(T)> df, T a, T b,
                                          const CriticalPoints1Options& opt) {
  using C = compute_t<T>;
  CriticalPoints1<T> r;
  r.status = Status::ok;
  r.min_value = r.max_value = std::numeric_limits<T>::quiet_NaN();
  if (!locus::is_finite(a) || !locus::is_finite(b)) {
    r.status = Status::non_finite_input;
    return r;
  }
  if (a > b || opt.samples < 1 || opt.max_iterations < 1) {
    r.status = Status::invalid_input;
    return r;
  }
  const int n = opt.samples;
  std::vector<T> xs(static_cast<std::size_t>(n) + 1);
  std::vector<C> ds(static_cast<std::size_t>(n) + 1);
  bool nonfinite = false, limit = false;
  for (int i = 0; i <= n; ++i) {
    const T x = i == n ? b : static_cast<T>(C(a) + (C(b) - C(a)) * C(i) / C(n));
    xs[static_cast<std::size_t>(i)] = x;
    ds[static_cast<std::size_t>(i)] = C(df(x));
    nonfinite = nonfinite || !locus::is_finite(ds[static_cast<std::size_t>(i)]);
  }
  const auto sgn = [](C v) { return v > C(0) ? 1 : (v < C(0) ? -1 : 0); };
  for (int i = 0; i <= n; ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    const C d = ds[k];
    if (!locus::is_finite(d)) continue;
    if (d == C(0)) {
      if (i == 0 || i == n) continue;  // an endpoint is an extremum candidate anyway
      const C dl = ds[k - 1], dr = ds[k + 1];
      if (!locus::is_finite(dl) || !locus::is_finite(dr)) continue;
      CriticalKind kind = CriticalKind::inflection;
      if (sgn(dl) < 0 && sgn(dr) > 0)
        kind = CriticalKind::minimum;
      else if (sgn(dl) > 0 && sgn(dr) < 0)
        kind = CriticalKind::maximum;
      r.points.push_back({xs[k], f(xs[k]), kind, 1});
      continue;
    }
    if (i == n) continue;
    const C dn = ds[k + 1];
    if (!locus::is_finite(dn) || dn == C(0) || sgn(d) == sgn(dn)) continue;
    // Illinois regula falsi with bisection whenever the secant point is not well inside.
    C lo = C(xs[k]), hi = C(xs[k + 1]), flo = d, fhi = dn;
    int side = 0;
    T x = xs[k];
    bool done = false;
    for (int it = 0; it < opt.max_iterations; ++it) {
      C m = (lo * fhi - hi * flo) / (fhi - flo);
      if (!(m > lo && m < hi) || !locus::is_finite(m) || it % 4 == 3) m = (lo + hi) / C(2);
      const T xm = static_cast<T>(m);
      if (C(xm) <= lo || C(xm) >= hi) {
        x = std::abs(flo) <= std::abs(fhi) ? static_cast<T>(lo) : static_cast<T>(hi);
        done = true;
        break;
      }
      const C fm = C(df(xm));
      if (fm != fm) {
        // f' undefined inside the bracket: report the point met, flag the status.
        nonfinite = true;
        x = xm;
        done = true;
        break;
      }
      if (fm == C(0)) {
        x = xm;
        done = true;
        break;
      }
      if (sgn(fm) == sgn(flo)) {
        lo = C(xm);
        flo = fm;
        if (side == -1) fhi /= C(2);
        side = -1;
      } else {
        hi = C(xm);
        fhi = fm;
        if (side == 1) flo /= C(2);
        side = 1;
      }
      x = static_cast<T>((lo + hi) / C(2));
    }
    if (!done) limit = true;
    r.points.push_back({x, f(x), sgn(d) < 0 ? CriticalKind::minimum : CriticalKind::maximum, 1});
  }
  std::sort(r.points.begin(), r.points.end(),
            [](const auto& p, const auto& q) { return p.x < q.x; });
  detail::calculus::absolute_extrema(r, f, a, b);
  if (nonfinite)
    r.status = Status::non_finite_input;
  else if (limit)
    r.status = Status::limit_exceeded;
  return r;
}
}  // namespace detail::calculus

#define LOCUS_CALCULUS_INSTANTIATE(T)                                                        \
  template LevelSet<T> level_set<T>(const ScalarGrid<T>&, std::type_identity_t<T>,           \
                                    const LevelSetOptions&);                                 \
  template CriticalPoints2<T> critical_points_2d<T>(const ScalarGrid<T>&,                    \
                                                    const CriticalPointOptions<T>&);         \
  template CriticalPoints1<T> critical_points<T>(const Polynomial<T>&, T,                    \
                                                 std::type_identity_t<T>);                   \
  template CriticalPoints2<T> detail::calculus::critical_points_2d_ref<T>(                   \
      FunctionRef<T(Vec2<T>)>, FunctionRef<Vec2<T>(Vec2<T>)>, FunctionRef<Mat2<T>(Vec2<T>)>, \
      const Vec2<T>&, const Vec2<T>&, const CriticalPointOptions<T>&);                       \
  template CriticalPoints1<T> detail::calculus::critical_points_1d_ref<T>(                   \
      FunctionRef<T(T)>, FunctionRef<T(T)>, T, T, const CriticalPoints1Options&);
LOCUS_CALCULUS_INSTANTIATE(float)
LOCUS_CALCULUS_INSTANTIATE(double)
#undef LOCUS_CALCULUS_INSTANTIATE

}  // namespace locus
