// SPDX-License-Identifier: BSL-1.0
#pragma once
// Umbrella header of locus's io area: mesh files (OBJ, OFF, PLY, STL), 2D geometries (WKT,
// GeoJSON), point lists (CSV, XYZ) and SVG output.
// Every public header of include/locus/io/ (not detail/). For users: nothing inside the library
// includes an umbrella (cmake/check_layering.cmake checks it, and that the list is complete).

#include <locus/io/geojson.hpp>
#include <locus/io/geometry.hpp>
#include <locus/io/mesh_io.hpp>
#include <locus/io/point_list.hpp>
#include <locus/io/svg.hpp>
#include <locus/io/svg_primitives.hpp>
#include <locus/io/wkt.hpp>
