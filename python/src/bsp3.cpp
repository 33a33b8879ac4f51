// SPDX-License-Identifier: BSL-1.0
// mesh_boolean: union, intersection, difference and xor of two closed triangle meshes through their
// BSP trees (bsp/bsp3_boolean.hpp). Each mesh is a (vertices (n, 3), triangles (k, 3)) pair;
// float32 runs the float instantiation only when both vertex arrays are float32.
#include "common.hpp"

#include <locus/bsp/bsp3_boolean.hpp>

#include <string>

namespace locus::python {

namespace {

struct MeshIn {
  ArrayView v;
  std::vector<std::uint32_t> f;
};

MeshIn read_mesh_pair(py::handle pair, const char* fn, const char* name) {
  if (!py::isinstance<py::sequence>(pair) || py::isinstance<py::str>(pair) || py::len(pair) != 2)
    fail(fn, std::string(name) + " must be a pair (vertices (n, 3), triangles (k, 3))");
  const auto seq = py::reinterpret_borrow<py::sequence>(pair);
  MeshIn m;
  const std::string vn = std::string(name) + "[0]", tn = std::string(name) + "[1]";
  m.v = view_array(seq[0], fn, vn.c_str(), 2, {3});
  m.f = index_array(seq[1], fn, tn.c_str(), 2, 3, m.v.rows);
  return m;
}

template <class T>
std::vector<Vec3<T>> vertices_as(const ArrayView& v) {
  const auto a = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(v.array);
  const T* d = a.data();
  std::vector<Vec3<T>> out(v.rows);
  for (std::size_t i = 0; i < v.rows; ++i) out[i] = {d[3 * i], d[3 * i + 1], d[3 * i + 2]};
  return out;
}

std::span<const std::array<std::uint32_t, 3>> triangles_of(const std::vector<std::uint32_t>& f) {
  return {reinterpret_cast<const std::array<std::uint32_t, 3>*>(f.data()), f.size() / 3};
}

}  // namespace

void bind_bsp3(py::module_& m) {
  m.def(
      "mesh_boolean",
      [](std::string op, py::handle a, py::handle b) -> py::object {
        const char* fn = "mesh_boolean";
        MeshBooleanOp o;
        if (op == "union")
          o = MeshBooleanOp::union_;
        else if (op == "intersection")
          o = MeshBooleanOp::intersection;
        else if (op == "difference")
          o = MeshBooleanOp::difference;
        else if (op == "xor" || op == "symmetric_difference")
          o = MeshBooleanOp::symmetric_difference;
        else
          fail(fn, "op must be 'union', 'intersection', 'difference' or 'xor', not '" + op + "'");
        const MeshIn ma = read_mesh_pair(a, fn, "a"), mb = read_mesh_pair(b, fn, "b");
        auto run = [&]<class T>() -> py::object {
          const std::vector<Vec3<T>> va = vertices_as<T>(ma.v), vb = vertices_as<T>(mb.v);
          MeshBoolean<T> r;
          {
            py::gil_scoped_release nogil;
            r = mesh_boolean<T>(o, va, triangles_of(ma.f), vb, triangles_of(mb.f));
          }
          // An empty operand is the empty solid: its status is reported with the result.
          if (r.status != Status::empty_input && r.status != Status::degenerate_input)
            check_status(r.status, fn);
          py::object res = new_result("MeshBooleanResult", r.status);
          const auto n = static_cast<py::ssize_t>(r.vertices.size());
          std::vector<T> flat;
          flat.reserve(r.vertices.size() * 3);
          for (const auto& v : r.vertices) flat.insert(flat.end(), {v.x, v.y, v.z});
          res.attr("vertices") = to_numpy(std::move(flat), {n, 3});
          res.attr("triangles") = to_numpy(std::move(r.triangles));
          return res;
        };
        if (ma.v.is_float && mb.v.is_float) return run.template operator()<float>();
        return run.template operator()<double>();
      },
      py::arg("op"), py::arg("a"), py::arg("b"),
      "Union, intersection, difference (a minus b) or xor (symmetric difference; also\n"
      "'symmetric_difference') of two closed triangle meshes with outward normals, each a pair\n"
      "(vertices (n, 3), triangles (k, 3)), through their BSP trees (bsp/bsp3_boolean.hpp).\n"
      "Returns MeshBooleanResult: status, vertices (m, 3), triangles (t, 3), outward; every\n"
      "constructed vertex shared by provenance, no T-junctions: each edge used once in each\n"
      "direction for generic inputs (xor: parts touch along the intersection curve). An empty\n"
      "operand is the empty solid (status 'empty_input' or 'degenerate_input', result still\n"
      "given); NaN or out-of-range indices raise ValueError.");
}

}  // namespace locus::python
