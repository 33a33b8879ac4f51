// SPDX-License-Identifier: BSL-1.0
// The batched squared distances of include/locus/distance/batch.hpp. Each kernel evaluates the
// branch-free fast path of one pair's per-query function (the same operations in the same order,
// mirrored lane by lane; see lanes.hpp) for W queries at once, and marks the lanes that path does
// not cover; run() recomputes those with the per-query function. Compiled with -ffp-contract=off
// (CMakeLists.txt) so that no operation is fused and every lane rounds as the scalar code does.

#include "lanes.hpp"

#include <locus/config.hpp>
#include <locus/distance/batch.hpp>
#include <locus/distance/point_aligned_box.hpp>
#include <locus/distance/point_oriented_box.hpp>
#include <locus/distance/point_triangle.hpp>
#include <locus/distance/segment_segment.hpp>
#include <locus/distance/segment_triangle.hpp>

#include <cstddef>
#include <functional>
#include <limits>

namespace locus {
namespace {

using lanes::gather;
using lanes::gather3;
using lanes::Group;
using lanes::M;
using lanes::Result;
using lanes::sel;
using lanes::Source;
using lanes::V;
using lanes::V3;

template <class T>
constexpr T kMin = std::numeric_limits<T>::min();
template <class T>
constexpr T kMax = std::numeric_limits<T>::max();

// ---- point - triangle (detail::point_triangle, the 3D fast path) -------------------------------

template <class T>
struct PointTriangleLanes {
  V3<T> bary;     // barycentric (u, v, w) of the closest point
  V3<T> closest;  // point_at_barycentric(tri, bary)
  V<T> sqr;
  M<T> scalar;  // lanes outside the fast path
};

template <class T>
LOCUS_LANE_INLINE PointTriangleLanes<T> point_triangle_lanes(const V3<T>& p, const V3<T>& v0,
                                                             const V3<T>& v1, const V3<T>& v2) {
  // The origin at the vertex opposite the longest edge (rotation r1: (v1, v2, v0), r2: (v2, v0,
  // v1)).
  const V3<T> d01 = v1 - v0, d02 = v2 - v0, d12 = v2 - v1;
  const V<T> l01 = dot(d01, d01), l02 = dot(d02, d02), l12 = dot(d12, d12);
  const M<T> keep = (l12 >= l01) & (l12 >= l02);
  const M<T> r1 = ~keep & (l02 >= l01), r2 = ~keep & ~(l02 >= l01);
  const V3<T> o = lanes::sel<T>(r1, v1, lanes::sel<T>(r2, v2, v0));
  const V3<T> x = lanes::sel<T>(r1, v2, lanes::sel<T>(r2, v0, v1));
  const V3<T> y = lanes::sel<T>(r1, v0, lanes::sel<T>(r2, v1, v2));
  const V3<T> e0 = x - o, e1 = y - o, e2 = y - x, w0 = p - o, w1 = p - x;
  const V<T> a = dot(e0, e0), b = dot(e0, e1), c = dot(e1, e1), f = dot(e2, e2);
  const V<T> d = dot(e0, w0), e = dot(e1, w0), g = dot(e2, w1);
  const V<T> ac = a * c, det = ac - b * b;
  const M<T> fast =
      (T(16) * det >= ac) & (a >= kMin<T>)&(c >= kMin<T>)&(f >= kMin<T>)&(ac <= kMax<T>)&(
                                f <= kMax<T>)&(((d - d) + (e - e)) + (g - g) == T(0));
  const V<T> sn = c * d - b * e, tn = a * e - b * d;
  const M<T> inside = (sn >= T(0)) & (tn >= T(0)) & (sn + tn <= det);
  const V<T> s = sn / det, t = tn / det;
  // Outside: the nearest of the three edges' clamped projections.
  const V<T> zero = a - a, one = zero + T(1);
  const V<T> l0 = lanes::clamp_minmax<T>(d / a, zero, one);
  const V<T> l1 = lanes::clamp_minmax<T>(e / c, zero, one);
  const V<T> l2 = lanes::clamp_minmax<T>(g / f, zero, one);
  const V3<T> q0v = w0 - l0 * e0, q1v = w0 - l1 * e1, q2v = w1 - l2 * e2;
  const V<T> q0 = dot(q0v, q0v), q1 = dot(q1v, q1v), q2 = dot(q2v, q2v);
  const M<T> m1 = q1 < q0;
  const V<T> q01 = sel<T>(m1, q1, q0);
  const V<T> u = sel<T>(m1, T(1) - l1, T(1) - l0), v = sel<T>(m1, zero, l0);
  const V<T> w = sel<T>(m1, l1, zero);
  const M<T> m2 = q2 < q01;
  V3<T> rb{sel<T>(m2, zero, u), sel<T>(m2, T(1) - l2, v), sel<T>(m2, l2, w)};
  rb = lanes::sel<T>(inside, V3<T>{T(1) - s - t, s, t}, rb);
  const V3<T> bary{sel<T>(r1, rb.z, sel<T>(r2, rb.y, rb.x)),
                   sel<T>(r1, rb.x, sel<T>(r2, rb.z, rb.y)),
                   sel<T>(r1, rb.y, sel<T>(r2, rb.x, rb.z))};
  const V3<T> cp = rb.x * o + rb.y * x + rb.z * y;
  const V3<T> dx = cp - p;
  return {bary, cp, dot(dx, dx), ~fast};
}

template <class T, class A, class B>
LOCUS_LANE_INLINE void point_triangle_run(const Source<A>& a, const Source<B>& b, T* out,
                                          std::size_t n) {
  lanes::run<T>(
      a, b, out, n,
      [](const auto& p, const auto& t) LOCUS_LANE_LAMBDA {
        const auto pl = point_triangle_lanes<T>(
            gather3<T>(p, std::identity{}), gather3<T>(t, &Triangle3<T>::v0),
            gather3<T>(t, &Triangle3<T>::v1), gather3<T>(t, &Triangle3<T>::v2));
        return Result<T>{pl.sqr, pl.scalar};
      },
      [](const Vec3<T>& p, const Triangle3<T>& t) LOCUS_LANE_LAMBDA { return sqr_distance(p, t); });
}

// ---- segment - segment (detail::segment_pair) ------------------------------------------------

template <class T>
struct SegmentLanes {
  V3<T> p0, p1;
};

template <class T>
struct SegmentPairLanes {
  V<T> s, t;  // parameters on the first and the second segment
  V<T> sqr;
  M<T> scalar;
};

/// detail::closest_param for a segment whose |dir|^2 = a is a normal number: the clamped
/// projection, and whether it was finite (otherwise the scalar code takes a rescaling path).
template <class T>
LOCUS_LANE_INLINE V<T> closest_param_lanes(const SegmentLanes<T>& l, const V3<T>& dir, V<T> a,
                                           const V3<T>& p, M<T>& not_finite) {
  const V<T> t = dot(p - l.p0, dir) / a;
  not_finite |= ~lanes::finite<T>(t);
  const V<T> lo = sel<T>(t < T(0), V<T>{}, t);
  return sel<T>(lo > T(1), lanes::splat<T>(T(1)), lo);
}

/// detail::lex_less of two segments (p0 lexicographically, then p1).
template <class T>
LOCUS_LANE_INLINE M<T> lex_less(const V3<T>& a, const V3<T>& b) {
  return (a.x < b.x) | ((a.x == b.x) & ((a.y < b.y) | ((a.y == b.y) & (a.z < b.z))));
}
template <class T>
LOCUS_LANE_INLINE M<T> lex_less(const SegmentLanes<T>& a, const SegmentLanes<T>& b) {
  const M<T> same = (a.p0.x == b.p0.x) & (a.p0.y == b.p0.y) & (a.p0.z == b.p0.z);
  return (same & lex_less<T>(a.p1, b.p1)) | (~same & lex_less<T>(a.p0, b.p0));
}

/// The lanes segment_pair_fast declines (nearly parallel, or an interior minimiser at a small
/// angle): the parameters in the caller's order, and the lanes left to the scalar code. regular:
/// segment_pair_fast's range and finiteness test.
template <class T>
LOCUS_LANE_INLINE SegmentPairLanes<T> segment_pair_rest(const SegmentLanes<T>& x,
                                                        const SegmentLanes<T>& y, M<T> regular) {
  constexpr T tiny = T(64) * eps_v<T>;
  // The rest (nearly parallel, or an interior minimiser at a small angle): detail::linear_linear
  // in the canonical argument order, for input in range (a, c normal, finite projections; other
  // lanes go to the scalar code). Since the fast path declined, linear_linear's only outcomes are
  // the refined interior point (inside and D > 64 eps ac) or the best of every candidate.
  const M<T> swap = lex_less<T>(y, x);
  const SegmentLanes<T> A{lanes::sel<T>(swap, y.p0, x.p0), lanes::sel<T>(swap, y.p1, x.p1)};
  const SegmentLanes<T> B{lanes::sel<T>(swap, x.p0, y.p0), lanes::sel<T>(swap, x.p1, y.p1)};
  const V3<T> dA = A.p1 - A.p0, dB = B.p1 - B.p0, rr = A.p0 - B.p0;
  const V<T> aa = dot(dA, dA), cc = dot(dB, dB);
  const V<T> bb = dot(dA, dB), dd = dot(dA, rr), ee = dot(dB, rr);
  const V<T> DD = lanes::sqr_cross_norm<T>(dA, dB), acc = aa * cc;
  // Lanes linear_linear would take elsewhere: input out of range (it may then reach its KKT
  // branch, or rescale a projection), or a projection that overflows.
  M<T> scalar = ~(regular & (aa <= kMax<T>)&(cc <= kMax<T>)&(acc >= kMin<T>));
  const V<T> s0 = (bb * ee - cc * dd) / DD, t0 = (aa * ee - bb * dd) / DD;
  const M<T> interior = (DD > T(0)) & lanes::finite<T>(s0) & lanes::finite<T>(t0);
  const M<T> inside = (s0 >= T(0)) & (s0 <= T(1)) & (t0 >= T(0)) & (t0 <= T(1));
  M<T> bad{};  // some projection the scalar code would rescale
  const V<T> s0c = lanes::clamp_minmax<T>(s0, V<T>{}, lanes::splat<T>(T(1)));
  const V<T> ti = closest_param_lanes<T>(B, dB, cc, lanes::lerp<T>(A.p0, A.p1, s0c), bad);
  const V<T> si = closest_param_lanes<T>(A, dA, aa, lanes::lerp<T>(B.p0, B.p1, ti), bad);
  bad &= interior;  // the refinement only runs with an interior point
  const V<T> zz{}, oo = lanes::splat<T>(T(1));
  V<T> bs = si, bt = ti;
  // |A(s) - B(t)|^2 as the scalar code evaluates it. At s = 0 or 1 the point lerp(A, s) is the end
  // point itself up to the sign of a zero coordinate, which no square sees: the end points'
  // candidates use the end points directly.
  const auto sqr_gap = [](const V3<T>& u, const V3<T>& v) LOCUS_LANE_LAMBDA {
    const V3<T> dq = u - v;
    return dot(dq, dq);
  };
  const V<T> q_interior = sqr_gap(lanes::lerp<T>(A.p0, A.p1, si), lanes::lerp<T>(B.p0, B.p1, ti));
  V<T> best = sel<T>(interior, q_interior, lanes::splat<T>(std::numeric_limits<T>::infinity()));
  const auto consider = [&](V<T> s, V<T> t, V<T> q) LOCUS_LANE_LAMBDA {
    const M<T> take = q < best;
    best = sel<T>(take, q, best);
    bs = sel<T>(take, s, bs);
    bt = sel<T>(take, t, bt);
  };
  const V<T> t_a0 = closest_param_lanes<T>(B, dB, cc, A.p0, bad);
  consider(zz, t_a0, sqr_gap(A.p0, lanes::lerp<T>(B.p0, B.p1, t_a0)));
  const V<T> t_a1 = closest_param_lanes<T>(B, dB, cc, A.p1, bad);
  consider(oo, t_a1, sqr_gap(A.p1, lanes::lerp<T>(B.p0, B.p1, t_a1)));
  const V<T> s_b0 = closest_param_lanes<T>(A, dA, aa, B.p0, bad);
  consider(s_b0, zz, sqr_gap(lanes::lerp<T>(A.p0, A.p1, s_b0), B.p0));
  const V<T> s_b1 = closest_param_lanes<T>(A, dA, aa, B.p1, bad);
  consider(s_b1, oo, sqr_gap(lanes::lerp<T>(A.p0, A.p1, s_b1), B.p1));
  const M<T> refined = interior & inside & (DD > tiny * acc);
  bs = sel<T>(refined, si, bs);
  bt = sel<T>(refined, ti, bt);
  scalar |= bad | ~lanes::finite<T>(best);
  // Back to the caller's order (the squared distance is symmetric: the chosen candidate's).
  return {sel<T>(swap, bt, bs), sel<T>(swap, bs, bt), sel<T>(refined, q_interior, best), scalar};
}

template <class T>
LOCUS_LANE_INLINE SegmentPairLanes<T> segment_pair_lanes(const SegmentLanes<T>& x,
                                                         const SegmentLanes<T>& y) {
  constexpr T tiny = T(64) * eps_v<T>;
  // detail::segment_pair_fast.
  const V3<T> da = x.p1 - x.p0, db = y.p1 - y.p0, r = x.p0 - y.p0;
  const V<T> a = dot(da, da), b = dot(da, db), c = dot(db, db), d = dot(da, r), e = dot(db, r);
  const V<T> D = lanes::sqr_cross_norm<T>(da, db), ac = a * c;
  const V<T> sn = b * e - c * d, tn = a * e - b * d;
  const M<T> sl = (sn < T(0)), sh = (sn > D), tl = (tn < T(0)), th = (tn > D);
  const M<T> s_out = sl | sh, t_out = tl | th;
  const M<T> regular =
      (a >= kMin<T>) & (c >= kMin<T>) & (ac <= kMax<T>) & ((d - d) + (e - e) == T(0));
  const M<T> fast = regular & (D > tiny * ac) & (s_out | t_out | (T(16) * D >= ac));
  // The parameters of the fast lanes: one exact clamped projection each.
  const auto fast_pair = [&]() LOCUS_LANE_LAMBDA {
    const V<T> zero = a - a, one = zero + T(1);
    const V<T> sc = sel<T>(sh, lanes::splat<T>(T(1)), V<T>{});
    const V<T> tc = sel<T>(th, lanes::splat<T>(T(1)), V<T>{});
    const V<T> gs = (a * sc - b * tc) + d, gt = (c * tc - b * sc) - e;
    const M<T> ds = (sl & (gs < T(0))) | (sh & (gs > T(0)));
    const M<T> dt = (tl & (gt < T(0))) | (th & (gt > T(0)));
    const M<T> move_t = s_out & (~t_out | (dt & ~ds));
    const M<T> move_s = t_out & (~s_out | (ds & ~dt));
    const M<T> pin_s = s_out & ~move_s, pin_t = t_out & ~move_t;
    const V<T> qs = sel<T>(move_s, b * tc - d, sn) / sel<T>(move_s, a, D);
    const V<T> qt = sel<T>(move_t, b * sc + e, tn) / sel<T>(move_t, c, D);
    SegmentPairLanes<T> f;
    f.s = sel<T>(pin_s, sc, lanes::clamp_minmax<T>(qs, zero, one));
    f.t = sel<T>(pin_t, tc, lanes::clamp_minmax<T>(qt, zero, one));
    const V3<T> dq = lanes::lerp<T>(x.p0, x.p1, f.s) - lanes::lerp<T>(y.p0, y.p1, f.t);
    f.sqr = dot(dq, dq);
    f.scalar = M<T>{};
    return f;
  };
  if (lanes::all<T>(fast)) return fast_pair();
  // Some lanes need the rest (all of them, for nearly parallel input); the fast lanes' work is
  // skipped when there are none.
  SegmentPairLanes<T> rest = segment_pair_rest<T>(x, y, regular);
  if (!lanes::any<T>(fast)) return rest;
  const SegmentPairLanes<T> f = fast_pair();
  return {sel<T>(fast, f.s, rest.s), sel<T>(fast, f.t, rest.t), sel<T>(fast, f.sqr, rest.sqr),
          rest.scalar & ~fast};
}

template <class T, class G>
LOCUS_LANE_INLINE SegmentLanes<T> gather_segment(const G& g) {
  return {gather3<T>(g, &Segment3<T>::p0), gather3<T>(g, &Segment3<T>::p1)};
}

template <class T>
LOCUS_LANE_INLINE void segment_segment_run(const Source<Segment3<T>>& a,
                                           const Source<Segment3<T>>& b, T* out, std::size_t n) {
  lanes::run<T>(
      a, b, out, n,
      [](const auto& x, const auto& y) LOCUS_LANE_LAMBDA {
        const SegmentPairLanes<T> r =
            segment_pair_lanes<T>(gather_segment<T>(x), gather_segment<T>(y));
        return Result<T>{r.sqr, r.scalar};
      },
      [](const Segment3<T>& x, const Segment3<T>& y)
          LOCUS_LANE_LAMBDA { return sqr_distance(x, y); });
}

// ---- segment - triangle (detail::linear_triangle_core for a segment) ---------------------------

/// Coordinates for which the orient3d filter below is valid: 0, or a magnitude in [2^-L, 2^H]
/// (double: L = H = 250; float: L = 16, H = 39). Then every nonzero difference of two such
/// coordinates is at least ulp(2^-L), so no product of three differences underflows (the
/// filter's relative error bound holds) and none overflows.
template <class T>
LOCUS_LANE_INLINE M<T> filter_range(const V3<T>& v) {
  constexpr T lo = sizeof(T) == 8 ? T(0x1p-250) : T(0x1p-16);
  constexpr T hi = sizeof(T) == 8 ? T(0x1p250) : T(0x1p39);
  const auto one = [](V<T> x) LOCUS_LANE_LAMBDA {
    const V<T> m = sel<T>(x < T(0), -x, x);
    return (m == T(0)) | ((m >= lo) & (m <= hi));
  };
  return one(v.x) & one(v.y) & one(v.z);
}

/// orient3d(a, b, c, d) (core/predicates.hpp's convention: the sign of det[b - a; c - a; d - a])
/// by Shewchuk's stage-A filter: `certain` lanes have the exact sign of det (input in
/// filter_range); the others are left to the exact predicate.
template <class T>
struct Orient {
  V<T> det;
  M<T> certain;
};
template <class T>
LOCUS_LANE_INLINE Orient<T> orient3d_filter(const V3<T>& a, const V3<T>& b, const V3<T>& c,
                                            const V3<T>& d) {
  const V3<T> u = b - a, v = c - a, w = d - a;
  const V<T> m0 = v.y * w.z, m1 = v.z * w.y, m2 = v.z * w.x, m3 = v.x * w.z;
  const V<T> m4 = v.x * w.y, m5 = v.y * w.x;
  const V<T> det = u.x * (m0 - m1) + u.y * (m2 - m3) + u.z * (m4 - m5);
  const auto abs = [](V<T> x) LOCUS_LANE_LAMBDA { return sel<T>(x < T(0), -x, x); };
  const V<T> permanent = abs(u.x) * (abs(m0) + abs(m1)) + abs(u.y) * (abs(m2) + abs(m3)) +
                         abs(u.z) * (abs(m4) + abs(m5));
  // Shewchuk's bound is (7 + 56 u) u permanent with u = eps / 2; 4 eps is a little larger.
  const V<T> bound = T(4) * eps_v<T> * permanent;
  return {det, (det > bound) | (-det > bound)};
}

template <class T>
LOCUS_LANE_INLINE V<T> max_abs(const V3<T>& v) {
  // core/vec.hpp max_abs (the maximum is exact whatever the order).
  const auto abs = [](V<T> x) LOCUS_LANE_LAMBDA { return sel<T>(x < T(0), -x, x); };
  const V<T> x = abs(v.x), y = abs(v.y), z = abs(v.z);
  const V<T> xy = sel<T>(x < y, y, x);
  return sel<T>(xy < z, z, xy);
}

template <class T>
LOCUS_LANE_INLINE Result<T> segment_triangle_lanes(const SegmentLanes<T>& seg, const V3<T>& v0,
                                                   const V3<T>& v1, const V3<T>& v2) {
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
    // The edges whose constraints the crossing violates, in the scalar order.
    const auto edge = [&](M<T> wanted, const V3<T>& vi, const V3<T>& vj, int i,
                          int j) LOCUS_LANE_LAMBDA {
      if (!lanes::any<T>(wanted & ok & ~end_wins)) return;
      const SegmentPairLanes<T> st = segment_pair_lanes<T>(seg, SegmentLanes<T>{vi, vj});
      scalar |= wanted & ~end_wins & st.scalar;
      const M<T> take = wanted & (~found | (st.sqr < best_sqr));
      best_sqr = sel<T>(take, st.sqr, best_sqr);
      best_t = sel<T>(take, st.s, best_t);
      V<T> b[3] = {zero, zero, zero};
      b[i] = T(1) - st.t;
      b[j] = st.t;
      best_bary = lanes::sel<T>(take, V3<T>{b[0], b[1], b[2]}, best_bary);
      found |= wanted;
    };
    edge(ss < T(0), v0, v2, 0, 2);
    edge(us < T(0), v0, v1, 0, 1);
    edge(ss + us > T(1), v1, v2, 1, 2);
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

template <class T>
LOCUS_LANE_INLINE void segment_triangle_run(const Source<Segment3<T>>& a,
                                            const Source<Triangle3<T>>& b, T* out, std::size_t n) {
  lanes::run<T>(
      a, b, out, n,
      [](const auto& s, const auto& t) LOCUS_LANE_LAMBDA {
        return segment_triangle_lanes<T>(gather_segment<T>(s), gather3<T>(t, &Triangle3<T>::v0),
                                         gather3<T>(t, &Triangle3<T>::v1),
                                         gather3<T>(t, &Triangle3<T>::v2));
      },
      [](const Segment3<T>& s, const Triangle3<T>& t) { return sqr_distance(s, t); });
}

// ---- point - boxes (the per-query functions have no special cases) --------------------------

template <class T>
LOCUS_LANE_INLINE void point_aligned_box_run(const Source<Vec3<T>>& a,
                                             const Source<AlignedBox3<T>>& b, T* out,
                                             std::size_t n) {
  lanes::run<T>(
      a, b, out, n,
      [](const auto& ps, const auto& bs) LOCUS_LANE_LAMBDA {
        const V3<T> p = gather3<T>(ps, std::identity{});
        const V3<T> lo = gather3<T>(bs, &AlignedBox3<T>::min);
        const V3<T> hi = gather3<T>(bs, &AlignedBox3<T>::max);
        // detail::point_aligned_box: the clamped coordinate's excess, squared and summed onto 0.
        const auto excess = [](V<T> x, V<T> l, V<T> h) LOCUS_LANE_LAMBDA {
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
          LOCUS_LANE_LAMBDA { return sqr_distance(p, box); });
}

template <class T>
LOCUS_LANE_INLINE void point_oriented_box_run(const Source<Vec3<T>>& a,
                                              const Source<OrientedBox3<T>>& b, T* out,
                                              std::size_t n) {
  lanes::run<T>(
      a, b, out, n,
      [](const auto& ps, const auto& bs) LOCUS_LANE_LAMBDA {
        const V3<T> p = gather3<T>(ps, std::identity{});
        const V3<T> c = gather3<T>(bs, &OrientedBox3<T>::center);
        const V3<T> ext = gather3<T>(bs, &OrientedBox3<T>::extent);
        V3<T> axis[3];
        for (int k = 0; k < 3; ++k)
          axis[k] = gather3<T>(bs,
                               [k](const OrientedBox3<T>& x)
                                   LOCUS_LANE_LAMBDA -> const Vec3<T>& { return x.axis[k]; });
        // detail::point_oriented_box: per axis the coordinate in the box frame and its excess
        // over the slab (a negative extent acts as 0), squared and summed onto 0.
        const V3<T> d = p - c;
        const V<T> extents[3] = {ext.x, ext.y, ext.z};
        V<T> sqr{};
        for (int k = 0; k < 3; ++k) {
          const V<T> x = dot(d, axis[k]);
          const V<T> e = sel<T>(extents[k] > T(0), extents[k], V<T>{});
          const V<T> ne = -e;
          const V<T> above = sel<T>(x < ne, ne, x);
          const V<T> excess = x - sel<T>(e < above, e, above);
          sqr = sqr + excess * excess;
        }
        V<T> fz = ((V<T>{} + lanes::finite_zero<T>(p)) + lanes::finite_zero<T>(c)) +
                  lanes::finite_zero<T>(ext);
        for (int k = 0; k < 3; ++k) fz = fz + lanes::finite_zero<T>(axis[k]);
        return Result<T>{sqr + fz, M<T>{}};
      },
      [](const Vec3<T>& p, const OrientedBox3<T>& box)
          LOCUS_LANE_LAMBDA { return sqr_distance(p, box); });
}

// ---- the entry points -------------------------------------------------------------------------

template <class A, class B>
struct Sources {
  Source<A> a;
  Source<B> b;
  std::size_t n;
};

template <class A, class B, class T>
Sources<A, B> sources(std::span<const A> a, std::span<const B> b, std::span<T> out) {
  LOCUS_ASSERT(a.size() == b.size() && a.size() == out.size(),
               "sqr_distances: the spans must have the same length");
  std::size_t n = a.size() < b.size() ? a.size() : b.size();
  n = n < out.size() ? n : out.size();
  return {{a.data(), 1}, {b.data(), 1}, n};
}
template <class A, class B, class T>
Sources<A, B> sources(std::span<const A> a, const B& b, std::span<T> out) {
  LOCUS_ASSERT(a.size() == out.size(), "sqr_distances: out must have one value per query");
  const std::size_t n = a.size() < out.size() ? a.size() : out.size();
  return {{a.data(), 1}, {&b, 0}, n};
}
template <class A, class B, class T>
Sources<A, B> sources(const A& a, std::span<const B> b, std::span<T> out) {
  LOCUS_ASSERT(b.size() == out.size(), "sqr_distances: out must have one value per query");
  const std::size_t n = b.size() < out.size() ? b.size() : out.size();
  return {{&a, 0}, {b.data(), 1}, n};
}

// One clone set per pair and scalar type (the target_clones functions are not templates).
#define LOCUS_BATCH_DRIVER(name, run, A, B, T)                                                 \
  LOCUS_LANE_CLONES void name(const Source<A>& a, const Source<B>& b, T* out, std::size_t n) { \
    run<T>(a, b, out, n);                                                                      \
  }
LOCUS_BATCH_DRIVER(point_triangle_f, point_triangle_run, Vec3<float>, Triangle3<float>, float)
LOCUS_BATCH_DRIVER(point_triangle_d, point_triangle_run, Vec3<double>, Triangle3<double>, double)
LOCUS_BATCH_DRIVER(segment_segment_f, segment_segment_run, Segment3<float>, Segment3<float>, float)
LOCUS_BATCH_DRIVER(segment_segment_d, segment_segment_run, Segment3<double>, Segment3<double>,
                   double)
LOCUS_BATCH_DRIVER(point_aligned_box_f, point_aligned_box_run, Vec3<float>, AlignedBox3<float>,
                   float)
LOCUS_BATCH_DRIVER(point_aligned_box_d, point_aligned_box_run, Vec3<double>, AlignedBox3<double>,
                   double)
LOCUS_BATCH_DRIVER(point_oriented_box_f, point_oriented_box_run, Vec3<float>, OrientedBox3<float>,
                   float)
LOCUS_BATCH_DRIVER(point_oriented_box_d, point_oriented_box_run, Vec3<double>, OrientedBox3<double>,
                   double)
LOCUS_BATCH_DRIVER(segment_triangle_f, segment_triangle_run, Segment3<float>, Triangle3<float>,
                   float)
LOCUS_BATCH_DRIVER(segment_triangle_d, segment_triangle_run, Segment3<double>, Triangle3<double>,
                   double)
#undef LOCUS_BATCH_DRIVER

}  // namespace

// Every overload: the three forms (span-span, span-one, one-span) for one pair and scalar type.
#define LOCUS_BATCH_ENTRY(A, B, T, driver)                                                \
  void sqr_distances(std::span<const A<T>> a, std::span<const B<T>> b,                    \
                     std::span<T> out) noexcept {                                         \
    const auto s = sources(a, b, out);                                                    \
    driver(s.a, s.b, out.data(), s.n);                                                    \
  }                                                                                       \
  void sqr_distances(std::span<const A<T>> a, const B<T>& b, std::span<T> out) noexcept { \
    const auto s = sources(a, b, out);                                                    \
    driver(s.a, s.b, out.data(), s.n);                                                    \
  }                                                                                       \
  void sqr_distances(const A<T>& a, std::span<const B<T>> b, std::span<T> out) noexcept { \
    const auto s = sources(a, b, out);                                                    \
    driver(s.a, s.b, out.data(), s.n);                                                    \
  }
LOCUS_BATCH_ENTRY(Vec3, Triangle3, float, point_triangle_f)
LOCUS_BATCH_ENTRY(Vec3, Triangle3, double, point_triangle_d)
LOCUS_BATCH_ENTRY(Segment3, Segment3, float, segment_segment_f)
LOCUS_BATCH_ENTRY(Segment3, Segment3, double, segment_segment_d)
LOCUS_BATCH_ENTRY(Segment3, Triangle3, float, segment_triangle_f)
LOCUS_BATCH_ENTRY(Segment3, Triangle3, double, segment_triangle_d)
LOCUS_BATCH_ENTRY(Vec3, AlignedBox3, float, point_aligned_box_f)
LOCUS_BATCH_ENTRY(Vec3, AlignedBox3, double, point_aligned_box_d)
LOCUS_BATCH_ENTRY(Vec3, OrientedBox3, float, point_oriented_box_f)
LOCUS_BATCH_ENTRY(Vec3, OrientedBox3, double, point_oriented_box_d)
#undef LOCUS_BATCH_ENTRY

}  // namespace locus
