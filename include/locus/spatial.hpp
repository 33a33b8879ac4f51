// SPDX-License-Identifier: BSL-1.0
#pragma once
// Umbrella header of locus's spatial area: acceleration structures (the bounding volume
// hierarchy of bvh.hpp for ray and nearest-point queries on triangle meshes and boxes). Every
// public header of include/locus/spatial/. For users: nothing inside the library includes an
// umbrella (cmake/check_layering.cmake checks it, and that the list is complete).

#include <locus/spatial/bvh.hpp>
