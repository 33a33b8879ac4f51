// SPDX-License-Identifier: BSL-1.0
// The BSP tree of a polygon (see include/locus/bsp/bsp2.hpp and docs/notes/bsp.md).

#include <locus/bsp/bsp2.hpp>

#include <locus/core/crossing.hpp>
#include <locus/core/predicates.hpp>

#include "../triangulate/rings.hpp"

#include <algorithm>
#include <limits>

namespace locus {

namespace {

template <Real T>
struct LineRef {
  Vec2<T> a, b;
};

enum class Rel { front, back, on, straddle };

/// The exact decisions of the header's rule: ends of fragments on a line f (two input points).
template <Real T>
struct Exact {
  std::span<const Vec2<T>> pts;
  std::span<const std::array<std::uint32_t, 2>> edges;

  [[nodiscard]] LineRef<T> line_of(std::uint32_t e) const noexcept {
    return {pts[edges[e][0]], pts[edges[e][1]]};
  }
  /// Side of the end x (on line f) of the line L.
  [[nodiscard]] Sign side(const LineRef<T>& f, const Bsp2End<T>& x,
                          const LineRef<T>& l) const noexcept {
    if (x.line == bsp2_none) return orient2d(l.a, l.b, x.point);
    const LineRef<T> s = line_of(x.line);
    return side_of_crossing(f.a, f.b, s.a, s.b, l.a, l.b);
  }
  /// sign(t_y - t_x) for two ends on the line f, t along f.b - f.a.
  [[nodiscard]] Sign order(const LineRef<T>& f, const Bsp2End<T>& x,
                           const Bsp2End<T>& y) const noexcept {
    const bool xv = x.line == bsp2_none, yv = y.line == bsp2_none;
    if (xv && yv) return lexicographic_compare(x.point, y.point) * lexicographic_compare(f.a, f.b);
    if (xv) {
      const LineRef<T> s = line_of(y.line);
      return -(orient2d(s.a, s.b, x.point) * turn2d(s.a, s.b, f.a, f.b));
    }
    if (yv) {
      const LineRef<T> s = line_of(x.line);
      return orient2d(s.a, s.b, y.point) * turn2d(s.a, s.b, f.a, f.b);
    }
    if (x.line == y.line) return Sign::zero;
    const LineRef<T> sx = line_of(x.line), sy = line_of(y.line);
    return compare_crossing_params(f.a, f.b, f.a, sx.a, sx.b, sy.a, sy.b);
  }
  /// Where the piece x0 x1 of line f lies relative to the line L; s0 gets the side of x0.
  [[nodiscard]] Rel relate(const LineRef<T>& f, const Bsp2End<T>& x0, const Bsp2End<T>& x1,
                           const LineRef<T>& l, Sign& s0) const noexcept {
    s0 = side(f, x0, l);
    const Sign s1 = side(f, x1, l);
    if (s0 == Sign::zero && s1 == Sign::zero) return Rel::on;
    if (s0 != Sign::negative && s1 != Sign::negative) return Rel::front;
    if (s0 != Sign::positive && s1 != Sign::positive) return Rel::back;
    return Rel::straddle;
  }
  /// The end where line f is cut by edge e's line (point rounded; f and L not parallel).
  [[nodiscard]] Bsp2End<T> cut(const LineRef<T>& f, std::uint32_t e) const noexcept {
    const LineRef<T> l = line_of(e);
    const double num = turn2d_value(l.a, l.b, l.a, f.a), den = turn2d_value(l.a, l.b, f.b, f.a);
    const double t = num / den;
    const double ax = static_cast<double>(f.a.x), ay = static_cast<double>(f.a.y);
    const Vec2<T> p{static_cast<T>(ax + t * (static_cast<double>(f.b.x) - ax)),
                    static_cast<T>(ay + t * (static_cast<double>(f.b.y) - ay))};
    return {p, e, bsp2_none};
  }
  /// Whether two edges' directions agree (their lines coincide): lexicographic order.
  [[nodiscard]] static bool same_direction(const LineRef<T>& f, const LineRef<T>& g) noexcept {
    return lexicographic_compare(f.a, f.b) == lexicographic_compare(g.a, g.b);
  }
};

}  // namespace

template <Real T>
Status Bsp2<T>::build(std::span<const Vec2<T>> points, std::span<const std::uint32_t> ring_ends,
                      Bsp2Options options) {
  points_.assign(points.begin(), points.end());
  edges_.clear();
  nodes_.clear();
  fragments_.clear();
  pending_.clear();
  pending_fragments_.clear();
  root_ = bsp2_outside;
  depth_ = 0;
  std::vector<std::uint32_t> verts, ends;
  status_ = triangulate_detail::prepare_rings(std::span<const Vec2<T>>(points_), ring_ends, true,
                                              verts, ends);
  if (status_ != Status::ok) return status_;
  std::uint32_t begin = 0;
  for (const std::uint32_t end : ends) {
    for (std::uint32_t i = begin; i < end; ++i)
      edges_.push_back({verts[i], verts[i + 1 == end ? begin : i + 1]});
    begin = end;
  }
  const Exact<T> ex{points_, edges_};

  struct Task {
    std::vector<Bsp2Fragment<T>> frags;
    std::int32_t parent;
    bool front;
    std::uint32_t depth;
  };
  std::vector<Task> stack;
  {
    Task all{{}, -1, true, 1};
    for (std::uint32_t e = 0; e < edges_.size(); ++e) {
      const std::uint32_t a = edges_[e][0], b = edges_[e][1];
      all.frags.push_back({e, {{{points_[a], bsp2_none, a}, {points_[b], bsp2_none, b}}}});
    }
    stack.push_back(std::move(all));
  }
  const std::uint32_t sample = std::max<std::uint32_t>(options.sample, 1);
  while (!stack.empty()) {
    Task task = std::move(stack.back());
    stack.pop_back();
    const auto link = [&](std::int32_t child) {
      if (task.parent < 0)
        root_ = child;
      else if (task.front)
        nodes_[static_cast<std::size_t>(task.parent)].front = child;
      else
        nodes_[static_cast<std::size_t>(task.parent)].back = child;
    };
    if (task.frags.empty()) {
      link(task.front ? bsp2_inside : bsp2_outside);
      continue;
    }
    if (options.max_nodes != 0 && nodes_.size() >= options.max_nodes) {
      pending_.push_back({task.parent, task.front,
                          static_cast<std::uint32_t>(pending_fragments_.size()),
                          static_cast<std::uint32_t>(task.frags.size())});
      pending_fragments_.insert(pending_fragments_.end(), task.frags.begin(), task.frags.end());
      link(bsp2_pending);
      continue;
    }
    depth_ = std::max(depth_, task.depth);
    const std::size_t m = task.frags.size();
    std::size_t pick = 0;
    if (options.split == Bsp2Split::balanced && m > 1) {
      std::uint64_t best = std::numeric_limits<std::uint64_t>::max();
      const std::size_t tries = std::min<std::size_t>(m, sample);
      for (std::size_t c = 0; c < tries; ++c) {
        const std::size_t k = c * m / tries;
        const LineRef<T> l = ex.line_of(task.frags[k].edge);
        std::uint64_t front = 0, back = 0, splits = 0;
        for (const Bsp2Fragment<T>& f : task.frags) {
          Sign s0;
          switch (ex.relate(ex.line_of(f.edge), f.end[0], f.end[1], l, s0)) {
            case Rel::front:
              ++front;
              break;
            case Rel::back:
              ++back;
              break;
            case Rel::straddle:
              ++splits;
              break;
            case Rel::on:
              break;
          }
        }
        const std::uint64_t cost =
            options.split_cost * splits + (front > back ? front - back : back - front);
        if (cost < best) {
          best = cost;
          pick = k;
        }
      }
    }
    const std::uint32_t split_edge = task.frags[pick].edge;
    const LineRef<T> l = ex.line_of(split_edge);
    const std::int32_t id = static_cast<std::int32_t>(nodes_.size());
    link(id);
    Bsp2Node node;
    node.edge = split_edge;
    node.first = static_cast<std::uint32_t>(fragments_.size());
    Task front{{}, id, true, task.depth + 1}, back{{}, id, false, task.depth + 1};
    for (const Bsp2Fragment<T>& f : task.frags) {
      const LineRef<T> fl = ex.line_of(f.edge);
      Sign s0;
      switch (ex.relate(fl, f.end[0], f.end[1], l, s0)) {
        case Rel::front:
          front.frags.push_back(f);
          break;
        case Rel::back:
          back.frags.push_back(f);
          break;
        case Rel::on:
          fragments_.push_back(f);
          break;
        case Rel::straddle: {
          const Bsp2End<T> c = ex.cut(fl, split_edge);
          Bsp2Fragment<T> f0{f.edge, {f.end[0], c}}, f1{f.edge, {c, f.end[1]}};
          (s0 == Sign::positive ? front : back).frags.push_back(f0);
          (s0 == Sign::positive ? back : front).frags.push_back(f1);
          break;
        }
      }
    }
    node.count = static_cast<std::uint32_t>(fragments_.size()) - node.first;
    node.front = node.back = bsp2_outside;
    nodes_.push_back(node);
    stack.push_back(std::move(back));
    stack.push_back(std::move(front));
  }
  return status_;
}

template <Real T>
Side Bsp2<T>::classify_at(std::int32_t node, const Vec2<T>& p) const noexcept {
  const Exact<T> ex{points_, edges_};
  while (node >= 0) {
    const Bsp2Node& n = nodes_[static_cast<std::size_t>(node)];
    const LineRef<T> l = ex.line_of(n.edge);
    const Sign s = orient2d(l.a, l.b, p);
    if (s == Sign::positive) {
      node = n.front;
    } else if (s == Sign::negative) {
      node = n.back;
    } else {
      const Bsp2End<T> q{p, bsp2_none, bsp2_none};
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
        const Bsp2Fragment<T>& f = fragments_[i];
        const LineRef<T> fl = ex.line_of(f.edge);
        if (ex.order(fl, f.end[0], q) != Sign::negative &&
            ex.order(fl, q, f.end[1]) != Sign::negative)
          return Side::boundary;
      }
      // Off the fragments the neighbourhood of p on the line is all inside or all outside, so
      // both subtrees agree; a disagreement (invalid input) is reported as boundary.
      const Side r1 = classify_at(n.front, p), r2 = classify_at(n.back, p);
      return r1 == r2 ? r1 : Side::boundary;
    }
  }
  return node == bsp2_inside ? Side::inside : Side::outside;
}

template <Real T>
Side Bsp2<T>::classify(const Vec2<T>& p) const noexcept {
  if (!is_finite(p) || status_ != Status::ok) return Side::outside;
  return classify_at(root_, p);
}

template <Real T>
Bsp2SegmentPartition<T> Bsp2<T>::partition(const Vec2<T>& s0, const Vec2<T>& s1) const {
  Bsp2SegmentPartition<T> r;
  if (!is_finite(s0) || !is_finite(s1)) {
    r.status = Status::non_finite_input;
    return r;
  }
  if (s0.x == s1.x && s0.y == s1.y) {
    r.status = Status::degenerate_input;
    return r;
  }
  const Bsp2End<T> e0{s0, bsp2_none, bsp2_none}, e1{s1, bsp2_none, bsp2_none};
  if (status_ != Status::ok) {
    r.status = status_;
    r.pieces.push_back({{e0, e1}, Bsp2Location::outside});
    return r;
  }
  r.status = Status::ok;
  const Exact<T> ex{points_, edges_};
  const LineRef<T> q{s0, s1};
  const auto emit = [&](const Bsp2End<T>& a, const Bsp2End<T>& b, Bsp2Location loc) {
    if (!r.pieces.empty() && r.pieces.back().location == loc)
      r.pieces.back().end[1] = b;
    else
      r.pieces.push_back({{a, b}, loc});
  };
  struct Lap {
    Bsp2End<T> lo, hi;
    bool same;
  };
  const auto walk = [&](const auto& self, std::int32_t node, const Bsp2End<T>& x0,
                        const Bsp2End<T>& x1) -> void {
    if (node < 0) {
      emit(x0, x1, node == bsp2_inside ? Bsp2Location::inside : Bsp2Location::outside);
      return;
    }
    const Bsp2Node& n = nodes_[static_cast<std::size_t>(node)];
    const LineRef<T> l = ex.line_of(n.edge);
    Sign side0;
    switch (ex.relate(q, x0, x1, l, side0)) {
      case Rel::front:
        self(self, n.front, x0, x1);
        return;
      case Rel::back:
        self(self, n.back, x0, x1);
        return;
      case Rel::straddle: {
        const Bsp2End<T> c = ex.cut(q, n.edge);
        self(self, side0 == Sign::positive ? n.front : n.back, x0, c);
        self(self, side0 == Sign::positive ? n.back : n.front, c, x1);
        return;
      }
      case Rel::on:
        break;
    }
    // On the splitting line: the overlaps with the node's fragments are coincident; the gaps
    // are off the boundary, so either subtree classifies them (the front one is used).
    std::vector<Lap> mine;
    for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
      const Bsp2Fragment<T>& f = fragments_[i];
      const bool same = Exact<T>::same_direction(q, ex.line_of(f.edge));
      mine.push_back({same ? f.end[0] : f.end[1], same ? f.end[1] : f.end[0], same});
    }
    std::sort(mine.begin(), mine.end(), [&](const Lap& a, const Lap& b) {
      return ex.order(q, a.lo, b.lo) == Sign::positive;
    });
    Bsp2End<T> cur = x0;
    for (const Lap& lap : mine) {
      const Bsp2End<T> lo = ex.order(q, cur, lap.lo) == Sign::positive ? lap.lo : cur;
      const Bsp2End<T> hi = ex.order(q, lap.hi, x1) == Sign::positive ? lap.hi : x1;
      if (ex.order(q, lo, hi) != Sign::positive) continue;
      if (ex.order(q, cur, lo) == Sign::positive) self(self, n.front, cur, lo);
      emit(lo, hi, lap.same ? Bsp2Location::coincident_same : Bsp2Location::coincident_opposite);
      cur = hi;
    }
    if (ex.order(q, cur, x1) == Sign::positive) self(self, n.front, cur, x1);
  };
  walk(walk, root_, e0, e1);
  return r;
}

template class Bsp2<float>;
template class Bsp2<double>;

}  // namespace locus
