// SPDX-License-Identifier: BSL-1.0
// Ear clipping with holes (see include/locus/triangulate/ear_clipping.hpp and
// docs/notes/triangulate.md).

#include <locus/triangulate/ear_clipping.hpp>

#include <locus/core/predicates.hpp>

#include "rings.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace locus {

using triangulate_detail::same_point;
using triangulate_detail::strictly_between;

template <Real T>
struct EarClipRun {
  using Node = typename EarClipping2<T>::Node;
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;

  std::span<const Vec2<T>> pts;
  PolygonTriangulation& out;
  std::vector<Node>& nodes;
  std::vector<std::uint32_t>& late;  // reflex vertices that were convex when the grid was built
  std::vector<std::uint32_t>& cell_start;
  std::vector<std::uint32_t>& cell_count;  // live entries at the front of each cell
  std::vector<GridEntry<T>>& cell_items;
  std::vector<std::uint32_t>& grid_pos;  // per node: its slot in cell_items, or kNone
  double min_x = 0, min_y = 0, inv_x = 0, inv_y = 0;
  std::uint32_t gx = 1, gy = 1;

  const Vec2<T>& at(std::uint32_t n) const { return pts[nodes[n].index]; }

  std::uint32_t add_node(std::uint32_t index) {
    nodes.push_back(Node{index, kNone, kNone, 0, 0});
    return static_cast<std::uint32_t>(nodes.size() - 1);
  }

  // The nearest ring neighbours at a different point (bridges and pinches make zero-length
  // edges; the cone of a copy is the one its true neighbours span).
  std::uint32_t distinct_prev(std::uint32_t a) const {
    std::uint32_t p = nodes[a].prev;
    for (std::uint32_t k = 0; k < 64 && p != a && same_point(at(p), at(a)); ++k) p = nodes[p].prev;
    return p;
  }
  std::uint32_t distinct_next(std::uint32_t a) const {
    std::uint32_t n = nodes[a].next;
    for (std::uint32_t k = 0; k < 64 && n != a && same_point(at(n), at(a)); ++k) n = nodes[n].next;
    return n;
  }

  // Strictly inside the cone of node a (interior on the left of prev -> a -> next).
  bool locally_inside(std::uint32_t a, const Vec2<T>& q) const {
    const Vec2<T>& p0 = at(distinct_prev(a));
    const Vec2<T>& p1 = at(a);
    const Vec2<T>& p2 = at(distinct_next(a));
    const bool l0 = orient2d(p0, p1, q) == Sign::positive;
    const bool l1 = orient2d(p1, p2, q) == Sign::positive;
    return orient2d(p0, p1, p2) != Sign::negative ? (l0 && l1) : (l0 || l1);
  }

  // Whether edge ab blocks the open segment mp: a proper crossing, or a or b on it.
  static bool blocks(const Vec2<T>& m, const Vec2<T>& p, const Vec2<T>& a, const Vec2<T>& b) {
    const Sign o1 = orient2d(m, p, a);
    const Sign o2 = orient2d(m, p, b);
    if (o1 == Sign::zero && strictly_between(m, a, p)) return true;
    if (o2 == Sign::zero && strictly_between(m, b, p)) return true;
    if (o1 == Sign::zero || o2 == Sign::zero || o1 == o2) return false;
    const Sign o3 = orient2d(a, b, m);
    const Sign o4 = orient2d(a, b, p);
    return o3 != Sign::zero && o4 != Sign::zero && o3 != o4;
  }

  static bool proper_cross(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& c, const Vec2<T>& d) {
    const Sign o1 = orient2d(a, b, c), o2 = orient2d(a, b, d);
    const Sign o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
    return o1 != Sign::zero && o2 != Sign::zero && o1 != o2 && o3 != Sign::zero &&
           o4 != Sign::zero && o3 != o4;
  }

  // The bridge index: every ring edge (a pair of nodes, fixed geometry) and every vertex in a
  // uniform grid of linked cells, so the bridge searches look only near the hole. Bridges and
  // the vertex copies they make are added as they are made. ring_of: a node's input ring (0 for
  // the copies, which belong to the joined ring); joined: rings already part of ring 0.
  double bmin_x = 0, bmin_y = 0, binv_x = 0, binv_y = 0;
  std::uint32_t bgx = 1, bgy = 1;
  std::vector<std::uint32_t> edge_head = {}, edge_link = {}, vert_head = {}, vert_link = {},
                             vert_node = {}, ring_of = {};
  std::vector<std::array<std::uint32_t, 2>> edge_nodes = {};
  std::vector<std::uint8_t> joined = {};

  std::uint32_t bcell_x(T x) const { return bcell_xd(double(x)); }
  std::uint32_t bcell_xd(double x) const {
    const double c = (x * 0.5 - bmin_x) * binv_x;
    return c >= 1.0 ? std::min(bgx - 1, static_cast<std::uint32_t>(c)) : 0u;
  }
  std::uint32_t bcell_y(T y) const {
    const double c = (double(y) * 0.5 - bmin_y) * binv_y;
    return c >= 1.0 ? std::min(bgy - 1, static_cast<std::uint32_t>(c)) : 0u;
  }

  void index_edge(std::uint32_t from, std::uint32_t to) {
    const Vec2<T>&a = at(from), &b = at(to);
    const std::uint32_t item = static_cast<std::uint32_t>(edge_nodes.size());
    edge_nodes.push_back({from, to});
    edge_link.push_back(kNone);
    bool first = true;
    for (std::uint32_t y = bcell_y(std::min(a.y, b.y)), y1 = bcell_y(std::max(a.y, b.y)); y <= y1;
         ++y)
      for (std::uint32_t x = bcell_x(std::min(a.x, b.x)), x1 = bcell_x(std::max(a.x, b.x)); x <= x1;
           ++x) {
        // One item per edge and cell: cells after the first get their own link entries.
        std::uint32_t slot = item;
        if (!first) {
          slot = static_cast<std::uint32_t>(edge_nodes.size());
          edge_nodes.push_back({from, to});
          edge_link.push_back(kNone);
        }
        first = false;
        const std::size_t c = std::size_t(y) * bgx + x;
        edge_link[slot] = edge_head[c];
        edge_head[c] = slot;
      }
  }

  void index_vertex(std::uint32_t n) {
    const std::size_t c = std::size_t(bcell_y(at(n).y)) * bgx + bcell_x(at(n).x);
    vert_node.push_back(n);
    vert_link.push_back(vert_head[c]);
    vert_head[c] = static_cast<std::uint32_t>(vert_node.size() - 1);
  }

  // Builds the bridge index over the rings (nodes 0 .. ring_ends.back()).
  void build_bridge_index(std::span<const std::uint32_t> ring_ends) {
    const std::uint32_t n = static_cast<std::uint32_t>(nodes.size());
    double lx = std::numeric_limits<double>::infinity(), ly = lx, hx = -lx, hy = -lx;
    for (std::uint32_t v = 0; v < n; ++v) {
      const Vec2<T>& p = at(v);
      lx = std::min(lx, double(p.x) * 0.5);
      hx = std::max(hx, double(p.x) * 0.5);
      ly = std::min(ly, double(p.y) * 0.5);
      hy = std::max(hy, double(p.y) * 0.5);
    }
    const double w = hx - lx, h = hy - ly;
    const double cells = std::max(1.0, double(n) * 0.5);
    double fx = w > 0 && h > 0 ? std::sqrt(cells * w / h) : (w > 0 ? cells : 1.0);
    fx = std::clamp(fx, 1.0, 2048.0);
    const double fy = std::clamp(h > 0 ? cells / fx : 1.0, 1.0, 2048.0);
    bmin_x = lx;
    bmin_y = ly;
    bgx = static_cast<std::uint32_t>(fx);
    bgy = static_cast<std::uint32_t>(fy);
    // Long edges would fill many cells: coarsen until the edges cover at most ~8 n cells.
    for (;;) {
      binv_x = w > 0 ? double(bgx) / w : 0.0;
      binv_y = h > 0 ? double(bgy) / h : 0.0;
      if (!std::isfinite(binv_x)) binv_x = 0.0, bgx = 1;
      if (!std::isfinite(binv_y)) binv_y = 0.0, bgy = 1;
      double covered = 0;
      for (std::uint32_t v = 0; v < n; ++v) {
        const Vec2<T>&a = at(v), &b = at(nodes[v].next);
        covered += double(bcell_x(std::max(a.x, b.x)) - bcell_x(std::min(a.x, b.x)) + 1) *
                   double(bcell_y(std::max(a.y, b.y)) - bcell_y(std::min(a.y, b.y)) + 1);
      }
      if (covered <= 8.0 * n + 64 || (bgx == 1 && bgy == 1)) break;
      bgx = std::max(1u, bgx / 2);
      bgy = std::max(1u, bgy / 2);
    }
    edge_head.assign(std::size_t(bgx) * bgy, kNone);
    vert_head.assign(std::size_t(bgx) * bgy, kNone);
    edge_nodes.clear();
    edge_link.clear();
    vert_node.clear();
    vert_link.clear();
    ring_of.assign(n, 0);
    joined.assign(ring_ends.size(), 0);
    joined[0] = 1;
    std::uint32_t begin = 0;
    for (std::uint32_t r = 0; r < ring_ends.size(); ++r) {
      for (std::uint32_t v = begin; v < ring_ends[r]; ++v) ring_of[v] = r;
      begin = ring_ends[r];
    }
    for (std::uint32_t v = 0; v < n; ++v) {
      index_edge(v, nodes[v].next);
      index_vertex(v);
    }
  }

  bool in_joined_ring(std::uint32_t v) const { return v >= ring_of.size() || joined[ring_of[v]]; }

  // The exact bridge test: the segment from outer node p to hole node m leaves both cones
  // inward and no edge of any ring blocks it.
  bool bridge_visible(std::uint32_t p, std::uint32_t m) const {
    const Vec2<T>& pm = at(m);
    const Vec2<T>& pp = at(p);
    if (same_point(pm, pp))
      return locally_inside(p, at(nodes[m].prev)) && locally_inside(p, at(nodes[m].next));
    if (!locally_inside(p, pm) || !locally_inside(m, pp)) return false;
    const T lo_x = std::min(pm.x, pp.x), hi_x = std::max(pm.x, pp.x);
    const T lo_y = std::min(pm.y, pp.y), hi_y = std::max(pm.y, pp.y);
    for (std::uint32_t y = bcell_y(lo_y), y1 = bcell_y(hi_y); y <= y1; ++y)
      for (std::uint32_t x = bcell_x(lo_x), x1 = bcell_x(hi_x); x <= x1; ++x)
        for (std::uint32_t i = edge_head[std::size_t(y) * bgx + x]; i != kNone; i = edge_link[i]) {
          const Vec2<T>& a = at(edge_nodes[i][0]);
          const Vec2<T>& b = at(edge_nodes[i][1]);
          if (std::max(a.x, b.x) < lo_x || std::min(a.x, b.x) > hi_x || std::max(a.y, b.y) < lo_y ||
              std::min(a.y, b.y) > hi_y)
            continue;
          if (blocks(pm, pp, a, b)) return false;
        }
    return true;
  }

  // Eberly's candidate: the nearest edge hit by the ray from m towards -x, then the visible
  // vertex of smallest angle in the triangle it spans (rounded arithmetic: a guess only).
  std::uint32_t bridge_candidate(std::uint32_t m) const {
    const Vec2<T>& h = at(m);
    const double hx = double(h.x), hy = double(h.y);
    double qx = -std::numeric_limits<double>::infinity();
    std::uint32_t cand = kNone;
    // The ray runs left along one row of cells; an edge it meets at x is in the cell of x (the
    // cell map is monotone), so the walk stops once the best hit lies right of the cell just
    // seen (a cell of margin against the rounding of the hit).
    const std::size_t row = std::size_t(bcell_y(h.y)) * bgx;
    for (std::uint32_t k = bcell_x(h.x) + 1; k-- > 0;) {
      for (std::uint32_t i = edge_head[row + k]; i != kNone; i = edge_link[i]) {
        const std::uint32_t p = edge_nodes[i][0], pn = edge_nodes[i][1];
        if (!in_joined_ring(p)) continue;
        const Vec2<T>& a = at(p);
        const Vec2<T>& b = at(pn);
        if (h.y <= a.y && h.y >= b.y && a.y != b.y) {
          // The slope first: a product of two differences would leave the exponent range.
          const double slope = (double(b.x) - double(a.x)) / (double(b.y) - double(a.y));
          const double x = double(a.x) + (hy - double(a.y)) * slope;
          if (x <= hx && (x > qx || (x == qx && p < cand))) {
            qx = x;
            cand = a.x < b.x ? p : pn;
          }
        }
      }
      if (cand != kNone && bcell_xd(qx) > k) break;
    }
    if (cand == kNone) return kNone;
    const Vec2<T> cm = at(cand);
    const Vec2<double> hd{hx, hy}, qd{qx, hy}, md{double(cm.x), double(cm.y)};
    const Vec2<double> t0 = hy < md.y ? hd : qd, t2 = hy < md.y ? qd : hd;
    double tan_min = std::numeric_limits<double>::infinity();
    std::uint32_t best = cand;
    // The candidate is tried first: among coincident vertices (touching rings) it wins ties.
    const auto consider = [&](std::uint32_t p) {
      const Vec2<T>& q = at(p);
      if (!(h.x >= q.x && q.x >= cm.x && h.x != q.x)) return;
      const Vec2<double> qd2{double(q.x), double(q.y)};
      if (orient2d(t0, md, qd2) != Sign::negative && orient2d(md, t2, qd2) != Sign::negative &&
          orient2d(t2, t0, qd2) != Sign::negative) {
        const double t = std::abs(hy - qd2.y) / (hx - qd2.x);
        if (locally_inside(p, h) && (t < tan_min || (t == tan_min && q.x > at(best).x))) {
          best = p;
          tan_min = t;
        }
      }
    };
    consider(cand);
    const T lo_y = std::min(h.y, cm.y), hi_y = std::max(h.y, cm.y);
    for (std::uint32_t y = bcell_y(lo_y), y1 = bcell_y(hi_y); y <= y1; ++y)
      for (std::uint32_t x = bcell_x(cm.x), x1 = bcell_x(h.x); x <= x1; ++x)
        for (std::uint32_t i = vert_head[std::size_t(y) * bgx + x]; i != kNone; i = vert_link[i]) {
          const std::uint32_t p = vert_node[i];
          if (p != cand && in_joined_ring(p)) consider(p);
        }
    return best;
  }

  // The nearest vertex of the ring through outer that sees hole node m, or kNone.
  // The vertices of the joined ring in increasing (distance, node) order, found ring of cells by
  // ring of cells around m: after the cells within Chebyshev distance k are read, every vertex
  // not yet read is at least (k - 1) cells away (one cell of margin against the rounding of the
  // cell map), so the candidates nearer than that are final and are tested in order.
  std::uint32_t nearest_visible(std::uint32_t m) const {
    const Vec2<T>& h = at(m);
    const auto cx = static_cast<std::int64_t>(bcell_x(h.x));
    const auto cy = static_cast<std::int64_t>(bcell_y(h.y));
    const double inf = std::numeric_limits<double>::infinity();
    const double step = std::min(binv_x > 0 ? 2.0 / binv_x : inf, binv_y > 0 ? 2.0 / binv_y : inf);
    using Cand = std::pair<double, std::uint32_t>;
    std::priority_queue<Cand, std::vector<Cand>, std::greater<Cand>> heap;
    const auto scan = [&](std::int64_t x, std::int64_t y) {
      if (x < 0 || y < 0 || x >= std::int64_t(bgx) || y >= std::int64_t(bgy)) return;
      for (std::uint32_t i = vert_head[std::size_t(y) * bgx + std::size_t(x)]; i != kNone;
           i = vert_link[i]) {
        const std::uint32_t q = vert_node[i];
        if (!in_joined_ring(q)) continue;
        // hypot: no overflow or underflow, and exact under power-of-two scaling.
        heap.emplace(std::hypot(double(at(q).x) - double(h.x), double(at(q).y) - double(h.y)), q);
      }
    };
    const std::int64_t last = std::int64_t(std::max(bgx, bgy));
    for (std::int64_t k = 0;; ++k) {
      if (k == 0) {
        scan(cx, cy);
      } else if (k <= last) {
        for (std::int64_t d = -k; d <= k; ++d) {
          scan(cx + d, cy - k);
          scan(cx + d, cy + k);
        }
        for (std::int64_t d = -k + 1; d <= k - 1; ++d) {
          scan(cx - k, cy + d);
          scan(cx + k, cy + d);
        }
      }
      const double bound = k >= last ? inf : (double(k) - 1.0) * step;
      while (!heap.empty() && heap.top().first < bound) {
        const std::uint32_t q = heap.top().second;
        heap.pop();
        if (bridge_visible(q, m)) return q;
      }
      if (k >= last && heap.empty()) return kNone;
    }
  }

  // Joins the hole whose lexicographically smallest vertex is node m to the ring through outer:
  // Eberly's candidate if it passes the exact test, else the nearest visible vertex, else the
  // same from the hole's other vertices (a hole lying along the outer ring needs that).
  // Returns false when no bridge is valid; the hole is then joined by Eberly's candidate (or
  // the nearest vertex) anyway, the best effort on input that is not a polygon.
  bool bridge(std::uint32_t outer, std::uint32_t m) {
    const std::uint32_t guess = bridge_candidate(m);
    std::uint32_t p = guess;
    bool valid = true;
    if (p == kNone || !bridge_visible(p, m)) {
      p = kNone;
      const std::uint32_t first = m;
      do {
        p = nearest_visible(m);
        if (p != kNone) break;
        m = nodes[m].next;
      } while (m != first);
      if (p == kNone) {
        valid = false;
        m = first;
        p = guess != kNone ? guess : outer;
      }
    }
    // p -> m -> (the hole) -> m2 -> p2 -> old p.next
    const std::uint32_t m2 = add_node(nodes[m].index);
    const std::uint32_t p2 = add_node(nodes[p].index);
    const std::uint32_t pn = nodes[p].next, mp = nodes[m].prev;
    nodes[p].next = m;
    nodes[m].prev = p;
    nodes[p2].next = pn;
    nodes[pn].prev = p2;
    nodes[m2].next = p2;
    nodes[p2].prev = m2;
    nodes[mp].next = m2;
    nodes[m2].prev = mp;
    // The hole is now part of the joined ring; the bridge's two edges and copies join the index.
    joined[ring_of[m]] = 1;
    ring_of.resize(nodes.size(), 0);
    index_edge(p, m);
    index_edge(m2, p2);
    index_vertex(m2);
    index_vertex(p2);
    return valid;
  }

  bool convex(std::uint32_t v) const {
    return orient2d(at(nodes[v].prev), at(v), at(nodes[v].next)) == Sign::positive;
  }

  // Coordinates in cell units (cell k spans [k, k + 1)).
  double gx_of(T x) const { return (double(x) * 0.5 - min_x) * inv_x; }
  double gy_of(T y) const { return (double(y) * 0.5 - min_y) * inv_y; }

  std::uint32_t cell_x(T x) const {
    const double c = (double(x) * 0.5 - min_x) * inv_x;
    return c >= 1.0 ? std::min(gx - 1, static_cast<std::uint32_t>(c)) : 0u;
  }
  std::uint32_t cell_y(T y) const {
    const double c = (double(y) * 0.5 - min_y) * inv_y;
    return c >= 1.0 ? std::min(gy - 1, static_cast<std::uint32_t>(c)) : 0u;
  }

  std::size_t cell_of(const Vec2<T>& p) const {
    return std::size_t(cell_y(p.y)) * gx + cell_x(p.x);
  }

  // Drops node v from the grid (it was cut or turned convex): the cell's last live entry takes
  // its slot, so the ear tests only ever visit live reflex vertices.
  void grid_remove(std::uint32_t v) {
    if (v >= grid_pos.size() || grid_pos[v] == kNone) return;
    const std::size_t c = cell_of(at(v));
    const std::uint32_t last = cell_start[c] + --cell_count[c];
    const std::uint32_t slot = grid_pos[v];
    cell_items[slot] = cell_items[last];
    grid_pos[cell_items[slot].node] = slot;
    grid_pos[v] = kNone;
    // Should it turn reflex again (only on input that is not a polygon), it goes to `late`.
    if (v < in_grid.size()) in_grid[v] = 0;
  }

  void build_grid(std::uint32_t start) {
    double lx = std::numeric_limits<double>::infinity(), ly = lx, hx = -lx, hy = -lx;
    std::uint32_t reflex = 0, v = start;
    do {
      nodes[v].reflex = convex(v) ? 0 : 1;
      reflex += nodes[v].reflex;
      const Vec2<T>& p = at(v);
      lx = std::min(lx, double(p.x) * 0.5);
      hx = std::max(hx, double(p.x) * 0.5);
      ly = std::min(ly, double(p.y) * 0.5);
      hy = std::max(hy, double(p.y) * 0.5);
      v = nodes[v].next;
    } while (v != start);
    // About one reflex vertex per cell, the cells shaped like the bounding box. Coordinates are
    // halved so the extent cannot overflow; any monotone cell map is correct.
    const double w = hx - lx, h = hy - ly;
    const double cells = std::max(1.0, double(reflex));
    double fx = w > 0 && h > 0 ? std::sqrt(cells * w / h) : (w > 0 ? cells : 1.0);
    fx = std::clamp(fx, 1.0, 4096.0);
    const double fy = std::clamp(h > 0 ? cells / fx : 1.0, 1.0, 4096.0);
    gx = static_cast<std::uint32_t>(fx);
    gy = static_cast<std::uint32_t>(fy);
    min_x = lx;
    min_y = ly;
    inv_x = w > 0 ? double(gx) / w : 0.0;
    inv_y = h > 0 ? double(gy) / h : 0.0;
    // Rounding of the cell map must stay far below a cell (the row clipping widens by one);
    // coordinates huge against their extent get one column or row instead.
    const double big = std::max({std::abs(lx), std::abs(hx), std::abs(ly), std::abs(hy)});
    if (!std::isfinite(inv_x) || big * 0x1p-48 * inv_x > 0.125) {
      inv_x = 0.0;
      gx = 1;
    }
    if (!std::isfinite(inv_y) || big * 0x1p-48 * inv_y > 0.125) {
      inv_y = 0.0;
      gy = 1;
    }
    cell_start.assign(std::size_t(gx) * gy + 1, 0);
    v = start;
    do {
      if (nodes[v].reflex) ++cell_start[cell_of(at(v)) + 1];
      v = nodes[v].next;
    } while (v != start);
    for (std::size_t c = 1; c < cell_start.size(); ++c) cell_start[c] += cell_start[c - 1];
    cell_items.resize(reflex);
    cell_count.assign(std::size_t(gx) * gy, 0);
    grid_pos.assign(nodes.size(), kNone);
    v = start;
    do {
      if (nodes[v].reflex) {
        const std::size_t c = cell_of(at(v));
        const std::uint32_t slot = cell_start[c] + cell_count[c]++;
        cell_items[slot] = GridEntry<T>{at(v), v};
        grid_pos[v] = slot;
      }
      v = nodes[v].next;
    } while (v != start);
    // Nodes reflex now are in the grid; a node turning reflex later goes to `late`.
    late.clear();
  }

  // Whether reflex node n blocks the ear a, b, c (closed triangle; a copy of corner a, which
  // bridges and pinches create, does not block).
  bool blocks_ear(std::uint32_t n, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                  const Vec2<T>& pa, const Vec2<T>& pb, const Vec2<T>& pc) const {
    if (nodes[n].removed || !nodes[n].reflex || n == a || n == b || n == c) return false;
    const Vec2<T>& q = at(n);
    if (same_point(q, pa)) return false;
    return orient2d(pa, pb, q) != Sign::negative && orient2d(pb, pc, q) != Sign::negative &&
           orient2d(pc, pa, q) != Sign::negative;
  }

  bool is_ear(std::uint32_t b) const {
    const std::uint32_t a = nodes[b].prev, c = nodes[b].next;
    const Vec2<T>&pa = at(a), &pb = at(b), &pc = at(c);
    if (orient2d(pa, pb, pc) != Sign::positive) return false;
    const T lx = std::min({pa.x, pb.x, pc.x}), hx = std::max({pa.x, pb.x, pc.x});
    const T ly = std::min({pa.y, pb.y, pc.y}), hy = std::max({pa.y, pb.y, pc.y});
    const std::uint32_t y0 = cell_y(ly), y1 = cell_y(hy);
    // Row by row, only the cells the triangle reaches (a long thin ear would otherwise visit
    // its whole bounding box): its x-extent in each row's band, in cell units, widened by a
    // cell against rounding. Cell units: the same map as cell_x/cell_y, so a point's cell is
    // within a rounding error of where the triangle puts it.
    const double ax = gx_of(pa.x), ay = gy_of(pa.y), bx = gx_of(pb.x), by = gy_of(pb.y);
    const double cx = gx_of(pc.x), cy = gy_of(pc.y);
    const std::array<std::array<double, 4>, 3> edges = {
        {{ax, ay, bx, by}, {bx, by, cx, cy}, {cx, cy, ax, ay}}};
    for (std::uint32_t y = y0; y <= y1; ++y) {
      const double band_lo = y == y0 ? -1e300 : double(y), band_hi = y == y1 ? 1e300 : y + 1.0;
      double lo = 1e300, hi = -1e300;
      for (const auto& e : edges) {
        // The part of edge e inside the band.
        double t0 = 0.0, t1 = 1.0;
        const double dy = e[3] - e[1];
        if (dy != 0.0) {
          double ta = (band_lo - e[1]) / dy, tb = (band_hi - e[1]) / dy;
          if (ta > tb) std::swap(ta, tb);
          t0 = std::max(t0, ta);
          t1 = std::min(t1, tb);
        } else if (e[1] < band_lo || e[1] > band_hi) {
          continue;
        }
        if (!(t0 <= t1)) continue;
        const double xa = e[0] + t0 * (e[2] - e[0]), xb = e[0] + t1 * (e[2] - e[0]);
        lo = std::min({lo, xa, xb});
        hi = std::max({hi, xa, xb});
      }
      std::uint32_t x0 = cell_x(lx), x1 = cell_x(hx);
      if (lo <= hi) {
        const double l = std::floor(lo) - 1.0, h = std::floor(hi) + 1.0;
        if (l > double(x0)) x0 = static_cast<std::uint32_t>(std::min(l, double(x1)));
        if (h < double(x1)) x1 = static_cast<std::uint32_t>(std::max(h, double(x0)));
      }
      const std::size_t row = std::size_t(y) * gx;
      for (std::uint32_t x = x0; x <= x1; ++x) {
        const std::uint32_t first = cell_start[row + x];
        for (std::uint32_t i = first, e = first + cell_count[row + x]; i < e; ++i) {
          const GridEntry<T>& item = cell_items[i];
          const Vec2<T>& q = item.p;
          if (q.x < lx || q.x > hx || q.y < ly || q.y > hy) continue;
          const std::uint32_t n = item.node;
          if (n == a || n == b || n == c || same_point(q, pa)) continue;
          if (orient2d(pa, pb, q) != Sign::negative && orient2d(pb, pc, q) != Sign::negative &&
              orient2d(pc, pa, q) != Sign::negative)
            return false;
        }
      }
    }
    for (const std::uint32_t n : late)
      if (blocks_ear(n, a, b, c, pa, pb, pc)) return false;
    return true;
  }

  std::vector<std::uint8_t> in_grid = {};

  void update_reflex(std::uint32_t v) {
    const std::uint8_t r = convex(v) ? 0 : 1;
    if (!r) grid_remove(v);
    if (in_grid.size() < nodes.size()) in_grid.resize(nodes.size(), 0);
    if (r && !in_grid[v]) {
      in_grid[v] = 1;
      late.push_back(v);
    }
    nodes[v].reflex = r;
  }

  void unlink(std::uint32_t v) {
    const std::uint32_t a = nodes[v].prev, c = nodes[v].next;
    nodes[a].next = c;
    nodes[c].prev = a;
    nodes[v].removed = 1;
    grid_remove(v);
  }

  void emit(std::uint32_t b) {
    out.triangles.push_back(
        {nodes[nodes[b].prev].index, nodes[b].index, nodes[nodes[b].next].index});
  }

  // Cuts the ear at b (emitted) and refreshes its neighbours.
  void cut(std::uint32_t b) {
    const std::uint32_t a = nodes[b].prev, c = nodes[b].next;
    emit(b);
    unlink(b);
    update_reflex(a);
    update_reflex(c);
  }

  // Whether ring through a has a diagonal a-b inside it that no ring edge blocks (used only
  // on rings without ears, i.e. non-simple input; the midpoint test is rounded).
  bool valid_diagonal(std::uint32_t a, std::uint32_t b) const {
    if (nodes[a].next == b || nodes[a].prev == b) return false;
    const Vec2<T>&pa = at(a), &pb = at(b);
    if (same_point(pa, pb) || !locally_inside(a, pb) || !locally_inside(b, pa)) return false;
    std::uint32_t e = a;
    do {
      if (blocks(pa, pb, at(e), at(nodes[e].next))) return false;
      e = nodes[e].next;
    } while (e != a);
    const double mx = (double(pa.x) + double(pb.x)) * 0.5, my = (double(pa.y) + double(pb.y)) * 0.5;
    bool in = false;
    e = a;
    do {
      const Vec2<T>&p = at(e), &q = at(nodes[e].next);
      if ((double(p.y) > my) != (double(q.y) > my) &&
          mx < (double(q.x) - double(p.x)) * ((my - double(p.y)) / (double(q.y) - double(p.y))) +
                   double(p.x))
        in = !in;
      e = nodes[e].next;
    } while (e != a);
    return in;
  }

  std::uint32_t ring_count(std::uint32_t start) const {
    std::uint32_t n = 0, v = start;
    do {
      ++n;
      v = nodes[v].next;
    } while (v != start);
    return n;
  }

  void clip(std::uint32_t start, std::uint32_t count) {
    std::uint32_t ear = start, stop = start;
    while (count > 2) {
      const std::uint32_t c = nodes[ear].next;
      if (is_ear(ear)) {
        cut(ear);
        --count;
        // Continuing two vertices on gives fewer slivers than re-testing the neighbour.
        ear = stop = nodes[c].next;
        continue;
      }
      ear = c;
      if (ear != stop) continue;
      // A full turn without an ear. First drop duplicates, straight-run middles and spikes
      // (bridges and cut ears create them).
      bool removed = false;
      std::uint32_t v = ear;
      for (std::uint32_t seen = 0, n = count; seen < n && count > 2; ++seen) {
        const std::uint32_t pv = nodes[v].prev, nv = nodes[v].next;
        if (same_point(at(pv), at(v)) || orient2d(at(pv), at(v), at(nv)) == Sign::zero) {
          unlink(v);
          --count;
          update_reflex(pv);
          update_reflex(nv);
          removed = true;
          v = pv;
        } else {
          v = nv;
        }
      }
      ear = stop = v;
      if (removed) continue;
      // No ear in a cleaned ring: the rings were not a polygon with holes. Say so, and make a
      // best effort that terminates: split the ring along a diagonal and clip both parts, or,
      // when there is none, cut a convex vertex anyway.
      out.status = Status::invalid_topology;
      // A local self-intersection a -> p -> p' -> b with ap crossing p'b: cut triangle a p b
      // and drop p, p' (earcut's cure; it keeps the area of small loops).
      {
        bool cured = false;
        std::uint32_t p = ear;
        for (std::uint32_t seen = 0, n = count; seen < n && count > 3; ++seen) {
          const std::uint32_t a = nodes[p].prev, pn = nodes[p].next, b = nodes[pn].next;
          if (!same_point(at(a), at(b)) && proper_cross(at(a), at(p), at(pn), at(b)) &&
              locally_inside(a, at(b)) && locally_inside(b, at(a))) {
            if (orient2d(at(a), at(p), at(b)) == Sign::positive)
              out.triangles.push_back({nodes[a].index, nodes[p].index, nodes[b].index});
            unlink(p);
            unlink(pn);
            count -= 2;
            update_reflex(a);
            update_reflex(b);
            cured = true;
            p = b;
          } else {
            p = pn;
          }
        }
        if (cured) {
          ear = stop = p;
          continue;
        }
      }
      if (count > 3) {
        std::uint32_t a = ear;
        do {
          for (std::uint32_t b = nodes[nodes[a].next].next; b != nodes[a].prev; b = nodes[b].next)
            if (valid_diagonal(a, b)) {
              const std::uint32_t a2 = add_node(nodes[a].index);
              const std::uint32_t b2 = add_node(nodes[b].index);
              const std::uint32_t an = nodes[a].next, bp = nodes[b].prev;
              nodes[a].next = b;
              nodes[b].prev = a;
              nodes[a2].next = an;
              nodes[an].prev = a2;
              nodes[b2].next = a2;
              nodes[a2].prev = b2;
              nodes[bp].next = b2;
              nodes[b2].prev = bp;
              for (const std::uint32_t u : {a, b, a2, b2}) update_reflex(u);
              clip(a, ring_count(a));
              clip(a2, ring_count(a2));
              return;
            }
          a = nodes[a].next;
        } while (a != ear);
      }
      std::uint32_t u = ear;
      bool found = false;
      for (std::uint32_t seen = 0; seen < count; ++seen, u = nodes[u].next)
        if (convex(u)) {
          found = true;
          break;
        }
      if (!found) return;
      const std::uint32_t uc = nodes[u].next;
      cut(u);
      --count;
      ear = stop = uc;
    }
  }
};

template <Real T>
const PolygonTriangulation& EarClipping2<T>::compute(std::span<const Vec2<T>> points,
                                                     std::span<const std::uint32_t> ring_ends) {
  result_.triangles.clear();
  nodes_.clear();
  std::vector<std::uint32_t> ends;
  result_.status = triangulate_detail::prepare_rings(points, ring_ends, false, ring_, ends);
  if (result_.status != Status::ok) return result_;
  // Crossing edges are not a polygon: say so, then clip anyway (a best effort that terminates).
  if (triangulate_detail::rings_cross(points, ring_, ends))
    result_.status = Status::invalid_topology;
  std::vector<std::uint32_t> late;
  EarClipRun<T> run{points,      result_,     nodes_,      late,
                    cell_start_, cell_count_, cell_items_, grid_pos_};
  // One cyclic list per ring; the first node of each ring is its lexicographically smallest.
  hole_starts_.clear();
  std::uint32_t begin = 0;
  for (const std::uint32_t end : ends) {
    const std::uint32_t first = static_cast<std::uint32_t>(nodes_.size());
    for (std::uint32_t i = begin; i < end; ++i) {
      const std::uint32_t n = run.add_node(ring_[i]);
      nodes_[n].prev = i == begin ? first + (end - begin) - 1 : n - 1;
      nodes_[n].next = i + 1 == end ? first : n + 1;
    }
    hole_starts_.push_back(first);
    begin = end;
  }
  // Holes in increasing lexicographic order of their smallest vertex: each bridge then reaches
  // left into the part already joined, as Eberly describes.
  std::sort(hole_starts_.begin() + 1, hole_starts_.end(), [&](std::uint32_t a, std::uint32_t b) {
    const Sign s = lexicographic_compare(run.at(a), run.at(b));
    return s == Sign::negative || (s == Sign::zero && a < b);
  });
  const std::uint32_t outer = hole_starts_[0];
  if (hole_starts_.size() > 1) run.build_bridge_index(ends);
  for (std::size_t h = 1; h < hole_starts_.size(); ++h) {
    if (!run.bridge(outer, hole_starts_[h])) result_.status = Status::invalid_topology;
  }
  std::uint32_t count = 0, v = outer;
  do {
    ++count;
    v = nodes_[v].next;
  } while (v != outer);
  result_.triangles.reserve(count);
  run.build_grid(outer);
  run.in_grid.assign(nodes_.size(), 0);
  for (std::size_t i = 0; i < nodes_.size(); ++i) run.in_grid[i] = nodes_[i].reflex;
  run.clip(outer, count);
  return result_;
}

template <Real T>
PolygonTriangulation triangulate_ear_clipping(std::span<const Vec2<T>> points,
                                              std::span<const std::uint32_t> ring_ends) {
  EarClipping2<T> e;
  return e.compute(points, ring_ends);
}

template class EarClipping2<float>;
template class EarClipping2<double>;
template PolygonTriangulation triangulate_ear_clipping<float>(std::span<const Vec2<float>>,
                                                              std::span<const std::uint32_t>);
template PolygonTriangulation triangulate_ear_clipping<double>(std::span<const Vec2<double>>,
                                                               std::span<const std::uint32_t>);

}  // namespace locus
