// SPDX-License-Identifier: BSL-1.0
// Booleans of polyhedra through BSP trees (see include/locus/bsp/bsp3_boolean.hpp and
// docs/notes/bsp3.md).

#include <locus/bsp/bsp3_boolean.hpp>

#include <locus/core/predicates.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace locus {

namespace {

template <Real T>
bool empty_solid(const Bsp3<T>& t) noexcept {
  return t.status() == Status::empty_input || t.status() == Status::degenerate_input;
}

template <Real T>
[[nodiscard]] bool collinear3(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) noexcept {
  return orient2d(Vec2<T>{a.y, a.z}, Vec2<T>{b.y, b.z}, Vec2<T>{c.y, c.z}) == Sign::zero &&
         orient2d(Vec2<T>{a.z, a.x}, Vec2<T>{b.z, b.x}, Vec2<T>{c.z, c.x}) == Sign::zero &&
         orient2d(Vec2<T>{a.x, a.y}, Vec2<T>{b.x, b.y}, Vec2<T>{c.x, c.y}) == Sign::zero;
}

/// Collects convex polygons as welded fan triangles.
template <Real T>
struct Soup {
  MeshBoolean<T>& out;
  std::map<std::array<T, 3>, std::uint32_t> index;

  std::uint32_t weld(const Vec3<T>& v) {
    // Adding zero turns -0 into +0, so the two zeros weld.
    const std::array<T, 3> key{v.x + T(0), v.y + T(0), v.z + T(0)};
    const auto [it, fresh] =
        index.try_emplace(key, static_cast<std::uint32_t>(out.vertices.size()));
    if (fresh) out.vertices.push_back({key[0], key[1], key[2]});
    return it->second;
  }
  void add(std::span<const Vec3<T>> poly, bool reversed) {
    if (poly.size() < 3) return;
    std::vector<std::uint32_t> ids;
    ids.reserve(poly.size());
    for (const Vec3<T>& p : poly) {
      const std::uint32_t i = weld(p);
      if (ids.empty() || ids.back() != i) ids.push_back(i);
    }
    while (ids.size() > 1 && ids.back() == ids.front()) ids.pop_back();
    if (reversed) std::reverse(ids.begin(), ids.end());
    for (std::size_t k = 1; k + 1 < ids.size(); ++k) {
      const std::uint32_t a = ids[0], b = ids[k], c = ids[k + 1];
      if (a == b || b == c || a == c) continue;
      if (collinear3(out.vertices[a], out.vertices[b], out.vertices[c])) continue;
      out.triangles.push_back({a, b, c});
    }
  }
};

/// Exact: v lies strictly inside the segment p q (collinear, within the box, not an end).
template <Real T>
[[nodiscard]] bool inside_segment(const Vec3<T>& p, const Vec3<T>& q, const Vec3<T>& v) noexcept {
  for (int k = 0; k < 3; ++k)
    if (v[k] < std::min(p[k], q[k]) || v[k] > std::max(p[k], q[k])) return false;
  return !(v == p) && !(v == q) && collinear3(p, q, v);
}

template <Real T>
[[nodiscard]] Vec2<T> drop_axis(const Vec3<T>& x, int k) noexcept {
  return k == 0 ? Vec2<T>{x.y, x.z} : (k == 1 ? Vec2<T>{x.z, x.x} : Vec2<T>{x.x, x.y});
}

/// Splits every triangle edge at the output vertices lying exactly on it (T-junctions) and
/// re-triangulates each split triangle by clipping non-degenerate ears (its ring is convex with
/// collinear runs). Vertices off an edge by rounding are not found (see the header).
template <Real T>
void repair_t_junctions(MeshBoolean<T>& out) {
  const std::vector<Vec3<T>>& v = out.vertices;
  std::vector<std::uint32_t> by_x(v.size());
  for (std::uint32_t i = 0; i < by_x.size(); ++i) by_x[i] = i;
  std::sort(by_x.begin(), by_x.end(),
            [&v](std::uint32_t i, std::uint32_t j) { return v[i].x < v[j].x; });
  std::vector<std::uint32_t> found;
  // The vertices strictly inside edge p q, in order from p (exact comparisons).
  const auto on_edge = [&v, &by_x, &found](std::uint32_t p, std::uint32_t q) {
    found.clear();
    const T lo = std::min(v[p].x, v[q].x), hi = std::max(v[p].x, v[q].x);
    auto it = std::lower_bound(by_x.begin(), by_x.end(), lo,
                               [&v](std::uint32_t i, T x) { return v[i].x < x; });
    for (; it != by_x.end() && v[*it].x <= hi; ++it)
      if (inside_segment(v[p], v[q], v[*it])) found.push_back(*it);
    int axis = 0;  // the axis of the edge's largest extent orders collinear points strictly
    for (int k = 1; k < 3; ++k)
      if (std::abs(double(v[q][k]) - double(v[p][k])) >
          std::abs(double(v[q][axis]) - double(v[p][axis])))
        axis = k;
    const bool up = v[q][axis] > v[p][axis];
    std::sort(found.begin(), found.end(), [&v, axis, up](std::uint32_t i, std::uint32_t j) {
      return up ? v[i][axis] < v[j][axis] : v[i][axis] > v[j][axis];
    });
  };
  std::vector<std::array<std::uint32_t, 3>> tris;
  tris.reserve(out.triangles.size());
  std::vector<std::uint32_t> ring;
  for (const auto& t : out.triangles) {
    ring.clear();
    for (int e = 0; e < 3; ++e) {
      ring.push_back(t[static_cast<std::size_t>(e)]);
      on_edge(t[static_cast<std::size_t>(e)], t[static_cast<std::size_t>((e + 1) % 3)]);
      ring.insert(ring.end(), found.begin(), found.end());
    }
    if (ring.size() == 3) {
      tris.push_back(t);
      continue;
    }
    int k = 0;  // a projection in which the triangle keeps its area
    Sign o = Sign::zero;
    for (; k < 3 && o == Sign::zero; ++k)
      o = orient2d(drop_axis(v[t[0]], k), drop_axis(v[t[1]], k), drop_axis(v[t[2]], k));
    --k;
    while (ring.size() > 3) {
      bool clipped = false;
      for (std::size_t i = 0; i < ring.size() && !clipped; ++i) {
        const std::uint32_t a = ring[(i + ring.size() - 1) % ring.size()], b = ring[i],
                            c = ring[(i + 1) % ring.size()];
        if (orient2d(drop_axis(v[a], k), drop_axis(v[b], k), drop_axis(v[c], k)) != o) continue;
        // The rest must keep some area, or its collinear points would stay T-junctions.
        bool rest_has_area = false;
        for (std::size_t j = 0; j < ring.size() && !rest_has_area; ++j)
          rest_has_area = ring[j] != a && ring[j] != b && ring[j] != c &&
                          orient2d(drop_axis(v[a], k), drop_axis(v[c], k),
                                   drop_axis(v[ring[j]], k)) != Sign::zero;
        if (!rest_has_area) continue;
        tris.push_back({a, b, c});
        ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
        clipped = true;
      }
      if (!clipped) break;  // not for a convex ring with area
    }
    if (ring.size() == 3 &&
        orient2d(drop_axis(v[ring[0]], k), drop_axis(v[ring[1]], k), drop_axis(v[ring[2]], k)) == o)
      tris.push_back({ring[0], ring[1], ring[2]});
  }
  out.triangles = std::move(tris);
}

/// Adds the pieces of every face of `from` partitioned by `by` whose location passes `keep`.
template <Real T, class Keep>
void clip_faces(const Bsp3<T>& from, const Bsp3<T>& by, Keep keep, bool reversed, Soup<T>& soup) {
  const auto v = from.vertices();
  for (const auto& f : from.faces()) {
    const Vec3<T> tri[3] = {v[f[0]], v[f[1]], v[f[2]]};
    const Bsp3PolygonPartition<T> part = by.partition(std::span<const Vec3<T>>(tri, 3));
    for (const Bsp3Piece& piece : part.pieces) {
      if (!keep(piece.location)) continue;
      soup.add(std::span<const Vec3<T>>(part.points).subspan(piece.first, piece.count), reversed);
    }
  }
}

}  // namespace

template <Real T>
MeshBoolean<T> mesh_boolean(MeshBooleanOp op, const Bsp3<T>& a, const Bsp3<T>& b) {
  MeshBoolean<T> r;
  for (const Status s : {a.status(), b.status()})
    if (s == Status::non_finite_input || s == Status::invalid_input) {
      r.status = s;
      return r;
    }
  r.status = Status::ok;
  if (empty_solid(a))
    r.status = a.status();
  else if (empty_solid(b))
    r.status = b.status();
  Soup<T> soup{r, {}};
  using L = Bsp3Location;
  switch (op) {
    case MeshBooleanOp::union_:
      clip_faces(
          a, b, [](L l) { return l == L::outside || l == L::coincident_same; }, false, soup);
      clip_faces(
          b, a, [](L l) { return l == L::outside; }, false, soup);
      break;
    case MeshBooleanOp::intersection:
      clip_faces(
          a, b, [](L l) { return l == L::inside || l == L::coincident_same; }, false, soup);
      clip_faces(
          b, a, [](L l) { return l == L::inside; }, false, soup);
      break;
    case MeshBooleanOp::difference:
      clip_faces(
          a, b, [](L l) { return l == L::outside || l == L::coincident_opposite; }, false, soup);
      clip_faces(
          b, a, [](L l) { return l == L::inside; }, true, soup);
      break;
  }
  repair_t_junctions(r);
  return r;
}

template <Real T>
MeshBoolean<T> mesh_boolean(MeshBooleanOp op, std::span<const Vec3<T>> a_vertices,
                            std::span<const std::array<std::uint32_t, 3>> a_triangles,
                            std::span<const Vec3<T>> b_vertices,
                            std::span<const std::array<std::uint32_t, 3>> b_triangles,
                            Bsp3Options options) {
  const Bsp3<T> a(a_vertices, a_triangles, options), b(b_vertices, b_triangles, options);
  return mesh_boolean(op, a, b);
}

#define LOCUS_BSP3_BOOLEAN_INSTANTIATE(T)                                                     \
  template MeshBoolean<T> mesh_boolean(MeshBooleanOp, const Bsp3<T>&, const Bsp3<T>&);        \
  template MeshBoolean<T> mesh_boolean(                                                       \
      MeshBooleanOp, std::span<const Vec3<T>>, std::span<const std::array<std::uint32_t, 3>>, \
      std::span<const Vec3<T>>, std::span<const std::array<std::uint32_t, 3>>, Bsp3Options);
LOCUS_BSP3_BOOLEAN_INSTANTIATE(float)
LOCUS_BSP3_BOOLEAN_INSTANTIATE(double)

}  // namespace locus
