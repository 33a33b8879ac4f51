// SPDX-License-Identifier: BSL-1.0
// Batched point - aligned box and point - oriented box squared distances (see batch_kernels.hpp).

#include "batch_kernels.hpp"

#include <locus/distance/point_aligned_box.hpp>
#include <locus/distance/point_oriented_box.hpp>

namespace locus {
namespace {

// ---- point - boxes (the per-query functions have no special cases) --------------------------

template <Real T>
LOCUS_ALWAYS_INLINE inline void point_aligned_box_run(const Source<Vec3<T>>& a,
                                                      const Source<AlignedBox3<T>>& b, T* out,
                                                      std::size_t n) {
  lanes::run<T, 2>(
      a, b, out, n,
      [](const auto& ps, const auto& bs) LOCUS_ALWAYS_INLINE_LAMBDA {
        const V3<T> p = gather3<T>(ps, std::identity{});
        const V3<T> lo = gather3<T>(bs, &AlignedBox3<T>::min);
        const V3<T> hi = gather3<T>(bs, &AlignedBox3<T>::max);
        // detail::point_aligned_box: the clamped coordinate's excess, squared and summed onto 0.
        const auto excess = [](V<T> x, V<T> l, V<T> h) LOCUS_ALWAYS_INLINE_LAMBDA {
          const V<T> above = sel<T>(x < l, l, x);
          const V<T> e = x - sel<T>(h < above, h, above);
          return e * e;
        };
        const V<T> sqr = ((V<T>{} + excess(p.x, lo.x, hi.x)) + excess(p.y, lo.y, hi.y)) +
                         excess(p.z, lo.z, hi.z);
        const V<T> fz = ((V<T>{} + lanes::finite_zero<T>(p)) + lanes::finite_zero<T>(lo)) +
                        lanes::finite_zero<T>(hi);
        const M<T> empty = (hi.x < lo.x) | (hi.y < lo.y) | (hi.z < lo.z);
        const V<T> nan = lanes::splat<T>(std::numeric_limits<T>::quiet_NaN());
        return Result<T>{sel<T>(empty, nan, sqr + fz), M<T>{}};
      },
      [](const Vec3<T>& p, const AlignedBox3<T>& box)
          LOCUS_ALWAYS_INLINE_LAMBDA { return sqr_distance(p, box); });
}

template <Real T>
LOCUS_ALWAYS_INLINE inline void point_oriented_box_run(const Source<Vec3<T>>& a,
                                                       const Source<OrientedBox3<T>>& b, T* out,
                                                       std::size_t n) {
  lanes::run<T, 2>(
      a, b, out, n,
      [](const auto& ps, const auto& bs) LOCUS_ALWAYS_INLINE_LAMBDA {
        const V3<T> p = gather3<T>(ps, std::identity{});
        const V3<T> c = gather3<T>(bs, &OrientedBox3<T>::center);
        const V3<T> ext = gather3<T>(bs, &OrientedBox3<T>::extent);
        V3<T> axis[3];
        for (int k = 0; k < 3; ++k)
          axis[k] = gather3<T>(
              bs, [k](const OrientedBox3<T>& x) LOCUS_ALWAYS_INLINE_LAMBDA -> const Vec3<T>& {
                return x.axis[k];
              });
        // detail::point_oriented_box: per axis the coordinate in the box frame and its excess
        // over the slab (a negative extent acts as 0), squared and summed onto 0.
        const V3<T> d = p - c;
        const V<T> extents[3] = {ext.x, ext.y, ext.z};
        V<T> sqr{}, fz{};
        for (int k = 0; k < 3; ++k) {
          const V<T> x = dot(d, axis[k]);
          const V<T> e = sel<T>(extents[k] > T(0), extents[k], V<T>{});
          const V<T> ne = -e;
          const V<T> above = sel<T>(x < ne, ne, x);
          const V<T> excess = x - sel<T>(e < above, e, above);
          sqr = sqr + excess * excess;
          fz = fz + x * T(0);  // PointOrientedBoxCore::finite_zero
        }
        fz = fz + lanes::finite_zero<T>(ext);
        return Result<T>{sqr + fz, M<T>{}};
      },
      [](const Vec3<T>& p, const OrientedBox3<T>& box)
          LOCUS_ALWAYS_INLINE_LAMBDA { return sqr_distance(p, box); });
}

}  // namespace

LOCUS_BATCH_DEFINE(Vec3, AlignedBox3, float, point_aligned_box_run)
LOCUS_BATCH_DEFINE(Vec3, AlignedBox3, double, point_aligned_box_run)
LOCUS_BATCH_DEFINE(Vec3, OrientedBox3, float, point_oriented_box_run)
LOCUS_BATCH_DEFINE(Vec3, OrientedBox3, double, point_oriented_box_run)

}  // namespace locus
