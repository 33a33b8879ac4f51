// SPDX-License-Identifier: BSL-1.0
#pragma once
// Umbrella header of locus's bsp area: the BSP tree of a polygon (bsp/bsp2.hpp) and booleans
// through it (bsp/bsp2_boolean.hpp), the BSP tree of a polyhedron (bsp/bsp3.hpp) and booleans of
// polyhedra through BSP trees (bsp/bsp3_boolean.hpp). Every public header of include/locus/bsp/.
// For users: nothing inside the library includes an umbrella (cmake/check_layering.cmake).

#include <locus/bsp/bsp2.hpp>
#include <locus/bsp/bsp2_boolean.hpp>
#include <locus/bsp/bsp3.hpp>
#include <locus/bsp/bsp3_boolean.hpp>
