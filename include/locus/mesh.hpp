// SPDX-License-Identifier: BSL-1.0
#pragma once
// Umbrella header of locus's mesh area: indexed polygon meshes.
// Every public header of include/locus/mesh/ (not detail/). For users: nothing inside the library
// includes an umbrella (cmake/check_layering.cmake checks it, and that the list is complete).

#include <locus/mesh/polygon_mesh.hpp>
