// SPDX-License-Identifier: BSL-1.0
#pragma once
// Engine of the intersections with parametric surfaces (rows int3.linear-surface,
// int3.plane-surface, int3.surface-surface; book sections 11.6-11.8). Internal: include a pair
// header. Every surface (BezierPatch, BSplineSurface, NurbsSurface; float or double) is first
// copied into a NurbsSurface<double, 3> (a Bézier patch is the NURBS with knots 0..0 1..1 and unit
// weights, so its parameters stay on [0, 1]^2); the engines run in double and are compiled once
// in src/intersection/surface3.cpp. Derivations: docs/notes/surface_intersection.md.

#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/curves/bezier_surface.hpp>
#include <locus/curves/bspline_surface.hpp>
#include <locus/curves/nurbs_surface.hpp>
#include <locus/intersection/detail/linear3.hpp>

#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace locus {

/// One isolated hit of a line, ray or segment on a parametric surface.
template <Real T>
struct SurfaceHit {
  T t = T(0);            ///< parameter on the linear component (its point_at)
  Vec2<T> uv{};          ///< (u, v) on the surface (its own parameter domain)
  Vec3<T> point{};       ///< the surface point S(u, v)
  Vec3<T> normal{};      ///< unit surface normal at the hit (zero where undefined)
  bool tangent = false;  ///< the component meets the surface tangentially (see the pair header)
};

/// The hits of a linear component on a parametric surface, by increasing t.
template <Real T>
struct LinearSurfaceHits {
  Status status = Status::empty_input;  ///< ok, or why nothing was computed
  std::vector<SurfaceHit<T>> hits;      ///< isolated hits, by increasing t
  bool on_surface = false;  ///< a piece of the component lies on the surface (not listed)
};

/// How an open surface-surface curve ends at its first or last point.
enum class SurfaceCurveEnd : unsigned char {
  boundary,       ///< on a domain boundary of either surface
  tangent_point,  ///< where the surfaces touch (normals parallel): the branch cannot go on
  stalled,        ///< the tracer could not continue (step underflow or point budget)
};

/// One intersection curve as a polyline: points with their parameters on both arguments (a
/// plane has none: param_a empty). A closed curve does not repeat its first point.
template <Real T>
struct SurfaceCurve {
  bool closed = false;
  std::vector<Vec3<T>> points;
  std::vector<Vec2<T>> param_a;  ///< (u, v) on the first argument (empty for a plane)
  std::vector<Vec2<T>> param_b;  ///< (u, v) on the second argument (empty for a plane)
  /// Surface-surface: the surfaces touch along this curve (normals parallel everywhere on it);
  /// its points are solutions of the contact system (see surface_surface.hpp).
  bool tangent = false;
  SurfaceCurveEnd first_end = SurfaceCurveEnd::boundary;  ///< open curves: end at points[0]
  SurfaceCurveEnd last_end = SurfaceCurveEnd::boundary;   ///< open curves: end at points.back()
};

/// An isolated point where two surfaces touch (surface-surface).
template <Real T>
struct SurfaceContact {
  Vec3<T> point{};    ///< on the first surface
  Vec2<T> param_a{};  ///< (u, v) on the first surface
  Vec2<T> param_b{};  ///< (u, v) on the second surface
};

/// A parameter rectangle [lo.x, hi.x] x [lo.y, hi.y].
template <Real T>
struct ParamRect {
  Vec2<T> lo{}, hi{};
};

/// The intersection curves of a plane or surface with a surface.
template <Real T>
struct SurfaceCurves {
  Status status = Status::empty_input;
  std::vector<SurfaceCurve<T>> curves;
  /// Surface-surface only: isolated points of tangential contact.
  std::vector<SurfaceContact<T>> contacts;
  /// Surface-surface only: where the surfaces coincide (share a 2D region), as unions of
  /// subdivision leaves in the parameters of the first (coincident_a) and second surface.
  std::vector<ParamRect<T>> coincident_a, coincident_b;
};

/// Exchanges the roles of the arguments (param_a <-> param_b).
template <Real T>
[[nodiscard]] inline SurfaceCurves<T> swapped(SurfaceCurves<T> r) {
  for (auto& c : r.curves) std::swap(c.param_a, c.param_b);
  for (auto& c : r.contacts) std::swap(c.param_a, c.param_b);
  std::swap(r.coincident_a, r.coincident_b);
  return r;
}

/// Options of the plane-surface and surface-surface curve computations.
struct SurfaceCurveOptions {
  /// Grid cells per Bézier span in each direction (plane-surface) or subdivision leaves per span
  /// for seeds (surface-surface). Curve components that cross no grid edge (tiny loops) can be
  /// missed; raise it for finer features (surface-surface also seeds small loops from the
  /// critical points of the gap, and reports coincident regions to within one leaf).
  int grid = 16;
  /// Tracing step (surface-surface) relative to the larger surface's control-net box diagonal.
  double step = 1.0 / 64.0;
};

namespace detail::surface3 {

using NS = NurbsSurface<double, 3>;
using V = Vec3<double>;

template <class T>
[[nodiscard]] std::vector<double> clamped_knots(int degree) {
  std::vector<double> k(2 * static_cast<std::size_t>(degree + 1), 0.0);
  for (std::size_t i = static_cast<std::size_t>(degree + 1); i < k.size(); ++i) k[i] = 1.0;
  return k;
}

template <class T>
[[nodiscard]] NS as_nurbs(const BezierPatch<T, 3>& p) {
  NS s{p.rows - 1, p.cols - 1, p.rows, p.cols, {}, {}, {}, {}};
  if (p.rows < 1 || p.cols < 1) return s;
  s.control.reserve(p.control.size());
  for (const auto& c : p.control) s.control.push_back(vec_cast<double>(c));
  s.weights.assign(p.control.size(), 1.0);
  s.knots_u = clamped_knots<T>(p.rows - 1);
  s.knots_v = clamped_knots<T>(p.cols - 1);
  return s;
}
template <class T>
[[nodiscard]] NS as_nurbs(const BSplineSurface<T, 3>& p) {
  NS s{p.degree_u, p.degree_v, p.rows, p.cols, {}, {}, {}, {}};
  for (const auto& c : p.control) s.control.push_back(vec_cast<double>(c));
  s.weights.assign(p.control.size(), 1.0);
  for (T k : p.knots_u) s.knots_u.push_back(double(k));
  for (T k : p.knots_v) s.knots_v.push_back(double(k));
  return s;
}
template <class T>
[[nodiscard]] NS as_nurbs(const NurbsSurface<T, 3>& p) {
  NS s{p.degree_u, p.degree_v, p.rows, p.cols, {}, {}, {}, {}};
  for (const auto& c : p.control) s.control.push_back(vec_cast<double>(c));
  for (T w : p.weights) s.weights.push_back(double(w));
  for (T k : p.knots_u) s.knots_u.push_back(double(k));
  for (T k : p.knots_v) s.knots_v.push_back(double(k));
  return s;
}

// Compiled in src/intersection/surface3.cpp.
[[nodiscard]] LinearSurfaceHits<double> linear_hits(const linear3::Lin& l, const NS& s);
[[nodiscard]] SurfaceCurves<double> plane_curves(const V& normal, double constant, const NS& s,
                                                 const SurfaceCurveOptions& opt);
[[nodiscard]] SurfaceCurves<double> surface_curves(const NS& a, const NS& b,
                                                   const SurfaceCurveOptions& opt);

/// Unit tangents of a plane-surface curve at its points (3D and per unit arc length in (u, v)).
struct CurveTangents {
  Status status = Status::empty_input;
  std::vector<V> tangent;
  std::vector<Vec2<double>> param_tangent;
};
[[nodiscard]] CurveTangents plane_curve_tangents(const V& normal, const NS& s,
                                                 const std::vector<V>& points,
                                                 const std::vector<Vec2<double>>& params,
                                                 bool closed);

template <Real T>
[[nodiscard]] LinearSurfaceHits<T> cast(const LinearSurfaceHits<double>& r) {
  LinearSurfaceHits<T> o;
  o.status = r.status;
  o.on_surface = r.on_surface;
  o.hits.reserve(r.hits.size());
  for (const auto& h : r.hits)
    o.hits.push_back({static_cast<T>(h.t), vec_cast<T>(h.uv), vec_cast<T>(h.point),
                      vec_cast<T>(h.normal), h.tangent});
  return o;
}

template <Real T>
[[nodiscard]] SurfaceCurves<T> cast(const SurfaceCurves<double>& r) {
  if constexpr (std::is_same_v<T, double>) {
    return r;
  } else {
    SurfaceCurves<T> o;
    o.status = r.status;
    for (const auto& c : r.curves) {
      SurfaceCurve<T> d;
      d.closed = c.closed;
      for (const auto& p : c.points) d.points.push_back(vec_cast<T>(p));
      for (const auto& p : c.param_a) d.param_a.push_back(vec_cast<T>(p));
      for (const auto& p : c.param_b) d.param_b.push_back(vec_cast<T>(p));
      d.tangent = c.tangent;
      d.first_end = c.first_end;
      d.last_end = c.last_end;
      o.curves.push_back(std::move(d));
    }
    for (const auto& c : r.contacts)
      o.contacts.push_back({vec_cast<T>(c.point), vec_cast<T>(c.param_a), vec_cast<T>(c.param_b)});
    for (const auto& b : r.coincident_a)
      o.coincident_a.push_back({vec_cast<T>(b.lo), vec_cast<T>(b.hi)});
    for (const auto& b : r.coincident_b)
      o.coincident_b.push_back({vec_cast<T>(b.lo), vec_cast<T>(b.hi)});
    return o;
  }
}

}  // namespace detail::surface3
}  // namespace locus
