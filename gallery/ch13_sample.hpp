// SPDX-License-Identifier: BSL-1.0
#pragma once
// The sample polygon of the book's section 13.9.2 (figure 13.56), which the figures that follow
// decompose: the incremental trapezoidal map (13.57-13.67, ch13_trapezoid_map.cpp), the merged
// trapezoids, the monotone pieces and an ear of one piece (13.68-13.70, ch13_triangulate.cpp).
// A simple counter-clockwise polygon with four reflex vertices (two of them y-extremes, a split
// and a merge vertex); its edges listed in the book's random insertion order s1 .. s9.
#include "gallery.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace locus_gallery {

/// The vertices, counter-clockwise (one ring: vertex i joins vertex i + 1 mod 9).
inline const std::vector<Vec2d> sample_polygon_points{
    {0, 0}, {4, 1.2}, {7, -0.4}, {9, 2.6}, {6.4, 4}, {8.2, 7.2}, {4, 5.6}, {1.4, 7.6}, {2.2, 3.4}};

/// The edges in insertion order: sample_polygon_edges[k] is s(k+1).
inline const std::vector<std::array<std::uint32_t, 2>> sample_polygon_edges{
    {2, 3}, {6, 7}, {2, 1}, {4, 5}, {8, 0}, {0, 1}, {5, 6}, {3, 4}, {7, 8}};

}  // namespace locus_gallery
