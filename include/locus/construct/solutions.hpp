// SPDX-License-Identifier: BSL-1.0
#pragma once
// The result of the chapter 8 constructions (rows cons2.*): every solution in a fixed-size array
// with a count, so no construction allocates (DESIGN.md: fixed arrays when the size is bounded).
//
// Solutions<X, Capacity> {status, infinite, count, item}: item[0 .. count) are the solutions
// (circles Circle2<T> or lines Line2<T>), in the order each construction's header documents;
// the entries past count are value-initialised. Capacity is the largest number of solutions the
// construction can have (two lines through a point tangent to a circle, eight circles of a
// given radius tangent to two circles, ...).
//
// status: ok when the input was usable (count may then be 0: no solution is data, not an
// error); non_finite_input when a coordinate, radius or distance is NaN or infinite;
// degenerate_input when an argument violates its documented precondition (a zero line
// direction, a negative or zero radius where a positive one is required). Both give count 0.
// infinite: true when the problem has infinitely many solutions (two coincident given circles,
// two parallel lines exactly 2r apart, ...); the family is not listed (count then counts only
// the isolated solutions the header names, usually 0). Never a magic count for "infinitely
// many".
//
// How many solutions there are (0, 1, 2, tangency, parallel or concurrent lines) is decided
// exactly from the input coordinates (core/exact_poly.hpp); the solutions themselves are then
// computed in floating point and rounded (each header states the bound). Float input is
// computed in double and rounded once at the end. Lines are returned with a unit direction.
// Book chapter 8; derivations: docs/notes/construct.md.

#include <locus/core/status.hpp>

#include <array>

namespace locus {

/// All solutions of a construction (see the header comment).
template <class X, int Capacity>
struct Solutions {
  static constexpr int capacity = Capacity;
  Status status = Status::ok;
  bool infinite = false;  ///< infinitely many solutions (not listed)
  int count = 0;          ///< number of valid entries of item
  std::array<X, Capacity> item{};

  /// Appends x; ignored past capacity (never reached: each construction is sized for its maximum).
  constexpr void push(const X& x) noexcept {
    if (count < Capacity) item[static_cast<std::size_t>(count++)] = x;
  }
};

}  // namespace locus
