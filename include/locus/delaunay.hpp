// SPDX-License-Identifier: BSL-1.0
#pragma once
// Umbrella header of locus's delaunay area: Delaunay triangulations in 2D and 3D, constrained
// Delaunay. Every public header of include/locus/delaunay/ (not detail/). For users: nothing inside
// the library includes an umbrella (cmake/check_layering.cmake checks it, and that the list is
// complete).

#include <locus/delaunay/constrained_delaunay2.hpp>
#include <locus/delaunay/delaunay2.hpp>
#include <locus/delaunay/delaunay3.hpp>
