// SPDX-License-Identifier: BSL-1.0
#pragma once
// Bounding volume hierarchy over a triangle mesh or over boxes of user objects; row
// int3.linear-polyhedron (ray against a triangle mesh) and the BVH of issue 20; book 11.5.
// Build (src/spatial/bvh.cpp, float and double): surface-area heuristic on 16 (options.bins)
// centroid bins per axis, leaves of at most options.leaf_size primitives, then collapsed to
// 4-wide nodes whose boxes are stored as float after an exact power-of-two rescaling of the
// scene, rounded outwards; leaf triangles are stored in packets of 4 (structure of arrays).
// Mesh input: the layout of point_mesh.hpp (vertices, triangles {i, j, k}, normal
// (vj - vi) x (vk - vi)). Ray queries use watertight_hit() of ray_triangle.hpp for every
// triangle (a packet's four edge filters run in SIMD lanes first; only the triangles the filter
// cannot reject run the exact test), so every answer equals the brute force over the triangles:
//  * closest_hit(ray, tmax): the hit with the least t <= tmax (MeshHit: triangle, t,
//    barycentric, front); exact ties in t go to the lower triangle index.
//  * any_hit(ray, tmax): some triangle hit with t <= tmax (occlusion).
//  * all_hits(ray, tmax): every hit with t <= tmax, by increasing (t, triangle).
//  * closest_hits / any_hits: batches (threads > 1 splits the batch over std::threads).
//  * distance(p, bvh): point-mesh distance, the same answer as distance_to_mesh (point_mesh.hpp).
// A watertight mesh therefore never leaks a ray through a shared edge or vertex and reports
// exactly one triangle there. Box culling is conservative: the float slab test of a node is
// widened by 2^-20 (|scene| + |origin|) along each axis, which covers every rounding in the
// test and in the hit parameter; NaN slab values (a zero direction component on a box plane)
// never cull. Boxes: Bvh::from_boxes(boxes); visit_ray(ray, tmax, f) calls f(id, tmax) for at
// least every box the ray meets within tmax (f returns the new tmax), visit_overlaps(box, f)
// calls f(id) for exactly the boxes meeting the closed query box.
// Bad input (status()): no primitives -> empty_input; an index out of range -> invalid_input; a
// non-finite used vertex or box -> non_finite_input; such a Bvh hits nothing (distance is NaN).
// A NaN, infinite or zero ray never hits. Queries never allocate except all_hits (its vector).

#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/point_mesh.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/aligned_box.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/triangle.hpp>

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <new>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace locus {

template <Real T>
class Bvh;
namespace detail {
template <Real T>
struct BvhCore;

/// Storage of a Bvh's arrays (src/spatial/bvh.cpp): blocks of 4 MiB or more are advised to use
/// transparent huge pages (Linux), since a ray visits a few random nodes and packets of tens of
/// megabytes and a 4 KiB page would cost a TLB miss on nearly every one of them.
void* bvh_allocate(std::size_t bytes, std::size_t align);
void bvh_deallocate(void* p, std::size_t bytes, std::size_t align) noexcept;

template <class U>
struct BvhAllocator {
  using value_type = U;
  BvhAllocator() noexcept = default;
  template <class W>
  constexpr BvhAllocator(const BvhAllocator<W>&) noexcept {}  // NOLINT: allocator rebinding
  [[nodiscard]] U* allocate(std::size_t n) {
    if (n > std::numeric_limits<std::size_t>::max() / sizeof(U)) throw std::bad_array_new_length();
    return static_cast<U*>(bvh_allocate(n * sizeof(U), alignof(U)));
  }
  void deallocate(U* p, std::size_t n) noexcept { bvh_deallocate(p, n * sizeof(U), alignof(U)); }
  template <class W>
  friend constexpr bool operator==(const BvhAllocator&, const BvhAllocator<W>&) noexcept {
    return true;
  }
};
}  // namespace detail

/// A ray's hit on a triangle mesh (closest_hit, all_hits).
template <Real T>
struct MeshHit {
  static constexpr std::uint32_t none = 0xffffffffu;  ///< no hit
  std::uint32_t triangle = none;                      ///< input triangle index
  T t = T(0);                                         ///< ray parameter of the hit
  Vec3<T> barycentric{};  ///< (b0, b1, b2) of the hit point in the triangle
  bool front = false;     ///< the ray arrives from the side the triangle's normal points to
  [[nodiscard]] constexpr explicit operator bool() const noexcept { return triangle != none; }
  friend constexpr bool operator==(const MeshHit&, const MeshHit&) noexcept = default;
};

/// Build parameters of a Bvh.
struct BvhOptions {
  int bins = 16;      ///< SAH bins per axis (clamped to 2..64)
  int leaf_size = 4;  ///< at most this many primitives per leaf (clamped to 1..16)
};

/// An 8-wide bounding volume hierarchy over triangles or boxes (see the header comment).
template <Real T>
class Bvh {
 public:
  static constexpr int width = 8;  ///< children per node
  /// `width` children: boxes in the scaled float frame, lanes lo x, y, z then hi x, y, z.
  struct alignas(64) Node {
    float box[6][width];
    std::uint32_t child[width];  ///< internal: node index; leaf: first slot
    std::uint32_t count[width];  ///< 0: empty; internal_child: a node; else leaf primitive count
  };
  static constexpr std::uint32_t internal_child = 0xffffffffu;

  Bvh() = default;
  /// Builds over a triangle mesh.
  Bvh(std::span<const Vec3<T>> vertices, std::span<const std::array<std::uint32_t, 3>> triangles,
      BvhOptions options = {});
  /// The same for any point range (core/point_range.hpp).
  template <PointRange3 R>
  requires std::same_as<range_scalar_t<R>, T> Bvh(
      const R& vertices, std::span<const std::array<std::uint32_t, 3>> triangles,
      BvhOptions options = {})
      : Bvh(point_span(vertices), triangles, options) {}
  /// Builds over boxes of user objects (box i is object i).
  [[nodiscard]] static Bvh from_boxes(std::span<const AlignedBox3<T>> boxes,
                                      BvhOptions options = {});

  [[nodiscard]] Status status() const noexcept { return status_; }
  [[nodiscard]] std::size_t primitive_count() const noexcept { return count_; }
  [[nodiscard]] std::size_t node_count() const noexcept { return nodes_.size(); }
  [[nodiscard]] bool has_triangles() const noexcept { return !tris_.empty(); }
  /// The input triangle `id` (mesh mode, id < primitive_count()).
  [[nodiscard]] Triangle3<T> triangle(std::uint32_t id) const noexcept;

  [[nodiscard]] MeshHit<T> closest_hit(const Ray3<T>& ray,
                                       T tmax = std::numeric_limits<T>::infinity()) const noexcept;
  [[nodiscard]] bool any_hit(const Ray3<T>& ray,
                             T tmax = std::numeric_limits<T>::infinity()) const noexcept;
  /// Every hit with t <= tmax into `out` (cleared first), by increasing (t, triangle).
  void all_hits(const Ray3<T>& ray, T tmax, std::vector<MeshHit<T>>& out) const;
  [[nodiscard]] std::vector<MeshHit<T>> all_hits(
      const Ray3<T>& ray, T tmax = std::numeric_limits<T>::infinity()) const {
    std::vector<MeshHit<T>> out;
    all_hits(ray, tmax, out);
    return out;
  }
  /// out[i] = closest_hit(rays[i], tmax) (out.size() >= rays.size(), asserted).
  void closest_hits(std::span<const Ray3<T>> rays, std::span<MeshHit<T>> out,
                    T tmax = std::numeric_limits<T>::infinity(), unsigned threads = 1) const;
  /// out[i] = any_hit(rays[i], tmax) ? 1 : 0.
  void any_hits(std::span<const Ray3<T>> rays, std::span<std::uint8_t> out,
                T tmax = std::numeric_limits<T>::infinity(), unsigned threads = 1) const;
  /// Nearest point of the mesh surface (see distance(p, bvh)).
  [[nodiscard]] Distance<T, 3, NoParam, MeshPoint<T>> nearest(const Vec3<T>& p) const noexcept;

  /// Calls f(id, tmax) -> new tmax for every primitive box the ray may meet within tmax,
  /// nearer nodes first (a superset: the test is conservative); a negative return stops.
  template <class F>
  void visit_ray(const Ray3<T>& ray, T tmax, F&& f) const {
    using Fn = std::remove_reference_t<F>;
    visit_ray_impl(
        ray, tmax, const_cast<void*>(static_cast<const void*>(&f)),
        [](void* c, std::uint32_t id, T t) -> T { return (*static_cast<Fn*>(c))(id, t); });
  }
  /// Calls f(id) for every primitive whose box meets the closed box q (exact on the stored
  /// boxes: the triangle bounds in mesh mode); f returns false to stop.
  template <class F>
  void visit_overlaps(const AlignedBox3<T>& q, F&& f) const {
    using Fn = std::remove_reference_t<F>;
    visit_overlaps_impl(
        q, const_cast<void*>(static_cast<const void*>(&f)),
        [](void* c, std::uint32_t id) -> bool { return (*static_cast<Fn*>(c))(id); });
  }

  [[nodiscard]] std::span<const Node> nodes() const noexcept { return nodes_; }

 private:
  friend struct detail::BvhCore<T>;
  void visit_ray_impl(const Ray3<T>& ray, T tmax, void* ctx,
                      T (*fn)(void*, std::uint32_t, T)) const;
  void visit_overlaps_impl(const AlignedBox3<T>& q, void* ctx,
                           bool (*fn)(void*, std::uint32_t)) const;
  void build(std::vector<AlignedBox3<T>> boxes, BvhOptions options, bool packets);

 public:
  /// Four triangles in structure-of-arrays form: v[vertex][axis][lane], and their input
  /// indices (MeshHit::none: padding), read with the vertices rather than from another array.
  struct Packet {
    T v[3][3][4];
    std::uint32_t id[4];
  };

 private:
  std::vector<Node, detail::BvhAllocator<Node>> nodes_;
  std::vector<std::uint32_t, detail::BvhAllocator<std::uint32_t>> ids_;  // slot's id (none: pad)
  std::vector<Packet, detail::BvhAllocator<Packet>> tris_;  // slot s: lane s % 4 of packet s / 4
  std::vector<AlignedBox3<T>> boxes_;                       // primitive box of each slot
  std::vector<std::uint32_t> slot_;                         // slot of each primitive id
  std::size_t count_ = 0;
  int scale_exp_ = 0;  // float boxes hold coordinates * 2^-scale_exp_
  Status status_ = Status::empty_input;
};

extern template class Bvh<float>;
extern template class Bvh<double>;

template <PointRange3 R>
Bvh(const R&, std::span<const std::array<std::uint32_t, 3>>, BvhOptions = {})
    -> Bvh<range_scalar_t<R>>;

/// The closest hit of the ray on the mesh (Bvh::closest_hit).
template <Real T>
[[nodiscard]] inline MeshHit<T> closest_hit(const Ray3<T>& ray, const Bvh<T>& bvh) noexcept {
  return bvh.closest_hit(ray);
}

/// Whether the ray hits the mesh (Bvh::any_hit).
template <Real T>
[[nodiscard]] inline bool intersects(const Ray3<T>& ray, const Bvh<T>& bvh) noexcept {
  return bvh.any_hit(ray);
}

/// Distance from p to the mesh surface; the answer of distance_to_mesh (point_mesh.hpp).
template <Real T>
[[nodiscard]] inline Distance<T, 3, NoParam, MeshPoint<T>> distance(const Vec3<T>& p,
                                                                    const Bvh<T>& bvh) noexcept {
  return bvh.nearest(p);
}

/// The swapped query: closest[0] and param_a belong to the mesh.
template <Real T>
[[nodiscard]] inline Distance<T, 3, MeshPoint<T>, NoParam> distance(const Bvh<T>& bvh,
                                                                    const Vec3<T>& p) noexcept {
  return swapped(bvh.nearest(p));
}

}  // namespace locus
