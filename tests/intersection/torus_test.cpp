// SPDX-License-Identifier: BSL-1.0
// Row int3.torus: Line3, Ray3, Segment3 against Torus3 (quartic roots), float and double. The
// hits are compared with an independent high-precision oracle: the torus function evaluated
// geometrically in long double along the line, sign changes bracketed on a fine grid and
// bisected; every hit lies on the torus (relative residual), its (u, v) maps back to the point
// through point_at, its normal is the unit gradient. Figures 11.74-11.77: a line through the
// hole (0 hits), across the ring (4), tangent to the top circle (two double roots), through the
// tube only (2). Near-tangent rays: one ulp above/below the top give 0 / 2 x 2 (within the
// documented bound: multiplicity 2 reported, or two close simple roots). Power-of-two scaling,
// reversed segments, swap, degenerate and NaN input.

#include <locus/intersection/line_torus.hpp>
#include <locus/intersection/ray_torus.hpp>
#include <locus/intersection/segment_torus.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include "support/typed.hpp"

namespace {

using namespace locus;
using locus_test::Rng;

template <class T>
class TorusHits : public ::testing::Test {};
TYPED_TEST_SUITE(TorusHits, locus_test::RealTypes);

using LD = long double;

/// (|X|^2 + R^2 - r^2)^2 - 4 R^2 (|X|^2 - (n.X)^2) in long double (X relative to the centre).
template <class T>
LD torus_value(const Torus3<T>& t, const Vec3<double>& o, const Vec3<double>& d, LD s) {
  LD x[3], n[3], nn = 0;
  for (int i = 0; i < 3; ++i) {
    x[i] = LD(o[i]) + s * LD(d[i]) - LD(double(t.center[i]));
    n[i] = LD(double(t.normal[i]));
    nn += n[i] * n[i];
  }
  LD xx = 0, xn = 0;
  for (int i = 0; i < 3; ++i) {
    xx += x[i] * x[i];
    xn += x[i] * n[i];
  }
  const LD big = LD(double(t.major_radius)), small = LD(double(t.minor_radius));
  const LD g = xx + big * big - small * small;
  return g * g - 4 * big * big * (xx - xn * xn / nn);
}

/// Simple roots of the torus function on [t0, t1] by grid bracketing and bisection.
template <class T>
std::vector<double> oracle_roots(const Torus3<T>& t, const Vec3<double>& o, const Vec3<double>& d,
                                 double t0, double t1, int grid) {
  std::vector<double> out;
  LD prev = torus_value(t, o, d, LD(t0));
  for (int i = 1; i <= grid; ++i) {
    const LD b = LD(t0) + (LD(t1) - LD(t0)) * i / grid;
    const LD cur = torus_value(t, o, d, b);
    if ((prev < 0) != (cur < 0)) {
      LD lo = LD(t0) + (LD(t1) - LD(t0)) * (i - 1) / grid, hi = b;
      const bool neg_lo = prev < 0;
      for (int k = 0; k < 80; ++k) {
        const LD m = (lo + hi) / 2;
        ((torus_value(t, o, d, m) < 0) == neg_lo ? lo : hi) = m;
      }
      out.push_back(double((lo + hi) / 2));
    }
    prev = cur;
  }
  return out;
}

TYPED_TEST(TorusHits, AgainstLongDoubleOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int compared = 0, four = 0;
  for (int n = 0; n < 80; ++n) {
    const Torus3<T> tor{rng.template vec<T, 3>(T(-1), T(1)),
                        normalize(rng.template vec<T, 3>(T(-1), T(1))), rng.uniform(T(1.5), T(3)),
                        rng.uniform(T(0.3), T(1.2))};
    const Vec3<T> p0 = rng.template vec<T, 3>(T(-6), T(6));
    const Segment3<T> sg{p0, tor.center + (tor.center - p0) + rng.template vec<T, 3>(T(-2), T(2))};
    const auto r = intersection(sg, tor);
    const Vec3<double> o = vec_cast<double>(sg.p0), d = vec_cast<double>(sg.p1) - o;
    const auto ref = oracle_roots(tor, o, d, 0.0, 1.0, 4000);
    bool crowded = false;
    for (std::size_t i = 1; i < ref.size(); ++i) crowded = crowded || ref[i] - ref[i - 1] < 1e-3;
    for (double x : ref) crowded = crowded || x < 1e-3 || x > 1 - 1e-3;
    for (int i = 0; i < r.count; ++i) crowded = crowded || r.multiplicity[std::size_t(i)] > 1;
    // Every reported point is on the torus (relative to its scale) and on the segment.
    const double scale = double(tor.major_radius + tor.minor_radius) + 8.0;
    for (int i = 0; i < r.count; ++i) {
      const auto k = std::size_t(i);
      const double res = std::abs(double(signed_value(tor, r.point[k])));
      EXPECT_LE(res, 4096.0 * double(eps_v<T>) * std::pow(scale, 4.0)) << i;
      EXPECT_TRUE(locus_test::vec_near(point_at(tor, r.param_b[k]), r.point[k],
                                       T(1024) * eps_v<T> * T(scale)));
      EXPECT_NEAR(double(length(r.normal[k])), 1.0, 64.0 * double(eps_v<T>));
    }
    if (crowded) continue;
    ++compared;
    four += ref.size() == 4;
    ASSERT_EQ(r.count, int(ref.size()));
    for (int i = 0; i < r.count; ++i)
      EXPECT_NEAR(double(r.param_a[std::size_t(i)]), ref[std::size_t(i)], 1e3 * double(eps_v<T>));
  }
  EXPECT_GT(compared, 60);
  EXPECT_GT(four, 5);
}

TYPED_TEST(TorusHits, Figures) {
  using T = TypeParam;
  const Torus3<T> tor{{T(0), T(0), T(0)}, {T(0), T(0), T(1)}, T(4), T(1)};
  // Through the hole along the axis: nothing (figure 11.74).
  EXPECT_EQ(intersection(Line3<T>{{T(0), T(0), T(-9)}, {T(0), T(0), T(1)}}, tor).kind, Kind::empty);
  // Across the ring in its plane: x = -5, -3, 3, 5 (figure 11.75).
  const auto r = intersection(Line3<T>{{T(-10), T(0), T(0)}, {T(1), T(0), T(0)}}, tor);
  ASSERT_EQ(r.count, 4);
  const double want[4] = {5, 7, 13, 15};
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(double(r.param_a[std::size_t(i)]), want[i], 64 * double(eps_v<T>) * 16);
    EXPECT_EQ(r.multiplicity[std::size_t(i)], 1);
  }
  EXPECT_TRUE(locus_test::vec_near(r.normal[0], Vec3<T>{T(-1), T(0), T(0)}, T(64) * eps_v<T>));
  EXPECT_TRUE(locus_test::vec_near(r.normal[1], Vec3<T>{T(1), T(0), T(0)}, T(64) * eps_v<T>));
  // (u, v) of the first hit: u = pi about the axis, v = 0 on the tube's outer equator.
  EXPECT_NEAR(std::abs(double(r.param_b[0].x)), 3.141592653589793, 1e-5);
  EXPECT_NEAR(double(r.param_b[0].y), 0.0, 1e-5);
  // Tangent to the top circle z = 1: two double roots at x = -4, 4 (figure 11.76).
  const auto t = intersection(Line3<T>{{T(-10), T(0), T(1)}, {T(1), T(0), T(0)}}, tor);
  ASSERT_EQ(t.count, 2);
  EXPECT_EQ(t.multiplicity[0], 2);
  EXPECT_EQ(t.multiplicity[1], 2);
  EXPECT_NEAR(double(t.param_a[0]), 6.0, 1e-2);
  EXPECT_NEAR(double(t.param_a[1]), 14.0, 1e-2);
  // Through the tube only (figure 11.77): a vertical line at x = 4.5 crosses the tube twice.
  const auto v = intersection(Ray3<T>{{T(4.5), T(0), T(-3)}, {T(0), T(0), T(1)}}, tor);
  ASSERT_EQ(v.count, 2);
  const double h = std::sqrt(1.0 - 0.25);
  EXPECT_NEAR(double(v.param_a[0]), 3.0 - h, 64 * double(eps_v<T>) * 8);
  EXPECT_NEAR(double(v.param_a[1]), 3.0 + h, 64 * double(eps_v<T>) * 8);
  // Near-tangent: clearly above the top misses, clearly below hits four times.
  EXPECT_EQ(intersection(Line3<T>{{T(-10), T(0), T(1.01)}, {T(1), T(0), T(0)}}, tor).count, 0);
  EXPECT_EQ(intersection(Line3<T>{{T(-10), T(0), T(0.99)}, {T(1), T(0), T(0)}}, tor).count, 4);
  // Within one ulp of the top: never more than the four intersections, each a tangency or a
  // close pair; never a point off the torus.
  const auto e =
      intersection(Line3<T>{{T(-10), T(0), std::nextafter(T(1), T(0))}, {T(1), T(0), T(0)}}, tor);
  int total = 0;
  for (int i = 0; i < e.count; ++i) total += e.multiplicity[std::size_t(i)];
  EXPECT_TRUE(total == 4 || total == 0) << total;
}

TYPED_TEST(TorusHits, ScalingReverseSwapDegenerate) {
  using T = TypeParam;
  Rng rng(5);
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 40; ++n) {
    const Torus3<T> tor{rng.template vec<T, 3>(T(-1), T(1)),
                        normalize(rng.template vec<T, 3>(T(-1), T(1))), rng.uniform(T(1.5), T(3)),
                        rng.uniform(T(0.3), T(1.2))};
    const Vec3<T> p0 = rng.template vec<T, 3>(T(-6), T(6));
    const Segment3<T> sg{p0, tor.center + (tor.center - p0)};
    const auto r = intersection(sg, tor);
    for (int k : {-12, 9}) {
      const T f = std::ldexp(T(1), k);
      const auto rs = intersection(
          Segment3<T>{sg.p0 * f, sg.p1 * f},
          Torus3<T>{tor.center * f, tor.normal, tor.major_radius * f, tor.minor_radius * f});
      ASSERT_EQ(rs.count, r.count);
      for (int i = 0; i < r.count; ++i)
        EXPECT_EQ(rs.param_a[std::size_t(i)], r.param_a[std::size_t(i)]);
    }
    const auto rr = intersection(Segment3<T>{sg.p1, sg.p0}, tor);
    ASSERT_EQ(rr.count, r.count);
    for (int i = 0; i < r.count; ++i)
      EXPECT_NEAR(double(rr.param_a[std::size_t(r.count - 1 - i)]),
                  1.0 - double(r.param_a[std::size_t(i)]), 1e3 * double(eps_v<T>));
    const auto sw = intersection(tor, sg);
    ASSERT_EQ(sw.count, r.count);
    if (r.count > 0) {
      EXPECT_EQ(sw.param_b[0], r.param_a[0]);
    }
  }
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const Torus3<T> tor{{T(0), T(0), T(0)}, {T(0), T(0), T(1)}, T(4), T(1)};
  EXPECT_EQ(intersection(Line3<T>{{nan, T(0), T(0)}, {T(1), T(0), T(0)}}, tor).kind, Kind::empty);
  EXPECT_EQ(intersection(Line3<T>{{T(0), T(0), T(0)}, {T(1), T(0), T(0)}},
                         Torus3<T>{{T(0), T(0), T(0)}, {T(0), T(0), T(0)}, T(4), T(1)})
                .kind,
            Kind::empty);
  EXPECT_EQ(intersection(Line3<T>{{T(0), T(0), T(0)}, {T(1), T(0), T(0)}},
                         Torus3<T>{{T(0), T(0), T(0)}, {T(0), T(0), T(1)}, T(-4), T(1)})
                .kind,
            Kind::empty);
  // A zero-length segment on the torus: one point.
  EXPECT_EQ(intersection(Segment3<T>{{T(5), T(0), T(0)}, {T(5), T(0), T(0)}}, tor).count, 1);
  EXPECT_EQ(intersection(Segment3<T>{{T(4), T(0), T(0)}, {T(4), T(0), T(0)}}, tor).count, 0);
}

}  // namespace
