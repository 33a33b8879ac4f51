// SPDX-License-Identifier: BSL-1.0
// The polynomial-curve intersection engine (include/locus/intersection/detail/polycurve2.hpp);
// rows int2.linear-polycurve and int2.polycurve, book sections 7.3-7.4 (figures 7.2-7.4, 7.11).
// Every curve arrives as rational Bézier pieces in double. Derivations: docs/notes/polycurve.md.

#include <locus/intersection/detail/polycurve2.hpp>
#include <locus/numeric/roots.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <span>
#include <utility>
#include <vector>

namespace locus::detail::polycurve2 {
namespace {

using V2 = Vec2<double>;
using V3 = Vec3<double>;
constexpr double eps = 0x1p-53;

std::size_t z(int i) noexcept { return static_cast<std::size_t>(i); }
int deg(const std::vector<V3>& h) noexcept { return static_cast<int>(h.size()) - 1; }
V2 proj(const V3& h) noexcept { return {h.x / h.z, h.y / h.z}; }
double global_t(const Piece& p, double u) noexcept { return p.t0 + u * (p.t1 - p.t0); }

struct Eval {
  V2 p;   // C(u)
  V2 dp;  // dC/du (local parameter)
};

/// Point and derivative of a rational Bézier piece by homogeneous de Casteljau.
Eval eval(const std::vector<V3>& h, double u) {
  const int n = deg(h);
  if (n <= 0) return {proj(h[0]), {0.0, 0.0}};
  // Degrees up to 15 on the stack (every curve in practice), larger ones on the heap.
  std::array<V3, 16> small;
  std::vector<V3> big;
  V3* b = small.data();
  if (h.size() > small.size()) {
    big = h;
    b = big.data();
  } else {
    std::copy(h.begin(), h.end(), small.begin());
  }
  const double s = 1.0 - u;
  for (int r = 1; r < n; ++r)
    for (int i = 0; i <= n - r; ++i) b[i] = s * b[i] + u * b[i + 1];
  const V3 hp = s * b[0] + u * b[1];
  const V3 hd = static_cast<double>(n) * (b[1] - b[0]);
  const V2 c{hp.x / hp.z, hp.y / hp.z};
  const V2 dc{(hd.x - c.x * hd.z) / hp.z, (hd.y - c.y * hd.z) / hp.z};
  return {c, dc};
}

/// The two halves of control points h at u = 1/2.
template <class P>
std::pair<std::vector<P>, std::vector<P>> halves(const std::vector<P>& h) {
  const std::size_t sz = h.size();
  std::vector<P> b = h, left(sz), right(sz);
  left[0] = b[0];
  right[sz - 1] = b[sz - 1];
  for (std::size_t r = 1; r < sz; ++r) {
    for (std::size_t i = 0; i + r < sz; ++i) b[i] = 0.5 * (b[i] + b[i + 1]);
    left[r] = b[0];
    right[sz - 1 - r] = b[sz - 1 - r];
  }
  return {std::move(left), std::move(right)};
}

struct Box {
  V2 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  V2 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  void add(const V2& p) noexcept {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  [[nodiscard]] double diag() const noexcept { return std::hypot(hi.x - lo.x, hi.y - lo.y); }
  [[nodiscard]] bool empty() const noexcept { return !(lo.x <= hi.x && lo.y <= hi.y); }
};

Box box_of(const std::vector<V3>& h) {
  Box b;
  for (const V3& q : h) b.add(proj(q));
  return b;
}

bool overlap(const Box& a, const Box& b) noexcept {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y;
}

double curve_scale(const Curve& c) {
  double m = 0.0;
  for (const Piece& p : c.pieces)
    for (const V3& q : p.h) {
      const V2 v = proj(q);
      m = std::max({m, std::abs(v.x), std::abs(v.y)});
    }
  return m;
}

/// Which piece holds global parameter t, and the local u there.
std::pair<std::size_t, double> locate(const Curve& c, double t) {
  std::size_t k = 0;
  while (k + 1 < c.pieces.size() && t > c.pieces[k].t1) ++k;
  const Piece& p = c.pieces[k];
  const double w = p.t1 - p.t0;
  double u = w > 0.0 ? (t - p.t0) / w : 0.0;
  u = std::clamp(u, 0.0, 1.0);
  return {k, u};
}

V2 point_at_t(const Curve& c, double t) {
  const auto [k, u] = locate(c, t);
  return eval(c.pieces[k].h, u).p;
}

/// Signed distance of C(t) from the line (positive left of the direction).
double line_dist(const Lin& l, const Curve& c, double t) {
  const V2 p = point_at_t(c, t);
  return perp_dot(l.d, p - l.o) / length(l.d);
}

double curve_front(const Curve& c) { return c.pieces.front().t0; }
double curve_back(const Curve& c) { return c.pieces.back().t1; }

// ---------------------------------------------------------------------------------------------
// Linear component against a curve.

struct LinCand {
  double t_lo, t_hi;  // global parameter interval holding the root
  double t;           // the root
  int mult;           // 1 isolated simple root; -1 decide from the signs around; 0 overlap
};

/// Bernstein coefficients (times the weights) of perp_dot(d, C(u) - o) on a piece.
std::vector<double> line_coeffs(const Lin& l, const Piece& p, double& noise) {
  std::vector<double> b(p.h.size());
  double m = 0.0;
  for (std::size_t i = 0; i < p.h.size(); ++i) {
    const V3& q = p.h[i];
    b[i] = l.d.x * (q.y - q.z * l.o.y) - l.d.y * (q.x - q.z * l.o.x);
    m = std::max(m, std::abs(l.d.x) * (std::abs(q.y) + q.z * std::abs(l.o.y)) +
                        std::abs(l.d.y) * (std::abs(q.x) + q.z * std::abs(l.o.x)));
  }
  noise = 32.0 * eps * static_cast<double>(p.h.size() + 2) * m;
  return b;
}

double bern_eval(const std::vector<double>& b, double u) {
  std::array<double, 16> small;
  std::vector<double> big;
  double* w = small.data();
  if (b.size() > small.size()) {
    big = b;
    w = big.data();
  } else {
    std::copy(b.begin(), b.end(), small.begin());
  }
  const double s = 1.0 - u;
  for (std::size_t r = 1; r < b.size(); ++r)
    for (std::size_t i = 0; i + r < b.size(); ++i) w[i] = s * w[i] + u * w[i + 1];
  return w[0];
}

int sign(double x) noexcept { return (x > 0.0) - (x < 0.0); }

/// A root of a Bernstein polynomial on [0, 1] found by isolate_bernstein (local parameters).
struct BernRoot {
  double a, b;  // interval holding it
  double t;     // the root
  int mult;     // 1 isolated simple root; -1 a noise run (decide from the signs around);
                // -3 an exactly zero end coefficient
};

/// Bernstein-Descartes isolation of the roots in [0, 1] of the Bernstein polynomial `whole`
/// whose coefficients carry absolute error up to `noise`: simple roots bisected to an ulp, runs
/// of subintervals where every coefficient is within the noise merged and reported once.
/// Shared by the line method (7.3) and the resultant (7.4.1). `strict`: a node is settled only
/// when every coefficient is beyond the noise (a double root at a split point, where the end
/// coefficient rounds to either side of zero, is not lost); otherwise exact signs decide.
/// False when the budget runs out.
bool isolate_bernstein(const std::vector<double>& whole, double noise, std::vector<BernRoot>& out,
                       int& budget, bool strict = false) {
  struct Node {
    double a, b;
    std::vector<double> c;
  };
  std::vector<Node> stack{{0.0, 1.0, whole}};
  // Noise leaves arrive left to right (the left child is popped first): merged when contiguous.
  double run_a = -1.0, run_b = -1.0;
  const auto flush = [&]() {
    if (run_a < 0.0) return;
    out.push_back({run_a, run_b, 0.5 * (run_a + run_b), -1});
    run_a = run_b = -1.0;
  };
  while (!stack.empty()) {
    Node nd = std::move(stack.back());
    stack.pop_back();
    if (--budget < 0) return false;
    const std::vector<double>& c = nd.c;
    const std::size_t n = c.size() - 1;
    if (!strict && c[0] == 0.0) out.push_back({nd.a, nd.a, nd.a, -3});
    if (!strict && c[n] == 0.0) out.push_back({nd.b, nd.b, nd.b, -3});
    const bool all_noise =
        std::all_of(c.begin(), c.end(), [&](double v) { return std::abs(v) <= noise; });
    const bool unsure =
        strict && std::any_of(c.begin(), c.end(), [&](double v) { return std::abs(v) <= noise; });
    int variations = 0, last = 0;
    for (double v : c) {
      const int s = sign(v);
      if (s == 0) continue;
      if (last != 0 && s != last) ++variations;
      last = s;
    }
    if (!all_noise && !unsure && variations == 0) continue;
    if (!all_noise && !unsure && variations == 1) {
      // Exactly one root in the open interval (a, b), simple (Descartes' rule in the Bernstein
      // basis; an exactly zero end coefficient is the root at that end, divided out): bisection
      // on the polynomial, the sign near a being that of the first non-zero coefficient.
      double a = nd.a, b = nd.b;
      int sa = 0;
      for (double v : c)
        if (v != 0.0) {
          sa = sign(v);
          break;
        }
      for (int it = 0; it < 200 && b - a > 2.0 * eps * std::max(1.0, std::abs(a)); ++it) {
        const double m = 0.5 * (a + b);
        const int sm = sign(bern_eval(whole, m));
        if (sm == 0) {
          a = b = m;
          break;
        }
        (sm == sa ? a : b) = m;
      }
      const double r = 0.5 * (a + b);
      out.push_back({r, r, r, 1});
      continue;
    }
    if (all_noise || nd.b - nd.a <= 0x1p-46) {
      if (run_a >= 0.0 && run_b == nd.a) {
        run_b = nd.b;
      } else {
        flush();
        run_a = nd.a;
        run_b = nd.b;
      }
      continue;
    }
    auto [left, right] = halves(c);
    const double m = 0.5 * (nd.a + nd.b);
    stack.push_back({m, nd.b, std::move(right)});
    stack.push_back({nd.a, m, std::move(left)});
  }
  flush();
  return true;
}

/// Algebraic method: Bernstein-Descartes isolation of the roots of the piece polynomial.
bool isolate_piece(const Lin& l, const Piece& p, std::vector<LinCand>& out, int& budget) {
  double noise = 0.0;
  const std::vector<double> whole = line_coeffs(l, p, noise);
  if (std::all_of(whole.begin(), whole.end(), [](double v) { return v == 0.0; })) {
    out.push_back({p.t0, p.t1, p.t0, 0});
    return true;
  }
  std::vector<BernRoot> roots;
  const bool within = isolate_bernstein(whole, noise, roots, budget);
  for (const BernRoot& r : roots)
    out.push_back({global_t(p, r.a), global_t(p, r.b), global_t(p, r.t), r.mult});
  return within;
}

/// Bounding-box hierarchy (figure 7.3): boxes of the control polygons against the line.
bool hierarchy_piece(const Lin& l, const Piece& p, double leaf, std::vector<LinCand>& out,
                     int& budget) {
  struct Node {
    double a, b;
    std::vector<V3> h;
  };
  std::vector<Node> stack{{0.0, 1.0, p.h}};
  double run_a = -1.0, run_b = -1.0;
  const auto flush = [&]() {
    if (run_a < 0.0) return;
    out.push_back({global_t(p, run_a), global_t(p, run_b), global_t(p, 0.5 * (run_a + run_b)), -2});
    run_a = run_b = -1.0;
  };
  const double dd = dot(l.d, l.d);
  while (!stack.empty()) {
    Node nd = std::move(stack.back());
    stack.pop_back();
    if (--budget < 0) return false;
    const Box bx = box_of(nd.h);
    const std::array<V2, 4> corner{bx.lo, V2{bx.hi.x, bx.lo.y}, bx.hi, V2{bx.lo.x, bx.hi.y}};
    int pos = 0, neg = 0, below = 0, above = 0;
    for (const V2& q : corner) {
      const double s = perp_dot(l.d, q - l.o);
      pos += s > 0.0;
      neg += s < 0.0;
      const double t = dot(q - l.o, l.d) / dd;
      below += t < l.lo;
      above += t > l.hi;
    }
    if (pos == 4 || neg == 4 || below == 4 || above == 4) continue;
    if (bx.diag() <= leaf || nd.b - nd.a <= 0x1p-40) {
      if (run_a >= 0.0 && run_b == nd.a) {
        run_b = nd.b;
      } else {
        flush();
        run_a = nd.a;
        run_b = nd.b;
      }
      continue;
    }
    auto [left, right] = halves(nd.h);
    const double m = 0.5 * (nd.a + nd.b);
    stack.push_back({m, nd.b, std::move(right)});
    stack.push_back({nd.a, m, std::move(left)});
  }
  flush();
  return true;
}

/// The root of the signed distance in [a, b] (global parameters) by bisection, given the signs
/// differ at the ends; or the point of least |distance| otherwise.
std::pair<double, double> solve_in(const Lin& l, const Curve& c, double a, double b) {
  double fa = line_dist(l, c, a);
  const double fb = line_dist(l, c, b);
  if (fa == 0.0) return {a, 0.0};
  if (fb == 0.0) return {b, 0.0};
  if (sign(fa) != sign(fb)) {
    for (int it = 0; it < 200 && b - a > 2.0 * eps * std::max(1.0, std::abs(a)); ++it) {
      const double m = 0.5 * (a + b);
      const double fm = line_dist(l, c, m);
      if (fm == 0.0) return {m, 0.0};
      if (sign(fm) == sign(fa)) {
        a = m;
        fa = fm;
      } else {
        b = m;
      }
    }
    const double r = 0.5 * (a + b);
    return {r, line_dist(l, c, r)};
  }
  // Least |f|: sample, then golden-section refinement around the best sample.
  constexpr int samples = 32;
  double best = a, fbest = std::abs(fa);
  for (int i = 1; i <= samples; ++i) {
    const double t = a + (b - a) * static_cast<double>(i) / samples;
    const double f = std::abs(line_dist(l, c, t));
    if (f < fbest) {
      fbest = f;
      best = t;
    }
  }
  double lo = std::max(a, best - (b - a) / samples), hi = std::min(b, best + (b - a) / samples);
  for (int it = 0; it < 80 && hi - lo > 2.0 * eps * std::max(1.0, std::abs(lo)); ++it) {
    const double m1 = lo + (hi - lo) * 0.381966, m2 = hi - (hi - lo) * 0.381966;
    if (std::abs(line_dist(l, c, m1)) < std::abs(line_dist(l, c, m2)))
      hi = m2;
    else
      lo = m1;
  }
  const double r = 0.5 * (lo + hi);
  const double fr = line_dist(l, c, r);
  if (std::abs(fr) < fbest) return {r, fr};
  return {best, line_dist(l, c, best)};
}

/// The multiplicity of a root found in a cluster [t_lo, t_hi]: the signs of the distance just
/// outside it (same: a tangency, 2; opposite: an odd contact, 3; a curve end: 2).
int cluster_multiplicity(const Lin& l, const Curve& c, double t_lo, double t_hi) {
  const double w = std::max(t_hi - t_lo, 1e-12 * (curve_back(c) - curve_front(c)));
  const double a = t_lo - w, b = t_hi + w;
  if (a < curve_front(c) || b > curve_back(c)) return 2;
  const int sa = sign(line_dist(l, c, a)), sb = sign(line_dist(l, c, b));
  return sa == sb ? 2 : 3;
}

}  // namespace

// The line's parameter of a point.
static double lin_param(const Lin& l, const V2& p) { return dot(p - l.o, l.d) / dot(l.d, l.d); }

CurveHits2<double> raster_hits(const Curve& a, const Curve& b, const CurveHitOptions& opt,
                               double scale);
CurveRaster2<double> grid_geometry(const Curve& a, const Curve& b, int cells);
int samples_for(const Piece& p, double cell);

CurveHits2<double> linear_curve(const Lin& l, const Curve& c, const CurveHitOptions& opt) {
  CurveHits2<double> r;
  r.status = c.status;
  if (c.status != Status::ok) return r;
  if (!(std::isfinite(l.o.x) && std::isfinite(l.o.y) && std::isfinite(l.d.x) &&
        std::isfinite(l.d.y))) {
    r.status = Status::non_finite_input;
    return r;
  }
  if (l.d.x == 0.0 && l.d.y == 0.0) {
    r.status = Status::degenerate_input;
    return r;
  }
  double scale = curve_scale(c);
  scale = std::max({scale, std::abs(l.o.x), std::abs(l.o.y)});
  if (std::isfinite(l.hi)) {
    const V2 e = l.o + l.hi * l.d;
    scale = std::max({scale, std::abs(e.x), std::abs(e.y)});
  }
  const double leaf = std::max(opt.tolerance * scale, std::numeric_limits<double>::min());
  const double gap = std::max(opt.tolerance * opt.tolerance * scale, 64.0 * eps * scale);

  if (opt.method == CurveMethod::raster) {
    // Clip the component to the curve's box (grown by two cells) and raster it as a segment.
    Box bx;
    for (const Piece& p : c.pieces) {
      const Box q = box_of(p.h);
      bx.add(q.lo);
      bx.add(q.hi);
    }
    const double side = std::max({bx.hi.x - bx.lo.x, bx.hi.y - bx.lo.y, leaf});
    const double grow = 2.0 * side / std::max(1, opt.raster_cells);
    double s0 = l.lo, s1 = l.hi;
    for (int axis = 0; axis < 2; ++axis) {
      const double o = l.o[axis], d = l.d[axis];
      const double lo = bx.lo[axis] - grow, hi = bx.hi[axis] + grow;
      if (d == 0.0) {
        if (o < lo || o > hi) s1 = -1.0, s0 = 1.0;
        continue;
      }
      double ta = (lo - o) / d, tb = (hi - o) / d;
      if (ta > tb) std::swap(ta, tb);
      s0 = std::max(s0, ta);
      s1 = std::min(s1, tb);
    }
    r.status = Status::ok;
    if (!(s0 <= s1)) return r;
    Curve seg;
    Piece sp;
    sp.h = {V3{l.o.x + s0 * l.d.x, l.o.y + s0 * l.d.y, 1.0},
            V3{l.o.x + s1 * l.d.x, l.o.y + s1 * l.d.y, 1.0}};
    sp.t0 = s0;
    sp.t1 = s1;
    seg.pieces.push_back(std::move(sp));
    r = raster_hits(seg, c, opt, scale);
    // The Newton refinement ran on the line through the clipped segment: recompute the line
    // parameter from the point so it is that of the given component.
    for (auto& h : r.hits) h.param_a = std::clamp(lin_param(l, h.point), l.lo, l.hi);
    return r;
  }

  std::vector<LinCand> cand;
  int budget = opt.max_steps;
  bool within = true;
  for (const Piece& p : c.pieces) {
    within = (opt.method == CurveMethod::hierarchy) ? hierarchy_piece(l, p, leaf, cand, budget)
                                                    : isolate_piece(l, p, cand, budget);
    if (!within) break;
  }
  r.status = within ? Status::ok : Status::limit_exceeded;
  // Merge candidates whose intervals meet (a root at a joint or split point found twice).
  std::sort(cand.begin(), cand.end(),
            [](const LinCand& x, const LinCand& y) { return x.t_lo < y.t_lo; });
  std::vector<LinCand> merged;
  for (const LinCand& k : cand) {
    if (!merged.empty()) {
      LinCand& m = merged.back();
      const double slack = 4.0 * eps * std::max(1.0, std::abs(m.t_hi));
      if (k.t_lo <= m.t_hi + slack) {
        // An overlap absorbs everything; a noise cluster decides over exact zeros and simple
        // roots; an exact zero over a simple root found again at a split point.
        const auto rank = [](int x) {
          return x == 0 ? 4 : x == -1 || x == -2 ? 3 : x == -3 ? 2 : 1;
        };
        if (rank(k.mult) > rank(m.mult)) m.mult = k.mult;
        m.t_hi = std::max(m.t_hi, k.t_hi);
        if (m.mult == -1 || m.mult == -2) m.t = 0.5 * (m.t_lo + m.t_hi);
        continue;
      }
    }
    merged.push_back(k);
  }
  const double slack_s = 16.0 * eps;
  const auto in_range = [&](double& s) {
    const double sl = slack_s * std::max(1.0, std::abs(s));
    if (s < l.lo - sl || s > l.hi + sl) return false;
    s = std::clamp(s, l.lo, l.hi);
    return true;
  };
  bool overlap_found = false;
  for (const LinCand& k : merged) {
    if (k.mult == 0) {
      for (double t : {k.t_lo, k.t_hi}) {
        const V2 p = point_at_t(c, t);
        double s = lin_param(l, p);
        if (in_range(s)) r.hits.push_back({p, s, t, 0});
      }
      overlap_found = true;
      continue;
    }
    double t = k.t;
    int mult = k.mult;
    if (mult == -3) {
      // An exact zero of the computed polynomial: simple when the distance changes sign across.
      const double w = 0x1p-20 * (curve_back(c) - curve_front(c));
      const double a = std::max(curve_front(c), t - w), b = std::min(curve_back(c), t + w);
      const int sa = a < t ? sign(line_dist(l, c, a)) : 0,
                sb = b > t ? sign(line_dist(l, c, b)) : 0;
      mult = (sa != 0 && sa == sb) ? 2 : 1;
    } else if (mult == -2 && k.t_hi > k.t_lo) {
      // A run of leaf boxes: every sign change of the distance at 64 steps over it is a
      // crossing (a shallow dip across the line can keep two crossings in one run).
      constexpr int steps = 64;
      int crossings = 0;
      double prev_t = k.t_lo;
      int prev_s = sign(line_dist(l, c, prev_t));
      for (int i = 1; i <= steps; ++i) {
        const double tt = k.t_lo + (k.t_hi - k.t_lo) * static_cast<double>(i) / steps;
        const int sg = sign(line_dist(l, c, tt));
        if (sg != 0 && prev_s != 0 && sg != prev_s) {
          const double tr = solve_in(l, c, prev_t, tt).first;
          const Eval e = eval(c.pieces[locate(c, tr).first].h, locate(c, tr).second);
          const double sn = std::abs(perp_dot(l.d, e.dp)) / (length(l.d) * length(e.dp));
          const V2 p = point_at_t(c, tr);
          double sp = lin_param(l, p);
          if (in_range(sp)) r.hits.push_back({p, sp, tr, sn > std::sqrt(opt.tolerance) ? 1 : 3});
          ++crossings;
        }
        if (sg != 0) {
          prev_s = sg;
          prev_t = tt;
        }
      }
      if (crossings > 0) continue;
      const auto [tr, f] = solve_in(l, c, k.t_lo, k.t_hi);
      if (std::abs(f) > gap) continue;
      t = tr;
      mult = cluster_multiplicity(l, c, k.t_lo, k.t_hi);
    } else if (mult < 0) {
      const auto [tr, f] = solve_in(l, c, k.t_lo, k.t_hi);
      const bool hier = mult == -2;
      if (std::abs(f) > (hier ? gap : std::max(gap, 1e3 * eps * scale))) continue;
      t = tr;
      const int fl = sign(line_dist(l, c, k.t_lo)), fh = sign(line_dist(l, c, k.t_hi));
      if (hier && fl != 0 && fh != 0 && fl != fh && k.t_hi - k.t_lo > 0.0) {
        // A crossing at box resolution: simple unless the curve barely leaves the line.
        mult = 1;
        const Eval e = eval(c.pieces[locate(c, t).first].h, locate(c, t).second);
        const double sn = std::abs(perp_dot(l.d, e.dp)) / (length(l.d) * length(e.dp));
        if (!(sn > std::sqrt(opt.tolerance))) mult = 3;
      } else {
        mult = cluster_multiplicity(l, c, k.t_lo, k.t_hi);
      }
    }
    const V2 p = point_at_t(c, t);
    double s = lin_param(l, p);
    if (in_range(s)) r.hits.push_back({p, s, t, mult});
  }
  std::stable_sort(
      r.hits.begin(), r.hits.end(),
      [](const CurveHit2<double>& x, const CurveHit2<double>& y) { return x.param_a < y.param_a; });
  r.kind = overlap_found && !r.hits.empty() ? Kind::coincident
           : r.hits.empty()                 ? Kind::empty
           : r.hits.size() == 1             ? Kind::point
                                            : Kind::points;
  return r;
}

// ---------------------------------------------------------------------------------------------
// Curve against curve.

namespace {

struct Sol {
  double u, v, dist;
};

/// Levenberg-Marquardt on A(u) - B(v) = 0 within [0, 1]^2: Newton where the Jacobian is regular
/// (quadratic convergence at crossings), damped where it is not (tangencies: the closest points).
Sol newton2(const Piece& pa, const Piece& pb, double u, double v) {
  Eval ea = eval(pa.h, u), eb = eval(pb.h, v);
  V2 f = ea.p - eb.p;
  double f2 = dot(f, f);
  double lambda = 1e-14;
  for (int it = 0; it < 200 && f2 > 0.0; ++it) {
    const double a11 = dot(ea.dp, ea.dp), a22 = dot(eb.dp, eb.dp), a12 = -dot(ea.dp, eb.dp);
    const double g1 = dot(ea.dp, f), g2 = -dot(eb.dp, f);
    const double mu = lambda * (a11 + a22) + std::numeric_limits<double>::min();
    const double m11 = a11 + mu, m22 = a22 + mu;
    const double det = m11 * m22 - a12 * a12;
    if (!(det > 0.0)) break;
    const double du = -(m22 * g1 - a12 * g2) / det, dv = -(m11 * g2 - a12 * g1) / det;
    const double nu = std::clamp(u + du, 0.0, 1.0), nv = std::clamp(v + dv, 0.0, 1.0);
    const Eval na = eval(pa.h, nu), nb = eval(pb.h, nv);
    const V2 nf = na.p - nb.p;
    const double nf2 = dot(nf, nf);
    if (nf2 < f2) {
      const bool tiny = std::abs(nu - u) <= eps && std::abs(nv - v) <= eps;
      u = nu;
      v = nv;
      ea = na;
      eb = nb;
      f = nf;
      f2 = nf2;
      lambda = std::max(lambda * 0.1, 1e-16);
      if (tiny) break;
    } else {
      lambda *= 10.0;
      if (lambda > 1e10) break;
    }
  }
  return {u, v, std::sqrt(f2)};
}

/// newton2 that may walk into the neighbouring piece when it stops on a piece's end (a common
/// point just past a joint): up to four hops. Returns the pieces it ended on.
struct PairSol {
  std::size_t ka, kb;
  Sol s;
};
PairSol solve_pair(const Curve& a, std::size_t ka, double u, const Curve& b, std::size_t kb,
                   double v, double gap) {
  Sol s = newton2(a.pieces[ka], b.pieces[kb], u, v);
  for (int hop = 0; hop < 4 && s.dist > gap; ++hop) {
    bool moved = false;
    if (s.u == 1.0 && ka + 1 < a.pieces.size()) {
      ++ka;
      s.u = 0.0;
      moved = true;
    } else if (s.u == 0.0 && ka > 0) {
      --ka;
      s.u = 1.0;
      moved = true;
    }
    if (s.v == 1.0 && kb + 1 < b.pieces.size()) {
      ++kb;
      s.v = 0.0;
      moved = true;
    } else if (s.v == 0.0 && kb > 0) {
      --kb;
      s.v = 1.0;
      moved = true;
    }
    if (!moved) break;
    s = newton2(a.pieces[ka], b.pieces[kb], s.u, s.v);
  }
  return {ka, kb, s};
}

struct Node {
  std::size_t piece;
  double a, b;
  std::vector<V3> h;
  Box box;
};

struct LeafPair {
  std::size_t pa, pb;
  double ua, ub, va, vb;  // local ranges
  double ta0, ta1, tb0, tb1;
  double gap;  // distance between box centres
};

struct Found {
  V2 p;
  double ta, tb;
  int mult;
};

int multiplicity_at(const Piece& pa, double u, const Piece& pb, double v, double tol) {
  const V2 da = eval(pa.h, u).dp, db = eval(pb.h, v).dp;
  const double la = length(da), lb = length(db);
  if (!(la > 0.0 && lb > 0.0)) return 2;
  return std::abs(perp_dot(da, db)) / (la * lb) <= std::sqrt(tol) ? 2 : 1;
}

/// Union-find root.
std::size_t root_of(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

bool same_pieces(const Curve& a, const Curve& b, bool reversed) {
  if (a.pieces.size() != b.pieces.size()) return false;
  const std::size_t n = a.pieces.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Piece& p = a.pieces[i];
    const Piece& q = b.pieces[reversed ? n - 1 - i : i];
    if (p.h.size() != q.h.size()) return false;
    for (std::size_t j = 0; j < p.h.size(); ++j) {
      const V3& x = p.h[j];
      const V3& y = q.h[reversed ? p.h.size() - 1 - j : j];
      // Homogeneous points equal up to a common factor of the piece: compare projections and
      // weight ratios.
      if (!(proj(x) == proj(y)) || !(x.z * q.h[0].z == y.z * p.h[0].z)) return false;
    }
  }
  return true;
}

void finish(CurveHits2<double>& r, std::vector<Found>& found, double scale, double leaf) {
  std::sort(found.begin(), found.end(), [](const Found& x, const Found& y) { return x.ta < y.ta; });
  std::vector<Found> out;
  for (const Found& f : found) {
    bool dup = false;
    for (Found& g : out) {
      const double d = length(f.p - g.p);
      if (d <= 0x1p-30 * scale || (std::max(f.mult, g.mult) >= 2 && d <= 4.0 * leaf)) {
        g.mult = std::max(g.mult, f.mult);
        dup = true;
        break;
      }
    }
    if (!dup) out.push_back(f);
  }
  for (const Found& f : out) r.hits.push_back({f.p, f.ta, f.tb, f.mult});
  r.kind = r.hits.empty() ? Kind::empty : r.hits.size() == 1 ? Kind::point : Kind::points;
}

}  // namespace

CurveHits2<double> raster_hits(const Curve& a, const Curve& b, const CurveHitOptions& opt,
                               double scale) {
  CurveHits2<double> r;
  r.status = Status::ok;
  const CurveRaster2<double> g = grid_geometry(a, b, opt.raster_cells);
  if (g.status != Status::ok || g.nx == 0) return r;
  // The cells each curve is drawn into, sparse: one mark (cell id, piece, u) per pass of the
  // curve through a cell (consecutive samples in the same cell are one pass), sorted by cell.
  struct Mark {
    long long cell;
    std::size_t piece;
    double u;
  };
  const auto draw = [&](const Curve& c) {
    std::vector<Mark> m;
    for (std::size_t k = 0; k < c.pieces.size(); ++k) {
      const Piece& p = c.pieces[k];
      const int n = samples_for(p, g.cell);
      for (int s = 0; s <= n; ++s) {
        const double u = static_cast<double>(s) / n;
        const V2 q = eval(p.h, u).p;
        const double fx = (q.x - g.min.x) / g.cell, fy = (q.y - g.min.y) / g.cell;
        if (!(fx >= 0.0 && fy >= 0.0 && fx <= g.nx && fy <= g.ny)) continue;
        const int i = std::min(static_cast<int>(fx), g.nx - 1);
        const int j = std::min(static_cast<int>(fy), g.ny - 1);
        const long long cell = static_cast<long long>(j) * g.nx + i;
        if (!m.empty() && m.back().cell == cell) continue;
        m.push_back({cell, k, u});
      }
    }
    std::stable_sort(m.begin(), m.end(),
                     [](const Mark& x, const Mark& y) { return x.cell < y.cell; });
    return m;
  };
  const std::vector<Mark> ma = draw(a), mb = draw(b);
  // The marks of a cell: [first, last) indices.
  const auto range = [](const std::vector<Mark>& m, long long cell) {
    const auto lo = std::lower_bound(m.begin(), m.end(), cell,
                                     [](const Mark& x, long long c) { return x.cell < c; });
    auto hi = lo;
    while (hi != m.end() && hi->cell == cell) ++hi;
    return std::pair<std::size_t, std::size_t>{static_cast<std::size_t>(lo - m.begin()),
                                               static_cast<std::size_t>(hi - m.begin())};
  };
  // The second curve's marks in the 3x3 neighbourhood of a cell (a curve can clip a cell corner
  // between two samples), those in the cell itself first.
  const auto b_near = [&](long long cell, std::vector<std::size_t>& out) {
    out.clear();
    const long long i = cell % g.nx, j = cell / g.nx;
    const auto [f0, f1] = range(mb, cell);
    for (std::size_t k = f0; k < f1; ++k) out.push_back(k);
    for (long long dj = -1; dj <= 1; ++dj)
      for (long long di = -1; di <= 1; ++di) {
        if ((di == 0 && dj == 0) || i + di < 0 || j + dj < 0 || i + di >= g.nx || j + dj >= g.ny)
          continue;
        const auto [k0, k1] = range(mb, (j + dj) * g.nx + i + di);
        for (std::size_t k = k0; k < k1; ++k) out.push_back(k);
      }
    return f1 - f0;
  };
  std::vector<std::size_t> near;
  std::vector<char> candidate(ma.size()), seen(ma.size(), 0);
  for (std::size_t i = 0; i < ma.size(); ++i) {
    b_near(ma[i].cell, near);
    candidate[i] = !near.empty();
  }
  std::vector<Found> found;
  const double leaf = std::max(opt.tolerance * scale, std::numeric_limits<double>::min());
  const double gap = std::max(opt.tolerance * opt.tolerance * scale, 64.0 * eps * scale);
  for (std::size_t i0 = 0; i0 < ma.size(); ++i0) {
    if (!candidate[i0] || seen[i0]) continue;
    // Flood the 8-connected component of candidate marks.
    std::vector<std::size_t> queue{i0};
    seen[i0] = 1;
    long long ci0 = g.nx, ci1 = -1, cj0 = g.ny, cj1 = -1;
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const long long cell = ma[queue[q]].cell, ci = cell % g.nx, cj = cell / g.nx;
      ci0 = std::min(ci0, ci);
      ci1 = std::max(ci1, ci);
      cj0 = std::min(cj0, cj);
      cj1 = std::max(cj1, cj);
      for (long long dj = -1; dj <= 1; ++dj)
        for (long long di = -1; di <= 1; ++di) {
          if (ci + di < 0 || cj + dj < 0 || ci + di >= g.nx || cj + dj >= g.ny) continue;
          const auto [k0, k1] = range(ma, (cj + dj) * g.nx + ci + di);
          for (std::size_t k = k0; k < k1; ++k) {
            if (!candidate[k] || seen[k]) continue;
            seen[k] = 1;
            queue.push_back(k);
          }
        }
    }
    // Seed pairs: each mark of the first curve with each mark of the second nearby, pairs in
    // the same cell and pairs in neighbouring cells, at least twelve (an eighth in long components)
    // of each spread over them. Every solution inside the component's cells (grown by one) is kept,
    // so crossings sharing a component can all be found.
    std::vector<std::pair<std::size_t, std::size_t>> same, other;
    for (std::size_t k : queue) {
      const std::size_t in_cell = b_near(ma[k].cell, near);
      for (std::size_t x = 0; x < near.size(); ++x)
        (x < in_cell ? same : other).push_back({k, near[x]});
    }
    std::vector<std::pair<std::size_t, std::size_t>> seeds;
    for (const auto* pool : {&same, &other}) {
      const std::size_t tries =
          std::min<std::size_t>(pool->size(), std::max<std::size_t>(12, pool->size() / 8));
      for (std::size_t s = 0; s < tries; ++s)
        seeds.push_back((*pool)[(2 * s + 1) * pool->size() / (2 * tries)]);
    }
    for (const auto& pr : seeds) {
      const Mark& sa = ma[pr.first];
      const Mark& sb = mb[pr.second];
      const PairSol ps = solve_pair(a, sa.piece, sa.u, b, sb.piece, sb.u, gap);
      const Sol& so = ps.s;
      if (so.dist > gap) continue;
      const Piece& pa = a.pieces[ps.ka];
      const Piece& pb = b.pieces[ps.kb];
      const V2 p = eval(pa.h, so.u).p;
      const double fx = (p.x - g.min.x) / g.cell, fy = (p.y - g.min.y) / g.cell;
      if (!(fx >= static_cast<double>(ci0 - 1) && fx <= static_cast<double>(ci1 + 2) &&
            fy >= static_cast<double>(cj0 - 1) && fy <= static_cast<double>(cj1 + 2)))
        continue;
      found.push_back({p, global_t(pa, so.u), global_t(pb, so.v),
                       multiplicity_at(pa, so.u, pb, so.v, opt.tolerance)});
    }
  }
  finish(r, found, scale, leaf);
  return r;
}

/// The grid over the joint box of both curves, cells square, `cells` along the longer side.
CurveRaster2<double> grid_geometry(const Curve& a, const Curve& b, int cells) {
  CurveRaster2<double> g;
  g.status = a.status != Status::ok ? a.status : b.status;
  if (g.status != Status::ok) return g;
  if (cells < 1) {
    g.status = Status::invalid_input;
    return g;
  }
  Box bx;
  for (const Curve* c : {&a, &b})
    for (const Piece& p : c->pieces)
      for (const V3& q : p.h) bx.add(proj(q));
  double side = std::max(bx.hi.x - bx.lo.x, bx.hi.y - bx.lo.y);
  if (!(side > 0.0)) side = std::max(1.0, std::max(std::abs(bx.lo.x), std::abs(bx.lo.y)));
  g.cell = side / cells;
  g.min = bx.lo;
  g.nx = std::clamp(static_cast<int>(std::ceil((bx.hi.x - bx.lo.x) / g.cell)), 1, cells);
  g.ny = std::clamp(static_cast<int>(std::ceil((bx.hi.y - bx.lo.y) / g.cell)), 1, cells);
  return g;
}

/// Samples per piece: about three per cell of control-polygon length (it bounds the arc).
int samples_for(const Piece& p, double cell) {
  double poly = 0.0;
  for (std::size_t i = 1; i < p.h.size(); ++i) poly += length(proj(p.h[i]) - proj(p.h[i - 1]));
  const double want = std::ceil(3.0 * poly / cell);
  return want > 65536.0 ? 65536 : std::max(4, static_cast<int>(want));
}

CurveRaster2<double> raster(const Curve& a, const Curve& b, int cells) {
  CurveRaster2<double> g = grid_geometry(a, b, cells);
  if (g.status != Status::ok) return g;
  g.mask.assign(z(g.nx) * z(g.ny), 0);
  const auto draw = [&](const Curve& c, std::uint8_t bit) {
    for (const Piece& p : c.pieces) {
      const int n = samples_for(p, g.cell);
      for (int s = 0; s <= n; ++s) {
        const V2 q = eval(p.h, static_cast<double>(s) / n).p;
        const double fx = (q.x - g.min.x) / g.cell, fy = (q.y - g.min.y) / g.cell;
        if (!(fx >= 0.0 && fy >= 0.0 && fx <= g.nx && fy <= g.ny)) continue;
        const int i = std::min(static_cast<int>(fx), g.nx - 1);
        const int j = std::min(static_cast<int>(fy), g.ny - 1);
        g.mask[z(j) * z(g.nx) + z(i)] |= bit;
      }
    }
  };
  draw(a, 1);
  draw(b, 2);
  return g;
}

namespace {

// ---------------------------------------------------------------------------------------------
// Inversion and overlaps (sub-arcs shared by the two curves).

/// The parameter of the point of piece p nearest q: 32 samples, then Gauss-Newton on the foot
/// condition (C(u) - q).C'(u) = 0 (quadratic for points on the curve); (u, distance).
std::pair<double, double> invert(const Piece& p, const V2& q) {
  constexpr int samples = 32;
  double u = 0.0, best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= samples; ++i) {
    const double s = static_cast<double>(i) / samples;
    const double d = length(eval(p.h, s).p - q);
    if (d < best) {
      best = d;
      u = s;
    }
  }
  for (int it = 0; it < 60 && best > 0.0; ++it) {
    const Eval e = eval(p.h, u);
    const double dd = dot(e.dp, e.dp);
    if (!(dd > 0.0)) break;
    const double nu = std::clamp(u - dot(e.p - q, e.dp) / dd, 0.0, 1.0);
    const double nd = length(eval(p.h, nu).p - q);
    if (!(nd < best)) break;
    const bool tiny = std::abs(nu - u) <= eps;
    best = nd;
    u = nu;
    if (tiny) break;
  }
  return {u, best};
}

/// A sub-arc shared by piece pa of the first curve and piece pb of the second: local
/// parameters [u0, u1] (u0 < u1) on pa matched to v0 -> v1 on pb (decreasing when reversed).
struct Overlap {
  std::size_t pa, pb;
  double u0, u1, v0, v1;
};

/// The overlaps of two pieces. Every sub-arc shared by two pieces starts and ends at an end
/// of one of them, so the anchors are the ends of each piece that lie on the other (within
/// `on`); consecutive anchors bound an overlap when deg(pa) deg(pb) + 2 points between them lie
/// on both pieces too (more common points than Bezout's bound: the same algebraic curve,
/// docs/notes/polycurve.md).
void piece_overlaps(const Piece& pa, std::size_t ia, const Piece& pb, std::size_t ib, double on,
                    std::vector<Overlap>& out) {
  if (!overlap(box_of(pa.h), box_of(pb.h))) return;
  std::vector<std::pair<double, double>> anchors;
  for (double u : {0.0, 1.0}) {
    const auto [v, d] = invert(pb, proj(u == 0.0 ? pa.h.front() : pa.h.back()));
    if (d <= on) anchors.push_back({u, v});
  }
  for (double v : {0.0, 1.0}) {
    const auto [u, d] = invert(pa, proj(v == 0.0 ? pb.h.front() : pb.h.back()));
    if (d <= on) anchors.push_back({u, v});
  }
  std::sort(anchors.begin(), anchors.end());
  const int k = std::min(64, deg(pa.h) * deg(pb.h) + 2);
  constexpr double min_width = 0x1p-30;
  for (std::size_t i = 0; i + 1 < anchors.size(); ++i) {
    const auto [u0, v0] = anchors[i];
    const auto [u1, v1] = anchors[i + 1];
    if (u1 - u0 <= min_width || std::abs(v1 - v0) <= min_width) continue;
    bool shared = true;
    for (int j = 1; j <= k && shared; ++j) {
      const double u = u0 + (u1 - u0) * static_cast<double>(j) / (k + 1);
      const auto [v, d] = invert(pb, eval(pa.h, u).p);
      shared = d <= on && v >= std::min(v0, v1) - min_width && v <= std::max(v0, v1) + min_width;
    }
    if (shared) out.push_back({ia, ib, u0, u1, v0, v1});
  }
}

/// An overlap in global parameters: [ta0, ta1] on the first curve, tb0 -> tb1 on the second.
struct GlobalOverlap {
  double ta0, ta1, tb0, tb1;
};

std::vector<GlobalOverlap> merge_overlaps(const Curve& a, const Curve& b,
                                          const std::vector<Overlap>& ov) {
  std::vector<GlobalOverlap> g;
  for (const Overlap& o : ov) {
    const Piece& pa = a.pieces[o.pa];
    const Piece& pb = b.pieces[o.pb];
    g.push_back({global_t(pa, o.u0), global_t(pa, o.u1), global_t(pb, o.v0), global_t(pb, o.v1)});
  }
  std::sort(g.begin(), g.end(),
            [](const GlobalOverlap& x, const GlobalOverlap& y) { return x.ta0 < y.ta0; });
  const double sa = 0x1p-30 * std::max(1.0, curve_back(a) - curve_front(a));
  const double sb = 0x1p-30 * std::max(1.0, curve_back(b) - curve_front(b));
  std::vector<GlobalOverlap> m;
  for (const GlobalOverlap& o : g) {
    if (!m.empty()) {
      GlobalOverlap& l = m.back();
      const bool same_dir = (l.tb1 >= l.tb0) == (o.tb1 >= o.tb0);
      if (o.ta0 <= l.ta1 + sa && same_dir && std::abs(o.tb0 - l.tb1) <= sb) {
        if (o.ta1 > l.ta1) {
          l.ta1 = o.ta1;
          l.tb1 = o.tb1;
        }
        continue;
      }
    }
    m.push_back(o);
  }
  return m;
}

/// Box-pair hierarchy on the given piece pairs (the algebraic default, the hierarchy method, and
/// the resultant's fallback: the subdivision isolates, Newton on the 2x2 system solves). Node
/// pairs inside a shared sub-arc on both sides are skipped. False when the budget runs out.
bool subdivide_pairs(const Curve& a, const Curve& b,
                     const std::vector<std::pair<std::size_t, std::size_t>>& pairs,
                     const std::vector<Overlap>& ov, const CurveHitOptions& opt, double leaf,
                     double gap, int& budget, std::vector<Found>& found) {
  std::vector<std::pair<Node, Node>> stack;
  for (const auto& pr : pairs) {
    const std::size_t i = pr.first, j = pr.second;
    stack.push_back({Node{i, 0.0, 1.0, a.pieces[i].h, box_of(a.pieces[i].h)},
                     Node{j, 0.0, 1.0, b.pieces[j].h, box_of(b.pieces[j].h)}});
  }
  const auto on_overlap = [&](const Node& na, const Node& nb) {
    return std::any_of(ov.begin(), ov.end(), [&](const Overlap& o) {
      return o.pa == na.piece && o.pb == nb.piece && na.a >= o.u0 && na.b <= o.u1 &&
             nb.a >= std::min(o.v0, o.v1) && nb.b <= std::max(o.v0, o.v1);
    });
  };
  std::vector<LeafPair> leaves;
  bool within = true;
  while (!stack.empty()) {
    auto [na, nb] = std::move(stack.back());
    stack.pop_back();
    if (--budget < 0) {
      within = false;
      break;
    }
    if (!overlap(na.box, nb.box)) continue;
    if (!ov.empty() && on_overlap(na, nb)) continue;
    const double da = na.box.diag(), db = nb.box.diag();
    const bool small_a = da <= leaf || na.b - na.a <= 0x1p-40;
    const bool small_b = db <= leaf || nb.b - nb.a <= 0x1p-40;
    if (small_a && small_b) {
      const Piece& pa = a.pieces[na.piece];
      const Piece& pb = b.pieces[nb.piece];
      const V2 ca = 0.5 * (na.box.lo + na.box.hi), cb = 0.5 * (nb.box.lo + nb.box.hi);
      leaves.push_back({na.piece, nb.piece, na.a, na.b, nb.a, nb.b, global_t(pa, na.a),
                        global_t(pa, na.b), global_t(pb, nb.a), global_t(pb, nb.b),
                        length(ca - cb)});
      continue;
    }
    Node& split = (!small_a && (small_b || da >= db)) ? na : nb;
    auto [left, right] = halves(split.h);
    const double m = 0.5 * (split.a + split.b);
    Node l{split.piece, split.a, m, std::move(left), {}};
    Node rr{split.piece, m, split.b, std::move(right), {}};
    l.box = box_of(l.h);
    rr.box = box_of(rr.h);
    if (&split == &na) {
      stack.push_back({std::move(rr), nb});
      stack.push_back({std::move(l), std::move(nb)});
    } else {
      stack.push_back({na, std::move(rr)});
      stack.push_back({std::move(na), std::move(l)});
    }
  }
  // Clusters of leaf pairs whose parameter rectangles touch: one common point each.
  std::sort(leaves.begin(), leaves.end(),
            [](const LeafPair& x, const LeafPair& y) { return x.ta0 < y.ta0; });
  std::vector<std::size_t> parent(leaves.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  for (std::size_t i = 0; i < leaves.size(); ++i)
    for (std::size_t j = i + 1; j < leaves.size() && leaves[j].ta0 <= leaves[i].ta1; ++j)
      if (leaves[j].tb0 <= leaves[i].tb1 && leaves[i].tb0 <= leaves[j].tb1)
        parent[root_of(parent, j)] = root_of(parent, i);
  std::vector<std::vector<std::size_t>> groups(leaves.size());
  for (std::size_t i = 0; i < leaves.size(); ++i) groups[root_of(parent, i)].push_back(i);
  for (auto& grp : groups) {
    if (grp.empty()) continue;
    std::sort(grp.begin(), grp.end(),
              [&](std::size_t x, std::size_t y) { return leaves[x].gap < leaves[y].gap; });
    // Seed from the closest box pairs (a few, in case the first converges outside).
    const std::size_t tries = std::min<std::size_t>(grp.size(), 4);
    for (std::size_t k = 0; k < tries; ++k) {
      const LeafPair& lp = leaves[grp[k]];
      const PairSol ps =
          solve_pair(a, lp.pa, 0.5 * (lp.ua + lp.ub), b, lp.pb, 0.5 * (lp.va + lp.vb), gap);
      const Sol& s = ps.s;
      if (s.dist > gap) continue;
      const Piece& pa = a.pieces[ps.ka];
      const Piece& pb = b.pieces[ps.kb];
      found.push_back({eval(pa.h, s.u).p, global_t(pa, s.u), global_t(pb, s.v),
                       multiplicity_at(pa, s.u, pb, s.v, opt.tolerance)});
      break;
    }
  }
  return within;
}

// ---------------------------------------------------------------------------------------------
// The resultant method (book 7.4.1): implicitise one piece by its Bezout resultant, substitute
// the other, isolate the roots of the univariate result, invert.

constexpr int max_implicit_degree = 4;
constexpr int max_resultant_degree = 64;  // m n: binomials and the isolation stay well scaled

double binom(int n, int k) {
  double r = 1.0;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

/// Power-basis coefficients on [0, 1] of the Bernstein polynomial b, and bounds of their
/// magnitudes (the same sums in absolute value).
void to_power(const std::vector<double>& b, std::vector<double>& c, std::vector<double>& mag) {
  const int n = static_cast<int>(b.size()) - 1;
  c.assign(b.size(), 0.0);
  mag.assign(b.size(), 0.0);
  for (int k = 0; k <= n; ++k) {
    double s = 0.0, sm = 0.0;
    for (int i = 0; i <= k; ++i) {
      const double t = binom(k, i) * b[z(i)];
      s += ((k - i) % 2 == 0) ? t : -t;
      sm += std::abs(t);
    }
    c[z(k)] = binom(n, k) * s;
    mag[z(k)] = binom(n, k) * sm;
  }
}

/// The Bezout matrix (m x m, row-major) of power-basis f and g of degree <= m:
/// (f(s) g(r) - f(r) g(s)) / (s - r) = sum B[i][j] s^i r^j; `mag` bounds the entries' terms.
void bezout(const std::vector<double>& f, const std::vector<double>& fm,
            const std::vector<double>& g, const std::vector<double>& gm, int m,
            std::vector<double>& out, std::vector<double>& mag) {
  out.assign(z(m * m), 0.0);
  mag.assign(z(m * m), 0.0);
  for (int a = 0; a <= m; ++a)
    for (int b = 0; b < a; ++b) {
      const double c = f[z(a)] * g[z(b)] - f[z(b)] * g[z(a)];
      const double cm = fm[z(a)] * gm[z(b)] + fm[z(b)] * gm[z(a)];
      for (int k = 0; k <= a - b - 1; ++k) {
        out[z((b + k) * m + (a - 1 - k))] += c;
        mag[z((b + k) * m + (a - 1 - k))] += cm;
      }
    }
}

/// Product of two Bernstein polynomials (degrees add).
std::vector<double> bern_mul(const std::vector<double>& p, const std::vector<double>& q) {
  const int n1 = static_cast<int>(p.size()) - 1, n2 = static_cast<int>(q.size()) - 1;
  std::vector<double> r(z(n1 + n2 + 1), 0.0);
  for (int i = 0; i <= n1; ++i)
    for (int j = 0; j <= n2; ++j)
      r[z(i + j)] += binom(n1, i) * binom(n2, j) / binom(n1 + n2, i + j) * p[z(i)] * q[z(j)];
  return r;
}

/// The resultant of piece `imp` (implicitised, degree m <= max_implicit_degree) and piece `oth`
/// (degree n) as a Bernstein polynomial of degree m n in oth's parameter: det M(t) with
/// M = W2 Bez(X, Y) - Y2 Bez(X, W) - X2 Bez(W, Y), the Bezout matrix of W2 X - X2 W and
/// W2 Y - Y2 W over W2 (docs/notes/polycurve.md). Coordinates relative to `centre`.
/// `noise` bounds the coefficients' rounding error.
std::vector<double> resultant_poly(const Piece& imp, const Piece& oth, const V2& centre,
                                   double& noise) {
  const int m = deg(imp.h), n = deg(oth.h);
  std::vector<double> xb, yb, wb;
  for (const V3& q : imp.h) {
    xb.push_back(q.x - centre.x * q.z);
    yb.push_back(q.y - centre.y * q.z);
    wb.push_back(q.z);
  }
  std::vector<double> X, Xm, Y, Ym, W, Wm;
  to_power(xb, X, Xm);
  to_power(yb, Y, Ym);
  to_power(wb, W, Wm);
  std::vector<double> bxy, mxy, bxw, mxw, bwy, mwy;
  bezout(X, Xm, Y, Ym, m, bxy, mxy);
  bezout(X, Xm, W, Wm, m, bxw, mxw);
  bezout(W, Wm, Y, Ym, m, bwy, mwy);
  // Entries of M(t), Bernstein of degree n, and their magnitude bounds.
  std::vector<std::vector<double>> e(z(m * m)), em(z(m * m));
  for (int ij = 0; ij < m * m; ++ij) {
    for (const V3& q : oth.h) {
      const double x2 = q.x - centre.x * q.z, y2 = q.y - centre.y * q.z, w2 = q.z;
      e[z(ij)].push_back(w2 * bxy[z(ij)] - y2 * bxw[z(ij)] - x2 * bwy[z(ij)]);
      em[z(ij)].push_back(std::abs(w2) * mxy[z(ij)] + std::abs(y2) * mxw[z(ij)] +
                          std::abs(x2) * mwy[z(ij)]);
    }
  }
  // Leibniz expansion (m <= 4: at most 24 products).
  std::vector<double> det(z(m * n + 1), 0.0), detm(z(m * n + 1), 0.0);
  std::array<int, max_implicit_degree> perm{};
  std::iota(perm.begin(), perm.begin() + m, 0);
  do {
    int inversions = 0;
    for (int i = 0; i < m; ++i)
      for (int j = i + 1; j < m; ++j) inversions += perm[z(i)] > perm[z(j)];
    std::vector<double> pr = e[z(perm[0])], prm = em[z(perm[0])];
    for (int i = 1; i < m; ++i) {
      pr = bern_mul(pr, e[z(i * m + perm[z(i)])]);
      prm = bern_mul(prm, em[z(i * m + perm[z(i)])]);
    }
    for (std::size_t k = 0; k < det.size(); ++k) {
      det[k] += (inversions % 2 == 0) ? pr[k] : -pr[k];
      detm[k] += prm[k];
    }
  } while (std::next_permutation(perm.begin(), perm.begin() + m));
  const double big = *std::max_element(detm.begin(), detm.end());
  noise = 8.0 * (m + 2) * (n + 2) * eps * big;
  return det;
}

/// Power-basis coefficients of X(s) - x W(s) (the implicit piece's x equation at a point).
std::vector<double> coordinate_poly(const Piece& imp, int axis, double x) {
  std::vector<double> b, c, mag;
  for (const V3& q : imp.h) b.push_back(q[axis] - x * q.z);
  to_power(b, c, mag);
  return c;
}

/// The common points of piece ka of a and piece kb of b by the resultant; false when the
/// resultant vanishes within its noise (one algebraic curve: the caller subdivides instead).
bool resultant_pair(const Curve& a, std::size_t ka, const Curve& b, std::size_t kb, double gap,
                    double tol, int& budget, std::vector<Found>& found) {
  const Piece& pa = a.pieces[ka];
  const Piece& pb = b.pieces[kb];
  const bool imp_is_a = deg(pa.h) <= deg(pb.h);
  const Piece& imp = imp_is_a ? pa : pb;
  const Piece& oth = imp_is_a ? pb : pa;
  const Box bx = box_of(imp.h);
  const V2 centre = 0.5 * (bx.lo + bx.hi);
  double noise = 0.0;
  if (deg(imp.h) * deg(oth.h) > max_resultant_degree) return false;
  const std::vector<double> g = resultant_poly(imp, oth, centre, noise);
  // Overflow (huge coordinates), or Q on P's algebraic curve: the subdivision decides.
  if (!std::isfinite(noise) ||
      !std::all_of(g.begin(), g.end(), [](double v) { return std::isfinite(v); }))
    return false;
  if (std::all_of(g.begin(), g.end(), [&](double v) { return std::abs(v) <= noise; })) return false;
  std::vector<BernRoot> roots;
  if (!isolate_bernstein(g, noise, roots, budget, true)) budget = -1;
  const double slack = 0x1p-20;
  for (const BernRoot& r : roots) {
    const V2 q = eval(oth.h, r.t).p;
    // Inversion: the roots of the implicit piece's coordinate equations at q.
    std::vector<double> cands;
    for (int axis = 0; axis < 2; ++axis) {
      const std::vector<double> c = coordinate_poly(imp, axis, q[axis]);
      const RealRootsResult<double> rr = detail::roots::real_roots_span<double>(
          std::span<const double>(c), -slack, 1.0 + slack, near_roots());
      if (rr.status != Status::ok) continue;
      for (const Root<double>& x : rr.roots) cands.push_back(std::clamp(x.value, 0.0, 1.0));
    }
    std::sort(cands.begin(), cands.end());
    double last = -1.0;
    for (double s : cands) {
      if (s - last <= 0x1p-40) continue;
      last = s;
      const Sol so = imp_is_a ? newton2(pa, pb, s, r.t) : newton2(pa, pb, r.t, s);
      if (so.dist > gap) continue;
      int mult = 1;
      const int geometric = multiplicity_at(pa, so.u, pb, so.v, tol);
      if (r.mult != 1) {
        // A noise run or an exact zero: the signs of the resultant just outside decide the
        // parity of the contact.
        const double w = std::max(r.b - r.a, 0x1p-30);
        const double lo = r.a - w, hi = r.b + w;
        if (lo < 0.0 || hi > 1.0) {
          mult = geometric;
        } else {
          const int sl = sign(bern_eval(g, lo)), sh = sign(bern_eval(g, hi));
          mult = sl == sh ? 2 : (geometric == 1 ? 1 : 3);
        }
      }
      found.push_back({eval(pa.h, so.u).p, global_t(pa, so.u), global_t(pb, so.v), mult});
    }
  }
  return true;
}

}  // namespace

CurveHits2<double> curve_curve(const Curve& a, const Curve& b, const CurveHitOptions& opt) {
  CurveHits2<double> r;
  r.status = a.status != Status::ok ? a.status : b.status;
  if (r.status != Status::ok) return r;
  const double scale = std::max(curve_scale(a), curve_scale(b));
  int exponent = 0;
  std::frexp(scale, &exponent);
  if (exponent > 500 || exponent < -500) {
    // Squares of coordinates (Newton's normal equations, the resultant) would overflow or
    // underflow: solve the copies scaled by a power of two (exact), scale the points back.
    Curve sa = a, sb = b;
    for (Curve* c : {&sa, &sb})
      for (Piece& p : c->pieces)
        for (V3& q : p.h) q = {std::ldexp(q.x, -exponent), std::ldexp(q.y, -exponent), q.z};
    CurveHits2<double> rs = curve_curve(sa, sb, opt);
    for (CurveHit2<double>& h : rs.hits)
      h.point = {std::ldexp(h.point.x, exponent), std::ldexp(h.point.y, exponent)};
    return rs;
  }
  const double leaf = std::max(opt.tolerance * scale, std::numeric_limits<double>::min());
  const double gap = std::max(opt.tolerance * opt.tolerance * scale, 64.0 * eps * scale);
  for (bool rev : {false, true}) {
    if (!same_pieces(a, b, rev)) continue;
    // The same point set (as given, or reversed): an overlap over the whole curve.
    const Piece& f = a.pieces.front();
    const Piece& l = a.pieces.back();
    const double b0 = rev ? curve_back(b) : curve_front(b);
    const double b1 = rev ? curve_front(b) : curve_back(b);
    r.kind = Kind::coincident;
    r.hits.push_back({proj(f.h.front()), f.t0, b0, 0});
    r.hits.push_back({proj(l.h.back()), l.t1, b1, 0});
    return r;
  }
  // Shared sub-arcs first (every method): the searches below skip them. Within the input's
  // own precision: float pieces of a curve are off it by a few float ulps.
  const double on = std::max(gap, 16.0 * std::max(a.unit, b.unit) * scale);
  std::vector<Overlap> ov;
  for (std::size_t i = 0; i < a.pieces.size(); ++i)
    for (std::size_t j = 0; j < b.pieces.size(); ++j)
      piece_overlaps(a.pieces[i], i, b.pieces[j], j, on, ov);
  const std::vector<GlobalOverlap> shared = merge_overlaps(a, b, ov);

  if (opt.method == CurveMethod::raster) {
    r = raster_hits(a, b, opt, scale);
  } else {
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    std::vector<Found> found;
    int budget = opt.max_steps;
    for (std::size_t i = 0; i < a.pieces.size(); ++i)
      for (std::size_t j = 0; j < b.pieces.size(); ++j) {
        const bool has_overlap = std::any_of(
            ov.begin(), ov.end(), [&](const Overlap& o) { return o.pa == i && o.pb == j; });
        if (opt.method == CurveMethod::resultant && !has_overlap &&
            std::min(deg(a.pieces[i].h), deg(b.pieces[j].h)) <= max_implicit_degree &&
            overlap(box_of(a.pieces[i].h), box_of(b.pieces[j].h))) {
          if (resultant_pair(a, i, b, j, gap, opt.tolerance, budget, found)) continue;
        }
        pairs.push_back({i, j});
      }
    if (!subdivide_pairs(a, b, pairs, ov, opt, leaf, gap, budget, found))
      r.status = Status::limit_exceeded;
    if (budget < 0) r.status = Status::limit_exceeded;
    finish(r, found, scale, leaf);
  }
  if (shared.empty()) return r;
  // Points found on a shared sub-arc (its ends, where the searches meet it) are the overlap.
  const double wa = std::sqrt(opt.tolerance) * std::max(1e-300, curve_back(a) - curve_front(a));
  const double wb = std::sqrt(opt.tolerance) * std::max(1e-300, curve_back(b) - curve_front(b));
  std::vector<CurveHit2<double>> kept;
  for (const CurveHit2<double>& h : r.hits) {
    const bool inside = std::any_of(shared.begin(), shared.end(), [&](const GlobalOverlap& o) {
      return h.param_a >= o.ta0 - wa && h.param_a <= o.ta1 + wa &&
             h.param_b >= std::min(o.tb0, o.tb1) - wb && h.param_b <= std::max(o.tb0, o.tb1) + wb;
    });
    if (!inside) kept.push_back(h);
  }
  for (const GlobalOverlap& o : shared) {
    kept.push_back({point_at_t(a, o.ta0), o.ta0, o.tb0, 0});
    kept.push_back({point_at_t(a, o.ta1), o.ta1, o.tb1, 0});
  }
  std::stable_sort(
      kept.begin(), kept.end(),
      [](const CurveHit2<double>& x, const CurveHit2<double>& y) { return x.param_a < y.param_a; });
  r.hits = std::move(kept);
  r.kind = Kind::coincident;
  return r;
}

// ---------------------------------------------------------------------------------------------
// Self-intersections.

namespace {

/// Whether the projected control points advance strictly along some direction: then every line
/// across that direction meets the piece at most once (variation diminishing property of
/// positive-weight Bezier curves), so the piece has no self-intersection.
bool monotone(const std::vector<V3>& h) {
  std::vector<double> ang;
  for (std::size_t i = 1; i < h.size(); ++i) {
    const V2 e = proj(h[i]) - proj(h[i - 1]);
    // A repeated point keeps the advance monotone (non-decreasing); a piece that is one point
    // has no double point to report.
    if (e.x != 0.0 || e.y != 0.0) ang.push_back(std::atan2(e.y, e.x));
  }
  if (ang.size() <= 1) return true;
  std::sort(ang.begin(), ang.end());
  constexpr double pi = 3.141592653589793;
  double widest = 2.0 * pi - (ang.back() - ang.front());
  for (std::size_t i = 1; i < ang.size(); ++i) widest = std::max(widest, ang[i] - ang[i - 1]);
  return widest > pi + 1e-9;
}

}  // namespace

CurveHits2<double> self_curve(const Curve& c, const CurveHitOptions& opt) {
  CurveHits2<double> r;
  r.status = c.status;
  if (c.status != Status::ok) return r;
  // The curve cut into monotone segments, in parameter order (a cusp stops at max_depth).
  constexpr int max_depth = 20;
  std::vector<Piece> segs;
  int budget = opt.max_steps;
  for (const Piece& p : c.pieces) {
    struct Item {
      std::vector<V3> h;
      double a, b;
      int depth;
    };
    std::vector<Item> stack{{p.h, 0.0, 1.0, 0}};
    while (!stack.empty()) {
      Item it = std::move(stack.back());
      stack.pop_back();
      if (--budget < 0) {
        r.status = Status::limit_exceeded;
        return r;
      }
      if (it.depth >= max_depth || monotone(it.h)) {
        segs.push_back({std::move(it.h), global_t(p, it.a), global_t(p, it.b)});
        continue;
      }
      auto [left, right] = halves(it.h);
      const double m = 0.5 * (it.a + it.b);
      stack.push_back({std::move(right), m, it.b, it.depth + 1});
      stack.push_back({std::move(left), it.a, m, it.depth + 1});
    }
  }
  r.status = Status::ok;
  const double scale = curve_scale(c);
  const double range = curve_back(c) - curve_front(c);
  const bool closed = proj(c.pieces.front().h.front()) == proj(c.pieces.back().h.back());
  const double near = std::sqrt(opt.tolerance);
  std::vector<CurveHit2<double>> hits;
  for (std::size_t i = 0; i < segs.size(); ++i)
    for (std::size_t j = i + 1; j < segs.size(); ++j) {
      if (!overlap(box_of(segs[i].h), box_of(segs[j].h))) continue;
      const Curve ci{Status::ok, {segs[i]}, c.unit}, cj{Status::ok, {segs[j]}, c.unit};
      const CurveHits2<double> h = curve_curve(ci, cj, opt);
      if (h.status != Status::ok) r.status = h.status;
      const double da = near * (segs[i].t1 - segs[i].t0), db = near * (segs[j].t1 - segs[j].t0);
      const bool adjacent = segs[i].t1 == segs[j].t0;
      const bool ends = closed && i == 0 && j + 1 == segs.size();
      for (const CurveHit2<double>& x : h.hits) {
        // The joint of two consecutive segments, and the closing point of a closed curve, are
        // not self-intersections (an overlap's end there is).
        if (x.multiplicity != 0 && adjacent && std::abs(x.param_a - segs[i].t1) <= da &&
            std::abs(x.param_b - segs[j].t0) <= db)
          continue;
        if (x.multiplicity != 0 && ends && std::abs(x.param_a - segs[i].t0) <= da &&
            std::abs(x.param_b - segs[j].t1) <= db)
          continue;
        hits.push_back(x);
      }
    }
  std::stable_sort(
      hits.begin(), hits.end(),
      [](const CurveHit2<double>& x, const CurveHit2<double>& y) { return x.param_a < y.param_a; });
  // A double point on a segment joint is found by both segments there: once.
  bool any_overlap = false;
  for (const CurveHit2<double>& x : hits) {
    any_overlap = any_overlap || x.multiplicity == 0;
    const bool dup = std::any_of(r.hits.begin(), r.hits.end(), [&](const CurveHit2<double>& y) {
      return x.multiplicity != 0 && y.multiplicity != 0 &&
             length(x.point - y.point) <= 0x1p-30 * scale &&
             std::abs(x.param_a - y.param_a) <= near * range &&
             std::abs(x.param_b - y.param_b) <= near * range;
    });
    if (!dup) r.hits.push_back(x);
  }
  r.kind = any_overlap          ? Kind::coincident
           : r.hits.empty()     ? Kind::empty
           : r.hits.size() == 1 ? Kind::point
                                : Kind::points;
  return r;
}

}  // namespace locus::detail::polycurve2
