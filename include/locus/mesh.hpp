// SPDX-License-Identifier: BSL-1.0
#pragma once
// Umbrella header of locus's mesh area: indexed polygon meshes, vertex-edge-face tables, mesh
// checks, generators and 3D polygon triangulation.
// Every public header of include/locus/mesh/ (not detail/). For users: nothing inside the library
// includes an umbrella (cmake/check_layering.cmake checks it, and that the list is complete).

#include <locus/mesh/mesh_checks.hpp>
#include <locus/mesh/platonic.hpp>
#include <locus/mesh/polygon_mesh.hpp>
#include <locus/mesh/polygon_triangulation3.hpp>
#include <locus/mesh/vet_mesh.hpp>
