// SPDX-License-Identifier: BSL-1.0
// Exact relation of two solid ellipsoids (include/locus/intersection/ellipsoid_ellipsoid.hpp,
// detail/quadric_pair3.hpp), row int3.surface-surface, book section 11.8. Derivation and proof
// of the classification: docs/notes/surface_intersection.md, "Exact ellipsoid relation".
//
// Each ellipsoid's quadric, exactly as stored (center C, axes U_i, extents e_i), is the 4x4
// symmetric integer matrix of e0^2 e1^2 e2^2 (sum_i (U_i.(x - C))^2 / e_i^2 - 1) in the
// homogeneous coordinates (2^s x, 1), s a shift common to both. The relation follows from the
// real roots of p(mu) = det(B - mu A) (exact integer coefficients) and the definiteness of
// B - mu A at rational or quadratic-irrational mu, all decided in integers; cheap exact
// certificates (points, a sign of p, a definite B - mu A) settle most pairs first.

#include <locus/intersection/detail/quadric_pair3.hpp>

#include "../core/big_int.hpp"
#include "../numeric/integer_poly.hpp"

#include <locus/numeric/roots.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <new>
#include <vector>

namespace locus::detail::quadric_pair3 {
namespace {

using roots::ZPoly;
using Z = DynBigInt;
using ZMat = std::array<std::array<Z, 4>, 4>;

[[nodiscard]] Z pow2(int k) { return Z(1) << static_cast<std::size_t>(k); }

/// The exact quadric of an ellipsoid (see the file comment) with the common shift s.
[[nodiscard]] ZMat exact_quadric(const V& c, const V (&u)[3], const V& e, int s) {
  Z cz[3], ez[3], uz[3][3];
  for (int k = 0; k < 3; ++k) {
    cz[k] = Z::from_double(c[k], s);
    ez[k] = Z::from_double(e[k], s);
    for (int i = 0; i < 3; ++i) uz[i][k] = Z::from_double(u[i][k], s);
  }
  // Row L_i = (U_i, -U_i.C) (scaled by 2^2s) acting on (2^s x, 1); weight prod_{j != i} e_j^2.
  ZMat m{};
  Z all = Z(1);
  for (int k = 0; k < 3; ++k) all = all * ez[k] * ez[k];
  for (int i = 0; i < 3; ++i) {
    Z w = Z(1);
    for (int j = 0; j < 3; ++j)
      if (j != i) w = w * ez[j] * ez[j];
    std::array<Z, 4> l{uz[i][0], uz[i][1], uz[i][2], Z()};
    l[3] = -(uz[i][0] * cz[0] + uz[i][1] * cz[1] + uz[i][2] * cz[2]);
    for (int r = 0; r < 4; ++r) {
      const Z wl = w * l[static_cast<std::size_t>(r)];
      for (int q = r; q < 4; ++q)
        m[static_cast<std::size_t>(r)][static_cast<std::size_t>(q)] +=
            wl * l[static_cast<std::size_t>(q)];
    }
  }
  m[3][3] -= (all << static_cast<std::size_t>(2 * s));
  for (std::size_t r = 0; r < 4; ++r)
    for (std::size_t q = 0; q < r; ++q) m[r][q] = m[q][r];
  return m;
}

// Ring operations shared by integer and polynomial determinants.
[[nodiscard]] Z times(const Z& a, const Z& b) { return a * b; }
[[nodiscard]] ZPoly times(const ZPoly& a, const ZPoly& b) { return roots::mul(a, b); }
[[nodiscard]] Z plus(const Z& a, const Z& b) { return a + b; }
[[nodiscard]] ZPoly plus(const ZPoly& a, const ZPoly& b) { return roots::add(a, b); }
[[nodiscard]] Z minus(const Z& a, const Z& b) { return a - b; }
[[nodiscard]] ZPoly minus(const ZPoly& a, const ZPoly& b) { return roots::sub(a, b); }

/// Determinant of the submatrix on rows and cols (n of each) by cofactor expansion.
template <class R>
[[nodiscard]] R minor_det(const std::array<std::array<R, 4>, 4>& m, const int* rows,
                          const int* cols, int n) {
  if (n == 1) return m[static_cast<std::size_t>(rows[0])][static_cast<std::size_t>(cols[0])];
  R sum{};
  for (int j = 0; j < n; ++j) {
    int sub[4];
    for (int k = 0, t = 0; k < n; ++k)
      if (k != j) sub[t++] = cols[k];
    const R term = times(m[static_cast<std::size_t>(rows[0])][static_cast<std::size_t>(cols[j])],
                         minor_det(m, rows + 1, sub, n - 1));
    sum = j % 2 == 0 ? plus(sum, term) : minus(sum, term);
  }
  return sum;
}

/// The 15 principal minors of B - mu A as polynomials in mu, with their orders; the last is p.
struct Minors {
  std::array<ZPoly, 15> poly;
  std::array<int, 15> order{};
};
[[nodiscard]] Minors pencil_minors(const ZMat& a, const ZMat& b) {
  std::array<std::array<ZPoly, 4>, 4> pm;
  for (std::size_t r = 0; r < 4; ++r)
    for (std::size_t q = 0; q < 4; ++q) {
      ZPoly e{b[r][q], -a[r][q]};
      roots::trim(e);
      pm[r][q] = std::move(e);
    }
  Minors out;
  std::size_t k = 0;
  for (int size = 1; size <= 4; ++size)
    for (int mask = 1; mask < 16; ++mask) {
      int idx[4], n = 0;
      for (int i = 0; i < 4; ++i)
        if ((mask >> i) & 1) idx[n++] = i;
      if (n != size) continue;
      out.poly[k] = minor_det(pm, idx, idx, n);
      roots::trim(out.poly[k]);
      out.order[k++] = n;
    }
  return out;
}

/// sign m(n / d), d > 0: the sign of d^deg m(n / d) = sum m_j n^j d^(deg - j) (Horner).
[[nodiscard]] int sign_at_rational(const ZPoly& m, const Z& n, const Z& d) {
  if (m.empty()) return 0;
  Z acc = m.back(), dp = Z(1);
  for (std::size_t i = m.size() - 1; i-- > 0;) {
    dp = dp * d;
    acc = acc * n + m[i] * dp;
  }
  return acc.sign();
}

/// sign of P + W sqrt(D), D > 0.
[[nodiscard]] int sign_plus_root(const Z& pz, const Z& w, const Z& d) {
  const int sp = pz.sign(), sw = w.sign();
  if (sw == 0) return sp;
  if (sp == 0 || sp == sw) return sw;
  const int c = compare(pz * pz, w * w * d);  // |P| against |W| sqrt(D)
  return c == 0 ? 0 : (c > 0 ? sp : sw);
}

/// A real algebraic number of degree <= 2: rational n / d (d > 0), or a root
/// (-beta + branch sqrt(disc)) / (2 alpha) of alpha mu^2 + beta mu + gamma (alpha > 0,
/// disc = beta^2 - 4 alpha gamma > 0; a square disc is harmless: the evaluation is exact).
struct AlgebraicRoot {
  bool rational = true;
  Z n, d;
  Z alpha, beta, gamma, disc;
  int branch = 1;
};

/// sign m(r).
[[nodiscard]] int sign_at(const ZPoly& m, const AlgebraicRoot& r) {
  if (r.rational) return sign_at_rational(m, r.n, r.d);
  // alpha^k m = Q h + (u + v mu), h = alpha mu^2 + beta mu + gamma, alpha > 0.
  ZPoly rem = m;
  const ZPoly h{r.gamma, r.beta, r.alpha};
  while (roots::degree(rem) >= 2) {
    const Z lead = rem.back();
    const auto shift = static_cast<std::size_t>(roots::degree(rem) - 2);
    for (Z& c : rem) c = c * r.alpha;
    for (std::size_t i = 0; i < 3; ++i) rem[i + shift] -= lead * h[i];
    rem.back() = Z();
    roots::trim(rem);
  }
  const Z u = rem.empty() ? Z() : rem[0];
  const Z v = rem.size() > 1 ? rem[1] : Z();
  // u + v r = (2 alpha u - beta v + branch v sqrt(disc)) / (2 alpha).
  const Z pz = Z(2) * r.alpha * u - r.beta * v;
  return sign_plus_root(pz, r.branch > 0 ? v : -v, r.disc);
}

enum class Definite { none, positive, negative };

/// Whether B - r A is positive or negative semidefinite (strict: definite) at r.
[[nodiscard]] Definite definiteness(const Minors& mi, const AlgebraicRoot& r, bool strict) {
  bool pos = true, neg = true;
  for (std::size_t k = 0; k < mi.poly.size() && (pos || neg); ++k) {
    const int s = sign_at(mi.poly[k], r);
    const int sn = mi.order[k] % 2 == 0 ? s : -s;
    if (strict) {  // definite: every principal minor of order k has sign (+-1)^k
      pos = pos && s > 0;
      neg = neg && sn > 0;
    } else {
      pos = pos && s >= 0;
      neg = neg && sn >= 0;
    }
  }
  return pos ? Definite::positive : neg ? Definite::negative : Definite::none;
}

/// x = m 2^e exactly as integers (x finite).
void dyadic(double x, Z& m, int& e) {
  e = std::min(0, low_exponent(x));
  m = Z::from_double(x, -e);
}

/// Exact real roots of q (no negative roots, so none is lost below the range of double; roots
/// beyond it are dropped, which only shortens the list at its top) in [lo, hi].
[[nodiscard]] bool real_roots(const ZPoly& q, double lo, double hi,
                              std::vector<Root<double>>& out) {
  out.clear();
  return roots::exact_real_roots_of_integers<double>(q, lo, hi, RootOptions{}, out) == Status::ok;
}

[[nodiscard]] int sign_at_double(const ZPoly& q, double x) {
  Z m;
  int e = 0;
  dyadic(x, m, e);
  return sign_at_rational(q, m, pow2(-e));
}

/// A dyadic rational n / 2^k strictly between the i-th and (i+1)-th distinct real roots of q
/// (counted from the smallest; q has no negative roots), whose rounded values are lo_known and
/// hi_known. Rounded roots in the same or adjacent
/// double cells are separated by zooming: the variable becomes t' = (t - lo) 2^g centred on the
/// lower rounded root, 2^60 times finer than its cell, and only the roots above a window edge a
/// few cells below lo are listed again (the index is shifted by the exact count of the roots left
/// below), so no root below the pair can be lost to overflow. False when out of budget.
[[nodiscard]] bool point_between(const ZPoly& q, std::size_t i, double lo_known, double hi_known,
                                 Z& n_out, int& k_out) {
  const double inf = std::numeric_limits<double>::infinity();
  ZPoly poly = q;
  Z x;        // mu = (x + t) / 2^k
  int k = 0;  // accumulated zoom
  double window = -inf;
  std::vector<Root<double>> rs, below;
  for (int round = 0; round < 40; ++round) {
    double lo = lo_known, hi = hi_known;  // the two roots' rounded values, known in round 0
    if (round > 0) {
      if (!real_roots(poly, window, inf, rs) || rs.size() <= i + 1) return false;
      lo = rs[i].value;
      hi = rs[i + 1].value;
    }
    if (!std::isfinite(lo) || !std::isfinite(hi)) return false;
    const double above = std::nextafter(lo, inf), under = std::nextafter(hi, -inf);
    if (above <= under) {
      const double t = std::clamp(0.5 * lo + 0.5 * hi, above, under);
      Z tm;
      int te = 0;
      dyadic(t, tm, te);  // t = tm 2^te, te <= 0
      n_out = (x << static_cast<std::size_t>(-te)) + tm;
      k_out = k - te;
      return true;
    }
    // The new window's edge: four doubles below lo (the i-th root is above it), but not below
    // the current window.
    double edge = lo;
    for (int j = 0; j < 4; ++j) edge = std::nextafter(edge, -inf);
    if (edge > window) {
      if (!real_roots(poly, window, edge, below)) return false;
      std::size_t left = below.size();
      if (left > 0 && sign_at_double(poly, edge) == 0) --left;  // listed again from the edge
      if (left > i) return false;
      i -= left;
    } else {
      edge = window;
    }
    const int ulp_exp = lo == 0.0 ? -1074 : std::max(std::ilogb(lo) - 52, -1074);
    const int g = std::min(std::max(60, 60 - ulp_exp), 900);
    Z lm;
    int le = 0;
    dyadic(lo, lm, le);
    if (g + le < 0) return false;
    const Z centre = lm << static_cast<std::size_t>(g + le);
    // poly'(t') = 2^(g deg) poly((centre + t') / 2^g) = sum c_j (centre + t')^j 2^(g (deg - j)).
    const int deg = roots::degree(poly);
    ZPoly next, power{Z(1)};
    const ZPoly lin{centre, Z(1)};
    for (int j = 0; j <= deg; ++j) {
      const Z scale = poly[static_cast<std::size_t>(j)] << static_cast<std::size_t>(g * (deg - j));
      next = roots::add(next, roots::scaled(power, scale));
      power = roots::mul(power, lin);
    }
    poly = std::move(next);
    window = std::ldexp(edge - lo, g);  // exact: edge and lo are a few doubles apart
    x = (x << static_cast<std::size_t>(g)) + centre;
    k += g;
  }
  return false;
}

/// The reversed polynomial mu^deg q(1 / mu): its roots are the reciprocals of q's.
[[nodiscard]] ZPoly reversed(const ZPoly& q) {
  ZPoly r(q.rbegin(), q.rend());
  roots::trim(r);
  return r;
}

/// The distinct real roots of p on one side of 0, each with its multiplicity, ordered by |mu|:
/// those with |mu| < 1 from p, those with |mu| >= 1 from the reversed polynomial (so that no
/// root is lost beyond the range of double). reciprocal marks the latter; value is in the
/// polynomial's own variable.
struct SideRoot {
  bool reciprocal;
  double value;
  int multiplicity;
  std::size_t index;  // its index among the real roots of its polynomial, counted from the smallest
};
[[nodiscard]] bool side_roots(const ZPoly& p, const ZPoly& rev, bool positive,
                              std::vector<SideRoot>& out) {
  std::vector<Root<double>> direct, far;
  if (!real_roots(p, positive ? 0.0 : -1.0, positive ? 1.0 : 0.0, direct) ||
      !real_roots(rev, positive ? 0.0 : -1.0, positive ? 1.0 : 0.0, far))
    return false;
  // A root at exactly +-1 is in both lists: keep it in the reversed one (it is the extreme of the
  // direct list, the last for positive roots, the first for negative ones).
  if (sign_at_rational(p, Z(positive ? 1 : -1), Z(1)) == 0 && !direct.empty()) {
    if (positive)
      direct.pop_back();
    else
      direct.erase(direct.begin());
  }
  out.clear();
  if (positive) {
    for (std::size_t j = 0; j < direct.size(); ++j)
      out.push_back({false, direct[j].value, direct[j].multiplicity, j});
    for (std::size_t j = far.size(); j-- > 0;)
      out.push_back({true, far[j].value, far[j].multiplicity, j});
  } else {
    for (const Root<double>& r : direct) out.push_back({false, r.value, r.multiplicity, 0});
    for (const Root<double>& r : far) out.push_back({true, r.value, r.multiplicity, 0});
  }
  return true;
}

/// Sign variations of a Sturm sequence at n / d (d > 0), or at -inf / +inf (at_inf -1 / +1).
[[nodiscard]] int variations(const std::vector<ZPoly>& seq, const Z& n, const Z& d, int at_inf) {
  int count = 0, last = 0;
  for (const ZPoly& q : seq) {
    int sg = 0;
    if (at_inf != 0)
      sg = q.back().sign() * (at_inf < 0 && roots::degree(q) % 2 == 1 ? -1 : 1);
    else
      sg = sign_at_rational(q, n, d);
    if (sg == 0) continue;
    if (last != 0 && sg != last) ++count;
    last = sg;
  }
  return count;
}

/// Definiteness of B - mu A on the gaps between consecutive positive roots where p > 0, from
/// points between approximate roots (floating point) whose gap is then certified by exact Sturm
/// counts. covered_all: every gap was reached (else the caller falls back to exact isolation).
[[nodiscard]] Definite gaps_from_estimates(const Minors& mi, const std::vector<ZPoly>& seq,
                                           int positive_roots, bool& covered_all) {
  const ZPoly& p = mi.poly.back();
  covered_all = false;
  if (positive_roots < 2) {
    covered_all = true;
    return Definite::none;
  }
  std::size_t bits = 0;
  for (const Z& c : p) bits = std::max(bits, c.bit_length());
  const std::size_t drop = bits > 900 ? bits - 900 : 0;  // keep the doubles finite
  double c[5] = {};
  for (std::size_t j = 0; j < p.size() && j < 5; ++j) c[j] = (p[j] >> drop).to_double();
  const RootsResult<double> est = solve_quartic<double>(c[0], c[1], c[2], c[3], c[4]);
  std::vector<bool> covered(static_cast<std::size_t>(positive_roots - 1), false);
  const int v0 = variations(seq, Z(0), Z(1), 0);
  for (int j = 0; j + 1 < est.count; ++j) {
    const double lo = est.roots[static_cast<std::size_t>(j)].value;
    const double hi = est.roots[static_cast<std::size_t>(j + 1)].value;
    const double m = 0.5 * lo + 0.5 * hi;
    if (!(m > 0.0) || !std::isfinite(m)) continue;
    AlgebraicRoot r;
    int e = 0;
    dyadic(m, r.n, e);
    r.d = pow2(-e);
    const int sp = sign_at_rational(p, r.n, r.d);
    if (sp == 0) continue;
    const int below = v0 - variations(seq, r.n, r.d, 0);  // distinct roots in (0, m)
    if (below < 1 || below >= positive_roots) continue;
    covered[static_cast<std::size_t>(below - 1)] = true;
    if (sp < 0) continue;  // definite 4x4 matrices have positive determinants
    const Definite d = definiteness(mi, r, true);
    if (d != Definite::none) {
      covered_all = true;
      return d;
    }
  }
  covered_all = std::find(covered.begin(), covered.end(), false) == covered.end();
  return Definite::none;
}

/// Sign of X^T M X at the point x (doubles): X = (2^s x, 1) times 2^f, f making every 2^f x_k an
/// integer (a positive factor: the sign is that of the quadric at x).
[[nodiscard]] int sign_at_point(const ZMat& m, const V& x, int s) {
  int f = 0;
  for (int k = 0; k < 3; ++k)
    if (x[k] != 0.0) f = std::max(f, -low_exponent(x[k]));
  std::array<Z, 4> h;
  for (int k = 0; k < 3; ++k)
    h[static_cast<std::size_t>(k)] = Z::from_double(x[k], f) << static_cast<std::size_t>(s);
  h[3] = pow2(f);
  Z sum;
  for (std::size_t r = 0; r < 4; ++r) {
    Z row;
    for (std::size_t q = 0; q < 4; ++q) row += m[r][q] * h[q];
    sum += row * h[r];
  }
  return sum.sign();
}

/// Cheap certificates, each exact (see the notes): a point in both interiors, one in a's interior
/// outside b and one in b's interior outside a prove overlapping; a negative mu with p(mu) > 0
/// proves two negative roots (separated); B - mu A definite at some mu > 0 proves strict
/// containment. Candidates come from floating point; undecided when none certifies.
struct Solid {
  V c;
  V axis[3];
  V extent;
};
[[nodiscard]] RegionRelation certified_by_points(const ZMat& a, const ZMat& b, const Solid& sa,
                                                 const Solid& sb, int s) {
  bool both = false, a_only = false, b_only = false;
  const auto probe = [&](const V& x) {
    if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z)) return;
    const int in_a = sign_at_point(a, x, s), in_b = sign_at_point(b, x, s);
    both = both || (in_a < 0 && in_b < 0);
    a_only = a_only || (in_a < 0 && in_b > 0);
    b_only = b_only || (in_b < 0 && in_a > 0);
  };
  for (const Solid* e : {&sa, &sb}) {
    probe(e->c);
    for (int i = 0; i < 3 && !(both && a_only && b_only); ++i) {
      const double len2 = dot(e->axis[i], e->axis[i]);
      for (double f : {0.99, 0.6}) {  // along axis i, near its ends and half way
        const V step = (f * e->extent[i] / len2) * e->axis[i];
        probe(e->c + step);
        probe(e->c - step);
      }
    }
  }
  for (int j = 1; j < 16 && !(both && a_only && b_only); ++j)
    probe(sa.c + (j / 16.0) * (sb.c - sa.c));
  return both && a_only && b_only ? RegionRelation::overlapping : RegionRelation::undecided;
}

[[nodiscard]] RegionRelation certified_by_pencil(const Minors& mi) {
  // Pencil roots estimated in floating point.
  const ZPoly& p = mi.poly.back();
  std::size_t bits = 0;
  for (const Z& c : p) bits = std::max(bits, c.bit_length());
  const std::size_t drop = bits > 900 ? bits - 900 : 0;  // keep the doubles finite
  double c[5] = {};
  for (std::size_t j = 0; j < p.size() && j < 5; ++j) c[j] = (p[j] >> drop).to_double();
  const RootsResult<double> est = solve_quartic<double>(c[0], c[1], c[2], c[3], c[4]);
  for (int j = 0; j + 1 < est.count; ++j) {
    const double m = 0.5 * est.roots[static_cast<std::size_t>(j)].value +
                     0.5 * est.roots[static_cast<std::size_t>(j + 1)].value;
    if (!std::isfinite(m) || m == 0.0) continue;
    AlgebraicRoot r;
    int e = 0;
    dyadic(m, r.n, e);
    r.d = pow2(-e);
    if (sign_at_rational(p, r.n, r.d) <= 0) continue;
    if (m < 0.0) return RegionRelation::separated;
    const Definite d = definiteness(mi, r, true);
    if (d == Definite::positive) return RegionRelation::a_contains_b;
    if (d == Definite::negative) return RegionRelation::b_contains_a;
  }
  return RegionRelation::undecided;
}

[[nodiscard]] RegionRelation exact_relation(const ZMat& a, const ZMat& b, const Solid& sa,
                                            const Solid& sb, int s, bool certificates) {
  // Equal solids: proportional quadrics (the x-blocks' (0,0) entries are positive).
  bool proportional = true;
  for (std::size_t r = 0; r < 4 && proportional; ++r)
    for (std::size_t q = r; q < 4 && proportional; ++q)
      proportional = a[r][q] * b[0][0] == b[r][q] * a[0][0];
  if (proportional) return RegionRelation::equal;
  if (certificates) {
    const RegionRelation by_points = certified_by_points(a, b, sa, sb, s);
    if (by_points != RegionRelation::undecided) return by_points;
  }
  const Minors mi = pencil_minors(a, b);
  const ZPoly& p = mi.poly.back();
  if (certificates) {
    const RegionRelation by_pencil = certified_by_pencil(mi);
    if (by_pencil != RegionRelation::undecided) return by_pencil;
  }
  // Negative roots exist iff the interiors are disjoint: two simple ones when separated, one
  // double when touching (counted exactly by Sturm's theorem; 0 is not a root).
  const std::vector<ZPoly> seq = roots::sturm_sequence(p);
  const int v_zero = variations(seq, Z(0), Z(1), 0);
  const int negative = variations(seq, Z(), Z(1), -1) - v_zero;
  const int positive = v_zero - variations(seq, Z(), Z(1), 1);
  if (negative == 2) return RegionRelation::separated;
  if (negative == 1) return RegionRelation::touching;
  if (negative != 0) return RegionRelation::undecided;  // excluded by the classification
  // Interiors meet. Strict containment: B - mu A definite on a gap between consecutive roots.
  // Fast path: sample points between estimated roots, certified by Sturm counts.
  bool covered_all = false;
  const Definite sampled = gaps_from_estimates(mi, seq, positive, covered_all);
  if (sampled == Definite::positive) return RegionRelation::a_contains_b;
  if (sampled == Definite::negative) return RegionRelation::b_contains_a;
  std::vector<SideRoot> pos;
  const ZPoly rev = reversed(p);  // p(0) = det B != 0: degree 4 too
  if (!covered_all && !side_roots(p, rev, true, pos)) return RegionRelation::undecided;
  int above = 0;  // total multiplicity of the roots above the gap
  for (const SideRoot& r : pos) above += r.multiplicity;
  for (std::size_t i = 0; i + 1 < pos.size(); ++i) {
    // det(B - mu A) > 0 on a definite gap: p's sign there is that of its leading coefficient
    // times (-1)^(multiplicities above).
    above -= pos[i].multiplicity;
    if (p.back().sign() * (above % 2 == 0 ? 1 : -1) <= 0) continue;
    AlgebraicRoot r;
    const SideRoot &s0 = pos[i], &s1 = pos[i + 1];
    int k = 0;
    if (!s0.reciprocal && !s1.reciprocal) {  // both below 1
      if (!point_between(p, s0.index, s0.value, s1.value, r.n, k)) return RegionRelation::undecided;
      r.d = pow2(k);
    } else if (s0.reciprocal) {  // both at least 1: between their reciprocals (s1 below s0 there)
      Z n;
      if (!point_between(rev, s1.index, s1.value, s0.value, n, k)) return RegionRelation::undecided;
      r.n = pow2(k);  // mu = 2^k / n, n > 0
      r.d = n;
    } else {  // s0 below 1, s1 at least 1: mu = 1 unless 1 is the root s1
      r.n = Z(1);
      r.d = Z(1);
      if (sign_at_rational(p, r.n, r.d) == 0) {  // s1 is exactly 1: between s0 and 1 in p
        if (!point_between(p, s0.index, s0.value, 1.0, r.n, k)) return RegionRelation::undecided;
        r.d = pow2(k);
      }
    }
    const Definite d = definiteness(mi, r, true);
    if (d == Definite::positive) return RegionRelation::a_contains_b;
    if (d == Definite::negative) return RegionRelation::b_contains_a;
  }
  // Tangent containment: B - r A semidefinite at a multiple root r (a root of gcd(p, p')).
  ZPoly g = seq.back();  // gcd(p, p') up to a constant
  roots::make_primitive(g);
  if (roots::degree(g) >= 1) {
    if (g.back().sign() < 0) g = roots::negated(g);
    std::vector<AlgebraicRoot> candidates;
    const int dg = roots::degree(g);
    const auto su = static_cast<std::size_t>(dg);
    const Z disc = dg == 2 ? g[1] * g[1] - Z(4) * g[2] * g[0] : Z();
    if (dg == 1 || (dg == 2 && disc.is_zero()) || dg == 3) {
      // One distinct multiple root r = -g_(n-1) / (n g_n) (g = g_n (mu - r)^n).
      AlgebraicRoot r;
      r.n = -g[su - 1];
      r.d = Z(dg) * g[su];
      candidates.push_back(r);
    } else if (dg == 2 && disc.sign() > 0) {
      for (int branch : {-1, 1}) {
        AlgebraicRoot r;
        r.rational = false;
        r.alpha = g[2];
        r.beta = g[1];
        r.gamma = g[0];
        r.disc = disc;
        r.branch = branch;
        candidates.push_back(r);
      }
    }
    for (const AlgebraicRoot& r : candidates) {
      const Definite d = definiteness(mi, r, false);
      if (d == Definite::positive) return RegionRelation::a_contains_b_touching;
      if (d == Definite::negative) return RegionRelation::b_contains_a_touching;
    }
  }
  return RegionRelation::overlapping;
}

/// Divides m by the gcd of its entries (a positive factor: the quadric is unchanged).
void make_primitive(ZMat& m) {
  Z g;
  for (const auto& row : m)
    for (const Z& x : row)
      if (!x.is_zero()) g = g.is_zero() ? abs(x) : gcd(g, x);
  if (g.is_zero() || g == Z(1)) return;
  for (auto& row : m)
    for (Z& x : row)
      if (!x.is_zero()) x = divide_exact(x, g);
}

[[nodiscard]] bool finite(const V& v) noexcept {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// Whether the axes are linearly independent (exact determinant of the stored axes).
[[nodiscard]] bool independent(const V (&u)[3], int s) {
  std::array<std::array<Z, 4>, 4> m{};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      m[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] = Z::from_double(u[i][k], s);
  const int idx[3] = {0, 1, 2};
  return !minor_det(m, idx, idx, 3).is_zero();
}

}  // namespace

RegionRelation ellipsoid_relation(const V& c0, const V (&a0)[3], const V& e0, const V& c1,
                                  const V (&a1)[3], const V& e1, bool certificates) noexcept {
  for (const V* v : {&c0, &e0, &c1, &e1, &a0[0], &a0[1], &a0[2], &a1[0], &a1[1], &a1[2]})
    if (!finite(*v)) return RegionRelation::undecided;
  for (int i = 0; i < 3; ++i)
    if (!(e0[i] > 0.0) || !(e1[i] > 0.0)) return RegionRelation::undecided;
  bool same = c0 == c1 && e0 == e1;
  for (int i = 0; i < 3; ++i) same = same && a0[i] == a1[i];
  try {
    int s = 0;  // common shift: every input times 2^s is an integer
    for (const V* v : {&c0, &e0, &c1, &e1, &a0[0], &a0[1], &a0[2], &a1[0], &a1[1], &a1[2]})
      for (int k = 0; k < 3; ++k)
        if ((*v)[k] != 0.0) s = std::max(s, -low_exponent((*v)[k]));
    if (!independent(a0, s) || !independent(a1, s)) return RegionRelation::undecided;
    if (same) return RegionRelation::equal;
    ZMat qa = exact_quadric(c0, a0, e0, s), qb = exact_quadric(c1, a1, e1, s);
    make_primitive(qa);
    make_primitive(qb);
    // Balance the two scales (a positive factor per matrix scales the roots of det(B - mu A) and
    // changes nothing else) so the roots tied to the shapes stay within the range of double.
    const auto trace_bits = [](const ZMat& m) {
      return static_cast<long>((m[0][0] + m[1][1] + m[2][2]).bit_length());
    };
    const long shift = trace_bits(qb) - trace_bits(qa);
    ZMat& smaller = shift > 0 ? qa : qb;
    for (auto& row : smaller)
      for (Z& x : row) x = x << static_cast<std::size_t>(shift > 0 ? shift : -shift);
    return exact_relation(qa, qb, Solid{c0, {a0[0], a0[1], a0[2]}, e0},
                          Solid{c1, {a1[0], a1[1], a1[2]}, e1}, s, certificates);
  } catch (const std::bad_alloc&) {
    return RegionRelation::undecided;
  }
}

}  // namespace locus::detail::quadric_pair3
