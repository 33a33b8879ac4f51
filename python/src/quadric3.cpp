// SPDX-License-Identifier: BSL-1.0
// Rays against curved surfaces over arrays: ray_quadric_hits (intersection/ray_quadric.hpp: exact
// counts and tangencies for the quadric as given) and ray_torus_hits (intersection/ray_torus.hpp:
// quartic roots with (u, v) and normals). Inputs are converted to float64; NaN or infinite
// values raise ValueError.
#include "common.hpp"

#include <locus/intersection/ray_quadric.hpp>
#include <locus/intersection/ray_torus.hpp>

#include <limits>
#include <string>

namespace locus::python {

namespace {

py::array_t<double> f64(py::handle obj, const char* fn, const char* name,
                        std::vector<py::ssize_t> shape, const char* shape_text) {
  if (obj.is_none()) fail(fn, std::string(name) + " is None");
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(obj);
  if (!a) fail(fn, std::string("cannot convert ") + name + " to float64");
  bool ok = a.ndim() == static_cast<py::ssize_t>(shape.size());
  for (std::size_t i = 0; ok && i < shape.size(); ++i)
    ok = shape[i] < 0 || a.shape(static_cast<py::ssize_t>(i)) == shape[i];
  if (!ok) fail(fn, std::string(name) + " must have shape " + shape_text);
  check_finite(a.data(), static_cast<std::size_t>(a.size()), fn, name);
  return a;
}

/// The per-ray fields of a SurfaceHits result with K slots.
template <class Query>
py::object surface_hits(const char* fn, py::handle origins, py::handle directions, int k,
                        const Query& query) {
  const auto o = f64(origins, fn, "origins", {-1, 3}, "(n, 3)");
  const auto d = f64(directions, fn, "directions", {-1, 3}, "(n, 3)");
  if (o.shape(0) != d.shape(0))
    fail(fn, "origins and directions must have the same number of rows, got " +
                 std::to_string(o.shape(0)) + " and " + std::to_string(d.shape(0)));
  const py::ssize_t n = o.shape(0), kk = k;
  py::array_t<int> count(n);
  py::array_t<bool> on(n);
  py::array_t<double> t({n, kk}), pts({n, kk, py::ssize_t(3)}), nrm({n, kk, py::ssize_t(3)}),
      uv({n, kk, py::ssize_t(2)});
  py::array_t<int> mult({n, kk});
  const auto* po = reinterpret_cast<const Vec3<double>*>(o.data());
  const auto* pd = reinterpret_cast<const Vec3<double>*>(d.data());
  int* c = count.mutable_data();
  bool* w = on.mutable_data();
  double* pt = t.mutable_data();
  double* pp = pts.mutable_data();
  double* pn = nrm.mutable_data();
  double* pu = uv.mutable_data();
  int* pm = mult.mutable_data();
  {
    py::gil_scoped_release nogil;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (py::ssize_t i = 0; i < n; ++i) {
      const LinearSurfaceIntersection3<double> r = query(Ray3<double>{po[i], pd[i]});
      const bool whole = r.kind == Kind::ray;
      w[i] = whole;
      c[i] = whole ? 0 : r.count;
      for (int j = 0; j < k; ++j) {
        const auto s = static_cast<std::size_t>(j);
        const bool has = !whole && j < r.count;
        const py::ssize_t q = i * kk + j;
        pt[q] = has ? r.param_a[s] : nan;
        pm[q] = has ? r.multiplicity[s] : 0;
        for (int e = 0; e < 3; ++e) {
          pp[3 * q + e] = has ? r.point[s][e] : nan;
          pn[3 * q + e] = has ? r.normal[s][e] : nan;
        }
        pu[2 * q] = has ? r.param_b[s].x : nan;
        pu[2 * q + 1] = has ? r.param_b[s].y : nan;
      }
    }
  }
  py::object out = new_result("SurfaceHits", Status::ok);
  out.attr("count") = count;
  out.attr("t") = t;
  out.attr("points") = pts;
  out.attr("normals") = nrm;
  out.attr("uv") = uv;
  out.attr("multiplicity") = mult;
  out.attr("on_surface") = on;
  return out;
}

}  // namespace

void bind_quadric3(py::module_& m) {
  m.def(
      "ray_quadric_hits",
      [](py::handle origins, py::handle directions, py::handle a, py::handle b,
         double c) -> py::object {
        const char* fn = "ray_quadric_hits";
        const auto am = f64(a, fn, "a", {3, 3}, "(3, 3) symmetric (upper triangle read)");
        const auto bv = f64(b, fn, "b", {3}, "(3,)");
        if (!std::isfinite(c)) fail(fn, "non_finite_input: c is NaN or infinite");
        Quadric3<double> q{};
        for (int i = 0; i < 3; ++i) {
          for (int j = 0; j < 3; ++j) q.a.a[i][j] = am.data()[3 * std::min(i, j) + std::max(i, j)];
          q.b[i] = bv.data()[i];
        }
        q.c = c;
        return surface_hits(fn, origins, directions, 2,
                            [&](const Ray3<double>& r) { return intersection(r, q); });
      },
      py::arg("origins"), py::arg("directions"), py::arg("a"), py::arg("b"), py::arg("c"),
      R"doc(Rays (origins + t directions, t >= 0; (n, 3) each) against the quadric
x^T a x + b.x + c = 0: a SurfaceHits with count (n,), t (n, 2), points (n, 2, 3), normals
(n, 2, 3) (unit gradient), uv (zeros), multiplicity (n, 2) (2 at a tangency) and on_surface
(n,) (the whole ray lies on the quadric; count 0 then). Unused slots are NaN. The count and the
tangency are decided exactly for the coefficients as given.)doc");

  m.def(
      "ray_torus_hits",
      [](py::handle origins, py::handle directions, py::handle center, py::handle normal,
         double major_radius, double minor_radius) -> py::object {
        const char* fn = "ray_torus_hits";
        const auto cv = f64(center, fn, "center", {3}, "(3,)");
        const auto nv = f64(normal, fn, "normal", {3}, "(3,)");
        if (!std::isfinite(major_radius) || !std::isfinite(minor_radius))
          fail(fn, "non_finite_input: a radius is NaN or infinite");
        const Torus3<double> tor{{cv.data()[0], cv.data()[1], cv.data()[2]},
                                 {nv.data()[0], nv.data()[1], nv.data()[2]},
                                 major_radius,
                                 minor_radius};
        return surface_hits(fn, origins, directions, 4,
                            [&](const Ray3<double>& r) { return intersection(r, tor); });
      },
      py::arg("origins"), py::arg("directions"), py::arg("center"), py::arg("normal"),
      py::arg("major_radius"), py::arg("minor_radius"),
      R"doc(Rays (origins + t directions, t >= 0; (n, 3) each) against a torus: a SurfaceHits
with count (n,), t (n, 4), points (n, 4, 3), normals (n, 4, 3), uv (n, 4, 2) (point_at's
angles: u about the axis, v about the tube) and multiplicity (n, 4). Unused slots are NaN.
Roots of the quartic in double; a tangency within the rounding bound is a double root.)doc");
}

}  // namespace locus::python
