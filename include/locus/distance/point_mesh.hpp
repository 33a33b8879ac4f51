// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a point and a triangle mesh (the surface), with a bounding-volume hierarchy
// for many queries on one mesh, and the exact inside/outside classification of a closed mesh for
// a signed distance; row dist3.pt-polyhedron (general polyhedron); book section 10.3.4 (figure
// 10.20). Convex polyhedra and tetrahedra (solids, O(F)) are in point_polyhedron.hpp.
//
// Input: vertices (Vec3) and triangles (std::array<std::uint32_t, 3> of vertex indices), the
// layout of containment/point_in_polyhedron.hpp; triangle {i, j, k} has normal
// (vj - vi) x (vk - vi). MeshDistanceTree<T> (compiled in src/distance/point_mesh.cpp) copies
// them into an AABB tree (median splits, leaves of at most 4 triangles). Build O(F log F) time,
// O(F) memory; queries never allocate and are reentrant.
//  * distance(p, tree) -> Distance<T, 3, NoParam, MeshPoint<T>>: closest[1] the nearest point of
//    the surface (need not be closed or manifold), param_b = {input triangle index, barycentric
//    (u, v, w)}, closest[1] = point_at(tree, param_b). The brute-force minimum over the
//    triangles (exact ties prefer the lower index visited), by best-first branch and bound:
//    O(log F) nodes near a well-shaped mesh, O(F) worst case. distance(tree, p) is swapped;
//    distance_to_mesh(p, vertices, triangles) is the one-call O(F) form without a tree.
//  * classify(p, tree): EXACT for finite input; Side::boundary on the surface, else the parity
//    of a +x ray perturbed by Simulation of Simplicity (containment/point_in_polyhedron.hpp's
//    rule). Meaningful for closed meshes (tree.closed(): every edge used an even number of
//    times); self-intersections are read by the even-odd rule. signed_distance(p, tree) =
//    -distance inside, 0 on the boundary, +distance outside.
// Bad input (tree.status()): no triangles -> empty_input; an index out of range -> invalid_input;
// a non-finite used vertex -> non_finite_input. Such a tree, or a non-finite query point, gives
// the NaN result (triangle MeshPoint::none), Side::outside and NaN. Degenerate triangles act as
// segments or points. unique is true (exact ties between triangles are not detected).

#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/side.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/point_triangle.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/triangle.hpp>

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace locus {

/// A point of a triangle mesh: the input triangle's index and barycentric coordinates in it.
template <Real T>
struct MeshPoint {
  static constexpr std::uint32_t none = 0xffffffffu;  ///< no triangle (the NaN result)
  std::uint32_t triangle = none;
  Vec3<T> barycentric{};
  friend constexpr bool operator==(const MeshPoint&, const MeshPoint&) noexcept = default;
};

/// Bounding-box tree over the triangles of a mesh, for nearest-point and inside queries.
template <Real T>
class MeshDistanceTree {
 public:
  struct Node {
    Vec3<T> lo, hi;       ///< bounds of the node's triangles
    std::uint32_t first;  ///< leaf: first triangle slot; internal: index of the left child
    std::uint32_t count;  ///< leaf: number of triangles (> 0); internal: 0 (right = first + 1)
  };

  MeshDistanceTree() = default;
  /// Builds the tree (see the header comment for the status values).
  MeshDistanceTree(std::span<const Vec3<T>> vertices,
                   std::span<const std::array<std::uint32_t, 3>> triangles);
  /// The same for any point range (core/point_range.hpp).
  template <PointRange3 R>
  requires std::same_as<range_scalar_t<R>, T> MeshDistanceTree(
      const R& vertices, std::span<const std::array<std::uint32_t, 3>> triangles)
      : MeshDistanceTree(point_span(vertices), triangles) {}

  [[nodiscard]] Status status() const noexcept { return status_; }
  /// Every undirected edge is used by an even number of triangles (classify() is meaningful).
  [[nodiscard]] bool closed() const noexcept { return closed_; }
  [[nodiscard]] std::size_t triangle_count() const noexcept { return tris_.size(); }
  [[nodiscard]] std::span<const Node> nodes() const noexcept { return nodes_; }
  /// The input triangle `id` (as stored; id < triangle_count()).
  [[nodiscard]] Triangle3<T> triangle(std::uint32_t id) const noexcept { return tris_[slot_[id]]; }

  /// Nearest surface point; see distance(p, tree).
  [[nodiscard]] Distance<T, 3, NoParam, MeshPoint<T>> nearest(const Vec3<T>& p) const noexcept;
  /// Exact inside/boundary/outside for a closed mesh; see classify(p, tree).
  [[nodiscard]] Side classify(const Vec3<T>& p) const noexcept;

 private:
  std::vector<Node> nodes_;
  std::vector<Triangle3<T>> tris_;   // in leaf order
  std::vector<std::uint32_t> ids_;   // input index of each slot
  std::vector<std::uint32_t> slot_;  // slot of each input index
  Status status_ = Status::empty_input;
  bool closed_ = false;
};

extern template class MeshDistanceTree<float>;
extern template class MeshDistanceTree<double>;

/// The point of the mesh with parameter mp: point_at_barycentric of the input triangle.
template <Real T>
[[nodiscard]] inline Vec3<T> point_at(const MeshDistanceTree<T>& tree,
                                      const MeshPoint<T>& mp) noexcept {
  return point_at_barycentric(tree.triangle(mp.triangle), mp.barycentric);
}

/// Distance from p to the mesh surface; param_b = {input triangle index, barycentric}.
template <Real T>
[[nodiscard]] inline Distance<T, 3, NoParam, MeshPoint<T>> distance(
    const Vec3<T>& p, const MeshDistanceTree<T>& tree) noexcept {
  return tree.nearest(p);
}

/// The swapped query: closest[0] and param_a belong to the mesh.
template <Real T>
[[nodiscard]] inline Distance<T, 3, MeshPoint<T>, NoParam> distance(const MeshDistanceTree<T>& tree,
                                                                    const Vec3<T>& p) noexcept {
  return swapped(tree.nearest(p));
}

/// Exact classification of p against the closed mesh (Side::outside for a bad tree or p).
template <Real T>
[[nodiscard]] inline Side classify(const Vec3<T>& p, const MeshDistanceTree<T>& tree) noexcept {
  return tree.classify(p);
}

/// -distance inside, 0 on the surface, +distance outside (NaN for a bad tree or p).
template <Real T>
[[nodiscard]] inline T signed_distance(const Vec3<T>& p, const MeshDistanceTree<T>& tree) noexcept {
  const auto d = tree.nearest(p);
  if (!(d.distance == d.distance)) return d.distance;
  const Side s = tree.classify(p);
  if (s == Side::boundary) return T(0);
  return s == Side::inside ? -d.distance : d.distance;
}

namespace detail {

template <Real T>
[[nodiscard]] constexpr Distance<T, 3, NoParam, MeshPoint<T>> mesh_nan_distance() noexcept {
  constexpr T nan = std::numeric_limits<T>::quiet_NaN();
  return {nan,
          nan,
          {splat<T, 3>(nan), splat<T, 3>(nan)},
          NoParam{},
          MeshPoint<T>{MeshPoint<T>::none, splat<T, 3>(nan)},
          false};
}

}  // namespace detail

/// One-call brute-force distance from p to the mesh surface (O(F), no tree, no allocation);
/// the same answer and bad-input rules as the tree (see the header comment).
template <Real T>
[[nodiscard]] inline Distance<T, 3, NoParam, MeshPoint<T>> distance_to_mesh(
    const Vec3<T>& p, std::span<const Vec3<T>> vertices,
    std::span<const std::array<std::uint32_t, 3>> triangles) noexcept {
  if (triangles.empty() || !is_finite(p)) return detail::mesh_nan_distance<T>();
  T best = std::numeric_limits<T>::infinity();
  MeshPoint<T> mp{};
  Vec3<T> q{};
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const auto& t = triangles[i];
    if (t[0] >= vertices.size() || t[1] >= vertices.size() || t[2] >= vertices.size())
      return detail::mesh_nan_distance<T>();
    const auto r = distance(p, Triangle3<T>{vertices[t[0]], vertices[t[1]], vertices[t[2]]});
    if (!(r.sqr_distance == r.sqr_distance)) return detail::mesh_nan_distance<T>();
    if (r.sqr_distance < best) {
      best = r.sqr_distance;
      mp = {static_cast<std::uint32_t>(i), r.param_b};
      q = r.closest[1];
    }
  }
  return detail::make_distance(p, q, NoParam{}, mp, true);
}

template <PointRange3 R>
MeshDistanceTree(const R&, std::span<const std::array<std::uint32_t, 3>>)
    -> MeshDistanceTree<range_scalar_t<R>>;

/// distance_to_mesh for any point range (core/point_range.hpp).
template <PointRange3 R>
[[nodiscard]] inline Distance<range_scalar_t<R>, 3, NoParam, MeshPoint<range_scalar_t<R>>>
distance_to_mesh(const range_point_t<R>& p, const R& vertices,
                 std::span<const std::array<std::uint32_t, 3>> triangles) noexcept {
  return distance_to_mesh(p, point_span(vertices), triangles);
}

}  // namespace locus
