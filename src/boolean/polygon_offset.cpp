// SPDX-License-Identifier: BSL-1.0
// Polygon offsetting by bands and join pieces resolved with the boolean engine
// (include/locus/boolean/polygon_offset.hpp, docs/notes/polygon_offset.md). Every piece is built
// in double (exact for float input) and checked to be a counter-clockwise star around its
// corner by exact orient2d, so that under the positive fill rule no piece can subtract area.

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
  bool overflow = false;  // a piece coordinate left the double range

  V along(V p, V dir, double t) {
    const V q{p.x + t * dir.x, p.y + t * dir.y};
    if (!std::isfinite(q.x) || !std::isfinite(q.y)) overflow = true;
    return q;
  }

  /// The star polygon v, fan[0], fan[1], ...: kept only where every fan triangle turns
  /// counter-clockwise (exact), so the piece is simple and counter-clockwise.
  void add_fan(V v, const std::vector<V>& fan) {
    Polygon2d p;
    p.vertices.push_back(v);
    for (const V& q : fan) {
      while (p.vertices.size() >= 2 && !positive(v, p.vertices.back(), q)) p.vertices.pop_back();
      p.vertices.push_back(q);
    }
    if (p.vertices.size() >= 3) pieces.push_back(std::move(p));
  }

  /// The join at corner v between offset directions a1 and a2 (unit), a2 counter-clockwise from
  /// a1 by an angle in (0, pi].
  void add_join(V v, V a1, V a2) {
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
    add_fan(v, fan);
  }

  /// The band of width d on one side of edge ab (side +1 left, -1 right), counter-clockwise.
  void add_band(V a, V b, V u, int side) {
    const V n = side > 0 ? left_normal(u) : right_normal(u);
    Polygon2d p;
    if (side > 0)
      p.vertices = {a, b, along(b, n, d), along(a, n, d)};
    else
      p.vertices = {a, along(a, n, d), along(b, n, d), b};
    const auto& q = p.vertices;
    for (std::size_t i = 0; i < 4; ++i)
      if (!positive(q[i], q[(i + 1) % 4], q[(i + 2) % 4])) return;  // thinner than rounding
    pieces.push_back(std::move(p));
  }

  /// Bands on one side of a chain of distinct consecutive points, and joins where that side is
  /// convex (a spike counts as convex on both sides).
  void add_side(const std::vector<V>& pts, bool closed, int side) {
    const std::size_t n = pts.size();
    const std::size_t edges = closed ? n : n - 1;
    for (std::size_t i = 0; i < edges; ++i) {
      const V a = pts[i], b = pts[(i + 1) % n];
      add_band(a, b, unit(a, b), side);
    }
    for (std::size_t i = closed ? 0 : 1; i < (closed ? n : n - 1); ++i) {
      const V prev = pts[(i + n - 1) % n], v = pts[i], next = pts[(i + 1) % n];
      const int turn = to_int(orient2d(prev, v, next));
      const V u1 = unit(prev, v), u2 = unit(v, next);
      const bool spike = turn == 0 && u1.x * u2.x + u1.y * u2.y < 0;
      if (turn * side > 0 && !spike) continue;  // concave on this side: the bands overlap
      if (side < 0)
        add_join(v, right_normal(u1), right_normal(u2));
      else
        add_join(v, left_normal(u2), left_normal(u1));
    }
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

}  // namespace

template <Real T>
OffsetResult<T> offset(const MultiPolygon2<T>& region, T delta, const OffsetOptions& options) {
  OffsetResult<T> out;
  Builder b{};
  if (!setup(delta, options, b, out)) return out;
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
  if (delta != 0) {
    // Inflate: bands outside (right of each edge); deflate: inside (left).
    const int side = delta > 0 ? -1 : 1;
    for (const auto& r : rings) b.add_side(r.vertices, true, side);
  }
  return finish<T>(delta < 0 ? BooleanOp::difference : BooleanOp::union_, rings, b, bits);
}

template <Real T>
OffsetResult<T> offset_polylines(std::span<const Polyline<T, 2>> paths, T delta,
                                 const OffsetOptions& options) {
  OffsetResult<T> out;
  Builder b{};
  if (!setup(delta, options, b, out)) return out;
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
    if (pts.size() == 1) closed = false;
    b.add_side(pts, closed, 1);
    b.add_side(pts, closed, -1);
    if (!closed) b.add_caps(pts, options.end);
  }
  const int bits =
      options.grid_bits != 0 ? options.grid_bits : (std::is_same_v<T, float> ? 24 : 40);
  std::vector<Polygon2d> pieces = std::move(b.pieces);
  b.pieces.clear();
  return finish<T>(BooleanOp::union_, pieces, b, bits);
}

#define LOCUS_INSTANTIATE(T)                                                            \
  template OffsetResult<T> offset<T>(const MultiPolygon2<T>&, T, const OffsetOptions&); \
  template OffsetResult<T> offset_polylines<T>(std::span<const Polyline<T, 2>>, T,      \
                                               const OffsetOptions&);
LOCUS_INSTANTIATE(float)
LOCUS_INSTANTIATE(double)
#undef LOCUS_INSTANTIATE

}  // namespace locus
