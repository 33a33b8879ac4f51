// SPDX-License-Identifier: BSL-1.0
#pragma once
// Exact oracle for the root-finder tests (num.roots, num.polysys): polynomials in GMP rationals,
// an independent Sturm-sequence root count, exact root isolation by bisection, and the exact
// expansion of prod (x - r_i) rounded to T. Nothing here uses the code under test.

#include <gmpxx.h>

#include <cmath>
#include <utility>
#include <vector>

namespace poly_oracle {

using Q = mpq_class;
using QPoly = std::vector<Q>;  // low to high, trailing zeros trimmed

/// a / b in canonical form (mpq_class(a, b) is not canonicalised by itself).
inline Q frac(long a, long b) {
  Q q(a, b);
  q.canonicalize();
  return q;
}

inline void trim(QPoly& p) {
  while (!p.empty() && p.back() == 0) p.pop_back();
}

inline Q eval(const QPoly& p, const Q& x) {
  Q r = 0;
  for (auto it = p.rbegin(); it != p.rend(); ++it) r = r * x + *it;
  return r;
}

inline int sign(const Q& v) { return sgn(v); }

/// lead * prod (x - r_i), exactly.
inline QPoly expand(const std::vector<Q>& roots, const Q& lead) {
  QPoly p{lead};
  for (const Q& r : roots) {
    QPoly n(p.size() + 1, Q(0));
    for (std::size_t i = 0; i < p.size(); ++i) {
      n[i + 1] += p[i];
      n[i] -= r * p[i];
    }
    p = std::move(n);
  }
  trim(p);
  return p;
}

inline QPoly mul(const QPoly& a, const QPoly& b) {
  if (a.empty() || b.empty()) return {};
  QPoly r(a.size() + b.size() - 1, Q(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  trim(r);
  return r;
}

/// Coefficients rounded to T, then taken back exactly: the polynomial the solver really sees.
template <class T>
std::vector<T> round_to(const QPoly& p) {
  std::vector<T> c(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) c[i] = static_cast<T>(p[i].get_d());
  return c;
}
template <class T>
QPoly exact_of(const std::vector<T>& c) {
  QPoly p(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) p[i] = Q(static_cast<double>(c[i]));
  trim(p);
  return p;
}

inline QPoly derivative(const QPoly& p) {
  QPoly d;
  for (std::size_t i = 1; i < p.size(); ++i) d.push_back(p[i] * static_cast<long>(i));
  trim(d);
  return d;
}

inline QPoly remainder(QPoly a, const QPoly& b) {
  while (a.size() >= b.size() && !a.empty()) {
    const Q f = a.back() / b.back();
    const std::size_t shift = a.size() - b.size();
    for (std::size_t i = 0; i < b.size(); ++i) a[shift + i] -= f * b[i];
    a.pop_back();  // the leading term cancels exactly
    trim(a);
  }
  return a;
}

/// Exact quotient a / b (b divides a).
inline QPoly quotient(QPoly a, const QPoly& b) {
  if (a.size() < b.size()) return {};
  QPoly q(a.size() - b.size() + 1, Q(0));
  while (a.size() >= b.size() && !a.empty()) {
    const Q f = a.back() / b.back();
    const std::size_t shift = a.size() - b.size();
    q[shift] = f;
    for (std::size_t i = 0; i < b.size(); ++i) a[shift + i] -= f * b[i];
    a.pop_back();
    trim(a);
  }
  trim(q);
  return q;
}

/// Sturm chain divided by gcd(p, p') (so multiple roots do not make every member vanish), used
/// for exact counts of distinct real roots in (lo, hi].
struct Sturm {
  std::vector<QPoly> seq;
  explicit Sturm(const QPoly& p) {
    if (p.empty()) return;
    seq.push_back(p);
    QPoly d = derivative(p);
    while (!d.empty()) {
      seq.push_back(d);
      QPoly r = remainder(seq[seq.size() - 2], seq.back());
      for (Q& c : r) c = -c;
      d = std::move(r);
    }
    if (seq.back().size() > 1) {
      const QPoly g = seq.back();
      for (QPoly& q : seq) q = quotient(q, g);
    }
  }
  int variations(const Q& x) const {
    int n = 0, last = 0;
    for (const QPoly& q : seq) {
      const int s = sign(eval(q, x));
      if (s != 0) {
        if (last != 0 && s != last) ++n;
        last = s;
      }
    }
    return n;
  }
  int count(const Q& lo, const Q& hi) const { return variations(lo) - variations(hi); }
};

/// Isolates every distinct real root of p in (lo, hi] to an interval of width <= width by
/// Sturm bisection; returns the midpoints (as doubles).
inline void isolate(const Sturm& s, const Q& lo, const Q& hi, const Q& width,
                    std::vector<double>& out, int depth = 0) {
  const int c = s.count(lo, hi);
  if (c == 0) return;
  if ((c == 1 && hi - lo <= width) || depth > 200) {
    out.push_back(Q((lo + hi) / 2).get_d());
    return;
  }
  const Q mid = (lo + hi) / 2;
  isolate(s, lo, mid, width, out, depth + 1);
  isolate(s, mid, hi, width, out, depth + 1);
}

/// The exact root of p nearest to r (p changes sign there), to about 2^-60 relative: bisection
/// in rationals from the smallest bracket [r - d, r + d] with a sign change. Returns false when
/// no sign change is found within |d| <= 1e-3 (1 + |r|).
inline bool exact_root_near(const QPoly& p, double r, double& root) {
  const Q x(r);
  const double scale = 1.0 + std::abs(r);
  const int sx = sign(eval(p, x));
  if (sx == 0) {
    root = r;
    return true;
  }
  double d = std::abs(r) * 1e-17 + 1e-300;
  Q lo, hi;
  bool found = false;
  for (int k = 0; k < 1200 && d <= 1e-3 * scale; ++k, d *= 2) {
    const Q qd(d);
    if (sign(eval(p, x - qd)) != sx) {
      lo = x - qd;
      hi = x;
      found = true;
      break;
    }
    if (sign(eval(p, x + qd)) != sx) {
      lo = x;
      hi = x + qd;
      found = true;
      break;
    }
  }
  if (!found) return false;
  const int slo = sign(eval(p, lo));
  for (int k = 0; k < 64; ++k) {
    const Q mid = (lo + hi) / 2;
    const int sm = sign(eval(p, mid));
    if (sm == 0) {
      lo = hi = mid;
      break;
    }
    if (sm == slo)
      lo = mid;
    else
      hi = mid;
  }
  root = Q((lo + hi) / 2).get_d();
  return true;
}

}  // namespace poly_oracle
