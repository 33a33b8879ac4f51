// SPDX-License-Identifier: BSL-1.0
// polynomial_roots (numeric/roots.hpp).
#include "common.hpp"

#include <locus/numeric/roots.hpp>

#include <limits>

namespace locus::python {

void bind_numeric(py::module_& m) {
  m.def(
      "polynomial_roots",
      [](py::handle coefficients, double lo, double hi, bool exact) -> py::object {
        const ArrayView v = view_array(coefficients, "polynomial_roots", "coefficients", 1, {});
        auto run = [&]<class T>(std::span<const T> c) -> py::object {
          RealRootsResult<T> r;
          {
            py::gil_scoped_release nogil;
            RootOptions opt;
            opt.mode = exact ? RootMode::exact : RootMode::near;
            r = real_roots(c, static_cast<T>(lo), static_cast<T>(hi), opt);
          }
          check_status(r.status, "polynomial_roots");
          py::object out = new_result("RootsResult", r.status);
          py::array_t<T> roots(static_cast<py::ssize_t>(r.roots.size()));
          py::array_t<std::int32_t> mult(static_cast<py::ssize_t>(r.roots.size()));
          for (std::size_t i = 0; i < r.roots.size(); ++i) {
            roots.mutable_data()[i] = r.roots[i].value;
            mult.mutable_data()[i] = r.roots[i].multiplicity;
          }
          out.attr("roots") = roots;
          out.attr("multiplicities") = mult;
          return out;
        };
        if (v.is_float)
          return run(std::span<const float>(static_cast<const float*>(v.array.data()), v.rows));
        return run(std::span<const double>(static_cast<const double*>(v.array.data()), v.rows));
      },
      py::arg("coefficients"), py::arg("lo") = -std::numeric_limits<double>::infinity(),
      py::arg("hi") = std::numeric_limits<double>::infinity(), py::arg("exact") = true,
      R"doc(Distinct real roots in [lo, hi] of the polynomial with coefficients LOW TO HIGH
(c[0] + c[1] x + ...), increasing, with multiplicities.

exact=True (default): the roots of the coefficients as given, certified with exact arithmetic
and correctly rounded; exact=False: floating point (faster; roots within noise of a turning
point are reported as multiple). RootsResult: `roots`, `multiplicities` (int32).
Raises ValueError for NaN/Inf coefficients or the zero polynomial.)doc");
}

}  // namespace locus::python
