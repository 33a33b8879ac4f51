// SPDX-License-Identifier: BSL-1.0
#pragma once
// Options shared by min_circle (bounding/min_circle.hpp) and min_sphere (bounding/min_sphere.hpp);
// rows cg.minball.

#include <cstdint>

namespace locus {

/// Options of the smallest enclosing circle / sphere.
struct MinBallOptions {
  /// Seed of the random permutation the points are visited in (deterministic: the same seed and
  /// input give the same result on every platform).
  std::uint64_t seed = 0x243f6a8885a308d3ull;
  /// Visit the points in random order (the expected-linear bound needs it); false keeps the
  /// input order (a move-to-front list still adapts it).
  bool shuffle = true;
  /// Budget of point-versus-ball tests; 0 means 1000 n + 10^6. When it runs out the result has
  /// Status::limit_exceeded and the ball of that moment (which may miss points).
  std::uint64_t max_tests = 0;
};

}  // namespace locus
