// SPDX-License-Identifier: BSL-1.0
// Polygon booleans by snap rounding (include/locus/boolean/polygon_boolean.hpp,
// docs/notes/boolean.md). Every coordinate is an integer of at most 40 bits (the grid of the
// header), so orientations fit in 84 bits and a crossing's rounded pixel in 126: all decisions are
// exact in 128-bit integers.

#include <locus/boolean/polygon_boolean.hpp>

#include <algorithm>
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
/// floor(a / b) for b > 0.
i128 floor_div(i128 a, i128 b) {
  i128 q = a / b;
  if (a % b != 0 && a < 0) --q;
  return q;
}

enum class Role : std::uint8_t { raw, outer, hole };
struct Ring {
  std::vector<Pt> pts;
  int operand;
  Role role;
};

struct Seg {
  Pt a, b;  // directed as in its ring
  int operand;
  i64 xmin, xmax, ymin, ymax;
};

/// A rational bound num / den (den > 0) on a segment parameter, open or closed.
struct Bound {
  i128 num, den;
  bool open;
};
int compare(const Bound& p, const Bound& q) { return sign(p.num * q.den - q.num * p.den); }

/// The parameter interval of a -> b (doubled coordinates) inside the half-open pixel of h, as
/// its lower bound; false when they are disjoint.
bool pixel_entry(Pt a, Pt b, Pt h, Bound& entry) {
  Bound lo{0, 1, false}, hi{1, 1, false};
  const auto constrain = [&](i64 a2, i64 d2, i64 c) {
    // 2c - 1 <= a2 + t d2 < 2c + 1
    const i128 l = static_cast<i128>(2) * c - 1 - a2, r = static_cast<i128>(2) * c + 1 - a2;
    if (d2 == 0) return l <= 0 && 0 < r;
    if (d2 > 0) {
      const Bound nl{l, d2, false}, nh{r, d2, true};
      const int cl = compare(nl, lo), ch = compare(nh, hi);
      if (cl > 0) lo = nl;
      if (ch < 0 || (ch == 0 && nh.open)) hi = nh;
    } else {
      const Bound nh{-l, -static_cast<i128>(d2), false}, nl{-r, -static_cast<i128>(d2), true};
      const int cl = compare(nl, lo), ch = compare(nh, hi);
      if (cl > 0 || (cl == 0 && nl.open)) lo = nl;
      if (ch < 0) hi = nh;
    }
    return true;
  };
  if (!constrain(2 * a.x, 2 * (b.x - a.x), h.x)) return false;
  if (!constrain(2 * a.y, 2 * (b.y - a.y), h.y)) return false;
  const int c = compare(lo, hi);
  if (c > 0 || (c == 0 && (lo.open || hi.open))) return false;
  entry = lo;
  return true;
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

  /// Visits (a superset of) the hot pixels whose closed square meets segment ab, each once.
  template <class F>
  void along(Pt a, Pt b, F&& f) const {
    const i64 xmin = std::min(a.x, b.x), xmax = std::max(a.x, b.x);
    const i64 ymin = std::min(a.y, b.y), ymax = std::max(a.y, b.y);
    if (xmax < x0_ || ymax < y0_) return;
    const std::size_t c0 = column(std::max(xmin, x0_)), c1 = column(xmax);
    const double dx = static_cast<double>(b.x - a.x), dy = static_cast<double>(b.y - a.y);
    for (std::size_t i = c0; i <= c1 && i < nx_; ++i) {
      const i64 xl = std::max(xmin, x0_ + static_cast<i64>(i) * cx_);
      const i64 xr = std::min(xmax, x0_ + static_cast<i64>(i + 1) * cx_ - 1);
      double ylo = static_cast<double>(ymin), yhi = static_cast<double>(ymax);
      if (dx != 0) {
        // y along the segment over [xl - 1/2, xr + 1/2], widened by a pixel: the rounding
        // error of this double evaluation (below 2^-10 for 40-bit coordinates) cannot matter.
        const double ya =
            static_cast<double>(a.y) + (static_cast<double>(xl - a.x) - 0.5) * dy / dx;
        const double yb =
            static_cast<double>(a.y) + (static_cast<double>(xr - a.x) + 0.5) * dy / dx;
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
  // 1. Directed edges of every ring, orientations normalised by role.
  std::vector<Seg> segs;
  for (Ring& r : rings) {
    std::vector<Pt> pts;
    for (Pt p : r.pts)
      if (pts.empty() || pts.back() != p) pts.push_back(p);
    while (pts.size() > 1 && pts.back() == pts.front()) pts.pop_back();
    if (pts.size() < 2) continue;
    if (r.role != Role::raw) {
      const int s = sign(twice_area(pts));
      if (s == 0) continue;
      if ((r.role == Role::outer) != (s > 0)) std::reverse(pts.begin(), pts.end());
    }
    for (std::size_t i = 0, n = pts.size(); i < n; ++i) {
      const Pt a = pts[i], b = pts[(i + 1) % n];
      segs.push_back({a, b, r.operand, std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y),
                      std::max(a.y, b.y)});
    }
  }
  if (segs.empty()) return true;

  // 2. Hot pixels: every vertex, and the pixel of every proper crossing (x-sorted sweep).
  std::vector<Pt> hot;
  hot.reserve(2 * segs.size());
  for (const Seg& s : segs) {
    hot.push_back(s.a);
    hot.push_back(s.b);
  }
  std::vector<std::size_t> order(segs.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t i, std::size_t j) { return segs[i].xmin < segs[j].xmin; });
  std::vector<std::size_t> active;
  for (std::size_t i : order) {
    const Seg& s = segs[i];
    std::size_t keep = 0;
    for (std::size_t j : active)
      if (segs[j].xmax >= s.xmin) active[keep++] = j;
    active.resize(keep);
    for (std::size_t j : active) {
      const Seg& t = segs[j];
      if (t.ymax < s.ymin || s.ymax < t.ymin) continue;
      const i128 oc = orient(s.a, s.b, t.a), od = orient(s.a, s.b, t.b);
      if (oc == 0 || od == 0 || (oc > 0) == (od > 0)) continue;  // apart, touching or collinear
      i128 oa = orient(t.a, t.b, s.a), ob = orient(t.a, t.b, s.b);
      if (oa == 0 || ob == 0 || (oa > 0) == (ob > 0)) continue;
      // s.a + t (s.b - s.a), t = oa / (oa - ob), rounded half up to its pixel.
      i128 den = oa - ob;
      if (den < 0) {
        den = -den;
        oa = -oa;
      }
      const i128 dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
      hot.push_back({s.a.x + static_cast<i64>(floor_div(2 * oa * dx + den, 2 * den)),
                     s.a.y + static_cast<i64>(floor_div(2 * oa * dy + den, 2 * den))});
    }
    active.push_back(i);
  }
  std::sort(hot.begin(), hot.end());
  hot.erase(std::unique(hot.begin(), hot.end()), hot.end());

  // 3. Route every segment through the centres of the hot pixels it meets, in order.
  const HotGrid grid(hot);
  std::vector<Frag> frags;
  std::vector<std::pair<Bound, Pt>> route;
  for (const Seg& s : segs) {
    route.clear();
    grid.along(s.a, s.b, [&](Pt h) {
      Bound e;
      if (pixel_entry(s.a, s.b, h, e)) route.emplace_back(e, h);
    });
    std::sort(route.begin(), route.end(), [](const auto& p, const auto& q) {
      const int c = compare(p.first, q.first);
      return c < 0 || (c == 0 && !p.first.open && q.first.open);
    });
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
      grid.along(f.u, f.v, [&](Pt h) {
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
  for (std::size_t e = 0; e < frags.size(); ++e) {
    origin[2 * e] = vid(frags[e].u);
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
    for (std::size_t e = 0; e < frags.size(); ++e) {
      const std::size_t cu = comp[origin[2 * e]];
      if (cu == c) continue;
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

  // 7. Each hole goes to the smallest outer ring containing its first edge's midpoint.
  std::vector<i128> area(outers.size());
  for (std::size_t i = 0; i < outers.size(); ++i) area[i] = twice_area(outers[i]);
  result.resize(outers.size());
  for (std::size_t i = 0; i < outers.size(); ++i) result[i].outer = std::move(outers[i]);
  for (auto& hole : holes) {
    const Pt m{hole[0].x + hole[1].x, hole[0].y + hole[1].y};
    std::size_t best = SIZE_MAX;
    for (std::size_t i = 0; i < result.size(); ++i) {
      if (best != SIZE_MAX && area[i] >= area[best]) continue;
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
    for (const auto& p : rings[k].vertices)
      r.pts.push_back(
          {static_cast<i64>(std::nearbyint(std::ldexp(static_cast<double>(p.x), -ge))),
           static_cast<i64>(std::nearbyint(std::ldexp(static_cast<double>(p.y), -ge)))});
    engine.rings.push_back(std::move(r));
  }
  if (!engine.run()) {
    out.status = Status::invalid_topology;
    out.message = engine.error;
    return out;
  }
  const auto convert = [&](const std::vector<Pt>& r) {
    Polygon2<T> p;
    p.vertices.reserve(r.size());
    for (Pt q : r)
      p.vertices.push_back({static_cast<T>(std::ldexp(static_cast<double>(q.x), ge)),
                            static_cast<T>(std::ldexp(static_cast<double>(q.y), ge))});
    return p;
  };
  for (const auto& poly : engine.result) {
    PolygonWithHoles2<T> p{convert(poly.outer), {}};
    for (const auto& h : poly.holes) p.holes.push_back(convert(h));
    out.polygons.push_back(std::move(p));
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
