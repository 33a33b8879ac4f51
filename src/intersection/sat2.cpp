// SPDX-License-Identifier: BSL-1.0
// Separating axes for convex polygons in the plane, stationary and moving
// (include/locus/intersection/convex_polygon2.hpp, moving_convex2.hpp; derivation in
// docs/notes/intersection2.md). Everything is computed in double (float input is exact in it).

#include <locus/core/crossing.hpp>
#include <locus/core/predicates.hpp>
#include <locus/intersection/convex_polygon2.hpp>
#include <locus/intersection/moving_convex2.hpp>
#include <locus/intersection/segment_segment.hpp>
#include <locus/primitives/polygon.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

namespace locus::detail::sat2 {

namespace {

using V = Vec2<double>;

[[nodiscard]] bool lex_lt(const V& a, const V& b) noexcept {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

/// A polygon as given: vertices, exact orientation, dimension and lexicographic extremes.
template <Real T>
struct Poly {
  std::span<const Vec2<T>> v;
  int sign = 0;  // +1 counter-clockwise, -1 clockwise, 0 all collinear
  int dim = -1;  // -1 empty, 0 a point, 1 a segment, 2 a region
  V lo{}, hi{};  // lexicographic extremes of a point or segment (dim <= 1; unset for regions)
  bool finite = true;

  [[nodiscard]] V at(std::size_t i) const noexcept { return vec_cast<double>(v[i]); }
};

/// The sign polygon_orientation() gives (primitives/polygon.hpp: the turn at the lowest, then
/// leftmost vertex between its nearest distinct neighbours), for finite v, without its second
/// finiteness pass and its modulo arithmetic (a query's hot path).
template <Real T>
[[nodiscard]] int orientation_of_finite(std::span<const Vec2<T>> v) noexcept {
  const std::size_t n = v.size();
  if (n < 3) return 0;
  std::size_t k = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (v[i].y < v[k].y || (v[i].y == v[k].y && v[i].x < v[k].x)) k = i;
  std::size_t prev = k == 0 ? n - 1 : k - 1, next = k + 1 == n ? 0 : k + 1;
  while (prev != k && v[prev] == v[k]) prev = prev == 0 ? n - 1 : prev - 1;
  while (next != k && v[next] == v[k]) next = next + 1 == n ? 0 : next + 1;
  if (prev == k || next == k) return 0;
  return to_int(orient2d(v[prev], v[k], v[next]));
}

template <Real T>
[[nodiscard]] Poly<T> make_poly(std::span<const Vec2<T>> v) noexcept {
  Poly<T> P;
  P.v = v;
  // Branch-free finiteness (finite_zero: NaN when a coordinate is not finite).
  T z = T(0);
  for (const Vec2<T>& p : v) z += finite_zero(p);
  P.finite = z == T(0);
  if (!P.finite || v.empty()) return P;
  P.sign = orientation_of_finite(v);
  if (P.sign != 0) {
    P.dim = 2;  // lo and hi serve only points and segments
    return P;
  }
  P.lo = P.hi = P.at(0);
  for (std::size_t i = 1; i < v.size(); ++i) {
    const V p = P.at(i);
    if (lex_lt(p, P.lo)) P.lo = p;
    if (lex_lt(P.hi, p)) P.hi = p;
  }
  P.dim = P.lo == P.hi ? 0 : 1;
  return P;
}

/// Calls f(line) for each edge of a region, as a line with the polygon on its left; stops and
/// returns true when f does.
template <Real T, class F>
bool for_each_edge(const Poly<T>& P, F&& f) noexcept {
  const std::size_t n = P.v.size();
  for (std::size_t i = 0; i < n; ++i) {
    const V p = P.at(i), q = P.at(i + 1 == n ? 0 : i + 1);
    if (p == q) continue;
    if (f(P.sign > 0 ? Line{p, q} : Line{q, p})) return true;
  }
  return false;
}

[[nodiscard]] int side(const Line& c, const V& x) noexcept { return to_int(orient2d(c.p, c.q, x)); }

/// Some edge line of region P has every vertex of Q strictly outside (an exact separation).
/// Each edge's scan of Q starts at the vertex that was not outside the previous edge (for
/// neighbouring edges it usually is not outside this one either), so an edge that does not
/// separate usually costs one orient2d; the answer does not depend on the order of the scan.
template <Real T>
[[nodiscard]] bool separated_by_edges(const Poly<T>& P, const Poly<T>& Q) noexcept {
  const std::size_t m = Q.v.size();
  std::size_t start = 0;
  return for_each_edge(P, [&](const Line& c) {
    for (std::size_t k = 0, j = start; k < m; ++k, j = j + 1 == m ? 0 : j + 1)
      if (side(c, Q.at(j)) >= 0) {
        start = j;
        return false;
      }
    return true;
  });
}

/// Every vertex of Q strictly on one side of the line through segment-like S.
template <Real T>
[[nodiscard]] bool separated_by_segment(const Poly<T>& S, const Poly<T>& Q) noexcept {
  const Line c{S.lo, S.hi};
  int first = 0;
  for (std::size_t j = 0; j < Q.v.size(); ++j) {
    const int s = side(c, Q.at(j));
    if (s == 0 || (first != 0 && s != first)) return false;
    first = s;
  }
  return true;
}

// ---- the symbolic clipper ---------------------------------------------------------------------

[[nodiscard]] Sym vertex(const V& p) noexcept {
  Sym s{};
  s.p = p;
  s.crossing = false;
  return s;
}

[[nodiscard]] bool same_line(const Line& a, const Line& b) noexcept {
  return a.p == b.p && a.q == b.q;
}

/// Both lines are the same geometric line (exact).
[[nodiscard]] bool coincide(const Line& a, const Line& b) noexcept {
  return same_line(a, b) || (side(a, b.p) == 0 && side(a, b.q) == 0);
}

/// Exact side of a symbolic vertex with respect to line c.
[[nodiscard]] int side(const Line& c, const Sym& s) noexcept {
  if (!s.crossing) return side(c, s.p);
  if (same_line(s.l1, c) || same_line(s.l2, c)) return 0;
  return to_int(side_of_crossing(s.l1.p, s.l1.q, s.l2.p, s.l2.q, c.p, c.q));
}

/// The two symbolic vertices are the same point (exact): a crossing is the only common point
/// of its two (non-parallel) lines.
[[nodiscard]] bool same_point(const Sym& a, const Sym& b) noexcept {
  if (!a.crossing && !b.crossing) return a.p == b.p;
  if (b.crossing) return side(b.l1, a) == 0 && side(b.l2, a) == 0;
  return side(a.l1, b) == 0 && side(a.l2, b) == 0;
}

/// Clips the closed polygon in[0..k) by the closed half-plane left of c (Sutherland-Hodgman);
/// returns the new count, at most cap.
int clip(const Sym* in, int k, const Line& c, Sym* out, int cap) noexcept {
  if (k == 0) return 0;
  const int s0 = side(c, in[0]);
  int m = 0, sp = s0;
  for (int i = 0; i < k && m + 2 <= cap; ++i) {
    const Sym& P = in[i];
    const int sq = i + 1 == k ? s0 : side(c, in[i + 1]);
    if (sp >= 0) {
      out[m] = P;
      if (sp == 0 && sq < 0) out[m].out = c;
      ++m;
    }
    if ((sp > 0 && sq < 0) || (sp < 0 && sq > 0)) {
      Sym x{};
      x.crossing = true;
      x.l1 = P.out;
      x.l2 = c;
      x.out = sp > 0 ? c : P.out;
      out[m++] = x;
    }
    sp = sq;
  }
  return m;
}

/// The crossing of two lines known to meet at a point of both edges, constructed once from the
/// input: an end point exactly when one lies on the other line; else parametrised on the
/// lexicographically smaller edge (so the answer does not depend on the argument order), from
/// its nearer end, with the two side values rounded from their exact values.
[[nodiscard]] V construct(const Sym& s) noexcept {
  if (!s.crossing) return s.p;
  const Line& a = s.l1;
  const Line& b = s.l2;
  for (const V& p : {a.p, a.q})
    if (side(b, p) == 0) return p;
  for (const V& p : {b.p, b.q})
    if (side(a, p) == 0) return p;
  const auto canon = [](const Line& l) { return lex_lt(l.q, l.p) ? Line{l.q, l.p} : l; };
  Line m = canon(a), n = canon(b);
  if (lex_lt(n.p, m.p) || (n.p == m.p && lex_lt(n.q, m.q))) std::swap(m, n);
  const double v0 = turn2d_value(n.p, n.q, n.p, m.p), v1 = turn2d_value(n.p, n.q, n.p, m.q);
  const double dd = v0 - v1;
  const V d = m.q - m.p;
  if (std::abs(v0) <= std::abs(v1)) return m.p + (v0 / dd) * d;
  return m.q + (v1 / dd) * d;
}

/// Removes repeated consecutive vertices (exact) from the cycle; the kept vertex takes the
/// outgoing line of the removed one.
int dedupe_cycle(Sym* s, int k) noexcept {
  bool changed = true;
  while (changed && k > 1) {
    changed = false;
    for (int i = 0; i < k && k > 1; ++i) {
      const int j = i + 1 == k ? 0 : i + 1;
      if (same_point(s[i], s[j])) {
        s[i].out = s[j].out;
        if (j == 0) {
          s[0] = s[i];
          --k;
        } else {
          for (int t = j; t + 1 < k; ++t) s[t] = s[t + 1];
          --k;
        }
        changed = true;
      }
    }
  }
  return k;
}

/// Removes straight-angle vertices (incoming and outgoing edges on one line, decided exactly)
/// from a counter-clockwise convex cycle of positive area.
int drop_straight(Sym* s, int k) noexcept {
  bool changed = true;
  while (changed && k > 3) {
    changed = false;
    for (int i = 0; i < k && k > 3; ++i) {
      const int prev = i == 0 ? k - 1 : i - 1;
      if (coincide(s[prev].out, s[i].out)) {
        for (int t = i; t + 1 < k; ++t) s[t] = s[t + 1];
        --k;
        changed = true;
      }
    }
  }
  return k;
}

/// Segment-like S against region P: the part of S in P (0, 1 or 2 points).
template <Real T>
int clip_segment(const Poly<T>& S, const Poly<T>& P, V* pts) noexcept {
  constexpr int cap = 8;
  Sym bufa[cap], bufb[cap];
  Sym* cur = bufa;
  Sym* nxt = bufb;
  const Line along{S.lo, S.hi};
  cur[0] = vertex(S.lo);
  cur[1] = vertex(S.hi);
  int k = 2;
  for_each_edge(P, [&](const Line& c) {
    for (int i = 0; i < k; ++i) cur[i].out = along;
    k = clip(cur, k, c, nxt, cap);
    std::swap(cur, nxt);
    // Every vertex lies on S: drop exact repeats anywhere (a clipped 2-gon repeats its crossing).
    int m = 0;
    for (int i = 0; i < k; ++i) {
      bool seen = false;
      for (int j = 0; j < m && !seen; ++j) seen = same_point(cur[j], cur[i]);
      if (!seen) cur[m++] = cur[i];
    }
    k = std::min(m, 2);
    return k == 0;
  });
  for (int i = 0; i < k; ++i) pts[i] = construct(cur[i]);
  return k;
}

/// Orders two points lexicographically.
void order(V* pts, int n) noexcept {
  if (n == 2 && lex_lt(pts[1], pts[0])) std::swap(pts[0], pts[1]);
}

/// The common set when it is not a region with an interior (or Kind::polygon when it is):
/// exact kinds; points as described in convex_polygon2.hpp.
template <Real T>
Kind classify(const Poly<T>& A, const Poly<T>& B, V* pts, int& np) noexcept {
  np = 0;
  if (!A.finite || !B.finite || A.dim < 0 || B.dim < 0) return Kind::empty;
  if (A.dim <= 1 && B.dim <= 1) {
    // Canonical argument order, so the rounded crossing does not depend on it.
    Segment2<double> s{A.lo, A.hi}, t{B.lo, B.hi};
    if (lex_lt(t.p0, s.p0) || (t.p0 == s.p0 && lex_lt(t.p1, s.p1))) std::swap(s, t);
    const auto r = intersection(s, t);
    np = r.count;
    for (int i = 0; i < r.count; ++i) pts[i] = r.point[static_cast<std::size_t>(i)];
    order(pts, np);
    return r.kind == Kind::empty ? Kind::empty : (np == 1 ? Kind::point : Kind::segment);
  }
  if (A.dim == 0 || B.dim == 0) {
    const Poly<T>& R = A.dim == 0 ? B : A;
    const V p = A.dim == 0 ? A.lo : B.lo;
    const bool in = !for_each_edge(R, [&](const Line& c) { return side(c, p) < 0; });
    if (!in) return Kind::empty;
    pts[0] = p;
    np = 1;
    return Kind::point;
  }
  if (A.dim == 1 || B.dim == 1) {
    np = A.dim == 1 ? clip_segment(A, B, pts) : clip_segment(B, A, pts);
    order(pts, np);
    return np == 0 ? Kind::empty : (np == 1 ? Kind::point : Kind::segment);
  }
  // Two regions: a strictly separating edge line gives empty, a weakly separating one holds the
  // whole (touching) common set, none means the interiors overlap.
  bool weak = false;
  Line w{};
  const auto scan = [&](const Poly<T>& P, const Poly<T>& Q) {
    return for_each_edge(P, [&](const Line& c) {
      int mx = -1;
      for (std::size_t j = 0; j < Q.v.size() && mx <= 0; ++j) mx = std::max(mx, side(c, Q.at(j)));
      if (mx < 0) return true;
      if (mx == 0 && !weak) weak = true, w = c;
      return false;
    });
  };
  if (scan(A, B) || scan(B, A)) return Kind::empty;
  if (!weak) return Kind::polygon;
  // Both polygons meet the line w in collinear vertex sets; the common set is the overlap of
  // their extents, ordered lexicographically (exact along a line).
  const auto extent = [&](const Poly<T>& P, V& lo, V& hi) {
    bool any = false;
    for (std::size_t j = 0; j < P.v.size(); ++j) {
      const V x = P.at(j);
      if (side(w, x) != 0) continue;
      if (!any || lex_lt(x, lo)) lo = x;
      if (!any || lex_lt(hi, x)) hi = x;
      any = true;
    }
  };
  V alo{}, ahi{}, blo{}, bhi{};
  extent(A, alo, ahi);
  extent(B, blo, bhi);
  pts[0] = lex_lt(alo, blo) ? blo : alo;
  pts[1] = lex_lt(ahi, bhi) ? ahi : bhi;
  np = pts[0] == pts[1] ? 1 : 2;
  return np == 1 ? Kind::point : Kind::segment;
}

}  // namespace

template <Real T>
bool test(std::span<const Vec2<T>> a, std::span<const Vec2<T>> b) noexcept {
  const Poly<T> A = make_poly(a), B = make_poly(b);
  if (!A.finite || !B.finite || A.dim < 0 || B.dim < 0) return false;
  if (A.dim <= 1 && B.dim <= 1) return segments_intersect_exact(A.lo, A.hi, B.lo, B.hi);
  if (A.dim == 2 && separated_by_edges(A, B)) return false;
  if (B.dim == 2 && separated_by_edges(B, A)) return false;
  if (A.dim == 1 && separated_by_segment(A, B)) return false;
  if (B.dim == 1 && separated_by_segment(B, A)) return false;
  return true;
}

template <Real T>
Kind find(std::span<const Vec2<T>> a, std::span<const Vec2<T>> b, Vec2<T>* out, int& count,
          Sym* work) noexcept {
  count = 0;
  const Poly<T> A = make_poly(a), B = make_poly(b);
  V pts[2];
  int np = 0;
  const Kind k = classify(A, B, pts, np);
  if (k != Kind::polygon) {
    for (int i = 0; i < np; ++i) out[i] = vec_cast<T>(pts[i]);
    count = np;
    return k;
  }
  // Interiors overlap: clip A (counter-clockwise, repeats removed) by B's edge half-planes.
  const int cap = static_cast<int>(a.size() + b.size() + 4);
  Sym* cur = work;
  Sym* nxt = work + cap;
  int n = 0;
  const std::size_t na = a.size();
  for (std::size_t j = 0; j < na; ++j) {
    const V p = A.at(A.sign > 0 ? j : na - 1 - j);
    if (n > 0 && cur[n - 1].p == p) continue;
    cur[n++] = vertex(p);
  }
  while (n > 1 && cur[n - 1].p == cur[0].p) --n;
  for (int i = 0; i < n; ++i) cur[i].out = Line{cur[i].p, cur[i + 1 == n ? 0 : i + 1].p};
  for_each_edge(B, [&](const Line& c) {
    n = clip(cur, n, c, nxt, cap);
    std::swap(cur, nxt);
    return n == 0;
  });
  n = dedupe_cycle(cur, n);
  n = drop_straight(cur, n);
  const int limit = static_cast<int>(a.size() + b.size());
  n = std::min(n, limit);
  int first = 0;
  for (int i = 0; i < n; ++i) {
    out[i] = vec_cast<T>(construct(cur[i]));
    if (lex_lt(vec_cast<double>(out[i]), vec_cast<double>(out[first]))) first = i;
  }
  std::rotate(out, out + first, out + n);
  count = n;
  return n >= 3 ? Kind::polygon : (n == 2 ? Kind::segment : (n == 1 ? Kind::point : Kind::empty));
}

// ---- moving polygons ----------------------------------------------------------------------------

namespace {

/// The projection onto an axis is f(x) = det[q - p; x] up to a constant; x is larger than y
/// along it iff turn2d(p, q, y, x) > 0 (exact).
struct Axis {
  Line l;
};

[[nodiscard]] int cmp_along(const Axis& ax, const V& x, const V& y) noexcept {
  return to_int(turn2d(ax.l.p, ax.l.q, y, x));
}

template <Real T>
void extremes(const Axis& ax, const Poly<T>& P, V& mn, V& mx) noexcept {
  mn = mx = P.at(0);
  for (std::size_t i = 1; i < P.v.size(); ++i) {
    const V x = P.at(i);
    if (cmp_along(ax, x, mn) < 0) mn = x;
    if (cmp_along(ax, x, mx) > 0) mx = x;
  }
}

/// The feature of P at the extreme `e` along the axis (all vertices level with it): its
/// lexicographic end points.
template <Real T>
void feature(const Axis& ax, const Poly<T>& P, const V& e, V& f0, V& f1) noexcept {
  f0 = f1 = e;
  for (std::size_t i = 0; i < P.v.size(); ++i) {
    const V x = P.at(i);
    if (cmp_along(ax, x, e) != 0) continue;
    if (lex_lt(x, f0)) f0 = x;
    if (lex_lt(f1, x)) f1 = x;
  }
}

}  // namespace

template <Real T>
Contact2<T> first_contact(std::span<const Vec2<T>> a, const Vec2<T>& va_,
                          std::span<const Vec2<T>> b, const Vec2<T>& vb_, T tmax_) noexcept {
  Contact2<T> r;
  const Poly<T> A = make_poly(a), B = make_poly(b);
  if (!A.finite || !B.finite || A.dim < 0 || B.dim < 0 || !is_finite(va_) || !is_finite(vb_) ||
      !(tmax_ >= T(0)) || !std::isfinite(tmax_))
    return r;
  // Time 0: exact.
  V pts[2];
  int np = 0;
  const Kind k0 = classify(A, B, pts, np);
  if (k0 != Kind::empty) {
    r.kind = k0;
    r.count = k0 == Kind::polygon ? 0 : np;
    for (int i = 0; i < r.count; ++i) r.point[static_cast<std::size_t>(i)] = vec_cast<T>(pts[i]);
    return r;
  }
  const V va = vec_cast<double>(va_), vb = vec_cast<double>(vb_);
  const double tmax = double(tmax_);
  constexpr double inf = std::numeric_limits<double>::infinity();
  double tfirst = -inf, tlast = inf;
  Axis best{};
  int best_speed = 0;
  bool never = false;
  const auto use = [&](const Axis& ax) {
    V amin, amax, bmin, bmax;
    extremes(ax, A, amin, amax);
    extremes(ax, B, bmin, bmax);
    const int s = to_int(turn2d(ax.l.p, ax.l.q, va, vb));  // sign of the speed of b along it
    if (s == 0) {
      never = cmp_along(ax, bmin, amax) > 0 || cmp_along(ax, amin, bmax) > 0;
      return never;
    }
    const double speed = turn2d_value(ax.l.p, ax.l.q, va, vb);
    const double enter = s > 0 ? turn2d_value(ax.l.p, ax.l.q, bmax, amin) / speed
                               : turn2d_value(ax.l.p, ax.l.q, bmin, amax) / speed;
    const double exit = s > 0 ? turn2d_value(ax.l.p, ax.l.q, bmin, amax) / speed
                              : turn2d_value(ax.l.p, ax.l.q, bmax, amin) / speed;
    if (enter > tfirst) tfirst = enter, best = ax, best_speed = s;
    tlast = std::min(tlast, exit);
    never = tfirst > tlast || tfirst > tmax || tlast < 0.0;
    return never;
  };
  const auto add_axes = [&](const Poly<T>& P) {
    if (P.dim == 2) return for_each_edge(P, [&](const Line& c) { return use(Axis{c}); });
    if (P.dim == 1) {
      // The segment's normal and its direction (f(x) = dot(hi - lo, x) via (x, y) -> (y, -x)).
      const auto rot = [](const V& x) { return V{x.y, -x.x}; };
      return use(Axis{Line{P.lo, P.hi}}) || use(Axis{Line{rot(P.lo), rot(P.hi)}});
    }
    return false;
  };
  bool stop = add_axes(A) || add_axes(B);
  if (!stop && (A.dim < 2 || B.dim < 2))
    stop = use(Axis{Line{V{0, 0}, V{0, -1}}}) || use(Axis{Line{V{0, 0}, V{1, 0}}});
  if (never || best_speed == 0) return r;
  const double t = std::max(tfirst, 0.0);
  // Contact features: b approaches from the side its speed points away from.
  V amin, amax, bmin, bmax, a0, a1, b0, b1;
  extremes(best, A, amin, amax);
  extremes(best, B, bmin, bmax);
  feature(best, A, best_speed > 0 ? amin : amax, a0, a1);
  feature(best, B, best_speed > 0 ? bmax : bmin, b0, b1);
  a0 += t * va, a1 += t * va, b0 += t * vb, b1 += t * vb;
  r.time = static_cast<T>(t);
  if (a0 == a1 || b0 == b1) {
    r.kind = Kind::point;
    r.count = 1;
    r.point[0] = vec_cast<T>(a0 == a1 ? a0 : b0);
    return r;
  }
  // Edge against edge: the overlap of the two moved edges along a's edge.
  const V u = a1 - a0;
  const double uu = dot(u, u);
  double s0 = dot(b0 - a0, u), s1 = dot(b1 - a0, u);
  if (s1 < s0) std::swap(s0, s1), std::swap(b0, b1);
  const V lo = s0 > 0.0 ? b0 : a0, hi = s1 < uu ? b1 : a1;
  if (std::max(s0, 0.0) < std::min(s1, uu)) {
    r.kind = Kind::segment;
    r.count = 2;
    V ends[2] = {lo, hi};
    order(ends, 2);
    r.point[0] = vec_cast<T>(ends[0]);
    r.point[1] = vec_cast<T>(ends[1]);
  } else {
    r.kind = Kind::point;
    r.count = 1;
    r.point[0] = vec_cast<T>(s0 > 0.0 ? b0 : b1);
  }
  return r;
}

template bool test<float>(std::span<const Vec2<float>>, std::span<const Vec2<float>>) noexcept;
template bool test<double>(std::span<const Vec2<double>>, std::span<const Vec2<double>>) noexcept;
template Kind find<float>(std::span<const Vec2<float>>, std::span<const Vec2<float>>, Vec2<float>*,
                          int&, Sym*) noexcept;
template Kind find<double>(std::span<const Vec2<double>>, std::span<const Vec2<double>>,
                           Vec2<double>*, int&, Sym*) noexcept;
template Contact2<float> first_contact<float>(std::span<const Vec2<float>>, const Vec2<float>&,
                                              std::span<const Vec2<float>>, const Vec2<float>&,
                                              float) noexcept;
template Contact2<double> first_contact<double>(std::span<const Vec2<double>>, const Vec2<double>&,
                                                std::span<const Vec2<double>>, const Vec2<double>&,
                                                double) noexcept;

}  // namespace locus::detail::sat2
