// SPDX-License-Identifier: BSL-1.0
#pragma once
// Private to src/bsp: the partition walk of Bsp3::partition with combinatorial provenance, used by
// mesh_boolean to share every constructed vertex by identity (docs/notes/bsp3.md, "Watertight
// output"). A corner carries a VertexKey naming the point symbolically, a polygon edge a LineKey
// naming its supporting line; the caller numbers planes (tree face -> plane id) so that coplanar
// faces of both operands share one id.

#include <locus/bsp/bsp3.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace locus::bsp3_detail {

/// {kind, ...}: vertex_input {solid, index}; vertex_planes {p < q < r} (three plane ids);
/// vertex_edge_plane {solid, u < v, p} (an input edge whose two faces are coplanar, cut by plane
/// p); vertex_unique {serial} (never shared).
using VertexKey = std::array<std::uint32_t, 5>;
/// {kind, ...}: line_planes {p < q}; line_edge {solid, u < v}; line_unique {serial}.
using LineKey = std::array<std::uint32_t, 4>;
inline constexpr std::uint32_t vertex_input = 1, vertex_planes = 2, vertex_edge_plane = 3,
                               vertex_unique = 4;
inline constexpr std::uint32_t line_planes = 1, line_edge = 2, line_unique = 3;

/// A piece: corners (rounded, double), their keys, lines[i] supports corners i -> i + 1.
struct KeyedPiece {
  std::vector<Vec3<double>> points;
  std::vector<VertexKey> keys;
  std::vector<LineKey> lines;
  std::vector<std::uint8_t> input;  ///< 1: the corner is an input point (exact coordinates)
  Bsp3Location location = Bsp3Location::outside;
};

/// Partitions the convex polygon `polygon` (corner keys `keys`, edge lines `lines`, lying in
/// plane key id `polygon_plane`) by `tree`, whose face f has the exact plane id plane_of_face[f]
/// (equal ids: exactly coplanar; a cut point's side of its own plane is 0) and the key id
/// key_of_face[f] (used in names only). `serial` numbers the unique keys. Same pieces and
/// locations as Bsp3::partition.
template <Real T>
[[nodiscard]] std::vector<KeyedPiece> partition_keyed(
    const Bsp3<T>& tree, std::span<const std::uint32_t> plane_of_face,
    std::span<const std::uint32_t> key_of_face, std::span<const Vec3<T>> polygon,
    std::span<const VertexKey> keys, std::span<const LineKey> lines, std::uint32_t polygon_plane,
    std::uint32_t& serial);

#define LOCUS_BSP3_KEYED_EXTERN(T)                                                    \
  extern template std::vector<KeyedPiece> partition_keyed(                            \
      const Bsp3<T>&, std::span<const std::uint32_t>, std::span<const std::uint32_t>, \
      std::span<const Vec3<T>>, std::span<const VertexKey>, std::span<const LineKey>, \
      std::uint32_t, std::uint32_t&);
LOCUS_BSP3_KEYED_EXTERN(float)
LOCUS_BSP3_KEYED_EXTERN(double)
#undef LOCUS_BSP3_KEYED_EXTERN

}  // namespace locus::bsp3_detail
