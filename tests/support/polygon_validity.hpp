// SPDX-License-Identifier: BSL-1.0
#pragma once
// An independent validity checker for polygon-boolean output (tests only; shares nothing with
// src/boolean). Brute force and exact: orient2d signs on the output coordinates, GMP rationals
// for areas and point-in-ring tests. A multipolygon is valid when
//   - every ring has >= 3 vertices, pairwise distinct (no repeated closing vertex);
//   - no two edges cross, overlap or touch, except at a vertex both share; within one ring only
//     consecutive edges meet (at their shared vertex): rings are simple, not self-touching;
//   - outer rings have positive exact signed area (CCW), holes negative (CW);
//   - every hole lies inside its outer ring and outside the polygon's other holes, and no edge
//     of one polygon lies inside another polygon (interiors pairwise disjoint): checked on edge
//     midpoints, which lie on no other edge once the edges meet only at vertices.
// Returns "" when valid, else what is wrong. Cost O(E^2) for E edges: keep test outputs small.

#include <gmpxx.h>

#include <locus/core/predicates.hpp>
#include <locus/primitives/polygon.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace locus_test {

template <class T>
mpq_class exact_twice_area(const std::vector<locus::Vec2<T>>& r) {
  mpq_class s = 0;
  for (std::size_t i = 0, n = r.size(); i < n; ++i) {
    const auto& p = r[i];
    const auto& q = r[(i + 1) % n];
    s += mpq_class(double(p.x)) * mpq_class(double(q.y)) -
         mpq_class(double(p.y)) * mpq_class(double(q.x));
  }
  return s;
}

/// Strictly inside ring r (even-odd crossing count), q not on r.
/// Winding number of p (not on any edge) around ring r, by exact orient2d.
template <class T>
int exact_winding(const std::vector<locus::Vec2<T>>& r, const locus::Vec2<T>& p) {
  int w = 0;
  for (std::size_t i = 0, n = r.size(); i < n; ++i) {
    const locus::Vec2<T>& a = r[i];
    const locus::Vec2<T>& b = r[(i + 1) % n];
    if (a.y <= p.y && p.y < b.y && locus::orient2d(a, b, p) == locus::Sign::positive) ++w;
    if (b.y <= p.y && p.y < a.y && locus::orient2d(a, b, p) == locus::Sign::negative) --w;
  }
  return w;
}

template <class T>
bool exact_ring_contains(const std::vector<locus::Vec2<T>>& r, const mpq_class& qx,
                         const mpq_class& qy) {
  bool in = false;
  const double qlo = qy.get_d();
  for (std::size_t i = 0, n = r.size(); i < n; ++i) {
    // get_d() truncates towards zero, within one ulp: edges entirely beyond that skip exactly.
    const double ylo = std::min(double(r[i].y), double(r[(i + 1) % n].y));
    const double yhi = std::max(double(r[i].y), double(r[(i + 1) % n].y));
    if (yhi < std::nextafter(qlo, -INFINITY) || ylo > std::nextafter(qlo, INFINITY)) continue;
    const mpq_class ax(double(r[i].x)), ay(double(r[i].y));
    const mpq_class bx(double(r[(i + 1) % n].x)), by(double(r[(i + 1) % n].y));
    if ((ay <= qy) != (by <= qy)) {
      const mpq_class o = (bx - ax) * (qy - ay) - (by - ay) * (qx - ax);
      if ((by > ay) ? o > 0 : o < 0) in = !in;
    }
  }
  return in;
}

/// Do closed segments ab and cd meet anywhere other than at one common endpoint?
template <class T>
bool segments_conflict(const locus::Vec2<T>& a, const locus::Vec2<T>& b, const locus::Vec2<T>& c,
                       const locus::Vec2<T>& d, bool may_share_endpoint) {
  using locus::orient2d;
  const int o1 = locus::to_int(orient2d(a, b, c)), o2 = locus::to_int(orient2d(a, b, d));
  const int o3 = locus::to_int(orient2d(c, d, a)), o4 = locus::to_int(orient2d(c, d, b));
  const auto on = [](const locus::Vec2<T>& p, const locus::Vec2<T>& q, const locus::Vec2<T>& x) {
    return std::min(p.x, q.x) <= x.x && x.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= x.y &&
           x.y <= std::max(p.y, q.y);
  };
  const bool shared = a == c || a == d || b == c || b == d;
  if (o1 == 0 && o2 == 0) {  // collinear: any overlap beyond a shared endpoint conflicts
    const int touching = int(on(a, b, c)) + int(on(a, b, d)) + int(on(c, d, a)) + int(on(c, d, b));
    if (touching == 0) return false;
    if (shared && touching == 2 && may_share_endpoint) {
      // exactly the shared endpoint: the other endpoints lie on opposite sides of it
      const locus::Vec2<T> s = (a == c || a == d) ? a : b;
      const locus::Vec2<T> p = s == a ? b : a, q = s == c ? d : c;
      return (p.x - s.x) * (q.x - s.x) + (p.y - s.y) * (q.y - s.y) > 0;
    }
    return true;
  }
  if (o1 * o2 > 0 || o3 * o4 > 0) return false;
  // They meet at one point; allowed only when it is a common endpoint.
  if (!may_share_endpoint || !shared) return true;
  // The meeting point is the shared endpoint iff no other endpoint lies on the other segment.
  if (o1 == 0 && c != a && c != b) return true;
  if (o2 == 0 && d != a && d != b) return true;
  if (o3 == 0 && a != c && a != d) return true;
  if (o4 == 0 && b != c && b != d) return true;
  return false;
}

template <class T>
std::string polygon_validity(const std::vector<locus::PolygonWithHoles2<T>>& polys) {
  struct Edge {
    locus::Vec2<T> a, b;
    std::size_t ring, index, ring_size;
  };
  std::vector<Edge> edges;
  std::vector<const std::vector<locus::Vec2<T>>*> rings;
  for (std::size_t pi = 0; pi < polys.size(); ++pi) {
    const auto& poly = polys[pi];
    for (std::size_t k = 0; k <= poly.holes.size(); ++k) {
      const auto& r = k == 0 ? poly.outer.vertices : poly.holes[k - 1].vertices;
      const std::string name = "polygon " + std::to_string(pi) + " ring " + std::to_string(k);
      if (r.size() < 3) return name + ": fewer than 3 vertices";
      for (std::size_t i = 0; i < r.size(); ++i) {
        if (!std::isfinite(r[i].x) || !std::isfinite(r[i].y)) return name + ": non-finite vertex";
        for (std::size_t j = i + 1; j < r.size(); ++j)
          if (r[i] == r[j]) return name + ": repeated vertex";
      }
      const mpq_class area = exact_twice_area(r);
      if (k == 0 && area <= 0) return name + ": outer ring not counter-clockwise";
      if (k > 0 && area >= 0) return name + ": hole not clockwise";
      for (std::size_t i = 0; i < r.size(); ++i)
        edges.push_back({r[i], r[(i + 1) % r.size()], rings.size(), i, r.size()});
      rings.push_back(&r);
    }
  }
  // All pairs of edges whose bounding boxes overlap (sorted by their least x, then swept).
  std::vector<std::size_t> by_x(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) by_x[i] = i;
  const auto lo_x = [&](std::size_t i) { return std::min(edges[i].a.x, edges[i].b.x); };
  std::sort(by_x.begin(), by_x.end(),
            [&](std::size_t i, std::size_t j) { return lo_x(i) < lo_x(j); });
  for (std::size_t ii = 0; ii < by_x.size(); ++ii) {
    const Edge& e = edges[by_x[ii]];
    const T hi_x = std::max(e.a.x, e.b.x);
    const T lo_y = std::min(e.a.y, e.b.y), hi_y = std::max(e.a.y, e.b.y);
    for (std::size_t jj = ii + 1; jj < by_x.size() && lo_x(by_x[jj]) <= hi_x; ++jj) {
      const Edge& f = edges[by_x[jj]];
      if (std::max(f.a.y, f.b.y) < lo_y || std::min(f.a.y, f.b.y) > hi_y) continue;
      bool may_share = true;
      if (e.ring == f.ring) {
        const std::size_t n = e.ring_size;
        may_share = (e.index + 1) % n == f.index || (f.index + 1) % n == e.index;
      }
      if (segments_conflict(e.a, e.b, f.a, f.b, may_share))
        return "edges conflict: ring " + std::to_string(e.ring) + " edge " +
               std::to_string(e.index) + " and ring " + std::to_string(f.ring) + " edge " +
               std::to_string(f.index);
    }
  }
  // Nesting, on edge midpoints.
  // Bounding boxes of the outer rings reject most midpoints exactly: a segment with both
  // endpoints beyond one side of the box has its midpoint beyond it too.
  std::vector<std::array<T, 4>> boxes;
  for (const auto& p : polys) {
    std::array<T, 4> b{p.outer.vertices[0].x, p.outer.vertices[0].y, p.outer.vertices[0].x,
                       p.outer.vertices[0].y};
    for (const auto& v : p.outer.vertices)
      b = {std::min(b[0], v.x), std::min(b[1], v.y), std::max(b[2], v.x), std::max(b[3], v.y)};
    boxes.push_back(b);
  }
  const auto outside_box = [&](std::size_t q, const locus::Vec2<T>& a, const locus::Vec2<T>& b) {
    const auto& x = boxes[q];
    return std::max(a.x, b.x) < x[0] || std::max(a.y, b.y) < x[1] || std::min(a.x, b.x) > x[2] ||
           std::min(a.y, b.y) > x[3];
  };
  const auto region_contains = [&](const locus::PolygonWithHoles2<T>& p, const mpq_class& x,
                                   const mpq_class& y) {
    if (!exact_ring_contains(p.outer.vertices, x, y)) return false;
    for (const auto& h : p.holes)
      if (exact_ring_contains(h.vertices, x, y)) return false;
    return true;
  };
  for (std::size_t pi = 0; pi < polys.size(); ++pi) {
    const auto& poly = polys[pi];
    for (std::size_t k = 0; k < poly.holes.size(); ++k) {
      const auto& h = poly.holes[k].vertices;
      const mpq_class mx = (mpq_class(double(h[0].x)) + mpq_class(double(h[1].x))) / 2;
      const mpq_class my = (mpq_class(double(h[0].y)) + mpq_class(double(h[1].y))) / 2;
      if (!exact_ring_contains(poly.outer.vertices, mx, my))
        return "polygon " + std::to_string(pi) + ": hole " + std::to_string(k) + " outside";
      for (std::size_t m = 0; m < poly.holes.size(); ++m)
        if (m != k && exact_ring_contains(poly.holes[m].vertices, mx, my))
          return "polygon " + std::to_string(pi) + ": nested holes";
    }
    for (std::size_t qi = 0; qi < polys.size(); ++qi) {
      if (qi == pi) continue;
      for (std::size_t k = 0; k <= poly.holes.size(); ++k) {
        const auto& r = k == 0 ? poly.outer.vertices : poly.holes[k - 1].vertices;
        for (std::size_t i = 0; i < r.size(); ++i) {
          const auto& a = r[i];
          const auto& b = r[(i + 1) % r.size()];
          if (outside_box(qi, a, b)) continue;
          const mpq_class mx = (mpq_class(double(a.x)) + mpq_class(double(b.x))) / 2;
          const mpq_class my = (mpq_class(double(a.y)) + mpq_class(double(b.y))) / 2;
          if (region_contains(polys[qi], mx, my))
            return "polygon " + std::to_string(pi) + " overlaps polygon " + std::to_string(qi);
        }
      }
    }
  }
  return "";
}

/// Exact area of a multipolygon (outer areas minus hole areas).
template <class T>
mpq_class exact_area(const std::vector<locus::PolygonWithHoles2<T>>& polys) {
  mpq_class s = 0;
  for (const auto& p : polys) {
    s += exact_twice_area(p.outer.vertices);
    for (const auto& h : p.holes) s += exact_twice_area(h.vertices);
  }
  return s / 2;
}

}  // namespace locus_test
