// SPDX-License-Identifier: BSL-1.0
#pragma once
// Umbrella header of locus's measure area: areas, volumes, mass properties.
// Every public header of include/locus/measure/ (not detail/). For users: nothing inside the
// library includes an umbrella (cmake/check_layering.cmake checks it, and that the list is
// complete).

#include <locus/measure/area_volume.hpp>
#include <locus/measure/formulas.hpp>
#include <locus/measure/inertia.hpp>
