// SPDX-License-Identifier: BSL-1.0
// read_points: CSV and XYZ point lists (io/point_list.hpp) as an (n, 2) or (n, 3) float64 array.
#include "common.hpp"

#include <locus/io/point_list.hpp>

#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

namespace locus::python {

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
}

}  // namespace locus::python
