// SPDX-License-Identifier: BSL-1.0
// gjk_distance and penetration (GJK / EPA) between convex hulls of point sets
// (distance/gjk.hpp, distance/support.hpp).
#include "common.hpp"

#include <locus/distance/gjk.hpp>
#include <locus/distance/support.hpp>

namespace locus::python {

namespace {

const char* contact_name(Contact c) {
  switch (c) {
    case Contact::separated:
      return "separated";
    case Contact::touching:
      return "touching";
    case Contact::intersecting:
      return "intersecting";
  }
  return "unknown";
}

template <class T, int N>
py::array pair_out(const std::array<Vec<T, N>, 2>& c) {
  py::array_t<T> a({2, N});
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < N; ++j) a.mutable_data()[i * N + j] = c[static_cast<std::size_t>(i)][j];
  return a;
}

// Both operands as point sets of one dimension and scalar type; calls f<T, N>(a, b).
template <class F>
py::object with_two_sets(py::handle a_obj, py::handle b_obj, const char* fn, F&& f) {
  ArrayView a = view_array(a_obj, fn, "a", 2, {2, 3});
  ArrayView b = view_array(b_obj, fn, "b", 2, {2, 3});
  if (a.last != b.last) fail(fn, "a and b must have the same dimension (2 or 3 columns)");
  if (a.rows == 0 || b.rows == 0) fail(fn, "empty_input (a point set is empty)");
  if (a.is_float != b.is_float)
    for (ArrayView* v : {&a, &b})
      if (v->is_float) {
        v->array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(v->array);
        v->is_float = false;
      }
  if (a.is_float) {
    if (a.last == 2)
      return f.template operator()<float, 2>(as_points<float, 2>(a), as_points<float, 2>(b));
    return f.template operator()<float, 3>(as_points<float, 3>(a), as_points<float, 3>(b));
  }
  if (a.last == 2)
    return f.template operator()<double, 2>(as_points<double, 2>(a), as_points<double, 2>(b));
  return f.template operator()<double, 3>(as_points<double, 3>(a), as_points<double, 3>(b));
}

}  // namespace

void bind_gjk(py::module_& m) {
  m.def(
      "gjk_distance",
      [](py::handle a, py::handle b) -> py::object {
        return with_two_sets(a, b, "gjk_distance",
                             [&]<class T, int N>(std::span<const Vec<T, N>> pa,
                                                 std::span<const Vec<T, N>> pb) -> py::object {
                               GjkDistance<T, N> r;
                               {
                                 py::gil_scoped_release nogil;
                                 r = gjk_distance(ConvexPoints<T, N>{pa}, ConvexPoints<T, N>{pb});
                               }
                               check_status(r.status, "gjk_distance");
                               py::object out = new_result("GjkResult", r.status);
                               out.attr("contact") = contact_name(r.contact);
                               out.attr("distance") = static_cast<double>(r.distance);
                               out.attr("closest") = pair_out(r.closest);
                               out.attr("normal") = vec_out(r.normal);
                               out.attr("iterations") = r.iterations;
                               return out;
                             });
      },
      py::arg("a"), py::arg("b"),
      R"doc(Distance between the convex hulls of two point sets ((n, 2) or (m, 3), same
dimension) by GJK.

GjkResult: `contact` ('separated', 'touching' or 'intersecting'), `distance`, `closest`
((2, N): a point of each hull), `normal` (unit, from a towards b), `iterations`.)doc");

  m.def(
      "penetration",
      [](py::handle a, py::handle b) -> py::object {
        return with_two_sets(a, b, "penetration",
                             [&]<class T, int N>(std::span<const Vec<T, N>> pa,
                                                 std::span<const Vec<T, N>> pb) -> py::object {
                               Penetration<T, N> r;
                               {
                                 py::gil_scoped_release nogil;
                                 r = penetration(ConvexPoints<T, N>{pa}, ConvexPoints<T, N>{pb});
                               }
                               check_status(r.status, "penetration");
                               py::object out = new_result("PenetrationResult", r.status);
                               out.attr("contact") = contact_name(r.contact);
                               out.attr("depth") = static_cast<double>(r.depth);
                               out.attr("normal") = vec_out(r.normal);
                               out.attr("closest") = pair_out(r.closest);
                               out.attr("iterations") = r.iterations;
                               return out;
                             });
      },
      py::arg("a"), py::arg("b"),
      R"doc(Penetration depth of the convex hulls of two point sets (GJK, then EPA when they
overlap): the shortest translation of b along `normal` by `depth` that separates them.

PenetrationResult: `contact`, `depth` (0 when separated), `normal`, `closest` ((2, N)),
`iterations`.)doc");
}

}  // namespace locus::python
