// SPDX-License-Identifier: BSL-1.0
// Distance between a point and a Bézier, B-spline or NURBS surface (distance/point_surface.hpp;
// row dist3.pt-paramsurface): the global branch and bound of docs/notes/distance.md, compiled
// once for float and double in 2D and 3D.

#include <locus/distance/detail/rational_span.hpp>
#include <locus/distance/detail/rescale.hpp>
#include <locus/distance/point_curve.hpp>
#include <locus/distance/point_surface.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <exception>
#include <limits>
#include <span>
#include <vector>

namespace locus {

namespace detail {
namespace {

/// A surface point with its first and second partials in the piece's local parameters.
template <class C, int N>
struct SurfaceJet {
  Vec<C, N> s, su, sv, suu, suv, svv;
};

/// Value, first and second derivative of the Bézier curve b[0..n] at t (b is overwritten).
template <class C, class V>
inline void bezier_jet(V* b, int n, C t, V& f, V& f1, V& f2) {
  f1 = V{};
  f2 = V{};
  if (n == 0) {
    f = b[0];
    return;
  }
  const C s = C(1) - t;
  for (int r = 1; r <= n - 2; ++r)
    for (int i = 0; i <= n - r; ++i) b[i] = s * b[i] + t * b[i + 1];
  if (n >= 2) {
    f2 = static_cast<C>(n * (n - 1)) * ((b[2] - b[1]) - (b[1] - b[0]));
    b[0] = s * b[0] + t * b[1];
    b[1] = s * b[1] + t * b[2];
  }
  f1 = static_cast<C>(n) * (b[1] - b[0]);
  f = s * b[0] + t * b[1];
}

/// The jet of S = A / W from the homogeneous A, A_u, A_v, A_uu, A_uv, A_vv (W the last
/// coordinate) by the quotient rule; false where W is not positive or a value is not finite.
template <class C, int N>
[[nodiscard]] inline bool rational_jet(const Vec<C, N + 1>* a, SurfaceJet<C, N>& j) {
  const C w = a[0][N];
  if (!(w > C(0))) return false;
  Vec<C, N> x[6];
  for (int k = 0; k < 6; ++k)
    for (int c = 0; c < N; ++c) x[k][c] = a[k][c];
  const C wu = a[1][N], wv = a[2][N], wuu = a[3][N], wuv = a[4][N], wvv = a[5][N];
  j.s = x[0] / w;
  j.su = (x[1] - wu * j.s) / w;
  j.sv = (x[2] - wv * j.s) / w;
  j.suu = (x[3] - C(2) * wu * j.su - wuu * j.s) / w;
  j.suv = (x[4] - wuv * j.s - wu * j.sv - wv * j.su) / w;
  j.svv = (x[5] - C(2) * wv * j.sv - wvv * j.s) / w;
  return is_finite(j.s) && is_finite(j.su) && is_finite(j.sv) && is_finite(j.suu) &&
         is_finite(j.suv) && is_finite(j.svv);
}

/// The jet of a rational tensor Bézier net (du + 1 rows along s, dv + 1 columns along t).
template <class C, int N>
[[nodiscard]] inline bool rect_jet(const Vec<C, N + 1>* net, int du, int dv, C s, C t,
                                   SurfaceJet<C, N>& j) {
  using V = Vec<C, N + 1>;
  const auto rows = static_cast<std::size_t>(du) + 1, cols = static_cast<std::size_t>(dv) + 1;
  SpanScratch<V, 16> work(cols), r0(rows), r1(rows), r2(rows);
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t k = 0; k < cols; ++k) work[k] = net[i * cols + k];
    bezier_jet(work.data(), dv, t, r0[i], r1[i], r2[i]);
  }
  V a[6], unused0, unused1;
  bezier_jet(r0.data(), du, s, a[0], a[1], a[3]);
  bezier_jet(r1.data(), du, s, a[2], a[4], unused0);
  bezier_jet(r2.data(), du, s, a[5], unused0, unused1);
  return rational_jet<C, N>(a, j);
}

/// The jet of a rational triangular Bézier net of degree n at barycentric (u, v, 1 - u - v),
/// partials with respect to u and v.
template <class C, int N>
[[nodiscard]] inline bool triangle_jet(const Vec<C, N + 1>* net, int n, C u, C v,
                                       SurfaceJet<C, N>& j) {
  using V = Vec<C, N + 1>;
  const C w = C(1) - u - v;
  const auto count = static_cast<std::size_t>(triangle_control_count(n));
  SpanScratch<V, 28> b(count);
  for (std::size_t i = 0; i < count; ++i) b[i] = net[i];
  V a[6] = {};
  if (n == 0) {
    a[0] = b[0];
  } else {
    for (int m = n; m >= 3; --m) triangle_level(b.data(), m, u, v, w);
    if (n >= 2) {
      // Level n - 2, a quadratic net: b002 b101 b200 b011 b110 b020 (triangle_index order).
      const C k = static_cast<C>(n * (n - 1));
      a[3] = k * ((b[2] - b[1]) - (b[1] - b[0]));
      a[5] = k * ((b[5] - b[3]) - (b[3] - b[0]));
      a[4] = k * ((b[4] - b[1]) - (b[3] - b[0]));
      triangle_level(b.data(), 2, u, v, w);
    }
    // Level n - 1: b001 = b[0], b100 = b[1], b010 = b[2].
    a[1] = static_cast<C>(n) * (b[1] - b[0]);
    a[2] = static_cast<C>(n) * (b[2] - b[0]);
    a[0] = u * b[1] + v * b[2] + w * b[0];
  }
  return rational_jet<C, N>(a, j);
}

/// out[j * ostride], j = 0..n: the Bézier points of the piece [a, b] of the curve
/// in[k * istride], k = 0..n, by blossoming (point j is the blossom b(a^(n-j), b^j)).
template <class C, class V>
inline void bezier_piece(const V* in, std::size_t istride, int n, C a, C b, V* out,
                         std::size_t ostride, V* scratch) {
  const auto un = static_cast<std::size_t>(n);
  for (std::size_t j = 0; j <= un; ++j) {
    for (std::size_t k = 0; k <= un; ++k) scratch[k] = in[k * istride];
    for (std::size_t r = 1; r <= un; ++r) {
      const C t = r <= un - j ? a : b;
      const C s = C(1) - t;
      for (std::size_t i = 0; i + r <= un; ++i) scratch[i] = s * scratch[i] + t * scratch[i + 1];
    }
    out[j * ostride] = scratch[0];
  }
}

/// The net of the sub-box [s0, s1] x [t0, t1] of a rational tensor net.
template <class C, class V>
inline void rect_subnet(const V* net, int du, int dv, C s0, C s1, C t0, C t1, V* out) {
  const auto rows = static_cast<std::size_t>(du) + 1, cols = static_cast<std::size_t>(dv) + 1;
  SpanScratch<V, 64> tmp(rows * cols);
  SpanScratch<V, 16> scratch(std::max(rows, cols));
  for (std::size_t i = 0; i < rows; ++i)
    bezier_piece(net + i * cols, 1, dv, t0, t1, tmp.data() + i * cols, 1, scratch.data());
  for (std::size_t k = 0; k < cols; ++k)
    bezier_piece(tmp.data() + k, cols, du, s0, s1, out + k, cols, scratch.data());
}

/// The net of the sub-triangle with parent parameters (corners a, b, c) of a triangular net:
/// control point ijk is the blossom b(a^i, b^j, c^k).
template <class C, class V>
inline void triangle_subnet(const V* net, int n, const Vec<C, 2>* corner, V* out) {
  const auto count = static_cast<std::size_t>(triangle_control_count(n));
  SpanScratch<V, 28> b(count);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i + j <= n; ++i) {
      for (std::size_t q = 0; q < count; ++q) b[q] = net[q];
      for (int m = n; m >= 1; --m) {
        const int level = n - m;
        const Vec<C, 2>& x = corner[level < i ? 0 : (level < i + j ? 1 : 2)];
        triangle_level(b.data(), m, x.x, x.y, C(1) - x.x - x.y);
      }
      out[static_cast<std::size_t>(triangle_index(n, i, j))] = b[0];
    }
}

/// The nearest candidate so far (global parameters), and the two nearest distinct CRITICAL
/// candidates (Newton-converged points, edge-curve minima that Q does not decrease from
/// inward) for the tie test: sub-piece corners and the other edge minima sharpen the bound but,
/// being no minima of the surface, are never evidence of a second minimum.
template <class C, int N>
struct SurfaceNearest {
  bool found = false;
  bool best_critical = false;  // the best point is a critical candidate (not to be polished)
  C best_d2 = std::numeric_limits<C>::infinity();
  Vec<C, 2> best_param{};
  Vec<C, N> best_point{};
  NearestTracker<C, N> critical;  // its best_t is unused
  C sep2 = C(0);                  // squared separation below which two points are "the same"
  C tie_rel = C(0);               // the tie test's tolerance, relative on squared distances

  void offer(C d2, const Vec<C, 2>& prm, const Vec<C, N>& x, bool is_critical = true) {
    if (!(d2 == d2)) return;
    if (is_critical) critical.offer(d2, C(0), x);
    if (!found || d2 < best_d2) {
      found = true;
      best_critical = is_critical;
      best_d2 = d2;
      best_param = prm;
      best_point = x;
    }
  }
  /// Whether a candidate would be a rival of the best point for the tie test: distinct from
  /// it and within tie_rel of it.
  [[nodiscard]] bool rival(C d2, const Vec<C, N>& x) const {
    return d2 <= best_d2 + tie_rel * best_d2 + std::numeric_limits<C>::min() &&
           sqr_length(x - best_point) > sep2;
  }
  /// True when a critical candidate is a rival.
  [[nodiscard]] bool tied() const {
    return (critical.found && rival(critical.best_d2, critical.best_point)) ||
           (critical.has_alt && rival(critical.alt_d2, critical.alt_point));
  }
};

/// An edge-curve minimum of a piece (kind: which edge), whether it is a critical candidate
/// decided after the search, for the few that could be rivals. c: its parameter along the edge
/// in [0, 1], or -1 where not known yet.
template <class C, int N>
struct EdgeMinimum {
  C d2;
  Vec<C, N> x;
  std::size_t piece;
  int kind;
  C c;
};

/// The minima of a rational Bézier edge curve h[0..d] of a piece, the nearest point and the
/// nearest one distinct from it, to add(c, d2, x): c the curve parameter in [0, 1], -1 for the
/// second (the tracker keeps no parameter for it; edge_param finds it when needed).
template <class C, int N, class Add>
inline void edge_minima(const Vec<C, N + 1>* h, int d, const Vec<C, N>& p, C sep2, const Add& add) {
  NearestTracker<C, N> e;
  e.sep2 = sep2;
  point_span_candidates<C, N>(h, d, p, C(0), C(1), e);
  if (!e.found) return;
  add(e.best_t, e.best_d2, e.best_point);
  if (e.has_alt) add(C(-1), e.alt_d2, e.alt_point);
}

/// The parameter in [0, 1] of the point x of the edge curve h[0..d]: that of its nearest point.
template <class C, int N>
[[nodiscard]] inline C edge_param(const Vec<C, N + 1>* h, int d, const Vec<C, N>& x) {
  NearestTracker<C, N> a;
  point_span_candidates<C, N>(h, d, x, C(0), C(1), a);
  return a.best_t;
}

/// Whether Q = |S - p|^2 decreases from the jet's point along the parameter direction dir: its
/// slope (S - p) . S_dir is negative beyond the rounding of the jet (coordinates of magnitude m,
/// derivatives of a degree-deg piece).
template <class C, int N>
[[nodiscard]] inline bool descends(const SurfaceJet<C, N>& j, const Vec<C, N>& p,
                                   const Vec<C, 2>& dir, int deg) {
  const Vec<C, N> r = j.s - p, sd = dir.x * j.su + dir.y * j.sv;
  const C m = max_abs(j.s) + max_abs(p);
  const C err = C(64) * std::numeric_limits<C>::epsilon() *
                (length(r) * (length(sd) + C(deg + 1) * m) + length(sd) * m);
  return dot(r, sd) < -err;
}

/// The lower bound of the distance from p to the convex hull of the projected net x[0..count)
/// described in the header comment; `toward` is a second direction point (the best point).
template <class C, int N>
[[nodiscard]] inline C hull_lower_bound(const Vec<C, N>* x, std::size_t count, const Vec<C, N>& p,
                                        const Vec<C, N>* toward) {
  Vec<C, N> lo = x[0], hi = x[0], mean{};
  C mag = max_abs(p);
  for (std::size_t k = 0; k < count; ++k) {
    lo = cwise_min(lo, x[k]);
    hi = cwise_max(hi, x[k]);
    mean += x[k];
    mag = std::max(mag, max_abs(x[k]));
  }
  mean = mean / static_cast<C>(count);
  C box2 = C(0);
  for (int i = 0; i < N; ++i) {
    const C g = std::max({lo[i] - p[i], p[i] - hi[i], C(0)});
    box2 += g * g;
  }
  C lb = std::sqrt(box2);
  const auto directional = [&](Vec<C, N> e) {
    const C len = length(e);
    if (!(len > C(0))) return;
    e = e / len;
    C m = std::numeric_limits<C>::infinity();
    for (std::size_t k = 0; k < count; ++k) m = std::min(m, dot(x[k] - p, e));
    lb = std::max(lb, m);
  };
  directional(mean - p);
  if (toward != nullptr) directional(*toward - p);
  // The bound's own rounding (a few operations on coordinates of magnitude mag).
  return std::max(C(0), lb - C(16) * std::numeric_limits<C>::epsilon() * mag);
}

/// binom(n, k) in C (exact for the moderate degrees of surfaces).
template <class C>
[[nodiscard]] inline C binomial(int n, int k) {
  C b = C(1);
  for (int i = 0; i < k; ++i) b = b * C(n - i) / C(i + 1);
  return b;
}

/// A lower bound of |S - p| over a rational tensor net (degrees m, n) from the Bernstein form of
/// the squared distance: with Q = A - p W, |S - p|^2 = |Q|^2 / W^2, and numerator and
/// denominator are Bernstein polynomials of degrees (2m, 2n) (products of the nets), so the
/// ratio is at least the smallest ratio of their coefficients (W^2's are positive). Exact where
/// the distance is constant (a sphere patch seen from its centre), where the hull bounds fail.
template <class C, int N>
[[nodiscard]] inline C rect_distance_lower_bound(const Vec<C, N + 1>* net, int m, int n,
                                                 const Vec<C, N>& p) {
  const auto rows = static_cast<std::size_t>(m) + 1, cols = static_cast<std::size_t>(n) + 1;
  const auto r2 = 2 * rows - 1, c2 = 2 * cols - 1;
  SpanScratch<Vec<C, N>, 64> q(rows * cols);
  SpanScratch<C, 64> w(rows * cols), qa(rows * cols);
  for (std::size_t k = 0; k < rows * cols; ++k) {
    w[k] = net[k][N];
    for (int c = 0; c < N; ++c) q[k][c] = net[k][c] - p[c] * w[k];
    qa[k] = length(q[k]);
  }
  // The product weights binom(m, a) binom(m, c) / binom(2m, a + c), per direction.
  const auto weights = [](int deg, SpanScratch<C, 64>& f) {
    const auto sz = static_cast<std::size_t>(deg) + 1;
    for (std::size_t a = 0; a < sz; ++a)
      for (std::size_t c = 0; c < sz; ++c)
        f[a * sz + c] = binomial<C>(deg, static_cast<int>(a)) *
                        binomial<C>(deg, static_cast<int>(c)) /
                        binomial<C>(2 * deg, static_cast<int>(a + c));
  };
  SpanScratch<C, 64> fu(rows * rows), fv(cols * cols);
  weights(m, fu);
  weights(n, fv);
  SpanScratch<C, 256> num(r2 * c2), den(r2 * c2), mag(r2 * c2);
  for (std::size_t k = 0; k < r2 * c2; ++k) num[k] = den[k] = mag[k] = C(0);
  for (std::size_t a = 0; a < rows; ++a)
    for (std::size_t c = 0; c < rows; ++c)
      for (std::size_t b = 0; b < cols; ++b)
        for (std::size_t d = 0; d < cols; ++d) {
          const std::size_t k = (a + c) * c2 + (b + d);
          const C f = fu[a * rows + c] * fv[b * cols + d];
          const std::size_t x = a * cols + b, y = c * cols + d;
          num[k] += f * dot(q[x], q[y]);
          den[k] += f * w[x] * w[y];
          mag[k] += f * qa[x] * qa[y];
        }
  C lb = std::numeric_limits<C>::infinity();
  const C slack = C(8 * (m + n + 4)) * std::numeric_limits<C>::epsilon();
  for (std::size_t k = 0; k < r2 * c2; ++k) {
    if (!(den[k] > C(0))) return C(0);
    lb = std::min(lb, (num[k] - slack * mag[k]) / den[k]);
  }
  return lb > C(0) ? std::sqrt(lb) : C(0);
}

/// The same bound for a rational triangular net of degree n: the product of two degree-n
/// Bernstein triangles is of degree 2n with coefficient I = sum over J + K = I of
/// multinomial(n; J) multinomial(n; K) / multinomial(2n; I) a_J b_K.
template <class C, int N>
[[nodiscard]] inline C triangle_distance_lower_bound(const Vec<C, N + 1>* net, int n,
                                                     const Vec<C, N>& p) {
  const auto cnt = static_cast<std::size_t>(triangle_control_count(n));
  const auto cnt2 = static_cast<std::size_t>(triangle_control_count(2 * n));
  SpanScratch<Vec<C, N>, 28> q(cnt);
  SpanScratch<C, 28> w(cnt), qa(cnt), mult(cnt);
  SpanScratch<C, 91> num(cnt2), den(cnt2), mag(cnt2), mult2(cnt2);
  const auto multinomial = [](int deg, int i, int j) {
    return binomial<C>(deg, i) * binomial<C>(deg - i, j);
  };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i + j <= n; ++i) {
      const auto k = static_cast<std::size_t>(triangle_index(n, i, j));
      w[k] = net[k][N];
      for (int c = 0; c < N; ++c) q[k][c] = net[k][c] - p[c] * w[k];
      qa[k] = length(q[k]);
      mult[k] = multinomial(n, i, j);
    }
  for (int j = 0; j <= 2 * n; ++j)
    for (int i = 0; i + j <= 2 * n; ++i) {
      const auto k = static_cast<std::size_t>(triangle_index(2 * n, i, j));
      mult2[k] = multinomial(2 * n, i, j);
      num[k] = den[k] = mag[k] = C(0);
    }
  for (int j1 = 0; j1 <= n; ++j1)
    for (int i1 = 0; i1 + j1 <= n; ++i1)
      for (int j2 = 0; j2 <= n; ++j2)
        for (int i2 = 0; i2 + j2 <= n; ++i2) {
          const auto x = static_cast<std::size_t>(triangle_index(n, i1, j1));
          const auto y = static_cast<std::size_t>(triangle_index(n, i2, j2));
          const auto k = static_cast<std::size_t>(triangle_index(2 * n, i1 + i2, j1 + j2));
          const C f = mult[x] * mult[y] / mult2[k];
          num[k] += f * dot(q[x], q[y]);
          den[k] += f * w[x] * w[y];
          mag[k] += f * qa[x] * qa[y];
        }
  C lb = std::numeric_limits<C>::infinity();
  const C slack = C(8 * (2 * n + 4)) * std::numeric_limits<C>::epsilon();
  for (std::size_t k = 0; k < cnt2; ++k) {
    if (!(den[k] > C(0))) return C(0);
    lb = std::min(lb, (num[k] - slack * mag[k]) / den[k]);
  }
  return lb > C(0) ? std::sqrt(lb) : C(0);
}

/// The parameter domain of a piece in local coordinates: the unit square or the unit triangle.
struct SquareDomain {
  template <class C>
  [[nodiscard]] static Vec<C, 2> project(const Vec<C, 2>& x) {
    return {std::clamp(x.x, C(0), C(1)), std::clamp(x.y, C(0), C(1))};
  }
  /// The number of constraints that block descent along -g at x (0, 1, 2) and, for one, the
  /// direction along it.
  template <class C>
  [[nodiscard]] static int blocking(const Vec<C, 2>& x, const Vec<C, 2>& g, Vec<C, 2>& along) {
    const bool bu = (x.x <= C(0) && g.x > C(0)) || (x.x >= C(1) && g.x < C(0));
    const bool bv = (x.y <= C(0) && g.y > C(0)) || (x.y >= C(1) && g.y < C(0));
    along = bu ? Vec<C, 2>{C(0), C(1)} : Vec<C, 2>{C(1), C(0)};
    return int(bu) + int(bv);
  }
};

struct TriangleDomain {
  template <class C>
  [[nodiscard]] static Vec<C, 2> project(const Vec<C, 2>& x) {
    if (x.x >= C(0) && x.y >= C(0) && x.x + x.y <= C(1)) return x;
    // The nearest of the three edges' nearest points.
    const C a = std::clamp(C(0.5) * (x.x - x.y + C(1)), C(0), C(1));
    const Vec<C, 2> cand[3] = {
        {C(0), std::clamp(x.y, C(0), C(1))}, {std::clamp(x.x, C(0), C(1)), C(0)}, {a, C(1) - a}};
    Vec<C, 2> best = cand[0];
    for (const auto& c : cand)
      if (sqr_length(c - x) < sqr_length(best - x)) best = c;
    return best;
  }
  template <class C>
  [[nodiscard]] static int blocking(const Vec<C, 2>& x, const Vec<C, 2>& g, Vec<C, 2>& along) {
    const C tol = C(4) * std::numeric_limits<C>::epsilon();
    const bool b0 = x.x <= C(0) && g.x > C(0);
    const bool b1 = x.y <= C(0) && g.y > C(0);
    const bool b2 = x.x + x.y >= C(1) - tol && g.x + g.y < C(0);
    along = b0 ? Vec<C, 2>{C(0), C(1)} : (b1 ? Vec<C, 2>{C(1), C(0)} : Vec<C, 2>{C(1), C(-1)});
    return int(b0) + int(b1) + int(b2);
  }
};

/// Bounded, projected, damped Newton descent of Q = |S - p|^2 from x on the domain `Dom`;
/// jet(x, j) evaluates the piece. Returns the last iterate's squared distance, point and x.
template <class C, int N, class Dom, class Jet>
inline bool surface_newton(const Jet& jet, const Vec<C, N>& p, Vec<C, 2>& x, C& f,
                           Vec<C, N>& point) {
  constexpr C eps = std::numeric_limits<C>::epsilon();
  SurfaceJet<C, N> j;
  if (!jet(x, j)) return false;
  Vec<C, N> r = j.s - p;
  f = sqr_length(r);
  const auto grad = [&p](const SurfaceJet<C, N>& q) {
    const Vec<C, N> rr = q.s - p;
    return Vec<C, 2>{dot(rr, q.su), dot(rr, q.sv)};
  };
  Vec<C, 2> g = grad(j);
  for (int it = 0; it < 48; ++it) {
    const C h00 = dot(j.su, j.su) + dot(r, j.suu), h01 = dot(j.su, j.sv) + dot(r, j.suv),
            h11 = dot(j.sv, j.sv) + dot(r, j.svv);
    Vec<C, 2> along{};
    const int nb = Dom::blocking(x, g, along);
    Vec<C, 2> d{};
    if (nb >= 2) break;
    if (nb == 1) {
      const C gt = dot(g, along);
      const C ht =
          along.x * along.x * h00 + C(2) * along.x * along.y * h01 + along.y * along.y * h11;
      if (ht > C(0))
        d = (-gt / ht) * along;
      else if (gt != C(0))
        d = (gt > C(0) ? C(-0.5) : C(0.5)) * along;
    } else {
      const C det = h00 * h11 - h01 * h01;
      if (h00 > C(0) && det > C(64) * eps * (h00 * h11 + h01 * h01)) {
        d = Vec<C, 2>{-(h11 * g.x - h01 * g.y) / det, -(h00 * g.y - h01 * g.x) / det};
      } else {
        // Gauss-Newton with Levenberg damping: positive definite unless S_u = S_v = 0.
        const C g00 = dot(j.su, j.su), g01 = dot(j.su, j.sv), g11 = dot(j.sv, j.sv);
        const C mu = C(1e-3) * (g00 + g11) + std::numeric_limits<C>::min();
        const C a = g00 + mu, b = g11 + mu, dd = a * b - g01 * g01;
        if (dd > C(0)) d = Vec<C, 2>{-(b * g.x - g01 * g.y) / dd, -(a * g.y - g01 * g.x) / dd};
      }
    }
    if (!is_finite(d) || (d.x == C(0) && d.y == C(0))) break;
    bool accepted = false;
    SurfaceJet<C, N> jn;
    Vec<C, 2> xn{};
    C fn = C(0);
    for (int bt = 0; bt < 40; ++bt, d = C(0.5) * d) {
      xn = Dom::project(x + d);
      if (xn.x == x.x && xn.y == x.y) break;
      if (!jet(xn, jn)) continue;
      fn = sqr_length(jn.s - p);
      // Near the minimiser Q is flat to rounding: a step that does not increase Q beyond its
      // rounding and halves the gradient is progress too.
      const Vec<C, 2> gn = grad(jn);
      if (fn < f || (fn <= f + C(16) * eps * (f + sqr_length(p) + sqr_length(jn.s)) &&
                     sqr_length(gn) < C(0.25) * sqr_length(g))) {
        accepted = true;
        g = gn;
        break;
      }
    }
    if (!accepted) break;
    const C step = std::max(std::fabs(xn.x - x.x), std::fabs(xn.y - x.y));
    x = xn;
    j = jn;
    f = fn;
    r = j.s - p;
    if (step <= C(4) * eps) break;
  }
  point = j.s;
  return true;
}

/// One rational Bézier piece of a surface: its net (in the shared pool) and the global
/// parameters of its local (0, 0) corner and extents (rectangles: u = u0 + s du, v = v0 + t dv).
template <class C>
struct SurfacePiece {
  std::size_t offset;
  C u0, u1, v0, v1;
};

template <class C>
struct SurfaceWork {
  C lb;
  int piece;
  int depth;
  Vec<C, 2> a, b, c;  // rectangles: a = (s0, t0), b = (s1, t1); triangles: the three corners
};

template <class C>
[[nodiscard]] inline bool work_after(const SurfaceWork<C>& x, const SurfaceWork<C>& y) {
  return x.lb > y.lb;
}

/// Squared diagonal of the box of the projected points of a homogeneous pool.
template <class C, int N>
[[nodiscard]] inline C pool_sqr_size(const std::vector<Vec<C, N + 1>>& pool) {
  Vec<C, N> lo = span_project<C, N>(pool[0]), hi = lo;
  for (const auto& h : pool) {
    const Vec<C, N> x = span_project<C, N>(h);
    lo = cwise_min(lo, x);
    hi = cwise_max(hi, x);
  }
  return sqr_length(hi - lo);
}

/// The branch and bound over tensor pieces of degrees (du, dv) (header comment).
/// The rounding part of the search tolerance tau (header comment): that of the bounds in C, and
/// the precision T of the input (a float surface is only defined to float accuracy, and a
/// near-constant distance within it would otherwise be refined to the work budget).
template <Real T>
inline constexpr compute_t<T> tau_rounding =
    compute_t<T>(64) * std::numeric_limits<compute_t<T>>::epsilon() +
    compute_t<T>(16) * static_cast<compute_t<T>>(std::numeric_limits<T>::epsilon());

/// The tie test's tolerance (header comment): 64 eps of T, relative on squared distances.
template <Real T>
inline constexpr compute_t<T> tie_tolerance =
    compute_t<T>(64) * static_cast<compute_t<T>>(std::numeric_limits<T>::epsilon());

template <class C, int N>
inline void rect_search(const std::vector<Vec<C, N + 1>>& pool,
                        const std::vector<SurfacePiece<C>>& pieces, int du, int dv,
                        const Vec<C, N>& p, C rounding, SurfaceNearest<C, N>& tr) {
  using V = Vec<C, N + 1>;
  const auto rows = static_cast<std::size_t>(du) + 1, cols = static_cast<std::size_t>(dv) + 1;
  const std::size_t cnt = rows * cols;
  const C size2 = pool_sqr_size<C, N>(pool);
  tr.sep2 = tr.critical.sep2 = C(256) * std::numeric_limits<C>::epsilon() * size2;
  const auto piece_jet = [&](std::size_t k) {
    const V* top = pool.data() + pieces[k].offset;
    return [top, du, dv](const Vec<C, 2>& st, SurfaceJet<C, N>& j) {
      return rect_jet<C, N>(top, du, dv, st.x, st.y, j);
    };
  };
  const auto global_of = [&](std::size_t k, const Vec<C, 2>& st) {
    const SurfacePiece<C>& pc = pieces[k];
    return Vec<C, 2>{pc.u0 + st.x * (pc.u1 - pc.u0), pc.v0 + st.y * (pc.v1 - pc.v0)};
  };
  // The pieces form a grid with the v spans inner (tensor_pieces): nv pieces per u span.
  std::size_t nv = 1;
  while (nv < pieces.size() && pieces[nv].u0 == pieces[0].u0) ++nv;
  const std::size_t nu = pieces.size() / nv;
  // Edge kind 0, 1: local t = 0, 1 (the net's first / last column, along s); kind 2, 3: local
  // s = 0, 1 (first / last row, along t); c the coordinate along the edge.
  const auto edge_local = [](int kind, C c) {
    return kind < 2 ? Vec<C, 2>{c, C(kind)} : Vec<C, 2>{C(kind - 2), c};
  };
  SpanScratch<V, 16> edge(std::max(rows, cols));
  const auto edge_net = [&](std::size_t k, int kind) {
    const V* net = pool.data() + pieces[k].offset;
    if (kind < 2) {
      for (std::size_t i = 0; i < rows; ++i) edge[i] = net[i * cols + (kind == 0 ? 0 : cols - 1)];
      return du;
    }
    for (std::size_t i = 0; i < cols; ++i) edge[i] = net[(kind == 2 ? 0 : rows - 1) * cols + i];
    return dv;
  };
  // An edge point is a critical candidate only if Q does not decrease from it into its piece,
  // nor into the neighbouring piece where the edge is a knot line: otherwise it is no minimum of
  // the surface and no evidence of a tie, only a bound (and a start for the final polish).
  // Whether Q decreases from the point st of piece k into a neighbouring piece across a knot
  // line that st lies on: then st is no minimum of the surface, whatever it is in piece k (a
  // Newton descent blocked there, an edge minimum).
  const auto descends_across = [&](std::size_t k, const Vec<C, 2>& st) {
    const std::size_t iu = k / nv, iv = k % nv;
    const auto down = [&](std::size_t kn, const Vec<C, 2>& stn, const Vec<C, 2>& dir) {
      SurfaceJet<C, N> j;
      return piece_jet(kn)(stn, j) && descends<C, N>(j, p, dir, std::max(du, dv));
    };
    return (st.y <= C(0) && iv > 0 && down(k - 1, {st.x, C(1)}, {C(0), C(-1)})) ||
           (st.y >= C(1) && iv + 1 < nv && down(k + 1, {st.x, C(0)}, {C(0), C(1)})) ||
           (st.x <= C(0) && iu > 0 && down(k - nv, {C(1), st.y}, {C(-1), C(0)})) ||
           (st.x >= C(1) && iu + 1 < nu && down(k + nv, {C(0), st.y}, {C(1), C(0)}));
  };
  const auto edge_critical = [&](std::size_t k, int kind, C c) {
    const Vec<C, 2> st = edge_local(kind, c);
    const Vec<C, 2> dir =
        kind < 2 ? Vec<C, 2>{C(0), C(1 - 2 * kind)} : Vec<C, 2>{C(1 - 2 * (kind - 2)), C(0)};
    SurfaceJet<C, N> j;
    if (piece_jet(k)(st, j) && descends<C, N>(j, p, dir, std::max(du, dv))) return false;
    return !descends_across(k, st);
  };
  std::vector<EdgeMinimum<C, N>> edge_mins;
  for (std::size_t k = 0; k < pieces.size(); ++k)
    for (int kind = 0; kind < 4; ++kind) {
      const int deg = edge_net(k, kind);
      edge_minima<C, N>(edge.data(), deg, p, tr.sep2, [&](C c, C d2, const Vec<C, N>& x) {
        // The second minimum of an edge never improves on its first, just offered.
        if (c >= C(0)) tr.offer(d2, global_of(k, edge_local(kind, c)), x, false);
        edge_mins.push_back({d2, x, k, kind, c});
      });
    }
  std::vector<Vec<C, N>> pts(cnt);
  std::vector<V> sub(cnt);
  const auto project_net = [&](const V* net) {
    for (std::size_t k = 0; k < cnt; ++k) pts[k] = span_project<C, N>(net[k]);
  };
  std::vector<SurfaceWork<C>> heap;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    project_net(pool.data() + pieces[i].offset);
    heap.push_back({hull_lower_bound<C, N>(pts.data(), cnt, p, nullptr),
                    static_cast<int>(i),
                    0,
                    {C(0), C(0)},
                    {C(1), C(1)},
                    {}});
  }
  std::make_heap(heap.begin(), heap.end(), work_after<C>);
  const C tau_scale = std::sqrt(size2) + max_abs(p);
  const std::size_t budget = 4096 + 16 * pieces.size();
  for (std::size_t done = 0; !heap.empty() && done < budget; ++done) {
    std::pop_heap(heap.begin(), heap.end(), work_after<C>);
    const SurfaceWork<C> w = heap.back();
    heap.pop_back();
    const C tau = std::ldexp(std::sqrt(size2), -26) + rounding * tau_scale;
    const auto settled = [&](C lb) { return tr.found && lb >= std::sqrt(tr.best_d2) - tau; };
    if (settled(w.lb)) break;  // every remaining bound is at least as large
    const SurfacePiece<C>& pc = pieces[static_cast<std::size_t>(w.piece)];
    const V* top = pool.data() + pc.offset;
    rect_subnet<C, V>(top, du, dv, w.a.x, w.b.x, w.a.y, w.b.y, sub.data());
    project_net(sub.data());
    const Vec<C, N> best = tr.best_point;
    C lb = std::max(w.lb, hull_lower_bound<C, N>(pts.data(), cnt, p, tr.found ? &best : nullptr));
    if (settled(lb)) continue;
    lb = std::max(lb, rect_distance_lower_bound<C, N>(sub.data(), du, dv, p));
    if (settled(lb)) continue;
    const auto global = [&pc](const Vec<C, 2>& st) {
      return Vec<C, 2>{pc.u0 + st.x * (pc.u1 - pc.u0), pc.v0 + st.y * (pc.v1 - pc.v0)};
    };
    // Corners of the sub-piece are points of the surface.
    const std::size_t corner[4] = {0, cols - 1, (rows - 1) * cols, cnt - 1};
    const Vec<C, 2> cpar[4] = {w.a, {w.a.x, w.b.y}, {w.b.x, w.a.y}, w.b};
    for (int k = 0; k < 4; ++k)
      tr.offer(sqr_length(pts[corner[k]] - p), global(cpar[k]), pts[corner[k]], false);
    const Vec<C, 2> g0 = global(w.a), g1 = global(w.b);
    const bool holds_best = tr.found && tr.best_param.x >= g0.x && tr.best_param.x <= g1.x &&
                            tr.best_param.y >= g0.y && tr.best_param.y <= g1.y;
    if (!holds_best) {
      Vec<C, 2> x = C(0.5) * (w.a + w.b);
      C f = C(0);
      Vec<C, N> at{};
      const auto jet = [top, du, dv](const Vec<C, 2>& st, SurfaceJet<C, N>& j) {
        return rect_jet<C, N>(top, du, dv, st.x, st.y, j);
      };
      if (surface_newton<C, N, SquareDomain>(jet, p, x, f, at))
        tr.offer(f, global(x), at, !descends_across(static_cast<std::size_t>(w.piece), x));
      if (settled(lb)) continue;
    }
    // Split along the physically longer direction (never along a degree-0 one).
    C ext_u = C(0), ext_v = C(0);
    for (std::size_t k = 0; k < cols; ++k)
      ext_u = std::max(ext_u, sqr_length(pts[(rows - 1) * cols + k] - pts[k]));
    for (std::size_t i = 0; i < rows; ++i)
      ext_v = std::max(ext_v, sqr_length(pts[i * cols + cols - 1] - pts[i * cols]));
    if (du == 0) ext_u = C(0);
    if (dv == 0) ext_v = C(0);
    if (!(ext_u > C(0) || ext_v > C(0)) || w.depth >= 96) continue;
    const bool along_u = ext_u >= ext_v;
    const C lo = along_u ? w.a.x : w.a.y, hi = along_u ? w.b.x : w.b.y;
    const C mid = C(0.5) * (lo + hi);
    if (!(mid > lo && mid < hi)) continue;
    SurfaceWork<C> c0 = w, c1 = w;
    c0.lb = c1.lb = lb;
    c0.depth = c1.depth = w.depth + 1;
    if (along_u) {
      c0.b.x = mid;
      c1.a.x = mid;
    } else {
      c0.b.y = mid;
      c1.a.y = mid;
    }
    heap.push_back(c0);
    std::push_heap(heap.begin(), heap.end(), work_after<C>);
    heap.push_back(c1);
    std::push_heap(heap.begin(), heap.end(), work_after<C>);
  }
  // A best point that is no critical candidate (a sub-piece corner, an edge point that Q
  // descends from) is only certified to within tau of the minimum, and the search skips
  // boxes whose bound comes within tau of it: Newton from it, on every piece holding it.
  if (tr.found && !tr.best_critical) {
    const Vec<C, 2> g = tr.best_param;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      const SurfacePiece<C>& pc = pieces[k];
      if (!(g.x >= pc.u0 && g.x <= pc.u1 && g.y >= pc.v0 && g.y <= pc.v1)) continue;
      Vec<C, 2> x = SquareDomain::project(
          Vec<C, 2>{(g.x - pc.u0) / (pc.u1 - pc.u0), (g.y - pc.v0) / (pc.v1 - pc.v0)});
      C f = C(0);
      Vec<C, N> at{};
      if (surface_newton<C, N, SquareDomain>(piece_jet(k), p, x, f, at))
        tr.offer(f, global_of(k, x), at, !descends_across(k, x));
    }
  }
  // The edge minima that could be rivals in the tie test, if they are minima of the surface.
  for (const EdgeMinimum<C, N>& e : edge_mins) {
    if (!tr.rival(e.d2, e.x)) continue;
    const int deg = edge_net(e.piece, e.kind);
    const C c = e.c >= C(0) ? e.c : edge_param<C, N>(edge.data(), deg, e.x);
    if (edge_critical(e.piece, e.kind, c)) tr.critical.offer(e.d2, C(0), e.x);
  }
}

/// The branch and bound over one triangular piece of degree n (header comment).
template <class C, int N>
inline void triangle_search(const std::vector<Vec<C, N + 1>>& net, int n, const Vec<C, N>& p,
                            C rounding, SurfaceNearest<C, N>& tr) {
  using V = Vec<C, N + 1>;
  const auto cnt = static_cast<std::size_t>(triangle_control_count(n));
  const C size2 = pool_sqr_size<C, N>(net);
  tr.sep2 = tr.critical.sep2 = C(256) * std::numeric_limits<C>::epsilon() * size2;
  // Edges (kind): v = 0 (P_i0k, u from 0 to 1), u = 0 (P_0jk, v from 0 to 1), w = 0 (P_ij0, u
  // from 0 to 1 with v = 1 - u); an edge point is critical only if Q does not decrease inward
  // (as for tensor pieces).
  SpanScratch<V, 16> edge(static_cast<std::size_t>(n) + 1);
  const auto edge_net = [&](int kind) {
    for (int i = 0; i <= n; ++i) {
      const int a = kind == 1 ? 0 : i, b = kind == 0 ? 0 : (kind == 1 ? i : n - i);
      edge[static_cast<std::size_t>(i)] = net[static_cast<std::size_t>(triangle_index(n, a, b))];
    }
  };
  const auto on_edge = [](int kind, C t) {
    return kind == 0 ? Vec<C, 2>{t, C(0)}
                     : (kind == 1 ? Vec<C, 2>{C(0), t} : Vec<C, 2>{t, C(1) - t});
  };
  const auto jet = [top = net.data(), n](const Vec<C, 2>& uv, SurfaceJet<C, N>& j) {
    return triangle_jet<C, N>(top, n, uv.x, uv.y, j);
  };
  const auto edge_critical = [&](int kind, C t) {
    const Vec<C, 2> inward[3] = {{C(0), C(1)}, {C(1), C(0)}, {C(-1), C(-1)}};
    SurfaceJet<C, N> j;
    return !(jet(on_edge(kind, t), j) &&
             descends<C, N>(j, p, inward[static_cast<std::size_t>(kind)], n));
  };
  std::vector<EdgeMinimum<C, N>> edge_mins;
  for (int kind = 0; kind < 3; ++kind) {
    edge_net(kind);
    edge_minima<C, N>(edge.data(), n, p, tr.sep2, [&](C t, C d2, const Vec<C, N>& x) {
      if (t >= C(0)) tr.offer(d2, on_edge(kind, t), x, false);
      edge_mins.push_back({d2, x, 0, kind, t});
    });
  }
  std::vector<Vec<C, N>> pts(cnt);
  std::vector<V> sub(cnt);
  const auto project_net = [&](const V* x) {
    for (std::size_t k = 0; k < cnt; ++k) pts[k] = span_project<C, N>(x[k]);
  };
  project_net(net.data());
  std::vector<SurfaceWork<C>> heap;
  // Corners: (1, 0) = e1 (P_n00), (0, 1) = e2 (P_0n0), (0, 0) = e3 (P_00n).
  heap.push_back({hull_lower_bound<C, N>(pts.data(), cnt, p, nullptr),
                  0,
                  0,
                  {C(1), C(0)},
                  {C(0), C(1)},
                  {C(0), C(0)}});
  const C tau_scale = std::sqrt(size2) + max_abs(p);
  const std::size_t budget = 4096;
  const std::size_t corner_index[3] = {static_cast<std::size_t>(triangle_index(n, n, 0)),
                                       static_cast<std::size_t>(triangle_index(n, 0, n)),
                                       static_cast<std::size_t>(triangle_index(n, 0, 0))};
  for (std::size_t done = 0; !heap.empty() && done < budget; ++done) {
    std::pop_heap(heap.begin(), heap.end(), work_after<C>);
    const SurfaceWork<C> w = heap.back();
    heap.pop_back();
    const C tau = std::ldexp(std::sqrt(size2), -26) + rounding * tau_scale;
    const auto settled = [&](C lb) { return tr.found && lb >= std::sqrt(tr.best_d2) - tau; };
    if (settled(w.lb)) break;
    const Vec<C, 2> corner[3] = {w.a, w.b, w.c};
    triangle_subnet<C, V>(net.data(), n, corner, sub.data());
    project_net(sub.data());
    const Vec<C, N> best = tr.best_point;
    C lb = std::max(w.lb, hull_lower_bound<C, N>(pts.data(), cnt, p, tr.found ? &best : nullptr));
    if (settled(lb)) continue;
    lb = std::max(lb, triangle_distance_lower_bound<C, N>(sub.data(), n, p));
    if (settled(lb)) continue;
    for (int k = 0; k < 3; ++k)
      tr.offer(sqr_length(pts[corner_index[k]] - p), corner[k], pts[corner_index[k]], false);
    // Does the sub-triangle hold the best parameter (barycentric coordinates >= 0)?
    bool holds_best = false;
    if (tr.found) {
      const Vec<C, 2> e1 = w.b - w.a, e2 = w.c - w.a, q = tr.best_param - w.a;
      const C den = e1.x * e2.y - e1.y * e2.x;
      if (den != C(0)) {
        const C l1 = (q.x * e2.y - q.y * e2.x) / den, l2 = (e1.x * q.y - e1.y * q.x) / den;
        const C slack = C(16) * std::numeric_limits<C>::epsilon();
        holds_best = l1 >= -slack && l2 >= -slack && l1 + l2 <= C(1) + slack;
      }
    }
    if (!holds_best) {
      Vec<C, 2> x = (w.a + w.b + w.c) / C(3);
      C f = C(0);
      Vec<C, N> at{};
      if (surface_newton<C, N, TriangleDomain>(jet, p, x, f, at)) tr.offer(f, x, at);
      if (settled(lb)) continue;
    }
    C ext = C(0);
    for (int k = 0; k < 3; ++k)
      ext = std::max(ext, sqr_length(pts[corner_index[k]] - pts[corner_index[(k + 1) % 3]]));
    if (n == 0 || !(ext > C(0)) || w.depth >= 48) continue;
    const Vec<C, 2> mab = C(0.5) * (w.a + w.b), mbc = C(0.5) * (w.b + w.c),
                    mca = C(0.5) * (w.c + w.a);
    const SurfaceWork<C> kids[4] = {{lb, 0, w.depth + 1, w.a, mab, mca},
                                    {lb, 0, w.depth + 1, mab, w.b, mbc},
                                    {lb, 0, w.depth + 1, mca, mbc, w.c},
                                    {lb, 0, w.depth + 1, mbc, mca, mab}};
    for (const auto& k : kids) {
      heap.push_back(k);
      std::push_heap(heap.begin(), heap.end(), work_after<C>);
    }
  }
  // The final polish and the edge minima of rect_search.
  if (tr.found && !tr.best_critical) {
    Vec<C, 2> x = TriangleDomain::project(tr.best_param);
    C f = C(0);
    Vec<C, N> at{};
    if (surface_newton<C, N, TriangleDomain>(jet, p, x, f, at)) tr.offer(f, x, at);
  }
  for (const EdgeMinimum<C, N>& e : edge_mins) {
    if (!tr.rival(e.d2, e.x)) continue;
    edge_net(e.kind);
    const C t = e.c >= C(0) ? e.c : edge_param<C, N>(edge.data(), n, e.x);
    if (edge_critical(e.kind, t)) tr.critical.offer(e.d2, C(0), e.x);
  }
}

/// The Bézier patches of the knot spans of a (homogeneous) tensor B-spline: get(i, j) returns
/// the homogeneous control point P_ij.
template <class C, int N, class T, class Get>
inline void tensor_pieces(std::span<const T> ku, int du, int rows, std::span<const T> kv, int dv,
                          int cols, const Get& get, std::vector<Vec<C, N + 1>>& pool,
                          std::vector<SurfacePiece<C>>& pieces) {
  using V = Vec<C, N + 1>;
  const auto nr = static_cast<std::size_t>(du) + 1, nc = static_cast<std::size_t>(dv) + 1;
  SpanScratch<V, 64> rowpts(nr * nc);
  SpanScratch<V, 16> col(nr);
  for (int a = du; a < rows; ++a) {
    const auto ua = static_cast<std::size_t>(a);
    if (!(ku[ua] < ku[ua + 1])) continue;
    for (int b = dv; b < cols; ++b) {
      const auto ub = static_cast<std::size_t>(b);
      if (!(kv[ub] < kv[ub + 1])) continue;
      // Along v for the du + 1 rows of the span, then along u for each of the dv + 1 columns.
      for (int i = 0; i <= du; ++i)
        span_bezier<C, V, T>(
            kv, dv, b, [&](int j) { return get(a - du + i, j); },
            rowpts.data() + static_cast<std::size_t>(i) * nc);
      const std::size_t off = pool.size();
      pool.resize(off + nr * nc);
      for (std::size_t k = 0; k < nc; ++k) {
        span_bezier<C, V, T>(
            ku, du, a,
            [&](int i) { return rowpts[static_cast<std::size_t>(i - (a - du)) * nc + k]; },
            col.data());
        for (std::size_t i = 0; i < nr; ++i) pool[off + i * nc + k] = col[i];
      }
      pieces.push_back({off, static_cast<C>(ku[ua]), static_cast<C>(ku[ua + 1]),
                        static_cast<C>(kv[ub]), static_cast<C>(kv[ub + 1])});
    }
  }
}

/// The search is scale-free (its tolerances are relative to the control net's size), but its
/// Newton steps form products of four coordinates: when those would leave the range, the
/// spatial parts of the homogeneous control points and the query point are first scaled by a
/// power of two (detail/rescale.hpp); the parameters found are evaluated on the surface itself
/// (point_surface_result).
template <class C, int N>
inline void rescale_search(std::vector<Vec<C, N + 1>>& net, Vec<C, N>& p) {
  C m = max_abs(p);
  for (const auto& h : net)
    for (int i = 0; i < N; ++i) m = std::max(m, std::abs(h[i]));
  if (!outside_product_range(m)) return;
  const C f = normalising_scale(m);
  for (auto& h : net)
    for (int i = 0; i < N; ++i) h[i] *= f;
  p = f * p;
}
/// The result from the search's best point, evaluated on the surface itself. complete: the
/// search ran to its end (not stopped by a failed allocation), so the tie test is meaningful.
template <class T, int N, class Surface>
[[nodiscard]] Distance<T, N, NoParam, Vec2<T>> point_surface_result(
    const Vec<T, N>& p, const Surface& s, const SurfaceNearest<compute_t<T>, N>& tr,
    bool complete) noexcept {
  if (!tr.found) return non_finite_distance<T, N, NoParam, Vec2<T>>();
  const Vec2<T> prm{static_cast<T>(tr.best_param.x), static_cast<T>(tr.best_param.y)};
  const Vec<T, N> q = point_at(s, prm.x, prm.y);
  if (!is_finite(q)) return non_finite_distance<T, N, NoParam, Vec2<T>>();
  return make_distance(p, q, NoParam{}, prm, complete && !tr.tied());
}

/// Runs search(tr) and catches a failed allocation (the piece nets, the work heap and the
/// scratch of high degrees are the only allocations): the query is noexcept, so running out of
/// memory ends the search with the best surface point found so far instead of terminating.
template <class T, int N, class Surface, class Search>
[[nodiscard]] Distance<T, N, NoParam, Vec2<T>> guarded_search(const Vec<T, N>& p, const Surface& s,
                                                              const Search& search) noexcept {
  SurfaceNearest<compute_t<T>, N> tr;
  tr.tie_rel = tie_tolerance<T>;
  bool complete = true;
  try {
    search(tr);
  } catch (const std::exception&) {  // std::bad_alloc, std::length_error
    complete = false;
  }
  return point_surface_result<T, N>(p, s, tr, complete);
}

template <class T, int N, class Surface, class Get>
void point_tensor_search(const Vec<T, N>& p, const Surface& s, const Get& get,
                         SurfaceNearest<compute_t<T>, N>& tr) {
  using C = compute_t<T>;
  std::vector<Vec<C, N + 1>> pool;
  std::vector<SurfacePiece<C>> pieces;
  tensor_pieces<C, N, T>(std::span<const T>(s.knots_u), s.degree_u, s.rows,
                         std::span<const T>(s.knots_v), s.degree_v, s.cols, get, pool, pieces);
  Vec<C, N> q = vec_cast<C>(p);
  rescale_search<C, N>(pool, q);
  if (!pieces.empty())
    rect_search<C, N>(pool, pieces, s.degree_u, s.degree_v, q, tau_rounding<T>, tr);
}

}  // namespace
}  // namespace detail

template <Real T, int N>
requires(N == 2 || N == 3)
    [[nodiscard]] Distance<T, N, NoParam, Vec2<T>> distance(const Vec<T, N>& p,
                                                            const BezierPatch<T, N>& s) noexcept {
  if (!is_finite(p) || !is_finite(s)) return non_finite_distance<T, N, NoParam, Vec2<T>>();
  using C = compute_t<T>;
  return detail::guarded_search<T, N>(p, s, [&](detail::SurfaceNearest<C, N>& tr) {
    std::vector<Vec<C, N + 1>> pool;
    pool.reserve(s.control.size());
    for (const auto& q : s.control) pool.push_back(detail::homogeneous<C, N>(vec_cast<C>(q), C(1)));
    const std::vector<detail::SurfacePiece<C>> pieces{{0, C(0), C(1), C(0), C(1)}};
    Vec<C, N> q = vec_cast<C>(p);
    detail::rescale_search<C, N>(pool, q);
    detail::rect_search<C, N>(pool, pieces, s.rows - 1, s.cols - 1, q, detail::tau_rounding<T>, tr);
  });
}

template <Real T, int N>
requires(N == 2 || N == 3) [[nodiscard]] Distance<T, N, NoParam, Vec2<T>> distance(
    const Vec<T, N>& p, const BezierTriangle<T, N>& s) noexcept {
  if (!is_finite(p) || !is_finite(s)) return non_finite_distance<T, N, NoParam, Vec2<T>>();
  using C = compute_t<T>;
  return detail::guarded_search<T, N>(p, s, [&](detail::SurfaceNearest<C, N>& tr) {
    std::vector<Vec<C, N + 1>> net;
    net.reserve(s.control.size());
    for (const auto& q : s.control) net.push_back(detail::homogeneous<C, N>(vec_cast<C>(q), C(1)));
    Vec<C, N> q = vec_cast<C>(p);
    detail::rescale_search<C, N>(net, q);
    detail::triangle_search<C, N>(net, s.degree, q, detail::tau_rounding<T>, tr);
  });
}

template <Real T, int N>
requires(N == 2 || N == 3) [[nodiscard]] Distance<T, N, NoParam, Vec2<T>> distance(
    const Vec<T, N>& p, const BSplineSurface<T, N>& s) noexcept {
  if (!is_finite(p) || validate(s) != Status::ok)
    return non_finite_distance<T, N, NoParam, Vec2<T>>();
  using C = compute_t<T>;
  const auto cols = static_cast<std::size_t>(s.cols);
  const auto get = [&s, cols](int i, int j) {
    return detail::homogeneous<C, N>(
        vec_cast<C>(s.control[static_cast<std::size_t>(i) * cols + static_cast<std::size_t>(j)]),
        C(1));
  };
  return detail::guarded_search<T, N>(p, s, [&](detail::SurfaceNearest<C, N>& tr) {
    detail::point_tensor_search<T, N>(p, s, get, tr);
  });
}

template <Real T, int N>
requires(N == 2 || N == 3)
    [[nodiscard]] Distance<T, N, NoParam, Vec2<T>> distance(const Vec<T, N>& p,
                                                            const NurbsSurface<T, N>& s) noexcept {
  if (!is_finite(p) || validate(s) != Status::ok)
    return non_finite_distance<T, N, NoParam, Vec2<T>>();
  using C = compute_t<T>;
  const auto cols = static_cast<std::size_t>(s.cols);
  const auto get = [&s, cols](int i, int j) {
    const std::size_t k = static_cast<std::size_t>(i) * cols + static_cast<std::size_t>(j);
    return detail::homogeneous<C, N>(vec_cast<C>(s.control[k]), static_cast<C>(s.weights[k]));
  };
  return detail::guarded_search<T, N>(p, s, [&](detail::SurfaceNearest<C, N>& tr) {
    detail::point_tensor_search<T, N>(p, s, get, tr);
  });
}

#define LOCUS_POINT_SURFACE_INSTANTIATE(T, N, S)                             \
  template Distance<T, N, NoParam, Vec2<T>> distance<T, N>(const Vec<T, N>&, \
                                                           const S<T, N>&) noexcept;
#define LOCUS_POINT_SURFACE_INSTANTIATE_ALL(T, N)       \
  LOCUS_POINT_SURFACE_INSTANTIATE(T, N, BezierPatch)    \
  LOCUS_POINT_SURFACE_INSTANTIATE(T, N, BezierTriangle) \
  LOCUS_POINT_SURFACE_INSTANTIATE(T, N, BSplineSurface) \
  LOCUS_POINT_SURFACE_INSTANTIATE(T, N, NurbsSurface)
LOCUS_POINT_SURFACE_INSTANTIATE_ALL(float, 2)
LOCUS_POINT_SURFACE_INSTANTIATE_ALL(float, 3)
LOCUS_POINT_SURFACE_INSTANTIATE_ALL(double, 2)
LOCUS_POINT_SURFACE_INSTANTIATE_ALL(double, 3)
#undef LOCUS_POINT_SURFACE_INSTANTIATE_ALL
#undef LOCUS_POINT_SURFACE_INSTANTIATE

}  // namespace locus
