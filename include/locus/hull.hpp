// SPDX-License-Identifier: BSL-1.0
#pragma once
// Umbrella header of locus's hull area: convex hulls in 2D and 3D.
// Every public header of include/locus/hull/ (not detail/). For users: nothing inside the library
// includes an umbrella (cmake/check_layering.cmake checks it, and that the list is complete).

#include <locus/hull/hull2.hpp>
#include <locus/hull/hull3.hpp>
