// SPDX-License-Identifier: BSL-1.0
// planar_polygon_pieces(polygon, p, q, kind, frame): every piece of a line, ray or segment in a
// filled polygon lying in a plane of 3D (intersection/{line,ray,segment}_polygon.hpp
// intersection_pieces; row int3.linear-polygon). Computed in float64; NaN or infinite
// coordinates, an empty polygon or a zero normal raise ValueError.
#include "common.hpp"

#include <locus/intersection/line_polygon.hpp>
#include <locus/intersection/ray_polygon.hpp>
#include <locus/intersection/segment_polygon.hpp>

#include <string>
#include <vector>

namespace locus::python {

namespace {

/// A C-contiguous float64 copy of obj with the given shape (checked).
py::array_t<double> f64_shape(py::handle obj, const char* fn, const char* name,
                              std::initializer_list<py::ssize_t> shape, const char* text) {
  if (obj.is_none()) fail(fn, std::string(name) + " is None");
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(obj);
  if (!a) fail(fn, std::string("cannot convert ") + name + " to float64");
  bool ok = a.ndim() == static_cast<py::ssize_t>(shape.size());
  py::ssize_t axis = 0;
  for (const py::ssize_t d : shape) {
    ok = ok && (d < 0 || a.shape(axis) == d);
    ++axis;
  }
  if (!ok) fail(fn, std::string(name) + " must have shape " + text);
  return a;
}

template <class A>
py::object pieces_out(const A& a, const PlanarPolygon3<double>& poly, const char* fn) {
  const LinearPlanarPieces<double> r = intersection_pieces(a, poly);
  check_status(r.status, fn, false);
  const auto k = static_cast<py::ssize_t>(r.pieces.size());
  py::array_t<std::int8_t> kind(k);
  py::array_t<double> t({k, py::ssize_t(2)}), points({k, py::ssize_t(2), py::ssize_t(3)}),
      st({k, py::ssize_t(2), py::ssize_t(2)});
  for (std::size_t i = 0; i < r.pieces.size(); ++i) {
    const auto& c = r.pieces[i];
    kind.mutable_data()[i] = static_cast<std::int8_t>(c.count);
    for (std::size_t j = 0; j < 2; ++j) {
      const std::size_t e = c.count == 2 ? j : 0;  // a point repeats its one entry
      t.mutable_data()[2 * i + j] = c.param_a[e];
      for (std::size_t d = 0; d < 3; ++d)
        points.mutable_data()[6 * i + 3 * j + d] = c.point[e][static_cast<int>(d)];
      for (std::size_t d = 0; d < 2; ++d)
        st.mutable_data()[4 * i + 2 * j + d] = c.param_b[e][static_cast<int>(d)];
    }
  }
  py::object out = new_result("PlanarPieces", r.status);
  out.attr("kind") = kind;
  out.attr("t") = t;
  out.attr("points") = points;
  out.attr("st") = st;
  return out;
}

}  // namespace

void bind_planar_pieces(py::module_& m) {
  m.def(
      "planar_polygon_pieces",
      [](py::handle polygon, py::handle p, py::handle q, const std::string& kind,
         py::object frame) -> py::object {
        const char* fn = "planar_polygon_pieces";
        const auto pa = f64_shape(polygon, fn, "polygon", {-1, 2}, "(n, 2)");
        const auto pp = f64_shape(p, fn, "p", {3}, "(3,)");
        const auto pq = f64_shape(q, fn, "q", {3}, "(3,)");
        PlanarPolygon3<double> poly{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {}};
        if (!frame.is_none()) {
          const auto pf = f64_shape(frame, fn, "frame", {4, 3}, "(4, 3): origin, u, v, normal");
          check_finite(pf.data(), 12, fn, "frame");
          const double* f = pf.data();
          poly.frame = {
              {f[0], f[1], f[2]}, {f[3], f[4], f[5]}, {f[6], f[7], f[8]}, {f[9], f[10], f[11]}};
        }
        check_finite(pa.data(), static_cast<std::size_t>(pa.size()), fn, "polygon");
        check_finite(pp.data(), 3, fn, "p");
        check_finite(pq.data(), 3, fn, "q");
        const double* v = pa.data();
        for (py::ssize_t i = 0; i < pa.shape(0); ++i)
          poly.polygon.vertices.push_back({v[2 * i], v[2 * i + 1]});
        const Vec3<double> a{pp.data()[0], pp.data()[1], pp.data()[2]};
        const Vec3<double> b{pq.data()[0], pq.data()[1], pq.data()[2]};
        if (kind == "line") return pieces_out(Line3<double>{a, b}, poly, fn);
        if (kind == "ray") return pieces_out(Ray3<double>{a, b}, poly, fn);
        if (kind == "segment") return pieces_out(Segment3<double>{a, b}, poly, fn);
        fail(fn, "kind must be 'line', 'ray' or 'segment', got '" + kind + "'");
      },
      py::arg("polygon"), py::arg("p"), py::arg("q"), py::arg("kind") = "segment",
      py::arg("frame") = py::none(),
      R"doc(Every piece of a line, ray or segment in a filled polygon lying in a plane of 3D.

polygon: (n, 2) vertices in the plane's frame coordinates (closed, any orientation, convex or
not; the even-odd rule, boundary included). frame: (4, 3) rows origin, u, v, normal (default
the xy plane: point (s, t) is origin + s u + t v). kind 'segment' (p to q), 'ray' or 'line'
(origin p, direction q). PlanarPieces: kind (k,) int8 (1 a point, 2 a segment), t (k, 2) the
parameters of each piece's ends on the component (p + t (q - p) for a segment, p + t q
otherwise), points (k, 2, 3), st (k, 2, 2) frame coordinates; a point repeats its entry. In order
along the component. A component crossing the plane gives its crossing point or nothing; one
lying in the plane is cut exactly where it meets the boundary (exact decisions on its rounded
frame image), touching points included.)doc");
}

}  // namespace locus::python
