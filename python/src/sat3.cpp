// SPDX-License-Identifier: BSL-1.0
// Separating axes for convex polyhedra (intersection/sat.hpp): sat3_test (exact) and
// sat3_first_contact (moving polyhedra over [0, tmax]). A polyhedron is an (n, 3) array of points
// whose convex hull is used (hull/hull3.hpp; a flat set gives its polygon), converted to float64;
// NaN or infinite coordinates, or a collinear set, raise ValueError.
#include "common.hpp"

#include <locus/hull/hull3.hpp>
#include <locus/intersection/sat.hpp>

#include <string>
#include <vector>

namespace locus::python {

namespace {

/// An (n, 3) array as float64 points with its hull's triangles.
struct Solid {
  py::array_t<double> keep;
  std::span<const Vec3d> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  [[nodiscard]] ConvexMesh3<double> view() const { return {points, triangles}; }
};

void solid_arg(py::handle obj, const char* fn, const char* name, Solid& s) {
  const ArrayView v = view_array(obj, fn, name, 2, {3});
  s.keep = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(v.array);
  if (!s.keep) fail(fn, std::string("cannot convert ") + name + " to float64");
  if (v.rows == 0) fail(fn, std::string("empty_input: ") + name + " has no point");
  check_finite(s.keep.data(), static_cast<std::size_t>(s.keep.size()), fn, name);
  s.points = {reinterpret_cast<const Vec3d*>(s.keep.data()), v.rows};
  const Hull3Result h = convex_hull(s.points);
  check_status(h.status, fn);
  if (h.dimension == 3) s.triangles = h.triangles;
  if (h.dimension == 2)
    for (std::size_t i = 1; i + 1 < h.polygon.size(); ++i)
      s.triangles.push_back({h.polygon[0], h.polygon[i], h.polygon[i + 1]});
  if (s.triangles.empty())
    fail(fn, std::string("degenerate_input: ") + name + " spans no polygon or solid");
}

Vec3d vector3_arg(py::handle obj, const char* fn, const char* name) {
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(obj);
  if (!a || a.ndim() != 1 || a.shape(0) != 3) fail(fn, std::string(name) + " must have shape (3,)");
  check_finite(a.data(), 3, fn, name);
  return {a.data()[0], a.data()[1], a.data()[2]};
}

}  // namespace

void bind_sat3(py::module_& m) {
  m.def(
      "sat3_test",
      [](py::handle a, py::handle b) {
        const char* fn = "sat3_test";
        Solid sa, sb;
        solid_arg(a, fn, "a", sa);
        solid_arg(b, fn, "b", sb);
        const SatTest3 r = sat_test(sa.view(), sb.view());
        check_status(r.status, fn);
        return r.intersects;
      },
      py::arg("a"), py::arg("b"),
      "Whether the convex hulls of two 3D point sets ((n, 3), (m, 3)) meet; touching counts. "
      "Exact for the float64 input (separating axes, intersection/sat.hpp).");
  m.def(
      "sat3_first_contact",
      [](py::handle a, py::handle va, py::handle b, py::handle vb, double tmax) {
        const char* fn = "sat3_first_contact";
        Solid sa, sb;
        solid_arg(a, fn, "a", sa);
        solid_arg(b, fn, "b", sb);
        const Vec3d wa = vector3_arg(va, fn, "va"), wb = vector3_arg(vb, fn, "vb");
        if (!(tmax >= 0.0) || !std::isfinite(tmax)) fail(fn, "tmax must be finite and >= 0");
        const Contact3<double> r = first_contact(sa.view(), wa, sb.view(), wb, tmax);
        check_status(r.status, fn);
        py::object out = new_result("Contact3", r.status);
        out.attr("kind") = r.overlap ? std::string("overlap") : std::string(to_string(r.kind));
        out.attr("time") = r ? py::object(py::float_(r.time)) : py::object(py::none());
        py::array_t<double> p({static_cast<py::ssize_t>(r.points.size()), py::ssize_t(3)});
        for (std::size_t i = 0; i < r.points.size(); ++i)
          for (int k = 0; k < 3; ++k)
            p.mutable_data()[3 * i + static_cast<std::size_t>(k)] = r.points[i][k];
        out.attr("points") = p;
        return out;
      },
      py::arg("a"), py::arg("va"), py::arg("b"), py::arg("vb"), py::arg("tmax"),
      "First contact of the convex hulls of two 3D point sets moving as a + t va and b + t vb "
      "over [0, tmax]: kind ('empty', 'point', 'segment', 'polygon', or 'overlap' when the "
      "interiors overlap at time 0), time (None when empty) and the contact set ((k, 3)).");
}

}  // namespace locus::python
