// SPDX-License-Identifier: BSL-1.0
// Booleans of polyhedra through BSP trees (see include/locus/bsp/bsp3_boolean.hpp and
// docs/notes/bsp3.md).

#include <locus/bsp/bsp3_boolean.hpp>

#include "bsp3_keyed.hpp"

#include <locus/core/predicates.hpp>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <map>
#include <utility>

namespace locus {

namespace {

template <Real T>
bool empty_solid(const Bsp3<T>& t) noexcept {
  return t.status() == Status::empty_input || t.status() == Status::degenerate_input;
}

/// Union-find with path halving.
struct Dsu {
  std::vector<std::uint32_t> parent;
  explicit Dsu(std::size_t n) : parent(n) {
    for (std::size_t i = 0; i < n; ++i) parent[i] = static_cast<std::uint32_t>(i);
  }
  std::uint32_t find(std::uint32_t i) noexcept {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void unite(std::uint32_t i, std::uint32_t j) noexcept {
    i = find(i);
    j = find(j);
    if (i != j) parent[std::max(i, j)] = std::min(i, j);  // the smallest index represents
  }
};

/// Plane ids for the faces of a (0 .. Fa - 1) then b (Fa .. Fa + Fb - 1): exactly coplanar
/// faces (orient3d, either orientation) share an id. Candidates come from a grid over the
/// rounded unit normal and offset (cells of 2^-20, neighbouring cells searched); a pair the grid
/// misses keeps two ids (only a cracked seam at a coincidence, never a wrong side).
template <Real T>
std::vector<std::uint32_t> number_planes(const Bsp3<T>& a, const Bsp3<T>& b,
                                         std::vector<Vec3<double>>& normals,
                                         std::vector<std::uint32_t>& exact_id) {
  const std::array<const Bsp3<T>*, 2> trees{&a, &b};
  std::vector<std::array<Vec3<T>, 3>> tri;
  for (const Bsp3<T>* t : trees)
    for (const auto& f : t->faces())
      tri.push_back({t->vertices()[f[0]], t->vertices()[f[1]], t->vertices()[f[2]]});
  double scale = 0;
  for (const auto& t : tri)
    for (const auto& p : t)
      for (int k = 0; k < 3; ++k) scale = std::max(scale, std::abs(double(p[k])));
  if (!(scale > 0) || !std::isfinite(scale)) scale = 1;
  constexpr double cell = 0x1p-20;
  // Planes closer than this (unit normals and offsets / scale) are one plane: rounding the
  // input (a rotated box's quads) folds a planar face by about eps(T); see the header.
  constexpr double tol = 64 * double(std::numeric_limits<T>::epsilon());
  using Cell = std::array<std::int64_t, 4>;
  std::map<Cell, std::vector<std::uint32_t>> grid;
  Dsu dsu(tri.size()), exact(tri.size());
  normals.assign(tri.size(), Vec3<double>{0, 0, 0});
  for (std::uint32_t i = 0; i < tri.size(); ++i) {
    const auto& t = tri[i];
    const Vec3<double> p0 = vec_cast<double>(t[0]) / scale, p1 = vec_cast<double>(t[1]) / scale,
                       p2 = vec_cast<double>(t[2]) / scale;
    Vec3<double> n = cross(p1 - p0, p2 - p0);
    const double len = std::sqrt(dot(n, n));
    if (!(len > 0) || !std::isfinite(len)) continue;  // an id of its own
    n = n / len;
    normals[i] = n;
    const std::array<double, 4> key{n.x, n.y, n.z, dot(n, p0)};
    Cell home{};
    for (int k = 0; k < 4; ++k) home[k] = static_cast<std::int64_t>(std::floor(key[k] / cell));
    for (const double sgn : {1.0, -1.0}) {
      Cell c0{};
      for (int k = 0; k < 4; ++k)
        c0[k] = static_cast<std::int64_t>(std::floor(sgn * key[k] / cell));
      for (int m = 0; m < 81; ++m) {
        Cell c = c0;
        for (int k = 0, r = m; k < 4; ++k, r /= 3) c[k] += r % 3 - 1;
        const auto it = grid.find(c);
        if (it == grid.end()) continue;
        for (const std::uint32_t j : it->second) {
          const auto& u = tri[j];
          const Vec3<double> nj = normals[j] * sgn;
          const double dj = dot(normals[j], vec_cast<double>(u[0]) / scale) * sgn;
          const bool near = std::abs(nj.x - n.x) <= tol && std::abs(nj.y - n.y) <= tol &&
                            std::abs(nj.z - n.z) <= tol && std::abs(dj - key[3]) <= tol;
          if (exact.find(i) != exact.find(j) && orient3d(u[0], u[1], u[2], t[0]) == Sign::zero &&
              orient3d(u[0], u[1], u[2], t[1]) == Sign::zero &&
              orient3d(u[0], u[1], u[2], t[2]) == Sign::zero) {
            exact.unite(i, j);
            dsu.unite(i, j);
          } else if (near) {
            dsu.unite(i, j);
          }
        }
      }
    }
    grid[home].push_back(i);
  }
  std::vector<std::uint32_t> id(tri.size());
  exact_id.resize(tri.size());
  for (std::uint32_t i = 0; i < tri.size(); ++i) {
    id[i] = dsu.find(i);
    exact_id[i] = exact.find(i);
  }
  return id;
}

/// The corner keys and edge lines of the faces of one operand (solid 0 or 1; its faces have
/// plane ids plane[offset + f]).
struct FaceKeys {
  std::vector<std::array<bsp3_detail::VertexKey, 3>> corners;
  std::vector<std::array<bsp3_detail::LineKey, 3>> edges;
};

template <Real T>
FaceKeys face_keys(const Bsp3<T>& t, std::uint32_t solid, std::span<const std::uint32_t> plane,
                   std::span<const Vec3<double>> normals, std::uint32_t offset) {
  using namespace bsp3_detail;
  const auto faces = t.faces();
  FaceKeys r;
  // An edge is the line of its two faces' planes when exactly one face lies on each side.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<std::uint32_t, std::uint32_t>>
      directed;  // (u, v) -> (count, face)
  for (std::uint32_t f = 0; f < faces.size(); ++f)
    for (int e = 0; e < 3; ++e) {
      auto& d = directed[{faces[f][e], faces[f][(e + 1) % 3]}];
      ++d.first;
      d.second = f;
    }
  // A vertex is the point of its faces' planes when there are exactly three, independent.
  std::vector<std::array<std::uint32_t, 4>> around(t.vertices().size(),
                                                   {bsp3_none, bsp3_none, bsp3_none, bsp3_none});
  std::vector<std::uint8_t> count(t.vertices().size(), 0);
  std::vector<std::array<std::uint32_t, 3>> face_of(t.vertices().size());
  for (std::uint32_t f = 0; f < faces.size(); ++f)
    for (const std::uint32_t v : faces[f]) {
      const std::uint32_t p = plane[offset + f];
      auto& a = around[v];
      if (a[0] == p || a[1] == p || a[2] == p) continue;
      if (count[v] < 3) face_of[v][count[v]] = offset + f;
      if (count[v] < 4) a[count[v]++] = p;
    }
  r.corners.resize(faces.size());
  r.edges.resize(faces.size());
  for (std::uint32_t f = 0; f < faces.size(); ++f)
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t u = faces[f][e], v = faces[f][(e + 1) % 3];
      VertexKey key{vertex_input, solid, u, 0, 0};
      if (count[u] == 3) {
        const auto& fo = face_of[u];
        const double det = dot(normals[fo[0]], cross(normals[fo[1]], normals[fo[2]]));
        if (std::abs(det) > 1e-9) {
          std::array<std::uint32_t, 3> k{around[u][0], around[u][1], around[u][2]};
          std::sort(k.begin(), k.end());
          key = {vertex_planes, k[0], k[1], k[2], 0};
        }
      }
      r.corners[f][e] = key;
      LineKey line{line_edge, solid, std::min(u, v), std::max(u, v)};
      const auto fwd = directed.find({u, v}), rev = directed.find({v, u});
      if (fwd != directed.end() && rev != directed.end() && fwd->second.first == 1 &&
          rev->second.first == 1) {
        const std::uint32_t p = plane[offset + f], q = plane[offset + rev->second.second];
        if (p != q) line = {line_planes, std::min(p, q), std::max(p, q), 0};
      }
      r.edges[f][e] = line;
    }
  return r;
}

/// A kept piece: vertex ids and lines (lines[i] supports v[i] -> v[i + 1]).
struct Ring {
  std::vector<std::uint32_t> v;
  std::vector<bsp3_detail::LineKey> lines;
  bool reversed = false;
};

/// Collects the kept pieces with their vertices shared by key, then makes them conforming and
/// triangulates them (see the header, "Watertight output").
template <Real T>
struct Assembler {
  std::map<bsp3_detail::VertexKey, std::uint32_t> by_key;
  std::vector<Vec3<double>> coords;
  std::vector<std::uint8_t> input;
  std::vector<Ring> rings;

  void add(const bsp3_detail::KeyedPiece& piece, bool reversed) {
    Ring ring;
    ring.reversed = reversed;
    for (std::size_t i = 0; i < piece.points.size(); ++i) {
      const auto [it, fresh] =
          by_key.try_emplace(piece.keys[i], static_cast<std::uint32_t>(coords.size()));
      if (fresh) {
        coords.push_back(piece.points[i]);
        input.push_back(piece.input[i]);
      } else if (piece.input[i] != 0 && input[it->second] == 0) {
        coords[it->second] = piece.points[i];  // an input point's exact coordinates win
        input[it->second] = 1;
      }
      ring.v.push_back(it->second);
    }
    ring.lines = piece.lines;
    rings.push_back(std::move(ring));
  }

  void finish(MeshBoolean<T>& out);
};

/// Triangulates a convex ring whose vertices may lie on its edges: a vertex is a corner when
/// its two edges have different lines. Ears are clipped only at corners while three corners
/// remain, so no triangle has its three vertices on one line (combinatorially).
inline void triangulate_ring(std::vector<std::uint32_t> v, std::vector<bsp3_detail::LineKey> l,
                             std::uint32_t& serial,
                             std::vector<std::array<std::uint32_t, 3>>& tris) {
  const auto emit = [&tris](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    if (a != b && b != c && a != c) tris.push_back({a, b, c});
  };
  while (v.size() > 3) {
    const std::size_t m = v.size();
    const auto corner = [&l, m](std::size_t i) { return l[(i + m - 1) % m] != l[i]; };
    std::size_t corners = 0;
    for (std::size_t i = 0; i < m; ++i) corners += corner(i) ? 1 : 0;
    std::size_t pick = m;
    for (std::size_t i = 0; i < m && pick == m; ++i) {
      if (!corner(i)) continue;
      const std::size_t rest =
          corners - 1 + (corner((i + m - 1) % m) ? 0 : 1) + (corner((i + 1) % m) ? 0 : 1);
      if (rest >= 3) pick = i;
    }
    if (pick == m) break;  // not for a ring of at least three corners
    const std::size_t prev = (pick + m - 1) % m, next = (pick + 1) % m;
    emit(v[prev], v[pick], v[next]);
    l[prev] = {bsp3_detail::line_unique, serial++, 0, 0};  // the diagonal prev -> next
    v.erase(v.begin() + static_cast<std::ptrdiff_t>(pick));
    l.erase(l.begin() + static_cast<std::ptrdiff_t>(pick));
  }
  // Three vertices, or a ring without three corners (rounding): a fan keeps every ring edge once.
  for (std::size_t k = 1; k + 1 < v.size(); ++k) emit(v[0], v[k], v[k + 1]);
}

template <Real T>
void Assembler<T>::finish(MeshBoolean<T>& out) {
  using bsp3_detail::LineKey;
  // Weld vertices whose coordinates round to the same T point (-0 = +0).
  Dsu dsu(coords.size());
  {
    std::map<std::array<T, 3>, std::uint32_t> at;
    for (std::uint32_t i = 0; i < coords.size(); ++i) {
      const Vec3<T> p = vec_cast<T>(coords[i]);
      const auto [it, fresh] = at.try_emplace({p.x + T(0), p.y + T(0), p.z + T(0)}, i);
      if (!fresh) dsu.unite(it->second, i);
    }
  }
  // Rings on welded ids, zero-length edges removed.
  for (Ring& r : rings) {
    for (std::uint32_t& x : r.v) x = dsu.find(x);
    std::vector<std::uint32_t> v;
    std::vector<LineKey> l;
    for (std::size_t i = 0; i < r.v.size(); ++i) {
      if (!v.empty() && v.back() == r.v[i]) {
        l.back() = r.lines[i];  // drop the zero-length edge, keep the next one's line
        continue;
      }
      v.push_back(r.v[i]);
      l.push_back(r.lines[i]);
    }
    while (v.size() > 1 && v.back() == v.front()) {
      v.pop_back();
      l.pop_back();
    }
    r.v = std::move(v);
    r.lines = std::move(l);
  }
  // Every vertex on a line, ordered along the line's dominant axis (one order per line, so the
  // two sides of an edge split it at the same vertices in the same order).
  std::map<LineKey, std::uint32_t> line_index;
  std::vector<std::vector<std::uint32_t>> members;
  for (const Ring& r : rings) {
    if (r.v.size() < 3) continue;
    for (std::size_t i = 0; i < r.v.size(); ++i) {
      if (r.lines[i][0] == bsp3_detail::line_unique) continue;
      const auto [it, fresh] =
          line_index.try_emplace(r.lines[i], static_cast<std::uint32_t>(members.size()));
      if (fresh) members.emplace_back();
      members[it->second].push_back(r.v[i]);
      members[it->second].push_back(r.v[(i + 1) % r.v.size()]);
    }
  }
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> position(members.size());
  for (std::size_t L = 0; L < members.size(); ++L) {
    auto& m = members[L];
    std::sort(m.begin(), m.end());
    m.erase(std::unique(m.begin(), m.end()), m.end());
    Vec3<double> lo = coords[m[0]], hi = coords[m[0]];
    for (const std::uint32_t x : m)
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], coords[x][k]);
        hi[k] = std::max(hi[k], coords[x][k]);
      }
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
    std::sort(m.begin(), m.end(), [this, axis](std::uint32_t x, std::uint32_t y) {
      return coords[x][axis] != coords[y][axis] ? coords[x][axis] < coords[y][axis] : x < y;
    });
    for (std::uint32_t p = 0; p < m.size(); ++p) position[L].push_back({m[p], p});
    std::sort(position[L].begin(), position[L].end());
  }
  const auto where = [&position](std::size_t L, std::uint32_t x) {
    const auto& pos = position[L];
    const auto it =
        std::lower_bound(pos.begin(), pos.end(), std::pair<std::uint32_t, std::uint32_t>{x, 0});
    return it->second;
  };
  std::uint32_t serial = 0;
  std::vector<std::array<std::uint32_t, 3>> tris;
  for (const Ring& r : rings) {
    if (r.v.size() < 3) continue;
    std::vector<std::uint32_t> v;
    std::vector<LineKey> l;
    for (std::size_t i = 0; i < r.v.size(); ++i) {
      const std::uint32_t x = r.v[i], y = r.v[(i + 1) % r.v.size()];
      v.push_back(x);
      l.push_back(r.lines[i]);
      if (r.lines[i][0] == bsp3_detail::line_unique) continue;
      const std::size_t L = line_index.at(r.lines[i]);
      const std::uint32_t px = where(L, x), py = where(L, y);
      if (px < py) {
        for (std::uint32_t p = px + 1; p < py; ++p) {
          v.push_back(members[L][p]);
          l.push_back(r.lines[i]);
        }
      } else {
        for (std::uint32_t p = px; p-- > py + 1;) {
          v.push_back(members[L][p]);
          l.push_back(r.lines[i]);
        }
      }
    }
    if (r.reversed) {
      // Reverse the ring; the line of edge i -> i + 1 becomes that of edge i + 1 -> i.
      std::reverse(v.begin(), v.end());
      std::reverse(l.begin(), l.end());
      std::rotate(l.begin(), l.begin() + 1, l.end());
    }
    triangulate_ring(std::move(v), std::move(l), serial, tris);
  }
  // Compact the used vertices.
  std::vector<std::uint32_t> remap(coords.size(), bsp3_none);
  for (auto& t : tris)
    for (std::uint32_t& x : t) {
      if (remap[x] == bsp3_none) {
        remap[x] = static_cast<std::uint32_t>(out.vertices.size());
        const Vec3<T> p = vec_cast<T>(coords[x]);
        out.vertices.push_back({p.x + T(0), p.y + T(0), p.z + T(0)});
      }
      x = remap[x];
    }
  out.triangles = std::move(tris);
}

/// Adds the pieces of every face of `from` partitioned by `by` whose location passes `keep`.
template <Real T, class Keep>
void clip_faces(const Bsp3<T>& from, std::uint32_t from_offset, const FaceKeys& keys,
                const Bsp3<T>& by, std::uint32_t by_offset, std::span<const std::uint32_t> plane,
                std::span<const std::uint32_t> exact_plane, Keep keep, bool reversed,
                std::uint32_t& serial, Assembler<T>& out) {
  const auto v = from.vertices();
  const auto faces = from.faces();
  const std::span<const std::uint32_t> by_planes = plane.subspan(by_offset, by.faces().size()),
                                       by_exact = exact_plane.subspan(by_offset, by.faces().size());
  for (std::uint32_t f = 0; f < faces.size(); ++f) {
    const Vec3<T> tri[3] = {v[faces[f][0]], v[faces[f][1]], v[faces[f][2]]};
    const auto pieces = bsp3_detail::partition_keyed<T>(
        by, by_exact, by_planes, std::span<const Vec3<T>>(tri, 3),
        std::span<const bsp3_detail::VertexKey>(keys.corners[f]),
        std::span<const bsp3_detail::LineKey>(keys.edges[f]), plane[from_offset + f], serial);
    for (const auto& piece : pieces)
      if (keep(piece.location)) out.add(piece, reversed);
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
  std::vector<Vec3<double>> normals;
  std::vector<std::uint32_t> exact_plane;
  const std::vector<std::uint32_t> plane = number_planes(a, b, normals, exact_plane);
  const auto fa = static_cast<std::uint32_t>(a.faces().size());
  const FaceKeys ka = face_keys(a, 0, plane, normals, 0), kb = face_keys(b, 1, plane, normals, fa);
  std::uint32_t serial = 0;
  Assembler<T> out;
  using L = Bsp3Location;
  const auto is = [](std::initializer_list<L> set) {
    return [set](L l) { return std::find(set.begin(), set.end(), l) != set.end(); };
  };
  // (keep pieces of A at these locations in B, keep reversed, the same for B in A)
  const auto both = [&](auto keep_a, bool rev_a, auto keep_b, bool rev_b) {
    clip_faces(a, 0, ka, b, fa, plane, exact_plane, keep_a, rev_a, serial, out);
    clip_faces(b, fa, kb, a, 0, plane, exact_plane, keep_b, rev_b, serial, out);
  };
  switch (op) {
    case MeshBooleanOp::union_:
      both(is({L::outside, L::coincident_same}), false, is({L::outside}), false);
      break;
    case MeshBooleanOp::intersection:
      both(is({L::inside, L::coincident_same}), false, is({L::inside}), false);
      break;
    case MeshBooleanOp::difference:
      both(is({L::outside, L::coincident_opposite}), false, is({L::inside}), true);
      break;
    case MeshBooleanOp::symmetric_difference:
      // (A - B) + (B - A): A's outside pieces, A's inside pieces reversed, and the same for B;
      // coincident faces bound the result on neither side.
      both(is({L::outside}), false, is({L::outside}), false);
      both(is({L::inside}), true, is({L::inside}), true);
      break;
  }
  out.finish(r);
  return r;
}

template <Real T>
MeshBoolean<T> mesh_complement(std::span<const Vec3<T>> vertices,
                               std::span<const std::array<std::uint32_t, 3>> triangles) {
  MeshBoolean<T> r;
  if (triangles.empty()) return r;  // empty_input
  for (const auto& t : triangles)
    for (const std::uint32_t i : t)
      if (i >= vertices.size()) {
        r.status = Status::invalid_input;
        return r;
      }
  for (const auto& v : vertices)
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
      r.status = Status::non_finite_input;
      return r;
    }
  r.status = Status::ok;
  r.vertices.assign(vertices.begin(), vertices.end());
  r.triangles.reserve(triangles.size());
  for (const auto& t : triangles) r.triangles.push_back({t[0], t[2], t[1]});
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
      std::span<const Vec3<T>>, std::span<const std::array<std::uint32_t, 3>>, Bsp3Options);  \
  template MeshBoolean<T> mesh_complement(std::span<const Vec3<T>>,                           \
                                          std::span<const std::array<std::uint32_t, 3>>);
LOCUS_BSP3_BOOLEAN_INSTANTIATE(float)
LOCUS_BSP3_BOOLEAN_INSTANTIATE(double)

}  // namespace locus
