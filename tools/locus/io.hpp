// SPDX-License-Identifier: BSL-1.0
#pragma once
// The input and output layer of the locus command (docs/cli.md): loading points, meshes and
// polygons by extension (overridable with --format), writing a result to -o FILE or stdout, the
// --json summary and the --svg drawing, the exit-code exceptions and the progress line.
// Every subcommand (cmd_*.cpp) goes through these functions, so formats and messages are alike.

#include <locus/core/vec.hpp>
#include <locus/io/geometry.hpp>
#include <locus/io/svg.hpp>
#include <locus/mesh/polygon_mesh.hpp>

#include <CLI/CLI.hpp>

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

namespace locus_cli {

using locus::Vec2d;
using locus::Vec3d;

/// Bad input (an unreadable or malformed file, input the algorithm refuses): exit code 1, the
/// message (one line: "file:line: reason") on stderr.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A usage error found after parsing (an unknown format, an option that does not fit the
/// input): exit code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The options every subcommand shares.
struct Common {
  std::string input;   ///< the input file ("-": standard input)
  std::string format;  ///< --format: overrides the input's extension
  std::string output;  ///< -o: where the result goes (stdout when empty)
  std::string svg;     ///< --svg: a drawing of a 2D result
  bool json = false;   ///< --json: a JSON summary on stdout
};

/// Adds the input positional, --format, -o, --json and (when svg) --svg to a subcommand.
void add_common(CLI::App* sub, Common& c, bool svg, std::string_view input_help);

/// Points from a point list (.csv .txt .tsv; 3D also .xyz and the vertices of a mesh file).
[[nodiscard]] std::vector<Vec2d> load_points2(const Common& c);
[[nodiscard]] std::vector<Vec3d> load_points3(const Common& c);
/// Rows of six numbers from a CSV file (.csv .txt .tsv, or standard input for "-"), read by the
/// library's point-list reader (io/point_list.hpp, N = 6): its header, separator, comment and
/// error rules; used for rays "ox,oy,oz,dx,dy,dz".
[[nodiscard]] std::vector<locus::Vec<double, 6>> load_rows6(const std::string& path);
/// The dimension of the input's points (2 or 3; mesh files are 3D).
[[nodiscard]] int input_dimension(const Common& c);

/// A mesh file (.obj .off .ply .stl, or --format).
[[nodiscard]] locus::PolygonMesh<double> load_mesh(const std::string& path,
                                                   const std::string& format);

/// A polygon with holes: ring k is points[ring_ends[k-1] .. ring_ends[k]); ring 0 the outer
/// boundary (io/geometry.hpp; the layout of triangulate/polygon_triangulation.hpp).
using PolygonInput = locus::RingPolygon2<double>;

/// The polygons of a WKT (.wkt) or GeoJSON (.json .geojson) file, in file order (every POLYGON
/// and each member of a MULTIPOLYGON; other geometries are skipped); none is an InputError.
[[nodiscard]] std::vector<PolygonInput> load_polygons(const Common& c);

/// Whether a file name or --format names a mesh format.
[[nodiscard]] bool is_mesh_name(const std::string& path, const std::string& format = {});

/// The shortest decimal form of v that reads back to the same double ("nan", "inf" otherwise).
[[nodiscard]] std::string num(double v);

/// A JSON object built in order; values are raw JSON text.
class JsonObject {
 public:
  JsonObject& raw(std::string_view key, std::string value);
  JsonObject& str(std::string_view key, std::string_view value);
  JsonObject& number(std::string_view key, double v);
  JsonObject& integer(std::string_view key, std::int64_t v);
  JsonObject& boolean(std::string_view key, bool v);
  [[nodiscard]] std::string text() const;

 private:
  std::vector<std::pair<std::string, std::string>> fields_;
};

[[nodiscard]] std::string json_string(std::string_view s);
[[nodiscard]] std::string json_number(double v);  ///< null for NaN and infinities
[[nodiscard]] std::string json_indices(std::span<const std::uint32_t> v);
template <int N>
[[nodiscard]] std::string json_vec(const locus::Vec<double, N>& v) {
  std::string s = "[";
  for (int i = 0; i < N; ++i) s += (i ? "," : "") + json_number(v[i]);
  return s + "]";
}
template <std::size_t K>
[[nodiscard]] std::string json_index_rows(std::span<const std::array<std::uint32_t, K>> rows) {
  std::string s = "[";
  for (std::size_t r = 0; r < rows.size(); ++r) {
    s += r ? ",[" : "[";
    for (std::size_t k = 0; k < K; ++k) s += (k ? "," : "") + std::to_string(rows[r][k]);
    s += ']';
  }
  return s + "]";
}

/// Index rows as text, one row per line, separated by spaces.
template <std::size_t K>
[[nodiscard]] std::string index_rows(std::span<const std::array<std::uint32_t, K>> rows) {
  std::string s;
  for (const auto& row : rows) {
    for (std::size_t k = 0; k < K; ++k) s += (k ? " " : "") + std::to_string(row[k]);
    s += '\n';
  }
  return s;
}

/// Writes the result: the text to -o or stdout, unless --json, which prints the JSON on stdout
/// (and still writes the text to -o when given).
void emit(const Common& c, const std::string& text, const JsonObject& json);

/// Prints the JSON on stdout when --json was given (after a result written to -o).
void emit_json(const Common& c, const JsonObject& json);

/// Writes a point list result (-o with .csv/.txt/.tsv/.xyz, else CSV text on stdout).
template <int N>
void emit_points(const Common& c, std::span<const locus::Vec<double, N>> points,
                 const JsonObject& json);

/// Writes a mesh result when -o names a mesh file (true), else does nothing (false).
bool emit_mesh(const Common& c, const locus::PolygonMesh<double>& mesh);

/// Writes the SVG drawing when --svg was given.
void save_svg(const Common& c, const locus::SvgWriter& svg);
/// Styles of the drawings: input points, the result outline, a filled result.
[[nodiscard]] locus::SvgStyle input_style();
[[nodiscard]] locus::SvgStyle result_style();
[[nodiscard]] locus::SvgStyle fill_style();

/// The first layer of the drawing of a polygon boolean's or offset's result: each polygon filled
/// (fill_style), its holes cut out.
void draw_polygons(locus::SvgWriter& svg,
                   std::span<const locus::PolygonWithHoles2<double>> polygons);
/// Writes a polygon boolean's or offset's result (boolean, offset): the drawing when --svg was
/// given, then the polygons as one WKT MULTIPOLYGON line, or with --json the command's fields in
/// json followed by "polygons", "rings" (outer rings and holes), "grid" and "wkt".
void emit_polygons(const Common& c, std::span<const locus::PolygonWithHoles2<double>> polygons,
                   double grid, const locus::SvgWriter& svg, JsonObject json);

/// A mesh of the given points (z = 0 for 2D) and triangles, keeping only the used vertices.
[[nodiscard]] locus::PolygonMesh<double> triangle_mesh(
    std::span<const Vec3d> points, std::span<const std::array<std::uint32_t, 3>> triangles);

/// Reports on stderr, when it is a terminal, work that runs over a second: a start line after
/// one second, and the time when it ends. Silent otherwise (and for scripts and tests).
class Progress {
 public:
  Progress(std::string what, std::size_t items);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

 private:
  std::string what_;
  std::chrono::steady_clock::time_point start_;
  std::mutex m_;
  std::condition_variable cv_;
  bool done_ = false;
  bool announced_ = false;
  std::thread thread_;
};

/// Raises InputError for a status other than ok: "<name>: <what>: <status>".
void require_ok(locus::Status s, std::string_view what);

}  // namespace locus_cli
