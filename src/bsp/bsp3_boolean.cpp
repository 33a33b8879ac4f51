// SPDX-License-Identifier: BSL-1.0
// Booleans of polyhedra through BSP trees (see include/locus/bsp/bsp3_boolean.hpp and
// docs/notes/bsp3.md).

#include <locus/bsp/bsp3_boolean.hpp>

#include <locus/core/predicates.hpp>

#include <algorithm>
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
