// SPDX-License-Identifier: BSL-1.0
#pragma once
// Shared helpers of the fit tests: seeded Gaussian noise, random rotations, rigid motions.
#include "support/typed.hpp"

#include <locus/core/mat.hpp>
#include <locus/core/vec.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace fit_test {

using locus_test::Rng;

/// One N(0, sigma^2) sample from the test's seeded engine.
inline double gauss(Rng& rng, double sigma) {
  return std::normal_distribution<double>(0.0, sigma)(rng.engine());
}

/// A random rotation (orthonormal columns, det +1) in 2D or 3D, in double.
inline locus::Mat2<double> random_rotation2(Rng& rng) {
  const double a = rng.uniform<double>(0, 2 * locus::pi_v<double>);
  return locus::Mat2<double>::from_cols(locus::Vec2d{std::cos(a), std::sin(a)},
                                        locus::Vec2d{-std::sin(a), std::cos(a)});
}
inline locus::Mat3<double> random_rotation3(Rng& rng) {
  const locus::Vec3d a = rng.unit<double, 3>();
  locus::Vec3d b = rng.unit<double, 3>();
  b = locus::normalize(b - a * locus::dot(a, b));
  return locus::Mat3<double>::from_cols(a, b, locus::cross(a, b));
}

/// The points mapped by x -> R x + t, computed in double and rounded to T.
template <class T, int N>
std::vector<locus::Vec<T, N>> moved(const std::vector<locus::Vec<T, N>>& pts,
                                    const locus::Mat<double, N, N>& r,
                                    const locus::Vec<double, N>& t) {
  std::vector<locus::Vec<T, N>> out;
  out.reserve(pts.size());
  for (const auto& p : pts) out.push_back(locus::vec_cast<T>(r * locus::vec_cast<double>(p) + t));
  return out;
}

/// |sin| of the angle between two directions (sign-insensitive parallelism measure).
template <int N>
double sin_angle(const locus::Vec<double, N>& a, const locus::Vec<double, N>& b) {
  // The component of a orthogonal to b, relative to |a|: accurate to eps also when parallel.
  const locus::Vec<double, N> bh = b / std::sqrt(locus::sqr_length(b));
  const locus::Vec<double, N> ap = a - locus::dot(a, bh) * bh;
  return std::sqrt(locus::sqr_length(ap) / locus::sqr_length(a));
}

template <class T>
T nan_v() {
  return std::numeric_limits<T>::quiet_NaN();
}

}  // namespace fit_test
