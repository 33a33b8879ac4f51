// SPDX-License-Identifier: BSL-1.0
#pragma once
// Umbrella header of the whole library: every area's umbrella (<locus/core.hpp>,
// <locus/distance.hpp>, ...). Convenient for applications; compile time is lower with the area
// or single headers. Nothing inside the library includes it (cmake/check_layering.cmake).

#include <locus/boolean.hpp>
#include <locus/bounding.hpp>
#include <locus/bsp.hpp>
#include <locus/config.hpp>
#include <locus/construct.hpp>
#include <locus/containment.hpp>
#include <locus/core.hpp>
#include <locus/curves.hpp>
#include <locus/delaunay.hpp>
#include <locus/distance.hpp>
#include <locus/fit.hpp>
#include <locus/hull.hpp>
#include <locus/intersection.hpp>
#include <locus/io.hpp>
#include <locus/measure.hpp>
#include <locus/mesh.hpp>
#include <locus/numeric.hpp>
#include <locus/primitives.hpp>
#include <locus/spatial.hpp>
#include <locus/triangulate.hpp>
