// SPDX-License-Identifier: BSL-1.0
// delaunay (2D, 3D) and constrained_delaunay (delaunay/*.hpp).
#include "common.hpp"

#include <locus/delaunay/constrained_delaunay2.hpp>
#include <locus/delaunay/delaunay2.hpp>
#include <locus/delaunay/delaunay3.hpp>

namespace locus::python {

namespace {

template <class V>
py::array vector_out(V&& v) {
  const auto k = static_cast<py::ssize_t>(v.size());
  return to_numpy(std::move(v), {k});
}

}  // namespace

void bind_delaunay(py::module_& m) {
  m.def(
      "delaunay",
      [](py::handle points) -> py::object {
        return with_points(points, "delaunay", {2, 3},
                           [&]<class T, int N>(std::span<const Vec<T, N>> p) -> py::object {
                             if constexpr (N == 2) {
                               Delaunay2Result r;
                               {
                                 py::gil_scoped_release nogil;
                                 r = delaunay(p);
                               }
                               check_status(r.status, "delaunay");
                               py::object out = new_result("Delaunay2Result", r.status);
                               out.attr("dimension") = r.dimension;
                               out.attr("triangles") = to_numpy(std::move(r.triangles));
                               out.attr("adjacency") = to_numpy(std::move(r.adjacency));
                               out.attr("hull") = vector_out(std::move(r.hull));
                               out.attr("duplicate_of") = vector_out(std::move(r.duplicate_of));
                               return out;
                             } else {
                               Delaunay3Result r;
                               {
                                 py::gil_scoped_release nogil;
                                 r = delaunay(p);
                               }
                               check_status(r.status, "delaunay");
                               py::object out = new_result("Delaunay3Result", r.status);
                               out.attr("dimension") = r.dimension;
                               out.attr("tetrahedra") = to_numpy(std::move(r.tetrahedra));
                               out.attr("adjacency") = to_numpy(std::move(r.adjacency));
                               out.attr("hull") = to_numpy(std::move(r.hull));
                               out.attr("duplicate_of") = vector_out(std::move(r.duplicate_of));
                               out.attr("triangles") = to_numpy(std::move(r.triangles));
                               out.attr("chain") = vector_out(std::move(r.chain));
                               return out;
                             }
                           });
      },
      py::arg("points"),
      R"doc(Delaunay triangulation of (n, 2) or (n, 3) points (exact predicates, symbolic
perturbation for cocircular/cospherical points).

2D: Delaunay2Result: `dimension` (2, 1 collinear, 0 one point), `triangles` ((m, 3) uint32,
counter-clockwise), `adjacency` ((m, 3): triangle across edge (v[i], v[i+1]), 0xFFFFFFFF on the
hull), `hull` (CCW hull vertices), `duplicate_of` (per input point: itself or the kept equal
point).
3D: Delaunay3Result: `tetrahedra` ((m, 4) uint32, positively oriented), `adjacency` ((m, 4),
across the face opposite v[i]), `hull` ((h, 3) outward faces), `duplicate_of`, and for
lower-dimensional input `triangles` (coplanar) or `chain` (collinear).
Raises ValueError for empty input or NaN/Inf coordinates.)doc");

  m.def(
      "constrained_delaunay",
      [](py::handle points, py::handle constraints) -> py::object {
        const ArrayView v = view_array(points, "constrained_delaunay", "points", 2, {2});
        std::vector<std::uint32_t> flat =
            index_array(constraints, "constrained_delaunay", "constraints", 2, 2, v.rows);
        std::vector<std::array<std::uint32_t, 2>> edges(flat.size() / 2);
        for (std::size_t i = 0; i < edges.size(); ++i) edges[i] = {flat[2 * i], flat[2 * i + 1]};
        auto run = [&]<class T>(std::span<const Vec2<T>> p) -> py::object {
          ConstrainedDelaunay2Result r;
          {
            py::gil_scoped_release nogil;
            r = constrained_delaunay(p, std::span<const std::array<std::uint32_t, 2>>(edges));
          }
          if (r.status == Status::invalid_input && !r.rejected.empty()) {
            std::string list;
            for (std::size_t i = 0; i < r.rejected.size() && i < 8; ++i)
              list += (i ? ", " : "") + std::to_string(r.rejected[i]);
            if (r.rejected.size() > 8) list += ", ...";
            fail("constrained_delaunay",
                 "invalid_input: constraints [" + list +
                     "] properly cross earlier constraints or are out of range (rejected; "
                     "locus inserts no Steiner points)");
          }
          check_status(r.status, "constrained_delaunay");
          py::object out = new_result("ConstrainedDelaunayResult", r.status);
          out.attr("dimension") = r.dimension;
          out.attr("triangles") = to_numpy(std::move(r.triangles));
          out.attr("adjacency") = to_numpy(std::move(r.adjacency));
          out.attr("hull") = vector_out(std::move(r.hull));
          out.attr("duplicate_of") = vector_out(std::move(r.duplicate_of));
          out.attr("constrained") = to_numpy(std::move(r.constrained));
          out.attr("rejected") = vector_out(std::move(r.rejected));
          return out;
        };
        return v.is_float ? run(as_points<float, 2>(v)) : run(as_points<double, 2>(v));
      },
      py::arg("points"), py::arg("constraints"),
      R"doc(Constrained Delaunay triangulation of (n, 2) points with (k, 2) integer constraint
edges (indices into points).

ConstrainedDelaunayResult: `triangles` ((m, 3) uint32, CCW), `adjacency`, `hull`,
`duplicate_of`, `constrained` ((m, 3) uint8: 1 where edge (v[i], v[i+1]) lies on a constraint)
and `rejected` (indices of constraints that could not be inserted, e.g. crossing an earlier
one). Raises ValueError for empty input, NaN/Inf coordinates or out-of-range indices.)doc");
}

}  // namespace locus::python
