// SPDX-License-Identifier: BSL-1.0
// Chapter 12 over arrays (construct/misc3.hpp): the angles between lines and planes given by
// their (n, 3) directions and normals, and the projection of (n, 3) points onto one plane.
// Inputs are converted to float64; NaN or infinite entries raise ValueError; a zero direction or
// normal gives a NaN angle (as the library).
#include "common.hpp"

#include <locus/construct/misc3.hpp>

#include <string>

namespace locus::python {

namespace {

py::array_t<double> f64(py::handle obj, const char* fn, const char* name, int ndim) {
  if (obj.is_none()) fail(fn, std::string(name) + " is None");
  py::array a = py::array::ensure(obj);
  if (!a) fail(fn, std::string(name) + " is not convertible to a numpy array");
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    fail(fn, std::string(name) + " must hold real numbers, not dtype " +
                 std::string(py::str(a.dtype())));
  if (a.ndim() != ndim || a.shape(ndim - 1) != 3)
    fail(fn, std::string(name) + " must have shape " + (ndim == 1 ? "(3,)" : "(n, 3)"));
  auto out = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  if (!out) fail(fn, std::string("cannot convert ") + name + " to float64");
  check_finite(out.data(), static_cast<std::size_t>(out.size()), fn, name);
  return out;
}

Vec3<double> row(const py::array_t<double>& a, py::ssize_t i) {
  const double* p = a.data() + 3 * i;
  return {p[0], p[1], p[2]};
}

/// angle(i) for n pairs of rows of a and b, as an (n,) float64 array.
template <class F>
py::array_t<double> angles(py::handle a, py::handle b, const char* fn, const char* na,
                           const char* nb, F&& f) {
  const auto pa = f64(a, fn, na, 2), pb = f64(b, fn, nb, 2);
  const py::ssize_t n = pa.shape(0);
  if (pb.shape(0) != n) fail(fn, std::string(na) + " and " + nb + " must have the same length");
  py::array_t<double> out(n);
  double* o = out.mutable_data();
  {
    py::gil_scoped_release nogil;
    for (py::ssize_t i = 0; i < n; ++i) o[i] = f(row(pa, i), row(pb, i));
  }
  return out;
}

}  // namespace

void bind_misc3(py::module_& m) {
  m.def(
      "line_plane_angles",
      [](py::handle directions, py::handle normals, bool acute) {
        return angles(directions, normals, "line_plane_angles", "directions", "normals",
                      [acute](const Vec3<double>& d, const Vec3<double>& n) {
                        const Line3<double> l{{}, d};
                        const Plane3<double> p{n, 0.0};
                        return acute ? acute_angle(l, p) : angle_between(l, p);
                      });
      },
      py::arg("directions"), py::arg("normals"), py::arg("acute") = false,
      "Angles (radians) between lines with the given (n, 3) directions and planes with the "
      "given (n, 3) normals: in [-pi/2, pi/2], positive when the direction points to the "
      "normal's side (acute=True: the absolute value). NaN for a zero vector.");
  m.def(
      "line_line_angles",
      [](py::handle d0, py::handle d1, bool acute) {
        return angles(d0, d1, "line_line_angles", "d0", "d1",
                      [acute](const Vec3<double>& a, const Vec3<double>& b) {
                        const Line3<double> la{{}, a}, lb{{}, b};
                        return acute ? acute_angle(la, lb) : angle_between(la, lb);
                      });
      },
      py::arg("d0"), py::arg("d1"), py::arg("acute") = false,
      "Angles (radians) between lines with the (n, 3) directions d0 and d1: in [0, pi] "
      "(acute=True: [0, pi/2], orientation ignored). NaN for a zero direction.");
  m.def(
      "plane_plane_angles",
      [](py::handle n0, py::handle n1, bool acute) {
        return angles(n0, n1, "plane_plane_angles", "n0", "n1",
                      [acute](const Vec3<double>& a, const Vec3<double>& b) {
                        const Plane3<double> pa{a, 0.0}, pb{b, 0.0};
                        return acute ? acute_angle(pa, pb) : angle_between(pa, pb);
                      });
      },
      py::arg("n0"), py::arg("n1"), py::arg("acute") = false,
      "Angles (radians) between planes with the (n, 3) normals n0 and n1: the angle between the "
      "normals in [0, pi] (acute=True: the dihedral angle in [0, pi/2]). NaN for a zero normal.");
  m.def(
      "project_points_to_plane",
      [](py::handle points, py::handle normal, double constant) {
        const char* fn = "project_points_to_plane";
        const auto pp = f64(points, fn, "points", 2), pn = f64(normal, fn, "normal", 1);
        if (!std::isfinite(constant)) fail(fn, "non_finite_input: constant is NaN or infinite");
        const Plane3<double> pl{row(pn, 0), constant};
        if (pl.normal == Vec3<double>{}) fail(fn, "degenerate_input: the normal is zero");
        const py::ssize_t n = pp.shape(0);
        py::array_t<double> out({n, py::ssize_t(3)});
        double* o = out.mutable_data();
        {
          py::gil_scoped_release nogil;
          for (py::ssize_t i = 0; i < n; ++i) {
            const Vec3<double> q = project_point(row(pp, i), pl);
            for (int k = 0; k < 3; ++k) o[3 * i + k] = q[k];
          }
        }
        return out;
      },
      py::arg("points"), py::arg("normal"), py::arg("constant"),
      "Orthogonal projections of (n, 3) points onto the plane {X : normal . X = constant} "
      "(figure 12.1), as an (n, 3) float64 array.");
}

}  // namespace locus::python
