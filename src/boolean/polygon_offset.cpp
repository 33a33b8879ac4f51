// SPDX-License-Identifier: BSL-1.0
// Polygon offsetting by raw offset contours resolved with the boolean engine
// (include/locus/boolean/polygon_offset.hpp, docs/notes/polygon_offset.md). Every contour point
// is built in double (exact for float input); each band and join piece is checked to be
// counter-clockwise by exact orient2d before it enters a contour, so that under the positive
// fill rule the contour's winding is the region's plus the number of pieces covering a point.

#include <locus/boolean/polygon_offset.hpp>
#include <locus/core/predicates.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <type_traits>
#include <utility>
#include <vector>

namespace locus {
namespace {

using V = Vec2d;

V left_normal(V u) { return {-u.y, u.x}; }
V right_normal(V u) { return {u.y, -u.x}; }
V unit(V a, V b) {
  const V d{b.x - a.x, b.y - a.y};
  const double l = std::hypot(d.x, d.y);
  return {d.x / l, d.y / l};
}
bool positive(V a, V b, V c) { return orient2d(a, b, c) == Sign::positive; }

struct Builder {
  JoinType join;
  double d;           // |delta| > 0
  double min_cos;     // miter allowed while 1 + cos(theta) >= min_cos
  double chord_step;  // the largest chord angle keeping the gap <= tolerance
  std::vector<Polygon2d> pieces;
  bool overflow = false;    // a piece coordinate left the double range
  bool drop_spokes = true;  // false: every concave spoke kept (the test oracle)

  V along(V p, V dir, double t) {
    const V q{p.x + t * dir.x, p.y + t * dir.y};
    if (!std::isfinite(q.x) || !std::isfinite(q.y)) overflow = true;
    return q;
  }

  /// The star polygon v, fan[0], fan[1], ...: kept only where every fan triangle turns
  /// counter-clockwise (exact), so the piece is simple and counter-clockwise. Returns the kept
  /// fan (without v; empty when the piece covers nothing).
  std::vector<V> keep_fan(V v, const std::vector<V>& fan) {
    std::vector<V> kept;
    for (const V& q : fan) {
      while (!kept.empty() && !positive(v, kept.back(), q)) kept.pop_back();
      kept.push_back(q);
    }
    if (kept.size() < 2) kept.clear();
    return kept;
  }
  void add_fan(V v, const std::vector<V>& fan) {
    const std::vector<V> kept = keep_fan(v, fan);
    if (kept.empty()) return;
    Polygon2d p;
    p.vertices.push_back(v);
    p.vertices.insert(p.vertices.end(), kept.begin(), kept.end());
    pieces.push_back(std::move(p));
  }

  /// The join at corner v between offset directions a1 and a2 (unit), a2 counter-clockwise from
  /// a1 by an angle in (0, pi].
  void add_join(V v, V a1, V a2) { add_fan(v, join_fan(v, a1, a2)); }
  std::vector<V> join_fan(V v, V a1, V a2) {
    const V p1 = along(v, a1, d), p2 = along(v, a2, d);
    const double c = a1.x * a2.x + a1.y * a2.y;
    std::vector<V> fan{p1};
    if (join == JoinType::round) {
      const double theta = std::atan2(std::abs(a1.x * a2.y - a1.y * a2.x), c);
      const double steps = std::ceil(theta / chord_step);
      const int n = steps > 1 ? static_cast<int>(std::min(steps, 1e6)) : 1;
      const V t1 = left_normal(a1);
      for (int k = 1; k < n; ++k) {
        const double phi = theta * k / n;
        const V dir{a1.x * std::cos(phi) + t1.x * std::sin(phi),
                    a1.y * std::cos(phi) + t1.y * std::sin(phi)};
        fan.push_back(along(v, dir, d));
      }
    } else if (join == JoinType::miter && 1 + c >= min_cos && 1 + c > 0) {
      fan.push_back(along(v, {a1.x + a2.x, a1.y + a2.y}, d / (1 + c)));
    } else {  // square: cut at distance d along the bisector, t = d tan(theta / 4)
      const double t =
          d * std::hypot(a2.x - a1.x, a2.y - a1.y) / (2 + std::hypot(a1.x + a2.x, a1.y + a2.y));
      fan.push_back(along(p1, left_normal(a1), t));
      fan.push_back(along(p2, right_normal(a2), t));
    }
    fan.push_back(p2);
    return fan;
  }

  /// The far side (oa, ob) of the band of width d on one side of edge ab (side +1 left, -1
  /// right); false when the band is not a strictly convex quadrilateral (thinner than rounding).
  bool band(V a, V b, int side, V& oa, V& ob) {
    const V u = unit(a, b);
    const V n = side > 0 ? left_normal(u) : right_normal(u);
    oa = along(a, n, d);
    ob = along(b, n, d);
    const V q[4] = {a, b, ob, oa};  // counter-clockwise for the left band, reversed for the right
    for (std::size_t i = 0; i < 4; ++i) {
      const Sign o = orient2d(q[i], q[(i + 1) % 4], q[(i + 2) % 4]);
      if (o != (side > 0 ? Sign::positive : Sign::negative)) return false;
    }
    return true;
  }

  /// Is p in the closed band q (a, b, far b, far a; counter-clockwise for side +1, clockwise
  /// for -1)? Exact.
  static bool in_band(const V (&q)[4], int side, V p) {
    for (std::size_t i = 0; i < 4; ++i)
      if (to_int(orient2d(q[i], q[(i + 1) % 4], p)) * side < 0) return false;
    return true;
  }

  /// The raw offset contour of a closed chain of distinct consecutive points, on one side
  /// (-1: right, the outside of a counter-clockwise ring; +1: left). As a 1-chain it is the ring
  /// plus (right side; left side: minus) the boundaries of its bands and convex-corner join
  /// pieces, so its winding number is the ring's plus (minus) the number of pieces covering a
  /// point (docs/notes/polygon_offset.md). Spike vertices listed in `ends` get the end join
  /// (nullptr: none, a butt end) instead of the join type.
  void add_contour(const std::vector<V>& pts, int side, const std::vector<bool>* ends = nullptr,
                   const JoinType* end_join = nullptr) {
    const std::size_t n = pts.size();
    std::vector<V> c;
    // Appends q, cancelling a step straight back (x, y, x becomes x).
    const auto push = [&c](V q) {
      if (!c.empty() && c.back() == q) return;
      if (c.size() >= 2 && c[c.size() - 2] == q) {
        c.pop_back();
        return;
      }
      c.push_back(q);
    };
    // The band of every edge, then the concave corners whose spoke p1 -> v -> p2 can go: the
    // triangle it cuts off lies in both bands (exact tests on the rounded points), where at
    // least two pieces cover every point, so the positive set is unchanged (the notes,
    // "Dropping spokes", also for several overlapping triangles).
    std::vector<V> far_a(n), far_b(n);
    std::vector<char> has_band(n), drop(n, 0);
    for (std::size_t i = 0; i < n; ++i)
      has_band[i] = band(pts[i], pts[(i + 1) % n], side, far_a[i], far_b[i]) ? 1 : 0;
    if (drop_spokes) {
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t j = (i + 1) % n;
        if (!has_band[i] || !has_band[j]) continue;
        if (to_int(orient2d(pts[i], pts[j], pts[(i + 2) % n])) * side <= 0) continue;
        const V band1[4] = {pts[i], pts[j], far_b[i], far_a[i]};
        const V band2[4] = {pts[j], pts[(j + 1) % n], far_b[j], far_a[j]};
        if (in_band(band1, side, far_a[j]) && in_band(band2, side, far_b[i])) drop[j] = 1;
      }
      // A point in the triangles of k dropped corners lies in the bands of their adjacent
      // edges, at least k + 1 of them while k < n: keep one spoke if every corner qualifies.
      if (std::find(drop.begin(), drop.end(), 0) == drop.end()) drop[0] = 0;
    }
    for (std::size_t i = 0; i < n; ++i) {
      const V a = pts[i], b = pts[(i + 1) % n], next = pts[(i + 2) % n];
      if (!drop[i]) push(a);
      if (has_band[i]) {
        push(far_a[i]);
        push(far_b[i]);
      }
      if (!drop[(i + 1) % n]) push(b);
      const int turn = to_int(orient2d(a, b, next));
      const V u1 = unit(a, b), u2 = unit(b, next);
      const bool spike = turn == 0 && u1.x * u2.x + u1.y * u2.y < 0;
      if (turn * side > 0 && !spike) continue;  // concave on this side: the bands overlap
      const JoinType saved = join;
      if (ends != nullptr && (*ends)[(i + 1) % n]) {
        if (end_join == nullptr) continue;
        join = *end_join;
      }
      std::vector<V> fan = side < 0 ? keep_fan(b, join_fan(b, right_normal(u1), right_normal(u2)))
                                    : keep_fan(b, join_fan(b, left_normal(u2), left_normal(u1)));
      join = saved;
      if (side > 0) std::reverse(fan.begin(), fan.end());
      for (const V& q : fan) push(q);
      push(b);
    }
    // The seam: the contour closes from its last point to its first.
    while (c.size() >= 3) {
      if (c.back() == c.front()) {
        c.pop_back();
      } else if (c[c.size() - 2] == c.front()) {
        c.pop_back();
        c.pop_back();
      } else if (c.back() == c[1]) {
        c.erase(c.begin());
      } else {
        break;
      }
    }
    if (c.size() >= 3) pieces.push_back({std::move(c)});
  }

  /// The caps of an open chain (or the whole shape of a single point).
  void add_caps(const std::vector<V>& pts, EndType end) {
    if (end == EndType::butt) return;
    const JoinType saved = join;
    join = end == EndType::round ? JoinType::round : JoinType::square;
    const std::size_t n = pts.size();
    const V u0 = n > 1 ? unit(pts[0], pts[1]) : V{1, 0};
    const V u1 = n > 1 ? unit(pts[n - 2], pts[n - 1]) : V{1, 0};
    add_join(pts[0], left_normal(u0), right_normal(u0));      // around -u0
    add_join(pts[n - 1], right_normal(u1), left_normal(u1));  // around +u1
    join = saved;
  }
};

template <Real T>
bool finite_rings(const MultiPolygon2<T>& m) {
  for (const auto& p : m) {
    for (const auto& v : p.outer.vertices)
      if (!std::isfinite(v.x) || !std::isfinite(v.y)) return false;
    for (const auto& h : p.holes)
      for (const auto& v : h.vertices)
        if (!std::isfinite(v.x) || !std::isfinite(v.y)) return false;
  }
  return true;
}

template <Real T>
Polygon2d to_double(const Polygon2<T>& p) {
  Polygon2d q;
  q.vertices.reserve(p.vertices.size());
  for (const auto& v : p.vertices) q.vertices.push_back({double(v.x), double(v.y)});
  return q;
}

/// Checks the options and delta; on success fills the builder. Empty message: fine.
template <Real T>
bool setup(T delta, const OffsetOptions& o, Builder& b, OffsetResult<T>& out) {
  if (!std::isfinite(delta)) {
    out.status = Status::non_finite_input;
    out.message = "delta is NaN or infinite";
    return false;
  }
  if (!(o.miter_limit >= 1) || !(o.arc_tolerance >= 0)) {
    out.status = Status::invalid_input;
    out.message = "miter_limit must be >= 1 and arc_tolerance >= 0";
    return false;
  }
  constexpr int max_bits = std::is_same_v<T, float> ? 24 : 40;
  if (o.grid_bits < 0 || o.grid_bits > max_bits) {
    out.status = Status::invalid_input;
    out.message = "grid_bits must be in 1..40 (1..24 for float), or 0";
    return false;
  }
  b.join = o.join;
  b.d = std::abs(static_cast<double>(delta));
  b.min_cos = 2 / (o.miter_limit * o.miter_limit);
  const double tol =
      std::clamp(o.arc_tolerance == 0 ? b.d / 1000 : o.arc_tolerance, std::ldexp(b.d, -20), b.d);
  b.chord_step = 2 * std::acos(1 - tol / b.d);
  return true;
}

/// Runs the boolean in double on the grid T asks for and converts the result to T.
template <Real T>
OffsetResult<T> finish(BooleanOp op, const std::vector<Polygon2d>& subject, const Builder& b,
                       int grid_bits) {
  OffsetResult<T> out;
  if (b.overflow) {
    out.status = Status::non_finite_input;
    out.message = "an offset coordinate overflows";
    return out;
  }
  const std::vector<Polygon2d>& clip = b.pieces;
  BooleanOptions bo;
  bo.fill_rule = FillRule::positive;
  bo.grid_bits = grid_bits != 0 ? grid_bits : (std::is_same_v<T, float> ? 24 : 40);
  BooleanResult<double> r = boolean_op<double>(op, subject, clip, bo);
  out.status = r.status;
  out.message = std::move(r.message);
  out.grid = r.grid;
  if (r.status != Status::ok) return out;
  if constexpr (std::is_same_v<T, double>) {
    out.polygons = std::move(r.polygons);
  } else {
    // Grid points of at most 24 bits below the largest coordinate's power of two: exact floats
    // unless beyond the float range.
    const auto convert = [&](const Polygon2d& p, Polygon2<T>& q) {
      for (const auto& v : p.vertices) {
        const T x = static_cast<T>(v.x), y = static_cast<T>(v.y);
        if (!std::isfinite(x) || !std::isfinite(y)) return false;
        q.vertices.push_back({x, y});
      }
      return true;
    };
    for (const auto& p : r.polygons) {
      PolygonWithHoles2<T> q;
      bool ok = convert(p.outer, q.outer);
      for (const auto& h : p.holes) {
        q.holes.emplace_back();
        ok = ok && convert(h, q.holes.back());
      }
      if (!ok) {
        out.polygons.clear();
        out.status = Status::non_finite_input;
        out.message = "an offset coordinate overflows float";
        return out;
      }
      out.polygons.push_back(std::move(q));
    }
  }
  return out;
}

template <Real T>
OffsetResult<T> offset_impl(const MultiPolygon2<T>& region, T delta, const OffsetOptions& options,
                            bool drop_spokes) {
  OffsetResult<T> out;
  Builder b{};
  if (!setup(delta, options, b, out)) return out;
  b.drop_spokes = drop_spokes;
  if (!finite_rings(region)) {
    out.status = Status::non_finite_input;
    out.message = "a coordinate is NaN or infinite";
    return out;
  }
  // Resolve the region into a valid multipolygon (outer CCW, holes CW: interior on the left).
  MultiPolygon2<double> input;
  for (const auto& p : region) {
    PolygonWithHoles2<double> q{to_double(p.outer), {}};
    for (const auto& h : p.holes) q.holes.push_back(to_double(h));
    input.push_back(std::move(q));
  }
  const int bits =
      options.grid_bits != 0 ? options.grid_bits : (std::is_same_v<T, float> ? 24 : 40);
  BooleanResult<double> resolved = boolean_op<double>(BooleanOp::union_, input, {}, bits);
  if (resolved.status != Status::ok) {
    out.status = resolved.status;
    out.message = std::move(resolved.message);
    return out;
  }
  std::vector<Polygon2d> rings;
  for (auto& p : resolved.polygons) {
    rings.push_back(std::move(p.outer));
    for (auto& h : p.holes) rings.push_back(std::move(h));
  }
  if (delta == 0) return finish<T>(BooleanOp::union_, rings, b, bits);
  // Inflate: contours outside (right of each edge, interior on the left); deflate: inside.
  for (const auto& r : rings) b.add_contour(r.vertices, delta > 0 ? -1 : 1);
  std::vector<Polygon2d> contours = std::move(b.pieces);
  b.pieces.clear();
  return finish<T>(BooleanOp::union_, contours, b, bits);
}

template <Real T>
OffsetResult<T> offset_polylines_impl(std::span<const Polyline<T, 2>> paths, T delta,
                                      const OffsetOptions& options, bool drop_spokes) {
  OffsetResult<T> out;
  Builder b{};
  if (!setup(delta, options, b, out)) return out;
  b.drop_spokes = drop_spokes;
  for (const auto& path : paths)
    for (const auto& v : path.vertices)
      if (!std::isfinite(v.x) || !std::isfinite(v.y)) {
        out.status = Status::non_finite_input;
        out.message = "a coordinate is NaN or infinite";
        return out;
      }
  if (delta == 0) return out;
  for (const auto& path : paths) {
    std::vector<V> pts;
    for (const auto& v : path.vertices) {
      const V p{double(v.x), double(v.y)};
      if (pts.empty() || !(pts.back() == p)) pts.push_back(p);
    }
    bool closed = path.closed;
    if (closed && pts.size() > 1 && pts.front() == pts.back()) pts.pop_back();
    if (pts.empty()) continue;
    if (pts.size() == 1) {
      b.add_caps(pts, options.end);
      continue;
    }
    // A closed path: its right side, then its left (the right side of the reversed loop). An
    // open one: the loop out and back, whose two spikes are the ends.
    std::vector<V> back(pts.rbegin(), pts.rend());
    if (closed) {
      b.add_contour(pts, -1);
      b.add_contour(back, -1);
      continue;
    }
    std::vector<V> loop = pts;
    loop.insert(loop.end(), back.begin() + 1, back.end() - 1);
    std::vector<bool> ends(loop.size(), false);
    ends[0] = ends[pts.size() - 1] = true;
    const JoinType cap = options.end == EndType::round ? JoinType::round : JoinType::square;
    b.add_contour(loop, -1, &ends, options.end == EndType::butt ? nullptr : &cap);
  }
  const int bits =
      options.grid_bits != 0 ? options.grid_bits : (std::is_same_v<T, float> ? 24 : 40);
  std::vector<Polygon2d> pieces = std::move(b.pieces);
  b.pieces.clear();
  return finish<T>(BooleanOp::union_, pieces, b, bits);
}

}  // namespace

template <Real T>
OffsetResult<T> offset(const MultiPolygon2<T>& region, T delta, const OffsetOptions& options) {
  return offset_impl(region, delta, options, true);
}
template <Real T>
OffsetResult<T> offset_polylines(std::span<const Polyline<T, 2>> paths, T delta,
                                 const OffsetOptions& options) {
  return offset_polylines_impl(paths, delta, options, true);
}
namespace detail {
template <Real T>
OffsetResult<T> offset_keeping_spokes(const MultiPolygon2<T>& region, T delta,
                                      const OffsetOptions& options) {
  return offset_impl(region, delta, options, false);
}
template <Real T>
OffsetResult<T> offset_polylines_keeping_spokes(std::span<const Polyline<T, 2>> paths, T delta,
                                                const OffsetOptions& options) {
  return offset_polylines_impl(paths, delta, options, false);
}
}  // namespace detail

#define LOCUS_INSTANTIATE(T)                                                            \
  template OffsetResult<T> offset<T>(const MultiPolygon2<T>&, T, const OffsetOptions&); \
  template OffsetResult<T> offset_polylines<T>(std::span<const Polyline<T, 2>>, T,      \
                                               const OffsetOptions&);                   \
  template OffsetResult<T> detail::offset_keeping_spokes<T>(const MultiPolygon2<T>&, T, \
                                                            const OffsetOptions&);      \
  template OffsetResult<T> detail::offset_polylines_keeping_spokes<T>(                  \
      std::span<const Polyline<T, 2>>, T, const OffsetOptions&);
LOCUS_INSTANTIATE(float)
LOCUS_INSTANTIATE(double)
#undef LOCUS_INSTANTIATE

}  // namespace locus
