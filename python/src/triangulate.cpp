// SPDX-License-Identifier: BSL-1.0
// triangulate_polygon: constrained Delaunay, ear clipping or monotone pieces
// (delaunay/constrained_delaunay2.hpp, triangulate/*.hpp); trapezoid_map: the trapezoidal map
// of segments with point location (triangulate/trapezoid_map.hpp).
#include "common.hpp"

#include <locus/delaunay/constrained_delaunay2.hpp>
#include <locus/triangulate/ear_clipping.hpp>
#include <locus/triangulate/monotone.hpp>
#include <locus/triangulate/trapezoid_map.hpp>

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

  m.def(
      "trapezoid_map",
      [](py::handle points, py::handle segments, py::object queries) -> py::object {
        const char* fn = "trapezoid_map";
        const ArrayView v = view_array(points, fn, "points", 2, {2});
        std::vector<Vec2d> pts(v.rows);
        for (std::size_t i = 0; i < v.rows; ++i)
          pts[i] =
              v.is_float ? vec_cast<double>(as_points<float, 2>(v)[i]) : as_points<double, 2>(v)[i];
        const std::vector<std::uint32_t> flat = index_array(segments, fn, "segments", 2, 2, v.rows);
        std::vector<std::array<std::uint32_t, 2>> segs(flat.size() / 2);
        for (std::size_t k = 0; k < segs.size(); ++k) segs[k] = {flat[2 * k], flat[2 * k + 1]};
        std::vector<Vec2d> qs;
        if (!queries.is_none()) {
          const ArrayView q = view_array(queries, fn, "queries", 2, {2});
          for (std::size_t i = 0; i < q.rows; ++i)
            qs.push_back(q.is_float ? vec_cast<double>(as_points<float, 2>(q)[i])
                                    : as_points<double, 2>(q)[i]);
          check_finite(reinterpret_cast<const double*>(qs.data()), 2 * qs.size(), fn, "queries");
        }
        TrapezoidMap2<double> map;
        Status st;
        std::vector<std::int64_t> traps, located;
        {
          py::gil_scoped_release nogil;
          st = map.build(std::span<const Vec2d>(pts), segs);
          for (const MapTrapezoid& t : map.trapezoids())
            for (const std::uint32_t x : {t.bottom, t.top, t.left, t.right})
              traps.push_back(x == trapezoid_unbounded ? -1 : std::int64_t(x));
          for (const Vec2d& q : qs) located.push_back(std::int64_t(map.locate(q)));
        }
        check_status(st, fn);
        py::object out = new_result("TrapezoidMapResult", st);
        const auto rows = static_cast<py::ssize_t>(traps.size() / 4);
        out.attr("trapezoids") = to_numpy(std::move(traps), {rows, 4});
        const auto k = static_cast<py::ssize_t>(located.size());
        out.attr("located") = to_numpy(std::move(located), {k});
        return out;
      },
      py::arg("points"), py::arg("segments"), py::arg("queries") = py::none(),
      R"doc(The horizontal trapezoidal map of non-crossing segments, with point location.

points: (n, 2); segments: (m, 2) indices into points (shared endpoints allowed). Seidel's
incremental construction with exact predicates (triangulate/trapezoid_map.hpp); float32 points
are promoted to float64 exactly. TrapezoidMapResult: `trapezoids` ((t, 4) int64 rows bottom,
top, left, right: the points whose heights bound each trapezoid and the segments bounding it,
-1 where unbounded; 3m + 1 rows for segments with distinct endpoints), `located` ((k,) int64:
the row of the trapezoid containing each query point; on a boundary the one above / right).
Raises ValueError for no segments, NaN/Inf, indices out of range or crossing segments.)doc");
}

}  // namespace locus::python
