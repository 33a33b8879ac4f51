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
#include <limits>
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
/// are not crossings. A uniform grid over the edges' boxes: near O(n) on ordinary input.
template <Real T>
[[nodiscard]] bool rings_cross(std::span<const Vec2<T>> points,
                               const std::vector<std::uint32_t>& verts,
                               const std::vector<std::uint32_t>& ends) {
  std::vector<std::array<std::uint32_t, 2>> edges;
  std::uint32_t begin = 0;
  for (const std::uint32_t end : ends) {
    for (std::uint32_t i = begin; i < end; ++i)
      edges.push_back({verts[i], verts[i + 1 == end ? begin : i + 1]});
    begin = end;
  }
  if (edges.size() < 4) return false;
  double lx = std::numeric_limits<double>::infinity(), ly = lx, hx = -lx, hy = -lx;
  for (const std::uint32_t v : verts) {
    lx = std::min(lx, double(points[v].x) * 0.5);
    hx = std::max(hx, double(points[v].x) * 0.5);
    ly = std::min(ly, double(points[v].y) * 0.5);
    hy = std::max(hy, double(points[v].y) * 0.5);
  }
  const double w = hx - lx, h = hy - ly;
  const double cells = double(edges.size());
  double fx = w > 0 && h > 0 ? std::sqrt(cells * w / h) : (w > 0 ? cells : 1.0);
  fx = std::clamp(fx, 1.0, 2048.0);
  const double fy = std::clamp(h > 0 ? cells / fx : 1.0, 1.0, 2048.0);
  const auto gx = static_cast<std::uint32_t>(fx), gy = static_cast<std::uint32_t>(fy);
  double ix = w > 0 ? double(gx) / w : 0.0, iy = h > 0 ? double(gy) / h : 0.0;
  if (!std::isfinite(ix)) ix = 0;
  if (!std::isfinite(iy)) iy = 0;
  const auto cx = [&](T x) {
    const double c = (double(x) * 0.5 - lx) * ix;
    return c >= 1.0 ? std::min(gx - 1, static_cast<std::uint32_t>(c)) : 0u;
  };
  const auto cy = [&](T y) {
    const double c = (double(y) * 0.5 - ly) * iy;
    return c >= 1.0 ? std::min(gy - 1, static_cast<std::uint32_t>(c)) : 0u;
  };
  std::vector<std::uint32_t> start(std::size_t(gx) * gy + 1, 0), items;
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<std::uint32_t> fill;
    if (pass == 1) {
      for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
      items.resize(start.back());
      fill.assign(start.begin(), start.end() - 1);
    }
    for (std::uint32_t e = 0; e < edges.size(); ++e) {
      const Vec2<T>&a = points[edges[e][0]], &b = points[edges[e][1]];
      const std::uint32_t x0 = cx(std::min(a.x, b.x)), x1 = cx(std::max(a.x, b.x));
      const std::uint32_t y0 = cy(std::min(a.y, b.y)), y1 = cy(std::max(a.y, b.y));
      for (std::uint32_t y = y0; y <= y1; ++y)
        for (std::uint32_t x = x0; x <= x1; ++x) {
          const std::size_t c = std::size_t(y) * gx + x;
          if (pass == 0)
            ++start[c + 1];
          else
            items[fill[c]++] = e;
        }
    }
  }
  for (std::size_t c = 0; c + 1 < start.size(); ++c)
    for (std::uint32_t i = start[c]; i < start[c + 1]; ++i)
      for (std::uint32_t j = i + 1; j < start[c + 1]; ++j) {
        const auto& e = edges[items[i]];
        const auto& f = edges[items[j]];
        const Vec2<T>&a = points[e[0]], &b = points[e[1]], &p = points[f[0]], &q = points[f[1]];
        if (std::max(a.x, b.x) < std::min(p.x, q.x) || std::max(p.x, q.x) < std::min(a.x, b.x) ||
            std::max(a.y, b.y) < std::min(p.y, q.y) || std::max(p.y, q.y) < std::min(a.y, b.y))
          continue;
        const Sign o1 = orient2d(a, b, p), o2 = orient2d(a, b, q);
        if (o1 == Sign::zero || o2 == Sign::zero || o1 == o2) continue;
        const Sign o3 = orient2d(p, q, a), o4 = orient2d(p, q, b);
        if (o3 != Sign::zero && o4 != Sign::zero && o3 != o4) return true;
      }
  return false;
}

}  // namespace locus::triangulate_detail
