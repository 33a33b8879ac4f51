// SPDX-License-Identifier: BSL-1.0
// boolean(op, a, b, fill_rule, grid_bits): polygon booleans (boolean/polygon_boolean.hpp). Each
// operand is an (n, 2) ring or a list of (k, 2) rings, raw (self-intersections allowed), read
// under the fill rule; float32 runs the float instantiation only when every array is float32.
#include "boolean_result.hpp"
#include "common.hpp"

#include <locus/boolean/polygon_boolean.hpp>

#include <string>

namespace locus::python {

namespace {

std::vector<ArrayView> read_operand(py::handle rings, const char* fn, const char* name) {
  if (rings.is_none()) fail(fn, std::string(name) + " is None");
  std::vector<ArrayView> views;
  // A single (n, 2) array is one ring; otherwise a sequence of (k, 2) arrays (maybe empty).
  py::array probe = py::array::ensure(rings);
  if (probe && probe.ndim() == 2 && probe.dtype().kind() != 'O') {
    views.push_back(view_array(rings, fn, name, 2, {2}));
    return views;
  }
  if (!py::isinstance<py::sequence>(rings) || py::isinstance<py::str>(rings))
    fail(fn, std::string(name) + " must be an (n, 2) array or a list of (k, 2) arrays");
  const auto seq = py::reinterpret_borrow<py::sequence>(rings);
  for (std::size_t k = 0; k < seq.size(); ++k) {
    const std::string ring_name = std::string(name) + "[" + std::to_string(k) + "]";
    views.push_back(view_array(seq[k], fn, ring_name.c_str(), 2, {2}));
  }
  return views;
}

template <class T>
std::vector<Polygon2<T>> to_rings(const std::vector<ArrayView>& views) {
  std::vector<Polygon2<T>> rings;
  for (const ArrayView& v : views) {
    const auto a = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(v.array);
    const T* d = a.data();
    Polygon2<T> r;
    for (std::size_t i = 0; i < v.rows; ++i) r.vertices.push_back(Vec2<T>{d[2 * i], d[2 * i + 1]});
    rings.push_back(std::move(r));
  }
  return rings;
}

template <class T>
py::array ring_out(const Polygon2<T>& p) {
  py::array_t<T> a(std::vector<py::ssize_t>{static_cast<py::ssize_t>(p.vertices.size()), 2});
  T* d = a.mutable_data();
  for (std::size_t i = 0; i < p.vertices.size(); ++i) {
    d[2 * i] = p.vertices[i].x;
    d[2 * i + 1] = p.vertices[i].y;
  }
  return a;
}

template <class T>
py::object result_out(const BooleanResult<T>& r, const char* fn) {
  check_status(r.status, fn, false);
  py::object out = new_result("BooleanResult", r.status);
  py::list polygons;
  for (const auto& p : r.polygons) {
    py::list rings;
    rings.append(ring_out(p.outer));
    for (const auto& h : p.holes) rings.append(ring_out(h));
    polygons.append(rings);
  }
  out.attr("polygons") = polygons;
  out.attr("grid") = py::float_(r.grid);
  return out;
}

}  // namespace

py::object boolean_result_out(const BooleanResult<float>& r, const char* fn) {
  return result_out(r, fn);
}
py::object boolean_result_out(const BooleanResult<double>& r, const char* fn) {
  return result_out(r, fn);
}

void bind_boolean(py::module_& m) {
  m.def(
      "boolean",
      [](const std::string& op_name, py::handle a, py::handle b, const std::string& rule_name,
         int grid_bits) -> py::object {
        const char* fn = "boolean";
        BooleanOp op = BooleanOp::union_;
        if (op_name == "intersection")
          op = BooleanOp::intersection;
        else if (op_name == "difference")
          op = BooleanOp::difference;
        else if (op_name == "xor" || op_name == "symmetric_difference")
          op = BooleanOp::symmetric_difference;
        else if (op_name != "union")
          fail(fn,
               "op must be 'intersection', 'union', 'difference' or 'xor', not '" + op_name + "'");
        FillRule rule = FillRule::even_odd;
        if (rule_name == "non_zero")
          rule = FillRule::non_zero;
        else if (rule_name == "positive")
          rule = FillRule::positive;
        else if (rule_name != "even_odd")
          fail(fn,
               "fill_rule must be 'even_odd', 'non_zero' or 'positive', not '" + rule_name + "'");
        const std::vector<ArrayView> va = read_operand(a, fn, "a"), vb = read_operand(b, fn, "b");
        bool all_float = true;
        for (const auto* set : {&va, &vb})
          for (const ArrayView& v : *set) all_float = all_float && v.is_float;
        auto run = [&]<class T>() -> py::object {
          const std::vector<Polygon2<T>> ra = to_rings<T>(va), rb = to_rings<T>(vb);
          BooleanResult<T> r;
          {
            py::gil_scoped_release nogil;
            r = boolean_op<T>(op, ra, rb, {rule, grid_bits});
          }
          return boolean_result_out(r, fn);
        };
        return all_float && !(va.empty() && vb.empty()) ? run.template operator()<float>()
                                                        : run.template operator()<double>();
      },
      py::arg("op"), py::arg("a"), py::arg("b"), py::arg("fill_rule") = "even_odd",
      py::arg("grid_bits") = 0,
      R"doc(Boolean operation on two polygon sets: 'intersection', 'union', 'difference' (a - b), 'xor'.

a, b: an (n, 2) ring or a list of (k, 2) rings (closed implicitly, any orientation,
self-intersections allowed; an empty list is the empty set), each operand read under fill_rule:
'even_odd' (default: [outer, hole, ...] lists need no orientation), 'non_zero' or 'positive'.
Coordinates are snap rounded to the grid 2^-grid_bits times the largest coordinate's power of
two (grid_bits 0: 40 for float64, 24 for float32); every decision is exact.
BooleanResult: `polygons` (a list of polygons, each a list of (k, 2) rings: the outer ring
counter-clockwise, then its holes clockwise; always valid: simple rings, disjoint interiors) and
`grid` (the spacing used). Raises ValueError for NaN/Inf, a bad op, fill rule or grid_bits.)doc");
}

}  // namespace locus::python
