// SPDX-License-Identifier: BSL-1.0
// Batched 2D segment - segment intersection (include/locus/intersection/segment_segment_batch.hpp):
// segments_fast and the cheap case of proper_crossing (intersection/detail/linear2.hpp) in the
// lanes of one register, the same operations in the same order, so every lane gets the bits of
// the per-pair function; the lanes outside that case are recomputed by it. Compiled with
// -ffp-contract=off (CMake: the batch sources).

#include <locus/config.hpp>
#include <locus/intersection/segment_segment_batch.hpp>

#include <cstddef>

#include "../core/crossing_stages.hpp"
#include "../core/lanes.hpp"

namespace locus {
namespace {

using VD = lanes::V<double>;
using MD = lanes::M<double>;
using Seg = Segment2<double>;
using Out = LinearIntersection2<double>;

struct DetL {
  VD v, perm;
};
/// detail::linear2::det_naive per lane.
LOCUS_ALWAYS_INLINE inline DetL det_naive(VD dx, VD dy, VD ex, VD ey) {
  const VD l = dx * ey, r = dy * ex;
  return {l - r, lanes::abs<double>(l) + lanes::abs<double>(r)};
}
/// detail::linear2::certain per lane.
LOCUS_ALWAYS_INLINE inline MD certain(const DetL& f) {
  return (lanes::abs<double>(f.v) > detail::orient2d_bound_a * f.perm) & (f.perm > 0x1p-900) &
         (f.perm < 0x1p1000);
}
/// The cheap test of detail::linear2::accurate_sides, with its range test (implied where the
/// filter is certain).
LOCUS_ALWAYS_INLINE inline MD cheap(const DetL& f) {
  return (lanes::abs<double>(f.v) >= 0.62 * f.perm) & (f.perm > 0x1p-900) & (f.perm < 0x1p1000);
}
/// detail::linear2::param_accurate per lane.
LOCUS_ALWAYS_INLINE inline MD param_accurate(const DetL& f0, const DetL& f1, double cp, double cv) {
  constexpr double u = 0x1p-53;
  const VD a0 = lanes::abs<double>(f0.v), a1 = lanes::abs<double>(f1.v);
  const VD dd = lanes::abs<double>(f0.v - f1.v);
  const VD inv = 1.0 / dd;
  const VD r0 = a0 * inv, r1 = a1 * inv;
  const VD e0 = (cp * f0.perm + cv * a0) * inv, e1 = (cp * f1.perm + cv * a1) * inv;
  return (r0 * e1 + r1 * e0 + 2.0 * u * e0 * e1 <= 2.99 * (1.0 - u * (e0 + e1))) & (dd >= 0x1p-900);
}
/// The value of detail::turn2d_value_accurate(q0, q1, q0, p) per lane, as src/core/crossing.cpp
/// computes it (its double-double, else triple-length stage: core/crossing_stages.hpp), and ok
/// where that value is accepted by the stage that gives it and every error-free product is exact
/// with Dekker's product as with the FMA (products above 2^-900 or zero, factors below 2^990);
/// elsewhere the per-pair function.
LOCUS_ALWAYS_INLINE inline VD exact_side(VD q0x, VD q0y, VD q1x, VD q1y, VD px, VD py, MD& ok) {
  namespace st = detail::crossing_stages;
  using Ops = st::LaneOps<double>;
  const st::Split<Ops> h = st::split<Ops>(q0x, q0y, q1x, q1y, q0x, q0y, px, py);
  const st::Leading<Ops> lead = st::leading(h);
  const st::Cross<Ops> c = st::cross(h);
  const VD hmax = st::largest_difference(h);
  const st::Value<Ops> dd = st::double_double(h, lead);
  const st::Value<Ops> tl = st::triple(h, lead, c, hmax);
  const auto exact = [](VD x) LOCUS_ALWAYS_INLINE_LAMBDA {
    const VD ax = lanes::abs<double>(x);
    return (ax > 0x1p-900) | (ax == 0.0);
  };
  ok = exact(lead.p) & exact(lead.q) & exact(c.c1) & exact(c.c2) & exact(c.c3) & exact(c.c4) &
       (hmax < 0x1p990) & (dd.ok | tl.ok);
  return lanes::sel<double>(dd.ok, dd.v, tl.v);
}

/// One end point side det[q1 - q0; p - q0] with exact differences (dx, dy = q1 - q0 split):
/// the value of detail::linear2::det_tails (g), and what turn2d_value_dd adds to it.
struct SideSplit {
  VD exh, exl, eyh, eyl, l, r, tail;
  DetL g;
};
LOCUS_ALWAYS_INLINE inline SideSplit side_split(VD dxh, VD dxl, VD dyh, VD dyl, VD px, VD py,
                                                VD q0x, VD q0y) {
  SideSplit t;
  lanes::two_sum<double>(px, -q0x, t.exh, t.exl);
  lanes::two_sum<double>(py, -q0y, t.eyh, t.eyl);
  t.l = dxh * t.eyh, t.r = dyh * t.exh;
  t.tail = (dxh * t.eyl + dxl * t.eyh) - (dyh * t.exl + dyl * t.exh);
  t.g = {(t.l - t.r) + t.tail, lanes::abs<double>(t.l) + lanes::abs<double>(t.r)};
  return t;
}
/// detail::linear2::accurate_sides<true> per lane, for the lanes of need: the values, and the
/// lanes where one of its tiers accepted them (the rest go to the per-pair function). The
/// costlier tiers run only when a lane of need asks for them.
LOCUS_ALWAYS_INLINE inline MD accurate_sides(MD need, const DetL& f0, const DetL& f1, VD q0x,
                                             VD q0y, VD q1x, VD q1y, VD p0x, VD p0y, VD p1x, VD p1y,
                                             VD& v0, VD& v1) {
  const MD naive = (cheap(f0) & cheap(f1)) | param_accurate(f0, f1, 3.01, 1.01);
  v0 = f0.v, v1 = f1.v;
  if (!lanes::any<double>(need & ~naive)) [[likely]]
    return naive;
  VD dxh, dxl, dyh, dyl;
  lanes::two_sum<double>(q1x, -q0x, dxh, dxl);
  lanes::two_sum<double>(q1y, -q0y, dyh, dyl);
  const SideSplit t0 = side_split(dxh, dxl, dyh, dyl, p0x, p0y, q0x, q0y);
  const SideSplit t1 = side_split(dxh, dxl, dyh, dyl, p1x, p1y, q0x, q0y);
  const MD tails = ~naive & param_accurate(t0.g, t1.g, 1.01, 2.01);
  v0 = lanes::sel<double>(tails, t0.g.v, v0);
  v1 = lanes::sel<double>(tails, t1.g.v, v1);
  const MD rest = need & ~naive & ~tails;
  if (!lanes::any<double>(rest)) return naive | tails;
  // turn2d_value_dd(q0, q1, q0, p) is turn2d_value_accurate's value (no FMA in the build).
  MD ok0, ok1;
  const VD dd0 = exact_side(q0x, q0y, q1x, q1y, p0x, p0y, ok0);
  const VD dd1 = exact_side(q0x, q0y, q1x, q1y, p1x, p1y, ok1);
  v0 = lanes::sel<double>(rest, dd0, v0);
  v1 = lanes::sel<double>(rest, dd1, v1);
  return naive | tails | (ok0 & ok1);
}

/// std::clamp(x, lo, hi) per lane: x < lo ? lo : (hi < x ? hi : x).
LOCUS_ALWAYS_INLINE inline VD clamp(VD x, double lo, double hi) {
  return lanes::sel<double>(x < lo, lanes::splat(lo),
                            lanes::sel<double>(hi < x, lanes::splat(hi), x));
}

/// Four pairs, a[0..3] and b[0..3]; the first m of them are written to out.
LOCUS_ALWAYS_INLINE inline void group(const Seg* a, const Seg* b, Out* out, std::size_t m) {
  const std::array<VD, 4> ca = lanes::load_columns4<double>(a, 0);
  const std::array<VD, 4> cb = lanes::load_columns4<double>(b, 0);
  const VD a0x = ca[0], a0y = ca[1], a1x = ca[2], a1y = ca[3];
  const VD b0x = cb[0], b0y = cb[1], b1x = cb[2], b1y = cb[3];
  const VD dax = a1x - a0x, day = a1y - a0y, dbx = b1x - b0x, dby = b1y - b0y;
  const DetL fa0 = det_naive(dbx, dby, a0x - b0x, a0y - b0y);
  const DetL fa1 = det_naive(dbx, dby, a1x - b0x, a1y - b0y);
  const DetL fb0 = det_naive(dax, day, b0x - a0x, b0y - a0y);
  const DetL fb1 = det_naive(dax, day, b1x - a0x, b1y - a0y);
  const MD ua0 = ~certain(fa0), ua1 = ~certain(fa1), ub0 = ~certain(fb0), ub1 = ~certain(fb1);
  const MD sure = ~(ua0 | ua1 | ub0 | ub1);
  // The side values that decide: the filters' where certain, else (detail::linear2::
  // segments_sides) the rounded exact values, for lanes finite, in range and not degenerate
  // (else the per-pair function); a segment whose two sides are both exact values builds with
  // them (Known), else with accurate_sides.
  MD decided = sure, ka{}, kb{};
  VD xa0 = fa0.v, xa1 = fa1.v, xb0 = fb0.v, xb1 = fb1.v;
  if (!lanes::all<double>(sure)) [[unlikely]] {
    const VD big = lanes::sel<double>(lanes::abs<double>(a0x) < lanes::abs<double>(a0y),
                                      lanes::abs<double>(a0y), lanes::abs<double>(a0x));
    VD mx = big;
    for (const VD c : {a1x, a1y, b0x, b0y, b1x, b1y}) {
      const VD ac = lanes::abs<double>(c);
      mx = lanes::sel<double>(mx < ac, ac, mx);
    }
    const MD finite = lanes::finite<double>(a0x) & lanes::finite<double>(a0y) &
                      lanes::finite<double>(a1x) & lanes::finite<double>(a1y) &
                      lanes::finite<double>(b0x) & lanes::finite<double>(b0y) &
                      lanes::finite<double>(b1x) & lanes::finite<double>(b1y);
    const MD in_range = (mx <= 0x1p400) & ((mx == 0.0) | (mx >= 0x1p-400));
    const MD proper = ~((a0x == a1x) & (a0y == a1y)) & ~((b0x == b1x) & (b0y == b1y));
    MD ok = ~sure & finite & in_range & proper;
    MD oa0, oa1, ob0, ob1;
    const VD ea0 = exact_side(b0x, b0y, b1x, b1y, a0x, a0y, oa0);
    const VD ea1 = exact_side(b0x, b0y, b1x, b1y, a1x, a1y, oa1);
    const VD eb0 = exact_side(a0x, a0y, a1x, a1y, b0x, b0y, ob0);
    const VD eb1 = exact_side(a0x, a0y, a1x, a1y, b1x, b1y, ob1);
    ok &= (~ua0 | oa0) & (~ua1 | oa1) & (~ub0 | ob0) & (~ub1 | ob1);
    xa0 = lanes::sel<double>(ua0, ea0, xa0), xa1 = lanes::sel<double>(ua1, ea1, xa1);
    xb0 = lanes::sel<double>(ub0, eb0, xb0), xb1 = lanes::sel<double>(ub1, eb1, xb1);
    decided = sure | ok;
    ka = ok & ua0 & ua1;
    kb = ok & ub0 & ub1;
  }
  const MD sa0 = xa0 > 0.0, sa1 = xa1 > 0.0, sb0 = xb0 > 0.0, sb1 = xb1 > 0.0;
  const MD miss = (sa0 == sa1) | (sb0 == sa0) | (sb1 != sa0);
  const MD hit = decided & ~miss;
  VD va0, va1, vb0, vb1;
  const MD ok_a =
      accurate_sides(hit & ~ka, fa0, fa1, b0x, b0y, b1x, b1y, a0x, a0y, a1x, a1y, va0, va1);
  const MD ok_b =
      accurate_sides(hit & ~kb, fb0, fb1, a0x, a0y, a1x, a1y, b0x, b0y, b1x, b1y, vb0, vb1);
  va0 = lanes::sel<double>(ka, xa0, va0), va1 = lanes::sel<double>(ka, xa1, va1);
  vb0 = lanes::sel<double>(kb, xb0, vb0), vb1 = lanes::sel<double>(kb, xb1, vb1);
  const MD easy = (ka | ok_a) & (kb | ok_b);
  const MD scalar = ~decided | (hit & ~easy);
  // proper_crossing (every lane; only the accepted hits are kept).
  const VD dda = va0 - va1, t = clamp(va0 / dda, 0.0, 1.0);
  const MD from_end = lanes::abs<double>(va1) < lanes::abs<double>(va0);
  const VD s = lanes::sel<double>(from_end, clamp(va1 / dda, -1.0, 0.0), t);
  const VD px = lanes::sel<double>(from_end, a1x, a0x) + s * dax;
  const VD py = lanes::sel<double>(from_end, a1y, a0y) + s * day;
  const VD tb = clamp(vb0 / (vb0 - vb1), 0.0, 1.0);
  // Misses and the per-pair lanes get zeros, as a default Result holds.
  const VD zero{};
  const VD ox = lanes::sel<double>(hit, px, zero), oy = lanes::sel<double>(hit, py, zero);
  const VD ota = lanes::sel<double>(hit, t, zero), otb = lanes::sel<double>(hit, tb, zero);
  for (std::size_t k = 0; k < m; ++k) {
    Out& r = out[k];
    r = Out{};
    r.kind = hit[k] ? Kind::point : Kind::empty;
    r.count = hit[k] ? 1 : 0;
    r.point[0] = Vec2<double>{ox[k], oy[k]};
    r.param_a[0] = ota[k];
    r.param_b[0] = otb[k];
  }
  if (lanes::any<double>(scalar))
    for (std::size_t k = 0; k < m; ++k)
      if (scalar[k]) out[k] = intersection(a[k], b[k]);
}

LOCUS_ALWAYS_INLINE inline void run(const Seg* a, const Seg* b, Out* out, std::size_t n) {
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4) group(a + i, b + i, out + i, 4);
  if (i < n) {
    // The last, partial group reads copies with the last pair repeated.
    Seg ta[4], tb[4];
    for (std::size_t k = 0; k < 4; ++k) {
      const std::size_t j = i + k < n ? i + k : n - 1;
      ta[k] = a[j];
      tb[k] = b[j];
    }
    group(ta, tb, out + i, n - i);
  }
}

LOCUS_LANE_VERSIONS(segments2_run, (const Seg* a, const Seg* b, Out* out, std::size_t n),
                    run(a, b, out, n))

}  // namespace

void intersections(std::span<const Segment2<double>> a, std::span<const Segment2<double>> b,
                   std::span<LinearIntersection2<double>> out) noexcept {
  LOCUS_ASSERT(a.size() == b.size() && a.size() == out.size(),
               "intersections: the spans must have the same length");
  std::size_t n = a.size() < b.size() ? a.size() : b.size();
  n = n < out.size() ? n : out.size();
  if (n == 0) return;
  segments2_run_versions.pick()(a.data(), b.data(), out.data(), n);
}

void intersections(std::span<const Segment2<float>> a, std::span<const Segment2<float>> b,
                   std::span<LinearIntersection2<float>> out) noexcept {
  LOCUS_ASSERT(a.size() == b.size() && a.size() == out.size(),
               "intersections: the spans must have the same length");
  std::size_t n = a.size() < b.size() ? a.size() : b.size();
  n = n < out.size() ? n : out.size();
  for (std::size_t i = 0; i < n; ++i) out[i] = intersection(a[i], b[i]);
}

}  // namespace locus
