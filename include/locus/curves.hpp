// SPDX-License-Identifier: BSL-1.0
#pragma once
// Umbrella header of locus's curves area: Bezier, B-spline and NURBS curves and surfaces.
// Every public header of include/locus/curves/ (not detail/). For users: nothing inside the library
// includes an umbrella (cmake/check_layering.cmake checks it, and that the list is complete).

#include <locus/curves/bezier.hpp>
#include <locus/curves/bezier_surface.hpp>
#include <locus/curves/bspline.hpp>
#include <locus/curves/bspline_surface.hpp>
#include <locus/curves/nurbs.hpp>
#include <locus/curves/nurbs_surface.hpp>
