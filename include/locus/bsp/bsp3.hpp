// SPDX-License-Identifier: BSL-1.0
#pragma once
// The BSP tree of a polyhedron (book section 13.1.2, extending bsp/bsp2.hpp; row cg.bsp3):
// construction with splitting (first-face, balanced or seeded random order), point
// classification and the partition of a convex polygon into inside / outside / coincident-same /
// coincident-opposite pieces. Input: vertices and triangles of a closed mesh, every triangle
// {i, j, k} oriented with its normal (vj - vi) x (vk - vi) pointing OUT (not checked: an open or
// inconsistently oriented mesh gives the answers of the tree built). Degenerate (collinear,
// exact) triangles are skipped.
// Tree: every node splits by the plane of one input triangle (faces()[node.face]); front =
// orient3d(face, p) > 0 (outside), back < 0. Planes are always three INPUT points, so the side of
// an input-precision point is exact (orient3d). Triangles coplanar with a node's plane (exact:
// their three vertices on it) are stored there as fragments; a leaf is outside (front) or
// inside (back).
// Splitting: a fragment crossing a plane is cut at rounded points, computed and kept in double
// (also for float input): on the edge u v (u on the positive side), with plane values du > 0 >
// dv (compensated dot product), p_i = u_i + ((v_i - u_i) du) / (du - dv) clamped to the box of
// u v, p = u (or v) when du (dv) rounds to the wrong sign, and p_k = the plane's coordinate when
// the plane is x_k = const (exact test). So p lies on the segment u v, is exact whenever the
// crossing is representable (dyadic boxes), and is within a few units of 2^-53 M of the plane
// (M = the largest |coordinate|). A cut point remembers its two parents: its side of a later
// plane is the parents' common side when they do not straddle it (exact: the crossing is a
// convex combination), and only otherwise the exact orient3d sign of the rounded point.
// Fragments flattened by rounding are kept, so slivers along an edge reach the same cells.
// points() and partition pieces report the corners rounded to T.
// classify(p): exact sign tests along the path; on a node's plane the point is tested against
// the coplanar input triangles (exact) and, if on none, sent down both sides. It is exact for
// the cells of the tree; the tree equals the polyhedron unless a rounded cut point whose parents
// straddle a later plane lies within rounding of it (seeded tests: rotated boxes, prisms and
// icospheres, ~10^6 queries, no disagreement with the exact point-in-polyhedron). Non-finite p:
// outside.
// partition(polygon): the polygon's plane is its first three non-collinear vertices (exact);
// pieces come out of the leaves, pieces on a node plane are pushed through both subtrees to
// tell inside / outside / coincident_same (its normal agrees with the surface's outward
// normal) / coincident_opposite. Status: ok, empty_input (no triangle), invalid_input (an index
// out of range), non_finite_input, degenerate_input (every triangle degenerate: empty tree).
// Cost: O(n^2) fragments at worst. A convex solid never splits but its tree is a chain of
// depth n, so the construction is O(n^2) (balanced sampling multiplies it by up to `sample`):
// measured 0.3 / 2.5 / 32 s for icospheres of 320 / 1280 / 5120 faces (balanced, one core);
// no recursion in the construction; classify O(depth). docs/notes/bsp3.md.

#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/side.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace locus {

inline constexpr std::uint32_t bsp3_none = 0xffffffffu;

/// A convex piece of input triangle `face`: points()[first, first + count), in the triangle's
/// orientation.
struct Bsp3Fragment {
  std::uint32_t face = 0;
  std::uint32_t first = 0, count = 0;
};

/// A node: children are node indices >= 0 or the leaves bsp3_inside / bsp3_outside.
struct Bsp3Node {
  std::uint32_t face = 0;  ///< splitting plane: the plane of faces()[face]
  std::int32_t front = 0, back = 0;
  std::uint32_t first = 0, count = 0;  ///< coplanar fragments: fragments()[first, first + count)
};
inline constexpr std::int32_t bsp3_inside = -1, bsp3_outside = -2;

enum class Bsp3Split : std::uint8_t { first_face, balanced, random_order };

struct Bsp3Options {
  Bsp3Split split = Bsp3Split::balanced;
  std::uint32_t sample = 16;     ///< candidates per node (balanced)
  std::uint32_t split_cost = 2;  ///< weight of one split against one unit of imbalance
  std::uint64_t seed = 1;        ///< random_order: the faces are shuffled with this seed
};

enum class Bsp3Location : std::uint8_t { inside, outside, coincident_same, coincident_opposite };

/// A piece of a partitioned polygon: points[first, first + count) of the partition, in the
/// input polygon's orientation.
struct Bsp3Piece {
  std::uint32_t first = 0, count = 0;
  Bsp3Location location = Bsp3Location::outside;
};

template <Real T>
struct Bsp3PolygonPartition {
  Status status = Status::empty_input;
  std::vector<Vec3<T>> points;
  std::vector<Bsp3Piece> pieces;
};

/// The BSP tree of a closed triangle mesh (see the top of the header).
template <Real T>
class Bsp3 {
 public:
  Bsp3() = default;
  Bsp3(std::span<const Vec3<T>> vertices, std::span<const std::array<std::uint32_t, 3>> triangles,
       Bsp3Options options = {}) {
    build(vertices, triangles, options);
  }

  /// Builds the tree (replaces any previous one); returns status().
  Status build(std::span<const Vec3<T>> vertices,
               std::span<const std::array<std::uint32_t, 3>> triangles, Bsp3Options options = {});

  /// Inside, outside, or boundary (see the top of the header). Non-finite p: outside.
  [[nodiscard]] Side classify(const Vec3<T>& p) const noexcept;
  /// The pieces of a convex planar polygon (at least three points; see the top of the header).
  /// Non-finite points give non_finite_input, fewer than three or all collinear
  /// degenerate_input (no pieces); a tree without faces gives every polygon as one outside piece.
  [[nodiscard]] Bsp3PolygonPartition<T> partition(std::span<const Vec3<T>> polygon) const;

  [[nodiscard]] Status status() const noexcept { return status_; }
  [[nodiscard]] std::int32_t root() const noexcept { return root_; }
  [[nodiscard]] std::span<const Bsp3Node> nodes() const noexcept { return nodes_; }
  [[nodiscard]] std::span<const Bsp3Fragment> fragments() const noexcept { return fragments_; }
  /// Fragment corners (input vertices and rounded cut points).
  [[nodiscard]] std::span<const Vec3<T>> points() const noexcept { return points_; }
  /// The non-degenerate input triangles (indices into vertices()), outward normals.
  [[nodiscard]] std::span<const std::array<std::uint32_t, 3>> faces() const noexcept {
    return faces_;
  }
  [[nodiscard]] std::span<const Vec3<T>> vertices() const noexcept { return vertices_; }
  /// Longest root-to-leaf path (in nodes); fragments().size() - faces().size() splits were made.
  [[nodiscard]] std::uint32_t depth() const noexcept { return depth_; }

 private:
  Side classify_at(std::int32_t node, const Vec3<T>& p) const noexcept;

  Status status_ = Status::empty_input;
  std::int32_t root_ = bsp3_outside;
  std::uint32_t depth_ = 0;
  std::vector<Vec3<T>> vertices_;
  std::vector<std::array<std::uint32_t, 3>> faces_;
  std::vector<Bsp3Node> nodes_;
  std::vector<Bsp3Fragment> fragments_;
  std::vector<Vec3<T>> points_;
};

/// classify(p, tree) = tree.classify(p).
template <Real T>
[[nodiscard]] inline Side classify(const Vec3<T>& p, const Bsp3<T>& tree) noexcept {
  return tree.classify(p);
}

/// The BSP tree for any 3D point range (core/point_range.hpp).
template <PointRange3 R>
[[nodiscard]] auto make_bsp3(const R& vertices,
                             std::span<const std::array<std::uint32_t, 3>> triangles,
                             Bsp3Options options = {}) {
  return Bsp3<range_scalar_t<R>>(point_span(vertices), triangles, options);
}

extern template class Bsp3<float>;
extern template class Bsp3<double>;

}  // namespace locus
