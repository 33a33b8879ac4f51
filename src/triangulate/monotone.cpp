// SPDX-License-Identifier: BSL-1.0
// Monotone decomposition, monotone triangulation and horizontal trapezoids (see
// include/locus/triangulate/monotone.hpp, trapezoid_decomposition.hpp and
// docs/notes/triangulate.md).

#include <locus/triangulate/monotone.hpp>
#include <locus/triangulate/trapezoid_decomposition.hpp>

#include <locus/core/predicates.hpp>

#include "rings.hpp"

#include <algorithm>
#include <bit>
#include <iterator>
#include <memory_resource>
#include <numeric>
#include <set>

namespace locus {

namespace {

constexpr std::uint32_t kNone = 0xFFFFFFFFu;

enum class VertexType : std::uint8_t { start, split, end, merge, regular_left, regular_right };

template <Real T>
struct Sweep {
  std::span<const Vec2<T>> pts;
  std::vector<std::uint32_t> index, prev, next;  // per node: input index, ring neighbours
  std::vector<VertexType> type;
  std::vector<std::array<std::uint32_t, 2>> diagonals;  // node pairs
  std::vector<Trapezoid> traps;
  bool want_traps = false;  // only trapezoid_decomposition needs them
  Status status = Status::ok;

  const Vec2<T>& at(std::uint32_t n) const { return pts[index[n]]; }

  // Sweep order: a before b when a is higher, or as high and further left; ties by node.
  bool above(std::uint32_t a, std::uint32_t b) const {
    const Vec2<T>&pa = at(a), &pb = at(b);
    if (pa.y != pb.y) return pa.y > pb.y;
    if (pa.x != pb.x) return pa.x < pb.x;
    return a < b;
  }

  struct Key {
    Vec2<T> p;
  };
  // Edge e joins node e and next[e]; up_pt/lo_pt are its endpoints in sweep order (left-chain
  // edges run downward, e -> next[e]; right-chain edges upward). The tree holds every edge the
  // sweep line crosses, ordered left to right; point p is left of edge u -> l (u above) iff
  // orient2d(u, l, p) < 0.
  std::vector<Vec2<T>> up_pt, lo_pt;
  std::vector<std::uint8_t> downward;  // edge e runs down: the interior is to its right

  // orient2d, with the frequent case of a shared endpoint (an exact zero, which the filter
  // cannot certify and would send to the adaptive stage) answered at once.
  static Sign orient_or_shared(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& p) {
    if ((p.x == a.x && p.y == a.y) || (p.x == b.x && p.y == b.y)) return Sign::zero;
    return orient2d(a, b, p);
  }

  struct Less {
    Sweep* s;
    using is_transparent = void;
    bool operator()(std::uint32_t e1, std::uint32_t e2) const {
      if (e1 == e2) return false;
      const Vec2<T>&u1 = s->up_pt[e1], &l1 = s->lo_pt[e1];
      const Vec2<T>&u2 = s->up_pt[e2], &l2 = s->lo_pt[e2];
      const Sign a = orient_or_shared(u1, l1, u2), b = orient_or_shared(u1, l1, l2);
      if (a != Sign::negative && b != Sign::negative && (a != Sign::zero || b != Sign::zero))
        return true;
      if (a != Sign::positive && b != Sign::positive && (a != Sign::zero || b != Sign::zero))
        return false;
      if (a == Sign::zero && b == Sign::zero) return e1 < e2;
      // e2 straddles e1's line; since they do not cross, e1 lies on one side of e2's line.
      const Sign c = orient_or_shared(u2, l2, u1), d = orient_or_shared(u2, l2, l1);
      // Each straddles the other's line: the edges cross.
      if (c != Sign::zero && d != Sign::zero && c != d) s->status = Status::invalid_topology;
      return c != Sign::positive && d != Sign::positive;
    }
    bool operator()(std::uint32_t e, const Key& k) const {
      return orient2d(s->up_pt[e], s->lo_pt[e], k.p) == Sign::positive;
    }
    bool operator()(const Key& k, std::uint32_t e) const {
      return orient2d(s->up_pt[e], s->lo_pt[e], k.p) == Sign::negative;
    }
  };

  // Whether edges e and f cross properly (interiors meet in one point; exact).
  bool crosses(std::uint32_t e, std::uint32_t f) const {
    const Vec2<T>&a = up_pt[e], &b = lo_pt[e], &p = up_pt[f], &q = lo_pt[f];
    const Sign o1 = orient_or_shared(a, b, p), o2 = orient_or_shared(a, b, q);
    if (o1 == Sign::zero || o2 == Sign::zero || o1 == o2) return false;
    const Sign o3 = orient2d(p, q, a), o4 = orient2d(p, q, b);
    return o3 != Sign::zero && o4 != Sign::zero && o3 != o4;
  }

  void build(const std::vector<std::uint32_t>& verts, const std::vector<std::uint32_t>& ends) {
    const std::size_t m = verts.size();
    index = verts;
    prev.resize(m);
    next.resize(m);
    std::uint32_t begin = 0;
    for (const std::uint32_t end : ends) {
      for (std::uint32_t i = begin; i < end; ++i) {
        prev[i] = i == begin ? end - 1 : i - 1;
        next[i] = i + 1 == end ? begin : i + 1;
      }
      begin = end;
    }
    type.resize(m);
    up_pt.resize(m);
    lo_pt.resize(m);
    downward.resize(m);
    for (std::uint32_t e = 0; e < m; ++e) {
      downward[e] = above(e, next[e]) ? 1 : 0;
      up_pt[e] = at(downward[e] ? e : next[e]);
      lo_pt[e] = at(downward[e] ? next[e] : e);
    }
    for (std::uint32_t v = 0; v < m; ++v) {
      const bool p_below = above(v, prev[v]), n_below = above(v, next[v]);
      const bool convex = orient2d(at(prev[v]), at(v), at(next[v])) == Sign::positive;
      if (p_below && n_below)
        type[v] = convex ? VertexType::start : VertexType::split;
      else if (!p_below && !n_below)
        type[v] = convex ? VertexType::end : VertexType::merge;
      else
        type[v] = p_below ? VertexType::regular_left : VertexType::regular_right;
    }
  }

  void close(std::uint32_t left, std::uint32_t right, std::uint32_t top, std::uint32_t bottom) {
    if (!want_traps || left == kNone || right == kNone || top == kNone) return;
    if (at(top).y == at(bottom).y) return;
    traps.push_back(Trapezoid{{index[left], index[next[left]]},
                              {index[next[right]], index[right]},
                              index[top],
                              index[bottom]});
  }

  // An order-preserving unsigned image of y (larger y first), -0 and +0 alike.
  static std::uint64_t descending_key(T y) {
    const double d = y == T(0) ? 0.0 : double(y);
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(d);
    const std::uint64_t ascending = (bits >> 63) != 0 ? ~bits : bits | (std::uint64_t(1) << 63);
    return ~ascending;
  }

  // The nodes in sweep order (y down, then x up, then node): a stable radix sort on y, then
  // runs of equal y sorted by x.
  template <class Event>
  void sweep_order(std::vector<Event>& events) const {
    const std::uint32_t m = static_cast<std::uint32_t>(index.size());
    const auto less = [](const Event& a, const Event& b) {
      if (a.y != b.y) return a.y > b.y;
      if (a.x != b.x) return a.x < b.x;
      return a.node < b.node;
    };
    for (std::uint32_t v = 0; v < m; ++v) events[v] = Event{at(v).y, at(v).x, v};
    if (m < 4096) {
      std::sort(events.begin(), events.end(), less);
      return;
    }
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keys(m), tmp(m);
    for (std::uint32_t v = 0; v < m; ++v) keys[v] = {descending_key(at(v).y), v};
    std::vector<std::uint32_t> count(65536);
    for (int shift = 0; shift < 64; shift += 16) {
      std::fill(count.begin(), count.end(), 0u);
      for (const auto& k : keys) ++count[(k.first >> shift) & 0xFFFF];
      std::uint32_t sum = 0;
      for (auto& c : count) {
        const std::uint32_t c0 = c;
        c = sum;
        sum += c0;
      }
      for (const auto& k : keys) tmp[count[(k.first >> shift) & 0xFFFF]++] = k;
      keys.swap(tmp);
    }
    for (std::uint32_t i = 0; i < m; ++i) {
      const std::uint32_t v = keys[i].second;
      events[i] = Event{at(v).y, at(v).x, v};
    }
    for (std::uint32_t i = 0; i < m;) {
      std::uint32_t j = i + 1;
      while (j < m && keys[j].first == keys[i].first) ++j;
      if (j - i > 1) std::sort(events.begin() + i, events.begin() + j, less);
      i = j;
    }
  }

  // The sweep of monotone.hpp: diagonals (node pairs) and trapezoids.
  void run() {
    const std::uint32_t m = static_cast<std::uint32_t>(index.size());
    // Sweep order on flat keys (no indirection in the comparisons).
    struct Event {
      T y, x;
      std::uint32_t node;
    };
    std::vector<Event> events(m);
    sweep_order(events);
    // Tree nodes come from a pool: one allocation per chunk, not per edge.
    std::pmr::unsynchronized_pool_resource pool;
    using Tree = std::pmr::set<std::uint32_t, Less>;
    Tree tree(Less{this}, &pool);
    std::vector<typename Tree::iterator> where(m, tree.end());
    std::vector<std::uint32_t> helper(m, kNone), right(m, kNone), top(m, kNone);
    const auto diag_if_merge = [&](std::uint32_t v, std::uint32_t e) {
      if (helper[e] != kNone && type[helper[e]] == VertexType::merge)
        diagonals.push_back({v, helper[e]});
    };
    // Shamos and Hoey: every pair of edges that becomes adjacent in the tree is tested, so the
    // first proper crossing is met before the sweep passes it (touching is not a crossing here;
    // the interval checks below catch the rest).
    const auto check = [&](typename Tree::iterator x, typename Tree::iterator y) {
      if (x != tree.end() && y != tree.end() && crosses(*x, *y)) status = Status::invalid_topology;
    };
    using It = typename Tree::iterator;
    // Inserts edge e just before `hint` when that is its place (amortised O(1); std::set checks
    // the hint against both neighbours and searches the whole tree otherwise).
    const auto insert_edge = [&](std::uint32_t e, It hint) {
      const std::size_t size = tree.size();
      const It it = tree.insert(hint, e);
      // An equal key exists only for overlapping edges: not a polygon.
      if (tree.size() == size) {
        status = Status::invalid_topology;
        return tree.end();
      }
      where[e] = it;
      if (it != tree.begin()) check(std::prev(it), it);
      check(it, std::next(it));
      return it;
    };
    const auto set_interval = [&](std::uint32_t e, std::uint32_t v, std::uint32_t r) {
      helper[e] = v;
      right[e] = r;
      top[e] = v;
    };
    // Erases edge e; returns the iterator after it (tree.end() on failure, with the status set).
    const auto erase = [&](std::uint32_t e) {
      if (where[e] == tree.end()) {
        status = Status::invalid_topology;
        return tree.end();
      }
      const It after = tree.erase(where[e]);
      if (after != tree.begin() && after != tree.end()) check(std::prev(after), after);
      where[e] = tree.end();
      return after;
    };
    // The left edge (downward) directly before position it, or kNone (status set).
    const auto left_before = [&](It it) {
      if (it == tree.begin() || !downward[*std::prev(it)]) {
        status = Status::invalid_topology;
        return kNone;
      }
      return *std::prev(it);
    };
    for (const Event& event : events) {
      const std::uint32_t v = event.node;
      // The tree order assumes non-crossing edges: stop at the first sign of a crossing.
      if (status != Status::ok) return;
      const std::uint32_t ein = prev[v], eout = v;
      // An upward edge leaving v ends here (v is its lower endpoint). The left edge of the
      // interval it bounded on the right is its tree predecessor.
      It hint = tree.end();
      std::uint32_t left_of_out = kNone;
      if (!downward[eout]) {
        if (where[eout] == tree.end()) {
          status = Status::invalid_topology;
          return;
        }
        left_of_out = left_before(where[eout]);
        hint = erase(eout);
        if (status != Status::ok) return;
      }
      switch (type[v]) {
        case VertexType::start: {
          // A start vertex lies outside the polygon above it: not strictly inside an interval.
          const It it = tree.lower_bound(Key{at(v)});
          if (it != tree.begin()) {
            const std::uint32_t r = right[*std::prev(it)];
            if (r != kNone && orient2d(at(r), at(next[r]), at(v)) == Sign::positive)
              status = Status::invalid_topology;
          }
          // Left edge eout, then right edge ein.
          const It at_out = insert_edge(eout, it);
          set_interval(eout, v, ein);
          if (at_out != tree.end()) insert_edge(ein, std::next(at_out));
          break;
        }
        case VertexType::end:
          if (where[ein] == tree.end()) {
            status = Status::invalid_topology;
            break;
          }
          if (right[ein] != eout) status = Status::invalid_topology;
          diag_if_merge(v, ein);
          close(ein, right[ein], top[ein], v);
          erase(ein);
          break;
        case VertexType::split: {
          const It it = tree.lower_bound(Key{at(v)});
          const std::uint32_t ej = left_before(it);
          if (ej == kNone) break;
          // v must lie strictly inside the interval (ej, right[ej]).
          if (right[ej] == kNone ||
              orient2d(at(right[ej]), at(next[right[ej]]), at(v)) != Sign::positive)
            status = Status::invalid_topology;
          diagonals.push_back({v, helper[ej]});
          close(ej, right[ej], top[ej], v);
          const std::uint32_t r = right[ej];
          set_interval(ej, v, ein);
          // Right edge ein, then left edge eout.
          const It at_in = insert_edge(ein, it);
          if (at_in != tree.end()) insert_edge(eout, std::next(at_in));
          set_interval(eout, v, r);
          break;
        }
        case VertexType::merge: {
          if (where[ein] == tree.end()) {
            status = Status::invalid_topology;
            break;
          }
          diag_if_merge(v, ein);
          close(ein, right[ein], top[ein], v);
          const std::uint32_t r = right[ein];
          erase(ein);
          const std::uint32_t ej = left_of_out;
          if (ej == kNone) break;
          if (right[ej] != eout) status = Status::invalid_topology;
          diag_if_merge(v, ej);
          close(ej, right[ej], top[ej], v);
          set_interval(ej, v, r);
          break;
        }
        case VertexType::regular_right: {  // on a left chain: the interior is to its right
          if (where[ein] == tree.end()) {
            status = Status::invalid_topology;
            break;
          }
          diag_if_merge(v, ein);
          close(ein, right[ein], top[ein], v);
          const std::uint32_t r = right[ein];
          // The left chain continues strictly left of the right edge of its interval.
          if (r == kNone || orient2d(at(r), at(next[r]), at(v)) != Sign::positive)
            status = Status::invalid_topology;
          const It after = erase(ein);
          if (status != Status::ok) break;
          insert_edge(eout, after);
          set_interval(eout, v, r);
          break;
        }
        case VertexType::regular_left: {
          const std::uint32_t ej = left_of_out;
          if (ej == kNone) break;
          if (right[ej] != eout) status = Status::invalid_topology;
          diag_if_merge(v, ej);
          close(ej, right[ej], top[ej], v);
          set_interval(ej, v, ein);
          // The right chain continues: ein takes eout's place.
          if (status == Status::ok) insert_edge(ein, hint);
          break;
        }
      }
    }
    if (!tree.empty()) status = Status::invalid_topology;
  }

  // The faces of the rings cut by the diagonals: pieces as node rings.
  void pieces(std::vector<std::uint32_t>& out, std::vector<std::uint32_t>& ends) {
    const std::uint32_t m = static_cast<std::uint32_t>(index.size());
    std::vector<std::uint32_t> start(m + 1, 2);
    start[m] = 0;
    for (const auto& d : diagonals) {
      ++start[d[0]];
      ++start[d[1]];
    }
    std::uint32_t sum = 0;
    for (std::uint32_t v = 0; v <= m; ++v) {
      const std::uint32_t c = v < m ? start[v] : 0;
      start[v] = sum;
      sum += c;
    }
    std::vector<std::uint32_t> adj(sum), fill(start.begin(), start.end() - 1);
    // Slot 0 of each vertex: its ring successor (the outgoing boundary half-edge).
    for (std::uint32_t v = 0; v < m; ++v) {
      adj[fill[v]++] = next[v];
      adj[fill[v]++] = prev[v];
    }
    for (const auto& d : diagonals) {
      adj[fill[d[0]]++] = d[1];
      adj[fill[d[1]]++] = d[0];
    }
    // Neighbours counter-clockwise by angle (half-plane, then orient2d: exact).
    for (std::uint32_t v = 0; v < m; ++v) {
      if (start[v + 1] - start[v] <= 2) continue;  // two neighbours: one cyclic order
      const Vec2<T>& c = at(v);
      const auto half = [&](std::uint32_t w) {
        const Vec2<T>& p = at(w);
        return (p.y > c.y || (p.y == c.y && p.x > c.x)) ? 0 : 1;
      };
      std::sort(adj.begin() + start[v], adj.begin() + start[v + 1],
                [&](std::uint32_t a, std::uint32_t b) {
                  const int ha = half(a), hb = half(b);
                  if (ha != hb) return ha < hb;
                  const Sign s = orient2d(c, at(a), at(b));
                  return s == Sign::positive || (s == Sign::zero && a < b);
                });
    }
    // Interior half-edges: v -> next[v] and both directions of every diagonal.
    std::vector<std::uint8_t> used(sum, 0);
    for (std::uint32_t v = 0; v < m; ++v)
      for (std::uint32_t i = start[v]; i < start[v + 1]; ++i)
        if (adj[i] == prev[v] && adj[i] != next[v]) used[i] = 1;
    const auto slot = [&](std::uint32_t v, std::uint32_t w) {
      for (std::uint32_t i = start[v]; i < start[v + 1]; ++i)
        if (adj[i] == w) return i;
      return kNone;
    };
    for (std::uint32_t v = 0; v < m; ++v)
      for (std::uint32_t i = start[v]; i < start[v + 1]; ++i) {
        if (used[i]) continue;
        std::uint32_t u = v, s = i, steps = 0;
        while (!used[s] && steps <= sum) {
          used[s] = 1;
          out.push_back(index[u]);
          const std::uint32_t w = adj[s];
          const std::uint32_t back = slot(w, u);
          if (back == kNone) break;
          // The next half-edge turns clockwise from w -> u around w.
          const std::uint32_t nxt = back == start[w] ? start[w + 1] - 1 : back - 1;
          u = w;
          s = nxt;
          ++steps;
        }
        if (s != i || !used[s]) status = Status::invalid_topology;
        ends.push_back(static_cast<std::uint32_t>(out.size()));
      }
  }
};

template <Real T>
bool sweep_above(const Vec2<T>& a, std::uint32_t ia, const Vec2<T>& b, std::uint32_t ib) {
  if (a.y != b.y) return a.y > b.y;
  if (a.x != b.x) return a.x < b.x;
  return ia < ib;
}

// The stack walk over a y-monotone piece (CCW ring of input indices).
template <Real T>
void triangulate_piece(std::span<const Vec2<T>> pts, std::span<const std::uint32_t> ring,
                       std::vector<std::array<std::uint32_t, 3>>& tris,
                       std::vector<std::pair<std::uint32_t, bool>>& merged,
                       std::vector<std::pair<std::uint32_t, bool>>& stack) {
  const std::size_t n = ring.size();
  if (n < 3) return;
  const auto above = [&](std::size_t a, std::size_t b) {
    return sweep_above(pts[ring[a]], ring[a], pts[ring[b]], ring[b]);
  };
  std::size_t top = 0, bottom = 0;
  for (std::size_t i = 1; i < n; ++i) {
    if (above(i, top)) top = i;
    if (above(bottom, i)) bottom = i;
  }
  // From the top, the ring's successors run down the left chain (true), its predecessors down
  // the right chain; merge the two by sweep order.
  merged.clear();
  merged.emplace_back(ring[top], true);
  std::size_t l = (top + 1) % n, r = (top + n - 1) % n;
  while (l != bottom || r != bottom) {
    if (r == bottom || (l != bottom && above(l, r))) {
      merged.emplace_back(ring[l], true);
      l = (l + 1) % n;
    } else {
      merged.emplace_back(ring[r], false);
      r = (r + n - 1) % n;
    }
  }
  merged.emplace_back(ring[bottom], true);
  const auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const Sign s = orient2d(pts[a], pts[b], pts[c]);
    if (s == Sign::positive)
      tris.push_back({a, b, c});
    else if (s == Sign::negative)
      tris.push_back({a, c, b});
  };
  stack.clear();
  stack.push_back(merged[0]);
  stack.push_back(merged[1]);
  for (std::size_t j = 2; j + 1 < n; ++j) {
    const auto [u, left] = merged[j];
    if (left != stack.back().second) {
      for (std::size_t k = 0; k + 1 < stack.size(); ++k)
        emit(u, stack[k].first, stack[k + 1].first);
      const auto last = stack.back();
      stack.clear();
      stack.push_back(last);
      stack.push_back(merged[j]);
    } else {
      auto last = stack.back();
      stack.pop_back();
      while (!stack.empty()) {
        const std::uint32_t s = stack.back().first;
        const Sign o = left ? orient2d(pts[s], pts[last.first], pts[u])
                            : orient2d(pts[u], pts[last.first], pts[s]);
        if (o != Sign::positive) break;
        emit(u, last.first, s);
        last = stack.back();
        stack.pop_back();
      }
      stack.push_back(last);
      stack.push_back(merged[j]);
    }
  }
  const std::uint32_t u = merged[n - 1].first;
  for (std::size_t k = 0; k + 1 < stack.size(); ++k) emit(u, stack[k].first, stack[k + 1].first);
}

template <Real T>
Status decompose(std::span<const Vec2<T>> points, std::span<const std::uint32_t> ring_ends,
                 Sweep<T>& sw, std::size_t& holes) {
  std::vector<std::uint32_t> verts, ends;
  const Status s = triangulate_detail::prepare_rings(points, ring_ends, true, verts, ends);
  if (s != Status::ok) return s;
  holes = ends.size() - 1;
  // The sweep itself tests every pair of edges that become neighbours (Shamos and Hoey), so a
  // proper crossing gives invalid_topology without a separate rings_cross pass.
  sw.pts = points;
  sw.build(verts, ends);
  sw.run();
  return sw.status;
}

}  // namespace

template <Real T>
MonotoneDecomposition monotone_decomposition(std::span<const Vec2<T>> points,
                                             std::span<const std::uint32_t> ring_ends) {
  MonotoneDecomposition out;
  Sweep<T> sw;
  std::size_t holes = 0;
  out.status = decompose(points, ring_ends, sw, holes);
  if (out.status != Status::ok) return out;
  sw.pieces(out.vertices, out.piece_ends);
  out.status = sw.status;
  if (out.status != Status::ok) {
    out.vertices.clear();
    out.piece_ends.clear();
    return out;
  }
  for (const auto& d : sw.diagonals) out.diagonals.push_back({sw.index[d[0]], sw.index[d[1]]});
  return out;
}

template <Real T>
PolygonTriangulation triangulate_monotone(std::span<const Vec2<T>> points,
                                          std::span<const std::uint32_t> ring_ends) {
  PolygonTriangulation out;
  Sweep<T> sw;
  std::size_t holes = 0;
  out.status = decompose(points, ring_ends, sw, holes);
  if (out.status != Status::ok) return out;
  std::vector<std::uint32_t> verts, ends;
  sw.pieces(verts, ends);
  out.status = sw.status;
  if (out.status != Status::ok) return out;
  const std::size_t n = sw.index.size();
  out.triangles.reserve(n + 2 * holes);
  std::vector<std::pair<std::uint32_t, bool>> merged, stack;
  std::uint32_t begin = 0;
  for (const std::uint32_t end : ends) {
    triangulate_piece(points, std::span<const std::uint32_t>(verts).subspan(begin, end - begin),
                      out.triangles, merged, stack);
    begin = end;
  }
  if (out.status == Status::ok && out.triangles.size() + 2 != n + 2 * holes)
    out.status = Status::invalid_topology;
  return out;
}

template <Real T>
TrapezoidDecomposition trapezoid_decomposition(std::span<const Vec2<T>> points,
                                               std::span<const std::uint32_t> ring_ends) {
  TrapezoidDecomposition out;
  Sweep<T> sw;
  sw.want_traps = true;
  std::size_t holes = 0;
  out.status = decompose(points, ring_ends, sw, holes);
  if (out.status == Status::ok) out.trapezoids = std::move(sw.traps);
  return out;
}

template MonotoneDecomposition monotone_decomposition<float>(std::span<const Vec2<float>>,
                                                             std::span<const std::uint32_t>);
template MonotoneDecomposition monotone_decomposition<double>(std::span<const Vec2<double>>,
                                                              std::span<const std::uint32_t>);
template PolygonTriangulation triangulate_monotone<float>(std::span<const Vec2<float>>,
                                                          std::span<const std::uint32_t>);
template PolygonTriangulation triangulate_monotone<double>(std::span<const Vec2<double>>,
                                                           std::span<const std::uint32_t>);
template TrapezoidDecomposition trapezoid_decomposition<float>(std::span<const Vec2<float>>,
                                                               std::span<const std::uint32_t>);
template TrapezoidDecomposition trapezoid_decomposition<double>(std::span<const Vec2<double>>,
                                                                std::span<const std::uint32_t>);

}  // namespace locus
