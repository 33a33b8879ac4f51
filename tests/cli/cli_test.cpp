// SPDX-License-Identifier: BSL-1.0
// End-to-end tests of the locus command (tools/locus, docs/cli.md): the built binary runs on
// files written here into a fresh temporary directory, and its output must equal the library's
// result on the same input, bit for bit (numbers are printed in the shortest form that reads
// back exactly). Bad files exit 1 with one stderr line naming the file and line; usage errors
// exit 2; --help lists the subcommands. The command works in double only, so these tests are
// not typed; the library's float paths are tested in each area.

#include <locus/bounding/min_box3.hpp>
#include <locus/bounding/min_circle.hpp>
#include <locus/bounding/min_rect2.hpp>
#include <locus/bounding/min_sphere.hpp>
#include <locus/delaunay/constrained_delaunay2.hpp>
#include <locus/delaunay/delaunay2.hpp>
#include <locus/delaunay/delaunay3.hpp>
#include <locus/distance/point_mesh.hpp>
#include <locus/fit/circle_fit.hpp>
#include <locus/fit/line_fit.hpp>
#include <locus/fit/plane_fit.hpp>
#include <locus/fit/sphere_fit.hpp>
#include <locus/hull/hull2.hpp>
#include <locus/hull/hull3.hpp>
#include <locus/intersection/plane_mesh.hpp>
#include <locus/intersection/ray_torus.hpp>
#include <locus/intersection/ray_triangle.hpp>
#include <locus/io/geojson.hpp>
#include <locus/io/mesh_io.hpp>
#include <locus/io/point_list.hpp>
#include <locus/io/wkt.hpp>
#include <locus/mesh/mesh_checks.hpp>
#include <locus/mesh/platonic.hpp>
#include <locus/mesh/vet_mesh.hpp>
#include <locus/numeric/roots.hpp>
#include <locus/triangulate/ear_clipping.hpp>
#include <locus/triangulate/monotone.hpp>

// tools/locus/CMakeLists.txt defines the path of the built tool; tests/CMakeLists.txt builds
// this area only with LOCUS_BUILD_TOOLS.
#ifndef LOCUS_CLI_PATH
#error "LOCUS_CLI_PATH (the locus tool) is not defined"
#endif
#include "support/files.hpp"
#include "support/typed.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using locus::Status;
using locus::Vec2d;
using locus::Vec3d;

struct Outcome {
  int code = -1;
  std::string out, err;
};

using locus_test::slurp;

void spit(const fs::path& p, const std::string& s) {
  std::ofstream out(p, std::ios::binary);
  out << s;
}

// A fresh directory per test, removed at the end.
class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    static std::atomic<int> counter{0};
    dir_ = fs::temp_directory_path() /
           ("locus_cli_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    if (!dir_.empty()) fs::remove_all(dir_, ec);
  }

  [[nodiscard]] std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // Runs `locus <args>` (args are shell words; paths here have no spaces), optionally with a
  // file on standard input.
  Outcome run(const std::string& args, const std::string& stdin_file = {}) const {
    Outcome r;
    const std::string out = path("stdout.txt"), err = path("stderr.txt");
    std::string cmd =
        std::string("'") + LOCUS_CLI_PATH + "' " + args + " >'" + out + "' 2>'" + err + "'";
    if (!stdin_file.empty()) cmd += " <'" + stdin_file + "'";
    const int s = std::system(cmd.c_str());
    r.code = WIFEXITED(s) ? WEXITSTATUS(s) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
  }

  template <int N>
  std::string write_points(const std::string& name, const std::vector<locus::Vec<double, N>>& p) {
    const std::string f = path(name);
    EXPECT_EQ((locus::write_points<double, N>(f, p).status), Status::ok);
    return f;
  }

  fs::path dir_;
};

double to_double(const std::string& s) {
  double v = 0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  EXPECT_TRUE(r.ec == std::errc() && r.ptr == s.data() + s.size()) << "not a number: " << s;
  return v;
}

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> w;
  for (std::string s; in >> s;) w.push_back(s);
  return w;
}

// "key v1 v2 ..." lines.
std::map<std::string, std::vector<std::string>> fields(const std::string& text) {
  std::map<std::string, std::vector<std::string>> m;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    auto w = words(line);
    if (w.empty()) continue;
    const std::string key = w.front();
    w.erase(w.begin());
    m[key] = w;
  }
  return m;
}

template <int N>
locus::Vec<double, N> vec_field(const std::map<std::string, std::vector<std::string>>& f,
                                const std::string& key) {
  locus::Vec<double, N> v{};
  const auto it = f.find(key);
  EXPECT_TRUE(it != f.end() && it->second.size() == std::size_t(N)) << key;
  if (it == f.end() || it->second.size() != std::size_t(N)) return v;
  for (int i = 0; i < N; ++i) v[i] = to_double(it->second[std::size_t(i)]);
  return v;
}

double num_field(const std::map<std::string, std::vector<std::string>>& f, const std::string& key) {
  const auto it = f.find(key);
  EXPECT_TRUE(it != f.end() && it->second.size() == 1u) << key;
  return it == f.end() || it->second.empty() ? 0.0 : to_double(it->second[0]);
}

std::string shortest(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

bool same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
template <int N>
bool same(const locus::Vec<double, N>& a, const locus::Vec<double, N>& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// Rows of unsigned integers, one per line ('#' lines skipped).
template <std::size_t K>
std::vector<std::array<std::uint32_t, K>> index_rows(const std::string& text) {
  std::vector<std::array<std::uint32_t, K>> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    const auto w = words(line);
    EXPECT_EQ(w.size(), K) << line;
    std::array<std::uint32_t, K> r{};
    for (std::size_t k = 0; k < K && k < w.size(); ++k) r[k] = std::uint32_t(std::stoul(w[k]));
    rows.push_back(r);
  }
  return rows;
}

std::vector<std::uint32_t> support_of(const std::map<std::string, std::vector<std::string>>& f) {
  std::vector<std::uint32_t> s;
  if (f.count("support")) {
    for (const auto& w : f.at("support")) s.push_back(std::uint32_t(std::stoul(w)));
  }
  return s;
}

std::vector<Vec2d> random_points2(locus_test::Rng& rng, int n) {
  std::vector<Vec2d> p;
  for (int i = 0; i < n; ++i) p.push_back(rng.vec<double, 2>(-10.0, 10.0));
  p.push_back(p[3]);  // a duplicate
  return p;
}

std::vector<Vec3d> random_points3(locus_test::Rng& rng, int n) {
  std::vector<Vec3d> p;
  for (int i = 0; i < n; ++i) p.push_back(rng.vec<double, 3>(-10.0, 10.0));
  return p;
}

const char* const cube_obj =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

TEST_F(Cli, HelpListsEverySubcommandWithAnExample) {
  const Outcome r = run("--help");
  EXPECT_EQ(r.code, 0);
  const char* const subs[] = {"hull",      "hull3",   "delaunay", "delaunay3", "mincircle",
                              "minsphere", "minrect", "minbox",   "distance",  "roots",
                              "fit",       "mesh",    "raycast",  "surfacehit"};
  for (const char* s : subs) {
    EXPECT_NE(r.out.find(std::string("  ") + s + " "), std::string::npos) << s;
    const Outcome h = run(std::string(s) + " --help");
    EXPECT_EQ(h.code, 0) << s;
    EXPECT_NE(h.out.find("Example:"), std::string::npos) << s;
  }
  for (const char* s : {"info", "check", "orient", "generate", "convert", "slice"}) {
    const Outcome h = run(std::string("mesh ") + s + " --help");
    EXPECT_EQ(h.code, 0) << s;
    EXPECT_NE(h.out.find("Example:"), std::string::npos) << s;
  }
  EXPECT_EQ(run("--version").code, 0);
}

TEST_F(Cli, UsageErrorsExitWith2) {
  const std::string pts = write_points<2>("p.csv", {{0, 0}, {1, 0}, {0, 1}});
  spit(path("p.dat"), "0,0\n1,0\n0,1\n");
  spit(path("c.xyz"), "0 0 0\n1 0 0\n0 1 0\n");
  const std::string cases[] = {"",
                               "nonsense",
                               "hull",
                               "hull " + pts + " --no-such-option",
                               "hull " + path("p.dat"),
                               "hull " + pts + " --format bogus",
                               "hull " + path("c.xyz"),
                               "hull " + pts + " -o " + path("out.xyz"),
                               "fit cone " + pts,
                               "fit plane " + pts + " --svg " + path("f.svg"),
                               "roots",
                               "roots 1 abc",
                               "roots 1 0 -1 --interval 2 1",
                               "mesh",
                               "cdt " + pts,
                               "triangulate " + pts + " --method nope",
                               "mesh convert " + path("a.obj"),
                               "mesh convert " + path("a.obj") + " " + path("b.obj") + " --to x",
                               "mesh generate cube",
                               "mesh generate sphere -o " + path("s.obj"),
                               "mesh generate icosphere --levels 9 -o " + path("s.obj"),
                               "mesh generate uvsphere --radius -1 -o " + path("s.obj"),
                               "mesh generate torus --minor-radius 2 -o " + path("s.obj"),
                               "mesh generate cube -o " + path("s.csv"),
                               "mesh orient " + path("a.obj"),
                               "mesh check " + path("a.obj") + " --tolerance -1",
                               "raycast " + path("a.obj"),
                               "raycast " + path("a.obj") + " " + path("c.xyz")};
  for (const std::string& args : cases) {
    const Outcome r = run(args);
    EXPECT_EQ(r.code, 2) << "locus " << args << "\n" << r.err;
    EXPECT_FALSE(r.err.empty()) << args;
  }
}

// One line on stderr: "locus: <file>:<line>: <reason>" (line 0: "locus: <file>: <reason>").
void expect_bad_input(const Outcome& r, const std::string& file, int line,
                      const std::string& reason) {
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  // "file:line: " for point lists and meshes, "file:line:column: " for WKT and GeoJSON.
  const std::string where = "locus: " + file + (line > 0 ? ":" + std::to_string(line) : "");
  EXPECT_EQ(r.err.rfind(where, 0), 0u) << r.err;
  EXPECT_EQ(r.err.substr(where.size(), 1), ":") << r.err;
  EXPECT_NE(r.err.find(reason), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.back(), '\n');
}

TEST_F(Cli, BadFilesExitWith1NamingFileAndLine) {
  const std::string bad = path("bad.csv");
  spit(bad, "x,y\n0,0\n1,1\n2,abc\n3,3\n");
  for (const char* cmd : {"hull", "delaunay", "mincircle", "minrect", "fit line"}) {
    expect_bad_input(run(std::string(cmd) + " " + bad), bad, 4, "bad number 'abc' in field 2");
  }
  expect_bad_input(run("hull -", bad), "<stdin>", 4, "bad number 'abc'");
  const std::string nan = path("nan.xyz");
  spit(nan, "0 0 0\n1 nan 0\n");
  for (const char* cmd : {"hull3", "delaunay3", "minsphere", "minbox", "fit plane"}) {
    expect_bad_input(run(std::string(cmd) + " " + nan), nan, 2, "non-finite coordinate 'nan'");
  }
  const std::string three = path("three.csv");
  spit(three, "1,2,3\n");
  expect_bad_input(run("hull " + three), three, 1, "expected 2 fields, found 3");
  const std::string obj = path("bad.obj");
  spit(obj, "v 0 0 0\nv 1 0 0\nf 1 2 7\n");
  expect_bad_input(run("mesh info " + obj), obj, 3, "index");
  expect_bad_input(run("mesh check " + obj), obj, 3, "index");
  expect_bad_input(run("hull3 " + obj), obj, 3, "index");
  const std::string pts = write_points<3>("q.csv", {{0, 0, 0}});
  expect_bad_input(run("distance " + pts + " --mesh " + obj), obj, 3, "index");
  // Files that cannot be read, and input the algorithm refuses.
  expect_bad_input(run("hull " + path("missing.csv")), path("missing.csv"), 0, "cannot read");
  const std::string empty = path("empty.csv");
  spit(empty, "x,y\n");
  expect_bad_input(run("hull " + empty), empty, 0, "empty_input");
  const std::string open = path("open.obj");
  spit(open, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  expect_bad_input(run("distance " + pts + " --mesh " + open + " --signed"), open, 0, "not closed");
  const Outcome zero = run("roots -- 0 0");  // the zero polynomial: no file to name
  EXPECT_EQ(zero.code, 1);
  EXPECT_EQ(std::count(zero.err.begin(), zero.err.end(), '\n'), 1) << zero.err;
}

TEST_F(Cli, HullMatchesTheLibrary) {
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  const auto pts = random_points2(rng, 300);
  const std::string f = write_points<2>("pts.csv", pts);
  const auto lib = locus::convex_hull(pts);
  ASSERT_EQ(lib.status, Status::ok);
  Outcome r = run("hull " + f + " --indices");
  ASSERT_EQ(r.code, 0) << r.err;
  std::vector<std::uint32_t> idx;
  for (const auto& row : index_rows<1>(r.out)) idx.push_back(row[0]);
  EXPECT_EQ(idx, lib.indices);
  // The default output is the hull's points as CSV, the same bits; also from stdin and to -o.
  std::vector<Vec2d> expected;
  for (const std::uint32_t i : lib.indices) expected.push_back(pts[i]);
  for (const Outcome& q : {run("hull " + f), run("hull - --format csv", f)}) {
    ASSERT_EQ(q.code, 0) << q.err;
    const auto back = locus::parse_points<double, 2>(q.out, locus::PointListFormat::csv);
    ASSERT_EQ(back.status, Status::ok) << back.message;
    ASSERT_EQ(back.points.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
      EXPECT_TRUE(same<2>(back.points[i], expected[i]));
  }
  r = run("hull " + f + " -o " + path("hull.csv") + " --json --svg " + path("hull.svg"));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto file = locus::read_points<double, 2>(path("hull.csv"));
  ASSERT_EQ(file.status, Status::ok);
  EXPECT_EQ(file.points.size(), expected.size());
  EXPECT_EQ(r.out.rfind("{\"command\": \"hull\"", 0), 0u) << r.out;
  std::string json_idx;
  for (std::size_t i = 0; i < lib.indices.size(); ++i) {
    json_idx += (i ? "," : "") + std::to_string(lib.indices[i]);
  }
  EXPECT_NE(r.out.find("\"indices\": [" + json_idx + "]"), std::string::npos) << r.out;
  EXPECT_NE(slurp(path("hull.svg")).find("<svg"), std::string::npos);
  // --collinear keeps the points inside hull edges.
  const std::string sq = write_points<2>("sq.csv", {{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}});
  EXPECT_EQ(index_rows<1>(run("hull " + sq + " --indices").out).size(), 4u);
  EXPECT_EQ(index_rows<1>(run("hull " + sq + " --indices --collinear").out).size(), 5u);
}

TEST_F(Cli, Hull3AndDelaunayMatchTheLibrary) {
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  const auto p3 = random_points3(rng, 200);
  const std::string f3 = write_points<3>("p3.xyz", p3);
  const auto h = locus::convex_hull(p3);
  ASSERT_EQ(h.dimension, 3);
  Outcome r = run("hull3 " + f3);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(index_rows<3>(r.out), h.triangles);
  // --method: the divide-and-conquer hull, as the library computes it; an unknown method is a
  // usage error.
  const auto hd =
      locus::convex_hull(p3, locus::Hull3Options{locus::Hull3Method::divide_and_conquer});
  r = run("hull3 " + f3 + " --method divide-conquer");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(index_rows<3>(r.out), hd.triangles);
  EXPECT_EQ(run("hull3 " + f3 + " --method gift-wrap").code, 2);
  // As a mesh file: each face's corners are the input points of the library's triangle.
  r = run("hull3 " + f3 + " -o " + path("hull.ply"));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto mesh = locus::read_mesh<double>(path("hull.ply"));
  ASSERT_EQ(mesh.status, Status::ok) << mesh.message;
  ASSERT_EQ(locus::face_count(mesh.mesh), h.triangles.size());
  EXPECT_EQ(mesh.mesh.vertices.size(), h.vertices.size());
  for (std::size_t t = 0; t < h.triangles.size(); ++t) {
    const auto face = locus::face(mesh.mesh, t);
    for (std::size_t k = 0; k < 3; ++k) {
      EXPECT_TRUE(same<3>(mesh.mesh.vertices[face[k]], p3[h.triangles[t][k]]));
    }
  }
  const auto d3 = locus::delaunay(std::span<const Vec3d>(p3));
  r = run("delaunay3 " + f3);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(index_rows<4>(r.out), d3.tetrahedra);

  const auto p2 = random_points2(rng, 200);
  const std::string f2 = write_points<2>("p2.csv", p2);
  const auto d2 = locus::delaunay(p2);
  r = run("delaunay " + f2 + " --svg " + path("d.svg"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(index_rows<3>(r.out), d2.triangles);
  EXPECT_NE(slurp(path("d.svg")).find("<svg"), std::string::npos);
  r = run("delaunay " + f2 + " -o " + path("d.obj"));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto dm = locus::read_mesh<double>(path("d.obj"));
  ASSERT_EQ(dm.status, Status::ok);
  EXPECT_EQ(locus::face_count(dm.mesh), d2.triangles.size());
  EXPECT_EQ(dm.mesh.vertices.size(), p2.size() - d2.duplicate_count);
}

TEST_F(Cli, BoundingShapesMatchTheLibraryBitForBit) {
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  const auto p2 = random_points2(rng, 500);
  const std::string f2 = write_points<2>("p2.csv", p2);
  const auto c = locus::min_circle(p2);
  Outcome r = run("mincircle " + f2 + " --svg " + path("c.svg"));
  ASSERT_EQ(r.code, 0) << r.err;
  auto f = fields(r.out);
  EXPECT_TRUE(same<2>(vec_field<2>(f, "center"), c.circle.center));
  EXPECT_TRUE(same(num_field(f, "radius"), c.circle.radius));
  EXPECT_EQ(support_of(f),
            std::vector<std::uint32_t>(c.support.begin(), c.support.begin() + c.support_count));
  EXPECT_NE(slurp(path("c.svg")).find("<circle"), std::string::npos);

  for (const bool perimeter : {false, true}) {
    const auto m = locus::min_rect(
        p2, perimeter ? locus::RectCriterion::perimeter : locus::RectCriterion::area);
    r = run("minrect " + f2 + (perimeter ? " --perimeter" : ""));
    ASSERT_EQ(r.code, 0) << r.err;
    f = fields(r.out);
    EXPECT_TRUE(same<2>(vec_field<2>(f, "center"), m.rectangle.center));
    EXPECT_TRUE(same<2>(vec_field<2>(f, "axis0"), m.rectangle.axis[0]));
    EXPECT_TRUE(same<2>(vec_field<2>(f, "axis1"), m.rectangle.axis[1]));
    EXPECT_TRUE(same<2>(vec_field<2>(f, "extent"), m.rectangle.extent));
    EXPECT_TRUE(same(num_field(f, "area"), m.area));
    EXPECT_TRUE(same(num_field(f, "perimeter"), m.perimeter));
  }

  const auto p3 = random_points3(rng, 300);
  const std::string f3 = write_points<3>("p3.csv", p3);
  const auto s = locus::min_sphere(p3);
  r = run("minsphere " + f3);
  ASSERT_EQ(r.code, 0) << r.err;
  f = fields(r.out);
  EXPECT_TRUE(same<3>(vec_field<3>(f, "center"), s.sphere.center));
  EXPECT_TRUE(same(num_field(f, "radius"), s.sphere.radius));
  EXPECT_EQ(support_of(f),
            std::vector<std::uint32_t>(s.support.begin(), s.support.begin() + s.support_count));
  const auto b = locus::min_box(p3);
  r = run("minbox " + f3 + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"volume\": " + shortest(b.volume)), std::string::npos) << r.out;
  r = run("minbox " + f3);
  f = fields(r.out);
  EXPECT_TRUE(same<3>(vec_field<3>(f, "center"), b.box.center));
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(same<3>(vec_field<3>(f, "axis" + std::to_string(i)), b.box.axis[i]));
  }
  EXPECT_TRUE(same<3>(vec_field<3>(f, "extent"), b.box.extent));
  EXPECT_TRUE(same(num_field(f, "volume"), b.volume));
}

TEST_F(Cli, RootsAndFitsMatchTheLibrary) {
  // (x - 1)(x - 2)(x - 3) highest first; the same constant term first; a triple root.
  const std::vector<double> c = {-6, 11, -6, 1};
  const auto lib = locus::real_roots(std::span<const double>(c));
  ASSERT_EQ(lib.roots.size(), 3u);
  for (const std::string& args :
       {std::string("roots 1 -6 11 -6"), std::string("roots --low-first -- -6 11 -6 1")}) {
    const Outcome r = run(args);
    ASSERT_EQ(r.code, 0) << r.err;
    std::istringstream in(r.out);
    for (const auto& root : lib.roots) {
      std::string v;
      int m = 0;
      in >> v >> m;
      EXPECT_TRUE(same(to_double(v), root.value)) << v;
      EXPECT_EQ(m, root.multiplicity);
    }
  }
  const Outcome t = run("roots -- -1 3 -3 1");
  EXPECT_EQ(t.out, "1 3\n");
  EXPECT_EQ(run("roots 1 0 1").out, "");  // no real root
  EXPECT_EQ(run("roots 1 -6 11 -6 --interval 1.5 2.5").out, "2 1\n");

  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  std::vector<Vec2d> arc;
  for (int i = 0; i < 50; ++i) {
    const double a = rng.uniform(0.0, 2.0);
    arc.push_back({3 + 2 * std::cos(a) + rng.uniform(-0.01, 0.01), -1 + 2 * std::sin(a)});
  }
  const std::string fa = write_points<2>("arc.csv", arc);
  const auto circle = locus::fit_circle(arc);
  Outcome r = run("fit circle " + fa + " --svg " + path("fit.svg"));
  ASSERT_EQ(r.code, 0) << r.err;
  auto f = fields(r.out);
  EXPECT_TRUE(same<2>(vec_field<2>(f, "center"), circle.circle.center));
  EXPECT_TRUE(same(num_field(f, "radius"), circle.circle.radius));
  const auto line2 = locus::fit_line(std::span<const Vec2d>(arc));
  r = run("fit line " + fa);
  f = fields(r.out);
  EXPECT_TRUE(same<2>(vec_field<2>(f, "origin"), line2.line.origin));
  EXPECT_TRUE(same<2>(vec_field<2>(f, "direction"), line2.line.direction));

  const auto p3 = random_points3(rng, 100);
  const std::string f3 = write_points<3>("p3.xyz", p3);
  const auto plane = locus::fit_plane(p3);
  r = run("fit plane " + f3);
  ASSERT_EQ(r.code, 0) << r.err;
  f = fields(r.out);
  EXPECT_TRUE(same<3>(vec_field<3>(f, "normal"), plane.plane.normal));
  EXPECT_TRUE(same(num_field(f, "constant"), plane.plane.constant));
  const auto line3 = locus::fit_line(std::span<const Vec3d>(p3));
  f = fields(run("fit line " + f3).out);
  EXPECT_TRUE(same<3>(vec_field<3>(f, "direction"), line3.line.direction));
  const auto sphere = locus::fit_sphere_algebraic(std::span<const Vec3d>(p3));
  f = fields(run("fit sphere " + f3 + " --algebraic").out);
  EXPECT_TRUE(same<3>(vec_field<3>(f, "center"), sphere.sphere.center));
  EXPECT_TRUE(same(num_field(f, "radius"), sphere.sphere.radius));
}

TEST_F(Cli, DistanceToAMeshMatchesTheLibrary) {
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  spit(path("cube.obj"), cube_obj);
  const auto mesh = locus::read_mesh<double>(path("cube.obj"));
  ASSERT_EQ(mesh.status, Status::ok);
  const auto tris = locus::fan_triangles(mesh.mesh);
  const locus::MeshDistanceTree<double> tree(std::span<const Vec3d>(mesh.mesh.vertices),
                                             std::span<const std::array<std::uint32_t, 3>>(tris));
  std::vector<Vec3d> q;
  for (int i = 0; i < 40; ++i) q.push_back(rng.vec<double, 3>(-1.0, 2.0));
  const std::string fq = write_points<3>("q.csv", q);
  const Outcome r = run("distance " + fq + " --mesh " + path("cube.obj") + " --signed");
  ASSERT_EQ(r.code, 0) << r.err;
  std::istringstream in(r.out);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "signed_distance,x,y,z,face");
  for (const Vec3d& p : q) {
    ASSERT_TRUE(std::getline(in, line));
    std::replace(line.begin(), line.end(), ',', ' ');
    const auto w = words(line);
    ASSERT_EQ(w.size(), 5u);
    const auto d = locus::distance(p, tree);
    EXPECT_TRUE(same(to_double(w[0]), locus::signed_distance(p, tree)));
    EXPECT_TRUE(same<3>(Vec3d{to_double(w[1]), to_double(w[2]), to_double(w[3])}, d.closest[1]));
    EXPECT_EQ(std::stoul(w[4]), d.param_b.triangle / 2);  // two fan triangles per square face
  }
}

TEST_F(Cli, MeshConvertRoundTripsAndInfoAndCheckReport) {
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  locus::PolygonMesh<double> m;
  for (int i = 0; i < 60; ++i) m.vertices.push_back(rng.vec<double, 3>(-1e3, 1e3));
  for (int f = 0; f < 40; ++f) {
    std::vector<std::uint32_t> face(std::size_t(rng.uniform_int(3, 7)));
    for (auto& v : face) v = std::uint32_t(rng.uniform_int(0, 59));
    locus::add_face(m, std::span<const std::uint32_t>(face));
  }
  ASSERT_EQ(locus::write_mesh(path("a.obj"), m).status, Status::ok);
  ASSERT_EQ(run("mesh convert " + path("a.obj") + " " + path("b.ply")).code, 0);
  ASSERT_EQ(run("mesh convert " + path("b.ply") + " " + path("c.obj")).code, 0);
  ASSERT_EQ(run("mesh convert " + path("c.obj") + " " + path("d.txt") + " --to ply-ascii").code, 0);
  for (const char* name : {"b.ply", "c.obj"}) {
    const auto back = locus::read_mesh<double>(path(name));
    ASSERT_EQ(back.status, Status::ok) << back.message;
    ASSERT_EQ(back.mesh.vertices.size(), m.vertices.size());
    for (std::size_t i = 0; i < m.vertices.size(); ++i) {
      EXPECT_TRUE(same<3>(back.mesh.vertices[i], m.vertices[i]));
    }
    EXPECT_EQ(back.mesh.face_offsets, m.face_offsets);
    EXPECT_EQ(back.mesh.face_indices, m.face_indices);
  }
  const auto ascii = locus::read_mesh<double>(path("d.txt"), locus::MeshFormat::ply);
  ASSERT_EQ(ascii.status, Status::ok);
  EXPECT_NE(slurp(path("d.txt")).find("format ascii 1.0"), std::string::npos);

  spit(path("cube.obj"), cube_obj);
  auto f = fields(run("mesh info " + path("cube.obj")).out);
  EXPECT_EQ(f["vertices"], std::vector<std::string>{"8"});
  EXPECT_EQ(f["faces"], std::vector<std::string>{"6"});
  EXPECT_EQ(f["triangles"], std::vector<std::string>{"12"});
  EXPECT_EQ(f["bbox_max"], (std::vector<std::string>{"1", "1", "1"}));
  f = fields(run("mesh check " + path("cube.obj")).out);
  EXPECT_EQ(f["closed"], std::vector<std::string>{"yes"});
  EXPECT_EQ(f["kind"], std::vector<std::string>{"polytope"});
  EXPECT_EQ(f["euler_characteristic"], std::vector<std::string>{"2"});
  EXPECT_EQ(f["edges"], std::vector<std::string>{"12"});
}

// A random star-shaped polygon around the origin with a square hole, and a triangle beside it.
locus::Geometry2<double> random_multipolygon(locus_test::Rng& rng) {
  locus::Geometry2<double> g;
  g.type = locus::GeometryType::multi_polygon;
  locus::RingPolygon2<double> star;
  const int n = 40;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * 3.14159265358979 * (i + rng.uniform(0.0, 0.8)) / n;
    const double r = rng.uniform(2.0, 5.0);
    star.points.push_back({r * std::cos(a), r * std::sin(a)});
  }
  star.ring_ends.push_back(std::uint32_t(star.points.size()));
  for (const Vec2d& p : {Vec2d{-1, -1}, Vec2d{-1, 1}, Vec2d{1, 1}, Vec2d{1, -1}}) {
    star.points.push_back(p);
  }
  star.ring_ends.push_back(std::uint32_t(star.points.size()));
  g.polygons.push_back(star);
  locus::RingPolygon2<double> tri;
  tri.points = {{10, 0}, {12, 0}, {11, rng.uniform(1.0, 3.0)}};
  tri.ring_ends = {3};
  g.polygons.push_back(tri);
  return g;
}

TEST_F(Cli, PolygonTriangulationsMatchTheLibrary) {
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  const auto g = random_multipolygon(rng);
  const auto wkt = locus::write_wkt_string(g);
  ASSERT_EQ(wkt.status, Status::ok) << wkt.message;
  spit(path("poly.wkt"), wkt.data + "\n");
  const auto json = locus::write_geojson_string(g);
  ASSERT_EQ(json.status, Status::ok) << json.message;
  spit(path("poly.geojson"), json.data);
  // The points as the files hold them (read back by the library's own reader).
  const auto read = locus::parse_wkt<double>(wkt.data);
  ASSERT_EQ(read.status, Status::ok);
  std::vector<Vec2d> pts;
  std::vector<std::uint32_t> ends;
  for (const auto& p : read.geometries.at(0).polygons) {
    const auto base = std::uint32_t(pts.size());
    pts.insert(pts.end(), p.points.begin(), p.points.end());
    for (const std::uint32_t e : p.ring_ends) ends.push_back(base + e);
  }
  // cdt: every ring at once, the triangles inside.
  const auto cdt =
      locus::triangulate_polygon(std::span<const Vec2d>(pts), std::span<const std::uint32_t>(ends));
  ASSERT_EQ(cdt.status, Status::ok);
  std::vector<std::array<std::uint32_t, 3>> inside;
  for (std::size_t t = 0; t < cdt.triangles.size(); ++t) {
    if (cdt.inside[t]) inside.push_back(cdt.triangles[t]);
  }
  for (const char* file : {"poly.wkt", "poly.geojson"}) {
    const Outcome r = run(std::string("cdt ") + path(file));
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(index_rows<3>(r.out), inside) << file;
  }
  EXPECT_EQ(index_rows<3>(run("cdt " + path("poly.wkt") + " --all").out), cdt.triangles);
  // triangulate: each polygon on its own, indices offset by the polygon's first point.
  for (const std::string method : {"ear", "monotone"}) {
    std::vector<std::array<std::uint32_t, 3>> expected;
    std::uint32_t base = 0;
    for (const auto& p : read.geometries.at(0).polygons) {
      const auto t =
          method == "ear"
              ? locus::triangulate_ear_clipping(std::span<const Vec2d>(p.points),
                                                std::span<const std::uint32_t>(p.ring_ends))
              : locus::triangulate_monotone(std::span<const Vec2d>(p.points),
                                            std::span<const std::uint32_t>(p.ring_ends));
      ASSERT_EQ(t.status, Status::ok);
      for (const auto& tri : t.triangles) {
        expected.push_back({base + tri[0], base + tri[1], base + tri[2]});
      }
      base += std::uint32_t(p.points.size());
    }
    const Outcome r =
        run("triangulate - --format geojson --method " + method + " --svg " + path("t.svg"),
            path("poly.geojson"));
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(index_rows<3>(r.out), expected) << method;
    EXPECT_NE(slurp(path("t.svg")).find("<svg"), std::string::npos);
  }
  const Outcome m = run("triangulate " + path("poly.wkt") + " -o " + path("poly.off"));
  ASSERT_EQ(m.code, 0) << m.err;
  const auto mesh = locus::read_mesh<double>(path("poly.off"));
  ASSERT_EQ(mesh.status, Status::ok);
  EXPECT_EQ(mesh.mesh.vertices.size(), pts.size());
  // Bad files: the reader's line and column; crossing rings refused.
  const std::string bad = path("bad.wkt");
  spit(bad, "POLYGON ((0 0, 1 0, 1 1, 0 0))\nPOLYGON ((0 0, 1 0, 1 x, 0 0))\n");
  for (const char* cmd : {"cdt ", "triangulate "}) {
    const Outcome r = run(cmd + bad);
    expect_bad_input(r, bad, 2, "");
    EXPECT_EQ(r.err.rfind("locus: " + bad + ":2:", 0), 0u) << r.err;
  }
  const std::string bow = path("bow.wkt");
  spit(bow, "POLYGON ((0 0, 4 4, 4 0, 0 4, 0 0))\n");
  expect_bad_input(run("cdt " + bow), bow, 0, "cross");
  expect_bad_input(run("triangulate " + bow), bow, 0, "invalid_topology");
  const std::string points_only = path("points.wkt");
  spit(points_only, "MULTIPOINT ((0 0), (1 1))\n");
  expect_bad_input(run("cdt " + points_only), points_only, 0, "no polygon");
}

// A Moebius strip of n quads split in triangles: one face component, non-orientable.
locus::PolygonMesh<double> moebius(int n) {
  locus::PolygonMesh<double> m;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * 3.14159265358979 * i / n, w = a / 2;
    for (const double s : {-0.3, 0.3}) {
      m.vertices.push_back({(2 + s * std::cos(w)) * std::cos(a),
                            (2 + s * std::cos(w)) * std::sin(a), s * std::sin(w)});
    }
  }
  const auto u = [](int k) { return static_cast<std::uint32_t>(k); };
  for (int i = 0; i < n; ++i) {
    // Row 0 of the last column joins row 1 of the first (the half twist).
    const std::uint32_t a = u(2 * i), b = u(2 * i + 1);
    const std::uint32_t c = i + 1 < n ? u(2 * i + 2) : 1u, d = i + 1 < n ? u(2 * i + 3) : 0u;
    locus::add_face(m, std::span<const std::uint32_t>(std::array{a, b, d}));
    locus::add_face(m, std::span<const std::uint32_t>(std::array{a, d, c}));
  }
  return m;
}

// The icosphere with faces reversed at random (seeded), and a second, far copy of a cube.
locus::PolygonMesh<double> scrambled_mesh(locus_test::Rng& rng) {
  locus::PolygonMesh<double> m = locus::icosphere_mesh<double>(1.0, 1);
  const locus::PolygonMesh<double> cube = locus::hexahedron_mesh<double>();
  const auto base = static_cast<std::uint32_t>(m.vertices.size());
  for (const Vec3d& v : cube.vertices) m.vertices.push_back(v + Vec3d{5, 0, 0});
  for (std::size_t f = 0; f < locus::face_count(cube); ++f) {
    std::vector<std::uint32_t> face;
    for (const std::uint32_t v : locus::face(cube, f)) face.push_back(v + base);
    locus::add_face(m, std::span<const std::uint32_t>(face));
  }
  for (std::size_t f = 0; f < locus::face_count(m); ++f) {
    if (rng.uniform_int(0, 2) == 0) {
      std::reverse(m.face_indices.begin() + m.face_offsets[f],
                   m.face_indices.begin() + m.face_offsets[f + 1]);
    }
  }
  return m;
}

// `mesh check` prints what classify_mesh() finds on the same file (face ids of the table
// mapped back to input faces), and exits 0 whatever it finds.
TEST_F(Cli, MeshCheckReportsTheLibraryClassification) {
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  spit(path("cube.obj"), cube_obj);
  const std::string open = std::string(cube_obj).substr(0, std::string(cube_obj).rfind("f 4"));
  spit(path("open.obj"), open);
  spit(path("flip.obj"), open + "f 8 5 1 4\n");
  spit(path("dup.obj"), std::string(cube_obj) + "f 1 4 3 2\nv 5 5 5\n");
  spit(path("degen.obj"), std::string(cube_obj) + "f 1 2 1\n");
  // Two triangles crossing each other, and a bow-tie at vertex 1.
  spit(path("cross.obj"),
       "v 0 0 0\nv 2 0 0\nv 0 2 0\nv 0.5 0.5 -1\nv 0.5 0.5 1\nv 3 3 0\n"
       "f 1 2 3\nf 4 5 6\n");
  spit(path("bowtie.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\nf 1 2 3\nf 1 4 5\n");
  spit(path("empty.obj"), "# nothing\n");
  ASSERT_EQ(locus::write_mesh(path("moebius.obj"), moebius(12)).status, Status::ok);
  ASSERT_EQ(locus::write_mesh(path("scrambled.obj"), scrambled_mesh(rng)).status, Status::ok);
  ASSERT_EQ(locus::write_mesh(path("dodeca.obj"), locus::dodecahedron_mesh<double>()).status,
            Status::ok);
  // Random polygon soup: self-intersections, non-manifold edges, skipped faces.
  locus::PolygonMesh<double> soup;
  for (int i = 0; i < 30; ++i) soup.vertices.push_back(rng.vec<double, 3>(-10.0, 10.0));
  for (int f = 0; f < 25; ++f) {
    std::vector<std::uint32_t> face(std::size_t(rng.uniform_int(3, 4)));
    for (auto& v : face) v = std::uint32_t(rng.uniform_int(0, 29));
    locus::add_face(soup, std::span<const std::uint32_t>(face));
  }
  ASSERT_EQ(locus::write_mesh(path("soup.obj"), soup).status, Status::ok);
  const char* const names[] = {"cube.obj",    "open.obj",      "flip.obj",   "dup.obj",
                               "degen.obj",   "cross.obj",     "bowtie.obj", "empty.obj",
                               "moebius.obj", "scrambled.obj", "dodeca.obj", "soup.obj"};
  for (const char* name : names) {
    for (const double tol : {0.0, 1e-12}) {
      SCOPED_TRACE(std::string(name) + " tolerance " + shortest(tol));
      const auto in = locus::read_mesh<double>(path(name));
      ASSERT_EQ(in.status, Status::ok) << in.message;
      const locus::VetMeshBuild b = locus::make_vet_mesh(in.mesh);
      const auto c = locus::classify_mesh(b.mesh, std::span<const Vec3d>(in.mesh.vertices), tol);
      std::vector<std::uint32_t> input_face(b.mesh.face_capacity(), 0);
      std::size_t skipped = 0;
      for (std::size_t i = 0; i < b.face_ids.size(); ++i) {
        if (b.face_ids[i] == locus::VetMesh::npos) {
          ++skipped;
        } else {
          input_face[b.face_ids[i]] = std::uint32_t(i);
        }
      }
      const std::string args = "mesh check " + path(name) + " --tolerance " + shortest(tol);
      const Outcome r = run(args);
      ASSERT_EQ(r.code, 0) << r.err;
      auto f = fields(r.out);
      const auto n = [&](const std::string& key) {
        return f.count(key) && f[key].size() == 1 ? f[key][0] : std::string("?");
      };
      const auto yes = [](bool v) { return std::string(v ? "yes" : "no"); };
      EXPECT_EQ(n("vertices"), std::to_string(in.mesh.vertices.size()));
      EXPECT_EQ(n("faces"), std::to_string(locus::face_count(in.mesh)));
      EXPECT_EQ(n("edges"), std::to_string(b.mesh.edge_count()));
      EXPECT_EQ(n("skipped_faces"), std::to_string(skipped));
      EXPECT_EQ(n("isolated_vertices"), std::to_string(c.topology.isolated_vertices.size()));
      EXPECT_EQ(n("isolated_edges"), std::to_string(c.topology.isolated_edges.size()));
      EXPECT_EQ(n("boundary_edges"), std::to_string(c.topology.boundary_edges.size()));
      EXPECT_EQ(n("non_manifold_edges"), std::to_string(c.topology.non_manifold_edges.size()));
      EXPECT_EQ(n("non_manifold_vertices"),
                std::to_string(c.topology.non_manifold_vertices.size()));
      EXPECT_EQ(n("face_components"),
                std::to_string(c.orientation.components.face_component_count));
      EXPECT_EQ(n("vertex_components"),
                std::to_string(c.orientation.components.vertex_component_count));
      EXPECT_EQ(n("faces_to_flip"), std::to_string(c.orientation.flipped_faces.size()));
      EXPECT_EQ(n("non_orientable_components"),
                std::to_string(c.orientation.non_orientable_components.size()));
      EXPECT_EQ(n("self_intersections"), std::to_string(c.intersections.face_pairs.size()));
      EXPECT_EQ(n("degenerate_faces"), std::to_string(c.intersections.degenerate_faces.size()));
      EXPECT_EQ(n("non_planar_faces"), std::to_string(c.non_planar_faces.size()));
      EXPECT_EQ(n("euler_characteristic"), std::to_string(c.euler_characteristic));
      EXPECT_EQ(n("closed"), yes(c.topology.closed));
      EXPECT_EQ(n("manifold"), yes(c.topology.manifold));
      EXPECT_EQ(n("orientable"), yes(c.orientation.orientable));
      EXPECT_EQ(n("convex"), yes(c.convex));
      // The JSON lists the intersecting pairs as input face indices.
      const Outcome j = run(args + " --json");
      ASSERT_EQ(j.code, 0) << j.err;
      std::string pairs = "\"self_intersection_pairs\": [";
      for (std::size_t k = 0; k < c.intersections.face_pairs.size(); ++k) {
        const auto& [a, g] = c.intersections.face_pairs[k];
        pairs += (k ? ",[" : "[") + std::to_string(input_face[a]) + "," +
                 std::to_string(input_face[g]) + "]";
      }
      EXPECT_NE(j.out.find(pairs + "]"), std::string::npos) << j.out;
    }
  }
  // Independent facts about the fixtures (not the library's word).
  const auto kind = [&](const std::string& name, const std::string& extra = {}) {
    return fields(run("mesh check " + path(name) + extra).out)["kind"];
  };
  using W = std::vector<std::string>;
  EXPECT_EQ(kind("cube.obj"), W{"polytope"});
  EXPECT_EQ(kind("open.obj"), W{"mesh"});
  EXPECT_EQ(kind("cross.obj"), W{"not_a_mesh"});
  EXPECT_EQ(kind("dodeca.obj", " --tolerance 1e-12"), W{"polytope"});
  EXPECT_EQ(fields(run("mesh check " + path("moebius.obj")).out)["orientable"], W{"no"});
  EXPECT_EQ(fields(run("mesh check " + path("flip.obj")).out)["faces_to_flip"], W{"1"});
  EXPECT_EQ(fields(run("mesh check " + path("degen.obj")).out)["skipped_faces"], W{"1"});
  EXPECT_EQ(fields(run("mesh check " + path("dup.obj")).out)["non_manifold_edges"], W{"4"});
  EXPECT_EQ(fields(run("mesh check " + path("dup.obj")).out)["isolated_vertices"], W{"1"});
  EXPECT_EQ(fields(run("mesh check " + path("cross.obj")).out)["self_intersections"], W{"1"});
  EXPECT_EQ(fields(run("mesh check " + path("bowtie.obj")).out)["non_manifold_vertices"], W{"1"});
}

TEST_F(Cli, MeshOrientMatchesMakeConsistent) {
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  ASSERT_EQ(locus::write_mesh(path("s.obj"), scrambled_mesh(rng)).status, Status::ok);
  ASSERT_EQ(locus::write_mesh(path("m.obj"), moebius(9)).status, Status::ok);
  for (const char* name : {"s.obj", "m.obj"}) {
    SCOPED_TRACE(name);
    auto in = locus::read_mesh<double>(path(name));
    ASSERT_EQ(in.status, Status::ok);
    const locus::MeshOrientation expected = locus::make_consistent(in.mesh);
    const Outcome r = run("mesh orient " + path(name) + " -o " + path("out.ply"));
    ASSERT_EQ(r.code, 0) << r.err;
    auto f = fields(r.out);
    EXPECT_EQ(f["flipped_faces"],
              std::vector<std::string>{std::to_string(expected.flipped_faces.size())});
    EXPECT_EQ(f["non_orientable_components"],
              std::vector<std::string>{std::to_string(expected.non_orientable_components.size())});
    EXPECT_EQ(f["orientable"], std::vector<std::string>{expected.orientable ? "yes" : "no"});
    const auto out = locus::read_mesh<double>(path("out.ply"));
    ASSERT_EQ(out.status, Status::ok) << out.message;
    ASSERT_EQ(out.mesh.vertices.size(), in.mesh.vertices.size());
    for (std::size_t i = 0; i < in.mesh.vertices.size(); ++i) {
      EXPECT_TRUE(same<3>(out.mesh.vertices[i], in.mesh.vertices[i]));
    }
    EXPECT_EQ(out.mesh.face_offsets, in.mesh.face_offsets);
    EXPECT_EQ(out.mesh.face_indices, in.mesh.face_indices);
    // Independently: the written orientable mesh needs no more flips.
    const Outcome again = run("mesh check " + path("out.ply"));
    EXPECT_EQ(fields(again.out)["faces_to_flip"], std::vector<std::string>{"0"});
  }
  EXPECT_EQ(fields(run("mesh orient " + path("m.obj") + " -o " + path("o.obj")).out)["orientable"],
            std::vector<std::string>{"no"});
  // A face repeating a vertex: bad input, nothing written.
  spit(path("degen.obj"), std::string(cube_obj) + "f 1 2 1\n");
  expect_bad_input(run("mesh orient " + path("degen.obj") + " -o " + path("d.obj")),
                   path("degen.obj"), 0, "repeats a vertex");
  EXPECT_FALSE(fs::exists(path("d.obj")));
}

TEST_F(Cli, MeshGenerateWritesTheLibraryMeshes) {
  const std::pair<std::string, locus::PolygonMesh<double>> cases[] = {
      {"tetrahedron", locus::tetrahedron_mesh<double>()},
      {"cube", locus::hexahedron_mesh<double>()},
      {"octahedron", locus::octahedron_mesh<double>()},
      {"dodecahedron", locus::dodecahedron_mesh<double>()},
      {"dodecahedron --triangles", locus::dodecahedron_triangle_mesh<double>()},
      {"icosahedron", locus::icosahedron_mesh<double>()},
      {"uvsphere", locus::uv_sphere_mesh<double>(1.0, 32, 16)},
      {"uvsphere --radius 2.5 --slices 7 --stacks 5", locus::uv_sphere_mesh<double>(2.5, 7, 5)},
      {"icosphere --radius 0.75 --levels 3", locus::icosphere_mesh<double>(0.75, 3)},
      {"torus", locus::torus_mesh<double>(1.0, 0.25, 32, 16)},
      {"torus --major-radius 3 --minor-radius 1.25 --major-segments 9 --minor-segments 5",
       locus::torus_mesh<double>(3.0, 1.25, 9, 5)},
      {"cylinder --radius 0.5 --height 3 --slices 11", locus::cylinder_mesh<double>(0.5, 3.0, 11)},
      {"cone --slices 2", locus::cone_mesh<double>(1.0, 2.0, 2)}};
  for (const auto& [args, expected] : cases) {
    SCOPED_TRACE(args);
    for (const char* ext : {".obj", ".ply"}) {
      const Outcome r = run("mesh generate " + args + " -o " + path(std::string("g") + ext));
      ASSERT_EQ(r.code, 0) << r.err;
      auto f = fields(r.out);
      EXPECT_EQ(f["vertices"], std::vector<std::string>{std::to_string(expected.vertices.size())});
      EXPECT_EQ(f["faces"], std::vector<std::string>{std::to_string(locus::face_count(expected))});
      const auto m = locus::read_mesh<double>(path(std::string("g") + ext));
      ASSERT_EQ(m.status, Status::ok) << m.message;
      ASSERT_EQ(m.mesh.vertices.size(), expected.vertices.size());
      for (std::size_t i = 0; i < expected.vertices.size(); ++i) {
        EXPECT_TRUE(same<3>(m.mesh.vertices[i], expected.vertices[i])) << i;
      }
      EXPECT_EQ(m.mesh.face_offsets, expected.face_offsets);
      EXPECT_EQ(m.mesh.face_indices, expected.face_indices);
    }
    // Independently of the generator's word: each written mesh is closed and orientable.
    auto f = fields(run("mesh check " + path("g.obj") + " --tolerance 1e-12").out);
    EXPECT_EQ(f["closed"], std::vector<std::string>{"yes"});
    EXPECT_EQ(f["orientable"], std::vector<std::string>{"yes"});
    EXPECT_EQ(f["faces_to_flip"], std::vector<std::string>{"0"});
  }
  const Outcome j = run("mesh generate cube --json -o " + path("c.off"));
  EXPECT_EQ(j.code, 0);
  EXPECT_NE(j.out.find("\"faces\": 6"), std::string::npos) << j.out;
}

// The library's answer for one ray: the smallest t over the watertight hits, lowest index.
struct ExpectedHit {
  bool hit = false;
  double t = 0;
  std::size_t triangle = 0;
  Vec3d b{};
};
ExpectedHit library_hit(const locus::Ray3d& ray, const locus::PolygonMesh<double>& m) {
  const auto tris = locus::fan_triangles(m);
  ExpectedHit e;
  for (std::size_t k = 0; k < tris.size(); ++k) {
    const auto& p = m.vertices;
    const auto h =
        locus::watertight_hit(ray, locus::Triangle3d{p[tris[k][0]], p[tris[k][1]], p[tris[k][2]]});
    if (h.hit && (!e.hit || h.t < e.t)) e = {true, h.t, k, h.barycentric};
  }
  return e;
}

TEST_F(Cli, RaycastMatchesWatertightHitsBitForBit) {
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  locus::PolygonMesh<double> mesh = locus::icosphere_mesh<double>(2.0, 2);
  ASSERT_EQ(locus::write_mesh(path("sphere.obj"), mesh).status, Status::ok);
  std::vector<locus::Ray3d> rays;
  std::string csv = "ox,oy,oz,dx,dy,dz\n";
  const auto add = [&](const Vec3d& o, const Vec3d& d) {
    rays.push_back({o, d});
    csv += shortest(o.x) + "," + shortest(o.y) + "," + shortest(o.z) + "," + shortest(d.x) + "," +
           shortest(d.y) + "," + shortest(d.z) + "\n";
  };
  for (int i = 0; i < 60; ++i) add(rng.vec<double, 3>(-4.0, 4.0), rng.unit<double, 3>());
  // From the centre through every vertex (shared by 5 or 6 triangles): exactly one hit each.
  for (std::size_t v = 0; v < mesh.vertices.size(); v += 7) add({0, 0, 0}, mesh.vertices[v]);
  add({0, 0, 0}, {0, 0, 0});  // zero direction: no hit
  add({9, 9, 9}, {1, 1, 1});  // pointing away
  spit(path("rays.csv"), csv);
  const Outcome r = run("raycast " + path("sphere.obj") + " " + path("rays.csv"));
  ASSERT_EQ(r.code, 0) << r.err;
  std::vector<std::vector<std::string>> lines;
  {
    std::istringstream in(r.out);
    for (std::string line; std::getline(in, line);) {
      if (!line.empty() && line[0] != '#') lines.push_back(words(line));
    }
  }
  ASSERT_EQ(lines.size(), rays.size());
  std::size_t hits = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    SCOPED_TRACE(i);
    const ExpectedHit e = library_hit(rays[i], mesh);
    if (!e.hit) {
      EXPECT_EQ(lines[i], std::vector<std::string>{"0"});
      continue;
    }
    ++hits;
    const std::vector<std::string> want = {"1",
                                           shortest(e.t),
                                           std::to_string(e.triangle),
                                           shortest(e.b.x),
                                           shortest(e.b.y),
                                           shortest(e.b.z)};
    EXPECT_EQ(lines[i], want);
  }
  // Independently: rays from the centre leave the closed sphere exactly once; the last two miss.
  for (std::size_t i = 60; i + 2 < rays.size(); ++i) EXPECT_EQ(lines[i][0], "1") << i;
  EXPECT_EQ(lines[rays.size() - 2], std::vector<std::string>{"0"});
  EXPECT_EQ(lines[rays.size() - 1], std::vector<std::string>{"0"});
  // Rays on standard input, -o and --json.
  const Outcome j =
      run("raycast " + path("sphere.obj") + " - --json -o " + path("hits.txt"), path("rays.csv"));
  ASSERT_EQ(j.code, 0) << j.err;
  EXPECT_EQ(slurp(path("hits.txt")), r.out);
  EXPECT_NE(j.out.find("\"hits\": " + std::to_string(hits)), std::string::npos) << j.out;
  EXPECT_NE(j.out.find("\"rays\": " + std::to_string(rays.size())), std::string::npos);
  // Polygon faces: triangle indices count fan triangles (the cube's quads give 2 each).
  spit(path("cube.obj"), cube_obj);
  spit(path("one.csv"), "0.25 0.75 -1 0 0 1\n");
  const auto cube = locus::read_mesh<double>(path("cube.obj"));
  const ExpectedHit e = library_hit({{0.25, 0.75, -1}, {0, 0, 1}}, cube.mesh);
  ASSERT_TRUE(e.hit);
  EXPECT_EQ(fields(run("raycast " + path("cube.obj") + " " + path("one.csv")).out)["1"],
            (std::vector<std::string>{shortest(e.t), std::to_string(e.triangle), shortest(e.b.x),
                                      shortest(e.b.y), shortest(e.b.z)}));
  EXPECT_EQ(e.t, 1.0);
  // Bad rays: the reader's line; bad mesh: its line.
  spit(path("bad.csv"), "ox,oy,oz,dx,dy,dz\n0,0,0,1,0,0\n0,0,x,1,0,0\n");
  expect_bad_input(run("raycast " + path("cube.obj") + " " + path("bad.csv")), path("bad.csv"), 3,
                   "bad number 'x' in field 3");
  spit(path("five.csv"), "0,0,0,1,0\n");
  expect_bad_input(run("raycast " + path("cube.obj") + " " + path("five.csv")), path("five.csv"), 1,
                   "expected 6 fields, found 5");
  spit(path("bad.obj"), "v 0 0 0\nv 1 0 0\nf 1 2 7\n");
  expect_bad_input(run("raycast " + path("bad.obj") + " " + path("one.csv")), path("bad.obj"), 3,
                   "index");
}

// surfacehit: rays against a sphere and a torus; the lines match the library's answers.
TEST_F(Cli, SurfacehitMatchesTheLibrary) {
  spit(path("srays.csv"), "ox,oy,oz,dx,dy,dz\n-9,0,0,1,0,0\n-9,0,1,1,0,0\n0,0,9,0,0,1\n");
  const Outcome t = run("surfacehit " + path("srays.csv") + " --torus 0,0,0,0,0,1,4,1");
  ASSERT_EQ(t.code, 0) << t.err;
  std::vector<std::vector<std::string>> lines;
  {
    std::istringstream in(t.out);
    for (std::string line; std::getline(in, line);)
      if (!line.empty() && line[0] != '#') lines.push_back(words(line));
  }
  ASSERT_EQ(lines.size(), 3u);
  const locus::Torus3d tor{{0, 0, 0}, {0, 0, 1}, 4, 1};
  const locus::Ray3d rays[3] = {
      {{-9, 0, 0}, {1, 0, 0}}, {{-9, 0, 1}, {1, 0, 0}}, {{0, 0, 9}, {0, 0, 1}}};
  for (int i = 0; i < 3; ++i) {
    const auto h = locus::intersection(rays[i], tor);
    std::vector<std::string> want = {std::to_string(h.count)};
    for (int k = 0; k < h.count; ++k) {
      want.push_back(shortest(h.param_a[std::size_t(k)]));
      want.push_back(std::to_string(h.multiplicity[std::size_t(k)]));
    }
    EXPECT_EQ(lines[std::size_t(i)], want) << i;
  }
  // Independently: across the ring 4 hits, tangent to the top 2 double ones, away none.
  EXPECT_EQ(lines[0][0], "4");
  EXPECT_EQ(lines[1][0], "2");
  EXPECT_EQ(lines[2], std::vector<std::string>{"0"});
  const Outcome bad = run("surfacehit " + path("srays.csv"));
  EXPECT_EQ(bad.code, 2);
}

}  // namespace

TEST_F(Cli, MeshSliceMatchesTheLibrary) {
  spit(path("cube.obj"), cube_obj);
  const Outcome r = run("mesh slice --plane 0,0,1,-0.5 " + path("cube.obj"));
  ASSERT_EQ(r.code, 0) << r.err;
  const locus::PolygonMesh<double> m = locus::read_mesh<double>(path("cube.obj")).mesh;
  const locus::MeshSlice<double> s = locus::slice_mesh(
      std::span<const Vec3d>(m.vertices), std::span<const std::uint32_t>(m.face_offsets),
      std::span<const std::uint32_t>(m.face_indices), locus::Plane3<double>{{0, 0, 1}, 0.5});
  ASSERT_EQ(s.polylines.size(), 1u);
  EXPECT_EQ(r.out.substr(0, r.out.find('\n')),
            "closed " + std::to_string(s.polylines[0].vertices.size()));
  EXPECT_EQ(run("mesh slice --plane 0,0,1 " + path("cube.obj")).code, 2);
}
