// SPDX-License-Identifier: BSL-1.0
// The exact real-root engine of numeric/roots.hpp (RootMode::exact), compiled once for float and
// double. Outline (derivation, invariants and cost in docs/notes/numeric.md):
//  1. The coefficients are doubles m_i 2^e_i: multiplied by 2^-min(e_i) they are integers, and
//     the polynomial keeps its roots. A factor x^z gives the root 0 of multiplicity z.
//  2. The gcd chain p_0 = p, p_{k+1} = gcd(p_k, p_k') (a root of multiplicity m of p is a root
//     of p_0..p_{m-1} only). Sturm sequences are computed over the integers by pseudo-remainders
//     (sign-corrected) made primitive; the last member of p_k's sequence is p_{k+1} up to a
//     constant. V_k(x), the sign variations at x of the Sturm sequence of the square-free part
//     p_k / p_{k+1}, counts the distinct roots of p_k in (x, y] as V_k(x) - V_k(y).
//  3. Isolation by bisection over the floating-point grid of T: points are T values bisected by
//     their ordered bit patterns, so at most 64 (double) or 32 (float) halvings reach adjacent
//     values. An interval holding one root of p gets its multiplicity m from the chain counts;
//     then it is narrowed with the sign of p_{m-1} alone (the root is simple there).
//  4. Rounding: a root strictly between adjacent T values x_lo < x_hi is compared with their
//     exact midpoint; it is correctly rounded (ties to even). Several distinct roots in one such
//     cell are isolated by exact dyadic bisection inside it (budget: max_exact_bisections).
// Every sign is exact: p(x) for x = M 2^-s is the sign of sum c_i M^i 2^(s(d-i)) (integers).
#include <locus/numeric/roots.hpp>

#include "integer_poly.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace locus::detail::roots {

namespace {

using Z = DynBigInt;

/// A positive multiple of -(a mod b) (the next member of a Sturm sequence), made primitive.
ZPoly neg_prem(const ZPoly& a, const ZPoly& b) {
  ZPoly r = a;
  const Z& lb = b.back();
  const int db = degree(b);
  int steps = 0;
  while (degree(r) >= db) {
    const Z lr = r.back();
    const auto shift = static_cast<std::size_t>(degree(r) - db);
    for (Z& c : r) c = c * lb;
    for (std::size_t i = 0; i < b.size(); ++i) r[i + shift] = r[i + shift] - lr * b[i];
    r.back() = Z(0);  // exactly zero by construction
    trim(r);
    ++steps;
  }
  // r = lb^steps a - q b: the multiplier is negative when lb < 0 and steps is odd.
  const bool negative_multiplier = lb.sign() < 0 && steps % 2 == 1;
  if (!negative_multiplier)
    for (Z& c : r) c = -c;
  make_primitive(r);
  return r;
}

/// Sturm sequence p, p', -rem, ...; its last member is gcd(p, p') up to a constant.
std::vector<ZPoly> sturm(const ZPoly& p) {
  std::vector<ZPoly> s{p};
  ZPoly d = derivative(p);
  make_primitive(d);
  if (d.empty()) return s;
  s.push_back(std::move(d));
  for (;;) {
    ZPoly r = neg_prem(s[s.size() - 2], s.back());
    if (r.empty()) break;
    s.push_back(std::move(r));
  }
  return s;
}

/// a / b for b dividing a in Z[x], b primitive (Gauss: every quotient coefficient is an
/// integer, so each step's division by the leading coefficient is exact).
ZPoly divide_exact(ZPoly a, const ZPoly& b) {
  const int db = degree(b);
  ZPoly q(static_cast<std::size_t>(degree(a) - db + 1));
  for (int i = degree(a); i >= db; --i) {
    const Z c = divide_exact(a[static_cast<std::size_t>(i)], b.back());
    q[static_cast<std::size_t>(i - db)] = c;
    if (c.is_zero()) continue;
    for (int j = 0; j <= db; ++j)
      a[static_cast<std::size_t>(i - db + j)] -= c * b[static_cast<std::size_t>(j)];
  }
  trim(q);
  return q;
}

/// A point of the extended line: -inf, +inf, or m 2^e.
struct Pt {
  int inf = 0;  // -1, 0, +1
  Z m;
  int e = 0;
  double xd = std::numeric_limits<double>::quiet_NaN();  // the value, when a double holds it
};

/// The coefficients rounded to double (empty when one would overflow): a filter for sign_at.
std::vector<double> to_doubles(const ZPoly& p) {
  std::vector<double> d;
  for (const Z& c : p) {
    if (c.bit_length() > 1000) return {};
    d.push_back(c.to_double());
  }
  return d;
}

/// The sign of p(x) from the rounded coefficients when Horner's error bound decides it, else 2.
/// Bound: each coefficient is rounded (relative u) and Horner adds gamma_{2n}; so
/// |computed - exact| <= gamma_{2n+2} sum |c_i| |x|^i, plus underflow (denormal) absolute errors.
int filtered_sign(const std::vector<double>& d, double x) {
  const int n = static_cast<int>(d.size()) - 1;
  double v = d.back(), s = std::abs(d.back());
  const double ax = std::abs(x);
  for (int i = n - 1; i >= 0; --i) {
    v = v * x + d[static_cast<std::size_t>(i)];
    s = s * ax + std::abs(d[static_cast<std::size_t>(i)]);
  }
  if (!std::isfinite(s) || !std::isfinite(v)) return 2;
  constexpr double u = 0.5 * std::numeric_limits<double>::epsilon();
  const double k = 2.0 * n + 4.0;
  const double bound = (k * u / (1.0 - k * u)) * s * (1.0 + 4.0 * u) +
                       4.0 * (n + 1) * std::numeric_limits<double>::denorm_min();
  if (std::abs(v) > bound) return v > 0 ? 1 : -1;
  return 2;
}

/// Sign of p at x, exactly.
int sign_at(const ZPoly& p, const Pt& x) {
  const int d = degree(p);
  if (d < 0) return 0;
  if (x.inf != 0) return p.back().sign() * ((x.inf < 0 && d % 2 == 1) ? -1 : 1);
  if (x.m.is_zero() || d == 0) return p[0].sign();
  if (x.e >= 0) {
    const Z X = x.m << static_cast<std::size_t>(x.e);
    Z r = p.back();
    for (int i = d - 1; i >= 0; --i) r = r * X + p[static_cast<std::size_t>(i)];
    return r.sign();
  }
  // p(m 2^-s) 2^(s d) = sum c_i m^i 2^(s (d - i)), by Horner in m.
  const auto s = static_cast<std::size_t>(-x.e);
  Z r = p.back();
  for (int i = d - 1; i >= 0; --i) {
    r = r * x.m;
    const Z& c = p[static_cast<std::size_t>(i)];
    if (!c.is_zero()) r += c << (s * static_cast<std::size_t>(d - i));
  }
  return r.sign();
}

/// The exact midpoint of two finite points.
Pt midpoint(const Pt& a, const Pt& b) {
  const int e = std::min(a.e, b.e);
  Pt r;
  r.m = (a.m << static_cast<std::size_t>(a.e - e)) + (b.m << static_cast<std::size_t>(b.e - e));
  r.e = e - 1;
  return r;
}

/// Ordered integer keys of the values of T: consecutive keys are adjacent values, -0 and +0
/// share the key 0, and +-inf are the keys just beyond +-max.
template <Real T>
struct Grid {
  using Bits = std::conditional_t<std::is_same_v<T, float>, std::uint32_t, std::uint64_t>;
  using Key = std::conditional_t<std::is_same_v<T, float>, std::int64_t, std::int64_t>;
  static constexpr Bits sign_bit = Bits{1} << (sizeof(Bits) * 8 - 1);

  static Key key(T x) {
    const Bits b = std::bit_cast<Bits>(x);
    const auto mag = static_cast<Key>(b & ~sign_bit);
    return (b & sign_bit) ? -mag : mag;
  }
  static T value(Key k) {
    const auto mag = static_cast<Bits>(k < 0 ? -k : k);
    return std::bit_cast<T>(k < 0 ? static_cast<Bits>(mag | sign_bit) : mag);
  }
  static Key inf_key() { return key(std::numeric_limits<T>::infinity()); }

  static Pt point(Key k) {
    Pt p;
    if (k >= inf_key()) {
      p.inf = 1;
    } else if (k <= -inf_key()) {
      p.inf = -1;
    } else {
      const double x = static_cast<double>(value(k));
      if (x != 0.0) {
        const int e = low_exponent(x);
        p.m = Z::from_double(x, -e);
        p.e = e;
      }
      p.xd = x;
    }
    return p;
  }
};

template <Real T>
class Engine {
 public:
  using G = Grid<T>;
  using Key = typename G::Key;

  Engine(std::vector<std::vector<ZPoly>> chain, const RootOptions& opt, Key first_inner,
         std::vector<Root<T>>& out)
      : chain_(std::move(chain)),
        budget_(opt.max_exact_bisections),
        first_inner_(first_inner),
        out_(out) {
    for (const auto& seq : chain_) {
      dchain_.emplace_back();
      for (const ZPoly& q : seq) dchain_.back().push_back(to_doubles(q));
    }
  }

  /// Appends the roots in (x(klo), x(khi)], increasing; of the cell below first_inner only
  /// its right end.
  void search(Key klo, Key khi) {
    // Explicit stack of intervals (klo, khi] with their variation counts: depth-first, left
    // first, so roots come out increasing. Depth <= 64 per root.
    struct Item {
      Key lo, hi;
      int vlo, vhi;
    };
    std::vector<Item> stack;
    stack.push_back({klo, khi, V(0, G::point(klo)), V(0, G::point(khi))});
    while (!stack.empty()) {
      const Item it = stack.back();
      stack.pop_back();
      const int c = it.vlo - it.vhi;
      if (c <= 0) continue;
      if (c == 1 || it.hi - it.lo == 1) {
        isolated(it.lo, it.hi, c);
        continue;
      }
      const Key mid = it.lo + (it.hi - it.lo) / 2;
      const int vm = V(0, G::point(mid));
      stack.push_back({mid, it.hi, vm, it.vhi});  // right half after the left one
      stack.push_back({it.lo, mid, it.vlo, vm});
    }
  }

  bool budget_hit() const { return budget_hit_; }

 private:
  int sign(std::size_t k, std::size_t j, const Pt& x) const {
    const std::vector<double>& d = dchain_[k][j];
    if (x.inf == 0 && !d.empty() && !std::isnan(x.xd)) {
      const int s = filtered_sign(d, x.xd);
      if (s != 2) return s;
    }
    return sign_at(chain_[k][j], x);
  }
  int V(std::size_t k, const Pt& x) const {
    int v = 0, last = 0;
    for (std::size_t j = 0; j < chain_[k].size(); ++j) {
      const int s = sign(k, j, x);
      if (s == 0) continue;
      if (last != 0 && s != last) ++v;
      last = s;
    }
    return v;
  }
  int p_sign(std::size_t k, const Pt& x) const { return sign(k, 0, x); }

  /// Multiplicity of the one root of p in (a, b] (b is not a root).
  int multiplicity(const Pt& a, const Pt& b) const {
    int m = 1;
    for (std::size_t k = 1; k < chain_.size(); ++k, ++m)
      if (V(k, a) - V(k, b) < 1) break;
    return m;
  }
  /// Multiplicity of the root x of p.
  int multiplicity_at(const Pt& x) const {
    int m = 0;
    for (std::size_t k = 0; k < chain_.size() && p_sign(k, x) == 0; ++k) ++m;
    return m;
  }

  void emit(Key k, int m) {
    // Roots below the first inner key's cell (below the caller's a) and beyond the range of T
    // are not reported.
    if (k < first_inner_ || k >= G::inf_key() || k <= -G::inf_key()) return;
    out_.push_back({G::value(k), m});
  }

  /// c >= 1 roots in (lo, hi]; c == 1, or lo and hi adjacent.
  void isolated(Key lo, Key hi, int c) {
    const Pt plo = G::point(lo);
    Pt phi = G::point(hi);
    if (c == 1) {
      if (phi.inf == 0 && p_sign(0, phi) == 0) {
        emit(hi, multiplicity_at(phi));
        return;
      }
      const int m = multiplicity(plo, phi);
      const std::size_t f = static_cast<std::size_t>(m - 1);  // the root is simple in p_{m-1}
      const int s_hi = p_sign(f, phi);
      // Bisection with the sign of p_{m-1}: its only root in (lo, hi] is this one.
      while (hi - lo > 1) {
        const Key mid = lo + (hi - lo) / 2;
        const Pt pm = G::point(mid);
        const int s = p_sign(f, pm);
        if (s == 0) {
          emit(mid, m);
          return;
        }
        if (s == s_hi) {
          hi = mid;
          phi = pm;
        } else {
          lo = mid;
        }
      }
      round_in_cell(lo, hi, m, f);
      return;
    }
    // Several distinct roots in one cell (lo, hi]: the endpoint, then the open cell.
    if (phi.inf == 0 && p_sign(0, phi) == 0) --c;
    // Interior roots beyond the range of T or below the caller's a are not reported.
    if (c > 0 && plo.inf == 0 && phi.inf == 0 && lo >= first_inner_)
      cluster_in_cell(lo, hi, plo, phi);
    if (phi.inf == 0 && p_sign(0, phi) == 0) emit(hi, multiplicity_at(phi));
  }

  /// The one root, of multiplicity m, strictly between the adjacent values of lo and hi; f is
  /// the chain member in which it is simple.
  void round_in_cell(Key lo, Key hi, int m, std::size_t f) {
    if (lo < first_inner_) return;  // the cell below the caller's a: the root is below a
    const Pt plo = G::point(lo), phi = G::point(hi);
    if (plo.inf != 0 || phi.inf != 0) return;  // beyond the range of T
    const Pt mid = midpoint(plo, phi);
    const int s_mid = p_sign(f, mid), s_hi = p_sign(f, phi);
    if (s_mid == 0)
      emit((lo % 2 == 0) ? lo : hi, m);  // a tie: to the even significand
    else
      emit(s_mid == s_hi ? lo : hi, m);  // same sign as hi: the root is below mid
  }

  /// Distinct roots strictly between adjacent values lo < hi: rounded by the side of the
  /// midpoint, multiplicities from an exact dyadic isolation.
  void cluster_in_cell(Key lo, Key hi, const Pt& plo, const Pt& phi) {
    const Pt mid = midpoint(plo, phi);
    const int vlo = V(0, plo), vm = V(0, mid), vhi = V(0, phi);
    const bool mid_root = p_sign(0, mid) == 0;
    const bool hi_root = p_sign(0, phi) == 0;
    isolate_open(plo, vlo, mid, vm, mid_root, lo);
    if (mid_root) emit((lo % 2 == 0) ? lo : hi, multiplicity_at(mid));
    isolate_open(mid, vm, phi, vhi, hi_root, hi);
  }

  /// Emits the roots strictly inside (a, b) as the value of key k, each with its multiplicity.
  /// va, vb: variation counts of p at a and b; b_root: p(b) == 0.
  void isolate_open(const Pt& a, int va, const Pt& b, int vb, bool b_root, Key k) {
    const int c = va - vb - (b_root ? 1 : 0);
    if (c <= 0) return;
    if (c == 1 && !b_root) {
      emit(k, multiplicity(a, b));
      return;
    }
    if (budget_ <= 0) {
      budget_hit_ = true;
      emit(k, c);  // unresolved: the number of distinct roots stands for their multiplicity
      return;
    }
    --budget_;
    const Pt m = midpoint(a, b);
    const int vm = V(0, m);
    const bool m_root = p_sign(0, m) == 0;
    isolate_open(a, va, m, vm, m_root, k);
    if (m_root) emit(k, multiplicity_at(m));
    isolate_open(m, vm, b, vb, b_root, k);
  }

  std::vector<std::vector<ZPoly>> chain_;
  std::vector<std::vector<std::vector<double>>> dchain_;  // chain_ rounded, for the filter
  int budget_;
  bool budget_hit_ = false;
  Key first_inner_;
  std::vector<Root<T>>& out_;
};

/// floor(log2 |c|) of a non-zero integer.
int ilogb_of(const Z& c) { return static_cast<int>(c.bit_length()) - 1; }

/// k with every root of a (a[0] != 0 when reversed) below 2^k in magnitude; for reversed,
/// every root of a is above 2^-k. Fujiwara's bound 2 max |a_i / a_n|^(1 / (n - i)) in exponents.
int root_bound_exponent(const ZPoly& a_in, bool reversed) {
  const int n = degree(a_in);
  const auto a = [&](int i) -> const Z& {
    return a_in[static_cast<std::size_t>(reversed ? n - i : i)];
  };
  const int en = ilogb_of(a(n));
  int k = 0;
  for (int i = 0; i < n; ++i) {
    if (a(i).is_zero()) continue;
    const int num = ilogb_of(a(i)) + 1 - en, den = n - i;
    const int c = num >= 0 ? (num + den - 1) / den : -((-num) / den);
    k = std::max(k, c + 1);
  }
  return k + 1;
}

}  // namespace

std::vector<ZPoly> sturm_sequence(const ZPoly& p) {
  ZPoly q = p;
  trim(q);
  make_primitive(q);
  return sturm(q);
}

template <Real T>
Status exact_real_roots_of_integers(ZPoly p, T lo, T hi, const RootOptions& opt,
                                    std::vector<Root<T>>& out) {
  using G = Grid<T>;
  trim(p);
  const int n = degree(p);
  if (n <= 0) return Status::ok;
  if (n > opt.max_exact_degree) return Status::limit_exceeded;
  int z = 0;  // p(x) = x^z q(x), q(0) != 0
  while (p[static_cast<std::size_t>(z)].is_zero()) ++z;
  p.erase(p.begin(), p.begin() + z);
  make_primitive(p);
  // chain[k]: the Sturm sequence of the square-free part of p_k (p_0 = p, p_{k+1} =
  // gcd(p_k, p_k')); square-free, so its variations count distinct roots at every point.
  std::vector<std::vector<ZPoly>> chain;
  for (ZPoly pk = p; degree(pk) >= 1;) {
    std::vector<ZPoly> seq = sturm(pk);
    ZPoly g = seq.back();
    if (degree(g) < 1) {
      chain.push_back(std::move(seq));
      break;
    }
    make_primitive(g);
    chain.push_back(sturm(divide_exact(pk, g)));
    pk = std::move(g);
  }
  // Keys: the search covers (key(lo) - 1, key(hi)], the cell below lo only for its right end,
  // cut down to the root bounds b_low < |x| < b_high (so that no sign is ever evaluated at the
  // extremes of the range, where the exact integers would be thousands of bits long).
  using Key = typename G::Key;
  const Key klo = lo == -std::numeric_limits<T>::infinity() ? -G::inf_key() : G::key(lo) - 1;
  const Key khi = hi == std::numeric_limits<T>::infinity() ? G::inf_key() : G::key(hi);
  const Key first_inner = klo + 1;
  const int m = n - z;
  const int k_high = root_bound_exponent(p, false);
  const int k_low = root_bound_exponent(p, true);
  const auto bound_key = [](int k) -> Key {  // key of 2^k, clamped to the range of T
    const double v = std::ldexp(1.0, k);
    if (v > static_cast<double>(std::numeric_limits<T>::max())) return G::inf_key();
    return G::key(static_cast<T>(v));  // 0 when 2^k underflows T (the search then includes 0)
  };
  const Key kh = bound_key(k_high), kl = bound_key(-k_low);
  Engine<T> eng(std::move(chain), opt, first_inner, out);
  const auto search = [&](Key a0, Key b0) {  // (a0, b0] intersected with (klo, khi]
    const Key a1 = std::max(a0, klo), b1 = std::min(b0, khi);
    if (a1 < b1) eng.search(a1, b1);
  };
  const bool zero_inside = z > 0 && lo <= T(0) && T(0) <= hi;
  if (m >= 1) {
    search(-kh, -kl);
    search(-kl, 0);  // empty unless 2^-k_low underflows T
    if (zero_inside) out.push_back({T(0), z});
    search(0, kl);
    search(kl, kh);
  } else if (zero_inside) {
    out.push_back({T(0), z});
  }
  return eng.budget_hit() ? Status::limit_exceeded : Status::ok;
}

template <Real T>
Status exact_real_roots(std::span<const double> a, T lo, T hi, const RootOptions& opt,
                        std::vector<Root<T>>& out) {
  // Integer coefficients: every coefficient times 2^-e_min (the roots are unchanged).
  int e_min = std::numeric_limits<int>::max();
  for (const double c : a)
    if (c != 0.0) e_min = std::min(e_min, low_exponent(c));
  ZPoly p;
  if (e_min != std::numeric_limits<int>::max())
    for (const double c : a) p.push_back(c == 0.0 ? Z(0) : Z::from_double(c, -e_min));
  return exact_real_roots_of_integers(std::move(p), lo, hi, opt, out);
}

ZPoly gcd(const ZPoly& a, const ZPoly& b) {
  ZPoly x = a, y = b;
  trim(x);
  trim(y);
  if (degree(x) < degree(y)) std::swap(x, y);
  while (!y.empty()) {
    ZPoly r = neg_prem(x, y);
    x = std::move(y);
    y = std::move(r);
  }
  make_primitive(x);
  if (!x.empty() && x.back().sign() < 0)
    for (Z& c : x) c = -c;
  return x;
}

template Status exact_real_roots_of_integers<float>(ZPoly, float, float, const RootOptions&,
                                                    std::vector<Root<float>>&);
template Status exact_real_roots_of_integers<double>(ZPoly, double, double, const RootOptions&,
                                                     std::vector<Root<double>>&);
template Status exact_real_roots<float>(std::span<const double>, float, float, const RootOptions&,
                                        std::vector<Root<float>>&);
template Status exact_real_roots<double>(std::span<const double>, double, double,
                                         const RootOptions&, std::vector<Root<double>>&);

}  // namespace locus::detail::roots
