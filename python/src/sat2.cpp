// SPDX-License-Identifier: BSL-1.0
// Separating axes for convex polygons (intersection/convex_polygon2.hpp, moving_convex2.hpp):
// convex_polygons_intersect (exact), convex_polygon_intersection (the common set) and
// first_contact (moving polygons over [0, tmax]). Polygons are (n, 2) arrays in either vertex
// order, converted to float64; NaN or infinite coordinates raise ValueError.
#include "common.hpp"

#include <locus/intersection/convex_polygon2.hpp>
#include <locus/intersection/moving_convex2.hpp>

#include <string>

namespace locus::python {

namespace {

/// An (n, 2) array as float64 points (n >= 1), checked finite.
std::span<const Vec2d> polygon_arg(py::handle obj, const char* fn, const char* name,
                                   py::array_t<double>& keep) {
  const ArrayView v = view_array(obj, fn, name, 2, {2});
  keep = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(v.array);
  if (!keep) fail(fn, std::string("cannot convert ") + name + " to float64");
  if (v.rows == 0) fail(fn, std::string("empty_input: ") + name + " has no vertex");
  check_finite(keep.data(), static_cast<std::size_t>(keep.size()), fn, name);
  return {reinterpret_cast<const Vec2d*>(keep.data()), v.rows};
}

Vec2d vector_arg(py::handle obj, const char* fn, const char* name) {
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(obj);
  if (!a || a.ndim() != 1 || a.shape(0) != 2) fail(fn, std::string(name) + " must have shape (2,)");
  check_finite(a.data(), 2, fn, name);
  return {a.data()[0], a.data()[1]};
}

py::array points_out(const Vec2d* p, int count) {
  py::array_t<double> a({static_cast<py::ssize_t>(count), py::ssize_t(2)});
  for (int i = 0; i < count; ++i) {
    a.mutable_data()[2 * i] = p[i].x;
    a.mutable_data()[2 * i + 1] = p[i].y;
  }
  return a;
}

}  // namespace

void bind_sat2(py::module_& m) {
  m.def(
      "convex_polygons_intersect",
      [](py::handle a, py::handle b) {
        const char* fn = "convex_polygons_intersect";
        py::array_t<double> ka, kb;
        const auto pa = polygon_arg(a, fn, "a", ka), pb = polygon_arg(b, fn, "b", kb);
        return intersects_convex_polygons(pa, pb);
      },
      py::arg("a"), py::arg("b"),
      "Whether two convex polygons ((n, 2) vertices, either order) meet; touching counts. "
      "Exact for the float64 input.");
  m.def(
      "convex_polygon_intersection",
      [](py::handle a, py::handle b) {
        const char* fn = "convex_polygon_intersection";
        py::array_t<double> ka, kb;
        const auto pa = polygon_arg(a, fn, "a", ka), pb = polygon_arg(b, fn, "b", kb);
        const ConvexIntersection2<double> r = convex_polygon_intersection(pa, pb);
        check_status(r.status, fn);
        py::object out = new_result("ConvexIntersection", r.status);
        out.attr("kind") = std::string(to_string(r.kind));
        out.attr("vertices") = points_out(r.vertices.data(), static_cast<int>(r.vertices.size()));
        return out;
      },
      py::arg("a"), py::arg("b"),
      "The common set of two convex polygons: kind ('empty', 'point', 'segment', 'polygon', "
      "decided exactly) and vertices ((k, 2), counter-clockwise for a polygon).");
  m.def(
      "first_contact",
      [](py::handle a, py::handle va, py::handle b, py::handle vb, double tmax) {
        const char* fn = "first_contact";
        py::array_t<double> ka, kb;
        const auto pa = polygon_arg(a, fn, "a", ka), pb = polygon_arg(b, fn, "b", kb);
        const Vec2d wa = vector_arg(va, fn, "va"), wb = vector_arg(vb, fn, "vb");
        if (!(tmax >= 0.0) || !std::isfinite(tmax)) fail(fn, "tmax must be finite and >= 0");
        const Contact2<double> r = first_contact_convex_polygons(pa, wa, pb, wb, tmax);
        py::object out = new_result("Contact", Status::ok);
        out.attr("kind") = std::string(to_string(r.kind));
        out.attr("time") = r.kind == Kind::empty ? py::object(py::none()) : py::float_(r.time);
        out.attr("points") = points_out(r.point.data(), r.count);
        return out;
      },
      py::arg("a"), py::arg("va"), py::arg("b"), py::arg("vb"), py::arg("tmax"),
      "First contact of convex polygons a + t va and b + t vb over [0, tmax]: kind ('empty', "
      "'point', 'segment', or 'polygon' when already overlapping at time 0), time (None when "
      "empty) and the contact set points ((k, 2)).");
}

}  // namespace locus::python
