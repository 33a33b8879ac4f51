// SPDX-License-Identifier: BSL-1.0
// End-to-end test of `locus boolean` (tools/locus/cmd_boolean.cpp, docs/cli.md): the built
// binary on WKT and GeoJSON files written here must print the library's result as one WKT
// MULTIPOLYGON for each operation; bad input exits 1 with a message.

#include <locus/boolean/polygon_boolean.hpp>
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

std::string library_wkt(locus::BooleanOp op, const locus::MultiPolygon2<double>& a,
                        const locus::MultiPolygon2<double>& b) {
  const auto r = locus::boolean_op(op, a, b);
  EXPECT_EQ(r.status, locus::Status::ok);
  locus::Geometry2<double> g;
  g.type = locus::GeometryType::multi_polygon;
  for (const auto& p : r.polygons) g.polygons.push_back(locus::to_ring_polygon(p));
  return locus::write_wkt_string(g).data + "\n";
}

TEST(BooleanCli, EveryOperationMatchesTheLibrary) {
  const fs::path dir =
      fs::temp_directory_path() / ("locus_boolean_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  {
    // A square with a hole, and a clockwise triangle (GeoJSON) crossing it.
    std::ofstream(dir / "a.wkt")
        << "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1))\n";
    std::ofstream(dir / "b.geojson")
        << R"({"type": "Polygon", "coordinates": [[[2, -1], [2.5, 5], [6, 2], [2, -1]]]})";
  }
  const locus::MultiPolygon2<double> a{
      {{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}}, {{{{1, 1}, {1, 3}, {3, 3}, {3, 1}}}}}};
  const locus::MultiPolygon2<double> b{{{{{2, -1}, {2.5, 5}, {6, 2}}}, {}}};
  const std::pair<const char*, locus::BooleanOp> ops[] = {
      {"intersection", locus::BooleanOp::intersection},
      {"union", locus::BooleanOp::union_},
      {"difference", locus::BooleanOp::difference},
      {"xor", locus::BooleanOp::symmetric_difference}};
  for (const auto& [name, op] : ops) {
    const CliRun r =
        run_locus(dir, "boolean " + (dir / "a.wkt").string() + " " + (dir / "b.geojson").string() +
                           " --op " + name + " --svg " + (dir / "r.svg").string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out, library_wkt(op, a, b)) << name;
    EXPECT_NE(r.out.find("MULTIPOLYGON ((("), std::string::npos) << name;
    EXPECT_NE(locus_test::slurp((dir / "r.svg").string()).find("<svg"), std::string::npos);
  }
  // Disjoint operands: an empty intersection is a valid answer.
  std::ofstream(dir / "far.wkt") << "POLYGON ((10 10, 11 10, 11 11, 10 10))\n";
  CliRun r = run_locus(dir, "boolean " + (dir / "a.wkt").string() + " " +
                                (dir / "far.wkt").string() + " --op intersection --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"polygons\": 0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("MULTIPOLYGON EMPTY"), std::string::npos) << r.out;
  // A non-finite coordinate or an unknown operation fails with a message.
  std::ofstream(dir / "nan.wkt") << "POLYGON ((0 0, nan 0, 1 1, 0 0))\n";
  r = run_locus(dir, "boolean " + (dir / "a.wkt").string() + " " + (dir / "nan.wkt").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_FALSE(r.err.empty());
  r = run_locus(
      dir, "boolean " + (dir / "a.wkt").string() + " " + (dir / "a.wkt").string() + " --op merge");
  EXPECT_NE(r.code, 0);
  fs::remove_all(dir);
}

}  // namespace
