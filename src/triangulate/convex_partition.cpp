// SPDX-License-Identifier: BSL-1.0
// Convex partitions (see include/locus/triangulate/convex_partition.hpp and
// docs/notes/triangulate.md, "Convex partitions").

#include <locus/triangulate/convex_partition.hpp>

#include <locus/core/predicates.hpp>
#include <locus/triangulate/ear_clipping.hpp>
#include <locus/triangulate/monotone.hpp>

#include "rings.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

namespace locus {

namespace {

/// Hertel-Mehlhorn on the triangles (CCW, input indices): the half-edge 3t + i runs from
/// corner i to corner i + 1 of triangle t.
template <Real T>
void merge_triangles(std::span<const Vec2<T>> points,
                     const std::vector<std::array<std::uint32_t, 3>>& tris, ConvexPartition& r) {
  const std::size_t m = 3 * tris.size();
  std::vector<std::uint32_t> org(m), next(m), prev(m), twin(m, 0xffffffffu), face(tris.size());
  for (std::size_t h = 0; h < m; ++h) {
    const std::size_t t = h / 3, i = h % 3;
    org[h] = tris[t][i];
    next[h] = static_cast<std::uint32_t>(3 * t + (i + 1) % 3);
    prev[h] = static_cast<std::uint32_t>(3 * t + (i + 2) % 3);
  }
  std::iota(face.begin(), face.end(), 0u);
  // Twins: the half-edges grouped by their unordered end pair; a pair used exactly twice, in
  // opposite directions, is a diagonal (anything else, e.g. at pinched vertices, stays).
  std::vector<std::uint32_t> order(m);
  std::iota(order.begin(), order.end(), 0u);
  const auto key = [&](std::uint32_t h) {
    const std::uint32_t a = org[h], b = org[next[h]];
    return std::pair{std::min(a, b), std::max(a, b)};
  };
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t x, std::uint32_t y) { return key(x) < key(y); });
  for (std::size_t k = 0; k < m;) {
    std::size_t e = k + 1;
    while (e < m && key(order[e]) == key(order[k])) ++e;
    if (e - k == 2 && org[order[k]] != org[order[k + 1]]) {
      twin[order[k]] = order[k + 1];
      twin[order[k + 1]] = order[k];
    }
    k = e;
  }
  const auto find = [&](std::uint32_t f) {
    while (face[f] != f) f = face[f] = face[face[f]];
    return f;
  };
  const auto dest = [&](std::uint32_t h) { return org[next[h]]; };
  std::vector<std::uint8_t> removed(m, 0);
  for (std::uint32_t h = 0; h < m; ++h) {
    const std::uint32_t g = twin[h];
    if (g == 0xffffffffu || g < h) continue;
    const std::uint32_t u = org[h], v = org[g];
    const std::uint32_t fh = find(h / 3), fg = find(g / 3);
    // Both ends must stay convex (weakly) in the merged piece; a piece on both sides of the
    // diagonal (around a hole) keeps it.
    const bool keep =
        fh == fg ||
        orient2d(points[org[prev[h]]], points[u], points[dest(next[g])]) == Sign::negative ||
        orient2d(points[org[prev[g]]], points[v], points[dest(next[h])]) == Sign::negative;
    if (keep) {
      r.diagonals.push_back({u, v});
      continue;
    }
    next[prev[h]] = next[g];
    prev[next[g]] = prev[h];
    next[prev[g]] = next[h];
    prev[next[h]] = prev[g];
    removed[h] = removed[g] = 1;
    face[fg] = fh;
  }
  std::vector<std::uint8_t> seen(m, 0);
  for (std::uint32_t h = 0; h < m; ++h) {
    if (removed[h] || seen[h]) continue;
    std::uint32_t x = h;
    do {
      seen[x] = 1;
      r.vertices.push_back(org[x]);
      x = next[x];
    } while (x != h);
    r.piece_ends.push_back(static_cast<std::uint32_t>(r.vertices.size()));
  }
}

/// p on the closed segment a b, for collinear a, b, p (lexicographic order along the line).
template <Real T>
bool between(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& p) noexcept {
  const Sign sa = lexicographic_compare(p, a), sb = lexicographic_compare(p, b);
  return sa == Sign::zero || sb == Sign::zero || sa != sb;
}

/// The closed segments a b and c d meet (exact).
template <Real T>
bool segments_meet(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& c,
                   const Vec2<T>& d) noexcept {
  const Sign o1 = orient2d(a, b, c), o2 = orient2d(a, b, d);
  const Sign o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
  if (o1 * o2 == Sign::negative && o3 * o4 == Sign::negative) return true;
  return (o1 == Sign::zero && between(a, b, c)) || (o2 == Sign::zero && between(a, b, d)) ||
         (o3 == Sign::zero && between(c, d, a)) || (o4 == Sign::zero && between(c, d, b));
}

}  // namespace

template <Real T>
ConvexPartition convex_partition(std::span<const Vec2<T>> points,
                                 std::span<const std::uint32_t> ring_ends) {
  ConvexPartition r;
  PolygonTriangulation tri = triangulate_monotone(points, ring_ends);
  // Rings touching at a vertex stop the sweep; ear clipping bridges them.
  if (tri.status == Status::invalid_topology) tri = triangulate_ear_clipping(points, ring_ends);
  r.status = tri.status;
  if (tri.status == Status::ok) merge_triangles(points, tri.triangles, r);
  return r;
}

/// Minimum convex decomposition after Keil and Snoeyink (docs/notes/triangulate.md): the ring
/// (CCW positions 0 .. n-1 of cleaned input indices `verts`, rotated so that 0 is reflex) is
/// cut by diagonals with a reflex end only. For each sub-polygon P(a, b) (a < b, a or b
/// reflex) the least piece count f and the narrowest (s, t) pairs of its a-b piece over the
/// optimal decompositions: s the piece's vertex after a, t the one before b.
template <Real T>
struct KeilRun {
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  std::span<const Vec2<T>> points;
  const std::vector<std::uint32_t>& verts;
  std::uint32_t n;
  std::vector<std::uint8_t> reflex;
  std::vector<std::uint32_t> row_of;  // reflex vertex -> its row, else kNone

  struct Pair {
    std::uint32_t s, t, k, child;   // child: the merged child's pair index, or kNone
    bool option_b;                  // k next to a in the piece (else next to b)
    bool line = false;              // the side a k (b k for option_b) is a straight line
    std::uint32_t child_b = kNone;  // option C: the merged k-b child's pair (child: a-k's)
  };
  struct Cell {
    std::uint32_t f = kNone, first = 0, count = 0;
    // Not visible but on a straight line of vertices from one end: the vertex before the far
    // end on that line, seen from the smaller or the larger end (kNone otherwise).
    std::uint32_t via_small = kNone, via_large = kNone;
    std::uint8_t visible = 0;
  };
  std::vector<Cell> cells;  // row_of[x] * n + y for the pair {x, y} stored with reflex x
  std::vector<Pair> pairs;

  const Vec2<T>& P(std::uint32_t k) const { return points[verts[k]]; }

  // The record of pair (a, b), a < b, with a reflex end (the smaller one when both are).
  Cell* cell(std::uint32_t a, std::uint32_t b) {
    if (reflex[a]) return &cells[std::size_t(row_of[a]) * n + b];
    if (reflex[b]) return &cells[std::size_t(row_of[b]) * n + a];
    return nullptr;
  }

  // Visibility from every reflex vertex through a triangulation (tris: CCW position triples):
  // a depth-first walk across the triangles with the wedge of rays still open; a vertex is
  // visible when strictly inside the wedge (exact orient2d), which is the diagonal test of the
  // direct programme (inside the polygon, no other vertex on the closed segment).
  void visibility(const std::vector<std::array<std::uint32_t, 3>>& tris) {
    const std::size_t m = tris.size();
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;  // directed edge -> half-edge
    keyed.reserve(3 * m);
    for (std::size_t t = 0; t < m; ++t)
      for (std::uint32_t i = 0; i < 3; ++i)
        keyed.emplace_back(std::uint64_t(tris[t][i]) << 32 | tris[t][(i + 1) % 3],
                           std::uint32_t(3 * t + i));
    std::sort(keyed.begin(), keyed.end());
    const auto twin = [&](std::uint32_t u, std::uint32_t v) {
      const std::uint64_t key = std::uint64_t(v) << 32 | u;
      const auto it =
          std::lower_bound(keyed.begin(), keyed.end(), std::make_pair(key, std::uint32_t(0)));
      return it != keyed.end() && it->first == key ? it->second : kNone;
    };
    std::vector<std::vector<std::uint32_t>> around(n);
    for (std::size_t t = 0; t < m; ++t)
      for (std::uint32_t i = 0; i < 3; ++i) around[tris[t][i]].push_back(std::uint32_t(t));
    struct Step {
      std::uint32_t u, v, right, left;  // crossing u -> v (u on the right), wedge rays
    };
    std::vector<Step> stack;
    for (std::uint32_t i = 0; i < n; ++i) {
      if (!reflex[i]) continue;
      const auto mark = [&](std::uint32_t w) {
        if (w != i) cell(std::min(i, w), std::max(i, w))->visible = 1;
      };
      // w lies on the ray from i through `before`, beyond it: a straight line of vertices.
      const auto mark_via = [&](std::uint32_t w, std::uint32_t before) {
        Cell* c = cell(std::min(i, w), std::max(i, w));
        (i < w ? c->via_small : c->via_large) = before;
      };
      const Vec2<T>& o = P(i);
      for (const std::uint32_t t : around[i]) {
        std::uint32_t c = 0;
        while (tris[t][c] != i) ++c;
        const std::uint32_t a = tris[t][(c + 1) % 3], b = tris[t][(c + 2) % 3];
        mark(a);
        mark(b);
        stack.push_back({a, b, a, b});
      }
      while (!stack.empty()) {
        const Step st = stack.back();
        stack.pop_back();
        const std::uint32_t h = twin(st.u, st.v);
        if (h == kNone) continue;  // a polygon edge
        const auto& tri = tris[h / 3];
        const std::uint32_t c = tri[(h % 3 + 2) % 3];
        const Vec2<T>& pc = P(c);
        const Sign to_right = orient2d(o, P(st.right), pc);
        const Sign to_left = orient2d(o, P(st.left), pc);
        const bool after_right = to_right == Sign::positive;
        const bool before_left = to_left == Sign::negative;
        if (after_right && before_left) mark(c);
        // On a boundary ray: not visible, but reached along a straight line of vertices; the
        // ray's vertex becomes c, so the next vertex on it records c as its predecessor.
        std::uint32_t right = st.right, left = st.left;
        if (to_right == Sign::zero && before_left) {
          mark_via(c, st.right);
          right = c;
        }
        if (to_left == Sign::zero && after_right) {
          mark_via(c, st.left);
          left = c;
        }
        // Through u -> c (right part) and c -> v (left part), each with its narrowed wedge.
        if (after_right) stack.push_back({st.u, c, st.right, before_left ? c : left});
        if (before_left) stack.push_back({c, st.v, after_right ? c : right, st.left});
      }
    }
  }

  bool valid(std::uint32_t a, std::uint32_t b) {
    if (b == a + 1) return true;
    const Cell* c = cell(a, b);
    return c && c->visible;
  }
  std::uint32_t f_of(std::uint32_t a, std::uint32_t b) { return b == a + 1 ? 0 : cell(a, b)->f; }

  // A straight line of vertices from `from` to `to` (no diagonal: vertices on the segment),
  // each step an edge or a valid diagonal, walked back from `to`: the sum of f over the steps
  // and the line's vertex next to `from`, or kNone.
  std::uint32_t straight(std::uint32_t from, std::uint32_t to, std::uint32_t& next_to_from) {
    std::uint32_t cost = 0, x = to;
    for (std::uint32_t guard = 0; guard < n; ++guard) {
      const Cell* c = cell(std::min(from, x), std::max(from, x));
      if (!c) return kNone;
      const std::uint32_t y = c->visible ? from : (from < x ? c->via_small : c->via_large);
      if (y == kNone || (from < to ? !(from <= y && y < x) : !(x < y && y <= from))) return kNone;
      const std::uint32_t lo = std::min(x, y), hi = std::max(x, y);
      if (!valid(lo, hi)) return kNone;
      const std::uint32_t f = f_of(lo, hi);
      if (f == kNone) return kNone;
      cost += f;
      if (y == from) {
        next_to_from = x;
        return cost;
      }
      x = y;
    }
    return kNone;
  }

  // Narrower at a: s1's angle after a (from a->s to a->b, in (0, pi]) is smaller than s2's.
  bool narrower_at_a(std::uint32_t a, std::uint32_t s1, std::uint32_t s2) const {
    return orient2d(P(a), P(s2), P(s1)) == Sign::positive;
  }
  bool narrower_at_b(std::uint32_t b, std::uint32_t t1, std::uint32_t t2) const {
    return orient2d(P(b), P(t2), P(t1)) == Sign::negative;
  }

  void solve(std::uint32_t a, std::uint32_t b) {
    Cell* me = cell(a, b);
    if (!me || !me->visible || b < a + 2) return;
    std::uint32_t best = kNone;
    std::vector<Pair> cand;
    const auto consider = [&](std::uint32_t cost, const Pair& p) {
      if (cost < best) {
        best = cost;
        cand.clear();
      }
      if (cost == best) cand.push_back(p);
    };
    // Both ways of splitting off the triangle a k b: k next to b in the a-b piece (option A:
    // the a-k part may merge into the piece, k b bounds it) or k next to a (option B, mirrored).
    // A separate part must be cut by an edge or a diagonal with a reflex end (an essential one);
    // a merged part needs a reflex end to have a table. With one reflex end, k runs over the
    // reflex vertices and the neighbours only: O(r) per pair, O(n) when both ends are reflex.
    for (std::uint32_t k = a + 1; k < b; ++k) {
      if ((k + 1 == b || reflex[k] || reflex[b]) && valid(k, b) && f_of(k, b) != kNone) {
        const std::uint32_t fb = f_of(k, b);
        if (valid(a, k)) {
          const std::uint32_t fa = f_of(a, k);
          std::uint32_t pick = kNone;
          if (fa != kNone && k > a + 1) {
            const Cell* c = cell(a, k);
            for (std::uint32_t q = c->first; q < c->first + c->count; ++q) {
              const Pair& pr = pairs[q];
              // Convex at a and at k once the triangle a k b is added.
              if (orient2d(P(b), P(a), P(pr.s)) == Sign::negative ||
                  orient2d(P(pr.t), P(k), P(b)) == Sign::negative)
                continue;
              if (pick == kNone || narrower_at_a(a, pr.s, pairs[pick].s)) pick = q;
            }
          }
          if (fa != kNone && pick != kNone)
            consider(fa + fb, Pair{pairs[pick].s, k, k, pick, false});
          else if (fa != kNone)
            consider(fa + fb + 1, Pair{k, k, k, kNone, false});
        } else if (reflex[a]) {
          // The piece's side a k is a straight line of vertices: the triangle with that side.
          std::uint32_t s1 = kNone;
          const std::uint32_t line = straight(a, k, s1);
          if (line != kNone) consider(line + fb + 1, Pair{s1, k, k, kNone, false, true});
        }
      }
      // Option C: both parts merge, the triangle a k b in the middle (needed when the piece
      // runs straight through a and b, so that neither A nor B has a diagonal to split along).
      if (k > a + 1 && k + 1 < b && (reflex[a] || reflex[k]) && (reflex[k] || reflex[b]) &&
          valid(a, k) && valid(k, b) && f_of(a, k) != kNone && f_of(k, b) != kNone) {
        const Cell* ca = cell(a, k);
        const Cell* cb = cell(k, b);
        for (std::uint32_t q1 = ca->first; q1 < ca->first + ca->count; ++q1) {
          const Pair& p1 = pairs[q1];
          if (orient2d(P(b), P(a), P(p1.s)) == Sign::negative) continue;
          for (std::uint32_t q2 = cb->first; q2 < cb->first + cb->count; ++q2) {
            const Pair& p2 = pairs[q2];
            if (orient2d(P(p2.t), P(b), P(a)) == Sign::negative ||
                orient2d(P(p1.t), P(k), P(p2.s)) == Sign::negative)
              continue;
            consider(f_of(a, k) + f_of(k, b) - 1, Pair{p1.s, p2.t, k, q1, false, false, q2});
          }
        }
      }
      if ((k == a + 1 || reflex[a] || reflex[k]) && valid(a, k) && f_of(a, k) != kNone) {
        const std::uint32_t fa = f_of(a, k);
        if (valid(k, b)) {
          const std::uint32_t fb = f_of(k, b);
          std::uint32_t pick = kNone;
          if (fb != kNone && k + 1 < b) {
            const Cell* c = cell(k, b);
            for (std::uint32_t q = c->first; q < c->first + c->count; ++q) {
              const Pair& pr = pairs[q];
              if (orient2d(P(a), P(k), P(pr.s)) == Sign::negative ||
                  orient2d(P(pr.t), P(b), P(a)) == Sign::negative)
                continue;
              if (pick == kNone || narrower_at_b(b, pr.t, pairs[pick].t)) pick = q;
            }
          }
          if (fb != kNone && pick != kNone)
            consider(fa + fb, Pair{k, pairs[pick].t, k, pick, true});
          else if (fb != kNone)
            consider(fa + fb + 1, Pair{k, k, k, kNone, true});
        } else if (reflex[b]) {
          std::uint32_t t1 = kNone;
          const std::uint32_t line = straight(b, k, t1);
          if (line != kNone) consider(fa + line + 1, Pair{k, t1, k, kNone, true, true});
        }
      }
    }
    if (best == kNone) return;
    me->f = best;
    me->first = static_cast<std::uint32_t>(pairs.size());
    // Keep the pairs no other pair beats at both ends (narrower or as narrow).
    for (std::size_t x = 0; x < cand.size(); ++x) {
      bool dominated = false;
      for (std::size_t y = 0; y < cand.size() && !dominated; ++y) {
        if (x == y) continue;
        const bool a_le = !narrower_at_a(a, cand[x].s, cand[y].s);
        const bool b_le = !narrower_at_b(b, cand[x].t, cand[y].t);
        const bool a_lt = narrower_at_a(a, cand[y].s, cand[x].s);
        const bool b_lt = narrower_at_b(b, cand[y].t, cand[x].t);
        // y at least as narrow at both ends, strictly at one, or an identical earlier pair.
        dominated = a_le && b_le && (a_lt || b_lt || y < x);
      }
      if (!dominated) pairs.push_back(cand[x]);
    }
    me->count = static_cast<std::uint32_t>(pairs.size() - me->first);
  }

  // The a-b piece's vertices from a to b (pair q of (a, b)); other pieces go to out.
  void chain(std::uint32_t a, std::uint32_t b, std::uint32_t q, std::vector<std::uint32_t>& ch,
             ConvexPartition& out) {
    const Pair pr = pairs[q];
    const std::uint32_t k = pr.k;
    if (pr.child_b != kNone) {
      chain(a, k, pr.child, ch, out);  // a ... k
      std::vector<std::uint32_t> rest;
      chain(k, b, pr.child_b, rest, out);  // k ... b
      ch.insert(ch.end(), rest.begin() + 1, rest.end());
      return;
    }
    if (pr.line) {
      // The triangle a k b with the straight side (a k, or k b) through its line's vertices.
      std::vector<std::uint32_t> line;
      const std::uint32_t from = pr.option_b ? b : a;
      std::uint32_t x = k;
      line.push_back(k);
      while (x != from) {
        const Cell* c = cell(std::min(from, x), std::max(from, x));
        x = c->visible ? from : (from < x ? c->via_small : c->via_large);
        line.push_back(x);
      }
      std::reverse(line.begin(), line.end());  // from ... k
      for (std::size_t i = 0; i + 1 < line.size(); ++i)
        finish(std::min(line[i], line[i + 1]), std::max(line[i], line[i + 1]), out);
      if (pr.option_b) {
        ch.push_back(a);
        for (std::size_t i = line.size(); i-- > 0;) ch.push_back(line[i]);  // k ... b
        finish(a, k, out);
      } else {
        ch.insert(ch.end(), line.begin(), line.end());  // a ... k
        ch.push_back(b);
        finish(k, b, out);
      }
      return;
    }
    if (pr.option_b) {
      ch.push_back(a);
      if (pr.child != kNone) {
        chain(k, b, pr.child, ch, out);
      } else {
        ch.push_back(k);
        ch.push_back(b);
        finish(k, b, out);
      }
      finish(a, k, out);
    } else {
      if (pr.child != kNone) {
        chain(a, k, pr.child, ch, out);
      } else {
        ch.push_back(a);
        ch.push_back(k);
        finish(a, k, out);
      }
      ch.push_back(b);
      finish(k, b, out);
    }
  }

  // The sub-polygon cut off by diagonal a b, decomposed on its own (nothing for an edge).
  void finish(std::uint32_t a, std::uint32_t b, ConvexPartition& out) {
    if (b == a + 1) return;
    std::vector<std::uint32_t> ch;
    chain(a, b, cell(a, b)->first, ch, out);
    for (const std::uint32_t v : ch) out.vertices.push_back(verts[v]);
    out.piece_ends.push_back(static_cast<std::uint32_t>(out.vertices.size()));
    out.diagonals.push_back({verts[a], verts[b]});
  }
};

template <Real T>
ConvexPartition min_convex_partition(std::span<const Vec2<T>> points,
                                     std::span<const std::uint32_t> ring_ends,
                                     MinConvexMethod method) {
  ConvexPartition r;
  if (ring_ends.size() > 1) {
    r.status = Status::invalid_input;
    return r;
  }
  std::vector<std::uint32_t> verts, ends;
  r.status = triangulate_detail::prepare_rings(points, ring_ends, true, verts, ends);
  if (r.status != Status::ok) return r;
  if (triangulate_detail::rings_cross(points, verts, ends)) {
    r.status = Status::invalid_topology;
    return r;
  }
  const std::uint32_t n = static_cast<std::uint32_t>(verts.size());
  const auto P = [&](std::uint32_t k) -> const Vec2<T>& { return points[verts[k]]; };
  // Keil's tables are kept for reflex vertices and, to cover pieces with a straight angle
  // there, for straight ones (orient2d = 0): "reflex" below means not strictly convex.
  std::vector<std::uint8_t> reflex(n);
  std::uint32_t reflex_count = 0, strictly_reflex = 0, first_reflex = 0;
  for (std::uint32_t k = 0; k < n; ++k) {
    const Sign turn = orient2d(P((k + n - 1) % n), P(k), P((k + 1) % n));
    reflex[k] = turn != Sign::positive;
    strictly_reflex += turn == Sign::negative;
    if (reflex[k] && reflex_count++ == 0) first_reflex = k;
  }
  if (strictly_reflex == 0) {
    r.vertices = verts;
    r.piece_ends.push_back(n);
    return r;
  }
  if (method == MinConvexMethod::keil) {
    if (std::uint64_t(reflex_count) * n > min_convex_partition_keil_cells) {
      r = convex_partition(points, ring_ends);
      if (r.status == Status::ok) r.status = Status::limit_exceeded;
      return r;
    }
    // Position 0 reflex: the whole polygon is then the sub-polygon of the edge n-1 -> 0.
    std::rotate(verts.begin(), verts.begin() + first_reflex, verts.end());
    std::rotate(reflex.begin(), reflex.begin() + first_reflex, reflex.end());
    KeilRun<T> run{points, verts, n, reflex, std::vector<std::uint32_t>(n, KeilRun<T>::kNone),
                   {},     {}};
    std::uint32_t rows = 0;
    for (std::uint32_t k = 0; k < n; ++k)
      if (reflex[k]) run.row_of[k] = rows++;
    run.cells.resize(std::size_t(rows) * n);
    // Visibility through a triangulation of the same cleaned ring (positions from indices).
    const PolygonTriangulation tri = triangulate_monotone(points, ring_ends);
    bool mapped = tri.status == Status::ok;
    std::vector<std::array<std::uint32_t, 3>> tris;
    if (mapped) {
      std::vector<std::uint32_t> pos(points.size(), KeilRun<T>::kNone);
      for (std::uint32_t k = 0; k < n; ++k) pos[verts[k]] = k;
      for (const auto& t : tri.triangles) {
        const std::array<std::uint32_t, 3> q{pos[t[0]], pos[t[1]], pos[t[2]]};
        if (q[0] == KeilRun<T>::kNone || q[1] == KeilRun<T>::kNone || q[2] == KeilRun<T>::kNone)
          mapped = false;
        tris.push_back(q);
      }
    }
    if (!mapped) {
      // Not a simple ring after all (e.g. a vertex on an edge): the direct programme decides.
      return n <= min_convex_partition_limit
                 ? min_convex_partition(points, ring_ends, MinConvexMethod::direct)
                 : ConvexPartition{Status::invalid_topology, {}, {}, {}};
    }
    run.visibility(tris);
    for (std::uint32_t len = 2; len < n; ++len)
      for (std::uint32_t a = 0; a + len < n; ++a) run.solve(a, a + len);
    const auto* top = run.cell(0, n - 1);
    if (top->f == KeilRun<T>::kNone || top->count == 0) {
      r.status = Status::invalid_topology;  // unreachable for a simple polygon
      return r;
    }
    std::vector<std::uint32_t> ch;
    run.chain(0, n - 1, top->first, ch, r);
    for (const std::uint32_t v : ch) r.vertices.push_back(verts[v]);
    r.piece_ends.push_back(static_cast<std::uint32_t>(r.vertices.size()));
    return r;
  }
  if (n > min_convex_partition_limit) {
    r = convex_partition(points, ring_ends);
    if (r.status == Status::ok) r.status = Status::limit_exceeded;
    return r;
  }

  // valid[a * n + b], a < b: a b is an edge or a diagonal (inside the cones at both ends, no
  // other boundary point on the closed segment).
  std::vector<std::uint8_t> valid(std::size_t(n) * n, 0);
  const auto in_cone = [&](std::uint32_t a, std::uint32_t b) {
    const Vec2<T>&p = P((a + n - 1) % n), &v = P(a), &q = P((a + 1) % n), &w = P(b);
    const bool left_out = orient2d(v, q, w) == Sign::positive;
    const bool left_in = orient2d(p, v, w) == Sign::positive;
    return orient2d(p, v, q) != Sign::negative ? (left_out && left_in) : (left_out || left_in);
  };
  for (std::uint32_t a = 0; a < n; ++a) {
    for (std::uint32_t b = a + 1; b < n; ++b) {
      bool ok = b == a + 1 || (a == 0 && b == n - 1);
      if (!ok && in_cone(a, b) && in_cone(b, a)) {
        ok = true;
        for (std::uint32_t e = 0; e < n && ok; ++e) {
          const std::uint32_t f = (e + 1) % n;
          if (e == a || e == b || f == a || f == b) continue;
          ok = !segments_meet(P(a), P(b), P(e), P(f));
        }
      }
      valid[std::size_t(a) * n + b] = ok;
    }
  }
  const auto at = [n](std::uint32_t a, std::uint32_t b) { return std::size_t(a) * n + b; };
  constexpr std::uint32_t inf = std::numeric_limits<std::uint32_t>::max() / 4;
  // f[i, j]: minimum pieces of the sub-polygon i..j closed by j i; chain[i, j]: the vertices
  // of its piece through the diagonal, i first.
  std::vector<std::uint32_t> f(std::size_t(n) * n, inf), g(std::size_t(n) * n),
      back(std::size_t(n) * n);
  std::vector<std::vector<std::uint32_t>> chain(std::size_t(n) * n);
  for (std::uint32_t i = 0; i + 1 < n; ++i) f[at(i, i + 1)] = 0;
  for (std::uint32_t len = 2; len < n; ++len) {
    for (std::uint32_t i = 0; i + len < n; ++i) {
      const std::uint32_t j = i + len;
      if (!valid[at(i, j)]) continue;
      // g[a, b]: least sum of f over a convex chain i ... a b (b < j), convex at i against j.
      for (std::uint32_t a = i; a <= j; ++a)
        for (std::uint32_t b = a + 1; b <= j; ++b) g[at(a, b)] = inf;
      for (std::uint32_t b = i + 1; b < j; ++b)
        if (valid[at(i, b)] && orient2d(P(j), P(i), P(b)) != Sign::negative) {
          g[at(i, b)] = f[at(i, b)];
          back[at(i, b)] = i;
        }
      for (std::uint32_t b = i + 1; b < j; ++b) {
        for (std::uint32_t a = i; a < b; ++a) {
          const std::uint32_t ga = g[at(a, b)];
          if (ga >= inf) continue;
          for (std::uint32_t c = b + 1; c <= j; ++c) {
            if (!valid[at(b, c)] || orient2d(P(a), P(b), P(c)) == Sign::negative) continue;
            const std::uint32_t cand = ga + f[at(b, c)];
            if (cand < g[at(b, c)]) {
              g[at(b, c)] = cand;
              back[at(b, c)] = a;
            }
          }
        }
      }
      std::uint32_t best = inf, best_a = 0;
      for (std::uint32_t a = i + 1; a < j; ++a)
        if (g[at(a, j)] < best && orient2d(P(a), P(j), P(i)) != Sign::negative) {
          best = g[at(a, j)];
          best_a = a;
        }
      if (best >= inf) continue;  // cannot happen: a triangulation is a convex partition
      f[at(i, j)] = best + 1;
      std::vector<std::uint32_t>& ch = chain[at(i, j)];
      std::uint32_t a = best_a, b = j;
      ch.push_back(j);
      while (a != i) {
        ch.push_back(a);
        const std::uint32_t pa = back[at(a, b)];
        b = a;
        a = pa;
      }
      ch.push_back(i);
      std::reverse(ch.begin(), ch.end());
    }
  }
  if (f[at(0, n - 1)] >= inf) {
    r.status = Status::invalid_topology;  // unreachable for a simple polygon
    return r;
  }
  std::vector<std::array<std::uint32_t, 2>> pending{{0, n - 1}};
  while (!pending.empty()) {
    const auto [i, j] = pending.back();
    pending.pop_back();
    const std::vector<std::uint32_t>& ch = chain[at(i, j)];
    for (std::size_t k = 0; k < ch.size(); ++k) {
      r.vertices.push_back(verts[ch[k]]);
      if (k + 1 < ch.size() && ch[k + 1] > ch[k] + 1) {
        r.diagonals.push_back({verts[ch[k]], verts[ch[k + 1]]});
        pending.push_back({ch[k], ch[k + 1]});
      }
    }
    r.piece_ends.push_back(static_cast<std::uint32_t>(r.vertices.size()));
  }
  return r;
}

template ConvexPartition convex_partition<float>(std::span<const Vec2<float>>,
                                                 std::span<const std::uint32_t>);
template ConvexPartition convex_partition<double>(std::span<const Vec2<double>>,
                                                  std::span<const std::uint32_t>);
template ConvexPartition min_convex_partition<float>(std::span<const Vec2<float>>,
                                                     std::span<const std::uint32_t>,
                                                     MinConvexMethod);
template ConvexPartition min_convex_partition<double>(std::span<const Vec2<double>>,
                                                      std::span<const std::uint32_t>,
                                                      MinConvexMethod);

}  // namespace locus
