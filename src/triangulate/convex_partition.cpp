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

template <Real T>
ConvexPartition min_convex_partition(std::span<const Vec2<T>> points,
                                     std::span<const std::uint32_t> ring_ends) {
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
  bool convex = true;
  for (std::uint32_t k = 0; k < n && convex; ++k)
    convex = orient2d(P((k + n - 1) % n), P(k), P((k + 1) % n)) != Sign::negative;
  if (convex) {
    r.vertices = verts;
    r.piece_ends.push_back(n);
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
                                                     std::span<const std::uint32_t>);
template ConvexPartition min_convex_partition<double>(std::span<const Vec2<double>>,
                                                      std::span<const std::uint32_t>);

}  // namespace locus
