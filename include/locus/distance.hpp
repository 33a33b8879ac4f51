// SPDX-License-Identifier: BSL-1.0
#pragma once
// Umbrella header of locus's distance area: distance queries between every pair of primitives, and
// the batch queries. Every public header of include/locus/distance/ (not detail/). For users:
// nothing inside the library includes an umbrella (cmake/check_layering.cmake checks it, and that
// the list is complete).

#include <locus/distance/batch.hpp>
#include <locus/distance/circle_circle.hpp>
#include <locus/distance/gjk.hpp>
#include <locus/distance/line_aligned_box.hpp>
#include <locus/distance/line_circle.hpp>
#include <locus/distance/line_curve.hpp>
#include <locus/distance/line_disk.hpp>
#include <locus/distance/line_ellipse.hpp>
#include <locus/distance/line_line.hpp>
#include <locus/distance/line_oriented_box.hpp>
#include <locus/distance/line_plane.hpp>
#include <locus/distance/line_polyline.hpp>
#include <locus/distance/line_quadratic_curve.hpp>
#include <locus/distance/line_ray.hpp>
#include <locus/distance/line_rectangle.hpp>
#include <locus/distance/line_segment.hpp>
#include <locus/distance/line_tetrahedron.hpp>
#include <locus/distance/line_triangle.hpp>
#include <locus/distance/point_aligned_box.hpp>
#include <locus/distance/point_circle.hpp>
#include <locus/distance/point_convex_polygon.hpp>
#include <locus/distance/point_curve.hpp>
#include <locus/distance/point_ellipse.hpp>
#include <locus/distance/point_ellipsoid.hpp>
#include <locus/distance/point_frustum.hpp>
#include <locus/distance/point_line.hpp>
#include <locus/distance/point_mesh.hpp>
#include <locus/distance/point_oriented_box.hpp>
#include <locus/distance/point_plane.hpp>
#include <locus/distance/point_polygon3.hpp>
#include <locus/distance/point_polyhedron.hpp>
#include <locus/distance/point_polyline.hpp>
#include <locus/distance/point_quadratic_curve.hpp>
#include <locus/distance/point_quadric.hpp>
#include <locus/distance/point_ray.hpp>
#include <locus/distance/point_rectangle.hpp>
#include <locus/distance/point_segment.hpp>
#include <locus/distance/point_sphere.hpp>
#include <locus/distance/point_surface.hpp>
#include <locus/distance/point_tetrahedron.hpp>
#include <locus/distance/point_triangle.hpp>
#include <locus/distance/ray_aligned_box.hpp>
#include <locus/distance/ray_oriented_box.hpp>
#include <locus/distance/ray_polyline.hpp>
#include <locus/distance/ray_ray.hpp>
#include <locus/distance/ray_rectangle.hpp>
#include <locus/distance/ray_segment.hpp>
#include <locus/distance/ray_tetrahedron.hpp>
#include <locus/distance/ray_triangle.hpp>
#include <locus/distance/rectangle_rectangle.hpp>
#include <locus/distance/result.hpp>
#include <locus/distance/segment_aligned_box.hpp>
#include <locus/distance/segment_oriented_box.hpp>
#include <locus/distance/segment_polyline.hpp>
#include <locus/distance/segment_rectangle.hpp>
#include <locus/distance/segment_segment.hpp>
#include <locus/distance/segment_tetrahedron.hpp>
#include <locus/distance/segment_triangle.hpp>
#include <locus/distance/support.hpp>
#include <locus/distance/triangle_rectangle.hpp>
#include <locus/distance/triangle_triangle.hpp>
