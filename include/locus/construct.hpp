// SPDX-License-Identifier: BSL-1.0
#pragma once
// Umbrella header of the construct area (chapter 8 circles and lines, chapter 12): every public
// header of include/locus/construct/. Nothing inside the library includes it.

#include <locus/construct/apollonius.hpp>
#include <locus/construct/circle_through.hpp>
#include <locus/construct/circles_of_radius.hpp>
#include <locus/construct/lines.hpp>
#include <locus/construct/misc3.hpp>
#include <locus/construct/solutions.hpp>
#include <locus/construct/tangent_lines.hpp>
