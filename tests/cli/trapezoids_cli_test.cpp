// SPDX-License-Identifier: BSL-1.0
// End-to-end test of `locus trapezoids` (tools/locus/cmd_polygon.cpp, docs/cli.md): the built
// binary on a WKT square with a square hole must print the library's trapezoidal map of the ring
// edges (rows bottom top left right, -1 unbounded) and locate query points as the library does;
// crossing edges exit 1 with a message.

#include <locus/triangulate/trapezoid_map.hpp>

#include "support/cli_run.hpp"
#include "support/files.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

using locus_test::CliRun;
using locus_test::run_locus;

std::vector<std::vector<long>> rows(const std::string& text) {
  std::vector<std::vector<long>> r;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::istringstream l(line);
    r.emplace_back();
    for (long v; l >> v;) r.back().push_back(v);
  }
  return r;
}

std::vector<long> row(const locus::MapTrapezoid& t) {
  std::vector<long> v;
  for (const std::uint32_t x : {t.bottom, t.top, t.left, t.right})
    v.push_back(x == locus::trapezoid_unbounded ? -1L : long(x));
  return v;
}

TEST(TrapezoidsCli, MapAndLocationMatchTheLibrary) {
  const fs::path dir =
      fs::temp_directory_path() / ("locus_trapezoids_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  {
    std::ofstream f(dir / "sq.wkt");
    f << "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1))\n";
    std::ofstream q(dir / "q.csv");
    q << "0.5,0.5\n2,2\n5,5\n3.5,1\n";
  }
  const std::vector<locus::Vec2d> pts{{0, 0}, {4, 0}, {4, 4}, {0, 4},
                                      {1, 1}, {1, 3}, {3, 3}, {3, 1}};
  const std::vector<std::array<std::uint32_t, 2>> segs{{0, 1}, {1, 2}, {2, 3}, {3, 0},
                                                       {4, 5}, {5, 6}, {6, 7}, {7, 4}};
  locus::TrapezoidMap2<double> lib;
  ASSERT_EQ(lib.build(std::span<const locus::Vec2d>(pts), segs), locus::Status::ok);
  std::vector<std::vector<long>> expected;
  for (const auto& t : lib.trapezoids()) expected.push_back(row(t));

  const CliRun r = run_locus(
      dir, "trapezoids " + (dir / "sq.wkt").string() + " --svg " + (dir / "t.svg").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(rows(r.out), expected);
  EXPECT_NE(locus_test::slurp((dir / "t.svg").string()).find("<svg"), std::string::npos);

  const CliRun l = run_locus(
      dir, "trapezoids " + (dir / "sq.wkt").string() + " --points " + (dir / "q.csv").string());
  ASSERT_EQ(l.code, 0) << l.err;
  std::vector<std::vector<long>> located;
  for (const locus::Vec2d& q :
       {locus::Vec2d{0.5, 0.5}, locus::Vec2d{2, 2}, locus::Vec2d{5, 5}, locus::Vec2d{3.5, 1}}) {
    const std::uint32_t k = lib.locate(q);
    std::vector<long> v{long(k)};
    for (const long x : row(lib.trapezoids()[k])) v.push_back(x);
    located.push_back(v);
  }
  EXPECT_EQ(rows(l.out), located);

  {
    std::ofstream f(dir / "bow.wkt");
    f << "POLYGON ((0 0, 4 4, 4 0, 0 4, 0 0))\n";
  }
  const CliRun b = run_locus(dir, "trapezoids " + (dir / "bow.wkt").string());
  EXPECT_EQ(b.code, 1);
  EXPECT_NE(b.err.find("cross"), std::string::npos) << b.err;
  fs::remove_all(dir);
}

}  // namespace
