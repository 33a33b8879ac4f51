// SPDX-License-Identifier: BSL-1.0
#pragma once
// Umbrella header of locus's containment area: point in polygon and point in polyhedron.
// Every public header of include/locus/containment/ (not detail/). For users: nothing inside the
// library includes an umbrella (cmake/check_layering.cmake checks it, and that the list is
// complete).

#include <locus/containment/point_in_polygon.hpp>
#include <locus/containment/point_in_polyhedron.hpp>
