// SPDX-License-Identifier: BSL-1.0
// Batched squared distances (distance/batch.hpp): point-triangle, segment-segment,
// segment-triangle, point-box; one-to-many, many-to-one or pairwise.
#include "common.hpp"

#include <locus/distance/batch.hpp>

namespace locus::python {

namespace {

// One operand: `inner` points of 3 coordinates per element (1: point, 2: segment or box,
// 3: triangle); a single element or an array of them.
struct Operand {
  ArrayView view;
  bool single = false;
  std::size_t count = 0;
};

Operand operand(py::handle obj, const char* fn, const char* name, int inner) {
  py::array a = py::array::ensure(obj);
  if (!a) fail(fn, std::string(name) + " is not convertible to a numpy array");
  const int base = inner == 1 ? 1 : 2;
  const std::string want =
      inner == 1 ? "(3,) or (n, 3)"
                 : "(" + std::to_string(inner) + ", 3) or (n, " + std::to_string(inner) + ", 3)";
  if (a.ndim() != base && a.ndim() != base + 1)
    fail(fn, std::string(name) + " must have shape " + want);
  const bool single = a.ndim() == base;
  if (a.shape(a.ndim() - 1) != 3 || (inner > 1 && a.shape(a.ndim() - 2) != inner))
    fail(fn, std::string(name) + " must have shape " + want);
  Operand o;
  o.single = single;
  const py::ssize_t rows = single ? 1 : a.shape(0);
  py::array flat = a.reshape({rows, static_cast<py::ssize_t>(3 * inner)});
  o.view = view_array(flat, fn, name, 2, {3 * inner});
  o.count = o.view.rows;
  if (o.count == 0) fail(fn, std::string("empty_input: ") + name + " is empty");
  if (o.view.is_float)
    check_finite(static_cast<const float*>(o.view.array.data()), o.count * std::size_t(3 * inner),
                 fn, name);
  else
    check_finite(static_cast<const double*>(o.view.array.data()), o.count * std::size_t(3 * inner),
                 fn, name);
  return o;
}

template <template <class> class A, template <class> class B>
py::array batch(py::handle a_obj, py::handle b_obj, const char* fn, const char* an, int ai,
                const char* bn, int bi) {
  Operand a = operand(a_obj, fn, an, ai), b = operand(b_obj, fn, bn, bi);
  if (a.view.is_float != b.view.is_float)
    for (Operand* o : {&a, &b})
      if (o->view.is_float) {
        o->view.array =
            py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(o->view.array);
        o->view.is_float = false;
      }
  if (!a.single && !b.single && a.count != b.count)
    fail(fn, std::string(an) + " and " + bn +
                 " must have the same length (or one be single), got " + std::to_string(a.count) +
                 " and " + std::to_string(b.count));
  const std::size_t n = a.single ? b.count : a.count;
  auto run = [&]<class T>() -> py::array {
    py::array_t<T> out(static_cast<py::ssize_t>(n));
    const std::span<T> o(out.mutable_data(), n);
    const A<T>* pa = static_cast<const A<T>*>(a.view.array.data());
    const B<T>* pb = static_cast<const B<T>*>(b.view.array.data());
    {
      py::gil_scoped_release nogil;
      if (a.single && !b.single)
        sqr_distances(*pa, std::span<const B<T>>(pb, n), o);
      else if (!a.single && b.single)
        sqr_distances(std::span<const A<T>>(pa, n), *pb, o);
      else
        sqr_distances(std::span<const A<T>>(pa, n), std::span<const B<T>>(pb, n), o);
    }
    return out;
  };
  return a.view.is_float ? run.template operator()<float>() : run.template operator()<double>();
}

static_assert(sizeof(Triangle3<double>) == 9 * sizeof(double));
static_assert(sizeof(Segment3<float>) == 6 * sizeof(float));
static_assert(sizeof(AlignedBox3<double>) == 6 * sizeof(double));
static_assert(sizeof(OrientedBox3<float>) == 15 * sizeof(float));

}  // namespace

void bind_distance(py::module_& m) {
  m.def(
      "point_triangle_sqr_distances",
      [](py::handle points, py::handle triangles) {
        return batch<Vec3, Triangle3>(points, triangles, "point_triangle_sqr_distances", "points",
                                      1, "triangles", 3);
      },
      py::arg("points"), py::arg("triangles"),
      R"doc(Squared distances between points ((n, 3) or (3,)) and solid triangles ((n, 3, 3) or
(3, 3), rows v0, v1, v2): pairwise, or one against many. Returns an (n,) array of the inputs'
dtype (SIMD batch kernels, distance/batch.hpp).)doc");
  m.def(
      "segment_segment_sqr_distances",
      [](py::handle a, py::handle b) {
        return batch<Segment3, Segment3>(a, b, "segment_segment_sqr_distances", "a", 2, "b", 2);
      },
      py::arg("a"), py::arg("b"),
      R"doc(Squared distances between 3D segments ((n, 2, 3) or (2, 3), rows p0, p1): pairwise,
or one against many. Returns an (n,) array.)doc");
  m.def(
      "segment_triangle_sqr_distances",
      [](py::handle segments, py::handle triangles) {
        return batch<Segment3, Triangle3>(segments, triangles, "segment_triangle_sqr_distances",
                                          "segments", 2, "triangles", 3);
      },
      py::arg("segments"), py::arg("triangles"),
      R"doc(Squared distances between 3D segments ((n, 2, 3) or (2, 3)) and solid triangles
((n, 3, 3) or (3, 3)). Returns an (n,) array.)doc");
  m.def(
      "point_box_sqr_distances",
      [](py::handle points, py::handle boxes) {
        return batch<Vec3, AlignedBox3>(points, boxes, "point_box_sqr_distances", "points", 1,
                                        "boxes", 2);
      },
      py::arg("points"), py::arg("boxes"),
      R"doc(Squared distances between points ((n, 3) or (3,)) and solid axis-aligned boxes
((n, 2, 3) or (2, 3), rows min, max). Returns an (n,) array.)doc");
  m.def(
      "point_oriented_box_sqr_distances",
      [](py::handle points, py::handle boxes) {
        return batch<Vec3, OrientedBox3>(points, boxes, "point_oriented_box_sqr_distances",
                                         "points", 1, "boxes", 5);
      },
      py::arg("points"), py::arg("boxes"),
      R"doc(Squared distances between points ((n, 3) or (3,)) and solid oriented boxes
((n, 5, 3) or (5, 3), rows center, axis0, axis1, axis2 (unit, orthogonal), extent (half
sides)). Returns an (n,) array.)doc");
}

}  // namespace locus::python
