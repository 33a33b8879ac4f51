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
#include <locus/numeric/detail/function_ref.hpp>
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
namespace detail::calculus {
template <Real T>
[[nodiscard]] CriticalPoints2<T> critical_points_2d_ref(FunctionRef<T(Vec2<T>)> f,
                                                        FunctionRef<Vec2<T>(Vec2<T>)> grad,
                                                        FunctionRef<Mat2<T>(Vec2<T>)> hess,
                                                        const Vec2<T>& lo, const Vec2<T>& hi,
                                                        const CriticalPointOptions<T>& opt);
}  // namespace detail::calculus

template <Real T, class F, class G, class H>
requires std::is_invocable_r_v<T, F&, Vec2<T>> && std::is_invocable_r_v<Vec2<T>, G&, Vec2<T>>&&
    std::is_invocable_r_v<Mat2<T>, H&, Vec2<T>> [[nodiscard]] CriticalPoints2<T>
    critical_points_2d(F&& f, G&& grad, H&& hess, const Vec2<T>& lo, const Vec2<T>& hi,
                       const CriticalPointOptions<T>& opt = {}) {
  return detail::calculus::critical_points_2d_ref<T>(f, grad, hess, lo, hi, opt);
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
namespace detail::calculus {
template <Real T>
[[nodiscard]] CriticalPoints1<T> critical_points_1d_ref(FunctionRef<T(T)> f, FunctionRef<T(T)> df,
                                                        T a, T b,
                                                        const CriticalPoints1Options& opt);
}  // namespace detail::calculus

template <Real T, class F, class DF>
requires std::is_invocable_r_v<T, F&, T> && std::is_invocable_r_v<T, DF&, T>
[[nodiscard]] CriticalPoints1<T> critical_points_1d(F&& f, DF&& df, T a, std::type_identity_t<T> b,
                                                    const CriticalPoints1Options& opt = {}) {
  return detail::calculus::critical_points_1d_ref<T>(f, df, a, b, opt);
}

}  // namespace locus
