// SPDX-License-Identifier: BSL-1.0
// End-to-end test of `locus sat` (tools/locus/cmd_sat.cpp, docs/cli.md): the command's output on
// two polygon files equals the library's convex_polygon_intersection / first_contact bit for bit
// (numbers print in the shortest form that reads back exactly).

#include <locus/intersection/convex_polygon2.hpp>
#include <locus/intersection/moving_convex2.hpp>
#include <locus/io/point_list.hpp>

#ifndef LOCUS_CLI_PATH
#error "LOCUS_CLI_PATH (the locus tool) is not defined"
#endif
#include "support/files.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <charconv>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using locus::Vec2d;

std::vector<std::vector<std::string>> lines(const std::string& text) {
  std::vector<std::vector<std::string>> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::istringstream w(line);
    std::vector<std::string> ws;
    for (std::string s; w >> s;) ws.push_back(s);
    if (!ws.empty()) out.push_back(ws);
  }
  return out;
}

double to_double(const std::string& s) {
  double v = 0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  EXPECT_TRUE(r.ec == std::errc() && r.ptr == s.data() + s.size()) << "not a number: " << s;
  return v;
}

TEST(CliSat, StationaryAndMovingMatchTheLibrary) {
  const fs::path dir = fs::temp_directory_path() / ("locus_cli_sat_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::vector<Vec2d> a{{0, 0}, {3, 0.1}, {2.5, 2}, {0.2, 1.7}};
  const std::vector<Vec2d> b{{1.3, 0.7}, {4, 1}, {3.3, 3.1}};
  const std::string fa = (dir / "a.csv").string(), fb = (dir / "b.csv").string();
  ASSERT_EQ((locus::write_points<double, 2>(fa, a).status), locus::Status::ok);
  ASSERT_EQ((locus::write_points<double, 2>(fb, b).status), locus::Status::ok);
  const auto run = [&](const std::string& args) {
    const std::string out = (dir / "out.txt").string();
    const std::string cmd = std::string("'") + LOCUS_CLI_PATH + "' sat '" + fa + "' --other '" +
                            fb + "' " + args + " >'" + out + "' 2>/dev/null";
    const int s = std::system(cmd.c_str());
    EXPECT_TRUE(WIFEXITED(s) && WEXITSTATUS(s) == 0) << cmd;
    return lines(locus_test::slurp(out));
  };
  const auto r = locus::convex_polygon_intersection(a, b);
  const auto st = run("");
  ASSERT_EQ(st.size(), 2 + r.vertices.size());
  EXPECT_EQ(st[0][1], "yes");
  EXPECT_EQ(st[1][1], "polygon");
  for (std::size_t i = 0; i < r.vertices.size(); ++i) {
    EXPECT_EQ(to_double(st[2 + i][1]), r.vertices[i].x);
    EXPECT_EQ(to_double(st[2 + i][2]), r.vertices[i].y);
  }
  std::vector<Vec2d> far = b;
  for (Vec2d& p : far) p += Vec2d{6, 0};
  ASSERT_EQ((locus::write_points<double, 2>(fb, far).status), locus::Status::ok);
  const auto c = locus::first_contact_convex_polygons(a, Vec2d{0.5, 0}, far, Vec2d{-1, 0}, 10.0);
  const auto mv = run("--va 0.5 0 --vb -1 0 --tmax 10");
  ASSERT_GE(mv.size(), 2u);
  EXPECT_EQ(mv[0][1], std::string(locus::to_string(c.kind)));
  EXPECT_EQ(to_double(mv[1][1]), c.time);
  ASSERT_EQ(mv.size(), 2u + static_cast<std::size_t>(c.count));
  for (int i = 0; i < c.count; ++i) {
    EXPECT_EQ(to_double(mv[2 + static_cast<std::size_t>(i)][1]),
              c.point[static_cast<std::size_t>(i)].x);
    EXPECT_EQ(to_double(mv[2 + static_cast<std::size_t>(i)][2]),
              c.point[static_cast<std::size_t>(i)].y);
  }
  std::error_code ec;
  fs::remove_all(dir, ec);
}

}  // namespace
