// SPDX-License-Identifier: BSL-1.0
// Exact relation of two solid ellipsoids (intersection/ellipsoid_ellipsoid.hpp): each ellipsoid
// as center (3,), axes (3, 3) (rows; independent, not necessarily unit) and extents (3,),
// converted to float64. Returns the relation's name ("separated", "touching", "overlapping",
// "a_contains_b", "b_contains_a", "a_contains_b_touching", "b_contains_a_touching", "equal", or
// "undecided" for non-positive extents or dependent axes); NaN or infinite entries raise
// ValueError.
#include "common.hpp"

#include <locus/intersection/ellipsoid_ellipsoid.hpp>

#include <string>

namespace locus::python {

namespace {

const char* relation_name(RegionRelation r) {
  switch (r) {
    case RegionRelation::separated:
      return "separated";
    case RegionRelation::touching:
      return "touching";
    case RegionRelation::overlapping:
      return "overlapping";
    case RegionRelation::a_contains_b:
      return "a_contains_b";
    case RegionRelation::b_contains_a:
      return "b_contains_a";
    case RegionRelation::a_contains_b_touching:
      return "a_contains_b_touching";
    case RegionRelation::b_contains_a_touching:
      return "b_contains_a_touching";
    case RegionRelation::equal:
      return "equal";
    case RegionRelation::undecided:
      break;
  }
  return "undecided";
}

/// A float64 array of the given shape ({3} or {3, 3}), finite, as its 3 or 9 values.
void fixed_arg(py::handle obj, const char* fn, const char* name, bool matrix, double* out) {
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(obj);
  const bool ok = a && (matrix ? (a.ndim() == 2 && a.shape(0) == 3 && a.shape(1) == 3)
                               : (a.ndim() == 1 && a.shape(0) == 3));
  if (!ok)
    fail(fn, std::string(name) + (matrix ? " must have shape (3, 3)" : " must have shape (3,)"));
  const std::size_t n = matrix ? 9 : 3;
  check_finite(a.data(), n, fn, name);
  for (std::size_t i = 0; i < n; ++i) out[i] = a.data()[i];
}

Ellipsoid3<double> ellipsoid_arg(py::handle center, py::handle axes, py::handle extents,
                                 const char* fn, const char* which) {
  double c[3], u[9], e[3];
  fixed_arg(center, fn, (std::string("center_") + which).c_str(), false, c);
  fixed_arg(axes, fn, (std::string("axes_") + which).c_str(), true, u);
  fixed_arg(extents, fn, (std::string("extents_") + which).c_str(), false, e);
  return {{c[0], c[1], c[2]},
          {{u[0], u[1], u[2]}, {u[3], u[4], u[5]}, {u[6], u[7], u[8]}},
          {e[0], e[1], e[2]}};
}

}  // namespace

void bind_ellipsoid_relation(py::module_& m) {
  m.def(
      "ellipsoid_relation",
      [](py::handle center_a, py::handle axes_a, py::handle extents_a, py::handle center_b,
         py::handle axes_b, py::handle extents_b) {
        const char* fn = "ellipsoid_relation";
        const Ellipsoid3<double> a = ellipsoid_arg(center_a, axes_a, extents_a, fn, "a");
        const Ellipsoid3<double> b = ellipsoid_arg(center_b, axes_b, extents_b, fn, "b");
        return std::string(relation_name(relation(a, b)));
      },
      py::arg("center_a"), py::arg("axes_a"), py::arg("extents_a"), py::arg("center_b"),
      py::arg("axes_b"), py::arg("extents_b"),
      "Exact relation of the solid ellipsoids sum_i (axes[i].(x - center))^2 / extents[i]^2 <= 1 "
      "(axes as rows, independent, taken as stored): 'separated', 'touching', 'overlapping', "
      "'a_contains_b', 'b_contains_a', 'a_contains_b_touching', 'b_contains_a_touching', "
      "'equal', or 'undecided' (non-positive extents, dependent axes). NaN or infinite entries "
      "raise ValueError.");
}

}  // namespace locus::python
