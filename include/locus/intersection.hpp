// SPDX-License-Identifier: BSL-1.0
#pragma once
// Umbrella header of locus's intersection area: intersects() / intersection() between pairs of
// primitives, and the shared Intersection result with its Kind. Every public header of
// include/locus/intersection/ (not detail/). For users: nothing inside the library includes an
// umbrella (cmake/check_layering.cmake checks it, and that the list is complete).

#include <locus/intersection/arc_arc.hpp>
#include <locus/intersection/circle_arc.hpp>
#include <locus/intersection/circle_circle.hpp>
#include <locus/intersection/circle_ellipse.hpp>
#include <locus/intersection/circle_quadratic_curve.hpp>
#include <locus/intersection/ellipse_ellipse.hpp>
#include <locus/intersection/ellipse_quadratic_curve.hpp>
#include <locus/intersection/line_arc.hpp>
#include <locus/intersection/line_circle.hpp>
#include <locus/intersection/line_ellipse.hpp>
#include <locus/intersection/line_line.hpp>
#include <locus/intersection/line_polygon.hpp>
#include <locus/intersection/line_polyline.hpp>
#include <locus/intersection/line_quadratic_curve.hpp>
#include <locus/intersection/line_ray.hpp>
#include <locus/intersection/line_segment.hpp>
#include <locus/intersection/quadratic_curve_quadratic_curve.hpp>
#include <locus/intersection/ray_arc.hpp>
#include <locus/intersection/ray_circle.hpp>
#include <locus/intersection/ray_ellipse.hpp>
#include <locus/intersection/ray_polygon.hpp>
#include <locus/intersection/ray_polyline.hpp>
#include <locus/intersection/ray_quadratic_curve.hpp>
#include <locus/intersection/ray_ray.hpp>
#include <locus/intersection/ray_segment.hpp>
#include <locus/intersection/result.hpp>
#include <locus/intersection/segment_arc.hpp>
#include <locus/intersection/segment_circle.hpp>
#include <locus/intersection/segment_ellipse.hpp>
#include <locus/intersection/segment_polygon.hpp>
#include <locus/intersection/segment_polyline.hpp>
#include <locus/intersection/segment_quadratic_curve.hpp>
#include <locus/intersection/segment_segment.hpp>
