// SPDX-License-Identifier: BSL-1.0
#pragma once
// Umbrella header of locus's numeric area: polynomials, roots, linear algebra, eigen-solvers,
// minimisation, calculus. Every public header of include/locus/numeric/ (not detail/). For users:
// nothing inside the library includes an umbrella (cmake/check_layering.cmake checks it, and that
// the list is complete).

#include <locus/numeric/calculus.hpp>
#include <locus/numeric/decompose.hpp>
#include <locus/numeric/eigen_sym.hpp>
#include <locus/numeric/least_squares.hpp>
#include <locus/numeric/matrix.hpp>
#include <locus/numeric/minimize.hpp>
#include <locus/numeric/polynomial.hpp>
#include <locus/numeric/polynomial_system.hpp>
#include <locus/numeric/roots.hpp>
#include <locus/numeric/subdivide.hpp>
