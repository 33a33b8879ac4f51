// SPDX-License-Identifier: BSL-1.0
// End-to-end test of `locus bsp` (tools/locus/cmd_bsp.cpp, docs/cli.md): the built binary on
// WKT and CSV files written here must print what the library computes: `bsp classify` the sides
// of Bsp2::classify, `bsp boolean` the loops of bsp2_boolean (as closed WKT LINESTRINGs) and,
// for an intersection, the shared segments and touching points; bad input exits 1.

#include <locus/bsp/bsp2_boolean.hpp>

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

void write(const fs::path& p, const std::string& text) {
  std::ofstream f(p);
  f << text;
}

/// The library's answer in the tool's text form (numbers are small integers here).
std::string expected_text(const locus::Bsp2BooleanResult<double>& r) {
  const auto xy = [](const locus::Vec2d& p) {
    std::ostringstream s;
    s << p.x << " " << p.y;
    return s.str();
  };
  std::string t;
  std::uint32_t b = 0;
  for (const std::uint32_t e : r.loop_ends) {
    t += "LINESTRING (";
    for (std::uint32_t i = b; i < e; ++i) t += xy(r.edges[r.loop_edges[i]].end[0].point) + ", ";
    t += xy(r.edges[r.loop_edges[b]].end[0].point) + ")\n";
    b = e;
  }
  for (const auto& s : r.segments)
    t += "LINESTRING (" + xy(s.end[0].point) + ", " + xy(s.end[1].point) + ")\n";
  for (const auto& p : r.points) t += "POINT (" + xy(p) + ")\n";
  return t;
}

TEST(BspCli, BooleanAndClassifyMatchTheLibrary) {
  const fs::path dir = fs::temp_directory_path() / ("locus_bsp_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // A: a square with a square hole; B: an L shape overlapping it; C: shares A's right edge.
  write(dir / "a.wkt", "POLYGON ((0 0, 6 0, 6 6, 0 6, 0 0), (2 2, 2 4, 4 4, 4 2, 2 2))\n");
  write(dir / "b.wkt", "POLYGON ((3 -1, 8 -1, 8 8, 5 8, 5 3, 3 3, 3 -1))\n");
  write(dir / "c.wkt", "POLYGON ((6 0, 9 0, 9 6, 6 6, 6 0))\n");
  const std::vector<locus::Vec2d> a{{0, 0}, {6, 0}, {6, 6}, {0, 6}, {2, 2}, {2, 4}, {4, 4}, {4, 2}};
  const std::vector<locus::Vec2d> b{{3, -1}, {8, -1}, {8, 8}, {5, 8}, {5, 3}, {3, 3}};
  const std::vector<locus::Vec2d> c{{6, 0}, {9, 0}, {9, 6}, {6, 6}};
  const std::uint32_t ea[] = {4, 8}, eb[] = {6}, ec[] = {4};
  const locus::Bsp2<double> ta(a, ea), tb(b, eb), tc(c, ec);
  const std::pair<const char*, locus::Bsp2Op> ops[] = {
      {"intersection", locus::Bsp2Op::intersection},
      {"union", locus::Bsp2Op::union_},
      {"difference", locus::Bsp2Op::difference},
      {"xor", locus::Bsp2Op::exclusive_or}};
  for (const auto& [name, op] : ops) {
    const CliRun r =
        run_locus(dir, "bsp boolean " + (dir / "a.wkt").string() + " " + (dir / "b.wkt").string() +
                           " --op " + name + " --svg " + (dir / "r.svg").string());
    ASSERT_EQ(r.code, 0) << r.err;
    const auto lib = locus::bsp2_boolean(op, ta, tb);
    ASSERT_FALSE(lib.loop_ends.empty());
    EXPECT_EQ(r.out, expected_text(lib)) << name;
    EXPECT_NE(locus_test::slurp((dir / "r.svg").string()).find("<svg"), std::string::npos);
  }
  // The shared edge of A and C is the whole intersection (a segment).
  const CliRun touch =
      run_locus(dir, "bsp boolean " + (dir / "a.wkt").string() + " " + (dir / "c.wkt").string());
  ASSERT_EQ(touch.code, 0) << touch.err;
  EXPECT_EQ(touch.out, expected_text(locus::bsp2_boolean(locus::Bsp2Op::intersection, ta, tc)));
  EXPECT_NE(touch.out.find("LINESTRING (6 "), std::string::npos) << touch.out;
  const CliRun js = run_locus(dir, "bsp boolean " + (dir / "a.wkt").string() + " " +
                                       (dir / "c.wkt").string() + " --op union --json");
  ASSERT_EQ(js.code, 0) << js.err;
  EXPECT_NE(js.out.find("\"area\": 50"), std::string::npos) << js.out;  // (36 - 4) + 18
  // classify: points inside, on the hole's boundary, in the hole, outside.
  write(dir / "p.csv", "1,1\n3,2\n3,3\n7,7\n");
  const CliRun cl = run_locus(
      dir, "bsp classify " + (dir / "a.wkt").string() + " --points " + (dir / "p.csv").string());
  ASSERT_EQ(cl.code, 0) << cl.err;
  EXPECT_EQ(cl.out, "inside\nboundary\noutside\noutside\n");
  // Bad input: a NaN coordinate, two polygons in one file.
  write(dir / "nan.wkt", "POLYGON ((0 0, nan 0, 1 1, 0 0))\n");
  const CliRun bad =
      run_locus(dir, "bsp boolean " + (dir / "a.wkt").string() + " " + (dir / "nan.wkt").string());
  EXPECT_EQ(bad.code, 1);
  EXPECT_FALSE(bad.err.empty());
  write(dir / "two.wkt", "MULTIPOLYGON (((0 0, 1 0, 0 1, 0 0)), ((5 5, 6 5, 5 6, 5 5)))\n");
  const CliRun two =
      run_locus(dir, "bsp boolean " + (dir / "two.wkt").string() + " " + (dir / "a.wkt").string());
  EXPECT_EQ(two.code, 1);
  EXPECT_NE(two.err.find("exactly one"), std::string::npos) << two.err;
  std::error_code err;
  fs::remove_all(dir, err);
}

}  // namespace
