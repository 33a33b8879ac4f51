// SPDX-License-Identifier: BSL-1.0
#pragma once
// The BooleanResult object that boolean() (boolean.cpp) and offset() / offset_polyline()
// (offset.cpp) return: one conversion for both, so the two give the same shape.
#include "common.hpp"

#include <locus/boolean/polygon_boolean.hpp>

namespace locus::python {

/// Raises for a bad status (check_status, no iteration limit allowed); else a BooleanResult whose
/// `polygons` is a list of polygons, each a list of (k, 2) arrays of T (the outer ring, then the
/// holes), and `grid` the snap-rounding spacing.
[[nodiscard]] py::object boolean_result_out(const BooleanResult<float>& r, const char* fn);
[[nodiscard]] py::object boolean_result_out(const BooleanResult<double>& r, const char* fn);

}  // namespace locus::python
