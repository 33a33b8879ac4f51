// SPDX-License-Identifier: BSL-1.0
#pragma once
// Level sets and critical points (row num.calculus; book appendix A.7-A.8, figures A.2-A.17).
// Methods and accuracy: docs/notes/numeric.md.
// ScalarGrid<T> holds f on a regular grid, values[j * nx + i] = f at origin + (i * spacing.x,
// j * spacing.y); sample_grid(f, lo, hi, nx, ny) builds one from a callable T f(Vec2<T>).
// level_set(grid, level)  marching squares -> polylines. A sample is ABOVE when f >= level (a
//   contour through a grid vertex passes exactly through it); saddle cells follow the bilinear
//   interpolant (asymptotic decider; SaddleRule::center_average uses the corners' mean). The
//   above region is on the LEFT of travel (x right, y up: counter-clockwise around a maximum).
//   Closed loops do not repeat their first point; open polylines end on the grid boundary or a
//   skipped cell; an extremum exactly at the level on a vertex is a closed contour of one point.
// Critical points (grad f = 0) are classified by the Hessian's eigenvalues against tau =
//   degenerate_tolerance * (a Hessian scale): minimum, maximum, saddle or degenerate.
//   critical_points_2d(f, grad, hess, lo, hi): damped Newton from a grid of seeds in the box,
//   merged within merge_tolerance * |box|, sorted by x then y. critical_points_2d(grid): the
//   central-difference quadratic model at each interior vertex, reported in its own cell.
//   critical_points(Polynomial p, a, b): roots of p' in [a, b] with multiplicities (odd: min/max,
//   even: inflection). critical_points_1d(f, df, a, b): sign changes of f' over `samples` + 1
//   points, refined (cusps with infinite f' included); zeros without a sign change are not seen.
// Bad input (every loop budgeted): bad sizes -> empty_input / invalid_input; non-finite level,
// box, bounds or coefficients -> non_finite_input; NaN samples or evaluations are skipped (holes)
// with status non_finite_input and the finite part's results; more than max_points points ->
// limit_exceeded with the first ones; a constant polynomial -> degenerate_input.
// Precision: computed in compute_t<T> (double for float); callables get points of type T.
// Cost: level_set O(nx ny) time and memory; critical_points_2d O(seeds * max_iterations)
// evaluations plus O(k^2) merging of k points; grid version O(nx ny).

#include <locus/core/mat.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/numeric/eigen_sym.hpp>
#include <locus/numeric/polynomial.hpp>
#include <locus/numeric/roots.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

namespace locus {

// ---------------------------------------------------------------------------------------------
// Sampled functions and level sets
// ---------------------------------------------------------------------------------------------

/// f sampled on a regular grid: values[j * nx + i] = f(origin + (i spacing.x, j spacing.y)).
template <Real T>
struct ScalarGrid {
  std::vector<T> values;
  int nx = 0;  ///< samples along x
  int ny = 0;  ///< samples along y
  Vec2<T> origin{};
  Vec2<T> spacing{T(1), T(1)};

  [[nodiscard]] T at(int i, int j) const {
    LOCUS_ASSERT(i >= 0 && i < nx && j >= 0 && j < ny, "ScalarGrid index out of range");
    return values[static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) +
                  static_cast<std::size_t>(i)];
  }
  [[nodiscard]] Vec2<T> position(int i, int j) const noexcept {
    return {origin.x + static_cast<T>(i) * spacing.x, origin.y + static_cast<T>(j) * spacing.y};
  }
};

/// Samples f at nx x ny points spanning [lo, hi] (spacing (hi - lo) / (n - 1)). nx or ny < 2,
/// or a box that is not finite with lo < hi, gives an empty grid (nx = ny = 0).
template <Real T, class F>
requires std::is_invocable_r_v<T, F&, Vec2<T>>
[[nodiscard]] ScalarGrid<T> sample_grid(F&& f, const Vec2<T>& lo, const Vec2<T>& hi, int nx,
                                        int ny) {
  ScalarGrid<T> g;
  if (nx < 2 || ny < 2 || !is_finite(lo) || !is_finite(hi) || !(lo.x < hi.x) || !(lo.y < hi.y))
    return g;
  g.nx = nx;
  g.ny = ny;
  g.origin = lo;
  g.spacing = {(hi.x - lo.x) / static_cast<T>(nx - 1), (hi.y - lo.y) / static_cast<T>(ny - 1)};
  g.values.resize(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      g.values[static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) +
               static_cast<std::size_t>(i)] = f(g.position(i, j));
  return g;
}

/// How marching squares resolves a cell whose diagonal corners agree.
enum class SaddleRule : std::uint8_t {
  asymptotic_decider,  ///< the bilinear interpolant's saddle value (topologically faithful)
  center_average,      ///< the mean of the four corner samples
};

struct LevelSetOptions {
  SaddleRule saddle = SaddleRule::asymptotic_decider;
};

/// One connected piece of a level set.
template <Real T>
struct Contour {
  std::vector<Vec2<T>> points;  ///< f >= level on the left; a loop does not repeat points[0]
  bool closed = false;
};

template <Real T>
struct LevelSet {
  Status status = Status::empty_input;
  std::vector<Contour<T>> contours;

  [[nodiscard]] int closed_count() const noexcept {
    int n = 0;
    for (const auto& c : contours) n += c.closed ? 1 : 0;
    return n;
  }
};

/// The level set f = level of a sampled function by marching squares (see the header comment).
template <Real T>
[[nodiscard]] LevelSet<T> level_set(const ScalarGrid<T>& grid, std::type_identity_t<T> level,
                                    const LevelSetOptions& opt = {});

// ---------------------------------------------------------------------------------------------
// Critical points
// ---------------------------------------------------------------------------------------------

enum class CriticalKind : std::uint8_t {
  minimum,     ///< relative minimum
  maximum,     ///< relative maximum
  saddle,      ///< 2D: Hessian eigenvalues of opposite signs
  inflection,  ///< 1D: f' = 0 without a sign change (stationary inflection point)
  degenerate,  ///< 2D: a Hessian eigenvalue within the tolerance of zero (test inconclusive)
};

/// Classification of a critical point by its Hessian: the eigenvalues (ascending) and the kind,
/// degenerate when an eigenvalue has magnitude <= tau (and when the matrix is not finite).
template <Real T>
struct HessianClass {
  CriticalKind kind = CriticalKind::degenerate;
  Vec2<T> eigenvalues{};
};

template <Real T>
[[nodiscard]] HessianClass<T> classify_critical_point(const Mat2<T>& hessian,
                                                      std::type_identity_t<T> tau) noexcept {
  HessianClass<T> r;
  // Symmetrise first: a user Hessian with rounded, slightly different mixed partials is fine.
  const T off = (hessian(0, 1) + hessian(1, 0)) / T(2);
  const Mat2<T> h = Mat2<T>::from_rows(Vec2<T>{hessian(0, 0), off}, Vec2<T>{off, hessian(1, 1)});
  const auto eig = eigen_symmetric(h);
  r.eigenvalues = eig.values;
  if (eig.status == Status::non_finite_input) return r;
  const T l0 = eig.values[0], l1 = eig.values[1];
  if (std::abs(l0) <= tau || std::abs(l1) <= tau)
    r.kind = CriticalKind::degenerate;
  else if (l0 > T(0))
    r.kind = CriticalKind::minimum;
  else if (l1 < T(0))
    r.kind = CriticalKind::maximum;
  else
    r.kind = CriticalKind::saddle;
  return r;
}

template <Real T>
struct CriticalPoint2 {
  Vec2<T> point{};
  T value = T(0);  ///< f at the point
  CriticalKind kind = CriticalKind::degenerate;
  Vec2<T> eigenvalues{};  ///< of the Hessian, ascending
};

template <Real T>
struct CriticalPoints2 {
  Status status = Status::empty_input;
  std::vector<CriticalPoint2<T>> points;  ///< sorted by x, then y
};

template <Real T>
struct CriticalPointOptions {
  int seeds_x = 12;  ///< Newton seeds along x (cell centres of a seeds_x x seeds_y grid)
  int seeds_y = 12;
  int max_iterations = 60;  ///< Newton steps per seed
  /// Eigenvalues with magnitude <= this times the Hessian scale make a point degenerate.
  T degenerate_tolerance = std::sqrt(eps_v<T>);
  /// Points closer than this times the box diagonal are one critical point.
  T merge_tolerance = std::sqrt(eps_v<T>);
  int max_points = 1024;
};

/// Critical points of a smooth f in the box [lo, hi] by Newton's method on grad f = 0 from a
/// grid of seeds; grad(p) returns Vec2<T>, hess(p) a symmetric Mat2<T>.
template <Real T, class F, class G, class H>
requires std::is_invocable_r_v<T, F&, Vec2<T>> && std::is_invocable_r_v<Vec2<T>, G&, Vec2<T>>&&
    std::is_invocable_r_v<Mat2<T>, H&, Vec2<T>> [[nodiscard]] CriticalPoints2<T>
    critical_points_2d(F&& f, G&& grad, H&& hess, const Vec2<T>& lo, const Vec2<T>& hi,
                       const CriticalPointOptions<T>& opt = {}) {
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

/// Critical points of a sampled f: stationary points of the central-difference quadratic model
/// at each interior vertex that fall in the vertex's own cell (see the header comment).
template <Real T>
[[nodiscard]] CriticalPoints2<T> critical_points_2d(const ScalarGrid<T>& grid,
                                                    const CriticalPointOptions<T>& opt = {});

/// A critical point of a function of one variable.
template <Real T>
struct CriticalPoint1 {
  T x = T(0);
  T value = T(0);
  CriticalKind kind = CriticalKind::inflection;
  int multiplicity = 1;  ///< as a root of f' (polynomial version; 1 otherwise)
};

template <Real T>
struct CriticalPoints1 {
  Status status = Status::empty_input;
  std::vector<CriticalPoint1<T>> points;  ///< increasing x, interior and endpoints alike
  T min_x = T(0), min_value = T(0);       ///< absolute minimum on [a, b] (endpoints included)
  T max_x = T(0), max_value = T(0);       ///< absolute maximum on [a, b]
};

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

/// Critical points of the polynomial p on [a, b] (roots of p') and its absolute extrema there.
template <Real T>
[[nodiscard]] CriticalPoints1<T> critical_points(const Polynomial<T>& p, T a,
                                                 std::type_identity_t<T> b);

struct CriticalPoints1Options {
  int samples = 256;         ///< sub-intervals on which f' is sampled for sign changes
  int max_iterations = 200;  ///< refinement steps per bracketed root of f'
};

/// Critical points of a function f on [a, b] given its derivative df: sign changes of f' on a
/// sampling, refined and classified by the direction of the change (see the header comment).
template <Real T, class F, class DF>
requires std::is_invocable_r_v<T, F&, T> && std::is_invocable_r_v<T, DF&, T>
[[nodiscard]] CriticalPoints1<T> critical_points_1d(F&& f, DF&& df, T a, std::type_identity_t<T> b,
                                                    const CriticalPoints1Options& opt = {}) {
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

}  // namespace locus
