// SPDX-License-Identifier: BSL-1.0
// Polygon booleans by snap rounding (include/locus/boolean/polygon_boolean.hpp,
// docs/notes/boolean.md). Decisions about the input segments (crossings, pixels of vertices and
// crossings, segments meeting hot pixels) use core's exact predicates on the input coordinates
// in pixel units; the rounded arrangement then lives on integer pixel centres of at most 40 bits,
// so orientations fit in 84 bits and everything after is exact in 128-bit integers.

#include <locus/boolean/polygon_boolean.hpp>
#include <locus/core/crossing.hpp>
#include <locus/core/exact_poly.hpp>
#include <locus/core/predicates.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <type_traits>
#include <utility>

namespace locus {
namespace {

__extension__ typedef __int128 i128;
using i64 = std::int64_t;

struct Pt {
  i64 x, y;
};
bool operator==(Pt a, Pt b) { return a.x == b.x && a.y == b.y; }
bool operator!=(Pt a, Pt b) { return !(a == b); }
bool operator<(Pt a, Pt b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

i128 cross(i128 ax, i128 ay, i128 bx, i128 by) { return ax * by - ay * bx; }
i128 orient(Pt a, Pt b, Pt c) { return cross(b.x - a.x, b.y - a.y, c.x - a.x, c.y - a.y); }
int sign(i128 v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }
enum class Role : std::uint8_t { raw, outer, hole };
/// A ring in pixel units (the input scaled by 2^-ge, exactly).
struct Ring {
  std::vector<Vec2d> pts;
  int operand;
  Role role;
};

/// The pixel of x: the k with k - 1/2 <= x < k + 1/2 (|x| < 2^52).
i64 pixel_of(double x) {
  i64 k = static_cast<i64>(std::nearbyint(x));
  const double r = x - static_cast<double>(k);  // exact: x and k are within 1/2
  if (r >= 0.5) ++k;
  if (r < -0.5) --k;
  return k;
}
Pt pixel_of(const Vec2d& p) { return {pixel_of(p.x), pixel_of(p.y)}; }

/// The exact sign of a ring's signed area (core/exact_poly.hpp).
int area_sign(const std::vector<Vec2d>& r) {
  std::vector<ExactTerm> terms;
  terms.reserve(2 * r.size());
  for (std::size_t i = 0, n = r.size(); i < n; ++i) {
    const Vec2d p = r[i], q = r[(i + 1) % n];
    terms.push_back({1, 0, 2, {p.x, q.y}});
    terms.push_back({-1, 0, 2, {p.y, q.x}});
  }
  return exact_sign_of_terms(terms);
}

struct Seg {
  Vec2d a, b;  // directed as in its ring, exact input (in pixel units)
  int operand;
  Pt pa, pb;                   // their pixels
  i64 xmin, xmax, ymin, ymax;  // pixel range
  int sx, sy;                  // signs of b - a
};

/// A bound on the parameter t of a + t (b - a): the constant 0 or 1, or where x (y) equals c.
struct Param {
  enum Kind : std::uint8_t { zero, one, x, y } kind;
  double c;
  bool open;
};
int sign_of(double v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }
/// Exact sign of p - q as parameters along s (orient2d for the mixed case).
int compare(const Seg& s, const Param& p, const Param& q) {
  const auto is_const = [](const Param& r) {
    return r.kind == Param::zero || r.kind == Param::one;
  };
  if (is_const(p) && is_const(q)) return static_cast<int>(p.kind) - static_cast<int>(q.kind);
  if (is_const(p)) return -compare(s, q, p);
  const bool px = p.kind == Param::x;
  const double a = px ? s.a.x : s.a.y, b = px ? s.b.x : s.b.y;
  const int sd = px ? s.sx : s.sy;
  if (q.kind == Param::zero) return sign_of(p.c - a) * sd;  // (c - a) / d
  if (q.kind == Param::one) return sign_of(p.c - b) * sd;   // (c - a) / d - 1 = (c - b) / d
  if (q.kind == p.kind) return sign_of(p.c - q.c) * sd;
  // t_x(c) - t_y(c') = -orient2d(a, b, (c, c')) / (dx dy)
  const Vec2d corner = px ? Vec2d{p.c, q.c} : Vec2d{q.c, p.c};
  const int o = to_int(orient2d(s.a, s.b, corner));
  return (px ? -o : o) * s.sx * s.sy;
}

/// Does segment s meet the half-open pixel [h - 1/2, h + 1/2)^2? Exact.
bool pixel_meets(const Seg& s, Pt h) {
  Param lo{Param::zero, 0, false}, hi{Param::one, 0, false};
  const auto constrain = [&](Param::Kind kind, double a, int sd, i64 k) {
    const double c0 = static_cast<double>(k) - 0.5, c1 = static_cast<double>(k) + 0.5;
    if (sd == 0) return c0 <= a && a < c1;
    // sd > 0: t_(c0) <= t < t_(c1); sd < 0: t_(c1) < t <= t_(c0).
    const Param nl = sd > 0 ? Param{kind, c0, false} : Param{kind, c1, true};
    const Param nh = sd > 0 ? Param{kind, c1, true} : Param{kind, c0, false};
    const int cl = compare(s, nl, lo), ch = compare(s, nh, hi);
    if (cl > 0 || (cl == 0 && nl.open)) lo = nl;
    if (ch < 0 || (ch == 0 && nh.open)) hi = nh;
    return true;
  };
  if (!constrain(Param::x, s.a.x, s.sx, h.x)) return false;
  if (!constrain(Param::y, s.a.y, s.sy, h.y)) return false;
  const int c = compare(s, lo, hi);
  return c < 0 || (c == 0 && !lo.open && !hi.open);
}

/// The pixel of the proper crossing of s and t: a rounded estimate corrected by exact signs of
/// the crossing against the pixel's boundary lines (core/crossing.hpp).
Pt crossing_pixel(const Seg& s, const Seg& t) {
  const double oa = turn2d_value(t.a, t.b, t.a, s.a), ob = turn2d_value(t.a, t.b, t.a, s.b);
  const double u = oa / (oa - ob);
  Pt k = pixel_of(Vec2d{s.a.x + u * (s.b.x - s.a.x), s.a.y + u * (s.b.y - s.a.y)});
  // sign(c - X.x) from the vertical line x = c, sign(X.y - c) from the horizontal y = c.
  const auto left_of = [&](double c) {
    return to_int(side_of_crossing(s.a, s.b, t.a, t.b, Vec2d{c, 0}, Vec2d{c, 1}));
  };
  const auto above = [&](double c) {
    return to_int(side_of_crossing(s.a, s.b, t.a, t.b, Vec2d{0, c}, Vec2d{1, c}));
  };
  for (int step = 0; step < 64; ++step) {
    const double c = static_cast<double>(k.x);
    if (left_of(c - 0.5) > 0)
      --k.x;
    else if (left_of(c + 0.5) <= 0)
      ++k.x;
    else
      break;
  }
  for (int step = 0; step < 64; ++step) {
    const double c = static_cast<double>(k.y);
    if (above(c - 0.5) < 0)
      --k.y;
    else if (above(c + 0.5) >= 0)
      ++k.y;
    else
      break;
  }
  return k;
}

/// An undirected fragment u < v with the winding change of each operand along u -> v.
struct Frag {
  Pt u, v;
  int w[2];
};
bool frag_less(const Frag& p, const Frag& q) { return p.u < q.u || (p.u == q.u && p.v < q.v); }
void merge_frags(std::vector<Frag>& f) {
  std::sort(f.begin(), f.end(), frag_less);
  std::size_t out = 0;
  for (std::size_t i = 0; i < f.size();) {
    Frag m = f[i];
    std::size_t j = i + 1;
    for (; j < f.size() && f[j].u == m.u && f[j].v == m.v; ++j) {
      m.w[0] += f[j].w[0];
      m.w[1] += f[j].w[1];
    }
    if (m.w[0] != 0 || m.w[1] != 0) f[out++] = m;
    i = j;
  }
  f.resize(out);
}

/// Hot pixels bucketed in a uniform grid of about one pixel per cell, so that a segment visits
/// the cells along it rather than every hot pixel in its x-range.
class HotGrid {
 public:
  explicit HotGrid(const std::vector<Pt>& hot) {
    x0_ = y0_ = std::numeric_limits<i64>::max();
    i64 x1 = std::numeric_limits<i64>::min(), y1 = x1;
    for (Pt p : hot) {
      x0_ = std::min(x0_, p.x);
      y0_ = std::min(y0_, p.y);
      x1 = std::max(x1, p.x);
      y1 = std::max(y1, p.y);
    }
    // About one pixel per cell, nx * ny <= 2 n cells even for long thin extents.
    const double w = static_cast<double>(x1 - x0_) + 1, h = static_cast<double>(y1 - y0_) + 1;
    const double n = static_cast<double>(hot.size());
    const double nx = std::clamp(std::round(std::sqrt(n * w / h)), 1.0, std::min(n, w));
    const double ny = std::clamp(std::round(n / nx), 1.0, std::min(n, h));
    cx_ = static_cast<i64>(std::ceil(w / nx));
    cy_ = static_cast<i64>(std::ceil(h / ny));
    nx_ = static_cast<std::size_t>((x1 - x0_) / cx_ + 1);
    ny_ = static_cast<std::size_t>((y1 - y0_) / cy_ + 1);
    start_.assign(nx_ * ny_ + 1, 0);
    for (Pt p : hot) ++start_[cell_of(p) + 1];
    for (std::size_t c = 0; c < nx_ * ny_; ++c) start_[c + 1] += start_[c];
    items_.resize(hot.size());
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for (Pt p : hot) items_[fill[cell_of(p)]++] = p;
  }

  /// Visits (a superset of) the hot pixels in the pixel box [xmin, xmax] x [ymin, ymax] whose
  /// square segment ab (pixel units) can meet, each once.
  template <class F>
  void along(const Vec2d& a, const Vec2d& b, i64 xmin, i64 xmax, i64 ymin, i64 ymax, F&& f) const {
    if (xmax < x0_ || ymax < y0_) return;
    const std::size_t c0 = column(std::max(xmin, x0_)), c1 = column(xmax);
    const double dx = b.x - a.x, dy = b.y - a.y;
    for (std::size_t i = c0; i <= c1 && i < nx_; ++i) {
      const i64 xl = std::max(xmin, x0_ + static_cast<i64>(i) * cx_);
      const i64 xr = std::min(xmax, x0_ + static_cast<i64>(i + 1) * cx_ - 1);
      double ylo = static_cast<double>(ymin), yhi = static_cast<double>(ymax);
      if (dx != 0) {
        // y along the segment over [xl - 1/2, xr + 1/2], widened by a pixel: the rounding
        // error of this double evaluation (below 2^-10 for 40-bit coordinates) cannot matter.
        const double ya = a.y + (static_cast<double>(xl) - 0.5 - a.x) * dy / dx;
        const double yb = a.y + (static_cast<double>(xr) + 0.5 - a.x) * dy / dx;
        ylo = std::max(ylo, std::min(ya, yb) - 1.5);
        yhi = std::min(yhi, std::max(ya, yb) + 1.5);
      }
      if (yhi < static_cast<double>(y0_) || ylo > static_cast<double>(ymax)) continue;
      const i64 ya = std::max(y0_, static_cast<i64>(std::floor(ylo)));
      const i64 yb = std::min(ymax, static_cast<i64>(std::ceil(yhi)));
      if (ya > yb) continue;
      const std::size_t r0 = static_cast<std::size_t>((ya - y0_) / cy_);
      const std::size_t r1 = std::min(ny_ - 1, static_cast<std::size_t>((yb - y0_) / cy_));
      for (std::size_t r = r0; r <= r1; ++r)
        for (std::size_t k = start_[i * ny_ + r]; k < start_[i * ny_ + r + 1]; ++k) {
          const Pt p = items_[k];
          if (p.x >= xmin && p.x <= xmax && p.y >= ymin && p.y <= ymax) f(p);
        }
    }
  }

 private:
  std::size_t column(i64 x) const { return static_cast<std::size_t>((x - x0_) / cx_); }
  std::size_t cell_of(Pt p) const {
    return column(p.x) * ny_ + static_cast<std::size_t>((p.y - y0_) / cy_);
  }
  i64 x0_, y0_, cx_ = 1, cy_ = 1;
  std::size_t nx_ = 0, ny_ = 0;
  std::vector<std::size_t> start_;
  std::vector<Pt> items_;
};

bool inside_by_rule(int w, FillRule rule) {
  switch (rule) {
    case FillRule::even_odd:
      return (w & 1) != 0;
    case FillRule::non_zero:
      return w != 0;
    case FillRule::positive:
      return w > 0;
  }
  return false;
}
bool apply_op(BooleanOp op, bool a, bool b) {
  switch (op) {
    case BooleanOp::intersection:
      return a && b;
    case BooleanOp::union_:
      return a || b;
    case BooleanOp::difference:
      return a && !b;
    case BooleanOp::symmetric_difference:
      return a != b;
  }
  return false;
}

i128 twice_area(const std::vector<Pt>& r) {
  i128 s = 0;
  for (std::size_t i = 0, n = r.size(); i < n; ++i) {
    const Pt p = r[i], q = r[(i + 1) % n];
    s += static_cast<i128>(p.x) * q.y - static_cast<i128>(p.y) * q.x;
  }
  return s;
}

/// Is q (coordinates doubled) strictly inside ring r (not on it: the caller guarantees)?
bool ring_contains_doubled(const std::vector<Pt>& r, Pt q) {
  bool in = false;
  for (std::size_t i = 0, n = r.size(); i < n; ++i) {
    const Pt a{2 * r[i].x, 2 * r[i].y}, b{2 * r[(i + 1) % n].x, 2 * r[(i + 1) % n].y};
    if ((a.y <= q.y) != (b.y <= q.y)) {
      const int o = sign(orient(a, b, q));
      if ((b.y > a.y) ? o > 0 : o < 0) in = !in;
    }
  }
  return in;
}

struct Engine {
  BooleanOp op;
  FillRule rule[2];
  std::vector<Ring> rings;
  std::string error;

  /// Output rings (outer CCW, holes CW) grouped into polygons.
  struct OutPolygon {
    std::vector<Pt> outer;
    std::vector<std::vector<Pt>> holes;
  };
  std::vector<OutPolygon> result;

  bool run();
};

bool Engine::run() {
  // 1. Directed edges of every ring, orientations normalised by role (the exact sign of the
  // ring's signed area).
  std::vector<Seg> segs;
  {
    std::size_t total = 0;
    for (const Ring& r : rings) total += r.pts.size();
    segs.reserve(total);
  }
  for (Ring& r : rings) {
    std::vector<Vec2d> pts;
    for (const Vec2d& p : r.pts)
      if (pts.empty() || pts.back() != p) pts.push_back(p);
    while (pts.size() > 1 && pts.back() == pts.front()) pts.pop_back();
    if (pts.size() < 2) continue;
    if (r.role != Role::raw) {
      const int s = area_sign(pts);
      if (s == 0) continue;
      if ((r.role == Role::outer) != (s > 0)) std::reverse(pts.begin(), pts.end());
    }
    for (std::size_t i = 0, n = pts.size(); i < n; ++i) {
      const Vec2d a = pts[i], b = pts[(i + 1) % n];
      const Pt pa = pixel_of(a), pb = pixel_of(b);
      segs.push_back({a, b, r.operand, pa, pb, std::min(pa.x, pb.x), std::max(pa.x, pb.x),
                      std::min(pa.y, pb.y), std::max(pa.y, pb.y), sign_of(b.x - a.x),
                      sign_of(b.y - a.y)});
    }
  }
  if (segs.empty()) return true;

  // 2. Hot pixels: every vertex's, and every proper crossing's (x-sorted sweep, exact).
  // Each segment's end b is the next segment's start in its ring: the starts are every vertex.
  std::vector<Pt> hot;
  hot.reserve(segs.size() + segs.size() / 8);
  for (const Seg& s : segs) hot.push_back(s.pa);
  // The sweep keeps each active segment's x-end and y-range inline (no look-up in segs).
  struct Active {
    double hi_x, lo_y, hi_y;
    std::size_t index;
  };
  std::vector<std::pair<double, std::size_t>> order(segs.size());
  for (std::size_t i = 0; i < segs.size(); ++i) order[i] = {std::min(segs[i].a.x, segs[i].b.x), i};
  std::sort(order.begin(), order.end(),
            [](const auto& p, const auto& q) { return p.first < q.first; });
  std::vector<Active> active;
  for (const auto& [lo_x, i] : order) {
    const Seg& s = segs[i];
    const double sy0 = std::min(s.a.y, s.b.y), sy1 = std::max(s.a.y, s.b.y);
    std::size_t keep = 0;
    for (const Active& t : active)
      if (t.hi_x >= lo_x) active[keep++] = t;
    active.resize(keep);
    for (const Active& at : active) {
      if (at.hi_y < sy0 || sy1 < at.lo_y) continue;
      const Seg& t = segs[at.index];
      const int oc = to_int(orient2d(s.a, s.b, t.a)), od = to_int(orient2d(s.a, s.b, t.b));
      if (oc * od >= 0) continue;  // apart, touching at an endpoint (hot already) or collinear
      const int oa = to_int(orient2d(t.a, t.b, s.a)), ob = to_int(orient2d(t.a, t.b, s.b));
      if (oa * ob >= 0) continue;
      hot.push_back(crossing_pixel(s, t));
    }
    active.push_back({std::max(s.a.x, s.b.x), sy0, sy1, i});
  }
  std::sort(hot.begin(), hot.end());
  hot.erase(std::unique(hot.begin(), hot.end()), hot.end());

  // 3. Route every segment through the centres of the hot pixels it meets (exact tests on the
  // input segment), in order along it: the pixels a segment visits are monotone in x and in y,
  // so sx * x + sy * y increases strictly along it.
  const HotGrid grid(hot);
  std::vector<Frag> frags;
  std::vector<std::pair<i64, Pt>> route;
  for (const Seg& s : segs) {
    route.clear();
    // The pixels of the segment's ends always meet it: only other hot pixels need the test.
    grid.along(s.a, s.b, s.xmin, s.xmax, s.ymin, s.ymax, [&](Pt h) {
      if (h == s.pa || h == s.pb || pixel_meets(s, h))
        route.emplace_back(s.sx * h.x + s.sy * h.y, h);
    });
    std::sort(route.begin(), route.end(),
              [](const auto& p, const auto& q) { return p.first < q.first; });
    for (std::size_t k = 0; k + 1 < route.size(); ++k) {
      const Pt p = route[k].second, q = route[k + 1].second;
      if (p == q) continue;
      Frag f{p < q ? p : q, p < q ? q : p, {0, 0}};
      f.w[s.operand] = p < q ? 1 : -1;
      frags.push_back(f);
    }
  }
  merge_frags(frags);
  // A hot centre lying inside a fragment (a degenerate case of the rounding) becomes a vertex.
  {
    std::vector<Frag> split;
    std::vector<Pt> on;
    for (const Frag& f : frags) {
      on.clear();
      const Vec2d u{static_cast<double>(f.u.x), static_cast<double>(f.u.y)};
      const Vec2d v{static_cast<double>(f.v.x), static_cast<double>(f.v.y)};
      grid.along(u, v, f.u.x, f.v.x, std::min(f.u.y, f.v.y), std::max(f.u.y, f.v.y), [&](Pt h) {
        if (h != f.u && h != f.v && orient(f.u, f.v, h) == 0) on.push_back(h);
      });
      if (on.empty()) {
        split.push_back(f);
        continue;
      }
      std::sort(on.begin(), on.end());
      Pt prev = f.u;
      for (Pt h : on) {
        split.push_back({prev, h, {f.w[0], f.w[1]}});
        prev = h;
      }
      split.push_back({prev, f.v, {f.w[0], f.w[1]}});
    }
    frags.swap(split);
    merge_frags(frags);
  }
  if (frags.empty()) return true;

  // 4. Planar graph: half-edges 2e (u -> v) and 2e + 1 (v -> u), rotation CCW at each vertex.
  std::vector<Pt> verts;
  verts.reserve(2 * frags.size());
  for (const Frag& f : frags) {
    verts.push_back(f.u);
    verts.push_back(f.v);
  }
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  const auto vid = [&](Pt p) {
    return static_cast<std::size_t>(std::lower_bound(verts.begin(), verts.end(), p) -
                                    verts.begin());
  };
  const std::size_t nh = 2 * frags.size(), nv = verts.size();
  std::vector<std::size_t> origin(nh);
  // frags are sorted by u (merge_frags): their u's are found by one forward walk.
  for (std::size_t e = 0, k = 0; e < frags.size(); ++e) {
    while (verts[k] < frags[e].u) ++k;
    origin[2 * e] = k;
    origin[2 * e + 1] = vid(frags[e].v);
  }
  const auto dest = [&](std::size_t h) { return origin[h ^ 1]; };
  std::vector<std::size_t> start(nv + 1, 0), rot(nh), pos(nh);
  for (std::size_t h = 0; h < nh; ++h) ++start[origin[h] + 1];
  for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t h = 0; h < nh; ++h) rot[fill[origin[h]]++] = h;
  }
  const auto direction = [&](std::size_t h) {
    const Pt a = verts[origin[h]], b = verts[dest(h)];
    return Pt{b.x - a.x, b.y - a.y};
  };
  const auto ccw_less = [&](std::size_t g, std::size_t h) {
    const Pt a = direction(g), b = direction(h);
    const int ha = (a.y < 0 || (a.y == 0 && a.x < 0)) ? 1 : 0;
    const int hb = (b.y < 0 || (b.y == 0 && b.x < 0)) ? 1 : 0;
    if (ha != hb) return ha < hb;
    return cross(a.x, a.y, b.x, b.y) > 0;
  };
  for (std::size_t v = 0; v < nv; ++v) {
    std::sort(rot.begin() + static_cast<std::ptrdiff_t>(start[v]),
              rot.begin() + static_cast<std::ptrdiff_t>(start[v + 1]), ccw_less);
    for (std::size_t k = start[v]; k < start[v + 1]; ++k) pos[rot[k]] = k;
  }
  // The half-edge after h around the face on h's left: the one just clockwise of twin(h).
  const auto clockwise_of = [&](std::size_t h) {
    const std::size_t v = origin[h], k = pos[h];
    return rot[k == start[v] ? start[v + 1] - 1 : k - 1];
  };
  std::vector<std::size_t> face(nh, SIZE_MAX);
  std::vector<std::size_t> face_first;
  for (std::size_t h = 0; h < nh; ++h) {
    if (face[h] != SIZE_MAX) continue;
    const std::size_t f = face_first.size();
    face_first.push_back(h);
    std::size_t g = h;
    do {
      face[g] = f;
      g = clockwise_of(g ^ 1);
    } while (g != h);
  }

  // 5. Winding numbers of both operands in every face: across each component from its outer
  // face, whose winding is that of its leftmost vertex against the other components' edges.
  const std::size_t nf = face_first.size();
  std::vector<std::size_t> comp(nv, SIZE_MAX);
  std::vector<int> wind(2 * nf, 0);
  std::vector<char> face_done(nf, 0);
  std::vector<std::size_t> stack, comp_edges;
  const auto delta = [&](std::size_t h, int k) {
    const int w = frags[h / 2].w[k];
    return (h & 1) ? -w : w;
  };
  // Horizontal strips of edges (each edge in every strip its y-range meets), so that the
  // ray from a component's leftmost vertex visits only the edges at its height.
  i64 strip_y0 = verts[0].y, strip_y1 = verts[0].y;
  for (const Pt& v : verts) {
    strip_y0 = std::min(strip_y0, v.y);
    strip_y1 = std::max(strip_y1, v.y);
  }
  i64 strip_h = 1;
  std::vector<std::size_t> strip_start, strip_edges;
  for (std::size_t nstrips = std::max<std::size_t>(1, frags.size() / 2);; nstrips /= 4) {
    const i64 span = strip_y1 - strip_y0 + 1, n = static_cast<i64>(nstrips);
    strip_h = std::max<i64>(1, (span + n - 1) / n);
    const std::size_t count = static_cast<std::size_t>((strip_y1 - strip_y0) / strip_h + 1);
    const auto strip_of = [&](i64 y) { return static_cast<std::size_t>((y - strip_y0) / strip_h); };
    std::size_t entries = 0;
    for (const Frag& f : frags)
      entries += strip_of(std::max(f.u.y, f.v.y)) - strip_of(std::min(f.u.y, f.v.y)) + 1;
    if (entries > 16 * frags.size() + 64 && nstrips > 1) continue;  // long edges: coarser
    strip_start.assign(count + 1, 0);
    for (const Frag& f : frags)
      for (std::size_t k = strip_of(std::min(f.u.y, f.v.y)); k <= strip_of(std::max(f.u.y, f.v.y));
           ++k)
        ++strip_start[k + 1];
    for (std::size_t k = 0; k < count; ++k) strip_start[k + 1] += strip_start[k];
    strip_edges.resize(entries);
    std::vector<std::size_t> fill(strip_start.begin(), strip_start.end() - 1);
    for (std::size_t e = 0; e < frags.size(); ++e)
      for (std::size_t k = strip_of(std::min(frags[e].u.y, frags[e].v.y));
           k <= strip_of(std::max(frags[e].u.y, frags[e].v.y)); ++k)
        strip_edges[fill[k]++] = e;
    break;
  }
  std::size_t ncomp = 0;
  for (std::size_t v0 = 0; v0 < nv; ++v0) {
    if (comp[v0] != SIZE_MAX) continue;
    // Vertices of v0's component (v0 is its leftmost-lowest: vertices are sorted).
    const std::size_t c = ncomp++;
    comp[v0] = c;
    stack.assign(1, v0);
    while (!stack.empty()) {
      const std::size_t v = stack.back();
      stack.pop_back();
      for (std::size_t k = start[v]; k < start[v + 1]; ++k) {
        const std::size_t w = dest(rot[k]);
        if (comp[w] == SIZE_MAX) {
          comp[w] = c;
          stack.push_back(w);
        }
      }
    }
    // Outer face: left of the most counter-clockwise edge out of v0.
    std::size_t top = rot[start[v0]];
    for (std::size_t k = start[v0]; k < start[v0 + 1]; ++k) {
      const Pt a = direction(top), b = direction(rot[k]);
      if (cross(a.x, a.y, b.x, b.y) > 0) top = rot[k];
    }
    const Pt p = verts[v0];
    int w0[2] = {0, 0};
    const std::size_t strip = static_cast<std::size_t>((p.y - strip_y0) / strip_h);
    for (std::size_t k = strip_start[strip]; k < strip_start[strip + 1]; ++k) {
      const std::size_t e = strip_edges[k];
      if (comp[origin[2 * e]] == c) continue;
      const Pt a = frags[e].u, b = frags[e].v;
      int s = 0;
      if (a.y <= p.y && p.y < b.y && orient(a, b, p) > 0) s = 1;
      if (b.y <= p.y && p.y < a.y && orient(a, b, p) < 0) s = -1;
      w0[0] += s * frags[e].w[0];
      w0[1] += s * frags[e].w[1];
    }
    const std::size_t f0 = face[top];
    wind[2 * f0] = w0[0];
    wind[2 * f0 + 1] = w0[1];
    face_done[f0] = 1;
    stack.assign(1, f0);
    while (!stack.empty()) {
      const std::size_t f = stack.back();
      stack.pop_back();
      std::size_t g = face_first[f];
      do {
        const std::size_t other = face[g ^ 1];
        if (!face_done[other]) {
          face_done[other] = 1;
          wind[2 * other] = wind[2 * f] - delta(g, 0);
          wind[2 * other + 1] = wind[2 * f + 1] - delta(g, 1);
          stack.push_back(other);
        }
        g = clockwise_of(g ^ 1);
      } while (g != face_first[f]);
    }
  }
  const auto face_inside = [&](std::size_t f) {
    return apply_op(op, inside_by_rule(wind[2 * f], rule[0]),
                    inside_by_rule(wind[2 * f + 1], rule[1]));
  };

  // 6. Result half-edges (inside on their left) walked into rings.
  std::vector<char> is_result(nh, 0);
  std::vector<int> degree(nv, 0);
  for (std::size_t e = 0; e < frags.size(); ++e) {
    const bool l = face_inside(face[2 * e]), r = face_inside(face[2 * e + 1]);
    if (l == r) continue;
    is_result[l ? 2 * e : 2 * e + 1] = 1;
    ++degree[origin[2 * e]];
    ++degree[origin[2 * e + 1]];
  }
  std::vector<char> used(nh, 0);
  std::vector<std::vector<Pt>> outers, holes;
  std::vector<std::size_t> walk, at(nv, SIZE_MAX);
  const auto emit = [&](std::vector<std::size_t>::const_iterator b,
                        std::vector<std::size_t>::const_iterator e) {
    const std::size_t n = static_cast<std::size_t>(e - b);
    std::vector<Pt> ring;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t v = b[static_cast<std::ptrdiff_t>(i)];
      const Pt p = verts[v], prev = verts[b[static_cast<std::ptrdiff_t>((i + n - 1) % n)]],
               next = verts[b[static_cast<std::ptrdiff_t>((i + 1) % n)]];
      if (degree[v] == 2 && orient(prev, p, next) == 0) continue;
      ring.push_back(p);
    }
    if (ring.size() < 3) {
      error = "internal: a result ring degenerated";
      return;
    }
    // Canonical start: the lowest-leftmost vertex (x, then y) first.
    std::rotate(ring.begin(), std::min_element(ring.begin(), ring.end()), ring.end());
    (twice_area(ring) > 0 ? outers : holes).push_back(std::move(ring));
  };
  for (std::size_t h0 = 0; h0 < nh; ++h0) {
    if (!is_result[h0] || used[h0]) continue;
    walk.clear();
    std::size_t h = h0;
    do {
      if (used[h]) {
        error = "internal: result edges do not form rings";
        return false;
      }
      used[h] = 1;
      const std::size_t v = origin[h];
      if (at[v] != SIZE_MAX) {
        // The walk came back to v: the loop since then is a ring of its own.
        const std::size_t k = at[v];
        for (std::size_t i = k; i < walk.size(); ++i) at[walk[i]] = SIZE_MAX;
        emit(walk.begin() + static_cast<std::ptrdiff_t>(k), walk.end());
        walk.resize(k);
      }
      at[v] = walk.size();
      walk.push_back(v);
      std::size_t g = h ^ 1;
      const std::size_t around = start[dest(h) + 1] - start[dest(h)];
      for (std::size_t step = 0; step < around; ++step) {
        g = clockwise_of(g);
        if (is_result[g]) break;
      }
      if (!is_result[g]) {
        error = "internal: a result vertex without an outgoing edge";
        return false;
      }
      h = g;
    } while (h != h0);
    for (std::size_t v : walk) at[v] = SIZE_MAX;
    emit(walk.begin(), walk.end());
    if (!error.empty()) return false;
  }
  if (!error.empty()) return false;

  // 7. Each hole goes to the smallest outer ring containing its first edge's midpoint. Rings
  // are listed by their first vertex, so the output does not depend on edge numbering.
  const auto by_first = [](const std::vector<Pt>& p, const std::vector<Pt>& q) {
    return p[0] < q[0] || (p[0] == q[0] && p[1] < q[1]);
  };
  std::sort(outers.begin(), outers.end(), by_first);
  std::sort(holes.begin(), holes.end(), by_first);
  std::vector<i128> area(outers.size());
  std::vector<std::array<i64, 4>> box(outers.size());
  for (std::size_t i = 0; i < outers.size(); ++i) {
    area[i] = twice_area(outers[i]);
    box[i] = {2 * outers[i][0].x, 2 * outers[i][0].y, 2 * outers[i][0].x, 2 * outers[i][0].y};
    for (const Pt& q : outers[i])
      box[i] = {std::min(box[i][0], 2 * q.x), std::min(box[i][1], 2 * q.y),
                std::max(box[i][2], 2 * q.x), std::max(box[i][3], 2 * q.y)};
  }
  result.resize(outers.size());
  for (std::size_t i = 0; i < outers.size(); ++i) result[i].outer = std::move(outers[i]);
  for (auto& hole : holes) {
    const Pt m{hole[0].x + hole[1].x, hole[0].y + hole[1].y};
    std::size_t best = SIZE_MAX;
    for (std::size_t i = 0; i < result.size(); ++i) {
      if (best != SIZE_MAX && area[i] >= area[best]) continue;
      const auto& b = box[i];  // doubled coordinates, like m
      if (m.x < b[0] || m.x > b[2] || m.y < b[1] || m.y > b[3]) continue;
      if (ring_contains_doubled(result[i].outer, m)) best = i;
    }
    if (best == SIZE_MAX) {
      error = "internal: a hole outside every outer ring";
      return false;
    }
    result[best].holes.push_back(std::move(hole));
  }
  return true;
}

template <Real T>
bool all_finite(std::span<const Polygon2<T>> rings, double& max_abs) {
  for (const auto& r : rings)
    for (const auto& p : r.vertices) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
      max_abs = std::max(
          {max_abs, std::abs(static_cast<double>(p.x)), std::abs(static_cast<double>(p.y))});
    }
  return true;
}

/// Shared driver: rings[k] with roles[k] of operand operand_of[k].
template <Real T>
BooleanResult<T> run_boolean(BooleanOp op, FillRule rule0, FillRule rule1,
                             std::span<const Polygon2<T>> rings, std::span<const int> operand_of,
                             std::span<const Role> roles, int grid_bits) {
  BooleanResult<T> out;
  constexpr bool is_float = std::is_same_v<T, float>;
  const int bits = grid_bits == 0 ? (is_float ? 24 : 40) : grid_bits;
  if (bits < 1 || bits > (is_float ? 24 : 40)) {
    out.status = Status::invalid_input;
    out.message = "grid_bits must be in 1..40 (1..24 for float)";
    return out;
  }
  double max_abs = 0;
  if (!all_finite<T>(rings, max_abs)) {
    out.status = Status::non_finite_input;
    out.message = "a coordinate is NaN or infinite";
    return out;
  }
  if (max_abs == 0) return out;
  int e = 0;
  (void)std::frexp(max_abs, &e);  // max_abs < 2^e
  const int min_exp = is_float ? -149 : -1074;
  const int ge = std::max(e - bits, min_exp);
  out.grid = std::ldexp(1.0, ge);
  Engine engine;
  engine.op = op;
  engine.rule[0] = rule0;
  engine.rule[1] = rule1;
  for (std::size_t k = 0; k < rings.size(); ++k) {
    Ring r{{}, operand_of[k], roles[k]};
    // Pixel units (an exact power-of-two scaling), rounded to multiples of 2^-60 of a pixel so
    // that the exact predicates stay in range (products of four coordinates above 2^-969).
    const auto unit = [&](T v) {
      return std::ldexp(std::nearbyint(std::ldexp(static_cast<double>(v), 60 - ge)), -60);
    };
    for (const auto& p : rings[k].vertices) r.pts.push_back({unit(p.x), unit(p.y)});
    engine.rings.push_back(std::move(r));
  }
  if (!engine.run()) {
    out.status = Status::invalid_topology;
    out.message = engine.error;
    return out;
  }
  // A coordinate within half a pixel of the largest finite value can snap past it.
  bool overflow = false;
  const auto to_t = [&](i64 k) {
    const double v = std::ldexp(static_cast<double>(k), ge);
    if (!(std::abs(v) <= static_cast<double>(std::numeric_limits<T>::max()))) {
      overflow = true;
      return T(0);
    }
    return static_cast<T>(v);
  };
  const auto convert = [&](const std::vector<Pt>& r) {
    Polygon2<T> p;
    p.vertices.reserve(r.size());
    for (Pt q : r) p.vertices.push_back({to_t(q.x), to_t(q.y)});
    return p;
  };
  for (const auto& poly : engine.result) {
    PolygonWithHoles2<T> p{convert(poly.outer), {}};
    for (const auto& h : poly.holes) p.holes.push_back(convert(h));
    out.polygons.push_back(std::move(p));
  }
  if (overflow) {
    out.status = Status::invalid_input;
    out.message =
        "a vertex snapped beyond the largest finite value (coordinates within a pixel "
        "of it)";
    out.polygons.clear();
  }
  return out;
}

}  // namespace

template <Real T>
BooleanResult<T> boolean_op(BooleanOp op, std::span<const Polygon2<T>> subject,
                            std::span<const Polygon2<T>> clip, const BooleanOptions& options) {
  std::vector<Polygon2<T>> rings(subject.begin(), subject.end());
  rings.insert(rings.end(), clip.begin(), clip.end());
  std::vector<int> operand(rings.size(), 0);
  std::fill(operand.begin() + static_cast<std::ptrdiff_t>(subject.size()), operand.end(), 1);
  const std::vector<Role> roles(rings.size(), Role::raw);
  return run_boolean<T>(op, options.fill_rule, options.fill_rule, rings, operand, roles,
                        options.grid_bits);
}

template <Real T>
BooleanResult<T> boolean_op(BooleanOp op, const MultiPolygon2<T>& a, const MultiPolygon2<T>& b,
                            int grid_bits) {
  std::vector<Polygon2<T>> rings;
  std::vector<int> operand;
  std::vector<Role> roles;
  int k = 0;
  for (const MultiPolygon2<T>* m : {&a, &b}) {
    for (const auto& p : *m) {
      rings.push_back(p.outer);
      operand.push_back(k);
      roles.push_back(Role::outer);
      for (const auto& h : p.holes) {
        rings.push_back(h);
        operand.push_back(k);
        roles.push_back(Role::hole);
      }
    }
    ++k;
  }
  return run_boolean<T>(op, FillRule::positive, FillRule::positive, rings, operand, roles,
                        grid_bits);
}

#define LOCUS_INSTANTIATE(T)                                                                    \
  template BooleanResult<T> boolean_op<T>(BooleanOp, std::span<const Polygon2<T>>,              \
                                          std::span<const Polygon2<T>>, const BooleanOptions&); \
  template BooleanResult<T> boolean_op<T>(BooleanOp, const MultiPolygon2<T>&,                   \
                                          const MultiPolygon2<T>&, int);
LOCUS_INSTANTIATE(float)
LOCUS_INSTANTIATE(double)
#undef LOCUS_INSTANTIATE

}  // namespace locus
