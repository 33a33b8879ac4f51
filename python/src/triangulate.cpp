// SPDX-License-Identifier: BSL-1.0
// triangulate_polygon: constrained Delaunay, ear clipping or monotone pieces
// (delaunay/constrained_delaunay2.hpp, triangulate/*.hpp).
#include "common.hpp"

#include <locus/delaunay/constrained_delaunay2.hpp>
#include <locus/triangulate/ear_clipping.hpp>
#include <locus/triangulate/monotone.hpp>

#include <string_view>

namespace locus::python {

void bind_triangulate(py::module_& m) {
  m.def(
      "triangulate_polygon",
      [](py::handle points, py::object ring_ends, std::string method) -> py::object {
        const char* fn = "triangulate_polygon";
        const ArrayView v = view_array(points, fn, "points", 2, {2});
        std::vector<std::uint32_t> ends;
        if (ring_ends.is_none())
          ends.push_back(static_cast<std::uint32_t>(v.rows));
        else
          ends = index_array(ring_ends, fn, "ring_ends", 1, 0, v.rows + 1);
        for (std::size_t i = 0; i < ends.size(); ++i)
          if ((i > 0 && ends[i] < ends[i - 1]) || (i + 1 == ends.size() && ends[i] != v.rows))
            fail(fn, "ring_ends must increase and end with len(points)");
        enum { cdt, ear, monotone } which;
        if (method == "cdt")
          which = cdt;
        else if (method == "ear_clipping")
          which = ear;
        else if (method == "monotone")
          which = monotone;
        else
          fail(fn, "method must be 'cdt', 'ear_clipping' or 'monotone', not '" + method + "'");
        auto run = [&]<class T>(std::span<const Vec2<T>> p) -> py::object {
          Status st;
          std::vector<std::array<std::uint32_t, 3>> tris;
          {
            py::gil_scoped_release nogil;
            const std::span<const std::uint32_t> e(ends);
            if (which == cdt) {
              ConstrainedDelaunay2Result r = triangulate_polygon(p, e);
              st = r.status;
              for (std::size_t t = 0; t < r.triangles.size(); ++t)
                if (r.inside[t]) tris.push_back(r.triangles[t]);
            } else {
              PolygonTriangulation r =
                  which == ear ? triangulate_ear_clipping(p, e) : triangulate_monotone(p, e);
              st = r.status;
              tris = std::move(r.triangles);
            }
          }
          check_status(st, "triangulate_polygon");
          py::object out = new_result("TriangulationResult", st);
          out.attr("triangles") = to_numpy(std::move(tris));
          return out;
        };
        return v.is_float ? run(as_points<float, 2>(v)) : run(as_points<double, 2>(v));
      },
      py::arg("points"), py::arg("ring_ends") = py::none(), py::arg("method") = "cdt",
      R"doc(Triangulates a polygon with holes given as rings of (n, 2) points.

Ring k is points[ring_ends[k-1]:ring_ends[k]] (ring_ends[-1] = 0; default: one ring of all the
points), closed implicitly. method: 'cdt' (constrained Delaunay, any orientation and nesting,
even-odd rule), 'ear_clipping' or 'monotone' (outer ring then holes, see the C++ headers).
TriangulationResult: `triangles` ((m, 3) uint32 indices into points, counter-clockwise).
Raises ValueError for empty input, NaN/Inf or invalid rings.)doc");
}

}  // namespace locus::python
