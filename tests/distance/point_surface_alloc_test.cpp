// SPDX-License-Identifier: BSL-1.0
// distance/point_surface.hpp is noexcept and allocates (piece nets, work heap): a failed
// allocation must end the search with a surface point (unique = false) or the NaN result, never
// escape (std::terminate). Oracle: the same query with memory available; each allocation of the
// query in turn is made to fail by a replaced global operator new.
#include <locus/distance/point_surface.hpp>

#include "distance/harness.hpp"
#include "support/typed.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <new>
#include <vector>

// The replacement pairs malloc with free throughout, which GCC cannot see across the calls.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif

namespace {
// -1: disarmed; k >= 0: the allocation after k more succeeds throws std::bad_alloc.
long g_fail_after = -1;
bool g_failed = false;
}  // namespace

void* operator new(std::size_t n) {
  if (g_fail_after == 0) {
    g_fail_after = -1;
    g_failed = true;
    throw std::bad_alloc();
  }
  if (g_fail_after > 0) --g_fail_after;
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

using namespace locus;

template <class T>
class PointSurfaceAllocTest : public ::testing::Test {};
TYPED_TEST_SUITE(PointSurfaceAllocTest, locus_test::RealTypes);

template <class T, class S>
void expect_survives_every_failed_allocation(const Vec3<T>& p, const S& s) {
  const auto full = distance(p, s);
  ASSERT_TRUE(std::isfinite(full.distance));
  int failures = 0;
  for (long k = 0;; ++k) {
    g_failed = false;
    g_fail_after = k;
    const auto r = distance(p, s);
    g_fail_after = -1;
    if (!g_failed) {  // the query needed fewer than k + 1 allocations: the full answer
      EXPECT_EQ(r.distance, full.distance) << k;
      EXPECT_EQ(r.unique, full.unique) << k;
      break;
    }
    ++failures;
    if (locus_test::dist::is_nan_result(r)) continue;
    // A surface point found before memory ran out: an upper bound, realised at closest[1].
    EXPECT_FALSE(r.unique) << k;
    EXPECT_GE(r.distance, full.distance) << k;
    const Vec3<T> q = point_at(s, r.param_b.x, r.param_b.y);
    EXPECT_EQ(q, r.closest[1]) << k;
    EXPECT_NEAR(r.distance, length(r.closest[1] - p),
                T(8) * std::numeric_limits<T>::epsilon() * (T(1) + r.distance))
        << k;
  }
  EXPECT_GT(failures, 0);
}

TYPED_TEST(PointSurfaceAllocTest, FailedAllocationNeverEscapes) {
  using T = TypeParam;
  const std::vector<T> knots{0, 0, 0, 0, T(0.3), T(0.6), 1, 1, 1, 1};
  BSplineSurface<T, 3> b{3, 3, 6, 6, {}, knots, knots};
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) b.control.push_back({T(i), T(j), T(0.25) * T((i * 7 + j * 3) % 5)});
  expect_survives_every_failed_allocation(Vec3<T>{T(2.2), T(1.7), T(3)}, b);
  expect_survives_every_failed_allocation(Vec3<T>{T(2.2), T(1.7), T(3)}, to_nurbs(b));
  BezierPatch<T, 3> bp{3, 3, {}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) bp.control.push_back({T(i), T(j), T((i + j) % 2)});
  expect_survives_every_failed_allocation(Vec3<T>{T(0.7), T(1.2), T(2)}, bp);
  BezierTriangle<T, 3> bt{2, {}};
  for (int k = 0; k < 6; ++k) bt.control.push_back({T(k % 3), T(k / 3), T(k % 2)});
  expect_survives_every_failed_allocation(Vec3<T>{T(0.5), T(0.4), T(1)}, bt);
}
