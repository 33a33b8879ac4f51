// SPDX-License-Identifier: BSL-1.0
// read_points: CSV and XYZ point lists (io/point_list.hpp) as an (n, 2) or (n, 3) float64 array;
// read_wkt / read_geojson: the geometries of a WKT or GeoJSON text (io/wkt.hpp, io/geojson.hpp)
// as Geometry results (points, line strings and polygons as rings of float64 arrays).
#include "common.hpp"

#include <locus/io/geojson.hpp>
#include <locus/io/point_list.hpp>
#include <locus/io/wkt.hpp>

#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

namespace locus::python {

namespace {

py::array xy_rows(const Vec2<double>* p, std::size_t n) {
  std::vector<double> xy;
  xy.reserve(2 * n);
  for (std::size_t i = 0; i < n; ++i) xy.insert(xy.end(), {p[i].x, p[i].y});
  return to_numpy(std::move(xy), {static_cast<py::ssize_t>(n), py::ssize_t(2)});
}

/// The geometries of a parsed text as a list of Geometry results (ValueError on a bad text).
py::list geometries_of(GeometryReadResult<double>& r, bool orient, const char* fn) {
  if (r.status != Status::ok)
    fail(fn, std::string(to_string(r.status)) + (r.message.empty() ? "" : ": ") + r.message);
  py::list out;
  for (Geometry2<double>& g : r.geometries) {
    if (orient) orient_rings(g);
    py::object o = new_result("Geometry", Status::ok);
    o.attr("type") = py::str(wkt_name(g.type));
    o.attr("points") = xy_rows(g.points.data(), g.points.size());
    py::list lines, polygons;
    for (const auto& l : g.lines) lines.append(xy_rows(l.data(), l.size()));
    for (const auto& poly : g.polygons) {
      py::list rings;
      std::size_t begin = 0;
      for (const std::uint32_t end : poly.ring_ends) {
        rings.append(xy_rows(poly.points.data() + begin, end - begin));
        begin = end;
      }
      polygons.append(rings);
    }
    o.attr("lines") = lines;
    o.attr("polygons") = polygons;
    out.append(o);
  }
  return out;
}

constexpr const char* geometry_doc = R"doc(

Returns a list of Geometry results, one per geometry in text order (a GeometryCollection is
flattened into its members): type ('POINT', 'LINESTRING', 'POLYGON', 'MULTIPOINT',
'MULTILINESTRING', 'MULTIPOLYGON'), points ((n, 2) float64: POINT / MULTIPOINT), lines (list of
(k, 2) arrays) and polygons (list of polygons, each a list of rings as (k, 2) arrays: ring 0
the outer boundary, then the holes; the closing point is not repeated). Rings keep the
orientation written unless orient=True (outer counter-clockwise, holes clockwise, decided
exactly). z (and m) coordinates are dropped. Malformed text raises ValueError naming the status
(parse_error, non_finite_input, empty_input) and the line and column.)doc";

}  // namespace

void bind_io(py::module_& m) {
  m.def(
      "read_points",
      [](const std::string& path, int dimension, const std::string& format) -> py::array {
        const char* fn = "read_points";
        PointListFormat f = PointListFormat::from_extension;
        if (format == "csv")
          f = PointListFormat::csv;
        else if (format == "xyz")
          f = PointListFormat::xyz;
        else if (!format.empty())
          fail(fn, "invalid_input: unknown format '" + format + "' (csv, xyz)");
        if (f == PointListFormat::from_extension) f = point_list_format_from_name(path);
        if (f == PointListFormat::from_extension)
          fail(fn, "invalid_input: cannot tell the format from '" + path + "' (give format)");
        std::string bytes;
        {
          std::ifstream in(path, std::ios::binary);
          if (!in) fail(fn, "io_error: cannot open '" + path + "'");
          std::ostringstream ss;
          ss << in.rdbuf();
          bytes = ss.str();
        }
        if (dimension == 0) dimension = point_list_dimension(bytes, f);
        if (dimension != 2 && dimension != 3)
          fail(fn, "invalid_input: points must have 2 or 3 coordinates, the first data line has " +
                       std::to_string(dimension) + " fields");
        auto run = [&]<int N>() -> py::array {
          PointListReadResult<double, N> r;
          {
            py::gil_scoped_release nogil;
            r = parse_points<double, N>(bytes, f, path);
          }
          if (r.status != Status::ok)
            fail(fn,
                 std::string(to_string(r.status)) + (r.message.empty() ? "" : ": ") + r.message);
          std::vector<double> xyz;
          xyz.reserve(N * r.points.size());
          for (const auto& p : r.points)
            for (int k = 0; k < N; ++k) xyz.push_back(p[k]);
          const auto rows = static_cast<py::ssize_t>(r.points.size());
          return to_numpy(std::move(xyz), {rows, py::ssize_t(N)});
        };
        return dimension == 2 ? run.template operator()<2>() : run.template operator()<3>();
      },
      py::arg("path"), py::arg("dimension") = 0, py::arg("format") = "",
      R"doc(Reads a CSV (.csv .txt .tsv) or XYZ (.xyz) point list: (n, 2) or (n, 3) float64.

dimension: 2, 3, or 0 (the number of fields on the first data line). format: '' (from the
extension), 'csv' or 'xyz'. A header line (no numeric field) is skipped. Malformed files raise
ValueError('locus.read_points: parse_error: file:line: reason').)doc");

  m.def(
      "read_wkt",
      [](const std::string& text, bool orient) -> py::list {
        GeometryReadResult<double> r;
        {
          py::gil_scoped_release nogil;
          r = parse_wkt<double>(text);
        }
        return geometries_of(r, orient, "read_wkt");
      },
      py::arg("text"), py::arg("orient") = false,
      (std::string("Reads the geometries of a well-known text (OGC simple features; several may "
                   "follow each other,\nseparated by white space) (io/wkt.hpp).") +
       geometry_doc)
          .c_str());
  m.def(
      "read_geojson",
      [](const std::string& text, bool orient) -> py::list {
        GeometryReadResult<double> r;
        {
          py::gil_scoped_release nogil;
          r = parse_geojson<double>(text);
        }
        return geometries_of(r, orient, "read_geojson");
      },
      py::arg("text"), py::arg("orient") = false,
      (std::string("Reads the geometries of a GeoJSON text (RFC 7946: a FeatureCollection, a "
                   "Feature or a geometry)\n(io/geojson.hpp).") +
       geometry_doc)
          .c_str());
}

}  // namespace locus::python
