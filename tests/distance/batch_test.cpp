// SPDX-License-Identifier: BSL-1.0
// Tests for distance/batch.hpp (batched squared distances; rows dist3.pt-triangle,
// dist3.linear-linear, dist3.linear-triangle, dist3.pt-aabb, dist3.pt-obb). The oracle is the
// per-query sqr_distance of each pair (itself tested against exact rationals and dense sampling
// in the pair's own test): the batch must return the same bits for every query, on inputs that
// mix every path of the per-query code in one batch (generic, inside, vertex and edge regions,
// thin and flat triangles, parallel and nearly parallel segments at every angle, zero-length
// segments, shared end points, huge and tiny coordinates, NaN and infinities, empty and flat
// boxes), in the span-span, span-one and one-span forms and both argument orders, for every batch
// length from 0 to a few lane groups (tails), under every compiled version of the kernels the
// processor runs (x86-64-v4, AVX2, baseline), plus the agreement of one sample with the exact
// rational distance.
#include <locus/distance/batch.hpp>
#include <locus/distance/point_aligned_box.hpp>
#include <locus/distance/point_oriented_box.hpp>
#include <locus/distance/point_triangle.hpp>
#include <locus/distance/segment_segment.hpp>
#include <locus/distance/segment_triangle.hpp>

#include "support/typed.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

using namespace locus;
using locus_test::Rng;

template <class T>
class BatchTest : public ::testing::Test {};
TYPED_TEST_SUITE(BatchTest, locus_test::RealTypes);

namespace {

// The same bits, or both NaN (the NaN's sign and payload are not part of the contract).
template <class T>
bool same_value(T a, T b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  return std::bit_cast<std::conditional_t<sizeof(T) == 8, std::uint64_t, std::uint32_t>>(a) ==
         std::bit_cast<std::conditional_t<sizeof(T) == 8, std::uint64_t, std::uint32_t>>(b);
}

// A coordinate scale drawn per object: mostly 1, sometimes huge or tiny (the per-query code's
// range checks and rescaling paths).
template <class T>
T random_scale(Rng& rng) {
  switch (rng.uniform_int(0, 15)) {
    case 0:
      return std::sqrt(std::numeric_limits<T>::max()) * T(0.5);
    case 1:
      return std::sqrt(std::numeric_limits<T>::min()) * T(2);
    case 2:
      return T(1e-3);
    default:
      return T(1);
  }
}

// One coordinate of the object is replaced by NaN or an infinity in 1 of 24 objects.
template <class T, int N>
void maybe_poison(Rng& rng, Vec<T, N>& v) {
  const int k = rng.uniform_int(0, 71);
  if (k < 3) {
    const T bad[3] = {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity(),
                      -std::numeric_limits<T>::infinity()};
    v[rng.uniform_int(0, N - 1)] = bad[k];
  }
}

template <class T>
Vec3<T> random_point(Rng& rng, T s) {
  Vec3<T> p = s * rng.vec<T, 3>(T(-2), T(2));
  maybe_poison(rng, p);
  return p;
}

template <class T>
Triangle3<T> random_triangle(Rng& rng) {
  const T s = random_scale<T>(rng);
  Triangle3<T> t{s * rng.vec<T, 3>(T(-1), T(1)), s * rng.vec<T, 3>(T(-1), T(1)),
                 s * rng.vec<T, 3>(T(-1), T(1))};
  switch (rng.uniform_int(0, 9)) {
    case 0:  // collinear
      t.v2 = lerp(t.v0, t.v1, rng.uniform<T>(T(-1), T(2)));
      break;
    case 1:  // a needle: thin, not flat
      t.v2 = lerp(t.v0, t.v1, T(0.5)) + T(1e-4) * s * rng.vec<T, 3>(T(-1), T(1));
      break;
    case 2:  // two vertices coincide
      t.v1 = t.v0;
      break;
    case 3:  // a sliver at ~10 degrees (the refinement threshold)
      t.v2 = t.v0 + (t.v1 - t.v0) + T(0.17) * s * rng.vec<T, 3>(T(-1), T(1));
      break;
    default:
      break;
  }
  maybe_poison(rng, t.v0);
  maybe_poison(rng, t.v2);
  return t;
}

template <class T>
Segment3<T> random_segment(Rng& rng, const Segment3<T>* partner) {
  const T s = random_scale<T>(rng);
  Segment3<T> seg{s * rng.vec<T, 3>(T(-1), T(1)), s * rng.vec<T, 3>(T(-1), T(1))};
  if (partner != nullptr) {
    const Vec3<T> d = partner->p1 - partner->p0;
    const Vec3<T> off = rng.vec<T, 3>(T(-1), T(1));
    switch (rng.uniform_int(0, 11)) {
      case 0:  // exactly parallel (same direction or reversed)
        seg = {partner->p0 + off, partner->p1 + off};
        if (rng.uniform_int(0, 1) == 0) seg = {seg.p1, seg.p0};
        break;
      case 1:  // nearly parallel at a random small angle (1e-7 .. 1e-1)
        seg = {partner->p0 + off,
               partner->p1 + off +
                   std::pow(T(10), rng.uniform<T>(T(-7), T(-1))) * rng.vec<T, 3>(T(-1), T(1))};
        break;
      case 2:  // collinear overlapping
        seg = {partner->p0 + rng.uniform<T>(T(-0.5), T(0.5)) * d,
               partner->p0 + rng.uniform<T>(T(0.5), T(1.5)) * d};
        break;
      case 3:  // zero length
        seg.p1 = seg.p0;
        break;
      case 4:  // the same first end point (the canonical order looks at p1)
        seg.p0 = partner->p0;
        break;
      case 5:  // identical
        seg = *partner;
        break;
      case 6:  // crossing at a small angle through the partner's middle
        seg = {lerp(partner->p0, partner->p1, T(0.5)) - T(0.5) * d + T(0.05) * off,
               lerp(partner->p0, partner->p1, T(0.5)) + T(0.5) * d - T(0.05) * off};
        break;
      default:
        break;
    }
  } else if (rng.uniform_int(0, 11) == 0) {
    seg.p1 = seg.p0;
  }
  maybe_poison(rng, seg.p0);
  maybe_poison(rng, seg.p1);
  return seg;
}

template <class T>
AlignedBox3<T> random_aabb(Rng& rng) {
  const Vec3<T> c = rng.vec<T, 3>(T(-1), T(1));
  Vec3<T> e = rng.vec<T, 3>(T(0), T(1));
  if (rng.uniform_int(0, 7) == 0) e[rng.uniform_int(0, 2)] = T(0);      // flat
  if (rng.uniform_int(0, 15) == 0) e[rng.uniform_int(0, 2)] = T(-0.1);  // empty axis
  AlignedBox3<T> b{c - e, c + e};
  maybe_poison(rng, b.min);
  return b;
}

template <class T>
OrientedBox3<T> random_obb(Rng& rng) {
  const Vec3<T> x = normalize(rng.vec<T, 3>(T(-1), T(1)));
  const Vec3<T> y = normalize(cross(x, rng.vec<T, 3>(T(-1), T(1))));
  OrientedBox3<T> b{rng.vec<T, 3>(T(-1), T(1)), {x, y, cross(x, y)}, rng.vec<T, 3>(T(0), T(1))};
  if (rng.uniform_int(0, 7) == 0) b.extent[rng.uniform_int(0, 2)] = T(0);
  if (rng.uniform_int(0, 15) == 0) b.extent[rng.uniform_int(0, 2)] = T(-0.5);
  maybe_poison(rng, b.axis[rng.uniform_int(0, 2)]);
  return b;
}

// Checks every form of sqr_distances over a[0..n), b[0..n) against the per-query function: the
// two spans in both orders (for a same-type pair, the spans exchanged), and one object against
// the other span, each way.
template <class T, class A, class B>
void check_pair_once(const std::vector<A>& a, const std::vector<B>& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size());
  const std::size_t n = a.size();
  std::vector<T> out(n, T(-1)), swapped(n, T(-1));
  sqr_distances(std::span<const A>(a), std::span<const B>(b), std::span<T>(out));
  sqr_distances(std::span<const B>(b), std::span<const A>(a), std::span<T>(swapped));
  int failures = 0;
  for (std::size_t i = 0; i < n && failures < 5; ++i) {
    const T want = sqr_distance(a[i], b[i]), want_swapped = sqr_distance(b[i], a[i]);
    if (!same_value(out[i], want) || !same_value(swapped[i], want_swapped)) {
      ++failures;
      ADD_FAILURE() << what << " query " << i << " of " << n << ": batch " << out[i] << " / "
                    << swapped[i] << ", per query " << want << " / " << want_swapped;
    }
  }
  if (n == 0) return;
  std::vector<T> one(n, T(-1)), one_swapped(n, T(-1)), other(n, T(-1));
  sqr_distances(std::span<const A>(a), b[0], std::span<T>(one));
  sqr_distances(b[0], std::span<const A>(a), std::span<T>(one_swapped));
  sqr_distances(a[0], std::span<const B>(b), std::span<T>(other));
  for (std::size_t i = 0; i < n && failures < 5; ++i) {
    const T want = sqr_distance(a[i], b[0]), want_swapped = sqr_distance(b[0], a[i]);
    const T want_other = sqr_distance(a[0], b[i]);
    if (!same_value(one[i], want) || !same_value(one_swapped[i], want_swapped) ||
        !same_value(other[i], want_other)) {
      ++failures;
      ADD_FAILURE() << what << " one-against-many query " << i << ": " << one[i] << " / "
                    << one_swapped[i] << " vs " << want << " / " << want_swapped << ", " << other[i]
                    << " vs " << want_other;
    }
  }
}

// check_pair_once under every compiled version of the kernels this processor runs (x86-64-v4,
// AVX2, baseline: detail::set_batch_isa), so that each is tested on one machine.
template <class T, class A, class B>
void check_pair(const std::vector<A>& a, const std::vector<B>& b, const std::string& what) {
  using detail::BatchIsa;
  int tested = -1;
  for (const BatchIsa level : {BatchIsa::x86_64_v4, BatchIsa::avx2, BatchIsa::baseline}) {
    const BatchIsa used = detail::set_batch_isa(level);
    EXPECT_LE(static_cast<int>(used), static_cast<int>(level));
    if (static_cast<int>(used) == tested) continue;  // the processor lacks this level
    tested = static_cast<int>(used);
    check_pair_once<T>(a, b, what + " isa " + std::to_string(tested));
  }
  detail::set_batch_isa(BatchIsa::x86_64_v4);
}

// Batch lengths: every length up to three lane groups of floats (tails of every size), then a
// large batch.
const std::size_t kLengths[] = {0, 1, 2, 3, 4, 5, 7, 8, 9, 11, 15, 16, 17, 23, 24, 25, 3000};

}  // namespace

TYPED_TEST(BatchTest, PointTriangleMatchesPerQuery) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (const std::size_t n : kLengths) {
    std::vector<Vec3<T>> p;
    std::vector<Triangle3<T>> t;
    for (std::size_t i = 0; i < n; ++i) {
      t.push_back(random_triangle<T>(rng));
      // A third of the points project into the triangle (inside region), the rest anywhere.
      if (rng.uniform_int(0, 2) == 0) {
        const T u = rng.uniform<T>(T(0), T(1)), v = rng.uniform<T>(T(0), T(1) - u);
        const Vec3<T> n3 = cross(t.back().v1 - t.back().v0, t.back().v2 - t.back().v0);
        p.push_back(point_at_barycentric(t.back(), Vec3<T>{T(1) - u - v, u, v}) +
                    rng.uniform<T>(T(-1), T(1)) * n3);
      } else {
        p.push_back(random_point<T>(rng, random_scale<T>(rng)));
      }
    }
    check_pair<T>(p, t, "point-triangle n=" + std::to_string(n));
  }
}

TYPED_TEST(BatchTest, SegmentSegmentMatchesPerQuery) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (const std::size_t n : kLengths) {
    std::vector<Segment3<T>> a, b;
    for (std::size_t i = 0; i < n; ++i) {
      a.push_back(random_segment<T>(rng, nullptr));
      b.push_back(random_segment<T>(rng, &a.back()));
    }
    check_pair<T>(a, b, "segment-segment n=" + std::to_string(n));
  }
}

TYPED_TEST(BatchTest, SegmentTriangleMatchesPerQuery) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (const std::size_t n : kLengths) {
    std::vector<Segment3<T>> s;
    std::vector<Triangle3<T>> t;
    for (std::size_t i = 0; i < n; ++i) {
      t.push_back(random_triangle<T>(rng));
      const Triangle3<T>& tri = t.back();
      switch (rng.uniform_int(0, 5)) {
        case 0: {  // through the triangle (an exact zero, or a grazing one near an edge)
          const T u = rng.uniform<T>(T(0), T(1)), v = rng.uniform<T>(T(0), T(1) - u);
          const Vec3<T> x = point_at_barycentric(tri, Vec3<T>{T(1) - u - v, u, v});
          const Vec3<T> d = rng.vec<T, 3>(T(-1), T(1));
          s.push_back({x - d, x + d});
          break;
        }
        case 1: {  // parallel to the plane
          const Vec3<T> lift =
              cross(tri.v1 - tri.v0, tri.v2 - tri.v0) * rng.uniform<T>(T(-1), T(1));
          s.push_back({tri.v0 + lift + rng.vec<T, 3>(T(-1), T(1)) * T(0),
                       tri.v1 + lift + (tri.v2 - tri.v0) * rng.uniform<T>(T(-1), T(1))});
          break;
        }
        case 2: {  // an end point on a vertex
          s.push_back({tri.v1, tri.v1 + rng.vec<T, 3>(T(-1), T(1))});
          break;
        }
        default:
          s.push_back(random_segment<T>(rng, nullptr));
          break;
      }
    }
    check_pair<T>(s, t, "segment-triangle n=" + std::to_string(n));
  }
}

TYPED_TEST(BatchTest, PointBoxesMatchPerQuery) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (const std::size_t n : kLengths) {
    std::vector<Vec3<T>> p;
    std::vector<AlignedBox3<T>> ab;
    std::vector<OrientedBox3<T>> ob;
    for (std::size_t i = 0; i < n; ++i) {
      p.push_back(random_point<T>(rng, T(1.5)));
      ab.push_back(random_aabb<T>(rng));
      ob.push_back(random_obb<T>(rng));
    }
    check_pair<T>(p, ab, "point-aabb n=" + std::to_string(n));
    check_pair<T>(p, ob, "point-obb n=" + std::to_string(n));
  }
}

// locus's Vec takes float and double only: a three-component long double vector for the brute
// force oracle below.
struct VL {
  long double x, y, z;
  VL operator+(const VL& o) const { return {x + o.x, y + o.y, z + o.z}; }
  VL operator-(const VL& o) const { return {x - o.x, y - o.y, z - o.z}; }
  friend VL operator*(long double k, const VL& v) { return {k * v.x, k * v.y, k * v.z}; }
  friend long double dot(const VL& u, const VL& v) { return u.x * v.x + u.y * v.y + u.z * v.z; }
};

// The fast lanes are not only equal to the per-query code but right: a generic sample against
// the exact distance computed in long double from the closest pair's definition (a brute-force
// scan of the six boundary features of two segments, which is exact for disjoint segments up to
// the long double rounding).
TYPED_TEST(BatchTest, SegmentSegmentAgreesWithBruteForce) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  using L = long double;
  const auto point_segment = [](const VL& p, const VL& a, const VL& b) {
    const VL d = b - a;
    const L dd = dot(d, d);
    L t = dd > 0 ? dot(p - a, d) / dd : L(0);
    t = t < 0 ? L(0) : (t > 1 ? L(1) : t);
    const VL x = a + t * d - p;
    return dot(x, x);
  };
  const auto to_l = [](const Vec3<T>& v) { return VL{L(v.x), L(v.y), L(v.z)}; };
  std::vector<Segment3<T>> a, b;
  for (int i = 0; i < 2000; ++i) {
    a.push_back({rng.vec<T, 3>(T(-1), T(1)), rng.vec<T, 3>(T(-1), T(1))});
    b.push_back({rng.vec<T, 3>(T(-1), T(1)), rng.vec<T, 3>(T(-1), T(1))});
  }
  std::vector<T> out(a.size());
  sqr_distances(std::span<const Segment3<T>>(a), std::span<const Segment3<T>>(b),
                std::span<T>(out));
  for (std::size_t i = 0; i < a.size(); ++i) {
    const VL p0 = to_l(a[i].p0), p1 = to_l(a[i].p1), q0 = to_l(b[i].p0), q1 = to_l(b[i].p1);
    // Either the segments' interiors have a common perpendicular inside both, or an end point
    // is involved: the minimum over the four end-point queries and the interior solution.
    L best = std::min({point_segment(p0, q0, q1), point_segment(p1, q0, q1),
                       point_segment(q0, p0, p1), point_segment(q1, p0, p1)});
    const VL u = p1 - p0, v = q1 - q0, w = p0 - q0;
    const L A = dot(u, u), B = dot(u, v), C = dot(v, v), D = dot(u, w), E = dot(v, w);
    const L den = A * C - B * B;
    if (den > 1e-12L) {
      const L s = (B * E - C * D) / den, t = (A * E - B * D) / den;
      if (s >= 0 && s <= 1 && t >= 0 && t <= 1) {
        const VL x = p0 + s * u - (q0 + t * v);
        best = std::min(best, dot(x, x));
      }
    }
    EXPECT_NEAR(double(out[i]), double(best), 16 * double(std::numeric_limits<T>::epsilon()))
        << "query " << i;
  }
}
