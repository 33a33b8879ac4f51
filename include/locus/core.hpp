// SPDX-License-Identifier: BSL-1.0
#pragma once
// Umbrella header of locus's core area: vectors, matrices, quaternions, transforms, exact
// predicates, status and side. Every public header of include/locus/core/ (not detail/). For users:
// nothing inside the library includes an umbrella (cmake/check_layering.cmake checks it, and that
// the list is complete).

#include <locus/core/affine.hpp>
#include <locus/core/angle.hpp>
#include <locus/core/barycentric.hpp>
#include <locus/core/basis.hpp>
#include <locus/core/crossing.hpp>
#include <locus/core/error_free.hpp>
#include <locus/core/exact_poly.hpp>
#include <locus/core/exact_sum.hpp>
#include <locus/core/frame.hpp>
#include <locus/core/linear_system.hpp>
#include <locus/core/mat.hpp>
#include <locus/core/plane_crossing.hpp>
#include <locus/core/plane_crossing_ball.hpp>
#include <locus/core/plane_side.hpp>
#include <locus/core/point_range.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/products.hpp>
#include <locus/core/projection.hpp>
#include <locus/core/quat.hpp>
#include <locus/core/rotation.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/side.hpp>
#include <locus/core/status.hpp>
#include <locus/core/transform.hpp>
#include <locus/core/vec.hpp>
