// SPDX-License-Identifier: BSL-1.0
#pragma once
// Ring validation and clean-up shared by the polygon triangulations (contract:
// include/locus/triangulate/polygon_triangulation.hpp). Internal to src/triangulate.

#include <locus/core/predicates.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>

#include <cstdint>
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
