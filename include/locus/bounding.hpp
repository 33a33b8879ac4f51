// SPDX-License-Identifier: BSL-1.0
#pragma once
// Umbrella header of locus's bounding area: minimal enclosing circles, spheres, rectangles and
// boxes. Every public header of include/locus/bounding/ (not detail/). For users: nothing inside
// the library includes an umbrella (cmake/check_layering.cmake checks it, and that the list is
// complete).

#include <locus/bounding/min_box3.hpp>
#include <locus/bounding/min_circle.hpp>
#include <locus/bounding/min_rect2.hpp>
#include <locus/bounding/min_sphere.hpp>
#include <locus/bounding/simplex_balls.hpp>
