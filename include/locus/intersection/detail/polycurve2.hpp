// SPDX-License-Identifier: BSL-1.0
#pragma once
// Internals of the polynomial-curve intersections (line_curve.hpp, ray_curve.hpp,
// segment_curve.hpp, curve_curve.hpp): every Bézier, B-spline or NURBS curve becomes a list of
// rational Bézier pieces in double (homogeneous control points (w x, w y, w)), each covering a
// parameter range [t0, t1] of the original curve; the engine (src/intersection/polycurve2.cpp)
// works on those. Derivations: docs/notes/polycurve.md.

#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/curves/bezier.hpp>
#include <locus/curves/bspline.hpp>
#include <locus/curves/nurbs.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/aligned_box.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace locus {

/// How a linear component or a curve is intersected with a polynomial curve (book 7.3-7.4).
enum class CurveMethod : std::uint8_t {
  algebraic,  ///< roots of the Bernstein polynomial n.(C(t) - P) (line) / subdivision + Newton
  hierarchy,  ///< bounding-box hierarchy refined to small boxes, then Newton (figure 7.3)
  raster,     ///< both drawn on a grid, shared cells refined by Newton (figures 7.4, 7.11)
  resultant,  ///< curve-curve: implicitise one piece (Bezout resultant), roots of the other
              ///< substituted, inversion (book 7.4.1); for a linear component the same as
              ///< algebraic (the line is the implicit curve)
};

/// Options of the curve intersections (see line_curve.hpp for their meaning).
struct CurveHitOptions {
  CurveMethod method = CurveMethod::algebraic;
  double tolerance = 0x1p-20;  ///< leaf box size relative to the scale (hierarchy, curve-curve)
  int raster_cells = 256;      ///< grid cells along the longer side (raster)
  int max_steps = 1 << 18;     ///< subdivision budget (box pairs / nodes): then limit_exceeded
};

/// One common point of a linear component or curve (argument a) and a curve (argument b).
template <Real T>
struct CurveHit2 {
  Vec2<T> point{};   ///< the point (rounded)
  T param_a{};       ///< its parameter on the first argument
  T param_b{};       ///< its parameter on the second argument
  int multiplicity;  ///< 1 crossing, 2 tangency, 3 odd higher contact; 0 end of an overlap
};

/// The common points of a linear component or curve and a polynomial curve, ordered by param_a.
template <Real T>
struct CurveHits2 {
  Status status = Status::empty_input;  ///< ok, empty_input, non_finite_input, invalid_input,
                                        ///< degenerate_input, limit_exceeded
  Kind kind = Kind::empty;              ///< empty, point, points or coincident (an overlap)
  std::vector<CurveHit2<T>> hits;       ///< the points (overlaps: their two ends, mult 0)
};

/// The same answer for the swapped query: parameters exchanged, reordered by the new param_a.
template <Real T>
[[nodiscard]] inline CurveHits2<T> swapped(CurveHits2<T> r) {
  for (CurveHit2<T>& h : r.hits) std::swap(h.param_a, h.param_b);
  std::stable_sort(r.hits.begin(), r.hits.end(), [](const CurveHit2<T>& x, const CurveHit2<T>& y) {
    return x.param_a < y.param_a;
  });
  return r;
}

/// The grid of the raster method (figures 7.4, 7.11): cell (i, j) covers
/// [min.x + i cell, min.x + (i + 1) cell] x [min.y + j cell, ...]; mask bit 1 the first curve
/// passes the cell, bit 2 the second; mask[j * nx + i].
template <Real T>
struct CurveRaster2 {
  Status status = Status::empty_input;
  Vec2<T> min{};
  T cell{};
  int nx = 0;
  int ny = 0;
  std::vector<std::uint8_t> mask;
};

namespace detail::polycurve2 {

struct Piece {
  std::vector<Vec3<double>> h;  // homogeneous control points (w x, w y, w), w > 0
  double t0 = 0.0;              // parameter of the original curve at local u = 0
  double t1 = 1.0;              // ... at u = 1
};

struct Curve {
  Status status = Status::ok;
  std::vector<Piece> pieces;
  double unit = 0x1p-53;  // unit roundoff of the caller's scalar type (the input's precision)
};

/// A linear component origin + s direction, s in [lo, hi].
struct Lin {
  Vec2<double> o;
  Vec2<double> d;
  double lo;
  double hi;
};

template <Real T>
[[nodiscard]] inline Vec3<double> hom(const Vec2<T>& p, double w) noexcept {
  return {w * static_cast<double>(p.x), w * static_cast<double>(p.y), w};
}

template <Real T>
[[nodiscard]] Curve as_curve(const BezierCurve<T, 2>& c) {
  Curve r;
  r.unit = static_cast<double>(eps_v<T>);
  if (c.control.empty()) return {Status::empty_input, {}};
  if (!is_finite(c)) return {Status::non_finite_input, {}};
  Piece p;
  for (const auto& q : c.control) p.h.push_back(hom(q, 1.0));
  r.pieces.push_back(std::move(p));
  return r;
}

template <Real T>
[[nodiscard]] Curve as_curve(const BSplineCurve<T, 2>& c) {
  BSplineCurve<double, 2> d{c.degree, {}, {}};
  for (const auto& q : c.control) d.control.push_back(vec_cast<double>(q));
  for (T k : c.knots) d.knots.push_back(static_cast<double>(k));
  const BezierSegments<double, 2> s = to_bezier(d);
  if (s.status != Status::ok) return {s.status, {}};
  Curve r;
  r.unit = static_cast<double>(eps_v<T>);
  for (std::size_t i = 0; i < s.segments.size(); ++i) {
    Piece p;
    for (const auto& q : s.segments[i].control) p.h.push_back(hom(q, 1.0));
    p.t0 = s.breaks[i];
    p.t1 = s.breaks[i + 1];
    r.pieces.push_back(std::move(p));
  }
  return r;
}

template <Real T>
[[nodiscard]] Curve as_curve(const NurbsCurve<T, 2>& c) {
  const Status st = validate(c);
  if (st != Status::ok) return {st, {}};
  BSplineCurve<double, 3> h{c.degree, {}, {}};
  for (std::size_t i = 0; i < c.control.size(); ++i)
    h.control.push_back(hom(c.control[i], static_cast<double>(c.weights[i])));
  for (T k : c.knots) h.knots.push_back(static_cast<double>(k));
  const BezierSegments<double, 3> s = to_bezier(h);
  if (s.status != Status::ok) return {s.status, {}};
  Curve r;
  r.unit = static_cast<double>(eps_v<T>);
  for (std::size_t i = 0; i < s.segments.size(); ++i) {
    Piece p;
    p.h = s.segments[i].control;
    p.t0 = s.breaks[i];
    p.t1 = s.breaks[i + 1];
    r.pieces.push_back(std::move(p));
  }
  return r;
}

/// The compiled engines (src/intersection/polycurve2.cpp).
CurveHits2<double> linear_curve(const Lin& a, const Curve& b, const CurveHitOptions& opt);
CurveHits2<double> curve_curve(const Curve& a, const Curve& b, const CurveHitOptions& opt);
CurveRaster2<double> raster(const Curve& a, const Curve& b, int cells);
CurveHits2<double> self_curve(const Curve& c, const CurveHitOptions& opt);

template <Real T>
[[nodiscard]] CurveHits2<T> cast(const CurveHits2<double>& r) {
  if constexpr (std::is_same_v<T, double>) {
    return r;
  } else {
    CurveHits2<T> o{r.status, r.kind, {}};
    o.hits.reserve(r.hits.size());
    for (const auto& h : r.hits)
      o.hits.push_back({vec_cast<T>(h.point), static_cast<T>(h.param_a), static_cast<T>(h.param_b),
                        h.multiplicity});
    return o;
  }
}

template <Real T>
[[nodiscard]] CurveRaster2<T> cast(const CurveRaster2<double>& r) {
  if constexpr (std::is_same_v<T, double>) {
    return r;
  } else {
    return {r.status, vec_cast<T>(r.min), static_cast<T>(r.cell), r.nx, r.ny, r.mask};
  }
}

template <class C>
struct CurveScalar;
template <class T>
struct CurveScalar<BezierCurve<T, 2>> {
  using type = T;
};
template <class T>
struct CurveScalar<BSplineCurve<T, 2>> {
  using type = T;
};
template <class T>
struct CurveScalar<NurbsCurve<T, 2>> {
  using type = T;
};

}  // namespace detail::polycurve2

/// A 2D Bézier, B-spline or NURBS curve (float or double).
template <class C>
concept PolyCurve2 = requires {
  typename detail::polycurve2::CurveScalar<C>::type;
};

/// The scalar type of a PolyCurve2.
template <PolyCurve2 C>
using curve_scalar_t = typename detail::polycurve2::CurveScalar<C>::type;

}  // namespace locus
