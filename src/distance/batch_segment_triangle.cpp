// SPDX-License-Identifier: BSL-1.0
// Batched segment - triangle squared distances (see batch_kernels.hpp).

#include "batch_kernels.hpp"

#include <locus/core/detail/predicate_filters.hpp>
#include <locus/distance/segment_triangle.hpp>

namespace locus {
namespace {

// ---- segment - triangle (detail::linear_triangle_core for a segment) ---------------------------

/// Coordinates for which the orient3d filter below is valid: 0, or a magnitude in [2^-L, 2^H]
/// (double: L = H = 250; float: L = 16, H = 30). Then every nonzero difference of two such
/// coordinates is at least ulp(2^-L), so no product of three differences underflows (the
/// filter's relative error bound holds) and none overflows. The range lies inside the one where
/// detail::linear_triangle solves without rescaling (detail/rescale.hpp,
/// outside_product_range), so that the lanes accepted here are solved as the scalar code does.
template <Real T>
LOCUS_ALWAYS_INLINE inline M<T> filter_range(const V3<T>& v) {
  constexpr T lo = sizeof(T) == 8 ? T(0x1p-250) : T(0x1p-16);
  constexpr T hi = sizeof(T) == 8 ? T(0x1p250) : T(0x1p30);
  const auto one = [](V<T> x) LOCUS_ALWAYS_INLINE_LAMBDA {
    const V<T> m = lanes::abs<T>(x);
    return (m == T(0)) | ((m >= lo) & (m <= hi));
  };
  return one(v.x) & one(v.y) & one(v.z);
}

/// orient3d(a, b, c, d) (core/predicates.hpp's convention: the sign of det[b - a; c - a; d - a])
/// by core's stage-A filter on lanes (detail::det3_stage_a, the scalar predicate's expression and
/// bound for T's unit roundoff): `certain` lanes have the exact sign of det (input in
/// filter_range); the others are left to the exact predicate.
template <Real T>
struct Orient {
  V<T> det;
  M<T> certain;
};
template <Real T>
LOCUS_ALWAYS_INLINE inline Orient<T> orient3d_filter(const V3<T>& a, const V3<T>& b, const V3<T>& c,
                                                     const V3<T>& d) {
  const detail::StageA<V<T>> f = detail::det3_stage_a<T>(
      b - a, c - a, d - a, [](V<T> x) LOCUS_ALWAYS_INLINE_LAMBDA { return lanes::abs<T>(x); });
  return {f.det, (f.det > f.bound) | (-f.det > f.bound)};
}

template <Real T>
LOCUS_ALWAYS_INLINE inline V<T> max_abs(const V3<T>& v) {
  // core/vec.hpp max_abs (the maximum is exact whatever the order).
  const V<T> x = lanes::abs<T>(v.x), y = lanes::abs<T>(v.y), z = lanes::abs<T>(v.z);
  const V<T> xy = sel<T>(x < y, y, x);
  return sel<T>(xy < z, z, xy);
}

template <Real T>
LOCUS_ALWAYS_INLINE inline Result<T> segment_triangle_lanes(const SegmentLanes<T>& seg,
                                                            const V3<T>& v0, const V3<T>& v1,
                                                            const V3<T>& v2) {
  constexpr T eps = eps_v<T>;
  const V<T> zero{}, one = lanes::splat<T>(T(1));
  // Exact meeting test (detail::segment_meets_triangle) where the filter is certain: the two end
  // points strictly on one side of the plane (meets = 0), or on opposite sides and the three
  // edge orientations decide.
  M<T> ok = filter_range<T>(seg.p0) & filter_range<T>(seg.p1) & filter_range<T>(v0) &
            filter_range<T>(v1) & filter_range<T>(v2);
  const Orient<T> op = orient3d_filter<T>(v0, v1, v2, seg.p0);
  const Orient<T> oq = orient3d_filter<T>(v0, v1, v2, seg.p1);
  ok &= op.certain & oq.certain;
  const M<T> same_side = (op.det > T(0)) == (oq.det > T(0));
  M<T> meets{};
  if (!lanes::all<T>(same_side | ~ok)) {
    const Orient<T> oa = orient3d_filter<T>(seg.p0, seg.p1, v0, v1);
    const Orient<T> ob = orient3d_filter<T>(seg.p0, seg.p1, v1, v2);
    const Orient<T> oc = orient3d_filter<T>(seg.p0, seg.p1, v2, v0);
    ok &= same_side | (oa.certain & ob.certain & oc.certain);
    const M<T> pos = (oa.det > T(0)) | (ob.det > T(0)) | (oc.det > T(0));
    const M<T> neg = (oa.det < T(0)) | (ob.det < T(0)) | (oc.det < T(0));
    meets = ~same_side & ~(pos & neg);
  }

  // detail::linear_triangle: the crossing of the segment's line with the plane.
  const V3<T> dir = seg.p1 - seg.p0;
  ok &= max_abs<T>(dir) > T(0);  // a zero-length segment is a point query
  const V3<T> e0 = v1 - v0, e1 = v2 - v0;
  const V3<T> n{e0.y * e1.z - e0.z * e1.y, e0.z * e1.x - e0.x * e1.z, e0.x * e1.y - e0.y * e1.x};
  const V<T> a = dot(e0, e0), c = dot(e1, e1), nn = dot(n, n), dd = dot(dir, dir);
  const V<T> dn = dot(n, dir);
  ok &= nn > T(64) * eps * a * c;  // not flat
  const V3<T> w = seg.p0 - v0;
  const V3<T> m{dir.y * w.z - dir.z * w.y, dir.z * w.x - dir.x * w.z, dir.x * w.y - dir.y * w.x};
  const V<T> ts = -dot(n, w) / dn, ss = dot(e1, m) / dn, us = -dot(e0, m) / dn;
  ok &= lanes::finite<T>(ts) & lanes::finite<T>(ss) & lanes::finite<T>(us);
  const M<T> in_t = (ts >= T(0)) & (ts <= T(1));
  const M<T> in_tri = (ss >= T(0)) & (us >= T(0)) & (ss + us <= T(1));
  const M<T> sharp = (T(16) * dn * dn >= nn * dd) & (T(16) * nn >= a * c);
  // The two outcomes computed here: the crossing itself (the segment meets the triangle there),
  // or the KKT candidates of a segment that does not meet it. Everything else is the scalar
  // code's (every candidate).
  const M<T> crossing = in_t & in_tri & meets & sharp;
  const M<T> kkt = ~(in_t & in_tri) & ~meets & (T(64) * eps * nn * dd < dn * dn);
  ok &= crossing | kkt;

  V<T> t = ts;
  V3<T> bary{T(1) - (ss + us), ss, us};
  if (lanes::any<T>(kkt & ok)) {
    // The end beyond the crossing: its point-triangle pair is optimal outright when moving into
    // the segment does not approach the triangle.
    const M<T> before = ts<T(0), after = ts> T(1);
    const V3<T> end = lanes::sel<T>(before, seg.p0, seg.p1);
    const PointTriangleLanes<T> pt = point_triangle_lanes<T>(end, v0, v1, v2);
    const M<T> has_end = before | after;
    const V<T> slope = dot(dir, end - pt.closest);
    const M<T> end_wins = has_end & ((before & (slope >= T(0))) | (after & (slope <= T(0))));
    M<T> scalar = has_end & pt.scalar;
    V<T> best_sqr = sel<T>(has_end, pt.sqr, lanes::splat<T>(std::numeric_limits<T>::infinity()));
    M<T> found = has_end;
    V<T> best_t = sel<T>(before, zero, one);
    V3<T> best_bary = pt.bary;
    // The edges whose constraints the crossing violates, offered in the scalar order (v0 v2 when
    // ss < 0, v0 v1 when us < 0, v1 v2 when ss + us > 1). At most two are violated (ss < 0 and
    // us < 0 give ss + us < 1), so each lane's first and second violated edge take one
    // segment-segment evaluation each, with the edge's vertices selected per lane: two
    // evaluations per group instead of one per edge that some lane wants (three in most groups).
    // An edge (i, j) is told by i0 (i = 0, else 1) and j2 (j = 2, else 1).
    const auto edge = [&](M<T> wanted, M<T> i0, M<T> j2) LOCUS_ALWAYS_INLINE_LAMBDA {
      if (!lanes::any<T>(wanted & ok & ~end_wins)) return;
      const V3<T> vi = lanes::sel<T>(i0, v0, v1), vj = lanes::sel<T>(j2, v2, v1);
      const SegmentPairLanes<T> st = segment_pair_lanes<T>(seg, SegmentLanes<T>{vi, vj});
      scalar |= wanted & ~end_wins & st.scalar;
      const M<T> take = wanted & (~found | (st.sqr < best_sqr));
      best_sqr = sel<T>(take, st.sqr, best_sqr);
      best_t = sel<T>(take, st.s, best_t);
      const V<T> u = T(1) - st.t;
      const V3<T> b{sel<T>(i0, u, zero), sel<T>(i0, sel<T>(j2, zero, st.t), u),
                    sel<T>(j2, st.t, zero)};
      best_bary = lanes::sel<T>(take, b, best_bary);
      found |= wanted;
    };
    const M<T> w02 = (ss < T(0)), w01 = (us < T(0)), w12 = (ss + us > T(1));
    edge(w02 | w01 | w12, w02 | w01, w02 | ~w01);  // the first: (0 2), else (0 1), else (1 2)
    const M<T> both = w02 & w01;
    edge(both | ((w02 | w01) & w12), both, ~both);  // the second: (0 1), else (1 2)
    // end_wins lanes keep the end's pair (it was offered first and the edges were skipped).
    best_t = sel<T>(end_wins, sel<T>(before, zero, one), best_t);
    best_bary = lanes::sel<T>(end_wins, pt.bary, best_bary);
    ok &= ~(kkt & scalar);
    t = sel<T>(kkt, best_t, t);
    bary = lanes::sel<T>(kkt, best_bary, bary);
  }
  // detail::linear_triangle_core: the pair from the parameters; a meeting pair that agrees to
  // 32 ulps of the coordinates' magnitude is the contact itself (distance exactly 0).
  const V3<T> on_line = lanes::lerp<T>(seg.p0, seg.p1, t);
  const V3<T> on_tri = bary.x * v0 + bary.y * v1 + bary.z * v2;
  const V3<T> gap = on_line - on_tri;
  const V<T> ma = max_abs<T>(v0), mb = max_abs<T>(v1), mc = max_abs<T>(v2);
  const V<T> md = max_abs<T>(on_line);
  const V<T> ab = sel<T>(ma > mb, ma, mb), cd = sel<T>(mc > md, mc, md);
  const V<T> scale = sel<T>(ab > cd, ab, cd);
  const M<T> contact = meets & (max_abs<T>(gap) <= T(32) * eps * scale);
  return {sel<T>(contact, zero, dot(gap, gap)), ~ok};
}

template <Real T>
LOCUS_ALWAYS_INLINE inline void segment_triangle_run(const Source<Segment3<T>>& a,
                                                     const Source<Triangle3<T>>& b, T* out,
                                                     std::size_t n) {
  lanes::run<T>(
      a, b, out, n,
      [](const auto& s, const auto& t) LOCUS_ALWAYS_INLINE_LAMBDA {
        return segment_triangle_lanes<T>(gather_segment<T>(s), gather3<T>(t, &Triangle3<T>::v0),
                                         gather3<T>(t, &Triangle3<T>::v1),
                                         gather3<T>(t, &Triangle3<T>::v2));
      },
      [](const Segment3<T>& s, const Triangle3<T>& t) { return sqr_distance(s, t); });
}

}  // namespace

LOCUS_BATCH_DEFINE(Segment3, Triangle3, float, segment_triangle_run)
LOCUS_BATCH_DEFINE(Segment3, Triangle3, double, segment_triangle_run)

}  // namespace locus
