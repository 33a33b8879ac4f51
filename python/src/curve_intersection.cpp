// SPDX-License-Identifier: BSL-1.0
// Intersections with Bézier / B-spline / NURBS curves (intersection/line_curve.hpp,
// ray_curve.hpp, segment_curve.hpp, curve_curve.hpp): line_curve_hits (a line, ray or segment
// against a curve) and curve_intersections (two curves), by the algebraic (default), hierarchy,
// resultant or raster method, and curve_self_intersections (intersection/curve_self.hpp). A curve
// is its control points ((n, 2)) alone (a Bézier curve), or a dict with "control", and "degree" and
// "knots" (a B-spline), plus "weights" (a NURBS curve). Computed in float64. Invalid curves and NaN
// / infinite input raise ValueError.
#include "common.hpp"

#include <locus/intersection/curve_curve.hpp>
#include <locus/intersection/curve_self.hpp>
#include <locus/intersection/line_curve.hpp>
#include <locus/intersection/ray_curve.hpp>
#include <locus/intersection/segment_curve.hpp>

#include <pybind11/stl.h>

#include <string>
#include <variant>
#include <vector>

namespace locus::python {

namespace {

using AnyCurve = std::variant<BezierCurve2<double>, BSplineCurve2<double>, NurbsCurve2<double>>;

std::vector<Vec2d> points_arg(py::handle obj, const char* fn, const char* name) {
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(obj);
  if (!a || a.ndim() != 2 || a.shape(1) != 2)
    fail(fn, std::string(name) + " must have shape (n, 2)");
  std::vector<Vec2d> p(static_cast<std::size_t>(a.shape(0)));
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = {a.data()[2 * i], a.data()[2 * i + 1]};
  return p;
}

std::vector<double> values_arg(py::handle obj, const char* fn, const char* name) {
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(obj);
  if (!a || a.ndim() != 1) fail(fn, std::string(name) + " must be one-dimensional");
  return {a.data(), a.data() + a.shape(0)};
}

AnyCurve curve_arg(py::handle obj, const char* fn, const char* name) {
  if (!py::isinstance<py::dict>(obj)) return BezierCurve2<double>{points_arg(obj, fn, name)};
  const py::dict d = py::reinterpret_borrow<py::dict>(obj);
  if (!d.contains("control")) fail(fn, std::string(name) + " needs a 'control' entry");
  std::vector<Vec2d> control = points_arg(d["control"], fn, name);
  if (!d.contains("knots")) return BezierCurve2<double>{std::move(control)};
  if (!d.contains("degree")) fail(fn, std::string(name) + " has knots but no 'degree'");
  const int degree = py::cast<int>(d["degree"]);
  std::vector<double> knots = values_arg(d["knots"], fn, "knots");
  if (!d.contains("weights"))
    return BSplineCurve2<double>{degree, std::move(control), std::move(knots)};
  return NurbsCurve2<double>{degree, std::move(control), values_arg(d["weights"], fn, "weights"),
                             std::move(knots)};
}

CurveHitOptions options(const std::string& method, double tolerance, int raster_cells,
                        const char* fn) {
  CurveHitOptions o;
  if (method == "algebraic")
    o.method = CurveMethod::algebraic;
  else if (method == "hierarchy")
    o.method = CurveMethod::hierarchy;
  else if (method == "raster")
    o.method = CurveMethod::raster;
  else if (method == "resultant")
    o.method = CurveMethod::resultant;
  else
    fail(fn, "method must be 'algebraic', 'hierarchy', 'resultant' or 'raster'");
  if (!(tolerance > 0.0 && tolerance < 1.0)) fail(fn, "tolerance must be in (0, 1)");
  if (raster_cells < 1) fail(fn, "raster_cells must be at least 1");
  o.tolerance = tolerance;
  o.raster_cells = raster_cells;
  return o;
}

py::object hits_out(const CurveHits2<double>& r, const char* fn) {
  check_status(r.status, fn);
  py::object out = new_result("CurveHits", r.status);
  const auto k = static_cast<py::ssize_t>(r.hits.size());
  py::array_t<double> pts({k, py::ssize_t(2)}), pa(k), pb(k);
  py::array_t<int> mult(k);
  for (py::ssize_t i = 0; i < k; ++i) {
    const auto& h = r.hits[static_cast<std::size_t>(i)];
    pts.mutable_data()[2 * i] = h.point.x;
    pts.mutable_data()[2 * i + 1] = h.point.y;
    pa.mutable_data()[i] = h.param_a;
    pb.mutable_data()[i] = h.param_b;
    mult.mutable_data()[i] = h.multiplicity;
  }
  out.attr("kind") = std::string(to_string(r.kind));
  out.attr("points") = pts;
  out.attr("param_a") = pa;
  out.attr("param_b") = pb;
  out.attr("multiplicity") = mult;
  return out;
}

Vec2d vec_arg(py::handle obj, const char* fn, const char* name) {
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(obj);
  if (!a || a.ndim() != 1 || a.shape(0) != 2) fail(fn, std::string(name) + " must have shape (2,)");
  return {a.data()[0], a.data()[1]};
}

}  // namespace

void bind_curve_intersection(py::module_& m) {
  m.def(
      "line_curve_hits",
      [](py::handle a, py::handle b, py::handle curve, const std::string& component,
         const std::string& method, double tolerance, int raster_cells) {
        const char* fn = "line_curve_hits";
        const CurveHitOptions o = options(method, tolerance, raster_cells, fn);
        const Vec2d pa = vec_arg(a, fn, "a"), pb = vec_arg(b, fn, "b");
        const AnyCurve c = curve_arg(curve, fn, "curve");
        return std::visit(
            [&](const auto& cv) {
              if (component == "line") return hits_out(intersection(Line2d{pa, pb}, cv, o), fn);
              if (component == "ray") return hits_out(intersection(Ray2d{pa, pb}, cv, o), fn);
              if (component == "segment")
                return hits_out(intersection(Segment2d{pa, pb}, cv, o), fn);
              fail(fn, "component must be 'line', 'ray' or 'segment'");
            },
            c);
      },
      py::arg("a"), py::arg("b"), py::arg("curve"), py::arg("component") = "line",
      py::arg("method") = "algebraic", py::arg("tolerance") = 0x1p-20,
      py::arg("raster_cells") = 256,
      "Common points of a line / ray (a = origin, b = direction) or segment (a = p0, b = p1) and "
      "a curve ((n, 2) Bezier control points, or a dict with control, degree, knots[, weights]): "
      "CurveHits (kind, points, param_a on the component, param_b on the curve, multiplicity "
      "1 crossing / 2 tangency / 3 odd contact / 0 overlap end), ordered by param_a.");
  m.def(
      "curve_intersections",
      [](py::handle a, py::handle b, const std::string& method, double tolerance,
         int raster_cells) {
        const char* fn = "curve_intersections";
        const CurveHitOptions o = options(method, tolerance, raster_cells, fn);
        const AnyCurve ca = curve_arg(a, fn, "a"), cb = curve_arg(b, fn, "b");
        return std::visit(
            [&](const auto& x, const auto& y) { return hits_out(intersection(x, y, o), fn); }, ca,
            cb);
      },
      py::arg("a"), py::arg("b"), py::arg("method") = "algebraic", py::arg("tolerance") = 0x1p-20,
      py::arg("raster_cells") = 256,
      "Common points of two curves (each (n, 2) Bezier control points, or a dict with control, "
      "degree, knots[, weights]) by method 'algebraic', 'hierarchy', 'resultant' (implicitise "
      "one, book 7.4.1) or 'raster': CurveHits ordered by param_a; kind 'coincident' when they "
      "share a stretch, whose two ends come as consecutive hits of multiplicity 0.");
  m.def(
      "curve_self_intersections",
      [](py::handle c, const std::string& method, double tolerance, int raster_cells) {
        const char* fn = "curve_self_intersections";
        const CurveHitOptions o = options(method, tolerance, raster_cells, fn);
        const AnyCurve cv = curve_arg(c, fn, "curve");
        return std::visit([&](const auto& x) { return hits_out(self_intersection(x, o), fn); }, cv);
      },
      py::arg("curve"), py::arg("method") = "algebraic", py::arg("tolerance") = 0x1p-20,
      py::arg("raster_cells") = 256,
      "Double points of one curve ((n, 2) Bezier control points, or a dict with control, degree, "
      "knots[, weights]): CurveHits with param_a < param_b the two parameters of each point, "
      "multiplicity 1 crossing / 2 touching; segment joints, cusps and the closing point of a "
      "closed curve are not reported.");
}

}  // namespace locus::python
