// SPDX-License-Identifier: BSL-1.0
// End-to-end test of `locus offset` (tools/locus/cmd_offset.cpp, docs/cli.md): the built binary
// on WKT and GeoJSON files written here must print the library's offset as one WKT
// MULTIPOLYGON for each join and end type; bad input exits non-zero with a message.

#include <locus/boolean/polygon_offset.hpp>
#include <locus/io/geometry.hpp>
#include <locus/io/wkt.hpp>

#include "support/cli_run.hpp"
#include "support/files.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;

using locus_test::CliRun;
using locus_test::run_locus;

std::string wkt_of(const locus::OffsetResult<double>& r) {
  EXPECT_EQ(r.status, locus::Status::ok) << r.message;
  locus::Geometry2<double> g;
  g.type = locus::GeometryType::multi_polygon;
  for (const auto& p : r.polygons) g.polygons.push_back(locus::to_ring_polygon(p));
  return locus::write_wkt_string(g).data + "\n";
}

TEST(OffsetCli, JoinsAndEndsMatchTheLibrary) {
  const fs::path dir =
      fs::temp_directory_path() / ("locus_offset_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // An L-shaped polygon with a hole (clockwise outer ring in the file), and a GeoJSON path.
  std::ofstream(dir / "a.wkt")
      << "POLYGON ((0 0, 0 4, 2 4, 2 2, 4 2, 4 0, 0 0), (0.5 0.5, 1.5 0.5, 1.5 1.5, 0.5 0.5))\n";
  std::ofstream(dir / "p.geojson")
      << R"({"type": "LineString", "coordinates": [[0, 0], [3, 0], [3, 2], [5, 3]]})";
  const locus::PolygonWithHoles2<double> a{{{{0, 0}, {0, 4}, {2, 4}, {2, 2}, {4, 2}, {4, 0}}},
                                           {{{{0.5, 0.5}, {1.5, 0.5}, {1.5, 1.5}}}}};
  const locus::Polyline<double, 2> path{{{0, 0}, {3, 0}, {3, 2}, {5, 3}}, false};
  const std::pair<const char*, locus::JoinType> joins[] = {{"round", locus::JoinType::round},
                                                           {"miter", locus::JoinType::miter},
                                                           {"square", locus::JoinType::square}};
  for (const auto& [name, join] : joins) {
    for (const double delta : {0.25, -0.2}) {
      locus::OffsetOptions o;
      o.join = join;
      o.miter_limit = 3;
      o.arc_tolerance = 0.01;
      const CliRun r = run_locus(dir, "offset " + (dir / "a.wkt").string() + " --delta " +
                                          std::to_string(delta) + " --join " + name +
                                          " --miter-limit 3 --arc-tolerance 0.01 --svg " +
                                          (dir / "r.svg").string());
      ASSERT_EQ(r.code, 0) << r.err;
      EXPECT_EQ(r.out, wkt_of(locus::offset(a, delta, o))) << name << " " << delta;
      EXPECT_NE(r.out.find("MULTIPOLYGON ((("), std::string::npos);
      EXPECT_NE(locus_test::slurp((dir / "r.svg").string()).find("<svg"), std::string::npos);
    }
  }
  const std::pair<const char*, locus::EndType> ends[] = {{"round", locus::EndType::round},
                                                         {"square", locus::EndType::square},
                                                         {"butt", locus::EndType::butt}};
  for (const auto& [name, end] : ends) {
    locus::OffsetOptions o;
    o.end = end;
    o.join = locus::JoinType::miter;
    const CliRun r = run_locus(dir, "offset " + (dir / "p.geojson").string() +
                                        " -d 0.5 --join miter --end " + name + " --json");
    ASSERT_EQ(r.code, 0) << r.err;
    std::string wkt = wkt_of(locus::offset_polyline(path, 0.5, o));
    wkt.pop_back();
    EXPECT_NE(r.out.find("\"wkt\": \"" + wkt + "\""), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"polygons\": 1"), std::string::npos) << r.out;
  }
  // Deflating until nothing is left is an empty answer, not an error.
  CliRun r = run_locus(dir, "offset " + (dir / "a.wkt").string() + " -d -5 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("MULTIPOLYGON EMPTY"), std::string::npos) << r.out;
  // NaN, a bad miter limit or a missing delta fail with a message.
  std::ofstream(dir / "nan.wkt") << "POLYGON ((0 0, nan 0, 1 1, 0 0))\n";
  r = run_locus(dir, "offset " + (dir / "nan.wkt").string() + " -d 1");
  EXPECT_EQ(r.code, 1);
  EXPECT_FALSE(r.err.empty());
  r = run_locus(dir, "offset " + (dir / "a.wkt").string() + " -d 1 --miter-limit 0.5");
  EXPECT_EQ(r.code, 1);
  EXPECT_FALSE(r.err.empty());
  r = run_locus(dir, "offset " + (dir / "a.wkt").string());
  EXPECT_NE(r.code, 0);
  r = run_locus(dir, "offset " + (dir / "a.wkt").string() + " -d 1 --join bevel");
  EXPECT_NE(r.code, 0);
  fs::remove_all(dir);
}

}  // namespace
