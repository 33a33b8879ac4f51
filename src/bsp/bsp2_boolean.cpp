// SPDX-License-Identifier: BSL-1.0
// Polygon booleans through 2D BSP trees (see include/locus/bsp/bsp2_boolean.hpp and
// docs/notes/bsp.md).

#include <locus/bsp/bsp2_boolean.hpp>

#include <locus/core/crossing.hpp>
#include <locus/core/predicates.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace locus {

namespace {

template <Real T>
struct Line {
  Vec2<T> a, b;
};

/// The source of a result edge: operand, edge, direction, and the two trees.
template <Real T>
struct Operands {
  const Bsp2<T>* tree[2];

  [[nodiscard]] Line<T> line(std::uint8_t operand, std::uint32_t e) const noexcept {
    const Bsp2<T>& t = *tree[operand];
    return {t.points()[t.edges()[e][0]], t.points()[t.edges()[e][1]]};
  }
  /// The exact direction of a result edge as two input points.
  [[nodiscard]] Line<T> direction(const Bsp2BooleanEdge<T>& r) const noexcept {
    const Line<T> l = line(r.operand, r.edge);
    return r.reversed ? Line<T>{l.b, l.a} : l;
  }
  /// Whether end x of result edge r and end y of result edge s are the same point (exact): an
  /// end is an input point (line == none) or X(carrier line, line of the other tree's edge).
  [[nodiscard]] bool same_point(const Bsp2BooleanEdge<T>& r, const Bsp2End<T>& x,
                                const Bsp2BooleanEdge<T>& s, const Bsp2End<T>& y) const noexcept {
    const bool xv = x.line == bsp2_none, yv = y.line == bsp2_none;
    if (xv && yv) return x.point == y.point;
    if (xv || yv) {
      const Bsp2BooleanEdge<T>& c = xv ? s : r;
      const Bsp2End<T>& cut = xv ? y : x;
      const Vec2<T>& p = xv ? x.point : y.point;
      const Line<T> f = line(c.operand, c.edge), g = line(1 - c.operand, cut.line);
      return orient2d(f.a, f.b, p) == Sign::zero && orient2d(g.a, g.b, p) == Sign::zero;
    }
    const Line<T> f = line(r.operand, r.edge), g = line(1 - r.operand, x.line);
    const Line<T> h = line(s.operand, s.edge), k = line(1 - s.operand, y.line);
    return side_of_crossing(f.a, f.b, g.a, g.b, h.a, h.b) == Sign::zero &&
           side_of_crossing(f.a, f.b, g.a, g.b, k.a, k.b) == Sign::zero;
  }
};

/// 0 for directions at a counter-clockwise angle in [0, pi) from r, else 1 (exact).
template <Real T>
int half(const Line<T>& r, const Line<T>& d) noexcept {
  const Sign s = turn2d(r.a, r.b, d.a, d.b);
  if (s != Sign::zero) return s == Sign::positive ? 0 : 1;
  return lexicographic_compare(r.a, r.b) == lexicographic_compare(d.a, d.b) ? 0 : 1;
}

/// Whether d1 comes before d2 counter-clockwise from r (angles in [0, 2 pi), exact).
template <Real T>
bool ccw_before(const Line<T>& r, const Line<T>& d1, const Line<T>& d2) noexcept {
  const int h1 = half(r, d1), h2 = half(r, d2);
  if (h1 != h2) return h1 < h2;
  return turn2d(d1.a, d1.b, d2.a, d2.b) == Sign::positive;
}

/// Chains the result edges into loops (see the header): exact end classes, then at each point
/// the unused outgoing edge turning most to the left.
template <Real T>
void assemble(const Operands<T>& ops, Bsp2BooleanResult<T>& r) {
  const std::size_t k = r.edges.size();
  // Classes of the 2k ends (2i start, 2i+1 end of edge i) by exact equality (union-find).
  // Only ends whose stored points are close enough to be the same exact point are compared: an
  // input point is stored exactly; a crossing within a few units in the last place of the
  // largest coordinate (t in [0, 1] from determinants of relative error 2 eps, then
  // a + t (b - a) in double, rounded to T), so `reach` bounds every stored crossing's error.
  std::vector<std::uint32_t> parent(2 * k);
  std::iota(parent.begin(), parent.end(), 0u);
  const auto find = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  double largest = 0;
  for (const Bsp2<T>* t : ops.tree)
    for (const Vec2<T>& p : t->points())
      largest = std::max(
          {largest, std::abs(static_cast<double>(p.x)), std::abs(static_cast<double>(p.y))});
  const double reach = 64.0 * static_cast<double>(std::numeric_limits<T>::epsilon()) * largest +
                       64.0 * static_cast<double>(std::numeric_limits<T>::denorm_min());
  const auto end_of = [&](std::uint32_t i) -> const Bsp2End<T>& {
    return r.edges[i / 2].end[i % 2];
  };
  const auto radius = [&](std::uint32_t i) { return end_of(i).line == bsp2_none ? 0.0 : reach; };
  std::vector<std::uint32_t> by_x(2 * k);
  std::iota(by_x.begin(), by_x.end(), 0u);
  std::sort(by_x.begin(), by_x.end(), [&](std::uint32_t i, std::uint32_t j) {
    return end_of(i).point.x < end_of(j).point.x;
  });
  for (std::size_t u = 0; u < by_x.size(); ++u) {
    const std::uint32_t i = by_x[u];
    const Vec2<T>& pi = end_of(i).point;
    for (std::size_t v = u + 1; v < by_x.size(); ++v) {
      const std::uint32_t j = by_x[v];
      const Vec2<T>& pj = end_of(j).point;
      const double dx = static_cast<double>(pj.x) - static_cast<double>(pi.x);
      if (dx > radius(i) + reach) break;
      const double near = radius(i) + radius(j);
      if (dx > near || std::abs(static_cast<double>(pj.y) - static_cast<double>(pi.y)) > near)
        continue;
      if (find(i) == find(j)) continue;
      const Bsp2BooleanEdge<T>&ei = r.edges[i / 2], &ej = r.edges[j / 2];
      if (ops.same_point(ei, ei.end[i % 2], ej, ej.end[j % 2])) parent[find(i)] = find(j);
    }
  }
  std::vector<std::vector<std::uint32_t>> out(2 * k);
  for (std::uint32_t i = 0; i < k; ++i) out[find(2 * i)].push_back(i);
  std::vector<char> used(k, 0);
  std::vector<std::uint32_t> loop;
  for (std::uint32_t first = 0; first < k; ++first) {
    if (used[first]) continue;
    loop.assign(1, first);
    used[first] = 1;
    const std::uint32_t home = find(2 * first);
    std::uint32_t cur = first;
    bool ok = true;
    while (find(2 * cur + 1) != home) {
      const Line<T> d = ops.direction(r.edges[cur]), back{d.b, d.a};
      std::uint32_t best = bsp2_none;
      for (const std::uint32_t c : out[find(2 * cur + 1)]) {
        if (used[c]) continue;
        if (best == bsp2_none ||
            ccw_before(back, ops.direction(r.edges[best]), ops.direction(r.edges[c])))
          best = c;
      }
      if (best == bsp2_none) {
        ok = false;
        break;
      }
      used[best] = 1;
      loop.push_back(best);
      cur = best;
    }
    if (!ok) {
      r.closed = false;
      continue;
    }
    r.loop_edges.insert(r.loop_edges.end(), loop.begin(), loop.end());
    r.loop_ends.push_back(static_cast<std::uint32_t>(r.loop_edges.size()));
  }
}

template <Real T>
Bsp2BooleanEdge<T> make_edge(const Bsp2Piece<T>& piece, std::uint8_t operand, std::uint32_t edge,
                             bool reversed) {
  Bsp2BooleanEdge<T> e;
  e.end = reversed ? std::array<Bsp2End<T>, 2>{piece.end[1], piece.end[0]} : piece.end;
  // `vertex` would index either tree's points; the exact point or `line` says all.
  for (Bsp2End<T>& x : e.end) x.vertex = bsp2_none;
  e.operand = operand;
  e.reversed = reversed;
  e.edge = edge;
  return e;
}

bool is_empty_set(Status s) noexcept {
  return s == Status::empty_input || s == Status::degenerate_input;
}

}  // namespace

template <Real T>
Bsp2BooleanResult<T> bsp2_boolean(Bsp2Op op, const Bsp2<T>& a, const Bsp2<T>& b) {
  Bsp2BooleanResult<T> r;
  for (const Status s : {a.status(), b.status()})
    if (s != Status::ok && !is_empty_set(s)) {
      r.status = s;
      return r;
    }
  r.status = Status::ok;
  const Operands<T> ops{{&a, &b}};
  std::vector<Bsp2BooleanEdge<T>> shared_b;  // B's copy of the segments (intersection)
  for (std::uint8_t o = 0; o < 2; ++o) {
    const Bsp2<T>& own = *ops.tree[o];
    const Bsp2<T>& other = *ops.tree[1 - o];
    for (std::uint32_t e = 0; e < own.edges().size(); ++e) {
      const Line<T> l = ops.line(o, e);
      const Bsp2SegmentPartition<T> part = other.partition(l.a, l.b);
      for (const Bsp2Piece<T>& piece : part.pieces) {
        const auto keep = [&](bool reversed) {
          r.edges.push_back(make_edge(piece, o, e, reversed));
        };
        switch (piece.location) {
          case Bsp2Location::inside:
            if (op == Bsp2Op::intersection) keep(false);
            if (op == Bsp2Op::exclusive_or || (op == Bsp2Op::difference && o == 1)) keep(true);
            break;
          case Bsp2Location::outside:
            if (op == Bsp2Op::union_ || op == Bsp2Op::exclusive_or ||
                (op == Bsp2Op::difference && o == 0))
              keep(false);
            break;
          case Bsp2Location::coincident_same:
            if (o == 0 && (op == Bsp2Op::intersection || op == Bsp2Op::union_)) keep(false);
            break;
          case Bsp2Location::coincident_opposite:
            if (o == 0 && op == Bsp2Op::difference) keep(false);
            if (op == Bsp2Op::intersection) {
              if (o == 0)
                r.segments.push_back(make_edge(piece, o, e, false));
              else
                shared_b.push_back(make_edge(piece, o, e, false));
            }
            break;
        }
      }
    }
  }
  if (op == Bsp2Op::intersection) {
    // Touching points: input vertices on the other operand's boundary that start or end no
    // result edge and no shared segment (of either operand's copy).
    std::vector<Bsp2BooleanEdge<T>> marks;  // zero-length "edges" at the candidate vertices
    for (std::uint8_t o = 0; o < 2; ++o) {
      const Bsp2<T>& own = *ops.tree[o];
      const Bsp2<T>& other = *ops.tree[1 - o];
      for (std::uint32_t e = 0; e < own.edges().size(); ++e) {
        const Vec2<T> v = own.points()[own.edges()[e][0]];
        if (other.classify(v) != Side::boundary) continue;
        Bsp2BooleanEdge<T> m;
        m.end[0] = m.end[1] = {v, bsp2_none, bsp2_none};
        m.operand = o;
        m.edge = e;
        const auto touches = [&](const std::vector<Bsp2BooleanEdge<T>>& list) {
          for (const Bsp2BooleanEdge<T>& s : list)
            for (const Bsp2End<T>& x : s.end)
              if (ops.same_point(m, m.end[0], s, x)) return true;
          return false;
        };
        if (touches(r.edges) || touches(r.segments) || touches(shared_b) || touches(marks))
          continue;
        marks.push_back(m);
        r.points.push_back(v);
      }
    }
  }
  assemble(ops, r);
  return r;
}

template <Real T>
Bsp2BooleanResult<T> bsp2_negation(const Bsp2<T>& a) {
  Bsp2BooleanResult<T> r;
  if (a.status() != Status::ok && !is_empty_set(a.status())) {
    r.status = a.status();
    return r;
  }
  r.status = Status::ok;
  for (std::uint32_t e = 0; e < a.edges().size(); ++e) {
    const auto ed = a.edges()[e];
    const Bsp2Piece<T> piece{
        {{{a.points()[ed[0]], bsp2_none, bsp2_none}, {a.points()[ed[1]], bsp2_none, bsp2_none}}},
        Bsp2Location::coincident_same};
    r.edges.push_back(make_edge(piece, 0, e, true));
  }
  const Operands<T> ops{{&a, &a}};
  assemble(ops, r);
  return r;
}

template Bsp2BooleanResult<float> bsp2_boolean(Bsp2Op, const Bsp2<float>&, const Bsp2<float>&);
template Bsp2BooleanResult<double> bsp2_boolean(Bsp2Op, const Bsp2<double>&, const Bsp2<double>&);
template Bsp2BooleanResult<float> bsp2_negation(const Bsp2<float>&);
template Bsp2BooleanResult<double> bsp2_negation(const Bsp2<double>&);

}  // namespace locus
