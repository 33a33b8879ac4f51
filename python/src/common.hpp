// SPDX-License-Identifier: BSL-1.0
#pragma once
// Shared machinery of the locus Python module: numpy arrays in (read in place when they are
// C-contiguous float32/float64, converted otherwise), numpy arrays out (the result's std::vector
// handed to numpy without a copy), Status -> ValueError, and the result objects (instances of
// small Python classes defined in module.cpp, fields set as attributes).
//
// Conventions (python/README.md): points are (n, 2) or (n, 3) arrays; float32 input runs the
// float instantiation, float64 the double one, integer input is converted to float64, anything
// else (complex, object, strings) is rejected. Every heavy call converts its inputs with the GIL
// held, then releases it (py::gil_scoped_release) while locus runs.

#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace locus::python {

namespace py = pybind11;

// Dense layout is what lets a C-contiguous (n, N) array be read as n Vec<T, N>.
static_assert(sizeof(Vec<double, 3>) == 3 * sizeof(double));
static_assert(sizeof(Vec<float, 2>) == 2 * sizeof(float));

/// Raises ValueError("locus.<fn>: <what>").
[[noreturn]] void fail(const char* fn, const std::string& what);

/// Raises ValueError with the status name and its meaning unless `s` is ok (or, when
/// `allow_limit`, limit_exceeded: a usable best-so-far result).
void check_status(Status s, const char* fn, bool allow_limit = true);

/// The result object of class `cls` (a Python class of the module) with its `status` set.
py::object new_result(const char* cls, Status s);

/// A C-contiguous array of float32 or float64 (the input itself when it already is one, else a
/// converted copy), checked for ndim and the trailing shape (-1: any; trailing[0] is the size of
/// axis 1, ...). `dims_allowed` lists acceptable sizes of the last axis when it is {2, 3}.
struct ArrayView {
  py::array array;  // keeps the data alive (the input or its converted copy)
  bool is_float = false;
  bool copied = false;
  std::size_t rows = 0;  // size of axis 0
  int last = 0;          // size of the last axis
};

ArrayView view_array(py::handle obj, const char* fn, const char* name, int ndim,
                     std::initializer_list<int> last_allowed, int middle = -1);

/// Rejects NaN and infinite entries with ValueError (batched queries: the library would give a
/// defined but meaningless answer for them).
template <class T>
void check_finite(const T* data, std::size_t count, const char* fn, const char* name) {
  for (std::size_t i = 0; i < count; ++i)
    if (!std::isfinite(data[i]))
      fail(fn, std::string("non_finite_input: ") + name +
                   " has a NaN or infinite coordinate (entry " + std::to_string(i) + ")");
}

template <class T, int N>
std::span<const Vec<T, N>> as_points(const ArrayView& v) {
  return {static_cast<const Vec<T, N>*>(v.array.data()), v.rows};
}

/// Calls f.template operator()<T, N>(span) for the (n, 2) or (n, 3) points in `obj` (finiteness
/// is left to the algorithm, which reports non_finite_input).
template <class F>
decltype(auto) with_points(py::handle obj, const char* fn, std::initializer_list<int> dims, F&& f) {
  const ArrayView v = view_array(obj, fn, "points", 2, dims);
  if (v.is_float) {
    if (v.last == 2) return f.template operator()<float, 2>(as_points<float, 2>(v));
    return f.template operator()<float, 3>(as_points<float, 3>(v));
  }
  if (v.last == 2) return f.template operator()<double, 2>(as_points<double, 2>(v));
  return f.template operator()<double, 3>(as_points<double, 3>(v));
}

/// Index arrays: (k, m) non-negative integers below `limit`, as uint32.
std::vector<std::uint32_t> index_array(py::handle obj, const char* fn, const char* name, int ndim,
                                       int cols, std::size_t limit);

/// A numpy array of `shape` owning `v`'s storage (no copy).
template <class T>
py::array to_numpy(std::vector<T>&& v, std::vector<py::ssize_t> shape) {
  auto* heap = new std::vector<T>(std::move(v));
  py::capsule owner(heap, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(shape, heap->data(), owner);
}

/// A numpy array of (k, 3) indices from a vector of index triples (no copy).
template <class I, std::size_t K>
py::array to_numpy(std::vector<std::array<I, K>>&& v) {
  static_assert(sizeof(std::array<I, K>) == K * sizeof(I));
  const auto rows = static_cast<py::ssize_t>(v.size());
  auto* heap = new std::vector<std::array<I, K>>(std::move(v));
  py::capsule owner(heap, [](void* p) { delete static_cast<std::vector<std::array<I, K>>*>(p); });
  return py::array_t<I>({rows, static_cast<py::ssize_t>(K)},
                        reinterpret_cast<const I*>(heap->data()), owner);
}

/// A fresh numpy vector holding the N coordinates of p.
template <class T, int N>
py::array vec_out(const Vec<T, N>& p) {
  py::array_t<T> a(N);
  for (int i = 0; i < N; ++i) a.mutable_data()[i] = p[i];
  return a;
}

// Registration of each area (one translation unit each).
void bind_hull(py::module_& m);
void bind_delaunay(py::module_& m);
void bind_triangulate(py::module_& m);
void bind_bounding(py::module_& m);
void bind_fit(py::module_& m);
void bind_numeric(py::module_& m);
void bind_containment(py::module_& m);
void bind_distance(py::module_& m);
void bind_gjk(py::module_& m);
void bind_intersection(py::module_& m);
void bind_svg(py::module_& m);
void bind_mesh(py::module_& m);
void bind_intersection3(py::module_& m);
void bind_intersection2(py::module_& m);
void bind_quadric3(py::module_& m);
void bind_surface_intersection(py::module_& m);
void bind_io(py::module_& m);
void bind_misc3(py::module_& m);

}  // namespace locus::python
