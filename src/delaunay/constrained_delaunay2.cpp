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

// Half-edge 3t + i runs from vertex i to vertex i + 1 of triangle t.
[[nodiscard]] inline std::uint32_t nxt(std::uint32_t e) noexcept {
  return e % 3 == 2 ? e - 2 : e + 1;
}
[[nodiscard]] inline std::uint32_t prv(std::uint32_t e) noexcept {
  return e % 3 == 0 ? e + 2 : e - 1;
}

}  // namespace

template <Real T>
const ConstrainedDelaunay2Result& ConstrainedDelaunay2<T>::compute(
    std::span<const Vec2<T>> points, std::span<const std::array<std::uint32_t, 2>> constraints) {
  triangulate(points, constraints);
  inside_.clear();
  write_result();
  return result_;
}

// The Delaunay triangulation, then every constraint, on the internal half-edge arrays.
template <Real T>
void ConstrainedDelaunay2<T>::triangulate(
    std::span<const Vec2<T>> points, std::span<const std::array<std::uint32_t, 2>> constraints) {
  points_ = points;
  const Delaunay2Result& d = delaunay_.compute(points);
  ConstrainedDelaunay2Result& r = result_;
  r.status = d.status;
  r.dimension = d.dimension;
  r.hull = d.hull;
  r.duplicate_of = d.duplicate_of;
  r.rejected.clear();
  load_delaunay(d);
  if (r.status != Status::ok || r.dimension < 2) return;

  vertex_edge_.assign(points.size(), kNone);
  for (std::uint32_t e = 0; e < tris_.size(); ++e) vertex_edge_[tris_[e]] = e;
  in_cavity_.assign(tris_.size() / 3, 0);

  const std::size_t n = points.size();
  for (std::size_t k = 0; k < constraints.size(); ++k) {
    const auto [ia, ib] = constraints[k];
    if (ia >= n || ib >= n) {
      r.rejected.push_back(static_cast<std::uint32_t>(k));
      continue;
    }
    const std::uint32_t a = r.duplicate_of[ia], b = r.duplicate_of[ib];
    if (a == b) continue;
    if (insert_segment(a, b) != Insertion::inserted)
      r.rejected.push_back(static_cast<std::uint32_t>(k));
  }
  if (!r.rejected.empty()) r.status = Status::invalid_input;
}

// The half-edge arrays of a Delaunay2Result: the twin of half-edge v[i] -> v[i+1] of t is the
// half-edge of the triangle across that starts at v[i+1].
template <Real T>
void ConstrainedDelaunay2<T>::load_delaunay(const Delaunay2Result& d) {
  const std::size_t nt = d.triangles.size();
  tris_.resize(3 * nt);
  halfedges_.resize(3 * nt);
  constrained_.assign(3 * nt, 0);
  for (std::size_t t = 0; t < nt; ++t)
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::size_t e = 3 * t + i;
      tris_[e] = d.triangles[t][i];
      const std::uint32_t u = d.adjacency[t][i];
      halfedges_[e] = -1;
      if (u == kNoTriangle) continue;
      const std::uint32_t start = d.triangles[t][i == 2 ? 0 : i + 1];
      for (std::uint32_t j = 0; j < 3; ++j)
        if (d.triangles[u][j] == start) halfedges_[e] = static_cast<std::int32_t>(3 * u + j);
    }
}

// The result in the index layout of the header.
template <Real T>
void ConstrainedDelaunay2<T>::write_result() {
  ConstrainedDelaunay2Result& r = result_;
  const std::size_t nt = tris_.size() / 3;
  r.triangles.resize(nt);
  r.adjacency.resize(nt);
  r.constrained.resize(nt);
  for (std::size_t t = 0; t < nt; ++t)
    for (std::size_t i = 0; i < 3; ++i) {
      const std::int32_t o = halfedges_[3 * t + i];
      r.triangles[t][i] = tris_[3 * t + i];
      r.adjacency[t][i] = o < 0 ? kNoTriangle : static_cast<std::uint32_t>(o) / 3;
      r.constrained[t][i] = constrained_[3 * t + i];
    }
  r.inside = inside_;
}

template <Real T>
void ConstrainedDelaunay2<T>::mark_constrained(std::uint32_t e) {
  constrained_[e] = 1;
  if (halfedges_[e] >= 0) constrained_[std::size_t(halfedges_[e])] = 1;
}

// Step 1 of a segment piece: the triangle of a's fan that ab leaves through, or an edge of the
// fan on ab. Turns counter-clockwise from any outgoing half-edge; at the hull, then clockwise
// from the start.
template <Real T>
auto ConstrainedDelaunay2<T>::find_exit(std::uint32_t a, std::uint32_t b) const -> FanExit {
  const auto P = [&](std::uint32_t v) -> const Vec2<T>& { return points_[v]; };
  const std::size_t budget = tris_.size() + 16;
  FanExit exit{kNone, kNone, kNone};
  const auto visit = [&](std::uint32_t e) {  // true: found
    const std::uint32_t x = tris_[nxt(e)], y = tris_[prv(e)];
    if (x == b) {
      exit.existing = e;
      return true;
    }
    const Sign sx = orient2d(P(a), P(b), P(x));
    if (sx == Sign::zero &&
        lexicographic_compare(P(a), P(x)) == lexicographic_compare(P(x), P(b))) {
      exit.existing = e;  // x on the open segment ab: constraint a x, then x b
      exit.on_segment = x;
      return true;
    }
    // y is also tested: at a hull vertex the last edge of the fan (y -> a) has no
    // counter-clockwise successor whose x would be y.
    if (y == b) {
      exit.existing = prv(e);
      return true;
    }
    const Sign sy = orient2d(P(a), P(b), P(y));
    if (sy == Sign::zero &&
        lexicographic_compare(P(a), P(y)) == lexicographic_compare(P(y), P(b))) {
      exit.existing = prv(e);
      exit.on_segment = y;
      return true;
    }
    if (sx == Sign::negative && sy == Sign::positive) {
      exit.first_cross = e;
      return true;
    }
    return false;
  };
  const std::uint32_t start = vertex_edge_[a];
  bool found = false, hit_hull = false;
  std::uint32_t e = start;
  for (std::size_t guard = 0; guard < budget && !found; ++guard) {
    found = visit(e);
    if (found) break;
    const std::int32_t o = halfedges_[prv(e)];
    if (o < 0) {
      hit_hull = true;
      break;
    }
    e = static_cast<std::uint32_t>(o);
    if (e == start) break;
  }
  e = start;
  for (std::size_t guard = 0; guard < budget && !found && hit_hull; ++guard) {
    const std::int32_t o = halfedges_[e];
    if (o < 0) break;
    e = nxt(static_cast<std::uint32_t>(o));
    found = visit(e);
  }
  return exit;
}

// Step 2: walks along ab from the half-edge a -> x of the first crossed triangle, collecting the
// crossed triangles (cavity_) and the vertices left and right of ab, until a vertex on ab: b, or
// one strictly inside ab (`end`, where this piece stops).
template <Real T>
auto ConstrainedDelaunay2<T>::collect_crossed(std::uint32_t a, std::uint32_t b,
                                              std::uint32_t first_cross, std::uint32_t& end)
    -> Insertion {
  const auto P = [&](std::uint32_t v) -> const Vec2<T>& { return points_[v]; };
  const std::size_t budget = tris_.size() + 16;
  cavity_.clear();
  left_.clear();
  right_.clear();
  std::uint32_t cross = nxt(first_cross);  // half-edge x -> y crossed by ab
  right_.push_back(tris_[cross]);
  left_.push_back(tris_[nxt(cross)]);
  cavity_.push_back(first_cross / 3);
  end = kNone;
  for (std::size_t guard = 0; guard < budget; ++guard) {
    if (constrained_[cross]) return Insertion::crosses_constraint;
    const std::int32_t o = halfedges_[cross];
    if (o < 0) return Insertion::failed;
    const std::uint32_t h = static_cast<std::uint32_t>(o);  // y -> x
    cavity_.push_back(h / 3);
    const std::uint32_t z = tris_[prv(h)];
    if (z == b) {
      end = b;
      return Insertion::inserted;
    }
    const Sign s = orient2d(P(a), P(b), P(z));
    if (s == Sign::zero) {
      end = z;  // z on the open segment: this piece ends at z
      return Insertion::inserted;
    }
    if (s == Sign::positive) {
      left_.push_back(z);
      cross = nxt(h);  // x -> z
    } else {
      right_.push_back(z);
      cross = prv(h);  // z -> y
    }
  }
  return Insertion::failed;
}

// Step 3: the cavity boundary, the half-edges of cavity triangles whose twin is outside it.
template <Real T>
void ConstrainedDelaunay2<T>::collect_cavity_boundary() {
  boundary_.clear();
  for (const std::uint32_t c : cavity_) in_cavity_[c] = 1;
  for (const std::uint32_t c : cavity_)
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = 3 * c + i;
      const std::int32_t o = halfedges_[h];
      if (o >= 0 && in_cavity_[std::size_t(o) / 3]) continue;
      boundary_.push_back({tris_[h], tris_[nxt(h)], o, constrained_[h]});
    }
  for (const std::uint32_t c : cavity_) in_cavity_[c] = 0;
}

// Step 4: the constrained Delaunay triangulation of the pseudo-polygon between edge a -> end and
// the chain `side` (in order along ab), appended to new_tris_: each edge takes the chain vertex
// whose circle through the edge contains no other (explicit stack instead of recursion).
template <Real T>
void ConstrainedDelaunay2<T>::retriangulate_side(std::uint32_t a, std::uint32_t end,
                                                 const std::vector<std::uint32_t>& side) {
  const auto P = [&](std::uint32_t v) -> const Vec2<T>& { return points_[v]; };
  struct Range {
    std::uint32_t u, v;
    std::size_t lo, hi;  // side[lo, hi) lie between u and v
  };
  std::vector<Range> stack{{a, end, 0, side.size()}};
  while (!stack.empty()) {
    const Range g = stack.back();
    stack.pop_back();
    if (g.lo >= g.hi) continue;
    std::size_t best = g.lo;
    for (std::size_t i = g.lo + 1; i < g.hi; ++i) {
      const Vec2<T>& pu = P(g.u);
      const Vec2<T>& pv = P(g.v);
      const Vec2<T>& pc = P(side[best]);
      const Sign o = orient2d(pu, pv, pc);
      const Sign in =
          o == Sign::positive ? incircle(pu, pv, pc, P(side[i])) : incircle(pv, pu, pc, P(side[i]));
      if (in == Sign::positive) best = i;
    }
    const std::uint32_t c = side[best];
    if (orient2d(P(g.u), P(g.v), P(c)) == Sign::positive) {
      new_tris_.insert(new_tris_.end(), {g.u, g.v, c});
    } else {
      new_tris_.insert(new_tris_.end(), {g.v, g.u, c});
    }
    stack.push_back({g.u, c, g.lo, best});
    stack.push_back({c, g.v, best + 1, g.hi});
  }
}

// Step 5: the new triangles go into the cavity's slots; their half-edges are linked to the
// boundary (taking over its constraint flags) or to each other, the edge a-end is constrained,
// and every vertex keeps a valid outgoing half-edge. False if an edge finds no twin.
template <Real T>
bool ConstrainedDelaunay2<T>::replace_cavity(std::uint32_t a, std::uint32_t end) {
  constexpr std::int32_t kUnlinked = -2;
  for (std::size_t k = 0; k < cavity_.size(); ++k)
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = 3 * cavity_[k] + i;
      tris_[h] = new_tris_[3 * k + i];
      halfedges_[h] = kUnlinked;
      constrained_[h] = 0;
    }
  for (std::size_t k = 0; k < cavity_.size(); ++k)
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = 3 * cavity_[k] + i;
      if (halfedges_[h] != kUnlinked) continue;
      const std::uint32_t u = tris_[h], v = tris_[nxt(h)];
      if ((u == a && v == end) || (u == end && v == a)) constrained_[h] = 1;
      bool linked = false;
      for (const BoundaryEdge& be : boundary_)
        if (be.u == u && be.v == v) {
          halfedges_[h] = be.outside;
          if (be.outside >= 0) halfedges_[std::size_t(be.outside)] = static_cast<std::int32_t>(h);
          constrained_[h] = be.constrained;
          linked = true;
          break;
        }
      for (std::size_t k2 = k; k2 < cavity_.size() && !linked; ++k2)
        for (std::uint32_t j = 0; j < 3 && !linked; ++j) {
          const std::uint32_t g2 = 3 * cavity_[k2] + j;
          if (g2 == h || halfedges_[g2] != kUnlinked) continue;
          if (tris_[g2] == v && tris_[nxt(g2)] == u) {
            halfedges_[h] = static_cast<std::int32_t>(g2);
            halfedges_[g2] = static_cast<std::int32_t>(h);
            constrained_[g2] = constrained_[h];
            linked = true;
          }
        }
      if (!linked) return false;
    }
  for (std::size_t k = 0; k < cavity_.size(); ++k)
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = 3 * cavity_[k] + i;
      const std::uint32_t v = tris_[h];
      if (tris_[vertex_edge_[v]] != v) vertex_edge_[v] = h;
    }
  return true;
}

// Inserts segment ab piece by piece: each piece ends at b or at a vertex lying on ab, and either
// follows an existing edge or replaces the triangles it crosses.
template <Real T>
auto ConstrainedDelaunay2<T>::insert_segment(std::uint32_t a, std::uint32_t b) -> Insertion {
  const std::size_t budget = tris_.size() + 16;
  for (std::size_t piece = 0; piece < budget && a != b; ++piece) {
    const FanExit exit = find_exit(a, b);
    if (exit.existing != kNone) {
      mark_constrained(exit.existing);
      a = exit.on_segment == kNone ? b : exit.on_segment;
      continue;
    }
    if (exit.first_cross == kNone) return Insertion::failed;  // not in a valid triangulation
    std::uint32_t end = kNone;
    const Insertion crossed = collect_crossed(a, b, exit.first_cross, end);
    if (crossed != Insertion::inserted) return crossed;
    collect_cavity_boundary();
    new_tris_.clear();
    retriangulate_side(a, end, left_);
    retriangulate_side(a, end, right_);
    if (new_tris_.size() != 3 * cavity_.size()) return Insertion::failed;
    if (!replace_cavity(a, end)) return Insertion::failed;
    a = end;
  }
  return a == b ? Insertion::inserted : Insertion::failed;
}

template <Real T>
void ConstrainedDelaunay2<T>::mark_inside() {
  const std::size_t nt = tris_.size() / 3;
  // 0-1 breadth-first search on the number of constraints crossed from outside the hull.
  std::vector<std::uint32_t> depth(nt, kNone);
  std::deque<std::uint32_t> queue;
  for (std::size_t e = 0; e < tris_.size(); ++e) {
    if (halfedges_[e] >= 0) continue;
    const std::uint32_t t = static_cast<std::uint32_t>(e / 3);
    const std::uint32_t d = constrained_[e] ? 1u : 0u;
    if (d < depth[t]) {
      depth[t] = d;
      if (d == 0)
        queue.push_front(t);
      else
        queue.push_back(t);
    }
  }
  std::size_t guard = 4 * tris_.size() + 16;
  while (!queue.empty() && guard-- > 0) {
    const std::uint32_t t = queue.front();
    queue.pop_front();
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::int32_t o = halfedges_[3 * t + i];
      if (o < 0) continue;
      const std::uint32_t u = static_cast<std::uint32_t>(o) / 3;
      const std::uint32_t d = depth[t] + (constrained_[3 * t + i] ? 1u : 0u);
      if (d < depth[u]) {
        depth[u] = d;
        if (d == depth[t])
          queue.push_front(u);
        else
          queue.push_back(u);
      }
    }
  }
  inside_.resize(nt);
  for (std::size_t t = 0; t < nt; ++t) inside_[t] = depth[t] != kNone && (depth[t] & 1u) ? 1 : 0;
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
  triangulate(points, edges);
  if (bad && result_.status == Status::ok) result_.status = Status::invalid_input;
  inside_.clear();
  if (result_.dimension == 2) mark_inside();
  write_result();
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
