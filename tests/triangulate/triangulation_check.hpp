// SPDX-License-Identifier: BSL-1.0
#pragma once
// Independent checks of a polygon triangulation, in GMP rationals: every triangle
// counter-clockwise, interiors pairwise disjoint (a separating edge line, SAT), no triangle
// edge crossing a polygon edge and no polygon vertex strictly inside a triangle, the centroids
// inside the polygon (even-odd), and the triangle areas summing exactly to the polygon's area
// (outer minus holes). Disjoint pieces inside the polygon with the polygon's total area cover
// it up to a set of measure zero.

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <locus/core/vec.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <sstream>
#include <string>
#include <vector>

namespace locus_test {

using Tri = std::array<std::uint32_t, 3>;

template <class T>
mpq_class orient_q(const locus::Vec2<T>& a, const locus::Vec2<T>& b, const locus::Vec2<T>& c) {
  const mpq_class ax(double(a.x)), ay(double(a.y));
  return (mpq_class(double(b.x)) - ax) * (mpq_class(double(c.y)) - ay) -
         (mpq_class(double(b.y)) - ay) * (mpq_class(double(c.x)) - ax);
}

/// The sign of orient_q: a conservative double filter (error below 4 eps of the terms' sum,
/// products far from underflow), else the rationals.
template <class T>
int orient_s(const locus::Vec2<T>& a, const locus::Vec2<T>& b, const locus::Vec2<T>& c) {
  const double l = (double(b.x) - double(a.x)) * (double(c.y) - double(a.y));
  const double r = (double(b.y) - double(a.y)) * (double(c.x) - double(a.x));
  const double det = l - r, bound = 1e-15 * (std::abs(l) + std::abs(r));
  if (std::isfinite(det) && std::abs(det) > bound && std::abs(det) > 1e-280)
    return det > 0 ? 1 : -1;
  return sgn(orient_q(a, b, c));
}

/// Twice the signed area of ring [b, e) of pts.
template <class T>
mpq_class twice_ring_area(std::span<const locus::Vec2<T>> pts, std::uint32_t b, std::uint32_t e) {
  mpq_class s = 0;
  for (std::uint32_t i = b; i < e; ++i) {
    const auto& p = pts[i];
    const auto& q = pts[i + 1 == e ? b : i + 1];
    s += mpq_class(double(p.x)) * mpq_class(double(q.y)) -
         mpq_class(double(q.x)) * mpq_class(double(p.y));
  }
  return s;
}

/// Twice the polygon's area: |outer| minus |hole| for each hole (the earcut fixtures' rule).
template <class T>
mpq_class twice_polygon_area(std::span<const locus::Vec2<T>> pts,
                             std::span<const std::uint32_t> ends) {
  mpq_class s = 0;
  std::uint32_t b = 0;
  for (std::size_t k = 0; k < ends.size(); ++k) {
    const mpq_class a = abs(twice_ring_area(pts, b, ends[k]));
    s += k == 0 ? a : mpq_class(-a);
    b = ends[k];
  }
  return s;
}

template <class T>
mpq_class twice_triangle_area(std::span<const locus::Vec2<T>> pts, std::span<const Tri> tris) {
  mpq_class s = 0;
  for (const Tri& t : tris) s += orient_q(pts[t[0]], pts[t[1]], pts[t[2]]);
  return s;
}

/// |sum of triangle areas - polygon area| / polygon area, the earcut fixtures' deviation.
template <class T>
double deviation(std::span<const locus::Vec2<T>> pts, std::span<const std::uint32_t> ends,
                 std::span<const Tri> tris) {
  const mpq_class a = twice_polygon_area(pts, ends);
  const mpq_class d = abs(twice_triangle_area(pts, tris) - a);
  if (a == 0) return d == 0 ? 0.0 : 1.0;
  return mpq_class(d / abs(a)).get_d();
}

// Even-odd inside test of the exact point (x, y) against all rings.
template <class T>
bool inside_q(std::span<const locus::Vec2<T>> pts, std::span<const std::uint32_t> ends,
              const mpq_class& x, const mpq_class& y) {
  bool in = false;
  std::uint32_t b = 0;
  for (const std::uint32_t e : ends) {
    for (std::uint32_t i = b; i < e; ++i) {
      const auto& p = pts[i];
      const auto& q = pts[i + 1 == e ? b : i + 1];
      const mpq_class py(double(p.y)), qy(double(q.y));
      if ((py > y) == (qy > y)) continue;
      const mpq_class px(double(p.x)), qx(double(q.x));
      const mpq_class xi = px + (y - py) * (qx - px) / (qy - py);
      if (xi > x) in = !in;
    }
    b = e;
  }
  return in;
}

/// All checks of the top of the file; returns an empty string or the first failure.
/// Centroids are tested for at most `centroid_limit` triangles (spread over the list).
template <class T>
std::string check_triangulation(std::span<const locus::Vec2<T>> pts,
                                std::span<const std::uint32_t> ends, std::span<const Tri> tris,
                                std::size_t centroid_limit = 4000) {
  std::ostringstream err;
  const std::uint32_t n = ends.empty() ? 0 : ends.back();
  for (std::size_t i = 0; i < tris.size(); ++i) {
    for (const auto v : tris[i])
      if (v >= n) return "triangle " + std::to_string(i) + " index out of range";
    if (orient_s(pts[tris[i][0]], pts[tris[i][1]], pts[tris[i][2]]) <= 0)
      return "triangle " + std::to_string(i) + " not counter-clockwise";
  }
  if (twice_triangle_area(pts, tris) != twice_polygon_area(pts, ends))
    return "area sum differs from the polygon's area";
  // Pairwise disjoint interiors: sweep over x with bounding boxes.
  struct Box {
    double lx, hx, ly, hy;
    std::size_t i;
  };
  std::vector<Box> boxes;
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const auto &a = pts[tris[i][0]], &b = pts[tris[i][1]], &c = pts[tris[i][2]];
    boxes.push_back({std::min({double(a.x), double(b.x), double(c.x)}),
                     std::max({double(a.x), double(b.x), double(c.x)}),
                     std::min({double(a.y), double(b.y), double(c.y)}),
                     std::max({double(a.y), double(b.y), double(c.y)}), i});
  }
  std::sort(boxes.begin(), boxes.end(), [](const Box& a, const Box& b) { return a.lx < b.lx; });
  const auto separated = [&](const Tri& s, const Tri& t) {
    for (int k = 0; k < 3; ++k) {
      const auto &a = pts[s[k]], &b = pts[s[(k + 1) % 3]];
      if (orient_s(a, b, pts[t[0]]) <= 0 && orient_s(a, b, pts[t[1]]) <= 0 &&
          orient_s(a, b, pts[t[2]]) <= 0)
        return true;
    }
    return false;
  };
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size() && boxes[j].lx < boxes[i].hx; ++j) {
      if (boxes[j].ly >= boxes[i].hy || boxes[j].hy <= boxes[i].ly) continue;
      const Tri &s = tris[boxes[i].i], &t = tris[boxes[j].i];
      if (!separated(s, t) && !separated(t, s))
        return "triangles " + std::to_string(boxes[i].i) + " and " + std::to_string(boxes[j].i) +
               " overlap";
    }
  // Polygon edges against triangles: no proper crossing, no polygon vertex strictly inside.
  std::vector<std::array<std::uint32_t, 2>> edges;
  std::uint32_t first = 0;
  for (const std::uint32_t e : ends) {
    // A ring of zero area (a Steiner point, a slit) bounds nothing: its points and edges may
    // lie inside triangles.
    if (twice_ring_area(pts, first, e) != 0)
      for (std::uint32_t i = first; i < e; ++i) edges.push_back({i, i + 1 == e ? first : i + 1});
    first = e;
  }
  std::vector<Box> eboxes;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const auto &p = pts[edges[i][0]], &q = pts[edges[i][1]];
    eboxes.push_back({std::min(double(p.x), double(q.x)), std::max(double(p.x), double(q.x)),
                      std::min(double(p.y), double(q.y)), std::max(double(p.y), double(q.y)), i});
  }
  std::sort(eboxes.begin(), eboxes.end(), [](const Box& a, const Box& b) { return a.lx < b.lx; });
  std::vector<double> emax(eboxes.size());  // prefix maximum of hx, to start the scan
  for (std::size_t i = 0; i < eboxes.size(); ++i)
    emax[i] = std::max(eboxes[i].hx, i ? emax[i - 1] : eboxes[i].hx);
  for (const Box& tb : boxes) {
    const Tri& t = tris[tb.i];
    std::size_t k = std::lower_bound(emax.begin(), emax.end(), tb.lx) - emax.begin();
    for (; k < eboxes.size() && eboxes[k].lx <= tb.hx; ++k) {
      const Box& eb = eboxes[k];
      if (eb.hx < tb.lx || eb.ly > tb.hy || eb.hy < tb.ly) continue;
      const auto &p = pts[edges[eb.i][0]], &q = pts[edges[eb.i][1]];
      for (const auto& v : {p, q}) {
        int s0 = orient_s(pts[t[0]], pts[t[1]], v), s1 = orient_s(pts[t[1]], pts[t[2]], v),
            s2 = orient_s(pts[t[2]], pts[t[0]], v);
        if (s0 > 0 && s1 > 0 && s2 > 0)
          return "polygon vertex inside triangle " + std::to_string(tb.i);
      }
      for (int c = 0; c < 3; ++c) {
        const auto &a = pts[t[c]], &d = pts[t[(c + 1) % 3]];
        const int o1 = orient_s(a, d, p), o2 = orient_s(a, d, q);
        const int o3 = orient_s(p, q, a), o4 = orient_s(p, q, d);
        if (o1 * o2 < 0 && o3 * o4 < 0)
          return "triangle " + std::to_string(tb.i) + " crosses polygon edge " +
                 std::to_string(eb.i);
      }
    }
  }
  const std::size_t step =
      std::max<std::size_t>(1, tris.size() / std::max<std::size_t>(1, centroid_limit));
  for (std::size_t i = 0; i < tris.size(); i += step) {
    const auto &a = pts[tris[i][0]], &c = pts[tris[i][1]], &d = pts[tris[i][2]];
    const mpq_class x = (mpq_class(double(a.x)) + double(c.x) + double(d.x)) / 3;
    const mpq_class y = (mpq_class(double(a.y)) + double(c.y) + double(d.y)) / 3;
    if (!inside_q(pts, ends, x, y)) return "triangle " + std::to_string(i) + " outside";
  }
  return err.str();
}

}  // namespace locus_test
