// SPDX-License-Identifier: BSL-1.0
#pragma once
// Umbrella header of locus's boolean area: boolean operations on polygons with holes and
// multipolygons (intersection, union, difference, xor, negation) and polygon offsetting. Every
// public header of include/locus/boolean/.
// For users: nothing inside the library includes an umbrella (cmake/check_layering.cmake).

#include <locus/boolean/polygon_boolean.hpp>
#include <locus/boolean/polygon_offset.hpp>
