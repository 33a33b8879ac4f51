// SPDX-License-Identifier: BSL-1.0
// point_in_polygon and point_in_polyhedron for many points (containment/*.hpp).
#include "common.hpp"

#include <locus/containment/point_in_polygon.hpp>
#include <locus/containment/point_in_polyhedron.hpp>

namespace locus::python {

namespace {

// Both arrays in one scalar type: float only when both are float32.
void same_type(ArrayView& a, ArrayView& b) {
  if (a.is_float == b.is_float) return;
  for (ArrayView* v : {&a, &b})
    if (v->is_float) {
      v->array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(v->array);
      v->is_float = false;
      v->copied = true;
    }
}

void check_view(const ArrayView& v, const char* fn, const char* name) {
  if (v.is_float)
    check_finite(static_cast<const float*>(v.array.data()), v.rows * std::size_t(v.last), fn, name);
  else
    check_finite(static_cast<const double*>(v.array.data()), v.rows * std::size_t(v.last), fn,
                 name);
}

}  // namespace

void bind_containment(py::module_& m) {
  m.def(
      "point_in_polygon",
      [](py::handle points, py::handle polygon, py::object ring_ends) -> py::array {
        const char* fn = "point_in_polygon";
        ArrayView q = view_array(points, fn, "points", 2, {2});
        ArrayView poly = view_array(polygon, fn, "polygon", 2, {2});
        if (poly.rows < 3) fail(fn, "empty_input: polygon needs at least 3 vertices");
        check_view(q, fn, "points");
        check_view(poly, fn, "polygon");
        same_type(q, poly);
        std::vector<std::uint32_t> ends;
        if (ring_ends.is_none())
          ends.push_back(static_cast<std::uint32_t>(poly.rows));
        else
          ends = index_array(ring_ends, fn, "ring_ends", 1, 0, poly.rows + 1);
        for (std::size_t i = 0; i < ends.size(); ++i)
          if ((i > 0 && ends[i] < ends[i - 1]) || (i + 1 == ends.size() && ends[i] != poly.rows))
            fail(fn, "ring_ends must increase and end with len(polygon)");
        py::array_t<std::int8_t> out(static_cast<py::ssize_t>(q.rows));
        std::int8_t* o = out.mutable_data();
        auto run = [&]<class T>(std::span<const Vec2<T>> p, std::span<const Vec2<T>> v) {
          py::gil_scoped_release nogil;
          std::vector<std::span<const Vec2<T>>> rings;
          std::uint32_t start = 0;
          for (std::uint32_t e : ends) {
            rings.push_back(v.subspan(start, e - start));
            start = e;
          }
          const PolygonLocator2<T> loc{std::span<const std::span<const Vec2<T>>>(rings)};
          if (loc.status() != Status::ok) return loc.status();
          for (std::size_t i = 0; i < p.size(); ++i)
            o[i] = static_cast<std::int8_t>(loc.classify(p[i]));
          return Status::ok;
        };
        const Status s = q.is_float ? run(as_points<float, 2>(q), as_points<float, 2>(poly))
                                    : run(as_points<double, 2>(q), as_points<double, 2>(poly));
        check_status(s, fn, false);
        return out;
      },
      py::arg("points"), py::arg("polygon"), py::arg("ring_ends") = py::none(),
      R"doc(Classifies (n, 2) points against a polygon with holes (exact predicates).

polygon: (m, 2) vertices of its rings; ring k is polygon[ring_ends[k-1]:ring_ends[k]]
(default: one ring), closed implicitly, even-odd rule. Returns an int8 array of n entries:
1 inside, 0 on the boundary, -1 outside (locus.Side values). Uses a slab locator built once
(containment/point_in_polygon.hpp PolygonLocator2). Raises ValueError for NaN/Inf input.)doc");

  m.def(
      "point_in_polyhedron",
      [](py::handle points, py::handle vertices, py::handle triangles) -> py::array {
        const char* fn = "point_in_polyhedron";
        ArrayView q = view_array(points, fn, "points", 2, {3});
        ArrayView v = view_array(vertices, fn, "vertices", 2, {3});
        check_view(q, fn, "points");
        check_view(v, fn, "vertices");
        same_type(q, v);
        const std::vector<std::uint32_t> flat =
            index_array(triangles, fn, "triangles", 2, 3, v.rows);
        if (flat.empty()) fail(fn, "empty_input: no triangles");
        std::vector<std::array<std::uint32_t, 3>> tris(flat.size() / 3);
        for (std::size_t i = 0; i < tris.size(); ++i)
          tris[i] = {flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]};
        py::array_t<std::int8_t> out(static_cast<py::ssize_t>(q.rows));
        std::int8_t* o = out.mutable_data();
        auto run = [&]<class T>(std::span<const Vec3<T>> p, std::span<const Vec3<T>> vv) {
          py::gil_scoped_release nogil;
          const std::span<const std::array<std::uint32_t, 3>> t(tris);
          for (std::size_t i = 0; i < p.size(); ++i)
            o[i] = static_cast<std::int8_t>(classify(p[i], vv, t));
        };
        if (q.is_float)
          run(as_points<float, 3>(q), as_points<float, 3>(v));
        else
          run(as_points<double, 3>(q), as_points<double, 3>(v));
        return out;
      },
      py::arg("points"), py::arg("vertices"), py::arg("triangles"),
      R"doc(Classifies (n, 3) points against a closed triangle mesh (exact ray parity).

vertices: (m, 3); triangles: (k, 3) integer indices. Returns int8: 1 inside, 0 on the surface,
-1 outside. Cost O(n k). Raises ValueError for NaN/Inf input or bad indices.)doc");
}

}  // namespace locus::python
