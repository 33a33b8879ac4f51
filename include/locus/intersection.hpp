// SPDX-License-Identifier: BSL-1.0
#pragma once
// Umbrella header of locus's intersection area: intersects() / intersection() between pairs of
// primitives, and the shared Intersection result with its Kind. Every public header of
// include/locus/intersection/ (not detail/). For users: nothing inside the library includes an
// umbrella (cmake/check_layering.cmake checks it, and that the list is complete).

#include <locus/intersection/aligned_box_aligned_box.hpp>
#include <locus/intersection/aligned_box_plane.hpp>
#include <locus/intersection/aligned_box_sphere.hpp>
#include <locus/intersection/arc_arc.hpp>
#include <locus/intersection/circle_arc.hpp>
#include <locus/intersection/circle_circle.hpp>
#include <locus/intersection/circle_ellipse.hpp>
#include <locus/intersection/circle_quadratic_curve.hpp>
#include <locus/intersection/ellipse_ellipse.hpp>
#include <locus/intersection/ellipse_quadratic_curve.hpp>
#include <locus/intersection/line_aligned_box.hpp>
#include <locus/intersection/line_arc.hpp>
#include <locus/intersection/line_circle.hpp>
#include <locus/intersection/line_disk.hpp>
#include <locus/intersection/line_ellipse.hpp>
#include <locus/intersection/line_line.hpp>
#include <locus/intersection/line_oriented_box.hpp>
#include <locus/intersection/line_plane.hpp>
#include <locus/intersection/line_polygon.hpp>
#include <locus/intersection/line_polyline.hpp>
#include <locus/intersection/line_quadratic_curve.hpp>
#include <locus/intersection/line_ray.hpp>
#include <locus/intersection/line_segment.hpp>
#include <locus/intersection/line_triangle.hpp>
#include <locus/intersection/oriented_box_oriented_box.hpp>
#include <locus/intersection/oriented_box_plane.hpp>
#include <locus/intersection/oriented_box_sphere.hpp>
#include <locus/intersection/plane_mesh.hpp>
#include <locus/intersection/plane_plane.hpp>
#include <locus/intersection/plane_polygon.hpp>
#include <locus/intersection/plane_triangle.hpp>
#include <locus/intersection/quadratic_curve_quadratic_curve.hpp>
#include <locus/intersection/ray_aligned_box.hpp>
#include <locus/intersection/ray_arc.hpp>
#include <locus/intersection/ray_circle.hpp>
#include <locus/intersection/ray_disk.hpp>
#include <locus/intersection/ray_ellipse.hpp>
#include <locus/intersection/ray_oriented_box.hpp>
#include <locus/intersection/ray_plane.hpp>
#include <locus/intersection/ray_polygon.hpp>
#include <locus/intersection/ray_polyline.hpp>
#include <locus/intersection/ray_quadratic_curve.hpp>
#include <locus/intersection/ray_ray.hpp>
#include <locus/intersection/ray_segment.hpp>
#include <locus/intersection/ray_triangle.hpp>
#include <locus/intersection/result.hpp>
#include <locus/intersection/segment_aligned_box.hpp>
#include <locus/intersection/segment_arc.hpp>
#include <locus/intersection/segment_circle.hpp>
#include <locus/intersection/segment_disk.hpp>
#include <locus/intersection/segment_ellipse.hpp>
#include <locus/intersection/segment_oriented_box.hpp>
#include <locus/intersection/segment_plane.hpp>
#include <locus/intersection/segment_polygon.hpp>
#include <locus/intersection/segment_polyline.hpp>
#include <locus/intersection/segment_quadratic_curve.hpp>
#include <locus/intersection/segment_segment.hpp>
#include <locus/intersection/segment_triangle.hpp>
#include <locus/intersection/triangle_triangle.hpp>
