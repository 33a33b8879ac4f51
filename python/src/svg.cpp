// SPDX-License-Identifier: BSL-1.0
// SvgWriter: a small wrapper of the SVG writer (io/svg.hpp) for 2D drawings; style keywords
// map to SvgStyle fields.
#include "common.hpp"

#include <locus/io/svg.hpp>

#include <pybind11/stl.h>

namespace locus::python {

namespace {

SvgStyle style_from(const py::kwargs& kw) {
  SvgStyle s;
  for (auto item : kw) {
    const std::string key = py::str(item.first);
    py::handle v = item.second;
    if (key == "stroke")
      s.stroke = py::str(v);
    else if (key == "fill")
      s.fill = py::str(v);
    else if (key == "width")
      s.width = v.cast<double>();
    else if (key == "opacity")
      s.opacity = v.cast<double>();
    else if (key == "fill_opacity")
      s.fill_opacity = v.cast<double>();
    else if (key == "marker_size")
      s.marker_size = v.cast<double>();
    else if (key == "font_size")
      s.font_size = v.cast<double>();
    else if (key == "dash")
      s.dash = v.cast<std::vector<double>>();
    else
      fail("SvgWriter", "unknown style keyword '" + key +
                            "' (stroke, fill, width, opacity, fill_opacity, marker_size, "
                            "font_size, dash)");
  }
  return s;
}

Vec2d point2(py::handle obj, const char* fn) {
  py::array_t<double, py::array::c_style | py::array::forcecast> a =
      py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(obj);
  if (!a || a.ndim() != 1 || a.shape(0) != 2) fail(fn, "a point must have shape (2,)");
  return {a.data()[0], a.data()[1]};
}

std::vector<Vec2d> points2(py::handle obj, const char* fn) {
  const ArrayView v = view_array(obj, fn, "points", 2, {2});
  std::vector<Vec2d> out(v.rows);
  for (std::size_t i = 0; i < v.rows; ++i)
    out[i] = v.is_float ? vec_cast<double>(as_points<float, 2>(v)[i]) : as_points<double, 2>(v)[i];
  return out;
}

}  // namespace

void bind_svg(py::module_& m) {
  const char* style_doc =
      " Style keywords: stroke, fill (colours, 'none' for nothing), width, opacity, "
      "fill_opacity, marker_size, font_size, dash (list of pixel lengths).";
  py::class_<SvgWriter>(m, "SvgWriter",
                        "SVG drawing of 2D geometry (io/svg.hpp): world coordinates, y up, fitted "
                        "into max_width x max_height pixels plus margins.")
      .def(py::init([](double max_width, double max_height, double margin, std::string background,
                       std::string title) {
             SvgOptions o;
             o.max_width = max_width;
             o.max_height = max_height;
             o.margin = margin;
             o.background = std::move(background);
             o.title = std::move(title);
             return SvgWriter(std::move(o));
           }),
           py::arg("max_width") = 480.0, py::arg("max_height") = 480.0, py::arg("margin") = 24.0,
           py::arg("background") = "white", py::arg("title") = "", "A new, empty drawing.")
      .def(
          "set_view",
          [](SvgWriter& w, py::handle lo, py::handle hi) {
            w.set_view(point2(lo, "SvgWriter.set_view"), point2(hi, "SvgWriter.set_view"));
          },
          py::arg("lo"), py::arg("hi"), "Fixes the world window (default: fitted to the items).")
      .def(
          "point",
          [](SvgWriter& w, py::handle p, const py::kwargs& kw) {
            w.point(point2(p, "SvgWriter.point"), style_from(kw));
          },
          py::arg("p"), (std::string("A point marker.") + style_doc).c_str())
      .def(
          "points",
          [](SvgWriter& w, py::handle pts, const py::kwargs& kw) {
            const SvgStyle s = style_from(kw);
            for (const Vec2d& p : points2(pts, "SvgWriter.points")) w.point(p, s);
          },
          py::arg("points"), "A marker at each row of an (n, 2) array.")
      .def(
          "segment",
          [](SvgWriter& w, py::handle a, py::handle b, const py::kwargs& kw) {
            w.segment(point2(a, "SvgWriter.segment"), point2(b, "SvgWriter.segment"),
                      style_from(kw));
          },
          py::arg("a"), py::arg("b"), "A segment from a to b.")
      .def(
          "polyline",
          [](SvgWriter& w, py::handle pts, bool closed, const py::kwargs& kw) {
            w.polyline(points2(pts, "SvgWriter.polyline"), style_from(kw), closed);
          },
          py::arg("points"), py::arg("closed") = false, "A polyline through (n, 2) points.")
      .def(
          "polygon",
          [](SvgWriter& w, py::handle pts, const py::kwargs& kw) {
            w.polygon(points2(pts, "SvgWriter.polygon"), style_from(kw));
          },
          py::arg("points"), "A filled polygon with (n, 2) vertices.")
      .def(
          "triangles",
          [](SvgWriter& w, py::handle pts, py::handle tris, const py::kwargs& kw) {
            const std::vector<Vec2d> p = points2(pts, "SvgWriter.triangles");
            const std::vector<std::uint32_t> t =
                index_array(tris, "SvgWriter.triangles", "triangles", 2, 3, p.size());
            const SvgStyle s = style_from(kw);
            for (std::size_t i = 0; i + 2 < t.size(); i += 3) {
              const std::vector<Vec2d> ring = {p[t[i]], p[t[i + 1]], p[t[i + 2]]};
              w.polygon(ring, s);
            }
          },
          py::arg("points"), py::arg("triangles"),
          "Each triangle (rows of a (k, 3) index array into (n, 2) points) as a polygon.")
      .def(
          "circle",
          [](SvgWriter& w, py::handle c, double r, const py::kwargs& kw) {
            w.circle(point2(c, "SvgWriter.circle"), r, style_from(kw));
          },
          py::arg("center"), py::arg("radius"), "A circle.")
      .def(
          "text",
          [](SvgWriter& w, py::handle p, const std::string& s, const py::kwargs& kw) {
            w.text(point2(p, "SvgWriter.text"), s, style_from(kw));
          },
          py::arg("p"), py::arg("text"), "A text label anchored at p.")
      .def("__len__", &SvgWriter::size, "Number of items drawn.")
      .def("to_string", &SvgWriter::to_string, "The SVG document.")
      .def(
          "write",
          [](const SvgWriter& w, const std::string& path) {
            Status s;
            {
              py::gil_scoped_release nogil;
              s = w.write_file(path);
            }
            if (s != Status::ok) fail("SvgWriter.write", std::string(to_string(s)) + ": " + path);
          },
          py::arg("path"), "Writes the document to path (ValueError when it cannot).");
}

}  // namespace locus::python
