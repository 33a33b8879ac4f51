// SPDX-License-Identifier: BSL-1.0
// Least-squares fits (fit/*.hpp): line, plane, circle, sphere, Gaussian.
#include "common.hpp"

#include <locus/fit/circle_fit.hpp>
#include <locus/fit/gaussian_fit.hpp>
#include <locus/fit/line_fit.hpp>
#include <locus/fit/plane_fit.hpp>
#include <locus/fit/sphere_fit.hpp>

namespace locus::python {

namespace {

template <class T, int N>
py::object sphere_fit_out(const SphereFit<T, N>& r, const char* fn) {
  check_status(r.status, fn);
  py::object out = new_result("SphereFitResult", r.status);
  out.attr("center") = vec_out(r.sphere.center);
  out.attr("radius") = static_cast<double>(r.sphere.radius);
  out.attr("rms") = static_cast<double>(r.rms);
  out.attr("iterations") = r.iterations;
  return out;
}

}  // namespace

void bind_fit(py::module_& m) {
  m.def(
      "fit_line",
      [](py::handle points) -> py::object {
        return with_points(points, "fit_line", {2, 3},
                           [&]<class T, int N>(std::span<const Vec<T, N>> p) -> py::object {
                             LineFit<T, N> r;
                             {
                               py::gil_scoped_release nogil;
                               r = fit_line(p);
                             }
                             check_status(r.status, "fit_line");
                             py::object out = new_result("LineFitResult", r.status);
                             out.attr("origin") = vec_out(r.line.origin);
                             out.attr("direction") = vec_out(r.line.direction);
                             out.attr("rms") = static_cast<double>(r.rms);
                             return out;
                           });
      },
      py::arg("points"),
      R"doc(Orthogonal least-squares line through (n, 2) or (n, 3) points.

LineFitResult: `origin` (the mean), `direction` (unit; sign canonical: largest component
positive), `rms` (RMS orthogonal distance). Raises ValueError when fewer than 2 distinct points.)doc");

  m.def(
      "fit_plane",
      [](py::handle points) -> py::object {
        return with_points(points, "fit_plane", {3},
                           [&]<class T, int N>(std::span<const Vec<T, N>> p) -> py::object {
                             if constexpr (N == 3) {
                               PlaneFit<T> r;
                               {
                                 py::gil_scoped_release nogil;
                                 r = fit_plane(p);
                               }
                               check_status(r.status, "fit_plane");
                               py::object out = new_result("PlaneFitResult", r.status);
                               out.attr("normal") = vec_out(r.plane.normal);
                               out.attr("constant") = static_cast<double>(r.plane.constant);
                               out.attr("rms") = static_cast<double>(r.rms);
                               return out;
                             } else {
                               return py::none();
                             }
                           });
      },
      py::arg("points"),
      R"doc(Orthogonal least-squares plane through (n, 3) points.

PlaneFitResult: `normal` (unit), `constant` (plane dot(normal, x) = constant), `rms`.
Raises ValueError for collinear or too few points.)doc");

  m.def(
      "fit_circle",
      [](py::handle points, bool algebraic) -> py::object {
        return with_points(points, "fit_circle", {2},
                           [&]<class T, int N>(std::span<const Vec<T, N>> p) -> py::object {
                             if constexpr (N == 2) {
                               SphereFit<T, 2> r;
                               {
                                 py::gil_scoped_release nogil;
                                 r = algebraic ? fit_sphere_algebraic(p) : fit_sphere(p);
                               }
                               return sphere_fit_out(r, "fit_circle");
                             } else {
                               return py::none();
                             }
                           });
      },
      py::arg("points"), py::arg("algebraic") = false,
      R"doc(Least-squares circle through (n, 2) points: geometric (Levenberg-Marquardt from the
algebraic fit) or, with algebraic=True, the algebraic fit only.

SphereFitResult: `center`, `radius`, `rms` (RMS geometric distance), `iterations`.)doc");

  m.def(
      "fit_sphere",
      [](py::handle points, bool algebraic) -> py::object {
        return with_points(points, "fit_sphere", {3},
                           [&]<class T, int N>(std::span<const Vec<T, N>> p) -> py::object {
                             if constexpr (N == 3) {
                               SphereFit<T, 3> r;
                               {
                                 py::gil_scoped_release nogil;
                                 r = algebraic ? fit_sphere_algebraic(p) : fit_sphere(p);
                               }
                               return sphere_fit_out(r, "fit_sphere");
                             } else {
                               return py::none();
                             }
                           });
      },
      py::arg("points"), py::arg("algebraic") = false,
      R"doc(Least-squares sphere through (n, 3) points (see fit_circle).

SphereFitResult: `center`, `radius`, `rms`, `iterations`.)doc");

  m.def(
      "fit_gaussian",
      [](py::handle points) -> py::object {
        return with_points(points, "fit_gaussian", {2, 3},
                           [&]<class T, int N>(std::span<const Vec<T, N>> p) -> py::object {
                             GaussianFit<T, N> r;
                             {
                               py::gil_scoped_release nogil;
                               r = fit_gaussian(p);
                             }
                             check_status(r.status, "fit_gaussian");
                             py::object out = new_result("GaussianFitResult", r.status);
                             out.attr("mean") = vec_out(r.mean);
                             py::array_t<T> cov({N, N}), axes({N, N});
                             for (int i = 0; i < N; ++i)
                               for (int j = 0; j < N; ++j) {
                                 cov.mutable_data()[i * N + j] = r.covariance(i, j);
                                 axes.mutable_data()[i * N + j] = r.box.axis[i][j];
                               }
                             out.attr("covariance") = cov;
                             out.attr("axes") = axes;
                             out.attr("extents") = vec_out(r.box.extent);
                             out.attr("rms") = static_cast<double>(r.rms);
                             return out;
                           });
      },
      py::arg("points"),
      R"doc(Gaussian (mean and covariance) of (n, 2) or (n, 3) points.

GaussianFitResult: `mean`, `covariance` ((N, N), normalised by n), `axes` ((N, N) unit rows,
eigenvectors by ascending eigenvalue), `extents` (standard deviations along them), `rms`.)doc");
}

}  // namespace locus::python
