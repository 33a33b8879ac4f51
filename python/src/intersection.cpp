// SPDX-License-Identifier: BSL-1.0
// segment_intersections: the 2D segment-segment find query over arrays of pairs
// (intersection/segment_segment.hpp).
#include "common.hpp"

#include <locus/intersection/segment_segment.hpp>

#include <limits>

namespace locus::python {

void bind_intersection(py::module_& m) {
  py::tuple names(12);
  for (int k = 0; k < 12; ++k)
    names[static_cast<std::size_t>(k)] = py::str(std::string(to_string(static_cast<Kind>(k))));
  m.attr("KIND_NAMES") = names;

  m.def(
      "segment_intersections",
      [](py::handle a, py::handle b) -> py::object {
        const char* fn = "segment_intersections";
        auto segs = [&](py::handle obj, const char* name) {
          py::array arr = py::array::ensure(obj);
          if (!arr || arr.ndim() != 3 || arr.shape(1) != 2 || arr.shape(2) != 2)
            fail(fn, std::string(name) + " must have shape (n, 2, 2): n segments (p0, p1) in 2D");
          ArrayView v = view_array(arr.reshape({arr.shape(0), py::ssize_t(4)}), fn, name, 2, {4});
          if (v.is_float)
            check_finite(static_cast<const float*>(v.array.data()), 4 * v.rows, fn, name);
          else
            check_finite(static_cast<const double*>(v.array.data()), 4 * v.rows, fn, name);
          return v;
        };
        ArrayView va = segs(a, "a"), vb = segs(b, "b");
        if (va.rows != vb.rows)
          fail(fn, "a and b must hold the same number of segments, got " + std::to_string(va.rows) +
                       " and " + std::to_string(vb.rows));
        if (va.is_float != vb.is_float)
          for (ArrayView* v : {&va, &vb})
            if (v->is_float) {
              v->array =
                  py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(v->array);
              v->is_float = false;
            }
        const std::size_t n = va.rows;
        auto run = [&]<class T>() -> py::object {
          py::array_t<std::uint8_t> kind(static_cast<py::ssize_t>(n));
          py::array_t<std::int8_t> count(static_cast<py::ssize_t>(n));
          py::array_t<T> pts({static_cast<py::ssize_t>(n), py::ssize_t(2), py::ssize_t(2)});
          py::array_t<T> ta({static_cast<py::ssize_t>(n), py::ssize_t(2)});
          py::array_t<T> tb({static_cast<py::ssize_t>(n), py::ssize_t(2)});
          const auto* sa = static_cast<const Segment2<T>*>(va.array.data());
          const auto* sb = static_cast<const Segment2<T>*>(vb.array.data());
          std::uint8_t* k = kind.mutable_data();
          std::int8_t* c = count.mutable_data();
          T* p = pts.mutable_data();
          T* pa = ta.mutable_data();
          T* pb = tb.mutable_data();
          {
            py::gil_scoped_release nogil;
            for (std::size_t i = 0; i < n; ++i) {
              const LinearIntersection2<T> r = intersection(sa[i], sb[i]);
              k[i] = static_cast<std::uint8_t>(r.kind);
              c[i] = static_cast<std::int8_t>(r.count);
              for (int j = 0; j < 2; ++j) {
                const bool has = j < r.count;
                const auto u = static_cast<std::size_t>(j);
                const T nan = std::numeric_limits<T>::quiet_NaN();
                p[4 * i + 2 * u] = has ? r.point[u].x : nan;
                p[4 * i + 2 * u + 1] = has ? r.point[u].y : nan;
                pa[2 * i + u] = has ? r.param_a[u] : nan;
                pb[2 * i + u] = has ? r.param_b[u] : nan;
              }
            }
          }
          py::object out = new_result("SegmentIntersections", Status::ok);
          out.attr("kind") = kind;
          out.attr("count") = count;
          out.attr("points") = pts;
          out.attr("param_a") = ta;
          out.attr("param_b") = tb;
          return out;
        };
        return va.is_float ? run.template operator()<float>() : run.template operator()<double>();
      },
      py::arg("a"), py::arg("b"),
      R"doc(Intersections of n pairs of 2D segments a[i], b[i] (each (n, 2, 2): rows p0, p1),
decided exactly.

SegmentIntersections: `kind` (uint8 codes, names in locus.KIND_NAMES: 0 empty, 1 point,
3 segment (collinear overlap)), `count` (points filled: 0..2), `points` ((n, 2, 2), NaN where
unused), `param_a`, `param_b` ((n, 2): parameters t in [0, 1] of the points on a[i], b[i]).)doc");
}

}  // namespace locus::python
