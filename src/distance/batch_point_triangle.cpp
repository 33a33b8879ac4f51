// SPDX-License-Identifier: BSL-1.0
// Batched point - triangle squared distances (see batch_kernels.hpp).

#include "batch_kernels.hpp"

#include <type_traits>

namespace locus {
namespace {

template <class T, class A, class B>
LOCUS_ALWAYS_INLINE inline void point_triangle_run(const Source<A>& a, const Source<B>& b, T* out,
                                                   std::size_t n) {
  lanes::run<T, 2>(
      a, b, out, n,
      [](const auto& p, const auto& t) LOCUS_ALWAYS_INLINE_LAMBDA {
        const auto pl = point_triangle_lanes<T, std::decay_t<decltype(t)>::kBroadcast>(
            gather3<T>(p, std::identity{}), gather3<T>(t, &Triangle3<T>::v0),
            gather3<T>(t, &Triangle3<T>::v1), gather3<T>(t, &Triangle3<T>::v2));
        return Result<T>{pl.sqr, pl.scalar};
      },
      [](const Vec3<T>& p, const Triangle3<T>& t)
          LOCUS_ALWAYS_INLINE_LAMBDA { return sqr_distance(p, t); });
}

}  // namespace

LOCUS_BATCH_DEFINE(Vec3, Triangle3, float, point_triangle_run)
LOCUS_BATCH_DEFINE(Vec3, Triangle3, double, point_triangle_run)

}  // namespace locus
