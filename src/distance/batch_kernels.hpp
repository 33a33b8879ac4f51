// SPDX-License-Identifier: BSL-1.0
#pragma once
// Private to src/distance/batch_*.cpp, the batched squared distances of
// include/locus/distance/batch.hpp: the lane kernels that more than one pair uses (point -
// triangle, segment - segment; the segment - triangle kernel is built from both) and the entry
// points' plumbing. Each kernel evaluates the branch-free fast path of one pair's per-query
// function (the same operations in the same order, mirrored lane by lane; see core/lanes.hpp) for W
// queries at once, and marks the lanes that path does not cover; lanes::run() recomputes those
// with the per-query function. The batch_*.cpp files are compiled with -ffp-contract=off
// (CMakeLists.txt) so that no operation is fused and every lane rounds as the scalar code does.
// One translation unit per pair keeps each compile short and lets them build in parallel.

#include "../core/lanes.hpp"

#include <locus/config.hpp>
#include <locus/distance/batch.hpp>
#include <locus/distance/point_triangle.hpp>
#include <locus/distance/segment_segment.hpp>

#include <cstddef>
#include <functional>
#include <limits>
#include <span>

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

template <Real T>
constexpr T kMin = std::numeric_limits<T>::min();
template <Real T>
constexpr T kMax = std::numeric_limits<T>::max();

// ---- point - triangle (detail::point_triangle, the 3D fast path) -------------------------------

template <Real T>
struct PointTriangleLanes {
  V3<T> bary;     // barycentric (u, v, w) of the closest point
  V3<T> closest;  // point_at_barycentric(tri, bary)
  V<T> sqr;
  M<T> scalar;  // lanes outside the fast path
};

/// detail::point_triangle_fast with the origin o and the other vertices x, y: barycentrics in
/// that order.
template <Real T>
LOCUS_ALWAYS_INLINE inline PointTriangleLanes<T> point_triangle_at(const V3<T>& p, const V3<T>& o,
                                                                   const V3<T>& x, const V3<T>& y) {
  const V3<T> e0 = x - o, e1 = y - o, e2 = y - x, w0 = p - o, w1 = p - x;
  const V<T> a = dot(e0, e0), b = dot(e0, e1), c = dot(e1, e1), f = dot(e2, e2);
  const V<T> d = dot(e0, w0), e = dot(e1, w0), g = dot(e2, w1);
  const V<T> ac = a * c, det = ac - b * b;
  const V<T> sn = c * d - b * e, tn = a * e - b * d;
  const M<T> v01 = (tn < T(0)), v02 = (sn < T(0)), v12 = (sn + tn > det);
  const M<T> inside = (sn >= T(0)) & (tn >= T(0)) & (sn + tn <= det);
  // Outside: the one edge detail::point_triangle_fast projects onto (its choice, lane by lane).
  const M<T> use12 = ~inside & v12 & (~(v01 | v02) | (v01 & ~(d < a)) | (v02 & ~(e < c)));
  const M<T> use02 = ~inside & ~use12 & v02 & (~v01 | ~(d > T(0)));
  const M<T> to_y = use12 | use02;
  // The edge x y's range test counts only where that edge is taken (as in the scalar code).
  const M<T> fast = (T(16) * det >= ac) &
                    (a >= kMin<T>)&(c >= kMin<T>)&(ac >= kMin<T>)&(ac <= kMax<T>)&(
                        (((d - d) + (e - e)) + (sn - sn)) + (tn - tn) == T(0)) &
                    (~use12 | ((f >= kMin<T>)&(f <= kMax<T>)&(g - g == T(0))));
  const V<T> num = sel<T>(use12, g, sel<T>(use02, e, d));
  const V<T> den = sel<T>(use12, f, sel<T>(use02, c, a));
  const V<T> zero = a - a, one = zero + T(1);
  // One division serves s (inside) and the edge parameter (outside).
  const V<T> q = sel<T>(inside, sn, num) / sel<T>(inside, det, den);
  const V<T> s = q, t = tn / det;
  const V<T> l = lanes::clamp_minmax<T>(q, zero, one), m = T(1) - l;
  const V3<T> from = lanes::sel<T>(use12, x, o), to = lanes::sel<T>(to_y, y, x);
  const V3<T> rb_edge{sel<T>(use12, zero, m), sel<T>(use12, m, sel<T>(use02, zero, l)),
                      sel<T>(to_y, l, zero)};
  const V3<T> rb_in{T(1) - s - t, s, t};
  const V3<T> rb = lanes::sel<T>(inside, rb_in, rb_edge);
  const V3<T> cp =
      lanes::sel<T>(inside, rb_in.x * o + rb_in.y * x + rb_in.z * y, m * from + l * to);
  const V3<T> dx = cp - p;
  return {rb, cp, dot(dx, dx), ~fast};
}

/// detail::point_triangle's fast path: the origin at v0 when the angle there is well-shaped (or
/// v1 v2 is the longest edge), else at the vertex opposite the longest edge (rotation r1:
/// (v1, v2, v0), r2: (v2, v0, v1)). kBroadcast: the triangle is the same in every lane and every
/// group (Group::kBroadcast).
template <class T, bool kBroadcast = false>
LOCUS_ALWAYS_INLINE inline PointTriangleLanes<T> point_triangle_lanes(const V3<T>& p,
                                                                      const V3<T>& v0,
                                                                      const V3<T>& v1,
                                                                      const V3<T>& v2) {
  const V3<T> d01 = v1 - v0, d02 = v2 - v0, d12 = v2 - v1;
  const V<T> l01 = dot(d01, d01), l02 = dot(d02, d02), l12 = dot(d12, d12);
  const V<T> b0 = dot(d01, d02), ac0 = l01 * l02;
  const M<T> keep = (T(16) * (ac0 - b0 * b0) >= ac0) | ((l12 >= l01) & (l12 >= l02));
  // A group that needs no rotation (most of them: 95% of random triangles are well-shaped at v0)
  // skips the selects: 18 blends on the way in and 9 on the way out cost every lane a quarter of
  // its time (86 against 115 M queries/s, double, x86-64-v4, bench/distance
  // point_triangle/sqr_distances<double>). The dot products above are the kernel's own a, b, c,
  // f, so the test costs three comparisons. A broadcast triangle instead takes the selects
  // unconditionally: they are then loop-invariant and hoisted out of the driver's loop with the
  // rest of the triangle's work, which a branch would prevent (GCC does not move floating-point
  // operations that may trap out of a conditional block).
  if (!kBroadcast && lanes::all<T>(keep)) return point_triangle_at<T>(p, v0, v1, v2);
  const M<T> r1 = ~keep & (l02 >= l01), r2 = ~keep & ~(l02 >= l01);
  const V3<T> o = lanes::sel<T>(r1, v1, lanes::sel<T>(r2, v2, v0));
  const V3<T> x = lanes::sel<T>(r1, v2, lanes::sel<T>(r2, v0, v1));
  const V3<T> y = lanes::sel<T>(r1, v0, lanes::sel<T>(r2, v1, v2));
  PointTriangleLanes<T> r = point_triangle_at<T>(p, o, x, y);
  const V3<T> rb = r.bary;
  r.bary = {sel<T>(r1, rb.z, sel<T>(r2, rb.y, rb.x)), sel<T>(r1, rb.x, sel<T>(r2, rb.z, rb.y)),
            sel<T>(r1, rb.y, sel<T>(r2, rb.x, rb.z))};
  return r;
}

// ---- segment - segment (detail::segment_pair) ------------------------------------------------

template <Real T>
struct SegmentLanes {
  V3<T> p0, p1;
};

template <Real T>
struct SegmentPairLanes {
  V<T> s, t;  // parameters on the first and the second segment
  V<T> sqr;
  M<T> scalar;
};

/// A segment parameter t clamped to [0, 1] as detail::LinearView::clamp_param does, and whether
/// it was finite (otherwise the scalar code takes a rescaling path).
template <Real T>
LOCUS_ALWAYS_INLINE inline V<T> clamp_param_lanes(V<T> t, M<T>& not_finite) {
  not_finite |= ~lanes::finite<T>(t);
  const V<T> lo = sel<T>(t < T(0), V<T>{}, t);
  return sel<T>(lo > T(1), lanes::splat<T>(T(1)), lo);
}

/// detail::closest_param for a segment whose |dir|^2 = a is a normal number: the clamped
/// projection, and whether it was finite (otherwise the scalar code takes a rescaling path).
template <Real T>
LOCUS_ALWAYS_INLINE inline V<T> closest_param_lanes(const SegmentLanes<T>& l, const V3<T>& dir,
                                                    V<T> a, const V3<T>& p, M<T>& not_finite) {
  return clamp_param_lanes<T>(dot(p - l.p0, dir) / a, not_finite);
}

/// detail::lex_less of two segments (p0 lexicographically, then p1).
template <Real T>
LOCUS_ALWAYS_INLINE inline M<T> lex_less(const V3<T>& a, const V3<T>& b) {
  return (a.x < b.x) | ((a.x == b.x) & ((a.y < b.y) | ((a.y == b.y) & (a.z < b.z))));
}
template <Real T>
LOCUS_ALWAYS_INLINE inline M<T> lex_less(const SegmentLanes<T>& a, const SegmentLanes<T>& b) {
  const M<T> same = (a.p0.x == b.p0.x) & (a.p0.y == b.p0.y) & (a.p0.z == b.p0.z);
  return (same & lex_less<T>(a.p1, b.p1)) | (~same & lex_less<T>(a.p0, b.p0));
}

/// The quantities of segment_pair_fast for segments x, y (caller's order): directions, offset
/// r = x.p0 - y.p0, a = |da|^2, b = da.db, c = |db|^2, d = da.r, e = db.r, D = |da x db|^2.
template <Real T>
struct SegmentPairTerms {
  V3<T> da, db;
  V<T> a, b, c, d, e, D, ac;
};

/// The lanes segment_pair_fast declines (nearly parallel, or an interior minimiser at a small
/// angle): the parameters in the caller's order, and the lanes left to the scalar code. regular:
/// segment_pair_fast's range and finiteness test; fast: the lanes whose result the caller takes
/// from the fast path instead.
template <Real T>
LOCUS_ALWAYS_INLINE inline SegmentPairLanes<T> segment_pair_rest(const SegmentLanes<T>& x,
                                                                 const SegmentLanes<T>& y,
                                                                 const SegmentPairTerms<T>& terms,
                                                                 M<T> regular, M<T> fast) {
  constexpr T tiny = T(64) * eps_v<T>;
  // The rest (nearly parallel, or an interior minimiser at a small angle): detail::linear_linear
  // in the canonical argument order, for input in range (a, c normal, finite projections; other
  // lanes go to the scalar code). Since the fast path declined, linear_linear's only outcomes are
  // the refined interior point (inside and D > 64 eps ac) or the best of every candidate.
  const M<T> swap = lex_less<T>(y, x);
  const SegmentLanes<T> A{lanes::sel<T>(swap, y.p0, x.p0), lanes::sel<T>(swap, y.p1, x.p1)};
  const SegmentLanes<T> B{lanes::sel<T>(swap, x.p0, y.p0), lanes::sel<T>(swap, x.p1, y.p1)};
  // linear_linear's terms in that order are the caller's, exchanged and negated where swapped:
  // dA = db, dB = da, A.p0 - B.p0 = -r (IEEE negation and subtraction are exactly antisymmetric,
  // products commute), so aa = c, cc = a, bb = b, dd = -e, ee = -d, and the squared minors of
  // |dA x dB|^2 are those of D; bit for bit, up to the sign of a zero, which no square sees.
  const V3<T> dA = lanes::sel<T>(swap, terms.db, terms.da),
              dB = lanes::sel<T>(swap, terms.da, terms.db);
  const V<T> aa = sel<T>(swap, terms.c, terms.a), cc = sel<T>(swap, terms.a, terms.c), bb = terms.b;
  const V<T> dd = sel<T>(swap, -terms.e, terms.d), ee = sel<T>(swap, -terms.d, terms.e);
  const V<T> DD = terms.D, acc = terms.ac;
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
  const auto sqr_gap = [](const V3<T>& u, const V3<T>& v) LOCUS_ALWAYS_INLINE_LAMBDA {
    const V3<T> dq = u - v;
    return dot(dq, dq);
  };
  const V<T> q_interior = sqr_gap(lanes::lerp<T>(A.p0, A.p1, si), lanes::lerp<T>(B.p0, B.p1, ti));
  const M<T> refined = interior & inside & (DD > tiny * acc);
  // The end points' candidates only for lanes that take them: on generic input most groups
  // reach this function for one lane whose minimiser is interior at a small angle (refined),
  // and the candidates would double the group's cost. (linear_linear returns the refined point
  // before its candidates' projections, so a refined lane's projections never reach the scalar
  // code's rescaling either.)
  if (!lanes::any<T>(~refined & ~fast & ~scalar)) {
    scalar |= bad;
    return {sel<T>(swap, ti, si), sel<T>(swap, si, ti), q_interior, scalar};
  }
  V<T> best = sel<T>(interior, q_interior, lanes::splat<T>(std::numeric_limits<T>::infinity()));
  const auto consider = [&](V<T> s, V<T> t, V<T> q) LOCUS_ALWAYS_INLINE_LAMBDA {
    const M<T> take = q < best;
    best = sel<T>(take, q, best);
    bs = sel<T>(take, s, bs);
    bt = sel<T>(take, t, bt);
  };
  // A.p0 - B.p0 is the offset in dd and ee: the projections of A.p0 onto B and of B.p0 onto A
  // are their quotients (as above, up to the sign of a zero).
  const V<T> t_a0 = clamp_param_lanes<T>(ee / cc, bad);
  consider(zz, t_a0, sqr_gap(A.p0, lanes::lerp<T>(B.p0, B.p1, t_a0)));
  const V<T> t_a1 = closest_param_lanes<T>(B, dB, cc, A.p1, bad);
  consider(oo, t_a1, sqr_gap(A.p1, lanes::lerp<T>(B.p0, B.p1, t_a1)));
  const V<T> s_b0 = clamp_param_lanes<T>(-dd / aa, bad);
  consider(s_b0, zz, sqr_gap(lanes::lerp<T>(A.p0, A.p1, s_b0), B.p0));
  const V<T> s_b1 = closest_param_lanes<T>(A, dA, aa, B.p1, bad);
  consider(s_b1, oo, sqr_gap(lanes::lerp<T>(A.p0, A.p1, s_b1), B.p1));
  bs = sel<T>(refined, si, bs);
  bt = sel<T>(refined, ti, bt);
  scalar |= bad | ~lanes::finite<T>(best);
  // Back to the caller's order (the squared distance is symmetric: the chosen candidate's).
  return {sel<T>(swap, bt, bs), sel<T>(swap, bs, bt), sel<T>(refined, q_interior, best), scalar};
}

template <Real T>
LOCUS_ALWAYS_INLINE inline SegmentPairLanes<T> segment_pair_lanes(const SegmentLanes<T>& x,
                                                                  const SegmentLanes<T>& y) {
  constexpr T tiny = T(64) * eps_v<T>;
  // detail::segment_pair_fast.
  const V3<T> da = x.p1 - x.p0, db = y.p1 - y.p0, r = x.p0 - y.p0;
  const V<T> a = dot(da, da), b = dot(da, db), c = dot(db, db), d = dot(da, r), e = dot(db, r);
  const V<T> D = lanes::sqr_cross_norm<T>(da, db), ac = a * c;
  const V<T> sn = b * e - c * d, tn = a * e - b * d;
  const M<T> sl = (sn < T(0)), sh = (sn > D), tl = (tn < T(0)), th = (tn > D);
  const M<T> s_out = sl | sh, t_out = tl | th;
  const M<T> regular = (a >= kMin<T>)&(c >= kMin<T>)&(ac <= kMax<T>)&((d - d) + (e - e) == T(0));
  const M<T> fast = regular & (D > tiny * ac) & (s_out | t_out | (T(16) * D >= ac));
  // The parameters of the fast lanes: one exact clamped projection each.
  const auto fast_pair = [&]() LOCUS_ALWAYS_INLINE_LAMBDA {
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
  SegmentPairLanes<T> rest =
      segment_pair_rest<T>(x, y, {da, db, a, b, c, d, e, D, ac}, regular, fast);
  if (!lanes::any<T>(fast)) return rest;
  const SegmentPairLanes<T> f = fast_pair();
  return {sel<T>(fast, f.s, rest.s), sel<T>(fast, f.t, rest.t), sel<T>(fast, f.sqr, rest.sqr),
          rest.scalar & ~fast};
}

template <class T, class G>
LOCUS_ALWAYS_INLINE inline SegmentLanes<T> gather_segment(const G& g) {
  return {gather3<T>(g, &Segment3<T>::p0), gather3<T>(g, &Segment3<T>::p1)};
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

}  // namespace

// Defines sqr_distances for one pair (A, B) and scalar type T in its three forms (span-span,
// span-one, one-span), over run<T>(source_a, source_b, out, n) compiled once per instruction set
// (core/lanes.hpp, LOCUS_LANE_VERSIONS). Used inside namespace locus.
#define LOCUS_BATCH_DEFINE(A, B, T, run)                                                   \
  namespace {                                                                              \
  LOCUS_LANE_VERSIONS(run##_##T,                                                           \
                      (const lanes::Source<A<T>>& a, const lanes::Source<B<T>>& b, T* out, \
                       std::size_t n),                                                     \
                      run<T>(a, b, out, n))                                                \
  void run##_##T(const lanes::Source<A<T>>& a, const lanes::Source<B<T>>& b, T* out,       \
                 std::size_t n) {                                                          \
    run##_##T##_versions.pick()(a, b, out, n);                                             \
  }                                                                                        \
  }                                                                                        \
  void sqr_distances(std::span<const A<T>> a, std::span<const B<T>> b,                     \
                     std::span<T> out) noexcept {                                          \
    const auto s = sources(a, b, out);                                                     \
    run##_##T(s.a, s.b, out.data(), s.n);                                                  \
  }                                                                                        \
  void sqr_distances(std::span<const A<T>> a, const B<T>& b, std::span<T> out) noexcept {  \
    const auto s = sources(a, b, out);                                                     \
    run##_##T(s.a, s.b, out.data(), s.n);                                                  \
  }                                                                                        \
  void sqr_distances(const A<T>& a, std::span<const B<T>> b, std::span<T> out) noexcept {  \
    const auto s = sources(a, b, out);                                                     \
    run##_##T(s.a, s.b, out.data(), s.n);                                                  \
  }

}  // namespace locus
