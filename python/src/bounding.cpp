// SPDX-License-Identifier: BSL-1.0
// min_circle, min_sphere, min_rect, min_box (bounding/*.hpp).
#include "common.hpp"

#include <locus/bounding/min_box3.hpp>
#include <locus/bounding/min_circle.hpp>
#include <locus/bounding/min_rect2.hpp>
#include <locus/bounding/min_sphere.hpp>

namespace locus::python {

namespace {

template <class T, int N>
py::array axes_out(const Vec<T, N>* axis, int count) {
  py::array_t<T> a({static_cast<py::ssize_t>(count), static_cast<py::ssize_t>(N)});
  for (int i = 0; i < count; ++i)
    for (int j = 0; j < N; ++j) a.mutable_data()[i * N + j] = axis[i][j];
  return a;
}

template <class I, std::size_t K>
py::array support_out(const std::array<I, K>& s, int count) {
  py::array_t<I> a(count);
  for (int i = 0; i < count; ++i) a.mutable_data()[i] = s[static_cast<std::size_t>(i)];
  return a;
}

}  // namespace

void bind_bounding(py::module_& m) {
  m.def(
      "min_circle",
      [](py::handle points) -> py::object {
        return with_points(points, "min_circle", {2},
                           [&]<class T, int N>(std::span<const Vec<T, N>> p) -> py::object {
                             if constexpr (N == 2) {
                               MinCircleResult<T> r;
                               {
                                 py::gil_scoped_release nogil;
                                 r = min_circle(p);
                               }
                               check_status(r.status, "min_circle");
                               py::object out = new_result("MinCircleResult", r.status);
                               out.attr("center") = vec_out(r.circle.center);
                               out.attr("radius") = static_cast<double>(r.circle.radius);
                               out.attr("support") = support_out(r.support, r.support_count);
                               return out;
                             } else {
                               return py::none();
                             }
                           });
      },
      py::arg("points"),
      R"doc(Smallest enclosing circle of (n, 2) points (Welzl, exact predicates).

MinCircleResult: `center` (2,), `radius` (float; rounded, see bounding/min_circle.hpp),
`support` (indices of the 1..3 points on the circle).)doc");

  m.def(
      "min_sphere",
      [](py::handle points) -> py::object {
        return with_points(points, "min_sphere", {3},
                           [&]<class T, int N>(std::span<const Vec<T, N>> p) -> py::object {
                             if constexpr (N == 3) {
                               MinSphereResult<T> r;
                               {
                                 py::gil_scoped_release nogil;
                                 r = min_sphere(p);
                               }
                               check_status(r.status, "min_sphere");
                               py::object out = new_result("MinSphereResult", r.status);
                               out.attr("center") = vec_out(r.sphere.center);
                               out.attr("radius") = static_cast<double>(r.sphere.radius);
                               out.attr("support") = support_out(r.support, r.support_count);
                               return out;
                             } else {
                               return py::none();
                             }
                           });
      },
      py::arg("points"),
      R"doc(Smallest enclosing sphere of (n, 3) points.

MinSphereResult: `center` (3,), `radius`, `support` (indices of the 1..4 points on the sphere).)doc");

  m.def(
      "min_rect",
      [](py::handle points, bool perimeter) -> py::object {
        return with_points(points, "min_rect", {2},
                           [&]<class T, int N>(std::span<const Vec<T, N>> p) -> py::object {
                             if constexpr (N == 2) {
                               MinRectResult<T> r;
                               {
                                 py::gil_scoped_release nogil;
                                 r = min_rect(
                                     p, perimeter ? RectCriterion::perimeter : RectCriterion::area);
                               }
                               check_status(r.status, "min_rect");
                               py::object out = new_result("MinRectResult", r.status);
                               out.attr("center") = vec_out(r.rectangle.center);
                               out.attr("axes") = axes_out(r.rectangle.axis, 2);
                               out.attr("extents") = vec_out(r.rectangle.extent);
                               out.attr("area") = static_cast<double>(r.area);
                               out.attr("perimeter") = static_cast<double>(r.perimeter);
                               out.attr("edge") = support_out(r.edge, 2);
                               return out;
                             } else {
                               return py::none();
                             }
                           });
      },
      py::arg("points"), py::arg("perimeter") = false,
      R"doc(Minimum-area (or, with perimeter=True, minimum-perimeter) enclosing rectangle of
(n, 2) points (rotating calipers on the exact hull).

MinRectResult: `center` (2,), `axes` ((2, 2), unit rows), `extents` (half side lengths),
`area`, `perimeter`, `edge` (input indices of the hull edge the rectangle is flush with).)doc");

  m.def(
      "min_box",
      [](py::handle points) -> py::object {
        return with_points(points, "min_box", {3},
                           [&]<class T, int N>(std::span<const Vec<T, N>> p) -> py::object {
                             if constexpr (N == 3) {
                               MinBoxResult<T> r;
                               {
                                 py::gil_scoped_release nogil;
                                 r = min_box(p);
                               }
                               check_status(r.status, "min_box");
                               py::object out = new_result("MinBoxResult", r.status);
                               out.attr("center") = vec_out(r.box.center);
                               out.attr("axes") = axes_out(r.box.axis, 3);
                               out.attr("extents") = vec_out(r.box.extent);
                               out.attr("volume") = static_cast<double>(r.volume);
                               out.attr("certified") = r.certified;
                               return out;
                             } else {
                               return py::none();
                             }
                           });
      },
      py::arg("points"),
      R"doc(Minimum-volume enclosing oriented box of (n, 3) points (O'Rourke's edge arcs with
branch and bound; `certified` tells whether optimality was proved within 1e-6).

MinBoxResult: `center` (3,), `axes` ((3, 3) unit rows), `extents` (half sides), `volume`,
`certified`. status may be 'limit_exceeded' (work budget spent; best box so far).)doc");
}

}  // namespace locus::python
