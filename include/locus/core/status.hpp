// SPDX-License-Identifier: BSL-1.0
#pragma once
// Status: the outcome of an algorithm or IO call (Side, the result of classify, is in
// core/side.hpp).
//
// Queries (distance, intersection, construction) never fail and do not use Status. Algorithms
// over sets (hulls, triangulations, fits, booleans) and readers/writers return a result struct
// whose first member is a Status. Lower-dimensional output (a hull of collinear points) is data,
// reported by the result, not a failure.

#include <cstdint>
#include <string_view>

namespace locus {

enum class Status : std::uint8_t {
  ok,                ///< the result is valid
  empty_input,       ///< nothing to work on (no points, empty mesh)
  degenerate_input,  ///< the input lacks the dimension or rank the algorithm needs
  non_finite_input,  ///< a coordinate or coefficient is NaN or infinite
  invalid_topology,  ///< the input violates a structural precondition (non-manifold, open)
  invalid_input,     ///< values violate a documented precondition (e.g. a non-symmetric matrix
                     ///< given to a symmetric solver)
  parse_error,       ///< malformed file or text
  io_error,          ///< a file could not be opened, read or written
  limit_exceeded,    ///< an iteration or size budget ran out; the result is the best so far
};

/// A short lower-case name for a status ("ok", "non_finite_input", ...).
[[nodiscard]] constexpr std::string_view to_string(Status s) noexcept {
  switch (s) {
    case Status::ok:
      return "ok";
    case Status::empty_input:
      return "empty_input";
    case Status::degenerate_input:
      return "degenerate_input";
    case Status::non_finite_input:
      return "non_finite_input";
    case Status::invalid_topology:
      return "invalid_topology";
    case Status::invalid_input:
      return "invalid_input";
    case Status::parse_error:
      return "parse_error";
    case Status::io_error:
      return "io_error";
    case Status::limit_exceeded:
      return "limit_exceeded";
  }
  return "unknown";
}

}  // namespace locus
