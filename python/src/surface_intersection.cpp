// SPDX-License-Identifier: BSL-1.0
// Rays and planes against parametric surfaces: ray_surface_hits (intersection/ray_surface.hpp:
// every hit of each ray) and plane_surface_curves (intersection/plane_surface.hpp: the section
// curves as polylines; plane_surface_hermite: the same curves with tangents and their cubic
// Hermite interpolants). A surface is a control net (rows, cols, 3): a Bézier patch, or with
// knots_u / knots_v a B-spline surface (degrees from the knot counts), and with weights
// (rows, cols) a NURBS surface. Inputs are converted to float64; NaN or infinite values raise
// ValueError, as does an invalid surface.
#include "common.hpp"

#include <locus/intersection/plane_surface.hpp>
#include <locus/intersection/ray_surface.hpp>

#include <string>

namespace locus::python {

namespace {

py::array_t<double> f64(py::handle obj, const char* fn, const char* name) {
  if (obj.is_none()) fail(fn, std::string(name) + " is None");
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(obj);
  if (!a) fail(fn, std::string("cannot convert ") + name + " to float64");
  check_finite(a.data(), static_cast<std::size_t>(a.size()), fn, name);
  return a;
}

/// The surface of the arguments as a NURBS surface (unit weights for Bézier / B-spline).
NurbsSurface<double, 3> surface_of(const char* fn, py::handle control, py::handle knots_u,
                                   py::handle knots_v, py::handle weights) {
  const auto c = f64(control, fn, "control");
  if (c.ndim() != 3 || c.shape(2) != 3 || c.shape(0) < 1 || c.shape(1) < 1)
    fail(fn, "control must have shape (rows, cols, 3)");
  const int rows = static_cast<int>(c.shape(0)), cols = static_cast<int>(c.shape(1));
  NurbsSurface<double, 3> s{rows - 1, cols - 1, rows, cols, {}, {}, {}, {}};
  const double* pc = c.data();
  for (py::ssize_t i = 0; i < c.shape(0) * c.shape(1); ++i)
    s.control.push_back({pc[3 * i], pc[3 * i + 1], pc[3 * i + 2]});
  if (knots_u.is_none() != knots_v.is_none()) fail(fn, "give both knots_u and knots_v or neither");
  if (knots_u.is_none()) {
    s.knots_u = detail::surface3::clamped_knots<double>(rows - 1);
    s.knots_v = detail::surface3::clamped_knots<double>(cols - 1);
  } else {
    const auto ku = f64(knots_u, fn, "knots_u"), kv = f64(knots_v, fn, "knots_v");
    if (ku.ndim() != 1 || kv.ndim() != 1) fail(fn, "knots must be 1-D");
    s.knots_u.assign(ku.data(), ku.data() + ku.size());
    s.knots_v.assign(kv.data(), kv.data() + kv.size());
    s.degree_u = static_cast<int>(ku.size()) - rows - 1;
    s.degree_v = static_cast<int>(kv.size()) - cols - 1;
    if (s.degree_u < 0 || s.degree_v < 0)
      fail(fn, "a knot vector needs rows + degree + 1 (cols + degree + 1) values");
  }
  if (weights.is_none()) {
    s.weights.assign(s.control.size(), 1.0);
  } else {
    const auto w = f64(weights, fn, "weights");
    if (w.ndim() != 2 || w.shape(0) != c.shape(0) || w.shape(1) != c.shape(1))
      fail(fn, "weights must have shape (rows, cols)");
    s.weights.assign(w.data(), w.data() + w.size());
  }
  check_status(validate(s), fn, false);
  return s;
}

}  // namespace

void bind_surface_intersection(py::module_& m) {
  m.def(
      "ray_surface_hits",
      [](py::handle origins, py::handle directions, py::handle control, py::handle knots_u,
         py::handle knots_v, py::handle weights) -> py::object {
        const char* fn = "ray_surface_hits";
        const auto o = f64(origins, fn, "origins"), d = f64(directions, fn, "directions");
        if (o.ndim() != 2 || o.shape(1) != 3 || d.ndim() != 2 || d.shape(1) != 3 ||
            o.shape(0) != d.shape(0))
          fail(fn, "origins and directions must both have shape (n, 3)");
        const NurbsSurface<double, 3> s = surface_of(fn, control, knots_u, knots_v, weights);
        const py::ssize_t n = o.shape(0);
        std::vector<std::int64_t> ray;
        std::vector<double> t, uv, pts, nrm;
        std::vector<char> tan;
        py::array_t<bool> on(n);
        bool* pon = on.mutable_data();
        {
          py::gil_scoped_release nogil;
          for (py::ssize_t i = 0; i < n; ++i) {
            const Ray3<double> r{{o.data()[3 * i], o.data()[3 * i + 1], o.data()[3 * i + 2]},
                                 {d.data()[3 * i], d.data()[3 * i + 1], d.data()[3 * i + 2]}};
            const LinearSurfaceHits<double> h = intersection(r, s);
            pon[i] = h.on_surface;
            for (const auto& x : h.hits) {
              ray.push_back(i);
              t.push_back(x.t);
              uv.insert(uv.end(), {x.uv.x, x.uv.y});
              pts.insert(pts.end(), {x.point.x, x.point.y, x.point.z});
              nrm.insert(nrm.end(), {x.normal.x, x.normal.y, x.normal.z});
              tan.push_back(x.tangent ? 1 : 0);
            }
          }
        }
        const auto m_hits = static_cast<py::ssize_t>(t.size());
        py::array_t<std::int64_t> ray_a(m_hits);
        py::array_t<double> t_a(m_hits), uv_a({m_hits, py::ssize_t(2)}),
            p_a({m_hits, py::ssize_t(3)}), n_a({m_hits, py::ssize_t(3)});
        py::array_t<bool> tan_a(m_hits);
        std::copy(ray.begin(), ray.end(), ray_a.mutable_data());
        std::copy(t.begin(), t.end(), t_a.mutable_data());
        std::copy(uv.begin(), uv.end(), uv_a.mutable_data());
        std::copy(pts.begin(), pts.end(), p_a.mutable_data());
        std::copy(nrm.begin(), nrm.end(), n_a.mutable_data());
        for (py::ssize_t k = 0; k < m_hits; ++k) tan_a.mutable_data()[k] = tan[std::size_t(k)] != 0;
        py::object out = new_result("PatchHits", Status::ok);
        out.attr("ray") = ray_a;
        out.attr("t") = t_a;
        out.attr("uv") = uv_a;
        out.attr("points") = p_a;
        out.attr("normals") = n_a;
        out.attr("tangent") = tan_a;
        out.attr("on_surface") = on;
        return out;
      },
      py::arg("origins"), py::arg("directions"), py::arg("control"),
      py::arg("knots_u") = py::none(), py::arg("knots_v") = py::none(),
      py::arg("weights") = py::none(),
      R"doc(Rays (origins + t directions, t >= 0; (n, 3) each) against a parametric surface:
control (rows, cols, 3) is a Bézier patch, with knots_u / knots_v a B-spline surface, with
weights (rows, cols) a NURBS surface. Returns a PatchHits with one row per hit, grouped by ray
and by increasing t: ray (m,) the ray index, t (m,), uv (m, 2) surface parameters, points
(m, 3), normals (m, 3), tangent (m,), and on_surface (n,) (a piece of the ray lies on the
surface). Bézier hierarchy refinement then Newton (see ray_surface.hpp for the guarantees).)doc");

  m.def(
      "plane_surface_curves",
      [](py::handle normal, double constant, py::handle control, py::handle knots_u,
         py::handle knots_v, py::handle weights, int grid) -> py::object {
        const char* fn = "plane_surface_curves";
        const auto nv = f64(normal, fn, "normal");
        if (nv.size() != 3) fail(fn, "normal must have 3 entries");
        if (!std::isfinite(constant)) fail(fn, "non_finite_input: constant is NaN or infinite");
        if (grid < 1 || grid > 1024) fail(fn, "grid must be in [1, 1024]");
        const NurbsSurface<double, 3> s = surface_of(fn, control, knots_u, knots_v, weights);
        SurfaceCurveOptions opt;
        opt.grid = grid;
        SurfaceCurves<double> r;
        {
          py::gil_scoped_release nogil;
          r = intersection(Plane3<double>{{nv.data()[0], nv.data()[1], nv.data()[2]}, constant}, s,
                           opt);
        }
        check_status(r.status, fn, false);
        py::list points, uv;
        py::array_t<bool> closed(static_cast<py::ssize_t>(r.curves.size()));
        for (std::size_t k = 0; k < r.curves.size(); ++k) {
          const auto& c = r.curves[k];
          const auto len = static_cast<py::ssize_t>(c.points.size());
          py::array_t<double> p({len, py::ssize_t(3)}), q({len, py::ssize_t(2)});
          for (py::ssize_t i = 0; i < len; ++i) {
            const auto si = static_cast<std::size_t>(i);
            for (int e = 0; e < 3; ++e) p.mutable_data()[3 * i + e] = c.points[si][e];
            q.mutable_data()[2 * i] = c.param_b[si].x;
            q.mutable_data()[2 * i + 1] = c.param_b[si].y;
          }
          points.append(p);
          uv.append(q);
          closed.mutable_data()[k] = c.closed;
        }
        py::object out = new_result("PatchCurves", Status::ok);
        out.attr("points") = points;
        out.attr("uv") = uv;
        out.attr("closed") = closed;
        return out;
      },
      py::arg("normal"), py::arg("constant"), py::arg("control"), py::arg("knots_u") = py::none(),
      py::arg("knots_v") = py::none(), py::arg("weights") = py::none(), py::arg("grid") = 16,
      R"doc(The curves where the plane normal . x = constant cuts a parametric surface (control,
knots and weights as in ray_surface_hits): a PatchCurves with points (list of (k, 3) arrays),
uv (list of (k, 2) surface parameters) and closed (bool per curve: a loop, first point not
repeated; else both ends on the domain boundary). grid: cells per Bézier span and direction
(loops smaller than a cell can be missed).)doc");

  m.def(
      "plane_surface_hermite",
      [](py::handle normal, double constant, py::handle control, py::handle knots_u,
         py::handle knots_v, py::handle weights, int grid, py::handle t) -> py::object {
        const char* fn = "plane_surface_hermite";
        const auto nv = f64(normal, fn, "normal");
        if (nv.size() != 3) fail(fn, "normal must have 3 entries");
        if (!std::isfinite(constant)) fail(fn, "non_finite_input: constant is NaN or infinite");
        if (grid < 1 || grid > 1024) fail(fn, "grid must be in [1, 1024]");
        const NurbsSurface<double, 3> s = surface_of(fn, control, knots_u, knots_v, weights);
        std::vector<double> ts;
        if (!t.is_none()) {
          const auto ta = f64(t, fn, "t");
          if (ta.ndim() != 1) fail(fn, "t must be 1-D");
          ts.assign(ta.data(), ta.data() + ta.size());
          for (const double x : ts)
            if (x < 0.0 || x > 1.0) fail(fn, "every t must lie in [0, 1]");
        }
        SurfaceCurveOptions opt;
        opt.grid = grid;
        const Plane3<double> plane{{nv.data()[0], nv.data()[1], nv.data()[2]}, constant};
        SurfaceCurves<double> r;
        std::vector<HermiteSurfaceCurve<double>> hs;
        {
          py::gil_scoped_release nogil;
          r = intersection(plane, s, opt);
          if (r.status == Status::ok)
            for (const auto& c : r.curves) hs.push_back(hermite_curve(plane, s, c));
        }
        check_status(r.status, fn, false);
        for (const auto& h : hs) check_status(h.status, fn, false);
        auto rows = [](const auto& v, int dim) {
          const auto len = static_cast<py::ssize_t>(v.size());
          py::array_t<double> a({len, py::ssize_t(dim)});
          for (py::ssize_t i = 0; i < len; ++i)
            for (int e = 0; e < dim; ++e)
              a.mutable_data()[dim * i + e] = v[static_cast<std::size_t>(i)][e];
          return a;
        };
        py::list points, uv, tangents, uv_tangents, curve_points, curve_uv;
        py::array_t<bool> closed(static_cast<py::ssize_t>(hs.size()));
        const auto nt = static_cast<py::ssize_t>(ts.size());
        for (std::size_t k = 0; k < hs.size(); ++k) {
          const auto& h = hs[k];
          points.append(rows(h.points, 3));
          uv.append(rows(h.params, 2));
          tangents.append(rows(h.tangents, 3));
          uv_tangents.append(rows(h.param_tangents, 2));
          closed.mutable_data()[k] = h.closed;
          const std::size_t segs = segment_count(h);
          const auto ns = static_cast<py::ssize_t>(segs);
          py::array_t<double> cp({ns, nt, py::ssize_t(3)}), cq({ns, nt, py::ssize_t(2)});
          double* pp = cp.mutable_data();
          double* pq = cq.mutable_data();
          for (std::size_t i = 0; i < segs; ++i)
            for (std::size_t j = 0; j < ts.size(); ++j) {
              const HermiteCurvePoint<double> q = point_at(h, i, ts[j]);
              const std::size_t at = i * ts.size() + j;
              for (int e = 0; e < 3; ++e) pp[3 * at + static_cast<std::size_t>(e)] = q.point[e];
              for (int e = 0; e < 2; ++e) pq[2 * at + static_cast<std::size_t>(e)] = q.param[e];
            }
          curve_points.append(cp);
          curve_uv.append(cq);
        }
        py::object out = new_result("PatchHermite", Status::ok);
        out.attr("points") = points;
        out.attr("uv") = uv;
        out.attr("tangents") = tangents;
        out.attr("uv_tangents") = uv_tangents;
        out.attr("closed") = closed;
        out.attr("curve_points") = curve_points;
        out.attr("curve_uv") = curve_uv;
        return out;
      },
      py::arg("normal"), py::arg("constant"), py::arg("control"), py::arg("knots_u") = py::none(),
      py::arg("knots_v") = py::none(), py::arg("weights") = py::none(), py::arg("grid") = 16,
      py::arg("t") = py::none(),
      R"doc(The curves of plane_surface_curves (same arguments) in Hermite form (book section
11.7): a PatchHermite with, per curve, points (k, 3), uv (k, 2), tangents (k, 3: unit, in the
plane, along the point order), uv_tangents (k, 2: (u, v) velocity per unit arc length), closed,
and with t (1-D values in [0, 1]) every cubic Hermite segment i (from point i to i + 1, the last
one closing a loop) evaluated at every t: curve_points (segments, len(t), 3), the 3D
interpolant R(t) (in the plane), and curve_uv (segments, len(t), 2), the parameter-space
interpolant p(t) (S(p(t)) on the surface); empty when t is None.)doc");
}

}  // namespace locus::python
