// SPDX-License-Identifier: BSL-1.0
// The input and output layer of the locus command (io.hpp).

#include "io.hpp"

#include <locus/io/geojson.hpp>
#include <locus/io/mesh_io.hpp>
#include <locus/io/point_list.hpp>
#include <locus/io/wkt.hpp>

#include <unistd.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <sstream>
#include <system_error>

namespace locus_cli {

namespace {

constexpr const char* formats_help = "csv, txt, tsv, xyz, obj, off, ply, stl, wkt or geojson";

std::string lower(std::string s) {
  for (char& ch : s) {
    if (ch >= 'A' && ch <= 'Z') ch = static_cast<char>(ch - 'A' + 'a');
  }
  return s;
}

// The bytes of the input: a file, or standard input for "-".
std::string slurp(const std::string& path) {
  if (path == "-") {
    std::ostringstream ss;
    ss << std::cin.rdbuf();
    return ss.str();
  }
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(path + ": cannot read the file");
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw InputError(path + ": cannot read the file");
  return bytes;
}

std::string display_name(const std::string& path) { return path == "-" ? "<stdin>" : path; }

// The point-list format named by --format or the name; from_extension when it names a mesh.
locus::PointListFormat point_format(const std::string& path, const std::string& format) {
  const std::string f = lower(format);
  if (f.empty()) {
    if (path == "-") return locus::PointListFormat::csv;
    const auto pf = locus::point_list_format_from_name(path);
    if (pf != locus::PointListFormat::from_extension || is_mesh_name(path)) return pf;
    throw UsageError(path + ": unknown input format (give --format: " + formats_help + ")");
  }
  if (f == "csv" || f == "txt" || f == "tsv") return locus::PointListFormat::csv;
  if (f == "xyz") return locus::PointListFormat::xyz;
  if (is_mesh_name({}, f)) return locus::PointListFormat::from_extension;
  throw UsageError("unknown --format '" + format + "' (use " + formats_help + ")");
}

locus::MeshFormat mesh_format(const std::string& path, const std::string& format) {
  const std::string f = lower(format);
  if (f.empty()) return locus::mesh_format_from_name(path);
  if (f == "obj") return locus::MeshFormat::obj;
  if (f == "off") return locus::MeshFormat::off;
  if (f == "ply") return locus::MeshFormat::ply;
  if (f == "stl") return locus::MeshFormat::stl;
  return locus::MeshFormat::from_extension;
}

template <int N>
std::vector<locus::Vec<double, N>> load_points(const Common& c) {
  const auto pf = point_format(c.input, c.format);
  if (pf == locus::PointListFormat::from_extension) {  // a mesh file: its vertices
    if constexpr (N == 2) {
      throw UsageError(c.input + ": a mesh file holds 3D points; this command needs 2D points");
    } else {
      return load_mesh(c.input, c.format).vertices;
    }
  }
  if (N == 2 && pf == locus::PointListFormat::xyz) {
    throw UsageError(c.input + ": XYZ files hold 3D points; this command needs 2D points");
  }
  const std::string bytes = slurp(c.input);
  auto r = locus::parse_points<double, N>(bytes, pf, display_name(c.input));
  if (r.status != locus::Status::ok) throw InputError(r.message);
  return std::move(r.points);
}

void write_text_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throw InputError(path + ": cannot write the file");
}

}  // namespace

void add_common(CLI::App* sub, Common& c, bool svg, std::string_view input_help) {
  sub->add_option("input", c.input, std::string(input_help))->required();
  sub->add_option("--format", c.format,
                  std::string("input format, overriding the extension: ") + formats_help);
  sub->add_option("-o,--output", c.output, "write the result to this file (default: stdout)");
  sub->add_flag("--json", c.json, "print a JSON summary on stdout");
  if (svg) sub->add_option("--svg", c.svg, "draw the input and the result as SVG");
}

std::vector<Vec2d> load_points2(const Common& c) { return load_points<2>(c); }
std::vector<Vec3d> load_points3(const Common& c) { return load_points<3>(c); }

std::vector<locus::Vec<double, 6>> load_rows6(const std::string& path) {
  const auto pf =
      path == "-" ? locus::PointListFormat::csv : locus::point_list_format_from_name(path);
  if (pf != locus::PointListFormat::csv) {
    throw UsageError(path + ": give a CSV file (.csv .txt .tsv) of six numbers per row");
  }
  const std::string bytes = slurp(path);
  auto r = locus::parse_points<double, 6>(bytes, pf, display_name(path));
  if (r.status != locus::Status::ok) throw InputError(r.message);
  return std::move(r.points);
}

int input_dimension(const Common& c) {
  const auto pf = point_format(c.input, c.format);
  if (pf == locus::PointListFormat::from_extension || pf == locus::PointListFormat::xyz) return 3;
  if (c.input == "-") throw UsageError("reading standard input: give the dimension (--dim)");
  const int d = locus::point_list_dimension(slurp(c.input), pf);
  if (d == 0) throw InputError(c.input + ": no data line");
  if (d != 2 && d != 3) {
    throw InputError(c.input + ": the first data line has " + std::to_string(d) +
                     " fields (2 or 3 expected)");
  }
  return d;
}

locus::PolygonMesh<double> load_mesh(const std::string& path, const std::string& format) {
  const auto mf = mesh_format(path, format);
  if (mf == locus::MeshFormat::from_extension) {
    throw UsageError(path + ": unknown mesh format (give --format: obj, off, ply or stl)");
  }
  // A file goes through read_mesh(), which maps it instead of copying it.
  auto r = path == "-" ? locus::parse_mesh<double>(slurp(path), mf, display_name(path))
                       : locus::read_mesh<double>(path, mf);
  if (r.status != locus::Status::ok) throw InputError(r.message);
  return std::move(r.mesh);
}

std::vector<PolygonInput> load_polygons(const Common& c) {
  std::string f = lower(c.format);
  if (f.empty()) {
    const std::string name = lower(c.input);
    const auto ends_with = [&name](std::string_view e) {
      return name.size() > e.size() && name.compare(name.size() - e.size(), e.size(), e) == 0;
    };
    if (ends_with(".wkt")) f = "wkt";
    if (ends_with(".json") || ends_with(".geojson")) f = "geojson";
  }
  if (f == "json") f = "geojson";
  if (f != "wkt" && f != "geojson") {
    throw UsageError(c.input + ": give a WKT (.wkt) or GeoJSON (.json .geojson) file, or " +
                     "--format wkt|geojson");
  }
  const std::string bytes = slurp(c.input);
  const std::string name = display_name(c.input);
  auto r = f == "wkt" ? locus::parse_wkt<double>(bytes, name)
                      : locus::parse_geojson<double>(bytes, name);
  if (r.status != locus::Status::ok) {
    throw InputError(r.message.empty() ? name + ": " + std::string(locus::to_string(r.status))
                                       : r.message);
  }
  std::vector<PolygonInput> polygons;
  for (auto& g : r.geometries) {
    for (auto& p : g.polygons) polygons.push_back(std::move(p));
  }
  if (polygons.empty()) throw InputError(name + ": no polygon in the file");
  return polygons;
}

bool is_mesh_name(const std::string& path, const std::string& format) {
  if (!format.empty()) {
    const std::string f = lower(format);
    return f == "obj" || f == "off" || f == "ply" || f == "stl";
  }
  return locus::mesh_format_from_name(path) != locus::MeshFormat::from_extension;
}

std::string num(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

JsonObject& JsonObject::raw(std::string_view key, std::string value) {
  fields_.emplace_back(std::string(key), std::move(value));
  return *this;
}
JsonObject& JsonObject::str(std::string_view key, std::string_view value) {
  return raw(key, json_string(value));
}
JsonObject& JsonObject::number(std::string_view key, double v) { return raw(key, json_number(v)); }
JsonObject& JsonObject::integer(std::string_view key, std::int64_t v) {
  return raw(key, std::to_string(v));
}
JsonObject& JsonObject::boolean(std::string_view key, bool v) {
  return raw(key, v ? "true" : "false");
}
std::string JsonObject::text() const {
  std::string s = "{";
  for (std::size_t i = 0; i < fields_.size(); ++i) {
    s += i ? ", " : "";
    s += json_string(fields_[i].first) + ": " + fields_[i].second;
  }
  return s + "}";
}

std::string json_string(std::string_view s) {
  std::string q = "\"";
  for (const char ch : s) {
    const auto u = static_cast<unsigned char>(ch);
    if (ch == '"' || ch == '\\') {
      q += '\\';
      q += ch;
    } else if (u < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", u);
      q += buf;
    } else {
      q += ch;
    }
  }
  return q + "\"";
}

std::string json_number(double v) { return std::isfinite(v) ? num(v) : "null"; }

std::string json_indices(std::span<const std::uint32_t> v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + std::to_string(v[i]);
  return s + "]";
}

void emit(const Common& c, const std::string& text, const JsonObject& json) {
  if (!c.output.empty()) write_text_file(c.output, text);
  if (c.json) {
    std::cout << json.text() << '\n';
  } else if (c.output.empty()) {
    std::cout << text;
  }
  std::cout.flush();
}

void emit_json(const Common& c, const JsonObject& json) {
  if (c.json) std::cout << json.text() << '\n' << std::flush;
}

template <int N>
void emit_points(const Common& c, std::span<const locus::Vec<double, N>> points,
                 const JsonObject& json) {
  auto pf = locus::PointListFormat::csv;
  if (!c.output.empty()) {
    pf = locus::point_list_format_from_name(c.output);
    if (pf == locus::PointListFormat::from_extension) {
      throw UsageError(c.output + ": give a point-list file name (.csv .txt .tsv .xyz)");
    }
  }
  const auto w = locus::write_points_string<double, N>(points, pf);
  if (w.status == locus::Status::invalid_input) throw UsageError(c.output + ": " + w.message);
  if (w.status != locus::Status::ok) throw InputError(w.message);
  emit(c, w.data, json);
}
template void emit_points<2>(const Common&, std::span<const Vec2d>, const JsonObject&);
template void emit_points<3>(const Common&, std::span<const Vec3d>, const JsonObject&);

bool emit_mesh(const Common& c, const locus::PolygonMesh<double>& mesh) {
  if (c.output.empty() || !is_mesh_name(c.output)) return false;
  const auto w = locus::write_mesh(c.output, mesh);
  if (w.status != locus::Status::ok) throw InputError(w.message);
  return true;
}

void save_svg(const Common& c, const locus::SvgWriter& svg) {
  if (c.svg.empty()) return;
  if (svg.write_file(c.svg) != locus::Status::ok)
    throw InputError(c.svg + ": cannot write the file");
}

void draw_polygons(locus::SvgWriter& svg,
                   std::span<const locus::PolygonWithHoles2<double>> polygons) {
  for (const auto& p : polygons) {
    std::vector<std::vector<Vec2d>> holes;
    for (const auto& h : p.holes) holes.push_back(h.vertices);
    svg.polygon(p.outer.vertices, holes, fill_style());
  }
}

void emit_polygons(const Common& c, std::span<const locus::PolygonWithHoles2<double>> polygons,
                   double grid, const locus::SvgWriter& svg, JsonObject json) {
  locus::Geometry2<double> g;
  g.type = locus::GeometryType::multi_polygon;
  std::size_t rings = 0;
  for (const auto& p : polygons) {
    g.polygons.push_back(locus::to_ring_polygon(p));
    rings += 1 + p.holes.size();
  }
  save_svg(c, svg);
  const auto text = locus::write_wkt_string(g);
  require_ok(text.status, "writing the result");
  json.integer("polygons", static_cast<std::int64_t>(polygons.size()))
      .integer("rings", static_cast<std::int64_t>(rings))
      .number("grid", grid)
      .str("wkt", text.data);
  emit(c, text.data + "\n", json);
}

locus::SvgStyle input_style() {
  locus::SvgStyle s;
  s.stroke = "none";
  s.fill = "#555555";
  s.marker_size = 2.0;
  return s;
}

locus::SvgStyle result_style() {
  locus::SvgStyle s;
  s.stroke = "#c0392b";
  s.width = 1.5;
  return s;
}

locus::SvgStyle fill_style() {
  locus::SvgStyle s;
  s.stroke = "#2c5aa0";
  s.fill = "#9cc3e6";
  s.fill_opacity = 0.5;
  s.width = 0.75;
  return s;
}

locus::PolygonMesh<double> triangle_mesh(std::span<const Vec3d> points,
                                         std::span<const std::array<std::uint32_t, 3>> triangles) {
  constexpr std::uint32_t unused = 0xffffffffu;
  std::vector<std::uint32_t> map(points.size(), unused);
  locus::PolygonMesh<double> mesh;
  for (const auto& t : triangles) {
    std::array<std::uint32_t, 3> f{};
    for (std::size_t k = 0; k < 3; ++k) {
      if (map[t[k]] == unused) {
        map[t[k]] = static_cast<std::uint32_t>(mesh.vertices.size());
        mesh.vertices.push_back(points[t[k]]);
      }
      f[k] = map[t[k]];
    }
    locus::add_face(mesh, std::span<const std::uint32_t>(f));
  }
  return mesh;
}

Progress::Progress(std::string what, std::size_t items)
    : what_(std::move(what) + " (" + std::to_string(items) + " items)"),
      start_(std::chrono::steady_clock::now()) {
  if (!isatty(STDERR_FILENO)) return;
  thread_ = std::thread([this] {
    std::unique_lock<std::mutex> lock(m_);
    if (!cv_.wait_for(lock, std::chrono::seconds(1), [this] { return done_; })) {
      std::fprintf(stderr, "locus: %s ...\n", what_.c_str());
      announced_ = true;
    }
  });
}

Progress::~Progress() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(m_);
    done_ = true;
  }
  cv_.notify_all();
  thread_.join();
  if (announced_) {
    const std::chrono::duration<double> t = std::chrono::steady_clock::now() - start_;
    std::fprintf(stderr, "locus: %s done in %.2f s\n", what_.c_str(), t.count());
  }
}

void require_ok(locus::Status s, std::string_view what) {
  if (s == locus::Status::ok) return;
  throw InputError(std::string(what) + ": " + std::string(locus::to_string(s)));
}

}  // namespace locus_cli
