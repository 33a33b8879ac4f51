// SPDX-License-Identifier: BSL-1.0
// Constrained Delaunay triangulation (see include/locus/delaunay/constrained_delaunay2.hpp).

#include <locus/delaunay/constrained_delaunay2.hpp>

#include <locus/core/predicates.hpp>

#include <algorithm>
#include <deque>
#include <utility>

namespace locus {

namespace {

constexpr std::uint32_t kNone = 0xFFFFFFFFu;

[[nodiscard]] inline std::uint32_t nxt(std::uint32_t e) noexcept { return next_halfedge(e); }
[[nodiscard]] inline std::uint32_t prv(std::uint32_t e) noexcept { return prev_halfedge(e); }

// An edge of the cavity boundary: the cavity-side half-edge u -> v, the half-edge outside it
// (or -1 on the hull) and whether it is a constraint.
struct BoundaryEdge {
  std::uint32_t u, v;
  std::int32_t outside;
  std::uint8_t constrained;
};

}  // namespace

template <Real T>
const ConstrainedDelaunay2Result& ConstrainedDelaunay2<T>::compute(
    std::span<const Vec2<T>> points, std::span<const std::array<std::uint32_t, 2>> constraints) {
  points_ = points;
  const Delaunay2Result& d = delaunay_.compute(points);
  ConstrainedDelaunay2Result& r = result_;
  r.status = d.status;
  r.dimension = d.dimension;
  r.triangles = d.triangles;
  r.halfedges = d.halfedges;
  r.hull = d.hull;
  r.duplicate_of = d.duplicate_of;
  r.constrained.assign(r.triangles.size(), 0);
  r.inside.clear();
  r.rejected.clear();
  if (r.status != Status::ok || r.dimension < 2) return r;

  vertex_edge_.assign(points.size(), kNone);
  for (std::uint32_t e = 0; e < r.triangles.size(); ++e) vertex_edge_[r.triangles[e]] = e;
  in_cavity_.assign(r.triangles.size() / 3, 0);

  const std::size_t n = points.size();
  for (std::size_t k = 0; k < constraints.size(); ++k) {
    const auto [ia, ib] = constraints[k];
    if (ia >= n || ib >= n) {
      r.rejected.push_back(static_cast<std::uint32_t>(k));
      continue;
    }
    const std::uint32_t a = r.duplicate_of[ia], b = r.duplicate_of[ib];
    if (a == b) continue;
    if (insert_segment(a, b) != 0) r.rejected.push_back(static_cast<std::uint32_t>(k));
  }
  if (!r.rejected.empty()) r.status = Status::invalid_input;
  return r;
}

template <Real T>
int ConstrainedDelaunay2<T>::insert_segment(std::uint32_t a, std::uint32_t b) {
  ConstrainedDelaunay2Result& r = result_;
  const auto P = [&](std::uint32_t v) -> const Vec2<T>& { return points_[v]; };
  const std::size_t budget = r.triangles.size() + 16;
  for (std::size_t piece = 0; piece < budget && a != b; ++piece) {
    // 1. The triangle of a's fan that ab leaves through (or an edge / vertex on ab). Turn
    // counter-clockwise from any outgoing half-edge; at the hull, turn clockwise from the start.
    const std::uint32_t start = vertex_edge_[a];
    std::uint32_t first_cross = kNone, on_segment = kNone, existing = kNone;
    const auto visit = [&](std::uint32_t e) {  // true: found
      const std::uint32_t x = r.triangles[nxt(e)], y = r.triangles[prv(e)];
      if (x == b) {
        existing = e;
        return true;
      }
      const Sign sx = orient2d(P(a), P(b), P(x));
      if (sx == Sign::zero &&
          lexicographic_compare(P(a), P(x)) == lexicographic_compare(P(x), P(b))) {
        existing = e;  // x on the open segment ab: constraint a x, then x b
        on_segment = x;
        return true;
      }
      // y is also tested: at a hull vertex the last edge of the fan (y -> a) has no
      // counter-clockwise successor whose x would be y.
      if (y == b) {
        existing = prv(e);
        return true;
      }
      const Sign sy = orient2d(P(a), P(b), P(y));
      if (sy == Sign::zero &&
          lexicographic_compare(P(a), P(y)) == lexicographic_compare(P(y), P(b))) {
        existing = prv(e);
        on_segment = y;
        return true;
      }
      if (sx == Sign::negative && sy == Sign::positive) {
        first_cross = e;
        return true;
      }
      return false;
    };
    bool found = false, hit_hull = false;
    std::uint32_t e = start;
    for (std::size_t guard = 0; guard < budget && !found; ++guard) {
      found = visit(e);
      if (found) break;
      const std::int32_t o = r.halfedges[prv(e)];
      if (o < 0) {
        hit_hull = true;
        break;
      }
      e = static_cast<std::uint32_t>(o);
      if (e == start) break;
    }
    e = start;
    for (std::size_t guard = 0; guard < budget && !found && hit_hull; ++guard) {
      const std::int32_t o = r.halfedges[e];
      if (o < 0) break;
      e = nxt(static_cast<std::uint32_t>(o));
      found = visit(e);
    }
    if (existing != kNone) {
      r.constrained[existing] = 1;
      if (r.halfedges[existing] >= 0) r.constrained[std::size_t(r.halfedges[existing])] = 1;
      a = on_segment == kNone ? b : on_segment;
      continue;
    }
    if (first_cross == kNone) return 2;  // cannot happen in a valid triangulation

    // 2. Walk along ab collecting the crossed triangles and the vertices left / right of ab.
    cavity_.clear();
    left_.clear();
    right_.clear();
    std::uint32_t t = first_cross / 3;
    std::uint32_t cross = nxt(first_cross);  // half-edge x -> y crossed by ab
    right_.push_back(r.triangles[cross]);
    left_.push_back(r.triangles[nxt(cross)]);
    cavity_.push_back(t);
    std::uint32_t end = kNone;
    for (std::size_t guard = 0; guard < budget; ++guard) {
      if (r.constrained[cross]) return 1;
      const std::int32_t o = r.halfedges[cross];
      if (o < 0) return 2;
      const std::uint32_t h = static_cast<std::uint32_t>(o);  // y -> x
      t = h / 3;
      cavity_.push_back(t);
      const std::uint32_t z = r.triangles[prv(h)];
      if (z == b) {
        end = b;
        break;
      }
      const Sign s = orient2d(P(a), P(b), P(z));
      if (s == Sign::zero) {
        end = z;  // z on the open segment: this piece ends at z
        break;
      }
      if (s == Sign::positive) {
        left_.push_back(z);
        cross = nxt(h);  // x -> z
      } else {
        right_.push_back(z);
        cross = prv(h);  // z -> y
      }
    }
    if (end == kNone) return 2;

    // 3. The cavity boundary (half-edges of cavity triangles whose opposite is outside it).
    for (const std::uint32_t c : cavity_) in_cavity_[c] = 1;
    std::vector<BoundaryEdge> boundary;
    for (const std::uint32_t c : cavity_)
      for (std::uint32_t i = 0; i < 3; ++i) {
        const std::uint32_t h = 3 * c + i;
        const std::int32_t o = r.halfedges[h];
        if (o >= 0 && in_cavity_[std::size_t(o) / 3]) continue;
        boundary.push_back({r.triangles[h], r.triangles[nxt(h)], o, r.constrained[h]});
      }
    for (const std::uint32_t c : cavity_) in_cavity_[c] = 0;

    // 4. Re-triangulate both pseudo-polygons (explicit stack instead of recursion).
    new_tris_.clear();
    for (int side = 0; side < 2; ++side) {
      const std::vector<std::uint32_t>& poly = side == 0 ? left_ : right_;
      struct Range {
        std::uint32_t u, v;
        std::size_t lo, hi;  // poly[lo, hi) lie between u and v
      };
      std::vector<Range> stack{{a, end, 0, poly.size()}};
      while (!stack.empty()) {
        const Range g = stack.back();
        stack.pop_back();
        if (g.lo >= g.hi) continue;
        std::size_t best = g.lo;
        for (std::size_t i = g.lo + 1; i < g.hi; ++i) {
          const Vec2<T>& pu = P(g.u);
          const Vec2<T>& pv = P(g.v);
          const Vec2<T>& pc = P(poly[best]);
          const Sign o = orient2d(pu, pv, pc);
          const Sign in = o == Sign::positive ? incircle(pu, pv, pc, P(poly[i]))
                                              : incircle(pv, pu, pc, P(poly[i]));
          if (in == Sign::positive) best = i;
        }
        const std::uint32_t c = poly[best];
        if (orient2d(P(g.u), P(g.v), P(c)) == Sign::positive) {
          new_tris_.insert(new_tris_.end(), {g.u, g.v, c});
        } else {
          new_tris_.insert(new_tris_.end(), {g.v, g.u, c});
        }
        stack.push_back({g.u, c, g.lo, best});
        stack.push_back({c, g.v, best + 1, g.hi});
      }
    }
    if (new_tris_.size() != 3 * cavity_.size()) return 2;

    // 5. Write the new triangles into the cavity slots and link them.
    for (std::size_t k = 0; k < cavity_.size(); ++k)
      for (std::uint32_t i = 0; i < 3; ++i) {
        const std::uint32_t h = 3 * cavity_[k] + i;
        r.triangles[h] = new_tris_[3 * k + i];
        r.halfedges[h] = -2;  // unlinked
        r.constrained[h] = 0;
      }
    for (std::size_t k = 0; k < cavity_.size(); ++k)
      for (std::uint32_t i = 0; i < 3; ++i) {
        const std::uint32_t h = 3 * cavity_[k] + i;
        if (r.halfedges[h] != -2) continue;
        const std::uint32_t u = r.triangles[h], v = r.triangles[nxt(h)];
        if ((u == a && v == end) || (u == end && v == a)) r.constrained[h] = 1;
        bool linked = false;
        for (const BoundaryEdge& be : boundary)
          if (be.u == u && be.v == v) {
            r.halfedges[h] = be.outside;
            if (be.outside >= 0)
              r.halfedges[std::size_t(be.outside)] = static_cast<std::int32_t>(h);
            r.constrained[h] = be.constrained;
            linked = true;
            break;
          }
        for (std::size_t k2 = k; k2 < cavity_.size() && !linked; ++k2)
          for (std::uint32_t j = 0; j < 3 && !linked; ++j) {
            const std::uint32_t g2 = 3 * cavity_[k2] + j;
            if (g2 == h || r.halfedges[g2] != -2) continue;
            if (r.triangles[g2] == v && r.triangles[nxt(g2)] == u) {
              r.halfedges[h] = static_cast<std::int32_t>(g2);
              r.halfedges[g2] = static_cast<std::int32_t>(h);
              r.constrained[g2] = r.constrained[h];
              linked = true;
            }
          }
        if (!linked) return 2;
      }
    for (std::size_t k = 0; k < cavity_.size(); ++k)
      for (std::uint32_t i = 0; i < 3; ++i) {
        const std::uint32_t h = 3 * cavity_[k] + i;
        const std::uint32_t v = r.triangles[h];
        // Keep an outgoing half-edge of every vertex valid.
        if (r.triangles[vertex_edge_[v]] != v) vertex_edge_[v] = h;
      }
    a = end;
  }
  return a == b ? 0 : 2;
}

template <Real T>
void ConstrainedDelaunay2<T>::mark_inside() {
  ConstrainedDelaunay2Result& r = result_;
  const std::size_t nt = r.triangles.size() / 3;
  // 0-1 breadth-first search on the number of constraints crossed from outside the hull.
  std::vector<std::uint32_t> depth(nt, kNone);
  std::deque<std::uint32_t> queue;
  for (std::size_t e = 0; e < r.triangles.size(); ++e) {
    if (r.halfedges[e] >= 0) continue;
    const std::uint32_t t = static_cast<std::uint32_t>(e / 3);
    const std::uint32_t d = r.constrained[e] ? 1u : 0u;
    if (d < depth[t]) {
      depth[t] = d;
      if (d == 0)
        queue.push_front(t);
      else
        queue.push_back(t);
    }
  }
  std::size_t guard = 4 * r.triangles.size() + 16;
  while (!queue.empty() && guard-- > 0) {
    const std::uint32_t t = queue.front();
    queue.pop_front();
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::int32_t o = r.halfedges[3 * t + i];
      if (o < 0) continue;
      const std::uint32_t u = static_cast<std::uint32_t>(o) / 3;
      const std::uint32_t d = depth[t] + (r.constrained[3 * t + i] ? 1u : 0u);
      if (d < depth[u]) {
        depth[u] = d;
        if (d == depth[t])
          queue.push_front(u);
        else
          queue.push_back(u);
      }
    }
  }
  r.inside.resize(nt);
  for (std::size_t t = 0; t < nt; ++t) r.inside[t] = depth[t] != kNone && (depth[t] & 1u) ? 1 : 0;
}

template <Real T>
const ConstrainedDelaunay2Result& ConstrainedDelaunay2<T>::compute_polygon(
    std::span<const Vec2<T>> points, std::span<const std::uint32_t> ring_ends) {
  std::vector<std::array<std::uint32_t, 2>> edges;
  std::uint32_t begin = 0;
  bool bad = false;
  for (const std::uint32_t end : ring_ends) {
    if (end < begin || end > points.size()) {
      bad = true;
      break;
    }
    for (std::uint32_t i = begin; i < end; ++i) edges.push_back({i, i + 1 == end ? begin : i + 1});
    begin = end;
  }
  compute(points, edges);
  if (bad && result_.status == Status::ok) result_.status = Status::invalid_input;
  if (result_.dimension == 2) mark_inside();
  return result_;
}

template <Real T>
ConstrainedDelaunay2Result constrained_delaunay(
    std::span<const Vec2<T>> points, std::span<const std::array<std::uint32_t, 2>> constraints) {
  ConstrainedDelaunay2<T> c;
  return c.compute(points, constraints);
}

template <Real T>
ConstrainedDelaunay2Result triangulate_polygon(std::span<const Vec2<T>> points,
                                               std::span<const std::uint32_t> ring_ends) {
  ConstrainedDelaunay2<T> c;
  return c.compute_polygon(points, ring_ends);
}

template class ConstrainedDelaunay2<float>;
template class ConstrainedDelaunay2<double>;
template ConstrainedDelaunay2Result constrained_delaunay<float>(
    std::span<const Vec2<float>>, std::span<const std::array<std::uint32_t, 2>>);
template ConstrainedDelaunay2Result constrained_delaunay<double>(
    std::span<const Vec2<double>>, std::span<const std::array<std::uint32_t, 2>>);
template ConstrainedDelaunay2Result triangulate_polygon<float>(std::span<const Vec2<float>>,
                                                               std::span<const std::uint32_t>);
template ConstrainedDelaunay2Result triangulate_polygon<double>(std::span<const Vec2<double>>,
                                                                std::span<const std::uint32_t>);

}  // namespace locus
