// SPDX-License-Identifier: BSL-1.0
// offset(region, delta, ...) and offset_polyline(paths, delta, ...): polygon offsetting and
// polyline buffering (boolean/polygon_offset.hpp). A region is an (n, 2) ring, a list of rings
// (outer then holes) or a list of such lists (a multipolygon, as BooleanResult.polygons); float32
// runs the float instantiation only when every array is float32.
#include "boolean_result.hpp"
#include "common.hpp"

#include <locus/boolean/polygon_offset.hpp>

#include <string>

namespace locus::python {

namespace {

bool is_ring(py::handle obj) {
  const py::array probe = py::array::ensure(obj);
  return probe && probe.ndim() == 2 && probe.dtype().kind() != 'O';
}

/// The rings of each polygon of the region (ring 0 outer).
std::vector<std::vector<ArrayView>> read_region(py::handle region, const char* fn) {
  std::vector<std::vector<ArrayView>> polygons;
  if (region.is_none()) fail(fn, "region is None");
  if (is_ring(region)) {
    polygons.push_back({view_array(region, fn, "region", 2, {2})});
    return polygons;
  }
  if (!py::isinstance<py::sequence>(region) || py::isinstance<py::str>(region))
    fail(fn, "region must be an (n, 2) ring, a list of rings or a list of lists of rings");
  const auto seq = py::reinterpret_borrow<py::sequence>(region);
  std::vector<ArrayView> one;
  for (std::size_t k = 0; k < seq.size(); ++k) {
    const std::string name = "region[" + std::to_string(k) + "]";
    if (is_ring(seq[k])) {
      one.push_back(view_array(seq[k], fn, name.c_str(), 2, {2}));
      continue;
    }
    if (!py::isinstance<py::sequence>(seq[k]))
      fail(fn, name + " must be an (n, 2) ring or a list of rings");
    const auto rings = py::reinterpret_borrow<py::sequence>(seq[k]);
    std::vector<ArrayView> poly;
    for (std::size_t j = 0; j < rings.size(); ++j) {
      const std::string ring = name + "[" + std::to_string(j) + "]";
      poly.push_back(view_array(rings[j], fn, ring.c_str(), 2, {2}));
    }
    if (!poly.empty()) polygons.push_back(std::move(poly));
  }
  if (!one.empty()) {
    if (!polygons.empty()) fail(fn, "region mixes rings and lists of rings");
    polygons.push_back(std::move(one));
  }
  return polygons;
}

std::vector<ArrayView> read_paths(py::handle paths, const char* fn) {
  if (paths.is_none()) fail(fn, "paths is None");
  if (is_ring(paths)) return {view_array(paths, fn, "paths", 2, {2})};
  if (!py::isinstance<py::sequence>(paths) || py::isinstance<py::str>(paths))
    fail(fn, "paths must be an (n, 2) array or a list of (k, 2) arrays");
  const auto seq = py::reinterpret_borrow<py::sequence>(paths);
  std::vector<ArrayView> views;
  for (std::size_t k = 0; k < seq.size(); ++k) {
    const std::string name = "paths[" + std::to_string(k) + "]";
    views.push_back(view_array(seq[k], fn, name.c_str(), 2, {2}));
  }
  return views;
}

template <class T>
std::vector<Vec2<T>> points_of(const ArrayView& v) {
  const auto a = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(v.array);
  const T* d = a.data();
  std::vector<Vec2<T>> pts;
  for (std::size_t i = 0; i < v.rows; ++i) pts.push_back(Vec2<T>{d[2 * i], d[2 * i + 1]});
  return pts;
}

OffsetOptions options_of(const char* fn, const std::string& join, const std::string& end,
                         double miter_limit, double arc_tolerance, int grid_bits) {
  OffsetOptions o;
  if (join == "miter" || join == "mitre")
    o.join = JoinType::miter;
  else if (join == "square")
    o.join = JoinType::square;
  else if (join != "round")
    fail(fn, "join must be 'round', 'miter' or 'square', not '" + join + "'");
  if (end == "butt" || end == "flat")
    o.end = EndType::butt;
  else if (end == "square")
    o.end = EndType::square;
  else if (end != "round")
    fail(fn, "end must be 'round', 'square' or 'butt', not '" + end + "'");
  o.miter_limit = miter_limit;
  o.arc_tolerance = arc_tolerance;
  o.grid_bits = grid_bits;
  return o;
}

}  // namespace

void bind_offset(py::module_& m) {
  m.def(
      "offset",
      [](py::handle region, double delta, const std::string& join, double miter_limit,
         double arc_tolerance, int grid_bits) -> py::object {
        const char* fn = "offset";
        const OffsetOptions o =
            options_of(fn, join, "round", miter_limit, arc_tolerance, grid_bits);
        const auto polys = read_region(region, fn);
        bool all_float = !polys.empty();
        for (const auto& p : polys)
          for (const ArrayView& v : p) all_float = all_float && v.is_float;
        auto run = [&]<class T>() -> py::object {
          MultiPolygon2<T> mp;
          for (const auto& p : polys) {
            PolygonWithHoles2<T> q{{points_of<T>(p[0])}, {}};
            for (std::size_t k = 1; k < p.size(); ++k) q.holes.push_back({points_of<T>(p[k])});
            mp.push_back(std::move(q));
          }
          OffsetResult<T> r;
          {
            py::gil_scoped_release nogil;
            r = offset(mp, static_cast<T>(delta), o);
          }
          return boolean_result_out(r, fn);
        };
        return all_float ? run.template operator()<float>() : run.template operator()<double>();
      },
      py::arg("region"), py::arg("delta"), py::arg("join") = "round", py::arg("miter_limit") = 2.0,
      py::arg("arc_tolerance") = 0.0, py::arg("grid_bits") = 0,
      R"doc(Inflate (delta > 0) or deflate (delta < 0) a polygon region by |delta|.

region: an (n, 2) ring, a list of rings (outer, then holes) or a list of such lists (a
multipolygon, e.g. BooleanResult.polygons); any orientation, overlapping members unite.
join: 'round' (chords inscribed in the arc, gap <= arc_tolerance, default |delta| / 1000),
'miter' (the offset edges extended while the miter length is <= miter_limit |delta|, square
beyond) or 'square' (cut at |delta| along the corner's bisector).
Returns BooleanResult: `polygons` (lists of rings, outer counter-clockwise then holes clockwise,
always valid; empty when the region vanishes) and `grid` (the snap-rounding spacing).
Raises ValueError for NaN/Inf, miter_limit < 1, arc_tolerance < 0 or a bad grid_bits.)doc");
  m.def(
      "offset_polyline",
      [](py::handle paths, double delta, const std::string& join, const std::string& end,
         bool closed, double miter_limit, double arc_tolerance, int grid_bits) -> py::object {
        const char* fn = "offset_polyline";
        const OffsetOptions o = options_of(fn, join, end, miter_limit, arc_tolerance, grid_bits);
        const std::vector<ArrayView> views = read_paths(paths, fn);
        bool all_float = !views.empty();
        for (const ArrayView& v : views) all_float = all_float && v.is_float;
        auto run = [&]<class T>() -> py::object {
          std::vector<Polyline<T, 2>> lines;
          for (const ArrayView& v : views) lines.push_back({points_of<T>(v), closed});
          OffsetResult<T> r;
          {
            py::gil_scoped_release nogil;
            r = offset_polylines(lines, static_cast<T>(delta), o);
          }
          return boolean_result_out(r, fn);
        };
        return all_float ? run.template operator()<float>() : run.template operator()<double>();
      },
      py::arg("paths"), py::arg("delta"), py::arg("join") = "round", py::arg("end") = "round",
      py::arg("closed") = false, py::arg("miter_limit") = 2.0, py::arg("arc_tolerance") = 0.0,
      py::arg("grid_bits") = 0,
      R"doc(The set within |delta| of one or more polylines (the sign of delta is ignored).

paths: an (n, 2) array or a list of (k, 2) arrays; closed: every path is a closed loop (joins at
every vertex, no ends). join as in offset(); end: 'round' (half disc), 'square' (extended by
|delta|) or 'butt' (flat). A single point gives a disc, a square or nothing.
Returns BooleanResult (polygons, grid) as offset() does.)doc");
}

}  // namespace locus::python
