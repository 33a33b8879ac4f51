// SPDX-License-Identifier: BSL-1.0
// Tests for distance/{line,ray,segment}_{aligned,oriented}_box.hpp (row dist3.linear-obb and its
// 2D analogue; book figures 10.46-10.52, the zero-component cases 10.48 and 10.49).
#include <locus/distance/line_aligned_box.hpp>
#include <locus/distance/line_oriented_box.hpp>
#include <locus/distance/point_aligned_box.hpp>
#include <locus/distance/point_oriented_box.hpp>
#include <locus/distance/ray_aligned_box.hpp>
#include <locus/distance/ray_oriented_box.hpp>
#include <locus/distance/segment_aligned_box.hpp>
#include <locus/distance/segment_oriented_box.hpp>

#include "distance/harness.hpp"
#include "support/typed.hpp"

#include <cmath>
#include <limits>
#include <utility>

using namespace locus;
using locus_test::Rng;
namespace dist = locus_test::dist;

template <class T>
class LinearBoxTest : public ::testing::Test {};
TYPED_TEST_SUITE(LinearBoxTest, locus_test::RealTypes);

namespace {

template <class T>
T random_extent(Rng& rng) {
  return rng.uniform_int(0, 7) == 0 ? T(0) : rng.uniform<T>(T(0.05), T(4));
}

template <class T, int N>
OrientedBox<T, N> random_obb(Rng& rng, T S) {
  const auto r = dist::random_rotation<T, N>(rng);
  OrientedBox<T, N> b{};
  b.center = rng.vec<T, N>(-S / 2, S / 2);
  for (int i = 0; i < N; ++i) {
    b.axis[i] = col(r, i);
    b.extent[i] = random_extent<T>(rng);
  }
  return b;
}

template <class T, int N>
AlignedBox<T, N> random_aabb(Rng& rng, T S) {
  const auto c = rng.vec<T, N>(-S / 2, S / 2);
  Vec<T, N> e{};
  for (int i = 0; i < N; ++i) e[i] = random_extent<T>(rng);
  return {c - e, c + e};
}

// Box-frame direction coefficients: each is zero with probability 1/3 (the zero-component
// cases), otherwise random; never all zero.
template <class T, int N>
Vec<T, N> random_coeffs(Rng& rng) {
  for (;;) {
    Vec<T, N> c{};
    for (int i = 0; i < N; ++i) c[i] = rng.uniform_int(0, 2) == 0 ? T(0) : rng.uniform<T>(-1, 1);
    if (max_abs(c) > T(0.05)) return c;
  }
}

template <class T, int N>
Vec<T, N> frame_dir(const OrientedBox<T, N>& b, const Vec<T, N>& c) {
  Vec<T, N> d{};
  for (int i = 0; i < N; ++i) d += c[i] * b.axis[i];
  return d;
}

template <class L, class T, int N>
L make_linear(const Vec<T, N>& o, const Vec<T, N>& d) {
  if constexpr (std::is_same_v<L, Segment<T, N>>)
    return {o, o + T(3) * d};
  else
    return {o, d};
}

// Independent oracle: f(t) = |l(t) - box|^2 (the tested point-box query) is convex in t, so a
// golden-section search over a window that provably holds the minimiser finds min f.
template <class T, int N, class L, class B>
T golden_sqr(const L& l, const B& box, T lo, T hi) {
  using C = double;
  auto f = [&](C t) { return double(distance(point_at(l, T(t)), box).sqr_distance); };
  const C g = 0.6180339887498949;
  C a = lo, b = hi, x1 = b - g * (b - a), x2 = a + g * (b - a);
  C f1 = f(x1), f2 = f(x2);
  for (int it = 0; it < 200; ++it) {
    if (f1 <= f2) {
      b = x2, x2 = x1, f2 = f1, x1 = b - g * (b - a), f1 = f(x1);
    } else {
      a = x1, x1 = x2, f1 = f2, x2 = a + g * (b - a), f2 = f(x2);
    }
  }
  return T(std::min({f1, f2, f(lo), f(hi)}));
}

template <class T, int N, class L>
std::pair<T, T> domain(const L& l, T window) {
  if constexpr (std::is_same_v<L, Segment<T, N>>)
    return {T(0), T(1)};
  else if constexpr (std::is_same_v<L, Ray<T, N>>)
    return {T(0), window / length(l.direction)};
  else
    return {-window / length(l.direction), window / length(l.direction)};
}

template <class T, int N, class L>
void harness_and_oracle() {
  const T S = 10;
  // Generic checks (oracle search, swap, rigid motions) on random boxes with random directions
  // that have zero components in the box frame.
  dist::Options<T> opt;
  opt.cases = 120;
  opt.check_agreement = false;  // replaced by the golden-section oracle below
  dist::check_pairs<T, N, L, OrientedBox<T, N>>(
      [&](Rng& rng) {
        const auto b = random_obb<T, N>(rng, S);
        return std::pair{
            make_linear<L, T, N>(rng.vec<T, N>(-S, S), frame_dir(b, random_coeffs<T, N>(rng))), b};
      },
      opt);
  dist::check_pairs<T, N, L, AlignedBox<T, N>>(
      [&](Rng& rng) {
        return std::pair{make_linear<L, T, N>(rng.vec<T, N>(-S, S), random_coeffs<T, N>(rng)),
                         random_aabb<T, N>(rng, S)};
      },
      opt);

  Rng rng(locus_test::test_seed() + 41);
  SCOPED_TRACE(rng.trace());
  const T tol_sq = std::is_same_v<T, float> ? T(2e-4) : T(1e-9);  // relative to S^2
  for (int n = 0; n < 400; ++n) {
    SCOPED_TRACE(n);
    const auto b = random_obb<T, N>(rng, S);
    const L l = make_linear<L, T, N>(rng.vec<T, N>(-S, S), frame_dir(b, random_coeffs<T, N>(rng)));
    const auto r = distance(l, b);
    const auto [lo, hi] = domain<T, N>(l, T(100));
    const T o = golden_sqr<T, N>(l, b, lo, hi);
    EXPECT_LE(r.sqr_distance, o + tol_sq * S * S);
    EXPECT_GE(r.sqr_distance, o - tol_sq * S * S);
    // The aligned query in the box's frame is the same problem: a second algorithm path.
    AlignedBox<T, N> a{};
    for (int i = 0; i < N; ++i) a.min[i] = -b.extent[i], a.max[i] = b.extent[i];
    const auto rotate = [&](const Vec<T, N>& v) {
      Vec<T, N> w{};
      for (int i = 0; i < N; ++i) w[i] = dot(v - b.center, b.axis[i]);
      return w;
    };
    L la = l;
    if constexpr (std::is_same_v<L, Segment<T, N>>) {
      la = {rotate(l.p0), rotate(l.p1)};
    } else {
      la.origin = rotate(l.origin);
      for (int i = 0; i < N; ++i) la.direction[i] = dot(l.direction, b.axis[i]);
    }
    const auto ra = distance(la, a);
    // (unique is not compared: the frame change perturbs zero components by rounding, and the
    // flag is decided relative to that noise; the figure cases check it exactly.)
    EXPECT_NEAR(ra.distance, r.distance, (std::is_same_v<T, float> ? T(1e-4) : T(1e-10)) * S);
  }
}

}  // namespace

TYPED_TEST(LinearBoxTest, HarnessAndOracle3D) {
  using T = TypeParam;
  harness_and_oracle<T, 3, Line<T, 3>>();
  harness_and_oracle<T, 3, Ray<T, 3>>();
  harness_and_oracle<T, 3, Segment<T, 3>>();
}

TYPED_TEST(LinearBoxTest, HarnessAndOracle2D) {
  using T = TypeParam;
  harness_and_oracle<T, 2, Line<T, 2>>();
  harness_and_oracle<T, 2, Ray<T, 2>>();
  harness_and_oracle<T, 2, Segment<T, 2>>();
}

// Figure cases against the unit-cube box [-1, 1]^3, answers derived by hand.
TYPED_TEST(LinearBoxTest, FigureCasesZeroComponents) {
  using T = TypeParam;
  using V = Vec3<T>;
  const AlignedBox3<T> box{{-1, -1, -1}, {1, 1, 1}};
  const T tl = std::is_same_v<T, float> ? T(1e-5) : T(1e-13);
  struct Case {
    V o, d;
    double dist;
    bool unique;
    V box_point;  // expected closest box point when unique
  };
  const Case cases[] = {
      // two zero components (figure 10.48): parallel to the x edges, a 1D problem + offset
      {{0, 3, 4}, {1, 0, 0}, std::sqrt(13.0), false, {}},
      {{5, 3, 0.5}, {-2, 0, 0}, 2.0, false, {}},
      {{0, 0.25, -0.5}, {0, 0, 1}, 0.0, false, {}},  // through the box
      // one zero component (figure 10.49): a 2D problem in the xy plane + z offset
      {{3, 0, 0}, {1, 1, 0}, std::sqrt(0.5), true, {1, -1, 0}},
      {{0, 0, 3}, {1, 1, 0}, 2.0, false, {}},  // over the top face
      {{3, 0, 4}, {1, 1, 0}, std::sqrt(0.5 + 9.0), true, {1, -1, 1}},
      // no zero component (figures 10.50-10.52): x - 3 = y = z
      {{3, 0, 0}, {1, 1, 1}, std::sqrt(2.0 / 3.0), true, {1, -1, -1}},
      {{-2, -4, 6}, {1, 2, -3}, 0.0, false, {}},  // passes through the center (t = 2)
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(::testing::Message() << "o = " << c.o.x << "," << c.o.y << "," << c.o.z);
    for (const T sg : {T(1), T(-1)}) {  // both orientations of the direction
      const auto r = distance(Line3<T>{c.o, sg * c.d}, box);
      EXPECT_NEAR(r.distance, T(c.dist), tl * 10);
      EXPECT_EQ(r.unique, c.unique);
      if (c.unique) {
        EXPECT_TRUE(locus_test::vec_near(r.closest[1], c.box_point, tl * 10));
      }
      // The same case in a rotated, translated frame (the OBB path).
      OrientedBox3<T> ob{};
      const auto rot = Mat<T, 3, 3>::from_cols(V{0, 1, 0}, V{0, 0, 1}, V{1, 0, 0});
      ob.center = V{2, -3, 5};
      for (int i = 0; i < 3; ++i) ob.axis[i] = col(rot, i);
      ob.extent = V{1, 1, 1};
      const auto ro = distance(Line3<T>{rot * c.o + ob.center, sg * (rot * c.d)}, ob);
      EXPECT_NEAR(ro.distance, T(c.dist), tl * 20);
      EXPECT_EQ(ro.unique, c.unique);
    }
  }
  // Segment and ray versions of a vertex region and an end-point region.
  EXPECT_NEAR(distance(Segment3<T>{{2, 2, 2}, {5, 5, 5}}, box).distance, std::sqrt(T(3)), tl * 10);
  EXPECT_NEAR(distance(Ray3<T>{{2, 2, 2}, {1, 1, 1}}, box).distance, std::sqrt(T(3)), tl * 10);
  EXPECT_NEAR(distance(Ray3<T>{{2, 2, 2}, {-1, -1, -1}}, box).distance, T(0), tl);
  const auto s = distance(Segment3<T>{{3, 0, 0}, {3, 0, 0}}, box);  // zero length: a point
  EXPECT_NEAR(s.distance, T(2), tl);
  EXPECT_TRUE(s.unique);
}

// Continuity as a direction component passes through zero: the distance is Lipschitz in the
// component (the origin is within ~10 of the box, so |d(e) - d(0)| <= ~20 |e|), across the switch
// from the general case to the one-zero and two-zero cases, including denormal components.
TYPED_TEST(LinearBoxTest, ContinuityThroughZeroComponent) {
  using T = TypeParam;
  using V = Vec3<T>;
  Rng rng(locus_test::test_seed() + 43);
  SCOPED_TRACE(rng.trace());
  const T eps_list[] = {
      T(1e-2), T(1e-4), T(1e-7), T(1e-12), T(1e-30), std::numeric_limits<T>::denorm_min(), T(0)};
  const T tl = std::is_same_v<T, float> ? T(2e-5) : T(1e-12);
  for (int n = 0; n < 200; ++n) {
    const auto b = random_obb<T, 3>(rng, T(4));
    const V o = rng.vec<T, 3>(-6, 6);
    V c = random_coeffs<T, 3>(rng);
    const int k = rng.uniform_int(0, 2);  // the component that crosses zero
    const int mode = rng.uniform_int(0, 2);
    c[k] = T(0);
    const auto query = [&](T e) {
      V cc = c;
      cc[k] = e;
      const V d = frame_dir(b, cc);
      if (mode == 0) return distance(Line3<T>{o, d}, b);
      if (mode == 1) return distance(Ray3<T>{o, d}, b);
      return distance(Segment3<T>{o, o + T(4) * d}, b);
    };
    if (max_abs(c) == T(0)) continue;
    // |d/de of the closest point| <= |t| |axis_k| (times 4 for the segment's length), so the
    // distance is Lipschitz in e with constant <= max(|t(0)|, |t(e)|) * 4 + 1.
    const auto r0 = query(T(0));
    for (const T e : eps_list) {
      for (const T sg : {T(1), T(-1)}) {
        const auto re = query(sg * e);
        const T lip = T(4) * std::max(std::abs(r0.param_a), std::abs(re.param_a)) + T(1);
        EXPECT_NEAR(re.distance, r0.distance, lip * e + tl * 20) << "n " << n << " e " << sg * e;
      }
    }
  }
  // Aligned box, line nearly parallel to a face and outside it: distance -> offset to the face.
  const AlignedBox3<T> box{{-1, -1, -1}, {1, 1, 1}};
  for (const T e : eps_list) {
    const auto r = distance(Line3<T>{{0, 0, 3}, {1, e, 0}}, box);
    EXPECT_NEAR(r.distance, T(2), tl * 10) << e;
    const auto r2 = distance(Line3<T>{{0, 3, 3}, {1, 0, e}}, box);
    EXPECT_NEAR(r2.distance, std::sqrt(T(8)), T(3) * e + tl * 10) << e;
  }
}

TYPED_TEST(LinearBoxTest, DegenerateAndNonFinite) {
  using T = TypeParam;
  using V = Vec3<T>;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const T tl = std::is_same_v<T, float> ? T(1e-5) : T(1e-13);
  const AlignedBox3<T> box{{-1, -1, -1}, {1, 1, 1}};
  // Zero direction and zero-length segment act as points.
  const auto rp = distance(Line3<T>{{4, 0, 0}, {0, 0, 0}}, box);
  EXPECT_NEAR(rp.distance, T(3), tl);
  EXPECT_EQ(rp.param_a, T(0));
  EXPECT_TRUE(rp.unique);
  // Flat boxes: a square and a segment.
  const AlignedBox3<T> flat{{-1, -1, 0}, {1, 1, 0}};
  EXPECT_NEAR(distance(Line3<T>{{0, 0, 2}, {1, 0, 0}}, flat).distance, T(2), tl);
  EXPECT_NEAR(distance(Segment3<T>{{3, 0, -1}, {3, 0, 1}}, flat).distance, T(2), tl);
  OrientedBox3<T> stick{};
  stick.axis[0] = V{1, 0, 0}, stick.axis[1] = V{0, 1, 0}, stick.axis[2] = V{0, 0, 1};
  stick.extent = V{2, 0, -1};  // negative extent counts as 0
  EXPECT_NEAR(distance(Line3<T>{{0, 3, 4}, {0, 0, 1}}, stick).distance, T(3), tl);
  // Tiny and huge directions stay finite and correct.
  EXPECT_NEAR(
      distance(Line3<T>{{0, 0, 3}, {std::numeric_limits<T>::min(), T(0), T(0)}}, box).distance,
      T(2), tl);
  EXPECT_NEAR(
      distance(Ray3<T>{{0, 0, 3}, {std::numeric_limits<T>::max(), T(1), T(0)}}, box).distance, T(2),
      tl);
  // Non-finite input and the empty box give the NaN result.
  EXPECT_TRUE(dist::is_nan_result(distance(Line3<T>{{nan, 0, 0}, {1, 0, 0}}, box)));
  EXPECT_TRUE(dist::is_nan_result(distance(Ray3<T>{{0, 0, 0}, {inf, 0, 0}}, box)));
  EXPECT_TRUE(dist::is_nan_result(distance(box, Segment3<T>{{0, 0, 0}, {1, nan, 0}})));
  EXPECT_TRUE(dist::is_nan_result(distance(Line3<T>{{0, 0, 0}, {1, 0, 0}}, empty_box<T, 3>())));
  OrientedBox3<T> bad = stick;
  bad.axis[1] = V{nan, 0, 0};
  EXPECT_TRUE(dist::is_nan_result(distance(Segment3<T>{{0, 0, 0}, {1, 0, 0}}, bad)));
  // Swapped overloads are the swap, bit for bit.
  const Segment3<T> sg{{3, 0.5, 2}, {-1, 4, 2}};
  const auto a = distance(sg, box);
  const auto b = distance(box, sg);
  EXPECT_EQ(a.sqr_distance, b.sqr_distance);
  EXPECT_EQ(a.closest[0], b.closest[1]);
  EXPECT_EQ(a.param_b, b.param_a);
}
