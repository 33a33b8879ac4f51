// SPDX-License-Identifier: BSL-1.0
#pragma once
// Ring validation and clean-up shared by the polygon triangulations (contract:
// include/locus/triangulate/polygon_triangulation.hpp). Internal to src/triangulate.

#include <locus/core/predicates.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <memory_resource>
#include <set>
#include <span>
#include <vector>

namespace locus::triangulate_detail {

template <Real T>
[[nodiscard]] inline bool same_point(const Vec2<T>& a, const Vec2<T>& b) noexcept {
  return a.x == b.x && a.y == b.y;
}

/// p strictly between a and c, for collinear a, p, c: lexicographic order along the line.
template <Real T>
[[nodiscard]] inline bool strictly_between(const Vec2<T>& a, const Vec2<T>& p,
                                           const Vec2<T>& c) noexcept {
  const Sign s1 = lexicographic_compare(a, p);
  const Sign s2 = lexicographic_compare(p, c);
  return s1 != Sign::zero && s1 == s2;
}

/// The cleaned rings: `verts` holds the rings back to back (input indices), `ends` their ends;
/// ring 0 is the outer ring, counter-clockwise; the kept holes follow, clockwise. Holes with
/// zero area are dropped. Returns ok, or the status of the top of polygon_triangulation.hpp
/// (degenerate_input when the outer ring has zero area).
template <Real T>
[[nodiscard]] Status prepare_rings(std::span<const Vec2<T>> points,
                                   std::span<const std::uint32_t> ring_ends, bool keep_collinear,
                                   std::vector<std::uint32_t>& verts,
                                   std::vector<std::uint32_t>& ends) {
  verts.clear();
  ends.clear();
  if (ring_ends.empty() || points.empty()) return Status::empty_input;
  std::uint32_t begin = 0;
  for (const std::uint32_t end : ring_ends) {
    if (end < begin || end > points.size()) return Status::invalid_input;
    begin = end;
  }
  for (std::uint32_t i = 0; i < begin; ++i)
    if (!is_finite(points[i])) return Status::non_finite_input;
  if (ring_ends[0] == 0) return Status::empty_input;

  std::vector<std::uint32_t> prev, next;
  begin = 0;
  for (std::size_t k = 0; k < ring_ends.size(); ++k) {
    const std::uint32_t end = ring_ends[k];
    const std::uint32_t n = end - begin;
    const std::uint32_t first = begin;
    begin = end;
    if (n < 3) {
      if (k == 0) return Status::degenerate_input;
      continue;
    }
    prev.resize(n);
    next.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) {
      prev[i] = i == 0 ? n - 1 : i - 1;
      next[i] = i + 1 == n ? 0 : i + 1;
    }
    const auto pt = [&](std::uint32_t i) -> const Vec2<T>& { return points[first + i]; };
    std::uint32_t count = n, p = 0, stop = 0;
    bool again = false;
    // Remove merged duplicates, spike tips and (unless kept) straight-run middles until none is
    // left; a removal re-examines the previous vertex, whose neighbour changed.
    do {
      again = false;
      const std::uint32_t a = prev[p], c = next[p];
      bool drop = same_point(pt(a), pt(p)) || same_point(pt(p), pt(c));
      if (!drop && orient2d(pt(a), pt(p), pt(c)) == Sign::zero)
        drop = !keep_collinear || !strictly_between(pt(a), pt(p), pt(c));
      if (drop) {
        next[a] = c;
        prev[c] = a;
        --count;
        p = stop = a;
        if (count < 3) break;
        again = true;
      } else {
        p = c;
      }
    } while (again || p != stop);
    if (count < 3) {
      if (k == 0) return Status::degenerate_input;
      continue;
    }
    // The lexicographically smallest vertex is strictly convex in a ring without spikes, so its
    // turn gives the ring's orientation exactly.
    std::uint32_t m = p, q = p;
    do {
      if (lexicographic_compare(pt(q), pt(m)) == Sign::negative) m = q;
      q = next[q];
    } while (q != p);
    const bool ccw = orient2d(pt(prev[m]), pt(m), pt(next[m])) == Sign::positive;
    const bool forward = (k == 0) == ccw;
    q = m;
    do {
      verts.push_back(first + q);
      q = forward ? next[q] : prev[q];
    } while (q != m);
    ends.push_back(static_cast<std::uint32_t>(verts.size()));
  }
  return Status::ok;
}

}  // namespace locus::triangulate_detail

namespace locus::triangulate_detail {

/// Whether two edges of the rings (verts/ends as prepare_rings gives them) cross properly
/// (interiors meet in one point, exact orient2d). Touching at vertices and collinear overlaps
/// are not crossings. Shamos and Hoey's sweep: edges in a balanced tree ordered along the
/// sweep line, each new neighbour pair tested; O(n log n).
template <Real T>
[[nodiscard]] bool rings_cross(std::span<const Vec2<T>> points,
                               const std::vector<std::uint32_t>& verts,
                               const std::vector<std::uint32_t>& ends) {
  const std::uint32_t m = static_cast<std::uint32_t>(verts.size());
  if (m < 4) return false;
  std::vector<std::uint32_t> next(m), prev(m);
  std::uint32_t begin = 0;
  for (const std::uint32_t end : ends) {
    for (std::uint32_t i = begin; i < end; ++i) {
      next[i] = i + 1 == end ? begin : i + 1;
      prev[i] = i == begin ? end - 1 : i - 1;
    }
    begin = end;
  }
  const auto at = [&](std::uint32_t n) -> const Vec2<T>& { return points[verts[n]]; };
  // Sweep order: higher first, then further left, then node; rank[n] its position.
  struct Event {
    T y, x;
    std::uint32_t node;
  };
  std::vector<Event> events(m);
  for (std::uint32_t i = 0; i < m; ++i) events[i] = Event{at(i).y, at(i).x, i};
  std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) {
    if (a.y != b.y) return a.y > b.y;
    if (a.x != b.x) return a.x < b.x;
    return a.node < b.node;
  });
  std::vector<std::uint32_t> rank(m);
  for (std::uint32_t i = 0; i < m; ++i) rank[events[i].node] = i;
  // Edge e joins node e and next[e]; up/lo its endpoints in sweep order, stored flat so the
  // tree comparisons read one place.
  std::vector<Vec2<T>> up(m), lo(m);
  for (std::uint32_t e = 0; e < m; ++e) {
    const bool down = rank[e] < rank[next[e]];
    up[e] = at(down ? e : next[e]);
    lo[e] = at(down ? next[e] : e);
  }
  // orient2d with a shared endpoint (an exact zero the filter cannot certify) answered at once.
  const auto orient = [](const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& p) {
    if ((p.x == a.x && p.y == a.y) || (p.x == b.x && p.y == b.y)) return Sign::zero;
    return orient2d(a, b, p);
  };
  const auto crosses = [&](std::uint32_t e, std::uint32_t f) {
    const Vec2<T>&a = up[e], &b = lo[e], &p = up[f], &q = lo[f];
    const Sign o1 = orient(a, b, p), o2 = orient(a, b, q);
    if (o1 == Sign::zero || o2 == Sign::zero || o1 == o2) return false;
    const Sign o3 = orient2d(p, q, a), o4 = orient2d(p, q, b);
    return o3 != Sign::zero && o4 != Sign::zero && o3 != o4;
  };
  bool found = false;
  // Left to right along the sweep line, for edges that do not cross (a crossing met on the
  // way sets `found`, and the sweep stops at the next event).
  const auto less = [&](std::uint32_t e1, std::uint32_t e2) {
    if (e1 == e2) return false;
    const Vec2<T>&u1 = up[e1], &l1 = lo[e1], &u2 = up[e2], &l2 = lo[e2];
    const Sign a = orient(u1, l1, u2), b = orient(u1, l1, l2);
    if (a != Sign::negative && b != Sign::negative && (a != Sign::zero || b != Sign::zero))
      return true;
    if (a != Sign::positive && b != Sign::positive && (a != Sign::zero || b != Sign::zero))
      return false;
    if (a == Sign::zero && b == Sign::zero) return e1 < e2;
    const Sign c = orient(u2, l2, u1), d = orient(u2, l2, l1);
    if (c != Sign::zero && d != Sign::zero && c != d) found = true;
    return c != Sign::positive && d != Sign::positive;
  };
  // Tree nodes from a pool (no allocation per edge).
  std::pmr::unsynchronized_pool_resource pool;
  using Tree = std::pmr::set<std::uint32_t, decltype(less)>;
  Tree tree(less, &pool);
  using It = typename Tree::iterator;
  std::vector<It> where(m, tree.end());
  const auto check = [&](It a, It b) {
    if (a != tree.end() && b != tree.end() && crosses(*a, *b)) found = true;
  };
  for (const Event& event : events) {
    const std::uint32_t v = event.node;
    if (found) return true;
    // Edges ending here first.
    for (const std::uint32_t e : {prev[v], v}) {
      const bool finishes = e == v ? rank[v] > rank[next[v]] : rank[v] > rank[e];
      if (!finishes || where[e] == tree.end()) continue;
      const It after = tree.erase(where[e]);
      where[e] = tree.end();
      if (after != tree.begin()) check(std::prev(after), after);
    }
    for (const std::uint32_t e : {prev[v], v}) {
      const bool starts = e == v ? rank[v] < rank[next[v]] : rank[v] < rank[e];
      if (!starts) continue;
      const auto [it, inserted] = tree.insert(e);
      if (!inserted) continue;  // collinear overlap with the same key: not a proper crossing
      where[e] = it;
      if (it != tree.begin()) check(std::prev(it), it);
      check(it, std::next(it));
    }
  }
  return found;
}

}  // namespace locus::triangulate_detail
