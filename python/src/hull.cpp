// SPDX-License-Identifier: BSL-1.0
// convex_hull for (n, 2) and (n, 3) points (hull/hull2.hpp, hull/hull3.hpp).
#include "common.hpp"

#include <locus/hull/hull2.hpp>
#include <locus/hull/hull3.hpp>

namespace locus::python {

void bind_hull(py::module_& m) {
  m.def(
      "convex_hull",
      [](py::handle points, bool keep_collinear, py::object method) -> py::object {
        const std::string name = method.is_none() ? "" : py::cast<std::string>(method);
        return with_points(points, "convex_hull", {2, 3},
                           [&]<class T, int N>(std::span<const Vec<T, N>> p) -> py::object {
                             if constexpr (N == 2) {
                               Hull2Options opt;
                               opt.keep_collinear = keep_collinear;
                               if (name == "incremental")
                                 opt.method = Hull2Method::incremental;
                               else if (name == "divide_and_conquer")
                                 opt.method = Hull2Method::divide_and_conquer;
                               else if (!name.empty() && name != "monotone_chain")
                                 fail("convex_hull",
                                      "2D method must be 'monotone_chain', 'incremental' or "
                                      "'divide_and_conquer', not '" +
                                          name + "'");
                               Hull2Result r;
                               {
                                 py::gil_scoped_release nogil;
                                 r = convex_hull(p, opt);
                               }
                               check_status(r.status, "convex_hull");
                               py::object out = new_result("Hull2Result", r.status);
                               out.attr("dimension") = r.dimension;
                               const auto k = static_cast<py::ssize_t>(r.indices.size());
                               out.attr("indices") = to_numpy(std::move(r.indices), {k});
                               return out;
                             } else {
                               Hull3Options opt;
                               if (name == "incremental")
                                 opt.method = Hull3Method::incremental;
                               else if (name == "divide_and_conquer")
                                 opt.method = Hull3Method::divide_and_conquer;
                               else if (!name.empty() && name != "quickhull")
                                 fail("convex_hull",
                                      "3D method must be 'quickhull', 'incremental' or "
                                      "'divide_and_conquer', not '" +
                                          name + "'");
                               Hull3Result r;
                               {
                                 py::gil_scoped_release nogil;
                                 r = convex_hull(p, opt);
                               }
                               check_status(r.status, "convex_hull");
                               py::object out = new_result("Hull3Result", r.status);
                               out.attr("dimension") = r.dimension;
                               out.attr("triangles") = to_numpy(std::move(r.triangles));
                               const auto kv = static_cast<py::ssize_t>(r.vertices.size());
                               out.attr("vertices") = to_numpy(std::move(r.vertices), {kv});
                               const auto kp = static_cast<py::ssize_t>(r.polygon.size());
                               out.attr("polygon") = to_numpy(std::move(r.polygon), {kp});
                               return out;
                             }
                           });
      },
      py::arg("points"), py::arg("keep_collinear") = false, py::arg("method") = py::none(),
      R"doc(Convex hull of (n, 2) or (n, 3) points (exact predicates).

2D: Hull2Result with `dimension` (0, 1 or 2) and `indices` (uint32, counter-clockwise from
the lowest-leftmost point; with keep_collinear, points inside hull edges are listed too).
3D: Hull3Result with `dimension` (0..3), `triangles` ((m, 3) uint32, outward, counter-clockwise
seen from outside; dimension 3 only), `vertices` (sorted hull vertex indices) and `polygon`
(dimension <= 2: the hull in its plane or line). keep_collinear applies to 2D only.
method (None: the fastest): 2D 'monotone_chain', 'incremental' or 'divide_and_conquer'; 3D
'quickhull', 'incremental' or 'divide_and_conquer' (the book's merge of two hulls). Every
method gives the same hull (3D: the same vertices; coplanar facets may be triangulated
differently).
Raises ValueError for empty input or NaN/Inf coordinates.)doc");
}

}  // namespace locus::python
