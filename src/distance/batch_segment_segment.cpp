// SPDX-License-Identifier: BSL-1.0
// Batched segment - segment squared distances (see batch_kernels.hpp).

#include "batch_kernels.hpp"

namespace locus {
namespace {

template <Real T>
LOCUS_ALWAYS_INLINE inline void segment_segment_run(const Source<Segment3<T>>& a,
                                                    const Source<Segment3<T>>& b, T* out,
                                                    std::size_t n) {
  lanes::run<T, 2>(
      a, b, out, n,
      [](const auto& x, const auto& y) LOCUS_ALWAYS_INLINE_LAMBDA {
        const SegmentPairLanes<T> r =
            segment_pair_lanes<T>(gather_segment<T>(x), gather_segment<T>(y));
        return Result<T>{r.sqr, r.scalar};
      },
      [](const Segment3<T>& x, const Segment3<T>& y)
          LOCUS_ALWAYS_INLINE_LAMBDA { return sqr_distance(x, y); });
}

}  // namespace

LOCUS_BATCH_DEFINE(Segment3, Segment3, float, segment_segment_run)
LOCUS_BATCH_DEFINE(Segment3, Segment3, double, segment_segment_run)

}  // namespace locus
