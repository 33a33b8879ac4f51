// SPDX-License-Identifier: BSL-1.0
// Bracketing, Brent's method and Powell's direction-set method (numeric/minimize.hpp; row
// num.minimize), compiled once for float and double: the user's function arrives as a
// detail::FunctionRef, Powell's point as a run-time-size array. Methods: docs/notes/numeric.md.

#include <locus/numeric/minimize.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

namespace locus {
namespace detail {
namespace {

// NaN counts as +infinity so that comparisons order it after every finite value.
template <Real T>
T sanitize_value(T v) noexcept {
  return v == v ? v : std::numeric_limits<T>::infinity();
}

constexpr double golden_ratio = 1.618033988749894848204586834365638;
constexpr double golden_section = 0.381966011250105151795413165634362;  // 2 - phi

template <class T, class F>
Bracket<T> bracket_impl(const F& f, T a, T b, int max_evaluations) {
  Bracket<T> out;
  out.status = Status::ok;
  if (!is_finite(a) || !is_finite(b)) {
    out.status = Status::non_finite_input;
    return out;
  }
  if (a == b) b = a + (a == T(0) ? T(1) : std::abs(a) * T(1e-3));
  T fa = sanitize_value(static_cast<T>(f(a)));
  T fb = sanitize_value(static_cast<T>(f(b)));
  int evals = 2;
  if (!is_finite(fa) && !is_finite(fb)) {
    out = {Status::non_finite_input, a, b, b, fa, fb, fb, evals};
    return out;
  }
  if (fb > fa) {
    std::swap(a, b);
    std::swap(fa, fb);
  }
  T c = b + T(golden_ratio) * (b - a);
  T fc = sanitize_value(static_cast<T>(f(c)));
  ++evals;
  while (!(fc > fb)) {
    if (evals >= max_evaluations || !is_finite(c)) {
      out = {Status::limit_exceeded, a, b, c, fa, fb, fc, evals};
      return out;
    }
    if (fc == fb && fb == fa) break;  // a plateau: every point of it is a minimiser
    a = b;
    fa = fb;
    b = c;
    fb = fc;
    c = b + T(golden_ratio) * (b - a);
    fc = sanitize_value(static_cast<T>(f(c)));
    ++evals;
  }
  out = {Status::ok, a, b, c, fa, fb, fc, evals};
  return out;
}

template <class T>
Minimum1<T> non_finite_minimum() noexcept {
  Minimum1<T> out;
  out.status = Status::non_finite_input;
  out.x = out.value = std::numeric_limits<T>::quiet_NaN();
  return out;
}

// Brent's localmin on [a, b] starting from the point x (f(x) = fx) inside it.
template <class T, class F>
Minimum1<T> brent_core(const F& f, T a, T b, T x, T fx, const BrentOptions<T>& opt, int evals) {
  Minimum1<T> out;
  out.status = Status::ok;
  if (a > b) std::swap(a, b);
  T w = x, v = x, fw = fx, fv = fx;
  T d = T(0), e = T(0);  // the last step and the one before it
  const T cgold = T(golden_section);
  int it = 0;
  bool converged = false;
  for (; it < opt.max_iterations; ++it) {
    const T xm = (a + b) / T(2);
    const T tol1 = opt.rel_tolerance * std::abs(x) + opt.abs_tolerance;
    const T tol2 = T(2) * tol1;
    if (std::abs(x - xm) <= tol2 - (b - a) / T(2)) {
      converged = true;
      break;
    }
    bool golden = true;
    if (std::abs(e) > tol1) {
      // Parabola through (x, fx), (w, fw), (v, fv): its vertex is x + p / q.
      const T r = (x - w) * (fx - fv);
      T q = (x - v) * (fx - fw);
      T p = (x - v) * q - (x - w) * r;
      q = T(2) * (q - r);
      if (q > T(0)) p = -p;
      q = std::abs(q);
      const T e_prev = e;
      // Accept only a step that lands inside (a, b) and is less than half the step before
      // last: this is what guarantees at least golden-section convergence.
      if (std::abs(p) < std::abs(T(0.5) * q * e_prev) && p > q * (a - x) && p < q * (b - x) &&
          is_finite(p / q)) {
        e = d;
        d = p / q;
        const T u = x + d;
        if (u - a < tol2 || b - u < tol2) d = xm >= x ? tol1 : -tol1;
        golden = false;
      }
    }
    if (golden) {
      e = x >= xm ? a - x : b - x;
      d = cgold * e;
    }
    const T u = std::abs(d) >= tol1 ? x + d : x + (d >= T(0) ? tol1 : -tol1);
    const T fu = sanitize_value(static_cast<T>(f(u)));
    ++evals;
    if (fu <= fx) {
      if (u >= x)
        a = x;
      else
        b = x;
      v = w;
      fv = fw;
      w = x;
      fw = fx;
      x = u;
      fx = fu;
    } else {
      if (u < x)
        a = u;
      else
        b = u;
      if (fu <= fw || w == x) {
        v = w;
        fv = fw;
        w = u;
        fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u;
        fv = fu;
      }
    }
  }
  out.x = x;
  out.value = fx;
  out.iterations = it;
  out.evaluations = evals;
  if (fx == std::numeric_limits<T>::infinity()) {  // every value seen was NaN or +inf
    out.status = Status::non_finite_input;
    out.value = std::numeric_limits<T>::quiet_NaN();
  } else if (!converged) {
    out.status = Status::limit_exceeded;
  }
  return out;
}

template <class T, class F>
Minimum1<T> brent_from_bracket(const F& f, const Bracket<T>& br, const BrentOptions<T>& opt) {
  if (br.status == Status::non_finite_input || !is_finite(br.a) || !is_finite(br.c))
    return non_finite_minimum<T>();
  return brent_core(f, std::min(br.a, br.c), std::max(br.a, br.c), br.b, br.fb, opt,
                    br.evaluations);
}

}  // namespace

template <Real T>
Bracket<T> bracket_minimum_ref(FunctionRef<T(T)> f, T a, T b, int max_evaluations) noexcept {
  return bracket_impl(f, a, b, max_evaluations);
}

template <Real T>
Minimum1<T> minimize_brent_ref(FunctionRef<T(T)> f, T lo, T hi,
                               const BrentOptions<T>& opt) noexcept {
  if (!is_finite(lo) || !is_finite(hi)) return non_finite_minimum<T>();
  if (lo > hi) std::swap(lo, hi);
  const T x = lo + T(golden_section) * (hi - lo);
  const T fx = sanitize_value(static_cast<T>(f(x)));
  return brent_core(f, lo, hi, x, fx, opt, 1);
}

template <Real T>
Minimum1<T> minimize_brent_ref(FunctionRef<T(T)> f, const Bracket<T>& br,
                               const BrentOptions<T>& opt) noexcept {
  return brent_from_bracket(f, br, opt);
}

namespace {

// Powell's method in dimension NC (0: the run-time n): the common small dimensions get their
// own instantiation so that the per-coordinate loops unroll as they did inline.
template <class T, std::size_t NC>
PowellRun<T> powell_impl(FunctionRef<T(const T*)> f, int n, T* x, T* work,
                         const PowellOptions<T>& opt) {
  PowellRun<T> out;
  const std::size_t un = NC > 0 ? NC : static_cast<std::size_t>(n);
  bool finite = is_finite(opt.initial_step);
  for (std::size_t k = 0; k < un; ++k) finite = finite && is_finite(x[k]);
  if (!finite) {
    out.status = Status::non_finite_input;
    out.value = std::numeric_limits<T>::quiet_NaN();
    return out;
  }
  // work: the n directions (row i is direction i), then x_start, the displacement, a probe.
  T* dir = work;
  T* x_start = work + un * un;
  T* disp = x_start + un;
  T* probe = disp + un;
  for (std::size_t i = 0; i < un; ++i)
    for (std::size_t k = 0; k < un; ++k) dir[i * un + k] = opt.initial_step * T(i == k ? 1 : 0);
  T fx = sanitize_value(static_cast<T>(f(x)));
  int evals = 1;
  if (!is_finite(fx)) {
    out.status = Status::non_finite_input;
    out.value = std::numeric_limits<T>::quiet_NaN();
    out.evaluations = evals;
    return out;
  }
  bool line_failed = false;
  // Moves x to the minimum along d; returns the decrease of f.
  const auto line_search = [&](const T* d) -> T {
    const auto g = [&](T t) {
      for (std::size_t k = 0; k < un; ++k) probe[k] = x[k] + t * d[k];
      return static_cast<T>(f(static_cast<const T*>(probe)));
    };
    const Bracket<T> br = bracket_impl(g, T(0), T(1), 64);
    evals += br.evaluations;
    const auto move = [&](T t) {
      for (std::size_t k = 0; k < un; ++k) x[k] = x[k] + t * d[k];
    };
    if (br.status != Status::ok) {
      line_failed = br.status == Status::limit_exceeded;
      // Keep the best point seen while bracketing.
      T best_t = T(0), best_f = fx;
      if (br.fa < best_f) best_t = br.a, best_f = br.fa;
      if (br.fb < best_f) best_t = br.b, best_f = br.fb;
      if (br.fc < best_f && is_finite(br.c)) best_t = br.c, best_f = br.fc;
      const T dec = fx - best_f;
      move(best_t);
      fx = best_f;
      return dec;
    }
    const Minimum1<T> m = brent_from_bracket(g, br, opt.line);
    evals += m.evaluations - br.evaluations;
    const T t = m.x, ft = m.value;
    if (!(ft < fx)) return T(0);  // no improvement: stay (also guards NaN)
    const T dec = fx - ft;
    move(t);
    fx = ft;
    return dec;
  };
  int it = 0;
  bool converged = false;
  for (; it < opt.max_iterations && evals < opt.max_evaluations && !line_failed; ++it) {
    std::copy(x, x + un, x_start);
    const T f_start = fx;
    std::size_t big_index = 0;
    T big_decrease = T(0);
    for (std::size_t i = 0; i < un; ++i) {
      const T dec = line_search(dir + i * un);
      if (dec > big_decrease) {
        big_decrease = dec;
        big_index = i;
      }
    }
    if (T(2) * (f_start - fx) <=
        opt.f_tolerance * (std::abs(f_start) + std::abs(fx)) + opt.f_abs_tolerance) {
      converged = true;
      break;
    }
    // Powell's test: adopt the net displacement as a new direction only if the extrapolated
    // point is lower and the decrease was not dominated by one direction (which would make the
    // set nearly dependent if that direction were dropped).
    for (std::size_t k = 0; k < un; ++k) {
      disp[k] = x[k] - x_start[k];
      probe[k] = x[k] + disp[k];
    }
    const T f_ext = sanitize_value(static_cast<T>(f(static_cast<const T*>(probe))));
    ++evals;
    if (f_ext < f_start) {
      const T t1 = f_start - fx - big_decrease, t2 = f_start - f_ext;
      const T lhs = T(2) * (f_start - T(2) * fx + f_ext) * t1 * t1;
      if (lhs < big_decrease * t2 * t2) {
        line_search(disp);
        std::copy(dir + (un - 1) * un, dir + un * un, dir + big_index * un);
        std::copy(disp, disp + un, dir + (un - 1) * un);
      }
    }
  }
  out.value = fx;
  out.iterations = it;
  out.evaluations = evals;
  out.status = converged ? Status::ok : Status::limit_exceeded;
  return out;
}

}  // namespace

template <Real T>
PowellRun<T> minimize_powell_ref(FunctionRef<T(const T*)> f, int n, T* x, T* work,
                                 const PowellOptions<T>& opt) noexcept {
  switch (n) {
    case 1:
      return powell_impl<T, 1>(f, n, x, work, opt);
    case 2:
      return powell_impl<T, 2>(f, n, x, work, opt);
    case 3:
      return powell_impl<T, 3>(f, n, x, work, opt);
    case 4:
      return powell_impl<T, 4>(f, n, x, work, opt);
    default:
      return powell_impl<T, 0>(f, n, x, work, opt);
  }
}

#define LOCUS_MINIMIZE_INSTANTIATE(T)                                                 \
  template Bracket<T> bracket_minimum_ref<T>(FunctionRef<T(T)>, T, T, int) noexcept;  \
  template Minimum1<T> minimize_brent_ref<T>(FunctionRef<T(T)>, T, T,                 \
                                             const BrentOptions<T>&) noexcept;        \
  template Minimum1<T> minimize_brent_ref<T>(FunctionRef<T(T)>, const Bracket<T>&,    \
                                             const BrentOptions<T>&) noexcept;        \
  template PowellRun<T> minimize_powell_ref<T>(FunctionRef<T(const T*)>, int, T*, T*, \
                                               const PowellOptions<T>&) noexcept;
LOCUS_MINIMIZE_INSTANTIATE(float)
LOCUS_MINIMIZE_INSTANTIATE(double)
#undef LOCUS_MINIMIZE_INSTANTIATE

}  // namespace detail
}  // namespace locus
