// SPDX-License-Identifier: BSL-1.0
#pragma once
// Umbrella header of locus's triangulate area: polygon triangulation by ear clipping, monotone
// decomposition, horizontal trapezoids and convex partitions. Every public header of
// include/locus/triangulate/.
// For users: nothing inside the library includes an umbrella (cmake/check_layering.cmake).

#include <locus/triangulate/convex_partition.hpp>
#include <locus/triangulate/ear_clipping.hpp>
#include <locus/triangulate/monotone.hpp>
#include <locus/triangulate/polygon_triangulation.hpp>
#include <locus/triangulate/trapezoid_decomposition.hpp>
#include <locus/triangulate/trapezoid_map.hpp>
