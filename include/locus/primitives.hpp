// SPDX-License-Identifier: BSL-1.0
#pragma once
// Umbrella header of locus's primitives area: lines, segments, polygons, boxes, circles, spheres
// and the other primitives. Every public header of include/locus/primitives/ (not detail/). For
// users: nothing inside the library includes an umbrella (cmake/check_layering.cmake checks it, and
// that the list is complete).

#include <locus/primitives/aligned_box.hpp>
#include <locus/primitives/arc.hpp>
#include <locus/primitives/capsule.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/cone.hpp>
#include <locus/primitives/cylinder.hpp>
#include <locus/primitives/ellipse.hpp>
#include <locus/primitives/ellipsoid.hpp>
#include <locus/primitives/frustum.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/oriented_box.hpp>
#include <locus/primitives/planar_polygon.hpp>
#include <locus/primitives/plane.hpp>
#include <locus/primitives/polygon.hpp>
#include <locus/primitives/polyline.hpp>
#include <locus/primitives/quadratic_curve.hpp>
#include <locus/primitives/quadric.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/rectangle.hpp>
#include <locus/primitives/segment.hpp>
#include <locus/primitives/sphere.hpp>
#include <locus/primitives/tetrahedron.hpp>
#include <locus/primitives/torus.hpp>
#include <locus/primitives/triangle.hpp>
