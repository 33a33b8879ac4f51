// SPDX-License-Identifier: BSL-1.0
// The locus module: shared conversions (common.hpp) and the registration of every area.
#include "common.hpp"

#include <pybind11/eval.h>
#include <pybind11/stl.h>

#include <string_view>

namespace locus::python {

void bind_sat2(py::module_& m);                // python/src/sat2.cpp
void bind_sat3(py::module_& m);                // python/src/sat3.cpp
void bind_construction(py::module_& m);        // construction.cpp
void bind_partition(py::module_& m);           // partition.cpp
void bind_curve_intersection(py::module_& m);  // curve_intersection.cpp
void bind_boolean(py::module_& m);             // boolean.cpp
void bind_offset(py::module_& m);              // offset.cpp
void bind_bsp3(py::module_& m);                // bsp3.cpp
void bind_ellipsoid_relation(py::module_& m);  // ellipsoid_relation.cpp
void bind_planar_pieces(py::module_& m);       // planar_pieces.cpp

namespace {

py::handle g_module;  // the module (borrowed: it lives as long as the interpreter), set at import

const char* status_meaning(Status s) {
  switch (s) {
    case Status::ok:
      return "the result is valid";
    case Status::empty_input:
      return "nothing to work on (no points)";
    case Status::degenerate_input:
      return "the input lacks the dimension or rank the algorithm needs";
    case Status::non_finite_input:
      return "a coordinate or coefficient is NaN or infinite";
    case Status::invalid_topology:
      return "the input violates a structural precondition";
    case Status::invalid_input:
      return "values violate a documented precondition";
    case Status::parse_error:
      return "malformed file or text";
    case Status::io_error:
      return "a file could not be opened, read or written";
    case Status::limit_exceeded:
      return "an iteration or size budget ran out";
  }
  return "unknown status";
}

// The result classes: plain Python classes whose instances carry the fields as attributes
// (documented in locus.pyi and python/README.md). Defined in Python so that they print, compare
// and pickle (Dask ships results between processes) like ordinary objects.
constexpr const char* kResultClasses = R"PY(
class Result:
    """Result of a locus algorithm: `status` ('ok' or 'limit_exceeded') and numpy fields."""
    def __repr__(self):
        fields = ", ".join(f"{k}={v!r}" for k, v in self.__dict__.items())
        return f"{type(self).__name__}({fields})"
    def __eq__(self, other):
        import numpy as _np
        if type(self) is not type(other) or self.__dict__.keys() != other.__dict__.keys():
            return NotImplemented
        return all(_np.array_equal(v, other.__dict__[k]) for k, v in self.__dict__.items())
    __hash__ = None

def _make(name, doc):
    globals()[name] = type(name, (Result,), {"__doc__": doc, "__module__": "locus"})

for _name, _doc in [
    ("Hull2Result", "convex_hull of (n, 2) points: dimension, indices (CCW hull vertices)."),
    ("Hull3Result", "convex_hull of (n, 3) points: dimension, triangles, vertices, polygon."),
    ("Delaunay2Result", "delaunay of (n, 2) points: dimension, triangles, adjacency, hull, "
                        "duplicate_of."),
    ("Delaunay3Result", "delaunay of (n, 3) points: dimension, tetrahedra, adjacency, hull, "
                        "duplicate_of, triangles, chain."),
    ("ConstrainedDelaunayResult", "constrained_delaunay: dimension, triangles, adjacency, hull, "
                                  "duplicate_of, constrained, rejected."),
    ("TriangulationResult", "triangulate_polygon: triangles (indices into points, CCW)."),
    ("TrapezoidMapResult", "trapezoid_map: trapezoids (bottom, top, left, right; -1 unbounded), "
                           "located."),
    ("Construction", "construct: circles (k, 3), lines (m, 4), infinite; apollonius: signs."),
    ("MinCircleResult", "min_circle: center, radius, support."),
    ("MinSphereResult", "min_sphere: center, radius, support."),
    ("MinRectResult", "min_rect: center, axes (rows), extents (half sides), area, perimeter, "
                      "edge."),
    ("MinBoxResult", "min_box: center, axes (rows), extents (half sides), volume, certified."),
    ("LineFitResult", "fit_line: origin, direction (unit), rms."),
    ("PlaneFitResult", "fit_plane: normal (unit), constant (dot(normal, x) = constant), rms."),
    ("SphereFitResult", "fit_circle / fit_sphere: center, radius, rms, iterations."),
    ("GaussianFitResult", "fit_gaussian: mean, covariance, axes (rows), extents, rms."),
    ("RootsResult", "polynomial_roots: roots (increasing), multiplicities."),
    ("GjkResult", "gjk_distance: contact, distance, closest (2, N), normal, iterations."),
    ("PenetrationResult", "penetration: contact, depth, normal, closest (2, N), iterations."),
    ("SegmentIntersections", "segment_intersections: kind, count, points, param_a, param_b."),
    ("MeshCheck", "check_mesh: kind, closed, manifold, orientable, convex, euler_characteristic, "
                  "counts, boundary_edges, non_manifold_edges / _vertices, isolated_vertices, "
                  "components, face_component, self_intersections, degenerate_faces, "
                  "non_planar_faces."),
    ("MeshSlice", "slice_mesh: polylines (list of (k, 3) arrays), closed (bool per polyline)."),
    ("OrientationResult", "orient_consistently: faces, flipped, orientable, face_component, "
                          "non_orientable_components."),
    ("RayHits", "ray_triangle_hits: hit, t, triangle, barycentric, point, front."),
    ("BoxHits", "ray_box_hits / segment_box_hits: hit, t_enter, t_exit."),
    ("ConvexIntersection", "convex_polygon_intersection: kind, vertices (k, 2)."),
    ("Contact", "first_contact: kind, time, points (k, 2)."),
    ("Contact3", "sat3_first_contact: kind, time, points (k, 3)."),
    ("SurfaceHits", "ray_quadric_hits / ray_torus_hits: count, t, points, normals, uv, "
                    "multiplicity, on_surface."),
    ("PatchHits", "ray_surface_hits: ray, t, uv, points, normals, tangent, on_surface."),
    ("PatchCurves", "plane_surface_curves: points, uv, closed."),
    ("Geometry", "read_wkt / read_geojson: type, points (n, 2), lines, polygons (lists of rings)."),
    ("PatchHermite", "plane_surface_hermite: points, uv, tangents, uv_tangents, closed, "
                     "curve_points, curve_uv."),
    ("CurveIntersections", "circle_circle / segment_circle: kind, count, points, multiplicity."),
    ("BspPartition", "bsp_partition: pieces (k, 2, 2), location, segment."),
    ("BspBoolean", "bsp_boolean: edges (k, 2, 2), operand, loops, closed, segments, points."),
    ("CurveHits", "line_curve_hits / curve_intersections: kind, points (k, 2), param_a, "
                  "param_b, multiplicity."),
    ("BooleanResult", "boolean, offset, offset_polyline: polygons (lists of rings: outer CCW, "
                      "holes CW), grid."),
    ("MeshBooleanResult", "mesh_boolean: vertices (m, 3), triangles (t, 3)."),
    ("PlanarPieces", "planar_polygon_pieces: kind (1 point, 2 segment), t (k, 2), points "
                     "(k, 2, 3), st (k, 2, 2)."),
]:
    _make(_name, _doc)
del _name, _doc, _make

class ConvexPartitionResult(Result):
    """convex_partition: points, vertices, piece_ends, diagonals; pieces (index arrays)."""
    __module__ = "locus"
    @property
    def pieces(self):
        return [self.vertices[s:e] for s, e in zip([0, *self.piece_ends[:-1]], self.piece_ends)]
)PY";

}  // namespace

void fail(const char* fn, const std::string& what) {
  throw py::value_error(std::string("locus.") + fn + ": " + what);
}

void check_status(Status s, const char* fn, bool allow_limit) {
  if (s == Status::ok || (allow_limit && s == Status::limit_exceeded)) return;
  fail(fn, std::string(to_string(s)) + " (" + status_meaning(s) + ")");
}

py::object new_result(const char* cls, Status s) {
  py::object r = g_module.attr(cls)();
  r.attr("status") = py::str(std::string(to_string(s)));
  return r;
}

ArrayView view_array(py::handle obj, const char* fn, const char* name, int ndim,
                     std::initializer_list<int> last_allowed, int middle) {
  ArrayView v;
  if (obj.is_none()) fail(fn, std::string(name) + " is None");
  py::array a = py::array::ensure(obj);
  if (!a) fail(fn, std::string(name) + " is not convertible to a numpy array");
  const char kind = a.dtype().kind();
  const py::dtype dt = a.dtype();
  const bool native = dt.byteorder() == '=' || dt.byteorder() == '|' ||
                      (dt.byteorder() == '<') == (py::dtype::of<double>().byteorder() != '>');
  const bool is_f32 = kind == 'f' && dt.itemsize() == 4;
  const bool is_f64 = kind == 'f' && dt.itemsize() == 8;
  if (!is_f32 && !is_f64 && kind != 'i' && kind != 'u' && kind != 'f')
    fail(fn, std::string(name) + " must hold real numbers (float32 or float64), not dtype " +
                 std::string(py::str(a.dtype())));
  if (a.ndim() != ndim) {
    std::string want = "(n";
    for (int i = 1; i < ndim; ++i) want += ", k";
    fail(fn, std::string(name) + " must be a " + std::to_string(ndim) + "-d array " + want +
                 (ndim == 1 ? ",)" : ")") + ", got an array with ndim " + std::to_string(a.ndim()));
  }
  auto shape_str = [&] {
    std::string s = "(";
    for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
    return s + (a.ndim() == 1 ? ",)" : ")");
  };
  const int last = static_cast<int>(a.shape(ndim - 1));
  bool ok = false;
  std::string allowed;
  for (int d : last_allowed) {
    ok = ok || d == last;
    allowed += (allowed.empty() ? "" : " or ") + std::to_string(d);
  }
  if (ndim > 1 && last_allowed.size() > 0 && !ok)
    fail(fn, std::string(name) + " must have " + allowed + " columns, got shape " + shape_str());
  if (ndim == 3 && middle >= 0 && a.shape(1) != middle)
    fail(fn, std::string(name) + " must have shape (n, " + std::to_string(middle) + ", " + allowed +
                 "), got " + shape_str());
  v.is_float = is_f32;
  const bool contiguous = (a.flags() & py::array::c_style) != 0;
  if ((is_f32 || is_f64) && contiguous && native) {
    v.array = a;
  } else {
    v.copied = true;
    if (is_f32)
      v.array = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(a);
    else
      v.array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!v.array) fail(fn, std::string("cannot convert ") + name + " to a float array");
  }
  v.rows = static_cast<std::size_t>(a.shape(0));
  v.last = last;
  return v;
}

std::vector<std::uint32_t> index_array(py::handle obj, const char* fn, const char* name, int ndim,
                                       int cols, std::size_t limit) {
  py::array a = py::array::ensure(obj);
  if (!a) fail(fn, std::string(name) + " is not convertible to a numpy array");
  const char kind = a.dtype().kind();
  if (a.size() > 0 && kind != 'i' && kind != 'u')
    fail(fn,
         std::string(name) + " must hold integers, not dtype " + std::string(py::str(a.dtype())));
  if (a.ndim() != ndim || (ndim == 2 && a.shape(1) != cols))
    fail(fn, std::string(name) + " must have shape " +
                 (ndim == 1 ? std::string("(k,)") : "(k, " + std::to_string(cols) + ")"));
  auto i64 = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
  std::vector<std::uint32_t> out(static_cast<std::size_t>(i64.size()));
  const std::int64_t* d = i64.data();
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (d[i] < 0 || static_cast<std::uint64_t>(d[i]) >= limit)
      fail(fn, std::string(name) + " entry " + std::to_string(i) + " = " + std::to_string(d[i]) +
                   " is not an index below " + std::to_string(limit));
    out[i] = static_cast<std::uint32_t>(d[i]);
  }
  return out;
}

}  // namespace locus::python

PYBIND11_MODULE(locus, m) {
  using namespace locus::python;
  g_module = m;
  m.doc() =
      "locus: robust geometric algorithms (Geometric Tools for Computer Graphics) for numpy.\n\n"
      "Points are (n, 2) or (n, 3) float64/float32 arrays, read in place when C-contiguous.\n"
      "Algorithms return a Result object (status 'ok' or 'limit_exceeded' plus numpy fields);\n"
      "a bad status raises ValueError with the library's status and its meaning. Batched\n"
      "queries return numpy arrays. The GIL is released during every heavy call.";
  m.attr("__version__") = "0.1.0";
  py::exec(kResultClasses, m.attr("__dict__"));
  m.def(
      "_input_address",
      [](py::handle points) {
        const ArrayView v = view_array(points, "_input_address", "points", 2, {2, 3});
        return py::make_tuple(reinterpret_cast<std::uintptr_t>(v.array.data()), v.copied);
      },
      py::arg("points"),
      "Debug aid: (address locus reads the points from, whether they were copied) for an "
      "(n, 2)/(n, 3) array, through the same conversion every function uses.");
  bind_hull(m);
  bind_delaunay(m);
  bind_triangulate(m);
  bind_bounding(m);
  bind_fit(m);
  bind_numeric(m);
  bind_containment(m);
  bind_distance(m);
  bind_gjk(m);
  bind_intersection(m);
  bind_svg(m);
  bind_mesh(m);
  bind_intersection3(m);
  bind_intersection2(m);
  bind_construction(m);
  bind_quadric3(m);
  bind_surface_intersection(m);
  bind_io(m);
  bind_misc3(m);
  bind_sat2(m);
  bind_sat3(m);
  bind_partition(m);
  bind_curve_intersection(m);
  bind_boolean(m);
  bind_offset(m);
  bind_bsp3(m);
  bind_ellipsoid_relation(m);
  bind_planar_pieces(m);
}
