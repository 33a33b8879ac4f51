// SPDX-License-Identifier: BSL-1.0
// MeshDistanceTree (include/locus/distance/point_mesh.hpp): build, nearest-point and exact
// classification queries, compiled once for float and double.
#include <locus/core/predicates.hpp>
#include <locus/distance/point_mesh.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace locus {

namespace {

// Squared distance from p to the box [lo, hi] (0 inside).
template <Real T>
inline T box_sqr_distance(const Vec3<T>& p, const Vec3<T>& lo, const Vec3<T>& hi) noexcept {
  T s = T(0);
  for (int i = 0; i < 3; ++i) {
    const T e = p[i] < lo[i] ? lo[i] - p[i] : (p[i] > hi[i] ? p[i] - hi[i] : T(0));
    s += e * e;
  }
  return s;
}

// Exact: p on the closed segment [a, b] (a point when a == b): inside the coordinate box and
// collinear in all three coordinate projections.
template <Real T>
bool on_segment3(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& p) noexcept {
  for (int i = 0; i < 3; ++i)
    if (p[i] < std::min(a[i], b[i]) || p[i] > std::max(a[i], b[i])) return false;
  const Vec2<T> axy{a.x, a.y}, bxy{b.x, b.y}, pxy{p.x, p.y};
  const Vec2<T> ayz{a.y, a.z}, byz{b.y, b.z}, pyz{p.y, p.z};
  const Vec2<T> azx{a.z, a.x}, bzx{b.z, b.x}, pzx{p.z, p.x};
  return orient2d(axy, bxy, pxy) == Sign::zero && orient2d(ayz, byz, pyz) == Sign::zero &&
         orient2d(azx, bzx, pzx) == Sign::zero;
}

template <Real T>
Vec2<T> project_out(const Vec3<T>& v, int axis) noexcept {
  return axis == 0 ? Vec2<T>{v.y, v.z} : (axis == 1 ? Vec2<T>{v.z, v.x} : Vec2<T>{v.x, v.y});
}

// Exact: p on the closed triangle abc (coplanar, then inside in a projection where the triangle
// keeps its area; a degenerate triangle is the union of its edges).
template <Real T>
bool on_triangle3(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, const Vec3<T>& p) noexcept {
  if (orient3d(a, b, c, p) != Sign::zero) return false;
  for (int k = 0; k < 3; ++k) {
    const Vec2<T> a2 = project_out(a, k), b2 = project_out(b, k), c2 = project_out(c, k);
    const int o = to_int(orient2d(a2, b2, c2));
    if (o == 0) continue;
    const Vec2<T> p2 = project_out(p, k);
    return to_int(orient2d(a2, b2, p2)) * o >= 0 && to_int(orient2d(b2, c2, p2)) * o >= 0 &&
           to_int(orient2d(c2, a2, p2)) * o >= 0;
  }
  return on_segment3(a, b, p) || on_segment3(b, c, p) || on_segment3(c, a, p);
}

// Side of the moved point (q.y + e, q.z + e^2), e -> 0+, relative to the yz-line a -> b:
// orient2d first, then the coefficient of e, then that of e^2.
template <Real T>
int side_perturbed(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& q) noexcept {
  const int s = to_int(orient2d(Vec2<T>{a.y, a.z}, Vec2<T>{b.y, b.z}, Vec2<T>{q.y, q.z}));
  if (s != 0) return s;
  // orient2d = (b.y - a.y)(q.z - a.z) - (b.z - a.z)(q.y - a.y): moving q.y by e adds
  // -(b.z - a.z) e, moving q.z by e^2 adds (b.y - a.y) e^2.
  if (b.z != a.z) return b.z < a.z ? 1 : -1;
  if (b.y != a.y) return b.y > a.y ? 1 : -1;
  return 0;
}

}  // namespace

template <Real T>
MeshDistanceTree<T>::MeshDistanceTree(std::span<const Vec3<T>> vertices,
                                      std::span<const std::array<std::uint32_t, 3>> triangles) {
  const std::size_t nt = triangles.size();
  if (nt == 0) {
    status_ = Status::empty_input;
    return;
  }
  if (nt >= std::size_t{0xffffffffu}) {
    status_ = Status::limit_exceeded;
    return;
  }
  for (const auto& t : triangles) {
    for (const std::uint32_t i : t) {
      if (i >= vertices.size()) {
        status_ = Status::invalid_input;
        return;
      }
      if (!is_finite(vertices[i])) {
        status_ = Status::non_finite_input;
        return;
      }
    }
  }
  status_ = Status::ok;

  // Closedness: every undirected edge used an even number of times.
  {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    edges.reserve(3 * nt);
    for (const auto& t : triangles)
      for (int e = 0; e < 3; ++e) {
        const std::uint32_t a = t[static_cast<std::size_t>(e)],
                            b = t[static_cast<std::size_t>((e + 1) % 3)];
        edges.emplace_back(std::min(a, b), std::max(a, b));
      }
    std::sort(edges.begin(), edges.end());
    closed_ = true;
    for (std::size_t i = 0; i < edges.size();) {
      std::size_t j = i;
      while (j < edges.size() && edges[j] == edges[i]) ++j;
      if ((j - i) % 2 != 0) closed_ = false;
      i = j;
    }
  }

  // Centroids (times 3) and the permutation that the median splits reorder.
  std::vector<Vec3<T>> cen(nt);
  ids_.resize(nt);
  for (std::size_t i = 0; i < nt; ++i) {
    const auto& t = triangles[i];
    cen[i] = vertices[t[0]] + vertices[t[1]] + vertices[t[2]];
    ids_[i] = static_cast<std::uint32_t>(i);
  }
  nodes_.reserve(2 * (nt / 2 + 1));
  nodes_.push_back({});
  struct Task {
    std::uint32_t node, first, count;
  };
  std::vector<Task> pending{{0, 0, static_cast<std::uint32_t>(nt)}};
  constexpr std::uint32_t leaf_size = 4;
  while (!pending.empty()) {
    const Task task = pending.back();
    pending.pop_back();
    Vec3<T> lo = splat<T, 3>(std::numeric_limits<T>::infinity()), hi = -lo;
    Vec3<T> clo = lo, chi = hi;
    for (std::uint32_t s = task.first; s < task.first + task.count; ++s) {
      const auto& t = triangles[ids_[s]];
      for (const std::uint32_t v : t) {
        lo = cwise_min(lo, vertices[v]);
        hi = cwise_max(hi, vertices[v]);
      }
      clo = cwise_min(clo, cen[ids_[s]]);
      chi = cwise_max(chi, cen[ids_[s]]);
    }
    Node& node = nodes_[task.node];
    node.lo = lo;
    node.hi = hi;
    if (task.count <= leaf_size) {
      node.first = task.first;
      node.count = task.count;
      continue;
    }
    const Vec3<T> ext = chi - clo;
    const int axis = ext.x >= ext.y ? (ext.x >= ext.z ? 0 : 2) : (ext.y >= ext.z ? 1 : 2);
    const std::uint32_t half = task.count / 2;
    const auto begin = ids_.begin() + task.first;
    std::nth_element(begin, begin + half, begin + task.count,
                     [&](std::uint32_t a, std::uint32_t b) { return cen[a][axis] < cen[b][axis]; });
    const auto left = static_cast<std::uint32_t>(nodes_.size());
    node.first = left;
    node.count = 0;
    nodes_.push_back({});
    nodes_.push_back({});
    pending.push_back({left + 1, task.first + half, task.count - half});
    pending.push_back({left, task.first, half});
  }
  tris_.resize(nt);
  slot_.resize(nt);
  for (std::size_t s = 0; s < nt; ++s) {
    const auto& t = triangles[ids_[s]];
    tris_[s] = {vertices[t[0]], vertices[t[1]], vertices[t[2]]};
    slot_[ids_[s]] = static_cast<std::uint32_t>(s);
  }
}

template <Real T>
Distance<T, 3, NoParam, MeshPoint<T>> MeshDistanceTree<T>::nearest(
    const Vec3<T>& p) const noexcept {
  if (status_ != Status::ok || !is_finite(p)) return detail::mesh_nan_distance<T>();
  struct Entry {
    std::uint32_t node;
    T bound;
  };
  // Median splits bound the depth by log2(F) + 1 <= 33; each level leaves at most one entry.
  Entry stack[72];
  int top = 0;
  stack[top++] = {0, box_sqr_distance(p, nodes_[0].lo, nodes_[0].hi)};
  T best = std::numeric_limits<T>::infinity();
  std::uint32_t best_slot = 0;
  Vec3<T> best_bary{T(1), T(0), T(0)};
  Vec3<T> best_point = tris_[0].v0;
  while (top > 0) {
    const Entry e = stack[--top];
    if (!(e.bound < best)) continue;
    const Node& node = nodes_[e.node];
    if (node.count > 0) {
      for (std::uint32_t s = node.first; s < node.first + node.count; ++s) {
        const auto r = distance(p, tris_[s]);
        if (r.sqr_distance < best || (r.sqr_distance == best && ids_[s] < ids_[best_slot])) {
          best = r.sqr_distance;
          best_slot = s;
          best_bary = r.param_b;
          best_point = r.closest[1];
        }
      }
      continue;
    }
    const std::uint32_t a = node.first, b = node.first + 1;
    const T da = box_sqr_distance(p, nodes_[a].lo, nodes_[a].hi);
    const T db = box_sqr_distance(p, nodes_[b].lo, nodes_[b].hi);
    // Push the farther child first so that the nearer one is opened next.
    if (da <= db) {
      if (db < best) stack[top++] = {b, db};
      if (da < best) stack[top++] = {a, da};
    } else {
      if (da < best) stack[top++] = {a, da};
      if (db < best) stack[top++] = {b, db};
    }
  }
  return detail::make_distance(p, best_point, NoParam{}, MeshPoint<T>{ids_[best_slot], best_bary},
                               true);
}

template <Real T>
Side MeshDistanceTree<T>::classify(const Vec3<T>& p) const noexcept {
  if (status_ != Status::ok || !is_finite(p)) return Side::outside;
  // The perturbed ray p + (0, e, e^2) + lambda (1, 0, 0), lambda >= 0, stays inside the closed
  // slab box {y = p.y, z = p.z, x >= p.x} up to infinitesimals: visit the nodes whose closed box
  // meets that ray.
  std::uint32_t stack[72];
  int top = 0;
  stack[top++] = 0;
  bool odd = false;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (p.y < node.lo.y || p.y > node.hi.y || p.z < node.lo.z || p.z > node.hi.z || p.x > node.hi.x)
      continue;
    if (node.count == 0) {
      stack[top++] = node.first;
      stack[top++] = node.first + 1;
      continue;
    }
    for (std::uint32_t s = node.first; s < node.first + node.count; ++s) {
      const Vec3<T>&a = tris_[s].v0, &b = tris_[s].v1, &c = tris_[s].v2;
      const T ylo = std::min({a.y, b.y, c.y}), yhi = std::max({a.y, b.y, c.y});
      const T zlo = std::min({a.z, b.z, c.z}), zhi = std::max({a.z, b.z, c.z});
      const T xlo = std::min({a.x, b.x, c.x}), xhi = std::max({a.x, b.x, c.x});
      if (p.y < ylo || p.y > yhi || p.z < zlo || p.z > zhi || p.x > xhi) continue;
      if (p.x >= xlo && on_triangle3(a, b, c, p)) return Side::boundary;
      // Sign of the normal's x component: the triangle's orientation seen along x.
      const int sx = to_int(orient2d(Vec2<T>{a.y, a.z}, Vec2<T>{b.y, b.z}, Vec2<T>{c.y, c.z}));
      if (sx == 0) continue;  // parallel to the ray: the perturbed ray never meets it
      if (side_perturbed(a, b, p) != sx || side_perturbed(b, c, p) != sx ||
          side_perturbed(c, a, p) != sx)
        continue;
      // The ray's line meets the triangle; the hit is ahead of p iff p is behind the plane
      // relative to the normal's x component (p is not on the triangle, tested above).
      if (to_int(orient3d(a, b, c, p)) == -sx) odd = !odd;
    }
  }
  return odd ? Side::inside : Side::outside;
}

template class MeshDistanceTree<float>;
template class MeshDistanceTree<double>;

}  // namespace locus
