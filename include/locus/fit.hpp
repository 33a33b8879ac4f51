// SPDX-License-Identifier: BSL-1.0
#pragma once
// Umbrella header of locus's fit area: least-squares fitting of lines, planes, circles, spheres,
// quadrics. Every public header of include/locus/fit/ (not detail/). For users: nothing inside the
// library includes an umbrella (cmake/check_layering.cmake checks it, and that the list is
// complete).

#include <locus/fit/circle_fit.hpp>
#include <locus/fit/fit_common.hpp>
#include <locus/fit/gaussian_fit.hpp>
#include <locus/fit/line_fit.hpp>
#include <locus/fit/plane_fit.hpp>
#include <locus/fit/quadratic_fit.hpp>
#include <locus/fit/sphere_fit.hpp>
